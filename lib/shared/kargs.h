/*
 * shared/kargs.h - the scalar arguments of the OpenCL kernels, one plain
 * struct per stage, passed by value (clSetKernelArg with the struct's
 * size).  The host (cl/stages.c, cl/trace.c) fills one struct per launch;
 * the kernel (cl/kernels.cl) reads its fields.
 *
 * Only u32, u64 and double fields, largest first, padded by hand to a
 * multiple of 8 bytes, so the layout is the same under any C ABI and
 * OpenCL C; the assertions at the end compile on both sides and pin every
 * size (types.h's ATRBVH_STATIC_ASSERT).  Strides are in elements (floats
 * or u32), counts are of items.
 */
#ifndef ATRBVH_SHARED_KARGS_H
#define ATRBVH_SHARED_KARGS_H

#include "types.h"

/* bounds_triangles, bounds_boxes */
typedef struct atrbvh_kargs_bounds {
    atrbvh_u64 vstride;      /* vertices: floats between vertices       */
    atrbvh_u64 istride;      /* indices: u32 between triangles          */
    atrbvh_u64 bstride;      /* boxes: floats between boxes             */
    atrbvh_u64 vertex_count;
    atrbvh_u32 n;            /* primitives                              */
    atrbvh_u32 indexed;      /* 1: indices used                         */
    atrbvh_u32 parts;        /* blocks, one partial box pair each       */
    atrbvh_u32 pad0;
} atrbvh_kargs_bounds;

/* What the bounds kernels' last block writes at the start of the partial
 * boxes' buffer (not an argument: a record in device memory, read by the
 * morton kernel and, in one read, by the host): the blocks' scene and
 * centroid boxes united in block order, the Morton frame of the centroid
 * box (shared/stages.h atrbvh_morton_frame) and the count of invalid
 * primitives.  Its size keeps the boxes after it aligned. */
typedef struct atrbvh_bounds_record {
    double lo[3];
    double scale[3];
    atrbvh_box scene;
    atrbvh_box centroids;
    atrbvh_u32 invalid;
    atrbvh_u32 pad0;
} atrbvh_bounds_record;

/* morton: the Morton frame (atrbvh_morton_quantise): the host's, or with
 * device_frame the bounds record's; and the sort's blocks (the morton
 * kernel finds the keys' varying bits by them) */
typedef struct atrbvh_kargs_morton {
    double lo[3];
    double scale[3];
    atrbvh_u32 n;
    atrbvh_u32 blocks;  /* as atrbvh_kargs_sort */
    atrbvh_u32 device_frame; /* 1: the frame of the bounds record */
    atrbvh_u32 pad1;
} atrbvh_kargs_morton;

/* sort_vary, sort_count, sort_scatter, sort_buckets: the MSD pass and the
 * buckets (shared/sort.h; the digit is atrbvh_sort_msd's, found on the
 * device), over the n keys from `off` of their arrays: the whole array,
 * or one big bucket of the first pass split by a pass of its own
 * (atrbvh_sort_big) */
typedef struct atrbvh_kargs_sort {
    atrbvh_u32 n;
    atrbvh_u32 blocks;  /* contiguous blocks (shared/sort.h) */
    atrbvh_u32 buckets; /* the most any n keys make: sort_buckets' items */
    atrbvh_u32 entries; /* buckets * blocks: the counts' size */
    atrbvh_u32 off;     /* the keys' first position in the arrays */
    atrbvh_u32 big;     /* sort_buckets leaves buckets of more keys alone */
    atrbvh_u32 into;    /* sort_buckets: 1 sorts from the first pair into
                           the second, 0 in place (the second scratch) */
    atrbvh_u32 pad;
} atrbvh_kargs_sort;

/* The hierarchy kernel's leftovers (cl/kernels.cl): a block's prefix
 * minima and its final stack are strictly monotone in delta (0 .. 95), so
 * at most ATRBVH_CL_HIER_SIDE each, as lib/cpu/hierarchy.c's; each is
 * recorded as two words (split position, subtree root), so a block's
 * share of the host's leftover buffer is ATRBVH_CL_HIER_OVER words, and
 * one count per block follows all shares, then one word per block: its
 * first pair of keys out of order + 1 (0: in order). */
#define ATRBVH_CL_HIER_SIDE 96u
#define ATRBVH_CL_HIER_OVER (4u * ATRBVH_CL_HIER_SIDE)

/* hierarchy, refit, collapse, layout */
typedef struct atrbvh_kargs_tree {
    double ci, ct;        /* the cost model (atrbvh_cost_params) */
    atrbvh_u32 n;         /* leaves */
    atrbvh_u32 collapse;
    atrbvh_u32 max_leaf;
    atrbvh_u32 has_ids;   /* hierarchy: 1 when kept ids map the leaves */
    atrbvh_u32 sizes;     /* hierarchy, refit: 1 for the collapse sizes
                             too (LBVH); hierarchy 2 for the collapse
                             decisions (a tree to optimise, which keeps
                             them: collapse_count counts its sizes) */
    atrbvh_u32 ranges;    /* layout: 1 when every subtree holds the leaves
                             of a range of sorted positions, in order (the
                             hierarchy's tree, not optimised) */
} atrbvh_kargs_tree;

