/*
 * cl/trace.c - ray batches on an open device: the tree, its primitive
 * indices and the geometry are uploaded once per batch into buffers the
 * handle keeps; the rays go in chunks that fit the device's largest
 * allocation, one launch of intersect_closest or intersect_any per chunk
 * (shared/traverse.h per ray, the CPU's functions).  On a device that
 * shares the host's memory every one of these arrays, and the results,
 * are the caller's own, wrapped for the batch (cl/memory.c): nothing is
 * copied.
 */
#include "config.h"

#include "opencl.h"

#include <string.h>

/* The geometry as the ray kernels read it; unused buffers are one-word
 * dummies. */
static atrbvh_status upload_scene(atrbvh_cl_device *c,
                                  const atrbvh_i_input *in,
                                  atrbvh_kargs_trace *a, atrbvh_error *error)
{
    const atrbvh_geometry *g = in->g;
    size_t bytes = 0;
    a->primitive_count = g->primitive_count;
    if (g->type != ATRBVH_GEOMETRY_BOXES) {
        size_t vs = in->vstride ? in->vstride : 3 * sizeof(float);
        size_t is = in->istride ? in->istride : 3 * sizeof(uint32_t);
        if (g->vertex_count &&
            (!atrbvh_i_mul_size(g->vertex_count - 1, vs, &bytes) ||
             (bytes += 3 * sizeof(float)) < 3 * sizeof(float)))
            return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE,
                                 ATRBVH_CL_NO_INDEX, "vertices overflow");
        CL_CHECK(atrbvh_i_cl_input(c, B_T_VERTICES, g->vertices, bytes,
                                   CL_TRUE, "vertices", error));
        bytes = 0;
        if (g->indices && g->primitive_count &&
            (!atrbvh_i_mul_size(g->primitive_count - 1, is, &bytes) ||
             (bytes += 12) < 12))
            return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE,
                                 ATRBVH_CL_NO_INDEX, "indices overflow");
        if (g->indices)
            CL_CHECK(atrbvh_i_cl_input(c, B_T_INDICES, g->indices, bytes,
                                       CL_TRUE, "indices", error));
        else /* (a kernel argument all the same) */
            CL_CHECK(atrbvh_i_cl_buffer(c, B_T_INDICES, bytes, 1, "indices",
                                        error));
        CL_CHECK(atrbvh_i_cl_buffer(c, B_T_BOXES, 1, 4, "boxes (unused)",
                                    error));
        a->vertex_count = g->vertex_count;
        a->vstride = vs / sizeof(float);
        a->istride = is / sizeof(uint32_t);
        a->indexed = g->indices != NULL;
        a->bstride = 6;
        return ATRBVH_OK;
    }
    {
        size_t bs = in->bstride ? in->bstride : 6 * sizeof(float);
        if (g->primitive_count &&
            (!atrbvh_i_mul_size(g->primitive_count - 1, bs, &bytes) ||
             (bytes += 6 * sizeof(float)) < 6 * sizeof(float)))
            return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE,
                                 ATRBVH_CL_NO_INDEX, "boxes overflow");
        CL_CHECK(atrbvh_i_cl_input(c, B_T_BOXES, g->boxes, bytes, CL_TRUE,
                                   "boxes", error));
        CL_CHECK(atrbvh_i_cl_buffer(c, B_T_VERTICES, 1, 4,
                                    "vertices (unused)", error));
        CL_CHECK(atrbvh_i_cl_buffer(c, B_T_INDICES, 1, 4, "indices (unused)",
                                    error));
        a->boxes = 1;
        a->bstride = bs / sizeof(float);
        a->vstride = 3;
        a->istride = 3;
    }
    return ATRBVH_OK;
}

