/*
 * cli_build.c - `atrbvh build`, and the build options, loading, building
 * and reporting that `atrbvh trace` shares.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"
#include "outfile.h"

#include <errno.h>
#include <pthread.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static const char *const method_names[] = {"lbvh", "trbvh", "atrbvh", NULL};
/* in the order of ATRBVH_SPLIT_TREE, ATRBVH_SPLIT_PRIORITY,
 * ATRBVH_SPLIT_SAH */
static const char *const split_rule_names[] = {"tree", "priority", "sah",
                                               NULL};
static const atrbvh_method method_values[] = {
    ATRBVH_METHOD_LBVH, ATRBVH_METHOD_TRBVH, ATRBVH_METHOD_ATRBVH};
static const char *const backend_names[] = {"cpu", "opencl", NULL};

void cli_build_args_init(cli_build_args *a)
{
    memset(a, 0, sizeof *a);
    atrbvh_build_options_init(&a->options);
    a->method = 2; /* atrbvh, the library's default */
    a->backend = 0;
}

/* The quality presets (atrbvh(1), --quality; docs/benchmarks.md has the
 * measurements they come from). */
int cli_quality_preset(const char *name, atrbvh_method *m, unsigned *treelet,
                       unsigned *rounds)
{
    if (strcmp(name, "fast") == 0) {
        *m = ATRBVH_METHOD_LBVH;
        *treelet = 0;
        *rounds = 0;
    } else if (strcmp(name, "balanced") == 0) {
        *m = ATRBVH_METHOD_ATRBVH;
        *treelet = 9;
        *rounds = 2;
    } else if (strcmp(name, "high") == 0) {
        *m = ATRBVH_METHOD_ATRBVH;
        *treelet = CLI_QUALITY_HIGH_TREELET;
        *rounds = CLI_QUALITY_HIGH_ROUNDS;
    } else {
        return 0;
    }
    return 1;
}

const char *cli_split_rule_name(int rule)
{
    return rule >= ATRBVH_SPLIT_TREE && rule <= ATRBVH_SPLIT_SAH
               ? split_rule_names[rule]
               : "";
}

const char *cli_treelet_text(unsigned size, char *buf)
{
    if (size == ATRBVH_TREELET_AUTO)
        return "auto";
    snprintf(buf, 16, "%u", size);
    return buf;
}

int cli_parse_treelet(const char *s, unsigned *out)
{
    unsigned long v;
    if (strcmp(s, "auto") == 0) {
        *out = ATRBVH_TREELET_AUTO;
        return 1;
    }
    if (!cli_parse_ulong(s, UINT_MAX - 1ul, &v))
        return 0;
    *out = (unsigned)v;
    return 1;
}

static int on_treelet(const char *cmd, const cli_opt *o, const char *v,
                      void *user)
{
    cli_build_args *a = o->dest;
    (void)user;
    if (!cli_parse_treelet(v, &a->options.treelet_size))
        return cli_usage(cmd, "--treelet: '%s' is not a whole number or "
                              "auto", v);
    a->tuned = 1;
    return 0;
}

static int on_rounds(const char *cmd, const cli_opt *o, const char *v,
                     void *user)
{
    cli_build_args *a = o->dest;
    unsigned long r;
    (void)user;
    if (!cli_parse_ulong(v, UINT_MAX, &r))
        return cli_usage(cmd, "--rounds: '%s' is not a whole number from 0 "
                              "to %u", v, UINT_MAX);
    a->options.rounds = (unsigned)r;
    a->tuned = 1;
    return 0;
}

static int on_quality(const char *cmd, const cli_opt *o, const char *v,
                      void *user)
{
    cli_build_args *a = o->dest;
    atrbvh_method m;
    unsigned t, r;
    int k;
    (void)user;
    if (!cli_quality_preset(v, &m, &t, &r))
        return cli_usage(cmd, "--quality: '%s' is not fast, balanced or high",
                         v);
    for (k = 0; method_names[k]; k++)
        if (method_values[k] == m)
            a->method = k;
    a->options.treelet_size = t;
    a->options.rounds = r;
    a->tuned = 0; /* (a preset's own sizes) */
    return 0;
}

