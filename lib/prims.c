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

/* The eight-wide rule (AVX2 lanes where the compiler has them). */
#include "shared/lanes.h"
#ifdef ATRBVH_LANES
#define PRIMS_AVX2 1
#endif

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

/* The sweep's groups: eight primitives, one vector of AVX2 lanes. */
#define GROUP 8
/* Groups a thread takes at a time (dynamic: the master, which starts the
 * region 50-70 us before a sleeping thread wakes under passive waiting,
 * takes more of them meanwhile; the results - boxes, a count, the
 * lowest bad index - do not depend on who took which). */
#define SWEEP_GROUPS 128

#ifdef PRIMS_AVX2
/* Triangles j .. j+7 by atrbvh_prim_box_triangle's common case, lane k
 * triangle j+k, when all eight take it (their indices in range, their
 * nine coordinates' sum finite): the loads (gathers) and the stores are
 * this function's, the rule and atrbvh_scene_add's into the lanes of acc
 * are shared/lanes.h's atrbvh_tri8_boxes, which the OpenCL bounds kernel
 * runs too.  Returns 1 with the eight boxes written, or 0 with nothing
 * written (the caller takes the eight one at a time).  The offsets are
 * 32-bit: the caller has checked that every index and vertex
 * offset of the geometry fits (vertex offsets only once the indices are
 * known to be in range). */
__attribute__((always_inline, target("avx2"))) static inline int
tri8_lanes(const float *vertices, int32_t vst, uint32_t vlast,
           const uint32_t *indices, int32_t ist, int64_t j, atrbvh_box *out,
           atrbvh_f8 *acc)
{
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i first = _mm256_add_epi32(_mm256_set1_epi32((int32_t)j), lane);
    __m256i v0, v1, v2, ok;
    __m256 c[3][3], mn[3], mx[3];
    int k;
    if (indices) {
        const __m256i at = _mm256_mullo_epi32(first, _mm256_set1_epi32(ist));
        const __m256i last = _mm256_set1_epi32((int32_t)vlast);
        v0 = _mm256_i32gather_epi32((const int *)indices, at, 4);
        v1 = _mm256_i32gather_epi32((const int *)(indices + 1), at, 4);
        v2 = _mm256_i32gather_epi32((const int *)(indices + 2), at, 4);
        /* v < vertex_count: v = min(v, vertex_count - 1), unsigned */
        ok = _mm256_and_si256(
            _mm256_and_si256(
                _mm256_cmpeq_epi32(_mm256_min_epu32(v0, last), v0),
                _mm256_cmpeq_epi32(_mm256_min_epu32(v1, last), v1)),
            _mm256_cmpeq_epi32(_mm256_min_epu32(v2, last), v2));
        if (_mm256_movemask_epi8(ok) != -1)
            return 0;
    } else { /* (the caller checked 3 (j + 7) + 2 < vertex_count) */
        v0 = _mm256_mullo_epi32(first, _mm256_set1_epi32(3));
        v1 = _mm256_add_epi32(v0, _mm256_set1_epi32(1));
        v2 = _mm256_add_epi32(v0, _mm256_set1_epi32(2));
    }
    v0 = _mm256_mullo_epi32(v0, _mm256_set1_epi32(vst));
    v1 = _mm256_mullo_epi32(v1, _mm256_set1_epi32(vst));
    v2 = _mm256_mullo_epi32(v2, _mm256_set1_epi32(vst));
    for (k = 0; k < 3; k++) {
        c[0][k] = _mm256_i32gather_ps(vertices + k, v0, 4);
        c[1][k] = _mm256_i32gather_ps(vertices + k, v1, 4);
        c[2][k] = _mm256_i32gather_ps(vertices + k, v2, 4);
    }
    /* the rule, lane by lane (shared/lanes.h) */
    if (!atrbvh_tri8_boxes(c, mn, mx, acc))
        return 0;
    /* Six coordinate vectors to eight 24-byte boxes, four at a time:
     * min x, y, z and max x transposed, max y and z interleaved. */
    for (k = 0; k < 2; k++) {
        float *o = (float *)(out + j + 4 * k);
        __m128 r0 = k ? _mm256_extractf128_ps(mn[0], 1)
                      : _mm256_castps256_ps128(mn[0]),
               r1 = k ? _mm256_extractf128_ps(mn[1], 1)
                      : _mm256_castps256_ps128(mn[1]),
               r2 = k ? _mm256_extractf128_ps(mn[2], 1)
                      : _mm256_castps256_ps128(mn[2]),
               r3 = k ? _mm256_extractf128_ps(mx[0], 1)
                      : _mm256_castps256_ps128(mx[0]);
        const __m128 y = k ? _mm256_extractf128_ps(mx[1], 1)
                           : _mm256_castps256_ps128(mx[1]),
                     z = k ? _mm256_extractf128_ps(mx[2], 1)
                           : _mm256_castps256_ps128(mx[2]);
        const __m128 yz01 = _mm_unpacklo_ps(y, z), yz23 = _mm_unpackhi_ps(y, z);
        _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
        _mm_storeu_ps(o, r0);
        _mm_storel_pi((__m64 *)(void *)(o + 4), yz01);
        _mm_storeu_ps(o + 6, r1);
        _mm_storeh_pi((__m64 *)(void *)(o + 10), yz01);
        _mm_storeu_ps(o + 12, r2);
        _mm_storel_pi((__m64 *)(void *)(o + 16), yz23);
        _mm_storeu_ps(o + 18, r3);
        _mm_storeh_pi((__m64 *)(void *)(o + 22), yz23);
    }
    return 1;
}

