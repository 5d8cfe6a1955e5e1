/*
 * test_clrays.c - the OpenCL ray queries (atrbvh_intersect_batch_device,
 * atrbvh_occluded_batch_device) against the CPU ones, bit for bit
 * (primitive, t, u, v; occluded flags), on random rays, rays with zero
 * direction components, axis-aligned rays through vertices, rays aimed at
 * shared vertices and edge midpoints, clipped and degenerate rays, over
 * triangle soups, the builtin sphere and city, strided indexed geometry
 * and boxes, with collapsed and binary trees.  One closed interval
 * [tmin, tmax] for closest and any hit, on both.  The error paths.  Every
 * test skips, saying so, when no OpenCL device (or no OpenCL support) is
 * there.  The per-ray counts of atrbvh_*_batch_stats (boxes and
 * primitives tested) are the same on the device as on the CPU.  All of it
 * twice: with the caller's arrays in place on a device that shares the
 * host's memory, and with ATRBVH_CL_COPY (copies).
 */
#define _POSIX_C_SOURCE 200809L
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atrbvh.h"
#include "testutil.h"

static int have_device = -1;
static atrbvh_status why_st; /* the failed call's status */
static char why_not[ATRBVH_ERROR_TEXT_LENGTH];
/* The OpenCL device every query runs on: opened once (the program is
 * built at open), closed at the end of main. */
static atrbvh_device *cl_dev;

/* 1 when a device query over one box works; else 0, reason in why_not. */
static int device_available(void)
{
    if (have_device < 0) {
        static const float box[6] = {0, 0, 0, 1, 1, 1};
        atrbvh_geometry g = atrbvh_geometry_boxes(box, 1);
        atrbvh_bvh *b = NULL;
        atrbvh_error e;
        atrbvh_ray r = {{0.5f, 0.5f, -1.0f}, {0, 0, 1}, 0.0f, 10.0f};
        atrbvh_hit h;
        have_device = 0;
        if ((why_st = atrbvh_build(&g, NULL, &b, &e)) != ATRBVH_OK) {
            snprintf(why_not, sizeof why_not, "CPU build: %.200s", e.text);
        } else if ((why_st = atrbvh_device_open("opencl", &cl_dev, &e)) !=
                   ATRBVH_OK) {
            snprintf(why_not, sizeof why_not, "%s", e.text);
        } else if ((why_st = atrbvh_intersect_batch_device(
                        cl_dev, b, &g, &r, 1, &h, NULL, &e)) != ATRBVH_OK) {
            snprintf(why_not, sizeof why_not, "%s", e.text);
        } else {
            have_device = 1;
        }
        atrbvh_bvh_free(b);
    }
    return have_device;
}

#define REQUIRE_DEVICE()                                                       \
    do {                                                                       \
        if (!device_available()) {                                             \
            ck_assert_msg(tu_opencl_may_skip(why_st),                          \
                          "the OpenCL backend failed: %s", why_not);           \
            fprintf(stderr, "SKIP %s: no OpenCL device (%s)\n", __func__,      \
                    why_not);                                                  \
            return;                                                            \
        }                                                                      \
    } while (0)

static uint32_t fbits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

