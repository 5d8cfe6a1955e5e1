/*
 * shared/traverse.h - the per-ray arithmetic of the ray queries (closest
 * hit and any hit), written once for the CPU (lib/traverse.c, C99) and the
 * OpenCL kernels (cl/kernels.cl: intersect_closest, intersect_any), so a
 * ray gets the same hit, the same t/u/v bits and the same primitive on
 * both.
 *
 * Same rules as shared/arith.h: no libc, no VLAs, no recursion, a
 * fixed-size private stack.  Geometry and tree arrays come in through
 * ATRBVH_CONST_GLOBAL pointers with strides in elements (the build
 * requires byte strides that are multiples of 4).
 *
 * The robustness rules (see lib/traverse.c and atrbvh(3), "Ray queries"):
 * conservative slab test with Ize's widening of the far distance, in
 * single precision for the rays where that is safe (atrbvh_trav_setup)
 * and in double for the others, watertight Woop/Benthin/Wald triangle
 * test in double, box
 * primitives as surfaces, closest-hit ties to the lower primitive index,
 * near-first traversal with a TRAVERSE_STACK-entry stack and a linear pass
 * over the leaves when a (hand-made) tree is deeper than that.
 *
 * Portability: there is no single-precision division (OpenCL allows
 * 2.5 ulp for it without -cl-fp32-correctly-rounded-divide-sqrt): the
 * reciprocal direction is 1.0 / (double)d (rounded to float for the float
 * slab test), and the triangle test is in double.  The float operations
 * are additions, subtractions, multiplications, comparisons and
 * conversions, which OpenCL rounds correctly; subnormal results must be
 * kept, so a device without CL_FP_DENORM gets float_slabs 0 (cl/trace.c).
 * The double ones (division included) are IEEE under cl_khr_fp64.
 */
#ifndef ATRBVH_SHARED_TRAVERSE_H
#define ATRBVH_SHARED_TRAVERSE_H

#include "fetch.h" /* types.h: atrbvh_node, atrbvh_ray, atrbvh_hit */

#ifndef __OPENCL_VERSION__
#include <math.h> /* INFINITY only */
#endif
#define ATRBVH_TRAV_INF INFINITY

/* The node test and the traversal loop inlined on the CPU (GCC otherwise
 * keeps the node test out of line: a call and the ray's fields reloaded
 * from memory per box). */
#if !defined(__OPENCL_VERSION__) && (defined(__GNUC__) || defined(__clang__))
#define ATRBVH_TRAV_HOT static inline __attribute__((always_inline))
#else
#define ATRBVH_TRAV_HOT ATRBVH_FN
#endif

#define ATRBVH_TRAVERSE_STACK 256
#define ATRBVH_TRAV_FLT_MAX 3.402823466e+38f
/* 1 + 2*gamma(3) and 1 - 2*gamma(3), gamma(n) = n*u / (1 - n*u), u = 2^-24,
 * rounded outwards. */
#define ATRBVH_TRAV_WIDEN_UP 1.00000036f
#define ATRBVH_TRAV_WIDEN_DOWN 0.99999964f
/* The single-precision node test (atrbvh_trav_node_hit_f).  The far
 * distance is widened by 1 + 2^-21 = 1 + 8u, above Ize's 1 + 2*gamma(3)
 * (= 1 + 6u + O(u^2)): the reciprocal is rounded twice (double, then
 * float), one more rounding of at most u(1 + 2^-29).  Then 2^-146 is added:
 * results in the subnormal range have absolute errors of up to 2^-150 per
 * rounding, which no relative factor covers. */
#define ATRBVH_TRAV_WIDEN_F 0x1.000008p+0f
#define ATRBVH_TRAV_SLACK_F 0x1p-146f
/* A ray takes the float test when every direction component has a
 * magnitude in [2^-125, 2^125] (its reciprocal is a finite normal float;
 * a zero component takes the double test, where 0 * inf gives NaN),
 * its origin and the root box lie within +-2^126 (b - o cannot overflow)
 * and tmin >= 0. */
#define ATRBVH_TRAV_F_DIR_MIN 0x1p-125f
#define ATRBVH_TRAV_F_DIR_MAX 0x1p+125f
#define ATRBVH_TRAV_F_COORD_MAX 0x1p+126f
/* Relative slack on the closest-hit distance when pruning (2^-12). */
#define ATRBVH_TRAV_PRUNE_SLACK (1.0f / 4096.0f)
/* The smallest absolute slack on that limit: FLT_MIN. */
#define ATRBVH_TRAV_MIN_SLACK 1.17549435e-38f
/* Relative slack on the near end of a triangle's own box
 * (atrbvh_trav_within_own_box): covers the float rounding of t (2^-24)
 * with a wide margin. */
#define ATRBVH_TRAV_OWN_BOX_SLACK (1.0 / 1048576.0)

/* What a query reads: the tree (depth-first atrbvh_node array, root 0) and
 * the geometry.  Strides are in floats (vertices, boxes) or in u32
 * (indices). */
typedef struct atrbvh_trav_scene {
    ATRBVH_CONST_GLOBAL atrbvh_node *nodes;
    atrbvh_u64 node_count;
    ATRBVH_CONST_GLOBAL atrbvh_u32 *prim_indices;
    atrbvh_u64 prim_count;
    int boxes;                    /* 0 triangles, 1 boxes                */
    atrbvh_u64 primitive_count;   /* of the geometry                     */
    ATRBVH_CONST_GLOBAL float *vertices;
    atrbvh_u64 vertex_count, vertex_stride;
    ATRBVH_CONST_GLOBAL atrbvh_u32 *indices; /* used when indexed        */
    int indexed;
    atrbvh_u64 index_stride;
    ATRBVH_CONST_GLOBAL float *box_data;
    atrbvh_u64 box_stride;
    /* 1: rays may take the single-precision node test (see
     * atrbvh_trav_scene_float); 0: every ray takes the double one. */
    int float_slabs;
} atrbvh_trav_scene;

