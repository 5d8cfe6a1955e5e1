/*
 * cli_bench.c - `atrbvh bench`: the speed/quality trade of every
 * configuration on the same scenes, beside Embree, in one process; and the
 * scaling study (--scaling).  See atrbvh(1), BENCH.
 *
 * Per configuration: one warm-up build, then K timed builds (median total
 * and per stage, minimum total); the peak bytes the library holds during a
 * build (memtrack.c wraps the library's allocator); one more build with
 * collapse off for the binary SAH; then the fixed ray sets of the scene
 * (rays.h) traced K times through the tree with the library's batch
 * traversal on all threads (median Mrays/s).  Embree rows build with
 * rtcBuildBVH into a binary tree laid out as atrbvh nodes, so the SAH and
 * the traversal are ours; Embree's own scene and rtcIntersect1 give the
 * embree_*_mrays columns.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"
#include "embree_bvh.h"
#include "memtrack.h"
#include "rays.h"

#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#define MAX_CONFIGS 256
#define MAX_SCENES 64
#define MAX_SIZES 32
#define MAX_SIDE 4096ul
#define MAX_REPEAT 1000ul
#define MAX_VIEWPOINTS 64ul
#define MAX_SPP 64ul
#define DEFAULT_CONFIGS "lbvh,trbvh:7:3,atrbvh:9:2,high,embree"
#define DEFAULT_SCALING_CONFIGS "lbvh,atrbvh:9:2"
#define DEFAULT_SCENE "builtin:city:100000"
#define DEFAULT_SIZES "10000,100000,1000000,10000000"
/* Above this many triangles the scaling study builds once, no warm-up. */
#define SCALING_SINGLE_RUN 2000000

typedef struct config {
    int embree;             /* 1: an Embree row (eq)              */
    embree_quality eq;
    atrbvh_method method;
    unsigned treelet, rounds; /* 0: the method's default          */
    atrbvh_backend backend;
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
    double mrays[3], total_mrays;
    double emb_mrays[3], emb_commit_ms;
    double rel_pct, time_pct, sah_pct;
} row;

typedef struct bench_args {
    const char *scenes[MAX_SCENES];
    int nscenes;
    config configs[MAX_CONFIGS];
    int nconfigs;
    atrbvh_build_options base;
    unsigned long repeat, width, height, viewpoints, spp;
    int rays;
    const char *csv, *plot;
    int scaling;
    size_t sizes[MAX_SIZES];
    int nsizes;
} bench_args;

static const char *const stage_csv[ATRBVH_STAGE_COUNT] = {
    "bounds_ms", "morton_ms", "sort_ms", "hierarchy_ms",
    "refit_ms", "optimise_ms", "collapse_ms", "layout_ms"};

