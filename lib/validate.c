/*
 * validate.c - atrbvh_validate_backends: build on the CPU and on OpenCL
 * with the pipeline's stage capture, compare every stage's output, name
 * the first difference.
 */
#include "config.h"

#include "internal.h"

#include <stdio.h>
#include <string.h>

static void box_text(char *buf, size_t size, const atrbvh_box *b)
{
    snprintf(buf, size, "[%.9g %.9g %.9g]-[%.9g %.9g %.9g]", b->min[0],
             b->min[1], b->min[2], b->max[0], b->max[1], b->max[2]);
}

static int box_differs(atrbvh_error *e, const char *stage, const char *what,
                       size_t i, const atrbvh_box *a, const atrbvh_box *b)
{
    char ta[160], tb[160];
    if (memcmp(a, b, sizeof *a) == 0)
        return 0;
    box_text(ta, sizeof ta, a);
    box_text(tb, sizeof tb, b);
    atrbvh_i_fail(e, ATRBVH_OK, i, "stage %s, %s %lu: box differs (cpu %s, "
                  "opencl %s)", stage, what, (unsigned long)i, ta, tb);
    return 1;
}

#define U32_DIFF(stage, what, field, i, a, b)                                  \
    if ((a) != (b)) {                                                          \
        atrbvh_i_fail(e, ATRBVH_OK, (uint64_t)(i),                             \
                      "stage %s, %s %lu: %s differs (cpu %lu, opencl %lu)",    \
                      stage, what, (unsigned long)(i), field,                  \
                      (unsigned long)(a), (unsigned long)(b));                 \
        return 1;                                                              \
    }

/* Topology (left, right, parent), counts, leaf primitives, and with
 * `values` boxes and costs. */
static int tree_differs(atrbvh_error *e, const char *stage,
                        const atrbvh_i_tree *a, const atrbvh_i_tree *b,
                        int values)
{
    size_t n = a->n, i;
    for (i = 0; i + 1 < n; i++) {
        U32_DIFF(stage, "node", "left child", i, a->left[i], b->left[i]);
        U32_DIFF(stage, "node", "right child", i, a->right[i], b->right[i]);
    }
    for (i = 0; i < 2 * n - 1; i++) {
        U32_DIFF(stage, "node", "parent", i, a->parent[i], b->parent[i]);
        U32_DIFF(stage, "node", "count", i, a->count[i], b->count[i]);
        if (!values)
            continue;
        if (box_differs(e, stage, "node", i, &a->box[i], &b->box[i]))
            return 1;
        if (memcmp(&a->cost[i], &b->cost[i], sizeof(double)) != 0) {
            atrbvh_i_fail(e, ATRBVH_OK, i,
                          "stage %s, node %lu: cost differs (cpu %.17g, "
                          "opencl %.17g)",
                          stage, (unsigned long)i, a->cost[i], b->cost[i]);
            return 1;
        }
    }
    for (i = 0; i < n; i++)
        U32_DIFF(stage, "leaf", "primitive", i, a->leaf_prim[i],
                 b->leaf_prim[i]);
    return 0;
}

