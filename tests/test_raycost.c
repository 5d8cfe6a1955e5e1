/*
 * test_raycost.c - the exact cost of ray queries (atrbvh_trace_stats):
 * boxes and primitives tested per ray.
 *
 *  - A one-leaf tree: a closest-hit ray that meets the root box tests 1
 *    box and every primitive; a ray missing the root box tests 1 box and
 *    0 primitives; a ray that can hit nothing (NaN origin) costs 0.
 *  - An independent count: a recursive walk that visits every node whose
 *    box the ray meets (the same box test, no pruning).  A ray that hits
 *    nothing must cost exactly that (no hit, so nothing is pruned), for
 *    closest and any hit; a ray that hits must cost at most that, and test
 *    at least one primitive.  Box tests are always odd (the root, then two
 *    children per internal node visited).
 *  - The counts and the results are the same for 1, 2, 3 and 4 threads,
 *    through a CPU device handle, and with per_ray NULL (sums only); the
 *    results equal atrbvh_intersect_batch/atrbvh_occluded_batch bit for
 *    bit; the sums equal the per-ray counts' sums.
 *  - Errors: stats->size below the first version, threads with a device.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shared/traverse.h"
#include "testutil.h"

typedef struct scene_t {
    float *v;
    size_t n;
    atrbvh_geometry g;
    float lo[3], hi[3];
} scene_t;

static void scene_make(scene_t *s, size_t n, uint64_t seed)
{
    s->n = n;
    s->v = tu_random_triangles(n, seed, 10.0f, 0.0f);
    ck_assert(s->v != NULL);
    s->g = atrbvh_geometry_triangles(s->v, 3 * n, NULL, n);
    tu_bounds(&s->g, s->lo, s->hi);
}

/* Rays from inside and outside the scene box; a quarter aimed away from
 * it (misses), the rest through random points of the box. */
static void make_rays(const scene_t *s, atrbvh_ray *rays, size_t n,
                      uint64_t seed)
{
    tu_rng r;
    size_t i;
    int k;
    tu_rng_seed(&r, seed);
    for (i = 0; i < n; i++) {
        float o[3], p[3];
        for (k = 0; k < 3; k++) {
            float ext = s->hi[k] - s->lo[k];
            o[k] = s->lo[k] - ext + 3.0f * ext * tu_rng_float(&r);
            p[k] = s->lo[k] + ext * tu_rng_float(&r);
        }
        for (k = 0; k < 3; k++) {
            rays[i].origin[k] = o[k];
            rays[i].dir[k] = p[k] - o[k];
            if (i % 4 == 3)
                rays[i].dir[k] = -rays[i].dir[k];
        }
        rays[i].tmin = 0.0f;
        rays[i].tmax = (i % 3 == 0) ? INFINITY : 1.0f + tu_rng_float(&r);
    }
}

static atrbvh_bvh *build(const atrbvh_geometry *g, atrbvh_method m,
                         double ci, int collapse)
{
    atrbvh_build_options o;
    atrbvh_build_options_init(&o);
    o.method = m;
    o.ci = ci;
    o.collapse = collapse;
    return tu_build(g, &o);
}

/* ------------------------------------------------- the independent count */
typedef struct walk {
    atrbvh_trav_scene s;
    atrbvh_trav_ray r;
    float tlo, thi;
    uint64_t boxes, prims;
} walk;

/* Every node whose box the ray meets (the traversal's own box test, its
 * interval [tlo, thi] without any closest-hit pruning), recursively. */
static void walk_node(walk *w, uint32_t i)
{
    const atrbvh_node *n = &w->s.nodes[i];
    float tn;
    w->boxes++;
    if (!atrbvh_trav_node_hit(n, &w->r, w->tlo, w->thi, &tn))
        return;
    if (n->count > 0) {
        w->prims += n->count;
        return;
    }
    walk_node(w, i + 1);
    walk_node(w, n->index);
}

