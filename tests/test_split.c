/*
 * test_split.c - triangle splitting (options.split_budget, atrbvh build
 * --split).
 *
 *  - Off by default: an options struct of the size before the field
 *    builds the same tree as split_budget 0; out-of-range budgets fail.
 *  - Axis-aligned triangles: nothing split, the unsplit tree (version 1
 *    file, refittable).
 *  - A split tree over long diagonal slivers among small triangles has
 *    more references than triangles, at most the budget more; every
 *    primitive is referenced at least once, never twice in one leaf;
 *    every leaf box touches each triangle it lists (the triangle clipped
 *    to the box is not empty), and every triangle's vertices and its
 *    points on the scene's mid planes lie in the box of a leaf that
 *    lists it; stats.primitives counts primitives, not references.
 *  - The three rules (ATRBVH_SPLIT_SAH, the default, _TREE and
 *    _PRIORITY) in the tests below; split_rule outside them (3, -1) is
 *    ATRBVH_ERR_INVALID_ARGUMENT, and a caller compiled before the field
 *    gets the default rule.
 *  - The same tree for 1, 2, 3 and 4 threads; the same on OpenCL
 *    (atrbvh_validate_backends; skipped, saying so, without a device).
 *  - The SAH rule over a scene large enough for its levels to be spread
 *    over the threads: the same references (in order) and tree for 1, 2
 *    and 3 threads, with a budget spent part way through a level and one
 *    the cuts leave unspent; the references' CRC-32 that of the
 *    single-threaded pre-process before it ran on the threads.
 *  - Closest and any hit through split trees (LBVH and ATRBVH, collapsed
 *    and not) equal brute force (every triangle tested on its own, the
 *    lowest t, the lowest index on a tie) on random rays and rays aimed
 *    at points on the split planes.
 *  - skip_invalid with splitting: the NaN triangle left out and counted.
 *  - Save and load: a split tree is written as version 2 with the split
 *    flag and loads back equal; an unsplit tree is still written as
 *    version 1 and loads; a version 1 file whose leaves share a
 *    primitive is rejected, and so is a version 2 split file with a
 *    primitive twice in one leaf.
 *  - atrbvh_refit of a split tree: ATRBVH_ERR_UNSUPPORTED.
 *  - The tree-guided rule: over a few slivers among small triangles the
 *    LBVH's SAH falls (collapsed and not), no triangle gets more than 8
 *    references; a sliver present twice is not split (its twin holds
 *    every box above it) where the same sliver alone is.
 *  - The SAH rule, judging a node's straddlers together, does cut such
 *    twins, and the SAH falls.
 *  - Every allocation of a split build failing in turn: ATRBVH_ERR_NOMEM,
 *    nothing leaked.
 */
#include <check.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* n small random triangles plus `slivers` long thin diagonal ones across
 * the unit cube (packed soup, 9 floats per triangle). */
static float *sliver_scene(size_t n, size_t slivers, uint64_t seed)
{
    float *small = tu_random_triangles(n, seed, 0.05f, 0.0f);
    float *v = malloc((n + slivers) * 9 * sizeof *v);
    tu_rng r;
    size_t i;
    ck_assert_ptr_nonnull(small);
    ck_assert_ptr_nonnull(v);
    tu_rng_seed(&r, seed + 1);
    for (i = 0; i < n; i++) { /* spread the small ones over the cube */
        float dx = tu_rng_float(&r), dy = tu_rng_float(&r),
              dz = tu_rng_float(&r);
        int c;
        for (c = 0; c < 3; c++) {
            v[9 * i + 3 * c + 0] = small[9 * i + 3 * c + 0] + dx;
            v[9 * i + 3 * c + 1] = small[9 * i + 3 * c + 1] + dy;
            v[9 * i + 3 * c + 2] = small[9 * i + 3 * c + 2] + dz;
        }
    }
    for (i = n; i < n + slivers; i++) {
        float a[3], b[3];
        int k;
        for (k = 0; k < 3; k++) {
            a[k] = tu_rng_float(&r) * 0.2f;
            b[k] = 0.8f + tu_rng_float(&r) * 0.2f;
        }
        if (i % 2) { /* the other diagonal */
            float t = a[1];
            a[1] = b[1];
            b[1] = t;
        }
        for (k = 0; k < 3; k++) {
            v[9 * i + k] = a[k];
            v[9 * i + 3 + k] = b[k];
            v[9 * i + 6 + k] = b[k] + (k == 2 ? 0.01f : -0.01f);
        }
    }
    free(small);
    return v;
}

static atrbvh_build_options split_options(double budget)
{
    atrbvh_build_options o;
    atrbvh_build_options_init(&o);
    o.split_budget = budget;
    o.max_leaf_size = 8;
    return o;
}

static const float *tri(const float *v, uint32_t t, int c)
{
    return v + 9 * (size_t)t + 3 * c;
}

/* Whether triangle t meets box [lo, hi] (testutil's clipping test). */
static int touches(const float *v, uint32_t t, const float *lo,
                   const float *hi)
{
    return tu_triangle_meets_box(tri(v, t, 0), tri(v, t, 1), tri(v, t, 2), lo,
                                 hi);
}

