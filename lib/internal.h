/*
 * internal.h - what the library's files share and nothing outside sees.
 * Non-static internal symbols carry the atrbvh_i_ prefix (not the reserved
 * double underscore) (hidden by
 * -fvisibility=hidden; the exported list is pinned by a test).
 */
#ifndef ATRBVH_INTERNAL_H
#define ATRBVH_INTERNAL_H

#include "atrbvh.h"
#include "shared/arith.h"
#include "shared/stages.h"

#include <stddef.h>
#include <stdint.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#define ATRBVH_NONE UINT32_MAX

/* ------------------------------------------------------------ allocation */
void *atrbvh_i_malloc(size_t size);
void atrbvh_i_free(void *ptr);
/* Multiplies count * size, failing (returns 0, sets *out = 0) on overflow. */
int atrbvh_i_mul_size(size_t count, size_t size, size_t *out);
/* Allocates count * size bytes; NULL on overflow or allocator failure. */
void *atrbvh_i_alloc_array(size_t count, size_t size);

/* ---------------------------------------------------------------- errors */
/* Fills `error` (may be NULL) and returns `status`. printf-style text. */
atrbvh_status atrbvh_i_fail(atrbvh_error *error, atrbvh_status status,
                            uint64_t index, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
void atrbvh_i_clear_error(atrbvh_error *error);

/* --------------------------------------------------------------- threads */
/* Resolves options->threads (0 = the OpenMP default; 1 without OpenMP). */
int atrbvh_i_resolve_threads(int requested);
double atrbvh_i_now_ms(void);

/* ------------------------------------------------------------ the config */
/* Options after validation and default resolution. */
typedef struct atrbvh_i_config {
    atrbvh_method method;
    unsigned treelet_size; /* resolved, 0 for LBVH */
    unsigned rounds;       /* resolved, 0 for LBVH */
    unsigned gamma;        /* resolved first-round gamma */
    atrbvh_cost_params cost; /* ci, ct, collapse, max_leaf */
    int threads;
    int skip_invalid;
    atrbvh_backend backend;
    const char *opencl_device;
    atrbvh_progress_fn progress;
    void *progress_user;
} atrbvh_i_config;

atrbvh_status atrbvh_i_resolve_options(const atrbvh_build_options *options,
                                       atrbvh_i_config *config,
                                       atrbvh_error *error);

/* ----------------------------------------------------------- the scene */
/* Stage "bounds" output: one box per primitive kept in the build. */
typedef struct atrbvh_i_prims {
    uint32_t count;       /* primitives in the build                      */
    uint32_t *ids;        /* NULL when every input primitive is kept (the
                             identity); else count original indices,
                             ascending                                   */
    atrbvh_box *boxes;    /* count boxes, in build order                  */
    atrbvh_box scene;     /* union of the boxes                           */
    atrbvh_box centroids; /* box of the centres                           */
    size_t invalid;       /* primitives skipped (skip_invalid)            */
} atrbvh_i_prims;

void atrbvh_i_prims_free(atrbvh_i_prims *p);

/* Validates pointers, strides and counts (no per-primitive check); fills
 * the effective strides in bytes. */
atrbvh_status atrbvh_i_check_geometry(const atrbvh_geometry *g,
                                     size_t *vstride, size_t *istride,
                                     size_t *bstride, atrbvh_error *error);
/* Validates the geometry and computes boxes (stage "bounds"). */
atrbvh_status atrbvh_i_bounds(const atrbvh_geometry *g,
                              const atrbvh_i_config *cfg, atrbvh_i_prims *out,
                              atrbvh_error *error);

/* --------------------------------------------------------- morton, sort */
/* The Morton frame of a centroid box: per axis the low end and the scale
 * 2^21 / extent (0 for a zero extent), computed once on the host for
 * every backend. */
void atrbvh_i_morton_frame(const atrbvh_box *centroids, double lo[3],
                           double scale[3]);
/* Stage "morton": 63-bit keys of the box centres. */
void atrbvh_i_morton(const atrbvh_i_prims *p, uint64_t *keys, int threads);
/* Stage "sort": stable LSD radix sort of (keys, values) pairs; `tmp_keys`
 * and `tmp_values` are scratch of the same length. The sorted result ends in
 * keys/values. Passes whose digit is the same for every key are skipped.
 * Returns ATRBVH_ERR_NOMEM (nothing else) when scratch cannot be had. */
atrbvh_status atrbvh_i_radix_sort(uint64_t *keys, uint32_t *values, uint64_t *tmp_keys,
                                  uint32_t *tmp_values, uint32_t n,
                                  int threads);

/* ------------------------------------------------------------- the tree */
/* The binary tree the stages work on (structure of arrays).
 * n leaves; internal nodes 0 .. n-2 (the root is node 0), leaves
 * n-1 .. 2n-2 (leaf n-1+p holds sorted position p).  With n == 1 the root
 * is the single leaf, node 0.  Restructuring keeps the root at node 0. */
typedef struct atrbvh_i_tree {
    uint32_t n;
    uint32_t *left;      /* n-1 entries: child of internal node i       */
    uint32_t *right;     /* n-1 entries                                 */
    uint32_t *parent;    /* 2n-1 entries, ATRBVH_NONE for the root       */
    uint32_t *count;     /* 2n-1: primitives under the node             */
    atrbvh_box *box;     /* 2n-1                                        */
    double *cost;        /* 2n-1: unnormalised SAH cost of the subtree
                            (atrbvh_node_cost / atrbvh_leaf_cost)       */
    uint32_t *leaf_prim; /* n: leaf n-1+p -> original primitive index   */
} atrbvh_i_tree;

static inline int atrbvh_i_is_leaf(const atrbvh_i_tree *t, uint32_t node)
{
    return node >= t->n - 1;
}

atrbvh_status atrbvh_i_tree_alloc(atrbvh_i_tree *t, uint32_t n);
void atrbvh_i_tree_free(atrbvh_i_tree *t);

/* Stage "hierarchy" (Karras 2012): topology from sorted keys.  Fills left,
 * right, parent, and count of internal nodes. */
void atrbvh_i_hierarchy(const uint64_t *sorted_keys, atrbvh_i_tree *t,
                        int threads);
/* Stage "refit": leaf n-1+p gets prim_boxes[order[p]] (order: the sorted
 * build indices), then boxes, counts and costs bottom-up (post-order OpenMP
 * tasks).  Sets every field but left/right/parent/leaf_prim. */
void atrbvh_i_refit(atrbvh_i_tree *t, const atrbvh_box *prim_boxes,
                    const uint32_t *order, const atrbvh_cost_params *cost,
                    int threads);

/* Stage "optimise": TRBVH or ATRBVH treelet restructuring in place.  On
 * return boxes, counts, costs and parents are consistent. */
atrbvh_status atrbvh_i_optimise(atrbvh_i_tree *t, const atrbvh_i_config *cfg,
                                atrbvh_error *error);

/* Stage "collapse" and "layout": the public node array from the tree.
 * Leaves: the topmost node whose collapsed cost ct*A*N is cheaper than its
 * subtree (and N <= max_leaf) when collapsing; single primitives otherwise. */
atrbvh_status atrbvh_i_collapse_layout(const atrbvh_i_tree *t,
                                       const atrbvh_i_config *cfg,
                                       atrbvh_bvh *bvh, double *collapse_ms,
                                       double *layout_ms,
                                       uint32_t **capture_size,
                                       atrbvh_error *error);

/* ------------------------------------------------------------- the BVH */
#define ATRBVH_MAX_KERNEL_TIMES 32
struct atrbvh_bvh {
    atrbvh_node *nodes;
    size_t node_count;
    uint32_t *prim_indices;
    size_t prim_count;
    atrbvh_stats stats;
    struct atrbvh_i_device_info *device; /* NULL unless built by OpenCL */
};

/* The device and per-kernel device times of an OpenCL build (allocated
 * separately: CPU builds and loaded files stay small). */
typedef struct atrbvh_i_device_info {
    char name[128];
    unsigned kernel_count;
    char kernel_name[ATRBVH_MAX_KERNEL_TIMES][24];
    double kernel_ms[ATRBVH_MAX_KERNEL_TIMES];
} atrbvh_i_device_info;

/* ------------------------------------------------------- stage capture */
/* Copies of every stage's output, filled by atrbvh_i_build_run when asked
 * (atrbvh_validate_backends compares two of them).  Arrays are the
 * library allocator's; atrbvh_i_capture_free releases them. */
typedef struct atrbvh_i_capture {
    uint32_t n;
    atrbvh_box *prim_boxes;   /* bounds: n boxes in build order        */
    atrbvh_box scene, centroids;
    uint64_t *keys;           /* morton: n keys in build order         */
    uint64_t *sorted_keys;    /* sort: keys and build indices, sorted  */
    uint32_t *order;
    atrbvh_i_tree hierarchy;  /* left, right, parent, count, leaf_prim */
    atrbvh_i_tree refit;      /* + box, count, cost                    */
    atrbvh_i_tree optimise;   /* the same after the optimise stage     */
    uint32_t *collapse_size;  /* collapse: output nodes per subtree    */
} atrbvh_i_capture;

void atrbvh_i_capture_free(atrbvh_i_capture *c);
/* A deep copy of a tree (every array), for the capture. */
atrbvh_status atrbvh_i_tree_copy(atrbvh_i_tree *dst, const atrbvh_i_tree *src);

/* atrbvh_build with an optional capture (NULL: none). */
atrbvh_status atrbvh_i_build_run(const atrbvh_geometry *geometry,
                                 const atrbvh_build_options *options,
                                 atrbvh_bvh **out, atrbvh_i_capture *capture,
                                 atrbvh_error *error);
/* The end of every backend's build: stats from the configuration and the
 * node array (measure), stage times, the debug check. */
atrbvh_status atrbvh_i_build_finish(atrbvh_bvh *bvh, const atrbvh_i_config *cfg,
                                    size_t invalid, const double *stage_ms,
                                    double t0, atrbvh_error *error);
/* Records a kernel time under `name` (added to an existing entry). */
void atrbvh_i_bvh_add_kernel_time(atrbvh_bvh *bvh, const char *name,
                                  double ms);

/* The argument checks of the batch ray queries (lib/traverse.c); `fn`
 * names the caller in the message. */
atrbvh_status atrbvh_i_trav_check(const atrbvh_bvh *bvh,
                                  const atrbvh_geometry *g,
                                  const atrbvh_ray *rays, size_t count,
                                  const void *out, int threads,
                                  const char *fn, atrbvh_error *error);

#ifdef ATRBVH_HAVE_OPENCL
/* The OpenCL backend (cl/backend.c): the whole pipeline on a device. */
atrbvh_status atrbvh_i_cl_build(const atrbvh_geometry *geometry,
                                const atrbvh_i_config *cfg, atrbvh_bvh **out,
                                atrbvh_i_capture *capture,
                                atrbvh_error *error);
/* The ray queries on a device (kernels intersect_closest / intersect_any):
 * closest hits into `hits`, or, when `occluded` is non-NULL, any hits into
 * it.  Arguments already checked.  *kernel_ms (may be NULL): the kernel's
 * device time from its profiling event. */
atrbvh_status atrbvh_i_cl_trace(const atrbvh_bvh *bvh,
                                const atrbvh_geometry *geometry,
                                const atrbvh_ray *rays, size_t count,
                                atrbvh_hit *hits, uint8_t *occluded,
                                const char *device, double *kernel_ms,
                                atrbvh_error *error);
#endif

/* Allocates an empty BVH object with room for the arrays. */
atrbvh_bvh *atrbvh_i_bvh_alloc(size_t node_count, size_t prim_count);
/* Fills stats.nodes, leaves, primitives, max_depth, max_leaf_primitives and
 * sah (with stats.ci/ct) from the node array; fails on an invalid array or
 * when scratch cannot be allocated. */
atrbvh_status atrbvh_i_bvh_measure(atrbvh_bvh *bvh);
/* Structural check of a node array (used on load and, in debug builds,
 * after every build): every child index in range and after its parent,
 * leaf ranges tiling the index array in order, child boxes inside parents
 * when check_boxes.  (Index values are the caller's to check.) */
atrbvh_status atrbvh_i_bvh_check(const atrbvh_bvh *bvh, int check_boxes,
                                 atrbvh_error *error);

#endif
