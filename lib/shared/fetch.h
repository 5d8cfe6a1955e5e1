/*
 * shared/fetch.h - reading one primitive from the caller's geometry,
 * written once for the bounds stage (CPU lib/cpu/bounds.c, OpenCL
 * bounds_triangles/bounds_boxes) and the ray queries (shared/traverse.h).
 *
 * The geometry is read in place through element strides: vertices and
 * boxes in floats, indices in u32 (the pipeline checks that the byte
 * strides are multiples of 4, so byte stride / 4 is exact).  Pointers are
 * ATRBVH_CONST_GLOBAL: device buffers in OpenCL, the caller's arrays in C.
 */
#ifndef ATRBVH_SHARED_FETCH_H
#define ATRBVH_SHARED_FETCH_H

#include "types.h"

/* Vertex id of corner c (0..2) of triangle i: indices[i * istride + c]
 * when indexed, else 3i + c (a plain triangle list). */
ATRBVH_FN atrbvh_u64 atrbvh_fetch_vertex_id(
    ATRBVH_CONST_GLOBAL atrbvh_u32 *indices, atrbvh_u64 istride, int indexed,
    atrbvh_u64 i, int c)
{
    if (indexed)
        return (atrbvh_u64)indices[i * istride + (atrbvh_u64)c];
    return 3u * i + (atrbvh_u64)c;
}

/* The three coordinates of vertex v. */
ATRBVH_FN void atrbvh_fetch_vertex(ATRBVH_CONST_GLOBAL float *vertices,
                                   atrbvh_u64 vstride, atrbvh_u64 v,
                                   float p[3])
{
    int c;
    for (c = 0; c < 3; c++)
        p[c] = vertices[v * vstride + (atrbvh_u64)c];
}

/* The six floats of box i: min x, y, z, max x, y, z. */
ATRBVH_FN void atrbvh_fetch_box(ATRBVH_CONST_GLOBAL float *boxes,
                                atrbvh_u64 bstride, atrbvh_u64 i, float f[6])
{
    int k;
    for (k = 0; k < 6; k++)
        f[k] = boxes[i * bstride + (atrbvh_u64)k];
}

#endif