/* A ray, prepared. */
typedef struct atrbvh_trav_ray {
    /* Node slab tests in float (use_float: see atrbvh_trav_setup) */
    float orgf[3];
    float idirf[3];
    int use_float;
    double orgd[3];  /* otherwise in double: see atrbvh_trav_node_hit_d */
    double idird[3];
    int sign[3]; /* 1 when idird[k] < 0 (direction -0 included) */
    /* Where a node's near and far planes are among its first six floats
     * (min x, y, z, max x, y, z): k or 3 + k by the sign. */
    int near_at[3], far_at[3];
    float tmin, tmax;
    /* watertight triangle test, in double (origin: orgd) */
    int kx, ky, kz;
    double sx, sy, sz;
} atrbvh_trav_ray;

typedef struct atrbvh_trav_best {
    float t, u, v;
    atrbvh_u32 prim;
    float tlim; /* node pruning bound: t widened by the slack */
    /* The ray's cost, exact and independent of thread count and backend:
     * node boxes tested (atrbvh_trav_node_hit calls) and primitives
     * tested (triangle or box tests, after the index checks). */
    atrbvh_u32 box_tests, prim_tests;
} atrbvh_trav_best;

/* |x| for float and double without libc: -0 gives +0, NaN stays NaN. */
ATRBVH_FN float atrbvh_trav_absf(float x)
{
    return x < 0.0f ? -x : (x == 0.0f ? 0.0f : x);
}

ATRBVH_FN double atrbvh_trav_abs(double x)
{
    return x < 0.0 ? -x : (x == 0.0 ? 0.0 : x);
}

ATRBVH_FN float atrbvh_trav_widen_limit(float t)
{
    /* t + |t| * slack, and at least the smallest normal float past t: a
     * hit at t = 0 must not prune a box entered at a subnormal distance,
     * whose primitive can tie at 0 and win by its lower index (found by
     * fuzz_build).  inf stays inf, -inf stays -inf. */
    float slack = atrbvh_trav_absf(t) * ATRBVH_TRAV_PRUNE_SLACK, r;
    if (slack < ATRBVH_TRAV_MIN_SLACK)
        slack = ATRBVH_TRAV_MIN_SLACK;
    r = t + slack;
    return r == r ? r : t;
}

/* No hit yet: the limits of ray r and no tests counted.  Returns the
 * lower end of the node interval, tmin widened like the upper one (tmin
 * itself where that is NaN). */
ATRBVH_FN float atrbvh_trav_best_start(const atrbvh_trav_ray *r,
                                       atrbvh_trav_best *best)
{
    float tlo = r->tmin - atrbvh_trav_absf(r->tmin) * ATRBVH_TRAV_PRUNE_SLACK;
    if (!(tlo == tlo))
        tlo = r->tmin;
    best->t = r->tmax;
    best->u = best->v = 0.0f;
    best->prim = ATRBVH_NO_HIT;
    best->tlim = atrbvh_trav_widen_limit(r->tmax);
    best->box_tests = best->prim_tests = 0u;
    return tlo;
}

/* Whether the single-precision node test is allowed for the scene:
 * `allowed` (0 on an OpenCL device that may flush subnormals: its float
 * results would differ from the CPU's) and the root box within
 * +-ATRBVH_TRAV_F_COORD_MAX (every box of a valid tree is inside it; NaN
 * fails). */
ATRBVH_FN int atrbvh_trav_scene_float(const atrbvh_trav_scene *s, int allowed)
{
    ATRBVH_CONST_GLOBAL float *b;
    int k;
    if (!allowed || s->node_count == 0u)
        return 0;
    b = (ATRBVH_CONST_GLOBAL float *)&s->nodes[0];
    for (k = 0; k < 6; k++)
        if (!(atrbvh_trav_absf(b[k]) <= ATRBVH_TRAV_F_COORD_MAX))
            return 0;
    return 1;
}

/* The watertight triangle test's shear of a ray (Woop, Benthin, Wald
 * 2013): the largest component of the direction (magnitudes ad; the first
 * on a tie) becomes z, x and y follow it cyclically, swapped when it is
 * negative to keep the winding.  r->idird must be set: sz is 1 / dir[kz],
 * which it holds. */
ATRBVH_FN void atrbvh_trav_setup_shear(const float *dir, const float *ad,
                                       atrbvh_trav_ray *r)
{
    r->kz = 0;
    if (ad[1] > ad[r->kz])
        r->kz = 1;
    if (ad[2] > ad[r->kz])
        r->kz = 2;
    r->kx = r->kz == 2 ? 0 : r->kz + 1;
    r->ky = r->kx == 2 ? 0 : r->kx + 1;
    if (dir[r->kz] < 0.0f) { /* keep the winding */
        int sw = r->kx;
        r->kx = r->ky;
        r->ky = sw;
    }
    r->sx = (double)dir[r->kx] / (double)dir[r->kz];
    r->sy = (double)dir[r->ky] / (double)dir[r->kz];
    r->sz = r->idird[r->kz];
}

/* Prepares a ray; 0 when it can hit nothing (NaN or infinite origin or
 * direction, all-zero direction, NaN tmin/tmax, tmin > tmax).  Sets
 * use_float by the ray alone (see ATRBVH_TRAV_F_DIR_MIN); the traversal
 * clears it when the scene does not allow it (atrbvh_trav_scene_float). */