int atrbvh_i_captures_differ(atrbvh_error *e, const atrbvh_i_capture *a,
                             const atrbvh_bvh *ba, const atrbvh_i_capture *b,
                             const atrbvh_bvh *bb)
{
    size_t n = a->n, i;
    U32_DIFF("bounds", "scene", "primitive count", 0, a->n, b->n);
    if (box_differs(e, "bounds", "scene box", 0, &a->scene, &b->scene) ||
        box_differs(e, "bounds", "centroid box", 0, &a->centroids,
                    &b->centroids))
        return 1;
    for (i = 0; i < n; i++)
        if (box_differs(e, "bounds", "primitive", i, &a->prim_boxes[i],
                        &b->prim_boxes[i]))
            return 1;
    for (i = 0; i < n; i++)
        if (a->keys[i] != b->keys[i]) {
            atrbvh_i_fail(e, ATRBVH_OK, i,
                          "stage morton, primitive %lu: key differs (cpu "
                          "%016llx, opencl %016llx)",
                          (unsigned long)i, (unsigned long long)a->keys[i],
                          (unsigned long long)b->keys[i]);
            return 1;
        }
    for (i = 0; i < n; i++) {
        if (a->sorted_keys[i] != b->sorted_keys[i]) {
            atrbvh_i_fail(e, ATRBVH_OK, i,
                          "stage sort, position %lu: key differs (cpu "
                          "%016llx, opencl %016llx)",
                          (unsigned long)i,
                          (unsigned long long)a->sorted_keys[i],
                          (unsigned long long)b->sorted_keys[i]);
            return 1;
        }
        U32_DIFF("sort", "position", "primitive", i, a->order[i], b->order[i]);
    }
    if (tree_differs(e, "hierarchy", &a->hierarchy, &b->hierarchy, 0) ||
        tree_differs(e, "refit", &a->refit, &b->refit, 1))
        return 1;
    if (tree_differs(e, "optimise", &a->optimise, &b->optimise, 1))
        return 1;
    for (i = 0; i < 2 * n - 1; i++)
        U32_DIFF("collapse", "node", "output size", i,
                 a->collapse_size[i] & ATRBVH_SIZE_MASK,
                 b->collapse_size[i] & ATRBVH_SIZE_MASK);
    for (i = 0; i < 2 * n - 1; i++)
        U32_DIFF("collapse", "node", "leaf decision", i,
                 a->collapse_size[i] >> 31, b->collapse_size[i] >> 31);
    U32_DIFF("layout", "array", "node count", 0, ba->node_count,
             bb->node_count);
    for (i = 0; i < ba->node_count; i++) {
        const atrbvh_node *x = &ba->nodes[i], *y = &bb->nodes[i];
        atrbvh_box bx, by;
        memcpy(bx.min, x->min, sizeof bx.min);
        memcpy(bx.max, x->max, sizeof bx.max);
        memcpy(by.min, y->min, sizeof by.min);
        memcpy(by.max, y->max, sizeof by.max);
        if (box_differs(e, "layout", "output node", i, &bx, &by))
            return 1;
        U32_DIFF("layout", "output node", "index", i, x->index, y->index);
        U32_DIFF("layout", "output node", "count", i, x->count, y->count);
    }
    /* a split tree's merged leaves: the index arrays' lengths first */
    U32_DIFF("layout", "array", "primitive index count", 0, ba->prim_count,
             bb->prim_count);
    for (i = 0; i < ba->prim_count; i++)
        U32_DIFF("layout", "index array entry", "primitive", i,
                 ba->prim_indices[i], bb->prim_indices[i]);
    return 0;
}

atrbvh_status atrbvh_validate_backends(const atrbvh_geometry *geometry,
                                       const atrbvh_build_options *options,
                                       int *identical, atrbvh_error *error)
{
    atrbvh_build_options o;
#ifdef ATRBVH_HAVE_OPENCL
    atrbvh_i_capture ca, cb;
    atrbvh_bvh *ba = NULL, *bb = NULL;
    atrbvh_status st;
#endif

    atrbvh_i_clear_error(error);
    if (!identical)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "the output pointer is NULL");
    *identical = 0;
    atrbvh_build_options_init(&o);
    if (options) {
        size_t size = options->size < sizeof o ? options->size : sizeof o;
        if (size < sizeof(size_t))
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                                 (uint64_t)-1, "options.size is %lu",
                                 (unsigned long)options->size);
        memcpy(&o, options, size);
        o.size = sizeof o;
    }
#ifndef ATRBVH_HAVE_OPENCL
    (void)geometry;
    return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, (uint64_t)-1,
                         "this build of atrbvh has no OpenCL backend "
                         "(configure --enable-opencl)");
#else
    memset(&ca, 0, sizeof ca);
    memset(&cb, 0, sizeof cb);
    /* The OpenCL side on the caller's device when it is an OpenCL one,
     * else on a device opened for this build; the CPU side on the CPU. */
    {
        atrbvh_device *dev = o.device;
        o.device = NULL;
        o.backend = ATRBVH_BACKEND_CPU;
        st = atrbvh_i_build_run(geometry, &o, &ba, &ca, error);
        if (st == ATRBVH_OK) {
            if (dev && atrbvh_device_backend(dev) == ATRBVH_BACKEND_OPENCL)
                o.device = dev;
            o.backend = ATRBVH_BACKEND_OPENCL;
            st = atrbvh_i_build_run(geometry, &o, &bb, &cb, error);
        }
    }
    if (st == ATRBVH_OK) {
        atrbvh_i_clear_error(error);
        *identical = !atrbvh_i_captures_differ(error, &ca, ba, &cb, bb);
    }
    atrbvh_bvh_free(ba);
    atrbvh_bvh_free(bb);
    atrbvh_i_capture_free(&ca);
    atrbvh_i_capture_free(&cb);
    return st;
#endif
}
