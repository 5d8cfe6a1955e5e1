/*
 * cli_animate.c - `atrbvh animate SCENE`: an animated built-in scene
 * (tools/animated.c) over --frames frames under one or more update
 * policies, each with its own tree on one device:
 *
 *   refit          atrbvh_refit every frame (topology of frame 0)
 *   reoptimise:N   atrbvh_reoptimise with N rounds (it refits itself)
 *   rebuild        atrbvh_rebuild every frame (into the last frame's tree)
 *   auto           atrbvh_refit; a rebuild when the drift (stats.sah /
 *                  stats.sah_built) passes --drift
 *
 * Per frame the SAH and the policy's time; with rebuild among the policies
 * also each SAH relative to the rebuild's of the same frame.  --json
 * prints them as one object, --plot DIR draws SAH and time per frame
 * (gnuplot started without a shell; every file through outfile.h).
 * --alloc counts the bytes the library asks its allocator for in each
 * update (a counting allocator through atrbvh_set_allocator, installed
 * before the device opens and removed after it closes).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "animated.h"
#include "cli.h"
#include "gnuplot.h"
#include "outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#define MAX_POLICIES 8
#define DEFAULT_POLICIES "refit,reoptimise:1,rebuild,auto"
/* auto: rebuild once the SAH is this much above the SAH when built
 * (docs/animation.md has the measurements behind it). */
#define DEFAULT_DRIFT 1.10

enum { P_REFIT, P_REOPT, P_REBUILD, P_AUTO };
static const char *const action_names[] = {"build", "refit", "reoptimise",
                                           "rebuild"};

typedef struct policy {
    int kind;
    unsigned rounds; /* reoptimise:N */
    char name[32];
    atrbvh_bvh *bvh;
    double *sah, *ms;
    unsigned long long *bytes; /* --alloc: allocated in the update */
    unsigned char *action; /* index into action_names */
    unsigned rebuilds;
} policy;

typedef struct anim_args {
    cli_build_args b;
    unsigned frames;
    const char *policies;
    double drift;
    const char *plot;
    int alloc;
} anim_args;

/* --alloc: every allocation the library makes, counted (its blocks are
 * plain malloc blocks, freed by free).  A build's threads may allocate
 * at once: the count is locked. */
static unsigned long long alloc_bytes;
static pthread_mutex_t alloc_lock = PTHREAD_MUTEX_INITIALIZER;

static void *counting_malloc(size_t size)
{
    pthread_mutex_lock(&alloc_lock);
    alloc_bytes += size;
    pthread_mutex_unlock(&alloc_lock);
    return malloc(size);
}

static int parse_policies(const char *text, policy *p, int *n)
{
    const char *s = text;
    *n = 0;
    while (*s) {
        const char *end = strchr(s, ',');
        size_t len = end ? (size_t)(end - s) : strlen(s);
        char word[32];
        policy *q = &p[*n];
        if (*n == MAX_POLICIES)
            return cli_usage("animate", "--policy: at most %d policies",
                             MAX_POLICIES);
        if (len == 0 || len >= sizeof word)
            return cli_usage("animate", "--policy: empty or overlong entry "
                             "in '%s'", text);
        memcpy(word, s, len);
        word[len] = '\0';
        memset(q, 0, sizeof *q);
        if (strcmp(word, "refit") == 0) {
            q->kind = P_REFIT;
        } else if (strcmp(word, "rebuild") == 0) {
            q->kind = P_REBUILD;
        } else if (strcmp(word, "auto") == 0) {
            q->kind = P_AUTO;
        } else if (strncmp(word, "reoptimise", 10) == 0 &&
                   (word[10] == '\0' || word[10] == ':')) {
            unsigned long r = 1;
            if (word[10] == ':' && !cli_parse_ulong(word + 11, 100, &r))
                r = 0;
            if (r < 1)
                return cli_usage("animate", "--policy: '%s': N must be a "
                                 "whole number from 1 to 100", word);
            q->kind = P_REOPT;
            q->rounds = (unsigned)r;
            snprintf(word, sizeof word, "reoptimise:%u", q->rounds);
        } else {
            return cli_usage("animate", "--policy: '%s' is not refit, "
                             "reoptimise:N, rebuild or auto", word);
        }
        snprintf(q->name, sizeof q->name, "%s", word);
        (*n)++;
        s = end ? end + 1 : s + len;
        if (end && !*s)
            return cli_usage("animate", "--policy: empty entry in '%s'",
                             text);
    }
    if (*n == 0)
        return cli_usage("animate", "--policy: no policy given");
    return 0;
}

