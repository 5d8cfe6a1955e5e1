/*
 * refit.c - stage "refit": leaf boxes from the primitive boxes, then boxes,
 * primitive counts and SAH costs bottom-up.
 *
 * The walk is the OpenCL backend's: every leaf climbs towards the root;
 * at each internal node an arrival counter (the node's count field, zeroed
 * first and overwritten with the real count once the node is done) lets
 * the first child to arrive stop and the second continue, computing the
 * node from both children (atrbvh_refit_node, left cost first).  A node is
 * therefore computed exactly once, after both children, with the same
 * arithmetic whichever thread gets there: the result is the same for any
 * thread count.  Each thread takes a contiguous block of leaves, so its
 * climbs touch neighbouring nodes (the hierarchy numbers nodes by key
 * position) and threads meet only along the block boundaries.
 *
 * With several threads the counter is a GCC/Clang atomic fetch-and-add
 * (acquire-release: the first child's box, count and cost are visible to
 * the second arrival, which reads them); with one thread it is a plain
 * increment.
 *
 * A tree from the hierarchy stage is refitted there, in the stack pass
 * that builds it (hierarchy.c: its post-order needs no counter); this
 * stage then has nothing to compute, and the climb below refits a
 * caller's tree (set_tree) and serves the tests as the reference.
 *
 * An LBVH's stage also takes the collapse stage's work (climb_sizes): its
 * sizes and costs in the same climb, so the tree is not walked again.
 * Callgrind, dragon, one thread: refit 135 -> 202 and collapse 161 -> 0
 * instructions per triangle.
 *
 * Measured on the dragon (871,414 triangles), one thread, callgrind: the
 * recursive post-order of OpenMP tasks this replaces ran ~128M
 * instructions; see the commit message for this walk's figures.
 */
#include "config.h"

#include "cpu.h"

#include <string.h>

#if defined(_OPENMP) && !(defined(__GNUC__) || defined(__clang__))
#error "refit.c needs the GCC/Clang __atomic builtins with OpenMP"
#endif

/* Leaves ahead of the current one whose primitive box is prefetched. */
#define PREFETCH 16

/* The climb's functions are specialised for each of refit()'s cases
 * (atomic, gather, size: constants at each call): without the
 * attribute GCC keeps one copy testing them at every step (callgrind,
 * dragon, one thread: about 16 more instructions per triangle). */
#if defined(__GNUC__) || defined(__clang__)
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ALWAYS_INLINE inline
#endif

/* A node's arrival: returns whether this is the second child to arrive
 * (the node is then computed by the caller); the counters were zeroed
 * before the climbs. */
static ALWAYS_INLINE int arrive(uint32_t *count, uint32_t up, int atomic)
{
    uint32_t before;
#if defined(__GNUC__) || defined(__clang__)
    if (atomic)
        before = __atomic_fetch_add(&count[up], 1u, __ATOMIC_ACQ_REL);
    else
#endif
        before = count[up]++;
    (void)atomic;
    return before != 0u;
}

/* Climbs from leaf position `i` (node already final) while it is the
 * second child to arrive at its parent.  Without a cost array (t->cost
 * NULL) boxes and counts only. */
static ALWAYS_INLINE void climb(atrbvh_i_tree *t,
                                const atrbvh_cost_params *p, int64_t i,
                                int atomic)
{
    uint32_t *const count = t->count;
    const uint32_t *const parent = t->parent;
    uint32_t node = (uint32_t)(t->n - 1 + i), up;
    while ((up = parent[node]) != ATRBVH_U32_MAX) {
        uint32_t l, r;
        if (!arrive(count, up, atomic))
            return; /* first to arrive: the sibling's climb goes on */
        l = t->left[up];
        r = t->right[up];
        if (t->cost) {
            atrbvh_refit_node(p, t->box[l], count[l], t->cost[l], t->box[r],
                              count[r], t->cost[r], &t->box[up], &count[up],
                              &t->cost[up]);
        } else { /* the same box and count, no cost (an LBVH) */
            t->box[up] = atrbvh_box_union(t->box[l], t->box[r]);
            count[up] = count[l] + count[r];
        }
        node = up;
    }
}