static void walk_count(const atrbvh_bvh *b, const scene_t *sc,
                       const atrbvh_ray *ray, uint64_t *boxes,
                       uint64_t *prims)
{
    walk w;
    size_t nn, np;
    memset(&w, 0, sizeof w);
    w.s.nodes = atrbvh_bvh_nodes(b, &nn);
    w.s.node_count = nn;
    w.s.prim_indices = atrbvh_bvh_primitive_indices(b, &np);
    w.s.prim_count = np;
    w.s.primitive_count = sc->n;
    ck_assert(atrbvh_trav_setup(ray->origin, ray->dir, ray->tmin, ray->tmax,
                                &w.r));
    /* the traversal's interval: both ends widened by the prune slack */
    w.tlo = ray->tmin - fabsf(ray->tmin) * ATRBVH_TRAV_PRUNE_SLACK;
    w.thi = atrbvh_trav_widen_limit(ray->tmax);
    walk_node(&w, 0);
    *boxes = w.boxes;
    *prims = w.prims;
}

/* ------------------------------------------------------------- the tests */
START_TEST(one_leaf)
{
    scene_t sc;
    atrbvh_bvh *b;
    size_t nn, n = 40, i, hit_box = 0, miss_box = 0;
    atrbvh_ray rays[64];
    atrbvh_hit hits[64];
    uint8_t occ[64];
    atrbvh_ray_cost cost[64];
    atrbvh_trace_stats st;
    atrbvh_error e;
    const atrbvh_node *root;
    uint64_t nb = 0, np = 0;
    scene_make(&sc, n, 5);
    /* a huge internal-node cost: the SAH collapse keeps one leaf */
    b = build(&sc.g, ATRBVH_METHOD_LBVH, 1e9, 1);
    ck_assert(b != NULL);
    root = atrbvh_bvh_nodes(b, &nn);
    ck_assert_uint_eq(nn, 1);
    ck_assert_uint_eq(root->count, n);
    make_rays(&sc, rays, 63, 17);
    /* a ray that can hit nothing costs 0 */
    rays[63] = rays[0];
    rays[63].origin[0] = NAN;
    atrbvh_trace_stats_init(&st);
    st.per_ray = cost;
    ck_assert_int_eq(atrbvh_intersect_batch_stats(NULL, b, &sc.g, rays, 64,
                                                  hits, 1, &st, &e),
                     ATRBVH_OK);
    for (i = 0; i < 64; i++) {
        atrbvh_trav_ray tr;
        float tn;
        int meets;
        if (i == 63) {
            ck_assert_uint_eq(cost[i].box_tests, 0);
            ck_assert_uint_eq(cost[i].prim_tests, 0);
            continue;
        }
        ck_assert(atrbvh_trav_setup(rays[i].origin, rays[i].dir,
                                    rays[i].tmin, rays[i].tmax, &tr));
        meets = atrbvh_trav_node_hit(root, &tr, rays[i].tmin,
                                     atrbvh_trav_widen_limit(rays[i].tmax),
                                     &tn);
        ck_assert_uint_eq(cost[i].box_tests, 1);
        ck_assert_uint_eq(cost[i].prim_tests, meets ? n : 0);
        hit_box += meets;
        miss_box += !meets;
        nb += cost[i].box_tests;
        np += cost[i].prim_tests;
    }
    ck_assert(hit_box > 10 && miss_box > 5);
    ck_assert_uint_eq(st.rays, 64);
    ck_assert_uint_eq(st.box_tests, nb);
    ck_assert_uint_eq(st.prim_tests, np);
    /* any hit: 1 box, and at most every primitive, 0 when it misses */
    ck_assert_int_eq(atrbvh_occluded_batch_stats(NULL, b, &sc.g, rays, 64,
                                                 occ, 1, &st, &e),
                     ATRBVH_OK);
    for (i = 0; i < 63; i++) {
        ck_assert_uint_eq(cost[i].box_tests, 1);
        ck_assert_uint_le(cost[i].prim_tests, n);
        if (occ[i])
            ck_assert_uint_ge(cost[i].prim_tests, 1);
    }
    atrbvh_bvh_free(b);
    free(sc.v);
}
END_TEST