void cli_build_opts(cli_build_args *a, unsigned groups, cli_opt *table)
{
    int n = 0;
    atrbvh_build_options *o = &a->options;
    if (groups & CLI_BUILD_CORE) {
        const cli_opt core[] = {
            {.name = "--method", .kind = CLI_OPT_ENUM, .dest = &a->method,
             .choices = method_names,
             .help = "construction method (default atrbvh)"},
            {.name = "--quality", .kind = CLI_OPT_CALL,
             .arg = "fast|balanced|high", .dest = a, .call = on_quality,
             .help = "a preset: LBVH, ATRBVH(9,2), ATRBVH(20,3)\n"
                     "(later --method/--treelet/--rounds override it)"},
            {.name = "--treelet", .kind = CLI_OPT_CALL, .arg = "N|auto",
             .dest = a, .call = on_treelet,
             .help = "treelet size (default: trbvh 7, atrbvh 9;\n"
                     "trbvh 3 to 10, atrbvh 3 to 128 or auto: 9, 16\n"
                     "or 32 per treelet by its subtree's size)"},
            {.name = "--rounds", .kind = CLI_OPT_CALL, .arg = "R",
             .dest = a, .call = on_rounds,
             .help = "optimisation rounds (default: trbvh 3, atrbvh 2,\n"
                     "atrbvh with --treelet auto 4)"},
            {.name = "--threads", .kind = CLI_OPT_INT, .arg = "N", .min = 0,
             .max = ATRBVH_MAX_THREADS, .dest = &o->threads,
             .help = "threads (default: all; 0 = OpenMP default)"},
            {.name = "--no-collapse", .kind = CLI_OPT_FLAG,
             .dest = &o->collapse, .flag_value = 0,
             .help = "keep one primitive per leaf"},
            {.name = "--max-leaf", .kind = CLI_OPT_UINT, .arg = "N", .min = 0,
             .max = UINT_MAX, .dest = &o->max_leaf_size,
             .help = "at most N primitives per leaf (0 = no limit)"},
            {.name = "--ci", .kind = CLI_OPT_DOUBLE, .arg = "X", .min = 0.0,
             .min_open = 1, .max = 1e30, .dest = &o->ci,
             .help = "SAH cost of an internal node (default 1.2)"},
            {.name = "--ct", .kind = CLI_OPT_DOUBLE, .arg = "X", .min = 0.0,
             .min_open = 1, .max = 1e30, .dest = &o->ct,
             .help = "SAH cost of a primitive (default 1.0)"},
            {.name = "--split", .kind = CLI_OPT_DOUBLE, .arg = "BUDGET",
             .min = 0.0, .max = 4.0, .dest = &o->split_budget,
             .help = "split the boxes of triangles that make the\n"
                     "nodes above them larger, at most BUDGET *\n"
                     "triangles extra references (e.g. 0.3; default 0:\n"
                     "off)"},
            {.name = "--split-rule", .kind = CLI_OPT_ENUM,
             .dest = &o->split_rule, .choices = split_rule_names,
             .help = "which triangles --split cuts: sah (top down\n"
                     "per grid cell, a cell's triangles judged\n"
                     "together; default), tree (where a first LBVH\n"
                     "says the cut pays) or priority (Karras-Aila)"},
            {.name = "--skip-invalid", .kind = CLI_OPT_FLAG,
             .dest = &o->skip_invalid, .flag_value = 1,
             .help = "leave out triangles with NaN or infinite\n"
                     "coordinates (counted) instead of failing"},
            {.name = "--quiet", .alias = "-q", .kind = CLI_OPT_FLAG,
             .dest = &a->quiet, .flag_value = 1,
             .help = "no progress on stderr (shown only on a\n"
                     "terminal, for work over a second)"},
        };
        size_t k;
        for (k = 0; k < sizeof core / sizeof core[0]; k++)
            table[n++] = core[k];
    }
    if (groups & CLI_BUILD_BACKEND) {
        const cli_opt be = {.name = "--backend", .kind = CLI_OPT_ENUM,
                            .dest = &a->backend, .choices = backend_names,
                            .help = "compute backend (default cpu)"};
        table[n++] = be;
    }
    if (groups & CLI_BUILD_DEVICE) {
        const cli_opt dev = {
            .name = "--device", .kind = CLI_OPT_STRING, .arg = "SPEC",
            .dest = &o->opencl_device, .seen = &a->device_given,
            .help = (groups & CLI_BUILD_BACKEND)
                        ? "OpenCL device (with --backend opencl):\n"
                          "PLATFORM:DEVICE indices or a name substring\n"
                          "(default $ATRBVH_OPENCL_DEVICE, else the first)"
                        : "OpenCL device: PLATFORM:DEVICE indices or a\n"
                          "name substring (default $ATRBVH_OPENCL_DEVICE,\n"
                          "else the first)"};
        table[n++] = dev;
    }
    if (groups & CLI_BUILD_OUTPUT) {
        const cli_opt out = {.name = "--output", .alias = "-o",
                             .kind = CLI_OPT_STRING, .arg = "FILE",
                             .dest = &a->output,
                             .help = "save the BVH to FILE (see atrbvh(5))"};
        table[n++] = out;
    }
    if (groups & CLI_BUILD_JSON) {
        const cli_opt js = {.name = "--json", .kind = CLI_OPT_FLAG,
                            .dest = &a->json, .flag_value = 1,
                            .help = "print one JSON object"};
        table[n++] = js;
    }
    memset(&table[n], 0, sizeof table[n]);
}