/* CPU and device, closest and any hit, every ray compared bit for bit. */
static void expect_same(const atrbvh_bvh *bvh, const atrbvh_geometry *g,
                        const atrbvh_ray *rays, size_t n, const char *what)
{
    atrbvh_hit *hc = malloc(n * sizeof *hc), *hd = malloc(n * sizeof *hd);
    uint8_t *oc = malloc(n), *od = malloc(n);
    atrbvh_error e;
    atrbvh_status st;
    double ms = -1.0;
    size_t i, hits = 0, occ = 0;
    ck_assert(hc && hd && oc && od);
    memset(hd, 0xab, n * sizeof *hd);
    memset(od, 0xab, n);
    ck_assert_int_eq(atrbvh_intersect_batch(bvh, g, rays, n, hc, 2, &e),
                     ATRBVH_OK);
    ck_assert_int_eq(atrbvh_occluded_batch(bvh, g, rays, n, oc, 2, &e),
                     ATRBVH_OK);
    st = atrbvh_intersect_batch_device(cl_dev, bvh, g, rays, n, hd, &ms, &e);
    ck_assert_msg(st == ATRBVH_OK, "%s: device closest hit: %s", what, e.text);
    ck_assert_msg(ms >= 0.0, "%s: kernel_ms %g", what, ms);
    st = atrbvh_occluded_batch_device(cl_dev, bvh, g, rays, n, od, NULL, &e);
    ck_assert_msg(st == ATRBVH_OK, "%s: device any hit: %s", what, e.text);
    for (i = 0; i < n; i++) {
        ck_assert_msg(hc[i].primitive == hd[i].primitive &&
                          fbits(hc[i].t) == fbits(hd[i].t) &&
                          fbits(hc[i].u) == fbits(hd[i].u) &&
                          fbits(hc[i].v) == fbits(hd[i].v),
                      "%s: ray %zu (o %a %a %a, d %a %a %a, [%a, %a]): cpu "
                      "prim %lu t %a u %a v %a, opencl prim %lu t %a u %a v "
                      "%a",
                      what, i, rays[i].origin[0], rays[i].origin[1],
                      rays[i].origin[2], rays[i].dir[0], rays[i].dir[1],
                      rays[i].dir[2], rays[i].tmin, rays[i].tmax,
                      (unsigned long)hc[i].primitive, hc[i].t, hc[i].u,
                      hc[i].v, (unsigned long)hd[i].primitive, hd[i].t,
                      hd[i].u, hd[i].v);
        ck_assert_msg(oc[i] == od[i], "%s: ray %zu: occluded cpu %d opencl %d",
                      what, i, oc[i], od[i]);
        hits += hc[i].primitive != ATRBVH_NO_HIT;
        occ += oc[i];
    }
    /* The exact ray cost: per ray, the same boxes and primitives tested on
     * the device as on the CPU, for both queries, with the same results. */
    {
        atrbvh_ray_cost *cc = malloc(n * sizeof *cc),
                        *cd = malloc(n * sizeof *cd);
        atrbvh_trace_stats sc, sd;
        int q;
        ck_assert(cc && cd);
        for (q = 0; q < 2; q++) {
            atrbvh_trace_stats_init(&sc);
            atrbvh_trace_stats_init(&sd);
            sc.per_ray = cc;
            sd.per_ray = cd;
            memset(cd, 0xab, n * sizeof *cd);
            if (q == 0) {
                ck_assert_int_eq(atrbvh_intersect_batch_stats(
                                     NULL, bvh, g, rays, n, hc, 2, &sc, &e),
                                 ATRBVH_OK);
                st = atrbvh_intersect_batch_stats(cl_dev, bvh, g, rays, n, hd,
                                                  0, &sd, &e);
            } else {
                ck_assert_int_eq(atrbvh_occluded_batch_stats(
                                     NULL, bvh, g, rays, n, oc, 2, &sc, &e),
                                 ATRBVH_OK);
                st = atrbvh_occluded_batch_stats(cl_dev, bvh, g, rays, n, od,
                                                 0, &sd, &e);
            }
            ck_assert_msg(st == ATRBVH_OK, "%s: device stats: %s", what,
                          e.text);
            ck_assert(q == 0 ? memcmp(hc, hd, n * sizeof *hc) == 0
                             : memcmp(oc, od, n) == 0);
            for (i = 0; i < n; i++)
                ck_assert_msg(cc[i].box_tests == cd[i].box_tests &&
                                  cc[i].prim_tests == cd[i].prim_tests,
                              "%s: %s ray %zu: cpu %u boxes %u prims, "
                              "opencl %u boxes %u prims",
                              what, q ? "any-hit" : "closest", i,
                              cc[i].box_tests, cc[i].prim_tests,
                              cd[i].box_tests, cd[i].prim_tests);
            ck_assert(sc.box_tests == sd.box_tests &&
                      sc.prim_tests == sd.prim_tests && sd.rays == n);
            ck_assert(sc.box_tests >= n / 2);
        }
        free(cc);
        free(cd);
    }
    /* The rays must exercise something. */
    ck_assert_msg(hits > n / 10 && hits < n, "%s: %zu hits of %zu rays", what,
                  hits, n);
    ck_assert_msg(occ >= hits, "%s: occluded %zu < hits %zu", what, occ, hits);
    free(hc);
    free(hd);
    free(oc);
    free(od);
}

