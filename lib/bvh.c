/*
 * bvh.c - the BVH object: lifetime, accessors, statistics and stage times,
 * and the device record of an OpenCL build.
 */
#include "config.h"

#include "internal.h"

#include <string.h>

atrbvh_bvh *atrbvh_i_bvh_alloc(size_t node_count, size_t prim_count)
{
    atrbvh_bvh *b = atrbvh_i_malloc(sizeof *b);
    if (!b)
        return NULL;
    memset(b, 0, sizeof *b);
    if (node_count) {
        b->nodes = atrbvh_i_alloc_array(node_count, sizeof *b->nodes);
        b->prim_indices = atrbvh_i_alloc_array(prim_count, sizeof *b->prim_indices);
        if (!b->nodes || !b->prim_indices) {
            atrbvh_bvh_free(b);
            return NULL;
        }
        b->node_count = node_count;
        b->prim_count = prim_count;
    }
    return b;
}

atrbvh_status atrbvh_i_bvh_measure_built(atrbvh_bvh *b)
{
    const size_t m = b->node_count;
    uint32_t *depth;
    size_t i, leaves = 0;
    unsigned largest = 0, deepest = 0;
    if (m == 0)
        return atrbvh_i_bvh_measure(b);
    depth = atrbvh_i_alloc_array(m, sizeof *depth);
    if (!depth)
        return ATRBVH_ERR_NOMEM;
    for (i = 1; i < m; i++)
        depth[i] = UINT32_MAX; /* not reached yet */
    depth[0] = 0;
    for (i = 0; i < m; i++) {
        const atrbvh_node *v = &b->nodes[i];
        if (depth[i] == UINT32_MAX)
            break; /* no parent before it */
        if (depth[i] > deepest)
            deepest = depth[i];
        if (v->count) {
            if (v->index > b->prim_count || v->count > b->prim_count - v->index)
                break;
            leaves++;
            if (v->count > largest)
                largest = v->count;
        } else {
            if (v->index <= i + 1 || v->index >= m ||
                depth[i + 1] != UINT32_MAX || depth[v->index] != UINT32_MAX)
                break;
            depth[i + 1] = depth[i] + 1;
            depth[v->index] = depth[i] + 1;
        }
    }
    atrbvh_i_free(depth);
    if (i < m)
        return ATRBVH_ERR_BACKEND;
    atrbvh_i_bvh_set_stats(b, leaves, deepest, largest);
    return ATRBVH_OK;
}

void atrbvh_i_bvh_set_stats(atrbvh_bvh *b, size_t leaves, unsigned depth,
                            unsigned largest)
{
    b->stats.nodes = b->node_count;
    b->stats.leaves = leaves;
    /* a split tree references some primitives more than once */
    b->stats.primitives = b->split_prims ? b->split_prims : b->prim_count;
    b->stats.max_depth = depth;
    b->stats.max_leaf_primitives = largest;
    b->stats.sah = atrbvh_sah(b->nodes, b->node_count, b->stats.ci,
                              b->stats.ct);
    b->stats.sah_built = b->stats.sah; /* atrbvh_refit's drift reference */
}

void atrbvh_bvh_free(atrbvh_bvh *bvh)
{
    if (!bvh)
        return;
    atrbvh_i_bvh_drop_wide(bvh);
    atrbvh_i_free(bvh->nodes);
    atrbvh_i_free(bvh->prim_indices);
    atrbvh_i_free(bvh->device);
    atrbvh_i_free(bvh);
}

const atrbvh_node *atrbvh_bvh_nodes(const atrbvh_bvh *bvh, size_t *count)
{
    if (count)
        *count = bvh ? bvh->node_count : 0;
    return bvh ? bvh->nodes : NULL;
}

const uint32_t *atrbvh_bvh_primitive_indices(const atrbvh_bvh *bvh,
                                             size_t *count)
{
    if (count)
        *count = bvh ? bvh->prim_count : 0;
    return bvh ? bvh->prim_indices : NULL;
}

/* The first version's atrbvh_stats ends with build_ms; the second
 * (animation) with refit_ms.  Only a version's size is accepted. */
#define STATS_SIZE_V1 (offsetof(atrbvh_stats, build_ms) + sizeof(double))
#define STATS_SIZE_V2 (offsetof(atrbvh_stats, refit_ms) + sizeof(double))

atrbvh_status atrbvh_bvh_stats_sized(const atrbvh_bvh *bvh,
                                     atrbvh_stats *stats, size_t size)
{
    if (!bvh || !stats ||
        (size != STATS_SIZE_V1 && size != STATS_SIZE_V2))
        return ATRBVH_ERR_INVALID_ARGUMENT;
    memcpy(stats, &bvh->stats, size);
    return ATRBVH_OK;
}

double atrbvh_bvh_stage_ms(const atrbvh_bvh *bvh, atrbvh_stage stage)
{
    if (!bvh || (int)stage < 0 || stage >= ATRBVH_STAGE_COUNT)
        return 0.0;
    return bvh->stage_ms[stage];
}

void atrbvh_i_bvh_add_kernel_time(atrbvh_bvh *bvh, const char *name,
                                  double ms)
{
    atrbvh_i_device_info *d = bvh->device;
    unsigned k;
    if (!d)
        return;
    for (k = 0; k < d->kernel_count; k++) {
        if (strcmp(d->kernel_name[k], name) == 0) {
            d->kernel_ms[k] += ms;
            return;
        }
    }
    if (d->kernel_count == ATRBVH_MAX_KERNEL_TIMES)
        return;
    strncpy(d->kernel_name[k], name, sizeof d->kernel_name[k] - 1);
    d->kernel_name[k][sizeof d->kernel_name[k] - 1] = '\0';
    d->kernel_ms[k] = ms;
    d->kernel_count++;
}

const char *atrbvh_bvh_device(const atrbvh_bvh *bvh)
{
    if (!bvh)
        return NULL;
    return bvh->device ? bvh->device->name : "cpu";
}

int atrbvh_bvh_kernel_time(const atrbvh_bvh *bvh, size_t i, const char **name,
                           double *ms)
{
    if (!bvh || !bvh->device || i >= bvh->device->kernel_count)
        return 0;
    if (name)
        *name = bvh->device->kernel_name[i];
    if (ms)
        *ms = bvh->device->kernel_ms[i];
    return 1;
}