START_TEST(independent_count)
{
    static const atrbvh_method methods[] = {ATRBVH_METHOD_LBVH,
                                            ATRBVH_METHOD_TRBVH,
                                            ATRBVH_METHOD_ATRBVH};
    scene_t sc;
    size_t n = 4000, m, i;
    atrbvh_ray *rays = malloc(n * sizeof *rays);
    atrbvh_hit *hits = malloc(n * sizeof *hits);
    uint8_t *occ = malloc(n);
    atrbvh_ray_cost *cc = malloc(n * sizeof *cc),
                    *ca = malloc(n * sizeof *ca);
    ck_assert(rays && hits && occ && cc && ca);
    scene_make(&sc, 3000, 23);
    make_rays(&sc, rays, n, 29);
    for (m = 0; m < 3 * 2; m++) {
        atrbvh_bvh *b = build(&sc.g, methods[m / 2], 1.2, (int)(m % 2));
        atrbvh_trace_stats st;
        atrbvh_error e;
        size_t misses = 0, hitting = 0;
        ck_assert(b != NULL);
        atrbvh_trace_stats_init(&st);
        st.per_ray = cc;
        ck_assert_int_eq(atrbvh_intersect_batch_stats(NULL, b, &sc.g, rays, n,
                                                      hits, 2, &st, &e),
                         ATRBVH_OK);
        st.per_ray = ca;
        ck_assert_int_eq(atrbvh_occluded_batch_stats(NULL, b, &sc.g, rays, n,
                                                     occ, 2, &st, &e),
                         ATRBVH_OK);
        for (i = 0; i < n; i++) {
            uint64_t wb, wp;
            walk_count(b, &sc, &rays[i], &wb, &wp);
            ck_assert_msg(cc[i].box_tests % 2 == 1 && ca[i].box_tests % 2 == 1,
                          "config %zu ray %zu: box tests %u, %u not odd", m,
                          i, cc[i].box_tests, ca[i].box_tests);
            if (hits[i].primitive == ATRBVH_NO_HIT) {
                ck_assert(!occ[i]);
                ck_assert_msg(cc[i].box_tests == wb && cc[i].prim_tests == wp,
                              "config %zu ray %zu (miss): %u/%u tests, the "
                              "walk %lu/%lu",
                              m, i, cc[i].box_tests, cc[i].prim_tests,
                              (unsigned long)wb, (unsigned long)wp);
                ck_assert(ca[i].box_tests == wb && ca[i].prim_tests == wp);
                misses++;
            } else {
                ck_assert(occ[i]);
                ck_assert(cc[i].box_tests <= wb && cc[i].prim_tests <= wp);
                ck_assert(ca[i].box_tests <= wb && ca[i].prim_tests <= wp);
                ck_assert(cc[i].prim_tests >= 1 && ca[i].prim_tests >= 1);
                hitting++;
            }
        }
        ck_assert(misses > n / 10 && hitting > n / 10);
        atrbvh_bvh_free(b);
    }
    free(rays);
    free(hits);
    free(occ);
    free(cc);
    free(ca);
    free(sc.v);
}
END_TEST