/* The words of the library's message that name each option. */
static const char *option_named(const char *text)
{
    static const struct {
        const char *word, *option;
    } words[] = {{"treelet size", "--treelet"}, {"rounds", "--rounds"},
                 {"gamma", "--treelet"},        {"ci ", "--ci"},
                 {"ct ", "--ct"},               {"threads", "--threads"},
                 {"max_leaf_size", "--max-leaf"},
                 {"split_budget", "--split"}};
    size_t k;
    for (k = 0; k < sizeof words / sizeof words[0]; k++)
        if (strstr(text, words[k].word))
            return words[k].option;
    return "options";
}

/* The library's own limits, asked before the scene is loaded: the same
 * options (on the CPU, one thread) over one triangle. */
static int check_with_library(const char *cmd, const cli_build_args *a)
{
    static const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    static const uint32_t idx[3] = {0, 1, 2};
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3, idx, 1);
    atrbvh_build_options o = a->options;
    atrbvh_bvh *bvh = NULL;
    atrbvh_error e;
    atrbvh_status st;
    o.backend = ATRBVH_BACKEND_CPU;
    o.opencl_device = NULL;
    o.threads = 1;
    o.progress = NULL;
    memset(&e, 0, sizeof e);
    st = atrbvh_build(&g, &o, &bvh, &e);
    atrbvh_bvh_free(bvh);
    if (st == ATRBVH_ERR_INVALID_ARGUMENT)
        return cli_usage(cmd, "%s: %s", option_named(e.text),
                         e.text[0] ? e.text : atrbvh_strerror(st));
    return 0;
}

int cli_build_parse(const char *cmd, int argc, char **argv,
                    const cli_opt *extra, unsigned groups, cli_build_args *a)
{
    static const cli_opt none[] = {{.name = NULL}};
    cli_opt table[CLI_BUILD_MAX_OPTS + 1];
    const cli_opt *tables[3];
    const char *pos[1];
    int n;
    cli_build_opts(a, groups, table);
    tables[0] = extra ? extra : none;
    tables[1] = table;
    tables[2] = NULL;
    if (cli_parse(cmd, argc, argv, tables, NULL, pos, 1, &n, "SCENE") != 0)
        return CLI_USAGE;
    if (n == 0)
        return cli_usage(cmd, "no SCENE given");
    a->scene = pos[0];
    a->cmd = cmd;
    a->options.method = method_values[a->method];
    if (a->tuned && a->options.method == ATRBVH_METHOD_LBVH)
        return cli_usage(cmd, "%s: lbvh takes no treelet size or rounds "
                              "(trbvh and atrbvh do)",
                         a->options.rounds && !a->options.treelet_size
                             ? "--rounds"
                             : "--treelet");
    a->options.backend =
        a->backend == 1 ? ATRBVH_BACKEND_OPENCL : ATRBVH_BACKEND_CPU;
    if ((groups & CLI_BUILD_BACKEND) && a->device_given &&
        a->options.backend != ATRBVH_BACKEND_OPENCL)
        return cli_usage(cmd, "--device needs --backend opencl");
    /* Device selection from the environment is the tool's business. */
    if ((groups & CLI_BUILD_DEVICE) && !a->options.opencl_device) {
        const char *env = getenv("ATRBVH_OPENCL_DEVICE");
        if (env && *env)
            a->options.opencl_device = env;
    }
    return check_with_library(cmd, a);
}

