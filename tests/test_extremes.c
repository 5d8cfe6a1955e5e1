/*
 * test_extremes.c - numerical extremes (issue 6).
 *
 * Every case is built with each method (lbvh, trbvh, atrbvh) and checked:
 *  - a valid tree (tu_check_bvh: every primitive once, boxes nested, stats
 *    and SAH recomputed independently);
 *  - a finite SAH, and every node box that is not degenerate (positive
 *    extent on at least two axes) has a finite, nonzero surface area when
 *    computed as the library does (double, from float bounds), recomputed
 *    here;
 *  - the same bits on 1, 2, 3 and 4 threads, and on every backend this
 *    build has (a backend that answers ATRBVH_ERR_UNSUPPORTED is skipped:
 *    the loop is over BACKENDS below, so OpenCL is compared as soon as it
 *    exists);
 *  - ray queries that agree with brute force.  The brute force is a linear
 *    scan over one-primitive BVHs (the library's own primitive test, so
 *    the closest hit must agree exactly: primitive and t bits, and any-hit
 *    likewise); this checks the traversal and the node boxes at the
 *    extremes.  Independently of the library, each ray is aimed (in double)
 *    at the centre of a primitive along a direction away from its plane: a
 *    hit must be found no farther than that centre (relative 1e-4), and
 *    when the aimed triangle itself is hit, its t must match the double
 *    computation to 1e-4 relative.  This test only uses triangles that are
 *    wide compared with the rounding of the ray (inradius above 1e-3 of
 *    the distance to the origin), so it cannot fail spuriously at any
 *    scale.
 *
 * The large cases (millions of primitives) are cut down when
 * $ATRBVH_TEST_SANITIZER is set (the ASan stage: shadow memory, slow code).
 */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "testutil.h"

static const atrbvh_backend BACKENDS[] = {ATRBVH_BACKEND_CPU,
                                          ATRBVH_BACKEND_OPENCL};
#define NBACKENDS (sizeof BACKENDS / sizeof BACKENDS[0])
static const atrbvh_method METHODS[] = {ATRBVH_METHOD_LBVH, ATRBVH_METHOD_TRBVH,
                                        ATRBVH_METHOD_ATRBVH};
static const char *const METHOD_NAMES[] = {"lbvh", "trbvh", "atrbvh"};

