/*
 * sweep.c - `atrbvh bench` without --scaling: every configuration on every
 * scene, the relative columns against TRBVH(7,3), tables, CSV and plots.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "bench.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int find_ref(const row *rows, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!rows[i].c.embree && rows[i].c.method == ATRBVH_METHOD_TRBVH &&
            rows[i].treelet == 7 && rows[i].rounds == 3 &&
            rows[i].c.backend == ATRBVH_BACKEND_CPU && rows[i].c.split == 0.0)
            return i;
    return -1;
}

int bench_sweep(bench_args *a, FILE *csv)
{
    int si, rc = CLI_OK;
    embree_ctx *emb = NULL;
    row *rows = malloc((size_t)a->nconfigs * sizeof *rows);
    bench_cfg *cfgs = malloc((size_t)a->nconfigs * sizeof *cfgs);
    if (!rows || !cfgs) {
        cli_error("out of memory");
        free(rows);
        free(cfgs);
        return CLI_FAIL;
    }
    table_header(stdout, a);
    if (embree_available()) {
        emb = embree_open(a->base.threads);
        if (!emb) {
            free(rows);
            free(cfgs);
            return CLI_FAIL;
        }
    }
    for (si = 0; si < a->nscenes && rc == CLI_OK; si++) {
        scene_data sd;
        int i, n = 0, ref;
        if (bench_load_scene(a->scenes[si], &sd) != 0) {
            bench_free_scene(&sd);
            rc = CLI_FAIL;
            break;
        }
        if (a->rays) {
            atrbvh_bvh *lb = NULL;
            atrbvh_build_options o = a->base;
            o.method = ATRBVH_METHOD_LBVH;
            if (bench_lib_build(&sd, &o, &lb, a->scenes[si], 0) != 0 ||
                ray_set_make(&sd.sc, lb, (unsigned)a->width,
                             (unsigned)a->height, (unsigned)a->viewpoints,
                             (unsigned)a->spp, a->base.threads, &a->view,
                             &sd.rays) != 0) {
                atrbvh_bvh_free(lb);
                bench_free_scene(&sd);
                rc = CLI_FAIL;
                break;
            }
            atrbvh_bvh_free(lb);
            sd.have_rays = 1;
        }
        printf("\n## %s: %zu triangles", a->scenes[si], sd.sc.triangle_count);
        if (sd.have_rays && a->view.have_eye)
            printf("; rays: %zu primary (%ux%u, the --eye camera), %zu "
                   "ao, %zu diffuse",
                   sd.rays.n_primary, a->width, a->height, sd.rays.n_ao,
                   sd.rays.n_diffuse);
        else if (sd.have_rays) {
            float lo[3], hi[3];
            scene_bounds(&sd.sc, lo, hi);
            printf("; rays: %zu primary (%ux%u, viewpoints 0..%u%s), %zu "
                   "ao, %zu diffuse",
                   sd.rays.n_primary, a->width, a->height, a->viewpoints - 1,
                   scene_is_room(&sd.sc, lo, hi, NULL)
                       ? ", a room: even ones inside"
                       : "",
                   sd.rays.n_ao, sd.rays.n_diffuse);
        }
        printf("\n");
        fflush(stdout);
        {
            /* Every configuration opened and warmed up, then the timed
             * builds in turns - round k builds each configuration once,
             * in the list's order - so that a drift of the machine's
             * speed during the scene's minute falls on every
             * configuration alike and the ratios between them (to
             * Embree's rows above all) hold; then each row.  Each timed
             * build comes right after an untimed one of the same
             * configuration: a build repeated back to back finds its
             * working set in the caches, one after other configurations'
             * builds does not, and that costs ours more than Embree's
             * (bunny LBVH 15-25%), so without it the turns would measure
             * the caches as much as the builders. */
            unsigned k;
            int opened = 0;
            for (i = 0; i < a->nconfigs && rc == CLI_OK; i++, opened++)
                if (bench_cfg_open(&cfgs[i], a, &sd, a->scenes[si],
                                   &a->configs[i], emb, a->rays, a->repeat,
                                   1, 1, &rows[i]) != 0)
                    rc = CLI_FAIL;
            for (k = 0; k < a->repeat && rc == CLI_OK; k++)
                for (i = 0; i < a->nconfigs && rc == CLI_OK; i++)
                    if (bench_cfg_time(&cfgs[i], k, 1) != 0)
                        rc = CLI_FAIL;
            for (i = 0; i < a->nconfigs && rc == CLI_OK; i++)
                if (bench_cfg_finish(&cfgs[i]) != 0)
                    rc = CLI_FAIL;
            for (i = 0; i < opened; i++)
                bench_cfg_close(&cfgs[i]);
            if (rc == CLI_OK)
                n = a->nconfigs;
        }
        if (rc != CLI_OK) {
            bench_free_scene(&sd);
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
            if (sd.have_rays)
                rows[i].cost_pct =
                    rows[i].ray_cost / rows[ref].ray_cost * 100.0;
        }
        table_sweep(stdout, rows, n, sd.have_rays);
        table_dominance(stdout, rows, n);
        if (csv)
            for (i = 0; i < n; i++)
                csv_row(csv, a, &rows[i]);
        fflush(stdout);
        if (a->plot &&
            plot_scene(a->plot, a->scenes[si], rows, n, sd.have_rays) != 0)
            rc = CLI_FAIL;
        bench_free_scene(&sd);
    }
    embree_close(emb);
    free(rows);
    free(cfgs);
    return rc;
}
