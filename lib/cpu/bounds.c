/*
 * bounds.c - stage "bounds": validate the caller's geometry and compute one
 * box per primitive, the scene box and the centroid box.
 *
 * The geometry is read in place (strides), never copied.  Errors name the
 * lowest-indexed offending primitive, whatever the thread count.
 */
#include "config.h"

#include "internal.h"

#include <math.h>
#include <string.h>

#define NO_INDEX UINT64_MAX

static const float *vertex_at(const atrbvh_geometry *g, size_t stride,
                              size_t v)
{
    return (const float *)((const char *)g->vertices + v * stride);
}

/* Validates pointers, strides and counts; fills the effective strides. */
atrbvh_status atrbvh_i_check_geometry(const atrbvh_geometry *g,
                                     size_t *vstride, size_t *istride,
                                     size_t *bstride, atrbvh_error *error)
{
    size_t need, last;
    if (!g)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "geometry is NULL");
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

/* Box of primitive i.  Returns a PRIM_* code; *bad_value receives the
 * offending vertex index (PRIM_BAD_INDEX). */
static int prim_box(const atrbvh_geometry *g, size_t vstride, size_t istride,
                    size_t bstride, size_t i, atrbvh_box *out,
                    uint32_t *bad_value)
{
    int c;
    if (g->type == ATRBVH_GEOMETRY_BOXES)
        return atrbvh_prim_box_from_box(
            (const float *)((const char *)g->boxes + i * bstride), out);
    *out = atrbvh_box_empty();
    for (c = 0; c < 3; c++) {
        size_t v;
        const float *p;
        if (g->indices) {
            const uint32_t *tri =
                (const uint32_t *)((const char *)g->indices + i * istride);
            v = tri[c];
            if (v >= g->vertex_count) {
                *bad_value = tri[c];
                return PRIM_BAD_INDEX;
            }
        } else {
            v = 3 * i + (size_t)c;
        }
        p = vertex_at(g, vstride, v);
        if (!atrbvh_box_grow(out, p[0], p[1], p[2]))
            return PRIM_NONFINITE;
    }
    return PRIM_OK;
}

void atrbvh_i_prims_free(atrbvh_i_prims *p)
{
    atrbvh_i_free(p->ids);
    atrbvh_i_free(p->boxes);
    p->ids = NULL;
    p->boxes = NULL;
}

atrbvh_status atrbvh_i_bounds(const atrbvh_geometry *g,
                              const atrbvh_i_config *cfg, atrbvh_i_prims *out,
                              atrbvh_error *error)
{
    size_t vstride = 0, istride = 0, bstride = 0;
    size_t n, i, kept;
    atrbvh_box *boxes;
    int64_t first_bad = -1;
    int bad_kind = PRIM_OK;
    uint32_t bad_value = 0;
    size_t invalid = 0;
    atrbvh_status st;
    float smin0, smin1, smin2, smax0, smax1, smax2;
    float cmin0, cmin1, cmin2, cmax0, cmax1, cmax2;

    memset(out, 0, sizeof *out);
    st = atrbvh_i_check_geometry(g, &vstride, &istride, &bstride, error);
    if (st != ATRBVH_OK)
        return st;
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
            int r = prim_box(g, vstride, istride, bstride, (size_t)j,
                             &boxes[j], &value);
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
        out->ids = atrbvh_i_alloc_array(n - invalid, sizeof *out->ids);
        if (!out->ids) {
            atrbvh_i_free(boxes);
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                 "cannot allocate the kept primitive list");
        }
        kept = 0;
        for (i = 0; i < n; i++) {
            if (isnan(boxes[i].min[0]))
                continue;
            out->ids[kept] = (uint32_t)i;
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
    out->scene.min[0] = smin0;
    out->scene.min[1] = smin1;
    out->scene.min[2] = smin2;
    out->scene.max[0] = smax0;
    out->scene.max[1] = smax1;
    out->scene.max[2] = smax2;
    out->centroids.min[0] = cmin0;
    out->centroids.min[1] = cmin1;
    out->centroids.min[2] = cmin2;
    out->centroids.max[0] = cmax0;
    out->centroids.max[1] = cmax1;
    out->centroids.max[2] = cmax2;
    out->count = (uint32_t)kept;
    out->boxes = boxes;
    out->invalid = invalid;
    return ATRBVH_OK;
}
