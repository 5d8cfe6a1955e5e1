/*
 * cli_stages.c - `atrbvh stages SCENE [build options] --dump DIR`: every
 * stage's output (and each optimise round's) as NumPy .npy files named
 * STAGE-ARRAY.npy, and manifest.json naming them with the options and the
 * host-computed constants (docs/stages.md, atrbvh-stages(7)).  Every file
 * goes through tools/outfile (a temporary file beside it); the temporary
 * files are flushed to disk only after the build succeeded, and renamed
 * into place only when all of them are, the manifest last, so a failed
 * run leaves DIR as it was; the other files of DIR are left alone.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"
#include "npy.h"
#include "outfile.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#define MAX_STAGES 80 /* 8 stages and at most ~32 optimise rounds */
#define MAX_ARRAYS 12
#define MAX_FILES (MAX_STAGES * MAX_ARRAYS)

typedef struct dumped_array {
    char name[32];
    atrbvh_dtype dtype;
    int ndim;
    size_t rows, cols;
} dumped_array;

typedef struct dumped_stage {
    char name[32];
    size_t count;
    dumped_array a[MAX_ARRAYS];
} dumped_stage;

typedef struct dump_state {
    const char *dir;
    dumped_stage stages[MAX_STAGES];
    size_t count;
    double morton[6]; /* lo, scale */
    int failed;       /* a file could not be written (message printed) */
    /* The written files, each still a temporary file: all of them are
     * renamed into place only once the build has succeeded and every one
     * is on disk, the manifest last (cli_out_commit_all), so a failed run
     * leaves DIR as it was.  One more for the manifest. */
    cli_out out[MAX_FILES + 1];
    size_t files;
} dump_state;

static int write_array(dump_state *s, const char *stage,
                       const atrbvh_array *a, int ndim)
{
    char name[96];
    char *path;
    cli_out *out = &s->out[s->files];
    FILE *f;
    if (s->files == MAX_FILES) {
        cli_error("%s: too many files to dump", s->dir);
        return -1;
    }
    snprintf(name, sizeof name, "%s-%s.npy", stage, a->name);
    path = cli_join(s->dir, name);
    if (!path) {
        cli_error("%s: out of memory", s->dir);
        return -1;
    }
    f = cli_out_open(path, out);
    if (!f) {
        free(path);
        return -1;
    }
    errno = 0;
    if (npy_write(f, a->dtype, ndim, a->rows, a->cols, a->data) != 0 ||
        fflush(f) != 0) {
        int why = errno ? errno : EIO;
        cli_out_abort(out);
        cli_error("%s: write failed: %s", path, strerror(why));
        free(path);
        return -1;
    }
    free(path);
    s->files++;
    return 0;
}

/* Puts every written file in place, the manifest last (0), or none of
 * them (-1, after the error line; a rename that fails part way puts the
 * files before it back: cli_out_commit_all). */
static int commit_all(dump_state *s)
{
    int rc = cli_out_commit_all(s->out, s->files);
    s->files = 0;
    return rc;
}

static void abort_all(dump_state *s)
{
    cli_out_abort_all(s->out, s->files);
    s->files = 0;
}

static int on_capture(const atrbvh_stage_output *o, void *user)
{
    dump_state *s = user;
    dumped_stage *d;
    size_t k;
    if (s->count == MAX_STAGES || o->array_count > MAX_ARRAYS) {
        cli_error("%s: too many stages or arrays to dump", s->dir);
        s->failed = 1;
        return 1;
    }
    d = &s->stages[s->count++];
    memset(d, 0, sizeof *d);
    snprintf(d->name, sizeof d->name, "%s", o->name);
    for (k = 0; k < o->array_count; k++) {
        const atrbvh_array *a = &o->arrays[k];
        dumped_array *e = &d->a[d->count++];
        atrbvh_dtype dt;
        size_t cols;
        int ndim;
        if (npy_array_schema(a->name, &dt, &ndim, &cols) != 0)
            ndim = a->cols == 1 ? 1 : 2;
        snprintf(e->name, sizeof e->name, "%s", a->name);
        e->dtype = a->dtype;
        e->ndim = ndim;
        e->rows = a->rows;
        e->cols = a->cols;
        if (strcmp(a->name, "morton_frame") == 0 &&
            a->dtype == ATRBVH_DTYPE_F64 && a->rows * a->cols == 6)
            memcpy(s->morton, a->data, sizeof s->morton);
        if (write_array(s, o->name, a, ndim) != 0) {
            s->failed = 1;
            return 1;
        }
    }
    return 0;
}

static void json_doubles(json_writer *w, const char *key, const double *v,
                         int n)
{
    int k;
    json_key(w, key);
    json_begin_array(w);
    for (k = 0; k < n; k++)
        json_double(w, v[k]);
    json_end_array(w);
}