static void animate_help(FILE *f);

static const cli_opt *own_opts(anim_args *a)
{
    static cli_opt t[6];
    const cli_opt opts[] = {
        {.name = "--frames", .kind = CLI_OPT_UINT, .arg = "F", .min = 1,
         .max = 100000, .dest = &a->frames,
         .help = "frames to animate (default 100; 30 per second)"},
        {.name = "--policy", .kind = CLI_OPT_STRING, .arg = "LIST",
         .dest = &a->policies,
         .help = "comma-separated update policies: refit,\n"
                 "reoptimise:N (refit + N treelet rounds), rebuild,\n"
                 "auto (refit; rebuild past --drift)\n"
                 "(default " DEFAULT_POLICIES ")"},
        {.name = "--drift", .kind = CLI_OPT_DOUBLE, .arg = "X", .min = 1.0,
         .max = 1e6, .dest = &a->drift,
         .help = "auto: rebuild once SAH / SAH when built exceeds X\n"
                 "(default 1.10)"},
        {.name = "--plot", .kind = CLI_OPT_STRING, .arg = "DIR",
         .dest = &a->plot,
         .help = "write animate.dat, animate.gp and the pictures\n"
                 "sah.png/.svg, ms.png/.svg into DIR (gnuplot)"},
        {.name = "--alloc", .kind = CLI_OPT_FLAG, .dest = &a->alloc,
         .flag_value = 1,
         .help = "count the host bytes the library allocates in each\n"
                 "update (its large arrays then get no huge-page advice)"},
        {.name = NULL}};
    CLI_OPTS_COPY(t, opts, 6);
    return t;
}

static void animate_help(FILE *f)
{
    anim_args a;
    memset(&a, 0, sizeof a);
    cli_build_help(f,
                   "Usage: atrbvh animate SCENE [--frames F] [--policy LIST] "
                   "[OPTIONS]\n"
                   "Animate SCENE and update its BVH every frame by each "
                   "policy; print the SAH\n"
                   "and the time of every frame (and the SAH relative to a "
                   "rebuild's).\n"
                   "SCENE: " ANIM_SCENE_NAMES ", with an optional :TRIANGLES "
                   "(default 100000).\n",
                   "Animation", own_opts(&a),
                   CLI_BUILD_CORE | CLI_BUILD_BACKEND | CLI_BUILD_DEVICE |
                       CLI_BUILD_JSON,
                   "0 success, 1 bad input or failure, 2 usage error");
}

/* ----------------------------------------------------------------- plot */
static FILE *open_in(const char *dir, const char *name, cli_out *h)
{
    char path[4200];
    int w = snprintf(path, sizeof path, "%s/%s", dir, name);
    if (w < 0 || (size_t)w >= sizeof path) {
        cli_error("%s: folder name too long", dir);
        return NULL;
    }
    return cli_out_open(path, h);
}

static const char *const pictures[4] = {"sah.png", "sah.svg", "ms.png",
                                        "ms.svg"};

/* gnuplot, then the pictures put in place (or dropped). */
static int run_gnuplot(const char *dir)
{
    return cli_gnuplot(dir, "animate.gp", pictures, 4);
}

static void gp_plot(FILE *g, const char *stem, const char *ylabel, int col,
                    const policy *p, int np, const char *title)
{
    static const char *const term[2][2] = {
        {"pngcairo size 900,600 font 'sans,10'", "png"},
        {"svg size 900,600 dynamic font 'sans,10'", "svg"}};
    int t, k;
    for (t = 0; t < 2; t++) {
        fprintf(g, "set terminal %s\nset output outdir.'%s.%s'\n",
                term[t][0], stem, term[t][1]);
        fprintf(g, "set title ");
        cli_gnuplot_string(g, title);
        fprintf(g, " noenhanced\nset xlabel 'frame'\nset ylabel '%s'\n"
                   "set key top left noenhanced\nset grid\n",
                ylabel);
        for (k = 0; k < np; k++) {
            fprintf(g, "%s 'animate.dat' using 1:%d with lines lw 2 title ",
                    k ? ", \\\n    " : "plot ", 2 + 2 * k + col);
            cli_gnuplot_string(g, p[k].name);
        }
        fprintf(g, "\nunset output\n");
    }
}

