/*
 * cpu/layout.c - stage "layout": the public depth-first node array and the
 * primitive index array, top-down from the collapse decisions: a node's
 * left child follows it, its right child comes after the left subtree, so
 * every offset is known before descending (OpenMP tasks above
 * TASK_CUTOFF primitives).
 */
#include "config.h"

#include "cpu.h"

#define TASK_CUTOFF 4096u

typedef struct layout_ctx {
    const atrbvh_i_tree *t;
    const uint32_t *size; /* collapse: nodes of the subtree | leaf flag */
    atrbvh_node *nodes;
    uint32_t *prims;
} layout_ctx;

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

/* Writes `node` at output position `at` with its primitives from
 * `prim_at` (shared/stages.h's placement rule), then its children. */
static void emit(layout_ctx *c, uint32_t node, uint32_t at, uint32_t prim_at)
{
    const atrbvh_i_tree *t = c->t;
    const int leaf = (c->size[node] & ATRBVH_SIZE_LEAF) != 0;
    const uint32_t l = leaf ? 0 : t->left[node], r = leaf ? 0 : t->right[node];
    c->nodes[at] = atrbvh_layout_node(t->box[node], c->size[node],
                                      t->count[node], at, prim_at,
                                      leaf ? 0 : c->size[l]);
    if (leaf) {
        gather(t, node, c->prims + prim_at);
        return;
    }
    {
        const uint32_t right_at = atrbvh_layout_right_pos(at, c->size[l]);
        const uint32_t right_prim =
            atrbvh_layout_right_prim(prim_at, t->count[l]);
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

atrbvh_status atrbvh_i_cpu_layout(atrbvh_device *dev, atrbvh_i_run *run,
                                  atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    layout_ctx x;
    (void)dev;
    (void)error;
    x.t = &c->tree;
    x.size = c->size;
    x.nodes = run->nodes;
    x.prims = run->prim_indices;
#ifdef _OPENMP
#pragma omp parallel num_threads(run->cfg->threads)
#pragma omp single
#endif
    emit(&x, 0, 0, 0);
    return ATRBVH_OK;
}
