/*
 * test_io.c - the atrbvh(5) file format: save, load and compare.
 *
 *  - Round trips through memory and files are identical bit for bit, and
 *    the bytes follow the documented layout (parsed here independently,
 *    with an independent CRC-32).
 *  - Single-byte corruption: with the stale checksum always rejected; with
 *    the checksum fixed up, either rejected or loaded into a BVH that
 *    differs (compare, or the stats the header carries); never a crash,
 *    never an allocation larger than the data.
 *  - Truncation at every length and trailing bytes rejected.
 *  - Huge declared counts rejected without a large allocation (a counting
 *    allocator records the largest request).
 *  - compare names the first difference.
 *  - A hand-made tree 1000 levels deep loads, and rays through it (the
 *    traversal's stack overflows into its fallback) give the same hits as
 *    the library's own build of the same triangles.
 *  - Nothing is lost (atrbvh_save): a failing write (full file system: a
 *    64 KiB tmpfs when root, RLIMIT_FSIZE for any user; a private copy of
 *    /dev/full; a symbolic link to /dev/full or /dev/stdout; a failing
 *    allocation) leaves the existing target byte for byte and no temporary
 *    file; devices, FIFOs and links to them are written in place and never
 *    removed; a link to a regular file stays a link; the replaced file
 *    keeps its mode.
 */
#define _GNU_SOURCE /* mkdtemp, mknod, mount, setrlimit */
#include <check.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/mount.h>
#endif

#include "testutil.h"

/* ------------------------------------------------- counting allocator */
/* Loading never allocates more than the data's size in one piece, except
 * for the fixed-size BVH object itself (a few hundred bytes), which can
 * exceed the smallest files. */
#define ALLOC_BOUND(n) ((n) > 512 ? (n) : 512)
static void counting_on(void)
{
    tu_count_reset(-1);
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
}

static void counting_off(void)
{
    atrbvh_set_allocator(NULL, NULL);
}

/* ----------------------------------------- independent format helpers */
static uint64_t rd64(const unsigned char *p)
{
    return tu_rd32(p) | (uint64_t)tu_rd32(p + 4) << 32;
}

static void wr64(unsigned char *p, uint64_t v)
{
    tu_wr32(p, (uint32_t)v);
    tu_wr32(p + 4, (uint32_t)(v >> 32));
}

/* ---------------------------------------------------------- builders */
static atrbvh_bvh *build_soup(size_t n, uint64_t seed, int collapse,
                              float **verts, atrbvh_geometry *g)
{
    atrbvh_build_options o;
    float *v = tu_random_triangles(n, seed, 4.0f, -1.0f);
    ck_assert_ptr_nonnull(v);
    *g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    o.collapse = collapse;
    o.threads = 2;
    *verts = v;
    return tu_build(g, &o);
}

static void save_mem(const atrbvh_bvh *b, unsigned char **d, size_t *n)
{
    void *p = NULL;
    atrbvh_error e;
    ck_assert_int_eq(atrbvh_save_memory(b, &p, n, &e), ATRBVH_OK);
    /* keep a malloc'd copy so that tests own it independently */
    *d = malloc(*n);
    ck_assert_ptr_nonnull(*d);
    memcpy(*d, p, *n);
    atrbvh_free(p);
}

static void same_stats(const atrbvh_bvh *a, const atrbvh_bvh *b)
{
    atrbvh_stats x, y;
    atrbvh_bvh_stats(a, &x);
    atrbvh_bvh_stats(b, &y);
    ck_assert_uint_eq(x.primitives, y.primitives);
    ck_assert_uint_eq(x.invalid_skipped, y.invalid_skipped);
    ck_assert_uint_eq(x.nodes, y.nodes);
    ck_assert_uint_eq(x.leaves, y.leaves);
    ck_assert_uint_eq(x.max_depth, y.max_depth);
    ck_assert_uint_eq(x.max_leaf_primitives, y.max_leaf_primitives);
    ck_assert(memcmp(&x.sah, &y.sah, sizeof x.sah) == 0);
    ck_assert(memcmp(&x.ci, &y.ci, sizeof x.ci) == 0);
    ck_assert(memcmp(&x.ct, &y.ct, sizeof x.ct) == 0);
    ck_assert_int_eq(x.method, y.method);
    ck_assert_uint_eq(x.treelet_size, y.treelet_size);
    ck_assert_uint_eq(x.rounds, y.rounds);
    ck_assert_int_eq(x.backend, y.backend);
}

