/*
 * prims.c - the input, checked on the host for every backend: the
 * geometry's metadata (pointers, strides, counts, size field) before any
 * stage runs, and, when a backend's bounds stage found an invalid
 * primitive, the exact error - the lowest-indexed offending primitive,
 * the most severe kind, whatever the thread count - or, with
 * skip_invalid, the compacted boxes and kept ids.  Also the Morton frame
 * (host constants that steer the morton stage of every backend).
 *
 * The geometry is read in place (strides), never copied.
 */
#include "config.h"

#include "internal.h"

#include <math.h>
#include <string.h>

#define NO_INDEX UINT64_MAX

atrbvh_status atrbvh_i_check_geometry(const atrbvh_geometry *g,
                                      atrbvh_i_input *in, atrbvh_error *error)
{
    size_t need, last;
    size_t *vstride = &in->vstride, *istride = &in->istride,
           *bstride = &in->bstride;
    memset(in, 0, sizeof *in);
    in->g = g;
    if (!g)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "geometry is NULL");
    if (g->size < ATRBVH_GEOMETRY_SIZE_V1 || g->size > sizeof *g)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "geometry.size is %lu; set it with "
                             "atrbvh_geometry_triangles() or "
                             "atrbvh_geometry_boxes(), or to "
                             "sizeof(atrbvh_geometry)",
                             (unsigned long)g->size);
    if (g->primitive_count == 0)
        return atrbvh_i_fail(error, ATRBVH_ERR_NO_PRIMITIVES, NO_INDEX,
                             "the geometry has no primitives");
    if (g->primitive_count > ATRBVH_MAX_PRIMITIVES)
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, NO_INDEX,
                             "%lu primitives exceed the limit of %lu",
                             (unsigned long)g->primitive_count,
                             (unsigned long)ATRBVH_MAX_PRIMITIVES);
    if (g->type == ATRBVH_GEOMETRY_TRIANGLES) {
        *vstride = g->vertex_stride ? g->vertex_stride : 3 * sizeof(float);
        *istride = g->index_stride ? g->index_stride : 3 * sizeof(uint32_t);
        if (!g->vertices)
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                                 "geometry.vertices is NULL");
        if (*vstride < 3 * sizeof(float) || *vstride % sizeof(float))
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                                 "vertex_stride %lu is not a multiple of 4 "
                                 "of at least 12 bytes",
                                 (unsigned long)*vstride);
        /* The last byte read must be addressable: stride * (count-1) + 12. */
        if (g->vertex_count == 0)
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                                 "geometry has triangles but no vertices");
        if (!atrbvh_i_mul_size(g->vertex_count - 1, *vstride, &last) ||
            last > SIZE_MAX - 3 * sizeof(float))
            return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, NO_INDEX,
                                 "vertex_count %lu times vertex_stride %lu "
                                 "overflows",
                                 (unsigned long)g->vertex_count,
                                 (unsigned long)*vstride);
        if (g->indices) {
            if (*istride < 3 * sizeof(uint32_t) || *istride % sizeof(uint32_t))
                return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                                     NO_INDEX,
                                     "index_stride %lu is not a multiple of "
                                     "4 of at least 12 bytes",
                                     (unsigned long)*istride);
            if (!atrbvh_i_mul_size(g->primitive_count, *istride, &need))
                return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, NO_INDEX,
                                     "primitive_count times index_stride "
                                     "overflows");
        } else {
            if (!atrbvh_i_mul_size(g->primitive_count, 3, &need))
                return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, NO_INDEX,
                                     "3 * primitive_count overflows");
            if (g->vertex_count < need)
                return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                                     NO_INDEX,
                                     "%lu unindexed triangles need %lu "
                                     "vertices, vertex_count is %lu",
                                     (unsigned long)g->primitive_count,
                                     (unsigned long)need,
                                     (unsigned long)g->vertex_count);
        }
    } else if (g->type == ATRBVH_GEOMETRY_BOXES) {
        *bstride = g->box_stride ? g->box_stride : 6 * sizeof(float);
        if (!g->boxes)
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                                 "geometry.boxes is NULL");
        if (*bstride < 6 * sizeof(float) || *bstride % sizeof(float))
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                                 "box_stride %lu is not a multiple of 4 of "
                                 "at least 24 bytes",
                                 (unsigned long)*bstride);
        if (!atrbvh_i_mul_size(g->primitive_count, *bstride, &need))
            return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, NO_INDEX,
                                 "primitive_count times box_stride overflows");
    } else {
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "geometry.type %d is not triangles or boxes",
                             (int)g->type);
    }
    return ATRBVH_OK;
}