/* Corner c of primitive i: a triangle vertex, or a box corner (bits of c
 * pick min/max per axis). */
static void corner(const atrbvh_geometry *g, size_t i, unsigned c, float p[3])
{
    int k;
    if (g->type == ATRBVH_GEOMETRY_BOXES) {
        const float *b = tu_box(g, i);
        for (k = 0; k < 3; k++)
            p[k] = (c >> k) & 1u ? b[3 + k] : b[k];
    } else {
        const float *q = tu_vertex(g, i, (int)(c % 3u));
        for (k = 0; k < 3; k++)
            p[k] = q[k];
    }
}

/* n rays of several kinds (see the file comment) plus the degenerate
 * ones; returns the count (n + 8). */
static size_t make_rays(const atrbvh_geometry *g, size_t n, uint64_t seed,
                        atrbvh_ray *rays)
{
    tu_rng rng;
    float lo[3], hi[3], ext[3];
    size_t i, m = 0;
    int k;
    tu_rng_seed(&rng, seed);
    tu_bounds(g, lo, hi);
    for (k = 0; k < 3; k++)
        ext[k] = hi[k] - lo[k] > 0.0f ? hi[k] - lo[k] : 1.0f;
    for (i = 0; i < n; i++) {
        atrbvh_ray *r = &rays[m++];
        size_t prim = (size_t)(tu_rng_next(&rng) % g->primitive_count);
        float a[3], b[3], target[3];
        unsigned kind = (unsigned)(i % 6u);
        for (k = 0; k < 3; k++)
            r->origin[k] = lo[k] + ext[k] * (1.5f * tu_rng_float(&rng) - 0.25f);
        r->tmin = 0.0f;
        r->tmax = INFINITY;
        corner(g, prim, (unsigned)(tu_rng_next(&rng) & 7u), a);
        corner(g, prim, (unsigned)(tu_rng_next(&rng) & 7u) + 1u, b);
        switch (kind) {
        case 0: /* random direction */
        case 1: /* ... with zero components (+0 and -0) */
            for (k = 0; k < 3; k++)
                r->dir[k] = 2.0f * tu_rng_float(&rng) - 1.0f;
            if (kind == 1) {
                int z = (int)(tu_rng_next(&rng) % 3u);
                r->dir[z] = (tu_rng_next(&rng) & 1u) ? 0.0f : -0.0f;
                if (tu_rng_next(&rng) & 1u)
                    r->dir[(z + 1) % 3] = 0.0f;
                /* aim the remaining axis at the primitive */
                for (k = 0; k < 3; k++)
                    if (r->dir[k] == 0.0f)
                        r->origin[k] = a[k];
                    else
                        r->dir[k] = a[k] - r->origin[k];
            }
            break;
        case 2: /* at a shared vertex */
            for (k = 0; k < 3; k++)
                r->dir[k] = a[k] - r->origin[k];
            break;
        case 3: /* at an edge midpoint */
            for (k = 0; k < 3; k++)
                target[k] = 0.5f * a[k] + 0.5f * b[k];
            for (k = 0; k < 3; k++)
                r->dir[k] = target[k] - r->origin[k];
            break;
        case 4: /* clipped: tmin > 0, tmax short of or past the target */
            for (k = 0; k < 3; k++)
                r->dir[k] = a[k] - r->origin[k];
            r->tmin = 0.25f * tu_rng_float(&rng);
            r->tmax = 0.5f + tu_rng_float(&rng);
            break;
        default: { /* axis-aligned through a vertex */
            int ax = (int)(tu_rng_next(&rng) % 3u);
            for (k = 0; k < 3; k++) {
                r->dir[k] = 0.0f;
                if (k != ax)
                    r->origin[k] = a[k];
            }
            r->origin[ax] = lo[ax] - ext[ax];
            r->dir[ax] = 1.0f;
            if (tu_rng_next(&rng) & 1u) {
                r->origin[ax] = hi[ax] + ext[ax];
                r->dir[ax] = -1.0f;
            }
            break;
        }
        }
    }
    /* Degenerate and extreme rays (NaN origin, zero direction, empty
     * interval, huge values, tiny components). */
    {
        static const atrbvh_ray bad[8] = {
            {{0, 0, 0}, {0, 0, 0}, 0.0f, 1e30f},
            {{0, 0, 0}, {1, 0, 0}, 1.0f, 0.5f},
            {{0, 0, 0}, {1, 1, 1}, 0.0f, 0.0f},
            {{0, 0, 0}, {-1, -1, -1}, -1e30f, 1e30f},
            {{1e30f, 1e30f, 1e30f}, {-1, -1, -1}, 0.0f, INFINITY},
            {{0, 0, 0}, {1e-30f, 1e-30f, 1.0f}, 0.0f, INFINITY},
            {{0, 0, 0}, {0, 1, 0}, 0.0f, INFINITY},
            {{0, 0, 0}, {0, 0, -1}, 0.0f, INFINITY}};
        for (i = 0; i < 8; i++)
            rays[m++] = bad[i];
        rays[m - 8].origin[0] = NAN;
    }
    return m;
}