/* ---------------------------------------------------------- round trip */
START_TEST(round_trip_memory)
{
    static const size_t sizes[] = {1, 2, 7, 100, 5000};
    size_t s;
    for (s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        int collapse;
        for (collapse = 0; collapse <= 1; collapse++) {
            float *v;
            atrbvh_geometry g;
            atrbvh_bvh *b = build_soup(sizes[s], 10 + s, collapse, &v, &g);
            atrbvh_bvh *l = NULL;
            unsigned char *d, *d2;
            size_t n, n2, nn, np, i;
            const atrbvh_node *nodes = atrbvh_bvh_nodes(b, &nn);
            const uint32_t *prims = atrbvh_bvh_primitive_indices(b, &np);
            atrbvh_error e;
            char msg[256];
            save_mem(b, &d, &n);
            /* the documented layout, read independently */
            ck_assert_uint_eq(n, 96 + 32 * nn + 4 * np + 4);
            ck_assert(memcmp(d, "ATRBVH\0\n", 8) == 0);
            ck_assert_uint_eq(tu_rd32(d + 8), 1);
            ck_assert_uint_eq(tu_rd32(d + 12), 96);
            ck_assert_uint_eq(tu_rd32(d + 16), 0);
            ck_assert_uint_eq(tu_rd32(d + 20), ATRBVH_METHOD_LBVH);
            ck_assert_uint_eq(rd64(d + 32), nn);
            ck_assert_uint_eq(rd64(d + 40), np);
            ck_assert_uint_eq(rd64(d + 48), sizes[s]);
            {
                /* the header's SAH: the tree's, which the build left to
                 * its first reader, here the save (lib/bvh.c) */
                atrbvh_stats st;
                uint64_t bits;
                ck_assert_int_eq(atrbvh_bvh_stats(b, &st), ATRBVH_OK);
                ck_assert(st.sah > 0.0);
                memcpy(&bits, &st.sah, sizeof bits);
                ck_assert_uint_eq(rd64(d + 72), bits);
            }
            ck_assert_uint_eq(tu_rd32(d + n - 4), tu_crc32(d, n - 4));
            for (i = 0; i < nn; i++) {
                const unsigned char *q = d + 96 + 32 * i;
                uint32_t bits;
                memcpy(&bits, &nodes[i].min[1], 4);
                ck_assert_uint_eq(tu_rd32(q + 4), bits);
                memcpy(&bits, &nodes[i].max[2], 4);
                ck_assert_uint_eq(tu_rd32(q + 20), bits);
                ck_assert_uint_eq(tu_rd32(q + 24), nodes[i].index);
                ck_assert_uint_eq(tu_rd32(q + 28), nodes[i].count);
            }
            for (i = 0; i < np; i++)
                ck_assert_uint_eq(tu_rd32(d + 96 + 32 * nn + 4 * i), prims[i]);
            /* load: identical, and saves to the same bytes */
            counting_on();
            ck_assert_int_eq(atrbvh_load_memory(d, n, &l, &e), ATRBVH_OK);
            ck_assert_uint_le(tu_alloc.largest, ALLOC_BOUND(n));
            counting_off();
            ck_assert_int_eq(atrbvh_compare(b, l, &e), 0);
            ck_assert_msg(tu_same_bvh(b, l, msg, sizeof msg), "%s", msg);
            ck_assert_msg(tu_check_bvh(l, &g, msg, sizeof msg), "%s", msg);
            same_stats(b, l);
            save_mem(l, &d2, &n2);
            ck_assert_uint_eq(n, n2);
            ck_assert(memcmp(d, d2, n) == 0);
            free(d);
            free(d2);
            atrbvh_bvh_free(l);
            atrbvh_bvh_free(b);
            free(v);
        }
    }
}
END_TEST

static void temp_path(char *buf, size_t len, const char *tag)
{
    const char *dir = getenv("ATRBVH_BUILDDIR");
    snprintf(buf, len, "%s/test_io_%s_%ld.bvh", dir && *dir ? dir : ".", tag,
             (long)getpid());
}

