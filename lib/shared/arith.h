/*
 * shared/arith.h - the per-item arithmetic of every stage, written once.
 *
 * This header compiles both as C99 (the CPU backend) and as OpenCL C 1.2
 * (the OpenCL backend embeds it), so the two backends cannot drift.  Keep it
 * to the common subset: no libc, no VLAs, fixed-width types through the
 * aliases below, address spaces through ATRBVH_GLOBAL.
 *
 * Numerics (see atrbvh(3), "Numerical behaviour"):
 *  - boxes are float; centres are 0.5*min + 0.5*max (cannot overflow);
 *  - surface areas, SAH costs and the Morton normalisation are computed in
 *    double: a float box of any finite extent has a finite, nonzero double
 *    area unless it is degenerate (FLT_MAX^2 ~ 1e77, FLT_TRUE_MIN^2 ~ 2e-90),
 *    so nothing overflows to Inf or underflows to 0.  The OpenCL backend
 *    therefore needs cl_khr_fp64.
 *  - no contraction: C is compiled with -ffp-contract=off, OpenCL with the
 *    FP_CONTRACT pragma below, so a*b+c rounds twice on both sides.
 */
#ifndef ATRBVH_SHARED_ARITH_H
#define ATRBVH_SHARED_ARITH_H

#ifdef __OPENCL_VERSION__
#pragma OPENCL FP_CONTRACT OFF
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef uint atrbvh_u32;
typedef ulong atrbvh_u64;
typedef int atrbvh_i32;
typedef long atrbvh_i64;
#define ATRBVH_FN static inline
#define ATRBVH_GLOBAL __global
#define ATRBVH_CONST_GLOBAL __global const
/* Global memory that other work-items of the same launch write (the tree
 * arrays of the optimise round): volatile, so every read goes to memory
 * and not to a non-coherent cache (a GPU's L1); the kernels fence around
 * the atomic counters that hand the nodes over. */
#define ATRBVH_SHARED_GLOBAL volatile __global
#define ATRBVH_CLZ64(x) ((int)clz((ulong)(x)))
#define ATRBVH_U32_MAX 0xffffffffu
#else
#include <stdint.h>
typedef uint32_t atrbvh_u32;
typedef uint64_t atrbvh_u64;
typedef int32_t atrbvh_i32;
typedef int64_t atrbvh_i64;
#define ATRBVH_FN static inline
#define ATRBVH_GLOBAL
#define ATRBVH_CONST_GLOBAL const
#define ATRBVH_SHARED_GLOBAL
#define ATRBVH_U32_MAX 0xffffffffu
#if defined(__GNUC__) || defined(__clang__)
#define ATRBVH_CLZ64(x) ((x) ? __builtin_clzll((unsigned long long)(x)) : 64)
#else
static inline int atrbvh_clz64_portable(uint64_t x)
{
    int n = 0;
    if (!x)
        return 64;
    while (!(x & 0x8000000000000000ull)) {
        x <<= 1;
        n++;
    }
    return n;
}
#define ATRBVH_CLZ64(x) atrbvh_clz64_portable(x)
#endif
#endif

/* ------------------------------------------------------------- finiteness */
/* Nonzero when x is neither NaN nor infinite: x - x is 0 exactly for every
 * finite x and NaN otherwise (no libc isfinite needed; never compiled with
 * fast-math, which would break it).  The one finiteness test of both
 * backends: the bounds stage and the ray setup use it. */
ATRBVH_FN int atrbvh_finite(float x)
{
    float d = x - x;
    return d == 0.0f;
}

/* ------------------------------------------------------------------ boxes */
typedef struct atrbvh_box {
    float min[3];
    float max[3];
} atrbvh_box;

/* Written out per axis: the hottest function of refit and the treelet
 * optimisers, and GCC -O2 keeps a 3-iteration loop as a loop. */