static atrbvh_bvh *build(const atrbvh_geometry *g, atrbvh_method method,
                         int collapse, atrbvh_backend backend)
{
    atrbvh_build_options o;
    atrbvh_build_options_init(&o);
    o.method = method;
    o.collapse = collapse;
    o.backend = backend;
    return tu_build(g, &o);
}

#define NRAYS 6000

static void check_geometry(const atrbvh_geometry *g, const char *what,
                           uint64_t seed)
{
    static const struct {
        atrbvh_method m;
        int collapse;
    } cfg[2] = {{ATRBVH_METHOD_ATRBVH, 1}, {ATRBVH_METHOD_LBVH, 0}};
    atrbvh_ray *rays = malloc((NRAYS + 8) * sizeof *rays);
    size_t n, c;
    ck_assert(rays);
    n = make_rays(g, NRAYS, seed, rays);
    for (c = 0; c < 2; c++) {
        char name[96];
        atrbvh_bvh *b = build(g, cfg[c].m, cfg[c].collapse, ATRBVH_BACKEND_CPU);
        snprintf(name, sizeof name, "%s, %s", what,
                 cfg[c].collapse ? "atrbvh collapsed" : "lbvh binary");
        expect_same(b, g, rays, n, name);
        atrbvh_bvh_free(b);
    }
    free(rays);
}

/* ------------------------------------------------------------------ tests */
START_TEST(soup)
{
    float *v;
    atrbvh_geometry g;
    REQUIRE_DEVICE();
    v = tu_random_triangles(3000, 7, 10.0f, -5.0f);
    g = atrbvh_geometry_triangles(v, 9000, NULL, 3000);
    check_geometry(&g, "soup", 11);
    free(v);
}
END_TEST

START_TEST(builtin_scenes)
{
    static const char *const names[] = {"sphere", "city"};
    size_t i;
    REQUIRE_DEVICE();
    for (i = 0; i < 2; i++) {
        scene s;
        char err[128];
        atrbvh_geometry g;
        ck_assert_msg(scene_builtin(names[i], 20000, &s, err, sizeof err) == 0,
                      "%s", err);
        g = scene_geometry(&s);
        check_geometry(&g, names[i], 100 + i);
        scene_free(&s);
    }
}
END_TEST

/* A batch large enough that the implementation, left to itself, would
 * pick big work-groups (PoCL: 4096 items, which overflowed its stack with
 * the traversal's private arrays before the ray kernels got an explicit
 * size). */
START_TEST(large_batch)
{
    scene s;
    char err[128];
    atrbvh_geometry g;
    atrbvh_ray *rays;
    atrbvh_bvh *b;
    size_t n;
    REQUIRE_DEVICE();
    ck_assert(scene_builtin("sphere", 20000, &s, err, sizeof err) == 0);
    g = scene_geometry(&s);
    /* 196608 = 48 * 4096 rays in all: a size PoCL splits into groups of
     * 4096 when it may choose */
    rays = malloc(196608 * sizeof *rays);
    ck_assert(rays);
    n = make_rays(&g, 196608 - 8, 77, rays);
    ck_assert_uint_eq(n, 196608);
    b = build(&g, ATRBVH_METHOD_ATRBVH, 1, ATRBVH_BACKEND_CPU);
    expect_same(b, &g, rays, n, "sphere, 196608 rays");
    atrbvh_bvh_free(b);
    free(rays);
    scene_free(&s);
}
END_TEST

