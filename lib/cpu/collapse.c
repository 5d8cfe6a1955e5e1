/*
 * cpu/collapse.c - stage "collapse": for every node, whether it is emitted
 * as a leaf holding all primitives below it when reached, and how many
 * output nodes its subtree then takes (shared/stages.h's
 * atrbvh_collapse_size: the leaf when its collapsed cost ct*A*N is
 * strictly cheaper than its best subtree cost, atrbvh_node_cost, and N is
 * within max_leaf).  Taking the topmost such node on every path from the
 * root gives the cheapest tree reachable from this topology by collapsing
 * subtrees: the costs are the exact dynamic programme
 * C(v) = min(ci*A(v) + C(l) + C(r), ct*A(v)*N(v)).  (The reference kept
 * only nodes whose parent's both children collapse; we do not.)
 *
 * An LBVH's sizes are already there: its refit computed them with the
 * boxes (hierarchy.c's pass, or refit.c's climb_sizes for a caller's
 * tree; the same rule and arithmetic as decide() below); this stage then
 * only releases memory.
 *
 * A tree from the hierarchy stage that the optimise stage restructured
 * comes with every node's decision (c->flat): the hierarchy's pass made
 * them with the costs, and every treelet refresh and write-back since
 * kept them with the costs it wrote (shared/treelet.h's
 * atrbvh_treelet_tree.flat), so only the sizes are left, counted from
 * the root down to the collapsed nodes (count_out, no arithmetic; the
 * nodes below a collapsed one are not visited, nor read by the layout).
 * Measured against deciding, Intel host, docs/bench/abpair.c (a build is
 * about 7% collapse): ATRBVH(9,2) builds 0.969 on dabrovic_sponza, 0.967
 * on sibenik and 0.971 on the dragon at two threads.  tests/test_collapse
 * checks every node's kept decision against the one decided from the
 * optimised tree's costs.  The OpenCL backend counts the same way
 * (cl/kernels.cl's collapse_count).
 *
 * Otherwise (a caller's tree, set_tree) decided, bottom-up in post-order
 * - and counted the same way: the "top" (the nodes of more than
 * `cut` primitives, cpu.h's atrbvh_i_frontier_cut) is cut
 * from the subtrees just below it, the frontier, listed left to right;
 * one parallel loop (dynamic, a subtree at a time) decides the frontier
 * subtrees, then the calling thread decides the top, taking the frontier
 * costs in the same left-to-right order.  One hand-over between threads,
 * where tasks woke a sleeping thread at every spawn (optimise.c says why
 * that costs).  Every node's size and cost are the same whichever thread
 * computes them.
 * The subtree costs are recomputed on the way up (the refit's rule on the
 * same boxes and counts: the same doubles the refit or a treelet
 * write-back stored), so the cost array is not read and the sizes take
 * its memory (backend.c's plan).  The node boxes are read for the last
 * time here: an LBVH's array is released at the end, before the layout
 * allocates the output; an optimised tree's leaf half takes the sizes
 * instead (the layout recomputes what it needs, layout.c).
 */
#include "config.h"

#include "cpu.h"

#include <string.h>

/* Trees smaller than this are decided on one thread. */
#define PARALLEL_MIN 4096u

typedef struct collapse_ctx {
    const atrbvh_i_tree *t;
    const atrbvh_cost_params *p;
    uint32_t *size; /* output nodes of the subtree | ATRBVH_SIZE_LEAF */
    const unsigned char *flat; /* the decisions kept (count_out), or NULL */
    /* the frontier (top_decide): its roots left to right, their costs,
     * and the next one the top's walk takes */
    uint32_t cut;
    uint32_t *list;
    double *cost;
    size_t next;
} collapse_ctx;

/* Internal node `node`, its children's costs cl and cr (their sizes
 * set): its size; returns its cost. */
static double decided(collapse_ctx *c, uint32_t node, double cl, double cr)
{
    const atrbvh_i_tree *t = c->t;
    const uint32_t l = t->left[node], r = t->right[node];
    int collapsed;
    c->size[node] = atrbvh_collapse_size(c->p, t->box[node], t->count[node],
                                         cl, cr, c->size[l], c->size[r]);
    return atrbvh_node_cost(c->p, atrbvh_box_area(t->box[node]),
                            t->count[node], cl, cr, &collapsed);
}