/* Per-primitive problems, in increasing severity for reporting (the
 * per-primitive arithmetic is shared/stages.h's, shared with OpenCL). */
#define PRIM_OK ATRBVH_PRIM_OK
#define PRIM_NONFINITE ATRBVH_PRIM_NONFINITE
#define PRIM_BAD_INDEX ATRBVH_PRIM_BAD_INDEX
#define PRIM_INVERTED ATRBVH_PRIM_INVERTED

/* Box of primitive j of the triangles or boxes below: an ATRBVH_PRIM_*
 * code, *bad_value the offending vertex index for ATRBVH_PRIM_BAD_INDEX
 * (the rule every backend's bounds stage applies). */
#define PRIM_BOX(j, b, value)                                                  \
    (boxes_in ? atrbvh_prim_box_box(boxes_in, bst, (atrbvh_u64)(j), (b))      \
              : atrbvh_prim_box_triangle(vertices, vst, vcount, indices, ist, \
                                         indexed, (atrbvh_u64)(j), (b),       \
                                         (value)))

void atrbvh_i_prims_sweep(const atrbvh_i_input *in, int threads,
                          atrbvh_box *boxes, atrbvh_i_prims_scan *out)
{
    const atrbvh_geometry *g = in->g;
    const int64_t n = (int64_t)g->primitive_count;
    /* Everything the loop reads, in locals: the stores to boxes[] could
     * alias *g, and the compiler would reload it for every primitive. */
    const float *const boxes_in =
        g->type == ATRBVH_GEOMETRY_BOXES ? g->boxes : NULL;
    const float *const vertices = g->vertices;
    const uint32_t *const indices = g->indices;
    const int indexed = indices != NULL;
    const atrbvh_u64 vcount = g->vertex_count,
                     vst = in->vstride / sizeof(float),
                     ist = in->istride / sizeof(uint32_t),
                     bst = in->bstride / sizeof(float);
    int k;
    for (k = 0; k < 3; k++) {
        out->scene.min[k] = out->centroids.min[k] = INFINITY;
        out->scene.max[k] = out->centroids.max[k] = -INFINITY;
    }
    out->invalid = 0;
    out->first_bad = -1;
    out->bad_kind = PRIM_OK;
    out->bad_value = 0;
    (void)threads; /* unused without OpenMP */
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
        atrbvh_box scene, centroids;
        int64_t my_first_skippable = -1, my_first_fatal = -1, j;
        int my_fatal_kind = PRIM_OK;
        uint32_t my_value = 0;
        size_t my_invalid = 0;
        scene = out->scene;
        centroids = out->centroids;
#ifdef _OPENMP
#pragma omp for schedule(static) nowait
#endif
        for (j = 0; j < n; j++) {
            /* Written in place, not into a local copied afterwards: the
             * local lived on the stack (the rule's slow path indexes it),
             * and the copy's 16-byte loads of its 4-byte stores missed
             * store forwarding (perf, dragon: a third of the stage's
             * samples).  A failed primitive's partial box is
             * overwritten below or never read (the build fails). */
            uint32_t value = 0;
            const int r = PRIM_BOX(j, &boxes[j], &value);
            if (r == PRIM_OK) {
                atrbvh_scene_add(&scene, &centroids, boxes[j]);
                continue;
            }
            if (r == PRIM_NONFINITE) {
                my_invalid++;
                boxes[j].min[0] = NAN; /* marks it for compaction */
                if (my_first_skippable < 0)
                    my_first_skippable = j;
            } else if (my_first_fatal < 0) {
                my_first_fatal = j;
                my_fatal_kind = r;
                my_value = value;
            }
        }
        /* A problem that cannot be skipped (bad index, inverted box)
         * always wins over NaN/Inf so that skip_invalid never hides it;
         * among equals the lowest index wins.  Min/max only: the order of
         * the threads cannot change the boxes. */
#ifdef _OPENMP
#pragma omp critical
#endif
        {
            out->scene = atrbvh_box_union(out->scene, scene);
            out->centroids = atrbvh_box_union(out->centroids, centroids);
            out->invalid += my_invalid;
            if (my_first_fatal >= 0 && (out->bad_kind < PRIM_BAD_INDEX ||
                                        my_first_fatal < out->first_bad)) {
                out->first_bad = my_first_fatal;
                out->bad_kind = my_fatal_kind;
                out->bad_value = my_value;
            }
            if (my_first_skippable >= 0 && out->bad_kind < PRIM_BAD_INDEX &&
                (out->first_bad < 0 || my_first_skippable < out->first_bad)) {
                out->first_bad = my_first_skippable;
                out->bad_kind = PRIM_NONFINITE;
            }
        }
    }
}