static int write_plot(const char *dir, const char *scene_name, size_t tris,
                      const policy *p, int np, unsigned frames)
{
    cli_out h;
    FILE *f;
    unsigned fr;
    int k;
    char title[200];
    f = open_in(dir, "animate.dat", &h);
    if (!f)
        return -1;
    fprintf(f, "# frame");
    for (k = 0; k < np; k++)
        fprintf(f, " sah(%s) ms(%s)", p[k].name, p[k].name);
    fputc('\n', f);
    for (fr = 0; fr < frames; fr++) {
        fprintf(f, "%u", fr);
        for (k = 0; k < np; k++)
            fprintf(f, " %.9g %.6g", p[k].sah[fr], p[k].ms[fr]);
        fputc('\n', f);
    }
    if (cli_out_commit(&h) != 0)
        return -1;
    f = open_in(dir, "animate.gp", &h);
    if (!f)
        return -1;
    fprintf(f, "# regenerate: gnuplot animate.gp (in this folder)\n"
               "if (!exists('outdir')) outdir = ''\n");
    snprintf(title, sizeof title, "%s, %zu triangles: SAH per frame",
             scene_name, tris);
    gp_plot(f, "sah", "SAH", 0, p, np, title);
    snprintf(title, sizeof title, "%s, %zu triangles: update time per frame",
             scene_name, tris);
    fprintf(f, "set logscale y\n");
    gp_plot(f, "ms", "milliseconds", 1, p, np, title);
    if (cli_out_commit(&h) != 0)
        return -1;
    return run_gnuplot(dir);
}

/* ------------------------------------------------------------- the run */
static atrbvh_status step(policy *q, unsigned frame,
                          const atrbvh_geometry *g,
                          const atrbvh_build_options *o, double drift,
                          atrbvh_error *e)
{
    atrbvh_build_options ro;
    atrbvh_stats st;
    atrbvh_status s = ATRBVH_OK;
    const unsigned long long b0 = alloc_bytes;
    double t0 = cli_now_ms();
    if (frame == 0 || q->kind == P_REBUILD) {
        /* into the last frame's tree (a failure frees it and ends the
         * run) */
        s = atrbvh_rebuild(g, o, &q->bvh, e);
        q->action[frame] = frame == 0 ? 0 : 3;
    } else if (q->kind == P_REOPT) {
        /* atrbvh_reoptimise refits (its refit stage) at the new
         * positions itself. */
        ro = *o;
        ro.rounds = q->rounds;
        s = atrbvh_reoptimise(q->bvh, g, &ro, e);
        q->action[frame] = 2;
    } else {
        s = atrbvh_refit(q->bvh, g, o, e);
        q->action[frame] = 1;
        if (s == ATRBVH_OK && q->kind == P_AUTO) {
            atrbvh_bvh_stats(q->bvh, &st);
            if (st.sah_built > 0 && st.sah > drift * st.sah_built) {
                s = atrbvh_rebuild(g, o, &q->bvh, e);
                if (s == ATRBVH_OK)
                    q->rebuilds++;
                q->action[frame] = 3;
            }
        }
    }
    q->ms[frame] = cli_now_ms() - t0;
    q->bytes[frame] = alloc_bytes - b0;
    if (s == ATRBVH_OK) {
        atrbvh_bvh_stats(q->bvh, &st);
        q->sah[frame] = st.sah;
    }
    return s;
}

/* Policy k over frames 1.. (frame 0 is the same build for all): mean and
 * largest time, SAH over the rebuild's (policy reb; -1: none, then the
 * mean is 1 and the largest 0) and the most bytes allocated. */
typedef struct summary {
    double mean_ms, max_ms, mean_r, max_r;
    unsigned long long max_bytes;
} summary;

static summary summarise(const policy *p, int k, int reb, unsigned frames)
{
    summary m;
    double sum = 0, rsum = 0;
    unsigned fr;
    memset(&m, 0, sizeof m);
    for (fr = 1; fr < frames; fr++) {
        const double r = reb >= 0 && p[reb].sah[fr] > 0
                             ? p[k].sah[fr] / p[reb].sah[fr]
                             : 0;
        sum += p[k].ms[fr];
        m.max_ms = p[k].ms[fr] > m.max_ms ? p[k].ms[fr] : m.max_ms;
        rsum += r;
        m.max_r = r > m.max_r ? r : m.max_r;
        m.max_bytes = p[k].bytes[fr] > m.max_bytes ? p[k].bytes[fr]
                                                   : m.max_bytes;
    }
    m.mean_ms = frames > 1 ? sum / (frames - 1) : 0.0;
    m.mean_r = frames > 1 ? rsum / (frames - 1) : 1.0;
    return m;
}