/* Decides `node`'s subtree; returns its cost. */
static double decide(collapse_ctx *c, uint32_t node)
{
    const atrbvh_i_tree *t = c->t;
    double cl;
    if (atrbvh_i_is_leaf(t, node)) {
        c->size[node] = 1u | ATRBVH_SIZE_LEAF;
        return atrbvh_refit_leaf_cost(c->p, t->box[node]);
    }
    /* The node's own box and count are read after both subtrees, the
     * right child after the left subtree: fetched ahead (the ids of an
     * optimised tree are scattered; no effect on any value). */
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(&t->box[node]);
    __builtin_prefetch(&t->count[node]);
    __builtin_prefetch(&t->box[t->right[node]]);
#endif
    cl = decide(c, t->left[node]);
    return decided(c, node, cl, decide(c, t->right[node]));
}

/* With the decisions kept (an optimised tree: c->flat, optimise.c): the
 * size of `node`'s subtree counted from them, no node below a collapsed
 * one visited (nor its size set: the layout reads none of them; tree
 * leaves are collapsed).  A node of at most `done` primitives that does
 * not collapse was counted already (the frontier, for the top's count:
 * `done` the cut; 0 otherwise). */
static uint32_t count_out(collapse_ctx *c, uint32_t node, uint32_t done)
{
    const atrbvh_i_tree *t = c->t;
    const unsigned flat = c->flat[node];
    uint32_t l = 0, r = 0;
    if (!flat) {
        if (t->count[node] <= done)
            return c->size[node];
        l = count_out(c, t->left[node], done);
        r = count_out(c, t->right[node], done);
    }
    return c->size[node] = atrbvh_size_counted(flat, l, r);
}

/* The frontier below `node` (a top node: more than c->cut primitives),
 * left to right, into c->list from *k; 0 when it does not fit in cap. */
static int frontier(collapse_ctx *c, uint32_t node, size_t *k, size_t cap)
{
    const atrbvh_i_tree *t = c->t;
    int side;
    for (side = 0; side < 2; side++) {
        const uint32_t x = side ? t->right[node] : t->left[node];
        if (!atrbvh_i_is_leaf(t, x) && t->count[x] > c->cut) {
            if (!frontier(c, x, k, cap))
                return 0;
        } else {
            if (*k == cap)
                return 0;
            c->list[(*k)++] = x;
        }
    }
    return 1;
}

/* decide() over the top, the frontier's costs taken in order. */
static double top_decide(collapse_ctx *c, uint32_t node)
{
    const atrbvh_i_tree *t = c->t;
    double cl;
    if (atrbvh_i_is_leaf(t, node) || t->count[node] <= c->cut)
        return c->cost[c->next++];
    cl = top_decide(c, t->left[node]);
    return decided(c, node, cl, top_decide(c, t->right[node]));
}

/* Every node's size: the frontier on the threads, then the top; on one
 * thread when the tree is small or the frontier does not fit.  With the
 * decisions kept, counted (count_out), else decided (decide). */
static atrbvh_status decide_all(collapse_ctx *c, atrbvh_i_scratch *scratch,
                                int threads, atrbvh_error *error)
{
    const uint32_t root_count = c->t->count[0];
    const size_t cap = atrbvh_i_frontier_cap(threads);
    atrbvh_i_join join = {0};
    size_t k = 0;
    int64_t i;
    unsigned char *block;
    c->cut = atrbvh_i_frontier_cut(root_count, threads);
    if (threads < 2 || root_count < PARALLEL_MIN || c->cut < 1u) {
        if (c->flat)
            (void)count_out(c, 0, 0);
        else
            (void)decide(c, 0);
        return ATRBVH_OK;
    }
    /* cap roots and their costs (cap <= 2^31: no overflow) */
    block = atrbvh_i_scratch_get(scratch, CPU_OPTIMISE,
                                 cap * (sizeof(double) + sizeof(uint32_t)), 1);
    if (!block)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate the collapse's frontier of %lu "
                             "subtrees",
                             (unsigned long)cap);
    c->cost = (double *)(void *)block;
    c->list = (uint32_t *)(void *)(block + cap * sizeof(double));
    if (!frontier(c, 0, &k, cap) || k < 2u) {
        if (c->flat)
            (void)count_out(c, 0, 0);
        else
            (void)decide(c, 0);
        return ATRBVH_OK;
    }
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1) nowait
#endif
        for (i = 0; i < (int64_t)k; i++) {
            if (c->flat)
                (void)count_out(c, c->list[i], 0);
            else
                c->cost[i] = decide(c, c->list[i]);
        }
        atrbvh_i_join_arrive(&join);
    }
    c->next = 0;
    if (c->flat)
        (void)count_out(c, 0, c->cut);
    else
        (void)top_decide(c, 0);
    return ATRBVH_OK;
}