/* The LBVH's refit and collapse in one climb (atrbvh_i_refit_sizes): as
 * climb() without a cost array, and the node's collapse size and cost
 * (collapse.c's decide, the same arithmetic).  A node's cost is only read
 * by its parent: the first child to arrive leaves it in the parent's box,
 * not yet computed (the left child in its first 8 bytes, the right in the
 * next 8), before its arrival is counted; the second reads it there, then
 * writes the box. */
static ALWAYS_INLINE void climb_sizes(atrbvh_i_tree *t,
                                      const atrbvh_cost_params *p,
                                      uint32_t *size, int64_t i, double cost,
                                      int atomic)
{
    uint32_t *const count = t->count;
    const uint32_t *const parent = t->parent;
    uint32_t node = (uint32_t)(t->n - 1 + i), up;
    while ((up = parent[node]) != ATRBVH_U32_MAX) {
        uint32_t l, r, cnt;
        const int right = t->left[up] != node;
        double other;
        atrbvh_box bx;
        unsigned char *pending = (unsigned char *)(void *)&t->box[up];
        memcpy(pending + (right ? sizeof cost : 0), &cost, sizeof cost);
        if (!arrive(count, up, atomic))
            return; /* first to arrive: the sibling's climb goes on */
        memcpy(&other, pending + (right ? 0 : sizeof other), sizeof other);
        l = t->left[up];
        r = t->right[up];
        /* the refit kernel's rule for an LBVH (shared/stages.h) */
        size[up] = atrbvh_refit_node_size(
            p, t->box[l], count[l], right ? other : cost, size[l], t->box[r],
            count[r], right ? cost : other, size[r], &bx, &cnt, &cost);
        t->box[up] = bx;
        count[up] = cnt;
        node = up;
    }
}

/* Leaves lo .. hi-1 (sorted positions): their boxes and costs, then the
 * climb from each.  gather: the leaf boxes still to be fetched from
 * prim_boxes (else they are in place). */
static ALWAYS_INLINE void refit_block(atrbvh_i_tree *t,
                                      const atrbvh_box *prim_boxes,
                                      const uint32_t *order,
                                      const atrbvh_cost_params *p, int64_t lo,
                                      int64_t hi, int atomic, int gather,
                                      uint32_t *size)
{
    const int64_t n = t->n;
    int64_t i;
    for (i = lo; i < hi; i++) {
        const uint32_t leaf = (uint32_t)(n - 1 + i);
        atrbvh_box b;
        if (gather) {
            b = prim_boxes[order[i]];
#if defined(__GNUC__) || defined(__clang__)
            /* The gather is random; the climb's branches would stall it. */
            if (i + PREFETCH < hi)
                __builtin_prefetch(&prim_boxes[order[i + PREFETCH]]);
#endif
            t->box[leaf] = b;
        } else {
            b = t->box[leaf];
        }
        t->count[leaf] = 1;
        if (size) {
            size[leaf] = 1u | ATRBVH_SIZE_LEAF;
            climb_sizes(t, p, size, i, atrbvh_refit_leaf_cost(p, b), atomic);
            continue;
        }
        if (t->cost)
            t->cost[leaf] = atrbvh_refit_leaf_cost(p, b);
        climb(t, p, i, atomic);
    }
}

/* In place: the primitive boxes are entries 0 .. n-1 of t->box (the
 * memory plan, backend.c), the leaves n-1 .. 2n-2 take them in sorted
 * order.  Only entry n-1 is both read and written, so it is read first;
 * every leaf is written before any climb writes an internal node over
 * entries 0 .. n-2. */
static void gather_in_place(atrbvh_i_tree *t, const uint32_t *order,
                            int threads)
{
    const int64_t n = t->n;
    atrbvh_box *const box = t->box;
    const atrbvh_box last = box[n - 1];
    int64_t i;
    (void)threads;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static)
#endif
    for (i = 0; i < n; i++)
        atrbvh_i_gather_leaf(box, order, n, i, &last);
}

