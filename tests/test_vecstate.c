/*
 * test_vecstate.c - the library hands the x86 vector unit back clean: no
 * public call returns, on the caller's thread or on the OpenMP threads
 * that ran its work, with the upper halves of the AVX registers in use.
 *
 * Why it matters: code compiled for SSE (legacy encodings) that runs while
 * those upper halves are dirty pays for it on every vector instruction.
 * On the AMD EPYC of docs/benchmarks.md, Embree's rtcBuildBVH (medium
 * quality, its SSE2 builder) run right after an atrbvh LBVH build took
 * 1.35x as long as after a TRBVH build, and no longer once a vzeroupper
 * was put between the two: the Morton stage's AVX2 code left the state
 * dirty by a tail call into scalar code, and so did the SAH sum (GCC puts
 * no vzeroupper before such a jump).  The library's own stages after the
 * Morton stage ran in that state too (with no cost measurable there).
 *
 * How: XGETBV with ECX = 1 reads XINUSE, which has bit 2 set while the
 * upper halves of YMM0-15 may be non-zero and bit 6 for the upper halves
 * of ZMM0-15.  Each case clears them with VZEROUPPER on this thread and on
 * every thread of an OpenMP team of THREADS, makes the call, and reads the
 * bits again on each.  Skips, saying so, off x86 or where the processor
 * lacks AVX or XGETBV with ECX = 1.  Runs in one process (CK_NOFORK): the
 * OpenMP team must be the one the library's calls used.
 *
 * GCC clears the state itself at the end of an AVX function only at -O2
 * and above, and not before a tail call, so every AVX function the
 * library calls from SSE code clears it explicitly: the property holds
 * at -O1 (the sanitizer stage's build) as at -O2.
 */
#define _POSIX_C_SOURCE 200809L
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "atrbvh.h"
#include "testutil.h"

#define THREADS 2
#define TRIANGLES 20000
#define RAYS 4096

/* XINUSE bits that make legacy SSE code pay: the upper halves of YMM0-15
 * (2) and of ZMM0-15 (6).  (Bit 7, ZMM16-31, does not: SSE cannot name
 * those registers.) */
#define DIRTY_BITS ((1u << 2) | (1u << 6))

#if (defined(__GNUC__) || defined(__clang__)) &&                            \
    (defined(__x86_64__) || defined(__i386__))
#include <cpuid.h>
#define VEC_X86 1

/* AVX, OSXSAVE and XGETBV with ECX = 1 (CPUID 0xD, sub-leaf 1, EAX bit 2). */
static int vec_supported(void)
{
    unsigned a, b, c, d;
    if (!__get_cpuid(1, &a, &b, &c, &d) || !(c & (1u << 27)) ||
        !(c & (1u << 28)))
        return 0;
    if (__get_cpuid_max(0, NULL) < 0xd)
        return 0;
    __cpuid_count(0xd, 1, a, b, c, d);
    return (a & (1u << 2)) != 0;
}

static unsigned vec_dirty(void)
{
    unsigned lo, hi;
    __asm__ volatile("xgetbv" : "=a"(lo), "=d"(hi) : "c"(1));
    (void)hi;
    return lo & DIRTY_BITS;
}

static void vec_clear(void) { __asm__ volatile("vzeroupper"); }
#else
static int vec_supported(void) { return 0; }
static unsigned vec_dirty(void) { return 0; }
static void vec_clear(void) {}
#endif

/* The state of each team thread (index 0: the caller), read in one
 * parallel region; `clear` clears it first. */
static void team_state(int clear, unsigned state[THREADS], int *team)
{
    memset(state, 0, THREADS * sizeof *state);
#ifdef _OPENMP
#pragma omp parallel num_threads(THREADS)
    {
        const int t = omp_get_thread_num();
        if (clear)
            vec_clear();
        if (t < THREADS)
            state[t] = vec_dirty();
#pragma omp single
        *team = omp_get_num_threads();
    }
#else
    if (clear)
        vec_clear();
    state[0] = vec_dirty();
    *team = 1;
#endif
}

/* Clean before (checked: else the case proves nothing). */
static void before(void)
{
    unsigned s[THREADS];
    int team, t;
    team_state(1, s, &team);
    for (t = 0; t < team; t++)
        ck_assert_msg(s[t] == 0, "thread %d: XINUSE %#x after vzeroupper",
                      t, s[t]);
    vec_clear();
    ck_assert_uint_eq(vec_dirty(), 0);
}

/* Clean after `what`: on this thread (read before anything else runs
 * here), then on each thread of the team. */
static void after(const char *what)
{
    const unsigned caller = vec_dirty();
    unsigned s[THREADS];
    int team, t;
    ck_assert_msg(caller == 0,
                  "%s returns with XINUSE %#x on the calling thread (the "
                  "upper halves of the AVX registers in use)",
                  what, caller);
    team_state(0, s, &team);
    for (t = 1; t < team; t++)
        ck_assert_msg(s[t] == 0,
                      "%s leaves XINUSE %#x on OpenMP thread %d", what, s[t],
                      t);
}

