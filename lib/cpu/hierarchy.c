/*
 * hierarchy.c - stage "hierarchy": the binary radix tree of Karras,
 * "Maximizing Parallelism in the Construction of BVHs, Octrees, and k-d
 * Trees" (HPG 2012), numbered as Karras numbers it, and (the stage) the
 * refit of that tree in the same pass.  The tie rule for equal keys
 * (positions told apart, atrbvh_karras_delta in shared/arith.h) decides
 * the tree and is the OpenCL backend's, which runs these same two passes
 * (cl/kernels.cl: hierarchy_block, hierarchy) and its refit separately.
 *
 * Both build the tree without Karras's per-node searches.  With
 * delta_s = atrbvh_karras_delta(s, s+1) for the n-1 split positions s,
 * the node whose split is s covers the leaves ps+1 .. ns, where ps (ns) is
 * the nearest split to the left (right) with a smaller delta (-1 and n-1
 * when there is none): the radix tree of distinct (key, position) strings
 * is the Cartesian tree of the adjacent common-prefix lengths, and between
 * two equal deltas there is always a smaller one, so every range has one
 * smallest split.  Its parent is the one of ps, ns with the larger delta;
 * Karras's numbering gives a left child (parent ns) the id of its last
 * leaf, a right child (parent ps) that of its first, the root id 0, and
 * every node the children gamma = s and s+1 (leaves when alone).
 *
 * The nearest smaller values come from one left-to-right pass with a stack
 * per contiguous block of splits (blocks taken in turn by the threads).
 * A node is written as soon as both neighbours are known; the rest of
 * each block - its prefix minima (no left neighbour in the block) and
 * what is left on its stack (no right neighbour) - are strictly
 * monotone in delta, so at most ATRBVH_HIER_SIDE each, and a second,
 * serial pass over these leftovers of every block, in position order,
 * finds their neighbours: the nearest smaller split of a leftover is
 * itself a leftover.  Deltas lie in 0 .. 95, so no stack is deeper
 * than 96.
 *
 * The refit in the same pass.  The stack pops nodes in post-order: the
 * node popped at split ns whose new top is ps has as its right child the
 * subtree finished just before (leaf ns for the first pop at ns), and as
 * its left child the subtree that ended at its own split when it was
 * pushed.  So each stack entry carries its left subtree's box, cost and
 * collapse size, the pass carries the subtree just finished, and every
 * node is computed from its children's values in registers, by the
 * refit's own rule (shared/stages.h: atrbvh_refit_node_size for an LBVH,
 * which also decides the collapse, atrbvh_refit_node with costs for the
 * others), left first: the same bits as the refit kernel's climb, with
 * no arrival counter to test and no child read back.  In the second pass
 * the subtree between two consecutive leftovers is one node finished by
 * the first pass (or a leaf): every split strictly between them found
 * both neighbours inside the block, and the smallest of them has the two
 * leftovers as its neighbours; the first pass keeps that subtree's root
 * and cost with each leftover.
 *
 * The refit needs the leaf boxes in sorted order, gathered in place in
 * the node box array (the memory plan, backend.c) before any internal
 * node is written over the primitive boxes, and its sizes or costs go to
 * the slot the keys are in: so the keys' deltas are computed first, into
 * the leaves' half of the count array (each becomes the leaf's count, 1,
 * once read), in the same parallel sweep as the gather, and the block
 * passes start after its barrier.  One parallel region for the hierarchy
 * and the refit, where there were three (hierarchy, gather, climbs).
 * In a build the sort stage does that sweep (sort.c's sort_leaves: each
 * bucket's leaves and deltas as soon as its keys are in place), so the
 * region is the block passes alone, with no barrier: a thread hand-over
 * fewer (the tool's threads sleep at a barrier, and a wake-up costs tens
 * of microseconds on a loaded machine).
 *
 * An LBVH of more than a few thousand primitives needs no node box after
 * this pass (its collapse sizes are decided here, and the layout
 * recomputes the boxes: layout.c), so the sort writes the deltas only and
 * the pass reads leaf i's box at its primitive's, box[order[i]]
 * (prefetched ahead), and writes no node box: the primitive boxes stay
 * whole, and the block passes keep their leftovers' subtree boxes after
 * them (hier_ctx's by_order).  No 24 bytes per primitive gathered, and
 * the array holds n + ATRBVH_I_HIER_LEFTOVERS boxes, not 2n-1 (the memory
 * plan, backend.c).
 */
