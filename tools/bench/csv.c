/*
 * csv.c - the --csv files of `atrbvh bench` (columns: atrbvh(1), BENCH).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "bench.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const stage_csv[ATRBVH_STAGE_COUNT] = {
    "bounds_ms", "morton_ms", "sort_ms", "hierarchy_ms",
    "refit_ms", "optimise_ms", "collapse_ms", "layout_ms"};

static void put_stage_names(FILE *f)
{
    int s;
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
        fprintf(f, ",%s", stage_csv[s]);
}

/* Shortest of %.15g / %.17g that reads back as v (as json_double); an
 * empty field when v is not finite. */
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

void csv_header(FILE *f)
{
    fputs("scene,triangles,method,treelet_size,rounds,backend,threads,"
          "max_leaf,repeat,build_ms,build_min_ms",
          f);
    put_stage_names(f);
    fputs(",sah,sah_binary,nodes,leaves,peak_bytes,bvh_bytes,primary_mrays,"
          "ao_mrays,diffuse_mrays,total_mrays,relative_pct,time_pct,sah_pct,"
          "embree_primary_mrays,embree_ao_mrays,embree_diffuse_mrays,"
          "embree_commit_ms,primary_box_tests_per_ray,"
          "ao_box_tests_per_ray,diffuse_box_tests_per_ray,box_tests_per_ray,"
          "primary_tri_tests_per_ray,ao_tri_tests_per_ray,"
          "diffuse_tri_tests_per_ray,tri_tests_per_ray,ray_cost,"
          "ray_cost_pct,split_budget,references,split_rule,cpu_use\n",
          f);
}

/* The split_rule column: the rule a split configuration ran with (its
 * "/RULE", else the library's default), "sbvh" for embree_split, else
 * empty. */
static const char *row_split_rule(const bench_args *a, const row *r)
{
    if (r->c.embree)
        return r->c.eq == EMBREE_SPLIT ? "sbvh" : "";
    if (!(r->c.split > 0.0))
        return "";
    return cli_split_rule_name(r->c.split_rule >= 0 ? r->c.split_rule
                                                    : a->base.split_rule);
}

void csv_row(FILE *f, const bench_args *a, const row *r)
{
    int s;
    char tb[16];
    put_csv_string(f, r->scene);
    fprintf(f, ",%zu,%s,%s,%u,%s,%d,%u,%u,", r->triangles, row_method(r),
            cli_treelet_text(r->treelet, tb), r->rounds,
            r->c.embree ? "embree" : bench_backend_name(r->c.backend), r->threads,
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
    for (s = 0; s < 4; s++) {
        fputc(',', f);
        put_double(f, r->box_per_ray[s]);
    }
    for (s = 0; s < 4; s++) {
        fputc(',', f);
        put_double(f, r->tri_per_ray[s]);
    }
    fputc(',', f);
    put_double(f, r->ray_cost);
    fputc(',', f);
    put_double(f, r->cost_pct);
    fputc(',', f);
    put_double(f, r->c.embree ? (r->c.eq == EMBREE_SPLIT ? EMBREE_SPLIT_BUDGET
                                                         : 0.0)
                              : r->c.split);
    fprintf(f, ",%zu,%s,", r->references, row_split_rule(a, r));
    put_double(f, r->cpu_use);
    fputc('\n', f);
}

void csv_scaling_header(FILE *f)
{
    fputs("base,triangles,copies,method,treelet_size,rounds,threads,build_ms",
          f);
    put_stage_names(f);
    fputs(",sah,nodes,peak_bytes,bvh_bytes,peak_bytes_per_triangle,"
          "peak_over_bvh,repeat\n",
          f);
}

void csv_scaling_row(FILE *f, const char *base, const row *w, size_t copies)
{
    char tb[16];
    int s;
    put_csv_string(f, base);
    fprintf(f, ",%zu,%zu,%s,%s,%u,%d,", w->triangles, copies, row_method(w),
            cli_treelet_text(w->treelet, tb), w->rounds, w->threads);
    put_double(f, w->build_ms);
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++) {
        fputc(',', f);
        put_double(f, w->stage_ms[s]);
    }
    fputc(',', f);
    put_double(f, w->sah);
    fprintf(f, ",%zu,%zu,%zu,", w->nodes, w->peak, w->bvh_bytes);
    put_double(f, (double)w->peak / (double)w->triangles);
    fputc(',', f);
    put_double(f, (double)w->peak / (double)w->bvh_bytes);
    fprintf(f, ",%u\n", w->timed);
}

/* --builds: one row per build, in the order the bench ran them (atrbvh(1),
 * BENCH): seq from 1; kind warmup (a configuration's first build), untimed
 * (the build right before each timed one), timed (turn 0 .. repeat-1) or
 * binary (the binary tree's SAH: collapse off, Embree leaf size 1);
 * build_ms the build's wall time, as the tables' (the library's
 * build_ms, Embree's the primitive boxes and rtcBuildBVH). */
void csv_build_header(FILE *f)
{
    fputs("seq,scene,triangles,configuration,kind,turn,build_ms\n", f);
}

void csv_build_row(bench_log *log, const row *r, const char *label,
                   const char *kind, int turn, double ms)
{
    FILE *f = log->f;
    fprintf(f, "%lu,", ++log->seq);
    put_csv_string(f, r->scene);
    fprintf(f, ",%zu,", r->triangles);
    put_csv_string(f, label);
    fprintf(f, ",%s,", kind);
    if (turn >= 0)
        fprintf(f, "%d", turn);
    fputc(',', f);
    put_double(f, ms);
    fputc('\n', f);
}
