/*
 * cpu/backend.c - the CPU backend's table: a build's arrays live in the
 * device's scratch (kept between builds), the stages are the OpenMP files
 * beside this one.  Ray batches run the OpenMP queries of lib/traverse.c.
 */
#include "config.h"

#include "cpu.h"

#include <string.h>

#define NO_INDEX ((uint64_t)-1)

static atrbvh_status cpu_open(atrbvh_device *dev, const char *spec,
                              atrbvh_error *error)
{
    if (spec && *spec)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "the CPU device takes no name (got \"%s\")",
                             spec);
    strcpy(dev->name, "cpu");
    return ATRBVH_OK;
}

static void cpu_close(atrbvh_device *dev)
{
    (void)dev;
}

static atrbvh_status cpu_begin(atrbvh_device *dev, atrbvh_i_run *run,
                               atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = atrbvh_i_malloc(sizeof *c);
    if (!c)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate the build state");
    memset(c, 0, sizeof *c);
    c->scratch = &dev->scratch;
    run->state = c;
    return ATRBVH_OK;
}

static void cpu_end(atrbvh_device *dev, atrbvh_i_run *run)
{
    (void)dev;
    atrbvh_i_free(run->state);
    run->state = NULL;
}

static atrbvh_status cpu_set_prims(atrbvh_device *dev, atrbvh_i_run *run,
                                   const atrbvh_box *boxes,
                                   const uint32_t *ids, atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    (void)dev;
    /* The pipeline's boxes may be the scratch the bounds stage wrote;
     * memmove keeps that case right.  Other boxes may be more than the
     * bounds stage's (split references): the slot grows. */
    if (boxes != c->boxes) {
        c->boxes = atrbvh_i_scratch_get(c->scratch, CPU_BOXES, run->n,
                                        sizeof *c->boxes);
        if (!c->boxes)
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                 "cannot allocate %lu primitive boxes",
                                 (unsigned long)run->n);
    }
    memmove(c->boxes, boxes, (size_t)run->n * sizeof *boxes);
    c->ids = NULL;
    if (ids) {
        c->ids = atrbvh_i_scratch_get(c->scratch, CPU_IDS, run->n,
                                      sizeof *c->ids);
        if (!c->ids)
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                 "cannot allocate %lu kept primitive ids",
                                 (unsigned long)run->n);
        memcpy(c->ids, ids, (size_t)run->n * sizeof *ids);
    }
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cpu_tree_arrays(atrbvh_i_cpu_run *c, uint32_t n,
                                       atrbvh_error *error)
{
    atrbvh_i_scratch *s = c->scratch;
    atrbvh_i_tree *t = &c->tree;
    const size_t nodes = 2 * (size_t)n - 1, inner = n > 1 ? n - 1 : 1;
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
    return ATRBVH_OK;
}

static atrbvh_status nomem(atrbvh_error *error)
{
    return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                         "cannot allocate the capture");
}

/* A copy of n items of `size` bytes into a new array at *dst. */
static int copy_out(void *dst_ptr, const void *src, size_t n, size_t size)
{
    void **dst = (void **)dst_ptr;
    *dst = atrbvh_i_alloc_array(n, size);
    if (!*dst)
        return 0;
    memcpy(*dst, src, n * size);
    return 1;
}

static atrbvh_status cpu_capture(atrbvh_device *dev, atrbvh_i_run *run,
                                 atrbvh_stage stage, atrbvh_i_capture *cap,
                                 atrbvh_error *error)
{
    const atrbvh_i_cpu_run *c = run->state;
    size_t n = run->n;
    int ok = 1;
    (void)dev;
    switch (stage) {
    case ATRBVH_STAGE_BOUNDS:
        cap->n = run->n;
        cap->scene = run->scene;
        cap->centroids = run->centroids;
        ok = copy_out(&cap->prim_boxes, c->boxes, n, sizeof *c->boxes);
        break;
    case ATRBVH_STAGE_MORTON:
        ok = copy_out(&cap->keys, c->keys, n, sizeof *c->keys);
        break;
    case ATRBVH_STAGE_SORT:
        ok = copy_out(&cap->sorted_keys, c->keys, n, sizeof *c->keys) &&
             copy_out(&cap->order, c->order, n, sizeof *c->order);
        break;
    case ATRBVH_STAGE_HIERARCHY:
        ok = atrbvh_i_tree_copy(&cap->hierarchy, &c->tree, 0) == ATRBVH_OK;
        break;
    case ATRBVH_STAGE_REFIT:
        ok = atrbvh_i_tree_copy(&cap->refit, &c->tree, 1) == ATRBVH_OK;
        break;
    case ATRBVH_STAGE_OPTIMISE:
        ok = atrbvh_i_tree_copy(&cap->optimise, &c->tree, 1) == ATRBVH_OK;
        break;
    case ATRBVH_STAGE_COLLAPSE:
        ok = copy_out(&cap->collapse_size, c->size, 2 * n - 1,
                      sizeof *c->size);
        break;
    default:
        break;
    }
    return ok ? ATRBVH_OK : nomem(error);
}

const atrbvh_i_backend atrbvh_i_cpu_backend = {
    "cpu",
    ATRBVH_BACKEND_CPU,
    cpu_open,
    cpu_close,
    cpu_begin,
    cpu_end,
    {atrbvh_i_cpu_bounds, atrbvh_i_cpu_morton, atrbvh_i_cpu_sort,
     atrbvh_i_cpu_hierarchy, atrbvh_i_cpu_refit, atrbvh_i_cpu_optimise,
     atrbvh_i_cpu_collapse, atrbvh_i_cpu_layout},
    cpu_set_prims,
    cpu_capture,
    NULL, /* trace: lib/traverse.c's OpenMP queries */
    NULL, /* kernel_time: none */
    atrbvh_i_cpu_set_tree
};