#include "config.h"

#include "cpu.h"

/* Strictly monotone runs of deltas in 0 .. 95 (clz of distinct keys
 * 0 .. 63, equal keys 64 .. 95): at most 96 entries, so a block leaves at
 * most 96 prefix minima and 95 more on its stack. */
#define ATRBVH_HIER_SIDE 96
/* Blocks of the first pass, at most (ATRBVH_I_BLOCKS_PER_THREAD a
 * thread, taken in turn: cpu.h): their leftovers live on the stack. */
#define ATRBVH_HIER_BLOCKS 16
/* (an LBVH reading its leaf boxes in place keeps every leftover's box
 * after the primitive boxes, in ATRBVH_I_HIER_LEFTOVERS entries: cpu.h) */
ATRBVH_STATIC_ASSERT(ATRBVH_I_HIER_LEFTOVERS >=
                         ATRBVH_HIER_BLOCKS * 2u * ATRBVH_HIER_SIDE,
                     hier_leftover_boxes_fit);

/* The pass is specialised for each mode (a constant at every call):
 * without the attribute GCC keeps one copy testing it at every step. */
#if defined(__GNUC__) || defined(__clang__)
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ALWAYS_INLINE inline
#endif

/* What the pass computes beside the topology. */
enum {
    TOPOLOGY, /* the topology only, deltas from the keys    */
    SIZES,    /* and boxes, collapse sizes (an LBVH)         */
    COSTS,    /* and boxes, costs                            */
    FLAGS     /* and boxes, costs and collapse decisions (a
                 tree to be optimised: optimise.c keeps them) */
};

typedef struct hier_ctx {
    atrbvh_i_tree *t;
    int64_t n;
    const uint64_t *keys;      /* TOPOLOGY: the sorted keys            */
    const atrbvh_cost_params *p; /* SIZES, COSTS, FLAGS                */
    uint32_t *size;            /* SIZES: collapse sizes (2n-1)         */
    unsigned char *flat;       /* FLAGS: collapse decisions (2n-1)     */
    /* SIZES, or NULL: leaf i's box is t->box[by_order[i]] (the primitive
     * boxes, never written over: no node box is written), and the
     * leftovers' subtree boxes go to left_box[b * 2 * ATRBVH_HIER_SIDE
     * + k] (the entries after the n primitive boxes: cpu.h) */
    const uint32_t *by_order;
    atrbvh_box *left_box;
} hier_ctx;

/* A finished subtree: its root and (SIZES, COSTS) its values. */
typedef struct hier_sub {
    atrbvh_box box;
    double cost;
    uint32_t node, size;
} hier_sub;

typedef struct hier_entry {
    int64_t s;     /* split position        */
    int d;         /* its delta             */
    hier_sub left; /* the subtree ending at leaf s: s's left child */
} hier_entry;

/* A leftover of the first pass: its split, and the subtree between the
 * previous leftover and it (its root; the box and size are in the tree). */
typedef struct hier_left {
    uint32_t s, node;
    double cost;
} hier_left;

/* The delta of split s: from the keys, or (SIZES, COSTS) where the first
 * sweep put it. */
static ALWAYS_INLINE int split_delta(const hier_ctx *x, int mode, int64_t s)
{
    if (mode == TOPOLOGY)
        return atrbvh_karras_delta(x->keys, x->n, s, s + 1);
    return (int)(int32_t)x->t->count[x->n - 1 + s];
}

