/*
 * shared/stages.h - the per-item arithmetic of the bounds, refit and
 * collapse stages, written once for the CPU (C99) and the OpenCL backend
 * (OpenCL C 1.2).  Same rules as shared/arith.h (no libc, no VLAs, no
 * recursion).  Boxes and tree arrays are passed by value or through
 * ATRBVH_GLOBAL pointers; the callers do the memory traffic (and, on the
 * OpenCL side, the fences around the bottom-up counters).
 */
#ifndef ATRBVH_SHARED_STAGES_H
#define ATRBVH_SHARED_STAGES_H

#include "fetch.h"

/* ------------------------------------------------------------------ bounds */
/* Grows box b by point (x, y, z); returns 0 (b untouched on that axis
 * onwards) when a coordinate is NaN or infinite. */
ATRBVH_FN int atrbvh_box_grow(atrbvh_box *b, float x, float y, float z)
{
    float p[3];
    int k;
    p[0] = x;
    p[1] = y;
    p[2] = z;
    for (k = 0; k < 3; k++) {
        if (!atrbvh_finite(p[k]))
            return 0;
        if (p[k] < b->min[k])
            b->min[k] = p[k];
        if (p[k] > b->max[k])
            b->max[k] = p[k];
    }
    return 1;
}

/* Per-primitive outcome of the bounds stage, in increasing severity. */
#define ATRBVH_PRIM_OK 0
#define ATRBVH_PRIM_NONFINITE 1
#define ATRBVH_PRIM_BAD_INDEX 2
#define ATRBVH_PRIM_INVERTED 3

/* Box primitive from its six floats (min x, y, z, max x, y, z). */
ATRBVH_FN int atrbvh_prim_box_from_box(const float *b, atrbvh_box *out)
{
    int k;
    for (k = 0; k < 6; k++)
        if (!atrbvh_finite(b[k]))
            return ATRBVH_PRIM_NONFINITE;
    for (k = 0; k < 3; k++) {
        if (b[k] > b[k + 3])
            return ATRBVH_PRIM_INVERTED;
        out->min[k] = b[k];
        out->max[k] = b[k + 3];
    }
    return ATRBVH_PRIM_OK;
}

/* Box of triangle i (strides in elements, shared/fetch.h): corners in
 * order, each index checked against vertex_count before its vertex is
 * read.  Returns ATRBVH_PRIM_OK, ATRBVH_PRIM_BAD_INDEX (*bad_value: the
 * index) or ATRBVH_PRIM_NONFINITE, whichever the first failing corner
 * gives; *out is then partial.  The CPU bounds and the bounds_triangles
 * kernel both call this. */
