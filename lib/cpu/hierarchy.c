/*
 * hierarchy.c - stage "hierarchy": the binary radix tree of Karras,
 * "Maximizing Parallelism in the Construction of BVHs, Octrees, and k-d
 * Trees" (HPG 2012).  One independent item per internal node; the
 * arithmetic (delta with -1 out of range and the index tie-break for equal
 * keys, the range search, the split search) is atrbvh_karras_node in
 * shared/arith.h, shared with the OpenCL backend.
 */
#include "config.h"

#include "internal.h"

#include <string.h>

atrbvh_status atrbvh_i_tree_alloc(atrbvh_i_tree *t, uint32_t n)
{
    size_t nodes = 2 * (size_t)n - 1, inner = n > 1 ? (size_t)n - 1 : 1;
    memset(t, 0, sizeof *t);
    t->n = n;
    t->left = atrbvh_i_alloc_array(inner, sizeof *t->left);
    t->right = atrbvh_i_alloc_array(inner, sizeof *t->right);
    t->parent = atrbvh_i_alloc_array(nodes, sizeof *t->parent);
    t->count = atrbvh_i_alloc_array(nodes, sizeof *t->count);
    t->box = atrbvh_i_alloc_array(nodes, sizeof *t->box);
    t->cost = atrbvh_i_alloc_array(nodes, sizeof *t->cost);
    t->leaf_prim = atrbvh_i_alloc_array(n, sizeof *t->leaf_prim);
    if (!t->left || !t->right || !t->parent || !t->count || !t->box ||
        !t->cost || !t->leaf_prim) {
        atrbvh_i_tree_free(t);
        return ATRBVH_ERR_NOMEM;
    }
    return ATRBVH_OK;
}

void atrbvh_i_tree_free(atrbvh_i_tree *t)
{
    atrbvh_i_free(t->left);
    atrbvh_i_free(t->right);
    atrbvh_i_free(t->parent);
    atrbvh_i_free(t->count);
    atrbvh_i_free(t->box);
    atrbvh_i_free(t->cost);
    atrbvh_i_free(t->leaf_prim);
    memset(t, 0, sizeof *t);
}

void atrbvh_i_hierarchy(const uint64_t *sorted_keys, atrbvh_i_tree *t,
                        int threads)
{
    const int64_t n = t->n;
    int64_t i;
    t->parent[0] = ATRBVH_NONE;
    if (n == 1) {
        t->count[0] = 1;
        return;
    }
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static)
#else
    (void)threads;
#endif
    for (i = 0; i < n - 1; i++) {
        uint32_t l, r, c;
        atrbvh_karras_node(sorted_keys, n, i, &l, &r, &c);
        t->left[i] = l;
        t->right[i] = r;
        t->count[i] = c;
        t->parent[l] = (uint32_t)i;
        t->parent[r] = (uint32_t)i;
        t->count[n - 1 + i] = 1;
    }
    t->count[2 * n - 2] = 1;
}
