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
    if (st == ATRBVH_ERR_UNSUPPORTED) {
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

int main(void)
{
    Suite *s = suite_create("clreuse");
    TCase *tc = tcase_create("buffers");
    tcase_add_test(tc, second_build_creates_no_buffer);
    tcase_set_timeout(tc, 300);
    suite_add_tcase(s, tc);
    return tu_run(s);
}