static int sanitizer_run(void)
{
    const char *s = getenv("ATRBVH_TEST_SANITIZER");
    return s && *s && strcmp(s, "0") != 0;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ------------------------------------------------------- primitive access */
static void prim_vertices(const atrbvh_geometry *g, size_t i, double v[3][3])
{
    int c, k;
    for (c = 0; c < 3; c++) {
        const float *p = tu_vertex(g, i, c);
        for (k = 0; k < 3; k++)
            v[c][k] = p[k];
    }
}

static void prim_bounds(const atrbvh_geometry *g, size_t i, double lo[3],
                        double hi[3])
{
    int k, c;
    if (g->type == ATRBVH_GEOMETRY_BOXES) {
        const float *b = tu_box(g, i);
        for (k = 0; k < 3; k++) {
            lo[k] = b[k];
            hi[k] = b[k + 3];
        }
        return;
    }
    {
        double v[3][3];
        prim_vertices(g, i, v);
        for (k = 0; k < 3; k++) {
            lo[k] = hi[k] = v[0][k];
            for (c = 1; c < 3; c++) {
                lo[k] = v[c][k] < lo[k] ? v[c][k] : lo[k];
                hi[k] = v[c][k] > hi[k] ? v[c][k] : hi[k];
            }
        }
    }
}

/* The geometry of primitive i alone (the same memory). */
static atrbvh_geometry single(const atrbvh_geometry *g, size_t i)
{
    atrbvh_geometry s = *g;
    s.primitive_count = 1;
    if (g->type == ATRBVH_GEOMETRY_BOXES) {
        s.boxes = tu_box(g, i);
    } else if (g->indices) {
        s.indices = (const uint32_t *)((const char *)g->indices +
                                       i * (g->index_stride ? g->index_stride
                                                            : 12));
    } else {
        size_t vs = g->vertex_stride ? g->vertex_stride : 12;
        s.vertices = (const float *)((const char *)g->vertices + 3 * i * vs);
        s.vertex_count = 3;
    }
    return s;
}

/* ------------------------------------------------------------ node areas */
/* Every node with positive extent on two axes or more has a finite,
 * nonzero area computed as the library does (double from float bounds). */
static void check_areas(const atrbvh_bvh *b, const char *what)
{
    size_t n, i;
    const atrbvh_node *nodes = atrbvh_bvh_nodes(b, &n);
    atrbvh_stats st;
    for (i = 0; i < n; i++) {
        double dx = (double)nodes[i].max[0] - (double)nodes[i].min[0];
        double dy = (double)nodes[i].max[1] - (double)nodes[i].min[1];
        double dz = (double)nodes[i].max[2] - (double)nodes[i].min[2];
        double s = dx * dy;
        int positive = (dx > 0) + (dy > 0) + (dz > 0);
        s = s + dy * dz;
        s = s + dz * dx;
        s = 2.0 * s;
        ck_assert_msg(isfinite(dx) && isfinite(dy) && isfinite(dz) &&
                          dx >= 0 && dy >= 0 && dz >= 0,
                      "%s: node %zu has a bad box", what, i);
        if (positive >= 2)
            ck_assert_msg(isfinite(s) && s > 0,
                          "%s: node %zu (extent %g %g %g) has area %g", what,
                          i, dx, dy, dz, s);
    }
    atrbvh_bvh_stats(b, &st);
    ck_assert_msg(isfinite(st.sah) && st.sah >= 0, "%s: SAH %g", what, st.sah);
    ck_assert_msg(isfinite(atrbvh_sah(nodes, n, st.ci, st.ct)), "%s: sah()",
                  what);
}

/* ------------------------------------------------------------ brute force */
typedef struct oracle {
    const atrbvh_geometry *g;
    atrbvh_bvh **singles; /* one BVH per primitive, or NULL */
    atrbvh_geometry *sg;
    atrbvh_bvh *flat;     /* or: one leaf holding everything */
} oracle;

static void oracle_init(oracle *o, const atrbvh_geometry *g)
{
    size_t i, n = g->primitive_count;
    atrbvh_build_options opt;
    memset(o, 0, sizeof *o);
    o->g = g;
    atrbvh_build_options_init(&opt);
    opt.method = ATRBVH_METHOD_LBVH;
    opt.threads = 1;
    if (n <= 4096) {
        o->singles = calloc(n, sizeof *o->singles);
        o->sg = calloc(n, sizeof *o->sg);
        ck_assert(o->singles && o->sg);
        for (i = 0; i < n; i++) {
            o->sg[i] = single(g, i);
            o->singles[i] = tu_build(&o->sg[i], &opt);
        }
    } else {
        /* A prohibitive internal-node cost (against a negligible primitive
         * cost) collapses the root: one leaf,
         * a linear scan.  (Needs a root of nonzero area.) */
        size_t nn;
        opt.ci = 1e29;
        opt.ct = 1e-29;
        opt.threads = 2;
        o->flat = tu_build(g, &opt);
        atrbvh_bvh_nodes(o->flat, &nn);
        ck_assert_msg(nn == 1, "oracle: %zu nodes, expected one leaf", nn);
    }
}

static void oracle_free(oracle *o)
{
    size_t i;
    if (o->singles)
        for (i = 0; i < o->g->primitive_count; i++)
            atrbvh_bvh_free(o->singles[i]);
    free(o->singles);
    free(o->sg);
    atrbvh_bvh_free(o->flat);
}

/* Closest hit by brute force: lowest t, the lowest index on a tie. */
static int oracle_hit(const oracle *o, const atrbvh_ray *r, atrbvh_hit *best,
                      int *occluded)
{
    size_t i;
    if (o->flat) {
        *occluded = atrbvh_occluded(o->flat, o->g, r);
        return atrbvh_intersect(o->flat, o->g, r, best);
    }
    best->primitive = ATRBVH_NO_HIT;
    best->t = INFINITY;
    *occluded = 0;
    for (i = 0; i < o->g->primitive_count; i++) {
        atrbvh_hit h;
        if (atrbvh_occluded(o->singles[i], &o->sg[i], r))
            *occluded = 1;
        if (atrbvh_intersect(o->singles[i], &o->sg[i], r, &h) &&
            (best->primitive == ATRBVH_NO_HIT || h.t < best->t)) {
            *best = h;
            best->primitive = (uint32_t)i;
        }
    }
    return best->primitive != ATRBVH_NO_HIT;
}

/* A ray aimed at the centre of primitive `p` (its box centre), from a
 * distance of a quarter of the scene's largest extent (at least the
 * primitive's own), along its normal tilted by a random direction.
 * Everything in double, then rounded; the direction is recomputed from the
 * rounded origin.  Returns the distance to the centre in units of t, or 0
 * when no such ray exists in float.  *inradius_rel is set to 0 when the
 * independent check cannot apply (a thin triangle or box, a ray nearly in
 * the triangle's plane, an origin inside the box), else above 1e-3. */
static double aim(const atrbvh_geometry *g, size_t p, const double scene_lo[3],
                  const double scene_hi[3], tu_rng *rng, atrbvh_ray *ray,
                  double *inradius_rel)
{
    double lo[3], hi[3], c[3], nrm[3] = {0, 0, 0}, d[3], len = 0, ext = 0,
           o[3], dir[3], scale = 1, t, dist;
    int k, box_ok = 0;
    prim_bounds(g, p, lo, hi);
    for (k = 0; k < 3; k++) {
        c[k] = 0.5 * lo[k] + 0.5 * hi[k];
        if (scene_hi[k] - scene_lo[k] > ext)
            ext = scene_hi[k] - scene_lo[k];
        if (hi[k] - lo[k] > ext)
            ext = hi[k] - lo[k];
    }
    *inradius_rel = 0;
    if (g->type == ATRBVH_GEOMETRY_TRIANGLES) {
        double v[3][3], e1[3], e2[3], area2, per = 0;
        prim_vertices(g, p, v);
        for (k = 0; k < 3; k++) {
            /* aim at the true centroid: strictly inside the triangle */
            c[k] = (v[0][k] + v[1][k] + v[2][k]) / 3.0;
            e1[k] = v[1][k] - v[0][k];
            e2[k] = v[2][k] - v[0][k];
        }
        nrm[0] = e1[1] * e2[2] - e1[2] * e2[1];
        nrm[1] = e1[2] * e2[0] - e1[0] * e2[2];
        nrm[2] = e1[0] * e2[1] - e1[1] * e2[0];
        area2 = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
        for (k = 0; k < 3; k++) {
            double a = v[(k + 1) % 3][0] - v[k][0],
                   b = v[(k + 1) % 3][1] - v[k][1],
                   cc = v[(k + 1) % 3][2] - v[k][2];
            per += sqrt(a * a + b * b + cc * cc);
        }
        /* inradius = 2A / perimeter, relative to the ray's length below */
        if (area2 > 0 && per > 0 && ext > 0)
            *inradius_rel = (area2 / per) / (0.25 * ext);
        if (area2 > 0)
            for (k = 0; k < 3; k++)
                nrm[k] /= area2;
    }
    for (k = 0; k < 3; k++) {
        d[k] = nrm[k] + (double)tu_rng_float(rng) - 0.5;
        len += d[k] * d[k];
    }
    len = sqrt(len);
    if (!(len > 0))
        return 0;
    if (!(ext > 0))
        ext = fabs(c[0]) + fabs(c[1]) + fabs(c[2]) + 1.0;
    dist = 0.25 * ext;
    if (g->type == ATRBVH_GEOMETRY_BOXES) {
        /* start outside the box: beyond its diagonal */
        double diag = 0;
        int wide = 0;
        for (k = 0; k < 3; k++)
            diag += (hi[k] - lo[k]) * (hi[k] - lo[k]);
        dist += sqrt(diag);
        for (k = 0; k < 3; k++)
            wide += hi[k] - lo[k] > 1e-3 * dist;
        box_ok = wide >= 2;
    }
    for (k = 0; k < 3; k++) {
        o[k] = c[k] + d[k] / len * dist;
        if (o[k] > FLT_MAX)
            o[k] = FLT_MAX;
        if (o[k] < -FLT_MAX)
            o[k] = -FLT_MAX;
        ray->origin[k] = (float)o[k];
    }
    for (k = 0; k < 3; k++) {
        dir[k] = c[k] - (double)ray->origin[k];
        if (fabs(dir[k]) > 0.5 * FLT_MAX)
            scale = 0.25;
    }
    for (k = 0; k < 3; k++)
        ray->dir[k] = (float)(dir[k] * scale);
    if (ray->dir[0] == 0 && ray->dir[1] == 0 && ray->dir[2] == 0)
        return 0;
    ray->tmin = 0.0f;
    ray->tmax = INFINITY;
    t = 1.0 / scale;
    if (g->type == ATRBVH_GEOMETRY_BOXES) {
        /* clamping may have put the origin back inside */
        int inside = 1;
        for (k = 0; k < 3; k++)
            inside &= (double)ray->origin[k] >= lo[k] &&
                      (double)ray->origin[k] <= hi[k];
        *inradius_rel = box_ok && !inside ? 1.0 : 0.0;
    }
    /* Rounding the origin (coarse far from 0) may tilt the ray into the
     * triangle's plane: the independent test needs a clear angle. */
    if (*inradius_rel > 0) {
        double dl = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        double cosang = fabs(nrm[0] * dir[0] + nrm[1] * dir[1] +
                             nrm[2] * dir[2]) / dl;
        if (!(cosang > 0.1))
            *inradius_rel = 0;
    }
    return t;
}

static size_t rays_total, rays_independent, cases_total;

/* Rays at up to `nrays` primitives (all when fewer), checked against the
 * oracle and the independent aim. */
static void check_rays(const atrbvh_bvh *b, const atrbvh_geometry *g,
                       const oracle *o, size_t nrays, const char *what)
{
    double slo[3], shi[3];
    size_t i, k, n = g->primitive_count;
    tu_rng rng;
    size_t independent = 0;
    tu_rng_seed(&rng, 99);
    for (k = 0; k < 3; k++) {
        slo[k] = INFINITY;
        shi[k] = -INFINITY;
    }
    for (i = 0; i < n; i++) {
        double lo[3], hi[3];
        prim_bounds(g, i, lo, hi);
        for (k = 0; k < 3; k++) {
            slo[k] = lo[k] < slo[k] ? lo[k] : slo[k];
            shi[k] = hi[k] > shi[k] ? hi[k] : shi[k];
        }
    }
    for (i = 0; i < nrays; i++) {
        size_t p = n <= nrays ? i % n : (size_t)(tu_rng_next(&rng) % n);
        atrbvh_ray ray;
        atrbvh_hit h, bh;
        int hit, bhit, occ, bocc;
        double inr, texp = aim(g, p, slo, shi, &rng, &ray, &inr);
        if (texp == 0)
            continue;
        hit = atrbvh_intersect(b, g, &ray, &h);
        occ = atrbvh_occluded(b, g, &ray);
        bhit = oracle_hit(o, &ray, &bh, &bocc);
        ck_assert_msg(hit == bhit, "%s: ray %zu at primitive %zu: hit %d, "
                      "brute force %d", what, i, p, hit, bhit);
        ck_assert_msg(occ == bocc, "%s: ray %zu: occluded %d, brute force %d",
                      what, i, occ, bocc);
        if (hit) {
            ck_assert_msg(h.primitive == bh.primitive &&
                              memcmp(&h.t, &bh.t, sizeof h.t) == 0,
                          "%s: ray %zu: hit %u at %.9g, brute force %u at "
                          "%.9g",
                          what, i, h.primitive, (double)h.t, bh.primitive,
                          (double)bh.t);
            ck_assert_msg(occ, "%s: ray %zu hits but is not occluded", what,
                          i);
        }
        /* independent: boxes are always hit before their centre; wide
         * triangles are hit at their centroid */
        if (inr > 1e-3) {
            independent++;
            ck_assert_msg(hit, "%s: ray %zu aimed at primitive %zu missed",
                          what, i, p);
            ck_assert_msg((double)h.t <= texp * (1 + 1e-4),
                          "%s: ray %zu: t %.9g beyond the aimed centre %.9g",
                          what, i, (double)h.t, texp);
            if (g->type == ATRBVH_GEOMETRY_TRIANGLES && h.primitive == p)
                ck_assert_msg(fabs((double)h.t - texp) <= 1e-4 * texp,
                              "%s: ray %zu: t %.9g, expected %.9g", what, i,
                              (double)h.t, texp);
        }
    }
    rays_total += nrays;
    rays_independent += independent;
}

/* ------------------------------------------------------------- the check */
typedef struct case_opts {
    size_t rays;       /* 0: 64 */
    int methods;       /* bit mask of METHODS, 0: all */
    int collapse_both; /* also without collapse, and with max_leaf 2 */
    int max_threads;   /* 0: 4 */
} case_opts;

/* Builds `g` every way and checks everything; `what` names the case. */
static void check_case(const char *what, const atrbvh_geometry *g,
                       const case_opts *co)
{
    size_t m;
    oracle o;
    size_t rays = co && co->rays ? co->rays : 64;
    int mask = co && co->methods ? co->methods : 7;
    int variants = co && co->collapse_both ? 3 : 1;
    int max_threads = co && co->max_threads ? co->max_threads : 4;
    oracle_init(&o, g);
    for (m = 0; m < 3; m++) {
        int var;
        if (!(mask & (1 << m)))
            continue;
        for (var = 0; var < variants; var++) {
            atrbvh_build_options opt;
            atrbvh_bvh *ref;
            char name[160], msg[256];
            int t;
            size_t be;
            atrbvh_build_options_init(&opt);
            opt.method = METHODS[m];
            opt.collapse = var != 1;
            opt.max_leaf_size = var == 2 ? 2 : 0;
            opt.threads = 1;
            snprintf(name, sizeof name, "%s [%s%s]", what, METHOD_NAMES[m],
                     var == 1 ? ", no collapse" : var == 2 ? ", max leaf 2" : "");
            ref = tu_build(g, &opt);
            ck_assert_msg(tu_check_bvh(ref, g, msg, sizeof msg), "%s: %s",
                          name, msg);
            check_areas(ref, name);
            for (be = 0; be < NBACKENDS; be++) {
                for (t = 1; t <= max_threads; t++) {
                    atrbvh_bvh *b = NULL;
                    atrbvh_error e;
                    atrbvh_status s;
                    if (be == 0 && t == 1)
                        continue;
                    opt.backend = BACKENDS[be];
                    opt.threads = t;
                    s = atrbvh_build(g, &opt, &b, &e);
                    if (s == ATRBVH_ERR_UNSUPPORTED &&
                        BACKENDS[be] != ATRBVH_BACKEND_CPU &&
                        tu_opencl_may_skip(s))
                        break; /* this build has no such backend */
                    ck_assert_msg(s == ATRBVH_OK, "%s backend %d threads %d: "
                                  "%s", name, (int)BACKENDS[be], t, e.text);
                    ck_assert_msg(tu_same_bvh(ref, b, msg, sizeof msg),
                                  "%s: backend %d, %d threads differ from "
                                  "cpu/1: %s",
                                  name, (int)BACKENDS[be], t, msg);
                    atrbvh_bvh_free(b);
                }
            }
            check_rays(ref, g, &o, rays, name);
            atrbvh_bvh_free(ref);
            cases_total++;
        }
    }
    oracle_free(&o);
}

static void check_triangles(const char *what, const float *v, size_t n,
                            const case_opts *co)
{
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
    check_case(what, &g, co);
}

/* --------------------------------------------------------------- scales */
/* Random triangles with each coordinate (2u - 1 + jitter) * scale +
 * offset, computed in double and rounded once. */
static float *soup(size_t n, uint64_t seed, double scale, double offset)
{
    tu_rng r;
    size_t i;
    float *v = malloc(n * 9 * sizeof *v);
    ck_assert_ptr_nonnull(v);
    tu_rng_seed(&r, seed);
    for (i = 0; i < n; i++) {
        double c[3];
        int k, j;
        for (k = 0; k < 3; k++)
            c[k] = 2.0 * tu_rng_float(&r) - 1.0;
        for (j = 0; j < 3; j++)
            for (k = 0; k < 3; k++) {
                double x = (c[k] + 0.1 * (tu_rng_float(&r) - 0.5));
                if (x > 1)
                    x = 1;
                if (x < -1)
                    x = -1;
                v[9 * i + 3 * j + k] = (float)(x * scale + offset);
            }
    }
    return v;
}

START_TEST(scaled)
{
    static const double scales[] = {1e-40, 1e-30, 1e-20, 1e-3, 1e+20, 1e+30,
                                    1e+37, 0.999 * FLT_MAX};
    double s = scales[_i];
    float *v = soup(200, (uint64_t)_i + 1, s, 0.0);
    char what[64];
    snprintf(what, sizeof what, "scale %g", s);
    check_triangles(what, v, 200, NULL);
    free(v);
}
END_TEST

START_TEST(whole_float_range)
{
    /* Boxes that span the whole float range, alongside tiny ones: node
     * extents up to 2*FLT_MAX (areas ~1e77 in double, finite). */
    enum { N = 40 };
    float b[N * 6];
    int i, k;
    tu_rng r;
    atrbvh_geometry g;
    tu_rng_seed(&r, 5);
    for (i = 0; i < N; i++)
        for (k = 0; k < 3; k++) {
            double a = (2.0 * tu_rng_float(&r) - 1.0) * FLT_MAX;
            double c = (2.0 * tu_rng_float(&r) - 1.0) * FLT_MAX;
            b[6 * i + k] = (float)(a < c ? a : c);
            b[6 * i + 3 + k] = (float)(a < c ? c : a);
        }
    for (k = 0; k < 3; k++) {
        b[k] = -FLT_MAX;
        b[3 + k] = FLT_MAX;
        b[6 + k] = nextafterf(0.0f, 1.0f); /* the smallest subnormal */
        b[9 + k] = 2 * nextafterf(0.0f, 1.0f);
    }
    g = atrbvh_geometry_boxes(b, N);
    check_case("boxes over the whole float range", &g, NULL);
    /* mixed magnitudes: triangles of size 1e-30 and 1e30 in one scene */
    {
        float *t1 = soup(100, 7, 1e-30, 0.0), *t2 = soup(100, 8, 1e30, 0.0);
        float *t = malloc(200 * 9 * sizeof *t);
        memcpy(t, t1, 900 * sizeof *t);
        memcpy(t + 900, t2, 900 * sizeof *t);
        check_triangles("mixed magnitudes 1e-30 and 1e30", t, 200, NULL);
        free(t);
        free(t1);
        free(t2);
    }
}
END_TEST

START_TEST(translated)
{
    /* Far from the origin: float spacing is 1 at 1e7, 2^43 at 1e20.  The
     * relative size 1e-5 at 1e7 leaves triangles ~10 units wide on a grid of
     * 1; the 1e-7 cases collapse many vertices onto each other. */
    static const double offsets[] = {1e7, 1e7, 1e9, 1e12, 1e20, -3e38};
    static const double rel[] = {1e-3, 1e-7, 1e-5, 1e-4, 1e-6, 1e-3};
    float *v = soup(200, 20 + (uint64_t)_i, offsets[_i] * rel[_i] *
                                                (offsets[_i] < 0 ? -1 : 1),
                    offsets[_i]);
    char what[96];
    snprintf(what, sizeof what, "translated by %g, size %g", offsets[_i],
             fabs(offsets[_i]) * rel[_i]);
    check_triangles(what, v, 200, NULL);
    free(v);
}
END_TEST

/* ----------------------------------------------------------------- flat */
START_TEST(flat)
{
    /* _i = number of axes with zero extent (1, 2, 3) */
    size_t n = 300, i;
    float *v = soup(n, 30 + (uint64_t)_i, 1.0, 0.0);
    char what[64];
    for (i = 0; i < 3 * n; i++) {
        if (_i >= 1)
            v[3 * i + 2] = 0.5f; /* z */
        if (_i >= 2)
            v[3 * i + 1] = -2.0f; /* y */
        if (_i >= 3)
            v[3 * i + 0] = 7.0f; /* x */
    }
    snprintf(what, sizeof what, "flat on %d axes", _i);
    check_triangles(what, v, n, NULL);
    /* the same as boxes: zero extent on the axes */
    {
        float *b = malloc(n * 6 * sizeof *b);
        atrbvh_geometry g;
        for (i = 0; i < n; i++) {
            int k;
            for (k = 0; k < 3; k++) {
                float a = v[9 * i + k], c = v[9 * i + 3 + k];
                b[6 * i + k] = a < c ? a : c;
                b[6 * i + 3 + k] = a < c ? c : a;
            }
        }
        g = atrbvh_geometry_boxes(b, n);
        snprintf(what, sizeof what, "flat boxes on %d axes", _i);
        check_case(what, &g, NULL);
        free(b);
    }
    free(v);
}
END_TEST

START_TEST(same_centroid)
{
    /* Every box centre is exactly (1, 2, 3): all Morton keys equal. */
    enum { N = 257 };
    float *v = malloc(N * 9 * sizeof *v), b[N * 6];
    atrbvh_geometry g;
    int i, k;
    for (i = 0; i < N; i++) {
        float h = 0.5f + (float)i / 64.0f;
        const float c[3] = {1, 2, 3};
        for (k = 0; k < 3; k++) {
            b[6 * i + k] = c[k] - h * (float)(k + 1);
            b[6 * i + 3 + k] = c[k] + h * (float)(k + 1);
        }
        /* a triangle whose bounding box is [c - h, c + h] */
        v[9 * i + 0] = c[0] - h; v[9 * i + 1] = c[1] - h; v[9 * i + 2] = c[2] - h;
        v[9 * i + 3] = c[0] + h; v[9 * i + 4] = c[1] + h; v[9 * i + 5] = c[2];
        v[9 * i + 6] = c[0];     v[9 * i + 7] = c[1] - h * 0.5f;
        v[9 * i + 8] = c[2] + h;
    }
    g = atrbvh_geometry_boxes(b, N);
    check_case("boxes with one centre", &g, NULL);
    check_triangles("triangles with one box centre", v, N, NULL);
    free(v);
}
END_TEST

START_TEST(identical)
{
    enum { N = 500 };
    float *v = malloc(N * 9 * sizeof *v);
    static const float t[9] = {0.25f, -1, 3, 1.5f, 0, 3.5f, -0.5f, 2, 2.75f};
    int i;
    for (i = 0; i < N; i++)
        memcpy(v + 9 * i, t, sizeof t);
    check_triangles("500 identical triangles", v, N, NULL);
    /* indexed: 500 triangles over the same three vertices */
    {
        uint32_t idx[N * 3];
        atrbvh_geometry g;
        for (i = 0; i < 3 * N; i++)
            idx[i] = (uint32_t)(i % 3);
        g = atrbvh_geometry_triangles(t, 3, idx, N);
        check_case("500 indexed copies", &g, NULL);
    }
    free(v);
}
END_TEST

START_TEST(one_and_two)
{
    static const float t[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0,
                                0, 0, 1, 1, 0, 1, 0, 1, 1};
    static const float b[12] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3};
    static const float same[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0,
                                   0, 0, 0, 1, 0, 0, 0, 1, 0};
    case_opts co = {0, 0, 1, 0};
    atrbvh_geometry g;
    check_triangles("one triangle", t, 1, &co);
    check_triangles("two triangles", t, 2, &co);
    check_triangles("two identical triangles", same, 2, &co);
    g = atrbvh_geometry_boxes(b, 1);
    check_case("one box", &g, &co);
    g = atrbvh_geometry_boxes(b, 2);
    check_case("two boxes", &g, &co);
    {
        static const float pt[6] = {1, 1, 1, 1, 1, 1};
        g = atrbvh_geometry_boxes(pt, 1);
        check_case("one point box", &g, &co);
    }
}
END_TEST