/* Indexed triangles with padded vertices (stride 16) and indices (stride
 * 16), and a tree built on the device. */
START_TEST(strided_and_device_built)
{
    scene s;
    char err[128];
    float *pv;
    uint32_t *pi;
    size_t i;
    int k;
    atrbvh_geometry g;
    atrbvh_ray *rays;
    atrbvh_bvh *b;
    size_t n;
    REQUIRE_DEVICE();
    ck_assert(scene_builtin("sphere", 5000, &s, err, sizeof err) == 0);
    pv = malloc(s.vertex_count * 4 * sizeof *pv);
    pi = malloc(s.triangle_count * 4 * sizeof *pi);
    ck_assert(pv && pi);
    for (i = 0; i < s.vertex_count; i++) {
        for (k = 0; k < 3; k++)
            pv[4 * i + k] = s.vertices[3 * i + k];
        pv[4 * i + 3] = NAN; /* never read */
    }
    for (i = 0; i < s.triangle_count; i++) {
        for (k = 0; k < 3; k++)
            pi[4 * i + k] = s.indices[3 * i + k];
        pi[4 * i + 3] = 0xffffffffu;
    }
    g = atrbvh_geometry_triangles(pv, s.vertex_count, pi, s.triangle_count);
    g.vertex_stride = 16;
    g.index_stride = 16;
    rays = malloc((NRAYS + 8) * sizeof *rays);
    ck_assert(rays);
    n = make_rays(&g, NRAYS, 5, rays);
    b = build(&g, ATRBVH_METHOD_TRBVH, 1, ATRBVH_BACKEND_OPENCL);
    expect_same(b, &g, rays, n, "strided sphere, trbvh built on OpenCL");
    atrbvh_bvh_free(b);
    free(rays);
    free(pv);
    free(pi);
    scene_free(&s);
}
END_TEST

START_TEST(boxes)
{
    tu_rng rng;
    float *bx = malloc(2000 * 7 * sizeof *bx);
    atrbvh_geometry g;
    size_t i;
    int k;
    REQUIRE_DEVICE();
    ck_assert(bx);
    tu_rng_seed(&rng, 3);
    /* stride 28 (7 floats); boxes snapped to a grid so faces coincide */
    for (i = 0; i < 2000; i++) {
        for (k = 0; k < 3; k++) {
            float a = floorf(16.0f * tu_rng_float(&rng)) * 0.5f;
            float d = floorf(1.0f + 4.0f * tu_rng_float(&rng)) * 0.25f;
            bx[7 * i + k] = a;
            bx[7 * i + 3 + k] = a + (i % 50 == 0 ? 0.0f : d);
        }
        bx[7 * i + 6] = NAN;
    }
    g = atrbvh_geometry_boxes(bx, 2000);
    g.box_stride = 28;
    check_geometry(&g, "boxes", 21);
    free(bx);
}
END_TEST

/* One interval on both backends: rays from the origin along +z meet a
 * triangle and a box face at exactly t = 1 (the box is left at t = 2);
 * tmin and tmax at, and one ulp past, those distances.  The device's
 * answers equal the CPU's bit for bit and the expected ones: a hit exactly
 * at tmin or tmax counts for closest and any hit alike. */