/* Writes manifest.json into the last of s->out (put in place with the
 * rest by commit_all): 0, or -1 after the error line. */
static int write_manifest(dump_state *s, const cli_build_args *a,
                          const scene *sc, const atrbvh_stats *st)
{
    const atrbvh_build_options *o = &a->options;
    const unsigned gamma = st->method == ATRBVH_METHOD_LBVH
                               ? 0u
                           : o->gamma ? o->gamma
                           /* the adaptive size's crown starts at 9
                            * (atrbvh(3)) */
                           : st->treelet_size == ATRBVH_TREELET_AUTO
                               ? 9u
                               : st->treelet_size;
    char *path = cli_join(s->dir, "manifest.json");
    json_writer w;
    cli_out *out = &s->out[s->files]; /* (room for one more) */
    FILE *f;
    size_t i, k;
    if (!path) {
        cli_error("%s: out of memory", s->dir);
        return -1;
    }
    f = cli_out_open(path, out);
    if (!f) {
        free(path);
        return -1;
    }
    json_init(&w, f);
    json_begin_object(&w);
    json_kv_string(&w, "format", "atrbvh-stages");
    json_kv_uint(&w, "version", 1);
    json_kv_string(&w, "atrbvh_version", atrbvh_version_string());
    json_key(&w, "scene");
    json_begin_object(&w);
    json_kv_string(&w, "name", a->scene);
    json_kv_uint(&w, "triangles", sc->triangle_count);
    json_kv_uint(&w, "primitives", st->primitives);
    json_end_object(&w);
    /* what decides the tree (threads and backend do not: the dumps are
     * the same for any) */
    json_key(&w, "options");
    json_begin_object(&w);
    json_kv_string(&w, "method", cli_method_name(st->method));
    json_kv_uint(&w, "treelet_size", st->treelet_size);
    json_kv_uint(&w, "rounds", st->rounds);
    json_kv_uint(&w, "gamma", gamma);
    json_kv_double(&w, "ci", st->ci);
    json_kv_double(&w, "ct", st->ct);
    json_kv_bool(&w, "collapse", o->collapse != 0);
    json_kv_uint(&w, "max_leaf_size", o->max_leaf_size);
    json_kv_bool(&w, "skip_invalid", o->skip_invalid != 0);
    json_end_object(&w);
    json_key(&w, "constants");
    json_begin_object(&w);
    json_doubles(&w, "morton_lo", s->morton, 3);
    json_doubles(&w, "morton_scale", s->morton + 3, 3);
    json_kv_uint(&w, "morton_bits_per_axis", 21);
    json_kv_uint(&w, "key_bits", 63);
    json_kv_double(&w, "ci", st->ci);
    json_kv_double(&w, "ct", st->ct);
    json_kv_bool(&w, "collapse", o->collapse != 0);
    json_kv_uint(&w, "max_leaf_size", o->max_leaf_size);
    json_kv_uint(&w, "treelet_size", st->treelet_size);
    json_kv_uint(&w, "rounds", st->rounds);
    json_kv_uint(&w, "gamma", gamma);
    json_end_object(&w);
    json_key(&w, "stages");
    json_begin_array(&w);
    for (i = 0; i < s->count; i++) {
        const dumped_stage *d = &s->stages[i];
        json_begin_object(&w);
        json_kv_string(&w, "name", d->name);
        json_key(&w, "files");
        json_begin_array(&w);
        for (k = 0; k < d->count; k++) {
            const dumped_array *e = &d->a[k];
            char file[96];
            snprintf(file, sizeof file, "%s-%s.npy", d->name, e->name);
            json_begin_object(&w);
            json_kv_string(&w, "array", e->name);
            json_kv_string(&w, "file", file);
            json_kv_string(&w, "dtype", npy_descr(e->dtype));
            json_key(&w, "shape");
            json_begin_array(&w);
            json_uint(&w, e->rows);
            if (e->ndim == 2)
                json_uint(&w, e->cols);
            json_end_array(&w);
            json_end_object(&w);
        }
        json_end_array(&w);
        json_end_object(&w);
    }
    json_end_array(&w);
    json_end_object(&w);
    if (ferror(f)) {
        cli_out_abort(out);
        cli_error("%s: write failed", path);
        free(path);
        return -1;
    }
    free(path);
    s->files++;
    return 0;
}

/* DIR, created when missing (its parent must exist). */
static int make_dir(const char *dir)
{
    struct stat sb;
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        cli_error("%s: cannot create the directory: %s", dir,
                  strerror(errno));
        return -1;
    }
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)) {
        cli_error("%s: not a directory", dir);
        return -1;
    }
    return 0;
}

static void stages_help(FILE *f);

