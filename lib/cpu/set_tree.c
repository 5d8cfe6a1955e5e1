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
    atrbvh_i_scratch *s = c->scratch;
    atrbvh_i_tree *t = &c->tree;
    const uint32_t n = run->n;
    const size_t nodes = 2 * (size_t)n - 1, inner = n > 1 ? n - 1 : 1;
    int64_t i;
    (void)dev;
    t->n = n;
    t->left = atrbvh_i_scratch_get(s, CPU_LEFT, inner, sizeof *t->left);
    t->right = atrbvh_i_scratch_get(s, CPU_RIGHT, inner, sizeof *t->right);
    t->parent = atrbvh_i_scratch_get(s, CPU_PARENT, nodes, sizeof *t->parent);
    t->count = atrbvh_i_scratch_get(s, CPU_COUNT, nodes, sizeof *t->count);
    t->box = atrbvh_i_scratch_get(s, CPU_BOX, nodes, sizeof *t->box);
    t->cost = atrbvh_i_scratch_get(s, CPU_COST, nodes, sizeof *t->cost);
    t->leaf_prim = atrbvh_i_scratch_get(s, CPU_LEAF_PRIM, n,
                                        sizeof *t->leaf_prim);
    c->order = atrbvh_i_scratch_get(s, CPU_ORDER, n, sizeof *c->order);
    if (!t->left || !t->right || !t->parent || !t->count || !t->box ||
        !t->cost || !t->leaf_prim || !c->order)
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
