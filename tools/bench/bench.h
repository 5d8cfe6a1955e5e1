/*
 * bench.h - what the files of `atrbvh bench` share (see atrbvh(1), BENCH).
 *
 *   main.c     the command line: options, configuration lists, help
 *   run.c      one configuration on one scene: builds, memory, tracing
 *   sweep.c    every configuration on every scene (the default study)
 *   scaling.c  build time and memory against triangle count (--scaling)
 *   csv.c      the --csv files
 *   tables.c   the text tables on standard output
 *   plots.c    gnuplot data, scripts and pictures (--plot)
 *   embree.c   Embree beside atrbvh; memtrack.c the library's peak bytes
 */
#ifndef ATRBVH_TOOLS_BENCH_H
#define ATRBVH_TOOLS_BENCH_H

#include <stdio.h>

#include "cli.h"
#include "embree.h"
#include "rays.h"

#define MAX_CONFIGS 256
#define MAX_SCENES 64
#define MAX_SIZES 32
/* The scaling study times one build instead of --repeat when the warm-up
 * build (every size has one) took longer than this: a size's builds then
 * take seconds each, and one is a fair sample. */
#define SCALING_SINGLE_MS 2000.0

typedef struct config {
    int embree; /* 1: an Embree row (eq) */
    embree_quality eq;
    atrbvh_method method;
    unsigned treelet, rounds; /* 0: the method's default */
    atrbvh_backend backend;
    double split; /* "+split=B": the library's split budget; 0 off */
    int split_rule; /* with split: "+split=B/RULE" an ATRBVH_SPLIT_
                       value, -1 (no "/RULE") the library's default */
} config;

typedef struct row {
    config c;
    const char *scene;
    size_t triangles;
    unsigned treelet, rounds;
    int threads;
    double build_ms, build_min_ms, stage_ms[ATRBVH_STAGE_COUNT];
    double sah, sah_binary;
    size_t nodes, leaves, peak, bvh_bytes;
    size_t references; /* primitive references in the leaves */
    /* median over the timed builds of the process's CPU time over threads
     * x wall time: the share of the threads' time the build kept busy
     * (passive waiting: a sleeping thread takes none); NaN for Embree,
     * whose idle workers may spin */
    double cpu_use;
    unsigned timed; /* timed builds the medians are of */
    double mrays[3], total_mrays;
    double emb_mrays[3], emb_commit_ms;
    double rel_pct, time_pct, sah_pct;
    /* Exact ray cost (atrbvh_trace_stats): boxes and primitives tested per
     * ray, per kind (primary, ao, diffuse) and [3] over every ray;
     * ray_cost = ci x boxes + ct x primitives per ray (over every ray),
     * cost_pct relative to the scene's TRBVH(7,3). */
    double box_per_ray[4], tri_per_ray[4], ray_cost, cost_pct;
} row;

/* --builds: every build the bench runs, a CSV row each, in the order
 * they ran (run.c's bench_log_build). */
typedef struct bench_log {
    FILE *f;           /* NULL: no log */
    unsigned long seq; /* builds logged so far */
} bench_log;

typedef struct bench_args {
    const char *scenes[MAX_SCENES];
    int nscenes;
    config configs[MAX_CONFIGS];
    int nconfigs;
    atrbvh_build_options base;
    unsigned repeat, width, height, viewpoints, spp;
    int rays;
    const char *csv, *plot, *builds;
    bench_log *log; /* the --builds file (main.c) */
    int scaling;
    int fresh; /* --fresh: free the last tree, then build (no rebuild) */
    size_t sizes[MAX_SIZES];
    int nsizes;
    camera_view view; /* --eye, --look-at, --fov */
} bench_args;

typedef struct scene_data {
    scene sc;
    atrbvh_geometry g;
    ray_set rays;
    int have_rays;
} scene_data;

/* One series of the scaling study: a base scene and a configuration at
 * each size. */
typedef struct scaling_series {
    const char *base;
    char label[64];
    row *rows; /* n of them */
    size_t *copies;
    int n;
    double slope; /* build time ~ N^slope from 1e5 triangles */
} scaling_series;

/* configs.c-like helpers (main.c) */
void config_label(const config *c, unsigned treelet, unsigned rounds,
                  char *buf, size_t n);
const char *row_method(const row *r);
const char *bench_backend_name(atrbvh_backend b);

/* run.c */
double bench_median(double *v, size_t n);
int bench_load_scene(const char *spec, scene_data *sd);
void bench_free_scene(scene_data *sd);
/* atrbvh_build, or with `rebuild` atrbvh_rebuild into *out. */
int bench_lib_build(const scene_data *sd, const atrbvh_build_options *o,
                    atrbvh_bvh **out, const char *spec, int rebuild);
/* One configuration on one scene in steps, so that the timed builds of
 * several configurations or sizes can take turns (sweep.c, scaling.c):
 * open (the device, the warm-up build), time
 * build k (0 .. repeat-1; warm: right after one more untimed build, so
 * that it finds the caches as a build repeated back to back does),
 * finish (the row: medians, the binary SAH, rays), close (always, also
 * after an error).  Each step: 0, or -1 after an error line. */
typedef struct bench_cfg {
    const bench_args *a;
    scene_data *sd;
    const char *spec;
    const config *c;
    embree_ctx *emb;
    int do_rays, binary;
    unsigned repeat;
    row *r;
    double *tot, *stg, *use; /* per timed build                        */
    atrbvh_device *dev;      /* the library's configurations           */
    atrbvh_build_options o;
    atrbvh_stats st;         /* the last build's                       */
    atrbvh_bvh *bvh;         /* the last build                         */
} bench_cfg;
int bench_cfg_open(bench_cfg *b, const bench_args *a, scene_data *sd,
                   const char *spec, const config *c, embree_ctx *emb,
                   int do_rays, unsigned repeat, int warmup, int binary,
                   row *r);
int bench_cfg_time(bench_cfg *b, unsigned k, int warm);
int bench_cfg_finish(bench_cfg *b);
void bench_cfg_close(bench_cfg *b);
/* Threads the builds use: --threads, else OpenMP's maximum. */
int bench_threads(const bench_args *a);

/* sweep.c, scaling.c */
int bench_sweep(bench_args *a, FILE *csv);
int bench_scaling(bench_args *a, FILE *csv);

/* csv.c */
void csv_header(FILE *f);
void csv_row(FILE *f, const bench_args *a, const row *r);
void csv_scaling_header(FILE *f);
void csv_scaling_row(FILE *f, const char *base, const row *w, size_t copies);
void csv_build_header(FILE *f);
void csv_build_row(bench_log *log, const row *r, const char *label,
                   const char *kind, int turn, double ms);

/* tables.c */
void table_header(FILE *f, const bench_args *a);
void table_sweep(FILE *f, const row *rows, int n, int have_rays);
void table_dominance(FILE *f, const row *rows, int n);
void table_scaling_header(FILE *f);
void table_scaling_row(FILE *f, const char *base, const char *label,
                       const row *w, size_t copies);

/* plots.c: 0, or -1 after an error line */
int plot_scene(const char *dir, const char *spec, const row *rows, int n,
               int have_rays);
int plot_scaling(const char *dir, const scaling_series *s, int n);

#endif