ATRBVH_FN int atrbvh_trav_setup(const float *origin, const float *dir,
                                float tmin, float tmax, atrbvh_trav_ray *r)
{
    int k, use_float;
    float ad[3];
    /* NaN tmin or tmax fails the comparison */
    if (!(tmin <= tmax))
        return 0;
    for (k = 0; k < 3; k++) {
        if (!atrbvh_finite(origin[k]) || !atrbvh_finite(dir[k]))
            return 0;
    }
    if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
        return 0;
    use_float = tmin >= 0.0f;
    for (k = 0; k < 3; k++) {
        float d = dir[k], a = d < 0.0f ? -d : d; /* -0 stays -0: == 0 */
        double id = 1.0 / (double)d;
        int sg = id < 0.0;
        /* finite for every nonzero float, subnormals included (a float
         * reciprocal overflows to inf below 2^-128); +-inf for +-0 */
        r->orgd[k] = (double)origin[k];
        r->idird[k] = id;
        r->sign[k] = sg;
        r->near_at[k] = sg ? 3 + k : k;
        r->far_at[k] = sg ? k : 3 + k;
        /* the double reciprocal rounded to float: OpenCL's float division
         * is not correctly rounded, the conversion is */
        r->orgf[k] = origin[k];
        r->idirf[k] = (float)id;
        ad[k] = a;
        if (!(origin[k] <= ATRBVH_TRAV_F_COORD_MAX &&
              origin[k] >= -ATRBVH_TRAV_F_COORD_MAX) ||
            !(a >= ATRBVH_TRAV_F_DIR_MIN && a <= ATRBVH_TRAV_F_DIR_MAX))
            use_float = 0;
    }
    r->tmin = tmin;
    r->tmax = tmax;
    r->use_float = use_float;
    atrbvh_trav_setup_shear(dir, ad, r);
    return 1;
}

/* The slab distance (b - o) / d, in double: b - o cannot overflow (it
 * can in float near FLT_MAX) and 1/d is finite for every nonzero float
 * direction (in float it overflows for subnormal components, which made
 * boxes the ray crosses look infinitely far).  A zero direction gives
 * +-inf, or NaN when b == o (dropped by the comparisons below). */
ATRBVH_FN double atrbvh_trav_slab_t(float b, const atrbvh_trav_ray *r, int k)
{
    return ((double)b - r->orgd[k]) * r->idird[k];
}

/* double to float for distances: beyond the float range is +-inf. */
ATRBVH_FN float atrbvh_trav_dist_float(double d)
{
    if (d > (double)ATRBVH_TRAV_FLT_MAX)
        return ATRBVH_TRAV_INF;
    if (d < -(double)ATRBVH_TRAV_FLT_MAX)
        return -ATRBVH_TRAV_INF;
    return (float)d;
}

/* Conservative ray/node test in double.  Hit when the slab interval, far
 * end widened, meets [tlo, thi]; *tnear is where it starts.  In double the
 * interval is exact to a few units of 2^-53; widening by the float factor
 * covers that with a wide margin. */
ATRBVH_FN int atrbvh_trav_node_hit_d(ATRBVH_CONST_GLOBAL atrbvh_node *n,
                                   const atrbvh_trav_ray *r, float tlo,
                                   float thi, float *tnear)
{
    double lo = -ATRBVH_TRAV_INF, hi = ATRBVH_TRAV_INF;
    /* the node's box as six floats: min x, y, z, max x, y, z */
    ATRBVH_CONST_GLOBAL float *b = (ATRBVH_CONST_GLOBAL float *)n;
    int k;
    for (k = 0; k < 3; k++) {
        double tn = atrbvh_trav_slab_t(b[r->near_at[k]], r, k);
        double tf = atrbvh_trav_slab_t(b[r->far_at[k]], r, k);
        /* NaN (0 * inf) fails the comparison and is dropped. */
        lo = tn > lo ? tn : lo;
        hi = tf < hi ? tf : hi;
    }
    hi = hi * (hi > 0.0 ? (double)ATRBVH_TRAV_WIDEN_UP
                        : (double)ATRBVH_TRAV_WIDEN_DOWN);
    if ((double)tlo > lo)
        lo = tlo;
    if ((double)thi < hi)
        hi = thi;
    *tnear = atrbvh_trav_dist_float(lo);
    return lo <= hi;
}

/* The same test in single precision, for rays with use_float (Ize, "Robust
 * BVH ray traversal", JCGT 2013): (b - o) * (1/d) in float, three
 * roundings of at most u = 2^-24 each in the normal range (b - o cannot
 * overflow, 1/d is a finite normal float), so the near distances are at
 * most (1 + u)^3 and the far ones at least (1 - u)^3 times their true
 * values; the far end, ray limit included, is widened by
 * ATRBVH_TRAV_WIDEN_F and ATRBVH_TRAV_SLACK_F (subnormal results), which
 * keeps every box the ray really crosses.  A product beyond FLT_MAX becomes
 * +-inf: such a box starts or ends beyond any finite hit, as the double
 * test says too.  With tmin >= 0 a negative far end is rejected either
 * way, so the widening needs no sign test (the sign of each product is
 * exact, underflow to 0 included).
 *
 * No direction component is 0 on this path, so no distance is NaN for a
 * valid tree (finite boxes within the root's): each axis's near and far
 * distances are the min and max of its two planes' distances, with no
 * choice by the sign.  The CPU computes the six distances with SSE: one
 * vector (min x, min y, min z, max x) and one (min z, max x, max y,
 * max z), both read straight from the node.  The scalar code below does
 * the same operations in the same order with the same operands (x < y ?
 * x : y is minss/minps, x > y ? x : y is maxss/maxps, NaN and signed zeros
 * included), so both give the same bits on any input, a hand-made tree
 * with NaN boxes included; test_clrays compares the CPU's results and
 * counts with OpenCL's (PoCL runs the scalar code). */
