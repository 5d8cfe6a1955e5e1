/*
 * run.c - one configuration on one scene for `atrbvh bench`: timed builds
 * (median, minimum), the peak bytes the library holds, the binary SAH, and
 * the scene's rays traced through the tree.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "bench.h"
#include "memtrack.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

double bench_median(double *v, size_t n)
{
    if (n == 0)
        return NAN;
    qsort(v, n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}


static size_t bvh_bytes(const atrbvh_stats *s)
{
    return s->nodes * sizeof(atrbvh_node) + s->primitives * sizeof(uint32_t);
}

int bench_lib_build(const scene_data *sd, const atrbvh_build_options *o,
                     atrbvh_bvh **out, const char *spec, int rebuild)
{
    atrbvh_error e;
    atrbvh_status st;
    memset(&e, 0, sizeof e);
    st = rebuild ? atrbvh_rebuild(&sd->g, o, out, &e)
                 : atrbvh_build(&sd->g, o, out, &e);
    if (st != ATRBVH_OK) {
        *out = NULL;
        cli_error("%s: %s", spec, e.text[0] ? e.text : atrbvh_strerror(st));
        return -1;
    }
    return 0;
}

/* Traces the scene's rays through `bvh` `repeat` times; median Mrays/s per
 * kind.  Then once more, untimed, counting (atrbvh_*_batch_stats): the
 * boxes and primitives tested per ray of each kind and over all rays. */
static int lib_trace(const scene_data *sd, const atrbvh_bvh *bvh, int threads,
                     unsigned repeat, double ci, double ct, row *row_out)
{
    double *mrays = row_out->mrays;
    uint64_t all_rays = 0, all_boxes = 0, all_prims = 0;
    const ray_set *rs = &sd->rays;
    size_t cap = rs->n_primary > rs->n_diffuse ? rs->n_primary : rs->n_diffuse;
    atrbvh_hit *hits = malloc((cap ? cap : 1) * sizeof *hits);
    uint8_t *occ = malloc(cap ? cap : 1);
    double *t = malloc(repeat * sizeof *t);
    int kind, rc = -1;
    unsigned r;
    if (!hits || !occ || !t) {
        cli_error("out of memory for %zu rays", cap);
        goto done;
    }
    for (kind = 0; kind < 3; kind++) {
        const atrbvh_ray *rays = kind == 0   ? rs->primary
                                 : kind == 1 ? rs->ao
                                             : rs->diffuse;
        size_t n = kind == 0 ? rs->n_primary
                   : kind == 1 ? rs->n_ao : rs->n_diffuse;
        if (n == 0) {
            mrays[kind] = NAN;
            continue;
        }
        for (r = 0; r < repeat; r++) {
            atrbvh_error e;
            atrbvh_status st;
            double t0 = cli_now_ms();
            memset(&e, 0, sizeof e);
            st = kind == 1 ? atrbvh_occluded_batch(bvh, &sd->g, rays, n, occ,
                                                   threads, &e)
                           : atrbvh_intersect_batch(bvh, &sd->g, rays, n,
                                                    hits, threads, &e);
            t[r] = cli_now_ms() - t0;
            if (st != ATRBVH_OK) {
                cli_error("tracing: %s", e.text);
                goto done;
            }
        }
        mrays[kind] = (double)n / (bench_median(t, repeat) * 1e3);
        {
            atrbvh_trace_stats ts;
            atrbvh_error e;
            atrbvh_status st;
            atrbvh_trace_stats_init(&ts);
            memset(&e, 0, sizeof e);
            st = kind == 1 ? atrbvh_occluded_batch_stats(NULL, bvh, &sd->g,
                                                         rays, n, occ,
                                                         threads, &ts, &e)
                           : atrbvh_intersect_batch_stats(NULL, bvh, &sd->g,
                                                          rays, n, hits,
                                                          threads, &ts, &e);
            if (st != ATRBVH_OK) {
                cli_error("counting ray cost: %s", e.text);
                goto done;
            }
            row_out->box_per_ray[kind] = (double)ts.box_tests / (double)n;
            row_out->tri_per_ray[kind] = (double)ts.prim_tests / (double)n;
            all_rays += ts.rays;
            all_boxes += ts.box_tests;
            all_prims += ts.prim_tests;
        }
    }
    if (all_rays > 0) {
        row_out->box_per_ray[3] = (double)all_boxes / (double)all_rays;
        row_out->tri_per_ray[3] = (double)all_prims / (double)all_rays;
        row_out->ray_cost =
            ci * row_out->box_per_ray[3] + ct * row_out->tri_per_ray[3];
    }
    rc = 0;
done:
    free(hits);
    free(occ);
    free(t);
    return rc;
}