ATRBVH_FN atrbvh_box atrbvh_box_union(atrbvh_box a, atrbvh_box b)
{
    atrbvh_box r;
    r.min[0] = a.min[0] < b.min[0] ? a.min[0] : b.min[0];
    r.min[1] = a.min[1] < b.min[1] ? a.min[1] : b.min[1];
    r.min[2] = a.min[2] < b.min[2] ? a.min[2] : b.min[2];
    r.max[0] = a.max[0] > b.max[0] ? a.max[0] : b.max[0];
    r.max[1] = a.max[1] > b.max[1] ? a.max[1] : b.max[1];
    r.max[2] = a.max[2] > b.max[2] ? a.max[2] : b.max[2];
    return r;
}

/* An "empty" box: union with it is the identity. */
ATRBVH_FN atrbvh_box atrbvh_box_empty(void)
{
    atrbvh_box r;
    int k;
    for (k = 0; k < 3; k++) {
        r.min[k] = 3.402823466e+38f;
        r.max[k] = -3.402823466e+38f;
    }
    return r;
}

/* Surface area in double; see the header comment for why. */
ATRBVH_FN double atrbvh_box_area(atrbvh_box b)
{
    double dx = (double)b.max[0] - (double)b.min[0];
    double dy = (double)b.max[1] - (double)b.min[1];
    double dz = (double)b.max[2] - (double)b.min[2];
    double s = dx * dy;
    s = s + dy * dz;
    s = s + dz * dx;
    return 2.0 * s;
}

ATRBVH_FN float atrbvh_box_centre(atrbvh_box b, int axis)
{
    return 0.5f * b.min[axis] + 0.5f * b.max[axis];
}

/* ------------------------------------------------------------------ costs */
/* The SAH cost model. Costs are unnormalised (not divided by the root area). */
typedef struct atrbvh_cost_params {
    double ci;          /* cost of an internal node (traversal step)       */
    double ct;          /* cost of one primitive test                      */
    int collapse;       /* nonzero: a subtree may become one leaf           */
    atrbvh_u32 max_leaf; /* most primitives in a collapsed leaf, 0 = any   */
} atrbvh_cost_params;

/* Cost of a single-primitive leaf. */
ATRBVH_FN double atrbvh_leaf_cost(const atrbvh_cost_params *p, double area)
{
    return p->ct * area;
}

/* Whether a subtree of `count` primitives may become one leaf. */
ATRBVH_FN int atrbvh_may_collapse(const atrbvh_cost_params *p, atrbvh_u32 count)
{
    return p->collapse && (p->max_leaf == 0 || count <= p->max_leaf);
}

/* Cost of an internal node with the given area and primitive count over
 * children of costs cl and cr (left first, always, so the sum rounds the
 * same way everywhere): ci*A + cl + cr, or ct*A*N when collapsing is
 * allowed and strictly cheaper.  *collapsed says which was taken. */
ATRBVH_FN double atrbvh_node_cost(const atrbvh_cost_params *p, double area,
                                  atrbvh_u32 count, double cl, double cr,
                                  int *collapsed)
{
    double binary = p->ci * area;
    binary = binary + cl;
    binary = binary + cr;
    if (atrbvh_may_collapse(p, count)) {
        double flat = p->ct * area;
        flat = flat * (double)count;
        if (flat < binary) {
            *collapsed = 1;
            return flat;
        }
    }
    *collapsed = 0;
    return binary;
}

/* ----------------------------------------------------------------- morton */
#define ATRBVH_MORTON_BITS 21
#define ATRBVH_MORTON_MAX 2097151u /* 2^21 - 1 */

/* Bits 0..6 of the index moved to bits 0, 3, .., 18: one 7-bit chunk of
 * atrbvh_morton_spread.  Program-scope __constant in OpenCL; a function's
 * static table in C (a file-scope one would be unused in most files). */