#if !defined(__OPENCL_VERSION__) && defined(__SSE2__) &&                       \
    !defined(ATRBVH_TRAV_NO_SSE)
#define ATRBVH_TRAV_SSE 1
#include <emmintrin.h>
typedef struct atrbvh_trav_fray {
    /* lanes (x, y, z, x) and (z, x, y, z), matching the two loads */
    __m128 o0, o1, i0, i1;
    __m128 widen, slack; /* ATRBVH_TRAV_WIDEN_F, ATRBVH_TRAV_SLACK_F */
    /* the traversal's limits broadcast (atrbvh_trav_fray_limits), kept
     * in registers across the loop instead of rebuilt per node pair */
    __m128 tlo4, thi4;
} atrbvh_trav_fray;

ATRBVH_TRAV_HOT atrbvh_trav_fray atrbvh_trav_fray_make(const atrbvh_trav_ray *r)
{
    atrbvh_trav_fray f;
    f.o0 = _mm_setr_ps(r->orgf[0], r->orgf[1], r->orgf[2], r->orgf[0]);
    f.o1 = _mm_setr_ps(r->orgf[2], r->orgf[0], r->orgf[1], r->orgf[2]);
    f.i0 = _mm_setr_ps(r->idirf[0], r->idirf[1], r->idirf[2], r->idirf[0]);
    f.i1 = _mm_setr_ps(r->idirf[2], r->idirf[0], r->idirf[1], r->idirf[2]);
    f.widen = _mm_set1_ps(ATRBVH_TRAV_WIDEN_F);
    f.slack = _mm_set1_ps(ATRBVH_TRAV_SLACK_F);
#if defined(__GNUC__) || defined(__clang__)
    /* Hide the constants' values from GCC: otherwise it rebuilds the
     * broadcasts from scalar constants in every node pair (two
     * instructions each) instead of keeping them in registers.  The
     * values and operations are unchanged. */
    __asm__("" : "+x"(f.widen), "+x"(f.slack));
#endif
    f.tlo4 = f.thi4 = _mm_setzero_ps();
    return f;
}

/* The limits atrbvh_trav_box2_f uses: set before the first pair and again
 * whenever the upper one changes (after a leaf). */
ATRBVH_TRAV_HOT void atrbvh_trav_fray_limits(atrbvh_trav_fray *f, float tlo,
                                             float thi)
{
    f->tlo4 = _mm_set1_ps(tlo);
    f->thi4 = _mm_set1_ps(thi);
}

ATRBVH_TRAV_HOT int atrbvh_trav_box_f(const float *b,
                                      const atrbvh_trav_fray *f, float tlo,
                                      float thi, float *tnear)
{
    /* t0: min x, min y, min z, max x; t1: min z, max x, max y, max z */
    __m128 t0 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(b), f->o0), f->i0);
    __m128 t1 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(b + 2), f->o1), f->i1);
    /* max x, max y, max z, min z */
    __m128 t1s = _mm_shuffle_ps(t1, t1, _MM_SHUFFLE(0, 3, 2, 1));
    __m128 nr = _mm_min_ps(t0, t1s), fr = _mm_max_ps(t0, t1s);
    __m128 lo = _mm_max_ss(nr, _mm_set_ss(tlo));
    __m128 hi = _mm_min_ss(fr, _mm_set_ss(thi));
    float l, h;
    lo = _mm_max_ss(_mm_shuffle_ps(nr, nr, _MM_SHUFFLE(1, 1, 1, 1)), lo);
    hi = _mm_min_ss(_mm_shuffle_ps(fr, fr, _MM_SHUFFLE(1, 1, 1, 1)), hi);
    lo = _mm_max_ss(_mm_movehl_ps(nr, nr), lo);
    hi = _mm_min_ss(_mm_movehl_ps(fr, fr), hi);
    l = _mm_cvtss_f32(lo);
    h = _mm_cvtss_f32(hi);
    h = h * ATRBVH_TRAV_WIDEN_F + ATRBVH_TRAV_SLACK_F;
    *tnear = l;
    return l <= h;
}

/* Both children at once: lane 0 the left, lane 1 the right, each lane the
 * operations of atrbvh_trav_box_f, with the limits f->tlo4 and f->thi4
 * (atrbvh_trav_fray_limits).  Bit 0: left hit, bit 1: right hit. */