static double total_mrays(const scene_data *sd, const double mrays[3])
{
    const ray_set *rs = &sd->rays;
    size_t n[3];
    double ms = 0.0, count = 0.0;
    int k;
    n[0] = rs->n_primary;
    n[1] = rs->n_ao;
    n[2] = rs->n_diffuse;
    for (k = 0; k < 3; k++) {
        if (n[k] == 0 || !(mrays[k] > 0.0))
            continue;
        ms += (double)n[k] / (mrays[k] * 1e3);
        count += (double)n[k];
    }
    return ms > 0.0 ? count / (ms * 1e3) : NAN;
}

/* Milliseconds on `clock` (CLOCK_MONOTONIC or the process's CPU time). */
static double clock_ms(clockid_t clock)
{
    struct timespec t;
    if (clock_gettime(clock, &t) != 0)
        return NAN;
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* The tree's size and the build times (minimum, median of `repeat`). */
static void set_tree_and_times(row *r, const atrbvh_stats *st, double *tot,
                               unsigned repeat)
{
    unsigned k;
    r->nodes = st->nodes;
    r->leaves = st->leaves;
    r->bvh_bytes = bvh_bytes(st);
    r->build_min_ms = tot[0];
    for (k = 1; k < repeat; k++)
        if (tot[k] < r->build_min_ms)
            r->build_min_ms = tot[k];
    r->build_ms = bench_median(tot, repeat);
    r->timed = repeat;
}

/* The row's fields before any build: NaN where nothing is measured. */
static void row_init(row *r, const config *c, const char *spec,
                     const scene_data *sd)
{
    int s;
    memset(r, 0, sizeof *r);
    r->c = *c;
    r->scene = spec;
    r->triangles = sd->sc.triangle_count;
    r->rel_pct = r->time_pct = r->sah_pct = NAN;
    r->ray_cost = r->cost_pct = NAN;
    for (s = 0; s < 4; s++)
        r->box_per_ray[s] = r->tri_per_ray[s] = NAN;
    for (s = 0; s < 3; s++)
        r->mrays[s] = r->emb_mrays[s] = NAN;
    r->emb_commit_ms = NAN;
    r->cpu_use = NAN;
    r->total_mrays = NAN;
    r->sah_binary = NAN;
}

/* A build into the --builds log, if there is one: kind from k as
 * cfg_build's (-1 warmup, -2 untimed, k >= 0 timed in turn k), or
 * "binary" for k < -2.  The label is the tables' (the library's sizes
 * and rounds as built). */
static void log_build(const bench_cfg *b, int k, const atrbvh_stats *st,
                      double ms)
{
    char label[64];
    if (!b->a->log || !b->a->log->f)
        return;
    if (st)
        config_label(b->c, st->treelet_size, st->rounds, label,
                     sizeof label);
    else
        config_label(b->c, 0, 0, label, sizeof label);
    csv_build_row(b->a->log, b->r, label,
                  k >= 0     ? "timed"
                  : k == -1  ? "warmup"
                  : k == -2  ? "untimed"
                             : "binary",
                  k, ms);
}

/* One build of the configuration into b->bvh (the previous one freed),
 * with its peak bytes; for the library also its CPU use.  Timed builds
 * record their times at index k; k < 0: untimed, the first warm-up
 * (Embree's with its memory monitor) at k = -1, a later one at k = -2. */
static int cfg_build(bench_cfg *b, int k)
{
    row *r = b->r;
    int s;
    if (b->c->embree) {
        embree_build_result res;
        /* The warm-up with Embree's memory monitor (a callback on every
         * allocation), the timed builds without it.  Only the trees read
         * are converted: the warm-up's (its references) and the last
         * timed build's (the row's tree), so that the builds before a
         * timed one end as Embree's do, not in a conversion longer than
         * the build (embree_build). */
        const int keep = k == -1 || k == (int)b->repeat - 1;
        if (embree_build(b->emb, &b->sd->sc, b->c->eq,
                         b->a->base.max_leaf_size, b->a->base.ci,
                         b->a->base.ct, k == -1, keep, &res) != 0)
            return -1;
        if (keep) {
            atrbvh_bvh_free(b->bvh);
            b->bvh = res.bvh;
        }
        log_build(b, k, NULL, res.build_ms);
        if (k == -1) {
            r->peak = res.peak_bytes;
            r->references = res.references;
        } else if (k >= 0) {
            b->tot[k] = res.build_ms;
        }
        return 0;
    }
    {
        size_t peak, before;
        double cpu, wall, w0, c0;
        if (b->a->fresh) {
            atrbvh_bvh_free(b->bvh);
            b->bvh = NULL;
        }
        before = memtrack_current();
        memtrack_reset_peak();
        w0 = clock_ms(CLOCK_MONOTONIC);
        c0 = clock_ms(CLOCK_PROCESS_CPUTIME_ID);
        /* (into the last build's tree unless --fresh: as a program that
         * builds frame after frame does; Embree's BVH object is kept
         * alike.  Its peak above what was held before, the old tree
         * included, is lower than the first build's, which makes the
         * row's peak.) */
        if (bench_lib_build(b->sd, &b->o, &b->bvh, b->spec, !b->a->fresh) !=
            0)
            return -1;
        peak = memtrack_peak() - before;
        cpu = clock_ms(CLOCK_PROCESS_CPUTIME_ID) - c0;
        wall = clock_ms(CLOCK_MONOTONIC) - w0;
        if (peak > r->peak)
            r->peak = peak;
        atrbvh_bvh_stats(b->bvh, &b->st);
        log_build(b, k, &b->st, b->st.build_ms);
        if (k < 0)
            return 0;
        b->tot[k] = b->st.build_ms;
        b->use[k] = wall > 0.0 && b->st.threads > 0
                        ? cpu / ((double)b->st.threads * wall)
                        : NAN;
        for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
            b->stg[s * b->repeat + (unsigned)k] =
                atrbvh_bvh_stage_ms(b->bvh, (atrbvh_stage)s);
    }
    return 0;
}

int bench_cfg_open(bench_cfg *b, const bench_args *a, scene_data *sd,
                   const char *spec, const config *c, embree_ctx *emb,
                   int do_rays, unsigned repeat, int warmup, int binary,
                   row *r)
{
    memset(b, 0, sizeof *b);
    b->a = a;
    b->sd = sd;
    b->spec = spec;
    b->c = c;
    b->emb = emb;
    b->do_rays = do_rays;
    b->repeat = repeat;
    b->binary = binary;
    b->r = r;
    row_init(r, c, spec, sd);
    b->tot = malloc((repeat + 1) * sizeof *b->tot);
    b->stg = malloc((repeat + 1) * ATRBVH_STAGE_COUNT * sizeof *b->stg);
    b->use = malloc((repeat + 1) * sizeof *b->use);
    if (!b->tot || !b->stg || !b->use) {
        cli_error("out of memory");
        return -1;
    }
    if (c->embree)
        return cfg_build(b, -1); /* Embree always warms up: its monitor */
    b->o = a->base;
    b->o.method = c->method;
    b->o.treelet_size = c->treelet;
    b->o.rounds = c->rounds;
    b->o.backend = c->backend;
    b->o.split_budget = c->split;
    if (c->split_rule >= 0)
        b->o.split_rule = c->split_rule;
    {
        /* One device per configuration, opened before the timed builds
         * (as users open it once): its first build also makes the
         * scratch, so the peak memory of the first build counts it.
         * OpenCL asked for (--backend, @opencl) and not to be had fails
         * the run rather than report the CPU rows alone. */
        atrbvh_error e;
        atrbvh_status x;
        char dspec[512];
        const char *name = a->base.opencl_device;
        if (c->backend == ATRBVH_BACKEND_OPENCL)
            snprintf(dspec, sizeof dspec, "opencl%s%s",
                     name && *name ? ":" : "", name && *name ? name : "");
        else
            snprintf(dspec, sizeof dspec, "cpu");
        memset(&e, 0, sizeof e);
        x = atrbvh_device_open(dspec, &b->dev, &e);
        if (x != ATRBVH_OK) {
            char label[64];
            config_label(c, c->treelet, c->rounds, label, sizeof label);
            cli_error("bench: %s: %s", label,
                      e.text[0] ? e.text : atrbvh_strerror(x));
            return -1;
        }
        b->o.device = b->dev;
    }
    return warmup ? cfg_build(b, -1) : 0;
}

int bench_cfg_time(bench_cfg *b, unsigned k, int warm)
{
    if (warm && cfg_build(b, -2) != 0)
        return -1;
    return cfg_build(b, (int)k);
}

int bench_cfg_finish(bench_cfg *b)
{
    row *r = b->r;
    const bench_args *a = b->a;
    const unsigned repeat = b->repeat;
    int s;
    if (!b->bvh)
        return -1;
    if (!b->c->embree) {
        atrbvh_bvh_primitive_indices(b->bvh, &r->references);
        r->threads = b->st.threads;
        r->treelet = b->st.treelet_size;
        r->rounds = b->st.rounds;
        r->sah = b->st.sah;
        set_tree_and_times(r, &b->st, b->tot, repeat);
        r->cpu_use = bench_median(b->use, repeat);
        for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
            r->stage_ms[s] = bench_median(b->stg + s * repeat, repeat);
        /* the binary tree */
        if (b->binary) {
            atrbvh_bvh *bin = NULL;
            atrbvh_stats bs;
            atrbvh_build_options o = b->o;
            o.collapse = 0;
            o.max_leaf_size = 0;
            if (bench_lib_build(b->sd, &o, &bin, b->spec, 0) != 0)
                return -1;
            atrbvh_bvh_stats(bin, &bs);
            log_build(b, -3, &bs, bs.build_ms);
            r->sah_binary = bs.sah;
            atrbvh_bvh_free(bin);
        }
    } else {
        atrbvh_stats st;
        size_t nn;
        const atrbvh_node *nodes;
        atrbvh_bvh_stats(b->bvh, &st);
        nodes = atrbvh_bvh_nodes(b->bvh, &nn);
        r->threads = bench_threads(a);
        r->sah = atrbvh_sah(nodes, nn, a->base.ci, a->base.ct);
        set_tree_and_times(r, &st, b->tot, repeat);
        for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
            r->stage_ms[s] = NAN;
        {
            embree_build_result bin;
            size_t bn;
            const atrbvh_node *bnodes;
            if (embree_build(b->emb, &b->sd->sc, b->c->eq, 1, a->base.ci,
                             a->base.ct, 0, 1, &bin) != 0)
                return -1;
            log_build(b, -3, NULL, bin.build_ms);
            bnodes = atrbvh_bvh_nodes(bin.bvh, &bn);
            r->sah_binary = atrbvh_sah(bnodes, bn, a->base.ci, a->base.ct);
            atrbvh_bvh_free(bin.bvh);
        }
        if (b->do_rays && b->sd->have_rays &&
            embree_trace(b->emb, &b->sd->sc, b->c->eq, &b->sd->rays,
                         a->base.threads, r->emb_mrays,
                         &r->emb_commit_ms) != 0)
            return -1;
        if (b->do_rays && b->sd->have_rays) {
            const scene_data *sd = b->sd;
            const size_t n[3] = {sd->rays.n_primary, sd->rays.n_ao,
                                 sd->rays.n_diffuse};
            for (s = 0; s < 3; s++)
                r->emb_mrays[s] = n[s] && r->emb_mrays[s] > 0.0
                                      ? (double)n[s] / (r->emb_mrays[s] * 1e3)
                                      : NAN;
        }
    }
    if (b->do_rays && b->sd->have_rays) {
        if (lib_trace(b->sd, b->bvh, a->base.threads, repeat, a->base.ci,
                      a->base.ct, r) != 0)
            return -1;
        r->total_mrays = total_mrays(b->sd, r->mrays);
    }
    return 0;
}

void bench_cfg_close(bench_cfg *b)
{
    atrbvh_bvh_free(b->bvh);
    b->bvh = NULL;
    atrbvh_device_close(b->dev);
    b->dev = NULL;
    free(b->tot);
    free(b->stg);
    free(b->use);
    b->tot = b->stg = b->use = NULL;
}

int bench_load_scene(const char *spec, scene_data *sd)
{
    char err[512];
    memset(sd, 0, sizeof *sd);
    if (scene_load(spec, &sd->sc, err, sizeof err) != 0) {
        cli_error("%s", err);
        return -1;
    }
    if (sd->sc.triangle_count == 0) {
        cli_error("%s: the scene has no triangles", spec);
        return -1;
    }
    sd->g = scene_geometry(&sd->sc);
    return 0;
}

void bench_free_scene(scene_data *sd)
{
    ray_set_free(&sd->rays);
    scene_free(&sd->sc);
}

int bench_threads(const bench_args *a)
{
    if (a->base.threads > 0)
        return a->base.threads;
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}
