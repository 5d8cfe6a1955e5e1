/*
 * shared/treelet.h - the per-treelet arithmetic of the optimise stage,
 * written once for the CPU (C99) and the OpenCL backend (OpenCL C 1.2).
 *
 * Same rules as shared/arith.h: no libc, no VLAs, no recursion, fixed-size
 * private arrays sized by the compile-time maxima below, everything larger
 * (the 2^n subset tables of TRBVH, the distance matrix and clusters of
 * ATRBVH) passed in as scratch by pointer.
 *
 * A treelet (Karras & Aila 2013, section 4) is a root R plus n-1 internal
 * nodes below it whose n children outside the set are the "treelet leaves"
 * (any BVH node: a real leaf or the root of an untouched subtree).  Both
 * optimisers rebuild the topology above the n treelet leaves and keep it
 * only when its cost is strictly lower than the cost of R.
 *
 * The pieces, in the order the driver uses them:
 *   atrbvh_treelet_form      - pick the n leaves (largest area first)
 *   atrbvh_treelet_gather    - copy their box, count, cost (TRBVH; ATRBVH
 *                              reads them in place)
 *   atrbvh_trbvh_dp          - TRBVH: optimal topology by subset DP
 *   atrbvh_agg_cluster       - ATRBVH: greedy agglomerative topology
 *   atrbvh_treelet_evaluate  - exact boxes, counts, costs of a topology
 *   atrbvh_treelet_write     - write it back, reusing the internal ids
 *
 * The formation steps, the pre-order and the write-back are written once
 * in shared/treelet_arrays.inc, included twice below: over the private
 * arrays of a treelet of up to ATRBVH_TREELET_MAX leaves, and over the
 * worker's scratch for larger ATRBVH treelets.
 *
 * A topology is n-1 local internal nodes; local node k has children
 * left[k], right[k] given as codes: c < n is treelet leaf c, c >= n is
 * local internal node c - n.  `root` is the local root.
 *
 * Every cost is computed with atrbvh_node_cost (ci*A + left + right, left
 * first, or the collapse term ct*A*N when allowed and strictly cheaper),
 * the same function the refit stage uses, so a written-back treelet is
 * bit-for-bit what a refit of the new tree would compute.
 */
#ifndef ATRBVH_SHARED_TREELET_H
#define ATRBVH_SHARED_TREELET_H

#include "arith.h"

/* Treelet sizes, the one definition (option checks in lib/api.c, the
 * private array sizes below, the CPU and OpenCL optimise stages).
 * Largest treelet of each optimiser: TRBVH needs 2^n subset entries of
 * scratch and O(3^n) work per treelet; ATRBVH keeps one cluster per leaf
 * and n(n-1)/2 distances.  ATRBVH_TREELET_MAX is the size of the private
 * arrays of a formed treelet and its topology: TRBVH and ATRBVH up to it
 * use them, larger ATRBVH treelets (up to ATRBVH_ATRBVH_MAX) keep those in
 * scratch too (section "ATRBVH, any size" at the end).  ATRBVH's
 * agglomeration works in scratch at every size (atrbvh_agg_cluster). */
#define ATRBVH_TREELET_MAX 32
#define ATRBVH_TRBVH_MAX 10
#define ATRBVH_TRBVH_MIN 3
#define ATRBVH_ATRBVH_MIN 3
#define ATRBVH_ATRBVH_MAX 128
/* ATRBVH_TREELET_AUTO (atrbvh.h): the adaptive size; its sizes lie in
 * ATRBVH_AUTO_MIN .. ATRBVH_AUTO_MAX. */
#ifndef ATRBVH_TREELET_AUTO
#define ATRBVH_TREELET_AUTO 0xffffffffu
#endif
#define ATRBVH_AUTO_MIN 9
#define ATRBVH_AUTO_MAX 32
#define ATRBVH_AUTO_ROUNDS_DEFAULT 4
/* Defaults (atrbvh_build_options: treelet_size 0, rounds 0). */
#define ATRBVH_TRBVH_DEFAULT 7
#define ATRBVH_ATRBVH_DEFAULT 9
#define ATRBVH_TRBVH_ROUNDS_DEFAULT 3
#define ATRBVH_ATRBVH_ROUNDS_DEFAULT 2
#define ATRBVH_ROUNDS_MAX 64

/* ------------------------------------------------------------- the tree */
/* The tree arrays the optimiser reads and writes (see atrbvh_i_tree):
 * nodes < n_internal are internal (left/right valid), the rest leaves.
 * On OpenCL they are volatile (ATRBVH_SHARED_GLOBAL): a treelet reads
 * nodes that other work-items of the same opt_round launch wrote, handed
 * over by a fence and an atomic counter; a plain load could be served by
 * a GPU's non-coherent L1 and be stale.  Plain pointers in C. */
typedef struct atrbvh_treelet_tree {
    ATRBVH_SHARED_GLOBAL atrbvh_u32 *left;
    ATRBVH_SHARED_GLOBAL atrbvh_u32 *right;
    ATRBVH_SHARED_GLOBAL atrbvh_u32 *parent;
    ATRBVH_SHARED_GLOBAL atrbvh_u32 *count;
    ATRBVH_SHARED_GLOBAL atrbvh_box *box;
    ATRBVH_SHARED_GLOBAL double *cost;
    /* Each node's collapse decision, 1 when atrbvh_node_cost's choice for
     * its cost is the collapsed one (a tree leaf: 1), kept exact like
     * its cost by every refresh and write-back, so that the collapse
     * stage only counts its sizes; NULL when the build keeps none (the
     * collapse stage then decides from the costs). */
    ATRBVH_SHARED_GLOBAL unsigned char *flat;
    atrbvh_u32 n_internal;
} atrbvh_treelet_tree;

/* A formed treelet. */
typedef struct atrbvh_treelet {
    atrbvh_u32 n;                                /* leaves formed          */
    atrbvh_u32 pend;                             /* forming: the slot
                                                    filled last beside
                                                    slot n-1, whose areas
                                                    wait (the formation's
                                                    comment)               */
    atrbvh_u32 leaf[ATRBVH_TREELET_MAX];         /* node ids, slot order   */
    atrbvh_u32 internal[ATRBVH_TREELET_MAX - 1]; /* [0] = root, then in
                                                    expansion order        */
} atrbvh_treelet;

/* The treelet leaves' data, in slot order. */
typedef struct atrbvh_treelet_leaves {
    atrbvh_box box[ATRBVH_TREELET_MAX];
    atrbvh_u32 count[ATRBVH_TREELET_MAX];
    double cost[ATRBVH_TREELET_MAX];
} atrbvh_treelet_leaves;

/* A topology over the leaves (codes as in the header comment) and, after
 * atrbvh_treelet_evaluate, the box, primitive count and cost of each local
 * internal node, plus `order`: the local nodes in pre-order (root first,
 * left subtree before right), the order internal ids are assigned in. */
typedef struct atrbvh_treelet_topo {
    atrbvh_u32 root;
    atrbvh_u32 left[ATRBVH_TREELET_MAX - 1];
    atrbvh_u32 right[ATRBVH_TREELET_MAX - 1];
    atrbvh_u32 order[ATRBVH_TREELET_MAX - 1];
    atrbvh_box box[ATRBVH_TREELET_MAX - 1];
    atrbvh_u32 count[ATRBVH_TREELET_MAX - 1];
    double cost[ATRBVH_TREELET_MAX - 1];
    /* bit k: local node k collapses (atrbvh_node_cost's choice for its
     * cost), for the collapse sizes of the write-back */
    atrbvh_u32 flat;
} atrbvh_treelet_topo;

/* -------------------------------------------------------------- forming */
/* Treelet formation (Karras & Aila 2013, section 4.1; reference
 * Treelet.cuh formTreelet): start from the root's two children and
 * expand, n-2 times, the treelet leaf with the largest surface area among
 * those that are internal BVH nodes (strict >, so ties go to the lowest
 * slot).  The expanded node's left child takes its slot, its right child
 * is appended.  Returns the number of leaves formed: n whenever the root's
 * subtree holds at least n primitives (it then has at least n-1 internal
 * nodes), fewer only otherwise. */
/* Formation in steps, so that a driver can advance several treelets side
 * by side (optimise.c: the loads of one overlap those of the others):
 * atrbvh_treelet_form_first takes the root's two children (tl->n = 2),
 * each atrbvh_treelet_form_next one expansion (tl->n + 1), returning 0
 * when no slot is an internal BVH node.  `area` holds the slots' areas
 * in between (-1 for a slot that is not an internal node), but those of
 * the two slots an expansion fills (tl->pend and n-1) only from the next
 * step on, which computes them first: their boxes then come from memory
 * while the other treelets of a driver take their steps, not on the way
 * of this one's (the same areas, the same choices).  On the CPU a slot's
 * box, cost and count are prefetched as it is filled, for that step and
 * the gather that follows (no effect on any value). */
#if !defined(__OPENCL_VERSION__) && (defined(__GNUC__) || defined(__clang__))
#define ATRBVH_TREELET_PREFETCH(t, x)                                          \
    do {                                                                       \
        __builtin_prefetch(&(t)->box[x]);                                      \
        __builtin_prefetch(&(t)->cost[x]);                                     \
        __builtin_prefetch(&(t)->count[x]);                                    \
    } while (0)
#else
#define ATRBVH_TREELET_PREFETCH(t, x) ((void)0)
#endif
/* A slot's area for the formation: its node's box area, or -1 for a slot
 * that is not an internal BVH node (areas are never negative, so "the
 * first expandable slot, then strictly larger" is one strict > against a
 * start of -0.5). */
ATRBVH_FN double atrbvh_treelet_slot_area(const atrbvh_treelet_tree *t,
                                          atrbvh_u32 x)
{
    return x < t->n_internal ? atrbvh_box_area(t->box[x]) : -1.0;
}

/* The formation, pre-order and write-back over private arrays (the _p
 * functions: atrbvh_treelet, atrbvh_treelet_topo) and over the scratch
 * (the _g functions, section "ATRBVH, any size"): one text,
 * shared/treelet_arrays.inc, for the two address spaces. */
#ifdef __OPENCL_VERSION__
#define ATRBVH_TA __private
#else
#define ATRBVH_TA
#endif
/* These and the private path's wrappers below inlined on the CPU: GCC
 * otherwise folds the two identical C instances into one function, calls
 * it out of line and keeps the wrappers out of line too (+1.5%
 * instructions in ATRBVH(9,2)'s optimise stage on sibenik, callgrind),
 * where the code they replace was inlined. */
#if !defined(__OPENCL_VERSION__) && (defined(__GNUC__) || defined(__clang__))
#define ATRBVH_TREELET_INLINE static inline __attribute__((always_inline))
#else
#define ATRBVH_TREELET_INLINE ATRBVH_FN
#endif
#define ATRBVH_TA_FN(f) f##_p
#define ATRBVH_TA_FLAT(flat, k) (((flat)[0] >> (k)) & 1u)
#include "treelet_arrays.inc"
#undef ATRBVH_TA
#undef ATRBVH_TA_FN
#undef ATRBVH_TA_FLAT
#define ATRBVH_TA ATRBVH_GLOBAL
#define ATRBVH_TA_FN(f) f##_g
#define ATRBVH_TA_FLAT(flat, k) ((flat)[k])
#include "treelet_arrays.inc"
#undef ATRBVH_TA
#undef ATRBVH_TA_FN
#undef ATRBVH_TA_FLAT

ATRBVH_TREELET_INLINE void
atrbvh_treelet_form_first(const atrbvh_treelet_tree *t, atrbvh_u32 root,
                          atrbvh_treelet *tl)
{
    atrbvh_form_first_p(t, root, tl->leaf, tl->internal);
    tl->pend = 0; /* slots 0 and 1 wait for the first step */
    tl->n = 2;
}

ATRBVH_TREELET_INLINE int
atrbvh_treelet_form_next(const atrbvh_treelet_tree *t, atrbvh_treelet *tl,
                         double *area)
{
    const atrbvh_u32 best =
        atrbvh_form_step_p(t, tl->n, tl->pend, tl->leaf, tl->internal, area);
    if (best == ATRBVH_U32_MAX)
        return 0;
    tl->pend = best;
    tl->n++;
    return 1;
}

/* The whole formation (the section's rule): up to n leaves. */
ATRBVH_FN atrbvh_u32 atrbvh_treelet_form(const atrbvh_treelet_tree *t,
                                         atrbvh_u32 root, atrbvh_u32 n,
                                         atrbvh_treelet *tl)
{
    double area[ATRBVH_TREELET_MAX];
    tl->n = atrbvh_form_p(t, root, n, tl->leaf, tl->internal, area);
    tl->pend = 0; /* (no step follows a whole formation) */
    return tl->n;
}

ATRBVH_FN void atrbvh_treelet_gather(const atrbvh_treelet_tree *t,
                                     const atrbvh_treelet *tl,
                                     atrbvh_treelet_leaves *lv)
{
    atrbvh_u32 k;
    for (k = 0; k < tl->n; k++) {
        atrbvh_u32 node = tl->leaf[k];
        lv->box[k] = t->box[node];
        lv->count[k] = t->count[node];
        lv->cost[k] = t->cost[node];
    }
}

/* --------------------------------------------------------------- TRBVH */
/* Scratch for atrbvh_trbvh_dp, 2^n entries each (n the treelet size):
 *  box:   the union boxes of the subsets by coordinate, six planes of 2^n
 *         floats (min x, y, z, max x, y, z; plane c at box + c * 2^n);
 *  cost:  first the surface area A(S) of each subset, then, once S is
 *         processed, its optimal cost C(S);
 *  count: primitives N(S);
 *  split: the best left part P of S, set by atrbvh_trbvh_extract for the
 *         subsets of the extracted topology only.
 * The sizes in bytes are those of 2^n atrbvh_box, double and two u32.
 * Once every subset's box is made, the DP reuses the start of `box` as
 * 2 * 2^n doubles (see atrbvh_trbvh_dp). */
typedef struct atrbvh_trbvh_scratch {
    ATRBVH_GLOBAL float *box;
    ATRBVH_GLOBAL double *cost;
    ATRBVH_GLOBAL atrbvh_u32 *count;
    ATRBVH_GLOBAL atrbvh_u32 *split;
} atrbvh_trbvh_scratch;

/* Subset masks as array indices: a native-width integer on the CPU (no
 * zero extension per load in the partition loop), 32 bits in OpenCL. */
#ifdef __OPENCL_VERSION__
typedef atrbvh_u32 atrbvh_trbvh_mask;
#else
typedef atrbvh_u64 atrbvh_trbvh_mask;
#endif

/* Entry 0 of the subset tables: leaf k's box b in the six planes of
 * `plane` floats, count 0. */
ATRBVH_FN void atrbvh_trbvh_subset_leaf(atrbvh_trbvh_mask plane,
                                        atrbvh_box b, atrbvh_trbvh_scratch s)
{
    s.box[0] = b.min[0];
    s.box[plane] = b.min[1];
    s.box[2u * plane] = b.min[2];
    s.box[3u * plane] = b.max[0];
    s.box[4u * plane] = b.max[1];
    s.box[5u * plane] = b.max[2];
    s.count[0] = 0;
}

/* Box, area and count of every subset S whose highest leaf is k (S = bit
 * | rest, bit = 2^k, rest < bit): box(S) = union(box(rest), box of leaf
 * k), rest first as atrbvh_box_union, area(S) as atrbvh_box_area, N(S) =
 * N(rest) + N(leaf k).  Entry 0 (the empty set, never a subset of the
 * DP) holds leaf k's own box and count 0 for the duration, so rest = 0
 * gives S = {k} by the same formula.  Writes entries bit .. 2*bit-1.
 * Here one subset at a time: OpenCL, CPUs without SSE2, and bit < 4. */
ATRBVH_FN void atrbvh_trbvh_subsets1(atrbvh_u32 n, atrbvh_u32 k,
                                     const atrbvh_treelet_leaves *lv,
                                     atrbvh_trbvh_scratch s)
{
    const atrbvh_trbvh_mask bit = (atrbvh_trbvh_mask)1 << k,
                            plane = (atrbvh_trbvh_mask)1 << n;
    ATRBVH_GLOBAL float *c0 = s.box, *c1 = c0 + plane, *c2 = c1 + plane,
                        *c3 = c2 + plane, *c4 = c3 + plane, *c5 = c4 + plane;
    const atrbvh_box b = lv->box[k];
    atrbvh_trbvh_mask r;
    atrbvh_trbvh_subset_leaf(plane, b, s);
    for (r = 0; r < bit; r++) {
        atrbvh_box u;
        u.min[0] = c0[r] < b.min[0] ? c0[r] : b.min[0];
        u.min[1] = c1[r] < b.min[1] ? c1[r] : b.min[1];
        u.min[2] = c2[r] < b.min[2] ? c2[r] : b.min[2];
        u.max[0] = c3[r] > b.max[0] ? c3[r] : b.max[0];
        u.max[1] = c4[r] > b.max[1] ? c4[r] : b.max[1];
        u.max[2] = c5[r] > b.max[2] ? c5[r] : b.max[2];
        c0[bit + r] = u.min[0];
        c1[bit + r] = u.min[1];
        c2[bit + r] = u.min[2];
        c3[bit + r] = u.max[0];
        c4[bit + r] = u.max[1];
        c5[bit + r] = u.max[2];
        s.cost[bit + r] = atrbvh_box_area(u);
        s.count[bit + r] = s.count[r] + lv->count[k];
    }
}