static int inside(const atrbvh_node *n, const double p[3])
{
    int k;
    for (k = 0; k < 3; k++)
        if (p[k] < n->min[k] || p[k] > n->max[k])
            return 0;
    return 1;
}

/* The properties of a split tree over soup v of nt triangles. */
static void check_split_tree(const atrbvh_bvh *b, const float *v, size_t nt,
                             double budget)
{
    size_t nn, np, i, j, refs = 0;
    const atrbvh_node *nodes = atrbvh_bvh_nodes(b, &nn);
    const uint32_t *idx = atrbvh_bvh_primitive_indices(b, &np);
    unsigned *seen = calloc(nt, sizeof *seen);
    atrbvh_stats st;
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    char msg[256];
    ck_assert_msg(tu_check_bvh_split(b, &g, budget, msg, sizeof msg), "%s",
                  msg);
    ck_assert_ptr_nonnull(seen);
    ck_assert_int_eq(atrbvh_bvh_stats(b, &st), ATRBVH_OK);
    ck_assert_uint_eq(st.primitives, nt);
    ck_assert_uint_eq(st.invalid_skipped, 0);
    for (i = 0; i < nn; i++) {
        const atrbvh_node *n = &nodes[i];
        if (!n->count)
            continue;
        refs += n->count;
        for (j = 0; j < n->count; j++) {
            uint32_t p = idx[n->index + j];
            size_t q;
            ck_assert_uint_lt(p, nt);
            seen[p]++;
            for (q = 0; q < j; q++)
                ck_assert_msg(idx[n->index + q] != p,
                              "leaf %zu lists primitive %u twice", i, p);
            ck_assert_msg(touches(v, p, n->min, n->max),
                          "leaf %zu lists triangle %u, which does not meet "
                          "its box",
                          i, p);
        }
    }
    ck_assert_uint_eq(refs, np);
    for (i = 0; i < nt; i++)
        ck_assert_msg(seen[i] >= 1, "triangle %zu is not referenced", i);
    ck_assert_msg(np > nt, "no triangle was split (%zu references)", np);
    ck_assert_msg((double)np <= (double)nt * (1.0 + budget),
                  "%zu references over the budget", np);
    /* coverage: vertices and mid-plane points lie in a listing leaf */
    for (i = 0; i < nt; i++) {
        double pts[9][3];
        int np_ = 0, c, k, e;
        for (c = 0; c < 3; c++, np_++)
            for (k = 0; k < 3; k++)
                pts[np_][k] = tri(v, (uint32_t)i, c)[k];
        for (k = 0; k < 3; k++) /* the edges' crossings of x_k = 0.5 */
            for (e = 0; e < 3; e++) {
                const float *p = tri(v, (uint32_t)i, e),
                            *q = tri(v, (uint32_t)i, (e + 1) % 3);
                double s;
                int m;
                if ((p[k] - 0.5f) * (q[k] - 0.5f) >= 0.0f || np_ >= 9)
                    continue;
                s = (0.5 - p[k]) / ((double)q[k] - p[k]);
                for (m = 0; m < 3; m++)
                    pts[np_][m] = p[m] + s * ((double)q[m] - p[m]);
                pts[np_++][k] = 0.5;
            }
        for (c = 0; c < np_; c++) {
            int found = 0;
            for (j = 0; j < nn && !found; j++) {
                size_t q;
                if (!nodes[j].count || !inside(&nodes[j], pts[c]))
                    continue;
                for (q = 0; q < nodes[j].count; q++)
                    if (idx[nodes[j].index + q] == i)
                        found = 1;
            }
            ck_assert_msg(found, "point %d of triangle %zu is in no leaf "
                                 "listing it",
                          c, i);
        }
    }
    free(seen);
}

