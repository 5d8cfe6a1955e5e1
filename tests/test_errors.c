/*
 * test_errors.c - every error of the build API is reached and reported with
 * its code and a message naming what and where; allocation failure at every
 * allocation in turn returns ATRBVH_ERR_NOMEM and leaks nothing.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "testutil.h"

static atrbvh_status build_err(const atrbvh_geometry *g,
                               const atrbvh_build_options *o,
                               atrbvh_error *e)
{
    atrbvh_bvh *b = (atrbvh_bvh *)&b; /* must be reset to NULL */
    atrbvh_status s = atrbvh_build(g, o, &b, e);
    if (s == ATRBVH_OK)
        atrbvh_bvh_free(b);
    else
        ck_assert_ptr_null(b);
    return s;
}

#define EXPECT(g, o, code, needle)                                             \
    do {                                                                       \
        atrbvh_error e_;                                                       \
        atrbvh_status s_ = build_err((g), (o), &e_);                           \
        ck_assert_msg(s_ == (code), "expected %s, got %s (%s)",                \
                      atrbvh_strerror(code), atrbvh_strerror(s_), e_.text);    \
        ck_assert_msg(strstr(e_.text, (needle)) != NULL,                       \
                      "message '%s' does not mention '%s'", e_.text,           \
                      (needle));                                               \
        ck_assert_int_eq(e_.status, (code));                                   \
    } while (0)

START_TEST(null_and_empty)
{
    float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3, NULL, 1);
    atrbvh_geometry empty = atrbvh_geometry_triangles(v, 3, NULL, 0);
    atrbvh_geometry nov = atrbvh_geometry_triangles(NULL, 3, NULL, 1);
    atrbvh_geometry nob = atrbvh_geometry_boxes(NULL, 1);
    atrbvh_error e;
    EXPECT(NULL, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "geometry is NULL");
    EXPECT(&empty, NULL, ATRBVH_ERR_NO_PRIMITIVES, "no primitives");
    EXPECT(&nov, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "vertices is NULL");
    EXPECT(&nob, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "boxes is NULL");
    ck_assert_int_eq(atrbvh_build(&g, NULL, NULL, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(e.text, "output pointer"));
    /* A NULL error pointer is allowed. */
    ck_assert_int_eq(build_err(&empty, NULL, NULL), ATRBVH_ERR_NO_PRIMITIVES);
    g.type = (atrbvh_geometry_type)5;
    EXPECT(&g, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "geometry.type 5");
}
END_TEST

START_TEST(nonfinite)
{
    enum { T = 40 };
    float *v = tu_random_triangles(T, 3, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    atrbvh_build_options o;
    atrbvh_bvh *b;
    atrbvh_error e;
    atrbvh_stats st;
    char msg[256];
    int threads;
    v[9 * 29 + 4] = INFINITY;
    v[9 * 5 + 7] = NAN; /* the first bad one is triangle 5 */
    for (threads = 1; threads <= 4; threads++) {
        atrbvh_build_options_init(&o);
        o.threads = threads;
        EXPECT(&g, &o, ATRBVH_ERR_NONFINITE, "triangle 5 ");
        ck_assert_int_eq(build_err(&g, &o, &e), ATRBVH_ERR_NONFINITE);
        ck_assert_uint_eq(e.index, 5);
    }
    o.skip_invalid = 1;
    ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_OK);
    atrbvh_bvh_stats(b, &st);
    ck_assert_uint_eq(st.invalid_skipped, 2);
    ck_assert_uint_eq(st.primitives, T - 2);
    ck_assert_msg(tu_check_bvh(b, &g, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_free(b);
    /* Nothing valid left. */
    {
        float bad[9] = {NAN, 0, 0, 0, 0, 0, 0, 0, 0};
        atrbvh_geometry one = atrbvh_geometry_triangles(bad, 3, NULL, 1);
        EXPECT(&one, &o, ATRBVH_ERR_NO_PRIMITIVES, "NaN or infinite");
    }
    free(v);
}
END_TEST

START_TEST(indices_and_strides)
{
    float v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    uint32_t idx[9] = {0, 1, 2, 1, 2, 3, 0, 7, 3};
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 4, idx, 3);
    atrbvh_build_options o;
    atrbvh_build_options_init(&o);
    EXPECT(&g, NULL, ATRBVH_ERR_INDEX_RANGE, "triangle 2 uses vertex 7");
    /* Not skippable: a bad index is a caller bug, not bad data. */
    o.skip_invalid = 1;
    EXPECT(&g, &o, ATRBVH_ERR_INDEX_RANGE, "only 4 vertices");
    g = atrbvh_geometry_triangles(v, 4, NULL, 2);
    EXPECT(&g, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "need 6 vertices");
    g = atrbvh_geometry_triangles(v, 4, idx, 2);
    g.vertex_stride = 8;
    EXPECT(&g, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "vertex_stride 8");
    g.vertex_stride = 14;
    EXPECT(&g, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "vertex_stride 14");
    g.vertex_stride = 0;
    g.index_stride = 4;
    EXPECT(&g, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "index_stride 4");
    {
        float box[6] = {0, 0, 0, 1, -1, 1};
        atrbvh_geometry bg = atrbvh_geometry_boxes(box, 1);
        EXPECT(&bg, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "box 0 has min greater");
        bg.box_stride = 20;
        EXPECT(&bg, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "box_stride 20");
    }
}
END_TEST

START_TEST(sizes_overflow)
{
    float v[9] = {0};
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3, NULL, 1);
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    tu_alloc.allocations = 0;
    g.primitive_count = ATRBVH_MAX_PRIMITIVES + 1;
    EXPECT(&g, NULL, ATRBVH_ERR_TOO_LARGE, "exceed the limit");
    g.primitive_count = 1;
    g.vertex_count = SIZE_MAX / 4;
    g.vertex_stride = 64;
    EXPECT(&g, NULL, ATRBVH_ERR_TOO_LARGE, "overflows");
    g = atrbvh_geometry_triangles(v, 3, NULL, ATRBVH_MAX_PRIMITIVES);
    /* Claims 2^30 unindexed triangles over 3 vertices: rejected before any
     * allocation. */
    EXPECT(&g, NULL, ATRBVH_ERR_INVALID_ARGUMENT, "vertex_count is 3");
    ck_assert_int_eq(tu_alloc.allocations, 0);
    atrbvh_set_allocator(NULL, NULL);
}
END_TEST