START_TEST(degenerate_triangles)
{
    enum { N = 400 };
    float *v = soup(N, 40, 1.0, 0.0);
    int i, k;
    for (i = 0; i < N; i++) {
        float *p = v + 9 * i;
        switch (i % 4) {
        case 0: /* collinear: the third vertex is the midpoint */
            for (k = 0; k < 3; k++)
                p[6 + k] = 0.5f * p[k] + 0.5f * p[3 + k];
            break;
        case 1: /* two equal vertices */
            memcpy(p + 3, p, 3 * sizeof *p);
            break;
        case 2: /* a point */
            memcpy(p + 3, p, 3 * sizeof *p);
            memcpy(p + 6, p, 3 * sizeof *p);
            break;
        default: /* a needle: the third vertex one ulp off the first */
            for (k = 0; k < 3; k++)
                p[6 + k] = nextafterf(p[k], INFINITY);
            break;
        }
    }
    check_triangles("zero-area and needle triangles", v, N, NULL);
    /* needles among ordinary triangles, at two scales */
    {
        float *w = soup(N, 41, 1e20, 0.0);
        for (i = 0; i < N; i += 3)
            for (k = 0; k < 3; k++)
                w[9 * i + 6 + k] = nextafterf(w[9 * i + 3 + k], 0.0f);
        check_triangles("needles among triangles at 1e20", w, N, NULL);
        free(w);
    }
    free(v);
}
END_TEST