START_TEST(same_for_every_thread_count)
{
    scene_t sc;
    size_t n = 20000, i;
    int q, t;
    atrbvh_ray *rays = malloc(n * sizeof *rays);
    atrbvh_hit *h0 = malloc(n * sizeof *h0), *h = malloc(n * sizeof *h);
    uint8_t *o0 = malloc(n), *o = malloc(n);
    atrbvh_ray_cost *c1 = malloc(n * sizeof *c1), *c = malloc(n * sizeof *c);
    atrbvh_bvh *b;
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    ck_assert(rays && h0 && h && o0 && o && c1 && c);
    scene_make(&sc, 5000, 41);
    make_rays(&sc, rays, n, 43);
    b = build(&sc.g, ATRBVH_METHOD_ATRBVH, 1.2, 1);
    ck_assert(b != NULL);
    ck_assert_int_eq(atrbvh_device_open("cpu", &dev, &e), ATRBVH_OK);
    ck_assert_int_eq(atrbvh_intersect_batch(b, &sc.g, rays, n, h0, 1, &e),
                     ATRBVH_OK);
    ck_assert_int_eq(atrbvh_occluded_batch(b, &sc.g, rays, n, o0, 1, &e),
                     ATRBVH_OK);
    for (q = 0; q < 2; q++) {
        uint64_t sb = 0, sp = 0;
        /* t: 1..4 threads, 5 the CPU device, 6 sums only (per_ray NULL) */
        for (t = 1; t <= 6; t++) {
            atrbvh_trace_stats st;
            atrbvh_status s;
            atrbvh_device *d = t == 5 ? dev : NULL;
            int th = t <= 4 ? t : (t == 5 ? 0 : 3);
            atrbvh_trace_stats_init(&st);
            st.per_ray = t == 6 ? NULL : (t == 1 ? c1 : c);
            memset(c, 0xa5, n * sizeof *c);
            memset(h, 0xa5, n * sizeof *h);
            memset(o, 0xa5, n);
            s = q == 0 ? atrbvh_intersect_batch_stats(d, b, &sc.g, rays, n, h,
                                                      th, &st, &e)
                       : atrbvh_occluded_batch_stats(d, b, &sc.g, rays, n, o,
                                                     th, &st, &e);
            ck_assert_int_eq(s, ATRBVH_OK);
            ck_assert_uint_eq(st.rays, n);
            if (t == 1) {
                for (i = 0; i < n; i++) {
                    sb += c1[i].box_tests;
                    sp += c1[i].prim_tests;
                }
                ck_assert(sb > n && sp > n);
            } else if (t != 6) {
                ck_assert_msg(memcmp(c, c1, n * sizeof *c) == 0,
                              "query %d run %d: per-ray costs differ", q, t);
            }
            ck_assert_uint_eq(st.box_tests, sb);
            ck_assert_uint_eq(st.prim_tests, sp);
            if (q == 0)
                ck_assert(memcmp(h, h0, n * sizeof *h) == 0);
            else
                ck_assert(memcmp(o, o0, n) == 0);
        }
    }
    atrbvh_device_close(dev);
    atrbvh_bvh_free(b);
    free(rays);
    free(h0);
    free(h);
    free(o0);
    free(o);
    free(c1);
    free(c);
    free(sc.v);
}
END_TEST

