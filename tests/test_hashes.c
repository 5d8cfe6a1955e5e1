/*
 * test_hashes.c - the trees themselves do not change unnoticed.  Every
 * configuration of `atrbvh bench`'s default list (Embree aside) is built on
 * every test scene through the public API, and the SHA-256 of the tree's
 * bytes is compared with tests/tree-hashes.txt (found through
 * $ATRBVH_SRCDIR).  A difference, a missing line or a line no scene
 * produces fails the test, naming the scene and the configuration and
 * giving the SAH and node count of the table beside those of the new tree.
 *
 * The bytes hashed: the node array (atrbvh_bvh_nodes, count *
 * sizeof(atrbvh_node)) then the primitive index array
 * (atrbvh_bvh_primitive_indices), each field as its little-endian bytes,
 * which is the arrays' memory as it is on the machines the table is made
 * on; a big-endian machine hashes the same bytes.
 *
 * Scenes: builtin:sphere, builtin:terrain and builtin:city at their default
 * size, builtin:city:100000 (bench's default scene), and every .ply in
 * $ATRBVH_SCENES, named by its file name without ".ply".  Without that
 * folder the real scenes are skipped with a message; the built-in scenes
 * always run.
 *
 * The optimised trees are built twice more, with ATRBVH_CPU_LANES=1 (the
 * CPU's post-order walk, one treelet at a time) and =2 (two treelets side
 * by side; TRBVH's DP in two of AVX's four lanes, the others repeating
 * the first), and must hash as the default build (four; TRBVH's DP in
 * AVX's four lanes where the CPU has AVX): the
 * optimiser's ways of taking treelets give the same bits.  The LBVH is
 * built once more with ATRBVH_NO_AVX2=1 (the bounds sweep and the Morton
 * keys one at a time, where the CPU has AVX2 they take eight) and must
 * hash the same.
 *
 * ATRBVH_WRITE_HASHES=FILE: write the table to FILE (a temporary file
 * beside it, then renamed) instead of comparing; the comment lines of the
 * current table are kept, so its header and change notes survive.
 */
#define _POSIX_C_SOURCE 200809L

#include <check.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sha256.h"
#include "testutil.h"

#define MAX_SCENES 64
#define MAX_LINES 1024
#define HASH_FILE "tests/tree-hashes.txt"

/* bench's DEFAULT_CONFIGS "lbvh,trbvh:7:3,atrbvh:9:2,high,embree"
 * (tools/cli_bench.c) without embree: the method with its treelet size and
 * rounds (0: the method's default, as bench passes them), everything else
 * as bench's base options: atrbvh_build_options_init, max leaf 8, gamma 0
 * (the treelet size), ci 1.2, ct 1.0, collapse on, CPU backend.  "high" is
 * the --quality high preset (tools/cli.h, CLI_QUALITY_HIGH_*). */
typedef struct hconfig {
    const char *name;
    atrbvh_method method;
    unsigned treelet, rounds;
} hconfig;

static const hconfig configs[] = {
    {"lbvh", ATRBVH_METHOD_LBVH, 0, 0},
    {"trbvh:7:3", ATRBVH_METHOD_TRBVH, 7, 3},
    {"atrbvh:9:2", ATRBVH_METHOD_ATRBVH, 9, 2},
    {"high", ATRBVH_METHOD_ATRBVH, ATRBVH_TREELET_AUTO, 4},
};
#define NCONFIGS (sizeof configs / sizeof *configs)

static const char *const builtin_scenes[] = {
    "builtin:sphere", "builtin:terrain", "builtin:city",
    "builtin:city:100000"};
#define NBUILTIN (sizeof builtin_scenes / sizeof *builtin_scenes)

/* Under the sanitizers (ATRBVH_TEST_SANITIZER, tests/suite.d/20-
 * sanitizers.sh) the two largest real scenes are left out so that the
 * stage stays fast: ASan's instrumented code is several times slower and
 * these two are most of this test's time.  The built-in scenes and the
 * smaller real scenes still run there. */
