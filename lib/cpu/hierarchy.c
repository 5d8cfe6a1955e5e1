/*
 * hierarchy.c - stage "hierarchy": the binary radix tree of Karras,
 * "Maximizing Parallelism in the Construction of BVHs, Octrees, and k-d
 * Trees" (HPG 2012), numbered as Karras numbers it.  The tie rule for
 * equal keys (positions told apart, atrbvh_karras_delta in shared/arith.h)
 * decides the tree and is the OpenCL backend's, which runs these same two
 * passes (cl/kernels.cl: hierarchy_block, hierarchy).
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
 * per contiguous block of splits (one block per thread).  A node is
 * written as soon as both neighbours are known; the rest of each block -
 * its prefix minima (no left neighbour in the block) and what is left on
 * its stack (no right neighbour) - are strictly monotone in delta, so at
 * most ATRBVH_HIER_SIDE each, and a second, serial pass over these
 * leftovers of every block, in position order, finds their neighbours:
 * the nearest smaller split of a leftover is itself a leftover.  Deltas
 * lie in -1 .. 96, so no stack is deeper than 97.
 */
#include "config.h"

#include "cpu.h"

/* Strictly monotone runs of deltas in 0 .. 95 (clz of distinct keys
 * 0 .. 63, equal keys 64 .. 95): at most 96 entries. */
#define ATRBVH_HIER_SIDE 128
/* Blocks (threads) of the first pass: its leftovers live on the stack. */
#define ATRBVH_HIER_BLOCKS 16

typedef struct hier_entry {
    int64_t s; /* split position */
    int d;     /* its delta       */
} hier_entry;

/* Writes internal node s (its split) from its neighbours ps (-1: none)
 * and ns (n-1: none) and their deltas. */
static inline void emit(atrbvh_i_tree *t, int64_t n, int64_t s, int64_t ps,
                        int dps, int64_t ns, int dns)
{
    uint32_t lc, rc, c;
    const uint32_t id = atrbvh_hier_node(n, s, ps, dps, ns, dns, &lc, &rc, &c);
    t->left[id] = lc;
    t->right[id] = rc;
    t->count[id] = c;
    t->parent[lc] = id;
    t->parent[rc] = id;
}

/* The first pass over the splits lo .. hi-1.  Leftovers (their positions,
 * ascending) go to `out`; returns how many. */
static uint32_t block_pass(const uint64_t *keys, atrbvh_i_tree *t, int64_t n,
                           int64_t lo, int64_t hi, int64_t *out)
{
    hier_entry st[ATRBVH_HIER_SIDE];
    uint32_t sp = 0, nout = 0, k;
    int64_t s;
    for (s = lo; s < hi; s++) {
        const int d = atrbvh_karras_delta(keys, n, s, s + 1);
        t->count[n - 1 + s] = 1;
        while (sp > 0 && st[sp - 1].d > d) {
            const hier_entry x = st[--sp];
            if (sp > 0)
                emit(t, n, x.s, st[sp - 1].s, st[sp - 1].d, s, d);
        }
        if (sp == 0 && nout < ATRBVH_HIER_SIDE)
            out[nout++] = s; /* a prefix minimum */
        if (sp == ATRBVH_HIER_SIDE)
            continue; /* keys out of order: cannot happen when sorted */
        st[sp++].s = s;
        st[sp - 1].d = d;
    }
    /* st[0] is the last prefix minimum, already out. */
    for (k = 1; k < sp; k++)
        out[nout++] = st[k].s;
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

/* The topology; with `order`, also each leaf's primitive (in the same
 * parallel region: one thread wake-up less per build). */
static void hierarchy(const uint64_t *sorted_keys, atrbvh_i_tree *t,
                      int threads, const uint32_t *order,
                      const uint32_t *ids)
{
    const int64_t n = t->n;
    int64_t left_over[ATRBVH_HIER_BLOCKS][2 * ATRBVH_HIER_SIDE];
    uint32_t counts[ATRBVH_HIER_BLOCKS];
    hier_entry st[ATRBVH_HIER_SIDE];
    int blocks, b;
    uint32_t sp = 0, k;
    t->parent[0] = ATRBVH_U32_MAX;
    t->count[2 * n - 2] = 1;
    if (n == 1) {
        if (order)
            leaf_prims(t, order, ids, 0, 1);
        return;
    }
    blocks = threads < 1 ? 1 : threads;
    if (blocks > ATRBVH_HIER_BLOCKS)
        blocks = ATRBVH_HIER_BLOCKS;
    if ((int64_t)blocks > n - 1)
        blocks = (int)(n - 1);
#ifdef _OPENMP
#pragma omp parallel for num_threads(blocks) schedule(static, 1)
#endif
    for (b = 0; b < blocks; b++) {
        counts[b] = block_pass(
            sorted_keys, t, n,
            (int64_t)((uint64_t)(n - 1) * (uint64_t)b / (uint64_t)blocks),
            (int64_t)((uint64_t)(n - 1) * (uint64_t)(b + 1) /
                      (uint64_t)blocks),
            left_over[b]);
        if (order)
            leaf_prims(t, order, ids,
                       (int64_t)((uint64_t)n * (uint64_t)b / (uint64_t)blocks),
                       (int64_t)((uint64_t)n * (uint64_t)(b + 1) /
                                 (uint64_t)blocks));
    }
    /* The second pass: the same stack over every block's leftovers. */
    for (b = 0; b < blocks; b++) {
        for (k = 0; k < counts[b]; k++) {
            const int64_t s = left_over[b][k];
            const int d = atrbvh_karras_delta(sorted_keys, n, s, s + 1);
            while (sp > 0 && st[sp - 1].d > d) {
                const hier_entry x = st[--sp];
                if (sp > 0)
                    emit(t, n, x.s, st[sp - 1].s, st[sp - 1].d, s, d);
                else
                    emit(t, n, x.s, -1, 0, s, d);
            }
            if (sp == ATRBVH_HIER_SIDE)
                continue; /* keys out of order (see block_pass) */
            st[sp].s = s;
            st[sp++].d = d;
        }
    }
    while (sp > 0) {
        const hier_entry x = st[--sp];
        if (sp > 0)
            emit(t, n, x.s, st[sp - 1].s, st[sp - 1].d, n - 1, 0);
        else
            emit(t, n, x.s, -1, 0, n - 1, 0);
    }
}

void atrbvh_i_hierarchy(const uint64_t *sorted_keys, atrbvh_i_tree *t,
                        int threads)
{
    hierarchy(sorted_keys, t, threads, NULL, NULL);
}

/* The stage: the tree's arrays (kept for the later stages), the topology,
 * and each leaf's original primitive. */
atrbvh_status atrbvh_i_cpu_hierarchy(atrbvh_device *dev, atrbvh_i_run *run,
                                     atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    atrbvh_i_tree *t = &c->tree;
    const uint32_t n = run->n;
    atrbvh_status st;
    (void)dev;
    st = atrbvh_i_cpu_tree_arrays(c, n, error);
    if (st != ATRBVH_OK)
        return st;
    hierarchy(c->keys, t, run->cfg->threads, c->order, c->ids);
    /* The keys and the sort's scratch are read no more. */
    atrbvh_i_scratch_done(c->scratch, CPU_KEYS);
    atrbvh_i_scratch_done(c->scratch, CPU_TMP_KEYS);
    atrbvh_i_scratch_done(c->scratch, CPU_TMP_ORDER);
    atrbvh_i_scratch_done(c->scratch, CPU_IDS);
    c->keys = NULL;
    c->ids = NULL;
    return ATRBVH_OK;
}