#if !defined(__OPENCL_VERSION__) && defined(__SSE2__)
#include <emmintrin.h>
/* Four subsets at a time with SSE2 (bit >= 4): MINPS/MAXPS are a < b ? a :
 * b and a > b ? a : b lane for lane, and the double arithmetic is the
 * scalar one's IEEE operations in the same order, so every bit equals
 * atrbvh_trbvh_subsets1's (which OpenCL and other CPUs run). */
ATRBVH_FN void atrbvh_trbvh_subsets(atrbvh_u32 n, atrbvh_u32 k,
                                    const atrbvh_treelet_leaves *lv,
                                    atrbvh_trbvh_scratch s)
{
    const atrbvh_trbvh_mask bit = (atrbvh_trbvh_mask)1 << k,
                            plane = (atrbvh_trbvh_mask)1 << n;
    float *c0 = s.box, *c1 = c0 + plane, *c2 = c1 + plane, *c3 = c2 + plane,
          *c4 = c3 + plane, *c5 = c4 + plane;
    const atrbvh_box b = lv->box[k];
    atrbvh_trbvh_mask r;
    if (bit < 4u) {
        atrbvh_trbvh_subsets1(n, k, lv, s);
        return;
    }
    atrbvh_trbvh_subset_leaf(plane, b, s);
    {
        const __m128 q0 = _mm_set1_ps(b.min[0]), q1 = _mm_set1_ps(b.min[1]),
                     q2 = _mm_set1_ps(b.min[2]), q3 = _mm_set1_ps(b.max[0]),
                     q4 = _mm_set1_ps(b.max[1]), q5 = _mm_set1_ps(b.max[2]);
        const __m128i qn = _mm_set1_epi32((int)lv->count[k]);
        const __m128d two = _mm_set1_pd(2.0);
        for (r = 0; r < bit; r += 4u) {
            const __m128 x0 = _mm_min_ps(_mm_loadu_ps(c0 + r), q0);
            const __m128 y0 = _mm_min_ps(_mm_loadu_ps(c1 + r), q1);
            const __m128 z0 = _mm_min_ps(_mm_loadu_ps(c2 + r), q2);
            const __m128 x1 = _mm_max_ps(_mm_loadu_ps(c3 + r), q3);
            const __m128 y1 = _mm_max_ps(_mm_loadu_ps(c4 + r), q4);
            const __m128 z1 = _mm_max_ps(_mm_loadu_ps(c5 + r), q5);
            __m128d dx, dy, dz, t;
            _mm_storeu_ps(c0 + bit + r, x0);
            _mm_storeu_ps(c1 + bit + r, y0);
            _mm_storeu_ps(c2 + bit + r, z0);
            _mm_storeu_ps(c3 + bit + r, x1);
            _mm_storeu_ps(c4 + bit + r, y1);
            _mm_storeu_ps(c5 + bit + r, z1);
            _mm_storeu_si128(
                (__m128i *)(void *)(s.count + bit + r),
                _mm_add_epi32(
                    _mm_loadu_si128((const __m128i *)(const void *)(s.count +
                                                                    r)),
                    qn));
            dx = _mm_sub_pd(_mm_cvtps_pd(x1), _mm_cvtps_pd(x0));
            dy = _mm_sub_pd(_mm_cvtps_pd(y1), _mm_cvtps_pd(y0));
            dz = _mm_sub_pd(_mm_cvtps_pd(z1), _mm_cvtps_pd(z0));
            t = _mm_mul_pd(dx, dy);
            t = _mm_add_pd(t, _mm_mul_pd(dy, dz));
            t = _mm_add_pd(t, _mm_mul_pd(dz, dx));
            _mm_storeu_pd(s.cost + bit + r, _mm_mul_pd(two, t));
            dx = _mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(x1, x1)),
                            _mm_cvtps_pd(_mm_movehl_ps(x0, x0)));
            dy = _mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(y1, y1)),
                            _mm_cvtps_pd(_mm_movehl_ps(y0, y0)));
            dz = _mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(z1, z1)),
                            _mm_cvtps_pd(_mm_movehl_ps(z0, z0)));
            t = _mm_mul_pd(dx, dy);
            t = _mm_add_pd(t, _mm_mul_pd(dy, dz));
            t = _mm_add_pd(t, _mm_mul_pd(dz, dx));
            _mm_storeu_pd(s.cost + bit + r + 2u, _mm_mul_pd(two, t));
        }
    }
}
#else
ATRBVH_FN void atrbvh_trbvh_subsets(atrbvh_u32 n, atrbvh_u32 k,
                                    const atrbvh_treelet_leaves *lv,
                                    atrbvh_trbvh_scratch s)
{
    atrbvh_trbvh_subsets1(n, k, lv, s);
}
#endif

/* The best partition of S (|S| >= 2; every proper subset's cost final in
 * cost[], and at rest[P] = C(S\P) for every subset P of S (rest =
 * rev + (full ^ S), see atrbvh_trbvh_dp), base = ci*A(S); both tables
 * read every st-th entry, cost[st * P] and rest[st * P]: st = 1 but for
 * the four-lane DP's interleaved tables, 4): the minimum
 * over P of (base + C(P)) + C(S\P),
 * P running through the nonempty subsets of delta = S minus its lowest
 * leaf in increasing order (the paper's P = (P - delta) & S), the first P
 * among equal minima (strict <).  *bestp receives it.  The enumeration
 * goes by pairs: with lb the lowest bit of delta and d2 = delta minus lb,
 * the subsets of delta in increasing order are 0, lb, then E, E|lb for
 * each nonempty subset E of d2 in increasing order (E|lb lies below the
 * next E, which differs from E above lb): P = lb first, then one mask
 * update and one loop test per two partitions, all four loads indexed by
 * E (E|lb = E + lb through pointers moved by lb).  The partitions, their
 * sums and the order of the comparisons are exactly the one-by-one
 * loop's.  (By fours, on the two lowest bits, the setup per subset cost
 * about what the loop saved.)  The comparison is
 * written as two selects so that it compiles to a conditional move: the
 * outcome is data-dependent and a branch mispredicts.  (An SSE2 version
 * taking four partitions per step with a branch on "any lane lower" ran
 * about 1.5x slower in wall-clock time despite 20% fewer instructions.) */
#define ATRBVH_TRBVH_TRY(c, part)                                              \
    do {                                                                       \
        const double c_ = (c);                                                 \
        const atrbvh_trbvh_mask p_ = (part);                                   \
        bp = c_ < best ? p_ : bp;                                              \
        best = c_ < best ? c_ : best;                                          \
    } while (0)
ATRBVH_FN double atrbvh_trbvh_best(ATRBVH_GLOBAL const double *cost,
                                   ATRBVH_GLOBAL const double *rest,
                                   atrbvh_trbvh_mask st, atrbvh_trbvh_mask S,
                                   double base, atrbvh_trbvh_mask *bestp)
{
    const atrbvh_trbvh_mask delta = (S - 1u) & S;
    const atrbvh_trbvh_mask lb = delta & (0u - delta), d2 = delta ^ lb;
    ATRBVH_GLOBAL const double *cost_lb = cost + st * lb,
                               *rest_lb = rest + st * lb;
    atrbvh_trbvh_mask E, bp = lb;
    double best = base + cost[st * lb];
    best = best + rest[st * lb];
    for (E = d2 & (0u - d2); E; E = (E - d2) & d2) {
        double c = base + cost[st * E];
        c = c + rest[st * E];
        ATRBVH_TRBVH_TRY(c, E);
        c = base + cost_lb[st * E];
        c = c + rest_lb[st * E];
        ATRBVH_TRBVH_TRY(c, E + lb);
    }
    *bestp = bp;
    return best;
}

/* The minimum of atrbvh_trbvh_best without its argument: the same sums
 * over the same partitions, so the same value, bit for bit.  Two running
 * minima, one for the partitions E and one for E|lb, joined at the end:
 * the minimum of a set does not depend on the order it is taken in, and
 * each is written lo < c ? lo : c, which x86 computes in place (MINSD),
 * no register copy per partition.  That form differs from strict <
 * (c < lo ? c : lo) only when neither value is below the other, i.e. for
 * equal values, which have the same bits here: costs are sums and
 * products of non-negative finite terms, never -0 (an area of min/max
 * planes is +0 or positive) nor NaN (ci and ct are finite, lib/api.c).
 * The argument of the minimum (the split) is wanted only for the few
 * subsets of the extracted topology, and only when the treelet is written
 * back: atrbvh_trbvh_extract finds it again with atrbvh_trbvh_best. */
ATRBVH_FN double atrbvh_trbvh_min(ATRBVH_GLOBAL const double *cost,
                                  ATRBVH_GLOBAL const double *rest,
                                  atrbvh_trbvh_mask S, double base)
{
    const atrbvh_trbvh_mask delta = (S - 1u) & S;
    const atrbvh_trbvh_mask lb = delta & (0u - delta), d2 = delta ^ lb;
    ATRBVH_GLOBAL const double *cost_lb = cost + lb, *rest_lb = rest + lb;
    atrbvh_trbvh_mask E;
    double lo0 = base + cost[lb], lo1;
    lo0 = lo0 + rest[lb];
    lo1 = lo0;
    for (E = d2 & (0u - d2); E; E = (E - d2) & d2) {
        double c = base + cost[E];
        c = c + rest[E];
        lo0 = lo0 < c ? lo0 : c;
        c = base + cost_lb[E];
        c = c + rest_lb[E];
        lo1 = lo1 < c ? lo1 : c;
    }
    return lo0 < lo1 ? lo0 : lo1;
}

/* The split of S that atrbvh_trbvh_best returns, found as the first
 * partition in its order whose cost equals `target`, the minimum
 * atrbvh_trbvh_costs found over the partitions (equal values have equal
 * bits here, so the first equal one is the first of equal minima that
 * strict < keeps).  The caller passes the partitions' minimum, so the
 * scan stops at it, on average about halfway; should it not be met, the
 * whole scan of atrbvh_trbvh_best decides.  The tables as there (st). */
ATRBVH_FN atrbvh_trbvh_mask
atrbvh_trbvh_first(ATRBVH_GLOBAL const double *cost,
                   ATRBVH_GLOBAL const double *rest, atrbvh_trbvh_mask st,
                   atrbvh_trbvh_mask S, double base, double target)
{
    const atrbvh_trbvh_mask delta = (S - 1u) & S;
    const atrbvh_trbvh_mask lb = delta & (0u - delta), d2 = delta ^ lb;
    ATRBVH_GLOBAL const double *cost_lb = cost + st * lb,
                               *rest_lb = rest + st * lb;
    atrbvh_trbvh_mask E, bp;
    double c = base + cost[st * lb];
    c = c + rest[st * lb];
    if (c == target)
        return lb;
    for (E = d2 & (0u - d2); E; E = (E - d2) & d2) {
        c = base + cost[st * E];
        c = c + rest[st * E];
        if (c == target)
            return E;
        c = base + cost_lb[st * E];
        c = c + rest_lb[st * E];
        if (c == target)
            return E + lb;
    }
    (void)atrbvh_trbvh_best(cost, rest, st, S, base, &bp);
    return bp;
}

/* TRBVH (Karras & Aila 2013, "Fast Parallel Construction of High-Quality
 * Bounding Volume Hierarchies", HPG 2013, section 4.2 and Algorithm 2):
 * dynamic programming over every subset S of the n treelet leaves,
 *
 *   C({k}) = the stored cost of leaf k,
 *   C(S)   = atrbvh_node_cost(A(S), N(S), C(P), C(S\P)) minimised over P,
 *          = min(ci*A(S) + C(P) + C(S\P), ct*A(S)*N(S)) where collapsing
 *            is allowed (cfg collapse and N(S) <= max_leaf),
 *
 * N(S) the primitives under S's leaves (not the treelet's: a bug of the
 * reference).  The partitions of S are enumerated with the paper's trick:
 * delta = (S-1) & S, P = (-delta) & S, P = (P - delta) & S until 0, which
 * visits each unordered split {P, S\P} once, with P never holding S's
 * lowest leaf (P runs through the nonempty subsets of delta in increasing
 * order); P becomes the left child.  Subsets are visited in increasing
 * numeric order, so every proper subset is final before S.  The boxes,
 * areas and counts come first, by highest leaf (atrbvh_trbvh_subsets, a
 * loop without dependences between its iterations), all of them before
 * the first partition, then the partition loop of each S reads only
 * costs: C(P) from cost[P] and C(S\P) from a mirror, rev[full ^ X] =
 * C(X) written with each final cost, at rev[(full ^ S) + P] (full ^ S
 * and P are disjoint): both loads indexed by P, no complement computed
 * per partition.  The mirror lives in the box planes, dead by then (2^n
 * doubles within 6 * 2^n floats, at the scratch's aligned start), and so
 * do the areas A(S), kept for atrbvh_trbvh_extract in the next 2^n
 * doubles (cost[S] holds A(S) until C(S) replaces it).
 *
 * Two steps: atrbvh_trbvh_costs fills the costs and returns C(all
 * leaves) - the value only, no split per subset (atrbvh_trbvh_min) -
 * and atrbvh_trbvh_extract, called only when the treelet is kept, finds
 * the split of each subset of the optimal topology (atrbvh_trbvh_best
 * over the final costs: the same sums, the first of equal minima) and
 * builds it; atrbvh_trbvh_dp is both.  On dragon, TRBVH(7,3) keeps about
 * 63% of its treelets, and the extracted subsets hold about a tenth of
 * the partitions.
 *
 * Exactness: the partition cost is computed as (ci*A + C(P)) + C(S\P),
 * literally atrbvh_node_cost's sum, and rounding is monotone, so the
 * returned cost is exactly (bit for bit) the minimum of that formula over
 * every binary tree on the leaves whose left children avoid their lowest
 * leaf, and equals the cost atrbvh_treelet_evaluate computes for the
 * extracted topology.  Ties keep the first partition in enumeration order
 * (strict <), i.e. the numerically smallest P.  Masks fit in 32 bits
 * (n <= ATRBVH_TRBVH_MAX). */
/* The box planes change type (floats, then the doubles of the mirror and
 * the areas, then floats again for the next treelet): C allows it in
 * allocated memory, and this compiler barrier (no instruction) keeps any
 * type-based reordering from moving an access across the change. */
#if !defined(__OPENCL_VERSION__) && (defined(__GNUC__) || defined(__clang__))
#define ATRBVH_TRBVH_RETYPE() __asm__ __volatile__("" ::: "memory")
#else
#define ATRBVH_TRBVH_RETYPE() ((void)0)
#endif
#if !defined(__OPENCL_VERSION__) && (defined(__GNUC__) || defined(__clang__))
/* Not inlined into atrbvh_treelet_process: in a frame of its own the
 * partition loop keeps its variables in registers (GCC spilled one per
 * partition when inlined). */