static float *verts;
static atrbvh_geometry geom;

static void setup(void)
{
    verts = tu_random_triangles(TRIANGLES, 7, 10.0f, 0.0f);
    ck_assert_ptr_nonnull(verts);
    geom = atrbvh_geometry_triangles(verts, 3 * (size_t)TRIANGLES, NULL,
                                     TRIANGLES);
}

static void teardown(void)
{
    free(verts);
    verts = NULL;
}

static void options(atrbvh_build_options *o, atrbvh_method m)
{
    atrbvh_build_options_init(o);
    o->method = m;
    o->threads = THREADS;
    o->max_leaf_size = 8;
}

static const char *method_name[3] = {"LBVH", "TRBVH", "ATRBVH"};

/* Every method, a new tree and one rebuilt into the last. */
START_TEST(build_leaves_vector_state_clean)
{
    atrbvh_build_options o;
    atrbvh_bvh *b = NULL;
    atrbvh_error e;
    char what[64];
    if (!vec_supported())
        return;
    options(&o, (atrbvh_method)_i);
    before();
    ck_assert_int_eq(atrbvh_build(&geom, &o, &b, &e), ATRBVH_OK);
    snprintf(what, sizeof what, "atrbvh_build (%s)", method_name[_i]);
    after(what);
    before();
    ck_assert_int_eq(atrbvh_rebuild(&geom, &o, &b, &e), ATRBVH_OK);
    snprintf(what, sizeof what, "atrbvh_rebuild (%s)", method_name[_i]);
    after(what);
    atrbvh_bvh_free(b);
}
END_TEST

/* Boxes geometry and triangle splitting take other first stages. */
START_TEST(boxes_and_split_builds_leave_vector_state_clean)
{
    atrbvh_build_options o;
    atrbvh_bvh *b = NULL;
    atrbvh_error e;
    float *boxes;
    size_t i;
    if (!vec_supported())
        return;
    boxes = malloc((size_t)TRIANGLES * 6 * sizeof *boxes);
    ck_assert_ptr_nonnull(boxes);
    /* (any valid boxes: one of side 0.1 at each triangle's first vertex) */
    for (i = 0; i < TRIANGLES; i++) {
        int k;
        for (k = 0; k < 3; k++) {
            boxes[6 * i + k] = verts[9 * i + k];
            boxes[6 * i + 3 + k] = verts[9 * i + k] + 0.1f;
        }
    }
    {
        const atrbvh_geometry g = atrbvh_geometry_boxes(boxes, TRIANGLES);
        options(&o, ATRBVH_METHOD_LBVH);
        before();
        ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_OK);
        after("atrbvh_build (LBVH, boxes)");
        atrbvh_bvh_free(b);
        b = NULL;
    }
    options(&o, ATRBVH_METHOD_LBVH);
    o.split_budget = 0.3;
    before();
    ck_assert_int_eq(atrbvh_build(&geom, &o, &b, &e), ATRBVH_OK);
    after("atrbvh_build (LBVH, split_budget 0.3)");
    atrbvh_bvh_free(b);
    free(boxes);
}
END_TEST

/* What a caller does with a tree: refit, re-optimise, statistics, the
 * SAH, save and load. */
START_TEST(tree_calls_leave_vector_state_clean)
{
    atrbvh_build_options o;
    atrbvh_bvh *b = NULL, *l = NULL;
    atrbvh_error e;
    atrbvh_stats st;
    const atrbvh_node *nodes;
    size_t count, size = 0;
    void *mem = NULL;
    double sah;
    if (!vec_supported())
        return;
    options(&o, ATRBVH_METHOD_LBVH);
    ck_assert_int_eq(atrbvh_build(&geom, &o, &b, &e), ATRBVH_OK);
    before();
    ck_assert_int_eq(atrbvh_refit(b, &geom, &o, &e), ATRBVH_OK);
    after("atrbvh_refit");
    options(&o, ATRBVH_METHOD_ATRBVH);
    before();
    ck_assert_int_eq(atrbvh_reoptimise(b, &geom, &o, &e), ATRBVH_OK);
    after("atrbvh_reoptimise");
    before();
    ck_assert_int_eq(atrbvh_bvh_stats(b, &st), ATRBVH_OK);
    after("atrbvh_bvh_stats");
    nodes = atrbvh_bvh_nodes(b, &count);
    before();
    sah = atrbvh_sah(nodes, count, 1.2, 1.0);
    after("atrbvh_sah");
    ck_assert(sah > 0.0);
    before();
    ck_assert_int_eq(atrbvh_save_memory(b, &mem, &size, &e), ATRBVH_OK);
    after("atrbvh_save_memory");
    before();
    ck_assert_int_eq(atrbvh_load_memory(mem, size, &l, &e), ATRBVH_OK);
    after("atrbvh_load_memory");
    atrbvh_free(mem);
    atrbvh_bvh_free(l);
    atrbvh_bvh_free(b);
}
END_TEST