static void report(const anim_args *a, const anim_scene *sc,
                   const char *device, const policy *p, int np)
{
    const unsigned frames = a->frames;
    int reb = -1, k;
    unsigned fr;
    json_writer w;
    for (k = 0; k < np; k++)
        if (p[k].kind == P_REBUILD)
            reb = k;
    if (a->b.json) {
        json_init(&w, stdout);
        json_begin_object(&w);
        json_kv_string(&w, "scene", sc->s.name);
        json_kv_uint(&w, "triangles", sc->s.triangle_count);
        json_kv_string(&w, "device", device);
        json_kv_string(&w, "method", cli_method_name(a->b.options.method));
        json_kv_uint(&w, "frame_count", frames);
        json_kv_double(&w, "drift", a->drift);
        json_key(&w, "frames");
        fputc('[', stdout);
        for (k = 0; k < np; k++)
            for (fr = 0; fr < frames; fr++) {
                json_begin_object(&w);
                json_kv_uint(&w, "frame", fr);
                json_kv_string(&w, "policy", p[k].name);
                json_kv_string(&w, "action", action_names[p[k].action[fr]]);
                json_kv_double(&w, "sah", p[k].sah[fr]);
                json_kv_double(&w, "ms", p[k].ms[fr]);
                if (a->alloc)
                    json_kv_uint(&w, "alloc_bytes", p[k].bytes[fr]);
                if (reb >= 0 && p[reb].sah[fr] > 0)
                    json_kv_double(&w, "sah_vs_rebuild",
                                   p[k].sah[fr] / p[reb].sah[fr]);
                json_end_object(&w);
            }
        fputc(']', stdout);
    } else {
        printf("scene %s, %zu triangles, device %s, %u frames\n",
               sc->s.name, sc->s.triangle_count, device, frames);
        printf("frame");
        for (k = 0; k < np; k++)
            printf("  %14s SAH   ms%s", p[k].name,
                   a->alloc ? "      bytes" : "");
        putchar('\n');
        for (fr = 0; fr < frames; fr++) {
            printf("%5u", fr);
            for (k = 0; k < np; k++) {
                printf("  %18.4f %7.2f", p[k].sah[fr], p[k].ms[fr]);
                if (a->alloc)
                    printf(" %10llu", p[k].bytes[fr]);
                putchar(p[k].action[fr] == 3 && fr ? '*' : ' ');
            }
            putchar('\n');
        }
        printf("(* rebuilt)\n\n");
        printf("%-16s %10s %10s %12s %12s %8s%s\n", "policy", "mean ms",
               "max ms", "mean SAH/r", "max SAH/r", "rebuilds",
               a->alloc ? "    max bytes" : "");
    }
    /* Summary over frames 1.. (frame 0 is the same build for all). */
    if (a->b.json) {
        json_key(&w, "summary");
        fputc('[', stdout);
        for (k = 0; k < np; k++) {
            const summary m = summarise(p, k, reb, frames);
            json_begin_object(&w);
            json_kv_string(&w, "policy", p[k].name);
            json_kv_double(&w, "mean_ms", m.mean_ms);
            json_kv_double(&w, "max_ms", m.max_ms);
            if (reb >= 0) {
                json_kv_double(&w, "mean_sah_vs_rebuild", m.mean_r);
                json_kv_double(&w, "max_sah_vs_rebuild", m.max_r);
            }
            json_kv_uint(&w, "rebuilds",
                         p[k].kind == P_REBUILD ? frames - 1 : p[k].rebuilds);
            if (a->alloc)
                json_kv_uint(&w, "max_alloc_bytes", m.max_bytes);
            json_end_object(&w);
        }
        fputc(']', stdout);
        json_end_object(&w);
    } else {
        for (k = 0; k < np; k++) {
            const summary m = summarise(p, k, reb, frames);
            printf("%-16s %10.3f %10.3f %12.4f %12.4f %8u", p[k].name,
                   m.mean_ms, m.max_ms, m.mean_r, m.max_r,
                   p[k].kind == P_REBUILD ? frames - 1 : p[k].rebuilds);
            if (a->alloc)
                printf(" %12llu", m.max_bytes);
            putchar('\n');
        }
        if (reb < 0)
            printf("(SAH/r: no rebuild policy to compare with)\n");
    }
}

