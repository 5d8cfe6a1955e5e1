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

/* The statistics with the SAH already summed (atrbvh_sah's value). */
static void set_stats_sah(atrbvh_bvh *b, size_t leaves, unsigned depth,
                          unsigned largest, double sah)
{
    b->stats.nodes = b->node_count;
    b->stats.leaves = leaves;
    /* a split tree references some primitives more than once */
    b->stats.primitives = b->split_prims ? b->split_prims : b->prim_count;
    b->stats.max_depth = depth;
    b->stats.max_leaf_primitives = largest;
    b->stats.sah = sah;
    b->stats.sah_built = sah; /* atrbvh_refit's drift reference */
}

/* Right children still to be reached in measure_built's walk, at most
 * (a deeper tree is measured by the general walk, check.c). */
#define MEASURE_STACK 512

/* One forward pass over the layout's depth-first array: node i+1 must be
 * i's left child when i is internal, else the right child last put aside
 * (the stack), and every right child lies after its parent; the depth
 * comes with each node, the SAH's sums are atrbvh_sah's, in node order,
 * serially (the same bits), so the array is read once and nothing is
 * allocated.  Before, a depth per node (4 bytes, a fresh array each
 * build) and a second pass over the nodes for the SAH. */
atrbvh_status atrbvh_i_bvh_measure_built(atrbvh_bvh *b)
{
    const size_t m = b->node_count;
    struct {
        uint32_t at, depth;
    } st[MEASURE_STACK];
    size_t i, leaves = 0, sp = 0;
    unsigned largest = 0, deepest = 0, depth = 0;
    double inner = 0.0, leaf_sum = 0.0, root = 0.0;
    if (m == 0)
        return atrbvh_i_bvh_measure(b);
    if (m > (size_t)UINT32_MAX)
        return ATRBVH_ERR_BACKEND; /* node indices are 32 bits */
    for (i = 0; i < m; i++) {
        const atrbvh_node *v = &b->nodes[i];
        const double a = atrbvh_i_node_area(v);
        if (i == 0)
            root = a;
        if (depth > deepest)
            deepest = depth;
        if (v->count) {
            if (v->index > b->prim_count || v->count > b->prim_count - v->index)
                break;
            leaf_sum += a * (double)v->count;
            leaves++;
            if (v->count > largest)
                largest = v->count;
            if (sp == 0) {
                if (i + 1 != m)
                    break; /* nodes after the whole tree */
                continue;
            }
            sp--;
            if (st[sp].at != i + 1)
                break; /* the next node is not the right child due */
            depth = st[sp].depth;
        } else {
            inner += a;
            if (v->index <= i + 1 || v->index >= m)
                break;
            if (sp == MEASURE_STACK)
                return atrbvh_i_bvh_measure(b); /* deeper: check.c */
            st[sp].at = v->index;
            st[sp].depth = depth + 1;
            sp++;
            depth++;
        }
    }
    if (i < m)
        return ATRBVH_ERR_BACKEND;
    set_stats_sah(b, leaves, deepest, largest,
                  atrbvh_i_sah_total(b->stats.ci, b->stats.ct, inner, leaf_sum,
                                     root));
    return ATRBVH_OK;
}

void atrbvh_i_bvh_set_stats(atrbvh_bvh *b, size_t leaves, unsigned depth,
                            unsigned largest)
{
    set_stats_sah(b, leaves, depth, largest,
                  atrbvh_sah(b->nodes, b->node_count, b->stats.ci,
                             b->stats.ct));
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
