/*
 * cli_build.c - `atrbvh build`, and the build options, loading, building
 * and reporting that `atrbvh trace` shares.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void cli_build_args_init(cli_build_args *a)
{
    memset(a, 0, sizeof *a);
    atrbvh_build_options_init(&a->options);
}

void cli_build_options_help(FILE *f)
{
    fputs("Build options:\n"
          "  --method lbvh|trbvh|atrbvh  construction method (default "
          "atrbvh)\n"
          "  --quality fast|balanced|high  a preset: LBVH, ATRBVH(9,2), "
          "ATRBVH(20,3)\n"
          "                       (later --method/--treelet/--rounds "
          "override it)\n"
          "  --treelet N          treelet size (default: trbvh 7, atrbvh 9)\n"
          "  --rounds R           optimisation rounds (default: trbvh 3, "
          "atrbvh 2)\n"
          "  --threads N          threads (default: all; 0 = OpenMP "
          "default)\n"
          "  --no-collapse        keep one primitive per leaf\n"
          "  --max-leaf N         at most N primitives per leaf (0 = no "
          "limit)\n"
          "  --ci X               SAH cost of an internal node (default "
          "1.2)\n"
          "  --ct X               SAH cost of a primitive (default 1.0)\n"
          "  --backend cpu|opencl compute backend (default cpu)\n"
          "  --device SPEC        OpenCL device: PLATFORM:DEVICE indices or a\n"
          "                       name substring (default $ATRBVH_OPENCL_DEVICE,\n"
          "                       else the first device)\n"
          "  --skip-invalid       leave out triangles with NaN or infinite\n"
          "                       coordinates (counted) instead of failing\n"
          "  -o, --output FILE    save the BVH to FILE (see atrbvh(5))\n"
          "  --json               print one JSON object\n",
          f);
}

int cli_build_option(const char *cmd, int argc, char **argv, int *i,
                     cli_build_args *a)
{
    const char *arg = argv[*i], *v;
    int r;
    unsigned long u;
    long l;
    double d;
    if (strcmp(arg, "--no-collapse") == 0) {
        a->options.collapse = 0;
        *i += 1;
        return 1;
    }
    if (strcmp(arg, "--skip-invalid") == 0) {
        a->options.skip_invalid = 1;
        *i += 1;
        return 1;
    }
    if (strcmp(arg, "--json") == 0) {
        a->json = 1;
        *i += 1;
        return 1;
    }
    if ((r = cli_option(cmd, argc, argv, i, "--method", &v)) != 0) {
        if (r < 0)
            return -1;
        if (strcmp(v, "lbvh") == 0)
            a->options.method = ATRBVH_METHOD_LBVH;
        else if (strcmp(v, "trbvh") == 0)
            a->options.method = ATRBVH_METHOD_TRBVH;
        else if (strcmp(v, "atrbvh") == 0)
            a->options.method = ATRBVH_METHOD_ATRBVH;
        else {
            cli_usage(cmd, "--method: '%s' is not lbvh, trbvh or atrbvh", v);
            return -1;
        }
        return 1;
    }
    if ((r = cli_option(cmd, argc, argv, i, "--quality", &v)) != 0) {
        atrbvh_method m;
        unsigned t, rr;
        if (r < 0)
            return -1;
        if (!cli_quality_preset(v, &m, &t, &rr)) {
            cli_usage(cmd, "--quality: '%s' is not fast, balanced or high",
                      v);
            return -1;
        }
        a->options.method = m;
        a->options.treelet_size = t;
        a->options.rounds = rr;
        return 1;
    }
    if ((r = cli_option(cmd, argc, argv, i, "--backend", &v)) != 0) {
        if (r < 0)
            return -1;
        if (strcmp(v, "cpu") == 0)
            a->options.backend = ATRBVH_BACKEND_CPU;
        else if (strcmp(v, "opencl") == 0)
            a->options.backend = ATRBVH_BACKEND_OPENCL;
        else {
            cli_usage(cmd, "--backend: '%s' is not cpu or opencl", v);
            return -1;
        }
        return 1;
    }
    if ((r = cli_option(cmd, argc, argv, i, "--device", &v)) != 0) {
        if (r < 0)
            return -1;
        a->options.opencl_device = v;
        return 1;
    }
    /* Values the tool can represent are passed on, and the library
     * judges the range (exit 1 with its message); what is not a number of
     * the right kind at all is a usage error here. */
    if ((r = cli_option(cmd, argc, argv, i, "--treelet", &v)) != 0) {
        if (r < 0)
            return -1;
        if (!cli_parse_ulong(v, UINT_MAX, &u)) {
            cli_usage(cmd, "--treelet: '%s' is not a whole number", v);
            return -1;
        }
        a->options.treelet_size = (unsigned)u;
        return 1;
    }
    if ((r = cli_option(cmd, argc, argv, i, "--rounds", &v)) != 0) {
        if (r < 0)
            return -1;
        if (!cli_parse_ulong(v, UINT_MAX, &u)) {
            cli_usage(cmd, "--rounds: '%s' is not a whole number", v);
            return -1;
        }
        a->options.rounds = (unsigned)u;
        return 1;
    }
    if ((r = cli_option(cmd, argc, argv, i, "--max-leaf", &v)) != 0) {
        if (r < 0)
            return -1;
        if (!cli_parse_ulong(v, UINT_MAX, &u)) {
            cli_usage(cmd, "--max-leaf: '%s' is not a whole number", v);
            return -1;
        }
        a->options.max_leaf_size = (unsigned)u;
        return 1;
    }
    if ((r = cli_option(cmd, argc, argv, i, "--threads", &v)) != 0) {
        if (r < 0)
            return -1;
        if (!cli_parse_long(v, INT_MIN, INT_MAX, &l)) {
            cli_usage(cmd, "--threads: '%s' is not a whole number", v);
            return -1;
        }
        a->options.threads = (int)l;
        return 1;
    }
    if ((r = cli_option(cmd, argc, argv, i, "--ci", &v)) != 0) {
        if (r < 0)
            return -1;
        if (!cli_parse_double(v, &d)) {
            cli_usage(cmd, "--ci: '%s' is not a number", v);
            return -1;
        }
        a->options.ci = d;
        return 1;
    }
    if ((r = cli_option(cmd, argc, argv, i, "--ct", &v)) != 0) {
        if (r < 0)
            return -1;
        if (!cli_parse_double(v, &d)) {
            cli_usage(cmd, "--ct: '%s' is not a number", v);
            return -1;
        }
        a->options.ct = d;
        return 1;
    }
    if ((r = cli_option(cmd, argc, argv, i, "--output", &v)) != 0 ||
        (r = cli_option(cmd, argc, argv, i, "-o", &v)) != 0) {
        if (r < 0)
            return -1;
        if (*v == '\0') {
            cli_usage(cmd, "--output: empty file name");
            return -1;
        }
        a->output = v;
        return 1;
    }
    return 0;
}

