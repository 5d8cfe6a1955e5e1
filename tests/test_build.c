/*
 * test_build.c - every build satisfies the structural invariants, and the
 * output is the same bits for 1, 2, 3 and 4 threads: on generated scenes,
 * on the built-in scenes and on the real scenes of $ATRBVH_SCENES (skipped
 * cleanly when that folder is absent).
 */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

static const atrbvh_method methods[] = {ATRBVH_METHOD_LBVH, ATRBVH_METHOD_TRBVH,
                                        ATRBVH_METHOD_ATRBVH};

/* Builds g with each thread count, checks each result and their equality. */
static void check_threads(const atrbvh_geometry *g, atrbvh_method m,
                          int collapse, unsigned max_leaf, const char *what)
{
    atrbvh_build_options o;
    atrbvh_bvh *first = NULL;
    char msg[256];
    int threads;
    atrbvh_build_options_init(&o);
    o.method = m;
    o.collapse = collapse;
    o.max_leaf_size = max_leaf;
    for (threads = 1; threads <= 4; threads++) {
        atrbvh_bvh *b;
        o.threads = threads;
        b = tu_build(g, &o);
        ck_assert_msg(tu_check_bvh(b, g, msg, sizeof msg),
                      "%s method %d collapse %d threads %d: %s", what, (int)m,
                      collapse, threads, msg);
        if (!first) {
            first = b;
        } else {
            ck_assert_msg(tu_same_bvh(first, b, msg, sizeof msg),
                          "%s method %d collapse %d: 1 vs %d threads: %s",
                          what, (int)m, collapse, threads, msg);
            atrbvh_bvh_free(b);
        }
    }
    atrbvh_bvh_free(first);
}

START_TEST(random_soups)
{
    static const size_t sizes[] = {1, 2, 3, 5, 17, 1000, 30000};
    size_t s;
    for (s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        float *v = tu_random_triangles(sizes[s], 7 + s, 10.0f, -3.0f);
        atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * sizes[s], NULL,
                                                      sizes[s]);
        size_t m;
        char what[64];
        snprintf(what, sizeof what, "random %zu", sizes[s]);
        for (m = 0; m < sizeof methods / sizeof *methods; m++) {
            check_threads(&g, methods[m], 1, 0, what);
            check_threads(&g, methods[m], 0, 0, what);
        }
        check_threads(&g, ATRBVH_METHOD_LBVH, 1, 4, what);
        free(v);
    }
}
END_TEST

/* ATRBVH treelets above 32 leaves (the scratch path of shared/treelet.h)
 * and the adaptive size: valid trees, the same bits for 1..4 threads
 * (30000 triangles: parallel tasks from 2048 primitives), the stats
 * naming the size asked for.  Before the scratch path, sizes above 32
 * and ATRBVH_TREELET_AUTO were rejected. */
START_TEST(large_and_auto_treelets)
{
    static const unsigned sizes[] = {48, 128, ATRBVH_TREELET_AUTO};
    float *v = tu_random_triangles(30000, 91, 10.0f, -3.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 90000, NULL, 30000);
    size_t k;
    int collapse;
    for (k = 0; k < sizeof sizes / sizeof *sizes; k++) {
        for (collapse = 0; collapse < 2; collapse++) {
            atrbvh_build_options o;
            atrbvh_bvh *first = NULL;
            char msg[256];
            int threads;
            atrbvh_build_options_init(&o);
            o.method = ATRBVH_METHOD_ATRBVH;
            o.treelet_size = sizes[k];
            o.rounds = 2;
            o.collapse = collapse;
            for (threads = 1; threads <= 4; threads++) {
                atrbvh_bvh *b;
                atrbvh_stats st;
                o.threads = threads;
                b = tu_build(&g, &o);
                ck_assert_msg(tu_check_bvh(b, &g, msg, sizeof msg),
                              "treelet %u collapse %d threads %d: %s",
                              sizes[k], collapse, threads, msg);
                ck_assert(atrbvh_bvh_stats(b, &st) == ATRBVH_OK);
                ck_assert_uint_eq(st.treelet_size, sizes[k]);
                if (!first) {
                    first = b;
                } else {
                    ck_assert_msg(tu_same_bvh(first, b, msg, sizeof msg),
                                  "treelet %u collapse %d: 1 vs %d "
                                  "threads: %s",
                                  sizes[k], collapse, threads, msg);
                    atrbvh_bvh_free(b);
                }
            }
            atrbvh_bvh_free(first);
        }
    }
    free(v);
}
END_TEST

