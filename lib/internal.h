/*
 * internal.h - what the library's files share and nothing outside sees.
 * Non-static internal symbols carry the atrbvh_i_ prefix (hidden by
 * -fvisibility=hidden; the exported list is pinned by a test).  The
 * backends (lib/cpu/, cl/) see backend.h only.
 */
#ifndef ATRBVH_INTERNAL_H
#define ATRBVH_INTERNAL_H

#include "atrbvh.h"

#include <stddef.h>
#include <stdint.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#define ATRBVH_NONE UINT32_MAX

/* The services every file may use (allocation, errors, clock), the
 * configuration, the tree and the capture are declared in backend.h, the
 * one header the backends see. */
#include "backend.h"

/* ---------------------------------------------------------------- errors */
void atrbvh_i_clear_error(atrbvh_error *error);

/* --------------------------------------------------------------- threads */
/* Resolves options->threads (0 = the OpenMP default; 1 without OpenMP). */
int atrbvh_i_resolve_threads(int requested);

/* ------------------------------------------------------------ the config */
/* What the pipeline needs beyond the backends' configuration. */
typedef struct atrbvh_i_request {
    atrbvh_i_config cfg;
    atrbvh_device *device;       /* NULL: a temporary one of `backend`  */
    atrbvh_backend backend;
    const char *opencl_device;
    atrbvh_progress_fn progress;
    void *progress_user;
    atrbvh_capture_fn capture;
    void *capture_user;
} atrbvh_i_request;

atrbvh_status atrbvh_i_resolve_options(const atrbvh_build_options *options,
                                       atrbvh_i_request *request,
                                       atrbvh_error *error);

/* ------------------------------------------------------------ the input */
/* The smallest atrbvh_geometry.size accepted: the first version's. */
#define ATRBVH_GEOMETRY_SIZE_V1                                                \
    (offsetof(atrbvh_geometry, box_stride) + sizeof(size_t))
/* Validates pointers, strides, counts and the size field (no
 * per-primitive check); fills the effective strides in bytes. */
atrbvh_status atrbvh_i_check_geometry(const atrbvh_geometry *g,
                                      atrbvh_i_input *in,
                                      atrbvh_error *error);
/* After a backend's bounds stage found an invalid primitive: the exact
 * error (the lowest index, the most severe kind), or with skip_invalid
 * the boxes and ascending ids of the valid primitives (*ids NULL when all
 * are kept), their count, the scene and centroid boxes, and how many were
 * left out.  Host code, OpenMP-parallel; the per-item rule is
 * shared/stages.h's atrbvh_prim_box. */
atrbvh_status atrbvh_i_scan_prims(const atrbvh_i_input *in,
                                  const atrbvh_i_config *cfg,
                                  atrbvh_box **boxes, uint32_t **ids,
                                  uint32_t *kept, atrbvh_box *scene,
                                  atrbvh_box *centroids, size_t *invalid,
                                  atrbvh_error *error);
/* Triangle splitting (lib/split.c): the most split_budget accepted. */
#define ATRBVH_I_SPLIT_MAX 4.0
/* After the bounds stage, with cfg->split_budget > 0 over triangles: the
 * exact error for an invalid primitive as atrbvh_i_scan_prims gives it,
 * or the split references (boxes and primitive ids) handed to the backend
 * (set_prims); sets run->n, scene, centroids, invalid, split_prims. */
atrbvh_status atrbvh_i_split_prims(atrbvh_device *dev, atrbvh_i_run *run,
                                   atrbvh_error *error);
/* After the layout of a split build: duplicate references within one
 * leaf merged (prim_count shrinks; primitive ids below input_count). */
atrbvh_status atrbvh_i_split_merge(atrbvh_bvh *bvh, size_t input_count,
                                   atrbvh_error *error);

/* The Morton frame of a centroid box: per axis the low end and the scale
 * 2^21 / extent (0 for a zero extent): shared/stages.h's
 * atrbvh_morton_frame, which the OpenCL bounds kernel also runs. */
void atrbvh_i_morton_frame(const atrbvh_box *centroids, double lo[3],
                           double scale[3]);

/* ------------------------------------------------------------- the tree */
void atrbvh_i_capture_free(atrbvh_i_capture *c);
/* Hands the output of `stage` (a backend's copy in `c`; round: the
 * optimise round just done, else 0) to the public capture callback, as
 * docs/stages.md describes it; ATRBVH_ERR_CANCELLED when it returns
 * nonzero. */