/* ------------------------------------------------------------ progress */
/* Shown only on a terminal, and only once a build has run for a while, so
 * short builds and logs stay clean. */
#define PROGRESS_AFTER_MS 1000.0

typedef struct progress {
    double start_ms;
    int shown;
} progress;

static int on_progress(const char *stage, double fraction, void *user)
{
    progress *p = user;
    if (!p->shown && cli_now_ms() - p->start_ms < PROGRESS_AFTER_MS)
        return 0;
    if (!(fraction >= 0.0))
        fraction = 0.0;
    if (fraction > 1.0)
        fraction = 1.0;
    fprintf(stderr, "\ratrbvh: building: %-10.10s %3d%%",
            stage ? stage : "", (int)(fraction * 100.0 + 0.5));
    fflush(stderr);
    p->shown = 1;
    return 0;
}

/* ----------------------------------------------------- load and build */
int cli_load_and_build(const cli_build_args *a, cli_built *b)
{
    char err[512];
    atrbvh_error e;
    atrbvh_build_options o = a->options;
    progress prog;
    double t0;
    atrbvh_status st;
    memset(b, 0, sizeof *b);
    t0 = cli_now_ms();
    if (scene_load(a->scene, &b->sc, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_FAIL;
    }
    b->load_ms = cli_now_ms() - t0;
    if (b->sc.triangle_count == 0) {
        cli_error("%s: the scene has no triangles", a->scene);
        return CLI_FAIL;
    }
    b->geometry = scene_geometry(&b->sc);
    if (o.backend == ATRBVH_BACKEND_OPENCL) {
        /* One device handle for the build and any ray batches after it;
         * the library reads no environment, the tool does. */
        const char *name = o.opencl_device ? o.opencl_device
                                           : getenv("ATRBVH_OPENCL_DEVICE");
        char spec[512];
        snprintf(spec, sizeof spec, "opencl%s%s", name && *name ? ":" : "",
                 name && *name ? name : "");
        memset(&e, 0, sizeof e);
        st = atrbvh_device_open(spec, &b->device, &e);
        if (st != ATRBVH_OK) {
            cli_error("%s", e.text[0] ? e.text : atrbvh_strerror(st));
            return CLI_FAIL;
        }
        o.device = b->device;
    }
    prog.start_ms = cli_now_ms();
    prog.shown = 0;
    if (isatty(STDERR_FILENO)) {
        o.progress = on_progress;
        o.progress_user = &prog;
    }
    memset(&e, 0, sizeof e);
    st = atrbvh_build(&b->geometry, &o, &b->bvh, &e);
    if (prog.shown)
        fprintf(stderr, "\r%40s\r", "");
    if (st != ATRBVH_OK) {
        b->bvh = NULL;
        cli_error("%s: %s", a->scene,
                  e.text[0] ? e.text : atrbvh_strerror(st));
        return CLI_FAIL;
    }
    atrbvh_bvh_stats(b->bvh, &b->stats);
    if (a->output) {
        memset(&e, 0, sizeof e);
        st = atrbvh_save(b->bvh, a->output, &e);
        if (st != ATRBVH_OK) {
            const char *text = e.text[0] ? e.text : atrbvh_strerror(st);
            /* Name the file once, whether or not the library did. */
            if (strstr(text, a->output))
                cli_error("%s", text);
            else
                cli_error("%s: %s", a->output, text);
            return CLI_FAIL;
        }
    }
    return CLI_OK;
}

void cli_built_free(cli_built *b)
{
    atrbvh_bvh_free(b->bvh);
    atrbvh_device_close(b->device);
    scene_free(&b->sc);
    memset(b, 0, sizeof *b);
}

/* -------------------------------------------------------------- output */
static const char *backend_name(atrbvh_backend be)
{
    return be == ATRBVH_BACKEND_OPENCL ? "opencl" : "cpu";
}

void cli_build_json(json_writer *w, const cli_build_args *a,
                    const cli_built *b)
{
    const atrbvh_stats *s = &b->stats;
    int k;
    json_kv_string(w, "scene", a->scene);
    json_kv_uint(w, "triangles", b->sc.triangle_count);
    json_kv_uint(w, "primitives", s->primitives);
    json_kv_uint(w, "invalid_skipped", s->invalid_skipped);
    json_kv_string(w, "method", cli_method_name(s->method));
    json_kv_uint(w, "treelet_size", s->treelet_size);
    json_kv_uint(w, "rounds", s->rounds);
    json_kv_string(w, "backend", backend_name(s->backend));
    json_kv_string(w, "device", atrbvh_bvh_device(b->bvh));
    json_kv_int(w, "threads", s->threads);
    json_kv_bool(w, "collapse", a->options.collapse != 0);
    json_kv_uint(w, "max_leaf_size", a->options.max_leaf_size);
    json_kv_double(w, "ci", s->ci);
    json_kv_double(w, "ct", s->ct);
    json_kv_double(w, "sah", s->sah);
    json_kv_uint(w, "nodes", s->nodes);
    json_kv_uint(w, "leaves", s->leaves);
    json_kv_uint(w, "max_depth", s->max_depth);
    json_kv_uint(w, "max_leaf_primitives", s->max_leaf_primitives);
    json_kv_double(w, "load_ms", b->load_ms);
    json_kv_double(w, "build_ms", s->build_ms);
    json_key(w, "stages_ms");
    json_begin_object(w);
    for (k = 0; k < ATRBVH_STAGE_COUNT; k++)
        json_kv_double(w, atrbvh_stage_name((atrbvh_stage)k),
                       atrbvh_bvh_stage_ms(b->bvh, (atrbvh_stage)k));
    json_end_object(w);
    if (s->backend == ATRBVH_BACKEND_OPENCL) {
        /* Device time per kernel (OpenCL profiling events, summed over
         * launches); stages_ms above are the stages' wall times. */
        const char *name;
        double ms;
        size_t i;
        json_key(w, "kernels_ms");
        json_begin_object(w);
        for (i = 0; atrbvh_bvh_kernel_time(b->bvh, i, &name, &ms); i++)
            json_kv_double(w, name, ms);
        json_end_object(w);
    }
    if (a->output)
        json_kv_string(w, "output", a->output);
}

void cli_build_text(FILE *f, const cli_build_args *a, const cli_built *b)
{
    const atrbvh_stats *s = &b->stats;
    int k;
    fprintf(f, "scene            %s\n", a->scene);
    fprintf(f, "triangles        %zu\n", b->sc.triangle_count);
    fprintf(f, "invalid skipped  %zu\n", s->invalid_skipped);
    fprintf(f, "method           %s", cli_method_name(s->method));
    if (s->method != ATRBVH_METHOD_LBVH)
        fprintf(f, " (treelet %u, %u rounds)", s->treelet_size, s->rounds);
    fputc('\n', f);
    if (s->backend == ATRBVH_BACKEND_OPENCL)
        fprintf(f, "backend          opencl, %s\n", atrbvh_bvh_device(b->bvh));
    else
        fprintf(f, "backend          %s, %d thread%s\n",
                backend_name(s->backend), s->threads,
                s->threads == 1 ? "" : "s");
    fprintf(f, "collapse         %s", a->options.collapse ? "yes" : "no");
    if (a->options.collapse && a->options.max_leaf_size)
        fprintf(f, " (at most %u per leaf)", a->options.max_leaf_size);
    fputc('\n', f);
    fprintf(f, "SAH              %.6g (ci %g, ct %g)\n", s->sah, s->ci, s->ct);
    fprintf(f, "nodes            %zu\n", s->nodes);
    fprintf(f, "leaves           %zu\n", s->leaves);
    fprintf(f, "max depth        %u\n", s->max_depth);
    fprintf(f, "largest leaf     %u\n", s->max_leaf_primitives);
    fprintf(f, "load             %.3f ms\n", b->load_ms);
    fprintf(f, "build            %.3f ms\n", s->build_ms);
    for (k = 0; k < ATRBVH_STAGE_COUNT; k++)
        fprintf(f, "  %-14s %.3f ms\n", atrbvh_stage_name((atrbvh_stage)k),
                atrbvh_bvh_stage_ms(b->bvh, (atrbvh_stage)k));
    if (a->output)
        fprintf(f, "saved to         %s\n", a->output);
}

/* ---------------------------------------------------------------- build */
static void build_help(FILE *f)
{
    fputs("Usage: atrbvh build SCENE [OPTIONS]\n"
          "Build a BVH over SCENE and print its statistics.\n"
          "SCENE: a .ply or .obj file, or builtin:NAME[:N] (NAME sphere, "
          "terrain or city;\n"
          "N roughly the triangle count, 1 to 50000000, default 100000).\n"
          "\n",
          f);
    cli_build_options_help(f);
    fputs("  -h, --help           this help\n"
          "  --version            the version\n"
          "\n"
          "Exit status: 0 success, 1 bad input or failure, 2 usage error.\n",
          f);
}

int cli_help_or_version(int argc, char **argv, void (*help)(FILE *))
{
    int i;
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--") == 0)
            break;
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            help(stdout);
            return CLI_OK;
        }
        if (strcmp(argv[i], "--version") == 0) {
            cli_print_version(stdout);
            return CLI_OK;
        }
    }
    return -1;
}

