/*
 * tables.c - the text tables `atrbvh bench` prints on standard output.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "bench.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
static void text_num(FILE *f, const char *fmt, double v, int width)
{
    if (isfinite(v))
        fprintf(f, fmt, width, v);
    else
        fprintf(f, "%*s", width, "-");
}

void table_sweep(FILE *f, const row *rows, int n, int have_rays)
{
    int i, w = 18; /* the config column: as wide as its longest label */
    for (i = 0; i < n; i++) {
        char label[64];
        config_label(&rows[i].c, rows[i].treelet, rows[i].rounds, label,
                     sizeof label);
        if ((int)strlen(label) > w)
            w = (int)strlen(label);
    }
    fprintf(f, "%-*s %9s %9s %9s %9s %9s %8s", w, "config", "build ms",
            "opt ms", "SAH", "SAH bin", "nodes", "peak MB");
    if (have_rays)
        fprintf(f, " %7s %7s %7s %7s %8s %7s %7s %7s", "prim", "ao", "diff",
                "all", "rel %", "box/ray", "tri/ray", "cost %");
    fprintf(f, " %7s %7s\n", "time %", "SAH %");
    for (i = 0; i < n; i++) {
        const row *r = &rows[i];
        char label[64];
        config_label(&r->c, r->treelet, r->rounds, label, sizeof label);
        fprintf(f, "%-*s", w, label);
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
            text_num(f, " %*.1f", r->box_per_ray[3], 7);
            text_num(f, " %*.1f", r->tri_per_ray[3], 7);
            text_num(f, " %*.1f", r->cost_pct, 7);
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

void table_header(FILE *f, const bench_args *a)
{
    int threads = bench_threads(a);
    fprintf(f, "# atrbvh bench %s, %d thread%s, max leaf %u, ci %g, ct %g, "
               "median of %u run%s after a warm-up\n",
            atrbvh_version_string(), threads, threads == 1 ? "" : "s",
            a->base.max_leaf_size, a->base.ci, a->base.ct, a->repeat,
            a->repeat == 1 ? "" : "s");
    fprintf(f, "# atrbvh: %s\n",
            a->fresh ? "each build after the last tree is freed (--fresh)"
                     : "each build into the last one's tree (atrbvh_rebuild)");
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
        /* Binding pins the main thread to one core at OpenMP's start, and
         * Embree's TBB sizes its pool by that thread's mask: its rows ran
         * on one core (bunny 1.8x slower, 3 December). */
        const char *pb = getenv("OMP_PROC_BIND");
        if (pb && *pb && strcmp(pb, "false") != 0 && embree_available())
            fprintf(f, "# OMP_PROC_BIND=%s: the main thread is bound to one "
                       "core and Embree's threads inherit its mask, so the "
                       "Embree rows are not comparable\n",
                    pb);
    }
    {
        /* PoCL's own knob for its CPU device's worker threads (each pinned
         * to the core of its index): docs/opencl.md. */
        const char *pa = getenv("POCL_AFFINITY");
        if (pa)
            fprintf(f, "# POCL_AFFINITY=%s\n", pa);
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

/* Each Embree row against the best atrbvh configuration that builds at
 * least as fast. */
void table_dominance(FILE *f, const row *rows, int n)
{
    int i, j;
    for (i = 0; i < n; i++) {
        char label[64], bl[64];
        int best = -1;
        if (!rows[i].c.embree)
            continue;
        config_label(&rows[i].c, 0, 0, label, sizeof label);
        for (j = 0; j < n; j++)
            if (!rows[j].c.embree && rows[j].build_ms <= rows[i].build_ms &&
                rows[j].sah < rows[i].sah &&
                (best < 0 || rows[j].sah < rows[best].sah))
                best = j;
        if (best >= 0) {
            config_label(&rows[best].c, rows[best].treelet, rows[best].rounds,
                         bl, sizeof bl);
            fprintf(f, "%s (%.1f ms, SAH %.3f) is dominated by %s (%.1f ms, "
                       "SAH %.3f)\n",
                    label, rows[i].build_ms, rows[i].sah, bl,
                    rows[best].build_ms, rows[best].sah);
        } else {
            fprintf(f, "%s (%.1f ms, SAH %.3f) is not dominated by any "
                       "atrbvh configuration run\n",
                    label, rows[i].build_ms, rows[i].sah);
        }
    }
}

void table_scaling_header(FILE *f)
{
    fprintf(f, "# copies: how many copies of a file's mesh make the size "
               "(builtin scenes are\n# generated at it); peak B/tri: the "
               "library's peak bytes per triangle during\n# the build; "
               "peak/tree: that peak over the finished tree's bytes\n");
    fprintf(f, "%-20s %-16s %10s %6s %10s %12s %10s\n", "base scene",
            "config", "triangles", "copies", "build ms", "peak B/tri",
            "peak/tree");
}

void table_scaling_row(FILE *f, const char *base, const char *label,
                       const row *w, size_t copies)
{
    fprintf(f, "%-20s %-16s %10zu %6zu %10.1f %12.1f %10.2f\n", base, label,
            w->triangles, copies, w->build_ms,
            (double)w->peak / (double)w->triangles,
            (double)w->peak / (double)w->bvh_bytes);
}