ATRBVH_TRAV_HOT int atrbvh_trav_box2_f(const float *bl, const float *br,
                                       const atrbvh_trav_fray *f, float *nl,
                                       float *nr)
{
    __m128 l0 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(bl), f->o0), f->i0);
    __m128 l1 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(bl + 2), f->o1), f->i1);
    __m128 r0 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(br), f->o0), f->i0);
    __m128 r1 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(br + 2), f->o1), f->i1);
    __m128 ln, lf, rn, rf, n01, n2, f01, f2, lo, hi;
    l1 = _mm_shuffle_ps(l1, l1, _MM_SHUFFLE(0, 3, 2, 1));
    r1 = _mm_shuffle_ps(r1, r1, _MM_SHUFFLE(0, 3, 2, 1));
    ln = _mm_min_ps(l0, l1);
    lf = _mm_max_ps(l0, l1);
    rn = _mm_min_ps(r0, r1);
    rf = _mm_max_ps(r0, r1);
    /* (x left, x right, y left, y right) and (z left, z right, -, -) */
    n01 = _mm_unpacklo_ps(ln, rn);
    n2 = _mm_unpackhi_ps(ln, rn);
    f01 = _mm_unpacklo_ps(lf, rf);
    f2 = _mm_unpackhi_ps(lf, rf);
    lo = _mm_max_ps(n01, f->tlo4);
    hi = _mm_min_ps(f01, f->thi4);
    lo = _mm_max_ps(_mm_movehl_ps(n01, n01), lo);
    hi = _mm_min_ps(_mm_movehl_ps(f01, f01), hi);
    lo = _mm_max_ps(n2, lo);
    hi = _mm_min_ps(f2, hi);
    hi = _mm_add_ps(_mm_mul_ps(hi, f->widen), f->slack);
    *nl = _mm_cvtss_f32(lo);
    *nr = _mm_cvtss_f32(_mm_shuffle_ps(lo, lo, _MM_SHUFFLE(1, 1, 1, 1)));
    return _mm_movemask_ps(_mm_cmple_ps(lo, hi)) & 3;
}
#else
typedef struct atrbvh_trav_fray {
    float o[3], id[3];
} atrbvh_trav_fray;

ATRBVH_TRAV_HOT atrbvh_trav_fray atrbvh_trav_fray_make(const atrbvh_trav_ray *r)
{
    atrbvh_trav_fray f;
    int k;
    for (k = 0; k < 3; k++) {
        f.o[k] = r->orgf[k];
        f.id[k] = r->idirf[k];
    }
    return f;
}

ATRBVH_TRAV_HOT void atrbvh_trav_fray_limits(atrbvh_trav_fray *f, float tlo,
                                             float thi)
{
    (void)f;
    (void)tlo;
    (void)thi;
}

ATRBVH_TRAV_HOT int atrbvh_trav_box_f(ATRBVH_CONST_GLOBAL float *b,
                                      const atrbvh_trav_fray *f, float tlo,
                                      float thi, float *tnear)
{
    float x0 = (b[0] - f->o[0]) * f->id[0];
    float y0 = (b[1] - f->o[1]) * f->id[1];
    float z0 = (b[2] - f->o[2]) * f->id[2];
    float x1 = (b[3] - f->o[0]) * f->id[0];
    float y1 = (b[4] - f->o[1]) * f->id[1];
    float z1 = (b[5] - f->o[2]) * f->id[2];
    float nx = x0 < x1 ? x0 : x1, fx = x0 > x1 ? x0 : x1;
    float ny = y0 < y1 ? y0 : y1, fy = y0 > y1 ? y0 : y1;
    float nz = z0 < z1 ? z0 : z1, fz = z0 > z1 ? z0 : z1;
    float lo = nx > tlo ? nx : tlo, hi = fx < thi ? fx : thi;
    lo = ny > lo ? ny : lo;
    hi = fy < hi ? fy : hi;
    lo = nz > lo ? nz : lo;
    hi = fz < hi ? fz : hi;
    hi = hi * ATRBVH_TRAV_WIDEN_F + ATRBVH_TRAV_SLACK_F;
    *tnear = lo;
    return lo <= hi;
}
#endif

ATRBVH_FN int atrbvh_trav_node_hit_f(ATRBVH_CONST_GLOBAL atrbvh_node *n,
                                     const atrbvh_trav_ray *r, float tlo,
                                     float thi, float *tnear)
{
    atrbvh_trav_fray f = atrbvh_trav_fray_make(r);
    return atrbvh_trav_box_f((ATRBVH_CONST_GLOBAL float *)n, &f, tlo, thi,
                             tnear);
}

/* The node test of the traversal: float or double by the ray. */
ATRBVH_FN int atrbvh_trav_node_hit(ATRBVH_CONST_GLOBAL atrbvh_node *n,
                                   const atrbvh_trav_ray *r, float tlo,
                                   float thi, float *tnear)
{
    if (r->use_float)
        return atrbvh_trav_node_hit_f(n, r, tlo, thi, tnear);
    return atrbvh_trav_node_hit_d(n, r, tlo, thi, tnear);
}

/* Exact ray/box primitive test: entry and exit distances, in double.
 * The caller compares them with the ray's limits before rounding to
 * float: a box just behind the origin has distances of about -1e-63 for
 * coordinates near 1e-29, which round to -0.0f and would pass t >= 0. */
ATRBVH_FN int atrbvh_trav_box_interval(const float *b,
                                       const atrbvh_trav_ray *r, double *t0,
                                       double *t1)
{
    double lo = -ATRBVH_TRAV_INF, hi = ATRBVH_TRAV_INF;
    int k;
    for (k = 0; k < 3; k++) {
        float bn = r->sign[k] ? b[3 + k] : b[k];
        float bf = r->sign[k] ? b[k] : b[3 + k];
        double tn = atrbvh_trav_slab_t(bn, r, k);
        double tf = atrbvh_trav_slab_t(bf, r, k);
        lo = tn > lo ? tn : lo;
        hi = tf < hi ? tf : hi;
    }
    *t0 = lo;
    *t1 = hi;
    return lo <= hi;
}