/* tri8_lanes, called from the sweep, which is not compiled for AVX2: the
 * upper halves of the YMM registers are cleared on the way back to its
 * SSE code (GCC clears them itself only at -O2 and above, and not before
 * a tail call; tests/test_vecstate.c).  So are the accumulators'
 * functions below. */
__attribute__((target("avx2"))) static int
tri8_avx2(const float *vertices, int32_t vst, uint32_t vlast,
          const uint32_t *indices, int32_t ist, int64_t j, atrbvh_box *out,
          atrbvh_f8 *acc)
{
    const int done = tri8_lanes(vertices, vst, vlast, indices, ist, j, out,
                                acc);
    _mm256_zeroupper();
    return done;
}

/* The lanes' accumulators, empty; and into the thread's boxes at the end
 * (shared/lanes.h; called from the sweep, which is not compiled for AVX2,
 * so not inlined). */
__attribute__((target("avx2"))) static void tri_acc_init(atrbvh_f8 *acc)
{
    atrbvh_tri8_acc_init(acc);
    _mm256_zeroupper();
}

__attribute__((target("avx2"))) static void
tri_acc_done(const atrbvh_f8 *acc, atrbvh_box *scene, atrbvh_box *centroids)
{
    float t[ATRBVH_TRI8_ACC][8];
    int k;
    for (k = 0; k < ATRBVH_TRI8_ACC; k++)
        _mm256_storeu_ps(t[k], acc[k]);
    _mm256_zeroupper();
    atrbvh_tri8_acc_unite(t, scene, centroids);
}
#endif

/* Whether the sweep may take triangles eight at a time: AVX2, and every
 * offset it computes fits 32 bits (the index array's, and the vertex
 * array's for an index in range). */
static int sweep_vector(const atrbvh_geometry *g, atrbvh_u64 vst,
                        atrbvh_u64 ist)
{
#ifdef PRIMS_AVX2
    const atrbvh_u64 big = (atrbvh_u64)INT32_MAX,
                     n = (atrbvh_u64)g->primitive_count,
                     vc = (atrbvh_u64)g->vertex_count;
    if (g->type != ATRBVH_GEOMETRY_TRIANGLES || n < GROUP || vc == 0 ||
        !atrbvh_i_avx2())
        return 0;
    if (vc > big / (vst ? vst : 1) - 3 || vst > big)
        return 0;
    if (g->indices && (ist > big || n > big / (ist ? ist : 1) - 3))
        return 0;
    if (!g->indices && n > vc / 3) /* (checked before the sweep) */
        return 0;
    return 1;
#else
    (void)g;
    (void)vst;
    (void)ist;
    return 0;
#endif
}

void atrbvh_i_prims_sweep(const atrbvh_i_input *in, int threads,
                          atrbvh_box *boxes, atrbvh_i_prims_scan *out)
{
    atrbvh_i_prims_sweep_with(in, threads, 1, boxes, out);
}

void atrbvh_i_prims_sweep_with(const atrbvh_i_input *in, int threads,
                               int vector_ok, atrbvh_box *boxes,
                               atrbvh_i_prims_scan *out)
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
    const int64_t groups = (n + GROUP - 1) / GROUP;
    const int vector = vector_ok && sweep_vector(g, vst, ist);
    const uint32_t vlast =
        vcount - 1 > UINT32_MAX ? UINT32_MAX : (uint32_t)(vcount - 1);
    atrbvh_i_join join = {0};
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
        int64_t g8, top;
#ifdef PRIMS_AVX2
        atrbvh_f8 acc[ATRBVH_TRI8_ACC];
        if (vector)
            tri_acc_init(acc);
#endif
        scene = out->scene;
        centroids = out->centroids;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, SWEEP_GROUPS) nowait
#endif
        for (g8 = 0; g8 < groups; g8++) {
            j = g8 * GROUP;
            top = n - j < GROUP ? n : j + GROUP;
#ifdef PRIMS_AVX2
            if (vector && top - j == GROUP &&
                tri8_avx2(vertices, (int32_t)vst, vlast, indices, (int32_t)ist,
                          j, boxes, acc))
                continue;
#endif
            for (; j < top; j++) {
                /* Written in place, not into a local copied afterwards:
                 * the local lived on the stack (the rule's slow path
                 * indexes it), and the copy's 16-byte loads of its 4-byte
                 * stores missed store forwarding (perf, dragon: a third
                 * of the stage's samples).  A failed primitive's partial
                 * box is overwritten below or never read (the build
                 * fails). */
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
        }
#ifdef PRIMS_AVX2
        if (vector)
            tri_acc_done(acc, &scene, &centroids);
#endif
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
        atrbvh_i_join_arrive(&join);
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