ATRBVH_FN int atrbvh_prim_box_triangle(ATRBVH_CONST_GLOBAL float *vertices,
                                       atrbvh_u64 vstride,
                                       atrbvh_u64 vertex_count,
                                       ATRBVH_CONST_GLOBAL atrbvh_u32 *indices,
                                       atrbvh_u64 istride, int indexed,
                                       atrbvh_u64 i, atrbvh_box *out,
                                       atrbvh_u32 *bad_value)
{
    int c;
    /* The common case first: three indices in range and nine finite
     * coordinates, then the box by the same comparisons, in the same
     * order, as atrbvh_box_grow from an empty box - the same bits.  The
     * sum of the nine is finite (s - s is 0 exactly) only when all are,
     * and also fails when finite coordinates overflow it: then, as for
     * anything else, the corner-by-corner loop below decides, and finds
     * the first failing corner.  Written out per axis: GCC -O2 keeps
     * 3-iteration loops as loops. */
    {
        const atrbvh_u64 v0 = atrbvh_fetch_vertex_id(indices, istride,
                                                     indexed, i, 0),
                         v1 = atrbvh_fetch_vertex_id(indices, istride,
                                                     indexed, i, 1),
                         v2 = atrbvh_fetch_vertex_id(indices, istride,
                                                     indexed, i, 2);
        if (v0 < vertex_count && v1 < vertex_count && v2 < vertex_count) {
            ATRBVH_CONST_GLOBAL float *a = vertices + v0 * vstride,
                                      *b = vertices + v1 * vstride,
                                      *d = vertices + v2 * vstride;
            const float a0 = a[0], a1 = a[1], a2 = a[2], b0 = b[0],
                        b1 = b[1], b2 = b[2], d0 = d[0], d1 = d[1],
                        d2 = d[2];
            float s = a0 + a1;
            s = s + a2;
            s = s + b0;
            s = s + b1;
            s = s + b2;
            s = s + d0;
            s = s + d1;
            s = s + d2;
            if (s - s == 0.0f) {
                float lo, hi;
                lo = b0 < a0 ? b0 : a0;
                hi = b0 > a0 ? b0 : a0;
                out->min[0] = d0 < lo ? d0 : lo;
                out->max[0] = d0 > hi ? d0 : hi;
                lo = b1 < a1 ? b1 : a1;
                hi = b1 > a1 ? b1 : a1;
                out->min[1] = d1 < lo ? d1 : lo;
                out->max[1] = d1 > hi ? d1 : hi;
                lo = b2 < a2 ? b2 : a2;
                hi = b2 > a2 ? b2 : a2;
                out->min[2] = d2 < lo ? d2 : lo;
                out->max[2] = d2 > hi ? d2 : hi;
                return ATRBVH_PRIM_OK;
            }
        }
    }
    *out = atrbvh_box_empty();
    for (c = 0; c < 3; c++) {
        float p[3];
        atrbvh_u64 v = atrbvh_fetch_vertex_id(indices, istride, indexed, i, c);
        if (v >= vertex_count) {
            *bad_value = (atrbvh_u32)v;
            return ATRBVH_PRIM_BAD_INDEX;
        }
        atrbvh_fetch_vertex(vertices, vstride, v, p);
        if (!atrbvh_box_grow(out, p[0], p[1], p[2]))
            return ATRBVH_PRIM_NONFINITE;
    }
    return ATRBVH_PRIM_OK;
}

/* Box of box primitive i (stride in floats): ATRBVH_PRIM_OK,
 * ATRBVH_PRIM_NONFINITE or ATRBVH_PRIM_INVERTED (*out then empty or
 * partial).  The CPU bounds and the bounds_boxes kernel both call this. */
ATRBVH_FN int atrbvh_prim_box_box(ATRBVH_CONST_GLOBAL float *boxes,
                                  atrbvh_u64 bstride, atrbvh_u64 i,
                                  atrbvh_box *out)
{
    float f[6];
    atrbvh_fetch_box(boxes, bstride, i, f);
    *out = atrbvh_box_empty();
    return atrbvh_prim_box_from_box(f, out);
}

/* ---------------------------------------------------------- Morton frame */
/* The Morton frame of a centroid box, per axis: the low end, and the
 * scale 2^21 / extent (0 for a zero extent) that atrbvh_morton_quantise
 * takes.  The host computes it (lib/prims.c, for the CPU backend and
 * triangle splitting) and so does the OpenCL bounds kernels' last block,
 * from the same box, so both key the primitives in the same frame, bit
 * for bit (double subtraction and division are correctly rounded on
 * both). */
ATRBVH_FN void atrbvh_morton_frame(atrbvh_box centroids, double *lo,
                                   double *scale)
{
    int k;
    for (k = 0; k < 3; k++) {
        double extent = (double)centroids.max[k] - (double)centroids.min[k];
        lo[k] = (double)centroids.min[k];
        scale[k] = extent > 0.0 ? (double)(1u << ATRBVH_MORTON_BITS) / extent
                                : 0.0;
    }
}

/* ---------------------------------------------------------- scene boxes */
/* Adds a primitive box to the scene box and its centre to the centroid
 * box (min/max only: any reduction order gives the same result). */