atrbvh_status atrbvh_i_scan_prims(const atrbvh_i_input *in,
                                  const atrbvh_i_config *cfg,
                                  atrbvh_box **boxes_out, uint32_t **ids_out,
                                  uint32_t *kept_out, atrbvh_box *scene,
                                  atrbvh_box *centroids, size_t *invalid_out,
                                  atrbvh_error *error)
{
    const atrbvh_geometry *g = in->g;
    uint32_t *ids = NULL;
    size_t n, i, kept, invalid;
    atrbvh_box *boxes;
    atrbvh_i_prims_scan scan;

    *boxes_out = NULL;
    *ids_out = NULL;
    n = g->primitive_count;
    boxes = atrbvh_i_alloc_array(n, sizeof *boxes);
    if (!boxes)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate %lu primitive boxes",
                             (unsigned long)n);

    /* One sweep: the boxes, the lowest-indexed problem, and the scene and
     * centroid boxes of the valid primitives (the kept ones). */
    atrbvh_i_prims_sweep(in, cfg->threads, boxes, &scan);
    invalid = scan.invalid;
    if (scan.bad_kind == PRIM_BAD_INDEX) {
        atrbvh_i_free(boxes);
        return atrbvh_i_fail(error, ATRBVH_ERR_INDEX_RANGE,
                             (uint64_t)scan.first_bad,
                             "triangle %ld uses vertex %lu, but there are "
                             "only %lu vertices",
                             (long)scan.first_bad,
                             (unsigned long)scan.bad_value,
                             (unsigned long)g->vertex_count);
    }
    if (scan.bad_kind == PRIM_INVERTED) {
        atrbvh_i_free(boxes);
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                             (uint64_t)scan.first_bad,
                             "box %ld has min greater than max",
                             (long)scan.first_bad);
    }
    if (scan.bad_kind == PRIM_NONFINITE && !cfg->skip_invalid) {
        atrbvh_i_free(boxes);
        return atrbvh_i_fail(error, ATRBVH_ERR_NONFINITE,
                             (uint64_t)scan.first_bad,
                             "%s %ld has a NaN or infinite coordinate",
                             g->type == ATRBVH_GEOMETRY_BOXES ? "box"
                                                              : "triangle",
                             (long)scan.first_bad);
    }
    if (invalid == n) {
        atrbvh_i_free(boxes);
        return atrbvh_i_fail(error, ATRBVH_ERR_NO_PRIMITIVES, NO_INDEX,
                             "all %lu primitives have NaN or infinite "
                             "coordinates",
                             (unsigned long)n);
    }
    kept = n;
    if (invalid) {
        /* Compact in input order, so the kept ids are ascending. */
        ids = atrbvh_i_alloc_array(n - invalid, sizeof *ids);
        if (!ids) {
            atrbvh_i_free(boxes);
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                 "cannot allocate the kept primitive list");
        }
        kept = 0;
        for (i = 0; i < n; i++) {
            if (isnan(boxes[i].min[0]))
                continue;
            ids[kept] = (uint32_t)i;
            boxes[kept++] = boxes[i];
        }
    }
    *scene = scan.scene;
    *centroids = scan.centroids;
    *kept_out = (uint32_t)kept;
    *boxes_out = boxes;
    *ids_out = ids;
    *invalid_out = invalid;
    return ATRBVH_OK;
}

void atrbvh_i_morton_frame(const atrbvh_box *centroids, double lo[3],
                           double scale[3])
{
    atrbvh_morton_frame(*centroids, lo, scale); /* shared/stages.h */
}