static const char *const sanitizer_skip[] = {"dragon", "conference"};

/* ------------------------------------------------------------- state */
typedef struct scene_entry {
    char name[256];  /* the table's name of the scene        */
    char spec[4096]; /* what scene_load takes                */
    const char *skip; /* why it is not run, NULL when it is */
} scene_entry;

typedef struct line {
    char scene[256], config[64], hash[65], sah[64];
    unsigned long long nodes;
    int used;
    int lineno;
} line;

static scene_entry scenes[MAX_SCENES];
static int nscenes;
static line table[MAX_LINES];
static int nlines;
static char table_path[4096];
static const char *write_path; /* ATRBVH_WRITE_HASHES */
static line written[MAX_LINES];
static int sha256_ok; /* the known answers passed */
static int nwritten;

static int sanitizer_run(void)
{
    const char *s = getenv("ATRBVH_TEST_SANITIZER");
    return s && *s && strcmp(s, "0") != 0;
}

/* ------------------------------------------------------------ hashing */
static void put_u32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)v;
    p[1] = (unsigned char)(v >> 8);
    p[2] = (unsigned char)(v >> 16);
    p[3] = (unsigned char)(v >> 24);
}

static uint32_t float_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

/* SHA-256 of the tree's bytes, as the file header says. */
static void tree_hash(const atrbvh_bvh *bvh, char hex[65], size_t *nodes)
{
    size_t nn, np, i;
    const atrbvh_node *n = atrbvh_bvh_nodes(bvh, &nn);
    const uint32_t *idx = atrbvh_bvh_primitive_indices(bvh, &np);
    sha256_ctx c;
    unsigned char d[32];
    sha256_init(&c);
    for (i = 0; i < nn; i++) {
        unsigned char b[32];
        int k;
        for (k = 0; k < 3; k++) {
            put_u32(b + 4 * k, float_bits(n[i].min[k]));
            put_u32(b + 12 + 4 * k, float_bits(n[i].max[k]));
        }
        put_u32(b + 24, n[i].index);
        put_u32(b + 28, n[i].count);
        sha256_update(&c, b, sizeof b);
    }
    for (i = 0; i < np; i++) {
        unsigned char b[4];
        put_u32(b, idx[i]);
        sha256_update(&c, b, sizeof b);
    }
    sha256_final(&c, d);
    sha256_hex(d, hex);
    *nodes = nn;
}

static void hash_string(const char *s, size_t chunk, char hex[65])
{
    sha256_ctx c;
    unsigned char d[32];
    size_t n = strlen(s), i;
    sha256_init(&c);
    for (i = 0; i < n; i += chunk)
        sha256_update(&c, s + i, n - i < chunk ? n - i : chunk);
    sha256_final(&c, d);
    sha256_hex(d, hex);
}

/* Known answers (FIPS 180-2 appendix B / NIST examples): one block, the
 * empty message, a two-block message; fed whole and byte by byte. */
START_TEST(sha256_known_answers)
{
    static const struct {
        const char *msg, *hex;
    } kat[] = {
        {"abc", "ba7816bf8f01cfea414140de5dae2223"
                "b00361a396177a9cb410ff61f20015ad"},
        {"", "e3b0c44298fc1c149afbf4c8996fb924"
             "27ae41e4649b934ca495991b7852b855"},
        {"abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq",
         "248d6a61d20638b8e5c026930c3e6039"
         "a33ce45964ff2167f6ecedd419db06c1"},
    };
    size_t i, chunk;
    for (i = 0; i < sizeof kat / sizeof *kat; i++)
        for (chunk = 1; chunk <= 64; chunk += 63) {
            char hex[65];
            hash_string(kat[i].msg, chunk, hex);
            ck_assert_msg(strcmp(hex, kat[i].hex) == 0,
                          "SHA-256(\"%s\") in pieces of %zu is %s, not %s",
                          kat[i].msg, chunk, hex, kat[i].hex);
        }
    /* One million 'a' (the third FIPS example), in uneven pieces. */
    {
        static char a[1000];
        sha256_ctx c;
        unsigned char d[32];
        char hex[65];
        int k;
        memset(a, 'a', sizeof a);
        sha256_init(&c);
        for (k = 0; k < 1000; k++) {
            sha256_update(&c, a, 333);
            sha256_update(&c, a + 333, 667);
        }
        sha256_final(&c, d);
        sha256_hex(d, hex);
        ck_assert_str_eq(hex, "cdc76e5c9914fb9281a1c7e284d73e67"
                              "f1809a48a497200e046d39ccc7112cd0");
    }
    ck_assert_uint_eq(sizeof(atrbvh_node), 32);
    sha256_ok = 1;
}
END_TEST