/* Rays: one at a time and in batches, closest hit and any hit. */
START_TEST(ray_calls_leave_vector_state_clean)
{
    atrbvh_build_options o;
    atrbvh_bvh *b = NULL;
    atrbvh_error e;
    atrbvh_ray *rays;
    atrbvh_hit *hits, h;
    uint8_t *occ;
    tu_rng rng;
    size_t i, hit_count = 0;
    if (!vec_supported())
        return;
    options(&o, ATRBVH_METHOD_ATRBVH);
    ck_assert_int_eq(atrbvh_build(&geom, &o, &b, &e), ATRBVH_OK);
    rays = malloc(RAYS * sizeof *rays);
    hits = malloc(RAYS * sizeof *hits);
    occ = malloc(RAYS);
    ck_assert(rays && hits && occ);
    tu_rng_seed(&rng, 11);
    for (i = 0; i < RAYS; i++) {
        int k;
        for (k = 0; k < 3; k++) {
            rays[i].origin[k] = -5.0f + 20.0f * tu_rng_float(&rng);
            rays[i].dir[k] = tu_rng_float(&rng) - 0.5f;
        }
        rays[i].tmin = 0.0f;
        rays[i].tmax = 1e30f;
    }
    before();
    ck_assert_int_eq(
        atrbvh_intersect_batch(b, &geom, rays, RAYS, hits, THREADS, &e),
        ATRBVH_OK);
    after("atrbvh_intersect_batch");
    for (i = 0; i < RAYS; i++)
        hit_count += hits[i].primitive != ATRBVH_NO_HIT;
    ck_assert_msg(hit_count > 0 && hit_count < RAYS,
                  "%zu of %d rays hit: the rays test too little", hit_count,
                  RAYS);
    before();
    ck_assert_int_eq(
        atrbvh_occluded_batch(b, &geom, rays, RAYS, occ, THREADS, &e),
        ATRBVH_OK);
    after("atrbvh_occluded_batch");
    before();
    (void)atrbvh_intersect(b, &geom, &rays[0], &h);
    after("atrbvh_intersect");
    before();
    (void)atrbvh_occluded(b, &geom, &rays[0]);
    after("atrbvh_occluded");
    free(rays);
    free(hits);
    free(occ);
    atrbvh_bvh_free(b);
}
END_TEST

/* The OpenCL backend: the host side of each method's build on an open
 * device (skips, saying so, without an OpenCL device). */
START_TEST(device_builds_leave_vector_state_clean)
{
    atrbvh_build_options o;
    atrbvh_device *dev = NULL;
    atrbvh_bvh *b = NULL;
    atrbvh_error e;
    int m;
    if (!vec_supported())
        return;
    if (atrbvh_device_open("opencl", &dev, &e) != ATRBVH_OK) {
        fprintf(stderr, "test_vecstate: device case skipped: %s\n", e.text);
        return;
    }
    for (m = 0; m < 3; m++) {
        char what[64];
        options(&o, (atrbvh_method)m);
        o.device = dev;
        before();
        ck_assert_int_eq(atrbvh_rebuild(&geom, &o, &b, &e), ATRBVH_OK);
        snprintf(what, sizeof what, "atrbvh_rebuild (%s, OpenCL)",
                 method_name[m]);
        after(what);
    }
    atrbvh_bvh_free(b);
    atrbvh_device_close(dev);
}
END_TEST

/* The check itself: a 256-bit instruction here must show (else the cases
 * above could not fail). */
START_TEST(the_check_sees_a_dirty_state)
{
    if (!vec_supported()) {
        fprintf(stderr, "test_vecstate: skipped: not x86, or no AVX or no "
                        "XGETBV with ECX = 1 on this processor\n");
        return;
    }
#ifdef VEC_X86
    vec_clear();
    ck_assert_uint_eq(vec_dirty(), 0);
    /* all ones: a zeroing idiom would leave the state clean */
    __asm__ volatile("vcmpps $15, %%ymm1, %%ymm1, %%ymm1" ::: "xmm1");
    ck_assert_uint_ne(vec_dirty() & (1u << 2), 0);
    vec_clear();
    ck_assert_uint_eq(vec_dirty(), 0);
#endif
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("vecstate");
    TCase *tc = tcase_create("vecstate");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, the_check_sees_a_dirty_state);
    tcase_add_loop_test(tc, build_leaves_vector_state_clean, 0, 3);
    tcase_add_test(tc, boxes_and_split_builds_leave_vector_state_clean);
    tcase_add_test(tc, tree_calls_leave_vector_state_clean);
    tcase_add_test(tc, ray_calls_leave_vector_state_clean);
    tcase_add_test(tc, device_builds_leave_vector_state_clean);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(suite());
    int failed;
    /* ATRBVH_NO_AVX2 would take the scalar paths this test is about. */
    unsetenv("ATRBVH_NO_AVX2");
    srunner_set_fork_status(sr, CK_NOFORK);
    srunner_run_all(sr, CK_NORMAL);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
