/*
 * internal.h - what the library's files share and nothing outside sees.
 * Non-static internal symbols carry the __atrbvh_ prefix (hidden by
 * -fvisibility=hidden; the exported list is pinned by a test).
 */
#ifndef ATRBVH_INTERNAL_H
#define ATRBVH_INTERNAL_H

#include "atrbvh.h"
#include "shared/arith.h"

#include <stddef.h>
#include <stdint.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#define ATRBVH_NONE UINT32_MAX

/* ------------------------------------------------------------ allocation */
void *__atrbvh_malloc(size_t size);
void __atrbvh_free(void *ptr);
/* Multiplies count * size, failing (returns 0, sets *out = 0) on overflow. */
int __atrbvh_mul_size(size_t count, size_t size, size_t *out);
/* Allocates count * size bytes; NULL on overflow or allocator failure. */
void *__atrbvh_alloc_array(size_t count, size_t size);

/* ---------------------------------------------------------------- errors */
/* Fills `error` (may be NULL) and returns `status`. printf-style text. */
atrbvh_status __atrbvh_fail(atrbvh_error *error, atrbvh_status status,
                            uint64_t index, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
void __atrbvh_clear_error(atrbvh_error *error);

/* --------------------------------------------------------------- threads */
/* Resolves options->threads (0 = the OpenMP default; 1 without OpenMP). */
int __atrbvh_resolve_threads(int requested);
double __atrbvh_now_ms(void);

/* ------------------------------------------------------------ the config */
/* Options after validation and default resolution. */
typedef struct __atrbvh_config {
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
} __atrbvh_config;

atrbvh_status __atrbvh_resolve_options(const atrbvh_build_options *options,
                                       __atrbvh_config *config,
                                       atrbvh_error *error);

/* ----------------------------------------------------------- the scene */
/* Stage "bounds" output: one box per primitive kept in the build. */
typedef struct __atrbvh_prims {
    uint32_t count;       /* primitives in the build                      */
    uint32_t *ids;        /* NULL when every input primitive is kept (the
                             identity); else count original indices,
                             ascending                                   */
    atrbvh_box *boxes;    /* count boxes, in build order                  */
    atrbvh_box scene;     /* union of the boxes                           */
    atrbvh_box centroids; /* box of the centres                           */
    size_t invalid;       /* primitives skipped (skip_invalid)            */
} __atrbvh_prims;

void __atrbvh_prims_free(__atrbvh_prims *p);

/* Validates the geometry and computes boxes (stage "bounds"). */
atrbvh_status __atrbvh_bounds(const atrbvh_geometry *g,
                              const __atrbvh_config *cfg, __atrbvh_prims *out,
                              atrbvh_error *error);

/* --------------------------------------------------------- morton, sort */
/* Stage "morton": 63-bit keys of the box centres. */
void __atrbvh_morton(const __atrbvh_prims *p, uint64_t *keys, int threads);
/* Stage "sort": stable LSD radix sort of (keys, values) pairs; `tmp_keys`
 * and `tmp_values` are scratch of the same length. The sorted result ends in
 * keys/values. Passes whose digit is the same for every key are skipped.
 * Returns ATRBVH_ERR_NOMEM (nothing else) when scratch cannot be had. */
atrbvh_status __atrbvh_radix_sort(uint64_t *keys, uint32_t *values, uint64_t *tmp_keys,
                                  uint32_t *tmp_values, uint32_t n,
                                  int threads);

/* ------------------------------------------------------------- the tree */
/* The binary tree the stages work on (structure of arrays).
 * n leaves; internal nodes 0 .. n-2 (the root is node 0), leaves
 * n-1 .. 2n-2 (leaf n-1+p holds sorted position p).  With n == 1 the root
 * is the single leaf, node 0.  Restructuring keeps the root at node 0. */
typedef struct __atrbvh_tree {
    uint32_t n;
    uint32_t *left;      /* n-1 entries: child of internal node i       */
    uint32_t *right;     /* n-1 entries                                 */
    uint32_t *parent;    /* 2n-1 entries, ATRBVH_NONE for the root       */
    uint32_t *count;     /* 2n-1: primitives under the node             */
    atrbvh_box *box;     /* 2n-1                                        */
    double *cost;        /* 2n-1: unnormalised SAH cost of the subtree
                            (atrbvh_node_cost / atrbvh_leaf_cost)       */
    uint32_t *leaf_prim; /* n: leaf n-1+p -> original primitive index   */
} __atrbvh_tree;

static inline int __atrbvh_is_leaf(const __atrbvh_tree *t, uint32_t node)
{
    return node >= t->n - 1;
}

atrbvh_status __atrbvh_tree_alloc(__atrbvh_tree *t, uint32_t n);
void __atrbvh_tree_free(__atrbvh_tree *t);

/* Stage "hierarchy" (Karras 2012): topology from sorted keys.  Fills left,
 * right, parent, and count of internal nodes. */
void __atrbvh_hierarchy(const uint64_t *sorted_keys, __atrbvh_tree *t,
                        int threads);
/* Stage "refit": leaf n-1+p gets prim_boxes[order[p]] (order: the sorted
 * build indices), then boxes, counts and costs bottom-up (post-order OpenMP
 * tasks).  Sets every field but left/right/parent/leaf_prim. */
void __atrbvh_refit(__atrbvh_tree *t, const atrbvh_box *prim_boxes,
                    const uint32_t *order, const atrbvh_cost_params *cost,
                    int threads);

/* Stage "optimise": TRBVH or ATRBVH treelet restructuring in place.  On
 * return boxes, counts, costs and parents are consistent. */
atrbvh_status __atrbvh_optimise(__atrbvh_tree *t, const __atrbvh_config *cfg,
                                atrbvh_error *error);

/* Stage "collapse" and "layout": the public node array from the tree.
 * Leaves: the topmost node whose collapsed cost ct*A*N is cheaper than its
 * subtree (and N <= max_leaf) when collapsing; single primitives otherwise. */
atrbvh_status __atrbvh_collapse_layout(const __atrbvh_tree *t,
                                       const __atrbvh_config *cfg,
                                       atrbvh_bvh *bvh, double *collapse_ms,
                                       double *layout_ms, atrbvh_error *error);

/* ------------------------------------------------------------- the BVH */
struct atrbvh_bvh {
    atrbvh_node *nodes;
    size_t node_count;
    uint32_t *prim_indices;
    size_t prim_count;
    atrbvh_stats stats;
};

/* Allocates an empty BVH object with room for the arrays. */
atrbvh_bvh *__atrbvh_bvh_alloc(size_t node_count, size_t prim_count);
/* Fills stats.nodes, leaves, primitives, max_depth, max_leaf_primitives and
 * sah (with stats.ci/ct) from the node array; fails on an invalid array or
 * when scratch cannot be allocated. */
atrbvh_status __atrbvh_bvh_measure(atrbvh_bvh *bvh);
/* Structural check of a node array (used on load and, in debug builds,
 * after every build): every child index in range and after its parent,
 * leaf ranges tiling the index array in order, child boxes inside parents
 * when check_boxes.  (Index values are the caller's to check.) */
atrbvh_status __atrbvh_bvh_check(const atrbvh_bvh *bvh, int check_boxes,
                                 atrbvh_error *error);

#endif