/* Leaf position i as a finished subtree (its delta already read: its
 * count is written here). */
static ALWAYS_INLINE void leaf(const hier_ctx *x, int mode, int64_t i,
                               hier_sub *out)
{
    atrbvh_i_tree *t = x->t;
    const uint32_t id = (uint32_t)(x->n - 1 + i);
    out->node = id;
    t->count[id] = 1;
    if (mode == TOPOLOGY) { /* (nothing read: defined values to copy) */
        out->box = atrbvh_box_empty();
        out->cost = 0.0;
        out->size = 0;
        return;
    }
    if (mode == SIZES && x->by_order) {
        /* (random reads, each one's address known ahead) */
#if defined(__GNUC__) || defined(__clang__)
        if (i + 16 < x->n)
            __builtin_prefetch(&t->box[x->by_order[i + 16]]);
#endif
        out->box = t->box[x->by_order[i]];
    } else {
        out->box = t->box[id];
    }
    out->cost = atrbvh_refit_leaf_cost(x->p, out->box);
    if (mode == SIZES) {
        out->size = 1u | ATRBVH_SIZE_LEAF;
        x->size[id] = out->size;
    } else {
        t->cost[id] = out->cost;
    }
    if (mode == FLAGS)
        x->flat[id] = 1; /* (a leaf: one output leaf) */
}

/* Writes internal node s (its split) from its neighbours ps (-1: none)
 * and ns (n-1: none) and their deltas, its left subtree *l and its right
 * subtree *r; *r becomes the node. */
static ALWAYS_INLINE void emit(const hier_ctx *x, int mode, int64_t s,
                               int64_t ps, int dps, int64_t ns, int dns,
                               const hier_sub *l, hier_sub *r)
{
    atrbvh_i_tree *t = x->t;
    uint32_t lc, rc, c;
    const uint32_t id =
        atrbvh_hier_node(x->n, s, ps, dps, ns, dns, &lc, &rc, &c);
    t->left[id] = lc;
    t->right[id] = rc;
    t->count[id] = c;
    t->parent[lc] = id;
    t->parent[rc] = id;
    if (mode == SIZES) {
        atrbvh_box b;
        double cost;
        uint32_t cnt;
        const uint32_t size = atrbvh_refit_node_size(
            x->p, l->box, (uint32_t)(s - ps), l->cost, l->size, r->box,
            (uint32_t)(ns - s), r->cost, r->size, &b, &cnt, &cost);
        if (!x->by_order)
            t->box[id] = b;
        x->size[id] = size;
        r->box = b;
        r->cost = cost;
        r->size = size;
    } else if (mode == COSTS || mode == FLAGS) {
        atrbvh_box b;
        double cost;
        uint32_t cnt;
        if (mode == FLAGS) /* (the size's flag: the cost's choice) */
            x->flat[id] = (unsigned char)(atrbvh_refit_node_size(
                                              x->p, l->box, (uint32_t)(s - ps),
                                              l->cost, 0u, r->box,
                                              (uint32_t)(ns - s), r->cost, 0u,
                                              &b, &cnt, &cost) >>
                                          31);
        else
            atrbvh_refit_node(x->p, l->box, (uint32_t)(s - ps), l->cost,
                              r->box, (uint32_t)(ns - s), r->cost, &b, &cnt,
                              &cost);
        t->box[id] = b;
        t->cost[id] = cost;
        r->box = b;
        r->cost = cost;
    }
    r->node = id;
}

/* The first pass over the splits lo .. hi-1.  Leftovers (ascending) go to
 * `out`, their deltas to `out_d`, and with x->by_order their subtrees'
 * boxes to `out_box`; returns how many. */