START_TEST(errors)
{
    scene_t sc;
    atrbvh_bvh *b;
    atrbvh_ray rays[8];
    atrbvh_hit hits[8];
    atrbvh_trace_stats st;
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    scene_make(&sc, 50, 3);
    make_rays(&sc, rays, 8, 4);
    b = build(&sc.g, ATRBVH_METHOD_LBVH, 1.2, 0);
    ck_assert(b != NULL);
    atrbvh_trace_stats_init(&st);
    ck_assert_uint_eq(st.size, sizeof st);
    ck_assert(st.per_ray == NULL);
    st.size = sizeof(size_t);
    ck_assert_int_eq(atrbvh_intersect_batch_stats(NULL, b, &sc.g, rays, 8,
                                                  hits, 1, &st, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert(strstr(e.text, "size") != NULL);
    ck_assert_int_eq(atrbvh_device_open("cpu", &dev, &e), ATRBVH_OK);
    st.size = sizeof st;
    ck_assert_int_eq(atrbvh_intersect_batch_stats(dev, b, &sc.g, rays, 8,
                                                  hits, 2, &st, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert(strstr(e.text, "threads") != NULL);
    /* stats NULL: the plain batch */
    ck_assert_int_eq(atrbvh_intersect_batch_stats(NULL, b, &sc.g, rays, 8,
                                                  hits, 1, NULL, &e),
                     ATRBVH_OK);
    atrbvh_device_close(dev);
    atrbvh_bvh_free(b);
    free(sc.v);
}
END_TEST


/* ------------------------------------ the float node test at the extremes */
/* A random float of magnitude 2^emin .. 2^(emax + 1), either sign; with
 * `coarse` a 4-bit mantissa (sums and products then often exact). */
static float extreme_float(tu_rng *r, int emin, int emax, int coarse)
{
    int e = emin + (int)(tu_rng_float(r) * (float)(emax - emin + 1));
    double m = coarse ? 1.0 + (double)(int)(tu_rng_float(r) * 16.0f) / 16.0
                      : 1.0 + (double)tu_rng_float(r);
    double x = ldexp(m, e);
    if (e > emax)
        x = ldexp(1.0, emax);
    return (float)(tu_rng_float(r) < 0.5f ? -x : x);
}

/* The tightest float box around the exact point o + t d, a point box
 * where the point is a float.  t d is exact in double (t a float, or t of
 * at most 25 significant bits and d of 5); the sum is s + err
 * exactly (Knuth's two-sum), and f = (float)s is on the side of the true
 * point that the sign of (s - f) + err says (s - f is exact, and when
 * nonzero larger than |err|).  0 when the box leaves the range the float
 * test requires (+-2^126). */
static int box_around(const float o[3], const float d[3], double t,
                      float lo[3], float hi[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        double a = (double)o[k], b = t * (double)d[k];
        double s = a + b, bb = s - a, err = (a - (s - bb)) + (b - bb);
        float f = (float)s;
        int side = s > (double)f ? 1 : s < (double)f ? -1
                                     : (err > 0.0) - (err < 0.0);
        if (!(fabs(s) < ldexp(1.0, 125)))
            return 0;
        lo[k] = side >= 0 ? f : nextafterf(f, -INFINITY);
        hi[k] = side <= 0 ? f : nextafterf(f, INFINITY);
    }
    return 1;
}

/* Ize's widening, the subnormal slack and the pair test: a ray that passes
 * through a box (a point box or the tightest box around a point of the
 * ray, at distances down to subnormal ones, with direction components
 * anywhere from 2^-125 to 2^125 and coordinates up to 2^125) is never
 * rejected by the single-precision node test, whether the point is at the
 * ray's tmin, its tmax or inside; and the two children of a hand-made
 * three-node tree whose boxes both hold a point of the ray are both
 * visited (box tests 3, primitive tests 2: the leaves' primitives are
 * empty boxes, never hit).  Also boxes that the ray crosses only between
 * two consecutive floats (around the point at t halfway between a float
 * and the next, from the origin 0): in the subnormal range only the
 * absolute slack keeps those. */
START_TEST(float_box_conservative)
{
    tu_rng rng;
    size_t trial, used = 0, points = 0, subnormal = 0, halfway = 0;
    tu_rng_seed(&rng, 97);
    for (trial = 0; trial < 400000; trial++) {
        int coarse = trial % 2 == 0, k, j;
        float o[3], d[3], t[2], lo[2][3], hi[2][3];
        atrbvh_trav_ray r;
        atrbvh_node n[3];
        float pbox[12] = {1, 1, 1, -1, -1, -1, 1, 1, 1, -1, -1, -1};
        atrbvh_u32 prims[2] = {0, 1}, nb, np;
        atrbvh_trav_scene s;
        int ocase = (int)(tu_rng_float(&rng) * 3.0f);
        for (k = 0; k < 3; k++) {
            o[k] = ocase == 0 ? 0.0f
                   : ocase == 1 ? extreme_float(&rng, -149, 20, coarse)
                                : extreme_float(&rng, -20, 124, coarse);
            d[k] = extreme_float(&rng, -125, 124, coarse);
        }
        for (j = 0; j < 2; j++) {
            t[j] = fabsf(extreme_float(&rng, -149, 120, coarse));
            if (!box_around(o, d, t[j], lo[j], hi[j]))
                break;
        }
        if (j < 2)
            continue;
        ck_assert(atrbvh_trav_setup(o, d, 0.0f, INFINITY, &r));
        if (ocase == 0 && coarse) {
            /* halfway between t and the next float: 25 bits */
            double th = (double)t[0] +
                        ((double)nextafterf(t[0], INFINITY) - (double)t[0]) /
                            2.0;
            float bl[3], bh[3], tn;
            if (box_around(o, d, th, bl, bh)) {
                memcpy(n[0].min, bl, sizeof bl);
                memcpy(n[0].max, bh, sizeof bh);
                halfway++;
                ck_assert_msg(atrbvh_trav_node_hit_f(&n[0], &r, 0.0f,
                                                     INFINITY, &tn),
                              "trial %zu: d %a %a %a, box [%a %a %a, %a %a "
                              "%a] around t %a rejected",
                              trial, (double)d[0], (double)d[1],
                              (double)d[2], (double)bl[0], (double)bl[1],
                              (double)bl[2], (double)bh[0], (double)bh[1],
                              (double)bh[2], th);
            }
        }
        ck_assert_msg(r.use_float, "trial %zu: the ray takes the double test",
                      trial);
        used++;
        points += lo[0][0] == hi[0][0] && lo[0][1] == hi[0][1] &&
                  lo[0][2] == hi[0][2];
        subnormal += t[0] < 1.17549435e-38f;
        for (j = 0; j < 2; j++) {
            float tn, lims[4][2];
            int c;
            memcpy(n[0].min, lo[j], sizeof lo[j]);
            memcpy(n[0].max, hi[j], sizeof hi[j]);
            lims[0][0] = 0.0f, lims[0][1] = INFINITY;
            lims[1][0] = 0.0f, lims[1][1] = t[j];
            lims[2][0] = t[j], lims[2][1] = INFINITY;
            lims[3][0] = t[j], lims[3][1] = t[j];
            for (c = 0; c < 4; c++)
                ck_assert_msg(atrbvh_trav_node_hit_f(&n[0], &r, lims[c][0],
                                                     lims[c][1], &tn),
                              "trial %zu case %d: o %a %a %a d %a %a %a, box "
                              "[%a %a %a, %a %a %a] around t %a rejected",
                              trial, c, (double)o[0], (double)o[1],
                              (double)o[2], (double)d[0], (double)d[1],
                              (double)d[2], (double)lo[j][0],
                              (double)lo[j][1], (double)lo[j][2],
                              (double)hi[j][0], (double)hi[j][1],
                              (double)hi[j][2], (double)t[j]);
        }
        /* the pair: root = both boxes' union, leaves 1 and 2 */
        for (j = 0; j < 2; j++) {
            memcpy(n[1 + j].min, lo[j], sizeof lo[j]);
            memcpy(n[1 + j].max, hi[j], sizeof hi[j]);
            n[1 + j].index = (atrbvh_u32)j;
            n[1 + j].count = 1;
        }
        for (k = 0; k < 3; k++) {
            n[0].min[k] = fminf(lo[0][k], lo[1][k]);
            n[0].max[k] = fmaxf(hi[0][k], hi[1][k]);
        }
        n[0].index = 2;
        n[0].count = 0;
        memset(&s, 0, sizeof s);
        s.nodes = n;
        s.node_count = 3;
        s.prim_indices = prims;
        s.prim_count = 2;
        s.boxes = 1;
        s.primitive_count = 2;
        s.box_data = pbox;
        s.box_stride = 6;
        s.float_slabs = atrbvh_trav_scene_float(&s, 1);
        ck_assert(s.float_slabs);
        ck_assert(!atrbvh_trav_any_cost(&s, o, d, 0.0f, INFINITY, &nb, &np));
        ck_assert_msg(nb == 3 && np == 2,
                      "trial %zu: pair test: %u boxes, %u primitives", trial,
                      nb, np);
    }
    /* the cases must be there */
    ck_assert_msg(used > 200000 && points > 1000 && subnormal > 1000 &&
                      halfway > 10000,
                  "%zu trials used, %zu point boxes, %zu subnormal t, %zu "
                  "halfway",
                  used, points, subnormal, halfway);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("raycost");
    TCase *t = tcase_create("counts");
    tcase_add_test(t, one_leaf);
    tcase_add_test(t, independent_count);
    tcase_add_test(t, same_for_every_thread_count);
    tcase_add_test(t, errors);
    tcase_add_test(t, float_box_conservative);
    tcase_set_timeout(t, 300);
    suite_add_tcase(s, t);
    return s;
}

int main(void)
{
    return tu_run(suite());
}
