/*
 * refit.c - stage "refit": leaf boxes from the primitive boxes, then boxes,
 * primitive counts and SAH costs bottom-up.
 *
 * The CPU reference walks the tree in post-order with OpenMP tasks: a node
 * is computed after both children, left cost first, so the result is the
 * same whichever thread computes what.  (The OpenCL backend uses the
 * atomic-counter walk; the arithmetic is atrbvh_node_cost in both.)
 */
#include "config.h"

#include "cpu.h"

/* Subtrees smaller than this are refitted by one task, serially. */
#define TASK_CUTOFF 4096u

static void refit_node(atrbvh_i_tree *t, uint32_t node,
                       const atrbvh_cost_params *p)
{
    uint32_t l, r;
    if (atrbvh_i_is_leaf(t, node))
        return;
    l = t->left[node];
    r = t->right[node];
    if (t->count[node] > TASK_CUTOFF) {
#ifdef _OPENMP
#pragma omp task default(shared) firstprivate(l)
#endif
        refit_node(t, l, p);
        refit_node(t, r, p);
#ifdef _OPENMP
#pragma omp taskwait
#endif
    } else {
        refit_node(t, l, p);
        refit_node(t, r, p);
    }
    atrbvh_refit_node(p, t->box[l], t->count[l], t->cost[l], t->box[r],
                      t->count[r], t->cost[r], &t->box[node], &t->count[node],
                      &t->cost[node]);
}

void atrbvh_i_refit(atrbvh_i_tree *t, const atrbvh_box *prim_boxes,
                    const uint32_t *order, const atrbvh_cost_params *p,
                    int threads)
{
    const int64_t n = t->n;
    int64_t i;
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#else
    (void)threads;
#endif
    {
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
        for (i = 0; i < n; i++) {
            const uint32_t leaf = (uint32_t)(n - 1 + i);
            t->box[leaf] = prim_boxes[order[i]];
            t->count[leaf] = 1;
            t->cost[leaf] = atrbvh_refit_leaf_cost(p, t->box[leaf]);
        }
#ifdef _OPENMP
#pragma omp single
#endif
        refit_node(t, 0, p);
    }
}

/* The stage: boxes, counts and costs of the tree. */
atrbvh_status atrbvh_i_cpu_refit(atrbvh_device *dev, atrbvh_i_run *run,
                                 atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    (void)dev;
    (void)error;
    atrbvh_i_refit(&c->tree, c->boxes, c->order, &run->cfg->cost,
                   run->cfg->threads);
    return ATRBVH_OK;
}