#define ATRBVH_MORTON_SPREAD7                                                  \
    {                                                                          \
    0x00000u, 0x00001u, 0x00008u, 0x00009u, 0x00040u, 0x00041u, 0x00048u, 0x00049u, \
    0x00200u, 0x00201u, 0x00208u, 0x00209u, 0x00240u, 0x00241u, 0x00248u, 0x00249u, \
    0x01000u, 0x01001u, 0x01008u, 0x01009u, 0x01040u, 0x01041u, 0x01048u, 0x01049u, \
    0x01200u, 0x01201u, 0x01208u, 0x01209u, 0x01240u, 0x01241u, 0x01248u, 0x01249u, \
    0x08000u, 0x08001u, 0x08008u, 0x08009u, 0x08040u, 0x08041u, 0x08048u, 0x08049u, \
    0x08200u, 0x08201u, 0x08208u, 0x08209u, 0x08240u, 0x08241u, 0x08248u, 0x08249u, \
    0x09000u, 0x09001u, 0x09008u, 0x09009u, 0x09040u, 0x09041u, 0x09048u, 0x09049u, \
    0x09200u, 0x09201u, 0x09208u, 0x09209u, 0x09240u, 0x09241u, 0x09248u, 0x09249u, \
    0x40000u, 0x40001u, 0x40008u, 0x40009u, 0x40040u, 0x40041u, 0x40048u, 0x40049u, \
    0x40200u, 0x40201u, 0x40208u, 0x40209u, 0x40240u, 0x40241u, 0x40248u, 0x40249u, \
    0x41000u, 0x41001u, 0x41008u, 0x41009u, 0x41040u, 0x41041u, 0x41048u, 0x41049u, \
    0x41200u, 0x41201u, 0x41208u, 0x41209u, 0x41240u, 0x41241u, 0x41248u, 0x41249u, \
    0x48000u, 0x48001u, 0x48008u, 0x48009u, 0x48040u, 0x48041u, 0x48048u, 0x48049u, \
    0x48200u, 0x48201u, 0x48208u, 0x48209u, 0x48240u, 0x48241u, 0x48248u, 0x48249u, \
    0x49000u, 0x49001u, 0x49008u, 0x49009u, 0x49040u, 0x49041u, 0x49048u, 0x49049u, \
    0x49200u, 0x49201u, 0x49208u, 0x49209u, 0x49240u, 0x49241u, 0x49248u, 0x49249u  \
    }
#ifdef __OPENCL_VERSION__
__constant atrbvh_u32 atrbvh_morton_spread7[128] = ATRBVH_MORTON_SPREAD7;
#endif

/* Spreads the low 21 bits of x so that there are two zero bits after
 * each: bit k moves to bit 3k.  Three 7-bit chunks through the table:
 * about half the instructions of the shift-and-mask ladder
 * (x = (x | x << 32) & 0x1f00000000ffff, ... & 0x1249249249249249), which
 * test_stages checks it against for every input. */
ATRBVH_FN atrbvh_u64 atrbvh_morton_spread(atrbvh_u64 x)
{
#ifndef __OPENCL_VERSION__
    static const atrbvh_u32 atrbvh_morton_spread7[128] = ATRBVH_MORTON_SPREAD7;
#endif
    return (atrbvh_u64)atrbvh_morton_spread7[x & 127u] |
           ((atrbvh_u64)atrbvh_morton_spread7[(x >> 7) & 127u] << 21) |
           ((atrbvh_u64)atrbvh_morton_spread7[(x >> 14) & 127u] << 42);
}

/* Quantises coordinate c of an axis whose centroid range starts at `lo`
 * with `scale` = 2^21 / extent (0 for a zero-extent axis, computed once
 * by the host) to 0 .. 2^21-1. */
ATRBVH_FN atrbvh_u32 atrbvh_morton_quantise(float c, double lo, double scale)
{
    double t = ((double)c - lo) * scale;
    if (!(t > 0.0))
        return 0u;
    if (t >= (double)ATRBVH_MORTON_MAX)
        return ATRBVH_MORTON_MAX;
    return (atrbvh_u32)t;
}

/* 63-bit key, x the most significant bit of every triplet. */
ATRBVH_FN atrbvh_u64 atrbvh_morton_key(atrbvh_u32 qx, atrbvh_u32 qy,
                                       atrbvh_u32 qz)
{
    return (atrbvh_morton_spread(qx) << 2) | (atrbvh_morton_spread(qy) << 1) |
           atrbvh_morton_spread(qz);
}