ATRBVH_FN void atrbvh_scene_add(atrbvh_box *scene, atrbvh_box *centroids,
                                atrbvh_box b)
{
    /* Written out per axis (GCC -O2 keeps a 3-iteration loop). */
    const float c0 = atrbvh_box_centre(b, 0), c1 = atrbvh_box_centre(b, 1),
                c2 = atrbvh_box_centre(b, 2);
    scene->min[0] = b.min[0] < scene->min[0] ? b.min[0] : scene->min[0];
    scene->min[1] = b.min[1] < scene->min[1] ? b.min[1] : scene->min[1];
    scene->min[2] = b.min[2] < scene->min[2] ? b.min[2] : scene->min[2];
    scene->max[0] = b.max[0] > scene->max[0] ? b.max[0] : scene->max[0];
    scene->max[1] = b.max[1] > scene->max[1] ? b.max[1] : scene->max[1];
    scene->max[2] = b.max[2] > scene->max[2] ? b.max[2] : scene->max[2];
    centroids->min[0] = c0 < centroids->min[0] ? c0 : centroids->min[0];
    centroids->min[1] = c1 < centroids->min[1] ? c1 : centroids->min[1];
    centroids->min[2] = c2 < centroids->min[2] ? c2 : centroids->min[2];
    centroids->max[0] = c0 > centroids->max[0] ? c0 : centroids->max[0];
    centroids->max[1] = c1 > centroids->max[1] ? c1 : centroids->max[1];
    centroids->max[2] = c2 > centroids->max[2] ? c2 : centroids->max[2];
}

/* ------------------------------------------------------------------- refit */
/* A leaf's cost from its box. */
ATRBVH_FN double atrbvh_refit_leaf_cost(const atrbvh_cost_params *p,
                                        atrbvh_box b)
{
    return atrbvh_leaf_cost(p, atrbvh_box_area(b));
}

/* An internal node from its children (left first): box, count, cost. */
ATRBVH_FN void atrbvh_refit_node(const atrbvh_cost_params *p, atrbvh_box bl,
                                 atrbvh_u32 nl, double cl, atrbvh_box br,
                                 atrbvh_u32 nr, double cr, atrbvh_box *box,
                                 atrbvh_u32 *count, double *cost)
{
    int collapsed;
    *box = atrbvh_box_union(bl, br);
    *count = nl + nr;
    *cost = atrbvh_node_cost(p, atrbvh_box_area(*box), *count, cl, cr,
                             &collapsed);
}

/* ---------------------------------------------------------------- collapse */
/* Output nodes of a subtree, with the flag set when the node is emitted as
 * a leaf (holding every primitive below it). */
#define ATRBVH_SIZE_LEAF 0x80000000u
#define ATRBVH_SIZE_MASK 0x7fffffffu

/* The collapse decision of an internal node: a leaf when its collapsed cost
 * is strictly cheaper than its best subtree cost (atrbvh_node_cost's
 * choice), else 1 + the sizes of its children. */
ATRBVH_FN atrbvh_u32 atrbvh_collapse_size(const atrbvh_cost_params *p,
                                          atrbvh_box b, atrbvh_u32 count,
                                          double cl, double cr,
                                          atrbvh_u32 size_l, atrbvh_u32 size_r)
{
    int collapsed = 0;
    (void)atrbvh_node_cost(p, atrbvh_box_area(b), count, cl, cr, &collapsed);
    if (collapsed)
        return 1u | ATRBVH_SIZE_LEAF;
    return 1u + (size_l & ATRBVH_SIZE_MASK) + (size_r & ATRBVH_SIZE_MASK);
}

/* The size of a node whose collapse decision was kept (flat: 1 when it is
 * emitted as a leaf), from its children's: the collapse of an optimised
 * tree, which keeps the decisions (treelet.h's atrbvh_treelet_tree.flat). */