void cli_build_help(FILE *f, const char *intro, const char *title,
                    const cli_opt *extra, unsigned groups,
                    const char *exit_status)
{
    cli_build_args a;
    cli_opt table[CLI_BUILD_MAX_OPTS + 1];
    cli_build_args_init(&a);
    cli_build_opts(&a, groups, table);
    fputs(intro, f);
    if (extra && extra->name) {
        fprintf(f, "\n%s options:\n", title);
        cli_opts_help(f, extra);
    }
    fputs("\nBuild options:\n", f);
    cli_opts_help(f, table);
    cli_common_help(f, exit_status);
}

/* A device the library cannot find by --device (or
 * $ATRBVH_OPENCL_DEVICE) is a usage error naming the option, not a
 * failure of the scene.  1 when `st`/`text` is that. */
int cli_bad_device(const cli_build_args *a, atrbvh_status st,
                   const char *text)
{
    return st == ATRBVH_ERR_INVALID_ARGUMENT && a->options.opencl_device &&
           strstr(text, "device") != NULL;
}

/* ------------------------------------------------------------ progress */
/* Shown only on a terminal (and not with --quiet), and only once loading
 * or building has run for a second, so short runs and logs stay clean.
 * The library and the loader report work done (stage, fraction) from the
 * working thread; a drawing thread redraws the line every
 * PROGRESS_EVERY_MS with that and the seconds elapsed, so the line moves
 * even through a long stage that reports only at its start. */
#define PROGRESS_AFTER_MS 1000.0
#define PROGRESS_EVERY_MS 250

typedef struct progress {
    pthread_mutex_t lock;
    pthread_cond_t wake;
    pthread_t thread;
    int running, stop, shown;
    double start_ms;
    const char *what;  /* "loading", "building" */
    char stage[16];
    double fraction;
} progress;

/* The delay before the first line: PROGRESS_AFTER_MS, or
 * $ATRBVH_PROGRESS_AFTER_MS (the tests use 0). */
static double progress_after_ms(void)
{
    const char *v = getenv("ATRBVH_PROGRESS_AFTER_MS");
    char *end;
    double d;
    if (!v || !*v)
        return PROGRESS_AFTER_MS;
    d = strtod(v, &end);
    return *end == '\0' && d >= 0.0 ? d : PROGRESS_AFTER_MS;
}

/* Draws the line (the lock held). */
static void draw(progress *p)
{
    double f = p->fraction, now = cli_now_ms();
    if (now - p->start_ms < progress_after_ms())
        return;
    if (!(f >= 0.0))
        f = 0.0;
    if (f > 1.0)
        f = 1.0;
    fprintf(stderr, "\ratrbvh: %s: %-10.10s %3d%%  %.1f s ", p->what,
            p->stage, (int)(f * 100.0 + 0.5), (now - p->start_ms) / 1000.0);
    fflush(stderr);
    p->shown = 1;
}