static ALWAYS_INLINE uint32_t block_pass(const hier_ctx *x, int mode,
                                         int64_t lo, int64_t hi,
                                         hier_left *out, signed char *out_d,
                                         atrbvh_box *out_box)
{
    hier_entry st[ATRBVH_HIER_SIDE];
    uint32_t sp = 0, nout = 0, k;
    int64_t s;
    hier_sub carry; /* the subtree ending at leaf s, finished last */
    for (s = lo; s < hi; s++) {
        const int d = split_delta(x, mode, s);
        leaf(x, mode, s, &carry);
        while (sp > 0 && st[sp - 1].d > d) {
            sp--;
            /* (the bottom entry is a prefix minimum, already out) */
            if (sp > 0)
                emit(x, mode, st[sp].s, st[sp - 1].s, st[sp - 1].d, s, d,
                     &st[sp].left, &carry);
        }
        if (sp == 0 && nout < ATRBVH_HIER_SIDE) { /* a prefix minimum */
            out[nout].s = (uint32_t)s;
            out[nout].node = carry.node;
            out[nout].cost = carry.cost;
            if (out_box)
                out_box[nout] = carry.box;
            out_d[nout++] = (signed char)d;
        }
        if (sp == ATRBVH_HIER_SIDE)
            continue; /* keys out of order: cannot happen when sorted */
        st[sp].s = s;
        st[sp].d = d;
        st[sp++].left = carry;
    }
    /* st[0] is the last prefix minimum, already out. */
    for (k = 1; k < sp; k++) {
        out[nout].s = (uint32_t)st[k].s;
        out[nout].node = st[k].left.node;
        out[nout].cost = st[k].left.cost;
        if (out_box)
            out_box[nout] = st[k].left.box;
        out_d[nout++] = (signed char)st[k].d;
    }
    return nout;
}

/* Each leaf's original primitive, for the leaves lo .. hi-1. */
static void leaf_prims(atrbvh_i_tree *t, const uint32_t *order,
                       const uint32_t *ids, int64_t lo, int64_t hi)
{
    uint32_t *const leaf_prim = t->leaf_prim;
    int64_t i;
    if (ids)
        for (i = lo; i < hi; i++)
            leaf_prim[i] = ids[order[i]];
    else if (leaf_prim != order) /* (the stage's: the same array) */
        for (i = lo; i < hi; i++)
            leaf_prim[i] = order[i];
}

/* The block passes (`blocks` of them, n >= 2), then the second pass;
 * SIZES and COSTS first gather the leaf boxes and write the deltas (the
 * file's comment).  With `order`, also each leaf's original primitive. */