START_TEST(bad_options)
{
    float *v = tu_random_triangles(50, 1, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 150, NULL, 50);
    atrbvh_build_options o;
#define WITH(field, value, code, needle)                                       \
    do {                                                                       \
        atrbvh_build_options_init(&o);                                         \
        o.field = value;                                                       \
        EXPECT(&g, &o, code, needle);                                          \
    } while (0)
    WITH(size, 0, ATRBVH_ERR_INVALID_ARGUMENT, "options.size");
    WITH(size, sizeof o + 8, ATRBVH_ERR_INVALID_ARGUMENT, "options.size");
    WITH(method, (atrbvh_method)7, ATRBVH_ERR_INVALID_ARGUMENT,
         "method 7");
    WITH(treelet_size, 2, ATRBVH_ERR_INVALID_ARGUMENT, "treelet size 2");
    WITH(treelet_size, 129, ATRBVH_ERR_INVALID_ARGUMENT, "treelet size 129");
    WITH(rounds, 1000, ATRBVH_ERR_INVALID_ARGUMENT, "rounds 1000");
    WITH(gamma, 4, ATRBVH_ERR_INVALID_ARGUMENT, "gamma 4");
    WITH(ci, NAN, ATRBVH_ERR_INVALID_ARGUMENT, "ci");
    WITH(ci, -1.0, ATRBVH_ERR_INVALID_ARGUMENT, "ci -1");
    WITH(ct, 0.0, ATRBVH_ERR_INVALID_ARGUMENT, "ct 0");
    WITH(ct, INFINITY, ATRBVH_ERR_INVALID_ARGUMENT, "ct inf");
    WITH(threads, -2, ATRBVH_ERR_INVALID_ARGUMENT, "threads -2");
    WITH(backend, (atrbvh_backend)9, ATRBVH_ERR_INVALID_ARGUMENT,
         "backend 9");
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_TRBVH;
    o.treelet_size = 11;
    EXPECT(&g, &o, ATRBVH_ERR_INVALID_ARGUMENT, "for trbvh");
    /* The adaptive size is ATRBVH's only; its gamma needs 3 leaves. */
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_TRBVH;
    o.treelet_size = ATRBVH_TREELET_AUTO;
    EXPECT(&g, &o, ATRBVH_ERR_INVALID_ARGUMENT, "(auto) is for atrbvh only");
    atrbvh_build_options_init(&o);
    o.treelet_size = ATRBVH_TREELET_AUTO;
    o.gamma = 2;
    EXPECT(&g, &o, ATRBVH_ERR_INVALID_ARGUMENT, "gamma 2");
    atrbvh_build_options_init(&o);
    o.collapse = 0;
    o.max_leaf_size = 4;
    EXPECT(&g, &o, ATRBVH_ERR_INVALID_ARGUMENT, "needs collapse");
#undef WITH
    free(v);
}
END_TEST

