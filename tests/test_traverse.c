/*
 * test_traverse.c - ray queries.
 *
 *  - Closest and any hit through the BVH agree, bit for bit, with testing
 *    every primitive on its own (a one-primitive BVH per primitive: the
 *    same ray/primitive arithmetic without the traversal), on thousands of
 *    random rays: origins inside and outside the scene, random and
 *    axis-aligned directions (zero components of both signs), origins on
 *    vertex coordinates (rays in box planes), finite and infinite tmax.
 *  - The primitive tests themselves are checked against an independent
 *    double-precision Moller-Trumbore / slab test: a clear hit (well inside
 *    the triangle) is never missed, and every reported hit lies where its t
 *    and barycentrics say.
 *  - Watertightness: rays from inside closed meshes (an icosphere, a
 *    subdivided cube) aimed exactly at vertices and edge points always hit,
 *    so do rays from outside aimed through them at the centre, and vertical
 *    rays onto the vertices and edges of a height field.
 *  - Batches equal single rays, bit for bit, for 1, 2 and 4 threads.
 *  - Box primitives; batch argument errors.
 *  - One interval for both queries: a hit exactly at tmin or at tmax counts
 *    for intersect and occluded alike (triangles and boxes; a box entered
 *    exactly at tmin is hit there, not where the ray leaves it).
 *  - The single-ray calls check the geometry as the batch calls do: fewer
 *    primitives than the BVH was built over is a miss, never a wrong hit.
 *  - threads above ATRBVH_MAX_THREADS: ATRBVH_ERR_INVALID_ARGUMENT from the
 *    build and from both batch calls.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* ------------------------------------------------------------- meshes */
typedef struct mesh {
    float *v;       /* 3 floats per vertex */
    size_t nv;
    uint32_t *idx;  /* 3 per triangle, or NULL (soup) */
    size_t nt;
    float *boxes;   /* 6 per box when a box scene */
    int is_boxes;
} mesh;

static atrbvh_geometry mesh_geometry(const mesh *m)
{
    if (m->is_boxes)
        return atrbvh_geometry_boxes(m->boxes, m->nt);
    return atrbvh_geometry_triangles(m->v, m->nv, m->idx, m->nt);
}

static void mesh_free(mesh *m)
{
    free(m->v);
    free(m->idx);
    free(m->boxes);
    memset(m, 0, sizeof *m);
}

static mesh soup(size_t n, uint64_t seed, float scale, float offset)
{
    mesh m;
    memset(&m, 0, sizeof m);
    m.v = tu_random_triangles(n, seed, scale, offset);
    ck_assert_ptr_nonnull(m.v);
    m.nv = 3 * n;
    m.nt = n;
    return m;
}

/* Grows the vertex/index arrays as needed. */
static uint32_t add_vertex(mesh *m, size_t *cap, float x, float y, float z)
{
    if (m->nv == *cap) {
        *cap = *cap ? 2 * *cap : 64;
        m->v = realloc(m->v, *cap * 3 * sizeof *m->v);
        ck_assert_ptr_nonnull(m->v);
    }
    m->v[3 * m->nv] = x;
    m->v[3 * m->nv + 1] = y;
    m->v[3 * m->nv + 2] = z;
    return (uint32_t)m->nv++;
}

static void add_tri(mesh *m, size_t *cap, uint32_t a, uint32_t b, uint32_t c)
{
    if (m->nt == *cap) {
        *cap = *cap ? 2 * *cap : 64;
        m->idx = realloc(m->idx, *cap * 3 * sizeof *m->idx);
        ck_assert_ptr_nonnull(m->idx);
    }
    m->idx[3 * m->nt] = a;
    m->idx[3 * m->nt + 1] = b;
    m->idx[3 * m->nt + 2] = c;
    m->nt++;
}

/* A closed cube [-1,1]^3 with an s x s grid per face, vertices shared
 * (exact coordinates: k / s * 2 - 1 with s a power of two). */
static mesh grid_cube(int s)
{
    mesh m;
    size_t vcap = 0, tcap = 0;
    int face, i, j;
    uint32_t *id = malloc((size_t)(s + 1) * (s + 1) * 6 * sizeof *id);
    memset(&m, 0, sizeof m);
    ck_assert_ptr_nonnull(id);
    /* vertices are deduplicated through a lookup on exact coordinates */
    for (face = 0; face < 6; face++) {
        int axis = face / 2;
        float side = face % 2 ? 1.0f : -1.0f;
        for (i = 0; i <= s; i++)
            for (j = 0; j <= s; j++) {
                float p[3];
                size_t q;
                uint32_t found = UINT32_MAX;
                p[axis] = side;
                p[(axis + 1) % 3] = -1.0f + 2.0f * (float)i / (float)s;
                p[(axis + 2) % 3] = -1.0f + 2.0f * (float)j / (float)s;
                for (q = 0; q < m.nv; q++)
                    if (m.v[3 * q] == p[0] && m.v[3 * q + 1] == p[1] &&
                        m.v[3 * q + 2] == p[2]) {
                        found = (uint32_t)q;
                        break;
                    }
                if (found == UINT32_MAX)
                    found = add_vertex(&m, &vcap, p[0], p[1], p[2]);
                id[(size_t)face * (s + 1) * (s + 1) + (size_t)i * (s + 1) + j] =
                    found;
            }
        for (i = 0; i < s; i++)
            for (j = 0; j < s; j++) {
                size_t base = (size_t)face * (s + 1) * (s + 1);
                uint32_t a = id[base + (size_t)i * (s + 1) + j];
                uint32_t b = id[base + (size_t)(i + 1) * (s + 1) + j];
                uint32_t c = id[base + (size_t)(i + 1) * (s + 1) + j + 1];
                uint32_t d = id[base + (size_t)i * (s + 1) + j + 1];
                add_tri(&m, &tcap, a, b, c);
                add_tri(&m, &tcap, a, c, d);
            }
    }
    free(id);
    return m;
}

/* Icosphere: an icosahedron subdivided `level` times, midpoints shared and
 * pushed to the unit sphere. */
static uint32_t midpoint(mesh *m, size_t *vcap, uint32_t *cache, size_t cn,
                         uint32_t a, uint32_t b)
{
    /* cache: pairs (key, vertex) in a linear table, fine for tests */
    uint64_t key = a < b ? ((uint64_t)a << 32) | b : ((uint64_t)b << 32) | a;
    size_t i;
    float x, y, z, l;
    for (i = 0; i < cn; i++) {
        uint64_t k = ((uint64_t)cache[3 * i] << 32) | cache[3 * i + 1];
        if (k == key)
            return cache[3 * i + 2];
    }
    x = 0.5f * (m->v[3 * a] + m->v[3 * b]);
    y = 0.5f * (m->v[3 * a + 1] + m->v[3 * b + 1]);
    z = 0.5f * (m->v[3 * a + 2] + m->v[3 * b + 2]);
    l = sqrtf(x * x + y * y + z * z);
    return add_vertex(m, vcap, x / l, y / l, z / l);
}