__attribute__((noinline, unused)) static double
#else
ATRBVH_FN double
#endif
atrbvh_trbvh_costs(const atrbvh_cost_params *p, atrbvh_u32 n,
                   const atrbvh_treelet_leaves *lv, atrbvh_trbvh_scratch s)
{
    atrbvh_u32 k, full = (1u << n) - 1u;
    /* Collapsing is allowed for N(S) <= lim (0: never; N(S) >= 1). */
    const atrbvh_u32 lim = !p->collapse          ? 0u
                           : p->max_leaf == 0u ? ATRBVH_U32_MAX
                                               : p->max_leaf;
    const double ci = p->ci, ct = p->ct;
    ATRBVH_GLOBAL double *cost = s.cost;
    /* The mirror's last entry: rev + (full ^ S) = rev_top - S; the areas
     * after the mirror. */
    ATRBVH_GLOBAL double *rev_top =
        (ATRBVH_GLOBAL double *)(ATRBVH_GLOBAL void *)s.box + full;
    ATRBVH_GLOBAL double *areas = rev_top + 1u;

    for (k = 0; k < n; k++)
        atrbvh_trbvh_subsets(n, k, lv, s);
    ATRBVH_TRBVH_RETYPE();
    for (k = 0; k < n; k++) {
        const atrbvh_trbvh_mask bit = (atrbvh_trbvh_mask)1 << k;
        atrbvh_trbvh_mask S;
        cost[bit] = lv->cost[k];
        *(rev_top - bit) = lv->cost[k];
        /* Every S whose highest leaf is k: S = bit | rest, 0 < rest < bit. */
        for (S = bit + 1u; S < bit + bit; S++) {
            const double area = cost[S];
            const double base = ci * area;
            ATRBVH_GLOBAL double *rest = rev_top - S;
            double best = atrbvh_trbvh_min(cost, rest, S, base);
            if (s.count[S] <= lim) {
                double flat = ct * area;
                flat = flat * (double)s.count[S];
                if (flat < best)
                    best = flat;
            }
            areas[S] = area;
            cost[S] = best;
            rest[0] = best; /* rev[full ^ S] */
        }
    }
    ATRBVH_TRBVH_RETYPE();
    return cost[full];
}

/* Where atrbvh_trbvh_extract_from reads a finished DP: C(S) at
 * cost[stride * S], the mirror rev[full ^ X] = C(X) at rev_top[-stride *
 * X], A(S) at area[stride * S] and N(S) at count[stride * S]; it writes
 * split[S].  The scalar DP's layout (atrbvh_trbvh_tables_of: stride 1,
 * the mirror and the areas in the box planes) or one lane of the
 * four-lane DP's (atrbvh_trbvh_tables_lane: stride 4, and the split of
 * all leaves, which that DP finds as it goes, in top). */
typedef struct atrbvh_trbvh_tables {
    ATRBVH_GLOBAL const double *cost, *rev_top, *area;
    ATRBVH_GLOBAL const atrbvh_u32 *count;
    ATRBVH_GLOBAL atrbvh_u32 *split;
    atrbvh_trbvh_mask stride;
    atrbvh_u32 top; /* the split of all leaves when the DP kept it, or 0 */
} atrbvh_trbvh_tables;

/* The tables atrbvh_trbvh_costs leaves in s (n leaves). */
ATRBVH_FN atrbvh_trbvh_tables atrbvh_trbvh_tables_of(atrbvh_u32 n,
                                                     atrbvh_trbvh_scratch s)
{
    const atrbvh_u32 full = (1u << n) - 1u;
    atrbvh_trbvh_tables tab;
    ATRBVH_GLOBAL double *rev_top =
        (ATRBVH_GLOBAL double *)(ATRBVH_GLOBAL void *)s.box + full;
    tab.cost = s.cost;
    tab.rev_top = rev_top;
    tab.area = rev_top + 1u;
    tab.count = s.count;
    tab.split = s.split;
    tab.stride = 1u;
    tab.top = 0u;
    return tab;
}

/* The optimal topology after the DP (its tables untouched since), top
 * down (explicit stack, no recursion): local node 0 is the root, children
 * get local ids as discovered.  The split of each subset S on the way is
 * atrbvh_trbvh_best over the final costs, the argument of the minimum
 * that the DP took (same sums, same order; it is also left in
 * tab->split[S]). */
ATRBVH_FN void atrbvh_trbvh_extract_from(const atrbvh_cost_params *p,
                                         atrbvh_u32 n,
                                         const atrbvh_trbvh_tables *tab,
                                         atrbvh_treelet_topo *topo)
{
    atrbvh_u32 full = (1u << n) - 1u;
    atrbvh_u32 stack_mask[ATRBVH_TRBVH_MAX];
    atrbvh_u32 stack_node[ATRBVH_TRBVH_MAX];
    atrbvh_u32 sp, next;
    const atrbvh_trbvh_mask st = tab->stride;
    const atrbvh_u32 lim = !p->collapse          ? 0u
                           : p->max_leaf == 0u ? ATRBVH_U32_MAX
                                               : p->max_leaf;
    ATRBVH_TRBVH_RETYPE();
    topo->root = 0;
    stack_mask[0] = full;
    stack_node[0] = 0;
    sp = 1;
    next = 1;
    while (sp > 0) {
        atrbvh_u32 S, node, parts[2], side;
        atrbvh_trbvh_mask bp;
        sp--;
        S = stack_mask[sp];
        node = stack_node[sp];
        if (S == full && tab->top != 0u) {
            bp = tab->top;
        } else {
            /* C(S) is the partitions' minimum unless the collapse term
             * (recomputed as the DP did) equals it: then the
             * partitions' minimum is unknown, scan them all. */
            const double area = tab->area[st * S], base = p->ci * area;
            const double target = tab->cost[st * S];
            const atrbvh_u32 count = tab->count[st * S];
            ATRBVH_GLOBAL const double *rest = tab->rev_top - st * S;
            int whole = 0;
            if (count <= lim) {
                double flat = p->ct * area;
                flat = flat * (double)count;
                whole = flat == target;
            }
            if (whole)
                (void)atrbvh_trbvh_best(tab->cost, rest, st, S, base, &bp);
            else
                bp = atrbvh_trbvh_first(tab->cost, rest, st, S, base,
                                        target);
        }
        tab->split[S] = (atrbvh_u32)bp;
        parts[0] = (atrbvh_u32)bp;
        parts[1] = S ^ parts[0];
        for (side = 0; side < 2; side++) {
            atrbvh_u32 part = parts[side], code;
            if ((part & (part - 1u)) == 0u) {
                /* a leaf: the index of its bit (the loop that counted up
                 * to it was mispredicted) */
                code = (atrbvh_u32)(63 - ATRBVH_CLZ64(part));
            } else {
                code = n + next;
                stack_mask[sp] = part;
                stack_node[sp] = next;
                sp++;
                next++;
            }
            if (side == 0)
                topo->left[node] = code;
            else
                topo->right[node] = code;
        }
    }
    ATRBVH_TRBVH_RETYPE();
}

/* The optimal topology after atrbvh_trbvh_costs, from its tables in s. */
ATRBVH_FN void atrbvh_trbvh_extract(const atrbvh_cost_params *p,
                                    atrbvh_u32 n, atrbvh_trbvh_scratch s,
                                    atrbvh_treelet_topo *topo)
{
    const atrbvh_trbvh_tables tab = atrbvh_trbvh_tables_of(n, s);
    atrbvh_trbvh_extract_from(p, n, &tab, topo);
}

/* The whole DP: costs, then the topology; returns C(all leaves). */
ATRBVH_FN double atrbvh_trbvh_dp(const atrbvh_cost_params *p, atrbvh_u32 n,
                                 const atrbvh_treelet_leaves *lv,
                                 atrbvh_trbvh_scratch s,
                                 atrbvh_treelet_topo *topo)
{
    double found = atrbvh_trbvh_costs(p, n, lv, s);
    atrbvh_trbvh_extract(p, n, s, topo);
    return found;
}

/* ------------------------------------------------ TRBVH, four at once */
/* Four treelets' DP side by side, one per lane of AVX's four doubles (x86
 * CPUs with AVX, chosen at run time by the driver, __builtin_cpu_supports;
 * the CPU driver takes treelets of disjoint subtrees, optimise.c) or of
 * an OpenCL double4 (the opt_round4 kernel on a CPU device).  Lane
 * by lane it is atrbvh_trbvh_costs: the same subsets, the same partitions,
 * the same IEEE sums in the same order (the compiler contracts nothing,
 * -ffp-contract=off, and AVX has no FMA), and each minimum written as the
 * scalar one's select (VMINPD's a < b ? a : b is the scalar lo < c ? lo :
 * c and flat < best ? flat : best), so each lane's C(S) has the scalar
 * bits.  The partition loop's instructions (about half of a TRBVH(7)
 * treelet's) then serve four treelets; its loads are one 32-byte vector
 * per cost.  Fewer than four treelets fill the other lanes with the first
 * one's (results unused).
 *
 * All four lanes' tables are interleaved in `quad`
 * (ATRBVH_TRBVH_QUAD_DOUBLES * 2^n doubles, 32-byte aligned), entry S of
 * lane l at 4S + l of each: C(S), then the mirror rev[full ^ X] = C(X) as
 * in atrbvh_trbvh_costs, then A(S), then the six box planes (floats),
 * then N(S) (u32).  So a subset's box, area and count are made for the
 * four lanes at once, and its ci*A(S) and collapse term are vector words
 * as its partitions' sums are (with each lane's tables apart, the
 * per-subset gathers of four areas and four counts were a third of
 * atrbvh_trbvh_costs4's samples, perf, TRBVH(7,3)).
 * atrbvh_trbvh_tables_lane names where a lane's tables are, for the
 * extraction of a kept treelet (atrbvh_trbvh_keep_from).  found[l] is
 * C(all leaves) of lane l, top[l] its split (atrbvh_trbvh_argmin4). */

/* atrbvh_trbvh_costs4's tables take this many doubles a subset (2^n
 * subsets): 4 costs, 4 mirror entries, 4 areas, 24 box floats and 4
 * counts. */
#define ATRBVH_TRBVH_QUAD_DOUBLES 26u

/* The tables of lane `lane` of atrbvh_trbvh_costs4 (n leaves), where
 * they are: every fourth entry of `quad`'s costs, mirror, areas and
 * counts; the split of all leaves `top`, the other splits in that lane's
 * scratch s.  The extraction reads about
 * six subsets' partitions, so it reads them there: a copy of a kept
 * lane's 2^n - 1 costs, mirror entries and areas back to the scalar
 * layout was 8.6% of TRBVH(7)'s optimise-stage instructions (callgrind,
 * sibenik, one thread). */
ATRBVH_FN atrbvh_trbvh_tables
atrbvh_trbvh_tables_lane(atrbvh_u32 n, ATRBVH_GLOBAL const double *quad,
                         atrbvh_u32 lane, atrbvh_u32 top,
                         atrbvh_trbvh_scratch s)
{
    const atrbvh_trbvh_mask full = ((atrbvh_trbvh_mask)1 << n) - 1u,
                            plane = (atrbvh_trbvh_mask)4 << n;
    atrbvh_trbvh_tables tab;
    tab.cost = quad + lane;
    tab.rev_top = quad + 4u * (((atrbvh_trbvh_mask)1 << n) + full) + lane;
    tab.area = quad + 2u * plane + lane;
    tab.count = (ATRBVH_GLOBAL const atrbvh_u32 *)(ATRBVH_GLOBAL const void *)(
                    quad + 6u * plane) +
                lane;
    tab.split = s.split;
    tab.stride = 4u;
    tab.top = top;
    return tab;
}

