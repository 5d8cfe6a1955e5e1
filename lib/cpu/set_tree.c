/*
 * cpu/set_tree.c - atrbvh_reoptimise's replacement for the morton, sort
 * and hierarchy stages: the caller's binary tree goes into the same
 * scratch arrays the hierarchy stage fills, so refit, optimise, collapse
 * and layout run unchanged on it.
 */
#include "config.h"

#include "cpu.h"

#include <string.h>

atrbvh_status atrbvh_i_cpu_set_tree(atrbvh_device *dev, atrbvh_i_run *run,
                                    const uint32_t *left,
                                    const uint32_t *right,
                                    const uint32_t *leaf_prim,
                                    atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    atrbvh_i_tree *t = &c->tree;
    const uint32_t n = run->n;
    int64_t i;
    atrbvh_status st;
    (void)dev;
    /* (a tree of the caller's: the leaf boxes are gathered, cpu.h) */
    st = atrbvh_i_cpu_all_node_boxes(c, run, error);
    if (st == ATRBVH_OK)
        st = atrbvh_i_cpu_tree_arrays(c, n, error);
    if (st != ATRBVH_OK)
        return st;
    c->order = atrbvh_i_scratch_get(c->scratch, CPU_ORDER, n,
                                    sizeof *c->order);
    if (!c->order)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate the tree for %lu primitives",
                             (unsigned long)n);
    c->ids = NULL;
    t->parent[0] = ATRBVH_U32_MAX;
    if (n > 1) {
        memcpy(t->left, left, (n - 1) * sizeof *left);
        memcpy(t->right, right, (n - 1) * sizeof *right);
    }
    memcpy(t->leaf_prim, leaf_prim, n * sizeof *leaf_prim);
    /* The bounds stage's boxes are in input order: leaf p's is entry
     * leaf_prim[p]. */
    memcpy(c->order, leaf_prim, n * sizeof *leaf_prim);
#ifdef _OPENMP
#pragma omp parallel for num_threads(run->cfg->threads) schedule(static)
#endif
    for (i = 0; i < (int64_t)n - 1; i++) {
        t->parent[t->left[i]] = (uint32_t)i;
        t->parent[t->right[i]] = (uint32_t)i;
    }
    return ATRBVH_OK;
}
