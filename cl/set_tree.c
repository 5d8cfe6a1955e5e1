/*
 * cl/set_tree.c - atrbvh_reoptimise's replacement for the morton, sort
 * and hierarchy stages on OpenCL (lib/backend.h's set_tree): the caller's
 * binary tree goes into the buffers the hierarchy kernel fills, so the
 * refit, optimise, collapse and layout kernels run on it unchanged.  The
 * parent links are made on the host (in the handle's host scratch, kept
 * between calls) and uploaded with the rest.
 */
#include "config.h"

#include "opencl.h"

#include <string.h>

atrbvh_status atrbvh_i_cl_set_tree(atrbvh_device *dev, atrbvh_i_run *run,
                                   const uint32_t *left,
                                   const uint32_t *right,
                                   const uint32_t *leaf_prim,
                                   atrbvh_error *error)
{
    atrbvh_cl_device *c = (atrbvh_cl_device *)dev->impl;
    const uint32_t n = run->n;
    const size_t nodes = 2 * (size_t)n - 1, inner = n > 1 ? n - 1 : 1;
    uint32_t *parent, i;
    c->has_ids = 0;
    c->ranges = 0; /* any tree: the layout walks its leaves */
    c->refitted = 0; /* the refit kernel climbs it */
    c->flags = 0;    /* (nor are its collapse decisions kept) */
    parent = atrbvh_i_scratch_get(&dev->scratch, 0, nodes, sizeof *parent);
    if (!parent)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, ATRBVH_CL_NO_INDEX,
                             "cannot allocate %lu parent links",
                             (unsigned long)nodes);
    parent[0] = ATRBVH_U32_MAX;
    for (i = 0; i + 1 < n; i++) {
        parent[left[i]] = i;
        parent[right[i]] = i;
    }
    CL_CHECK(atrbvh_i_cl_buffer(c, B_LEFT, inner, 4, "left", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_RIGHT, inner, 4, "right", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_PARENT, nodes, 4, "parent", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_COUNT, nodes, 4, "count", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_LEAF_PRIM, n, 4, "leaf primitives",
                                error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_ORDER, n, 4, "order", error));
    if (n > 1) {
        CL_CHECK(atrbvh_i_cl_upload(c, B_LEFT, left, (size_t)(n - 1) * 4,
                                    "left", error));
        CL_CHECK(atrbvh_i_cl_upload(c, B_RIGHT, right, (size_t)(n - 1) * 4,
                                    "right", error));
    }
    CL_CHECK(atrbvh_i_cl_upload(c, B_PARENT, parent, nodes * 4, "parent",
                                error));
    CL_CHECK(atrbvh_i_cl_upload(c, B_LEAF_PRIM, leaf_prim, (size_t)n * 4,
                                "leaf primitives", error));
    /* The bounds kernel's boxes are in input order: leaf p's is entry
     * leaf_prim[p]. */
    CL_CHECK(atrbvh_i_cl_upload(c, B_ORDER, leaf_prim, (size_t)n * 4,
                                "order", error));
    return atrbvh_i_cl_finish(c, error);
}