#if !defined(__OPENCL_VERSION__) && (defined(__GNUC__) || defined(__clang__)) && \
    (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define ATRBVH_TRBVH_QUADS 1
/* Lane for lane m ? b : a, m a mask of all ones or all zeros per lane
 * (a comparison's).  Not VBLENDVPD: GCC 12 folds _mm256_blendv_pd into a
 * vector condition, which in a function compiled for AVX by attribute
 * it lowers lane by lane, a branch on each lane's sign (objdump: not one
 * VBLENDVPD left in atrbvh_agglomerate4, which was then slower than the
 * scalar agglomeration). */
__attribute__((target("avx"))) static inline __m256d
atrbvh_select4(__m256d a, __m256d b, __m256d m)
{
    return _mm256_or_pd(_mm256_and_pd(m, b), _mm256_andnot_pd(m, a));
}
#endif

/* The vector words of the four-lane code (atrbvh_trbvh_costs4 and
 * atrbvh_agglomerate4 below), written once for both: AVX's intrinsics in
 * C (x86 CPUs with AVX, chosen at run time) and OpenCL C's vector types
 * and built-ins (the opt_round4 kernel on a CPU device), each the same
 * operation lane for lane: a comparison's mask all ones or all zeros per
 * lane, select(a, b, m) m ? b : a, the minima and maxima a < b ? a : b
 * and a > b ? a : b as VMINPD/VMAXPD (the second operand on equal values
 * and NaN).  tests/test_opencl.c compares the kernel's trees with the
 * CPU's, tests/test_hashes.c the CPU's lanes with its scalar path. */
#if defined(__OPENCL_VERSION__) || defined(ATRBVH_TRBVH_QUADS)
#define ATRBVH_LANES4 1
#ifdef __OPENCL_VERSION__
typedef float4 atrbvh_v4f;  /* one coordinate of four lanes' boxes */
typedef double4 atrbvh_v4d; /* four lanes' areas, costs or codes    */
typedef long4 atrbvh_v4m;   /* a comparison's lanes: all ones or 0  */
#define ATRBVH_V4_FN static inline
#define ATRBVH_V4_MAIN static
#define ATRBVH_V4_ALIGNED(b)
#define atrbvh_v4_fload(p) vload4(0, (p))
#define atrbvh_v4_fstore(p, v) vstore4((v), 0, (p))
#define atrbvh_v4_fset(a, b, c, d) ((float4)((a), (b), (c), (d)))
#define atrbvh_v4_fset1(x) ((float4)(x))
#define atrbvh_v4_fmin(a, b) select((b), (a), (a) < (b))
#define atrbvh_v4_fmax(a, b) select((b), (a), (a) > (b))
#define atrbvh_v4_widen(v) convert_double4(v)
#define atrbvh_v4_set1(x) ((double4)(x))
#define atrbvh_v4_set(a, b, c, d) ((double4)((a), (b), (c), (d)))
#define atrbvh_v4_add(a, b) ((a) + (b))
#define atrbvh_v4_sub(a, b) ((a) - (b))
#define atrbvh_v4_mul(a, b) ((a) * (b))
#define atrbvh_v4_min(a, b) select((b), (a), (a) < (b))
#define atrbvh_v4_max(a, b) select((b), (a), (a) > (b))
#define atrbvh_v4_narrow(v) convert_float4(v)
#define atrbvh_v4_lt(a, b) ((a) < (b))
#define atrbvh_v4_eq(a, b) ((a) == (b))
#define atrbvh_v4_select(a, b, m) select((a), (b), (m))
#define atrbvh_v4_mor(a, b) ((a) | (b))
#define atrbvh_v4_mand(a, b) ((a) & (b))
#define atrbvh_v4_bits(m)                                                    \
    ((atrbvh_u32)(((m).s0 & 1) | ((m).s1 & 2) | ((m).s2 & 4) | ((m).s3 & 8)))
#define atrbvh_v4_mask(a, b, c, d)                                           \
    ((long4)(-(long)(a), -(long)(b), -(long)(c), -(long)(d)))
#define atrbvh_v4_load(p) vload4(0, (p))
#define atrbvh_v4_store(p, v) vstore4((v), 0, (p))
#define atrbvh_v4_storeu(p, v) vstore4((v), 0, (p))
#define ATRBVH_V4_INF ((double)INFINITY)
#define atrbvh_v4_done() ((void)0)
typedef uint4 atrbvh_v4u; /* four counts                          */
#define atrbvh_v4_uload(p) vload4(0, (p))
#define atrbvh_v4_ustore(p, v) vstore4((v), 0, (p))
#define atrbvh_v4_uadd(a, b) ((a) + (b))
#define atrbvh_v4_uset(a, b, c, d) ((uint4)((a), (b), (c), (d)))
#define atrbvh_v4_ucvt(v) convert_double4(v)
#define atrbvh_v4_le(a, b) ((a) <= (b))
/* The six coordinate vectors of four boxes (pointers), lane l box pl. */
#define ATRBVH_V4_BOXES(p0, p1, p2, p3, v)                                     \
    do {                                                                       \
        int c_;                                                                \
        for (c_ = 0; c_ < 3; c_++) {                                           \
            (v)[c_] = atrbvh_v4_fset((p0)->min[c_], (p1)->min[c_],             \
                                     (p2)->min[c_], (p3)->min[c_]);            \
            (v)[c_ + 3] = atrbvh_v4_fset((p0)->max[c_], (p1)->max[c_],         \
                                         (p2)->max[c_], (p3)->max[c_]);        \
        }                                                                      \
    } while (0)
#else
typedef __m128 atrbvh_v4f;
typedef __m256d atrbvh_v4d;
typedef __m256d atrbvh_v4m;
#define ATRBVH_V4_FN __attribute__((target("avx"))) static inline
#define ATRBVH_V4_MAIN __attribute__((noinline, unused, target("avx"))) static
#define ATRBVH_V4_ALIGNED(b) __attribute__((aligned(b)))
#define atrbvh_v4_fload(p) _mm_load_ps(p)
#define atrbvh_v4_fstore(p, v) _mm_store_ps((p), (v))
#define atrbvh_v4_fset(a, b, c, d) _mm_set_ps((d), (c), (b), (a))
#define atrbvh_v4_fset1(x) _mm_set1_ps(x)
#define atrbvh_v4_fmin(a, b) _mm_min_ps((a), (b))
#define atrbvh_v4_fmax(a, b) _mm_max_ps((a), (b))
#define atrbvh_v4_widen(v) _mm256_cvtps_pd(v)
#define atrbvh_v4_set1(x) _mm256_set1_pd(x)
#define atrbvh_v4_set(a, b, c, d) _mm256_set_pd((d), (c), (b), (a))
#define atrbvh_v4_add(a, b) _mm256_add_pd((a), (b))
#define atrbvh_v4_sub(a, b) _mm256_sub_pd((a), (b))
#define atrbvh_v4_mul(a, b) _mm256_mul_pd((a), (b))
#define atrbvh_v4_min(a, b) _mm256_min_pd((a), (b))
#define atrbvh_v4_max(a, b) _mm256_max_pd((a), (b))
#define atrbvh_v4_narrow(v) _mm256_cvtpd_ps(v)
#define atrbvh_v4_lt(a, b) _mm256_cmp_pd((a), (b), _CMP_LT_OQ)
#define atrbvh_v4_eq(a, b) _mm256_cmp_pd((a), (b), _CMP_EQ_OQ)
#define atrbvh_v4_select(a, b, m) atrbvh_select4((a), (b), (m))
#define atrbvh_v4_mor(a, b) _mm256_or_pd((a), (b))
#define atrbvh_v4_mand(a, b) _mm256_and_pd((a), (b))
#define atrbvh_v4_bits(m) ((atrbvh_u32)_mm256_movemask_pd(m))
#define atrbvh_v4_mask(a, b, c, d)                                           \
    _mm256_castsi256_pd(_mm256_set_epi64x(-(long long)(d), -(long long)(c),  \
                                          -(long long)(b), -(long long)(a)))
#define atrbvh_v4_load(p) _mm256_load_pd(p)
#define atrbvh_v4_store(p, v) _mm256_store_pd((p), (v))
#define atrbvh_v4_storeu(p, v) _mm256_storeu_pd((p), (v))
#define ATRBVH_V4_INF __builtin_inf()
/* The end of a four-lane function: the upper halves of the YMM registers
 * cleared for the SSE code that runs next (GCC puts its own VZEROUPPER
 * there only at -O2 and above; tests/test_vecstate.c). */
#define atrbvh_v4_done() _mm256_zeroupper()
typedef __m128i atrbvh_v4u;
#define atrbvh_v4_uload(p) _mm_loadu_si128((const __m128i *)(const void *)(p))
#define atrbvh_v4_ustore(p, v) _mm_storeu_si128((__m128i *)(void *)(p), (v))
#define atrbvh_v4_uadd(a, b) _mm_add_epi32((a), (b))
#define atrbvh_v4_uset(a, b, c, d)                                           \
    _mm_set_epi32((int)(d), (int)(c), (int)(b), (int)(a))
#define atrbvh_v4_ucvt(v) atrbvh_ucvt4(v)
#define atrbvh_v4_le(a, b) _mm256_cmp_pd((a), (b), _CMP_LE_OQ)
/* ATRBVH_V4_BOXES: the six coordinate vectors of four boxes by a
 * transpose of their rows (min x, y, z, max x in one load, max y, z in
 * another), where building each vector from four scalars took 24 loads
 * and 18 inserts. */
ATRBVH_V4_FN void atrbvh_v4_boxes(const atrbvh_box *p0, const atrbvh_box *p1,
                                  const atrbvh_box *p2, const atrbvh_box *p3,
                                  atrbvh_v4f v[6])
{
    __m128 r0 = _mm_loadu_ps(p0->min), r1 = _mm_loadu_ps(p1->min),
           r2 = _mm_loadu_ps(p2->min), r3 = _mm_loadu_ps(p3->min);
    const __m128 zero = _mm_setzero_ps();
    const __m128 s0 = _mm_loadl_pi(zero, (const __m64 *)(const void *)
                                             &p0->max[1]),
                 s1 = _mm_loadl_pi(zero, (const __m64 *)(const void *)
                                             &p1->max[1]),
                 s2 = _mm_loadl_pi(zero, (const __m64 *)(const void *)
                                             &p2->max[1]),
                 s3 = _mm_loadl_pi(zero, (const __m64 *)(const void *)
                                             &p3->max[1]);
    const __m128 u01 = _mm_unpacklo_ps(s0, s1), u23 = _mm_unpacklo_ps(s2, s3);
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    v[0] = r0;
    v[1] = r1;
    v[2] = r2;
    v[3] = r3;
    v[4] = _mm_movelh_ps(u01, u23);
    v[5] = _mm_movehl_ps(u23, u01);
}
#define ATRBVH_V4_BOXES(p0, p1, p2, p3, v)                                     \
    atrbvh_v4_boxes((p0), (p1), (p2), (p3), (v))
/* Four u32 as exact doubles (AVX converts signed ones only): x - 2^31 as
 * a signed integer, converted, plus 2^31, every step exact. */
ATRBVH_V4_FN atrbvh_v4d atrbvh_ucvt4(atrbvh_v4u v)
{
    return _mm256_add_pd(
        _mm256_cvtepi32_pd(_mm_xor_si128(v, _mm_set1_epi32(-2147483647 - 1))),
        _mm256_set1_pd(2147483648.0));
}
#endif

/* atrbvh_box_area of four lanes' boxes, given by coordinate: its double
 * operations in its order, lane for lane. */
ATRBVH_V4_FN atrbvh_v4d atrbvh_area4d(atrbvh_v4d x0, atrbvh_v4d y0,
                                      atrbvh_v4d z0, atrbvh_v4d x1,
                                      atrbvh_v4d y1, atrbvh_v4d z1)
{
    const atrbvh_v4d dx = atrbvh_v4_sub(x1, x0), dy = atrbvh_v4_sub(y1, y0),
                     dz = atrbvh_v4_sub(z1, z0);
    atrbvh_v4d t = atrbvh_v4_mul(dx, dy);
    t = atrbvh_v4_add(t, atrbvh_v4_mul(dy, dz));
    t = atrbvh_v4_add(t, atrbvh_v4_mul(dz, dx));
    return atrbvh_v4_mul(atrbvh_v4_set1(2.0), t);
}

/* The same of boxes given as floats (widened exactly). */
ATRBVH_V4_FN atrbvh_v4d atrbvh_area4(atrbvh_v4f x0, atrbvh_v4f y0,
                                     atrbvh_v4f z0, atrbvh_v4f x1,
                                     atrbvh_v4f y1, atrbvh_v4f z1)
{
    return atrbvh_area4d(atrbvh_v4_widen(x0), atrbvh_v4_widen(y0),
                         atrbvh_v4_widen(z0), atrbvh_v4_widen(x1),
                         atrbvh_v4_widen(y1), atrbvh_v4_widen(z1));
}

/* atrbvh_trbvh_min on the four lanes (its enumeration, two running minima
 * per lane); cost and rest as doubles, lane l of subset P at 4P + l: the
 * masks are kept times four, so each vector is addressed with x86's scale
 * of 8. */
ATRBVH_V4_FN atrbvh_v4d atrbvh_trbvh_min4(ATRBVH_GLOBAL const double *cost,
                                               ATRBVH_GLOBAL const double *rest,
                                               atrbvh_trbvh_mask S,
                                               atrbvh_v4d base)
{
    const atrbvh_trbvh_mask delta = (S - 1u) & S;
    const atrbvh_trbvh_mask lb = delta & (0u - delta);
    const atrbvh_trbvh_mask l4 = lb << 2, d2 = (delta ^ lb) << 2;
    ATRBVH_GLOBAL const double *cost_lb = cost + l4, *rest_lb = rest + l4;
    atrbvh_trbvh_mask E;
    atrbvh_v4d lo0 = atrbvh_v4_add(base, atrbvh_v4_load(cost + l4)),
                  lo1;
    lo0 = atrbvh_v4_add(lo0, atrbvh_v4_load(rest + l4));
    lo1 = lo0;
    for (E = d2 & (0u - d2); E; E = (E - d2) & d2) {
        atrbvh_v4d c = atrbvh_v4_add(base, atrbvh_v4_load(cost + E));
        c = atrbvh_v4_add(c, atrbvh_v4_load(rest + E));
        lo0 = atrbvh_v4_min(lo0, c);
        c = atrbvh_v4_add(base, atrbvh_v4_load(cost_lb + E));
        c = atrbvh_v4_add(c, atrbvh_v4_load(rest_lb + E));
        lo1 = atrbvh_v4_min(lo1, c);
    }
    return atrbvh_v4_min(lo0, lo1);
}


/* atrbvh_trbvh_min4 with its argument: the same value, and in *arg each
 * lane's split as atrbvh_trbvh_best finds it, the first among equal
 * minima in the enumeration order, which is increasing P (each running
 * minimum moves on strict <; at the join the lower value, or on equal
 * values the smaller P).  The splits as doubles (exact), so that the
 * selects are the cost's.  For the subset of all leaves, whose split a
 * kept treelet's extraction would otherwise find again by a scalar scan
 * of 2^(n-1) - 1 partitions. */
ATRBVH_V4_FN atrbvh_v4d atrbvh_trbvh_argmin4(ATRBVH_GLOBAL const double *cost,
                                             ATRBVH_GLOBAL const double *rest,
                                             atrbvh_trbvh_mask S,
                                             atrbvh_v4d base, atrbvh_v4d *arg)
{
    const atrbvh_trbvh_mask delta = (S - 1u) & S;
    const atrbvh_trbvh_mask lb = delta & (0u - delta);
    const atrbvh_trbvh_mask l4 = lb << 2, d2 = (delta ^ lb) << 2;
    ATRBVH_GLOBAL const double *cost_lb = cost + l4, *rest_lb = rest + l4;
    atrbvh_trbvh_mask E;
    atrbvh_v4d lo0 = atrbvh_v4_add(base, atrbvh_v4_load(cost + l4)), lo1,
               p0 = atrbvh_v4_set1((double)lb), p1 = p0;
    atrbvh_v4m m;
    lo0 = atrbvh_v4_add(lo0, atrbvh_v4_load(rest + l4));
    lo1 = lo0;
    for (E = d2 & (0u - d2); E; E = (E - d2) & d2) {
        const double e = (double)(E >> 2);
        atrbvh_v4d c = atrbvh_v4_add(base, atrbvh_v4_load(cost + E));
        c = atrbvh_v4_add(c, atrbvh_v4_load(rest + E));
        m = atrbvh_v4_lt(c, lo0);
        lo0 = atrbvh_v4_select(lo0, c, m);
        p0 = atrbvh_v4_select(p0, atrbvh_v4_set1(e), m);
        c = atrbvh_v4_add(base, atrbvh_v4_load(cost_lb + E));
        c = atrbvh_v4_add(c, atrbvh_v4_load(rest_lb + E));
        m = atrbvh_v4_lt(c, lo1);
        lo1 = atrbvh_v4_select(lo1, c, m);
        p1 = atrbvh_v4_select(p1, atrbvh_v4_set1(e + (double)lb), m);
    }
    m = atrbvh_v4_mor(atrbvh_v4_lt(lo1, lo0),
                      atrbvh_v4_mand(atrbvh_v4_eq(lo1, lo0),
                                     atrbvh_v4_lt(p1, p0)));
    *arg = atrbvh_v4_select(p0, p1, m);
    return atrbvh_v4_min(lo0, lo1);
}

/* atrbvh_trbvh_costs on four lanes, their tables interleaved in quad
 * (above).  Subset S = bit | r (bit = 2^k its highest leaf, 0 < r < bit)
 * is made where the scalar code makes it, then costed at once: its box
 * union(box(r), box of leaf k), rest first (atrbvh_v4_fmin, fmax: a < b ?
 * a : b and a > b ? a : b lane for lane), its area atrbvh_box_area's
 * double operations in their order (atrbvh_area4), N(S) = N(r) + N(leaf
 * k); every subset of S is smaller than S, so already costed.  The six
 * planes are named one by one (with arrays of six, the earlier per-lane
 * subset loop made the CPU's TRBVH(7,3) optimise stage 25% slower). */
ATRBVH_V4_MAIN void
atrbvh_trbvh_costs4(const atrbvh_cost_params *p, atrbvh_u32 n,
                    const atrbvh_treelet_leaves *const lv[4],
                    ATRBVH_GLOBAL double *quad, double found[4],
                    atrbvh_u32 top[4])
{
    const atrbvh_u32 full = (1u << n) - 1u;
    const atrbvh_u32 lim = !p->collapse          ? 0u
                           : p->max_leaf == 0u ? ATRBVH_U32_MAX
                                               : p->max_leaf;
    const atrbvh_trbvh_mask plane = (atrbvh_trbvh_mask)4 << n;
    const atrbvh_v4d ci = atrbvh_v4_set1(p->ci), ct = atrbvh_v4_set1(p->ct),
                     limit = atrbvh_v4_set1((double)lim);
    ATRBVH_GLOBAL double *rev_top =
        quad + 4u * (((atrbvh_trbvh_mask)1 << n) + full);
    ATRBVH_GLOBAL double *area = quad + 2u * plane;
    ATRBVH_GLOBAL float *c0 =
        (ATRBVH_GLOBAL float *)(ATRBVH_GLOBAL void *)(quad + 3u * plane);
    ATRBVH_GLOBAL float *c1 = c0 + plane, *c2 = c1 + plane, *c3 = c2 + plane,
                        *c4 = c3 + plane, *c5 = c4 + plane;
    ATRBVH_GLOBAL atrbvh_u32 *count =
        (ATRBVH_GLOBAL atrbvh_u32 *)(ATRBVH_GLOBAL void *)(quad + 6u * plane);
    atrbvh_v4d arg = atrbvh_v4_set1(0.0);
    double split[4];
    atrbvh_u32 k, l;

    for (k = 0; k < n; k++) {
        const atrbvh_trbvh_mask bit = (atrbvh_trbvh_mask)1 << k;
        const atrbvh_v4d leaf =
            atrbvh_v4_set(lv[0]->cost[k], lv[1]->cost[k], lv[2]->cost[k],
                          lv[3]->cost[k]);
        const atrbvh_box *const b0 = &lv[0]->box[k], *const b1 = &lv[1]->box[k],
                         *const b2 = &lv[2]->box[k], *const b3 = &lv[3]->box[k];
        const atrbvh_v4f
            q0 = atrbvh_v4_fset(b0->min[0], b1->min[0], b2->min[0], b3->min[0]),
            q1 = atrbvh_v4_fset(b0->min[1], b1->min[1], b2->min[1], b3->min[1]),
            q2 = atrbvh_v4_fset(b0->min[2], b1->min[2], b2->min[2], b3->min[2]),
            q3 = atrbvh_v4_fset(b0->max[0], b1->max[0], b2->max[0], b3->max[0]),
            q4 = atrbvh_v4_fset(b0->max[1], b1->max[1], b2->max[1], b3->max[1]),
            q5 = atrbvh_v4_fset(b0->max[2], b1->max[2], b2->max[2], b3->max[2]);
        const atrbvh_v4u qn =
            atrbvh_v4_uset(lv[0]->count[k], lv[1]->count[k], lv[2]->count[k],
                           lv[3]->count[k]);
        atrbvh_trbvh_mask S;
        atrbvh_v4_store(quad + 4u * bit, leaf);
        atrbvh_v4_store(rev_top - 4u * bit, leaf);
        atrbvh_v4_fstore(c0 + 4u * bit, q0);
        atrbvh_v4_fstore(c1 + 4u * bit, q1);
        atrbvh_v4_fstore(c2 + 4u * bit, q2);
        atrbvh_v4_fstore(c3 + 4u * bit, q3);
        atrbvh_v4_fstore(c4 + 4u * bit, q4);
        atrbvh_v4_fstore(c5 + 4u * bit, q5);
        atrbvh_v4_ustore(count + 4u * bit, qn);
        for (S = bit + 1u; S < bit + bit; S++) {
            const atrbvh_trbvh_mask r4 = 4u * (S - bit), s4 = 4u * S;
            const atrbvh_v4f x0 = atrbvh_v4_fmin(atrbvh_v4_fload(c0 + r4), q0),
                             y0 = atrbvh_v4_fmin(atrbvh_v4_fload(c1 + r4), q1),
                             z0 = atrbvh_v4_fmin(atrbvh_v4_fload(c2 + r4), q2),
                             x1 = atrbvh_v4_fmax(atrbvh_v4_fload(c3 + r4), q3),
                             y1 = atrbvh_v4_fmax(atrbvh_v4_fload(c4 + r4), q4),
                             z1 = atrbvh_v4_fmax(atrbvh_v4_fload(c5 + r4), q5);
            const atrbvh_v4d a = atrbvh_area4(x0, y0, z0, x1, y1, z1);
            const atrbvh_v4u m =
                atrbvh_v4_uadd(atrbvh_v4_uload(count + r4), qn);
            const atrbvh_v4d nd = atrbvh_v4_ucvt(m);
            ATRBVH_GLOBAL double *rest = rev_top - s4;
            atrbvh_v4d best, flat;
            if (S != full)
                best = atrbvh_trbvh_min4(quad, rest, S, atrbvh_v4_mul(ci, a));
            else
                best = atrbvh_trbvh_argmin4(quad, rest, S,
                                            atrbvh_v4_mul(ci, a), &arg);
            atrbvh_v4_fstore(c0 + s4, x0);
            atrbvh_v4_fstore(c1 + s4, y0);
            atrbvh_v4_fstore(c2 + s4, z0);
            atrbvh_v4_fstore(c3 + s4, x1);
            atrbvh_v4_fstore(c4 + s4, y1);
            atrbvh_v4_fstore(c5 + s4, z1);
            atrbvh_v4_store(area + s4, a);
            atrbvh_v4_ustore(count + s4, m);
            /* flat < best ? flat : best in the lanes that may collapse
             * (N(S) <= lim, compared as doubles: exact), best in the
             * others; computed for every subset, with no branch (the test
             * whether any lane may collapse was mispredicted at about one
             * subset in three, callgrind) */
            flat = atrbvh_v4_mul(atrbvh_v4_mul(ct, a), nd);
            flat = atrbvh_v4_min(flat, best);
            best = atrbvh_v4_select(best, flat, atrbvh_v4_le(nd, limit));
            atrbvh_v4_store(quad + s4, best);
            atrbvh_v4_store(rest, best); /* rev[full ^ S] */
        }
    }
    atrbvh_v4_storeu(split, arg);
    for (l = 0; l < 4u; l++) {
        found[l] = quad[4u * full + l];
        top[l] = (atrbvh_u32)split[l];
    }
    atrbvh_v4_done();
}
#endif

/* -------------------------------------------------------------- ATRBVH */
/* Index of the distance between clusters in slots a != b in the strictly
 * lower-triangular, row-major matrix: row r > column c at r(r-1)/2 + c.
 * The pairs of slots 0..m-1 are exactly the first m(m-1)/2 entries. */
ATRBVH_FN atrbvh_u32 atrbvh_tri_index(atrbvh_u32 a, atrbvh_u32 b)
{
    return a > b ? a * (a - 1u) / 2u + b : b * (b - 1u) / 2u + a;
}

/* Minimum of row r (columns 0..r-1) and its column, the lowest among
 * equal values (strict <). */
ATRBVH_FN void atrbvh_row_min(ATRBVH_GLOBAL const double *dist, atrbvh_u32 r,
                              double *v, atrbvh_u32 *c)
{
    ATRBVH_GLOBAL const double *row = dist + r * (r - 1u) / 2u;
    atrbvh_u32 k, bc = 0;
    double bv = row[0];
    /* bc moves on strict <; the minimum in place as in
     * atrbvh_agglomerate_at's row search (equal values, equal bits). */
    for (k = 1; k < r; k++) {
        const double d = row[k];
        bc = d < bv ? k : bc;
        bv = bv < d ? bv : d;
    }
    *v = bv;
    *c = bc;
}

/* The worker scratch of ATRBVH, every array of a treelet's agglomeration
 * (and, above ATRBVH_TREELET_MAX leaves, of its formation and write-back)
 * in one place: private arrays of a work-item could hold neither a
 * 128-leaf treelet's 8128 distances nor, in OpenCL C 1.2 (no generic
 * address space), be passed where the scratch is, so the one
 * agglomeration below works in the scratch at every size.  `w` is the row
 * stride of the six coordinate rows of `soa` (padded so that a kernel may
 * read ATRBVH_SOA_PAD - 1 lanes past the last slot). */
#define ATRBVH_SOA_PAD 4
typedef struct atrbvh_agg_scratch {
    ATRBVH_GLOBAL double *dist;      /* n(n-1)/2                          */
    ATRBVH_GLOBAL atrbvh_u32 *leaf;  /* n: the treelet leaves, slot order */
    ATRBVH_GLOBAL atrbvh_box *box;   /* n: the clusters                   */
    ATRBVH_GLOBAL double *cost;
    ATRBVH_GLOBAL atrbvh_u32 *count;
    ATRBVH_GLOBAL atrbvh_u32 *code;
    ATRBVH_GLOBAL double *rmin;      /* n: row minima and their columns   */
    ATRBVH_GLOBAL atrbvh_u32 *rcol;
    ATRBVH_GLOBAL float *soa;        /* 6 rows of w floats                */
    ATRBVH_GLOBAL double *area_of;   /* w                                 */
    ATRBVH_GLOBAL atrbvh_u32 *left;  /* n: the merges (as _topo)          */
    ATRBVH_GLOBAL atrbvh_u32 *right;
    ATRBVH_GLOBAL atrbvh_box *tbox;
    ATRBVH_GLOBAL atrbvh_u32 *tcount;
    ATRBVH_GLOBAL double *tcost;
    ATRBVH_GLOBAL atrbvh_u32 *flat;  /* n: 1 where merge q collapses      */
    /* above ATRBVH_TREELET_MAX leaves only (null up to it): the
     * formation and the write-back */
    ATRBVH_GLOBAL atrbvh_u32 *internal; /* n: [0] root, expansion order   */
    ATRBVH_GLOBAL double *area;      /* n: formation areas                */
    ATRBVH_GLOBAL atrbvh_u32 *order; /* n: the merges in pre-order        */
    ATRBVH_GLOBAL atrbvh_u32 *ids;   /* n: write-back                     */
    ATRBVH_GLOBAL atrbvh_u32 *node_of; /* 2n                              */
    ATRBVH_GLOBAL atrbvh_u32 *stack; /* n: pre-order walk                 */
    atrbvh_u32 w;
} atrbvh_agg_scratch;

ATRBVH_FN atrbvh_u64 atrbvh_agg_align(atrbvh_u64 x)
{
    return (x + 63u) & ~(atrbvh_u64)63u;
}

/* Lays the scratch for treelets of at most n leaves out from `base`
 * (64-byte aligned; may be 0 to only size it) and returns its bytes: the
 * distances first, then the agglomeration's arrays, then, only when n is
 * above ATRBVH_TREELET_MAX, those of the formation and write-back in the
 * scratch (atrbvh_agg_process_large; null otherwise: treelets up to
 * ATRBVH_TREELET_MAX leaves keep them in private arrays).  The host
 * sizes with it, the kernel and the CPU driver carve with it. */
ATRBVH_FN atrbvh_u64 atrbvh_agg_layout(ATRBVH_GLOBAL unsigned char *base,
                                       atrbvh_u32 n, atrbvh_agg_scratch *s)
{
    const atrbvh_u64 n8 = (atrbvh_u64)n, w = n8 + ATRBVH_SOA_PAD;
    const atrbvh_u64 large = n8 > ATRBVH_TREELET_MAX ? n8 : 0u;
    atrbvh_u64 o = atrbvh_agg_align(n8 * (n8 - 1u) / 2u * 8u);
    if (s) {
        s->dist = (ATRBVH_GLOBAL double *)(base);
        s->w = (atrbvh_u32)w;
    }
#define ATRBVH_AGG_PART(field, type, entries)                                 \
    do {                                                                      \
        if (s)                                                                \
            s->field = (entries) > 0u ? (ATRBVH_GLOBAL type *)(base + o)      \
                                 : (ATRBVH_GLOBAL type *)0;                   \
        o += atrbvh_agg_align((entries) * sizeof(type));                      \
    } while (0)
    ATRBVH_AGG_PART(leaf, atrbvh_u32, n8);
    ATRBVH_AGG_PART(box, atrbvh_box, n8);
    ATRBVH_AGG_PART(cost, double, n8);
    ATRBVH_AGG_PART(count, atrbvh_u32, n8);
    ATRBVH_AGG_PART(code, atrbvh_u32, n8);
    ATRBVH_AGG_PART(rmin, double, n8);
    ATRBVH_AGG_PART(rcol, atrbvh_u32, n8);
    ATRBVH_AGG_PART(soa, float, 6u * w);
    ATRBVH_AGG_PART(area_of, double, w);
    ATRBVH_AGG_PART(left, atrbvh_u32, n8);
    ATRBVH_AGG_PART(right, atrbvh_u32, n8);
    ATRBVH_AGG_PART(tbox, atrbvh_box, n8);
    ATRBVH_AGG_PART(tcount, atrbvh_u32, n8);
    ATRBVH_AGG_PART(tcost, double, n8);
    ATRBVH_AGG_PART(flat, atrbvh_u32, n8);
    /* (no entries, a null pointer: up to ATRBVH_TREELET_MAX) */
    ATRBVH_AGG_PART(internal, atrbvh_u32, large);
    ATRBVH_AGG_PART(area, double, large);
    ATRBVH_AGG_PART(order, atrbvh_u32, large);
    ATRBVH_AGG_PART(ids, atrbvh_u32, large);
    ATRBVH_AGG_PART(node_of, atrbvh_u32, 2u * large);
    ATRBVH_AGG_PART(stack, atrbvh_u32, large);
#undef ATRBVH_AGG_PART
    return o;
}

ATRBVH_FN void atrbvh_agg_soa_set(const atrbvh_agg_scratch *s, atrbvh_u32 k,
                                  atrbvh_box b)
{
    ATRBVH_GLOBAL float *c = s->soa;
    atrbvh_u32 w = s->w;
    c[k] = b.min[0];
    c[w + k] = b.min[1];
    c[2u * w + k] = b.min[2];
    c[3u * w + k] = b.max[0];
    c[4u * w + k] = b.max[1];
    c[5u * w + k] = b.max[2];
}

/* out[a] = atrbvh_box_area(atrbvh_box_union(q, box of slot a)) for a in
 * lo .. hi-1, q the first union operand, over the scratch's coordinate
 * rows; out needs ATRBVH_SOA_PAD - 1 entries of room past hi.  On x86
 * CPUs four at a time with SSE2 (the upper pair of the last four skipped
 * when not wanted, so at most one entry past hi is written): MINPS and
 * MAXPS are q < b ? q : b and q > b ? q : b, lane for lane the scalar
 * expressions, and the double arithmetic is the same IEEE operations in
 * the same order, so the bits are the same as the scalar loop's (which
 * OpenCL runs). */
#if !defined(__OPENCL_VERSION__) && defined(__SSE2__)
#include <emmintrin.h>
ATRBVH_FN void atrbvh_agg_union_areas(const atrbvh_agg_scratch *s,
                                      atrbvh_box q, atrbvh_u32 lo,
                                      atrbvh_u32 hi, double *out)
{
    const __m128 q0 = _mm_set1_ps(q.min[0]), q1 = _mm_set1_ps(q.min[1]),
                 q2 = _mm_set1_ps(q.min[2]), q3 = _mm_set1_ps(q.max[0]),
                 q4 = _mm_set1_ps(q.max[1]), q5 = _mm_set1_ps(q.max[2]);
    const __m128d two = _mm_set1_pd(2.0);
    const float *c0 = s->soa, *c1 = c0 + s->w, *c2 = c1 + s->w,
                *c3 = c2 + s->w, *c4 = c3 + s->w, *c5 = c4 + s->w;
    atrbvh_u32 a;
    for (a = lo; a < hi; a += 4u) {
        const __m128 x0 = _mm_min_ps(q0, _mm_loadu_ps(c0 + a));
        const __m128 y0 = _mm_min_ps(q1, _mm_loadu_ps(c1 + a));
        const __m128 z0 = _mm_min_ps(q2, _mm_loadu_ps(c2 + a));
        const __m128 x1 = _mm_max_ps(q3, _mm_loadu_ps(c3 + a));
        const __m128 y1 = _mm_max_ps(q4, _mm_loadu_ps(c4 + a));
        const __m128 z1 = _mm_max_ps(q5, _mm_loadu_ps(c5 + a));
        __m128d dx = _mm_sub_pd(_mm_cvtps_pd(x1), _mm_cvtps_pd(x0));
        __m128d dy = _mm_sub_pd(_mm_cvtps_pd(y1), _mm_cvtps_pd(y0));
        __m128d dz = _mm_sub_pd(_mm_cvtps_pd(z1), _mm_cvtps_pd(z0));
        __m128d t = _mm_mul_pd(dx, dy);
        t = _mm_add_pd(t, _mm_mul_pd(dy, dz));
        t = _mm_add_pd(t, _mm_mul_pd(dz, dx));
        _mm_storeu_pd(out + a, _mm_mul_pd(two, t));
        /* The upper two lanes only when one of them is wanted. */
        if (hi - a <= 2u)
            break;
        dx = _mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(x1, x1)),
                        _mm_cvtps_pd(_mm_movehl_ps(x0, x0)));
        dy = _mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(y1, y1)),
                        _mm_cvtps_pd(_mm_movehl_ps(y0, y0)));
        dz = _mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(z1, z1)),
                        _mm_cvtps_pd(_mm_movehl_ps(z0, z0)));
        t = _mm_mul_pd(dx, dy);
        t = _mm_add_pd(t, _mm_mul_pd(dy, dz));
        t = _mm_add_pd(t, _mm_mul_pd(dz, dx));
        _mm_storeu_pd(out + a + 2, _mm_mul_pd(two, t));
    }
}
#else
ATRBVH_FN void atrbvh_agg_union_areas(const atrbvh_agg_scratch *s,
                                      atrbvh_box q, atrbvh_u32 lo,
                                      atrbvh_u32 hi, ATRBVH_GLOBAL double *out)
{
    ATRBVH_GLOBAL const float *c = s->soa;
    atrbvh_u32 a, w = s->w;
    for (a = lo; a < hi; a++) {
        atrbvh_box b;
        b.min[0] = q.min[0] < c[a] ? q.min[0] : c[a];
        b.min[1] = q.min[1] < c[w + a] ? q.min[1] : c[w + a];
        b.min[2] = q.min[2] < c[2u * w + a] ? q.min[2] : c[2u * w + a];
        b.max[0] = q.max[0] > c[3u * w + a] ? q.max[0] : c[3u * w + a];
        b.max[1] = q.max[1] > c[4u * w + a] ? q.max[1] : c[4u * w + a];
        b.max[2] = q.max[2] > c[5u * w + a] ? q.max[2] : c[5u * w + a];
        out[a] = atrbvh_box_area(b);
    }
}
#endif