START_TEST(strings_and_version)
{
    int s, t;
    char buf[32];
    for (s = ATRBVH_OK; s <= ATRBVH_ERR_BACKEND; s++) {
        ck_assert_ptr_nonnull(atrbvh_strerror((atrbvh_status)s));
        ck_assert_int_gt((int)strlen(atrbvh_strerror((atrbvh_status)s)), 3);
        for (t = ATRBVH_OK; t < s; t++)
            ck_assert_str_ne(atrbvh_strerror((atrbvh_status)s),
                             atrbvh_strerror((atrbvh_status)t));
    }
    ck_assert_str_eq(atrbvh_strerror((atrbvh_status)999), "unknown status");
    ck_assert_uint_eq(atrbvh_version(), ATRBVH_VERSION_HEX);
    snprintf(buf, sizeof buf, "%d.%d.%d", ATRBVH_VERSION_MAJOR,
             ATRBVH_VERSION_MINOR, ATRBVH_VERSION_PATCH);
    ck_assert_str_eq(atrbvh_version_string(), buf);
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
        ck_assert_ptr_nonnull(atrbvh_stage_name((atrbvh_stage)s));
    ck_assert_ptr_null(atrbvh_stage_name(ATRBVH_STAGE_COUNT));
}
END_TEST

/* Fails allocation k for k = 0, 1, 2, ... until the build of g succeeds;
 * every failure must be ATRBVH_ERR_NOMEM with nothing left allocated.
 * `leaf`: 0 no collapse, 1 collapse, 2 collapse with at most 3 per leaf,
 * 3 at most 8.  On a backend this build does not have
 * (ATRBVH_ERR_UNSUPPORTED before any allocation) there is nothing to
 * test. */
static void fail_each_allocation_in(atrbvh_backend backend, atrbvh_method m,
                                    int skip, int threads, int leaf,
                                    const atrbvh_geometry *g)
{
    atrbvh_build_options o;
    long k;
    atrbvh_build_options_init(&o);
    o.method = m;
    o.skip_invalid = skip;
    o.threads = threads;
    o.backend = backend;
    o.collapse = leaf != 0;
    o.max_leaf_size = leaf == 2 ? 3 : leaf == 3 ? 8 : 0;
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    for (k = 0;; k++) {
        atrbvh_bvh *b = NULL;
        atrbvh_error e;
        atrbvh_status s;
        tu_count_reset(k);
        s = atrbvh_build(g, &o, &b, &e);
        tu_alloc.countdown = -1;
        if (s == ATRBVH_ERR_UNSUPPORTED && backend != ATRBVH_BACKEND_CPU &&
            k == 0 && tu_opencl_may_skip(s)) {
            ck_assert_int_eq(tu_alloc.outstanding, 0);
            break;
        }
        if (s == ATRBVH_OK) {
            char msg[256];
            ck_assert_msg(tu_check_bvh(b, g, msg, sizeof msg), "%s", msg);
            atrbvh_bvh_free(b);
            ck_assert_int_eq(tu_alloc.outstanding, 0);
            break;
        }
        ck_assert_msg(s == ATRBVH_ERR_NOMEM, "allocation %ld: %s (%s)", k,
                      atrbvh_strerror(s), e.text);
        ck_assert_ptr_null(b);
        ck_assert_msg(tu_alloc.outstanding == 0,
                      "allocation %ld failed: %ld leaked", k,
                      tu_alloc.outstanding);
        ck_assert_int_gt((int)strlen(e.text), 0);
    }
    if (backend == ATRBVH_BACKEND_CPU)
        ck_assert_int_gt(k, 5); /* the loop really failed several */
    atrbvh_set_allocator(NULL, NULL);
}

