/*
 * test_clreuse.c - an open OpenCL handle keeps its device buffers between
 * builds: a second build of the same scene, and a build of a smaller one,
 * create no buffer (cl/memory.c counts clCreateBuffer calls in the
 * handle's state), and still give the CPU's tree; a larger scene grows
 * them.  White-box: links the library's core and reads the backend's
 * state (cl/opencl.h).  Skips without an OpenCL device.
 */
#define _POSIX_C_SOURCE 200809L
#include <check.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "atrbvh.h"
#include "backend.h" /* struct atrbvh_device: impl */
#include "opencl.h"  /* atrbvh_cl_device: buffers_created */
#include "testutil.h"

static unsigned long created(const atrbvh_device *dev)
{
    return ((const atrbvh_cl_device *)dev->impl)->buffers_created;
}

/* Builds n random triangles on dev and on the CPU; the trees must match. */
static void build_and_compare(atrbvh_device *dev, unsigned n, unsigned seed)
{
    float *v = tu_random_triangles(n, seed, 3.0f, 1.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
    atrbvh_build_options o;
    atrbvh_bvh *x, *y;
    atrbvh_error e;
    atrbvh_build_options_init(&o);
    x = tu_build(&g, &o);
    o.device = dev;
    y = tu_build(&g, &o);
    ck_assert_msg(atrbvh_compare(x, y, &e) == 0, "%u triangles: %s", n,
                  e.text);
    atrbvh_bvh_free(x);
    atrbvh_bvh_free(y);
    free(v);
}

START_TEST(second_build_creates_no_buffer)
{
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    unsigned long after_first, after_second;
    atrbvh_status st = atrbvh_device_open("opencl", &dev, &e);
    if (tu_opencl_may_skip(st)) {
        fprintf(stderr, "SKIP second_build_creates_no_buffer: %s\n", e.text);
        return;
    }
    ck_assert_msg(st == ATRBVH_OK, "%s", e.text);
    ck_assert_uint_eq(created(dev), 0); /* open makes no buffer */
    build_and_compare(dev, 5000, 1);
    after_first = created(dev);
    ck_assert(after_first > 0);
    build_and_compare(dev, 5000, 2); /* same size, other triangles */
    after_second = created(dev);
    ck_assert_msg(after_second == after_first,
                  "second build created %lu buffers",
                  after_second - after_first);
    build_and_compare(dev, 1200, 3); /* smaller */
    ck_assert_uint_eq(created(dev), after_first);
    build_and_compare(dev, 9000, 4); /* larger: grows */
    ck_assert(created(dev) > after_first);
    atrbvh_device_close(dev);
}
END_TEST

/* The optimise stage's skip marks (atrbvh_treelet_process_marked, on the
 * device as on the CPU): from the second round on, treelets known to
 * change nothing are skipped, the tree still the CPU's; one round skips
 * none; ATRBVH above 32 leaves keeps no marks; a second build on the
 * same handle starts from clean marks (the same counts again). */
/* Builds g with the method on the CPU and on dev, the trees equal; the
 * handle's counters then describe the device build. */
static const atrbvh_cl_device *device_build(atrbvh_device *dev,
                                            const atrbvh_geometry *g,
                                            atrbvh_method method,
                                            unsigned treelet, unsigned rounds)
{
    atrbvh_build_options o;
    atrbvh_bvh *x, *y;
    atrbvh_error e;
    atrbvh_build_options_init(&o);
    o.method = method;
    o.treelet_size = treelet;
    o.rounds = rounds;
    x = tu_build(g, &o);
    o.device = dev;
    y = tu_build(g, &o);
    ck_assert_msg(atrbvh_compare(x, y, &e) == 0, "%s", e.text);
    atrbvh_bvh_free(x);
    atrbvh_bvh_free(y);
    return (const atrbvh_cl_device *)dev->impl;
}

static void opt_counts(atrbvh_device *dev, const atrbvh_geometry *g,
                       atrbvh_method method, unsigned treelet,
                       unsigned rounds, unsigned long out[3])
{
    const atrbvh_cl_device *c = device_build(dev, g, method, treelet, rounds);
    out[0] = c->opt_treelets;
    out[1] = c->opt_applied;
    out[2] = c->opt_skipped;
}

START_TEST(skip_marks_on_the_device)
{
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    unsigned n = 20000;
    float *v;
    atrbvh_geometry g;
    unsigned long a[3], b[3];
    atrbvh_status st = atrbvh_device_open("opencl", &dev, &e);
    if (tu_opencl_may_skip(st)) {
        fprintf(stderr, "SKIP skip_marks_on_the_device: %s\n", e.text);
        return;
    }
    ck_assert_msg(st == ATRBVH_OK, "%s", e.text);
    v = tu_random_triangles(n, 7, 3.0f, 1.0f);
    g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
    /* ATRBVH(9, 2) */
    opt_counts(dev, &g, ATRBVH_METHOD_ATRBVH, 9, 2, a);
    ck_assert(a[0] > 0 && a[1] > 0 && a[1] <= a[0]);
    ck_assert_msg(a[2] > 0, "ATRBVH(9,2): no treelet skipped");
    /* again on the same handle: the marks start clean */
    opt_counts(dev, &g, ATRBVH_METHOD_ATRBVH, 9, 2, b);
    ck_assert_msg(a[0] == b[0] && a[1] == b[1] && a[2] == b[2],
                  "second build: %lu/%lu/%lu treelets/applied/skipped, "
                  "first %lu/%lu/%lu",
                  b[0], b[1], b[2], a[0], a[1], a[2]);
    /* TRBVH(7, 3) and the adaptive size */
    opt_counts(dev, &g, ATRBVH_METHOD_TRBVH, 7, 3, a);
    ck_assert_msg(a[0] > 0 && a[2] > 0, "TRBVH(7,3): %lu/%lu", a[0], a[2]);
    opt_counts(dev, &g, ATRBVH_METHOD_ATRBVH, ATRBVH_TREELET_AUTO, 4, a);
    ck_assert_msg(a[0] > 0 && a[2] > 0, "ATRBVH(auto,4): %lu/%lu", a[0],
                  a[2]);
    /* one round: nothing known yet */
    opt_counts(dev, &g, ATRBVH_METHOD_ATRBVH, 9, 1, a);
    ck_assert(a[0] > 0 && a[2] == 0);
    /* above 32 leaves: no marks */
    opt_counts(dev, &g, ATRBVH_METHOD_ATRBVH, 48, 2, a);
    ck_assert(a[0] > 0 && a[2] == 0);
    free(v);
    atrbvh_device_close(dev);
}
END_TEST

/* The fixed costs of a build on an open handle (cl/stages.c; counted in
 * the handle's state, cl/memory.c): an LBVH of unindexed triangles
 * queues 8 launches (bounds 1, morton 1, sort 3: the MSD pass's count and
 * scatter and the buckets, hierarchy 1 with the refit, layout 2; 21 with
 * the sort's eight LSD passes and the refit's own launch), one queued
 * write (the vertices) and no fill, and waits twice: the collapse's
 * root size (the bounds record's read and the hierarchy's status, the
 * keys' order, queued before it: the Morton frame is the device's, the
 * invalid count and the order are checked there) and the output's
 * primitives (the nodes' read queued before it), with no clFinish (the
 * profiling times are read after the last wait).  Before: 4 blocking
 * reads (the bounds' partial boxes first) and a clFinish; before the
 * launches were fused and the waits between stages dropped, 32 launches,
 * 2 fills, 6 reads and 7 clFinish calls.  (From 131072 primitives the
 * sort reads back its bucket starts, two more waits, to split a big
 * bucket: cl/stages.c's big_buckets; 20000 here.)  ATRBVH(9, 2) of indexed
 * triangles adds 2 launches per round, two fills (the skip marks and the
 * treelet counts; the walks find their starts in opt_prepare's marks,
 * with no start list whose length a fill would zero per round), one
 * queued read (the treelet counts, which arrive with the root size) and
 * the indices' write, and no wait.  Every tree is the CPU's. */
static void counted_build(atrbvh_device *dev, const atrbvh_geometry *g,
                          atrbvh_method method, unsigned long out[6])
{
    const atrbvh_cl_device *c = device_build(dev, g, method, 9, 2);
    out[0] = c->n_launches;
    out[1] = c->n_writes;
    out[2] = c->n_fills;
    out[3] = c->n_reads;
    out[4] = c->n_finishes;
    out[5] = c->n_queued_reads;
}

START_TEST(launches_and_waits_per_build)
{
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    unsigned n = 20000, k;
    float *v;
    uint32_t *idx;
    atrbvh_geometry g;
    unsigned long a[6];
    atrbvh_status st = atrbvh_device_open("opencl", &dev, &e);
    if (tu_opencl_may_skip(st)) {
        fprintf(stderr, "SKIP launches_and_waits_per_build: %s\n", e.text);
        return;
    }
    ck_assert_msg(st == ATRBVH_OK, "%s", e.text);
    v = tu_random_triangles(n, 9, 3.0f, 1.0f);
    g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
    counted_build(dev, &g, ATRBVH_METHOD_LBVH, a); /* makes the buffers */
    counted_build(dev, &g, ATRBVH_METHOD_LBVH, a);
    ck_assert_msg(a[0] == 8 && a[1] == 1 && a[2] == 0 && a[3] == 2 &&
                      a[4] == 0 && a[5] == 3,
                  "LBVH: %lu launches, %lu writes, %lu fills, %lu blocking "
                  "reads, %lu clFinish, %lu queued reads (want 8, 1, 0, 2, "
                  "0, 3)",
                  a[0], a[1], a[2], a[3], a[4], a[5]);
    /* indexed (each triangle's own three vertices), ATRBVH(9, 2) */
    idx = malloc(3 * (size_t)n * sizeof *idx);
    ck_assert_ptr_nonnull(idx);
    for (k = 0; k < 3 * n; k++)
        idx[k] = k;
    g = atrbvh_geometry_triangles(v, 3 * n, idx, n);
    counted_build(dev, &g, ATRBVH_METHOD_ATRBVH, a);
    ck_assert_msg(a[0] == 13 && a[1] == 2 && a[2] == 2 && a[3] == 2 &&
                      a[4] == 0 && a[5] == 4,
                  "ATRBVH(9,2): %lu launches, %lu writes, %lu fills, %lu "
                  "blocking reads, %lu clFinish, %lu queued reads (want 13, "
                  "2, 2, 2, 0, 4)",
                  a[0], a[1], a[2], a[3], a[4], a[5]);
    free(idx);
    free(v);
    atrbvh_device_close(dev);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("clreuse");
    TCase *tc = tcase_create("buffers");
    tcase_add_test(tc, second_build_creates_no_buffer);
    tcase_add_test(tc, skip_marks_on_the_device);
    tcase_add_test(tc, launches_and_waits_per_build);
    tcase_set_timeout(tc, 300);
    suite_add_tcase(s, tc);
    return tu_run(s);
}