START_TEST(closed_interval)
{
    static const float tris[] = {-1, -1, 1, 1, -1, 1, 0, 1, 1,
                                 5, 5, 5, 6, 5, 5, 5, 6, 5};
    static const float bxs[] = {-1, -1, 1, 1, 1, 2, 5, 5, 5, 6, 6, 6};
    const float a1 = nextafterf(1.0f, 2.0f), b1 = nextafterf(1.0f, 0.0f);
    const float a2 = nextafterf(2.0f, 3.0f);
    /* tmin, tmax, expected t for the triangle, for the box (-1: miss) */
    const float cases[][4] = {
        {1.0f, INFINITY, 1.0f, 1.0f}, {0.0f, 1.0f, 1.0f, 1.0f},
        {1.0f, 1.0f, 1.0f, 1.0f},     {a1, INFINITY, -1.0f, 2.0f},
        {0.0f, b1, -1.0f, -1.0f},     {2.0f, INFINITY, -1.0f, 2.0f},
        {a2, INFINITY, -1.0f, -1.0f}, {0.0f, INFINITY, 1.0f, 1.0f},
    };
    enum { N = sizeof cases / sizeof *cases };
    atrbvh_geometry gs[2];
    int which;
    REQUIRE_DEVICE();
    gs[0] = atrbvh_geometry_triangles(tris, 6, NULL, 2);
    gs[1] = atrbvh_geometry_boxes(bxs, 2);
    for (which = 0; which < 2; which++) {
        atrbvh_bvh *b = build(&gs[which], ATRBVH_METHOD_LBVH, 0,
                              ATRBVH_BACKEND_CPU);
        atrbvh_ray rays[N];
        atrbvh_hit hc[N], hd[N];
        uint8_t oc[N], od[N];
        atrbvh_error e;
        size_t i;
        for (i = 0; i < N; i++) {
            atrbvh_ray r = {{0, 0, 0}, {0, 0, 1}, 0, 0};
            r.tmin = cases[i][0];
            r.tmax = cases[i][1];
            rays[i] = r;
        }
        ck_assert_int_eq(atrbvh_intersect_batch(b, &gs[which], rays, N, hc, 1,
                                                &e),
                         ATRBVH_OK);
        ck_assert_int_eq(atrbvh_occluded_batch(b, &gs[which], rays, N, oc, 1,
                                               &e),
                         ATRBVH_OK);
        ck_assert_msg(atrbvh_intersect_batch_device(cl_dev, b, &gs[which],
                                                    rays, N, hd, NULL, &e) ==
                          ATRBVH_OK,
                      "%s", e.text);
        ck_assert_msg(atrbvh_occluded_batch_device(cl_dev, b, &gs[which],
                                                   rays, N, od, NULL, &e) ==
                          ATRBVH_OK,
                      "%s", e.text);
        for (i = 0; i < N; i++) {
            float want = cases[i][2 + which];
            ck_assert_msg(hd[i].primitive == hc[i].primitive &&
                              fbits(hd[i].t) == fbits(hc[i].t) &&
                              od[i] == oc[i],
                          "%s case %zu: cpu %lu t %a occ %d, opencl %lu t %a "
                          "occ %d",
                          which ? "box" : "triangle", i,
                          (unsigned long)hc[i].primitive, (double)hc[i].t,
                          oc[i], (unsigned long)hd[i].primitive,
                          (double)hd[i].t, od[i]);
            if (want < 0.0f) {
                ck_assert_msg(hd[i].primitive == ATRBVH_NO_HIT && od[i] == 0,
                              "%s case %zu: a hit (t %a) outside [%a, %a]",
                              which ? "box" : "triangle", i, (double)hd[i].t,
                              (double)cases[i][0], (double)cases[i][1]);
            } else {
                ck_assert_msg(hd[i].primitive == 0 && hd[i].t == want &&
                                  od[i] == 1,
                              "%s case %zu: prim %lu t %a occ %d, expected t "
                              "%a in [%a, %a]",
                              which ? "box" : "triangle", i,
                              (unsigned long)hd[i].primitive, (double)hd[i].t,
                              od[i], (double)want, (double)cases[i][0],
                              (double)cases[i][1]);
            }
        }
        atrbvh_bvh_free(b);
    }
}
END_TEST