/* -------------------------------------------------------------- table */
static char table_error[1200]; /* why the table could not be read */

static int table_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(table_error, sizeof table_error, fmt, ap);
    va_end(ap);
    return -1;
}

/* Reads table_path into table[]; -1 with table_error set on failure. */
static int load_table(void)
{
    FILE *f = fopen(table_path, "r");
    char buf[1024];
    int lineno = 0;
    if (!f)
        return table_fail("%s: %s (set ATRBVH_SRCDIR to the source tree)",
                          table_path, strerror(errno));
    while (fgets(buf, sizeof buf, f)) {
        line *l;
        char extra[8];
        int k;
        lineno++;
        if (!strchr(buf, '\n') && !feof(f)) {
            fclose(f);
            return table_fail("%s:%d: line too long", table_path, lineno);
        }
        if (buf[0] == '#' || strspn(buf, " \t\r\n") == strlen(buf))
            continue;
        if (nlines == MAX_LINES) {
            fclose(f);
            return table_fail("%s: more than %d lines", table_path,
                              MAX_LINES);
        }
        l = &table[nlines];
        memset(l, 0, sizeof *l);
        if (sscanf(buf, "%255s %63s %64s %63s %llu %7s", l->scene, l->config,
                   l->hash, l->sah, &l->nodes, extra) != 5 ||
            strlen(l->hash) != 64 ||
            strspn(l->hash, "0123456789abcdef") != 64) {
            fclose(f);
            return table_fail("%s:%d: not 'scene config sha256 sah nodes': "
                              "%.200s", table_path, lineno, buf);
        }
        for (k = 0; k < nlines; k++)
            if (strcmp(table[k].scene, l->scene) == 0 &&
                strcmp(table[k].config, l->config) == 0) {
                fclose(f);
                return table_fail("%s:%d: %s %s again (first on line %d)",
                                  table_path, lineno, l->scene, l->config,
                                  table[k].lineno);
            }
        l->lineno = lineno;
        nlines++;
    }
    fclose(f);
    return 0;
}

/* Whether the build of (g, o) with the environment variable `var` set to
 * `value` hashes as `hex` (the default build's, of `nodes` nodes); says
 * so on stderr when not. */
static int same_with(const char *var, const char *value,
                     const atrbvh_geometry *g, const atrbvh_build_options *o,
                     const char *hex, size_t nodes, const char *scene_name,
                     const char *config)
{
    char other[65];
    size_t other_nodes;
    atrbvh_bvh *bvh;
    ck_assert_int_eq(setenv(var, value, 1), 0);
    bvh = tu_build(g, o);
    ck_assert_int_eq(unsetenv(var), 0);
    tree_hash(bvh, other, &other_nodes);
    atrbvh_bvh_free(bvh);
    if (strcmp(other, hex) == 0)
        return 1;
    fprintf(stderr, "test_hashes: %s %s: %s=%s builds another tree (sha256 "
            "%s, %zu nodes) than the default (%s, %zu nodes)\n", scene_name,
            config, var, value, other, other_nodes, hex, nodes);
    return 0;
}

static line *find_line(const char *scene_name, const char *config)
{
    int k;
    for (k = 0; k < nlines; k++)
        if (strcmp(table[k].scene, scene_name) == 0 &&
            strcmp(table[k].config, config) == 0)
            return &table[k];
    return NULL;
}