START_TEST(off_by_default)
{
    float *v = sliver_scene(300, 40, 5);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * 340, NULL, 340);
    atrbvh_build_options o = split_options(0.0), old = split_options(0.0);
    atrbvh_bvh *a, *b, *c;
    atrbvh_error e;
    char msg[256];
    size_t np;
    old.size = offsetof(atrbvh_build_options, capture_user) + sizeof(void *);
    old.split_budget = 1.0; /* past the caller's size: never read */
    a = tu_build(&g, &o);
    b = tu_build(&g, &old);
    ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg), "%s", msg);
    ck_assert_msg(tu_check_bvh(a, &g, msg, sizeof msg), "%s", msg);
    (void)atrbvh_bvh_primitive_indices(a, &np);
    ck_assert_uint_eq(np, 340);
    o.split_budget = -0.1;
    ck_assert_int_eq(atrbvh_build(&g, &o, &c, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(e.text, "split_budget"));
    o.split_budget = 4.5;
    ck_assert_int_eq(atrbvh_build(&g, &o, &c, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    o.split_budget = NAN;
    ck_assert_int_eq(atrbvh_build(&g, &o, &c, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    o.split_budget = 0.3;
    o.split_rule = 3;
    ck_assert_int_eq(atrbvh_build(&g, &o, &c, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(e.text, "split_rule"));
    o.split_rule = -1;
    ck_assert_int_eq(atrbvh_build(&g, &o, &c, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    /* a caller compiled before split_rule gets the default (sah) rule */
    o = split_options(0.3);
    ck_assert_int_eq(o.split_rule, ATRBVH_SPLIT_SAH); /* the default */
    old = o;
    old.size = offsetof(atrbvh_build_options, split_budget) + sizeof(double);
    old.split_rule = 7; /* past the caller's size: never read */
    atrbvh_bvh_free(a);
    atrbvh_bvh_free(b);
    a = tu_build(&g, &o);
    b = tu_build(&g, &old);
    ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_free(a);
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

/* Axis-aligned triangles (a grid of squares in the plane z = 0) have
 * boxes no larger than their area allows: nothing is split, and the tree
 * is the unsplit one - saved as version 1, refittable - by every rule.
 * Each square is there twice, the copies in the reverse order, so equal
 * Morton keys are common (their ties are broken by reference index).
 * The SAH rule once emitted uncut references in its recursion's order:
 * the fuzz seed corpus/build/split-sah-nothing-cut-reordered caught that,
 * this scene does not. */
START_TEST(nothing_to_split)
{
    const size_t side = 20, nq = 2 * side * side, nt = 2 * nq;
    float *v = malloc(nt * 9 * sizeof *v);
    atrbvh_geometry g;
    atrbvh_bvh *b;
    atrbvh_error e;
    char msg[256];
    size_t i, j, t = 0;
    int rule;
    ck_assert_ptr_nonnull(v);
    for (i = 0; i < side; i++)
        for (j = 0; j < side; j++) {
            const float x = (float)i, y = (float)j;
            const float q[2][9] = {{x, y, 0, x + 1, y, 0, x, y + 1, 0},
                                   {x + 1, y, 0, x + 1, y + 1, 0, x, y + 1,
                                    0}};
            memcpy(v + 9 * t++, q[0], sizeof q[0]);
            memcpy(v + 9 * t++, q[1], sizeof q[1]);
        }
    for (i = 0; i < nq; i++)
        memcpy(v + 9 * (nq + i), v + 9 * (nq - 1 - i), 9 * sizeof *v);
    g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    {
        atrbvh_build_options o = split_options(0.0);
        b = tu_build(&g, &o);
    }
    for (rule = ATRBVH_SPLIT_TREE; rule <= ATRBVH_SPLIT_SAH; rule++) {
        atrbvh_build_options o = split_options(0.5);
        atrbvh_bvh *a;
        void *data;
        size_t size;
        o.split_rule = rule;
        a = tu_build(&g, &o);
        ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg), "rule %d: %s",
                      rule, msg);
        ck_assert_msg(tu_check_bvh(a, &g, msg, sizeof msg), "%s", msg);
        ck_assert_int_eq(atrbvh_save_memory(a, &data, &size, &e), ATRBVH_OK);
        ck_assert_uint_eq(((unsigned char *)data)[8], 1);
        atrbvh_free(data);
        ck_assert_int_eq(atrbvh_refit(a, &g, NULL, &e), ATRBVH_OK);
        atrbvh_bvh_free(a);
    }
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

START_TEST(references_cover_triangles)
{
    static const double budgets[] = {0.1, 0.3, 1.0};
    float *v = sliver_scene(1500, 150, 11);
    const size_t nt = 1650;
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    size_t k;
    for (k = 0; k < 9; k++) {
        atrbvh_build_options o = split_options(budgets[k % 3]);
        atrbvh_bvh *b;
        o.method = k % 3 == 0 ? ATRBVH_METHOD_LBVH : ATRBVH_METHOD_ATRBVH;
        o.split_rule = (int)(k / 3); /* tree, priority, sah */
        b = tu_build(&g, &o);
        check_split_tree(b, v, nt, budgets[k % 3]);
        atrbvh_bvh_free(b);
        o.collapse = 0;
        o.max_leaf_size = 0;
        b = tu_build(&g, &o);
        check_split_tree(b, v, nt, budgets[k % 3]);
        atrbvh_bvh_free(b);
    }
    free(v);
}
END_TEST

START_TEST(same_for_threads)
{
    float *v = sliver_scene(4000, 30, 21);
    const size_t nt = 4030;
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    int rule;
    for (rule = ATRBVH_SPLIT_TREE; rule <= ATRBVH_SPLIT_SAH; rule++) {
        atrbvh_build_options o = split_options(0.3);
        atrbvh_bvh *ref;
        char msg[256];
        size_t np;
        int t;
        o.threads = 1;
        o.split_rule = rule;
        ref = tu_build(&g, &o);
        (void)atrbvh_bvh_primitive_indices(ref, &np);
        ck_assert_msg(np > nt, "rule %d: nothing split", rule);
        for (t = 2; t <= 4; t++) {
            atrbvh_bvh *b;
            o.threads = t;
            b = tu_build(&g, &o);
            ck_assert_msg(tu_same_bvh(ref, b, msg, sizeof msg),
                          "rule %d, %d threads: %s", rule, t, msg);
            atrbvh_bvh_free(b);
        }
        atrbvh_bvh_free(ref);
    }
    free(v);
}
END_TEST

/* The references (bounds stage: one box per reference, in order) of a
 * split build, copied from the stage capture. */
typedef struct refs_seen {
    size_t n;
    float *boxes;
} refs_seen;

static int keep_refs(const atrbvh_stage_output *out, void *user)
{
    refs_seen *r = user;
    size_t i;
    if (out->stage != ATRBVH_STAGE_BOUNDS)
        return 0;
    for (i = 0; i < out->array_count; i++) {
        const atrbvh_array *a = &out->arrays[i];
        if (strcmp(a->name, "prim_boxes") != 0)
            continue;
        ck_assert_int_eq(a->dtype, ATRBVH_DTYPE_F32);
        ck_assert_uint_eq(a->cols, 6);
        r->n = a->rows;
        r->boxes = malloc(a->rows * 6 * sizeof *r->boxes);
        ck_assert_ptr_nonnull(r->boxes);
        memcpy(r->boxes, a->data, a->rows * 6 * sizeof *r->boxes);
    }
    return 0;
}

/* The CRC-32 of floats f[0..n) as little-endian bytes. */
static uint32_t floats_crc(const float *f, size_t n)
{
    unsigned char *b = malloc(4 * n + 1);
    uint32_t crc;
    size_t i;
    ck_assert_ptr_nonnull(b);
    for (i = 0; i < n; i++) {
        uint32_t u;
        int k;
        memcpy(&u, &f[i], 4);
        for (k = 0; k < 4; k++)
            b[4 * i + (size_t)k] = (unsigned char)(u >> (8 * k));
    }
    crc = tu_crc32(b, 4 * n);
    free(b);
    return crc;
}

/* The SAH rule's pre-process runs a level's nodes on the threads and
 * hands out the budget serially in cell order: the references (boxes in
 * order) and the trees of 1, 2 and 3 threads are the same, over a scene
 * whose levels are large enough to be spread over the threads, with a
 * budget that runs out part way through a level (0.02) and one that the
 * cuts do not spend (0.5). */
START_TEST(sah_same_for_threads)
{
    const size_t n = 24000, s = 600, nt = n + s;
    float *v = sliver_scene(n, s, 57);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    static const double budgets[] = {0.02, 0.5};
    /* the references' CRC as the single-threaded pre-process (before it
     * ran on the threads, 510b12f) gave them: the order is today's */
    static const uint32_t crcs[] = {0x202f1a3bu, 0xb34e55dbu};
    size_t k;
    for (k = 0; k < 2; k++) {
        atrbvh_build_options o = split_options(budgets[k]);
        refs_seen one = {0, NULL};
        atrbvh_bvh *ref;
        size_t np;
        int t;
        o.method = ATRBVH_METHOD_LBVH;
        o.split_rule = ATRBVH_SPLIT_SAH;
        o.capture = keep_refs;
        o.threads = 1;
        o.capture_user = &one;
        ref = tu_build(&g, &o);
        (void)atrbvh_bvh_primitive_indices(ref, &np);
        ck_assert_msg(one.n > nt, "budget %g: nothing split", budgets[k]);
        ck_assert_msg(floats_crc(one.boxes, 6 * one.n) == crcs[k],
                      "budget %g: %zu references, CRC 0x%08lx, not 0x%08lx",
                      budgets[k], one.n,
                      (unsigned long)floats_crc(one.boxes, 6 * one.n),
                      (unsigned long)crcs[k]);
        for (t = 2; t <= 3; t++) {
            refs_seen many = {0, NULL};
            atrbvh_bvh *b;
            char msg[256];
            o.threads = t;
            o.capture_user = &many;
            b = tu_build(&g, &o);
            ck_assert_msg(many.n == one.n,
                          "budget %g, %d threads: %zu references, %zu on "
                          "one thread",
                          budgets[k], t, many.n, one.n);
            ck_assert_msg(memcmp(many.boxes, one.boxes,
                                 one.n * 6 * sizeof *one.boxes) == 0,
                          "budget %g, %d threads: the references differ",
                          budgets[k], t);
            ck_assert_msg(tu_same_bvh(ref, b, msg, sizeof msg),
                          "budget %g, %d threads: %s", budgets[k], t, msg);
            atrbvh_bvh_free(b);
            free(many.boxes);
        }
        atrbvh_bvh_free(ref);
        free(one.boxes);
    }
    free(v);
}
END_TEST

START_TEST(same_on_opencl)
{
    float *v = sliver_scene(3000, 20, 31);
    const size_t nt = 3020;
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    static const double budgets[] = {0.1, 0.5};
    size_t k;
    for (k = 0; k < 6; k++) {
        atrbvh_build_options o = split_options(budgets[k % 2]);
        atrbvh_error e;
        atrbvh_bvh *b;
        size_t np;
        int same = 0;
        atrbvh_status st;
        o.method = k % 2 ? ATRBVH_METHOD_ATRBVH : ATRBVH_METHOD_TRBVH;
        o.split_rule = (int)(k / 2); /* tree, priority, sah */
        b = tu_build(&g, &o);
        (void)atrbvh_bvh_primitive_indices(b, &np);
        ck_assert_msg(np > nt, "case %zu: nothing split", k);
        atrbvh_bvh_free(b);
        st = atrbvh_validate_backends(&g, &o, &same, &e);
        if (st != ATRBVH_OK && tu_opencl_may_skip(st)) {
            fprintf(stderr, "SKIP same_on_opencl: no OpenCL device (%s)\n",
                    e.text);
            break;
        }
        ck_assert_msg(st == ATRBVH_OK, "%s", e.text);
        ck_assert_msg(same, "case %zu, budget %g: %s", k, budgets[k % 2],
                      e.text);
    }
    free(v);
}
END_TEST

/* Brute force: every triangle on its own (a one-triangle BVH each: the
 * library's ray/triangle arithmetic without a traversal); the lowest t,
 * the lowest index on a tie. */
static int brute(atrbvh_bvh **one, const atrbvh_geometry *single, size_t nt,
                 const atrbvh_ray *r, atrbvh_hit *best)
{
    size_t i;
    memset(best, 0, sizeof *best);
    best->primitive = ATRBVH_NO_HIT;
    best->t = INFINITY;
    for (i = 0; i < nt; i++) {
        atrbvh_hit h;
        if (atrbvh_intersect(one[i], &single[i], r, &h) && h.t < best->t) {
            *best = h;
            best->primitive = (uint32_t)i;
        }
    }
    return best->primitive != ATRBVH_NO_HIT;
}

START_TEST(rays_equal_brute_force)
{
    const size_t nt = 400;
    float *v = sliver_scene(370, 30, 41);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    atrbvh_geometry *single = malloc(nt * sizeof *single);
    atrbvh_bvh **one = malloc(nt * sizeof *one);
    const size_t nr = 3000;
    atrbvh_ray *rays = malloc(nr * sizeof *rays);
    tu_rng r;
    size_t i, k;
    ck_assert_ptr_nonnull(single);
    ck_assert_ptr_nonnull(one);
    ck_assert_ptr_nonnull(rays);
    for (i = 0; i < nt; i++) {
        single[i] = atrbvh_geometry_triangles(v + 9 * i, 3, NULL, 1);
        one[i] = tu_build(&single[i], NULL);
    }
    tu_rng_seed(&r, 99);
    for (i = 0; i < nr; i++) {
        atrbvh_ray *ry = &rays[i];
        float target[3];
        int c;
        if (i % 2) { /* at a point of a sliver on a mid plane */
            uint32_t t = 370 + (uint32_t)(tu_rng_next(&r) % 30);
            const float *p = tri(v, t, 0), *q = tri(v, t, 1);
            int axis = (int)(tu_rng_next(&r) % 3);
            float s = (0.5f - p[axis]) / (q[axis] - p[axis]);
            for (c = 0; c < 3; c++)
                target[c] = p[c] + s * (q[c] - p[c]);
            target[axis] = 0.5f;
        } else {
            for (c = 0; c < 3; c++)
                target[c] = tu_rng_float(&r);
        }
        for (c = 0; c < 3; c++) {
            ry->origin[c] = tu_rng_float(&r) * 1.4f - 0.2f;
            ry->dir[c] = target[c] - ry->origin[c];
        }
        ry->tmin = 0.0f;
        ry->tmax = i % 3 ? INFINITY : 0.9f;
    }
    for (k = 0; k < 9; k++) {
        atrbvh_build_options o = split_options(k % 4 < 2 ? 0.3 : 2.0);
        atrbvh_bvh *b;
        size_t np;
        o.method = k % 2 ? ATRBVH_METHOD_ATRBVH : ATRBVH_METHOD_LBVH;
        o.split_rule = k < 4   ? ATRBVH_SPLIT_TREE
                       : k < 6 ? ATRBVH_SPLIT_PRIORITY
                               : ATRBVH_SPLIT_SAH;
        if (k == 3 || k == 8) {
            o.collapse = 0;
            o.max_leaf_size = 0;
        }
        b = tu_build(&g, &o);
        (void)atrbvh_bvh_primitive_indices(b, &np);
        ck_assert_msg(np > nt, "config %zu: nothing split", k);
        for (i = 0; i < nr; i++) {
            atrbvh_hit h, bh;
            int hit = atrbvh_intersect(b, &g, &rays[i], &h);
            int bhit = brute(one, single, nt, &rays[i], &bh);
            int occ = atrbvh_occluded(b, &g, &rays[i]);
            ck_assert_msg(hit == bhit, "config %zu ray %zu: hit %d, brute "
                                       "force %d",
                          k, i, hit, bhit);
            ck_assert_msg(occ == bhit, "config %zu ray %zu: occluded %d, "
                                       "brute force %d",
                          k, i, occ, bhit);
            if (!hit)
                continue;
            ck_assert_msg(h.primitive == bh.primitive && h.t == bh.t &&
                              h.u == bh.u && h.v == bh.v,
                          "config %zu ray %zu: %u at %.9g, brute force %u "
                          "at %.9g",
                          k, i, h.primitive, (double)h.t, bh.primitive,
                          (double)bh.t);
        }
        atrbvh_bvh_free(b);
    }
    for (i = 0; i < nt; i++)
        atrbvh_bvh_free(one[i]);
    free(one);
    free(single);
    free(rays);
    free(v);
}
END_TEST

START_TEST(skip_invalid_with_split)
{
    const size_t nt = 500;
    float *v = sliver_scene(490, 10, 51);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    atrbvh_build_options o = split_options(0.5);
    atrbvh_bvh *b;
    atrbvh_error e;
    atrbvh_stats st;
    size_t nn, np, i, j;
    const atrbvh_node *nodes;
    const uint32_t *idx;
    int rule;
    v[9 * 7 + 4] = NAN;
    for (rule = ATRBVH_SPLIT_TREE; rule <= ATRBVH_SPLIT_SAH; rule++) {
        o.split_rule = rule;
        o.skip_invalid = 0;
        ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e),
                         ATRBVH_ERR_NONFINITE);
        ck_assert_uint_eq(e.index, 7);
        o.skip_invalid = 1;
        b = tu_build(&g, &o);
        ck_assert_int_eq(atrbvh_bvh_stats(b, &st), ATRBVH_OK);
        ck_assert_uint_eq(st.invalid_skipped, 1);
        ck_assert_uint_eq(st.primitives, nt - 1);
        nodes = atrbvh_bvh_nodes(b, &nn);
        idx = atrbvh_bvh_primitive_indices(b, &np);
        ck_assert_msg(np > nt, "rule %d: nothing split", rule);
        for (i = 0; i < nn; i++)
            for (j = 0; j < nodes[i].count; j++)
                ck_assert_uint_ne(idx[nodes[i].index + j], 7);
        atrbvh_bvh_free(b);
    }
    free(v);
}
END_TEST

START_TEST(save_load_versions)
{
    const size_t nt = 800;
    float *v = sliver_scene(700, 100, 61);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    atrbvh_build_options o = split_options(0.5);
    atrbvh_bvh *b, *plain, *l = NULL;
    atrbvh_stats sb, sl;
    atrbvh_error e;
    void *data;
    size_t size, nn, np, i, leaf_a = 0, leaf_b = 0;
    unsigned char *c;
    const atrbvh_node *nodes;
    b = tu_build(&g, &o);
    o.split_budget = 0.0;
    plain = tu_build(&g, &o);

    /* split: version 2, the split flag; loads back equal */
    ck_assert_int_eq(atrbvh_save_memory(b, &data, &size, &e), ATRBVH_OK);
    c = data;
    ck_assert_uint_eq(tu_rd32(c + 8), 2);
    ck_assert_uint_eq(tu_rd32(c + 16), 1);
    ck_assert_int_eq(atrbvh_load_memory(data, size, &l, &e), ATRBVH_OK);
    ck_assert_msg(atrbvh_compare(b, l, &e) == 0, "%s", e.text);
    ck_assert_int_eq(atrbvh_bvh_stats(b, &sb), ATRBVH_OK);
    ck_assert_int_eq(atrbvh_bvh_stats(l, &sl), ATRBVH_OK);
    ck_assert_uint_eq(sl.primitives, nt);
    ck_assert_uint_eq(sl.invalid_skipped, 0);
    ck_assert(sl.sah == sb.sah);
    check_split_tree(l, v, nt, 0.5);
    atrbvh_bvh_free(l);
    /* the same bytes as version 1 (flags 0): a shared primitive fails */
    tu_wr32(c + 8, 1);
    tu_wr32(c + 16, 0);
    tu_fix_crc(c, size);
    ck_assert_int_eq(atrbvh_load_memory(data, size, &l, &e),
                     ATRBVH_ERR_FORMAT);
    ck_assert_msg(strstr(e.text, "referenced twice") ||
                      strstr(e.text, "input primitive count"),
                  "%s", e.text);
    /* version 2 with the flag, a primitive twice in one leaf: fails */
    tu_wr32(c + 8, 2);
    tu_wr32(c + 16, 1);
    nodes = atrbvh_bvh_nodes(b, &nn);
    (void)atrbvh_bvh_primitive_indices(b, &np);
    for (i = 0; i < nn; i++)
        if (nodes[i].count >= 2) {
            leaf_a = nodes[i].index;
            leaf_b = leaf_a + 1;
            break;
        }
    ck_assert_uint_lt(i, nn);
    memcpy(c + 96 + 32 * nn + 4 * leaf_b, c + 96 + 32 * nn + 4 * leaf_a, 4);
    tu_fix_crc(c, size);
    ck_assert_int_eq(atrbvh_load_memory(data, size, &l, &e),
                     ATRBVH_ERR_FORMAT);
    ck_assert_ptr_nonnull(strstr(e.text, "twice"));
    /* an unknown flag of version 2 */
    tu_wr32(c + 16, 3);
    tu_fix_crc(c, size);
    ck_assert_int_eq(atrbvh_load_memory(data, size, &l, &e),
                     ATRBVH_ERR_FORMAT);
    ck_assert_ptr_nonnull(strstr(e.text, "flags"));
    atrbvh_free(data);

    /* unsplit: still version 1, flags 0, and loads */
    ck_assert_int_eq(atrbvh_save_memory(plain, &data, &size, &e), ATRBVH_OK);
    c = data;
    ck_assert_uint_eq(tu_rd32(c + 8), 1);
    ck_assert_uint_eq(tu_rd32(c + 16), 0);
    ck_assert_int_eq(atrbvh_load_memory(data, size, &l, &e), ATRBVH_OK);
    ck_assert_msg(atrbvh_compare(plain, l, &e) == 0, "%s", e.text);
    atrbvh_bvh_free(l);
    atrbvh_free(data);
    atrbvh_bvh_free(b);
    atrbvh_bvh_free(plain);
    free(v);
}
END_TEST

START_TEST(refit_refuses_split_trees)
{
    const size_t nt = 300;
    float *v = sliver_scene(250, 50, 71);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    atrbvh_build_options o = split_options(0.5);
    atrbvh_bvh *b = tu_build(&g, &o);
    atrbvh_error e;
    ck_assert_int_eq(atrbvh_refit(b, &g, NULL, &e), ATRBVH_ERR_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(e.text, "split"));
    ck_assert_int_eq(atrbvh_reoptimise(b, &g, NULL, &e),
                     ATRBVH_ERR_UNSUPPORTED);
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

/* Each allocation of a split build (threads 1 and 3, skip_invalid on and
 * off) failing in turn: ATRBVH_ERR_NOMEM with nothing leaked, until the
 * build succeeds. */
/* References per triangle of a tree. */
static unsigned *ref_counts(const atrbvh_bvh *b, size_t nt)
{
    size_t nn, np, i, j;
    const atrbvh_node *nodes = atrbvh_bvh_nodes(b, &nn);
    const uint32_t *idx = atrbvh_bvh_primitive_indices(b, &np);
    unsigned *seen = calloc(nt, sizeof *seen);
    ck_assert_ptr_nonnull(seen);
    for (i = 0; i < nn; i++)
        for (j = 0; j < nodes[i].count; j++)
            seen[idx[nodes[i].index + j]]++;
    return seen;
}

/* The tree rule (ATRBVH_SPLIT_TREE) splits where the first tree says it
 * pays: over a few slivers among small triangles, the LBVH's SAH (one
 * primitive per leaf: the first tree's own form, and collapsed) falls by
 * a tenth, and no triangle gets more than 7 splits (8 references). */
START_TEST(splitting_pays)
{
    const size_t n = 3000, s = 20, nt = n + s;
    float *v = sliver_scene(n, s, 31);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    int collapse;
    for (collapse = 0; collapse < 2; collapse++) {
        atrbvh_build_options o = split_options(0.3);
        atrbvh_bvh *a, *b;
        atrbvh_stats sa, sb;
        unsigned *seen;
        size_t i;
        o.split_rule = ATRBVH_SPLIT_TREE;
        o.method = ATRBVH_METHOD_LBVH;
        o.collapse = collapse;
        o.max_leaf_size = collapse ? 8 : 0;
        a = tu_build(&g, &o);
        o.split_budget = 0.0;
        b = tu_build(&g, &o);
        ck_assert_int_eq(atrbvh_bvh_stats(a, &sa), ATRBVH_OK);
        ck_assert_int_eq(atrbvh_bvh_stats(b, &sb), ATRBVH_OK);
        ck_assert_msg(sa.sah < 0.95 * sb.sah,
                      "collapse %d: SAH %g split, %g unsplit", collapse,
                      sa.sah, sb.sah);
        seen = ref_counts(a, nt);
        for (i = 0; i < nt; i++)
            ck_assert_msg(seen[i] <= 8, "triangle %zu: %u references", i,
                          seen[i]);
        atrbvh_bvh_free(a);
        atrbvh_bvh_free(b);
        free(seen);
    }
    free(v);
}
END_TEST

/* By the tree rule a triangle is split for what it alone adds to the
 * nodes above it: each of two identical slivers leaves the other to hold
 * every box above it, so no sliver of a pair is split, while in the same
 * scene with one of each, slivers are. */
START_TEST(twins_not_split)
{
    const size_t n = 3000, s = 20, nt = n + 2 * s;
    float *one = sliver_scene(n, s, 31);
    float *v = malloc(nt * 9 * sizeof *v);
    atrbvh_geometry g;
    atrbvh_build_options o = split_options(0.3);
    atrbvh_bvh *a;
    unsigned *seen;
    size_t i, split = 0;
    ck_assert_ptr_nonnull(v);
    memcpy(v, one, (n + s) * 9 * sizeof *v);
    memcpy(v + 9 * (n + s), one + 9 * n, s * 9 * sizeof *v);
    o.split_rule = ATRBVH_SPLIT_TREE;
    o.method = ATRBVH_METHOD_LBVH;
    g = atrbvh_geometry_triangles(one, 3 * (n + s), NULL, n + s);
    a = tu_build(&g, &o);
    seen = ref_counts(a, n + s);
    for (i = n; i < n + s; i++)
        split += seen[i] > 1;
    ck_assert_msg(split > 0, "the slivers alone: none split");
    free(seen);
    atrbvh_bvh_free(a);
    g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    a = tu_build(&g, &o);
    seen = ref_counts(a, nt);
    for (i = n; i < nt; i++)
        ck_assert_msg(seen[i] == 1, "sliver %zu of a pair: %u references",
                      i, seen[i]);
    free(seen);
    atrbvh_bvh_free(a);
    free(one);
    free(v);
}
END_TEST

/* The SAH rule decides per node, all of a node's straddlers together.
 * Floors across the whole scene among small triangles, each a square of
 * two axis-aligned triangles sharing one box: the tree rule cuts neither
 * half (each holds the other's boxes up: twins_not_split), the priority
 * rule neither (an axis-aligned triangle's box is as small as its area
 * allows); the SAH rule cuts every one, and the LBVH's SAH falls,
 * collapsed and not. */
START_TEST(sah_rule_cuts_twins)
{
    const size_t n = 3000, floors = 8, nt = n + 2 * floors;
    float *v = sliver_scene(n, 0, 33);
    atrbvh_geometry g;
    size_t i;
    int collapse;
    v = realloc(v, nt * 9 * sizeof *v);
    ck_assert_ptr_nonnull(v);
    for (i = 0; i < floors; i++) {
        const float z = 0.06f + 0.12f * (float)i;
        const float q[2][9] = {{0, 0, z, 1, 0, z, 0, 1, z},
                               {1, 0, z, 1, 1, z, 0, 1, z}};
        memcpy(v + 9 * (n + 2 * i), q, sizeof q);
    }
    g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    for (collapse = 0; collapse < 2; collapse++) {
        atrbvh_build_options o = split_options(0.3);
        atrbvh_bvh *a, *b;
        atrbvh_stats sa, sb;
        unsigned *seen;
        o.method = ATRBVH_METHOD_LBVH;
        o.split_rule = ATRBVH_SPLIT_SAH;
        o.collapse = collapse;
        o.max_leaf_size = collapse ? 8 : 0;
        a = tu_build(&g, &o);
        o.split_budget = 0.0;
        b = tu_build(&g, &o);
        check_split_tree(a, v, nt, 0.3);
        seen = ref_counts(a, nt);
        for (i = n; i < nt; i++)
            ck_assert_msg(seen[i] > 1, "floor triangle %zu: %u reference",
                          i, seen[i]);
        ck_assert_int_eq(atrbvh_bvh_stats(a, &sa), ATRBVH_OK);
        ck_assert_int_eq(atrbvh_bvh_stats(b, &sb), ATRBVH_OK);
        ck_assert_msg(sa.sah < 0.95 * sb.sah,
                      "collapse %d: SAH %g split, %g unsplit", collapse,
                      sa.sah, sb.sah);
        free(seen);
        atrbvh_bvh_free(a);
        atrbvh_bvh_free(b);
    }
    free(v);
}
END_TEST

START_TEST(allocation_failures)
{
    const size_t nt = 200;
    float *v = sliver_scene(170, 30, 81);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * nt, NULL, nt);
    int variant;
    v[9 * 3] = NAN;
    for (variant = 0; variant < 4; variant++) {
        atrbvh_build_options o = split_options(0.5);
        long k;
        o.threads = variant % 2 ? 3 : 1;
        o.split_rule = variant < 2 ? ATRBVH_SPLIT_TREE : ATRBVH_SPLIT_SAH;
        o.skip_invalid = 1;
        atrbvh_set_allocator(tu_count_malloc, tu_count_free);
        for (k = 0;; k++) {
            atrbvh_bvh *b = NULL;
            atrbvh_error e;
            atrbvh_status st;
            tu_count_reset(k);
            st = atrbvh_build(&g, &o, &b, &e);
            tu_alloc.countdown = -1;
            if (st == ATRBVH_OK) {
                size_t np;
                (void)atrbvh_bvh_primitive_indices(b, &np);
                ck_assert_uint_gt(np, nt);
                atrbvh_bvh_free(b);
                ck_assert_int_eq(tu_alloc.outstanding, 0);
                break;
            }
            ck_assert_msg(st == ATRBVH_ERR_NOMEM, "allocation %ld: %s (%s)",
                          k, atrbvh_strerror(st), e.text);
            ck_assert_ptr_null(b);
            ck_assert_msg(tu_alloc.outstanding == 0,
                          "allocation %ld failed: %ld leaked", k,
                          tu_alloc.outstanding);
        }
        atrbvh_set_allocator(NULL, NULL);
        /* the split's own allocations among them */
        ck_assert_int_gt(k, variant < 2 ? 8 : 6);
    }
    free(v);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("split");
    TCase *t = tcase_create("split");
    tcase_set_timeout(t, 600);
    tcase_add_test(t, off_by_default);
    tcase_add_test(t, nothing_to_split);
    tcase_add_test(t, references_cover_triangles);
    tcase_add_test(t, same_for_threads);
    tcase_add_test(t, sah_same_for_threads);
    tcase_add_test(t, same_on_opencl);
    tcase_add_test(t, rays_equal_brute_force);
    tcase_add_test(t, skip_invalid_with_split);
    tcase_add_test(t, save_load_versions);
    tcase_add_test(t, refit_refuses_split_trees);
    tcase_add_test(t, splitting_pays);
    tcase_add_test(t, twins_not_split);
    tcase_add_test(t, sah_rule_cuts_twins);
    tcase_add_test(t, allocation_failures);
    suite_add_tcase(s, t);
    return s;
}

int main(void)
{
    return tu_run(suite());
}
