/*
 * scaling.c - `atrbvh bench --scaling`: build time per stage and peak
 * memory against triangle count, with a log-log fit.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "bench.h"
#include <limits.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

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

static void series_free(scaling_series *s, int n)
{
    int k;
    for (k = 0; k < n; k++) {
        free(s[k].rows);
        free(s[k].copies);
    }
    free(s);
}

/* The fitted exponents of one series: build time, then each stage that
 * does something. */
static void print_fit(const bench_args *a, scaling_series *sr)
{
    double *xs = malloc((size_t)sr->n * sizeof *xs);
    double *ys = malloc((size_t)sr->n * sizeof *ys);
    fit f, fall;
    int si, s;
    (void)a;
    if (!xs || !ys) {
        free(xs);
        free(ys);
        sr->slope = NAN;
        return;
    }
    for (si = 0; si < sr->n; si++) {
        xs[si] = (double)sr->rows[si].triangles;
        ys[si] = sr->rows[si].build_ms;
    }
    /* "from 1e5": builtin sizes come out a little under */
    f = fit_loglog(xs, ys, sr->n, 0.9e5);
    fall = fit_loglog(xs, ys, sr->n, 0.0);
    sr->slope = f.slope;
    printf("%-20s %-16s build time ~ N^%.3f from 1e5 (%d points), N^%.3f "
           "over all %d;",
           sr->base, sr->label, f.slope, f.n, fall.slope, fall.n);
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++) {
        double most = 0.0;
        fit fs;
        for (si = 0; si < sr->n; si++) {
            ys[si] = sr->rows[si].stage_ms[s];
            if (ys[si] > most)
                most = ys[si];
        }
        if (!(most >= 0.1)) /* a stage that does nothing */
            continue;
        fs = fit_loglog(xs, ys, sr->n, 0.9e5);
        if (isfinite(fs.slope))
            printf(" %s %.2f", atrbvh_stage_name((atrbvh_stage)s), fs.slope);
    }
    printf("\n");
    free(xs);
    free(ys);
}

/* One configuration at every size: each size's scene made and its device
 * opened with the warm-up build (its first: the scratch, so the peak
 * counts it; measured from the bytes held before it, not the other
 * sizes'), then the timed builds in turns - turn k builds each size once,
 * smallest first, each right after an untimed build of the same size -
 * so that a drift of the machine's speed during the minute falls on every
 * size alike, as the speed section's turns do for the configurations.
 * Measured one size after another, the fitted exponent moved with the
 * host (the LBVH on the sphere, 10^5 to 10^7: N^0.98 to N^1.11 in five
 * runs within an hour, 6 December, docs/bench/log.md).  A size whose
 * warm-up took over SCALING_SINGLE_MS is timed in the first turn only.
 * All sizes are held at once: about the largest size's memory again. */
static int time_sizes(const bench_args *a, const char *spec,
                      const scene *base, const config *c, scaling_series *sr,
                      FILE *csv)
{
    const int n = a->nsizes;
    scene_data *sd = calloc((size_t)n, sizeof *sd);
    bench_cfg *cf = calloc((size_t)n, sizeof *cf);
    int si, made = 0, opened = 0, rc = 0;
    unsigned k;
    if (!sd || !cf) {
        cli_error("out of memory");
        free(sd);
        free(cf);
        return -1;
    }
    for (si = 0; si < n && rc == 0; si++) {
        if (scaled_scene(spec, base, a->sizes[si], &sd[si].sc,
                         &sr->copies[si]) != 0) {
            rc = -1;
            break;
        }
        made++;
        sd[si].g = scene_geometry(&sd[si].sc);
        /* (the warm-up also pays for faulting in memory the system
         * handed out fresh, 0.3-2.6 ns per byte on a VM that returns
         * freed memory to its host: docs/stages.md; untimed) */
        if (bench_cfg_open(&cf[si], a, &sd[si], spec, c, NULL, 0, a->repeat,
                           1, 0, &sr->rows[si]) != 0)
            rc = -1;
        opened++;
        /* (the warm-up's stats: cfg_build keeps them for the library) */
        if (rc == 0 && cf[si].st.build_ms > SCALING_SINGLE_MS)
            cf[si].repeat = 1;
    }
    for (k = 0; k < a->repeat && rc == 0; k++)
        for (si = 0; si < n && rc == 0; si++)
            if (k < cf[si].repeat && bench_cfg_time(&cf[si], k, 1) != 0)
                rc = -1;
    for (si = 0; si < n && rc == 0; si++) {
        row *w = &sr->rows[si];
        if (bench_cfg_finish(&cf[si]) != 0) {
            rc = -1;
            break;
        }
        config_label(c, w->treelet, w->rounds, sr->label, sizeof sr->label);
        table_scaling_row(stdout, spec, sr->label, w, sr->copies[si]);
        fflush(stdout);
        if (csv)
            csv_scaling_row(csv, spec, w, sr->copies[si]);
        sr->n++;
    }
    for (si = 0; si < opened; si++)
        bench_cfg_close(&cf[si]);
    for (si = 0; si < made; si++)
        bench_free_scene(&sd[si]);
    free(sd);
    free(cf);
    return rc;
}

int bench_scaling(bench_args *a, FILE *csv)
{
    const char *defaults[] = {"builtin:sphere", "builtin:city"};
    const char **bases = a->nscenes ? a->scenes : defaults;
    int nb = a->nscenes ? a->nscenes : 2, b, ci, rc = CLI_OK, nser = 0;
    scaling_series *series =
        calloc((size_t)nb * (size_t)a->nconfigs, sizeof *series);
    if (!series) {
        cli_error("out of memory");
        return CLI_FAIL;
    }
    table_header(stdout, a);
    printf("# scaling: median of %u run%s after one warm-up build (one run "
           "when the warm-up took over %.0f ms), the sizes in turns, each "
           "timed build right after an untimed one\n",
           a->repeat, a->repeat == 1 ? "" : "s", SCALING_SINGLE_MS);
    table_scaling_header(stdout);
    if (csv)
        csv_scaling_header(csv);
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
            scaling_series *sr = &series[nser];
            sr->base = bases[b];
            sr->rows = calloc((size_t)a->nsizes, sizeof *sr->rows);
            sr->copies = calloc((size_t)a->nsizes, sizeof *sr->copies);
            nser++;
            if (!sr->rows || !sr->copies) {
                cli_error("out of memory");
                rc = CLI_FAIL;
                break;
            }
            if (time_sizes(a, bases[b], &base, c, sr, csv) != 0) {
                rc = CLI_FAIL;
                break;
            }
            if (rc != CLI_OK || sr->n == 0)
                break;
            print_fit(a, sr);
            fflush(stdout);
        }
        scene_free(&base);
    }
    if (rc == CLI_OK && a->plot && plot_scaling(a->plot, series, nser) != 0)
        rc = CLI_FAIL;
    series_free(series, nser);
    return rc;
}