/* An LBVH reading its leaf boxes in place reads its node box slot no more
 * (the layout recomputes the boxes): the slot's block becomes the output's
 * nodes when it holds them with at most an eighth to spare, its first n
 * boxes' pages already touched by the bounds stage.  A new block for the
 * output would be fresh pages, which the system zeroes as they are first
 * written: at 10^7 triangles the layout took up to a fifth longer so.  The
 * slot's size for the next build is learned here (backend.c). */
static void take_box_slot(atrbvh_i_cpu_run *c, atrbvh_i_run *run)
{
    size_t bytes, need;
    void *block = atrbvh_i_scratch_take(c->scratch, CPU_BOX, &bytes);
    const int fits =
        atrbvh_i_mul_size(run->node_count, sizeof(atrbvh_node), &need) &&
        need <= bytes;
    if (c->device)
        c->device->lbvh_nodes_per_1024 =
            (uint32_t)((uint64_t)run->node_count * 1024 / run->n);
    if (block && fits && bytes - need <= bytes / 8) {
        run->out_block = block;
        run->out_block_bytes = bytes;
    } else {
        atrbvh_i_free(block);
    }
}

atrbvh_status atrbvh_i_cpu_collapse(atrbvh_device *dev, atrbvh_i_run *run,
                                    atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    collapse_ctx x;
    (void)dev;
    atrbvh_i_scratch_done(c->scratch, CPU_COST);
    c->tree.cost = NULL;
    if (run->cfg->method != ATRBVH_METHOD_LBVH || !c->size) {
        /* (an LBVH's refit computed the sizes: hierarchy.c, refit.c) */
        atrbvh_status st = atrbvh_i_cpu_tree_sizes(c, error);
        if (st != ATRBVH_OK)
            return st;
        x.t = &c->tree;
        x.p = &run->cfg->cost;
        x.size = c->size;
        x.flat = c->flat;
        st = decide_all(&x, c->scratch, run->cfg->threads, error);
        if (st != ATRBVH_OK)
            return st;
    }
    run->node_count = c->size[0] & ATRBVH_SIZE_MASK;
    if (c->flat && !run->captured) { /* (the capture reads them: layout) */
        atrbvh_i_scratch_done(c->scratch, CPU_FLAT);
        c->flat = NULL;
    }
    if (!c->kept_ids && run->cfg->method != ATRBVH_METHOD_LBVH &&
        c->scratch->transient) {
        /* An optimised tree's internal boxes are read by the layout (a
         * treelet root keeps its old box), its leaves' are the
         * primitives': the sizes move into the leaves' half of the box
         * array (4 of its 24 bytes per leaf) and the cost slot goes.  A
         * handle keeps it instead: re-optimising an animation frame by
         * frame then allocates nothing of the primitive count. */
        uint32_t *moved = (uint32_t *)(void *)(c->tree.box + (run->n - 1));
        memcpy(moved, c->size, (2 * (size_t)run->n - 1) * sizeof *moved);
        c->size = moved;
        c->sizes_in_leaf_boxes = 1;
        atrbvh_i_scratch_release(c->scratch, CPU_SIZE);
    } else if (!c->kept_ids && run->cfg->method == ATRBVH_METHOD_LBVH) {
        /* the layout recomputes the boxes (layout.c says when it can) */
        if (c->leaf_boxes_by_order)
            take_box_slot(c, run);
        else
            atrbvh_i_scratch_release(c->scratch, CPU_BOX);
        c->tree.box = NULL;
    }
    if (c->ranges && run->cfg->method == ATRBVH_METHOD_LBVH &&
        c->scratch->transient) {
        /* The layout of a hierarchy's own tree needs no parent links
         * (cpu.h's ranges) */
        atrbvh_i_scratch_release(c->scratch, CPU_PARENT);
        c->tree.parent = NULL;
    } else if (c->scratch->transient && !run->captured &&
               (!run->cfg->cost.collapse ||
                (run->cfg->cost.max_leaf >= 1u &&
                 run->cfg->cost.max_leaf <= ATRBVH_I_GATHER_MAX))) {
        /* Nor any other tree's whose collapsed leaves are that small:
         * the layout finds a leaf's primitives by the counts (layout.c;
         * a handle keeps the links for the tree's next use, a capture
         * reads them) */
        atrbvh_i_scratch_release(c->scratch, CPU_PARENT);
        c->tree.parent = NULL;
    }
    return ATRBVH_OK;
}