/* ATRBVH (Domingues & Pedrini 2015, "Bounding Volume Hierarchy
 * Optimization through Agglomerative Treelet Restructuring", HPG 2015,
 * Algorithm 1): greedy agglomerative clustering of the n treelet leaves
 * s->leaf[0 .. n-1] (their box, cost and count read from the tree), any
 * n from 3 to ATRBVH_ATRBVH_MAX, in the scratch `s`.  The distance of two
 * clusters is the surface area (double) of their union box; distances are
 * cached in a triangular matrix s->dist and updated after each merge, the
 * cache of Gu et al. 2013 ("Efficient BVH Construction via Approximate
 * Agglomerative Clustering", HPG 2013).
 *
 * Slots and ties, precisely: the m live clusters sit in slots 0..m-1,
 * initially slot k = treelet leaf k.  Each step merges the pair (i, j),
 * i > j, whose distance is smallest, the lowest linear index i(i-1)/2 + j
 * among equal minima (strict < in a linear scan).  The merged cluster
 * takes slot j with left child = the cluster of slot j, right child = that
 * of slot i; the cluster of the last slot m-1 moves into slot i (nothing
 * moves when i = m-1).  Merge q (0-based) is local internal node q, with
 * its children's codes in s->left[q], s->right[q] (c < n: leaf c, else
 * merge c - n) and in s->tbox, s->tcount, s->tcost exactly what
 * atrbvh_treelet_evaluate computes for local node q (the same union of
 * the same children, left first); s->flat[q] is 1 where its cost is the
 * collapse term (atrbvh_node_cost's choice).  The last merge, n - 2, is
 * the root.  Returns the root's cost.
 *
 * The minimum search keeps each row's minimum (and its lowest column) and
 * updates them incrementally after a merge, so a step costs O(m) plus a
 * rescan of the few rows whose minimum was in a changed column, instead of
 * an O(m^2) scan; the pair chosen is exactly the lowest-linear-index
 * minimum of the full scan (the test compares with a naive scan). */
