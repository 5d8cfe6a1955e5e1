/*
 * capture.c - a stage's output as the public capture callback sees it
 * (atrbvh_capture_fn): the arrays of the backend's copy (atrbvh_i_capture)
 * named, typed and shaped as docs/stages.md documents them, the same for
 * every backend.
 */
#include "config.h"

#include "internal.h"

#include <stdio.h>
#include <string.h>

#define MAX_ARRAYS 12

typedef struct arrays {
    atrbvh_array a[MAX_ARRAYS];
    size_t n;
} arrays;

static void add(arrays *x, const char *name, atrbvh_dtype dtype, size_t rows,
                size_t cols, const void *data)
{
    atrbvh_array *a = &x->a[x->n++];
    a->name = name;
    a->dtype = dtype;
    a->rows = rows;
    a->cols = cols;
    a->data = data;
}

/* A tree's arrays (values: box and cost too). */
static void add_tree(arrays *x, const atrbvh_i_tree *t, int values)
{
    const size_t n = t->n, nodes = 2 * n - 1, inner = n > 1 ? n - 1 : 0;
    add(x, "left", ATRBVH_DTYPE_U32, inner, 1, t->left);
    add(x, "right", ATRBVH_DTYPE_U32, inner, 1, t->right);
    add(x, "parent", ATRBVH_DTYPE_U32, nodes, 1, t->parent);
    add(x, "count", ATRBVH_DTYPE_U32, nodes, 1, t->count);
    add(x, "leaf_prim", ATRBVH_DTYPE_U32, n, 1, t->leaf_prim);
    if (values) {
        add(x, "box", ATRBVH_DTYPE_F32, nodes, 6, t->box);
        add(x, "cost", ATRBVH_DTYPE_F64, nodes, 1, t->cost);
    }
}

atrbvh_status atrbvh_i_capture_emit(atrbvh_capture_fn fn, void *user,
                                    atrbvh_stage stage, unsigned round,
                                    const atrbvh_i_capture *c,
                                    const atrbvh_i_run *run,
                                    atrbvh_error *error)
{
    atrbvh_stage_output out;
    arrays x;
    char name[32];
    float *node_boxes = NULL;
    uint32_t *node_links = NULL;
    double frame[6];
    const size_t n = c->n;
    int k, stop;

    memset(&x, 0, sizeof x);
    switch (stage) {
    case ATRBVH_STAGE_BOUNDS:
        add(&x, "prim_boxes", ATRBVH_DTYPE_F32, n, 6, c->prim_boxes);
        add(&x, "scene_box", ATRBVH_DTYPE_F32, 1, 6, &c->scene);
        add(&x, "centroid_box", ATRBVH_DTYPE_F32, 1, 6, &c->centroids);
        break;
    case ATRBVH_STAGE_MORTON:
        for (k = 0; k < 3; k++) {
            frame[k] = run->morton_lo[k];
            frame[3 + k] = run->morton_scale[k];
        }
        add(&x, "morton_frame", ATRBVH_DTYPE_F64, 2, 3, frame);
        add(&x, "keys", ATRBVH_DTYPE_U64, n, 1, c->keys);
        break;
    case ATRBVH_STAGE_SORT:
        add(&x, "sorted_keys", ATRBVH_DTYPE_U64, n, 1, c->sorted_keys);
        add(&x, "order", ATRBVH_DTYPE_U32, n, 1, c->order);
        break;
    case ATRBVH_STAGE_HIERARCHY:
        add_tree(&x, &c->hierarchy, 0);
        break;
    case ATRBVH_STAGE_REFIT:
        add_tree(&x, &c->refit, 1);
        break;
    case ATRBVH_STAGE_OPTIMISE:
        add_tree(&x, &c->optimise, 1);
        break;
    case ATRBVH_STAGE_COLLAPSE:
        add(&x, "collapse_size", ATRBVH_DTYPE_U32, 2 * n - 1, 1,
            c->collapse_size);
        break;
    case ATRBVH_STAGE_LAYOUT: {
        /* atrbvh_node mixes floats and integers: two arrays. */
        size_t i, m = run->node_count;
        node_boxes = atrbvh_i_alloc_array(m, 6 * sizeof *node_boxes);
        node_links = atrbvh_i_alloc_array(m, 2 * sizeof *node_links);
        if (!node_boxes || !node_links) {
            atrbvh_i_free(node_boxes);
            atrbvh_i_free(node_links);
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                                 "cannot allocate the layout capture");
        }
        for (i = 0; i < m; i++) {
            for (k = 0; k < 3; k++) {
                node_boxes[6 * i + k] = run->nodes[i].min[k];
                node_boxes[6 * i + 3 + k] = run->nodes[i].max[k];
            }
            node_links[2 * i] = run->nodes[i].index;
            node_links[2 * i + 1] = run->nodes[i].count;
        }
        add(&x, "node_boxes", ATRBVH_DTYPE_F32, m, 6, node_boxes);
        add(&x, "node_index_count", ATRBVH_DTYPE_U32, m, 2, node_links);
        add(&x, "prim_indices", ATRBVH_DTYPE_U32, run->n, 1,
            run->prim_indices);
        break;
    }
    default:
        return ATRBVH_OK;
    }
    if (round)
        snprintf(name, sizeof name, "%s_round%u", atrbvh_stage_name(stage),
                 round);
    else
        snprintf(name, sizeof name, "%s", atrbvh_stage_name(stage));
    memset(&out, 0, sizeof out);
    out.size = sizeof out;
    out.stage = stage;
    out.round = round;
    out.name = name;
    out.array_count = x.n;
    out.arrays = x.a;
    stop = fn(&out, user);
    atrbvh_i_free(node_boxes);
    atrbvh_i_free(node_links);
    if (stop)
        return atrbvh_i_fail(error, ATRBVH_ERR_CANCELLED, (uint64_t)-1,
                             "cancelled by the capture callback after %s",
                             name);
    return ATRBVH_OK;
}