static void *drawing(void *arg)
{
    progress *p = arg;
    pthread_mutex_lock(&p->lock);
    while (!p->stop) {
        struct timespec until;
        clock_gettime(CLOCK_REALTIME, &until);
        until.tv_nsec += (long)PROGRESS_EVERY_MS * 1000000L;
        if (until.tv_nsec >= 1000000000L) {
            until.tv_sec++;
            until.tv_nsec -= 1000000000L;
        }
        pthread_cond_timedwait(&p->wake, &p->lock, &until);
        if (!p->stop)
            draw(p);
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

/* Starts the display for `what` when stderr is a terminal and not quiet;
 * without a thread (none could be made) nothing is shown. */
static void begin_progress(progress *p, const char *what, int quiet)
{
    memset(p, 0, sizeof *p);
    p->start_ms = cli_now_ms();
    p->what = what;
    if (quiet || !isatty(STDERR_FILENO))
        return;
    if (pthread_mutex_init(&p->lock, NULL) != 0)
        return;
    if (pthread_cond_init(&p->wake, NULL) != 0) {
        pthread_mutex_destroy(&p->lock);
        return;
    }
    if (pthread_create(&p->thread, NULL, drawing, p) != 0) {
        pthread_cond_destroy(&p->wake);
        pthread_mutex_destroy(&p->lock);
        return;
    }
    p->running = 1;
}

static void report(progress *p, const char *stage, double fraction)
{
    if (!p->running)
        return;
    pthread_mutex_lock(&p->lock);
    snprintf(p->stage, sizeof p->stage, "%s", stage ? stage : "");
    p->fraction = fraction;
    if (!p->shown)
        draw(p); /* the first line as soon as the delay is over */
    pthread_mutex_unlock(&p->lock);
}

static int on_progress(const char *stage, double fraction, void *user)
{
    report(user, stage, fraction);
    return 0;
}

static void on_load_progress(double fraction, void *user)
{
    report(user, "", fraction);
}

/* Stops the drawing thread and clears the line. */
static void end_progress(progress *p)
{
    if (!p->running)
        return;
    pthread_mutex_lock(&p->lock);
    p->stop = 1;
    pthread_cond_signal(&p->wake);
    pthread_mutex_unlock(&p->lock);
    pthread_join(p->thread, NULL);
    if (p->shown)
        fprintf(stderr, "\r%60s\r", "");
    pthread_cond_destroy(&p->wake);
    pthread_mutex_destroy(&p->lock);
    p->running = 0;
}

/* ----------------------------------------------------- load and build */
/* Through outfile.h (a temporary file renamed over the target when
 * complete; devices, FIFOs and /dev/stdout written in place). */
static int save_bvh(const atrbvh_bvh *bvh, const char *path)
{
    void *data = NULL;
    size_t size = 0;
    atrbvh_error e;
    atrbvh_status st;
    cli_out out;
    FILE *f;
    memset(&e, 0, sizeof e);
    st = atrbvh_save_memory(bvh, &data, &size, &e);
    if (st != ATRBVH_OK) {
        cli_error("%s: %s", path, e.text[0] ? e.text : atrbvh_strerror(st));
        return -1;
    }
    f = cli_out_open(path, &out);
    if (!f) {
        atrbvh_free(data);
        return -1;
    }
    errno = 0;
    if (fwrite(data, 1, size, f) != size) {
        int why = errno ? errno : EIO;
        cli_out_abort(&out);
        atrbvh_free(data);
        cli_error("%s: write failed: %s", path, strerror(why));
        return -1;
    }
    atrbvh_free(data);
    return cli_out_commit(&out);
}

int cli_load_and_build(const cli_build_args *a, cli_built *b)
{
    char err[512];
    atrbvh_error e;
    atrbvh_build_options o = a->options;
    progress prog;
    double t0;
    atrbvh_status st;
    memset(b, 0, sizeof *b);
    if (a->output && cli_out_usable(a->output, a->scene) != 0)
        return CLI_FAIL;
    t0 = cli_now_ms();
    begin_progress(&prog, "loading", a->quiet);
    scene_set_progress(on_load_progress, &prog);
    if (scene_load(a->scene, &b->sc, err, sizeof err) != 0) {
        scene_set_progress(NULL, NULL);
        end_progress(&prog);
        cli_error("%s", err);
        return CLI_FAIL;
    }
    scene_set_progress(NULL, NULL);
    end_progress(&prog);
    b->load_ms = cli_now_ms() - t0;
    if (b->sc.triangle_count == 0) {
        cli_error("%s: the scene has no triangles", a->scene);
        return CLI_FAIL;
    }
    b->geometry = scene_geometry(&b->sc);
    if (o.backend == ATRBVH_BACKEND_OPENCL) {
        /* One device handle for the build and any ray batches after it;
         * the library reads no environment, the tool does. */
        const char *name = o.opencl_device; /* --device or the env */
        char spec[512];
        snprintf(spec, sizeof spec, "opencl%s%s", name && *name ? ":" : "",
                 name && *name ? name : "");
        memset(&e, 0, sizeof e);
        st = atrbvh_device_open(spec, &b->device, &e);
        if (st != ATRBVH_OK && cli_bad_device(a, st, e.text))
            return cli_usage(a->cmd, "--device: %s", e.text);
        if (st != ATRBVH_OK) {
            cli_error("%s", e.text[0] ? e.text : atrbvh_strerror(st));
            return CLI_FAIL;
        }
        o.device = b->device;
    }
    begin_progress(&prog, "building", a->quiet);
    if (prog.running) {
        o.progress = on_progress;
        o.progress_user = &prog;
    }
    memset(&e, 0, sizeof e);
    st = atrbvh_build(&b->geometry, &o, &b->bvh, &e);
    end_progress(&prog);
    if (st != ATRBVH_OK && cli_bad_device(a, st, e.text)) {
        b->bvh = NULL;
        return cli_usage(a->cmd, "--device: %s", e.text);
    }
    if (st != ATRBVH_OK) {
        b->bvh = NULL;
        cli_error("%s: %s", a->scene,
                  e.text[0] ? e.text : atrbvh_strerror(st));
        return CLI_FAIL;
    }
    atrbvh_bvh_stats(b->bvh, &b->stats);
    if (a->output && save_bvh(b->bvh, a->output) != 0)
        return CLI_FAIL;
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
    if (a->options.split_budget > 0.0) {
        size_t refs = 0;
        (void)atrbvh_bvh_primitive_indices(b->bvh, &refs);
        json_kv_double(w, "split_budget", a->options.split_budget);
        json_kv_string(w, "split_rule",
                       cli_split_rule_name(a->options.split_rule));
        json_kv_uint(w, "references", refs);
    }
    json_kv_string(w, "method", cli_method_name(s->method));
    if (s->treelet_size == ATRBVH_TREELET_AUTO)
        json_kv_string(w, "treelet_size", "auto");
    else
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
    if (a->options.split_budget > 0.0) {
        size_t refs = 0;
        (void)atrbvh_bvh_primitive_indices(b->bvh, &refs);
        fprintf(f, "references       %zu (split budget %g)\n", refs,
                a->options.split_budget);
    }
    fprintf(f, "method           %s", cli_method_name(s->method));
    if (s->method != ATRBVH_METHOD_LBVH)
    {
        char tb[16];
        fprintf(f, " (treelet %s, %u rounds)",
                cli_treelet_text(s->treelet_size, tb), s->rounds);
    }
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
    cli_build_help(f,
                   "Usage: atrbvh build SCENE [OPTIONS]\n"
                   "Build a BVH over SCENE and print its statistics.\n"
                   "SCENE: a .ply or .obj file, or builtin:NAME[:N] (NAME "
                   "sphere, terrain or city;\n"
                   "N roughly the triangle count, 1 to 50000000, default "
                   "100000).\n",
                   NULL, NULL, CLI_BUILD_ALL,
                   "0 success, 1 bad input or failure, 2 usage error");
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

void cli_common_help(FILE *f, const char *exit_status)
{
    fprintf(f,
            "  -h, --help           this help\n"
            "  --version            the version, optional parts and licence\n"
            "\n"
            "Exit status: %s.\n",
            exit_status);
}

int cli_build(int argc, char **argv)
{
    cli_build_args a;
    cli_built b;
    int rc;
    if ((rc = cli_help_or_version(argc, argv, build_help)) >= 0)
        return rc;
    cli_build_args_init(&a);
    if (cli_build_parse("build", argc, argv, NULL, CLI_BUILD_ALL, &a) != 0)
        return CLI_USAGE;
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