static const char *dump_dir;

static const cli_opt stage_opts[] = {
    {.name = "--dump", .kind = CLI_OPT_STRING, .arg = "DIR",
     .dest = &dump_dir,
     .help = "write the .npy files and manifest.json to DIR\n"
             "(created when missing; other files left alone)"},
    {.name = NULL}};

static void stages_help(FILE *f)
{
    cli_build_help(f,
                   "Usage: atrbvh stages SCENE --dump DIR [OPTIONS]\n"
                   "Build a BVH over SCENE and write every stage's output "
                   "(and each optimise\n"
                   "round's) to DIR as NumPy .npy files STAGE-ARRAY.npy, "
                   "with manifest.json\n"
                   "naming them, the options and the host-computed "
                   "constants.  The files are\n"
                   "the same for any thread count and backend.  See "
                   "atrbvh-stages(7).\n",
                   "Stages", stage_opts,
                   CLI_BUILD_CORE | CLI_BUILD_BACKEND | CLI_BUILD_DEVICE,
                   "0 success, 1 bad input or failure, 2 usage error");
}

int cli_stages(int argc, char **argv)
{
    cli_build_args a;
    dump_state *s = NULL;
    scene sc;
    atrbvh_geometry g;
    atrbvh_device *dev = NULL;
    atrbvh_bvh *bvh = NULL;
    atrbvh_build_options o;
    atrbvh_stats st;
    atrbvh_error e;
    atrbvh_status rs;
    char err[512], *probe;
    size_t files = 0;
    const char *why = NULL;
    int rc;

    rc = cli_help_or_version(argc, argv, stages_help);
    if (rc >= 0)
        return rc;
    dump_dir = NULL;
    cli_build_args_init(&a);
    rc = cli_build_parse("stages", argc, argv, stage_opts,
                         CLI_BUILD_CORE | CLI_BUILD_BACKEND |
                             CLI_BUILD_DEVICE,
                         &a);
    if (rc != CLI_OK)
        return rc;
    if (!dump_dir)
        return cli_usage("stages", "--dump DIR is required");
    if (make_dir(dump_dir) != 0)
        return CLI_FAIL;
    probe = cli_join(dump_dir, "manifest.json");
    if (!probe || cli_out_check(probe, &why) != 0) {
        cli_error("%s: %s", probe ? probe : dump_dir,
                  why ? why : "out of memory");
        free(probe);
        return CLI_FAIL;
    }
    free(probe);
    if (scene_load(a.scene, &sc, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_FAIL;
    }
    if (sc.triangle_count == 0) {
        cli_error("%s: the scene has no triangles", a.scene);
        scene_free(&sc);
        return CLI_FAIL;
    }
    s = calloc(1, sizeof *s);
    if (!s) {
        cli_error("out of memory");
        scene_free(&sc);
        return CLI_FAIL;
    }
    s->dir = dump_dir;
    g = scene_geometry(&sc);
    o = a.options;
    o.capture = on_capture;
    o.capture_user = s;
    o.progress = NULL;
    rc = CLI_OK;
    memset(&e, 0, sizeof e);
    if (o.backend == ATRBVH_BACKEND_OPENCL) {
        const char *name = o.opencl_device;
        char spec[512];
        snprintf(spec, sizeof spec, "opencl%s%s", name && *name ? ":" : "",
                 name && *name ? name : "");
        rs = atrbvh_device_open(spec, &dev, &e);
        if (rs != ATRBVH_OK) {
            rc = cli_bad_device(&a, rs, e.text)
                     ? cli_usage("stages", "--device: %s", e.text)
                     : (cli_error("%s", e.text[0] ? e.text
                                                  : atrbvh_strerror(rs)),
                        CLI_FAIL);
            goto done;
        }
        o.device = dev;
    }
    rs = atrbvh_build(&g, &o, &bvh, &e);
    if (rs != ATRBVH_OK) {
        bvh = NULL;
        if (!s->failed) /* else the file's error line is already out */
            cli_error("%s: %s", a.scene,
                      e.text[0] ? e.text : atrbvh_strerror(rs));
        rc = CLI_FAIL;
        goto done;
    }
    atrbvh_bvh_stats(bvh, &st);
    if (write_manifest(s, &a, &sc, &st) != 0 || commit_all(s) != 0) {
        rc = CLI_FAIL;
        goto done;
    }
    {
        size_t i;
        for (i = 0; i < s->count; i++)
            files += s->stages[i].count;
        printf("%zu stages, %zu files written to %s\n", s->count, files + 1,
               dump_dir);
    }
done:
    if (s)
        abort_all(s);
    atrbvh_bvh_free(bvh);
    atrbvh_device_close(dev);
    scene_free(&sc);
    free(s);
    return rc;
}