START_TEST(builtin_scenes)
{
    static const char *const names[] = {"sphere", "terrain", "city"};
    size_t i, m;
    for (i = 0; i < 3; i++) {
        scene s;
        char err[256];
        atrbvh_geometry g;
        ck_assert_msg(scene_builtin(names[i], 20000, &s, err, sizeof err) == 0,
                      "%s", err);
        g = scene_geometry(&s);
        for (m = 0; m < sizeof methods / sizeof *methods; m++)
            check_threads(&g, methods[m], 1, 0, names[i]);
        check_threads(&g, ATRBVH_METHOD_LBVH, 0, 0, names[i]);
        scene_free(&s);
    }
}
END_TEST

/* Boxes as primitives, including degenerate (point and flat) boxes. */
START_TEST(box_geometry)
{
    enum { N = 5000 };
    float *b = malloc(sizeof *b * 6 * N);
    tu_rng r;
    size_t i;
    atrbvh_geometry g;
    tu_rng_seed(&r, 99);
    for (i = 0; i < N; i++) {
        int k;
        for (k = 0; k < 3; k++) {
            float lo = tu_rng_float(&r) * 100.0f;
            float ext = (i % 7 == 0) ? 0.0f : tu_rng_float(&r) * (i % 3 ? 1 : 20);
            b[6 * i + k] = lo;
            b[6 * i + 3 + k] = lo + ext;
        }
    }
    g = atrbvh_geometry_boxes(b, N);
    check_threads(&g, ATRBVH_METHOD_LBVH, 1, 0, "boxes");
    check_threads(&g, ATRBVH_METHOD_ATRBVH, 1, 8, "boxes");
    free(b);
}
END_TEST

/* Strided, indexed input: every fourth float is padding, indices carry a
 * fourth word; the result must equal the packed equivalent's. */
START_TEST(strides)
{
    enum { T = 3000 };
    float *packed = tu_random_triangles(T, 5, 1.0f, 0.0f);
    float *padded = malloc(sizeof *padded * 4 * 3 * T);
    uint32_t *idx = malloc(sizeof *idx * 4 * T);
    atrbvh_geometry a, b;
    atrbvh_bvh *x, *y;
    char msg[256];
    size_t i;
    for (i = 0; i < 3 * T; i++) {
        memcpy(&padded[4 * i], &packed[3 * i], 3 * sizeof(float));
        padded[4 * i + 3] = -1e30f;
    }
    for (i = 0; i < T; i++) {
        idx[4 * i] = (uint32_t)(3 * i);
        idx[4 * i + 1] = (uint32_t)(3 * i + 1);
        idx[4 * i + 2] = (uint32_t)(3 * i + 2);
        idx[4 * i + 3] = 0xdeadbeefu;
    }
    a = atrbvh_geometry_triangles(packed, 3 * T, NULL, T);
    b = atrbvh_geometry_triangles(padded, 3 * T, idx, T);
    b.vertex_stride = 16;
    b.index_stride = 16;
    x = tu_build(&a, NULL);
    y = tu_build(&b, NULL);
    ck_assert_msg(tu_check_bvh(y, &b, msg, sizeof msg), "%s", msg);
    ck_assert_msg(tu_same_bvh(x, y, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_free(x);
    atrbvh_bvh_free(y);
    free(packed);
    free(padded);
    free(idx);
}
END_TEST

START_TEST(real_scenes)
{
    char *paths[16];
    size_t n = tu_scene_paths(paths, 16), i;
    if (n == 0) {
        fprintf(stderr, "test_build: no scenes in $ATRBVH_SCENES; skipped\n");
        return;
    }
    for (i = 0; i < n; i++) {
        scene s;
        char err[512];
        atrbvh_geometry g;
        ck_assert_msg(scene_load(paths[i], &s, err, sizeof err) == 0, "%s", err);
        g = scene_geometry(&s);
        /* The default (ATRBVH) on every scene; LBVH without collapse too. */
        check_threads(&g, ATRBVH_METHOD_ATRBVH, 1, 0, paths[i]);
        check_threads(&g, ATRBVH_METHOD_LBVH, 0, 0, paths[i]);
        scene_free(&s);
    }
    tu_free_paths(paths, n);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("build");
    TCase *tc = tcase_create("synthetic");
    TCase *real = tcase_create("real");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, random_soups);
    tcase_add_test(tc, builtin_scenes);
    tcase_add_test(tc, large_and_auto_treelets);
    tcase_add_test(tc, box_geometry);
    tcase_add_test(tc, strides);
    suite_add_tcase(s, tc);
    tcase_set_timeout(real, 1800);
    tcase_add_test(real, real_scenes);
    suite_add_tcase(s, real);
    return tu_run(s);
}