/* ---------------------------------------------------------- the trees */
START_TEST(tree_hashes)
{
    const scene_entry *se = &scenes[_i];
    scene s;
    atrbvh_geometry g;
    char err[512];
    size_t c;
    int bad = 0;
    ck_assert_msg(table_error[0] == '\0', "%s", table_error);
    if (se->skip) {
        fprintf(stderr, "test_hashes: %s skipped: %s\n", se->name, se->skip);
        return;
    }
    ck_assert_msg(scene_load(se->spec, &s, err, sizeof err) == 0, "%s", err);
    g = scene_geometry(&s);
    for (c = 0; c < NCONFIGS; c++) {
        atrbvh_build_options o;
        atrbvh_bvh *bvh;
        atrbvh_stats st;
        char hex[65], sah[64];
        size_t nodes;
        line *l;
        atrbvh_build_options_init(&o);
        o.method = configs[c].method;
        o.treelet_size = configs[c].treelet;
        o.rounds = configs[c].rounds;
        o.max_leaf_size = 8;
        o.ci = 1.2;
        o.ct = 1.0;
        o.collapse = 1;
        o.backend = ATRBVH_BACKEND_CPU;
        o.threads = 2;
        bvh = tu_build(&g, &o);
        tree_hash(bvh, hex, &nodes);
        atrbvh_bvh_stats(bvh, &st);
        atrbvh_bvh_free(bvh);
        if (o.method == ATRBVH_METHOD_LBVH) {
            /* The bounds sweep and the Morton keys without AVX2: every
             * later stage reads only what they give, so the LBVH's
             * boxes and order show it all. */
            bad += !same_with("ATRBVH_NO_AVX2", "1", &g, &o, hex, nodes,
                              se->name, configs[c].name);
        } else {
            bad += !same_with("ATRBVH_CPU_LANES", "1", &g, &o, hex, nodes,
                              se->name, configs[c].name);
            bad += !same_with("ATRBVH_CPU_LANES", "2", &g, &o, hex, nodes,
                              se->name, configs[c].name);
        }
        snprintf(sah, sizeof sah, "%.17g", st.sah);
        if (write_path) {
            line *w;
            ck_assert_int_lt(nwritten, MAX_LINES);
            w = &written[nwritten++];
            snprintf(w->scene, sizeof w->scene, "%s", se->name);
            snprintf(w->config, sizeof w->config, "%s", configs[c].name);
            memcpy(w->hash, hex, sizeof w->hash);
            snprintf(w->sah, sizeof w->sah, "%s", sah);
            w->nodes = (unsigned long long)nodes;
            continue;
        }
        l = find_line(se->name, configs[c].name);
        if (!l) {
            fprintf(stderr, "test_hashes: %s %s: no line in %s (new tree: "
                    "%s SAH %s, %zu nodes)\n", se->name, configs[c].name,
                    table_path, hex, sah, nodes);
            bad++;
            continue;
        }
        l->used = 1;
        if (strcmp(l->hash, hex) != 0) {
            fprintf(stderr, "test_hashes: %s %s: the tree changed: sha256 %s, "
                    "the table (line %d) has %s; SAH %s -> %s, nodes %llu -> "
                    "%zu\n", se->name, configs[c].name, hex, l->lineno,
                    l->hash, l->sah, sah, l->nodes, nodes);
            bad++;
        } else if (strcmp(l->sah, sah) != 0 || l->nodes != nodes) {
            /* The same tree: only its measure moved.  Said, not failed. */
            fprintf(stderr, "test_hashes: %s %s: the same tree, but its SAH "
                    "reads %s (table %s), %zu nodes (table %llu)\n",
                    se->name, configs[c].name, sah, l->sah, nodes, l->nodes);
        }
    }
    fprintf(stderr, "test_hashes: %s (%zu triangles): %s\n", se->name,
            s.triangle_count, write_path ? "hashed" : bad ? "DIFFERS" : "same");
    scene_free(&s);
    ck_assert_msg(bad == 0, "%s: %d of %d trees differ from %s or have no "
                  "line there (details above); a deliberate change updates "
                  "the lines (see the file's header)", se->name, bad,
                  (int)NCONFIGS, table_path);
}
END_TEST