int cli_build(int argc, char **argv)
{
    cli_build_args a;
    cli_built b;
    int i = 1, rc, dashdash = 0;
    if ((rc = cli_help_or_version(argc, argv, build_help)) >= 0)
        return rc;
    cli_build_args_init(&a);
    while (i < argc) {
        const char *arg = argv[i];
        if (!dashdash && arg[0] == '-' && arg[1] != '\0') {
            int r;
            if (strcmp(arg, "--") == 0) {
                dashdash = 1;
                i++;
                continue;
            }
            r = cli_build_option("build", argc, argv, &i, &a);
            if (r < 0)
                return CLI_USAGE;
            if (r == 0)
                return cli_usage("build", "unknown option '%s'", arg);
            continue;
        }
        if (a.scene)
            return cli_usage("build", "more than one SCENE ('%s', '%s')",
                             a.scene, arg);
        a.scene = arg;
        i++;
    }
    if (!a.scene)
        return cli_usage("build", "no SCENE given");
    rc = cli_load_and_build(&a, &b);
    if (rc == CLI_OK) {
        if (a.json) {
            json_writer w;
            json_init(&w, stdout);
            json_begin_object(&w);
            cli_build_json(&w, &a, &b);
            json_end_object(&w);
        } else {
            cli_build_text(stdout, &a, &b);
        }
    }
    cli_built_free(&b);
    return rc;
}