static void refit(atrbvh_i_tree *t, const atrbvh_box *prim_boxes,
                  const uint32_t *order, const atrbvh_cost_params *p,
                  int threads, uint32_t *size)
{
    const int64_t n = t->n;
    /* prim_boxes in the node box array: gather first, in place. */
    const int gather = prim_boxes != t->box;
    int64_t i;
    if (threads < 1)
        threads = 1;
    if ((int64_t)threads > n)
        threads = (int)n;
    if (threads == 1) {
        if (!gather)
            gather_in_place(t, order, 1);
        for (i = 0; i + 1 < n; i++)
            t->count[i] = 0;
        refit_block(t, prim_boxes, order, p, 0, n, 0, gather, size);
        return;
    }
#ifdef _OPENMP
    /* The in-place gather in the climbs' region (gather_in_place's loop,
     * entry n-1 read before any thread writes leaf 0 over it): one region
     * where there were two, a thread hand-over fewer.  Its loop needs no
     * barrier of its own: the counters' loop's orders every leaf before
     * the climbs write internal nodes over the primitive boxes. */
    const atrbvh_box last = gather ? atrbvh_box_empty() : t->box[n - 1];
#pragma omp parallel num_threads(threads)
    {
        int b;
        if (!gather) { /* (the same for every thread) */
#pragma omp for schedule(static) nowait
            for (i = 0; i < n; i++)
                atrbvh_i_gather_leaf(t->box, order, n, i, &last);
        }
#pragma omp for schedule(static)
        for (i = 0; i < n - 1; i++)
            t->count[i] = 0;
        /* (the implied barrier: every counter is zero and every leaf
         * gathered before a climb; the region's end waits for the
         * climbs) */
#pragma omp for schedule(static, 1) nowait
        for (b = 0; b < threads; b++) {
            const int64_t lo = (int64_t)((uint64_t)n * (uint64_t)b /
                                         (uint64_t)threads),
                          hi = (int64_t)((uint64_t)n * (uint64_t)(b + 1) /
                                         (uint64_t)threads);
            refit_block(t, prim_boxes, order, p, lo, hi, 1, gather, size);
        }
    }
#endif
}

void atrbvh_i_refit(atrbvh_i_tree *t, const atrbvh_box *prim_boxes,
                    const uint32_t *order, const atrbvh_cost_params *p,
                    int threads)
{
    refit(t, prim_boxes, order, p, threads, NULL);
}

void atrbvh_i_refit_sizes(atrbvh_i_tree *t, const atrbvh_box *prim_boxes,
                          const uint32_t *order, const atrbvh_cost_params *p,
                          int threads, uint32_t *size)
{
    refit(t, prim_boxes, order, p, threads, size);
}

/* The stage: boxes, counts and costs of the tree. */
atrbvh_status atrbvh_i_cpu_refit(atrbvh_device *dev, atrbvh_i_run *run,
                                 atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    atrbvh_status st;
    (void)dev;
    /* The keys are read no more: their slot takes the costs. */
    atrbvh_i_scratch_done(c->scratch, CPU_KEYS);
    /* An LBVH reads no cost after this stage (the collapse recomputes
     * them): it keeps none. */
    st = atrbvh_i_cpu_tree_values(c, run->cfg->method != ATRBVH_METHOD_LBVH,
                                  error);
    if (st != ATRBVH_OK)
        return st;
    if (c->refitted) {
        /* the hierarchy stage's pass did it (hierarchy.c) */
    } else if (run->cfg->method == ATRBVH_METHOD_LBVH) {
        /* The LBVH's collapse sizes in the same climb, into the cost
         * slot (the keys' memory; collapse.c then has nothing to do). */
        st = atrbvh_i_cpu_tree_sizes(c, error);
        if (st != ATRBVH_OK)
            return st;
        refit(&c->tree, c->boxes, c->order, &run->cfg->cost,
              run->cfg->threads, c->size);
    } else {
        refit(&c->tree, c->boxes, c->order, &run->cfg->cost,
              run->cfg->threads, NULL);
    }
    /* The leaves hold the primitive boxes now; the order array lives on
     * as leaf_prim unless there are kept ids. */
    atrbvh_i_scratch_done(c->scratch, CPU_BOXES);
    if (c->order != c->tree.leaf_prim)
        atrbvh_i_scratch_done(c->scratch, CPU_ORDER);
    c->boxes = NULL;
    c->order = NULL;
    return ATRBVH_OK;
}
