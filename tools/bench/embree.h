/*
 * embree.h - Embree 3 on the same triangles, for `atrbvh bench`:
 * rtcBuildBVH (binary, our leaf limit, our SAH constants) with callbacks
 * that make a tree which is then laid out as atrbvh nodes (so our SAH and
 * our traverser apply), and an Embree scene traced with rtcIntersect1 /
 * rtcOccluded1 for Embree's own throughput.  Without HAVE_EMBREE every
 * function fails with "not built with Embree".
 */
#ifndef ATRBVH_TOOLS_BENCH_EMBREE_H
#define ATRBVH_TOOLS_BENCH_EMBREE_H

#include "atrbvh.h"
#include "rays.h"
#include "scene.h"

typedef enum embree_quality {
    EMBREE_LOW = 0,
    EMBREE_MEDIUM = 1,
    EMBREE_HIGH = 2,
    /* HIGH with spatial splits (SBVH): a primitive array with room for
     * EMBREE_SPLIT_BUDGET x triangles more references and a splitter
     * that clips the triangle; not part of "embree" (all three). */
    EMBREE_SPLIT = 3
} embree_quality;

#define EMBREE_SPLIT_BUDGET 0.2

const char *embree_quality_name(embree_quality q); /* "embree_low", ... */

/* 1 when the tool was built with Embree. */
int embree_available(void);
/* Embree's version string, or NULL. */
const char *embree_version(void);

typedef struct embree_ctx embree_ctx;

/* threads 0: Embree's default (all).  NULL after a cli_error line. */
embree_ctx *embree_open(int threads);
void embree_close(embree_ctx *ctx);

typedef struct embree_build_result {
    atrbvh_bvh *bvh;      /* the tree as an atrbvh BVH (free it)          */
    double build_ms;      /* primitive boxes + rtcBuildBVH, wall clock    */
    double convert_ms;    /* layout into atrbvh nodes (not in build_ms)   */
    size_t references;    /* primitive references in the leaves: the
                             triangle count unless EMBREE_SPLIT split
                             some (a repeat within one leaf is dropped) */
    size_t peak_bytes;    /* primitive array + Embree's memory monitor,
                             0 unless measure_memory                    */
} embree_build_result;

/* As Embree's users build: the device, the BVH object and the primitive
 * array are the context's, made once and reused; each build refills the
 * primitive array (inside build_ms) and calls rtcBuildBVH.  The tree lives
 * until the context's next build; with keep_tree, res->bvh is a copy of
 * it as an atrbvh BVH (convert_ms; without, NULL and no references
 * counted).  A conversion takes longer than a small build, and Embree's
 * worker threads fall asleep in it: a build right after one ran up to
 * 1.35x slower than back to back (bunny, low quality), so the bench
 * converts only the trees it reads.  measure_memory installs Embree's
 * memory monitor for this build only (a callback on every allocation: do
 * not time such a build).  max_leaf 0 means 1 (Embree needs a bound).  0,
 * or -1 after cli_error. */
int embree_build(embree_ctx *ctx, const scene *sc, embree_quality q,
                 unsigned max_leaf, double ci, double ct, int measure_memory,
                 int keep_tree, embree_build_result *res);

/* Embree's own scene (rtcCommitScene at quality q) traced with
 * rtcIntersect1 (primary, diffuse) and rtcOccluded1 (ao) on `threads`
 * OpenMP threads; ms[0..2] the tracing times, *commit_ms the scene build.
 * 0, or -1 after cli_error. */
int embree_trace(embree_ctx *ctx, const scene *sc, embree_quality q,
                 const ray_set *rays, int threads, double ms[3],
                 double *commit_ms);

#endif