static int scene_known(const char *name)
{
    int i;
    for (i = 0; i < nscenes; i++)
        if (strcmp(scenes[i].name, name) == 0)
            return i;
    return -1;
}

/* Writes the comment lines of the current table, then written[], to
 * write_path through a temporary file beside it; NULL, or why not. */
static const char *write_table(void)
{
    static char why[4400];
    char tmp[4200], buf[1024];
    FILE *in, *out;
    int k, ok;
    if ((size_t)snprintf(tmp, sizeof tmp, "%s.tmp", write_path) >= sizeof tmp)
        return "ATRBVH_WRITE_HASHES: name too long";
    out = fopen(tmp, "w");
    if (!out) {
        snprintf(why, sizeof why, "%s: %s", tmp, strerror(errno));
        return why;
    }
    in = fopen(table_path, "r");
    if (!in)
        fprintf(stderr, "test_hashes: %s: %s; the table is written without "
                "its header\n", table_path, strerror(errno));
    while (in && fgets(buf, sizeof buf, in))
        if (buf[0] == '#')
            fputs(buf, out);
    if (in)
        fclose(in);
    for (k = 0; k < nwritten; k++)
        fprintf(out, "%s %s %s %s %llu\n", written[k].scene,
                written[k].config, written[k].hash, written[k].sah,
                written[k].nodes);
    ok = fflush(out) == 0 && !ferror(out);
    if (fclose(out) != 0)
        ok = 0;
    if (!ok) {
        snprintf(why, sizeof why, "%s: write error", tmp);
        remove(tmp); /* ours */
        return why;
    }
    if (rename(tmp, write_path) != 0) {
        snprintf(why, sizeof why, "%s -> %s: %s", tmp, write_path,
                 strerror(errno));
        remove(tmp);
        return why;
    }
    return NULL;
}

/* Every line of the table was compared, or belongs to a scene skipped
 * here (absent file, sanitizer); or, in the writing mode, the table is
 * written. */
START_TEST(table_complete)
{
    int k, stale = 0, skipped = 0;
    if (write_path) {
        const char *why;
        int scenes_run = 0;
        ck_assert_msg(sha256_ok, "SHA-256 failed its known answers: no "
                      "table written");
        for (k = 0; k < nscenes; k++)
            scenes_run += scenes[k].skip == NULL;
        ck_assert_msg(scenes_run == nscenes && nscenes > (int)NBUILTIN,
                      "ATRBVH_WRITE_HASHES wants every scene: set "
                      "ATRBVH_SCENES to the scene folder and do not set "
                      "ATRBVH_TEST_SANITIZER");
        /* A scene of the current table that is not here would lose its
         * lines: removing a scene is an edit by hand. */
        for (k = 0; k < nlines; k++)
            ck_assert_msg(scene_known(table[k].scene) >= 0,
                          "%s:%d: scene %s is not in $ATRBVH_SCENES: no "
                          "table written (remove its lines by hand if it "
                          "is gone for good)", table_path, table[k].lineno,
                          table[k].scene);
        ck_assert_msg(nwritten == nscenes * (int)NCONFIGS,
                      "%d of %d trees hashed (a scene failed above)",
                      nwritten, nscenes * (int)NCONFIGS);
        why = write_table();
        ck_assert_msg(why == NULL, "%s", why);
        fprintf(stderr, "test_hashes: wrote %d lines to %s (comments from "
                "%s)\n", nwritten, write_path, table_path);
        return;
    }
    for (k = 0; k < nlines; k++) {
        int i;
        if (table[k].used)
            continue;
        i = scene_known(table[k].scene);
        if (i >= 0 && scenes[i].skip) {
            skipped++;
            continue;
        }
        if (i < 0 && strncmp(table[k].scene, "builtin:", 8) != 0) {
            /* a real scene whose file is not here: said once per scene */
            if (k == 0 || strcmp(table[k - 1].scene, table[k].scene) != 0)
                fprintf(stderr, "test_hashes: %s skipped: no %s.ply in "
                        "$ATRBVH_SCENES\n", table[k].scene, table[k].scene);
            skipped++;
            continue;
        }
        fprintf(stderr, "test_hashes: %s:%d: %s %s: no such %s here (a "
                "stale line)\n", table_path, table[k].lineno, table[k].scene,
                table[k].config, i < 0 ? "scene" : "configuration");
        stale++;
    }
    if (skipped)
        fprintf(stderr, "test_hashes: %d lines of %s not checked: their "
                "scenes are skipped or absent\n", skipped, table_path);
    ck_assert_msg(stale == 0, "%d lines of %s name a scene or configuration "
                  "this test does not build", stale, table_path);
}
END_TEST