static mesh icosphere(int level)
{
    static const float t0 = 1.6180339887f;
    static const int f0[20][3] = {
        {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
        {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
        {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
        {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    const float p0[12][3] = {{-1, t0, 0}, {1, t0, 0},   {-1, -t0, 0},
                             {1, -t0, 0}, {0, -1, t0},  {0, 1, t0},
                             {0, -1, -t0}, {0, 1, -t0}, {t0, 0, -1},
                             {t0, 0, 1},  {-t0, 0, -1}, {-t0, 0, 1}};
    mesh m;
    size_t vcap = 0, tcap = 0, i;
    int l;
    memset(&m, 0, sizeof m);
    for (i = 0; i < 12; i++) {
        float n = sqrtf(p0[i][0] * p0[i][0] + p0[i][1] * p0[i][1] +
                        p0[i][2] * p0[i][2]);
        add_vertex(&m, &vcap, p0[i][0] / n, p0[i][1] / n, p0[i][2] / n);
    }
    for (i = 0; i < 20; i++)
        add_tri(&m, &tcap, (uint32_t)f0[i][0], (uint32_t)f0[i][1],
                (uint32_t)f0[i][2]);
    for (l = 0; l < level; l++) {
        mesh next;
        size_t ncap = 0, cn = 0;
        uint32_t *cache = malloc(m.nt * 3 * 3 * sizeof *cache);
        ck_assert_ptr_nonnull(cache);
        memset(&next, 0, sizeof next);
        next.v = m.v;
        next.nv = m.nv;
        for (i = 0; i < m.nt; i++) {
            uint32_t a = m.idx[3 * i], b = m.idx[3 * i + 1],
                     c = m.idx[3 * i + 2], mid[3];
            uint32_t pr[3][2];
            int e;
            pr[0][0] = a; pr[0][1] = b;
            pr[1][0] = b; pr[1][1] = c;
            pr[2][0] = c; pr[2][1] = a;
            for (e = 0; e < 3; e++) {
                size_t before = next.nv;
                mid[e] = midpoint(&next, &vcap, cache, cn, pr[e][0], pr[e][1]);
                if (next.nv != before) {
                    cache[3 * cn] = pr[e][0] < pr[e][1] ? pr[e][0] : pr[e][1];
                    cache[3 * cn + 1] = pr[e][0] < pr[e][1] ? pr[e][1] : pr[e][0];
                    cache[3 * cn + 2] = mid[e];
                    cn++;
                }
            }
            add_tri(&next, &ncap, a, mid[0], mid[2]);
            add_tri(&next, &ncap, b, mid[1], mid[0]);
            add_tri(&next, &ncap, c, mid[2], mid[1]);
            add_tri(&next, &ncap, mid[0], mid[1], mid[2]);
        }
        free(cache);
        free(m.idx);
        m.v = next.v;
        m.nv = next.nv;
        m.idx = next.idx;
        m.nt = next.nt;
        tcap = ncap;
    }
    return m;
}

/* A height field over the integer grid [0, s]^2 (x, y), z from a hash. */
static mesh terrain(int s, uint64_t seed)
{
    mesh m;
    size_t vcap = 0, tcap = 0;
    int i, j;
    tu_rng r;
    tu_rng_seed(&r, seed);
    memset(&m, 0, sizeof m);
    for (i = 0; i <= s; i++)
        for (j = 0; j <= s; j++)
            add_vertex(&m, &vcap, (float)i, (float)j,
                       2.0f * tu_rng_float(&r));
    for (i = 0; i < s; i++)
        for (j = 0; j < s; j++) {
            uint32_t a = (uint32_t)(i * (s + 1) + j), b = a + (uint32_t)(s + 1);
            if ((i + j) % 2) {
                add_tri(&m, &tcap, a, b, b + 1);
                add_tri(&m, &tcap, a, b + 1, a + 1);
            } else {
                add_tri(&m, &tcap, a, b, a + 1);
                add_tri(&m, &tcap, b, b + 1, a + 1);
            }
        }
    return m;
}

static mesh random_boxes(size_t n, uint64_t seed)
{
    mesh m;
    tu_rng r;
    size_t i;
    memset(&m, 0, sizeof m);
    m.is_boxes = 1;
    m.nt = n;
    m.boxes = malloc(n * 6 * sizeof *m.boxes);
    ck_assert_ptr_nonnull(m.boxes);
    tu_rng_seed(&r, seed);
    for (i = 0; i < n; i++) {
        int k;
        for (k = 0; k < 3; k++) {
            float c = 10.0f * tu_rng_float(&r);
            float h = tu_rng_float(&r) < 0.1f ? 0.0f /* flat */
                                              : 0.5f * tu_rng_float(&r);
            m.boxes[6 * i + k] = c - h;
            m.boxes[6 * i + 3 + k] = c + h;
        }
    }
    return m;
}

/* ---------------------------------------------------- the reference */
/* One BVH per primitive, over a one-primitive view of the geometry. */
typedef struct reference {
    const mesh *m;
    atrbvh_geometry *g1;
    atrbvh_bvh **b1;
} reference;

static atrbvh_geometry one_prim(const mesh *m, size_t i)
{
    if (m->is_boxes)
        return atrbvh_geometry_boxes(m->boxes + 6 * i, 1);
    if (m->idx)
        return atrbvh_geometry_triangles(m->v, m->nv, m->idx + 3 * i, 1);
    return atrbvh_geometry_triangles(m->v + 9 * i, 3, NULL, 1);
}

static reference ref_make(const mesh *m)
{
    reference r;
    size_t i;
    atrbvh_build_options o;
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    o.threads = 1;
    r.m = m;
    r.g1 = malloc(m->nt * sizeof *r.g1);
    r.b1 = malloc(m->nt * sizeof *r.b1);
    ck_assert(r.g1 && r.b1);
    for (i = 0; i < m->nt; i++) {
        r.g1[i] = one_prim(m, i);
        r.b1[i] = tu_build(&r.g1[i], &o);
    }
    return r;
}

static void ref_free(reference *r)
{
    size_t i;
    for (i = 0; i < r->m->nt; i++)
        atrbvh_bvh_free(r->b1[i]);
    free(r->g1);
    free(r->b1);
}

static int ref_intersect(const reference *r, const atrbvh_ray *ray,
                         atrbvh_hit *best)
{
    size_t i;
    best->t = ray->tmax;
    best->u = best->v = 0.0f;
    best->primitive = ATRBVH_NO_HIT;
    for (i = 0; i < r->m->nt; i++) {
        atrbvh_hit h;
        if (!atrbvh_intersect(r->b1[i], &r->g1[i], ray, &h))
            continue;
        ck_assert_uint_eq(h.primitive, 0);
        if (best->primitive == ATRBVH_NO_HIT || h.t < best->t) {
            *best = h;
            best->primitive = (uint32_t)i;
        }
    }
    return best->primitive != ATRBVH_NO_HIT;
}

static int ref_occluded(const reference *r, const atrbvh_ray *ray)
{
    size_t i;
    for (i = 0; i < r->m->nt; i++)
        if (atrbvh_occluded(r->b1[i], &r->g1[i], ray))
            return 1;
    return 0;
}

/* ------------------------------------------- independent primitive tests */
static void tri_verts(const mesh *m, size_t i, double v[3][3])
{
    int c, k;
    for (c = 0; c < 3; c++) {
        size_t id = m->idx ? m->idx[3 * i + c] : 3 * i + (size_t)c;
        for (k = 0; k < 3; k++)
            v[c][k] = m->v[3 * id + k];
    }
}

/* Moller-Trumbore in double: t and barycentrics (b1, b2), no range test. */
static int mt(double v[3][3], const double o[3], const double d[3],
              double *t, double *b1, double *b2)
{
    double e1[3], e2[3], p[3], s[3], q[3], det;
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = v[1][k] - v[0][k];
        e2[k] = v[2][k] - v[0][k];
        s[k] = o[k] - v[0][k];
    }
    p[0] = d[1] * e2[2] - d[2] * e2[1];
    p[1] = d[2] * e2[0] - d[0] * e2[2];
    p[2] = d[0] * e2[1] - d[1] * e2[0];
    det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (det == 0.0)
        return 0;
    q[0] = s[1] * e1[2] - s[2] * e1[1];
    q[1] = s[2] * e1[0] - s[0] * e1[2];
    q[2] = s[0] * e1[1] - s[1] * e1[0];
    *b1 = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    *b2 = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    *t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    return 1;
}

/* Independent checks of one query result (triangles). */
static void check_independent(const mesh *m, const atrbvh_ray *ray,
                              const atrbvh_hit *h, int hit, double scale)
{
    double o[3], d[3], dl, clear = INFINITY;
    size_t i;
    int k;
    for (k = 0; k < 3; k++) {
        o[k] = ray->origin[k];
        d[k] = ray->dir[k];
    }
    dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (i = 0; i < m->nt; i++) {
        double v[3][3], t, b1, b2, n[3], e1[3], e2[3], nl, cosang;
        const double mg = 1e-3;
        tri_verts(m, i, v);
        if (!mt(v, o, d, &t, &b1, &b2))
            continue;
        for (k = 0; k < 3; k++) {
            e1[k] = v[1][k] - v[0][k];
            e2[k] = v[2][k] - v[0][k];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        nl = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (nl == 0.0)
            continue;
        cosang = fabs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / (nl * dl);
        /* clear: well inside, not grazing, well inside (tmin, tmax) */
        if (b1 > mg && b2 > mg && b1 + b2 < 1.0 - mg && cosang > 1e-2 &&
            t > (double)ray->tmin + 1e-3 * scale / dl &&
            t < (double)ray->tmax - 1e-3 * scale / dl && t < clear)
            clear = t;
    }
    if (clear < INFINITY) {
        ck_assert_msg(hit, "a clear hit at t=%g was missed", clear);
        ck_assert_msg((double)h->t <= clear + 1e-4 * scale / dl,
                      "closest hit t=%g beyond a clear hit at t=%g",
                      (double)h->t, clear);
    }
    if (hit) {
        double v[3][3], p[3], q[3], err = 0.0;
        double u = h->u, w = h->v;
        ck_assert_uint_lt(h->primitive, m->nt);
        tri_verts(m, h->primitive, v);
        ck_assert_msg(u >= -1e-6 && w >= -1e-6 && u + w <= 1.0 + 1e-6,
                      "barycentrics %g %g outside the triangle", u, w);
        for (k = 0; k < 3; k++) {
            p[k] = (1.0 - u - w) * v[0][k] + u * v[1][k] + w * v[2][k];
            q[k] = o[k] + (double)h->t * d[k];
            err += (p[k] - q[k]) * (p[k] - q[k]);
        }
        ck_assert_msg(sqrt(err) <= 1e-4 * scale,
                      "hit point from t (%g) and from barycentrics differ by "
                      "%g",
                      (double)h->t, sqrt(err));
    }
}

static void check_independent_box(const mesh *m, const atrbvh_ray *ray,
                                  const atrbvh_hit *h, int hit)
{
    if (hit) {
        const float *b = m->boxes + 6 * (size_t)h->primitive;
        int k, on_face = 0;
        ck_assert_uint_lt(h->primitive, m->nt);
        ck_assert(h->u == 0.0f && h->v == 0.0f);
        for (k = 0; k < 3; k++) {
            double p = (double)ray->origin[k] + (double)h->t * ray->dir[k];
            double tol = 1e-5 * (fabs(p) + 1.0);
            ck_assert_msg(p >= b[k] - tol && p <= b[3 + k] + tol,
                          "box hit point outside box %u on axis %d",
                          h->primitive, k);
            if (fabs(p - b[k]) <= tol || fabs(p - b[3 + k]) <= tol)
                on_face = 1;
        }
        ck_assert_msg(on_face, "box hit point not on a face");
    }
}

/* --------------------------------------------------------------- rays */
static void scene_box(const mesh *m, float lo[3], float hi[3])
{
    size_t i;
    int k;
    for (k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    if (m->is_boxes) {
        for (i = 0; i < m->nt; i++)
            for (k = 0; k < 3; k++) {
                lo[k] = fminf(lo[k], m->boxes[6 * i + k]);
                hi[k] = fmaxf(hi[k], m->boxes[6 * i + 3 + k]);
            }
        return;
    }
    for (i = 0; i < m->nv; i++)
        for (k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], m->v[3 * i + k]);
            hi[k] = fmaxf(hi[k], m->v[3 * i + k]);
        }
}

/* A point of primitive i (vertex or box corner) */
static void prim_point(const mesh *m, tu_rng *r, float p[3])
{
    size_t i = (size_t)(tu_rng_next(r) % m->nt);
    int k;
    if (m->is_boxes) {
        for (k = 0; k < 3; k++)
            p[k] = m->boxes[6 * i + (tu_rng_next(r) & 1 ? 3 : 0) + k];
    } else {
        size_t c = (size_t)(tu_rng_next(r) % 3);
        size_t id = m->idx ? m->idx[3 * i + c] : 3 * i + c;
        for (k = 0; k < 3; k++)
            p[k] = m->v[3 * id + k];
    }
}

/* lo, hi: the scene box (scene_box) */
static void random_ray(const mesh *m, const float lo[3], const float hi[3],
                       tu_rng *r, atrbvh_ray *ray)
{
    float target[3];
    int k, kind = (int)(tu_rng_next(r) % 8);
    for (k = 0; k < 3; k++) {
        float ext = hi[k] - lo[k];
        if (tu_rng_float(r) < 0.5f) /* inside the scene box */
            ray->origin[k] = lo[k] + ext * tu_rng_float(r);
        else
            ray->origin[k] = lo[k] - ext + 3.0f * ext * tu_rng_float(r);
    }
    if (kind == 0 || kind == 1) /* origin on a vertex: rays in box planes */
        prim_point(m, r, ray->origin);
    switch (kind) {
    case 0:
    case 2: { /* axis-aligned, zeros of random sign */
        int a = (int)(tu_rng_next(r) % 3);
        for (k = 0; k < 3; k++)
            ray->dir[k] = tu_rng_next(r) & 1 ? -0.0f : 0.0f;
        ray->dir[a] = tu_rng_next(r) & 1 ? -1.0f : 1.0f;
        break;
    }
    case 1:
    case 3: { /* one zero component */
        int a = (int)(tu_rng_next(r) % 3);
        for (k = 0; k < 3; k++)
            ray->dir[k] = 2.0f * tu_rng_float(r) - 1.0f;
        ray->dir[a] = tu_rng_next(r) & 1 ? -0.0f : 0.0f;
        if (ray->dir[(a + 1) % 3] == 0.0f)
            ray->dir[(a + 1) % 3] = 0.5f;
        break;
    }
    case 4:
    case 5: /* aimed at a point of a primitive */
        prim_point(m, r, target);
        for (k = 0; k < 3; k++)
            ray->dir[k] = target[k] - ray->origin[k];
        if (ray->dir[0] == 0.0f && ray->dir[1] == 0.0f && ray->dir[2] == 0.0f)
            ray->dir[2] = 1.0f;
        break;
    default:
        for (k = 0; k < 3; k++)
            ray->dir[k] = 2.0f * tu_rng_float(r) - 1.0f;
        if (ray->dir[0] == 0.0f && ray->dir[1] == 0.0f && ray->dir[2] == 0.0f)
            ray->dir[0] = 1.0f;
        break;
    }
    ray->tmin = tu_rng_float(r) < 0.8f ? 0.0f : 0.3f * tu_rng_float(r);
    ray->tmax = tu_rng_float(r) < 0.6f ? INFINITY : 0.2f + 2.0f * tu_rng_float(r);
}

static int same_hit(const atrbvh_hit *a, const atrbvh_hit *b)
{
    if (a->primitive != b->primitive)
        return 0;
    if (a->primitive == ATRBVH_NO_HIT)
        return 1;
    return memcmp(a, b, sizeof *a) == 0;
}

/* Checks `nrays` random rays through `bvh` against the reference. Returns
 * the number of hits. */
static size_t check_rays(const mesh *m, const reference *ref,
                         const atrbvh_bvh *bvh, size_t nrays, uint64_t seed,
                         const char *what)
{
    atrbvh_geometry g = mesh_geometry(m);
    tu_rng r;
    size_t i, hits = 0;
    float lo[3], hi[3];
    double scale = 0.0;
    int k;
    scene_box(m, lo, hi);
    for (k = 0; k < 3; k++)
        scale = fmax(scale, fmax(fabs(lo[k]), fabs(hi[k])));
    tu_rng_seed(&r, seed);
    for (i = 0; i < nrays; i++) {
        atrbvh_ray ray;
        atrbvh_hit h, e;
        int hit, ehit, occ, eocc;
        random_ray(m, lo, hi, &r, &ray);
        hit = atrbvh_intersect(bvh, &g, &ray, &h);
        ehit = ref_intersect(ref, &ray, &e);
        ck_assert_msg(hit == ehit && same_hit(&h, &e),
                      "%s ray %zu (o %a %a %a d %a %a %a t %g..%g): bvh "
                      "%d prim %u t %.9g u %.9g v %.9g, all primitives %d "
                      "prim %u t %.9g u %.9g v %.9g",
                      what, i, (double)ray.origin[0], (double)ray.origin[1],
                      (double)ray.origin[2], (double)ray.dir[0],
                      (double)ray.dir[1], (double)ray.dir[2],
                      (double)ray.tmin, (double)ray.tmax, hit, h.primitive,
                      (double)h.t, (double)h.u, (double)h.v, ehit,
                      e.primitive, (double)e.t, (double)e.u, (double)e.v);
        occ = atrbvh_occluded(bvh, &g, &ray);
        eocc = ref_occluded(ref, &ray);
        ck_assert_msg(occ == eocc, "%s ray %zu: occluded %d, all primitives "
                                   "%d",
                      what, i, occ, eocc);
        if (hit)
            ck_assert_msg(occ, "%s ray %zu: a closest hit but not occluded",
                          what, i);
        if (m->is_boxes)
            check_independent_box(m, &ray, &h, hit);
        else
            check_independent(m, &ray, &h, hit, scale);
        hits += (size_t)hit;
    }
    return hits;
}

typedef struct config {
    atrbvh_method method;
    int collapse;
    unsigned max_leaf;
} config;

static const config configs[] = {
    {ATRBVH_METHOD_LBVH, 0, 0},   {ATRBVH_METHOD_LBVH, 1, 0},
    {ATRBVH_METHOD_LBVH, 1, 2},   {ATRBVH_METHOD_LBVH, 1, 8},
    {ATRBVH_METHOD_TRBVH, 1, 0},  {ATRBVH_METHOD_ATRBVH, 1, 0},
    {ATRBVH_METHOD_ATRBVH, 0, 0},
};

/* Builds with config c; NULL when the method is not built in yet. */
static atrbvh_bvh *build_config(const atrbvh_geometry *g, const config *c)
{
    atrbvh_build_options o;
    atrbvh_bvh *b = NULL;
    atrbvh_error e;
    atrbvh_status s;
    atrbvh_build_options_init(&o);
    o.method = c->method;
    o.collapse = c->collapse;
    o.max_leaf_size = c->max_leaf;
    o.threads = 2;
    s = atrbvh_build(g, &o, &b, &e);
    if (s == ATRBVH_ERR_UNSUPPORTED && c->method != ATRBVH_METHOD_LBVH)
        return NULL;
    ck_assert_msg(s == ATRBVH_OK, "build failed: %s", e.text);
    return b;
}

static void check_scene(const mesh *m, size_t nrays, uint64_t seed,
                        const char *name)
{
    reference ref = ref_make(m);
    atrbvh_geometry g = mesh_geometry(m);
    size_t c;
    for (c = 0; c < sizeof configs / sizeof *configs; c++) {
        char what[128];
        size_t hits;
        atrbvh_bvh *b = build_config(&g, &configs[c]);
        if (!b)
            continue;
        snprintf(what, sizeof what, "%s method %d collapse %d max_leaf %u",
                 name, (int)configs[c].method, configs[c].collapse,
                 configs[c].max_leaf);
        hits = check_rays(m, &ref, b, nrays, seed + c, what);
        /* the ray mix must actually hit and miss */
        ck_assert_msg(hits > nrays / 50 && hits < nrays, "%s: %zu hits of %zu",
                      what, hits, nrays);
        atrbvh_bvh_free(b);
    }
    ref_free(&ref);
}

START_TEST(brute_force_soups)
{
    mesh m = soup(600, 11, 10.0f, -5.0f);
    check_scene(&m, 3000, 100, "soup 600");
    mesh_free(&m);
    m = soup(40, 12, 1.0f, 0.0f);
    check_scene(&m, 2000, 200, "soup 40");
    mesh_free(&m);
    m = soup(1, 13, 1.0f, 0.0f);
    check_scene(&m, 500, 300, "soup 1");
    mesh_free(&m);
}
END_TEST

START_TEST(brute_force_meshes)
{
    mesh m = icosphere(3);
    check_scene(&m, 2000, 400, "icosphere");
    mesh_free(&m);
    m = grid_cube(8);
    check_scene(&m, 2000, 500, "cube");
    mesh_free(&m);
    m = terrain(24, 3);
    check_scene(&m, 2000, 600, "terrain");
    mesh_free(&m);
}
END_TEST

START_TEST(brute_force_boxes)
{
    mesh m = random_boxes(500, 21);
    check_scene(&m, 3000, 700, "boxes");
    mesh_free(&m);
}
END_TEST

/* ----------------------------------------------------------- watertight */
static void expect_hit(const atrbvh_bvh *b, const atrbvh_geometry *g,
                       const float o[3], const float d[3], float tmax,
                       const char *what, size_t i)
{
    atrbvh_ray ray;
    atrbvh_hit h;
    int k;
    for (k = 0; k < 3; k++) {
        ray.origin[k] = o[k];
        ray.dir[k] = d[k];
    }
    ray.tmin = 0.0f;
    ray.tmax = tmax;
    ck_assert_msg(atrbvh_intersect(b, g, &ray, &h),
                  "%s %zu: ray o %a %a %a d %a %a %a fell through", what, i,
                  (double)o[0], (double)o[1], (double)o[2], (double)d[0],
                  (double)d[1], (double)d[2]);
    ck_assert_msg(atrbvh_occluded(b, g, &ray), "%s %zu: not occluded", what,
                  i);
}

/* Rays from `centre` (inside the closed mesh) aimed at every vertex and at
 * points along every edge, and the reverse rays from outside through those
 * points at the centre, must hit. */
static void closed_mesh_rays(const mesh *m, const float centre[3],
                             const atrbvh_bvh *b, const char *name)
{
    atrbvh_geometry g = mesh_geometry(m);
    static const float fr[] = {0.0f, 0.5f, 0.25f, 1.0f / 3.0f, 0.1f};
    size_t i, count = 0;
    for (i = 0; i < m->nt; i++) {
        int e;
        for (e = 0; e < 3; e++) {
            const float *a = m->v + 3 * m->idx[3 * i + e];
            const float *c = m->v + 3 * m->idx[3 * i + (e + 1) % 3];
            size_t f;
            for (f = 0; f < sizeof fr / sizeof *fr; f++) {
                float p[3], d[3], o[3], back[3];
                int k;
                for (k = 0; k < 3; k++) {
                    p[k] = a[k] + fr[f] * (c[k] - a[k]);
                    d[k] = p[k] - centre[k];
                    o[k] = centre[k] + 3.0f * d[k]; /* outside */
                    back[k] = -d[k];
                }
                expect_hit(b, &g, centre, d, INFINITY, name, count);
                /* the reverse ray must hit before reaching the centre */
                expect_hit(b, &g, o, back, 3.0f, name, count);
                count++;
            }
        }
    }
}

START_TEST(watertight)
{
    mesh sph = icosphere(3), cube = grid_cube(8), ter = terrain(16, 5);
    static const float c0[3] = {0.0f, 0.0f, 0.0f};
    static const float c1[3] = {0.125f, -0.25f, 0.0625f};
    size_t c;
    for (c = 0; c < sizeof configs / sizeof *configs; c++) {
        atrbvh_geometry gs = mesh_geometry(&sph), gc = mesh_geometry(&cube),
                        gt = mesh_geometry(&ter);
        atrbvh_bvh *bs = build_config(&gs, &configs[c]);
        atrbvh_bvh *bc = build_config(&gc, &configs[c]);
        atrbvh_bvh *bt = build_config(&gt, &configs[c]);
        int i, j;
        size_t n = 0;
        if (!bs)
            continue;
        ck_assert(bc && bt);
        closed_mesh_rays(&sph, c0, bs, "icosphere from the centre");
        closed_mesh_rays(&sph, c1, bs, "icosphere off centre");
        closed_mesh_rays(&cube, c0, bc, "cube from the centre");
        closed_mesh_rays(&cube, c1, bc, "cube off centre");
        /* vertical rays onto grid vertices, edge midpoints and diagonals
         * of the height field: all zero x and y direction components */
        for (i = 1; i < 32; i++)
            for (j = 1; j < 32; j++) {
                float o[3], d[3] = {0.0f, 0.0f, -1.0f};
                o[0] = 0.5f * (float)i;
                o[1] = 0.5f * (float)j;
                o[2] = 10.0f;
                expect_hit(bt, &gt, o, d, INFINITY, "terrain", n++);
                d[0] = -0.0f;
                d[1] = -0.0f;
                expect_hit(bt, &gt, o, d, INFINITY, "terrain -0", n++);
            }
        atrbvh_bvh_free(bs);
        atrbvh_bvh_free(bc);
        atrbvh_bvh_free(bt);
    }
    mesh_free(&sph);
    mesh_free(&cube);
    mesh_free(&ter);
}
END_TEST

/* From inside a closed mesh every direction hits: random directions. */
START_TEST(watertight_random_inside)
{
    mesh sph = icosphere(4);
    atrbvh_geometry g = mesh_geometry(&sph);
    atrbvh_bvh *b;
    config c = {ATRBVH_METHOD_LBVH, 1, 0};
    tu_rng r;
    size_t i;
    b = build_config(&g, &c);
    tu_rng_seed(&r, 77);
    for (i = 0; i < 20000; i++) {
        float o[3], d[3];
        int k;
        for (k = 0; k < 3; k++) {
            o[k] = 0.9f * (tu_rng_float(&r) - 0.5f);
            d[k] = 2.0f * tu_rng_float(&r) - 1.0f;
        }
        if (i % 4 == 0)
            d[i % 3] = 0.0f;
        if (d[0] == 0.0f && d[1] == 0.0f && d[2] == 0.0f)
            d[2] = 1.0f;
        expect_hit(b, &g, o, d, INFINITY, "inside the icosphere", i);
    }
    atrbvh_bvh_free(b);
    mesh_free(&sph);
}
END_TEST

/* --------------------------------------------------------------- batches */
START_TEST(batch_equals_single)
{
    mesh m = soup(3000, 31, 10.0f, 0.0f);
    mesh bx = random_boxes(800, 32);
    const mesh *scenes[2];
    int s;
    scenes[0] = &m;
    scenes[1] = &bx;
    for (s = 0; s < 2; s++) {
        atrbvh_geometry g = mesh_geometry(scenes[s]);
        config c = {ATRBVH_METHOD_LBVH, 1, 0};
        atrbvh_bvh *b = build_config(&g, &c);
        size_t n = 20000, i, nhit = 0;
        atrbvh_ray *rays = malloc(n * sizeof *rays);
        atrbvh_hit *single = malloc(n * sizeof *single),
                   *batch = malloc(n * sizeof *batch);
        uint8_t *occ1 = malloc(n), *occ = malloc(n);
        tu_rng r;
        static const int threads[] = {1, 2, 4, 0};
        size_t t;
        ck_assert(rays && single && batch && occ1 && occ);
        float lo[3], hi[3];
        scene_box(scenes[s], lo, hi);
        tu_rng_seed(&r, 99);
        for (i = 0; i < n; i++) {
            random_ray(scenes[s], lo, hi, &r, &rays[i]);
            atrbvh_intersect(b, &g, &rays[i], &single[i]);
            occ1[i] = (uint8_t)(atrbvh_occluded(b, &g, &rays[i]) != 0);
            nhit += single[i].primitive != ATRBVH_NO_HIT;
        }
        ck_assert(nhit > n / 10 && nhit < n);
        for (t = 0; t < sizeof threads / sizeof *threads; t++) {
            atrbvh_error e;
            memset(batch, 0xa5, n * sizeof *batch);
            memset(occ, 0xa5, n);
            ck_assert_int_eq(atrbvh_intersect_batch(b, &g, rays, n, batch,
                                                    threads[t], &e),
                             ATRBVH_OK);
            ck_assert_int_eq(atrbvh_occluded_batch(b, &g, rays, n, occ,
                                                   threads[t], &e),
                             ATRBVH_OK);
            for (i = 0; i < n; i++) {
                ck_assert_msg(memcmp(&batch[i], &single[i], sizeof *batch) ==
                                  0,
                              "scene %d threads %d ray %zu: batch differs",
                              s, threads[t], i);
                ck_assert_msg(occ[i] == occ1[i],
                              "scene %d threads %d ray %zu: occluded %u vs %u",
                              s, threads[t], i, occ[i], occ1[i]);
            }
        }
        free(rays);
        free(single);
        free(batch);
        free(occ1);
        free(occ);
        atrbvh_bvh_free(b);
    }
    mesh_free(&m);
    mesh_free(&bx);
}
END_TEST

START_TEST(batch_errors)
{
    mesh m = soup(50, 41, 1.0f, 0.0f);
    atrbvh_geometry g = mesh_geometry(&m), small = g, nov = g, bad = g;
    config c = {ATRBVH_METHOD_LBVH, 1, 0};
    atrbvh_bvh *b = build_config(&g, &c);
    atrbvh_ray ray = {{0, 0, -1}, {0, 0, 1}, 0.0f, INFINITY};
    atrbvh_hit hit;
    uint8_t occ;
    atrbvh_error e;
    small.primitive_count = 49;
    nov.vertices = NULL;
    bad.type = (atrbvh_geometry_type)7;
#define EXPECT(call, want, word)                                              \
    do {                                                                       \
        memset(&e, 0, sizeof e);                                               \
        ck_assert_int_eq((call), (want));                                      \
        ck_assert_int_eq(e.status, (want));                                    \
        ck_assert_msg(strstr(e.text, (word)) != NULL,                          \
                      "message '%s' lacks '%s'", e.text, (word));              \
    } while (0)
    EXPECT(atrbvh_intersect_batch(NULL, &g, &ray, 1, &hit, 0, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "bvh");
    EXPECT(atrbvh_intersect_batch(b, NULL, &ray, 1, &hit, 0, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "geometry");
    EXPECT(atrbvh_intersect_batch(b, &g, NULL, 1, &hit, 0, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "rays");
    EXPECT(atrbvh_intersect_batch(b, &g, &ray, 1, NULL, 0, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "output");
    EXPECT(atrbvh_intersect_batch(b, &small, &ray, 1, &hit, 0, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "49");
    EXPECT(atrbvh_intersect_batch(b, &nov, &ray, 1, &hit, 0, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "vertices");
    EXPECT(atrbvh_intersect_batch(b, &bad, &ray, 1, &hit, 0, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "type");
    EXPECT(atrbvh_intersect_batch(b, &g, &ray, 1, &hit, -1, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "threads");
    EXPECT(atrbvh_occluded_batch(NULL, &g, &ray, 1, &occ, 0, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "bvh");
    EXPECT(atrbvh_occluded_batch(b, &small, &ray, 1, &occ, 0, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "50");
    EXPECT(atrbvh_occluded_batch(b, &g, &ray, 1, NULL, 0, &e),
           ATRBVH_ERR_INVALID_ARGUMENT, "output");
    /* zero rays with NULL arrays is fine */
    ck_assert_int_eq(atrbvh_intersect_batch(b, &g, NULL, 0, NULL, 0, &e),
                     ATRBVH_OK);
    /* single-ray calls: NULLs and degenerate rays hit nothing */
    ck_assert_int_eq(atrbvh_intersect(NULL, &g, &ray, &hit), 0);
    ck_assert_uint_eq(hit.primitive, ATRBVH_NO_HIT);
    ck_assert_int_eq(atrbvh_occluded(b, NULL, &ray), 0);
    ray.dir[2] = 0.0f;
    ck_assert_int_eq(atrbvh_intersect(b, &g, &ray, &hit), 0);
    ray.dir[2] = NAN;
    ck_assert_int_eq(atrbvh_occluded(b, &g, &ray), 0);
    ray.dir[2] = 1.0f;
    ray.tmax = NAN;
    ck_assert_int_eq(atrbvh_intersect(b, &g, &ray, &hit), 0);
    /* a geometry with too few vertices is never read out of bounds */
    nov = g;
    nov.vertex_count = 30;
    ray.origin[0] = ray.origin[1] = 0.5f;
    ray.tmax = INFINITY;
    {
        size_t i, n = 0;
        tu_rng r;
        float lo[3], hi[3];
        scene_box(&m, lo, hi);
        tu_rng_seed(&r, 5);
        for (i = 0; i < 2000; i++) {
            random_ray(&m, lo, hi, &r, &ray);
            if (atrbvh_intersect(b, &nov, &ray, &hit))
                ck_assert_uint_lt(hit.primitive, 10);
            n++;
        }
        ck_assert_uint_eq(n, 2000);
    }
    atrbvh_bvh_free(b);
    mesh_free(&m);
}
END_TEST

/* Exact ties: two identical triangles (same t everywhere) must give the
 * lower index, and a triangle duplicated at indices 0 and n-1 too. */
START_TEST(ties_lower_index)
{
    size_t n = 64, i;
    mesh m = soup(n, 51, 1.0f, 0.0f);
    atrbvh_geometry g;
    size_t cfg;
    memcpy(m.v + 9 * (n - 1), m.v, 9 * sizeof *m.v); /* 63 == 0 */
    memcpy(m.v + 9 * 17, m.v + 9 * 40, 9 * sizeof *m.v); /* 17 == 40 */
    g = mesh_geometry(&m);
    for (cfg = 0; cfg < sizeof configs / sizeof *configs; cfg++) {
        atrbvh_bvh *b = build_config(&g, &configs[cfg]);
        if (!b)
            continue;
        for (i = 0; i < 2; i++) {
            size_t tri = i ? 40 : 0, k;
            atrbvh_ray ray;
            atrbvh_hit h;
            const float *v = m.v + 9 * tri;
            for (k = 0; k < 3; k++) {
                float c = (v[k] + v[3 + k] + v[6 + k]) / 3.0f;
                ray.origin[k] = c - 5.0f * (k == 2 ? 1.0f : 0.0f);
                ray.dir[k] = k == 2 ? 1.0f : 0.0f;
            }
            ray.tmin = 0.0f;
            ray.tmax = INFINITY;
            /* the centre of the duplicated triangle: whichever triangle is
             * nearest, when it is the duplicate the lower index wins */
            ck_assert(atrbvh_intersect(b, &g, &ray, &h));
            ck_assert_uint_ne(h.primitive, n - 1);
            ck_assert_uint_ne(h.primitive, 40);
        }
        atrbvh_bvh_free(b);
    }
    mesh_free(&m);
}
END_TEST

/* A triangle in the plane z = 1 and a box [-1,1]^2 x [1,2]; rays from the
 * origin along +z meet them at exactly t = 1 (and leave the box at 2). */
static const float interval_tris[] = {-1, -1, 1, 1, -1, 1, 0, 1, 1,
                                      5, 5, 5, 6, 5, 5, 5, 6, 5};
static const float interval_boxes[] = {-1, -1, 1, 1, 1, 2,
                                       5, 5, 5, 6, 6, 6};

/* Both queries on one ray, single and batch: the closest t (or -1 for a
 * miss) and whether occluded agrees with it. */
static float interval_query(const atrbvh_bvh *b, const atrbvh_geometry *g,
                            float tmin, float tmax)
{
    atrbvh_ray ray = {{0, 0, 0}, {0, 0, 1}, 0, 0};
    atrbvh_hit h, hb;
    uint8_t ob = 7;
    atrbvh_error e;
    int hit, occ;
    ray.tmin = tmin;
    ray.tmax = tmax;
    hit = atrbvh_intersect(b, g, &ray, &h);
    occ = atrbvh_occluded(b, g, &ray);
    ck_assert_int_eq(atrbvh_intersect_batch(b, g, &ray, 1, &hb, 1, &e),
                     ATRBVH_OK);
    ck_assert_int_eq(atrbvh_occluded_batch(b, g, &ray, 1, &ob, 1, &e),
                     ATRBVH_OK);
    ck_assert_uint_eq(hb.primitive, h.primitive);
    ck_assert(hb.t == h.t);
    ck_assert_int_eq(ob, occ != 0);
    ck_assert_msg((hit != 0) == (occ != 0),
                  "[%a, %a]: intersect %d but occluded %d", (double)tmin,
                  (double)tmax, hit, occ);
    if (!hit)
        return -1.0f;
    ck_assert_uint_eq(h.primitive, 0);
    return h.t;
}

START_TEST(closed_interval)
{
    atrbvh_geometry tg = atrbvh_geometry_triangles(interval_tris, 6, NULL, 2);
    atrbvh_geometry bg = atrbvh_geometry_boxes(interval_boxes, 2);
    config c = {ATRBVH_METHOD_LBVH, 0, 0};
    atrbvh_bvh *tb = build_config(&tg, &c), *bb = build_config(&bg, &c);
    const float above1 = nextafterf(1.0f, 2.0f), below1 = nextafterf(1.0f, 0.0f);
    const float above2 = nextafterf(2.0f, 3.0f);
    /* triangle at t = 1 */
    ck_assert(interval_query(tb, &tg, 1.0f, INFINITY) == 1.0f);  /* tmin */
    ck_assert(interval_query(tb, &tg, 0.0f, 1.0f) == 1.0f);      /* tmax */
    ck_assert(interval_query(tb, &tg, 1.0f, 1.0f) == 1.0f);      /* both */
    ck_assert(interval_query(tb, &tg, above1, INFINITY) == -1.0f);
    ck_assert(interval_query(tb, &tg, 0.0f, below1) == -1.0f);
    /* box entered at t = 1, left at t = 2 */
    ck_assert(interval_query(bb, &bg, 0.0f, INFINITY) == 1.0f);
    ck_assert(interval_query(bb, &bg, 1.0f, INFINITY) == 1.0f); /* entry */
    ck_assert(interval_query(bb, &bg, above1, INFINITY) == 2.0f); /* exit */
    ck_assert(interval_query(bb, &bg, 2.0f, INFINITY) == 2.0f);
    ck_assert(interval_query(bb, &bg, above2, INFINITY) == -1.0f);
    ck_assert(interval_query(bb, &bg, 0.0f, 1.0f) == 1.0f);
    ck_assert(interval_query(bb, &bg, 0.0f, below1) == -1.0f);
    atrbvh_bvh_free(tb);
    atrbvh_bvh_free(bb);
}
END_TEST

/* The geometry has fewer primitives than the BVH was built over: the
 * batch calls refuse it, the single calls miss (they used to return a hit
 * on whichever primitive happened to remain). */
START_TEST(single_call_checks)
{
    mesh m = soup(50, 41, 1.0f, 0.0f);
    atrbvh_geometry g = mesh_geometry(&m), small = g;
    atrbvh_geometry bg = atrbvh_geometry_boxes(interval_boxes, 2), bsmall;
    config c = {ATRBVH_METHOD_LBVH, 1, 0};
    atrbvh_bvh *b = build_config(&g, &c), *bb = build_config(&bg, &c);
    atrbvh_ray ray;
    atrbvh_hit h;
    atrbvh_error e;
    size_t k, hits_full = 0;
    small.primitive_count = 49;
    bsmall = bg;
    bsmall.primitive_count = 1;
    /* rays at the centre of each triangle, from below */
    for (k = 0; k < 50; k++) {
        const float *v = m.v + 9 * k;
        int a;
        for (a = 0; a < 3; a++) {
            ray.origin[a] = (v[a] + v[3 + a] + v[6 + a]) / 3.0f -
                            (a == 2 ? 10.0f : 0.0f);
            ray.dir[a] = a == 2 ? 1.0f : 0.0f;
        }
        ray.tmin = 0.0f;
        ray.tmax = INFINITY;
        hits_full += atrbvh_intersect(b, &g, &ray, &h) != 0;
        ck_assert_int_eq(atrbvh_intersect(b, &small, &ray, &h), 0);
        ck_assert_uint_eq(h.primitive, ATRBVH_NO_HIT);
        ck_assert(h.t == ray.tmax);
        ck_assert_int_eq(atrbvh_occluded(b, &small, &ray), 0);
    }
    ck_assert_uint_eq(hits_full, 50);
    ck_assert_int_eq(atrbvh_intersect_batch(b, &small, &ray, 1, &h, 0, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    /* boxes: the remaining box 0 is hit by this ray, but the geometry is
     * not the one the BVH was built from */
    {
        atrbvh_ray r = {{0, 0, 0}, {0, 0, 1}, 0.0f, INFINITY};
        ck_assert_int_eq(atrbvh_intersect(bb, &bg, &r, &h), 1);
        ck_assert_int_eq(atrbvh_intersect(bb, &bsmall, &r, &h), 0);
        ck_assert_int_eq(atrbvh_occluded(bb, &bsmall, &r), 0);
        /* an unusable geometry: a stride that is not a multiple of 4 */
        bsmall = bg;
        bsmall.box_stride = 26;
        ck_assert_int_eq(atrbvh_intersect(bb, &bsmall, &r, &h), 0);
        ck_assert_int_eq(atrbvh_occluded(bb, &bsmall, &r), 0);
    }
    atrbvh_bvh_free(b);
    atrbvh_bvh_free(bb);
    mesh_free(&m);
}
END_TEST

START_TEST(threads_limit)
{
    atrbvh_geometry bg = atrbvh_geometry_boxes(interval_boxes, 2);
    atrbvh_build_options o;
    atrbvh_bvh *b = NULL;
    atrbvh_ray r = {{0, 0, 0}, {0, 0, 1}, 0.0f, INFINITY};
    atrbvh_hit h;
    uint8_t occ;
    atrbvh_error e;
    atrbvh_build_options_init(&o);
    o.threads = ATRBVH_MAX_THREADS + 1;
    memset(&e, 0, sizeof e);
    ck_assert_int_eq(atrbvh_build(&bg, &o, &b, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_null(b);
    ck_assert_msg(strstr(e.text, "threads") != NULL, "%s", e.text);
    o.threads = 2147483647;
    ck_assert_int_eq(atrbvh_build(&bg, &o, &b, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    o.threads = 2;
    ck_assert_int_eq(atrbvh_build(&bg, &o, &b, &e), ATRBVH_OK);
    memset(&e, 0, sizeof e);
    ck_assert_int_eq(atrbvh_intersect_batch(b, &bg, &r, 1, &h,
                                            ATRBVH_MAX_THREADS + 1, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_msg(strstr(e.text, "threads") != NULL, "%s", e.text);
    ck_assert_int_eq(atrbvh_occluded_batch(b, &bg, &r, 1, &occ, 2147483647,
                                           &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_occluded_batch(b, &bg, &r, 1, &occ, 2, &e),
                     ATRBVH_OK);
    ck_assert_uint_eq(occ, 1);
    atrbvh_bvh_free(b);
}
END_TEST

/* ------------------------------------------------------ wide batches */
/* The uncounted batch calls trace the rays with nonzero direction
 * components over an 8-wide copy of the tree (lib/traverse.c); rays whose
 * float slab tests are most at risk graze boxes: aimed at primitives'
 * vertices (on the boxes of every node holding them) and at corners and
 * edge midpoints of the tree's own node boxes.  Those batches must give
 * what testing every primitive gives, and what the counted batch (binary
 * traversal) gives, bit for bit. */
static void grazing_rays(const mesh *m, const atrbvh_bvh *b, size_t n,
                         uint64_t seed, atrbvh_ray *rays)
{
    float lo[3], hi[3];
    size_t i, node_count;
    const atrbvh_node *nodes = atrbvh_bvh_nodes(b, &node_count);
    tu_rng r;
    scene_box(m, lo, hi);
    tu_rng_seed(&r, seed);
    for (i = 0; i < n; i++) {
        atrbvh_ray *ray = &rays[i];
        float target[3];
        int k, kind = (int)(i % 4);
        if (kind == 0) { /* the tests' mix */
            random_ray(m, lo, hi, &r, ray);
            continue;
        }
        for (k = 0; k < 3; k++) {
            float ext = hi[k] - lo[k];
            ray->origin[k] = lo[k] - ext + 3.0f * ext * tu_rng_float(&r);
        }
        if (kind == 1) {
            prim_point(m, &r, target);
        } else {
            const atrbvh_node *nd =
                &nodes[(size_t)(tu_rng_next(&r) % node_count)];
            unsigned corner = (unsigned)(tu_rng_next(&r) & 7u);
            for (k = 0; k < 3; k++)
                target[k] = corner >> k & 1u ? nd->max[k] : nd->min[k];
            if (kind == 3) { /* the midpoint of an edge */
                int a = (int)(tu_rng_next(&r) % 3);
                target[a] = 0.5f * (nd->min[a] + nd->max[a]);
            }
        }
        for (k = 0; k < 3; k++) {
            ray->dir[k] = target[k] - ray->origin[k];
            if (ray->dir[k] == 0.0f)
                ray->dir[k] = 0.25f;
        }
        ray->tmin = tu_rng_float(&r) < 0.8f ? 0.0f : 0.1f * tu_rng_float(&r);
        /* ending just past, at or just before the target */
        ray->tmax = tu_rng_float(&r) < 0.5f
                        ? INFINITY
                        : 0.999999f + 2e-6f * tu_rng_float(&r);
    }
}

/* check_wide with the geometry g, the same triangles as m laid out
 * otherwise (rays are aimed at m's). */
static void check_wide_geometry(const mesh *m, const atrbvh_geometry *gp,
                                const atrbvh_bvh *b, const reference *ref,
                                size_t n, uint64_t seed, const char *what)
{
    atrbvh_geometry g = *gp;
    atrbvh_ray *rays = malloc(n * sizeof *rays);
    atrbvh_hit *hits = malloc(n * sizeof *hits), *bin = malloc(n * sizeof *bin);
    uint8_t *occ = malloc(n), *bocc = malloc(n);
    atrbvh_trace_stats ts;
    atrbvh_error e;
    size_t i, nhit = 0;
    ck_assert(rays && hits && bin && occ && bocc);
    grazing_rays(m, b, n, seed, rays);
    ck_assert_int_eq(atrbvh_intersect_batch(b, &g, rays, n, hits, 2, &e),
                     ATRBVH_OK);
    ck_assert_int_eq(atrbvh_occluded_batch(b, &g, rays, n, occ, 2, &e),
                     ATRBVH_OK);
    atrbvh_trace_stats_init(&ts);
    ck_assert_int_eq(atrbvh_intersect_batch_stats(NULL, b, &g, rays, n, bin, 1,
                                                  &ts, &e),
                     ATRBVH_OK);
    ck_assert_int_eq(atrbvh_occluded_batch_stats(NULL, b, &g, rays, n, bocc, 1,
                                                 &ts, &e),
                     ATRBVH_OK);
    for (i = 0; i < n; i++) {
        ck_assert_msg(memcmp(&hits[i], &bin[i], sizeof *hits) == 0 &&
                          occ[i] == bocc[i],
                      "%s ray %zu: the batch gives prim %u t %a occluded %u, "
                      "the counted batch prim %u t %a occluded %u",
                      what, i, hits[i].primitive, (double)hits[i].t, occ[i],
                      bin[i].primitive, (double)bin[i].t, bocc[i]);
        nhit += hits[i].primitive != ATRBVH_NO_HIT;
        if (ref) {
            atrbvh_hit eh;
            int ehit = ref_intersect(ref, &rays[i], &eh);
            ck_assert_msg(ehit == (hits[i].primitive != ATRBVH_NO_HIT) &&
                              same_hit(&hits[i], &eh),
                          "%s ray %zu (o %a %a %a d %a %a %a t %g..%g): "
                          "batch prim %u t %a, all primitives prim %u t %a",
                          what, i, (double)rays[i].origin[0],
                          (double)rays[i].origin[1], (double)rays[i].origin[2],
                          (double)rays[i].dir[0], (double)rays[i].dir[1],
                          (double)rays[i].dir[2], (double)rays[i].tmin,
                          (double)rays[i].tmax, hits[i].primitive,
                          (double)hits[i].t, eh.primitive, (double)eh.t);
            ck_assert_msg(occ[i] == (uint8_t)ref_occluded(ref, &rays[i]),
                          "%s ray %zu: occluded %u, all primitives differ",
                          what, i, occ[i]);
        }
    }
    /* the mix must hit and miss */
    ck_assert_msg(nhit > n / 20 && nhit < n, "%s: %zu hits of %zu", what, nhit,
                  n);
    free(rays);
    free(hits);
    free(bin);
    free(occ);
    free(bocc);
}

static void check_wide(const mesh *m, const atrbvh_bvh *b,
                       const reference *ref, size_t n, uint64_t seed,
                       const char *what)
{
    atrbvh_geometry g = mesh_geometry(m);
    check_wide_geometry(m, &g, b, ref, n, seed, what);
}

START_TEST(wide_batches)
{
    mesh ms[5];
    const char *names[5] = {"soup 600", "icosphere", "cube", "terrain",
                            "boxes"};
    int s;
    ms[0] = soup(600, 41, 10.0f, -5.0f);
    ms[1] = icosphere(3);
    ms[2] = grid_cube(8);
    ms[3] = terrain(16, 7);
    ms[4] = random_boxes(400, 42);
    for (s = 0; s < 5; s++) {
        atrbvh_geometry g = mesh_geometry(&ms[s]);
        reference ref = ref_make(&ms[s]);
        size_t c;
        for (c = 0; c < sizeof configs / sizeof *configs; c++) {
            char what[128];
            atrbvh_bvh *b = build_config(&g, &configs[c]);
            if (!b)
                continue;
            snprintf(what, sizeof what, "%s method %d collapse %d max_leaf %u",
                     names[s], (int)configs[c].method, configs[c].collapse,
                     configs[c].max_leaf);
            /* against every primitive for two trees, against the binary
             * traversal for all */
            check_wide(&ms[s], b, c == 3 || c == 5 ? &ref : NULL,
                       c == 3 || c == 5 ? 2048 : 8192, 900 + c, what);
            atrbvh_bvh_free(b);
        }
        ref_free(&ref);
        mesh_free(&ms[s]);
    }
}
END_TEST

/* The wide copy is made by the first batch and kept: refit and reoptimise
 * must drop it, or the next batch would trace the old boxes. */
START_TEST(wide_after_refit)
{
    mesh m = icosphere(3);
    atrbvh_geometry g = mesh_geometry(&m);
    config c = {ATRBVH_METHOD_LBVH, 1, 8};
    atrbvh_bvh *b = build_config(&g, &c);
    reference ref;
    atrbvh_error e;
    size_t i;
    int step;
    check_wide(&m, b, NULL, 4096, 950, "icosphere before the move");
    for (step = 0; step < 2; step++) {
        /* move the sphere away by twice its radius and squash it */
        for (i = 0; i < m.nv; i++) {
            m.v[3 * i] += 2.0f;
            m.v[3 * i + 1] *= 0.5f;
        }
        ck_assert_int_eq(step == 0 ? atrbvh_refit(b, &g, NULL, &e)
                                   : atrbvh_reoptimise(b, &g, NULL, &e),
                         ATRBVH_OK);
        ref = ref_make(&m);
        check_wide(&m, b, &ref, 2048, 960 + (uint64_t)step,
                   step == 0 ? "icosphere after refit"
                             : "icosphere after reoptimise");
        ref_free(&ref);
    }
    atrbvh_bvh_free(b);
    mesh_free(&m);
}
END_TEST

/* Batches on several threads at once on a fresh tree: each may make the
 * wide copy, one keeps it (the others free theirs: LeakSanitizer in the
 * suite), and all give the counted batch's hits. */
START_TEST(wide_concurrent_first_use)
{
    mesh m = soup(2000, 51, 10.0f, -5.0f);
    atrbvh_geometry g = mesh_geometry(&m);
    config c = {ATRBVH_METHOD_LBVH, 1, 4};
    size_t n = 4096, i;
    atrbvh_ray *rays = malloc(n * sizeof *rays);
    atrbvh_hit *ref = malloc(n * sizeof *ref);
    atrbvh_hit *hits = malloc(8 * n * sizeof *hits);
    int round;
    ck_assert(rays && ref && hits);
    for (round = 0; round < 4; round++) {
        atrbvh_bvh *b = build_config(&g, &c);
        atrbvh_trace_stats ts;
        atrbvh_error e;
        int k, fails = 0;
        grazing_rays(&m, b, n, 970 + (uint64_t)round, rays);
        atrbvh_trace_stats_init(&ts);
        ck_assert_int_eq(atrbvh_intersect_batch_stats(NULL, b, &g, rays, n,
                                                      ref, 1, &ts, &e),
                         ATRBVH_OK);
#ifdef _OPENMP
#pragma omp parallel for num_threads(4) schedule(static, 1) reduction(+ : fails)
#endif
        for (k = 0; k < 8; k++) {
            atrbvh_error ke;
            if (atrbvh_intersect_batch(b, &g, rays, n, hits + (size_t)k * n, 1,
                                       &ke) != ATRBVH_OK)
                fails++;
        }
        ck_assert_int_eq(fails, 0);
        for (k = 0; k < 8; k++)
            for (i = 0; i < n; i++)
                ck_assert_msg(memcmp(&hits[(size_t)k * n + i], &ref[i],
                                     sizeof *ref) == 0,
                              "round %d call %d ray %zu differs", round, k, i);
        atrbvh_bvh_free(b);
    }
    free(rays);
    free(ref);
    free(hits);
    mesh_free(&m);
}
END_TEST

/* The wide batches prepare the common rays (float test) by their own
 * code and hand the others to the shared setup: rays at and just across
 * every limit of that choice (direction components at 2^-125 and 2^125,
 * zeros, subnormals, infinities and NaNs; origins at 2^126; tmin negative,
 * -0, at or past tmax; NaN limits) must give the counted batch's results
 * bit for bit, on triangles (indexed) and boxes. */
static void edge_ray(tu_rng *r, atrbvh_ray *ray)
{
    static const float dirs[] = {0.0f, -0.0f, 0x1p-125f, -0x1p-125f,
                                 0x1.fffffep-126f, -0x1.fffffep-126f,
                                 1e-40f, 0x1p125f, -0x1p125f,
                                 0x1.000002p125f, -0x1p126f, INFINITY,
                                 NAN, 0x1p-60f, -3.0e-20f};
    static const float orgs[] = {0x1p126f, -0x1p126f, 0x1.000002p126f,
                                 -0x1.000002p126f, INFINITY, NAN, 0x1p100f};
    int k = (int)(tu_rng_next(r) % 3), what = (int)(tu_rng_next(r) % 6);
    switch (what) {
    case 0:
    case 1:
    case 2:
        ray->dir[k] = dirs[tu_rng_next(r) % (sizeof dirs / sizeof *dirs)];
        break;
    case 3:
        ray->origin[k] = orgs[tu_rng_next(r) % (sizeof orgs / sizeof *orgs)];
        break;
    case 4: {
        static const float tmins[] = {-0.0f, -1e-30f, 0x1p-149f, -1.0f, NAN};
        size_t j = (size_t)(tu_rng_next(r) % 7);
        if (j < 5)
            ray->tmin = tmins[j];
        else if (j == 5)
            ray->tmin = ray->tmax;
        else
            ray->tmin = ray->tmax == INFINITY ? INFINITY
                                              : nextafterf(ray->tmax, 2.0f);
        break;
    }
    default: {
        static const float tmaxs[] = {NAN, -0.0f, 0.0f, 0x1p-149f};
        ray->tmax = tmaxs[tu_rng_next(r) % 4];
        break;
    }
    }
}

START_TEST(wide_setup_edges)
{
    mesh ms[2];
    int s;
    ms[0] = icosphere(3);
    ms[1] = random_boxes(400, 43);
    for (s = 0; s < 2; s++) {
        atrbvh_geometry g = mesh_geometry(&ms[s]);
        config c = {ATRBVH_METHOD_LBVH, 1, 4};
        atrbvh_bvh *b = build_config(&g, &c);
        size_t n = 8192, i, nhit = 0, edge_hits = 0;
        atrbvh_ray *rays = malloc(n * sizeof *rays);
        atrbvh_hit *hits = malloc(n * sizeof *hits);
        atrbvh_hit *bin = malloc(n * sizeof *bin);
        uint8_t *occ = malloc(n), *bocc = malloc(n);
        atrbvh_trace_stats ts;
        atrbvh_error e;
        tu_rng r;
        ck_assert(rays && hits && bin && occ && bocc);
        grazing_rays(&ms[s], b, n, 990 + (uint64_t)s, rays);
        tu_rng_seed(&r, 995 + (uint64_t)s);
        for (i = 0; i < n; i++)
            if (i % 4 != 0)
                edge_ray(&r, &rays[i]);
        ck_assert_int_eq(atrbvh_intersect_batch(b, &g, rays, n, hits, 2, &e),
                         ATRBVH_OK);
        ck_assert_int_eq(atrbvh_occluded_batch(b, &g, rays, n, occ, 2, &e),
                         ATRBVH_OK);
        atrbvh_trace_stats_init(&ts);
        ck_assert_int_eq(atrbvh_intersect_batch_stats(NULL, b, &g, rays, n,
                                                      bin, 1, &ts, &e),
                         ATRBVH_OK);
        ck_assert_int_eq(atrbvh_occluded_batch_stats(NULL, b, &g, rays, n,
                                                     bocc, 1, &ts, &e),
                         ATRBVH_OK);
        for (i = 0; i < n; i++) {
            ck_assert_msg(memcmp(&hits[i], &bin[i], sizeof *hits) == 0 &&
                              occ[i] == bocc[i],
                          "%s ray %zu (o %a %a %a d %a %a %a t %a..%a): the "
                          "batch gives prim %u t %a occluded %u, the counted "
                          "batch prim %u t %a occluded %u",
                          s ? "boxes" : "icosphere", i,
                          (double)rays[i].origin[0], (double)rays[i].origin[1],
                          (double)rays[i].origin[2], (double)rays[i].dir[0],
                          (double)rays[i].dir[1], (double)rays[i].dir[2],
                          (double)rays[i].tmin, (double)rays[i].tmax,
                          hits[i].primitive, (double)hits[i].t, occ[i],
                          bin[i].primitive, (double)bin[i].t, bocc[i]);
            nhit += hits[i].primitive != ATRBVH_NO_HIT;
            edge_hits += i % 4 != 0 && hits[i].primitive != ATRBVH_NO_HIT;
        }
        /* the edge rays must hit too, not only miss */
        ck_assert_msg(nhit > n / 20 && edge_hits > n / 40,
                      "%zu hits, %zu of the edge rays, of %zu", nhit,
                      edge_hits, n);
        atrbvh_bvh_free(b);
        free(rays);
        free(hits);
        free(bin);
        free(occ);
        free(bocc);
        mesh_free(&ms[s]);
    }
}
END_TEST

/* --------------------------------------------- wide batches: triangles
 * Over triangles the batches keep a copy of the leaves' vertices, made
 * for the geometry of the first batch (lib/traverse.c): its vertex and
 * index arrays, counts and strides.  A batch given other arrays must read
 * those, and the copy must be made right from every layout. */

/* Soup m with each triangle shrunk towards its vertex 0, in a new buffer:
 * every new vertex lies between two old ones, so inside the triangle's
 * own box and every node box above it (the tree stays valid). */
static mesh shrunk_soup(const mesh *m)
{
    mesh s;
    size_t i;
    int k, a;
    memset(&s, 0, sizeof s);
    s.nv = m->nv;
    s.nt = m->nt;
    s.v = malloc(9 * m->nt * sizeof *s.v);
    ck_assert_ptr_nonnull(s.v);
    for (i = 0; i < m->nt; i++)
        for (k = 0; k < 3; k++)
            for (a = 0; a < 3; a++)
                s.v[9 * i + 3 * k + a] =
                    k == 0 ? m->v[9 * i + a]
                           : (m->v[9 * i + 3 * k + a] + m->v[9 * i + a]) * 0.5f;
    return s;
}

START_TEST(wide_tris_other_geometry)
{
    mesh m = soup(1500, 61, 10.0f, -5.0f), sh = shrunk_soup(&m);
    mesh ico = icosphere(3);
    config c = {ATRBVH_METHOD_LBVH, 1, 4};
    atrbvh_geometry g = mesh_geometry(&m), gi = mesh_geometry(&ico), gr;
    atrbvh_bvh *b = build_config(&g, &c), *bi = build_config(&gi, &c);
    reference ref = ref_make(&sh);
    uint32_t *rot = malloc(3 * ico.nt * sizeof *rot);
    size_t i;
    ck_assert_ptr_nonnull(rot);
    /* the first batch makes the copy from m; a batch over the shrunk
     * triangles (another vertex buffer) must hit those */
    check_wide(&m, b, NULL, 4096, 1000, "soup (the copy's geometry)");
    check_wide(&sh, b, &ref, 2048, 1001, "shrunk soup, another buffer");
    check_wide(&m, b, NULL, 2048, 1002, "soup again");
    /* the same vertices through another index buffer, each triangle's
     * corners rotated: the same surfaces, other u and v */
    for (i = 0; i < ico.nt; i++) {
        rot[3 * i] = ico.idx[3 * i + 1];
        rot[3 * i + 1] = ico.idx[3 * i + 2];
        rot[3 * i + 2] = ico.idx[3 * i];
    }
    gr = atrbvh_geometry_triangles(ico.v, ico.nv, rot, ico.nt);
    check_wide(&ico, bi, NULL, 4096, 1003, "icosphere (the copy's)");
    check_wide_geometry(&ico, &gr, bi, NULL, 4096, 1004,
                        "icosphere, corners rotated");
    /* and fewer vertices than the copy was made with: the ids past the
     * count are out of range */
    gr = gi;
    gr.vertex_count = ico.nv / 2;
    check_wide_geometry(&ico, &gr, bi, NULL, 4096, 1005,
                        "icosphere, half the vertices");
    free(rot);
    ref_free(&ref);
    atrbvh_bvh_free(b);
    atrbvh_bvh_free(bi);
    mesh_free(&sh);
    mesh_free(&m);
    mesh_free(&ico);
}
END_TEST

START_TEST(wide_tris_layouts)
{
    mesh m = soup(1200, 71, 10.0f, -5.0f), ico = icosphere(3);
    mesh dg = soup(900, 72, 10.0f, -5.0f);
    reference rm = ref_make(&m), ri = ref_make(&ico), rd;
    config c = {ATRBVH_METHOD_LBVH, 1, 8};
    float *v4 = malloc(12 * m.nt * sizeof *v4);
    float *v5 = malloc(5 * ico.nv * sizeof *v5);
    uint32_t *i4 = malloc(4 * ico.nt * sizeof *i4);
    uint32_t *bad = malloc(3 * ico.nt * sizeof *bad);
    atrbvh_geometry g;
    atrbvh_bvh *b;
    size_t i, nbad = 0;
    int k;
    ck_assert(v4 && v5 && i4 && bad);
    /* a soup with 16-byte vertices (the fourth float NaN) */
    for (i = 0; i < 3 * m.nt; i++) {
        for (k = 0; k < 3; k++)
            v4[4 * i + (size_t)k] = m.v[3 * i + (size_t)k];
        v4[4 * i + 3] = NAN;
    }
    g = atrbvh_geometry_triangles(v4, 3 * m.nt, NULL, m.nt);
    g.vertex_stride = 4 * sizeof(float);
    b = build_config(&g, &c);
    check_wide_geometry(&m, &g, b, &rm, 4096, 1010, "soup, vertex stride 16");
    atrbvh_bvh_free(b);
    /* an indexed mesh with 20-byte vertices and 16-byte triangles */
    for (i = 0; i < ico.nv; i++) {
        for (k = 0; k < 3; k++)
            v5[5 * i + (size_t)k] = ico.v[3 * i + (size_t)k];
        v5[5 * i + 3] = v5[5 * i + 4] = -1e30f;
    }
    for (i = 0; i < ico.nt; i++) {
        for (k = 0; k < 3; k++)
            i4[4 * i + (size_t)k] = ico.idx[3 * i + (size_t)k];
        i4[4 * i + 3] = 0xffffffffu;
    }
    g = atrbvh_geometry_triangles(v5, ico.nv, i4, ico.nt);
    g.vertex_stride = 5 * sizeof(float);
    g.index_stride = 4 * sizeof(uint32_t);
    b = build_config(&g, &c);
    check_wide_geometry(&ico, &g, b, &ri, 4096, 1011,
                        "icosphere, strides 20 and 16");
    atrbvh_bvh_free(b);
    /* a tree built over the mesh, first traced with every seventh
     * triangle's corner 1 out of range: the copy is made from those, which
     * no batch may hit */
    memcpy(bad, ico.idx, 3 * ico.nt * sizeof *bad);
    for (i = 0; i < ico.nt; i += 7) {
        bad[3 * i + 1] = (uint32_t)ico.nv + (uint32_t)(i % 3);
        nbad++;
    }
    g = mesh_geometry(&ico);
    b = build_config(&g, &c);
    g.indices = bad;
    check_wide_geometry(&ico, &g, b, NULL, 4096, 1012,
                        "icosphere, vertex ids out of range");
    {
        size_t n = 4096, hit_bad = 0, nhit = 0;
        atrbvh_ray *rays = malloc(n * sizeof *rays);
        atrbvh_hit *hits = malloc(n * sizeof *hits);
        atrbvh_error e;
        ck_assert(rays && hits);
        grazing_rays(&ico, b, n, 1013, rays);
        ck_assert_int_eq(atrbvh_intersect_batch(b, &g, rays, n, hits, 2, &e),
                         ATRBVH_OK);
        for (i = 0; i < n; i++) {
            nhit += hits[i].primitive != ATRBVH_NO_HIT;
            hit_bad += hits[i].primitive != ATRBVH_NO_HIT &&
                       hits[i].primitive % 7u == 0u;
        }
        ck_assert_msg(hit_bad == 0 && nhit > n / 20,
                      "%zu hits, %zu on the %zu triangles out of range",
                      nhit, hit_bad, nbad);
        free(rays);
        free(hits);
    }
    atrbvh_bvh_free(b);
    /* degenerate triangles: a segment, a point, two equal corners */
    for (i = 0; i < dg.nt; i++) {
        float *t = dg.v + 9 * i;
        for (k = 0; k < 3; k++) {
            if (i % 5 == 1) /* collinear: corner 2 between 0 and 1 */
                t[6 + k] = (t[k] + t[3 + k]) * 0.5f;
            else if (i % 5 == 2) /* a point */
                t[3 + k] = t[6 + k] = t[k];
            else if (i % 5 == 3) /* corners 1 and 2 equal */
                t[6 + k] = t[3 + k];
        }
    }
    rd = ref_make(&dg);
    g = mesh_geometry(&dg);
    b = build_config(&g, &c);
    check_wide(&dg, b, &rd, 4096, 1014, "soup with degenerate triangles");
    atrbvh_bvh_free(b);
    ref_free(&rd);
    ref_free(&rm);
    ref_free(&ri);
    free(v4);
    free(v5);
    free(i4);
    free(bad);
    mesh_free(&m);
    mesh_free(&ico);
    mesh_free(&dg);
}
END_TEST

/* ------------------------------------ 8-wide batches: SSE2 and AVX2
 * The uncounted batches test the wide nodes' boxes with AVX2 where the CPU
 * has it, else with SSE2 (four lanes at a time); ATRBVH_NO_AVX2 set makes
 * them take SSE2 (lib/traverse.c, wide_avx2).  Both node tests must give
 * the counted batch's hits (the binary traversal) and every primitive's,
 * bit for bit; on a CPU without AVX2 both passes take SSE2.  setenv and
 * unsetenv are POSIX's (this file is compiled as plain C99). */
int setenv(const char *name, const char *value, int overwrite);
int unsetenv(const char *name);

START_TEST(wide_isa_paths)
{
    mesh ms[4];
    const char *names[4] = {"soup 900", "icosphere", "terrain", "boxes"};
    const size_t cfg[3] = {1, 3, 5};
    int s, isa;
    ms[0] = soup(900, 77, 10.0f, -5.0f);
    ms[1] = icosphere(4);
    ms[2] = terrain(24, 9);
    ms[3] = random_boxes(500, 78);
    for (s = 0; s < 4; s++) {
        atrbvh_geometry g = mesh_geometry(&ms[s]);
        reference ref = ref_make(&ms[s]);
        size_t c;
        for (c = 0; c < 3; c++) {
            atrbvh_bvh *b = build_config(&g, &configs[cfg[c]]);
            if (!b)
                continue;
            for (isa = 0; isa < 2; isa++) {
                char what[128];
                ck_assert_int_eq(isa ? unsetenv("ATRBVH_NO_AVX2")
                                     : setenv("ATRBVH_NO_AVX2", "1", 1),
                                 0);
                snprintf(what, sizeof what, "%s config %zu node test %s",
                         names[s], cfg[c], isa ? "AVX2 if any" : "SSE2");
                check_wide(&ms[s], b, &ref, 4096, 1100 + (uint64_t)c, what);
            }
            atrbvh_bvh_free(b);
        }
        ref_free(&ref);
        mesh_free(&ms[s]);
    }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("traverse");
    TCase *t = tcase_create("brute force");
    tcase_add_test(t, brute_force_soups);
    tcase_add_test(t, brute_force_meshes);
    tcase_add_test(t, brute_force_boxes);
    tcase_set_timeout(t, 600);
    suite_add_tcase(s, t);
    t = tcase_create("watertight");
    tcase_add_test(t, watertight);
    tcase_add_test(t, watertight_random_inside);
    tcase_set_timeout(t, 300);
    suite_add_tcase(s, t);
    t = tcase_create("batch");
    tcase_add_test(t, batch_equals_single);
    tcase_add_test(t, batch_errors);
    tcase_add_test(t, ties_lower_index);
    tcase_add_test(t, closed_interval);
    tcase_add_test(t, single_call_checks);
    tcase_add_test(t, threads_limit);
    tcase_set_timeout(t, 300);
    suite_add_tcase(s, t);
    t = tcase_create("wide");
    tcase_add_test(t, wide_batches);
    tcase_add_test(t, wide_after_refit);
    tcase_add_test(t, wide_concurrent_first_use);
    tcase_add_test(t, wide_setup_edges);
    tcase_add_test(t, wide_tris_other_geometry);
    tcase_add_test(t, wide_tris_layouts);
    tcase_add_test(t, wide_isa_paths);
    tcase_set_timeout(t, 600);
    suite_add_tcase(s, t);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(suite());
    int failed;
    srunner_run_all(sr, CK_NORMAL);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