static ALWAYS_INLINE void pass(const hier_ctx *x, int mode, int blocks,
                               int threads, const uint32_t *order,
                               const uint32_t *ids, int ready)
{
    atrbvh_i_tree *t = x->t;
    const int64_t n = x->n;
    hier_left left_over[ATRBVH_HIER_BLOCKS][2 * ATRBVH_HIER_SIDE];
    signed char left_d[ATRBVH_HIER_BLOCKS][2 * ATRBVH_HIER_SIDE];
    uint32_t counts[ATRBVH_HIER_BLOCKS];
    hier_entry st[ATRBVH_HIER_SIDE];
    hier_sub carry;
    uint32_t sp = 0, k;
    /* Read before any leaf is written over it: the gather is in place,
     * and primitive box n-1 is also leaf 0's entry. */
    const atrbvh_box last =
        mode != TOPOLOGY && !ready ? t->box[n - 1] : atrbvh_box_empty();
    atrbvh_i_join join = {0};
    int b;
#ifdef _OPENMP
#pragma omp parallel num_threads(atrbvh_i_team(blocks, threads))
#endif
    {
        int64_t i;
        if (mode != TOPOLOGY && !ready) { /* (the same for every thread) */
            atrbvh_box *const box = t->box;
            uint32_t *const count = t->count;
            const uint64_t *const keys = x->keys;
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
            for (i = 0; i < n; i++) {
                atrbvh_i_gather_leaf(box, order, n, i, &last);
                if (i + 1 < n)
                    count[n - 1 + i] =
                        (uint32_t)atrbvh_karras_delta(keys, n, i, i + 1);
            }
            /* (the implied barrier: every leaf box and delta is there
             * before a block writes an internal node over a primitive
             * box, or a size or cost over a key) */
        }
        /* nowait: the second pass reads the blocks' leftovers after the
         * region's end, which waits for them; the loop's own barrier was
         * one more thread hand-over. */
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1) nowait
#endif
        for (b = 0; b < blocks; b++) {
            counts[b] = block_pass(
                x, mode,
                (int64_t)((uint64_t)(n - 1) * (uint64_t)b / (uint64_t)blocks),
                (int64_t)((uint64_t)(n - 1) * (uint64_t)(b + 1) /
                          (uint64_t)blocks),
                left_over[b], left_d[b],
                x->by_order ? x->left_box + (size_t)b * 2 * ATRBVH_HIER_SIDE
                            : NULL);
            if (order)
                leaf_prims(t, order, ids,
                           (int64_t)((uint64_t)n * (uint64_t)b /
                                     (uint64_t)blocks),
                           (int64_t)((uint64_t)n * (uint64_t)(b + 1) /
                                     (uint64_t)blocks));
        }
        atrbvh_i_join_arrive(&join);
    }
    /* The second pass: the same stack over every block's leftovers, each
     * arriving with the subtree between the previous leftover and it. */
    for (b = 0; b < blocks; b++) {
        for (k = 0; k < counts[b]; k++) {
            const hier_left *lo = &left_over[b][k];
            const int64_t s = lo->s;
            const int d = left_d[b][k];
            carry.node = lo->node;
            carry.cost = lo->cost;
            carry.box = x->by_order ? x->left_box[(size_t)b * 2 *
                                                      ATRBVH_HIER_SIDE + k]
                        : mode != TOPOLOGY ? t->box[lo->node]
                                           : last;
            carry.size = mode == SIZES ? x->size[lo->node] : 0u;
            while (sp > 0 && st[sp - 1].d > d) {
                sp--;
                if (sp > 0)
                    emit(x, mode, st[sp].s, st[sp - 1].s, st[sp - 1].d, s, d,
                         &st[sp].left, &carry);
                else
                    emit(x, mode, st[sp].s, -1, 0, s, d, &st[sp].left,
                         &carry);
            }
            if (sp == ATRBVH_HIER_SIDE)
                continue; /* keys out of order (see block_pass) */
            st[sp].s = s;
            st[sp].d = d;
            st[sp++].left = carry;
        }
    }
    leaf(x, mode, n - 1, &carry);
    while (sp > 0) {
        sp--;
        if (sp > 0)
            emit(x, mode, st[sp].s, st[sp - 1].s, st[sp - 1].d, n - 1, 0,
                 &st[sp].left, &carry);
        else
            emit(x, mode, st[sp].s, -1, 0, n - 1, 0, &st[sp].left, &carry);
    }
}

/* The topology, and with `p` the refit's values (into `size` when not
 * NULL, else into t->cost, and the collapse decisions into `flat` when
 * not NULL); with `order`, each leaf's primitive.
 * `ready`: the sort stage gathered the leaves and wrote the deltas
 * (sort.c's sort_leaves); `by_order` (with ready, size and order, no
 * ids): it wrote the deltas only, and leaf i's box is t->box[order[i]]
 * (hier_ctx). */