ATRBVH_FN double atrbvh_agg_cluster(const atrbvh_treelet_tree *t,
                                    const atrbvh_cost_params *p, atrbvh_u32 n,
                                    const atrbvh_agg_scratch *s)
{
    ATRBVH_GLOBAL double *dist = s->dist;
    ATRBVH_GLOBAL atrbvh_box *box = s->box;
    ATRBVH_GLOBAL double *cost = s->cost;
    ATRBVH_GLOBAL atrbvh_u32 *count = s->count;
    ATRBVH_GLOBAL atrbvh_u32 *code = s->code;
    ATRBVH_GLOBAL double *rmin = s->rmin;
    ATRBVH_GLOBAL atrbvh_u32 *rcol = s->rcol;
    ATRBVH_GLOBAL double *area_of = s->area_of;
    atrbvh_u32 m, a, b, q = 0;
    double root_cost = 0.0;

    for (a = 0; a < n; a++) {
        const atrbvh_u32 node = s->leaf[a];
        box[a] = t->box[node];
        atrbvh_agg_soa_set(s, a, box[a]);
        cost[a] = t->cost[node];
        count[a] = t->count[node];
        code[a] = a;
    }
    /* Lanes read past the end, never used: any finite value.  Every
     * union_areas call below has hi <= n-1, and the SSE2 loop reads
     * lanes in fours from 0, so up to lane (n+2)/4*4 - 1; the scalar
     * loop reads none. */
    for (a = n; a < n + ATRBVH_SOA_PAD; a++)
        atrbvh_agg_soa_set(s, a, box[0]);
    /* The matrix row by row, each row's minimum found on the way (strict
     * <: the lowest column among equals, as atrbvh_row_min). */
    for (a = 1; a < n; a++) {
        ATRBVH_GLOBAL double *row = dist + a * (a - 1u) / 2u;
        double bv;
        atrbvh_u32 bc = 0;
#if !defined(__OPENCL_VERSION__) && defined(__SSE2__)
        /* Straight into the row: the SSE2 loop writes at most one entry
         * past it, the next row's first, which that row then writes; the
         * last row (nothing after it) goes through area_of. */
        if (a + 1u < n) {
            atrbvh_agg_union_areas(s, box[a], 0, a, row);
            bv = row[0];
            for (b = 1; b < a; b++) {
                const double d = row[b];
                bc = d < bv ? b : bc;
                bv = bv < d ? bv : d;
            }
            rmin[a] = bv;
            rcol[a] = bc;
            continue;
        }
#endif
        atrbvh_agg_union_areas(s, box[a], 0, a, area_of);
        bv = area_of[0];
        row[0] = bv;
        for (b = 1; b < a; b++) {
            const double d = area_of[b];
            row[b] = d;
            bc = d < bv ? b : bc;
            bv = bv < d ? bv : d;
        }
        rmin[a] = bv;
        rcol[a] = bc;
    }
    for (m = n; m > 1; m--) {
        atrbvh_u32 i = 1, j, last = m - 1u, r;
        double best = rmin[1];
        atrbvh_box merged;
        ATRBVH_GLOBAL double *jrow;
        int collapsed;
        /* Rows in order, strict <: the lowest row among equal minima, and
         * within it (atrbvh_row_min) the lowest column: the lowest linear
         * index. */
        for (r = 2; r < m; r++) {
            /* i moves on strict <; best = best < v ? best : v is the
             * same minimum (equal row minima have the same bits: areas
             * are +0 or positive, never NaN), computed in place. */
            const double v = rmin[r];
            i = v < best ? r : i;
            best = best < v ? best : v;
        }
        j = rcol[i];
        merged = atrbvh_box_union(box[j], box[i]);
        /* The merged area is the pair's distance (best), already
         * computed: the union may have been taken in the other operand
         * order, which changes a coordinate (MINSS/MAXSS or ?:) only in
         * the sign of a zero, hence the area only in the sign of a zero,
         * which no comparison below or in the callers distinguishes. */
        s->left[q] = code[j];
        s->right[q] = code[i];
        root_cost = atrbvh_node_cost(p, best, count[j] + count[i], cost[j],
                                     cost[i], &collapsed);
        s->flat[q] = (atrbvh_u32)collapsed;
        box[j] = merged;
        atrbvh_agg_soa_set(s, j, merged);
        cost[j] = root_cost;
        count[j] += count[i];
        code[j] = n + q;
        s->tbox[q] = merged;
        s->tcount[q] = count[j];
        s->tcost[q] = root_cost;
        q++;
        if (last == 1u)
            break;
        /* (a) the last cluster moves into slot i: row i (columns < i) and
         * column i (rows i+1 .. last-1) take row `last`'s entries. */
        if (i != last) {
            ATRBVH_GLOBAL double *irow = dist + i * (i - 1u) / 2u;
            ATRBVH_GLOBAL double *lrow = dist + last * (last - 1u) / 2u;
            box[i] = box[last];
            atrbvh_agg_soa_set(s, i, box[i]);
            cost[i] = cost[last];
            count[i] = count[last];
            code[i] = code[last];
            for (a = 0; a < i; a++)
                irow[a] = lrow[a];
            /* Column i: entry (a, i) at a(a-1)/2 + i, a step of a from
             * row a to row a + 1. */
            irow += i + i;
            for (a = i + 1u; a < last; a++) {
                *irow = lrow[a];
                irow += a;
            }
        }
        /* (b) distances to the merged cluster in slot j (after (a), so
         * the (i, j) entry gets the new value): row j here, column j
         * (rows r > j) in the loop below, each row's entry written before
         * that row's minimum is looked at.
         * (c) Row minima of the rows 1..last-1 that remain.  Rows i and j
         * changed entirely; a row r > j changed in column j, and a row
         * r > i in column i: rescan it if its minimum sat in a changed
         * column (the value may have grown), else a changed entry can only
         * take over the minimum (lower column first among equals).  Rows
         * below j hold neither column. */
        atrbvh_agg_union_areas(s, merged, 0, last, area_of);
        jrow = dist + j * (j - 1u) / 2u;
        /* Row j is area_of[0 .. j-1] and changes no more in this merge:
         * its minimum (atrbvh_row_min's, strict <) on the way (a plain
         * copy would become a library memcpy call). */
        if (j > 0u) {
            double bv = area_of[0];
            atrbvh_u32 bc = 0;
            jrow[0] = bv;
            for (a = 1; a < j; a++) {
                const double d = area_of[a];
                jrow[a] = d;
                bc = d < bv ? a : bc;
                bv = bv < d ? bv : d;
            }
            rmin[j] = bv;
            rcol[j] = bc;
        }
        /* Row r starts r - 1 entries after row r - 1. */
        jrow += j;
        for (r = j + 1u; r < last; r++) {
            ATRBVH_GLOBAL double *row = jrow;
            double v = area_of[r];
            jrow += r;
            row[j] = v;
            if (r == i || rcol[r] == j || (r > i && rcol[r] == i)) {
                double rv;
                atrbvh_u32 rc;
                atrbvh_row_min(dist, r, &rv, &rc);
                rmin[r] = rv;
                rcol[r] = rc;
            } else {
                if (v < rmin[r] || (v == rmin[r] && j < rcol[r])) {
                    rmin[r] = v;
                    rcol[r] = j;
                }
                if (r > i) {
                    v = row[i];
                    if (v < rmin[r] || (v == rmin[r] && i < rcol[r])) {
                        rmin[r] = v;
                        rcol[r] = i;
                    }
                }
            }
        }
    }
    return root_cost;
}

/* The agglomeration of a treelet of up to ATRBVH_TREELET_MAX leaves
 * formed into *tl (at least 3): atrbvh_agg_cluster in the scratch `s`,
 * its merges copied into *topo (boxes, counts, costs, the collapse bits in
 * topo->flat; root n - 2), where atrbvh_treelet_write and the lanes'
 * atrbvh_agglomerate4 keep theirs.  Returns the root merge's cost. */
ATRBVH_FN double atrbvh_agglomerate_at(const atrbvh_cost_params *p,
                                       const atrbvh_treelet_tree *t,
                                       const atrbvh_treelet *tl,
                                       const atrbvh_agg_scratch *s,
                                       atrbvh_treelet_topo *topo)
{
    const atrbvh_u32 n = tl->n;
    atrbvh_u32 a, q;
    double found;
    for (a = 0; a < n; a++)
        s->leaf[a] = tl->leaf[a];
    found = atrbvh_agg_cluster(t, p, n, s);
    topo->flat = 0;
    for (q = 0; q + 1u < n; q++) {
        topo->left[q] = s->left[q];
        topo->right[q] = s->right[q];
        topo->box[q] = s->tbox[q];
        topo->count[q] = s->tcount[q];
        topo->cost[q] = s->tcost[q];
        topo->flat |= s->flat[q] << q;
    }
    topo->root = n - 2u;
    return found;
}

#ifdef ATRBVH_LANES4
/* ------------------------------------------------------ ATRBVH in lanes */
/* The agglomerations of four formed treelets of n leaves each side by
 * side in the lanes of a vector (on the CPU AVX's, x86, chosen at run
 * time: optimise.c's lane_batch; in OpenCL C double4 and float4, the
 * opt_round4 kernel on a CPU device); lane l is treelet tl[l], read in place as
 * atrbvh_agglomerate_at reads it (a lane left over may repeat another
 * lane's treelet into a spare topology).  Each lane's result is exactly
 * atrbvh_agglomerate_at's for its treelet: the same merges in the same
 * order, the same boxes, counts and costs in topo[l] (all but the
 * pre-order), the root merge's cost in found[l].
 *
 * The search is the one the scalar function's row minima stand for, done
 * in full: the pair of slots (i, j), i > j, of smallest distance, the
 * first in linear order (row i, then column j) among equal minima, with
 * strict < in that order.  Distances are union areas, never NaN and never
 * -0 (a sum of three products of non-negative widths is -0 only when
 * each product is, and three widths cannot pairwise differ in sign), so
 * equal minima have equal bits and the minimum is the scalar one's value.
 * After the merge (slot j's cluster left, slot i's right, the result in
 * slot j, the last slot's cluster into slot i) every live entry of the
 * matrix is rewritten with masks, lane for lane: row and column j take
 * the distances to the merged cluster, row and column i those of the last
 * slot, the others stay; the same pass finds the next minimum.  Nothing
 * branches on a value and every loop's trip count depends on the step
 * only, the same in every treelet.
 *
 * The arithmetic is the scalar one's: the clusters' boxes are kept
 * widened to doubles (exact), and the unions are VMINPD and VMAXPD
 * (OpenCL: the same selects, atrbvh_v4_min) with the scalar's first
 * operand (the row's cluster when the matrix is
 * filled, the merged cluster after a merge, slot j's in the merge: x < y
 * ? x : y lane for lane), the widened unions of floats bit for bit
 * (atrbvh_union_area4); the areas atrbvh_box_area's double operations
 * in its order, the merge's cost atrbvh_node_cost's (VMINPD of flat and
 * binary is `flat < binary ? flat : binary`, blended in where the count
 * may collapse); the merged boxes narrowed back (exact) for the
 * topologies.  Kept in floats, the boxes took six conversions per union
 * (dabrovic_sponza's ATRBVH(9,2) at two threads: builds 0.975-0.989 of
 * that, docs/bench/abpair.c).
 *
 * Scratch: dist4, 32-byte aligned, atrbvh_agglomerate4_doubles(n)
 * doubles: the four triangular matrices interleaved, entry k of lane l at
 * 4k + l.  n is 3 .. ATRBVH_TREELET_MAX.  Written once for both, over
 * the vector words of atrbvh_trbvh_costs4 (ATRBVH_LANES4). */
#define ATRBVH_AGG_QUADS 1
ATRBVH_FN atrbvh_u64 atrbvh_agglomerate4_doubles(atrbvh_u32 n)
{
    return 4u * ((atrbvh_u64)n * (n - 1u) / 2u);
}

/* The union areas of the four lanes' boxes q (the first operand) and b,
 * both widened: VMINPD and VMAXPD of widened floats are the widened
 * VMINPS and VMAXPS (the conversion is exact and keeps the order and
 * the sign of zero, and both keep the second operand on equal values),
 * so the areas are atrbvh_area4's of the float unions. */
ATRBVH_V4_FN atrbvh_v4d atrbvh_union_area4(atrbvh_v4d q0, atrbvh_v4d q1,
                                           atrbvh_v4d q2, atrbvh_v4d q3,
                                           atrbvh_v4d q4, atrbvh_v4d q5,
                                           double b[6][4])
{
    return atrbvh_area4d(atrbvh_v4_min(q0, atrbvh_v4_load(b[0])),
                         atrbvh_v4_min(q1, atrbvh_v4_load(b[1])),
                         atrbvh_v4_min(q2, atrbvh_v4_load(b[2])),
                         atrbvh_v4_max(q3, atrbvh_v4_load(b[3])),
                         atrbvh_v4_max(q4, atrbvh_v4_load(b[4])),
                         atrbvh_v4_max(q5, atrbvh_v4_load(b[5])));
}
/* (six vectors, not an array: GCC 12 copied an array of them through
 * the stack in halves, and each reload waited for both stores) */
#define ATRBVH_UNION_AREA4(q, b)                                               \
    atrbvh_union_area4((q)[0], (q)[1], (q)[2], (q)[3], (q)[4], (q)[5], (b))

/* One live entry of the search: v at pair code `at` (64 i + j) taken
 * where strictly lower than the lanes' minimum so far. */
#define ATRBVH_AGG4_SEEK(v, code, best, at)                                    \
    do {                                                                       \
        (at) = atrbvh_v4_select((at), (code), atrbvh_v4_lt((v), (best)));  \
        (best) = atrbvh_v4_min((best), (v));                                 \
    } while (0)