/* The same over 3000 random triangles, one of them NaN with skip. */
static void fail_each_allocation_on(atrbvh_backend backend, atrbvh_method m,
                                    int skip, int threads, int leaf)
{
    enum { T = 3000 };
    float *v = tu_random_triangles(T, 11, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    if (skip)
        v[9 * 17] = NAN;
    fail_each_allocation_in(backend, m, skip, threads, leaf, &g);
    free(v);
}

static void fail_each_allocation(atrbvh_method m, int skip, int threads)
{
    fail_each_allocation_on(ATRBVH_BACKEND_CPU, m, skip, threads, 1);
}

START_TEST(allocation_failure)
{
    fail_each_allocation(ATRBVH_METHOD_LBVH, 0, 1);
    fail_each_allocation(ATRBVH_METHOD_LBVH, 1, 2);
    fail_each_allocation(ATRBVH_METHOD_TRBVH, 0, 2);
    fail_each_allocation(ATRBVH_METHOD_ATRBVH, 0, 3);
    {
        /* An LBVH of 3073 primitives or more reads its leaf boxes in
         * place; with max leaf 8 the output's nodes of this sphere (0.96
         * per triangle) then take the node box slot (cpu/collapse.c). */
        scene sc;
        atrbvh_geometry g;
        char err[256];
        ck_assert_msg(scene_builtin("sphere", 20000, &sc, err, sizeof err) ==
                          0,
                      "%s", err);
        g = scene_geometry(&sc);
        fail_each_allocation_in(ATRBVH_BACKEND_CPU, ATRBVH_METHOD_LBVH, 0, 2,
                                3, &g);
        scene_free(&sc);
    }
}
END_TEST

/* Every method, collapse off / on / max leaf 3, on every backend. */
START_TEST(allocation_failure_all)
{
    static const atrbvh_backend backends[] = {ATRBVH_BACKEND_CPU,
                                              ATRBVH_BACKEND_OPENCL};
    int m = _i % 3, leaf = _i / 3;
    size_t be;
    for (be = 0; be < sizeof backends / sizeof *backends; be++)
        fail_each_allocation_on(backends[be], (atrbvh_method)m, leaf == 1,
                                1 + (_i % 2), leaf);
}
END_TEST

/* Loads: every allocation of atrbvh_load_memory and atrbvh_load fails in
 * turn; each failure is ATRBVH_ERR_NOMEM, names itself, and frees
 * everything; save_memory likewise. */
START_TEST(allocation_failure_load)
{
    enum { T = 500 };
    float *v = tu_random_triangles(T, 12, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    atrbvh_build_options o;
    atrbvh_bvh *b, *l;
    void *data = NULL;
    size_t size = 0;
    char path[256];
    const char *tmp = getenv("TMPDIR");
    int pass;
    long k;
    atrbvh_error e;
    atrbvh_build_options_init(&o);
    o.threads = 2;
    v[9 * 3 + 1] = NAN;
    o.skip_invalid = 1; /* input count != index count in the file */
    b = tu_build(&g, &o);
    snprintf(path, sizeof path, "%s/atrbvh_errors_%ld.bvh",
             tmp && *tmp ? tmp : "/tmp", (long)getpid());
    ck_assert_int_eq(atrbvh_save(b, path, &e), ATRBVH_OK);
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    for (pass = 0; pass < 3; pass++) {
        for (k = 0;; k++) {
            atrbvh_status s;
            tu_count_reset(k);
            l = NULL;
            if (pass == 0) {
                s = atrbvh_save_memory(b, &data, &size, &e);
            } else if (pass == 1) {
                s = atrbvh_load_memory(data, size, &l, &e);
            } else {
                s = atrbvh_load(path, &l, &e);
            }
            tu_alloc.countdown = -1;
            if (s == ATRBVH_OK) {
                if (pass == 0) {
                    ck_assert_int_eq(tu_alloc.outstanding, 1);
                } else {
                    ck_assert_int_eq(atrbvh_compare(b, l, &e), 0);
                    atrbvh_bvh_free(l);
                    ck_assert_int_eq(tu_alloc.outstanding, 0);
                }
                break;
            }
            ck_assert_msg(s == ATRBVH_ERR_NOMEM, "pass %d allocation %ld: %s",
                          pass, k, e.text);
            ck_assert_ptr_null(l);
            ck_assert_msg(tu_alloc.outstanding == 0,
                          "pass %d allocation %ld: %ld "
                          "leaked",
                          pass, k, tu_alloc.outstanding);
            ck_assert_msg(strstr(e.text, "memory") != NULL, "%s", e.text);
        }
        ck_assert_int_gt(k, 0);
    }
    atrbvh_free(data);
    atrbvh_set_allocator(NULL, NULL);
    remove(path);
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("errors");
    TCase *tc = tcase_create("errors");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, null_and_empty);
    tcase_add_test(tc, nonfinite);
    tcase_add_test(tc, indices_and_strides);
    tcase_add_test(tc, sizes_overflow);
    tcase_add_test(tc, bad_options);
    tcase_add_test(tc, strings_and_version);
    tcase_add_test(tc, allocation_failure);
    tcase_add_loop_test(tc, allocation_failure_all, 0, 9);
    tcase_add_test(tc, allocation_failure_load);
    suite_add_tcase(s, tc);
    return tu_run(s);
}