atrbvh_status atrbvh_i_capture_emit(atrbvh_capture_fn fn, void *user,
                                    atrbvh_stage stage, unsigned round,
                                    const atrbvh_i_capture *c,
                                    const atrbvh_i_run *run,
                                    atrbvh_error *error);

/* ------------------------------------------------------------- the BVH */
#define ATRBVH_MAX_KERNEL_TIMES 32
struct atrbvh_bvh {
    atrbvh_node *nodes;
    size_t node_count;
    uint32_t *prim_indices;
    size_t prim_count;
    atrbvh_stats stats;
    double stage_ms[ATRBVH_STAGE_COUNT];
    struct atrbvh_i_device_info *device; /* NULL unless built by OpenCL */
    size_t node_bytes;    /* the node array's allocation in bytes, at
                             least node_count's (atrbvh_reoptimise and
                             atrbvh_rebuild reuse it)                  */
    size_t split_prims;   /* a split tree (its leaves may share a
                             primitive): the distinct primitives it
                             references; 0: every primitive once       */
    void *wide; /* the 4-wide copy of the tree the uncounted ray batches
                   make on first use (lib/traverse.c); NULL: none yet.
                   Whatever changes the nodes drops it first
                   (atrbvh_i_bvh_drop_wide). */
    void *wide_tris; /* beside it, the triangles of the leaves for one
                        geometry (lib/traverse.c); dropped with it */
    /* A build leaves the statistics that take a pass over the nodes
     * (leaves, max_depth, max_leaf_primitives, sah, sah_built) to their
     * first reader: atrbvh_i_bvh_stats_of measures them into a copy,
     * atrbvh_i_bvh_settle_stats into stats (lib/bvh.c).  0: stats holds
     * them (a loaded, refitted or re-optimised tree, a debug build). */
    int stats_pending;
};

/* Frees the 4-wide copy of the tree (lib/traverse.c); the next uncounted
 * ray batch makes a new one. */
void atrbvh_i_bvh_drop_wide(atrbvh_bvh *bvh);

/* The device and per-kernel device times of an OpenCL build (allocated
 * separately: CPU builds and loaded files stay small). */
typedef struct atrbvh_i_device_info {
    char name[128];
    unsigned kernel_count;
    char kernel_name[ATRBVH_MAX_KERNEL_TIMES][24];
    double kernel_ms[ATRBVH_MAX_KERNEL_TIMES];
} atrbvh_i_device_info;

/* atrbvh_build with an optional capture (NULL: none). */
atrbvh_status atrbvh_i_build_run(const atrbvh_geometry *geometry,
                                 const atrbvh_build_options *options,
                                 atrbvh_bvh **out, atrbvh_i_capture *capture,
                                 atrbvh_error *error);
/* atrbvh_validate_backends' comparison (lib/validate.c): 1 when two
 * builds' captures and trees differ, with the first difference in stage
 * order in *e (its text names the stage, the item and both values, "cpu"
 * for a and "opencl" for b; its index is the item's; its status stays
 * ATRBVH_OK), else 0. */
int atrbvh_i_captures_differ(atrbvh_error *e, const atrbvh_i_capture *a,
                             const atrbvh_bvh *ba, const atrbvh_i_capture *b,
                             const atrbvh_bvh *bb);
/* Records a kernel time under `name` (added to an existing entry). */
void atrbvh_i_bvh_add_kernel_time(atrbvh_bvh *bvh, const char *name,
                                  double ms);

/* ------------------------------------------------------------ devices */
/* Opens a device of `backend` (spec as the backend reads it). */
atrbvh_status atrbvh_i_device_open_backend(const atrbvh_i_backend *backend,
                                           const char *spec,
                                           atrbvh_device **out,
                                           atrbvh_error *error);
/* One build or ray batch at a time per handle. */
void atrbvh_i_device_lock(atrbvh_device *dev);
void atrbvh_i_device_unlock(atrbvh_device *dev);
/* A CPU device for one call, on the caller's stack (no handle opened);
 * release its scratch with atrbvh_i_scratch_free(&dev->scratch). */
void atrbvh_i_device_cpu_temp(atrbvh_device *dev);

/* The argument checks of the batch ray queries (lib/traverse.c); `fn`
 * names the caller in the message. */
atrbvh_status atrbvh_i_trav_check(const atrbvh_bvh *bvh,
                                  const atrbvh_geometry *g,
                                  const atrbvh_ray *rays, size_t count,
                                  const void *out, int threads,
                                  const char *fn, atrbvh_error *error);

/* A node's surface area: shared/arith.h's atrbvh_box_area, the same
 * operations in the same order (the same bits), on the node's fields
 * directly (a box copied first goes through the stack).  With
 * atrbvh_i_sah_total, the SAH of atrbvh_sah (sah.c) and of the statistics
 * pass after a build (bvh.c), which must agree to the bit. */