/* ------------------------------------------------------------- helpers */
static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, size_t n)
{
    if (n == 0)
        return NAN;
    qsort(v, n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Shortest of %.15g / %.17g that reads back as v (as json_double). */
static void put_double(FILE *f, double v)
{
    char buf[40];
    if (!isfinite(v))
        return; /* empty field */
    snprintf(buf, sizeof buf, "%.15g", v);
    if (strtod(buf, NULL) != v)
        snprintf(buf, sizeof buf, "%.17g", v);
    fputs(buf, f);
}

static void put_csv_string(FILE *f, const char *s)
{
    if (strpbrk(s, ",\"\n\r")) {
        fputc('"', f);
        for (; *s; s++) {
            if (*s == '"')
                fputc('"', f);
            fputc(*s, f);
        }
        fputc('"', f);
    } else {
        fputs(s, f);
    }
}

static const char *backend_name(atrbvh_backend b)
{
    return b == ATRBVH_BACKEND_OPENCL ? "opencl" : "cpu";
}

static const char *row_method(const row *r)
{
    return r->c.embree ? embree_quality_name(r->c.eq)
                       : cli_method_name(r->c.method);
}

static void config_label(const config *c, unsigned treelet, unsigned rounds,
                         char *buf, size_t n)
{
    if (c->embree)
        snprintf(buf, n, "%s", embree_quality_name(c->eq));
    else if (c->method == ATRBVH_METHOD_LBVH)
        snprintf(buf, n, "LBVH%s",
                 c->backend == ATRBVH_BACKEND_OPENCL ? "/cl" : "");
    else
        snprintf(buf, n, "%s(%u,%u)%s",
                 c->method == ATRBVH_METHOD_TRBVH ? "TRBVH" : "ATRBVH",
                 treelet, rounds,
                 c->backend == ATRBVH_BACKEND_OPENCL ? "/cl" : "");
}

/* The scene's name without directories or extension, for file names. */
static void scene_tag(const char *spec, char *buf, size_t n)
{
    const char *s = strrchr(spec, '/');
    size_t k = 0;
    s = s ? s + 1 : spec;
    for (; *s && k + 1 < n; s++) {
        if (*s == '.' && strchr(s + 1, '.') == NULL)
            break;
        buf[k++] = isalnum((unsigned char)*s) ? *s : '_';
    }
    buf[k] = '\0';
}

/* ---------------------------------------------------- parsing configs */
static int add_config(bench_args *a, const config *c)
{
    int k;
    for (k = 0; k < a->nconfigs; k++)
        if (memcmp(&a->configs[k], c, sizeof *c) == 0)
            return 0; /* once each */
    if (a->nconfigs == MAX_CONFIGS)
        return cli_usage("bench", "more than %d configurations",
                         MAX_CONFIGS), -1;
    a->configs[a->nconfigs++] = *c;
    return 0;
}

static int parse_uint_list(const char *opt, const char *s, unsigned long max,
                           unsigned long *out, int *n, int cap)
{
    char buf[512], *tok, *save = NULL;
    if (strlen(s) >= sizeof buf)
        return cli_usage("bench", "%s: list too long", opt), -1;
    strcpy(buf, s);
    *n = 0;
    for (tok = strtok_r(buf, ",", &save); tok;
         tok = strtok_r(NULL, ",", &save)) {
        if (*n == cap)
            return cli_usage("bench", "%s: more than %d values", opt, cap),
                   -1;
        if (!cli_parse_ulong(tok, max, &out[*n]))
            return cli_usage("bench", "%s: '%s' is not a whole number from "
                             "0 to %lu", opt, tok, max), -1;
        (*n)++;
    }
    if (*n == 0)
        return cli_usage("bench", "%s: empty list", opt), -1;
    return 0;
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

/* "lbvh", "trbvh[:N[:R]]", "atrbvh[:N[:R]]", "fast|balanced|high",
 * "embree" (all three), "embree_low|medium|high"; each with an optional
 * "@opencl" or "@cpu" for the library's configurations. */
static int parse_configs(bench_args *a, const char *s, atrbvh_backend be)
{
    char buf[1024], *tok, *save = NULL;
    if (strlen(s) >= sizeof buf)
        return cli_usage("bench", "--configs: list too long"), -1;
    strcpy(buf, s);
    for (tok = strtok_r(buf, ",", &save); tok;
         tok = strtok_r(NULL, ",", &save)) {
        config c;
        char *at = strchr(tok, '@'), *p;
        unsigned long v;
        memset(&c, 0, sizeof c);
        c.backend = be;
        if (at) {
            *at++ = '\0';
            if (strcmp(at, "cpu") == 0)
                c.backend = ATRBVH_BACKEND_CPU;
            else if (strcmp(at, "opencl") == 0)
                c.backend = ATRBVH_BACKEND_OPENCL;
            else
                return cli_usage("bench", "--configs: unknown backend '%s'",
                                 at), -1;
        }
        if (strcmp(tok, "embree") == 0 || strncmp(tok, "embree_", 7) == 0) {
            int q, lo = 0, hi = 2;
            if (tok[6] == '_') {
                if (strcmp(tok + 7, "low") == 0)
                    lo = hi = 0;
                else if (strcmp(tok + 7, "medium") == 0)
                    lo = hi = 1;
                else if (strcmp(tok + 7, "high") == 0)
                    lo = hi = 2;
                else
                    return cli_usage("bench", "--configs: unknown '%s'", tok),
                           -1;
            }
            if (!embree_available())
                continue; /* the header says so */
            for (q = lo; q <= hi; q++) {
                memset(&c, 0, sizeof c);
                c.embree = 1;
                c.eq = (embree_quality)q;
                if (add_config(a, &c) != 0)
                    return -1;
            }
            continue;
        }
        if (cli_quality_preset(tok, &c.method, &c.treelet, &c.rounds)) {
            if (add_config(a, &c) != 0)
                return -1;
            continue;
        }
        p = strchr(tok, ':');
        if (p)
            *p++ = '\0';
        if (strcmp(tok, "lbvh") == 0)
            c.method = ATRBVH_METHOD_LBVH;
        else if (strcmp(tok, "trbvh") == 0)
            c.method = ATRBVH_METHOD_TRBVH;
        else if (strcmp(tok, "atrbvh") == 0)
            c.method = ATRBVH_METHOD_ATRBVH;
        else
            return cli_usage("bench", "--configs: unknown method '%s'", tok),
                   -1;
        if (p && c.method != ATRBVH_METHOD_LBVH) {
            char *r = strchr(p, ':');
            if (r)
                *r++ = '\0';
            if (!cli_parse_ulong(p, 64, &v) || v == 0)
                return cli_usage("bench", "--configs: treelet size '%s' is "
                                 "not a whole number from 1 to 64", p), -1;
            c.treelet = (unsigned)v;
            if (r) {
                if (!cli_parse_ulong(r, 64, &v) || v == 0)
                    return cli_usage("bench", "--configs: rounds '%s' is not "
                                     "a whole number from 1 to 64", r), -1;
                c.rounds = (unsigned)v;
            }
        } else if (p) {
            return cli_usage("bench", "--configs: lbvh takes no treelet "
                             "size"), -1;
        }
        if (add_config(a, &c) != 0)
            return -1;
    }
    return 0;
}

/* ------------------------------------------------------------ building */
typedef struct scene_data {
    scene sc;
    atrbvh_geometry g;
    ray_set rays;
    int have_rays;
} scene_data;

static size_t bvh_bytes(const atrbvh_stats *s)
{
    return s->nodes * sizeof(atrbvh_node) + s->primitives * sizeof(uint32_t);
}

static int lib_build(const scene_data *sd, const atrbvh_build_options *o,
                     atrbvh_bvh **out, const char *spec)
{
    atrbvh_error e;
    atrbvh_status st;
    memset(&e, 0, sizeof e);
    st = atrbvh_build(&sd->g, o, out, &e);
    if (st != ATRBVH_OK) {
        *out = NULL;
        cli_error("%s: %s", spec, e.text[0] ? e.text : atrbvh_strerror(st));
        return -1;
    }
    return 0;
}

/* Traces the scene's rays through `bvh` `repeat` times; median Mrays/s per
 * kind. */
static int lib_trace(const scene_data *sd, const atrbvh_bvh *bvh, int threads,
                     unsigned long repeat, double mrays[3])
{
    const ray_set *rs = &sd->rays;
    size_t cap = rs->n_primary > rs->n_diffuse ? rs->n_primary : rs->n_diffuse;
    atrbvh_hit *hits = malloc((cap ? cap : 1) * sizeof *hits);
    uint8_t *occ = malloc(cap ? cap : 1);
    double *t = malloc(repeat * sizeof *t);
    int kind, rc = -1;
    unsigned long r;
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
        mrays[kind] = (double)n / (median(t, repeat) * 1e3);
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

/* One configuration on one scene.  0; 1 when the configuration is not
 * available (skipped, noted); -1 after an error line. */
static int run_config(const bench_args *a, scene_data *sd, const char *spec,
                      const config *c, embree_ctx *emb, int do_rays,
                      unsigned long repeat, int warmup, int binary, row *r)
{
    double *tot = malloc((repeat + 1) * sizeof *tot);
    double *stg = malloc((repeat + 1) * ATRBVH_STAGE_COUNT * sizeof *stg);
    atrbvh_bvh *bvh = NULL;
    unsigned long k;
    int s, rc = -1;
    memset(r, 0, sizeof *r);
    r->c = *c;
    r->scene = spec;
    r->triangles = sd->sc.triangle_count;
    r->rel_pct = r->time_pct = r->sah_pct = NAN;
    for (s = 0; s < 3; s++)
        r->mrays[s] = r->emb_mrays[s] = NAN;
    r->emb_commit_ms = NAN;
    r->total_mrays = NAN;
    if (!tot || !stg) {
        cli_error("out of memory");
        goto done;
    }
    if (!c->embree) {
        atrbvh_build_options o = a->base;
        atrbvh_stats st;
        o.method = c->method;
        o.treelet_size = c->treelet;
        o.rounds = c->rounds;
        o.backend = c->backend;
        if (c->backend == ATRBVH_BACKEND_OPENCL) {
            atrbvh_error e;
            atrbvh_status x;
            memset(&e, 0, sizeof e);
            x = atrbvh_build(&sd->g, &o, &bvh, &e);
            if (x == ATRBVH_ERR_UNSUPPORTED || x == ATRBVH_ERR_BACKEND) {
                char label[64];
                config_label(c, c->treelet, c->rounds, label, sizeof label);
                fprintf(stderr, "atrbvh: bench: %s skipped: %s\n", label,
                        e.text[0] ? e.text : atrbvh_strerror(x));
                rc = 1;
                goto done;
            }
            atrbvh_bvh_free(bvh);
            bvh = NULL;
        }
        for (k = 0; k < repeat + (warmup ? 1 : 0); k++) {
            size_t peak;
            atrbvh_bvh_free(bvh);
            bvh = NULL;
            memtrack_reset_peak();
            {
                size_t before = memtrack_current();
                if (lib_build(sd, &o, &bvh, spec) != 0)
                    goto done;
                peak = memtrack_peak() - before;
            }
            if (peak > r->peak)
                r->peak = peak;
            atrbvh_bvh_stats(bvh, &st);
            if (warmup && k == 0)
                continue;
            tot[k - (warmup ? 1 : 0)] = st.build_ms;
            for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
                stg[s * repeat + k - (warmup ? 1 : 0)] =
                    atrbvh_bvh_stage_ms(bvh, (atrbvh_stage)s);
        }
        r->threads = st.threads;
        r->treelet = st.treelet_size;
        r->rounds = st.rounds;
        r->sah = st.sah;
        r->nodes = st.nodes;
        r->leaves = st.leaves;
        r->bvh_bytes = bvh_bytes(&st);
        r->build_min_ms = tot[0];
        for (k = 1; k < repeat; k++)
            if (tot[k] < r->build_min_ms)
                r->build_min_ms = tot[k];
        r->build_ms = median(tot, repeat);
        for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
            r->stage_ms[s] = median(stg + s * repeat, repeat);
        /* the binary tree */
        r->sah_binary = NAN;
        if (binary) {
            atrbvh_bvh *bin = NULL;
            atrbvh_stats bs;
            o.collapse = 0;
            o.max_leaf_size = 0;
            if (lib_build(sd, &o, &bin, spec) != 0)
                goto done;
            atrbvh_bvh_stats(bin, &bs);
            r->sah_binary = bs.sah;
            atrbvh_bvh_free(bin);
        }
    } else {
        embree_build_result res;
        atrbvh_stats st;
        size_t nn;
        const atrbvh_node *nodes;
        for (k = 0; k < repeat + (warmup ? 1 : 0); k++) {
            atrbvh_bvh_free(bvh);
            bvh = NULL;
            if (embree_build(emb, &sd->sc, c->eq, a->base.max_leaf_size,
                             a->base.ci, a->base.ct, &res) != 0)
                goto done;
            bvh = res.bvh;
            if (res.peak_bytes > r->peak)
                r->peak = res.peak_bytes;
            if (warmup && k == 0)
                continue;
            tot[k - (warmup ? 1 : 0)] = res.build_ms;
        }
        atrbvh_bvh_stats(bvh, &st);
        nodes = atrbvh_bvh_nodes(bvh, &nn);
        r->threads = a->base.threads > 0 ? a->base.threads :
#ifdef _OPENMP
                                         omp_get_max_threads();
#else
                                         1;
#endif
        r->sah = atrbvh_sah(nodes, nn, a->base.ci, a->base.ct);
        r->nodes = st.nodes;
        r->leaves = st.leaves;
        r->bvh_bytes = bvh_bytes(&st);
        r->build_min_ms = tot[0];
        for (k = 1; k < repeat; k++)
            if (tot[k] < r->build_min_ms)
                r->build_min_ms = tot[k];
        r->build_ms = median(tot, repeat);
        for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
            r->stage_ms[s] = NAN;
        {
            embree_build_result bin;
            size_t bn;
            const atrbvh_node *bnodes;
            if (embree_build(emb, &sd->sc, c->eq, 1, a->base.ci, a->base.ct,
                             &bin) != 0)
                goto done;
            bnodes = atrbvh_bvh_nodes(bin.bvh, &bn);
            r->sah_binary = atrbvh_sah(bnodes, bn, a->base.ci, a->base.ct);
            atrbvh_bvh_free(bin.bvh);
        }
        if (do_rays && sd->have_rays &&
            embree_trace(emb, &sd->sc, c->eq, &sd->rays, a->base.threads,
                         r->emb_mrays, &r->emb_commit_ms) != 0)
            goto done;
        if (do_rays && sd->have_rays) {
            const size_t n[3] = {sd->rays.n_primary, sd->rays.n_ao,
                                 sd->rays.n_diffuse};
            for (s = 0; s < 3; s++)
                r->emb_mrays[s] = n[s] && r->emb_mrays[s] > 0.0
                                      ? (double)n[s] / (r->emb_mrays[s] * 1e3)
                                      : NAN;
        }
    }
    if (do_rays && sd->have_rays) {
        if (lib_trace(sd, bvh, a->base.threads, repeat, r->mrays) != 0)
            goto done;
        r->total_mrays = total_mrays(sd, r->mrays);
    }
    rc = 0;
done:
    atrbvh_bvh_free(bvh);
    free(tot);
    free(stg);
    return rc;
}

/* -------------------------------------------------------------- output */
static void csv_header(FILE *f)
{
    int s;
    fputs("scene,triangles,method,treelet_size,rounds,backend,threads,"
          "max_leaf,repeat,build_ms,build_min_ms",
          f);
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
        fprintf(f, ",%s", stage_csv[s]);
    fputs(",sah,sah_binary,nodes,leaves,peak_bytes,bvh_bytes,primary_mrays,"
          "ao_mrays,diffuse_mrays,total_mrays,relative_pct,time_pct,sah_pct,"
          "embree_primary_mrays,embree_ao_mrays,embree_diffuse_mrays,"
          "embree_commit_ms\n",
          f);
}

static void csv_row(FILE *f, const bench_args *a, const row *r)
{
    int s;
    put_csv_string(f, r->scene);
    fprintf(f, ",%zu,%s,%u,%u,%s,%d,%u,%lu,", r->triangles, row_method(r),
            r->treelet, r->rounds,
            r->c.embree ? "embree" : backend_name(r->c.backend), r->threads,
            a->base.max_leaf_size, a->repeat);
    put_double(f, r->build_ms);
    fputc(',', f);
    put_double(f, r->build_min_ms);
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++) {
        fputc(',', f);
        put_double(f, r->stage_ms[s]);
    }
    fputc(',', f);
    put_double(f, r->sah);
    fputc(',', f);
    put_double(f, r->sah_binary);
    fprintf(f, ",%zu,%zu,%zu,%zu", r->nodes, r->leaves, r->peak,
            r->bvh_bytes);
    for (s = 0; s < 3; s++) {
        fputc(',', f);
        put_double(f, r->mrays[s]);
    }
    fputc(',', f);
    put_double(f, r->total_mrays);
    fputc(',', f);
    put_double(f, r->rel_pct);
    fputc(',', f);
    put_double(f, r->time_pct);
    fputc(',', f);
    put_double(f, r->sah_pct);
    for (s = 0; s < 3; s++) {
        fputc(',', f);
        put_double(f, r->emb_mrays[s]);
    }
    fputc(',', f);
    put_double(f, r->emb_commit_ms);
    fputc('\n', f);
}

static void text_num(FILE *f, const char *fmt, double v, int width)
{
    if (isfinite(v))
        fprintf(f, fmt, width, v);
    else
        fprintf(f, "%*s", width, "-");
}

static void text_table(FILE *f, const row *rows, int n, int have_rays)
{
    int i;
    fprintf(f, "%-18s %9s %9s %9s %9s %9s %8s", "config", "build ms",
            "opt ms", "SAH", "SAH bin", "nodes", "peak MB");
    if (have_rays)
        fprintf(f, " %7s %7s %7s %7s %8s", "prim", "ao", "diff", "all",
                "rel %");
    fprintf(f, " %7s %7s\n", "time %", "SAH %");
    for (i = 0; i < n; i++) {
        const row *r = &rows[i];
        char label[64];
        config_label(&r->c, r->treelet, r->rounds, label, sizeof label);
        fprintf(f, "%-18s", label);
        text_num(f, " %*.1f", r->build_ms, 9);
        text_num(f, " %*.1f", r->stage_ms[ATRBVH_STAGE_OPTIMISE], 9);
        text_num(f, " %*.3f", r->sah, 9);
        text_num(f, " %*.3f", r->sah_binary, 9);
        fprintf(f, " %9zu", r->nodes);
        text_num(f, " %*.1f", (double)r->peak / 1048576.0, 8);
        if (have_rays) {
            text_num(f, " %*.2f", r->mrays[0], 7);
            text_num(f, " %*.2f", r->mrays[1], 7);
            text_num(f, " %*.2f", r->mrays[2], 7);
            text_num(f, " %*.2f", r->total_mrays, 7);
            text_num(f, " %*.1f", r->rel_pct, 8);
        }
        text_num(f, " %*.1f", r->time_pct, 7);
        text_num(f, " %*.1f", r->sah_pct, 7);
        fputc('\n', f);
    }
    if (have_rays) {
        int any = 0;
        for (i = 0; i < n; i++) {
            const row *r = &rows[i];
            if (!r->c.embree || !isfinite(r->emb_mrays[0]))
                continue;
            if (!any)
                fprintf(f, "Embree's own traversal (rtcIntersect1/"
                           "rtcOccluded1), Mrays/s:\n");
            any = 1;
            fprintf(f, "  %-16s", embree_quality_name(r->c.eq));
            text_num(f, " prim %*.2f", r->emb_mrays[0], 7);
            text_num(f, " ao %*.2f", r->emb_mrays[1], 7);
            text_num(f, " diff %*.2f", r->emb_mrays[2], 7);
            text_num(f, "   (scene commit %*.1f ms)\n", r->emb_commit_ms, 1);
        }
    }
}

/* --------------------------------------------------------------- plots */
static int plot_path_ok(const char *dir)
{
    return strchr(dir, '\'') == NULL && strchr(dir, '\n') == NULL;
}

static FILE *open_in(const char *dir, const char *name, char *path,
                     size_t n)
{
    FILE *f;
    snprintf(path, n, "%s/%s", dir, name);
    f = fopen(path, "w");
    if (!f)
        cli_error("%s: %s", path, strerror(errno));
    return f;
}

static int run_gnuplot(const char *dir, const char *script)
{
    char cmd[4200];
    int st;
    snprintf(cmd, sizeof cmd, "cd '%s' && gnuplot '%s' 2>gnuplot.log", dir,
             script);
    st = system(cmd);
    if (st != 0) {
        cli_error("%s/%s: gnuplot failed (is gnuplot installed? see "
                  "%s/gnuplot.log)", dir, script, dir);
        return -1;
    }
    return 0;
}

/* Both terminals; `body` is the plot commands, %s the output's stem. */
static void gp_both(FILE *g, const char *stem, const char *body)
{
    fprintf(g,
            "set terminal pngcairo size 900,600 font 'sans,10'\n"
            "set output '%s.png'\n%s\n"
            "set terminal svg size 900,600 dynamic font 'sans,10'\n"
            "set output '%s.svg'\nreplot\nunset output\n",
            stem, body, stem);
}

static int is_dominated(const row *rows, int n, int i)
{
    int j;
    for (j = 0; j < n; j++)
        if (j != i && rows[j].build_ms <= rows[i].build_ms &&
            rows[j].sah <= rows[i].sah &&
            (rows[j].build_ms < rows[i].build_ms ||
             rows[j].sah < rows[i].sah))
            return 1;
    return 0;
}

static int cmp_row_time(const void *a, const void *b)
{
    const row *x = *(row *const *)a, *y = *(row *const *)b;
    return x->build_ms < y->build_ms ? -1 : x->build_ms > y->build_ms;
}

static int plot_scene(const char *dir, const char *spec, const row *rows,
                      int n, int have_rays)
{
    char tag[64], name[128], path[4200], body[4096];
    FILE *f, *g;
    const row **front;
    int i, nf = 0, pass;
    const char *base = strrchr(spec, '/') ? strrchr(spec, '/') + 1 : spec;
    scene_tag(spec, tag, sizeof tag);
    snprintf(name, sizeof name, "bench-%s.dat", tag);
    if (!(f = open_in(dir, name, path, sizeof path)))
        return -1;
    /* index 0: atrbvh configurations, 1: Embree, 2: the Pareto front */
    for (pass = 0; pass < 2; pass++) {
        fprintf(f, "# %s\n# label build_ms sah total_mrays\n",
                pass ? "embree" : "atrbvh");
        for (i = 0; i < n; i++) {
            char label[64];
            if (rows[i].c.embree != pass)
                continue;
            config_label(&rows[i].c, rows[i].treelet, rows[i].rounds, label,
                         sizeof label);
            /* column 5: the label drawn; with many points only those on
             * the front and Embree's */
            fprintf(f, "\"%s\" %.6g %.9g %.6g \"%s\"\n", label,
                    rows[i].build_ms, rows[i].sah,
                    isfinite(rows[i].total_mrays) ? rows[i].total_mrays : 0.0,
                    n <= 14 || pass || !is_dominated(rows, n, i) ? label
                                                                 : "");
        }
        fputs("\n\n", f);
    }
    front = malloc((size_t)(n ? n : 1) * sizeof *front);
    if (!front) {
        fclose(f);
        cli_error("out of memory");
        return -1;
    }
    for (i = 0; i < n; i++)
        if (!is_dominated(rows, n, i))
            front[nf++] = &rows[i];
    qsort(front, (size_t)nf, sizeof *front, cmp_row_time);
    fputs("# pareto front\n", f);
    for (i = 0; i < nf; i++)
        fprintf(f, "\"-\" %.6g %.9g 0 \"\"\n", front[i]->build_ms,
                front[i]->sah);
    free(front);
    if (fclose(f) != 0) {
        cli_error("%s: %s", path, strerror(errno));
        return -1;
    }
    snprintf(name, sizeof name, "bench-%s.gp", tag);
    if (!(g = open_in(dir, name, path, sizeof path)))
        return -1;
    fprintf(g, "# regenerate: gnuplot %s (in this folder)\n", name);
    snprintf(body, sizeof body,
             "set title \"%s: build time against SAH (lower left is better)\" "
             "noenhanced\n"
             "set xlabel 'build time, ms (median; log scale)'\n"
             "set ylabel 'SAH cost (collapsed, max leaf as run)'\n"
             "set logscale x\nset grid\nset key top right\n"
             "plot 'bench-%s.dat' index 2 using 2:3 with steps lw 1 lc "
             "rgb '#999999' title 'Pareto front', \\\n"
             "  '' index 0 using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' "
             "title 'atrbvh', \\\n"
             "  '' index 0 using 2:3:5 with labels offset 0.6,0.6 left "
             "font ',8' noenhanced notitle, \\\n"
             "  '' index 1 using 2:3 with points pt 5 ps 1.2 lc rgb '#d62728' "
             "title 'Embree (rtcBuildBVH)', \\\n"
             "  '' index 1 using 2:3:5 with labels offset 0.6,-0.6 left "
             "font ',8' noenhanced notitle",
             base, tag);
    {
        char stem[128];
        snprintf(stem, sizeof stem, "pareto-%s", tag);
        gp_both(g, stem, body);
    }
    if (have_rays) {
        char stem[128];
        fputs("reset\n", g);
        snprintf(body, sizeof body,
                 "set title \"%s: ray throughput (our traverser, primary+AO+"
                 "diffuse) against build time\" noenhanced\n"
                 "set xlabel 'build time, ms (median; log scale)'\n"
                 "set ylabel 'Mrays/s, all threads'\n"
                 "set logscale x\nset grid\nset key bottom right\n"
                 "plot 'bench-%s.dat' index 0 using 2:4 with points pt 7 ps "
                 "1.2 lc rgb '#1f77b4' title 'atrbvh', \\\n"
                 "  '' index 0 using 2:4:5 with labels offset 0.6,0.6 left "
                 "font ',8' noenhanced notitle, \\\n"
                 "  '' index 1 using 2:4 with points pt 5 ps 1.2 lc rgb "
                 "'#d62728' title 'Embree tree, our traverser', \\\n"
                 "  '' index 1 using 2:4:5 with labels offset 0.6,-0.6 left "
                 "font ',8' noenhanced notitle",
                 base, tag);
        snprintf(stem, sizeof stem, "rays-%s", tag);
        gp_both(g, stem, body);
    }
    if (fclose(g) != 0) {
        cli_error("%s: %s", path, strerror(errno));
        return -1;
    }
    return run_gnuplot(dir, name);
}

/* -------------------------------------------------------- the sweep */
static int find_ref(const row *rows, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!rows[i].c.embree && rows[i].c.method == ATRBVH_METHOD_TRBVH &&
            rows[i].treelet == 7 && rows[i].rounds == 3 &&
            rows[i].c.backend == ATRBVH_BACKEND_CPU)
            return i;
    return -1;
}

static void print_header(FILE *f, const bench_args *a)
{
    int threads =
#ifdef _OPENMP
        a->base.threads > 0 ? a->base.threads : omp_get_max_threads();
#else
        1;
#endif
    fprintf(f, "# atrbvh bench %s, %d thread%s, max leaf %u, ci %g, ct %g, "
               "median of %lu run%s after a warm-up\n",
            atrbvh_version_string(), threads, threads == 1 ? "" : "s",
            a->base.max_leaf_size, a->base.ci, a->base.ct, a->repeat,
            a->repeat == 1 ? "" : "s");
    if (embree_available())
        fprintf(f, "# Embree %s: rtcBuildBVH (binary, same leaf limit and "
                   "costs) traced by our traverser; own rtcIntersect1 "
                   "listed apart\n",
                embree_version());
    else
        fprintf(f, "# Embree: not available (built without Embree); no "
                   "Embree rows\n");
    {
        const char *wp = getenv("OMP_WAIT_POLICY");
        fprintf(f, "# OMP_WAIT_POLICY=%s\n",
                wp ? wp : "(unset: OpenMP threads spin at barriers; on a "
                          "loaded machine set it to passive)");
    }
    {
        double l[3];
        FILE *la = fopen("/proc/loadavg", "r");
        if (la) {
            if (fscanf(la, "%lf %lf %lf", &l[0], &l[1], &l[2]) == 3)
                fprintf(f, "# load average at start %.2f %.2f %.2f\n", l[0],
                        l[1], l[2]);
            fclose(la);
        }
    }
}

static int load_scene(const char *spec, scene_data *sd)
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

static void free_scene(scene_data *sd)
{
    ray_set_free(&sd->rays);
    scene_free(&sd->sc);
}

static int bench_sweep(bench_args *a, FILE *csv)
{
    int si, rc = CLI_OK;
    embree_ctx *emb = NULL;
    row *rows = malloc((size_t)a->nconfigs * sizeof *rows);
    if (!rows) {
        cli_error("out of memory");
        return CLI_FAIL;
    }
    print_header(stdout, a);
    if (embree_available()) {
        emb = embree_open(a->base.threads);
        if (!emb) {
            free(rows);
            return CLI_FAIL;
        }
    }
    for (si = 0; si < a->nscenes && rc == CLI_OK; si++) {
        scene_data sd;
        int i, n = 0, ref;
        if (load_scene(a->scenes[si], &sd) != 0) {
            free_scene(&sd);
            rc = CLI_FAIL;
            break;
        }
        if (a->rays && a->spp + 1 > 0) {
            atrbvh_bvh *lb = NULL;
            atrbvh_build_options o = a->base;
            o.method = ATRBVH_METHOD_LBVH;
            if (lib_build(&sd, &o, &lb, a->scenes[si]) != 0 ||
                ray_set_make(&sd.sc, lb, (unsigned)a->width,
                             (unsigned)a->height, (unsigned)a->viewpoints,
                             (unsigned)a->spp, a->base.threads,
                             &sd.rays) != 0) {
                atrbvh_bvh_free(lb);
                free_scene(&sd);
                rc = CLI_FAIL;
                break;
            }
            atrbvh_bvh_free(lb);
            sd.have_rays = 1;
        }
        printf("\n## %s: %zu triangles", a->scenes[si], sd.sc.triangle_count);
        if (sd.have_rays)
            printf("; rays: %zu primary (%lux%lu, viewpoints 0..%lu), %zu "
                   "ao, %zu diffuse",
                   sd.rays.n_primary, a->width, a->height, a->viewpoints - 1,
                   sd.rays.n_ao, sd.rays.n_diffuse);
        printf("\n");
        fflush(stdout);
        for (i = 0; i < a->nconfigs; i++) {
            int r = run_config(a, &sd, a->scenes[si], &a->configs[i], emb,
                               a->rays, a->repeat, 1, 1, &rows[n]);
            if (r < 0) {
                rc = CLI_FAIL;
                break;
            }
            if (r == 0)
                n++;
        }
        if (rc != CLI_OK) {
            free_scene(&sd);
            break;
        }
        ref = find_ref(rows, n);
        for (i = 0; i < n && ref >= 0; i++) {
            /* (x / ref) * 100, so that the reference is exactly 100 */
            rows[i].time_pct = rows[i].build_ms / rows[ref].build_ms * 100.0;
            rows[i].sah_pct = rows[i].sah / rows[ref].sah * 100.0;
            if (sd.have_rays)
                rows[i].rel_pct =
                    rows[i].total_mrays / rows[ref].total_mrays * 100.0;
        }
        text_table(stdout, rows, n, sd.have_rays);
        for (i = 0; i < n; i++) {
            char label[64];
            if (!rows[i].c.embree)
                continue;
            config_label(&rows[i].c, 0, 0, label, sizeof label);
            {
                int j, best = -1;
                for (j = 0; j < n; j++)
                    if (!rows[j].c.embree &&
                        rows[j].build_ms <= rows[i].build_ms &&
                        rows[j].sah < rows[i].sah &&
                        (best < 0 || rows[j].sah < rows[best].sah))
                        best = j;
                if (best >= 0) {
                    char bl[64];
                    config_label(&rows[best].c, rows[best].treelet,
                                 rows[best].rounds, bl, sizeof bl);
                    printf("%s (%.1f ms, SAH %.3f) is dominated by %s (%.1f "
                           "ms, SAH %.3f)\n",
                           label, rows[i].build_ms, rows[i].sah, bl,
                           rows[best].build_ms, rows[best].sah);
                } else {
                    printf("%s (%.1f ms, SAH %.3f) is not dominated by any "
                           "atrbvh configuration run\n",
                           label, rows[i].build_ms, rows[i].sah);
                }
            }
        }
        if (csv)
            for (i = 0; i < n; i++)
                csv_row(csv, a, &rows[i]);
        fflush(stdout);
        if (a->plot &&
            plot_scene(a->plot, a->scenes[si], rows, n, sd.have_rays) != 0)
            rc = CLI_FAIL;
        free_scene(&sd);
    }
    embree_close(emb);
    free(rows);
    return rc;
}

/* ------------------------------------------------------------- scaling */
/* A scene of about `target` triangles from `base`: builtin scenes are
 * generated at that size; a file's mesh is cut to its first `target`
 * triangles when it is larger, or copied into a g x g x g grid (offsets of
 * 1.1 x its extent) of round(target / T) copies. */
static int scaled_scene(const char *spec, const scene *base, size_t target,
                        scene *out, size_t *copies)
{
    char err[512];
    *copies = 1;
    memset(out, 0, sizeof *out);
    if (strncmp(spec, "builtin:", 8) == 0) {
        char name[64];
        const char *p = spec + 8, *q = strchr(p, ':');
        size_t len = q ? (size_t)(q - p) : strlen(p);
        if (len >= sizeof name)
            len = sizeof name - 1;
        memcpy(name, p, len);
        name[len] = '\0';
        if (scene_builtin(name, target, out, err, sizeof err) != 0) {
            cli_error("%s", err);
            return -1;
        }
        return 0;
    }
    {
        size_t t = base->triangle_count, c, g, i, k;
        float lo[3], hi[3], step[3];
        if (target <= t) {
            out->vertices = malloc(base->vertex_count * 12);
            out->indices = malloc(target * 12);
            if (!out->vertices || !out->indices)
                goto oom;
            memcpy(out->vertices, base->vertices, base->vertex_count * 12);
            memcpy(out->indices, base->indices, target * 12);
            out->vertex_count = base->vertex_count;
            out->triangle_count = target;
            snprintf(out->name, sizeof out->name, "%s", base->name);
            return 0;
        }
        c = (target + t / 2) / t;
        for (g = 1; g * g * g < c; g++)
            ;
        scene_bounds(base, lo, hi);
        for (k = 0; k < 3; k++)
            step[k] = 1.1f * (hi[k] - lo[k]);
        if (c * base->vertex_count > UINT32_MAX) {
            cli_error("%s: %zu copies are too many vertices", spec, c);
            return -1;
        }
        out->vertices = malloc(c * base->vertex_count * 12);
        out->indices = malloc(c * t * 12);
        if (!out->vertices || !out->indices)
            goto oom;
        for (i = 0; i < c; i++) {
            size_t gx = i % g, gy = (i / g) % g, gz = i / (g * g), v;
            float off[3];
            float *dv = out->vertices + i * base->vertex_count * 3;
            uint32_t *di = out->indices + i * t * 3;
            uint32_t shift = (uint32_t)(i * base->vertex_count);
            off[0] = step[0] * (float)gx;
            off[1] = step[1] * (float)gy;
            off[2] = step[2] * (float)gz;
            for (v = 0; v < base->vertex_count; v++)
                for (k = 0; k < 3; k++)
                    dv[3 * v + k] = base->vertices[3 * v + k] + off[k];
            for (v = 0; v < 3 * t; v++)
                di[v] = base->indices[v] + shift;
        }
        out->vertex_count = c * base->vertex_count;
        out->triangle_count = c * t;
        snprintf(out->name, sizeof out->name, "%s", base->name);
        *copies = c;
        return 0;
    }
oom:
    scene_free(out);
    cli_error("out of memory for a scene of %zu triangles", target);
    return -1;
}

typedef struct fit {
    double slope, intercept;
    int n;
} fit;

/* Least squares of log(y) on log(x) over points with x >= xmin. */
static fit fit_loglog(const double *x, const double *y, int n, double xmin)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int i, m = 0;
    fit r;
    for (i = 0; i < n; i++) {
        double lx, ly;
        if (x[i] < xmin || !(y[i] > 0.0))
            continue;
        lx = log(x[i]);
        ly = log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        m++;
    }
    r.n = m;
    if (m < 2 || sxx * m - sx * sx == 0.0) {
        r.slope = r.intercept = NAN;
        return r;
    }
    r.slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    r.intercept = (sy - r.slope * sx) / m;
    return r;
}

static int bench_scaling(bench_args *a, FILE *csv)
{
    const char *defaults[] = {"builtin:sphere", "builtin:city"};
    const char **bases = a->nscenes ? a->scenes : defaults;
    int nb = a->nscenes ? a->nscenes : 2, b, ci, si, rc = CLI_OK, nser = 0;
    FILE *dat = NULL;
    char path[4200];
    row *rows = calloc((size_t)a->nsizes, sizeof *rows);
    double *xs = calloc((size_t)a->nsizes, sizeof *xs);
    double *ys = calloc((size_t)a->nsizes, sizeof *ys);
    if (!rows || !xs || !ys) {
        cli_error("out of memory");
        rc = CLI_FAIL;
        goto done;
    }
    print_header(stdout, a);
    printf("# scaling: median of %lu run%s (one run, no warm-up, above %d "
           "triangles)\n",
           a->repeat, a->repeat == 1 ? "" : "s", SCALING_SINGLE_RUN);
    if (csv)
        fputs("base,triangles,copies,method,treelet_size,rounds,threads,"
              "build_ms,bounds_ms,morton_ms,sort_ms,hierarchy_ms,refit_ms,"
              "optimise_ms,collapse_ms,layout_ms,sah,nodes,peak_bytes,"
              "bvh_bytes,peak_bytes_per_triangle,peak_over_bvh\n",
              csv);
    if (a->plot) {
        if (!(dat = open_in(a->plot, "scaling.dat", path, sizeof path))) {
            rc = CLI_FAIL;
            goto done;
        }
    }
    for (b = 0; b < nb && rc == CLI_OK; b++) {
        scene base;
        int is_builtin = strncmp(bases[b], "builtin:", 8) == 0;
        memset(&base, 0, sizeof base);
        if (!is_builtin) {
            char err[512];
            if (scene_load(bases[b], &base, err, sizeof err) != 0) {
                cli_error("%s", err);
                rc = CLI_FAIL;
                break;
            }
        }
        for (ci = 0; ci < a->nconfigs && rc == CLI_OK; ci++) {
            const config *c = &a->configs[ci];
            char label[64];
            int n = 0;
            fit f, fall, fs[ATRBVH_STAGE_COUNT];
            for (si = 0; si < a->nsizes; si++) {
                scene_data sd;
                size_t copies;
                int big = a->sizes[si] > SCALING_SINGLE_RUN, r;
                memset(&sd, 0, sizeof sd);
                if (scaled_scene(bases[b], &base, a->sizes[si], &sd.sc,
                                 &copies) != 0) {
                    rc = CLI_FAIL;
                    break;
                }
                sd.g = scene_geometry(&sd.sc);
                r = run_config(a, &sd, bases[b], c, NULL, 0,
                               big ? 1 : a->repeat, !big, 0, &rows[n]);
                if (r < 0) {
                    free_scene(&sd);
                    rc = CLI_FAIL;
                    break;
                }
                if (r == 0) {
                    row *w = &rows[n];
                    int s;
                    config_label(c, w->treelet, w->rounds, label,
                                 sizeof label);
                    printf("%-16s %-16s %10zu tri %5zu cop %10.1f ms "
                           "%8.1f B/tri peak/bvh %.2f\n",
                           bases[b], label, w->triangles, copies, w->build_ms,
                           (double)w->peak / (double)w->triangles,
                           (double)w->peak / (double)w->bvh_bytes);
                    fflush(stdout);
                    if (csv) {
                        put_csv_string(csv, bases[b]);
                        fprintf(csv, ",%zu,%zu,%s,%u,%u,%d,", w->triangles,
                                copies, row_method(w), w->treelet, w->rounds,
                                w->threads);
                        put_double(csv, w->build_ms);
                        for (s = 0; s < ATRBVH_STAGE_COUNT; s++) {
                            fputc(',', csv);
                            put_double(csv, w->stage_ms[s]);
                        }
                        fputc(',', csv);
                        put_double(csv, w->sah);
                        fprintf(csv, ",%zu,%zu,%zu,", w->nodes, w->peak,
                                w->bvh_bytes);
                        put_double(csv,
                                   (double)w->peak / (double)w->triangles);
                        fputc(',', csv);
                        put_double(csv,
                                   (double)w->peak / (double)w->bvh_bytes);
                        fputc('\n', csv);
                    }
                    n++;
                }
                free_scene(&sd);
            }
            if (rc != CLI_OK || n == 0)
                break;
            for (si = 0; si < n; si++) {
                xs[si] = (double)rows[si].triangles;
                ys[si] = rows[si].build_ms;
            }
            /* "from 1e5": builtin sizes come out a little under */
            f = fit_loglog(xs, ys, n, 0.9e5);
            fall = fit_loglog(xs, ys, n, 0.0);
            printf("%-16s %-16s build time ~ N^%.3f from 1e5 (%d points), "
                   "N^%.3f over all %d;",
                   bases[b], label, f.slope, f.n, fall.slope, fall.n);
            {
                int s;
                for (s = 0; s < ATRBVH_STAGE_COUNT; s++) {
                    double most = 0.0;
                    for (si = 0; si < n; si++) {
                        ys[si] = rows[si].stage_ms[s];
                        if (ys[si] > most)
                            most = ys[si];
                    }
                    if (!(most >= 0.1)) /* a stage that does nothing */
                        continue;
                    fs[s] = fit_loglog(xs, ys, n, 0.9e5);
                    if (isfinite(fs[s].slope))
                        printf(" %s %.2f",
                               atrbvh_stage_name((atrbvh_stage)s),
                               fs[s].slope);
                }
                printf("\n");
            }
            if (dat) {
                int s;
                fprintf(dat, "# %s %s (N^%.3f from 1e5)\n", bases[b], label,
                        f.slope);
                fprintf(dat, "# triangles build_ms stages... peak_per_tri\n");
                for (si = 0; si < n; si++) {
                    fprintf(dat, "%zu %.6g", rows[si].triangles,
                            rows[si].build_ms);
                    for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
                        fprintf(dat, " %.6g", rows[si].stage_ms[s]);
                    fprintf(dat, " %.6g\n", (double)rows[si].peak /
                                                (double)rows[si].triangles);
                }
                fputs("\n\n", dat);
                {
                    char t[160];
                    const char *bn = strrchr(bases[b], '/');
                    snprintf(t, sizeof t, "%s %s: N^{%.2f}",
                             bn ? bn + 1 : bases[b], label, f.slope);
                    /* titles kept in a side file for the script */
                    {
                        FILE *tf;
                        char tp[4200];
                        snprintf(tp, sizeof tp, "%s/scaling.titles",
                                 a->plot);
                        tf = fopen(tp, nser == 0 ? "w" : "a");
                        if (tf) {
                            fprintf(tf, "%s\n", t);
                            fclose(tf);
                        }
                    }
                }
                nser++;
            }
            fflush(stdout);
        }
        scene_free(&base);
    }
    if (dat) {
        FILE *g;
        int k, s;
        char tp[4200], line[160];
        FILE *tf;
        char titles[64][160];
        int nt = 0;
        fclose(dat);
        dat = NULL;
        snprintf(tp, sizeof tp, "%s/scaling.titles", a->plot);
        tf = fopen(tp, "r");
        while (tf && nt < 64 && fgets(line, sizeof line, tf)) {
            line[strcspn(line, "\n")] = '\0';
            snprintf(titles[nt++], sizeof titles[0], "%s", line);
        }
        if (tf)
            fclose(tf);
        remove(tp);
        if (rc != CLI_OK || nser == 0)
            goto done;
        if (!(g = open_in(a->plot, "scaling.gp", path, sizeof path))) {
            rc = CLI_FAIL;
            goto done;
        }
        {
            char body[8192];
            size_t off;
            off = (size_t)snprintf(
                body, sizeof body,
                "set title 'Build time against triangle count (log-log)'\n"
                "set xlabel 'triangles'\nset ylabel 'build time, ms'\n"
                "set logscale xy\nset grid\nset key top left\n"
                "set format x '10^{%%L}'\nplot ");
            for (k = 0; k < nser && off < sizeof body - 400; k++)
                off += (size_t)snprintf(
                    body + off, sizeof body - off,
                    "%s'scaling.dat' index %d using 1:2 with linespoints lw 2 "
                    "title '%s'",
                    k ? ", \\\n  " : "", k, titles[k]);
            gp_both(g, "scaling", body);
            fputs("reset\n", g);
            off = (size_t)snprintf(
                body, sizeof body,
                "set title 'Build time per stage, %s (log-log)'\n"
                "set xlabel 'triangles'\nset ylabel 'ms'\n"
                "set logscale xy\nset grid\nset key top left\n"
                "set format x '10^{%%L}'\nplot ",
                titles[nser - 1]);
            for (s = 0; s < ATRBVH_STAGE_COUNT && off < sizeof body - 400;
                 s++)
                off += (size_t)snprintf(
                    body + off, sizeof body - off,
                    "%s'scaling.dat' index %d using 1:%d with linespoints "
                    "title '%s'",
                    s ? ", \\\n  " : "", nser - 1, 3 + s,
                    atrbvh_stage_name((atrbvh_stage)s));
            gp_both(g, "scaling-stages", body);
            fputs("reset\n", g);
            off = (size_t)snprintf(
                body, sizeof body,
                "set title 'Peak library memory during the build, bytes per "
                "triangle'\nset xlabel 'triangles'\n"
                "set ylabel 'bytes per triangle'\nset logscale x\nset grid\n"
                "set key top right\nset yrange [0:*]\n"
                "set format x '10^{%%L}'\nplot ");
            for (k = 0; k < nser && off < sizeof body - 400; k++)
                off += (size_t)snprintf(
                    body + off, sizeof body - off,
                    "%s'scaling.dat' index %d using 1:%d with linespoints "
                    "lw 2 title '%s'",
                    k ? ", \\\n  " : "", k, 3 + ATRBVH_STAGE_COUNT,
                    titles[k]);
            gp_both(g, "scaling-memory", body);
        }
        if (fclose(g) != 0) {
            cli_error("%s: %s", path, strerror(errno));
            rc = CLI_FAIL;
            goto done;
        }
        if (run_gnuplot(a->plot, "scaling.gp") != 0)
            rc = CLI_FAIL;
    }
done:
    if (dat)
        fclose(dat);
    free(rows);
    free(xs);
    free(ys);
    return rc;
}

/* ---------------------------------------------------------------- main */
static void bench_help(FILE *f)
{
    fputs(
        "Usage: atrbvh bench [SCENE...] [OPTIONS]\n"
        "Build every configuration on each SCENE (default " DEFAULT_SCENE
        "),\n"
        "trace the same rays through each tree, and report build time (per\n"
        "stage), SAH, nodes, peak memory and rays per second, beside "
        "Embree.\n"
        "\n"
        "Configurations:\n"
        "  --configs LIST       comma-separated: lbvh, trbvh[:N[:R]],\n"
        "                       atrbvh[:N[:R]], fast, balanced, high, embree,\n"
        "                       embree_low, embree_medium, embree_high; "
        "@cpu or\n"
        "                       @opencl after one picks its backend\n"
        "                       (default " DEFAULT_CONFIGS ")\n"
        "  --methods LIST       instead of --configs: methods (lbvh, trbvh,\n"
        "                       atrbvh, embree) crossed with --treelet and\n"
        "                       --rounds\n"
        "  --treelet LIST       treelet sizes for --methods\n"
        "  --rounds LIST        rounds for --methods\n"
        "  --backend LIST       cpu, opencl (default cpu)\n"
        "  --quality PRESET     add fast, balanced or high to the list\n"
        "TRBVH(7,3) is always run: the relative columns are against it.\n"
        "\n"
        "Measurement:\n"
        "  --repeat K           timed runs per configuration after one "
        "warm-up\n"
        "                       (median; default 3)\n"
        "  --threads N          threads for builds and tracing (default: "
        "all)\n"
        "  --max-leaf N         leaf limit on both sides (default 8)\n"
        "  --ci X, --ct X       SAH costs (default 1.2, 1.0)\n"
        "  --width W, --height H  image size per viewpoint (default 256x192)\n"
        "  --viewpoints V       cameras 0..V-1 (default 3; see CAMERAS in "
        "atrbvh(1))\n"
        "  --spp N              AO and diffuse rays per primary hit (default "
        "2)\n"
        "  --no-rays            builds only\n"
        "\n"
        "Output:\n"
        "  --csv FILE           one row per configuration (columns: "
        "atrbvh(1))\n"
        "  --plot DIR           gnuplot PNG and SVG plots into DIR\n"
        "\n"
        "Scaling study:\n"
        "  --scaling            build time per stage and peak bytes against\n"
        "                       triangle count; SCENEs are the bases (builtin:"
        "NAME\n"
        "                       regenerated, files cut or replicated in a "
        "grid);\n"
        "                       default builtin:sphere builtin:city, "
        "configs\n"
        "                       " DEFAULT_SCALING_CONFIGS "\n"
        "  --sizes LIST         triangle counts (default " DEFAULT_SIZES ")\n"
        "\n"
        "  -h, --help           this help\n"
        "  --version            the version\n"
        "\n"
        "Exit status: 0 success, 1 bad input or failure, 2 usage error.\n",
        f);
}

int cli_bench(int argc, char **argv)
{
    static bench_args a;
    const char *configs = NULL, *methods = NULL, *treelets = NULL,
               *rounds = NULL, *backends = NULL, *qualities[8];
    int nq = 0, i = 1, rc, dashdash = 0, k;
    FILE *csv = NULL;
    atrbvh_backend be = ATRBVH_BACKEND_CPU;
    if ((rc = cli_help_or_version(argc, argv, bench_help)) >= 0)
        return rc;
    memset(&a, 0, sizeof a);
    atrbvh_build_options_init(&a.base);
    a.base.max_leaf_size = 8;
    a.repeat = 3;
    a.width = 256;
    a.height = 192;
    a.viewpoints = 3;
    a.spp = 2;
    a.rays = 1;
    while (i < argc) {
        const char *arg = argv[i], *v;
        int r;
        unsigned long u;
        long l;
        double d;
        if (dashdash || arg[0] != '-' || arg[1] == '\0') {
            if (a.nscenes == MAX_SCENES)
                return cli_usage("bench", "more than %d scenes", MAX_SCENES);
            a.scenes[a.nscenes++] = arg;
            i++;
            continue;
        }
        if (strcmp(arg, "--") == 0) {
            dashdash = 1;
            i++;
            continue;
        }
        if (strcmp(arg, "--no-rays") == 0) {
            a.rays = 0;
            i++;
            continue;
        }
        if (strcmp(arg, "--scaling") == 0) {
            a.scaling = 1;
            i++;
            continue;
        }
#define STR_OPT(NAME, VAR)                                                     \
    if ((r = cli_option("bench", argc, argv, &i, NAME, &v)) != 0) {            \
        if (r < 0)                                                             \
            return CLI_USAGE;                                                  \
        VAR = v;                                                               \
        continue;                                                              \
    }
#define UINT_OPT(NAME, VAR, MIN, MAX)                                          \
    if ((r = cli_option("bench", argc, argv, &i, NAME, &v)) != 0) {            \
        if (r < 0)                                                             \
            return CLI_USAGE;                                                  \
        if (!cli_parse_ulong(v, MAX, &u) || u + 1 < (MIN) + 1)                 \
            return cli_usage("bench", NAME ": '%s' is not a whole number "     \
                             "from %lu to %lu", v, (unsigned long)MIN,         \
                             (unsigned long)MAX);                              \
        VAR = u;                                                               \
        continue;                                                              \
    }
        STR_OPT("--configs", configs)
        STR_OPT("--methods", methods)
        STR_OPT("--treelet", treelets)
        STR_OPT("--rounds", rounds)
        STR_OPT("--backend", backends)
        if ((r = cli_option("bench", argc, argv, &i, "--quality", &v)) != 0) {
            atrbvh_method m;
            unsigned t, rr;
            if (r < 0)
                return CLI_USAGE;
            if (!cli_quality_preset(v, &m, &t, &rr))
                return cli_usage("bench", "--quality: '%s' is not fast, "
                                 "balanced or high", v);
            if (nq == 8)
                return cli_usage("bench", "--quality: too many");
            qualities[nq++] = v;
            continue;
        }
        if ((r = cli_option("bench", argc, argv, &i, "--csv", &v)) != 0) {
            if (r < 0)
                return CLI_USAGE;
            if (*v == '\0')
                return cli_usage("bench", "--csv: empty file name");
            a.csv = v;
            continue;
        }
        if ((r = cli_option("bench", argc, argv, &i, "--plot", &v)) != 0) {
            if (r < 0)
                return CLI_USAGE;
            if (*v == '\0')
                return cli_usage("bench", "--plot: empty folder name");
            if (!plot_path_ok(v))
                return cli_usage("bench", "--plot: a folder name with a "
                                 "quote or a newline is not supported");
            a.plot = v;
            continue;
        }
        UINT_OPT("--repeat", a.repeat, 1, MAX_REPEAT)
        UINT_OPT("--width", a.width, 1, MAX_SIDE)
        UINT_OPT("--height", a.height, 1, MAX_SIDE)
        UINT_OPT("--viewpoints", a.viewpoints, 1, MAX_VIEWPOINTS)
        UINT_OPT("--spp", a.spp, 0, MAX_SPP)
        if ((r = cli_option("bench", argc, argv, &i, "--max-leaf", &v)) !=
            0) {
            if (r < 0)
                return CLI_USAGE;
            if (!cli_parse_ulong(v, 1024, &u))
                return cli_usage("bench", "--max-leaf: '%s' is not a whole "
                                 "number from 0 to 1024", v);
            a.base.max_leaf_size = (unsigned)u;
            continue;
        }
        if ((r = cli_option("bench", argc, argv, &i, "--threads", &v)) !=
            0) {
            if (r < 0)
                return CLI_USAGE;
            if (!cli_parse_long(v, 0, 1024, &l))
                return cli_usage("bench", "--threads: '%s' is not a whole "
                                 "number from 0 to 1024", v);
            a.base.threads = (int)l;
            continue;
        }
        if ((r = cli_option("bench", argc, argv, &i, "--ci", &v)) != 0 ||
            (r = cli_option("bench", argc, argv, &i, "--ct", &v)) != 0) {
            int is_ci = strncmp(arg, "--ci", 4) == 0;
            if (r < 0)
                return CLI_USAGE;
            if (!cli_parse_double(v, &d) || !(d > 0.0) || !isfinite(d))
                return cli_usage("bench", "%s: '%s' is not a positive "
                                 "number", is_ci ? "--ci" : "--ct", v);
            if (is_ci)
                a.base.ci = d;
            else
                a.base.ct = d;
            continue;
        }
        if ((r = cli_option("bench", argc, argv, &i, "--sizes", &v)) != 0) {
            unsigned long vals[MAX_SIZES];
            if (r < 0)
                return CLI_USAGE;
            if (parse_uint_list("--sizes", v, 50000000ul, vals, &a.nsizes,
                                MAX_SIZES) != 0)
                return CLI_USAGE;
            for (k = 0; k < a.nsizes; k++) {
                if (vals[k] == 0)
                    return cli_usage("bench", "--sizes: 0 triangles");
                a.sizes[k] = vals[k];
            }
            continue;
        }
#undef STR_OPT
#undef UINT_OPT
        return cli_usage("bench", "unknown option '%s'", arg);
    }
    if (backends) {
        if (strcmp(backends, "cpu") == 0)
            be = ATRBVH_BACKEND_CPU;
        else if (strcmp(backends, "opencl") == 0)
            be = ATRBVH_BACKEND_OPENCL;
        else if (strcmp(backends, "cpu,opencl") != 0 &&
                 strcmp(backends, "opencl,cpu") != 0)
            return cli_usage("bench", "--backend: '%s' is not cpu, opencl "
                             "or cpu,opencl", backends);
    }
    if (configs && methods)
        return cli_usage("bench", "--configs and --methods exclude each "
                         "other");
    if ((treelets || rounds) && !methods)
        return cli_usage("bench", "--treelet and --rounds go with --methods");
    if (methods) {
        unsigned long tl[32], rl[32];
        int nt = 0, nr = 0, m, t, r2;
        char buf[512], *tok, *save = NULL, spec[64];
        if (treelets &&
            parse_uint_list("--treelet", treelets, 32, tl, &nt, 32) != 0)
            return CLI_USAGE;
        if (rounds && parse_uint_list("--rounds", rounds, 64, rl, &nr, 32) !=
                          0)
            return CLI_USAGE;
        if (strlen(methods) >= sizeof buf)
            return cli_usage("bench", "--methods: list too long");
        strcpy(buf, methods);
        for (tok = strtok_r(buf, ",", &save); tok;
             tok = strtok_r(NULL, ",", &save)) {
            if (strcmp(tok, "lbvh") == 0 || strncmp(tok, "embree", 6) == 0) {
                if (parse_configs(&a, tok, be) != 0)
                    return CLI_USAGE;
                continue;
            }
            if (strcmp(tok, "trbvh") != 0 && strcmp(tok, "atrbvh") != 0)
                return cli_usage("bench", "--methods: unknown method '%s'",
                                 tok);
            for (t = 0; t < (nt ? nt : 1); t++)
                for (r2 = 0; r2 < (nr ? nr : 1); r2++) {
                    if (nt && tl[t] == 0)
                        return cli_usage("bench", "--treelet: 0");
                    if (nr && rl[r2] == 0)
                        return cli_usage("bench", "--rounds: 0");
                    if (nt && strcmp(tok, "trbvh") == 0 && tl[t] > 10) {
                        if (r2 == 0)
                            fprintf(stderr, "atrbvh: bench: trbvh treelet %lu "
                                    "skipped (TRBVH takes 3 to 10)\n",
                                    tl[t]);
                        continue;
                    }
                    m = snprintf(spec, sizeof spec, "%s", tok);
                    if (nt)
                        m += snprintf(spec + m, sizeof spec - (size_t)m,
                                      ":%lu", tl[t]);
                    else if (nr)
                        m += snprintf(spec + m, sizeof spec - (size_t)m,
                                      ":%u", strcmp(tok, "trbvh") == 0 ? 7u
                                                                       : 9u);
                    if (nr)
                        snprintf(spec + m, sizeof spec - (size_t)m, ":%lu",
                                 rl[r2]);
                    if (parse_configs(&a, spec, be) != 0)
                        return CLI_USAGE;
                }
        }
    } else if (parse_configs(&a, configs ? configs
                                         : a.scaling ? DEFAULT_SCALING_CONFIGS
                                                     : DEFAULT_CONFIGS,
                             be) != 0) {
        return CLI_USAGE;
    }
    for (k = 0; k < nq; k++)
        if (parse_configs(&a, qualities[k], be) != 0)
            return CLI_USAGE;
    if (backends && strchr(backends, ',')) {
        /* both backends: every library configuration again on OpenCL */
        int n0 = a.nconfigs;
        for (k = 0; k < n0; k++) {
            config c = a.configs[k];
            if (c.embree)
                continue;
            c.backend = ATRBVH_BACKEND_OPENCL;
            if (add_config(&a, &c) != 0)
                return CLI_USAGE;
        }
    }
    if (!a.scaling) {
        /* the reference of the relative columns */
        config ref;
        memset(&ref, 0, sizeof ref);
        ref.method = ATRBVH_METHOD_TRBVH;
        ref.treelet = 7;
        ref.rounds = 3;
        for (k = 0; k < a.nconfigs; k++)
            if (!a.configs[k].embree &&
                a.configs[k].method == ATRBVH_METHOD_TRBVH &&
                a.configs[k].backend == ATRBVH_BACKEND_CPU &&
                (a.configs[k].treelet == 7 || a.configs[k].treelet == 0) &&
                (a.configs[k].rounds == 3 || a.configs[k].rounds == 0))
                break;
        if (k == a.nconfigs && add_config(&a, &ref) != 0)
            return CLI_USAGE;
        if (a.nscenes == 0)
            a.scenes[a.nscenes++] = DEFAULT_SCENE;
    } else {
        if (a.nsizes == 0) {
            size_t d[] = {10000, 100000, 1000000, 10000000};
            for (k = 0; k < 4; k++)
                a.sizes[a.nsizes++] = d[k];
        }
        for (k = 0; k < a.nconfigs; k++)
            if (a.configs[k].embree)
                return cli_usage("bench", "--scaling measures atrbvh "
                                 "configurations only");
    }
    if (a.nconfigs == 0)
        return cli_usage("bench", "no configuration to run");
    if (a.csv) {
        csv = fopen(a.csv, "w");
        if (!csv) {
            cli_error("%s: %s", a.csv, strerror(errno));
            return CLI_FAIL;
        }
        if (!a.scaling)
            csv_header(csv);
    }
    if (a.plot && mkdir(a.plot, 0777) != 0 && errno != EEXIST) {
        cli_error("%s: %s", a.plot, strerror(errno));
        if (csv)
            fclose(csv);
        return CLI_FAIL;
    }
    memtrack_install();
    rc = a.scaling ? bench_scaling(&a, csv) : bench_sweep(&a, csv);
    memtrack_uninstall();
    if (csv && (fclose(csv) != 0) && rc == CLI_OK) {
        cli_error("%s: %s", a.csv, strerror(errno));
        rc = CLI_FAIL;
    }
    return rc;
}
