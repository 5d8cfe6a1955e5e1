/*
 * shared/lanes.h - eight primitives at a time: the lane form of the bounds
 * stage's per-item rules (shared/stages.h: atrbvh_prim_box_triangle's
 * common case, then atrbvh_scene_add), written once for the CPU's AVX2
 * sweep (lib/prims.c; C99 with the AVX2 intrinsics of GCC and Clang on
 * x86) and the OpenCL bounds kernel (cl/kernels.cl, float8).  Each lane
 * computes what the scalar rule computes for its item, by the same
 * operations in the same operand order, so the bits are the scalar
 * rule's: the CPU builds once more with ATRBVH_NO_AVX2 in test_hashes, and
 * test_opencl's bounds_eight_at_a_time checks the kernel against the CPU.
 * Only the loads and stores are each side's own (gathers on the CPU, a
 * lane at a time in OpenCL C).
 *
 * ATRBVH_LANES is defined where the lanes exist: always in OpenCL C, in
 * C where the compiler has the AVX2 intrinsics (the caller still asks the
 * processor, atrbvh_i_avx2, before it calls a lane function).
 */
#ifndef ATRBVH_SHARED_LANES_H
#define ATRBVH_SHARED_LANES_H

#include "stages.h"

#ifdef __OPENCL_VERSION__
#define ATRBVH_LANES 1
typedef float8 atrbvh_f8;
#define ATRBVH_LANES_FN static inline
#define atrbvh_f8_set1(x) ((float8)(x))
#define atrbvh_f8_add(a, b) ((a) + (b))
#define atrbvh_f8_mul(a, b) ((a) * (b))
/* a < b ? a : b and a > b ? a : b, lane by lane */
#define atrbvh_f8_lt_pick(a, b) select((b), (a), (a) < (b))
#define atrbvh_f8_gt_pick(a, b) select((b), (a), (a) > (b))
/* whether s - s is 0 in every lane (s finite in every lane) */
#define atrbvh_f8_all_finite(s) all(isequal((s) - (s), (float8)(0.0f)))
#elif (defined(__GNUC__) || defined(__clang__)) &&                          \
    (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#include <math.h> /* INFINITY */
#define ATRBVH_LANES 1
typedef __m256 atrbvh_f8;
/* Compiled for AVX2 whatever the file's target, and inlined into its
 * AVX2 caller (the lanes then stay in registers). */
#define ATRBVH_LANES_FN                                                        \
    static inline __attribute__((always_inline, target("avx2")))
#define atrbvh_f8_set1(x) _mm256_set1_ps(x)
#define atrbvh_f8_add(a, b) _mm256_add_ps((a), (b))
#define atrbvh_f8_mul(a, b) _mm256_mul_ps((a), (b))
/* MINPS and MAXPS are a < b ? a : b and a > b ? a : b (the second operand
 * for equal values and NaN), lane by lane */
#define atrbvh_f8_lt_pick(a, b) _mm256_min_ps((a), (b))
#define atrbvh_f8_gt_pick(a, b) _mm256_max_ps((a), (b))
#define atrbvh_f8_all_finite(s)                                                \
    (_mm256_movemask_ps(_mm256_cmp_ps(_mm256_sub_ps((s), (s)),                \
                                      _mm256_setzero_ps(), _CMP_EQ_OQ)) ==    \
     0xff)
#endif

#ifdef ATRBVH_LANES
/* The lanes' accumulators of the scene and centroid boxes: scene min x,
 * y, z, max x, y, z, then the centroids' alike. */
#define ATRBVH_TRI8_ACC 12

ATRBVH_LANES_FN void atrbvh_tri8_acc_init(atrbvh_f8 *acc)
{
    int k;
    for (k = 0; k < 3; k++) {
        acc[k] = acc[6 + k] = atrbvh_f8_set1(INFINITY);
        acc[3 + k] = acc[9 + k] = atrbvh_f8_set1(-INFINITY);
    }
}

/* Eight triangles, lane l the triangle of the caller's item j + l, from
 * their corners' coordinates c[corner][axis], by atrbvh_prim_box_triangle's
 * common case: the nine coordinates' sum in the rule's order (a0 + a1 +
 * a2 + b0 + ... + d2), finite in every lane, else 0 and nothing written
 * (the caller takes the eight one at a time by the scalar rule, which
 * also finds what is wrong).  Else 1, the boxes' min and max per axis in
 * mn and mx by the rule's comparisons, and each lane's box added to the
 * lane's scene and centroid boxes in acc as atrbvh_scene_add adds it. */
ATRBVH_LANES_FN int atrbvh_tri8_boxes(atrbvh_f8 (*c)[3],
                                      atrbvh_f8 *mn, atrbvh_f8 *mx,
                                      atrbvh_f8 *acc)
{
    /* ("half" is a type in OpenCL C) */
    const atrbvh_f8 one_half = atrbvh_f8_set1(0.5f);
    atrbvh_f8 sum;
    int k;
    sum = atrbvh_f8_add(c[0][0], c[0][1]);
    sum = atrbvh_f8_add(sum, c[0][2]);
    sum = atrbvh_f8_add(sum, c[1][0]);
    sum = atrbvh_f8_add(sum, c[1][1]);
    sum = atrbvh_f8_add(sum, c[1][2]);
    sum = atrbvh_f8_add(sum, c[2][0]);
    sum = atrbvh_f8_add(sum, c[2][1]);
    sum = atrbvh_f8_add(sum, c[2][2]);
    if (!atrbvh_f8_all_finite(sum))
        return 0;
    for (k = 0; k < 3; k++) {
        /* lo = b < a ? b : a; min = d < lo ? d : lo (and max alike) */
        mn[k] = atrbvh_f8_lt_pick(c[2][k], atrbvh_f8_lt_pick(c[1][k], c[0][k]));
        mx[k] = atrbvh_f8_gt_pick(c[2][k], atrbvh_f8_gt_pick(c[1][k], c[0][k]));
        /* atrbvh_scene_add: the box, then its centre (atrbvh_box_centre) */
        acc[k] = atrbvh_f8_lt_pick(mn[k], acc[k]);
        acc[3 + k] = atrbvh_f8_gt_pick(mx[k], acc[3 + k]);
        sum = atrbvh_f8_add(atrbvh_f8_mul(one_half, mn[k]),
                            atrbvh_f8_mul(one_half, mx[k]));
        acc[6 + k] = atrbvh_f8_lt_pick(sum, acc[6 + k]);
        acc[9 + k] = atrbvh_f8_gt_pick(sum, acc[9 + k]);
    }
    return 1;
}
#endif /* ATRBVH_LANES */

/* The accumulators' lanes, stored as t[vector][lane], into *scene and
 * *centroids, lane by lane as boxes are united (min and max: in any order
 * the same values, up to the sign of a zero, which no Morton frame or SAH
 * distinguishes).  Plain scalar code: each side stores its vectors
 * first.  (No const on the arrays of arrays: C99 would not convert a
 * caller's float[12][8] to a pointer to const arrays without a cast.) */
ATRBVH_FN void atrbvh_tri8_acc_unite(float (*t)[8], atrbvh_box *scene,
                                     atrbvh_box *centroids)
{
    int k, l;
    for (l = 0; l < 8; l++) {
        atrbvh_box s, c;
        for (k = 0; k < 3; k++) {
            s.min[k] = t[k][l];
            s.max[k] = t[3 + k][l];
            c.min[k] = t[6 + k][l];
            c.max[k] = t[9 + k][l];
        }
        *scene = atrbvh_box_union(*scene, s);
        *centroids = atrbvh_box_union(*centroids, c);
    }
}

#endif /* ATRBVH_SHARED_LANES_H */