ATRBVH_V4_MAIN void
atrbvh_agglomerate4(const atrbvh_cost_params *p, atrbvh_u32 n,
                    const atrbvh_treelet_tree *t,
                    const atrbvh_treelet *const tl[4],
                    ATRBVH_GLOBAL double *dist4,
                    atrbvh_treelet_topo *const topo[4], double found[4])
{
    /* per slot: the four lanes' cluster boxes (six coordinates of four
     * lanes, widened to doubles: no conversion per union), costs, counts
     * and codes; the merged boxes (and as floats, for the topologies) */
    ATRBVH_V4_ALIGNED(32) double box[ATRBVH_TREELET_MAX][6][4];
    ATRBVH_V4_ALIGNED(32) double area_of[ATRBVH_TREELET_MAX][4];
    ATRBVH_V4_ALIGNED(32) double pick[4], cost_of[4];
    ATRBVH_V4_ALIGNED(32) double merged[6][4];
    ATRBVH_V4_ALIGNED(16) float mergedf[6][4];
    double cost[ATRBVH_TREELET_MAX][4];
    atrbvh_u32 count[ATRBVH_TREELET_MAX][4], code[ATRBVH_TREELET_MAX][4];
    atrbvh_u32 base[ATRBVH_TREELET_MAX], cnt[4];
    atrbvh_v4m is_i[ATRBVH_TREELET_MAX], is_j[ATRBVH_TREELET_MAX];
    const atrbvh_u32 lim = !p->collapse          ? 0u
                           : p->max_leaf == 0u ? ATRBVH_U32_MAX
                                               : p->max_leaf;
    const atrbvh_v4d one = atrbvh_v4_set1(1.0),
                        inf = atrbvh_v4_set1(ATRBVH_V4_INF);
    atrbvh_v4d best = inf, at = atrbvh_v4_set1(0.0);
    atrbvh_u32 a, r, c, l, m, q;

    for (a = 0; a < n; a++) {
        const atrbvh_u32 n0 = tl[0]->leaf[a], n1 = tl[1]->leaf[a],
                         n2 = tl[2]->leaf[a], n3 = tl[3]->leaf[a];
        atrbvh_v4f q4[6];
        ATRBVH_V4_BOXES(&t->box[n0], &t->box[n1], &t->box[n2], &t->box[n3],
                        q4);
        for (c = 0; c < 6u; c++)
            atrbvh_v4_store(box[a][c], atrbvh_v4_widen(q4[c]));
        cost[a][0] = t->cost[n0];
        cost[a][1] = t->cost[n1];
        cost[a][2] = t->cost[n2];
        cost[a][3] = t->cost[n3];
        count[a][0] = t->count[n0];
        count[a][1] = t->count[n1];
        count[a][2] = t->count[n2];
        count[a][3] = t->count[n3];
        for (l = 0; l < 4u; l++)
            code[a][l] = a;
        base[a] = a * (a - 1u) / 2u;
    }
    for (l = 0; l < 4u; l++)
        topo[l]->flat = 0;
    /* the matrix row by row (the row's cluster first, as
     * atrbvh_agglomerate_at fills it), searched on the way */
    for (r = 1; r < n; r++) {
        atrbvh_v4d k = atrbvh_v4_set1((double)(64u * r));
        const atrbvh_v4d r0 = atrbvh_v4_load(box[r][0]),
                         r1 = atrbvh_v4_load(box[r][1]),
                         r2 = atrbvh_v4_load(box[r][2]),
                         r3 = atrbvh_v4_load(box[r][3]),
                         r4 = atrbvh_v4_load(box[r][4]),
                         r5 = atrbvh_v4_load(box[r][5]);
        for (c = 0; c < r; c++, k = atrbvh_v4_add(k, one)) {
            const atrbvh_v4d v =
                atrbvh_union_area4(r0, r1, r2, r3, r4, r5, box[c]);
            atrbvh_v4_store(dist4 + 4u * (base[r] + c), v);
            ATRBVH_AGG4_SEEK(v, k, best, at);
        }
    }
    for (m = n, q = 0;; m--, q++) {
        const atrbvh_u32 last = m - 1u;
        atrbvh_u32 I[4], J[4], fbits;
        atrbvh_v4d iv, jv, binary, flat, res, far;
        atrbvh_v4m take;
        atrbvh_v4d mb[6];
        /* each lane's pair: slot j's cluster (left) and slot i's */
        atrbvh_v4_store(pick, at);
        for (l = 0; l < 4u; l++) {
            const atrbvh_u32 k = (atrbvh_u32)pick[l];
            I[l] = k >> 6;
            J[l] = k & 63u;
        }
        iv = atrbvh_v4_set((double)I[0], (double)I[1], (double)I[2],
                             (double)I[3]);
        jv = atrbvh_v4_set((double)J[0], (double)J[1], (double)J[2],
                             (double)J[3]);
        for (c = 0; c < 6u; c++) {
            const atrbvh_v4d x =
                atrbvh_v4_set(box[J[0]][c][0], box[J[1]][c][1],
                              box[J[2]][c][2], box[J[3]][c][3]);
            const atrbvh_v4d y =
                atrbvh_v4_set(box[I[0]][c][0], box[I[1]][c][1],
                              box[I[2]][c][2], box[I[3]][c][3]);
            mb[c] = c < 3u ? atrbvh_v4_min(x, y) : atrbvh_v4_max(x, y);
            atrbvh_v4_store(merged[c], mb[c]);
            atrbvh_v4_fstore(mergedf[c], atrbvh_v4_narrow(mb[c]));
        }
        /* the merges' costs, atrbvh_node_cost lane for lane: the pair's
         * distance (best) is the merged area */
        for (l = 0; l < 4u; l++)
            cnt[l] = count[J[l]][l] + count[I[l]][l];
        binary = atrbvh_v4_mul(atrbvh_v4_set1(p->ci), best);
        binary = atrbvh_v4_add(
            binary, atrbvh_v4_set(cost[J[0]][0], cost[J[1]][1],
                                    cost[J[2]][2], cost[J[3]][3]));
        binary = atrbvh_v4_add(
            binary, atrbvh_v4_set(cost[I[0]][0], cost[I[1]][1],
                                    cost[I[2]][2], cost[I[3]][3]));
        flat = atrbvh_v4_mul(atrbvh_v4_set1(p->ct), best);
        flat = atrbvh_v4_mul(flat,
                               atrbvh_v4_set((double)cnt[0], (double)cnt[1],
                                               (double)cnt[2], (double)cnt[3]));
        take = atrbvh_v4_mask(cnt[0] <= lim, cnt[1] <= lim, cnt[2] <= lim,
                                cnt[3] <= lim);
        res = atrbvh_v4_select(binary, atrbvh_v4_min(flat, binary), take);
        atrbvh_v4_store(cost_of, res);
        /* lane l's bit: collapsed, atrbvh_node_cost's choice (take, and
         * VMINPD's flat < binary) */
        fbits = atrbvh_v4_bits(
            atrbvh_v4_mand(take, atrbvh_v4_lt(flat, binary)));
        /* each lane's merge into its topology, then its slots' costs,
         * counts and codes: slot j takes the merge, slot i the last
         * cluster (onto itself when i is the last slot) */
        for (l = 0; l < 4u; l++) {
            atrbvh_treelet_topo *to = topo[l];
            const atrbvh_u32 i = I[l], j = J[l];
            const float x0 = mergedf[0][l], y0 = mergedf[1][l],
                        z0 = mergedf[2][l], x1 = mergedf[3][l],
                        y1 = mergedf[4][l], z1 = mergedf[5][l];
            to->left[q] = code[j][l];
            to->right[q] = code[i][l];
            to->count[q] = cnt[l];
            to->cost[q] = cost_of[l];
            to->flat |= ((fbits >> l) & 1u) << q;
            to->box[q].min[0] = x0;
            to->box[q].min[1] = y0;
            to->box[q].min[2] = z0;
            to->box[q].max[0] = x1;
            to->box[q].max[1] = y1;
            to->box[q].max[2] = z1;
            cost[j][l] = cost_of[l];
            count[j][l] = cnt[l];
            code[j][l] = n + q;
            cost[i][l] = cost[last][l];
            count[i][l] = count[last][l];
            code[i][l] = code[last][l];
        }
        if (last == 1u) {
            atrbvh_v4_storeu(found, res);
            break;
        }
        /* the distances to the merged clusters (the merged box first, as
         * atrbvh_agg_cluster's atrbvh_agg_union_areas), slot i's being
         * the last cluster's in its lanes, and each slot's masks: whether
         * it is the lane's slot i, slot j */
        far = ATRBVH_UNION_AREA4(mb, box[last]);
        for (a = 0; a < last; a++) {
            const atrbvh_v4d av = atrbvh_v4_set1((double)a);
            is_i[a] = atrbvh_v4_eq(av, iv);
            is_j[a] = atrbvh_v4_eq(av, jv);
            atrbvh_v4_store(area_of[a],
                            atrbvh_v4_select(ATRBVH_UNION_AREA4(mb, box[a]),
                                             far, is_i[a]));
        }
        /* the live entries of the next step rewritten, lane for lane:
         * (r, c) takes (last, c) in row i and (last, r) in column i,
         * then the distance to the merge in row and column j (the (i, j)
         * entry that of slot i's new cluster), and the search for the
         * next pair on the way */
        best = inf;
        at = atrbvh_v4_set1(0.0);
        for (r = 1; r < last; r++) {
            const atrbvh_v4m ri = is_i[r], rj = is_j[r];
            const atrbvh_v4d lr =
                atrbvh_v4_load(dist4 + 4u * (base[last] + r));
            const atrbvh_v4d ar = atrbvh_v4_load(area_of[r]);
            ATRBVH_GLOBAL double *at_r = dist4 + 4u * base[r];
            ATRBVH_GLOBAL const double *lrow = dist4 + 4u * base[last];
            atrbvh_v4d k = atrbvh_v4_set1((double)(64u * r));
            for (c = 0; c < r; c++, k = atrbvh_v4_add(k, one)) {
                atrbvh_v4d v = atrbvh_v4_load(at_r + 4u * c);
                v = atrbvh_v4_select(v, atrbvh_v4_load(lrow + 4u * c), ri);
                v = atrbvh_v4_select(v, lr, is_i[c]);
                v = atrbvh_v4_select(v, atrbvh_v4_load(area_of[c]), rj);
                v = atrbvh_v4_select(v, ar, is_j[c]);
                atrbvh_v4_store(at_r + 4u * c, v);
                ATRBVH_AGG4_SEEK(v, k, best, at);
            }
        }
        /* the boxes: the merge into slot j, the last cluster into slot i
         * (j is neither; i may be the last slot) */
        for (l = 0; l < 4u; l++) {
            double *bj = &box[J[l]][0][l], *bi = &box[I[l]][0][l];
            const double *bl = &box[last][0][l];
            bj[0] = merged[0][l];
            bj[4] = merged[1][l];
            bj[8] = merged[2][l];
            bj[12] = merged[3][l];
            bj[16] = merged[4][l];
            bj[20] = merged[5][l];
            bi[0] = bl[0];
            bi[4] = bl[4];
            bi[8] = bl[8];
            bi[12] = bl[12];
            bi[16] = bl[16];
            bi[20] = bl[20];
        }
    }
    for (l = 0; l < 4u; l++)
        topo[l]->root = n - 2u;
    atrbvh_v4_done();
}
#undef ATRBVH_AGG4_SEEK
#endif

/* ------------------------------------------------------ evaluate, write */
/* Fills topo->order: the local nodes in pre-order from the root, left
 * subtree first (atrbvh_topo_preorder). */
ATRBVH_TREELET_INLINE void atrbvh_treelet_preorder(atrbvh_u32 n,
                                                   atrbvh_treelet_topo *topo)
{
    atrbvh_u32 stack[ATRBVH_TREELET_MAX];
    atrbvh_topo_preorder_p(n, topo->root, topo->left, topo->right, topo->order,
                           stack);
}

/* Fills topo->order (pre-order from the root, explicit stack) and, bottom
 * up, the box, count and cost of every local node.  Returns the root's
 * cost: exactly what a refit of the written-back treelet computes. */
ATRBVH_FN double atrbvh_treelet_evaluate(const atrbvh_cost_params *p,
                                         atrbvh_u32 n,
                                         const atrbvh_treelet_leaves *lv,
                                         atrbvh_treelet_topo *topo)
{
    atrbvh_u32 k;
    atrbvh_treelet_preorder(n, topo);
    topo->flat = 0;
    for (k = n - 1u; k-- > 0u;) {
        atrbvh_u32 node = topo->order[k];
        atrbvh_u32 l = topo->left[node], r = topo->right[node];
        atrbvh_box bl = l < n ? lv->box[l] : topo->box[l - n];
        atrbvh_box br = r < n ? lv->box[r] : topo->box[r - n];
        atrbvh_u32 nl = l < n ? lv->count[l] : topo->count[l - n];
        atrbvh_u32 nr = r < n ? lv->count[r] : topo->count[r - n];
        double cl = l < n ? lv->cost[l] : topo->cost[l - n];
        double cr = r < n ? lv->cost[r] : topo->cost[r - n];
        int collapsed;
        atrbvh_box b = atrbvh_box_union(bl, br);
        topo->box[node] = b;
        topo->count[node] = nl + nr;
        topo->cost[node] = atrbvh_node_cost(p, atrbvh_box_area(b), nl + nr,
                                             cl, cr, &collapsed);
        topo->flat |= (atrbvh_u32)collapsed << node;
    }
    return topo->cost[topo->root];
}

/* Writes an evaluated topology back into the tree (atrbvh_topo_write:
 * the root keeps its id, the other ids go in ascending order to the
 * local nodes in pre-order). */
ATRBVH_TREELET_INLINE void
atrbvh_treelet_write(const atrbvh_treelet_tree *t, const atrbvh_treelet *tl,
                     const atrbvh_treelet_topo *topo)
{
    atrbvh_u32 ids[ATRBVH_TREELET_MAX - 1];
    atrbvh_u32 node_of[2u * ATRBVH_TREELET_MAX - 1u];
    atrbvh_topo_write_p(t, tl->n, tl->leaf, tl->internal, topo->order,
                        topo->left, topo->right, topo->box, topo->count,
                        topo->cost, &topo->flat, ids, node_of);
}

/* Refreshes an internal node's cost from its children (box and count do
 * not change when only the subtrees below were restructured). */
ATRBVH_FN void atrbvh_treelet_refresh(const atrbvh_treelet_tree *t,
                                      const atrbvh_cost_params *p,
                                      atrbvh_u32 node)
{
    const atrbvh_u32 l = t->left[node], r = t->right[node];
    int collapsed;
    t->cost[node] =
        atrbvh_node_cost(p, atrbvh_box_area(t->box[node]), t->count[node],
                         t->cost[l], t->cost[r], &collapsed);
    if (t->flat)
        t->flat[node] = (unsigned char)collapsed;
}

/* ------------------------------------------------------------ one treelet */
/* The start of every treelet: refreshes the root's cost from its
 * children and forms the treelet into *tl; returns its leaves (below 3:
 * nothing to restructure). */
ATRBVH_FN atrbvh_u32 atrbvh_treelet_begin(const atrbvh_treelet_tree *t,
                                          const atrbvh_cost_params *p,
                                          atrbvh_u32 root, atrbvh_u32 n,
                                          atrbvh_treelet *tl)
{
    atrbvh_treelet_refresh(t, p, root);
    tl->n = 0;
    return atrbvh_treelet_form(t, root, n, tl);
}

/* The end of a TRBVH treelet once the DP has filled the tables *tab for
 * the gathered leaves *lv and found C(all leaves):
 * the optimal topology is extracted, evaluated and written back when it
 * is strictly cheaper than the root's cost.  Returns 1 when written back.
 * A quick reject first: the DP's optimum is what evaluate recomputes (the
 * same sums in the same order), so nothing strictly cheaper exists when
 * `found` is not. */
ATRBVH_FN int atrbvh_trbvh_keep_from(const atrbvh_treelet_tree *t,
                                     const atrbvh_cost_params *p,
                                     atrbvh_u32 root,
                                     const atrbvh_treelet *tl,
                                     const atrbvh_treelet_leaves *lv,
                                     const atrbvh_trbvh_tables *tab,
                                     double found)
{
    atrbvh_treelet_topo topo;
    double cost;
    if (!(found < t->cost[root]))
        return 0;
    atrbvh_trbvh_extract_from(p, tl->n, tab, &topo);
    cost = atrbvh_treelet_evaluate(p, tl->n, lv, &topo);
    if (!(cost < t->cost[root]))
        return 0;
    atrbvh_treelet_write(t, tl, &topo);
    return 1;
}

/* The same with the tables atrbvh_trbvh_costs left in s. */
ATRBVH_FN int atrbvh_trbvh_keep(const atrbvh_treelet_tree *t,
                                const atrbvh_cost_params *p, atrbvh_u32 root,
                                const atrbvh_treelet *tl,
                                const atrbvh_treelet_leaves *lv,
                                atrbvh_trbvh_scratch s, double found)
{
    const atrbvh_trbvh_tables tab = atrbvh_trbvh_tables_of(tl->n, s);
    return atrbvh_trbvh_keep_from(t, p, root, tl, lv, &tab, found);
}

/* The end of an ATRBVH treelet whose agglomeration left its merges in
 * *topo and the root merge's cost in `found`: written back when strictly
 * cheaper than the root's cost (a quick reject as in atrbvh_trbvh_keep:
 * the merges hold evaluate's boxes, counts and costs, the root's is
 * `found`).  Returns 1 when written back. */
ATRBVH_FN int atrbvh_atrbvh_apply(const atrbvh_treelet_tree *t,
                                  atrbvh_u32 root, const atrbvh_treelet *tl,
                                  atrbvh_treelet_topo *topo, double found)
{
    if (!(found < t->cost[root]))
        return 0;
    /* only the pre-order is missing */
    atrbvh_treelet_preorder(tl->n, topo);
    atrbvh_treelet_write(t, tl, topo);
    return 1;
}

/* The end of an ATRBVH treelet of up to ATRBVH_TREELET_MAX leaves, formed
 * into *tl (at least 3 leaves): the agglomerative clustering of its
 * leaves, read from the tree in place (no gather), in the scratch `agg`,
 * then atrbvh_atrbvh_apply.  Returns 1 when written back. */
ATRBVH_FN int atrbvh_atrbvh_keep(const atrbvh_treelet_tree *t,
                                 const atrbvh_cost_params *p, atrbvh_u32 root,
                                 const atrbvh_treelet *tl,
                                 const atrbvh_agg_scratch *agg)
{
    atrbvh_treelet_topo topo;
    const double found = atrbvh_agglomerate_at(p, t, tl, agg, &topo);
    return atrbvh_atrbvh_apply(t, root, tl, &topo, found);
}

#ifdef ATRBVH_AGG_QUADS
/* The agglomerations of `ready` (1 to 4) formed ATRBVH treelets whose
 * subtrees are disjoint (roots root[l], formed into tl[l], each root
 * refreshed): those with as many leaves as the first (at least 3) side by
 * side in atrbvh_agglomerate4's lanes when two or more do (the lanes left
 * over repeat the first, into a spare topology), any other one by one as
 * atrbvh_atrbvh_keep does it; then each one's write-back when cheaper
 * (applied[l] 1).  No treelet reads what another writes back.  The CPU's
 * walk_lanes (lib/cpu/optimise.c, with AVX) and the opt_round4 kernel
 * call this; agg is one treelet's scratch, dist4 the four lanes'
 * matrices. */
