/*
 * hierarchy.c - stage "hierarchy": the binary radix tree of Karras,
 * "Maximizing Parallelism in the Construction of BVHs, Octrees, and k-d
 * Trees" (HPG 2012).  One independent item per internal node; the
 * arithmetic (delta with -1 out of range and the index tie-break for equal
 * keys, the range search, the split search) is atrbvh_karras_node in
 * shared/arith.h, shared with the OpenCL backend.
 */
#include "config.h"

#include "cpu.h"

void atrbvh_i_hierarchy(const uint64_t *sorted_keys, atrbvh_i_tree *t,
                        int threads)
{
    const int64_t n = t->n;
    int64_t i;
    t->parent[0] = ATRBVH_U32_MAX;
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

/* The stage: the tree's arrays (kept for the later stages), the topology,
 * and each leaf's original primitive. */
atrbvh_status atrbvh_i_cpu_hierarchy(atrbvh_device *dev, atrbvh_i_run *run,
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
    if (!t->left || !t->right || !t->parent || !t->count || !t->box ||
        !t->cost || !t->leaf_prim)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate the tree for %lu primitives",
                             (unsigned long)n);
    atrbvh_i_hierarchy(c->keys, t, run->cfg->threads);
#ifdef _OPENMP
#pragma omp parallel for num_threads(run->cfg->threads) schedule(static)
#endif
    for (i = 0; i < (int64_t)n; i++)
        t->leaf_prim[i] = c->ids ? c->ids[c->order[i]] : c->order[i];
    return ATRBVH_OK;
}