/* opt_prepare, opt_round: one round */
typedef struct atrbvh_kargs_optimise {
    double ci, ct;
    atrbvh_u64 stride;    /* scratch bytes per worker, and the offsets of */
    atrbvh_u64 off_cost;  /* its arrays within them                       */
    atrbvh_u64 off_count;
    atrbvh_u64 off_split;
    atrbvh_u64 off_dist;
    atrbvh_u64 off_dist4; /* opt_round4: ATRBVH's four interleaved
                             matrices (atrbvh_agglomerate4), TRBVH's
                             interleaved tables (atrbvh_trbvh_costs4)    */
    atrbvh_u64 off_lanes; /* opt_round4, TRBVH: lanes 1-3's splits, each
                             off_dist - off_split bytes (lane 0's at
                             off_split)                                   */
    atrbvh_u32 collapse;
    atrbvh_u32 max_leaf;
    atrbvh_u32 n_internal;
    atrbvh_u32 gamma;     /* crown: subtrees of at least gamma primitives */
    atrbvh_u32 list_len;  /* unused (opt_round finds the walks' starts in
                             opt_prepare's marks, on the device)         */
    atrbvh_u32 treelet_size;
    atrbvh_u32 agglomerative; /* 1: ATRBVH, 0: TRBVH                       */
    atrbvh_u32 workers;
    atrbvh_u32 round;     /* from 0 (the skip marks)                      */
    atrbvh_u32 marks;     /* 1: skip marks (atrbvh_treelet_process_marked) */
    atrbvh_u32 walks;     /* 1: opt_round4 (several treelets an item)     */
    atrbvh_u32 flags;     /* 1: the collapse decisions kept (treelet.h's
                             atrbvh_treelet_tree.flat)                    */
} atrbvh_kargs_optimise;

/* intersect_closest, intersect_any (atrbvh_trav_scene's scalars) */
typedef struct atrbvh_kargs_trace {
    atrbvh_u64 node_count;
    atrbvh_u64 prim_count;      /* entries of the primitive index array */
    atrbvh_u64 primitive_count; /* of the geometry                      */
    atrbvh_u64 vertex_count;
    atrbvh_u64 vstride;
    atrbvh_u64 istride;
    atrbvh_u64 bstride;
    atrbvh_u64 ray_count;
    atrbvh_u32 boxes;   /* 0 triangles, 1 boxes */
    atrbvh_u32 indexed;
    atrbvh_u32 count_cost; /* 1: write each ray's box and primitive tests */
    atrbvh_u32 float_slabs; /* 1: the device keeps float subnormals, so
                             * rays may take the float node test */
} atrbvh_kargs_trace;

/* The cost model from a struct's fields. */
ATRBVH_FN atrbvh_cost_params atrbvh_kargs_cost(double ci, double ct,
                                               atrbvh_u32 collapse,
                                               atrbvh_u32 max_leaf)
{
    atrbvh_cost_params p;
    p.ci = ci;
    p.ct = ct;
    p.collapse = collapse != 0u;
    p.max_leaf = max_leaf;
    return p;
}

ATRBVH_STATIC_ASSERT(sizeof(atrbvh_kargs_bounds) == 48, kargs_bounds);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_kargs_bounds, n) == 32,
                     kargs_bounds_n);
ATRBVH_STATIC_ASSERT(sizeof(atrbvh_bounds_record) == 104, bounds_record);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_bounds_record, scene) == 48,
                     bounds_record_scene);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_bounds_record, invalid) == 96,
                     bounds_record_invalid);
ATRBVH_STATIC_ASSERT(sizeof(atrbvh_kargs_morton) == 64, kargs_morton);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_kargs_morton, n) == 48,
                     kargs_morton_n);
ATRBVH_STATIC_ASSERT(sizeof(atrbvh_kargs_sort) == 32, kargs_sort);
ATRBVH_STATIC_ASSERT(sizeof(atrbvh_kargs_tree) == 40, kargs_tree);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_kargs_tree, n) == 16,
                     kargs_tree_n);
ATRBVH_STATIC_ASSERT(sizeof(atrbvh_kargs_optimise) == 120, kargs_optimise);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_kargs_optimise, collapse) == 72,
                     kargs_optimise_collapse);
ATRBVH_STATIC_ASSERT(sizeof(atrbvh_kargs_trace) == 80, kargs_trace);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_kargs_trace, boxes) == 64,
                     kargs_trace_boxes);

#endif