/* The three vertices of triangle `prim`; 0 if an index is out of range. */
ATRBVH_FN int atrbvh_trav_triangle_vertices(const atrbvh_trav_scene *s,
                                            atrbvh_u32 prim, float v[3][3])
{
    atrbvh_u64 id[3];
    int k;
    for (k = 0; k < 3; k++)
        id[k] = atrbvh_fetch_vertex_id(s->indices, s->index_stride,
                                       s->indexed, (atrbvh_u64)prim, k);
    for (k = 0; k < 3; k++) {
        if (id[k] >= s->vertex_count)
            return 0;
        atrbvh_fetch_vertex(s->vertices, s->vertex_stride, id[k], v[k]);
    }
    return 1;
}

/* Whether distance t lies where the ray crosses the triangle's own box,
 * both ends widened a little (float rounding of t, a few ulps of the double
 * slab distances).  A true hit point lies in the triangle, so inside its
 * box: this only rejects hits the edge functions got wrong, which happens
 * for slivers mixing coordinates of wildly different magnitudes (1e36 next
 * to 1e-28: the double edge functions cancel).  It also makes the answer
 * independent of the tree: every node containing the triangle contains its
 * box, so a hit accepted here is never behind a node the traversal skips
 * (found by fuzz_build: tests/fuzz/corpus/build/regress-sliver-*). */
ATRBVH_FN int atrbvh_trav_within_own_box(float v[3][3],
                                         const atrbvh_trav_ray *r, float t)
{
    double lo = -ATRBVH_TRAV_INF, hi = ATRBVH_TRAV_INF;
    int k;
    for (k = 0; k < 3; k++) {
        float mn = v[0][k], mx = v[0][k];
        double tn, tf;
        if (v[1][k] < mn)
            mn = v[1][k];
        if (v[2][k] < mn)
            mn = v[2][k];
        if (v[1][k] > mx)
            mx = v[1][k];
        if (v[2][k] > mx)
            mx = v[2][k];
        tn = atrbvh_trav_slab_t(r->sign[k] ? mx : mn, r, k);
        tf = atrbvh_trav_slab_t(r->sign[k] ? mn : mx, r, k);
        /* NaN (0 * inf: origin on the plane of a zero direction) drops */
        lo = tn > lo ? tn : lo;
        hi = tf < hi ? tf : hi;
    }
    hi = hi * (hi > 0.0 ? (double)ATRBVH_TRAV_WIDEN_UP
                        : (double)ATRBVH_TRAV_WIDEN_DOWN);
    lo = lo * (lo > 0.0 ? 1.0 - ATRBVH_TRAV_OWN_BOX_SLACK
                        : 1.0 + ATRBVH_TRAV_OWN_BOX_SLACK);
    return (double)t >= lo && (double)t <= hi;
}

/* Watertight ray/triangle test (Woop, Benthin, Wald 2013), in double.
 * On a hit with a finite t returns 1 with t and the barycentrics of
 * vertices 1 and 2. */
ATRBVH_FN int atrbvh_trav_triangle_hit(float v[3][3],
                                       const atrbvh_trav_ray *r, float *t,
                                       float *u, float *w)
{
    /* only the six sheared coordinates and the three z ones: no arrays
     * indexed by kx, ky, kz (stores and reloads per triangle) */
    int kx = r->kx, ky = r->ky, kz = r->kz;
    double ox = r->orgd[kx], oy = r->orgd[ky], oz = r->orgd[kz];
    double az = (double)v[0][kz] - oz;
    double bz = (double)v[1][kz] - oz;
    double cz = (double)v[2][kz] - oz;
    double ax = ((double)v[0][kx] - ox) - r->sx * az;
    double ay = ((double)v[0][ky] - oy) - r->sy * az;
    double bx = ((double)v[1][kx] - ox) - r->sx * bz;
    double by = ((double)v[1][ky] - oy) - r->sy * bz;
    double cx = ((double)v[2][kx] - ox) - r->sx * cz;
    double cy = ((double)v[2][ky] - oy) - r->sy * cz;
    double e0, e1, e2, det, tt;
    /* e0 weighs vertex 0 (edge 1-2), e1 vertex 1, e2 vertex 2. */
    e0 = cx * by - cy * bx;
    e1 = ax * cy - ay * cx;
    e2 = bx * ay - by * ax;
    if ((e0 < 0.0 || e1 < 0.0 || e2 < 0.0) &&
        (e0 > 0.0 || e1 > 0.0 || e2 > 0.0))
        return 0;
    det = e0 + e1 + e2;
    if (det == 0.0 || !(det == det))
        return 0;
    tt = e0 * (r->sz * az);
    tt = tt + e1 * (r->sz * bz);
    tt = tt + e2 * (r->sz * cz);
    tt = tt / det;
    /* tmin in double: a hit just behind the origin (tt about -1e-50)
     * rounds to -0.0f, which t >= tmin would take. */
    if (!(tt >= (double)r->tmin) ||
        !(atrbvh_trav_abs(tt) <= (double)ATRBVH_TRAV_FLT_MAX))
        return 0;
    *t = (float)tt;
    if (!(atrbvh_trav_absf(*t) <= ATRBVH_TRAV_FLT_MAX) ||
        !atrbvh_trav_within_own_box(v, r, *t))
        return 0;
    *u = (float)(e1 / det);
    *w = (float)(e2 / det);
    return 1;
}

/* Tests the primitives of a leaf.  Returns 1 when `any` and something was
 * hit (the query is over). */