int cli_animate(int argc, char **argv)
{
    anim_args a;
    const cli_opt *own;
    policy p[MAX_POLICIES];
    int np = 0, k, rc = CLI_OK;
    anim_scene sc;
    char err[512], spec[300];
    atrbvh_device *dev = NULL;
    atrbvh_geometry g;
    atrbvh_error e;
    atrbvh_status st;
    unsigned fr;
    if ((rc = cli_help_or_version(argc, argv, animate_help)) >= 0)
        return rc;
    rc = CLI_OK;
    memset(&a, 0, sizeof a);
    cli_build_args_init(&a.b);
    a.frames = 100;
    a.policies = DEFAULT_POLICIES;
    a.drift = DEFAULT_DRIFT;
    own = own_opts(&a);
    if (cli_build_parse("animate", argc, argv, own,
                        CLI_BUILD_CORE | CLI_BUILD_BACKEND | CLI_BUILD_DEVICE |
                            CLI_BUILD_JSON,
                        &a.b) != 0)
        return CLI_USAGE;
    if (parse_policies(a.policies, p, &np) != 0)
        return CLI_USAGE;
    if (a.plot) {
        struct stat s;
        if (stat(a.plot, &s) != 0 || !S_ISDIR(s.st_mode)) {
            cli_error("%s: not a folder (--plot needs an existing one)",
                      a.plot);
            return CLI_FAIL;
        }
    }
    if (anim_scene_open(a.b.scene, &sc, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_FAIL;
    }
    snprintf(spec, sizeof spec, "%s%s%s",
             a.b.options.backend == ATRBVH_BACKEND_OPENCL ? "opencl" : "cpu",
             a.b.options.backend == ATRBVH_BACKEND_OPENCL &&
                     a.b.options.opencl_device
                 ? ":"
                 : "",
             a.b.options.backend == ATRBVH_BACKEND_OPENCL &&
                     a.b.options.opencl_device
                 ? a.b.options.opencl_device
                 : "");
    memset(&e, 0, sizeof e);
    /* (no library call is running, and none has allocated yet) */
    if (a.alloc)
        atrbvh_set_allocator(counting_malloc, free);
    st = atrbvh_device_open(spec, &dev, &e);
    if (st != ATRBVH_OK) {
        atrbvh_set_allocator(NULL, NULL);
        anim_scene_free(&sc);
        if (cli_bad_device(&a.b, st, e.text))
            return cli_usage("animate", "--device: %s", e.text);
        cli_error("%s: %s", spec, e.text[0] ? e.text : atrbvh_strerror(st));
        return CLI_FAIL;
    }
    a.b.options.device = dev;
    for (k = 0; k < np; k++) {
        p[k].sah = calloc(a.frames, sizeof *p[k].sah);
        p[k].ms = calloc(a.frames, sizeof *p[k].ms);
        p[k].bytes = calloc(a.frames, sizeof *p[k].bytes);
        p[k].action = calloc(a.frames, 1);
        if (!p[k].sah || !p[k].ms || !p[k].bytes || !p[k].action) {
            cli_error("out of memory for %u frames", a.frames);
            rc = CLI_FAIL;
        }
    }
    g = scene_geometry(&sc.s);
    for (fr = 0; rc == CLI_OK && fr < a.frames; fr++) {
        anim_scene_frame(&sc, fr);
        for (k = 0; rc == CLI_OK && k < np; k++) {
            memset(&e, 0, sizeof e);
            st = step(&p[k], fr, &g, &a.b.options, a.drift, &e);
            if (st != ATRBVH_OK) {
                cli_error("%s, frame %u, %s: %s", sc.s.name, fr, p[k].name,
                          e.text[0] ? e.text : atrbvh_strerror(st));
                rc = CLI_FAIL;
            }
        }
    }
    if (rc == CLI_OK) {
        report(&a, &sc, atrbvh_device_name(dev), p, np);
        if (a.plot && write_plot(a.plot, sc.s.name, sc.s.triangle_count, p,
                                 np, a.frames) != 0)
            rc = CLI_FAIL;
    }
    for (k = 0; k < np; k++) {
        atrbvh_bvh_free(p[k].bvh);
        free(p[k].sah);
        free(p[k].ms);
        free(p[k].bytes);
        free(p[k].action);
    }
    atrbvh_device_close(dev);
    /* every block of the library is freed: the default allocator back */
    atrbvh_set_allocator(NULL, NULL);
    anim_scene_free(&sc);
    return rc;
}
