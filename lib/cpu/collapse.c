/*
 * collapse.c - stages "collapse" and "layout".
 *
 * Collapse: a node becomes a leaf holding all primitives below it when its
 * collapsed cost ct*A*N is strictly cheaper than its best subtree cost
 * (atrbvh_node_cost, which already takes the cheaper option for every
 * child) and N is within max_leaf.  Taking the topmost such node on every
 * path from the root gives the cheapest tree reachable from this topology by
 * collapsing subtrees: the costs are the exact dynamic programme
 * C(v) = min(ci*A(v) + C(l) + C(r), ct*A(v)*N(v)).  (The reference kept only
 * nodes whose parent's both children collapse; we do not.)
 *
 * Pass 1 (bottom-up, tasks) decides for every node whether it is emitted as
 * a leaf if reached and how many output nodes its subtree then takes.
 * Pass 2 (layout, top-down, tasks) writes the depth-first node array and the
 * primitive index array: a node's left child follows it, its right child
 * comes after the left subtree, so every offset is known before descending.
 */
#include "config.h"

#include "internal.h"

#include <string.h>

#define TASK_CUTOFF 4096u
#define IS_LEAF_FLAG ATRBVH_SIZE_LEAF

typedef struct collapse_ctx {
    const atrbvh_i_tree *t;
    const atrbvh_cost_params *p;
    uint32_t *size; /* output nodes of the subtree | IS_LEAF_FLAG */
    atrbvh_node *nodes;
    uint32_t *prims;
} collapse_ctx;

static void decide(collapse_ctx *c, uint32_t node)
{
    const atrbvh_i_tree *t = c->t;
    uint32_t l, r;
    if (atrbvh_i_is_leaf(t, node)) {
        c->size[node] = 1u | IS_LEAF_FLAG;
        return;
    }
    l = t->left[node];
    r = t->right[node];
    if (t->count[node] > TASK_CUTOFF) {
#ifdef _OPENMP
#pragma omp task default(shared) firstprivate(l)
#endif
        decide(c, l);
        decide(c, r);
#ifdef _OPENMP
#pragma omp taskwait
#endif
    } else {
        decide(c, l);
        decide(c, r);
    }
    c->size[node] = atrbvh_collapse_size(c->p, t->box[node], t->count[node],
                                         t->cost[l], t->cost[r], c->size[l],
                                         c->size[r]);
}

/* Writes the primitives under `node`, left to right, from prims[at]:
 * a stackless walk with parent links, so any depth is fine. */
static void gather(const atrbvh_i_tree *t, uint32_t node, uint32_t *out)
{
    uint32_t cur = node, k = 0;
    for (;;) {
        while (!atrbvh_i_is_leaf(t, cur))
            cur = t->left[cur];
        out[k++] = t->leaf_prim[cur - (t->n - 1)];
        /* Climb while we are a right child, then step to the sibling. */
        for (;;) {
            uint32_t up;
            if (cur == node)
                return;
            up = t->parent[cur];
            if (t->left[up] == cur) {
                cur = t->right[up];
                break;
            }
            cur = up;
        }
    }
}

static void emit(collapse_ctx *c, uint32_t node, uint32_t at, uint32_t prim_at)
{
    const atrbvh_i_tree *t = c->t;
    atrbvh_node *out = &c->nodes[at];
    int k;
    for (k = 0; k < 3; k++) {
        out->min[k] = t->box[node].min[k];
        out->max[k] = t->box[node].max[k];
    }
    if (c->size[node] & IS_LEAF_FLAG) {
        out->index = prim_at;
        out->count = t->count[node];
        gather(t, node, c->prims + prim_at);
        return;
    }
    {
        const uint32_t l = t->left[node], r = t->right[node];
        const uint32_t right_at = at + 1 + (c->size[l] & ~IS_LEAF_FLAG);
        const uint32_t right_prim = prim_at + t->count[l];
        out->index = right_at;
        out->count = 0;
        if (t->count[node] > TASK_CUTOFF) {
#ifdef _OPENMP
#pragma omp task default(shared) firstprivate(l, at, prim_at)
#endif
            emit(c, l, at + 1, prim_at);
            emit(c, r, right_at, right_prim);
#ifdef _OPENMP
#pragma omp taskwait
#endif
        } else {
            emit(c, l, at + 1, prim_at);
            emit(c, r, right_at, right_prim);
        }
    }
}

atrbvh_status atrbvh_i_collapse_layout(const atrbvh_i_tree *t,
                                       const atrbvh_i_config *cfg,
                                       atrbvh_bvh *bvh, double *collapse_ms,
                                       double *layout_ms,
                                       uint32_t **capture_size,
                                       atrbvh_error *error)
{
    collapse_ctx c;
    double t0 = atrbvh_i_now_ms(), t1;
    uint32_t node_count;
    c.t = t;
    c.p = &cfg->cost;
    c.size = atrbvh_i_alloc_array(2 * (size_t)t->n - 1, sizeof *c.size);
    if (!c.size)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate the collapse flags");
#ifdef _OPENMP
#pragma omp parallel num_threads(cfg->threads)
#pragma omp single
#endif
    decide(&c, 0);
    node_count = c.size[0] & ~IS_LEAF_FLAG;
    if (capture_size) {
        size_t bytes = (2 * (size_t)t->n - 1) * sizeof *c.size;
        *capture_size = atrbvh_i_malloc(bytes);
        if (!*capture_size) {
            atrbvh_i_free(c.size);
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                                 "cannot allocate the capture");
        }
        memcpy(*capture_size, c.size, bytes);
    }
    t1 = atrbvh_i_now_ms();
    *collapse_ms = t1 - t0;

    bvh->nodes = atrbvh_i_alloc_array(node_count, sizeof *bvh->nodes);
    bvh->prim_indices = atrbvh_i_alloc_array(t->n, sizeof *bvh->prim_indices);
    if (!bvh->nodes || !bvh->prim_indices) {
        atrbvh_i_free(c.size);
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate the output (%lu nodes)",
                             (unsigned long)node_count);
    }
    bvh->node_count = node_count;
    bvh->prim_count = t->n;
    c.nodes = bvh->nodes;
    c.prims = bvh->prim_indices;
#ifdef _OPENMP
#pragma omp parallel num_threads(cfg->threads)
#pragma omp single
#endif
    emit(&c, 0, 0, 0);
    atrbvh_i_free(c.size);
    *layout_ms = atrbvh_i_now_ms() - t1;
    return ATRBVH_OK;
}
