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
 * Otherwise bottom-up in post-order, OpenMP tasks above TASK_CUTOFF
 * primitives.
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

#define TASK_CUTOFF 4096u

typedef struct collapse_ctx {
    const atrbvh_i_tree *t;
    const atrbvh_cost_params *p;
    uint32_t *size; /* output nodes of the subtree | ATRBVH_SIZE_LEAF */
} collapse_ctx;

/* Decides `node`'s subtree; returns its cost. */
static double decide(collapse_ctx *c, uint32_t node)
{
    const atrbvh_i_tree *t = c->t;
    uint32_t l, r;
    double cl, cr, cost;
    int collapsed;
    if (atrbvh_i_is_leaf(t, node)) {
        c->size[node] = 1u | ATRBVH_SIZE_LEAF;
        return atrbvh_refit_leaf_cost(c->p, t->box[node]);
    }
    l = t->left[node];
    r = t->right[node];
    if (t->count[node] > TASK_CUTOFF) {
#ifdef _OPENMP
#pragma omp task default(shared) firstprivate(l)
#endif
        cl = decide(c, l);
        cr = decide(c, r);
#ifdef _OPENMP
#pragma omp taskwait
#endif
    } else {
        cl = decide(c, l);
        cr = decide(c, r);
    }
    c->size[node] = atrbvh_collapse_size(c->p, t->box[node], t->count[node],
                                         cl, cr, c->size[l], c->size[r]);
    cost = atrbvh_node_cost(c->p, atrbvh_box_area(t->box[node]),
                            t->count[node], cl, cr, &collapsed);
    return cost;
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
        /* (nowait: the region's end waits for the tasks; the single's
         * barrier would only be one more thread hand-over) */
#ifdef _OPENMP
#pragma omp parallel num_threads(run->cfg->threads)
#pragma omp single nowait
#endif
        (void)decide(&x, 0);
    }
    run->node_count = c->size[0] & ATRBVH_SIZE_MASK;
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
        atrbvh_i_scratch_release(c->scratch, CPU_BOX);
        c->tree.box = NULL;
    }
    if (c->ranges && run->cfg->method == ATRBVH_METHOD_LBVH &&
        c->scratch->transient) {
        /* The layout of a hierarchy's own tree needs no parent links
         * (cpu.h's ranges) */
        atrbvh_i_scratch_release(c->scratch, CPU_PARENT);
        c->tree.parent = NULL;
    }
    return ATRBVH_OK;
}