START_TEST(errors)
{
    static const float box[6] = {0, 0, 0, 1, 1, 1};
    atrbvh_geometry g = atrbvh_geometry_boxes(box, 1), bad;
    atrbvh_bvh *b = build(&g, ATRBVH_METHOD_LBVH, 0, ATRBVH_BACKEND_CPU);
    atrbvh_ray r = {{0.5f, 0.5f, -1.0f}, {0, 0, 1}, 0.0f, 10.0f};
    atrbvh_hit h;
    uint8_t o;
    atrbvh_error e;
    atrbvh_status st;
    double ms = 5.0;
    atrbvh_device *cpu = NULL;
    /* Argument errors, with or without OpenCL (checked before the device
     * is used: a "cpu" handle serves). */
    ck_assert_int_eq(atrbvh_device_open("cpu", &cpu, &e), ATRBVH_OK);
    ck_assert_int_eq(atrbvh_intersect_batch_device(cpu, NULL, &g, &r, 1, &h,
                                                   NULL, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_msg(strstr(e.text, "bvh is NULL"), "%s", e.text);
    ck_assert_int_eq(atrbvh_intersect_batch_device(NULL, b, &g, &r, 1, &h,
                                                   NULL, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_occluded_batch_device(cpu, b, &g, &r, 1, NULL,
                                                  &ms, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert(strstr(e.text, "output array is NULL"));
    ck_assert(ms == 0.0);
    ck_assert_int_eq(atrbvh_occluded_batch_device(cpu, b, &g, NULL, 1, &o,
                                                  NULL, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    bad = g;
    bad.box_stride = 26;
    ck_assert_int_eq(atrbvh_intersect_batch_device(cpu, b, &bad, &r, 1, &h,
                                                   NULL, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert(strstr(e.text, "multiple of 4"));
    bad = g;
    bad.primitive_count = 0;
    ck_assert_int_eq(atrbvh_intersect_batch_device(cpu, b, &bad, &r, 1, &h,
                                                   NULL, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_occluded_batch_device(cpu, b, &bad, &r, 1, &o,
                                                  NULL, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_msg(strstr(e.text, "primitives"), "%s", e.text);
    /* the single calls make the same check: a miss, not a read */
    ck_assert_int_eq(atrbvh_intersect(b, &bad, &r, &h), 0);
    ck_assert_uint_eq(h.primitive, ATRBVH_NO_HIT);
    ck_assert_int_eq(atrbvh_occluded(b, &bad, &r), 0);
    atrbvh_device_close(cpu);
    if (!device_available()) {
        ck_assert_msg(tu_opencl_may_skip(why_st),
                      "the OpenCL backend failed: %s", why_not);
        fprintf(stderr, "SKIP errors (device part): no OpenCL device (%s)\n",
                why_not);
        atrbvh_bvh_free(b);
        return;
    }
    st = atrbvh_intersect_batch_device(cl_dev, b, &g, &r, 1, &h, NULL, &e);
    ck_assert_int_eq(st, ATRBVH_OK);
    ck_assert_uint_eq(h.primitive, 0);
    ck_assert(h.t == 1.0f);
    /* count 0: nothing to do */
    ck_assert_int_eq(atrbvh_occluded_batch_device(cl_dev, b, &g, NULL, 0, NULL,
                                                  NULL, &e),
                     ATRBVH_OK);
    st = atrbvh_occluded_batch_device(cl_dev, b, &g, &r, 1, &o, &ms, &e);
    ck_assert_msg(st == ATRBVH_OK, "%s", e.text);
    ck_assert_uint_eq(o, 1);
    atrbvh_bvh_free(b);
}
END_TEST

static Suite *clrays_suite(void)
{
    Suite *s = suite_create("clrays");
    TCase *tc = tcase_create("agree");
    tcase_add_test(tc, soup);
    tcase_add_test(tc, builtin_scenes);
    tcase_add_test(tc, strided_and_device_built);
    tcase_add_test(tc, boxes);
    tcase_add_test(tc, large_batch);
    tcase_add_test(tc, closed_interval);
    tcase_set_timeout(tc, 240);
    suite_add_tcase(s, tc);
    tc = tcase_create("errors");
    tcase_add_test(tc, errors);
    tcase_set_timeout(tc, 120);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    /* Twice: on a device that shares the host's memory (PoCL's) the
     * batches use the caller's arrays in place, and with ATRBVH_CL_COPY
     * set at the open they copy them as on any other device. */
    int status = tu_run(clrays_suite());
    atrbvh_device_close(cl_dev);
    cl_dev = NULL;
    have_device = -1;
    if (setenv("ATRBVH_CL_COPY", "1", 1) != 0)
        return EXIT_FAILURE;
    if (tu_run(clrays_suite()) != EXIT_SUCCESS)
        status = EXIT_FAILURE;
    atrbvh_device_close(cl_dev);
    return status;
}