/* ------------------------------------------------------------- setup */
static void add_scene(const char *name, const char *spec, const char *skip)
{
    scene_entry *e;
    if (nscenes == MAX_SCENES)
        return;
    e = &scenes[nscenes++];
    snprintf(e->name, sizeof e->name, "%s", name);
    snprintf(e->spec, sizeof e->spec, "%s", spec);
    e->skip = skip;
}

static void find_scenes(void)
{
    char *paths[MAX_SCENES];
    size_t n, i, k;
    for (i = 0; i < NBUILTIN; i++)
        add_scene(builtin_scenes[i], builtin_scenes[i], NULL);
    n = tu_scene_paths(paths, MAX_SCENES - NBUILTIN);
    if (n == 0)
        fprintf(stderr, "test_hashes: no scenes in $ATRBVH_SCENES; the real "
                "scenes are skipped\n");
    for (i = 0; i < n; i++) {
        const char *base = strrchr(paths[i], '/');
        char name[256];
        const char *skip = NULL;
        size_t l;
        base = base ? base + 1 : paths[i];
        snprintf(name, sizeof name, "%s", base);
        l = strlen(name);
        if (l > 4 && strcmp(name + l - 4, ".ply") == 0)
            name[l - 4] = '\0';
        if (sanitizer_run())
            for (k = 0; k < sizeof sanitizer_skip / sizeof *sanitizer_skip;
                 k++)
                if (strcmp(name, sanitizer_skip[k]) == 0)
                    skip = "a large scene, left out under the sanitizers";
        add_scene(name, paths[i], skip);
    }
    tu_free_paths(paths, n);
}

/* The table was read (in main, before the scenes run). */
START_TEST(read_table)
{
    ck_assert_msg(table_error[0] == '\0', "%s", table_error);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hashes");
    TCase *tc = tcase_create("hashes");
    SRunner *sr;
    const char *src = getenv("ATRBVH_SRCDIR");
    int failed;
    write_path = getenv("ATRBVH_WRITE_HASHES");
    if (write_path && !*write_path)
        write_path = NULL;
    snprintf(table_path, sizeof table_path, "%s/%s",
             src && *src ? src : ".", HASH_FILE);
    find_scenes();
    /* Writing keeps only the current table's comments: a table that cannot
     * be read is no error then. */
    if (load_table() != 0 && write_path)
        table_error[0] = '\0';
    /* The tests share the table and the marks of the lines compared, so
     * they run in order in this process, whatever CK_FORK says. */
    tcase_set_timeout(tc, 1800);
    tcase_add_test(tc, sha256_known_answers);
    tcase_add_test(tc, read_table);
    tcase_add_loop_test(tc, tree_hashes, 0, nscenes);
    tcase_add_test(tc, table_complete);
    suite_add_tcase(s, tc);
    sr = srunner_create(s);
    srunner_set_fork_status(sr, CK_NOFORK);
    srunner_run_all(sr, CK_NORMAL);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
