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

int bench_scaling(bench_args *a, FILE *csv)
{
    const char *defaults[] = {"builtin:sphere", "builtin:city"};
    const char **bases = a->nscenes ? a->scenes : defaults;
    int nb = a->nscenes ? a->nscenes : 2, b, ci, si, rc = CLI_OK, nser = 0;
    scaling_series *series =
        calloc((size_t)nb * (size_t)a->nconfigs, sizeof *series);
    if (!series) {
        cli_error("out of memory");
        return CLI_FAIL;
    }
    table_header(stdout, a);
    printf("# scaling: median of %u run%s after one warm-up build (one run "
           "when the warm-up took over %.0f ms)\n",
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
            for (si = 0; si < a->nsizes; si++) {
                scene_data sd;
                row *w = &sr->rows[sr->n];
                memset(&sd, 0, sizeof sd);
                if (scaled_scene(bases[b], &base, a->sizes[si], &sd.sc,
                                 &sr->copies[sr->n]) != 0) {
                    rc = CLI_FAIL;
                    break;
                }
                sd.g = scene_geometry(&sd.sc);
                /* Every size is timed the same way, after a warm-up
                 * build: the first build of a process also pays for
                 * faulting in memory the system handed out fresh (on a
                 * VM that returns freed memory to its host, 0.3-2.6 ns
                 * per byte here: docs/stages.md), which would grow the
                 * time of the largest sizes only. */
                if (bench_run_config(a, &sd, bases[b], c, NULL, 0,
                                     a->repeat, 1, 0, SCALING_SINGLE_MS,
                                     w) != 0) {
                    bench_free_scene(&sd);
                    rc = CLI_FAIL;
                    break;
                }
                bench_free_scene(&sd);
                config_label(c, w->treelet, w->rounds, sr->label,
                             sizeof sr->label);
                table_scaling_row(stdout, bases[b], sr->label, w,
                                  sr->copies[sr->n]);
                fflush(stdout);
                if (csv)
                    csv_scaling_row(csv, bases[b], w, sr->copies[sr->n]);
                sr->n++;
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
