/*
 * test_clreuse.c - an open OpenCL handle keeps its device buffers between
 * builds: a second build of the same scene, and a build of a smaller one,
 * create no buffer (cl/memory.c counts clCreateBuffer calls in the
 * handle's state), and still give the CPU's tree; a larger scene grows
 * them.  A device that shares the host's memory reads the geometry and
 * writes the output in place (no copy; ATRBVH_CL_COPY asks for the
 * copies), with the same trees.  White-box: links the library's core and
 * reads the backend's state (cl/opencl.h).  Skips without an OpenCL
 * device.
 */
#define _POSIX_C_SOURCE 200809L
#include <check.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

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
/* Builds g with the method on the CPU and on dev, the trees equal;
 * returns the device's. */
static atrbvh_bvh *device_tree(atrbvh_device *dev, const atrbvh_geometry *g,
                               atrbvh_method method, unsigned treelet,
                               unsigned rounds)
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
    return y;
}

/* device_tree; the handle's counters then describe the device build. */
static const atrbvh_cl_device *device_build(atrbvh_device *dev,
                                            const atrbvh_geometry *g,
                                            atrbvh_method method,
                                            unsigned treelet, unsigned rounds)
{
    atrbvh_bvh_free(device_tree(dev, g, method, treelet, rounds));
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

/* The optimise stage's kernel (cl/stages.c): on a CPU device, where the
 * skip marks are kept (TRBVH, ATRBVH up to 32 leaves or adaptive), each
 * work-item takes several treelets at once (opt_round4, as the CPU's
 * walk_lanes; ATRBVH's agglomerations side by side in a double4's
 * lanes), else one at a time (opt_round), and ATRBVH_CL_WALKS=1 at the
 * open asks for opt_round on any device.  The trees are the CPU's either
 * way.  Returns the build's optimise kernel: 4 for opt_round4, 1 for
 * opt_round (failing when both or neither ran). */
static int opt_kernel(atrbvh_device *dev, const atrbvh_geometry *g,
                      atrbvh_method method, unsigned treelet,
                      unsigned rounds)
{
    atrbvh_bvh *y = device_tree(dev, g, method, treelet, rounds);
    const char *name;
    size_t i;
    int four = 0, one = 0;
    for (i = 0; atrbvh_bvh_kernel_time(y, i, &name, NULL); i++) {
        four += strcmp(name, "opt_round4") == 0;
        one += strcmp(name, "opt_round") == 0;
    }
    atrbvh_bvh_free(y);
    ck_assert_msg((four > 0) != (one > 0),
                  "method %d, treelet %u: opt_round4 %d, opt_round %d",
                  (int)method, treelet, four, one);
    return four ? 4 : 1;
}

static atrbvh_device *open_walks(const char *walks, const char *test)
{
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    atrbvh_status st;
    if (walks)
        ck_assert_int_eq(setenv("ATRBVH_CL_WALKS", walks, 1), 0);
    st = atrbvh_device_open("opencl", &dev, &e);
    ck_assert_int_eq(unsetenv("ATRBVH_CL_WALKS"), 0);
    if (tu_opencl_may_skip(st)) {
        fprintf(stderr, "SKIP %s: %s\n", test, e.text);
        return NULL;
    }
    ck_assert_msg(st == ATRBVH_OK, "%s", e.text);
    return dev;
}

START_TEST(several_treelets_an_item_on_a_cpu_device)
{
    const char *const modes[3] = {NULL, "0", "1"};
    unsigned n = 20000, k;
    float *v = tu_random_triangles(n, 11, 3.0f, 1.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
    for (k = 0; k < 3u; k++) {
        atrbvh_device *dev =
            open_walks(modes[k], "several_treelets_an_item_on_a_cpu_device");
        cl_device_type type = 0;
        int want;
        if (!dev)
            break;
        ck_assert_int_eq(
            clGetDeviceInfo(((const atrbvh_cl_device *)dev->impl)->device,
                            CL_DEVICE_TYPE, sizeof type, &type, NULL),
            CL_SUCCESS);
        want = (type & CL_DEVICE_TYPE_CPU) && k < 2u ? 4 : 1;
        ck_assert_int_eq(opt_kernel(dev, &g, ATRBVH_METHOD_ATRBVH, 9, 2),
                         want);
        ck_assert_int_eq(opt_kernel(dev, &g, ATRBVH_METHOD_TRBVH, 7, 3),
                         want);
        ck_assert_int_eq(opt_kernel(dev, &g, ATRBVH_METHOD_ATRBVH,
                                    ATRBVH_TREELET_AUTO, 4),
                         want);
        ck_assert_int_eq(opt_kernel(dev, &g, ATRBVH_METHOD_ATRBVH, 3, 2),
                         want);
        /* above 32 leaves (no marks): one at a time on any device */
        ck_assert_int_eq(opt_kernel(dev, &g, ATRBVH_METHOD_ATRBVH, 48, 2), 1);
        atrbvh_device_close(dev);
    }
    free(v);
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
                          atrbvh_method method, unsigned long out[7])
{
    const atrbvh_cl_device *c = device_build(dev, g, method, 9, 2);
    out[0] = c->n_launches;
    out[1] = c->n_writes;
    out[2] = c->n_fills;
    out[3] = c->n_reads;
    out[4] = c->n_finishes;
    out[5] = c->n_queued_reads;
    out[6] = c->n_wraps;
}

/* Opens "opencl", with ATRBVH_CL_COPY set to `copy` for the open (NULL:
 * unset); NULL when there is no OpenCL (a skip). */
static atrbvh_device *open_mode(const char *copy, const char *test)
{
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    atrbvh_status st;
    if (copy)
        ck_assert_int_eq(setenv("ATRBVH_CL_COPY", copy, 1), 0);
    else
        ck_assert_int_eq(unsetenv("ATRBVH_CL_COPY"), 0);
    st = atrbvh_device_open("opencl", &dev, &e);
    ck_assert_int_eq(unsetenv("ATRBVH_CL_COPY"), 0);
    if (tu_opencl_may_skip(st)) {
        fprintf(stderr, "SKIP %s: %s\n", test, e.text);
        return NULL;
    }
    ck_assert_msg(st == ATRBVH_OK, "%s", e.text);
    return dev;
}

/* What the device says of its memory, asked here. */
static int reports_host_memory(const atrbvh_device *dev)
{
    const atrbvh_cl_device *c = (const atrbvh_cl_device *)dev->impl;
    cl_bool unified = CL_FALSE;
    ck_assert_int_eq(clGetDeviceInfo(c->device, CL_DEVICE_HOST_UNIFIED_MEMORY,
                                     sizeof unified, &unified, NULL),
                     CL_SUCCESS);
    return unified == CL_TRUE;
}

/* The counts of the comment above on one handle, whose mode (copies or
 * the caller's memory in place) is the device's unless ATRBVH_CL_COPY
 * was set at its open: in place, no write and one wrap per geometry
 * array and per output array, the rest the same. */
static void counts_on(atrbvh_device *dev, int in_place)
{
    unsigned n = 20000, k;
    float *v;
    uint32_t *idx;
    atrbvh_geometry g;
    unsigned long a[7], w;
    ck_assert_uint_eq(((const atrbvh_cl_device *)dev->impl)->host_memory,
                      (unsigned)in_place);
    v = tu_random_triangles(n, 9, 3.0f, 1.0f);
    g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
    counted_build(dev, &g, ATRBVH_METHOD_LBVH, a); /* makes the buffers */
    counted_build(dev, &g, ATRBVH_METHOD_LBVH, a);
    w = in_place ? 0 : 1;
    ck_assert_msg(a[0] == 8 && a[1] == w && a[2] == 0 && a[3] == 2 &&
                      a[4] == 0 && a[5] == 3 && a[6] == 3 * (1 - w),
                  "LBVH: %lu launches, %lu writes, %lu fills, %lu blocking "
                  "reads, %lu clFinish, %lu queued reads, %lu wraps (want "
                  "8, %lu, 0, 2, 0, 3, %lu)",
                  a[0], a[1], a[2], a[3], a[4], a[5], a[6], w, 3 * (1 - w));
    /* indexed (each triangle's own three vertices), ATRBVH(9, 2) */
    idx = malloc(3 * (size_t)n * sizeof *idx);
    ck_assert_ptr_nonnull(idx);
    for (k = 0; k < 3 * n; k++)
        idx[k] = k;
    g = atrbvh_geometry_triangles(v, 3 * n, idx, n);
    counted_build(dev, &g, ATRBVH_METHOD_ATRBVH, a);
    ck_assert_msg(a[0] == 13 && a[1] == 2 * w && a[2] == 2 && a[3] == 2 &&
                      a[4] == 0 && a[5] == 4 && a[6] == 4 * (1 - w),
                  "ATRBVH(9,2): %lu launches, %lu writes, %lu fills, %lu "
                  "blocking reads, %lu clFinish, %lu queued reads, %lu "
                  "wraps (want 13, %lu, 2, 2, 0, 4, %lu)",
                  a[0], a[1], a[2], a[3], a[4], a[5], a[6], 2 * w,
                  4 * (1 - w));
    free(idx);
    free(v);
}

START_TEST(launches_and_waits_per_build)
{
    atrbvh_device *dev = open_mode(NULL, "launches_and_waits_per_build");
    if (!dev)
        return;
    /* in place exactly when the device says it shares the host's memory */
    counts_on(dev, reports_host_memory(dev));
    atrbvh_device_close(dev);
    dev = open_mode("1", "launches_and_waits_per_build");
    ck_assert_ptr_nonnull(dev);
    counts_on(dev, 0); /* ATRBVH_CL_COPY: copies on any device */
    atrbvh_device_close(dev);
    /* "0" and empty read as unset (as ATRBVH_NO_AVX2) */
    dev = open_mode("0", "launches_and_waits_per_build");
    ck_assert_ptr_nonnull(dev);
    ck_assert_uint_eq(((const atrbvh_cl_device *)dev->impl)->host_memory,
                      (unsigned)reports_host_memory(dev));
    atrbvh_device_close(dev);
    dev = open_mode("", "launches_and_waits_per_build");
    ck_assert_ptr_nonnull(dev);
    ck_assert_uint_eq(((const atrbvh_cl_device *)dev->impl)->host_memory,
                      (unsigned)reports_host_memory(dev));
    atrbvh_device_close(dev);
}
END_TEST

/* `bytes` of src in fresh pages that end where the copy ends, made
 * read-only, with an inaccessible page after them: a write into the copy,
 * or a read past its end, is a segmentation fault.  *base and *len: the
 * mapping, for munmap. */
static void *guarded_copy(const void *src, size_t bytes, void **base,
                          size_t *len)
{
    size_t page = (size_t)sysconf(_SC_PAGESIZE);
    size_t data = (bytes + page - 1) / page * page;
    int fd = open("/dev/zero", O_RDWR); /* (MAP_ANONYMOUS is not C99's POSIX) */
    char *m;
    ck_assert_int_ge(fd, 0);
    *len = data + page;
    m = mmap(NULL, *len, PROT_READ | PROT_WRITE, MAP_PRIVATE, fd, 0);
    close(fd);
    ck_assert(m != MAP_FAILED);
    memcpy(m + data - bytes, src, bytes);
    ck_assert_int_eq(mprotect(m, data, PROT_READ), 0);
    ck_assert_int_eq(mprotect(m + data, page, PROT_NONE), 0);
    *base = m;
    return m + data - bytes;
}

/* The same trees whether a build reads the caller's geometry and writes
 * the output in place or copies them (ATRBVH_CL_COPY), and the CPU's:
 * unindexed and indexed triangles with padded vertices (16 bytes apart,
 * the last vertex's padding absent) and boxes 32 bytes apart, LBVH and
 * ATRBVH(9, 2), each geometry array alone in read-only pages with an
 * inaccessible page right after its last byte (cl/stages.c wraps them
 * read-only and sized exactly). */
START_TEST(in_place_and_copied_agree)
{
    atrbvh_device *dev[2];
    unsigned n = 6000, k, d, m;
    float *v = tu_random_triangles(n, 11, 3.0f, 1.0f), *pad, *boxes;
    uint32_t *idx;
    const float *rv, *rb;
    const uint32_t *ri;
    void *base[3];
    size_t len[3], vbytes, ibytes, bbytes;
    atrbvh_geometry g[3];
    dev[0] = open_mode(NULL, "in_place_and_copied_agree");
    if (!dev[0]) {
        free(v);
        return;
    }
    dev[1] = open_mode("1", "in_place_and_copied_agree");
    ck_assert_ptr_nonnull(dev[1]);
    /* vertices 4 floats apart; the last one's fourth float is not part of
     * the array the geometry describes */
    pad = malloc(12 * (size_t)n * sizeof *pad);
    boxes = malloc(8 * (size_t)n * sizeof *boxes);
    idx = malloc(3 * (size_t)n * sizeof *idx);
    ck_assert(pad && boxes && idx);
    for (k = 0; k < 3 * n; k++) {
        memcpy(pad + 4 * k, v + 3 * k, 3 * sizeof *v);
        pad[4 * k + 3] = -1.0f;
        idx[k] = 3 * n - 1 - k; /* backwards */
    }
    for (k = 0; k < n; k++) {
        const float *t = v + 9 * k;
        for (d = 0; d < 3; d++) {
            float lo = t[d], hi = t[d];
            for (m = 1; m < 3; m++) {
                lo = t[3 * m + d] < lo ? t[3 * m + d] : lo;
                hi = t[3 * m + d] > hi ? t[3 * m + d] : hi;
            }
            boxes[8 * k + d] = lo;
            boxes[8 * k + 3 + d] = hi;
        }
        boxes[8 * k + 6] = boxes[8 * k + 7] = 0.0f;
    }
    vbytes = (12 * (size_t)n - 1) * sizeof *pad;
    ibytes = 3 * (size_t)n * sizeof *idx;
    bbytes = (8 * (size_t)n - 2) * sizeof *boxes;
    rv = guarded_copy(pad, vbytes, &base[0], &len[0]);
    ri = guarded_copy(idx, ibytes, &base[1], &len[1]);
    rb = guarded_copy(boxes, bbytes, &base[2], &len[2]);
    g[0] = atrbvh_geometry_triangles(rv, 3 * n, NULL, n);
    g[0].vertex_stride = 4 * sizeof(float);
    g[1] = atrbvh_geometry_triangles(rv, 3 * n, ri, n);
    g[1].vertex_stride = 4 * sizeof(float);
    g[2] = atrbvh_geometry_boxes(rb, n);
    g[2].box_stride = 8 * sizeof(float);
    for (k = 0; k < 3; k++)
        for (d = 0; d < 2; d++) {
            const atrbvh_cl_device *c;
            c = device_build(dev[d], &g[k], ATRBVH_METHOD_LBVH, 9, 2);
            ck_assert_uint_eq(c->n_wraps, c->host_memory ? 3u + (k == 1) : 0u);
            if (c->host_memory) /* the wraps are gone */
                ck_assert(!c->buf[B_GEOMETRY] && !c->buf[B_OUT_NODES]);
            c = device_build(dev[d], &g[k], ATRBVH_METHOD_ATRBVH, 9, 2);
            ck_assert_uint_eq(c->n_wraps, c->host_memory ? 3u + (k == 1) : 0u);
        }
    for (k = 0; k < 3; k++)
        ck_assert_int_eq(munmap(base[k], len[k]), 0);
    free(idx);
    free(boxes);
    free(pad);
    free(v);
    atrbvh_device_close(dev[0]);
    atrbvh_device_close(dev[1]);
}
END_TEST

/* The program text (cl/source.c): shared/treelet_arrays.inc, which
 * shared/treelet.h includes twice (its private and scratch instances),
 * stands in the text twice, each time where treelet.h includes it and
 * nowhere else, followed by a #line that names treelet.h's next line; no
 * include line is left.  The line numbers are checked against the text
 * itself: treelet.h's lines before each insertion, counted from its
 * #line, must be the ones the #line after it skips. */
START_TEST(program_text_takes_inc_where_included)
{
    static const char inc[] = "#line 1 \"treelet_arrays.inc\"\n";
    static const char head[] = "#line 1 \"treelet.h\"\n";
    char *src = atrbvh_i_cl_source();
    const char *p, *from;
    unsigned long next = 1, lines, back;
    int sites = 0;
    ck_assert_ptr_nonnull(src);
    for (p = src; *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : p + strlen(p))
        ck_assert_msg(strncmp(p, "#include \"", 10) != 0,
                      "an include line is left in the program text");
    from = strstr(src, head);
    ck_assert_ptr_nonnull(from);
    from += sizeof head - 1;
    while ((p = strstr(from, inc)) != NULL) {
        const char *q = from;
        sites++;
        /* treelet.h's lines before this site, from the last #line */
        for (lines = 0; q < p; q++)
            lines += *q == '\n';
        /* the include line itself is replaced: the #line after the
         * inserted text names the line after it */
        q = strstr(p + sizeof inc - 1, "#line ");
        ck_assert_ptr_nonnull(q);
        ck_assert_int_eq(sscanf(q, "#line %lu \"treelet.h\"", &back), 1);
        ck_assert_uint_eq(back, next + lines + 1);
        /* the inserted text is the template's */
        ck_assert(strstr(p, "ATRBVH_TA_FN(atrbvh_topo_write)") < q);
        next = back;
        from = strchr(q, '\n') + 1;
    }
    ck_assert_int_eq(sites, 2);
    /* and nowhere else (not at its own place in the file list) */
    for (sites = 0, p = src; (p = strstr(p, inc)) != NULL; p++)
        sites++;
    ck_assert_int_eq(sites, 2);
    atrbvh_i_free(src);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("clreuse");
    TCase *tc = tcase_create("buffers");
    tcase_add_test(tc, second_build_creates_no_buffer);
    tcase_add_test(tc, skip_marks_on_the_device);
    tcase_add_test(tc, several_treelets_an_item_on_a_cpu_device);
    tcase_add_test(tc, launches_and_waits_per_build);
    tcase_add_test(tc, in_place_and_copied_agree);
    tcase_add_test(tc, program_text_takes_inc_where_included);
    tcase_set_timeout(tc, 300);
    suite_add_tcase(s, tc);
    return tu_run(s);
}