static inline double atrbvh_i_node_area(const atrbvh_node *v)
{
    const double dx = (double)v->max[0] - (double)v->min[0];
    const double dy = (double)v->max[1] - (double)v->min[1];
    const double dz = (double)v->max[2] - (double)v->min[2];
    double s = dx * dy;
    s = s + dy * dz;
    s = s + dz * dx;
    return 2.0 * s;
}

/* The SAH from the sums over the nodes in node order: internal areas,
 * leaf areas times their counts, and the root's area (0 if not > 0). */
static inline double atrbvh_i_sah_total(double ci, double ct, double inner,
                                        double leaves, double root)
{
    return root > 0.0 ? (ci * inner + ct * leaves) / root : 0.0;
}

/* The sums of the SAH over nodes 0 .. m-1 in node order (sah.c): the
 * internal nodes' areas, the leaves' areas times their counts; and the
 * leaves and their largest count.  atrbvh_i_sah_sum_with(..., 0, ...)
 * takes the scalar loop even where AVX is there (the tests compare the
 * two: the same bits). */
typedef struct atrbvh_i_sah_sums {
    double inner, leaf_sum;
    size_t leaves;
    uint32_t largest;
} atrbvh_i_sah_sums;
void atrbvh_i_sah_sum(const atrbvh_node *nodes, size_t m,
                       atrbvh_i_sah_sums *s);
void atrbvh_i_sah_sum_with(const atrbvh_node *nodes, size_t m, int vector,
                            atrbvh_i_sah_sums *s);

/* Allocates an empty BVH object with room for the arrays. */
atrbvh_bvh *atrbvh_i_bvh_alloc(size_t node_count, size_t prim_count);
/* Blocks (of the library's allocator) an output may take instead of new
 * allocations: its nodes the first of `nodes` and `nodes2` that holds
 * them, its primitive indices `indices` when it holds them.  A block
 * taken is set to NULL (the object owns it); the others stay the
 * caller's.  Any pointer may be NULL. */
typedef struct atrbvh_i_blocks {
    void **nodes, **nodes2, **indices;
    size_t node_bytes, node_bytes2, index_bytes;
} atrbvh_i_blocks;
/* The same, in `blocks` where they hold the arrays (NULL: none). */
atrbvh_bvh *atrbvh_i_bvh_alloc_in(size_t node_count, size_t prim_count,
                                  const atrbvh_i_blocks *blocks);
/* Fills stats.nodes, leaves, primitives, max_depth, max_leaf_primitives and
 * sah (with stats.ci/ct) from the node array; fails on an invalid array or
 * when scratch cannot be allocated. */
atrbvh_status atrbvh_i_bvh_measure(atrbvh_bvh *bvh);
/* The same for a tree the layout stage just wrote (lib/bvh.c), on up to
 * `threads` threads (the same statistics for any count): the sums in node
 * order, and the order check with the depths, a walk of the top's
 * subtrees side by side; ATRBVH_ERR_BACKEND when the array is not such a
 * tree, ATRBVH_ERR_NOMEM. */
atrbvh_status atrbvh_i_bvh_measure_built(atrbvh_bvh *bvh, int threads);
/* The statistics of `b` into *out: its stats, with the pending fields
 * (stats_pending) measured as atrbvh_i_bvh_measure_built does, on the
 * build's threads; b is not changed.  ATRBVH_ERR_BACKEND, ATRBVH_ERR_NOMEM
 * as there. */
atrbvh_status atrbvh_i_bvh_stats_of(const atrbvh_bvh *b, atrbvh_stats *out);
/* The same into b->stats, none pending after it: before anything changes
 * the nodes (atrbvh_refit's drift is against the SAH as built). */
atrbvh_status atrbvh_i_bvh_settle_stats(atrbvh_bvh *b);
/* The statistics both measures end with: counts, depth, SAH (bvh.c). */
void atrbvh_i_bvh_set_stats(atrbvh_bvh *b, size_t leaves, unsigned depth,
                            unsigned largest);
/* Structural check of a node array (used on load and, in debug builds,
 * after every build): every child index in range and after its parent,
 * leaf ranges tiling the index array in order, child boxes inside parents
 * when check_boxes; every primitive index below the input count and
 * listed once (a split tree: never twice in one leaf, every kept
 * primitive listed). */
atrbvh_status atrbvh_i_bvh_check(const atrbvh_bvh *bvh, int check_boxes,
                                 atrbvh_error *error);

#endif
