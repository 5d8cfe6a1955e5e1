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

/* Box of primitive i: an ATRBVH_PRIM_* code, *bad_value the offending
 * vertex index for ATRBVH_PRIM_BAD_INDEX (the rule every backend's bounds
 * stage applies). */
static int prim_box(const atrbvh_i_input *in, size_t i, atrbvh_box *out,
                    uint32_t *bad_value)
{
    const atrbvh_geometry *g = in->g;
    if (g->type == ATRBVH_GEOMETRY_BOXES)
        return atrbvh_prim_box_box(g->boxes, in->bstride / sizeof(float), i,
                                   out);
    return atrbvh_prim_box_triangle(
        g->vertices, in->vstride / sizeof(float), g->vertex_count, g->indices,
        in->istride / sizeof(uint32_t), g->indices != NULL, i, out,
        bad_value);
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
    size_t n, i, kept;
    atrbvh_box *boxes;
    int64_t first_bad = -1;
    int bad_kind = PRIM_OK;
    uint32_t bad_value = 0;
    size_t invalid = 0;
    float smin0, smin1, smin2, smax0, smax1, smax2;
    float cmin0, cmin1, cmin2, cmax0, cmax1, cmax2;

    *boxes_out = NULL;
    *ids_out = NULL;
    n = g->primitive_count;
    boxes = atrbvh_i_alloc_array(n, sizeof *boxes);
    if (!boxes)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate %lu primitive boxes",
                             (unsigned long)n);

    /* Pass 1: boxes and the lowest-indexed problem.  A problem that cannot
     * be skipped (bad index, inverted box) always wins over NaN/Inf so that
     * skip_invalid never hides it; among equals the lowest index wins. */
#ifdef _OPENMP
#pragma omp parallel num_threads(cfg->threads)
#endif
    {
        int64_t my_first_skippable = -1, my_first_fatal = -1;
        int my_fatal_kind = PRIM_OK;
        uint32_t my_value = 0;
        size_t my_invalid = 0;
        int64_t j;
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
        for (j = 0; j < (int64_t)n; j++) {
            uint32_t value = 0;
            int r = prim_box(in, (size_t)j, &boxes[j], &value);
            if (r == PRIM_NONFINITE) {
                my_invalid++;
                boxes[j].min[0] = NAN; /* marks it for compaction */
                if (my_first_skippable < 0)
                    my_first_skippable = j;
            } else if (r != PRIM_OK && my_first_fatal < 0) {
                my_first_fatal = j;
                my_fatal_kind = r;
                my_value = value;
            }
        }
#ifdef _OPENMP
#pragma omp critical
#endif
        {
            invalid += my_invalid;
            if (my_first_fatal >= 0 &&
                (bad_kind < PRIM_BAD_INDEX || my_first_fatal < first_bad)) {
                first_bad = my_first_fatal;
                bad_kind = my_fatal_kind;
                bad_value = my_value;
            }
            if (my_first_skippable >= 0 && bad_kind < PRIM_BAD_INDEX &&
                (first_bad < 0 || my_first_skippable < first_bad)) {
                first_bad = my_first_skippable;
                bad_kind = PRIM_NONFINITE;
            }
        }
    }

    if (bad_kind == PRIM_BAD_INDEX) {
        atrbvh_i_free(boxes);
        return atrbvh_i_fail(error, ATRBVH_ERR_INDEX_RANGE, (uint64_t)first_bad,
                             "triangle %ld uses vertex %lu, but there are "
                             "only %lu vertices",
                             (long)first_bad, (unsigned long)bad_value,
                             (unsigned long)g->vertex_count);
    }
    if (bad_kind == PRIM_INVERTED) {
        atrbvh_i_free(boxes);
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                             (uint64_t)first_bad,
                             "box %ld has min greater than max",
                             (long)first_bad);
    }
    if (bad_kind == PRIM_NONFINITE && !cfg->skip_invalid) {
        atrbvh_i_free(boxes);
        return atrbvh_i_fail(error, ATRBVH_ERR_NONFINITE, (uint64_t)first_bad,
                             "%s %ld has a NaN or infinite coordinate",
                             g->type == ATRBVH_GEOMETRY_BOXES ? "box"
                                                              : "triangle",
                             (long)first_bad);
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

    /* Scene and centroid boxes: min/max only, so the order of the
     * reduction cannot change the result. */
    smin0 = smin1 = smin2 = cmin0 = cmin1 = cmin2 = INFINITY;
    smax0 = smax1 = smax2 = cmax0 = cmax1 = cmax2 = -INFINITY;
    {
        int64_t j;
#ifdef _OPENMP
#pragma omp parallel for num_threads(cfg->threads) schedule(static) \
    reduction(min : smin0, smin1, smin2, cmin0, cmin1, cmin2)          \
    reduction(max : smax0, smax1, smax2, cmax0, cmax1, cmax2)
#endif
        for (j = 0; j < (int64_t)kept; j++) {
            const atrbvh_box b = boxes[j];
            float c0 = atrbvh_box_centre(b, 0), c1 = atrbvh_box_centre(b, 1),
                  c2 = atrbvh_box_centre(b, 2);
            smin0 = b.min[0] < smin0 ? b.min[0] : smin0;
            smin1 = b.min[1] < smin1 ? b.min[1] : smin1;
            smin2 = b.min[2] < smin2 ? b.min[2] : smin2;
            smax0 = b.max[0] > smax0 ? b.max[0] : smax0;
            smax1 = b.max[1] > smax1 ? b.max[1] : smax1;
            smax2 = b.max[2] > smax2 ? b.max[2] : smax2;
            cmin0 = c0 < cmin0 ? c0 : cmin0;
            cmin1 = c1 < cmin1 ? c1 : cmin1;
            cmin2 = c2 < cmin2 ? c2 : cmin2;
            cmax0 = c0 > cmax0 ? c0 : cmax0;
            cmax1 = c1 > cmax1 ? c1 : cmax1;
            cmax2 = c2 > cmax2 ? c2 : cmax2;
        }
    }
    scene->min[0] = smin0;
    scene->min[1] = smin1;
    scene->min[2] = smin2;
    scene->max[0] = smax0;
    scene->max[1] = smax1;
    scene->max[2] = smax2;
    centroids->min[0] = cmin0;
    centroids->min[1] = cmin1;
    centroids->min[2] = cmin2;
    centroids->max[0] = cmax0;
    centroids->max[1] = cmax1;
    centroids->max[2] = cmax2;
    *kept_out = (uint32_t)kept;
    *boxes_out = boxes;
    *ids_out = ids;
    *invalid_out = invalid;
    return ATRBVH_OK;
}

void atrbvh_i_morton_frame(const atrbvh_box *centroids, double lo[3],
                           double scale[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        double extent = (double)centroids->max[k] - (double)centroids->min[k];
        lo[k] = (double)centroids->min[k];
        scale[k] = extent > 0.0 ? (double)(1u << ATRBVH_MORTON_BITS) / extent
                                : 0.0;
    }
}