ATRBVH_FN void atrbvh_agglomerate_side(const atrbvh_treelet_tree *t,
                                       const atrbvh_cost_params *p,
                                       atrbvh_u32 ready,
                                       const atrbvh_u32 *root,
                                       const atrbvh_treelet *tl,
                                       const atrbvh_agg_scratch *agg,
                                       ATRBVH_GLOBAL double *dist4,
                                       int *applied)
{
    const atrbvh_treelet *in[4];
    atrbvh_treelet_topo topo[4], spare;
    atrbvh_treelet_topo *out[4];
    double found[4];
    atrbvh_u32 l, lane[4], used = 0;
    const atrbvh_u32 n = tl[0].n;
    for (l = 0; l < ready; l++)
        lane[l] = n >= 3u && tl[l].n == n ? used++ : 4u;
    if (used > 1u) {
        for (l = 0; l < 4u; l++) {
            in[l] = &tl[0];
            out[l] = &spare;
        }
        for (l = 0; l < ready; l++)
            if (lane[l] < 4u) {
                in[lane[l]] = &tl[l];
                out[lane[l]] = &topo[l];
            }
        atrbvh_agglomerate4(p, n, t, in, dist4, out, found);
    }
    for (l = 0; l < ready; l++) {
        applied[l] = 0;
        if (used > 1u && lane[l] < 4u)
            applied[l] = atrbvh_atrbvh_apply(t, root[l], &tl[l], &topo[l],
                                             found[lane[l]]);
        else if (tl[l].n >= 3u)
            applied[l] = atrbvh_atrbvh_keep(t, p, root[l], &tl[l], agg);
    }
}
#endif

/* Restructures the treelet rooted at internal node `root` (whose subtree
 * must be final): refreshes the root's cost from its children, forms the
 * treelet, builds a topology (TRBVH subset DP, or ATRBVH agglomerative
 * clustering when `agglomerative`), and writes it back when it is
 * strictly cheaper.  Returns 1 when written back.  The CPU driver
 * (optimise.c) and the OpenCL kernel (cl/kernels.cl) both call this; only
 * the scratch (`s` for TRBVH, `agg` for ATRBVH) and the walk differ.
 * The formed treelet is left in *tl (its internal ids are the ones a
 * write-back reuses). */
/* The rest of a treelet once it is formed into *tl (its root refreshed):
 * the topology and the write-back when strictly cheaper (1), or nothing
 * (0, and always for fewer than 3 leaves).  The OpenCL kernel that forms
 * several treelets side by side (opt_round4) ends each with this. */
ATRBVH_FN int atrbvh_treelet_finish(const atrbvh_treelet_tree *t,
                                    const atrbvh_cost_params *p,
                                    atrbvh_u32 root, int agglomerative,
                                    atrbvh_trbvh_scratch s,
                                    const atrbvh_agg_scratch *agg,
                                    const atrbvh_treelet *tl)
{
    atrbvh_treelet_leaves lv;
    double found;
    if (tl->n < 3u)
        return 0;
    if (!agglomerative) {
        atrbvh_treelet_gather(t, tl, &lv);
        found = atrbvh_trbvh_costs(p, tl->n, &lv, s);
        return atrbvh_trbvh_keep(t, p, root, tl, &lv, s, found);
    }
    return atrbvh_atrbvh_keep(t, p, root, tl, agg);
}

/* The TRBVH DP of `ready` (1 to 4) formed treelets whose subtrees are
 * disjoint (roots root[l], formed into tl[l], each root refreshed), then
 * each one's write-back when cheaper (applied[l] 1): with the four-lane
 * code (ATRBVH_LANES4) and two or more of them of n leaves, those side by
 * side in atrbvh_trbvh_costs4's lanes (the first repeated in the lanes
 * left over, their results unused; the tables read in place,
 * atrbvh_trbvh_tables_lane), any other one by one by the scalar DP (one
 * of fewer than n leaves is not a crown node's, which holds at least n
 * primitives: kept for safety).  s: the four lanes' splits (the scalar
 * DP takes s[0]'s whole tables); quad: ATRBVH_TRBVH_QUAD_DOUBLES * 2^n
 * doubles; lv: four leaves' records.  The CPU's walk_lanes
 * (lib/cpu/optimise.c, with AVX) and the opt_round4 kernel call this. */
ATRBVH_FN void atrbvh_trbvh_ready(const atrbvh_treelet_tree *t,
                                  const atrbvh_cost_params *p, atrbvh_u32 n,
                                  atrbvh_u32 ready, const atrbvh_u32 *root,
                                  const atrbvh_treelet *tl,
                                  atrbvh_treelet_leaves *lv,
                                  const atrbvh_trbvh_scratch *s,
                                  ATRBVH_GLOBAL double *quad, int *applied)
{
    atrbvh_u32 l, full = 0, sel[4];
#ifdef ATRBVH_LANES4
    const int lanes = ready > 1u;
#else
    const int lanes = 0;
    (void)quad;
#endif
    for (l = 0; l < ready; l++) {
        applied[l] = 0;
        if (tl[l].n < 3u)
            continue;
        if (tl[l].n == n && lanes) {
            atrbvh_treelet_gather(t, &tl[l], &lv[full]);
            sel[full++] = l;
            continue;
        }
        applied[l] =
            atrbvh_treelet_finish(t, p, root[l], 0, s[0], NULL, &tl[l]);
    }
    if (full == 1u) {
        const atrbvh_u32 k = sel[0];
        applied[k] = atrbvh_trbvh_keep(t, p, root[k], &tl[k], &lv[0], s[0],
                                       atrbvh_trbvh_costs(p, n, &lv[0], s[0]));
    }
#ifdef ATRBVH_LANES4
    if (full > 1u) {
        const atrbvh_treelet_leaves *in[4];
        double found[4];
        atrbvh_u32 top[4];
        for (l = 0; l < 4u; l++)
            in[l] = &lv[l < full ? l : 0u];
        atrbvh_trbvh_costs4(p, n, in, quad, found, top);
        for (l = 0; l < full; l++) {
            const atrbvh_u32 k = sel[l];
            const atrbvh_trbvh_tables tab =
                atrbvh_trbvh_tables_lane(n, quad, l, top[l], s[l]);
            applied[k] = atrbvh_trbvh_keep_from(t, p, root[k], &tl[k], &lv[l],
                                                &tab, found[l]);
        }
    }
#endif
}

ATRBVH_FN int atrbvh_treelet_process_tl(const atrbvh_treelet_tree *t,
                                        const atrbvh_cost_params *p,
                                        atrbvh_u32 root, atrbvh_u32 n,
                                        int agglomerative,
                                        atrbvh_trbvh_scratch s,
                                        const atrbvh_agg_scratch *agg,
                                        atrbvh_treelet *tl)
{
    (void)atrbvh_treelet_begin(t, p, root, n, tl);
    return atrbvh_treelet_finish(t, p, root, agglomerative, s, agg, tl);
}

ATRBVH_FN int atrbvh_treelet_process(const atrbvh_treelet_tree *t,
                                     const atrbvh_cost_params *p,
                                     atrbvh_u32 root, atrbvh_u32 n,
                                     int agglomerative,
                                     atrbvh_trbvh_scratch s,
                                     const atrbvh_agg_scratch *agg)
{
    atrbvh_treelet tl;
    return atrbvh_treelet_process_tl(t, p, root, n, agglomerative, s, agg,
                                     &tl);
}

/* ------------------------------------------------------ skip marks */
/* Skipping treelets known to change nothing (TRBVH, and ATRBVH up to
 * ATRBVH_TREELET_MAX leaves or adaptive; both backends, the same marks).
 * A treelet is a pure function of its root's subtree (refresh, form, the
 * TRBVH DP or the ATRBVH agglomeration, the strict comparison; the
 * adaptive size is a function of the root's primitive count; nothing
 * depends on the round or on gamma), so when the root was processed
 * without a change in an earlier round and nothing in its subtree changed
 * since, it would again change nothing.
 *
 * Two bytes per internal node, zero before the first round: chg, the last
 * round + 1 in which the node's subtree changed, and same, the last round
 * + 1 in which it was processed without a change since (0: never).  chg
 * is carried up as the walk goes (children are final before their parent,
 * on the CPU by the post-order walk, on OpenCL by the arrival counters; a
 * child outside the crown was not touched this round except through a
 * write-back, which marks it); a write-back marks every id it reused, so
 * a node's `same` never outlives its content.  Skipping changes no bit of
 * the tree, only the work done.  On OpenCL the marks are volatile (a
 * child's marks were written by another work-item of the launch, handed
 * over like the tree's arrays). */
typedef struct atrbvh_treelet_marks {
    ATRBVH_SHARED_GLOBAL unsigned char *chg;
    ATRBVH_SHARED_GLOBAL unsigned char *same;
} atrbvh_treelet_marks;

/* The value atrbvh_treelet_process_marked returns for a skipped treelet. */
#define ATRBVH_TREELET_SKIPPED (-1)

/* The marks before treelet `root` is processed: its subtree's last
 * change carried up from its children (final before it); returns 1 when
 * the treelet is known to change nothing (then nothing is computed). */
ATRBVH_FN int atrbvh_treelet_marks_skip(const atrbvh_treelet_tree *t,
                                        atrbvh_treelet_marks m,
                                        atrbvh_u32 root)
{
    atrbvh_u32 l = t->left[root], r = t->right[root];
    unsigned char ch = m.chg[root];
    if (l < t->n_internal && m.chg[l] > ch)
        ch = m.chg[l];
    if (r < t->n_internal && m.chg[r] > ch)
        ch = m.chg[r];
    m.chg[root] = ch;
    return m.same[root] != 0 && ch <= m.same[root];
}

/* The marks after treelet `root`, formed into *tl, was processed in
 * round `round` and written back (applied) or not. */
ATRBVH_FN void atrbvh_treelet_marks_done(atrbvh_treelet_marks m,
                                         const atrbvh_treelet *tl,
                                         atrbvh_u32 root, int applied,
                                         atrbvh_u32 round)
{
    unsigned char r1 = (unsigned char)(round + 1u);
    atrbvh_u32 k;
    if (applied) {
        /* A write-back reused the treelet's internal ids (the root's
         * too) for new nodes: changed, and not known unchanged. */
        for (k = 0; k + 1u < tl->n; k++) {
            m.chg[tl->internal[k]] = r1;
            m.same[tl->internal[k]] = 0;
        }
    } else {
        m.same[root] = r1;
    }
}

/* atrbvh_treelet_process_tl behind the skip marks, in round `round`
 * (from 0; rounds fit a byte, ATRBVH_ROUNDS_MAX): ATRBVH_TREELET_SKIPPED
 * when the treelet is known to change nothing (nothing computed), else
 * what atrbvh_treelet_process_tl returns, the marks updated.  The CPU
 * driver (optimise.c) and the opt_round kernel both call this. */
ATRBVH_FN int atrbvh_treelet_process_marked(const atrbvh_treelet_tree *t,
                                            const atrbvh_cost_params *p,
                                            atrbvh_u32 root, atrbvh_u32 n,
                                            int agglomerative,
                                            atrbvh_trbvh_scratch s,
                                            const atrbvh_agg_scratch *agg,
                                            atrbvh_treelet_marks m,
                                            atrbvh_u32 round)
{
    atrbvh_treelet tl;
    int applied;
    if (atrbvh_treelet_marks_skip(t, m, root))
        return ATRBVH_TREELET_SKIPPED;
    applied = atrbvh_treelet_process_tl(t, p, root, n, agglomerative, s, agg,
                                        &tl);
    atrbvh_treelet_marks_done(m, &tl, root, applied, round);
    return applied;
}

/* ------------------------------------------------- ATRBVH, any size */
/* Treelets of more than ATRBVH_TREELET_MAX leaves (up to ATRBVH_ATRBVH_MAX)
 * and the adaptive size.  The formation and write-back above keep the
 * treelet and its topology in private arrays of ATRBVH_TREELET_MAX
 * entries; a larger treelet keeps those in the worker's scratch too
 * (atrbvh_agg_layout, sized from the largest size the build asks for: a
 * 128-leaf treelet needs 8128 distances and about 20 KiB besides, which
 * no private array of a work-item should hold).  Its agglomeration is
 * the same atrbvh_agg_cluster; its formation, pre-order and write-back
 * are the scratch's instance of shared/treelet_arrays.inc (the _g
 * functions), the text of the private path's, so for a size both paths
 * accept they give the same tree (the tests compare them). */

/* atrbvh_treelet_form into the scratch. */
ATRBVH_FN atrbvh_u32 atrbvh_agg_form(const atrbvh_treelet_tree *t,
                                     atrbvh_u32 root, atrbvh_u32 n,
                                     const atrbvh_agg_scratch *s)
{
    return atrbvh_form_g(t, root, n, s->leaf, s->internal, s->area);
}

/* atrbvh_treelet_preorder and atrbvh_treelet_write over the scratch
 * (root n-2, the agglomerative root). */
ATRBVH_FN void atrbvh_agg_write(const atrbvh_treelet_tree *t, atrbvh_u32 n,
                                const atrbvh_agg_scratch *s)
{
    atrbvh_topo_preorder_g(n, n - 2u, s->left, s->right, s->order, s->stack);
    atrbvh_topo_write_g(t, n, s->leaf, s->internal, s->order, s->left,
                        s->right, s->tbox, s->tcount, s->tcost, s->flat,
                        s->ids, s->node_of);
}

/* atrbvh_treelet_process for ATRBVH with every array in the scratch. */
ATRBVH_FN int atrbvh_agg_process_large(const atrbvh_treelet_tree *t,
                                       const atrbvh_cost_params *p,
                                       atrbvh_u32 root, atrbvh_u32 n,
                                       const atrbvh_agg_scratch *s)
{
    atrbvh_u32 m;
    double found;
    atrbvh_treelet_refresh(t, p, root);
    m = atrbvh_agg_form(t, root, n, s);
    if (m < 3u)
        return 0;
    found = atrbvh_agg_cluster(t, p, m, s);
    if (!(found < t->cost[root]))
        return 0;
    atrbvh_agg_write(t, m, s);
    return 1;
}

/* The adaptive treelet size (ATRBVH_TREELET_AUTO), a pure function of
 * the treelet root's primitive count, so the same on both backends and
 * for any schedule:
 *
 *   count <  512   9 leaves (the paper's size)
 *   count >= 512   16 leaves
 *   count >= 4096  32 leaves
 *
 * Why: a treelet of n leaves costs about n^2 (n(n-1)/2 distances, and
 * forming it scans up to n slots n times), and a crown holds about 2N/c
 * roots of at least c primitives.  The nodes below 512 primitives are
 * nearly all of the crown (the round's work at 9 leaves); the few above
 * carry the largest boxes, hence most of the SAH, and there a larger
 * search pays: 16 leaves from 512 add about (2N/512)(120 - 36) and 32
 * from 4096 about (2N/4096)(496 - 120) distances, about 0.5 N against
 * the 9-leaf base's (2N/9) * 36 = 8 N per round.  The crown starts at 9
 * primitives (gamma 9), so the bottom is optimised as by ATRBVH(9, R),
 * which fixed sizes of 16 or 32 (gamma = n) leave to their first round.
 * Other thresholds measured (16 from 64, 24 from 512, 32 from 4096; 16
 * from 32, 32 from 1024) cost more and lost 1% on bunny
 * (docs/optimisers.md).  `gamma` (the round's crown threshold) is not
 * used by this rule; it is passed so that a rule may use the round. */
ATRBVH_FN atrbvh_u32 atrbvh_treelet_auto_size(atrbvh_u32 count,
                                              atrbvh_u32 gamma)
{
    (void)gamma;
    return count >= 4096u ? 32u : count >= 512u ? 16u : 9u;
}

/* One ATRBVH treelet of size n (ATRBVH_TREELET_AUTO: by the rule above
 * from the root's primitive count and the round's crown threshold gamma):
 * the fixed-size path up to ATRBVH_TREELET_MAX, the scratch path above.
 * Both drivers call this. */
ATRBVH_FN int atrbvh_atrbvh_process(const atrbvh_treelet_tree *t,
                                    const atrbvh_cost_params *p,
                                    atrbvh_u32 root, atrbvh_u32 n,
                                    atrbvh_u32 gamma,
                                    atrbvh_trbvh_scratch none,
                                    const atrbvh_agg_scratch *s)
{
    if (n == ATRBVH_TREELET_AUTO)
        n = atrbvh_treelet_auto_size(t->count[root], gamma);
    if (n <= ATRBVH_TREELET_MAX)
        return atrbvh_treelet_process(t, p, root, n, 1, none, s);
    return atrbvh_agg_process_large(t, p, root, n, s);
}

#endif