static atrbvh_status trace_batch(atrbvh_cl_device *c,
                                  const atrbvh_node *nodes, size_t node_count,
                                  const uint32_t *prim_indices,
                                  size_t prim_count, const atrbvh_i_input *in,
                                  const atrbvh_ray *rays, size_t count,
                                  atrbvh_hit *hits, uint8_t *occluded,
                                  atrbvh_ray_cost *cost, atrbvh_error *error)
{
    atrbvh_kargs_trace a;
    int k = occluded ? K_INTERSECT_ANY : K_INTERSECT_CLOSEST;
    cl_ulong chunk;
    size_t done;
    memset(&a, 0, sizeof a);
    a.node_count = node_count;
    a.prim_count = prim_count;
    a.count_cost = cost != NULL;
    {
        /* The float node test gives the CPU's answers only where float
         * subnormals are kept (CL_FP_DENORM, and no -cl-denorms-are-zero
         * in the build options); elsewhere every ray takes the double
         * test: the same hits, counts that may differ from the CPU's. */
        cl_device_fp_config fp = 0;
        if (clGetDeviceInfo(c->device, CL_DEVICE_SINGLE_FP_CONFIG, sizeof fp,
                            &fp, NULL) == CL_SUCCESS &&
            (fp & CL_FP_DENORM))
            a.float_slabs = 1;
    }
    CL_CHECK(atrbvh_i_cl_input(c, B_T_NODES, nodes,
                               node_count * sizeof(atrbvh_node), CL_TRUE,
                               "BVH nodes", error));
    CL_CHECK(atrbvh_i_cl_input(c, B_T_PRIMS, prim_indices,
                               prim_count * sizeof(uint32_t), CL_TRUE,
                               "BVH primitive indices", error));
    CL_CHECK(upload_scene(c, in, &a, error));
    chunk = c->max_alloc / sizeof(atrbvh_ray);
    if (chunk > ((cl_ulong)1 << 24))
        chunk = (cl_ulong)1 << 24;
    if (chunk > count)
        chunk = count;
    if (chunk == 0)
        chunk = 1;
    if (!cost) /* a one-word dummy */
        CL_CHECK(atrbvh_i_cl_buffer(c, B_T_COST, 1, 4, "ray costs", error));
    for (done = 0; done < count; done += (size_t)chunk) {
        size_t n = count - done < chunk ? count - done : (size_t)chunk;
        a.ray_count = n;
        /* the chunk's rays and results: the caller's arrays in place, or
         * the handle's buffers (sized for a whole chunk: the next batch
         * of that size reuses them) */
        CL_CHECK(atrbvh_i_cl_input(c, B_T_RAYS, rays + done,
                                   n * sizeof(atrbvh_ray), CL_TRUE, "rays",
                                   error));
        if (occluded)
            CL_CHECK(atrbvh_i_cl_output(c, B_T_OUT, occluded + done, n,
                                        (size_t)chunk, 1,
                                        "occlusion results", error));
        else
            CL_CHECK(atrbvh_i_cl_output(c, B_T_OUT, hits + done, n,
                                        (size_t)chunk, sizeof(atrbvh_hit),
                                        "hits", error));
        if (cost) /* two u32 per ray (atrbvh_ray_cost) */
            CL_CHECK(atrbvh_i_cl_output(c, B_T_COST, cost + done, n,
                                        (size_t)chunk,
                                        sizeof(atrbvh_ray_cost), "ray costs",
                                        error));
        CL_RUN(c, k, n, error, CL_BUF(B_T_NODES), CL_BUF(B_T_PRIMS),
               CL_BUF(B_T_VERTICES), CL_BUF(B_T_INDICES), CL_BUF(B_T_BOXES),
               CL_BUF(B_T_RAYS), CL_BUF(B_T_OUT), CL_BUF(B_T_COST),
               CL_VAL(a));
        if (cost)
            CL_CHECK(atrbvh_i_cl_download(c, B_T_COST, cost + done,
                                          n * sizeof(atrbvh_ray_cost),
                                          "ray costs", error));
        if (occluded)
            CL_CHECK(atrbvh_i_cl_download(c, B_T_OUT, occluded + done, n,
                                          "occlusion results", error));
        else
            CL_CHECK(atrbvh_i_cl_download(c, B_T_OUT, hits + done,
                                          n * sizeof(atrbvh_hit), "hits",
                                          error));
        CL_CHECK(atrbvh_i_cl_finish(c, error));
    }
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cl_rays(atrbvh_device *dev, const atrbvh_node *nodes,
                                size_t node_count,
                                const uint32_t *prim_indices,
                                size_t prim_count, const atrbvh_i_input *in,
                                const atrbvh_ray *rays, size_t count,
                                atrbvh_hit *hits, uint8_t *occluded,
                                atrbvh_ray_cost *cost, int threads,
                                double *kernel_ms, atrbvh_error *error)
{
    atrbvh_cl_device *c = (atrbvh_cl_device *)dev->impl;
    atrbvh_cl_times times;
    atrbvh_status st;
    unsigned i;
    (void)threads;
    if (kernel_ms)
        *kernel_ms = 0.0;
    CL_CHECK(atrbvh_i_cl_usable(c, error));
    memset(&times, 0, sizeof times);
    c->times = &times; /* the pipeline holds the handle's lock */
    st = trace_batch(c, nodes, node_count, prim_indices, prim_count, in, rays,
                      count, hits, occluded, cost, error);
    if (c->event_count || c->pending) {
        atrbvh_error ignored;
        (void)atrbvh_i_cl_finish(c, &ignored);
    }
    atrbvh_i_cl_unwrap(c); /* the caller's arrays are theirs again */
    c->times = &c->build_times;
    if (kernel_ms)
        for (i = 0; i < times.count; i++)
            *kernel_ms += times.ms[i];
    return st;
}