/* -------------------------------------------------------------- hierarchy */
/* Karras 2012, delta(i, j): the length of the longest common prefix of the
 * keys at sorted positions i and j, -1 when j is outside [0, n).  Equal
 * keys are told apart by their positions (64 + the common prefix of i and
 * j), so every pair has a distinct prefix length ordering. */
ATRBVH_FN int atrbvh_karras_delta(ATRBVH_CONST_GLOBAL atrbvh_u64 *keys,
                                  atrbvh_i64 n, atrbvh_i64 i, atrbvh_i64 j)
{
    atrbvh_u64 a, b;
    if (j < 0 || j >= n)
        return -1;
    a = keys[i];
    b = keys[j];
    if (a == b)
        return 64 + ATRBVH_CLZ64((atrbvh_u64)(i ^ j)) - 32;
    return ATRBVH_CLZ64(a ^ b);
}

/* The children of internal node i of a Karras tree over n sorted keys:
 * writes child indices in the tree numbering (internal 0..n-2, leaves
 * n-1..2n-2) and the number of primitives under i. */
ATRBVH_FN void atrbvh_karras_node(ATRBVH_CONST_GLOBAL atrbvh_u64 *keys,
                                  atrbvh_i64 n, atrbvh_i64 i,
                                  atrbvh_u32 *left, atrbvh_u32 *right,
                                  atrbvh_u32 *count)
{
    int d, dmin, dnode;
    atrbvh_i64 lmax, l, t, j, s, gamma, lo, hi;
    d = atrbvh_karras_delta(keys, n, i, i + 1) -
                    atrbvh_karras_delta(keys, n, i, i - 1) >
                0
            ? 1
            : -1;
    dmin = atrbvh_karras_delta(keys, n, i, i - d);
    lmax = 2;
    while (atrbvh_karras_delta(keys, n, i, i + lmax * d) > dmin)
        lmax *= 2;
    l = 0;
    for (t = lmax / 2; t >= 1; t /= 2)
        if (atrbvh_karras_delta(keys, n, i, i + (l + t) * d) > dmin)
            l += t;
    j = i + l * d;
    dnode = atrbvh_karras_delta(keys, n, i, j);
    s = 0;
    t = l;
    do {
        t = (t + 1) / 2;
        if (atrbvh_karras_delta(keys, n, i, i + (s + t) * d) > dnode)
            s += t;
    } while (t > 1);
    gamma = i + s * d + (d < 0 ? d : 0);
    lo = i < j ? i : j;
    hi = i < j ? j : i;
    *left = (atrbvh_u32)(lo == gamma ? gamma + n - 1 : gamma);
    *right = (atrbvh_u32)(hi == gamma + 1 ? gamma + 1 + n - 1 : gamma + 1);
    *count = (atrbvh_u32)(hi - lo + 1);
}

/* The same tree by nearest smaller deltas (lib/cpu/hierarchy.c and the
 * hierarchy kernels): the internal node of split s spans the leaves
 * ps + 1 .. ns, where ps is the nearest split to its left with a smaller
 * delta (-1: none) and ns the nearest to its right (n - 1: none), dps and
 * dns their deltas.  Returns its id in the Karras numbering (the end of
 * its range next to its parent's split) and writes its children (tree
 * numbering: leaves from n - 1) and primitive count. */
ATRBVH_FN atrbvh_u32 atrbvh_hier_node(atrbvh_i64 n, atrbvh_i64 s,
                                      atrbvh_i64 ps, int dps, atrbvh_i64 ns,
                                      int dns, atrbvh_u32 *left,
                                      atrbvh_u32 *right, atrbvh_u32 *count)
{
    const atrbvh_i64 l = ps + 1, r = ns;
    *left = (atrbvh_u32)(l == s ? s + n - 1 : s);
    *right = (atrbvh_u32)(s + 1 == r ? s + n : s + 1);
    *count = (atrbvh_u32)(r - l + 1);
    if (ps < 0)
        return ns == n - 1 ? 0u : (atrbvh_u32)r;
    if (ns == n - 1)
        return (atrbvh_u32)l;
    return dns > dps ? (atrbvh_u32)r : (atrbvh_u32)l;
}

#endif