ATRBVH_FN atrbvh_u32 atrbvh_size_counted(unsigned flat, atrbvh_u32 size_l,
                                         atrbvh_u32 size_r)
{
    if (flat)
        return 1u | ATRBVH_SIZE_LEAF;
    return 1u + (size_l & ATRBVH_SIZE_MASK) + (size_r & ATRBVH_SIZE_MASK);
}

/* The LBVH's refit and collapse in one climb: atrbvh_refit_node's box,
 * count and cost, and the node's collapse size from the same cost
 * decision (what atrbvh_collapse_size computes again from them).  The
 * refit kernel calls it for an LBVH, whose collapse stage then has
 * nothing to do (lib/cpu/refit.c's climb_sizes does the same on the
 * CPU). */
ATRBVH_FN atrbvh_u32 atrbvh_refit_node_size(const atrbvh_cost_params *p,
                                            atrbvh_box bl, atrbvh_u32 nl,
                                            double cl, atrbvh_u32 size_l,
                                            atrbvh_box br, atrbvh_u32 nr,
                                            double cr, atrbvh_u32 size_r,
                                            atrbvh_box *box,
                                            atrbvh_u32 *count, double *cost)
{
    int collapsed;
    *box = atrbvh_box_union(bl, br);
    *count = nl + nr;
    *cost = atrbvh_node_cost(p, atrbvh_box_area(*box), *count, cl, cr,
                             &collapsed);
    if (collapsed)
        return 1u | ATRBVH_SIZE_LEAF;
    return 1u + (size_l & ATRBVH_SIZE_MASK) + (size_r & ATRBVH_SIZE_MASK);
}

/* ------------------------------------------------------------------ layout */
/* The depth-first placement rule of the output (lib/cpu/collapse.c's
 * top-down emission, which cl/kernels.cl's layout_top/layout mirror): a node
 * at output position `pos` whose primitives start at `prim` puts its left
 * child at pos + 1 with the same first primitive, and its right child
 * after the whole left subtree: pos + 1 + size(left), primitives from
 * prim + count(left).  `size_left` is the left child's collapse size
 * (ATRBVH_SIZE_LEAF flag allowed). */
ATRBVH_FN atrbvh_u32 atrbvh_layout_right_pos(atrbvh_u32 pos,
                                             atrbvh_u32 size_left)
{
    return pos + 1u + (size_left & ATRBVH_SIZE_MASK);
}

ATRBVH_FN atrbvh_u32 atrbvh_layout_right_prim(atrbvh_u32 prim,
                                              atrbvh_u32 count_left)
{
    return prim + count_left;
}

/* Writes the output node at `pos` (atrbvh_node, depth-first) into *out:
 * a leaf (size has ATRBVH_SIZE_LEAF) holds primitives prim .. prim +
 * count - 1; an internal node's left child is the next node and its right
 * child is at atrbvh_layout_right_pos.  Field by field into place: a node
 * built in a local and copied out was reassembled by GCC 12 through the
 * stack in pieces of other sizes than it was stored in, and each reload
 * waited for the stores (perf, the CPU layout: half of emit()'s
 * samples). */
ATRBVH_FN void atrbvh_layout_write(ATRBVH_GLOBAL atrbvh_node *out,
                                   atrbvh_box b, atrbvh_u32 size,
                                   atrbvh_u32 count, atrbvh_u32 pos,
                                   atrbvh_u32 prim, atrbvh_u32 size_left)
{
    out->min[0] = b.min[0];
    out->min[1] = b.min[1];
    out->min[2] = b.min[2];
    out->max[0] = b.max[0];
    out->max[1] = b.max[1];
    out->max[2] = b.max[2];
    if (size & ATRBVH_SIZE_LEAF) {
        out->index = prim;
        out->count = count;
    } else {
        out->index = atrbvh_layout_right_pos(pos, size_left);
        out->count = 0u;
    }
}

#endif
