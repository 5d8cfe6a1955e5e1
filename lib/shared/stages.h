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

#include "arith.h"

/* ------------------------------------------------------------------ bounds */
/* Nonzero when x is neither NaN nor infinite: x - x is 0 exactly for every
 * finite x and NaN otherwise (no libc isfinite needed; never compiled with
 * fast-math, which would break it). */
ATRBVH_FN int atrbvh_finite(float x)
{
    float d = x - x;
    return d == 0.0f;
}

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

/* ---------------------------------------------------------- scene boxes */
/* Adds a primitive box to the scene box and its centre to the centroid
 * box (min/max only: any reduction order gives the same result). */
ATRBVH_FN void atrbvh_scene_add(atrbvh_box *scene, atrbvh_box *centroids,
                                atrbvh_box b)
{
    int k;
    for (k = 0; k < 3; k++) {
        float c = atrbvh_box_centre(b, k);
        scene->min[k] = b.min[k] < scene->min[k] ? b.min[k] : scene->min[k];
        scene->max[k] = b.max[k] > scene->max[k] ? b.max[k] : scene->max[k];
        centroids->min[k] = c < centroids->min[k] ? c : centroids->min[k];
        centroids->max[k] = c > centroids->max[k] ? c : centroids->max[k];
    }
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

#endif