ATRBVH_FN int atrbvh_trav_leaf(const atrbvh_trav_scene *s,
                               ATRBVH_CONST_GLOBAL atrbvh_node *n,
                               const atrbvh_trav_ray *r, int any,
                               atrbvh_trav_best *best)
{
    atrbvh_u32 j;
    atrbvh_u64 first = n->index;
    if (first > s->prim_count || (atrbvh_u64)n->count > s->prim_count - first)
        return 0; /* never for a valid tree */
    for (j = 0; j < n->count; j++) {
        atrbvh_u32 prim = s->prim_indices[first + j];
        float t, u = 0.0f, v = 0.0f;
        if ((atrbvh_u64)prim >= s->primitive_count)
            continue;
        best->prim_tests++;
        if (!s->boxes) {
            float vtx[3][3];
            if (!atrbvh_trav_triangle_vertices(s, prim, vtx) ||
                !atrbvh_trav_triangle_hit(vtx, r, &t, &u, &v))
                continue;
            if (any) {
                if (t >= r->tmin && t <= r->tmax)
                    return 1;
                continue;
            }
        } else {
            float box[6], f0, f1;
            double t0, t1, tmin = (double)r->tmin;
            atrbvh_fetch_box(s->box_data, s->box_stride, (atrbvh_u64)prim,
                             box);
            if (!atrbvh_trav_box_interval(box, r, &t0, &t1))
                continue;
            /* the box is hit where the ray enters or leaves it; against
             * tmin in double (see atrbvh_trav_box_interval), against
             * tmax in float like every other hit */
            f0 = atrbvh_trav_dist_float(t0);
            f1 = atrbvh_trav_dist_float(t1);
            if (any) {
                if ((t0 >= tmin && f0 <= r->tmax) ||
                    (t1 >= tmin && f1 <= r->tmax))
                    return 1;
                continue;
            }
            if (t0 >= tmin)
                t = f0;
            else if (t1 >= tmin)
                t = f1;
            else
                continue;
            if (!(atrbvh_trav_absf(t) <= ATRBVH_TRAV_FLT_MAX))
                continue;
        }
        /* Both queries accept t in the closed [tmin, tmax] (the upper end
         * through best->t starting at tmax with no primitive). */
        if (t >= r->tmin &&
            (t < best->t || (t == best->t && prim < best->prim))) {
            best->t = t;
            best->u = u;
            best->v = v;
            best->prim = prim;
            best->tlim = atrbvh_trav_widen_limit(t);
        }
    }
    return 0;
}

/* The fallback for trees deeper than the stack: every leaf, in order. */
ATRBVH_FN int atrbvh_trav_linear(const atrbvh_trav_scene *s,
                                 const atrbvh_trav_ray *r, int any,
                                 atrbvh_trav_best *best, float tlo)
{
    atrbvh_u64 i;
    for (i = 0; i < s->node_count; i++) {
        ATRBVH_CONST_GLOBAL atrbvh_node *n = &s->nodes[i];
        float tn;
        if (n->count == 0u)
            continue;
        best->box_tests++;
        if (!atrbvh_trav_node_hit(n, r, tlo, best->tlim, &tn))
            continue;
        if (atrbvh_trav_leaf(s, n, r, any, best))
            return 1;
    }
    return 0;
}

/* The boxes of the two children: bit 0 left hit, bit 1 right hit, and
 * their entry distances. */
ATRBVH_TRAV_HOT int atrbvh_trav_children(ATRBVH_CONST_GLOBAL atrbvh_node *nodes,
                                         atrbvh_u32 l, atrbvh_u32 rr,
                                         const atrbvh_trav_ray *r,
                                         const atrbvh_trav_fray *f,
                                         int use_float, float tlo, float thi,
                                         float *nl, float *nr)
{
    if (use_float) {
#ifdef ATRBVH_TRAV_SSE
        (void)tlo;
        (void)thi;
        return atrbvh_trav_box2_f((const float *)&nodes[l],
                                  (const float *)&nodes[rr], f, nl, nr);
#else
        int hl = atrbvh_trav_box_f((ATRBVH_CONST_GLOBAL float *)&nodes[l], f,
                                   tlo, thi, nl);
        int hr = atrbvh_trav_box_f((ATRBVH_CONST_GLOBAL float *)&nodes[rr], f,
                                   tlo, thi, nr);
        return hl | (hr << 1);
#endif
    }
    return atrbvh_trav_node_hit_d(&nodes[l], r, tlo, thi, nl) |
           (atrbvh_trav_node_hit_d(&nodes[rr], r, tlo, thi, nr) << 1);
}

/* The loop of atrbvh_trav_run past the root, inlined twice: use_float
 * constant 1 and 0.  The box tests are counted in a local and the pruning
 * limit kept in one (reread after each leaf), the ray's float fields in
 * `f`: the leaf test writes through `best`, which the compiler cannot tell
 * apart from *r, so it would reload them per box. */