/* ------------------------------------------------- NaN and Inf policy */
START_TEST(nonfinite_boxes_and_indexed)
{
    enum { N = 64 };
    float b[N * 6], vert[(N + 2) * 3];
    uint32_t idx[N * 3];
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_bvh *bvh = NULL;
    atrbvh_error e;
    atrbvh_stats st;
    char msg[256];
    int i, t;
    tu_rng r;
    tu_rng_seed(&r, 8);
    for (i = 0; i < N; i++) {
        int k;
        for (k = 0; k < 3; k++) {
            float a = tu_rng_float(&r), c = tu_rng_float(&r);
            b[6 * i + k] = a < c ? a : c;
            b[6 * i + 3 + k] = a < c ? c : a;
        }
    }
    for (i = 0; i < (N + 2) * 3; i++)
        vert[i] = tu_rng_float(&r);
    for (i = 0; i < N; i++) {
        idx[3 * i] = (uint32_t)i;
        idx[3 * i + 1] = (uint32_t)i + 1;
        idx[3 * i + 2] = (uint32_t)i + 2;
    }
    /* boxes: Inf in box 40's max, NaN in box 9's min */
    b[6 * 40 + 4] = INFINITY;
    b[6 * 9 + 1] = NAN;
    g = atrbvh_geometry_boxes(b, N);
    for (t = 1; t <= 4; t++) {
        atrbvh_build_options_init(&o);
        o.threads = t;
        ck_assert_int_eq(atrbvh_build(&g, &o, &bvh, &e), ATRBVH_ERR_NONFINITE);
        ck_assert_ptr_null(bvh);
        ck_assert_uint_eq(e.index, 9);
        ck_assert_msg(strstr(e.text, "box 9 ") != NULL, "%s", e.text);
    }
    o.skip_invalid = 1;
    ck_assert_int_eq(atrbvh_build(&g, &o, &bvh, &e), ATRBVH_OK);
    atrbvh_bvh_stats(bvh, &st);
    ck_assert_uint_eq(st.invalid_skipped, 2);
    ck_assert_msg(tu_check_bvh(bvh, &g, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_free(bvh);
    /* -inf as a min is not finite either */
    b[6 * 9 + 1] = 0.0f;
    b[6 * 40 + 4] = 1.0f;
    b[6 * 50 + 0] = -INFINITY;
    o.skip_invalid = 0;
    ck_assert_int_eq(atrbvh_build(&g, &o, &bvh, &e), ATRBVH_ERR_NONFINITE);
    ck_assert_uint_eq(e.index, 50);

    /* indexed triangles: vertex 30 is NaN and used by triangles 28, 29,
     * 30; vertex N + 1 (used by triangle N - 1 only) is -Inf.  The first
     * is named; skip_invalid leaves out exactly those four. */
    vert[3 * 30 + 2] = NAN;
    vert[3 * (N + 1)] = -INFINITY;
    g = atrbvh_geometry_triangles(vert, N + 2, idx, N);
    for (t = 1; t <= 4; t++) {
        atrbvh_build_options_init(&o);
        o.threads = t;
        ck_assert_int_eq(atrbvh_build(&g, &o, &bvh, &e), ATRBVH_ERR_NONFINITE);
        ck_assert_uint_eq(e.index, 28);
        ck_assert_msg(strstr(e.text, "triangle 28 ") != NULL, "%s", e.text);
    }
    o.skip_invalid = 1;
    ck_assert_int_eq(atrbvh_build(&g, &o, &bvh, &e), ATRBVH_OK);
    atrbvh_bvh_stats(bvh, &st);
    ck_assert_uint_eq(st.invalid_skipped, 4);
    ck_assert_uint_eq(st.primitives, N - 4);
    ck_assert_msg(tu_check_bvh(bvh, &g, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_free(bvh);
    /* a NaN in a vertex no triangle uses is not looked at */
    vert[3 * 30 + 2] = 0.5f;
    vert[3 * (N + 1)] = 0.5f;
    idx[3 * (N - 1) + 2] = (uint32_t)N; /* vertex N + 1 now unused */
    vert[3 * (N + 1) + 1] = NAN;
    o.skip_invalid = 0;
    ck_assert_int_eq(atrbvh_build(&g, &o, &bvh, &e), ATRBVH_OK);
    atrbvh_bvh_stats(bvh, &st);
    ck_assert_uint_eq(st.invalid_skipped, 0);
    atrbvh_bvh_free(bvh);
    /* a bad index beats a NaN, even with skip_invalid, even when later */
    vert[3 * 5] = NAN;
    idx[3 * 40 + 1] = N + 7;
    o.skip_invalid = 1;
    ck_assert_int_eq(atrbvh_build(&g, &o, &bvh, &e), ATRBVH_ERR_INDEX_RANGE);
    ck_assert_uint_eq(e.index, 40);
}
END_TEST

/* --------------------------------------------------- limits, allocation */
START_TEST(beyond_the_limit)
{
    /* Counts past ATRBVH_MAX_PRIMITIVES are refused before any
     * allocation, for every kind of geometry (the arrays are never read:
     * the count is checked first). */
    static const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    static const uint32_t idx[3] = {0, 1, 2};
    static const size_t counts[] = {ATRBVH_MAX_PRIMITIVES + 1,
                                    ATRBVH_MAX_PRIMITIVES * 2,
                                    (size_t)UINT32_MAX + 1, SIZE_MAX};
    atrbvh_geometry gs[3];
    size_t c, k;
    gs[0] = atrbvh_geometry_triangles(v, 3, NULL, 1);
    gs[1] = atrbvh_geometry_triangles(v, 3, idx, 1);
    gs[2] = atrbvh_geometry_boxes(v, 1);
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    for (c = 0; c < sizeof counts / sizeof *counts; c++)
        for (k = 0; k < 3; k++) {
            atrbvh_bvh *b = NULL;
            atrbvh_error e;
            atrbvh_geometry g = gs[k];
            size_t m;
            g.primitive_count = counts[c];
            for (m = 0; m < 3; m++) {
                atrbvh_build_options o;
                atrbvh_build_options_init(&o);
                o.method = METHODS[m];
                tu_alloc.allocations = 0;
                ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e),
                                 ATRBVH_ERR_TOO_LARGE);
                ck_assert_int_eq(tu_alloc.allocations, 0);
                ck_assert_ptr_null(b);
                ck_assert_msg(strstr(e.text, "limit") != NULL, "%s", e.text);
            }
        }
    atrbvh_set_allocator(NULL, NULL);
}
END_TEST

/* ------------------------------------------------------------ large runs */
START_TEST(morton_collisions)
{
    /* Millions of boxes in [0, 1e-6]^3 plus one box at (1, 1, 1): the
     * cluster falls into a handful of Morton cells (the centroid box is
     * 1e6 times larger), so the keys collide in runs of hundreds of
     * thousands and the hierarchy splits them by position alone.  Without
     * the outlier the cluster is spread over the 2^63 keys.  lbvh both ways,
     * atrbvh on the colliding keys. */
    size_t n = sanitizer_run() ? 200000 : 2000000, i;
    float *b = malloc(n * 6 * sizeof *b);
    tu_rng r;
    int outlier;
    ck_assert_ptr_nonnull(b);
    tu_rng_seed(&r, 77);
    for (i = 0; i < n; i++) {
        int k;
        for (k = 0; k < 3; k++) {
            float lo = tu_rng_float(&r) * 1e-6f;
            b[6 * i + k] = lo;
            b[6 * i + 3 + k] = lo + tu_rng_float(&r) * 1e-8f;
        }
    }
    for (outlier = 1; outlier >= 0; outlier--) {
        atrbvh_geometry g;
        oracle o;
        int m;
        for (i = 0; i < 6; i++)
            b[i] = outlier ? 1.0f : 5e-7f;
        g = atrbvh_geometry_boxes(b, n);
        oracle_init(&o, &g);
        /* lbvh both ways; atrbvh on the colliding keys */
        for (m = 0; m < 3; m += outlier ? 2 : 3) {
            atrbvh_build_options opt;
            atrbvh_bvh *x, *y;
            char msg[256], name[96];
            double t0 = now_s();
            atrbvh_build_options_init(&opt);
            opt.method = METHODS[m];
            opt.threads = 2;
            x = tu_build(&g, &opt);
            snprintf(name, sizeof name, "%zu boxes in 1e-6, %s, %s", n,
                     outlier ? "outlier" : "no outlier", METHOD_NAMES[m]);
            fprintf(stderr, "extremes: %s: built in %.1f s\n", name,
                    now_s() - t0);
            ck_assert_msg(tu_check_bvh(x, &g, msg, sizeof msg), "%s: %s",
                          name, msg);
            check_areas(x, name);
            {
                atrbvh_stats st;
                atrbvh_bvh_stats(x, &st);
                /* a balanced split of equal keys: depth ~ log2 n */
                ck_assert_msg(st.max_depth < 200, "%s: depth %u", name,
                              st.max_depth);
            }
            if (m == 0) { /* the thread count does not matter */
                opt.threads = 1;
                y = tu_build(&g, &opt);
                ck_assert_msg(tu_same_bvh(x, y, msg, sizeof msg), "%s: %s",
                              name, msg);
                atrbvh_bvh_free(y);
            }
            check_rays(x, &g, &o, 24, name);
            atrbvh_bvh_free(x);
        }
        oracle_free(&o);
    }
    free(b);
}
END_TEST

START_TEST(largest_scene)
{
    /* The largest scene this suite builds: builtin:city at 6 million
     * triangles (about 1.2 GB peak), one atrbvh build on 2 threads, checked
     * in full and queried. */
    size_t want = sanitizer_run() ? 300000 : 6000000;
    scene s;
    char err[256], msg[256];
    atrbvh_geometry g;
    atrbvh_build_options opt;
    atrbvh_bvh *b;
    atrbvh_stats st;
    oracle o;
    double t0;
    ck_assert_msg(scene_builtin("city", want, &s, err, sizeof err) == 0, "%s",
                  err);
    g = scene_geometry(&s);
    atrbvh_build_options_init(&opt);
    opt.threads = 2;
    t0 = now_s();
    b = tu_build(&g, &opt);
    atrbvh_bvh_stats(b, &st);
    fprintf(stderr, "extremes: builtin:city, %zu triangles: atrbvh built in "
            "%.1f s (%zu nodes, SAH %.2f)\n",
            s.triangle_count, now_s() - t0, st.nodes, st.sah);
    ck_assert_uint_ge(s.triangle_count, want / 2);
    ck_assert_msg(tu_check_bvh(b, &g, msg, sizeof msg), "%s", msg);
    check_areas(b, "largest scene");
    oracle_init(&o, &g);
    check_rays(b, &g, &o, 16, "largest scene");
    oracle_free(&o);
    atrbvh_bvh_free(b);
    scene_free(&s);
}
END_TEST

/* A sliver with coordinates from 1e-28 to 4e36 (triangle 4, found by
 * fuzz_build): the double-precision edge functions cancel and used to
 * report a hit at t = 7.5e-14, at x = -0.73 where no vertex has x below
 * 3.5e-19.  A one-primitive tree kept that false hit, a bigger tree pruned
 * its leaf behind a real hit, so the answer depended on the tree.  Now a
 * hit must lie in the ray's interval through the triangle's own box. */
START_TEST(sliver_false_hit)
{
    static const float v[54] = {
        -0x1.766938p-1f, 0x1.63c5acp-1f, 0x1.0e1afp-1f, -0x1.f59e5ep-2f, -0x1.2b2a88p-7f, -0x1.9dc4eap-4f, 0x1.36766p-2f, 0x1.27a718p-1f, -0x1.9fe346p-1f,
        -0x1.e2f8e2p-1f, 0x1.57d2cep-1f, -0x1.1362d6p-3f, 0x1.0c9326p-1f, -0x1.fdd7eap-1f, -0x1.bf635ap-4f, 0x1.c5b6c8p-2f, -0x1.15bf5cp-1f, 0x1.c7f50ap-1f,
        0x1.9b0fccp-1f, -0x1.e0ad04p-1f, -0x1.e5f186p-1f, 0x1.53404p-4f, 0x1.c1b052p-1f, -0x1.e69662p-3f, -0x1.2233c4p-1f, -0x1.3f02bp-3f, -0x1.e24322p-1f,
        -0x1.1cfcdcp-1f, -0x1.fcd328p-4f, -0x1.1272eep-7f, -0x1.11525p-1f, -0x1.1397b8p-1f, -0x1.1ff7dep-1f, -0x1.4aedacp-4f, -0x1.ae86fap-2f, -0x1.e9fe9ap-1f,
        0x1.ae800ap-38f, -0x1.794c7ep+79f, -0x1.6b3a7ap-92f, 0x1.a1ca7cp-62f, 0x1.5d4d7ep+121f, 0x1.95d27ep-15f, 0x1.356c7ep+5f, -0x1.a3e97ep-41f, -0x1.999f7cp+70f,
        0x1.85507cp+99f, 0x1.fcdd7ep-99f, -0x1.d3297ep+125f, 0x1.72ef7ap-109f, 0x1.525178p-110f, -0x1.97b97ep-2f, 0x1.51f4ep-1f, 0x1.5cc92ap-2f, -0x1.92b388p-2f};
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 18, NULL, 6);
    atrbvh_ray ray;
    atrbvh_hit h, best;
    atrbvh_bvh *b;
    int k, i;
    for (k = 0; k < 3; k++) {
        ray.origin[k] = v[k];
        ray.dir[k] = v[3 + k] - v[k];
    }
    ray.tmin = 0.0f;
    ray.tmax = INFINITY;
    best.primitive = ATRBVH_NO_HIT;
    best.t = INFINITY;
    for (i = 0; i < 6; i++) {
        atrbvh_geometry one = atrbvh_geometry_triangles(v + 9 * i, 3, NULL, 1);
        atrbvh_bvh *s = tu_build(&one, NULL);
        if (atrbvh_intersect(s, &one, &ray, &h) && h.t < best.t) {
            best = h;
            best.primitive = (uint32_t)i;
        }
        if (i == 4)
            ck_assert_msg(!atrbvh_intersect(s, &one, &ray, &h) || h.t > 1.0f,
                          "false hit on the sliver at t = %g", (double)h.t);
        atrbvh_bvh_free(s);
    }
    for (k = 0; k < 3; k++) {
        atrbvh_build_options o;
        atrbvh_build_options_init(&o);
        o.method = (atrbvh_method)k;
        b = tu_build(&g, &o);
        ck_assert(atrbvh_intersect(b, &g, &ray, &h));
        ck_assert_uint_eq(h.primitive, best.primitive);
        ck_assert(memcmp(&h.t, &best.t, sizeof h.t) == 0);
        atrbvh_bvh_free(b);
    }
}
END_TEST

/* Hits just behind the origin (found by fuzz_build), each in one leaf with
 * a primitive ahead: a flat box at z = -1e-30, and a triangle of the plane
 * z = y, which a ray from (0, -1e-30, 0) along +z crosses at z = -1e-30.
 * With a direction of 1e16 the exact distance, -1e-46, rounds to -0.0f, which passed t >= tmin = 0: the box behind was reported at
 * t = -0 by a tree whose root leaf also held a real hit ahead, and not by
 * its one-primitive tree (its root box behind the origin); the triangle
 * was hit at -0 by both.  Now the limits are compared in double, before
 * rounding. */
START_TEST(behind_origin_underflow)
{
    static const float boxes[12] = {
        -1.0f, -1.0f, -1e-30f, 1.0f, 1.0f, -1e-30f, /* flat, behind */
        -1.0f, -1.0f, 0.5f,    1.0f, 1.0f, 1.0f};   /* ahead */
    static const float tris[18] = {
        -1e-20f, -1e-20f, -1e-20f, 1e-20f, -1e-20f, -1e-20f,
        0.0f,    1e-20f,  1e-20f,  /* the plane z = y */
        -1e-20f, -1e-20f, 2.5e-21f, 1e-20f, -1e-20f, 2.5e-21f,
        0.0f,    1e-20f,  2.5e-21f}; /* ahead */
    atrbvh_geometry g[2];
    int kind, k;
    g[0] = atrbvh_geometry_boxes(boxes, 2);
    g[1] = atrbvh_geometry_triangles(tris, 6, NULL, 2);
    for (kind = 0; kind < 2; kind++) {
        atrbvh_ray ray;
        atrbvh_hit h;
        ray.origin[0] = 0.0f;
        ray.origin[1] = -1e-30f;
        ray.origin[2] = 0.0f;
        ray.dir[0] = 0.0f;
        ray.dir[1] = 0.0f;
        ray.dir[2] = 1e16f;
        ray.tmin = 0.0f;
        ray.tmax = INFINITY;
        for (k = 0; k < 3; k++) {
            atrbvh_build_options o;
            atrbvh_bvh *b;
            size_t nodes;
            atrbvh_build_options_init(&o);
            o.method = (atrbvh_method)k;
            /* both in the root's leaf: the boxes overlap enough that the
             * SAH keeps one leaf (checked below) */
            o.max_leaf_size = 2;
            b = tu_build(&g[kind], &o);
            atrbvh_bvh_nodes(b, &nodes);
            ck_assert_uint_eq(nodes, 1);
            ck_assert(atrbvh_intersect(b, &g[kind], &ray, &h));
            ck_assert_msg(h.primitive == 1 && h.t > 0.0f,
                          "%s, %s: hit %u at t = %a, behind the origin",
                          kind ? "triangles" : "boxes", METHOD_NAMES[k],
                          h.primitive, (double)h.t);
            ck_assert(atrbvh_occluded(b, &g[kind], &ray));
            /* only the primitive behind: nothing is hit */
            ray.tmax = h.t * 0.5f;
            ck_assert_msg(!atrbvh_intersect(b, &g[kind], &ray, &h) &&
                              !atrbvh_occluded(b, &g[kind], &ray),
                          "%s, %s: hit behind the origin",
                          kind ? "triangles" : "boxes", METHOD_NAMES[k]);
            ray.tmax = INFINITY;
            atrbvh_bvh_free(b);
        }
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("extremes");
    TCase *num = tcase_create("numerics");
    TCase *deg = tcase_create("degenerate");
    TCase *pol = tcase_create("policy");
    TCase *big = tcase_create("large");
    int status;
    tcase_set_timeout(num, 600);
    tcase_add_loop_test(num, scaled, 0, 8);
    tcase_add_test(num, whole_float_range);
    tcase_add_loop_test(num, translated, 0, 6);
    tcase_add_test(num, sliver_false_hit);
    tcase_add_test(num, behind_origin_underflow);
    suite_add_tcase(s, num);
    tcase_set_timeout(deg, 600);
    tcase_add_loop_test(deg, flat, 1, 4);
    tcase_add_test(deg, same_centroid);
    tcase_add_test(deg, identical);
    tcase_add_test(deg, one_and_two);
    tcase_add_test(deg, degenerate_triangles);
    suite_add_tcase(s, deg);
    tcase_set_timeout(pol, 60);
    tcase_add_test(pol, nonfinite_boxes_and_indexed);
    tcase_add_test(pol, beyond_the_limit);
    suite_add_tcase(s, pol);
    tcase_set_timeout(big, 1200);
    tcase_add_test(big, morton_collisions);
    tcase_add_test(big, largest_scene);
    suite_add_tcase(s, big);
    status = tu_run(s);
    printf("extremes: %zu case builds checked, %zu rays (%zu also checked "
           "independently)\n",
           cases_total, rays_total, rays_independent);
    return status;
}