START_TEST(round_trip_file)
{
    float *v;
    atrbvh_geometry g;
    atrbvh_bvh *b = build_soup(3000, 3, 1, &v, &g), *l = NULL;
    char path[512];
    atrbvh_error e;
    unsigned char *d, *fd;
    size_t n, got;
    FILE *f;
    temp_path(path, sizeof path, "round");
    ck_assert_int_eq(atrbvh_save(b, path, &e), ATRBVH_OK);
    counting_on();
    ck_assert_int_eq(atrbvh_load(path, &l, &e), ATRBVH_OK);
    counting_off();
    ck_assert_int_eq(atrbvh_compare(b, l, &e), 0);
    same_stats(b, l);
    /* the file holds exactly save_memory's bytes */
    save_mem(b, &d, &n);
    ck_assert_uint_le(tu_alloc.largest, ALLOC_BOUND(n));
    fd = malloc(n + 16);
    f = fopen(path, "rb");
    ck_assert_ptr_nonnull(f);
    got = fread(fd, 1, n + 16, f);
    fclose(f);
    ck_assert_uint_eq(got, n);
    ck_assert(memcmp(fd, d, n) == 0);
    /* a truncated and an extended file are rejected */
    f = fopen(path, "wb");
    fwrite(d, 1, n - 1, f);
    fclose(f);
    atrbvh_bvh_free(l);
    ck_assert_int_eq(atrbvh_load(path, &l, &e), ATRBVH_ERR_FORMAT);
    ck_assert_ptr_null(l);
    ck_assert_msg(strstr(e.text, path) && strstr(e.text, "truncated"), "%s",
                  e.text);
    f = fopen(path, "wb");
    fwrite(d, 1, n, f);
    fwrite("x", 1, 1, f);
    fclose(f);
    ck_assert_int_eq(atrbvh_load(path, &l, &e), ATRBVH_ERR_FORMAT);
    f = fopen(path, "wb");
    fwrite(d, 1, 50, f);
    fclose(f);
    ck_assert_int_eq(atrbvh_load(path, &l, &e), ATRBVH_ERR_FORMAT);
    f = fopen(path, "wb");
    fclose(f);
    ck_assert_int_eq(atrbvh_load(path, &l, &e), ATRBVH_ERR_FORMAT);
    remove(path);
    /* I/O errors */
    ck_assert_int_eq(atrbvh_load(path, &l, &e), ATRBVH_ERR_IO);
    ck_assert_ptr_null(l);
    ck_assert_msg(strstr(e.text, path) != NULL, "%s", e.text);
    ck_assert_int_eq(atrbvh_save(b, "/nonexistent-dir/x/y.bvh", &e),
                     ATRBVH_ERR_IO);
    /* NULL arguments */
    ck_assert_int_eq(atrbvh_save(NULL, path, &e), ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_save(b, NULL, &e), ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_load(NULL, &l, &e), ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_load(path, NULL, &e), ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_save_memory(b, NULL, &n, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_load_memory(NULL, 10, &l, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_load_memory(NULL, 0, &l, &e), ATRBVH_ERR_FORMAT);
    ck_assert_int_eq(atrbvh_load_memory(d, n, NULL, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert(atrbvh_compare(NULL, b, &e) != 0);
    ck_assert_int_eq(e.status, ATRBVH_ERR_INVALID_ARGUMENT);
    free(d);
    free(fd);
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

/* ------------------------------------------------------------ corruption */
/* Loads `d` (n bytes) expecting rejection or a differing BVH; returns 1 when
 * it loaded. `off` is the corrupted byte. */
static int load_corrupt(const unsigned char *d, size_t n, size_t off,
                        const atrbvh_bvh *orig, int crc_fixed)
{
    atrbvh_bvh *l = NULL;
    atrbvh_error e;
    atrbvh_status s;
    counting_on();
    s = atrbvh_load_memory(d, n, &l, &e);
    ck_assert_msg(tu_alloc.largest <= ALLOC_BOUND(n),
                  "byte %zu: an allocation of %zu bytes for %zu bytes of data",
                  off, tu_alloc.largest, n);
    if (s != ATRBVH_OK) {
        counting_off();
        ck_assert_ptr_null(l);
        ck_assert_msg(tu_alloc.outstanding == 0, "byte %zu: %ld blocks leaked",
                      off, tu_alloc.outstanding);
        ck_assert_int_eq(e.status, s);
        ck_assert_msg(s == ATRBVH_ERR_FORMAT, "byte %zu: status %d (%s)", off,
                      (int)s, e.text);
        ck_assert(e.text[0] != '\0');
        return 0;
    }
    counting_off();
    ck_assert_msg(crc_fixed, "byte %zu: loaded despite a stale checksum", off);
    if (atrbvh_compare(orig, l, &e) == 0) {
        atrbvh_stats x, y;
        atrbvh_bvh_stats(orig, &x);
        atrbvh_bvh_stats(l, &y);
        /* the header fields compare does not look at must show in stats;
         * only the SAH field (informative: the loader measures the SAH)
         * may change unseen */
        ck_assert_msg(x.method != y.method ||
                          x.treelet_size != y.treelet_size ||
                          x.rounds != y.rounds || x.backend != y.backend ||
                          x.invalid_skipped != y.invalid_skipped ||
                          (off >= 72 && off < 80),
                      "byte %zu: corrupted, loaded, and no difference", off);
    }
    atrbvh_bvh_free(l);
    return 1;
}

START_TEST(single_byte_corruption)
{
    float *v;
    atrbvh_geometry g;
    atrbvh_bvh *b = build_soup(12, 5, 0, &v, &g);
    unsigned char *d, *c;
    size_t n, off, loaded = 0, rejected = 0;
    static const unsigned char masks[] = {0x01, 0x80, 0xff, 0x10};
    save_mem(b, &d, &n);
    c = malloc(n);
    for (off = 0; off < n; off++) {
        size_t m;
        /* header, the first nodes, the indices and the checksum byte by
         * byte; the rest of the body sampled */
        if (off >= 96 + 32 * 4 && off < n - 4 * 12 - 4 && off % 5 != 0)
            continue;
        for (m = 0; m < sizeof masks; m++) {
            memcpy(c, d, n);
            c[off] ^= masks[m];
            if (off < n - 4)
                load_corrupt(c, n, off, b, 0); /* stale checksum */
            if (off >= n - 4)
                continue; /* fixing the checksum would undo it */
            tu_fix_crc(c, n);
            if (load_corrupt(c, n, off, b, 1))
                loaded++;
            else
                rejected++;
        }
    }
    /* both outcomes occur: box values change and load, the rest does not */
    ck_assert(loaded > 0 && rejected > 0);
    free(c);
    free(d);
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

START_TEST(truncation)
{
    float *v;
    atrbvh_geometry g;
    atrbvh_bvh *b = build_soup(20, 6, 1, &v, &g), *l = NULL;
    unsigned char *d;
    size_t n, len;
    atrbvh_error e;
    save_mem(b, &d, &n);
    for (len = 0; len < n; len++) {
        unsigned char *t = malloc(len + 1);
        memcpy(t, d, len);
        counting_on();
        ck_assert_int_eq(atrbvh_load_memory(t, len, &l, &e),
                         ATRBVH_ERR_FORMAT);
        counting_off();
        ck_assert_uint_eq(tu_alloc.largest, 0);
        ck_assert_ptr_null(l);
        ck_assert_msg(strstr(e.text, "truncated") != NULL, "%zu: %s", len,
                      e.text);
        free(t);
    }
    {
        unsigned char *t = malloc(n + 1);
        memcpy(t, d, n);
        t[n] = 0;
        ck_assert_int_eq(atrbvh_load_memory(t, n + 1, &l, &e),
                         ATRBVH_ERR_FORMAT);
        free(t);
    }
    free(d);
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

START_TEST(huge_counts)
{
    float *v;
    atrbvh_geometry g;
    atrbvh_bvh *b = build_soup(30, 7, 1, &v, &g), *l = NULL;
    unsigned char *d, *c;
    size_t n, i;
    atrbvh_error e;
    static const uint64_t huge[] = {UINT64_MAX, (uint64_t)1 << 63,
                                    (uint64_t)1 << 40, (uint64_t)1 << 31,
                                    (uint64_t)1 << 30, 1000000, 0};
    save_mem(b, &d, &n);
    c = malloc(n);
    for (i = 0; i < sizeof huge / sizeof *huge; i++) {
        static const size_t fields[] = {32, 40, 48};
        size_t f;
        for (f = 0; f < 3; f++) {
            atrbvh_status s;
            memcpy(c, d, n);
            wr64(c + fields[f], huge[i]);
            tu_fix_crc(c, n);
            counting_on();
            s = atrbvh_load_memory(c, n, &l, &e);
            counting_off();
            ck_assert_msg(tu_alloc.largest <= ALLOC_BOUND(n),
                          "count %llu at byte %zu: allocated %zu",
                          (unsigned long long)huge[i], fields[f],
                          tu_alloc.largest);
            if (fields[f] == 48 && huge[i] <= ((uint64_t)1 << 30) &&
                huge[i] >= 30) {
                /* a large input count with few primitives kept is valid */
                ck_assert_msg(s == ATRBVH_OK, "%s", e.text);
                {
                    atrbvh_stats st;
                    atrbvh_bvh_stats(l, &st);
                    ck_assert_uint_eq(st.invalid_skipped, huge[i] - 30);
                }
                ck_assert_int_eq(atrbvh_compare(b, l, &e), 0);
                atrbvh_bvh_free(l);
                l = NULL;
            } else {
                ck_assert_int_eq(s, ATRBVH_ERR_FORMAT);
                ck_assert_ptr_null(l);
                ck_assert_msg(strstr(e.text, "byte") != NULL, "%s", e.text);
            }
        }
    }
    /* a checksum mismatch names itself */
    memcpy(c, d, n);
    c[n - 1] ^= 0x40;
    ck_assert_int_eq(atrbvh_load_memory(c, n, &l, &e), ATRBVH_ERR_FORMAT);
    ck_assert_msg(strstr(e.text, "checksum") != NULL, "%s", e.text);
    free(c);
    free(d);
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

/* Hand-edited files name the problem and its place. */
START_TEST(structural_errors)
{
    float *v;
    atrbvh_geometry g;
    atrbvh_bvh *b = build_soup(16, 8, 0, &v, &g), *l = NULL;
    unsigned char *d, *c;
    size_t n, nn, np;
    atrbvh_error e;
    const atrbvh_node *nodes = atrbvh_bvh_nodes(b, &nn);
    atrbvh_bvh_primitive_indices(b, &np);
    save_mem(b, &d, &n);
    c = malloc(n);
#define TRY(expect_word)                                                       \
    do {                                                                       \
        tu_fix_crc(c, n);                                                      \
        ck_assert_int_eq(atrbvh_load_memory(c, n, &l, &e), ATRBVH_ERR_FORMAT); \
        ck_assert_msg(strstr(e.text, (expect_word)) != NULL, "'%s' lacks '%s'", \
                      e.text, (expect_word));                                  \
    } while (0)
    ck_assert_uint_eq(nodes[0].count, 0);
    /* a treelet size or rounds no build of the method records (the
     * header's method at byte 20, size 24, rounds 28) */
    {
        static const struct {
            uint32_t method, size, rounds;
            const char *word;
        } bad[] = {{2, 2147483647u, 2, "byte 24: treelet size 2147483647"},
                   {2, 2, 2, "byte 24: treelet size 2 "},
                   {1, 0xffffffffu, 3, "byte 24: treelet size 4294967295"},
                   {1, 11, 3, "byte 24: treelet size 11"},
                   {0, 9, 0, "byte 24: treelet size 9"},
                   {0, 0, 2, "byte 28: 2 rounds"},
                   {2, 9, 0, "byte 28: 0 rounds"},
                   {2, 9, 0xffffffffu, "byte 28: 4294967295 rounds"},
                   {1, 7, 65, "byte 28: 65 rounds"}};
        static const uint32_t good[][3] = {
            {0, 0, 0}, {1, 3, 1}, {1, 10, 64}, {2, 128, 1},
            {2, 0xffffffffu, 4}};
        size_t k;
        for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
            memcpy(c, d, n);
            tu_wr32(c + 20, bad[k].method);
            tu_wr32(c + 24, bad[k].size);
            tu_wr32(c + 28, bad[k].rounds);
            TRY(bad[k].word);
        }
        for (k = 0; k < sizeof good / sizeof good[0]; k++) {
            atrbvh_stats st;
            memcpy(c, d, n);
            tu_wr32(c + 20, good[k][0]);
            tu_wr32(c + 24, good[k][1]);
            tu_wr32(c + 28, good[k][2]);
            tu_fix_crc(c, n);
            ck_assert_msg(atrbvh_load_memory(c, n, &l, &e) == ATRBVH_OK,
                          "method %u, size %u, %u rounds: %s", good[k][0],
                          good[k][1], good[k][2], e.text);
            ck_assert_int_eq(atrbvh_bvh_stats(l, &st), ATRBVH_OK);
            ck_assert_uint_eq(st.treelet_size, good[k][1]);
            ck_assert_uint_eq(st.rounds, good[k][2]);
            atrbvh_bvh_free(l);
            l = NULL;
        }
    }
    /* root's right child out of range */
    memcpy(c, d, n);
    tu_wr32(c + 96 + 24, 4000);
    TRY("node 0 at byte 96: right child 4000 out of range");
    /* right child pointing at the left child */
    memcpy(c, d, n);
    tu_wr32(c + 96 + 24, 1);
    TRY("right child 1 out of range");
    /* a leaf's range beyond the indices */
    {
        size_t i;
        for (i = 0; i < nn && nodes[i].count == 0; i++)
            ;
        memcpy(c, d, n);
        tu_wr32(c + 96 + 32 * i + 24, (uint32_t)np);
        TRY("beyond");
        memcpy(c, d, n);
        tu_wr32(c + 96 + 32 * i + 28, 0); /* the leaf becomes internal */
        TRY("out of range");
    }
    /* a duplicated primitive */
    memcpy(c, d, n);
    memcpy(c + 96 + 32 * nn + 4, c + 96 + 32 * nn, 4);
    TRY("referenced twice");
    /* an index beyond the input count */
    memcpy(c, d, n);
    tu_wr32(c + 96 + 32 * nn + 8, 16);
    TRY("primitive index 2 at byte");
    /* NaN and inverted boxes */
    memcpy(c, d, n);
    tu_wr32(c + 96 + 32 * 3 + 8, 0x7fc00000u);
    TRY("node 3 at byte 192: min[2] is not finite");
    memcpy(c, d, n);
    tu_wr32(c + 96 + 32 * 3 + 16, 0xff800000u);
    TRY("max[1] is not finite");
    memcpy(c, d, n);
    {
        float lo = 100.0f;
        uint32_t bits;
        memcpy(&bits, &lo, 4);
        tu_wr32(c + 96 + 32 * 2, bits);
    }
    TRY("node 2 at byte 160: min[0] 100 is above max[0]");
    /* header fields */
    memcpy(c, d, n);
    c[3] = 'X';
    TRY("magic");
    memcpy(c, d, n);
    tu_wr32(c + 8, 3);
    TRY("version 3");
    memcpy(c, d, n);
    tu_wr32(c + 8, 2); /* flags stay 0 */
    TRY("version 2 without the split flag");
    memcpy(c, d, n);
    tu_wr32(c + 16, 4);
    TRY("flags");
    memcpy(c, d, n);
    tu_wr32(c + 20, 3);
    TRY("method 3");
    memcpy(c, d, n);
    wr64(c + 32, 0);
    TRY("node count is 0");
    memcpy(c, d, n);
    wr64(c + 40, 0);
    TRY("primitive index count is 0");
    memcpy(c, d, n);
    wr64(c + 56, 0x7ff0000000000000ull);
    TRY("ci");
    memcpy(c, d, n);
    tu_wr32(c + 84, 1);
    TRY("reserved");
    free(c);
    free(d);
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

/* ------------------------------------------------------------- compare */
START_TEST(compare_names_difference)
{
    float *v, *v2;
    atrbvh_geometry g, g2;
    atrbvh_bvh *b = build_soup(20, 9, 0, &v, &g);
    atrbvh_bvh *b2 = build_soup(21, 9, 0, &v2, &g2), *l = NULL;
    unsigned char *d, *c;
    size_t n, nn;
    atrbvh_error e;
    const atrbvh_node *nodes = atrbvh_bvh_nodes(b, &nn);
    char want[128];
    save_mem(b, &d, &n);
    c = malloc(n);
    memset(&e, 0, sizeof e);
    ck_assert_int_ne(atrbvh_compare(b, b2, &e), 0);
    ck_assert_msg(strstr(e.text, "node count differs: 39 vs 41"), "%s",
                  e.text);
    /* a box value: node 5's max[1] grows */
    memcpy(c, d, n);
    {
        float f = nodes[5].max[1] + 0.5f;
        uint32_t bits;
        memcpy(&bits, &f, 4);
        tu_wr32(c + 96 + 32 * 5 + 16, bits);
        tu_fix_crc(c, n);
        ck_assert_int_eq(atrbvh_load_memory(c, n, &l, &e), ATRBVH_OK);
        ck_assert_int_ne(atrbvh_compare(b, l, &e), 0);
        snprintf(want, sizeof want, "node 5 differs: max[1] %.9g vs %.9g",
                 (double)nodes[5].max[1], (double)f);
        ck_assert_msg(strstr(e.text, want), "'%s' lacks '%s'", e.text, want);
        ck_assert_uint_eq(e.index, 5);
        atrbvh_bvh_free(l);
    }
    /* -0 vs +0 compare different (bits, not values) */
    {
        size_t i;
        int k, found = 0;
        for (i = 0; i < nn && !found; i++)
            for (k = 0; k < 3 && !found; k++)
                if (nodes[i].min[k] == 0.0f)
                    found = 1;
        (void)found; /* random data rarely has an exact zero; make one */
        memcpy(c, d, n);
        {
            /* 0x80000000 (-0) as node 0's min[0] only if it stays valid:
             * use ci instead, which is compared by bits too */
            double ci = 1.2000000000000002;
            uint64_t bits;
            memcpy(&bits, &ci, 8);
            wr64(c + 56, bits);
        }
        tu_fix_crc(c, n);
        ck_assert_int_eq(atrbvh_load_memory(c, n, &l, &e), ATRBVH_OK);
        ck_assert_int_ne(atrbvh_compare(b, l, &e), 0);
        ck_assert_msg(strstr(e.text, "ci differs"), "%s", e.text);
        atrbvh_bvh_free(l);
    }
    /* two primitive indices swapped: still a valid file */
    memcpy(c, d, n);
    {
        unsigned char t[4];
        unsigned char *p = c + 96 + 32 * nn;
        uint32_t a = tu_rd32(p + 4 * 7), z = tu_rd32(p + 4 * 9);
        memcpy(t, p + 4 * 7, 4);
        memcpy(p + 4 * 7, p + 4 * 9, 4);
        memcpy(p + 4 * 9, t, 4);
        tu_fix_crc(c, n);
        ck_assert_int_eq(atrbvh_load_memory(c, n, &l, &e), ATRBVH_OK);
        ck_assert_int_ne(atrbvh_compare(b, l, &e), 0);
        snprintf(want, sizeof want, "primitive index 7 differs: %u vs %u",
                 (unsigned)a, (unsigned)z);
        ck_assert_msg(strstr(e.text, want), "'%s' lacks '%s'", e.text, want);
        atrbvh_bvh_free(l);
    }
    /* identical */
    ck_assert_int_eq(atrbvh_load_memory(d, n, &l, &e), ATRBVH_OK);
    ck_assert_int_eq(atrbvh_compare(b, l, &e), 0);
    ck_assert_int_eq(atrbvh_compare(l, l, &e), 0);
    atrbvh_bvh_free(l);
    free(c);
    free(d);
    atrbvh_bvh_free(b);
    atrbvh_bvh_free(b2);
    free(v);
    free(v2);
}
END_TEST

/* ------------------------------------------------------- a deep tree */
/* Triangles 0..k (k+1 leaves), all around the same place so every box
 * overlaps: internal nodes 0..k-1 in a chain down the left, node k the
 * deepest leaf (triangle k), then the right leaves of nodes k-1 .. 0. */
START_TEST(deep_tree_traversal)
{
    const size_t k = 1000, leaves = k + 1;
    float *v = malloc(leaves * 9 * sizeof(float));
    atrbvh_geometry g;
    size_t n, i;
    unsigned char *d;
    atrbvh_bvh *deep = NULL, *ref;
    atrbvh_build_options o;
    atrbvh_error e;
    atrbvh_stats st;
    tu_rng r;
    size_t hits = 0;
    ck_assert(v);
    /* large random triangles in the unit cube: a ray through the middle
     * crosses about half the leaf boxes, more than the traversal stack
     * holds (its pushes happen on the way down the chain) */
    tu_rng_seed(&r, 17);
    for (i = 0; i < 9 * leaves; i++)
        v[i] = tu_rng_float(&r);
    g = atrbvh_geometry_triangles(v, 3 * leaves, NULL, leaves);
    d = tu_chain_bvh_bytes(v, leaves, &n);
    ck_assert(d);
    ck_assert_msg(atrbvh_load_memory(d, n, &deep, &e) == ATRBVH_OK, "%s",
                  e.text);
    atrbvh_bvh_stats(deep, &st);
    ck_assert_uint_eq(st.max_depth, k);
    ck_assert_uint_eq(st.leaves, leaves);
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    ref = tu_build(&g, &o);
    tu_rng_seed(&r, 23);
    for (i = 0; i < 3000; i++) {
        atrbvh_ray ray;
        atrbvh_hit h1, h2;
        int a, x1, x2;
        for (a = 0; a < 3; a++) {
            ray.origin[a] = -0.5f + 2.0f * tu_rng_float(&r);
            ray.dir[a] = 0.5f + 0.05f * (tu_rng_float(&r) - 0.5f) -
                         ray.origin[a];
        }
        ray.tmin = 0.0f;
        ray.tmax = INFINITY;
        x1 = atrbvh_intersect(deep, &g, &ray, &h1);
        x2 = atrbvh_intersect(ref, &g, &ray, &h2);
        ck_assert_int_eq(x1, x2);
        if (x1)
            ck_assert_msg(memcmp(&h1, &h2, sizeof h1) == 0,
                          "ray %zu: deep tree prim %u t %g, built tree prim "
                          "%u t %g",
                          i, h1.primitive, (double)h1.t, h2.primitive,
                          (double)h2.t);
        ck_assert_int_eq(atrbvh_occluded(deep, &g, &ray),
                         atrbvh_occluded(ref, &g, &ray));
        hits += (size_t)x1;
    }
    ck_assert(hits > 100);
    atrbvh_bvh_free(deep);
    atrbvh_bvh_free(ref);
    free(d);
    free(v);
}
END_TEST

/* ------------------------------------------------------- nothing lost */
static char *make_temp_dir(void)
{
    return tu_make_temp_dir("test_io_safe_");
}

/* A big BVH (over 64 KiB as a file) and a small one's file image. */
static atrbvh_bvh *big_and_small(float **v, unsigned char **small,
                                 size_t *small_n)
{
    atrbvh_geometry g, g2;
    float *v2;
    atrbvh_bvh *big = build_soup(4000, 21, 0, v, &g);
    atrbvh_bvh *b2 = build_soup(20, 22, 0, &v2, &g2);
    save_mem(b2, small, small_n);
    ck_assert_uint_lt(*small_n, 4096);
    atrbvh_bvh_free(b2);
    free(v2);
    return big;
}

START_TEST(save_full_disk_keeps_target)
{
    float *v;
    unsigned char *small, *bigimg;
    size_t small_n, big_n;
    atrbvh_bvh *big = big_and_small(&v, &small, &small_n);
    char *dir = make_temp_dir(), path[700], names[1024];
    atrbvh_error e;
    int mounted = 0;
    save_mem(big, &bigimg, &big_n);
    ck_assert_uint_gt(big_n, 64 * 1024);
#ifdef __linux__
    mounted = mount("tmpfs", dir, "tmpfs", 0, "size=64k") == 0;
#endif
    snprintf(path, sizeof path, "%s/scene.bvh", dir);
    tu_write_bytes(path, small, small_n);
    if (mounted) {
        /* a real full file system; unmounted before asserting, so that a
         * failure leaves no mount behind */
        atrbvh_status st = atrbvh_save(big, path, &e);
        int named = strstr(e.text, path) != NULL;
        int kept = tu_holds(path, small, small_n);
        tu_list_dir(dir, names, sizeof names);
        remove(path);
#ifdef __linux__
        ck_assert_int_eq(umount(dir), 0);
#endif
        ck_assert_int_eq(st, ATRBVH_ERR_IO);
        ck_assert_msg(named, "%s", e.text);
        ck_assert_msg(kept, "the existing file was lost or changed");
        ck_assert_str_eq(names, "scene.bvh ");
        tu_write_bytes(path, small, small_n);
    }
    {
        /* a file size limit (any user): writes past 32 KiB fail (EFBIG) */
        struct rlimit old, lim;
        void (*prev)(int) = signal(SIGXFSZ, SIG_IGN);
        ck_assert_int_eq(getrlimit(RLIMIT_FSIZE, &old), 0);
        lim = old;
        lim.rlim_cur = 32 * 1024;
        ck_assert_int_eq(setrlimit(RLIMIT_FSIZE, &lim), 0);
        ck_assert_int_eq(atrbvh_save(big, path, &e), ATRBVH_ERR_IO);
        ck_assert_int_eq(setrlimit(RLIMIT_FSIZE, &old), 0);
        signal(SIGXFSZ, prev);
        ck_assert_msg(strstr(e.text, path) != NULL, "%s", e.text);
        ck_assert_msg(tu_holds(path, small, small_n),
                      "the existing file was lost or changed");
        tu_list_dir(dir, names, sizeof names);
        ck_assert_str_eq(names, "scene.bvh ");
    }
    remove(path);
    /* with room, the same save replaces the file whole */
    tu_write_bytes(path, small, small_n);
    ck_assert_int_eq(chmod(path, 0640), 0);
    ck_assert_int_eq(atrbvh_save(big, path, &e), ATRBVH_OK);
    ck_assert(tu_holds(path, bigimg, big_n));
    {
        struct stat st;
        ck_assert_int_eq(stat(path, &st), 0);
        ck_assert_uint_eq(st.st_mode & 07777, 0640); /* mode kept */
    }
    tu_list_dir(dir, names, sizeof names);
    ck_assert_str_eq(names, "scene.bvh ");
    remove(path);
    ck_assert_int_eq(rmdir(dir), 0);
    atrbvh_bvh_free(big);
    free(small);
    free(bigimg);
    free(dir);
    free(v);
}
END_TEST

START_TEST(save_devices_never_removed)
{
    float *v;
    unsigned char *small;
    size_t small_n;
    atrbvh_bvh *big = big_and_small(&v, &small, &small_n);
    char *dir = make_temp_dir(), path[700], link[700], names[1024];
    atrbvh_error e;
    struct stat st;
    /* (a system without /dev/full or /dev/stdout skips those parts) */
    int have_full = stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode);
    int have_stdout = lstat("/dev/stdout", &st) == 0;
    if (!have_full || !have_stdout)
        fprintf(stderr, "save_devices_never_removed: no /dev/%s: skipped "
                "in part\n", have_full ? "stdout" : "full");
    /* a symbolic link to /dev/full (any user): the write fails, the link
     * and the device stay */
    snprintf(link, sizeof link, "%s/full-link", dir);
    if (have_full) {
    ck_assert_int_eq(symlink("/dev/full", link), 0);
    ck_assert_int_eq(atrbvh_save(big, link, &e), ATRBVH_ERR_IO);
    ck_assert_msg(strstr(e.text, link) != NULL, "%s", e.text);
    ck_assert_int_eq(lstat(link, &st), 0);
    ck_assert(S_ISLNK(st.st_mode));
    ck_assert_int_eq(stat("/dev/full", &st), 0);
    ck_assert(S_ISCHR(st.st_mode));
    remove(link);
    /* a private device node (root only): a copy of /dev/full */
    snprintf(path, sizeof path, "%s/full-node", dir);
    if (mknod(path, S_IFCHR | 0600, st.st_rdev) == 0) {
        ck_assert_int_eq(atrbvh_save(big, path, &e), ATRBVH_ERR_IO);
        ck_assert_int_eq(lstat(path, &st), 0);
        ck_assert_msg(S_ISCHR(st.st_mode), "the device node was replaced");
        remove(path);
    }
    }
    /* a symbolic link to /dev/stdout, stdout being /dev/full: it fails and
     * the link stays */
    if (have_full && have_stdout) {
        int saved = dup(1), full = open("/dev/full", O_WRONLY);
        ck_assert_int_ge(saved, 0);
        ck_assert_int_ge(full, 0);
        snprintf(link, sizeof link, "%s/stdout-link", dir);
        ck_assert_int_eq(symlink("/dev/stdout", link), 0);
        fflush(stdout);
        ck_assert_int_eq(dup2(full, 1), 1);
        ck_assert_int_eq(atrbvh_save(big, link, &e), ATRBVH_ERR_IO);
        ck_assert_int_eq(dup2(saved, 1), 1);
        close(saved);
        close(full);
        ck_assert_int_eq(lstat(link, &st), 0);
        ck_assert(S_ISLNK(st.st_mode));
        ck_assert_int_eq(lstat("/dev/stdout", &st), 0);
    }
    /* ... stdout being a regular file the caller opened: written in place
     * (appended after what is there), the file and link stay */
    if (have_stdout) {
        int saved = dup(1), fd;
        unsigned char *img;
        size_t n;
        snprintf(path, sizeof path, "%s/stdout.txt", dir);
        fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ck_assert_int_ge(fd, 0);
        ck_assert_int_eq(write(fd, "head", 4), 4);
        fflush(stdout);
        ck_assert_int_eq(dup2(fd, 1), 1);
        ck_assert_int_eq(atrbvh_save(big, link, &e), ATRBVH_OK);
        ck_assert_int_eq(dup2(saved, 1), 1);
        close(saved);
        close(fd);
        save_mem(big, &img, &n);
        img = realloc(img, n + 4);
        memmove(img + 4, img, n);
        memcpy(img, "head", 4);
        ck_assert_msg(tu_holds(path, img, n + 4),
                      "not written in place after the existing bytes");
        free(img);
        remove(path);
        remove(link);
    }
    /* a FIFO: written in place, still a FIFO */
    snprintf(path, sizeof path, "%s/fifo", dir);
    ck_assert_int_eq(mkfifo(path, 0600), 0);
    {
        int rd = open(path, O_RDONLY | O_NONBLOCK);
        atrbvh_geometry g;
        float *v3;
        atrbvh_bvh *tiny = build_soup(20, 22, 0, &v3, &g);
        unsigned char *img, buf[8192];
        size_t n;
        ck_assert_int_ge(rd, 0);
        save_mem(tiny, &img, &n);
        ck_assert_uint_lt(n, sizeof buf);
        ck_assert_int_eq(atrbvh_save(tiny, path, &e), ATRBVH_OK);
        ck_assert_int_eq(read(rd, buf, sizeof buf), (ssize_t)n);
        ck_assert(memcmp(buf, img, n) == 0);
        close(rd);
        ck_assert_int_eq(lstat(path, &st), 0);
        ck_assert(S_ISFIFO(st.st_mode));
        remove(path);
        atrbvh_bvh_free(tiny);
        free(img);
        free(v3);
    }
    /* a directory is refused and stays */
    snprintf(path, sizeof path, "%s/sub", dir);
    ck_assert_int_eq(mkdir(path, 0700), 0);
    ck_assert_int_eq(atrbvh_save(big, path, &e), ATRBVH_ERR_IO);
    ck_assert_int_eq(rmdir(path), 0);
    tu_list_dir(dir, names, sizeof names);
    ck_assert_str_eq(names, "");
    ck_assert_int_eq(rmdir(dir), 0);
    atrbvh_bvh_free(big);
    free(small);
    free(dir);
    free(v);
}
END_TEST

/* Paths that cannot be written (lib/atomicfile.c's resolve): an empty
 * path, a loop of symbolic links, a link to itself, a path through a
 * regular file, a link whose target lies through one, a link into a
 * folder that does not exist.  Each is refused with ATRBVH_ERR_IO, a
 * text naming the path and the system's reason, and leaves the folder
 * as it was: the same names, the links pointing where they did, the
 * file's bytes, and no temporary file. */
START_TEST(save_unwritable_paths)
{
    static const struct {
        const char *name; /* under the folder; "" the empty path */
        int err;
    } cases[] = {{"", ENOENT},          {"loop-a", ELOOP},
                 {"self", ELOOP},       {"file/x", ENOTDIR},
                 {"through-file", ENOTDIR}, {"into-nothing", ENOENT}};
    static const char *const links[][2] = {
        {"loop-a", "loop-b"}, {"loop-b", "loop-a"}, {"self", "self"},
        {"through-file", "file/x"}, {"into-nothing", "none/x"}};
    static const unsigned char bytes[] = "not a BVH, keep me\n";
    float *v;
    unsigned char *small;
    size_t small_n, k;
    atrbvh_bvh *big = big_and_small(&v, &small, &small_n);
    char *dir = make_temp_dir(), path[700], before[1024], after[1024];
    atrbvh_error e;
    snprintf(path, sizeof path, "%s/file", dir);
    tu_write_bytes(path, bytes, sizeof bytes);
    for (k = 0; k < sizeof links / sizeof links[0]; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, links[k][0]);
        ck_assert_int_eq(symlink(links[k][1], path), 0);
    }
    tu_list_dir(dir, before, sizeof before);
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        size_t j;
        if (*cases[k].name)
            snprintf(path, sizeof path, "%s/%s", dir, cases[k].name);
        else
            path[0] = '\0';
        memset(&e, 0, sizeof e);
        ck_assert_int_eq(atrbvh_save(big, path, &e), ATRBVH_ERR_IO);
        ck_assert_msg(e.status == ATRBVH_ERR_IO &&
                          strstr(e.text, strerror(cases[k].err)) &&
                          (!*path || strstr(e.text, path)),
                      "%s: \"%s\" (expected the path and \"%s\")",
                      cases[k].name, e.text, strerror(cases[k].err));
        tu_list_dir(dir, after, sizeof after);
        ck_assert_msg(!strcmp(before, after), "%s: the folder held \"%s\", "
                      "now \"%s\"", cases[k].name, before, after);
        for (j = 0; j < sizeof links / sizeof links[0]; j++) {
            char got[64];
            ssize_t n;
            snprintf(path, sizeof path, "%s/%s", dir, links[j][0]);
            n = readlink(path, got, sizeof got - 1);
            ck_assert_int_ge(n, 0);
            got[n] = '\0';
            ck_assert_str_eq(got, links[j][1]);
        }
        snprintf(path, sizeof path, "%s/file", dir);
        ck_assert(tu_holds(path, bytes, sizeof bytes));
    }
    for (k = 0; k < sizeof links / sizeof links[0]; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, links[k][0]);
        ck_assert_int_eq(remove(path), 0);
    }
    snprintf(path, sizeof path, "%s/file", dir);
    ck_assert_int_eq(remove(path), 0);
    ck_assert_int_eq(rmdir(dir), 0);
    atrbvh_bvh_free(big);
    free(small);
    free(dir);
    free(v);
}
END_TEST

/* Allocation k fails: whatever the outcome, the target holds either its
 * old bytes or the new ones, and no temporary file is left. */
static long fail_at, alloc_count;
static void *failing_malloc(size_t n)
{
    if (alloc_count++ == fail_at)
        return NULL;
    return malloc(n);
}

START_TEST(save_allocation_failures)
{
    float *v;
    unsigned char *small, *bigimg;
    size_t small_n, big_n;
    atrbvh_bvh *big = big_and_small(&v, &small, &small_n);
    char *dir = make_temp_dir(), path[700], link[700], names[1024];
    atrbvh_error e;
    atrbvh_status s = ATRBVH_ERR_NOMEM;
    save_mem(big, &bigimg, &big_n);
    snprintf(path, sizeof path, "%s/t.bvh", dir);
    snprintf(link, sizeof link, "%s/link.bvh", dir);
    ck_assert_int_eq(symlink("t.bvh", link), 0);
    for (fail_at = 0;; fail_at++) {
        tu_write_bytes(path, small, small_n);
        alloc_count = 0;
        atrbvh_set_allocator(failing_malloc, free);
        s = atrbvh_save(big, link, &e);
        atrbvh_set_allocator(NULL, NULL);
        ck_assert_msg(s == ATRBVH_OK || s == ATRBVH_ERR_NOMEM,
                      "allocation %ld failing: %d %s", fail_at, (int)s,
                      e.text);
        ck_assert(tu_holds(path, s == ATRBVH_OK ? bigimg : small,
                        s == ATRBVH_OK ? big_n : small_n));
        tu_list_dir(dir, names, sizeof names);
        ck_assert_msg(!strcmp(names, "t.bvh link.bvh ") ||
                          !strcmp(names, "link.bvh t.bvh "),
                      "after allocation %ld failed: %s", fail_at, names);
        if (alloc_count <= fail_at) { /* none failed: done */
            ck_assert_int_eq(s, ATRBVH_OK);
            break;
        }
        ck_assert_int_lt(fail_at, 100);
    }
    remove(link);
    remove(path);
    ck_assert_int_eq(rmdir(dir), 0);
    atrbvh_bvh_free(big);
    free(small);
    free(bigimg);
    free(dir);
    free(v);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("io");
    TCase *t = tcase_create("round trip");
    tcase_add_test(t, round_trip_memory);
    tcase_add_test(t, round_trip_file);
    tcase_add_test(t, compare_names_difference);
    tcase_set_timeout(t, 120);
    suite_add_tcase(s, t);
    t = tcase_create("hostile");
    tcase_add_test(t, single_byte_corruption);
    tcase_add_test(t, truncation);
    tcase_add_test(t, huge_counts);
    tcase_add_test(t, structural_errors);
    tcase_set_timeout(t, 300);
    suite_add_tcase(s, t);
    t = tcase_create("nothing lost");
    tcase_add_test(t, save_full_disk_keeps_target);
    tcase_add_test(t, save_devices_never_removed);
    tcase_add_test(t, save_unwritable_paths);
    tcase_add_test(t, save_allocation_failures);
    tcase_set_timeout(t, 120);
    suite_add_tcase(s, t);
    t = tcase_create("deep");
    tcase_add_test(t, deep_tree_traversal);
    tcase_set_timeout(t, 120);
    suite_add_tcase(s, t);
    return s;
}

int main(void)
{
    return tu_run(suite());
}