ATRBVH_TRAV_HOT int atrbvh_trav_loop(const atrbvh_trav_scene *s,
                                     const atrbvh_trav_ray *r, int any,
                                     atrbvh_trav_best *best, int use_float,
                                     float tlo)
{
    atrbvh_u32 stack_node[ATRBVH_TRAVERSE_STACK];
    float stack_t[ATRBVH_TRAVERSE_STACK];
    atrbvh_u32 sp = 0, cur = 0, nb = 1;
    ATRBVH_CONST_GLOBAL atrbvh_node *nodes = s->nodes;
    atrbvh_u64 count = s->node_count;
    atrbvh_trav_fray f = atrbvh_trav_fray_make(r);
    float thi = best->tlim;
    int ret;
    atrbvh_trav_fray_limits(&f, tlo, thi);
    for (;;) {
        ATRBVH_CONST_GLOBAL atrbvh_node *n = &nodes[cur];
        atrbvh_u32 ncount = n->count, nindex = n->index;
        if (ncount > 0u) {
            int done = atrbvh_trav_leaf(s, n, r, any, best);
            if (best->tlim != thi) {
                thi = best->tlim;
                atrbvh_trav_fray_limits(&f, tlo, thi);
            }
            if (done) {
                ret = 1;
                break;
            }
        } else {
            atrbvh_u32 l = cur + 1u, rr = nindex;
            /* rr <= l or out of range: never for a valid tree (pop) */
            if (rr > l && (atrbvh_u64)rr < count) {
                float nl, nr;
                int h = atrbvh_trav_children(nodes, l, rr, r, &f, use_float,
                                             tlo, thi, &nl, &nr);
                nb += 2u;
                if (h == 3) {
                    atrbvh_u32 near_node = l, far_node = rr;
                    float far_t = nr;
                    if (nr < nl) {
                        near_node = rr;
                        far_node = l;
                        far_t = nl;
                    }
                    if (sp == ATRBVH_TRAVERSE_STACK) {
                        best->box_tests += nb;
                        if (atrbvh_trav_linear(s, r, any, best, tlo))
                            return 1;
                        return any ? 0 : best->prim != ATRBVH_NO_HIT;
                    }
                    stack_node[sp] = far_node;
                    stack_t[sp] = far_t;
                    sp++;
                    cur = near_node;
                    continue;
                }
                if (h) {
                    cur = h == 1 ? l : rr;
                    continue;
                }
            }
        }
        /* pop: the next entry that starts within the closest hit */
        while (sp > 0u && !(stack_t[sp - 1u] <= thi))
            sp--;
        if (sp == 0u) {
            ret = any ? 0 : best->prim != ATRBVH_NO_HIT;
            break;
        }
        sp--;
        cur = stack_node[sp];
    }
    best->box_tests += nb;
    return ret;
}

/* The traversal: depth-first, near child first, the far one pushed with
 * its entry distance and skipped on pop when it starts beyond the closest
 * hit.  Returns, for `any`, whether anything was hit; otherwise whether
 * best holds a hit. */
ATRBVH_FN int atrbvh_trav_run(const atrbvh_trav_scene *s,
                              const atrbvh_trav_ray *r, int any,
                              atrbvh_trav_best *best)
{
    /* the lower end of the node interval, widened like the upper one */
    float tlo = atrbvh_trav_best_start(r, best);
    float tn;
    if (s->node_count == 0u)
        return 0;
    if (!atrbvh_trav_node_hit(s->nodes, r, tlo, best->tlim, &tn)) {
        best->box_tests = 1u;
        return 0;
    }
    if (r->use_float)
        return atrbvh_trav_loop(s, r, any, best, 1, tlo);
    return atrbvh_trav_loop(s, r, any, best, 0, tlo);
}

/* Closest hit of one ray with t in [tmin, tmax]: hit->primitive
 * ATRBVH_NO_HIT (t = tmax, u = v = 0) when nothing is hit.  Returns 1 on a
 * hit. */
ATRBVH_FN int atrbvh_trav_closest_cost(const atrbvh_trav_scene *s,
                                       const float *origin, const float *dir,
                                       float tmin, float tmax, float *t,
                                       float *u, float *v, atrbvh_u32 *prim,
                                       atrbvh_u32 *box_tests,
                                       atrbvh_u32 *prim_tests)
{
    atrbvh_trav_ray r;
    atrbvh_trav_best best;
    int hit;
    *t = tmax;
    *u = 0.0f;
    *v = 0.0f;
    *prim = ATRBVH_NO_HIT;
    *box_tests = 0u;
    *prim_tests = 0u;
    /* a ray that can hit nothing is not traversed: cost 0 */
    if (!atrbvh_trav_setup(origin, dir, tmin, tmax, &r))
        return 0;
    if (!s->float_slabs)
        r.use_float = 0;
    hit = atrbvh_trav_run(s, &r, 0, &best);
    *box_tests = best.box_tests;
    *prim_tests = best.prim_tests;
    if (!hit)
        return 0;
    *t = best.t;
    *u = best.u;
    *v = best.v;
    *prim = best.prim;
    return 1;
}

ATRBVH_FN int atrbvh_trav_closest(const atrbvh_trav_scene *s,
                                  const float *origin, const float *dir,
                                  float tmin, float tmax, float *t, float *u,
                                  float *v, atrbvh_u32 *prim)
{
    atrbvh_u32 nb, np;
    return atrbvh_trav_closest_cost(s, origin, dir, tmin, tmax, t, u, v, prim,
                                    &nb, &np);
}

/* Any hit of one ray in [tmin, tmax]; the _cost version also returns the
 * boxes and primitives tested (up to the first hit found). */
ATRBVH_FN int atrbvh_trav_any_cost(const atrbvh_trav_scene *s,
                                   const float *origin, const float *dir,
                                   float tmin, float tmax,
                                   atrbvh_u32 *box_tests,
                                   atrbvh_u32 *prim_tests)
{
    atrbvh_trav_ray r;
    atrbvh_trav_best best;
    int hit;
    *box_tests = 0u;
    *prim_tests = 0u;
    if (!atrbvh_trav_setup(origin, dir, tmin, tmax, &r))
        return 0;
    if (!s->float_slabs)
        r.use_float = 0;
    hit = atrbvh_trav_run(s, &r, 1, &best);
    *box_tests = best.box_tests;
    *prim_tests = best.prim_tests;
    return hit;
}

ATRBVH_FN int atrbvh_trav_any(const atrbvh_trav_scene *s, const float *origin,
                              const float *dir, float tmin, float tmax)
{
    atrbvh_u32 nb, np;
    return atrbvh_trav_any_cost(s, origin, dir, tmin, tmax, &nb, &np);
}

#endif