static void hierarchy(const uint64_t *sorted_keys, atrbvh_i_tree *t,
                      int threads, const uint32_t *order,
                      const uint32_t *ids, const atrbvh_cost_params *p,
                      uint32_t *size, unsigned char *flat, int ready,
                      int by_order)
{
    const int64_t n = t->n;
    hier_ctx x;
    int blocks;
    x.t = t;
    x.n = n;
    x.keys = sorted_keys;
    x.p = p;
    x.size = size;
    x.flat = flat;
    x.by_order = NULL;
    x.left_box = NULL;
    if (by_order) { /* (the sort's decision: sort.c, cpu.h) */
        x.by_order = order;
        x.left_box = t->box + n; /* (after primitive n-1's box) */
    }
    t->parent[0] = ATRBVH_U32_MAX;
    if (n == 1) {
        /* one leaf, the root (its box is primitive box 0, in place) */
        hier_sub one;
        if (p)
            leaf(&x, size ? SIZES : flat ? FLAGS : COSTS, 0, &one);
        else
            leaf(&x, TOPOLOGY, 0, &one);
        if (order)
            leaf_prims(t, order, ids, 0, 1);
        return;
    }
    /* blocks taken in turn by the threads (cpu.h) */
    blocks = atrbvh_i_blocks_for(threads, ATRBVH_HIER_BLOCKS);
    if ((int64_t)blocks > n - 1)
        blocks = (int)(n - 1);
    /* (four calls: each inlined for its own mode) */
    if (!p)
        pass(&x, TOPOLOGY, blocks, threads, order, ids, 0);
    else if (size)
        pass(&x, SIZES, blocks, threads, order, ids, ready);
    else if (flat)
        pass(&x, FLAGS, blocks, threads, order, ids, ready);
    else
        pass(&x, COSTS, blocks, threads, order, ids, ready);
}

void atrbvh_i_hierarchy(const uint64_t *sorted_keys, atrbvh_i_tree *t,
                        int threads)
{
    hierarchy(sorted_keys, t, threads, NULL, NULL, NULL, NULL, NULL, 0, 0);
}

void atrbvh_i_hierarchy_refit(const uint64_t *sorted_keys, atrbvh_i_tree *t,
                              const uint32_t *order,
                              const atrbvh_cost_params *p, int threads,
                              uint32_t *size)
{
    hierarchy(sorted_keys, t, threads, order, NULL, p, size, NULL, 0, 0);
}

/* The stage: the tree's arrays (kept for the later stages), the topology,
 * each leaf's original primitive, and the refit (the refit stage then has
 * nothing to compute): boxes and the collapse sizes for an LBVH (which
 * keeps no costs, refit.c), boxes and costs for a tree to optimise. */
atrbvh_status atrbvh_i_cpu_hierarchy(atrbvh_device *dev, atrbvh_i_run *run,
                                     atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    atrbvh_i_tree *t = &c->tree;
    const uint32_t n = run->n;
    const int lbvh = run->cfg->method == ATRBVH_METHOD_LBVH;
    atrbvh_status st;
    (void)dev;
    st = atrbvh_i_cpu_tree_arrays(c, n, error);
    if (st == ATRBVH_OK) /* (the primitive boxes are in its first n) */
        st = atrbvh_i_cpu_tree_values(c, !lbvh, error);
    if (st == ATRBVH_OK && lbvh)
        st = atrbvh_i_cpu_tree_sizes(c, error);
    else if (st == ATRBVH_OK) /* (kept by the optimise stage) */
        st = atrbvh_i_cpu_tree_flags(c, error);
    if (st != ATRBVH_OK)
        return st;
    hierarchy(c->keys, t, run->cfg->threads, c->order, c->ids,
              &run->cfg->cost, lbvh ? c->size : NULL, c->flat,
              c->leaves_ready, c->leaf_boxes_by_order);
    c->leaves_ready = 0;
    c->refitted = 1;
    /* The keys and the sort's scratch are read no more. */
    atrbvh_i_scratch_done(c->scratch, CPU_KEYS);
    atrbvh_i_scratch_done(c->scratch, CPU_TMP_KEYS);
    atrbvh_i_scratch_done(c->scratch, CPU_TMP_ORDER);
    atrbvh_i_scratch_done(c->scratch, CPU_IDS);
    c->keys = NULL;
    c->ids = NULL;
    return ATRBVH_OK;
}
