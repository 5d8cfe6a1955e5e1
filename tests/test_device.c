/*
 * test_device.c - the pipeline's public surface beyond one build: device
 * handles (open, reuse, close, threads), scratch reuse on an open handle,
 * allocation failure through open/build/build/close, progress and
 * cancellation, and the structs that can grow (stats by size, geometry
 * size field).  CPU devices here; tests/test_opencl.c covers OpenCL ones.
 */
#include "config.h" /* ATRBVH_DEBUG_CHECKS */

#include <check.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atrbvh.h"
#include "scene.h"
#include "testutil.h"

enum { T = 4000 };

static atrbvh_geometry soup(float **v, size_t n, uint64_t seed)
{
    *v = tu_random_triangles(n, seed, 1.0f, 0.0f);
    return atrbvh_geometry_triangles(*v, 3 * n, NULL, n);
}

/* The scene's vertices into dst (3 floats each), moved by dx along x. */
static void move_along_x(float *dst, const scene *sc, float dx)
{
    size_t i;
    for (i = 0; i < sc->vertex_count * 3; i++)
        dst[i] = sc->vertices[i] + (i % 3 == 0 ? dx : 0.0f);
}

START_TEST(open_specs)
{
    atrbvh_device *d = NULL;
    atrbvh_error e;
    ck_assert_int_eq(atrbvh_device_open("cpu", &d, &e), ATRBVH_OK);
    ck_assert_ptr_nonnull(d);
    ck_assert_str_eq(atrbvh_device_name(d), "cpu");
    ck_assert_int_eq(atrbvh_device_backend(d), ATRBVH_BACKEND_CPU);
    atrbvh_device_close(d);
    ck_assert_int_eq(atrbvh_device_open(NULL, &d, &e), ATRBVH_OK);
    ck_assert_str_eq(atrbvh_device_name(d), "cpu");
    atrbvh_device_close(d);
    atrbvh_device_close(NULL);

    d = (atrbvh_device *)&e; /* must be reset to NULL on failure */
    ck_assert_int_eq(atrbvh_device_open("gpu", &d, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_null(d);
    ck_assert_msg(strstr(e.text, "\"gpu\""), "%s", e.text);
    ck_assert_int_eq(atrbvh_device_open("openclx", &d, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_device_open("cpu", NULL, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    /* A name that matches nothing: no such device (or no OpenCL). */
    {
        atrbvh_status st = atrbvh_device_open(
            "opencl:no such device, surely", &d, &e);
        ck_assert_msg(st == ATRBVH_ERR_INVALID_ARGUMENT ||
                          st == ATRBVH_ERR_UNSUPPORTED,
                      "%s", e.text);
        ck_assert_ptr_null(d);
    }
}
END_TEST

/* Builds on one open device give the trees builds without one give, and a
 * second build of the same size allocates no scratch but the node box
 * array (2n-1 boxes, released before every output so that the handle does
 * not hold it beside the output): the output (node and index arrays, the
 * object), the statistics pass's depths (a 32-bit array per node; at most
 * three counted) and that array, plus small fixed-size state. */
START_TEST(reuse_allocates_no_scratch)
{
    float *v;
    atrbvh_geometry g = soup(&v, T, 3);
    atrbvh_build_options o;
    atrbvh_device *d;
    atrbvh_bvh *ref, *a, *b;
    atrbvh_error e;
    char msg[256];
    size_t nodes, prims, first_bytes, output;
    atrbvh_build_options_init(&o);
    o.max_leaf_size = 8;
    o.threads = 2;
    ref = tu_build(&g, &o);
    ck_assert_int_eq(atrbvh_device_open("cpu", &d, &e), ATRBVH_OK);
    o.device = d;
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    tu_alloc.total_bytes = 0;
    ck_assert_int_eq(atrbvh_build(&g, &o, &a, &e), ATRBVH_OK);
    first_bytes = tu_alloc.total_bytes;
    tu_alloc.total_bytes = 0;
    ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_OK);
    atrbvh_set_allocator(NULL, NULL);
    ck_assert_msg(tu_same_bvh(ref, a, msg, sizeof msg), "%s", msg);
    ck_assert_msg(tu_same_bvh(ref, b, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_nodes(b, &nodes);
    atrbvh_bvh_primitive_indices(b, &prims);
    output = nodes * (sizeof(atrbvh_node) + 12) + prims * 4 + 4096 +
             (2 * (size_t)T - 1) * sizeof(float) * 6;
    /* The first build made the scratch: keys, boxes, the binary tree. */
    ck_assert_uint_gt(first_bytes, tu_alloc.total_bytes + (size_t)T * 30);
    ck_assert_msg(tu_alloc.total_bytes <= output,
                  "second build allocated %lu bytes (output, walk and node "
                  "boxes %lu)",
                  (unsigned long)tu_alloc.total_bytes, (unsigned long)output);
    atrbvh_bvh_free(a);
    atrbvh_bvh_free(b);
    atrbvh_bvh_free(ref);
    atrbvh_device_close(d);
    free(v);
}
END_TEST

/* An LBVH that reads its leaf boxes in place hands its node box slot's
 * block to the output as its nodes (lib/cpu/collapse.c): the output then
 * owns it and the handle does not.  Three builds on one handle, all kept,
 * of the sphere moved by 0, 4 and 8 along x (the same tree shape, other
 * boxes), each the tree a build without a handle gives, also after the
 * later builds (which would have written their boxes into an earlier
 * output left in the handle's slot) and after the handle is closed
 * (which would have freed it). */
START_TEST(lbvh_outputs_own_their_nodes)
{
    scene sc;
    char err[256], msg[256];
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_device *d;
    atrbvh_error e;
    atrbvh_bvh *ref[3], *out[3];
    float *moved[3];
    int k, j;
    ck_assert_int_eq(scene_builtin("sphere", 20000, &sc, err, sizeof err), 0);
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    o.max_leaf_size = 8;
    o.threads = 2;
    for (k = 0; k < 3; k++) {
        moved[k] = malloc(sc.vertex_count * 3 * sizeof *moved[k]);
        ck_assert_ptr_nonnull(moved[k]);
        move_along_x(moved[k], &sc, 4.0f * (float)k);
        g = atrbvh_geometry_triangles(moved[k], sc.vertex_count, sc.indices,
                                      sc.triangle_count);
        ref[k] = tu_build(&g, &o);
    }
    ck_assert_int_eq(atrbvh_device_open("cpu", &d, &e), ATRBVH_OK);
    o.device = d;
    for (k = 0; k < 3; k++) {
        g = atrbvh_geometry_triangles(moved[k], sc.vertex_count, sc.indices,
                                      sc.triangle_count);
        ck_assert_int_eq(atrbvh_build(&g, &o, &out[k], &e), ATRBVH_OK);
        for (j = 0; j <= k; j++)
            ck_assert_msg(tu_same_bvh(ref[j], out[j], msg, sizeof msg),
                          "build %d after build %d: %s", j, k, msg);
    }
    atrbvh_device_close(d);
    for (k = 0; k < 3; k++) {
        ck_assert_msg(tu_same_bvh(ref[k], out[k], msg, sizeof msg),
                      "build %d after the close: %s", k, msg);
        atrbvh_bvh_free(out[k]);
        atrbvh_bvh_free(ref[k]);
        free(moved[k]);
    }
    scene_free(&sc);
}
END_TEST

/* A handle learns how many nodes its LBVH outputs have per primitive
 * (lib/cpu/backend.c's plan).  With leaves of up to 8 primitives an
 * output has about n nodes; with leaves of one, 2n - 1.  After a build of
 * the first kind, a handle's node box slot has room for n nodes, so the
 * next build, of the second kind, allocates its output's nodes apart;
 * from then on the slot has room for 2n - 1 and the output takes its
 * block: one allocation fewer, some 32 bytes per primitive less.  Each
 * tree is the one a build without a handle gives. */
START_TEST(lbvh_handle_learns_node_count)
{
    scene sc;
    char err[256], msg[256];
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_device *d;
    atrbvh_error e;
    atrbvh_bvh *ref, *b;
    long allocs[4];
    size_t bytes[4];
    int k;
    ck_assert_int_eq(scene_builtin("sphere", 20000, &sc, err, sizeof err), 0);
    g = scene_geometry(&sc);
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    o.max_leaf_size = 1;
    o.threads = 2;
    ref = tu_build(&g, &o);
    ck_assert_int_eq(atrbvh_device_open("cpu", &d, &e), ATRBVH_OK);
    o.device = d;
    for (k = 0; k < 4; k++) {
        o.max_leaf_size = k ? 1 : 8;
        atrbvh_set_allocator(tu_count_malloc, tu_count_free);
        tu_count_reset(-1);
        ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_OK);
        atrbvh_set_allocator(NULL, NULL);
        allocs[k] = tu_alloc.allocations;
        bytes[k] = tu_alloc.total_bytes;
        if (k)
            ck_assert_msg(tu_same_bvh(ref, b, msg, sizeof msg),
                          "build %d: %s", k, msg);
        atrbvh_bvh_free(b);
    }
    atrbvh_device_close(d);
    ck_assert_msg(allocs[2] == allocs[1] - 1 && allocs[3] == allocs[2],
                  "allocations per build %ld, %ld, %ld", allocs[1],
                  allocs[2], allocs[3]);
    ck_assert_msg(bytes[2] + 16 * (size_t)sc.triangle_count <= bytes[1] &&
                      bytes[3] == bytes[2],
                  "bytes allocated per build %lu, %lu, %lu",
                  (unsigned long)bytes[1], (unsigned long)bytes[2],
                  (unsigned long)bytes[3]);
    atrbvh_bvh_free(ref);
    scene_free(&sc);
}
END_TEST

/* Every allocation of open, build, build (larger), close fails in turn:
 * each failure is ATRBVH_ERR_NOMEM, and nothing leaks once the handle is
 * closed. */
START_TEST(allocation_failure_open_build_close)
{
    /* _i: 0 the CPU, 1 an OpenCL device (skipped without one) */
    const char *spec = _i ? "opencl" : "cpu";
    float *v1, *v2;
    atrbvh_geometry g1 = soup(&v1, 500, 5), g2 = soup(&v2, 2000, 6);
    atrbvh_build_options o;
    long k;
    int done = 0;
    atrbvh_build_options_init(&o);
    o.threads = 2;
    if (_i) {
        atrbvh_device *probe = NULL;
        atrbvh_error e;
        if (atrbvh_device_open(spec, &probe, &e) != ATRBVH_OK) {
            fprintf(stderr, "SKIP allocation failure on OpenCL: %s\n",
                    e.text);
            free(v1);
            free(v2);
            return;
        }
        atrbvh_device_close(probe);
    }
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    for (k = 0; !done; k++) {
        atrbvh_device *d = NULL;
        atrbvh_bvh *b = NULL;
        atrbvh_error e;
        atrbvh_status st;
        tu_count_reset(k);
        st = atrbvh_device_open(spec, &d, &e);
        if (st == ATRBVH_OK) {
            o.device = d;
            st = atrbvh_build(&g1, &o, &b, &e);
            atrbvh_bvh_free(b);
            b = NULL;
            if (st == ATRBVH_OK) /* larger: the scratch grows */
                st = atrbvh_build(&g2, &o, &b, &e);
            atrbvh_bvh_free(b);
            b = NULL;
            if (st == ATRBVH_OK) /* smaller again: reuses it */
                st = atrbvh_build(&g1, &o, &b, &e);
            atrbvh_bvh_free(b);
            atrbvh_device_close(d);
        } else {
            ck_assert_ptr_null(d);
        }
        tu_alloc.countdown = -1;
        ck_assert_msg(tu_alloc.outstanding == 0,
                      "allocation %ld: %ld blocks leaked", k,
                      tu_alloc.outstanding);
        if (st == ATRBVH_OK)
            done = 1;
        else
            ck_assert_msg(st == ATRBVH_ERR_NOMEM, "allocation %ld: %s", k,
                          atrbvh_strerror(st));
    }
    ck_assert_int_gt(k, 10);
    atrbvh_set_allocator(NULL, NULL);
    free(v1);
    free(v2);
}
END_TEST

/* ------------------------------------------------------- peak memory */
/* A size-tracking allocator: bytes held now and the peak since reset. */
static size_t held, peak;
typedef union sized {
    size_t size;
    long double align_ld;
    void *align_p;
} sized;
static void *sized_malloc(size_t n)
{
    sized *h;
    if (tu_alloc.countdown == 0)
        return NULL;
    if (tu_alloc.countdown > 0)
        tu_alloc.countdown--;
    h = malloc(sizeof *h + n);
    if (!h)
        return NULL;
    h->size = n;
    tu_alloc.outstanding++;
    tu_alloc.allocations++;
    tu_alloc.total_bytes += n;
    held += n;
    if (held > peak)
        peak = held;
    return h + 1;
}
static void sized_free(void *p)
{
    sized *h;
    if (!p)
        return;
    h = (sized *)p - 1;
    held -= h->size;
    tu_alloc.outstanding--;
    free(h);
}

/* The output's bytes: its node and primitive index arrays. */
static double output_bytes(const atrbvh_bvh *b)
{
    size_t nodes, prims;
    atrbvh_bvh_nodes(b, &nodes);
    atrbvh_bvh_primitive_indices(b, &prims);
    return (double)nodes * sizeof(atrbvh_node) + (double)prims * 4;
}

/* The LBVH of a built-in scene (max leaf 8, as `atrbvh bench` builds it)
 * holds at its peak at most 80 bytes per triangle and 2.2 times the
 * output (node and index arrays), without a handle, on a handle's first
 * build (which makes its scratch) and on its second; a handle keeps no
 * more than 40 bytes per triangle between builds.  Before the memory plan
 * (lib/cpu/backend.c) these were about 150 and 200 bytes per triangle, 4
 * and 5 times the output, and a handle kept 148; before an LBVH read its
 * leaf boxes in place (lib/cpu/hierarchy.c) its node box slot held 2n-1
 * boxes, 84 bytes per triangle and more at the peak (now 68-70 without a
 * handle, whose node box slot has room for the output's nodes, 71-78 on
 * one, 1.7-2.05 times the output). */
START_TEST(peak_memory_lbvh)
{
    /* _i: 0 sphere, 1 city, 2 terrain */
    static const char *const names[] = {"sphere", "city", "terrain"};
    scene sc;
    char err[256];
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_device *d;
    atrbvh_error e;
    size_t base;
    int k;
    ck_assert_int_eq(scene_builtin(names[_i], 60000, &sc, err, sizeof err), 0);
    g = scene_geometry(&sc);
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    o.max_leaf_size = 8;
    o.threads = 2;
    atrbvh_set_allocator(sized_malloc, sized_free);
    tu_alloc.outstanding = 0;
    base = held;
    ck_assert_int_eq(atrbvh_device_open("cpu", &d, &e), ATRBVH_OK);
    for (k = 0; k < 3; k++) { /* no handle, first and second on one */
        const double tris = (double)sc.triangle_count;
        size_t before = held;
        double out_bytes, build_peak, kept, check = 0.0;
        atrbvh_bvh *b = NULL;
        o.device = k ? d : NULL;
        peak = held;
        ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_OK);
        out_bytes = output_bytes(b);
#ifdef ATRBVH_DEBUG_CHECKS
        {   /* --enable-debug-checks: the tree check after the build holds
             * its scratch beside the output (lib/check.c: 12 bytes a
             * node, 4 a primitive) */
            size_t nodes;
            atrbvh_bvh_nodes(b, &nodes);
            check = 12.0 * (double)nodes + 4.0 * tris;
        }
#endif
        /* from before the handle's first build: its scratch counts */
        build_peak = (double)(peak - base);
        kept = (double)held - (double)before - out_bytes;
        ck_assert_msg(build_peak <= 80.0 * tris + check &&
                          build_peak <= 2.2 * out_bytes + check,
                      "%s, build %d: peak %.1f bytes per triangle, %.2f "
                      "times the output",
                      names[_i], k, build_peak / tris, build_peak / out_bytes);
        if (k == 1)
            ck_assert_msg(kept <= 40.0 * tris + 65536.0,
                          "%s: the handle keeps %.1f bytes per triangle",
                          names[_i], kept / tris);
        atrbvh_bvh_free(b);
    }
    atrbvh_device_close(d);
    atrbvh_set_allocator(NULL, NULL);
    ck_assert_int_eq(tu_alloc.outstanding, 0);
    scene_free(&sc);
}
END_TEST

/* An optimised tree built without a handle holds at its peak, the layout,
 * no more than its tree (left, right, count and leaf primitives: 20 bytes
 * per triangle), its node boxes (2n-1 of them, 48; the collapse sizes in
 * the leaves' half) and the output, plus the collapse's and the layout's
 * frontier lists.  The optimise stage's treelet scratch, marks and lists
 * (about 5 bytes per triangle) are freed when it ends (lib/cpu/
 * optimise.c), the cost slot at the collapse, and, with collapsed leaves
 * of at most ATRBVH_I_GATHER_MAX primitives (max leaf 8 here), the parent
 * links after it (8 bytes: collapse.c, layout.c's gather).  (Both stayed
 * to the end of the build until 6 December: 114-119 bytes per triangle
 * at the peak on the sphere, bunny and dragon, now 101-105.) */
START_TEST(peak_memory_optimised)
{
    /* _i: 0 sphere, 1 city, 2 terrain */
    static const char *const names[] = {"sphere", "city", "terrain"};
    static const struct {
        atrbvh_method method;
        unsigned size, rounds;
    } cfg[] = {{ATRBVH_METHOD_ATRBVH, 9, 2},
               {ATRBVH_METHOD_TRBVH, 7, 3},
               {ATRBVH_METHOD_ATRBVH, ATRBVH_TREELET_AUTO, 4},
               {ATRBVH_METHOD_ATRBVH, 48, 2}};
    scene sc;
    char err[256];
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_error e;
    unsigned k;
    ck_assert_int_eq(scene_builtin(names[_i], 60000, &sc, err, sizeof err), 0);
    g = scene_geometry(&sc);
    atrbvh_set_allocator(sized_malloc, sized_free);
    tu_alloc.outstanding = 0;
    for (k = 0; k < sizeof cfg / sizeof cfg[0]; k++) {
        const double tris = (double)sc.triangle_count;
        size_t before = held;
        double out_bytes, build_peak, tree_boxes;
        atrbvh_bvh *b = NULL;
        atrbvh_build_options_init(&o);
        o.method = cfg[k].method;
        o.treelet_size = cfg[k].size;
        o.rounds = cfg[k].rounds;
        o.max_leaf_size = 8;
        o.threads = 2;
        peak = held;
        ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_OK);
        out_bytes = output_bytes(b);
        build_peak = (double)(peak - before);
        tree_boxes = 68.0 * tris;
        ck_assert_msg(build_peak <= tree_boxes + out_bytes + 65536.0,
                      "%s, configuration %u: peak %.1f bytes per triangle, "
                      "the tree, boxes and output %.1f",
                      names[_i], k, build_peak / tris,
                      (tree_boxes + out_bytes) / tris);
        atrbvh_bvh_free(b);
    }
    atrbvh_set_allocator(NULL, NULL);
    ck_assert_int_eq(tu_alloc.outstanding, 0);
    scene_free(&sc);
}
END_TEST

/* A build without a handle finds a collapsed leaf's primitives by the
 * counts, its parent links released (lib/cpu/layout.c, collapse.c: max
 * leaf at most ATRBVH_I_GATHER_MAX); a handle keeps the links and walks
 * them.  Both give the same tree, with leaves of up to 64 primitives (an
 * internal node cost of 100 makes the collapse take leaves as large as
 * max leaf allows: the largest has 64) and at the other limits (max leaf
 * 65 and none: both walk the links). */
START_TEST(large_leaves_gathered_alike)
{
    static const unsigned max_leaf[] = {64, 65, 0, 8};
    scene sc;
    char err[256], msg[256];
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_device *d;
    atrbvh_error e;
    unsigned k;
    ck_assert_int_eq(scene_builtin("city", 20000, &sc, err, sizeof err), 0);
    g = scene_geometry(&sc);
    ck_assert_int_eq(atrbvh_device_open("cpu", &d, &e), ATRBVH_OK);
    for (k = 0; k < sizeof max_leaf / sizeof max_leaf[0]; k++) {
        atrbvh_bvh *alone = NULL, *kept = NULL;
        const atrbvh_node *node;
        size_t nodes, i;
        uint32_t largest = 0;
        atrbvh_build_options_init(&o);
        o.method = ATRBVH_METHOD_ATRBVH;
        o.ci = 100.0;
        o.max_leaf_size = max_leaf[k];
        o.threads = 2;
        ck_assert_int_eq(atrbvh_build(&g, &o, &alone, &e), ATRBVH_OK);
        o.device = d;
        ck_assert_int_eq(atrbvh_build(&g, &o, &kept, &e), ATRBVH_OK);
        ck_assert_msg(tu_same_bvh(alone, kept, msg, sizeof msg),
                      "max leaf %u: %s", max_leaf[k], msg);
        node = atrbvh_bvh_nodes(alone, &nodes);
        for (i = 0; i < nodes; i++)
            if (node[i].count > largest)
                largest = node[i].count;
        if (max_leaf[k] == 64)
            ck_assert_uint_eq(largest, 64);
        atrbvh_bvh_free(alone);
        atrbvh_bvh_free(kept);
    }
    atrbvh_device_close(d);
    scene_free(&sc);
}
END_TEST

/* Every allocation of LBVH builds (the node box array released before the
 * output and made again, the statistics pass) and of a build leaving out
 * invalid triangles (leaf primitives and kept ids in their own slots, the
 * node boxes kept to the layout) fails in turn, on a handle (growing,
 * then shrinking) and without one: ATRBVH_ERR_NOMEM, and nothing leaks. */
START_TEST(allocation_failure_lbvh_and_invalid)
{
    float *v1, *v2;
    atrbvh_geometry g1 = soup(&v1, 700, 11), g2 = soup(&v2, 2500, 12);
    atrbvh_build_options o;
    long k;
    int done = 0;
    v2[3 * 3 * 17 + 1] = 1.0f / 0.0f; /* triangle 17 invalid */
    atrbvh_build_options_init(&o);
    o.method = _i ? ATRBVH_METHOD_ATRBVH : ATRBVH_METHOD_LBVH;
    o.max_leaf_size = 8;
    o.skip_invalid = 1;
    o.threads = 2;
    atrbvh_set_allocator(sized_malloc, sized_free);
    for (k = 0; !done; k++) {
        atrbvh_device *d = NULL;
        atrbvh_bvh *b = NULL;
        atrbvh_error e;
        atrbvh_status st;
        tu_count_reset(k);
        o.device = NULL;
        st = atrbvh_build(&g1, &o, &b, &e);
        atrbvh_bvh_free(b);
        b = NULL;
        if (st == ATRBVH_OK)
            st = atrbvh_device_open("cpu", &d, &e);
        if (st == ATRBVH_OK) {
            o.device = d;
            st = atrbvh_build(&g1, &o, &b, &e);
            atrbvh_bvh_free(b);
            b = NULL;
            if (st == ATRBVH_OK)
                st = atrbvh_build(&g2, &o, &b, &e);
            atrbvh_bvh_free(b);
            b = NULL;
            if (st == ATRBVH_OK)
                st = atrbvh_build(&g1, &o, &b, &e);
            atrbvh_bvh_free(b);
            atrbvh_device_close(d);
        }
        tu_alloc.countdown = -1;
        ck_assert_msg(tu_alloc.outstanding == 0,
                      "allocation %ld: %ld blocks leaked", k,
                      tu_alloc.outstanding);
        if (st == ATRBVH_OK)
            done = 1;
        else
            ck_assert_msg(st == ATRBVH_ERR_NOMEM, "allocation %ld: %s", k,
                          atrbvh_strerror(st));
    }
    ck_assert_int_gt(k, 20);
    atrbvh_set_allocator(NULL, NULL);
    free(v1);
    free(v2);
}
END_TEST

/* ------------------------------------------------------------ rebuild */
/* atrbvh_rebuild gives the tree atrbvh_build gives, frame after frame (the
 * sphere moved by 0, 4, 8 and 12 along x), and needs fewer new bytes: its
 * primitive indices go in the old tree's index array, and an LBVH's nodes
 * in the old tree's node array, through the node box slot that the bounds
 * stage writes (lib/cpu/backend.c's begin, collapse.c), as do an
 * optimised tree's on a handle (straight to the output).  Each frame is
 * built twice on its own handle (or twice without one): freed then built,
 * and rebuilt into the last frame's tree; the second allocates at least
 * those arrays' bytes less.  Without a handle its peak, above what was
 * held before less the old tree, is at most the old index array above the
 * first's: an optimised tree's node boxes need more than the old nodes,
 * which are freed at once, not held to the output.  On a handle, from the
 * second frame on, the rebuild's peak above all that was held (old tree
 * and scratch) is the build's less the arrays it reuses, within a few
 * hundred bytes. */
START_TEST(rebuild_same_tree_fewer_bytes)
{
    /* _i: 0 LBVH without a handle, 1 on one, 2 ATRBVH(9,2) without, 3 on
     * one */
    const int lbvh = _i < 2, handle = _i % 2;
    scene sc;
    char err[256], msg[256];
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_device *d[2] = {NULL, NULL};
    atrbvh_error e;
    atrbvh_bvh *plain = NULL, *re = NULL;
    float *moved;
    size_t re_tree = 0; /* what `re` holds (without a handle) */
    int k;
    ck_assert_int_eq(scene_builtin("sphere", 20000, &sc, err, sizeof err), 0);
    moved = malloc(sc.vertex_count * 3 * sizeof *moved);
    ck_assert_ptr_nonnull(moved);
    atrbvh_build_options_init(&o);
    o.method = lbvh ? ATRBVH_METHOD_LBVH : ATRBVH_METHOD_ATRBVH;
    o.max_leaf_size = 8;
    o.threads = 2;
    atrbvh_set_allocator(sized_malloc, sized_free);
    tu_alloc.outstanding = 0;
    if (handle) {
        ck_assert_int_eq(atrbvh_device_open("cpu", &d[0], &e), ATRBVH_OK);
        ck_assert_int_eq(atrbvh_device_open("cpu", &d[1], &e), ATRBVH_OK);
    }
    for (k = 0; k < 4; k++) {
        size_t plain_bytes, re_bytes, nodes, prims, reused, before;
        size_t plain_peak, re_peak, held_at_call, re_extra;
        atrbvh_bvh *ref;
        move_along_x(moved, &sc, 4.0f * (float)k);
        g = atrbvh_geometry_triangles(moved, sc.vertex_count, sc.indices,
                                      sc.triangle_count);
        o.device = NULL;
        ref = tu_build(&g, &o);
        /* what the last frame's tree will give back */
        atrbvh_bvh_nodes(re, &nodes);
        atrbvh_bvh_primitive_indices(re, &prims);
        reused = prims * sizeof(uint32_t) +
                 (lbvh || handle ? nodes * sizeof(atrbvh_node) : 0);
        atrbvh_bvh_free(plain);
        tu_alloc.total_bytes = 0;
        o.device = d[0];
        before = held;
        peak = held;
        ck_assert_int_eq(atrbvh_build(&g, &o, &plain, &e), ATRBVH_OK);
        plain_bytes = tu_alloc.total_bytes;
        plain_peak = peak - before;
        tu_alloc.total_bytes = 0;
        o.device = d[1];
        before = held - re_tree;
        peak = held;
        held_at_call = held;
        ck_assert_int_eq(atrbvh_rebuild(&g, &o, &re, &e), ATRBVH_OK);
        re_bytes = tu_alloc.total_bytes;
        re_extra = peak - held_at_call;
        re_peak = peak - before;
        re_tree = held - before;
        ck_assert_msg(tu_same_bvh(ref, plain, msg, sizeof msg),
                      "frame %d, built: %s", k, msg);
        ck_assert_msg(tu_same_bvh(ref, re, msg, sizeof msg),
                      "frame %d, rebuilt: %s", k, msg);
        ck_assert_msg(re_bytes + reused <= plain_bytes,
                      "frame %d: built with %lu bytes, rebuilt with %lu, "
                      "the old tree's arrays that were to be reused %lu",
                      k, (unsigned long)plain_bytes, (unsigned long)re_bytes,
                      (unsigned long)reused);
        if (!handle)
            ck_assert_msg(re_peak <= plain_peak + prims * sizeof(uint32_t),
                          "frame %d: peak %lu bytes built, %lu rebuilt", k,
                          (unsigned long)plain_peak, (unsigned long)re_peak);
        /* On a handle from the second frame on (its scratch held by
         * then), a build allocates its output and a rebuild the output
         * less the old arrays it takes: above all that was held, the old
         * tree included, at most a build's peak less those arrays, give
         * or take the BVH's own record (a few hundred bytes whatever the
         * scene; 20000 triangles' arrays are 0.67 MB) */
        if (handle && k > 0)
            ck_assert_msg(re_extra + reused <= plain_peak + 4096,
                          "frame %d on a handle: built with %lu bytes above "
                          "what was held, rebuilt with %lu, reusing %lu",
                          k, (unsigned long)plain_peak,
                          (unsigned long)re_extra, (unsigned long)reused);
        atrbvh_bvh_free(ref);
    }
    atrbvh_bvh_free(plain);
    atrbvh_bvh_free(re);
    atrbvh_device_close(d[0]);
    atrbvh_device_close(d[1]);
    atrbvh_set_allocator(NULL, NULL);
    ck_assert_int_eq(tu_alloc.outstanding, 0);
    free(moved);
    scene_free(&sc);
}
END_TEST

/* Frames whose trees have more nodes or fewer (random soups of T
 * triangles, one seed a frame, ATRBVH(9,2) on a handle): a rebuild whose
 * old node array is too small allocates one with room for an eighth
 * more nodes, and the rebuilds whose trees fit in it allocate no node
 * array (fewer bytes than half of one); every tree is atrbvh_build's. */
START_TEST(rebuild_leaves_room)
{
    atrbvh_build_options o;
    atrbvh_device *d;
    atrbvh_error e;
    atrbvh_bvh *re = NULL;
    size_t room = 0; /* the node array's entries, as the test expects */
    int k, grew = 0, fit = 0;
    char msg[256];
    atrbvh_build_options_init(&o);
    o.max_leaf_size = 8;
    o.threads = 2;
    atrbvh_set_allocator(sized_malloc, sized_free);
    tu_alloc.outstanding = 0;
    ck_assert_int_eq(atrbvh_device_open("cpu", &d, &e), ATRBVH_OK);
    for (k = 0; k < 12; k++) {
        float *v;
        atrbvh_geometry g = soup(&v, T, 100u + (uint64_t)k);
        atrbvh_bvh *ref;
        size_t nodes, bytes;
        o.device = NULL;
        ref = tu_build(&g, &o);
        o.device = d;
        tu_alloc.total_bytes = 0;
        ck_assert_int_eq(atrbvh_rebuild(&g, &o, &re, &e), ATRBVH_OK);
        bytes = tu_alloc.total_bytes;
        ck_assert_msg(tu_same_bvh(ref, re, msg, sizeof msg), "frame %d: %s",
                      k, msg);
        atrbvh_bvh_nodes(re, &nodes);
        if (k == 0) {
            room = nodes; /* a first build: exactly its nodes */
        } else if (nodes <= room) {
            ck_assert_msg(bytes < nodes * sizeof(atrbvh_node) / 2,
                          "frame %d: %lu nodes in room for %lu, yet %lu "
                          "bytes allocated", k, (unsigned long)nodes,
                          (unsigned long)room, (unsigned long)bytes);
            fit++;
        } else {
            ck_assert_msg(bytes >= (nodes + nodes / 8) * sizeof(atrbvh_node),
                          "frame %d: %lu nodes, more than %lu: %lu bytes "
                          "allocated, not room for an eighth more", k,
                          (unsigned long)nodes, (unsigned long)room,
                          (unsigned long)bytes);
            room = nodes + nodes / 8;
            grew++;
        }
        atrbvh_bvh_free(ref);
        free(v);
    }
    /* (the soups' trees grew at least once, and fitted after) */
    ck_assert_int_gt(grew, 0);
    ck_assert_int_gt(fit, 0);
    atrbvh_bvh_free(re);
    atrbvh_device_close(d);
    atrbvh_set_allocator(NULL, NULL);
    ck_assert_int_eq(tu_alloc.outstanding, 0);
}
END_TEST

/* Boxes read from the old tree's own nodes (a BVH over a BVH's nodes):
 * its arrays are not reused while the build reads them, and the tree is
 * the one built from a copy of those boxes, for an LBVH (whose node box
 * slot would take them) and an ATRBVH. */
START_TEST(rebuild_reads_old_nodes)
{
    float *v;
    atrbvh_geometry g = soup(&v, T, 21), gb;
    atrbvh_build_options o;
    atrbvh_error e;
    atrbvh_bvh *old, *ref;
    const atrbvh_node *nodes;
    atrbvh_node *copy;
    size_t count;
    char msg[256];
    atrbvh_build_options_init(&o);
    o.method = _i ? ATRBVH_METHOD_ATRBVH : ATRBVH_METHOD_LBVH;
    o.max_leaf_size = 1;
    o.threads = 2;
    old = tu_build(&g, &o);
    nodes = atrbvh_bvh_nodes(old, &count);
    copy = malloc(count * sizeof *copy);
    ck_assert_ptr_nonnull(copy);
    memcpy(copy, nodes, count * sizeof *copy);
    gb = atrbvh_geometry_boxes(copy[0].min, count);
    gb.box_stride = sizeof *copy;
    ref = tu_build(&gb, &o);
    gb.boxes = nodes[0].min;
    ck_assert_int_eq(atrbvh_rebuild(&gb, &o, &old, &e), ATRBVH_OK);
    ck_assert_msg(tu_same_bvh(ref, old, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_free(old);
    atrbvh_bvh_free(ref);
    free(copy);
    free(v);
}
END_TEST

/* atrbvh_rebuild frees the old tree whatever it returns: after bad
 * arguments (an option out of range, invalid geometry) *bvh is NULL and
 * nothing leaks; a NULL BVH pointer is an error; *bvh NULL is a plain
 * build.  Then every allocation of rebuilds into a tree of other sizes,
 * with and without a handle, fails in turn: ATRBVH_ERR_NOMEM each time,
 * *bvh NULL, and nothing leaks. */
START_TEST(rebuild_frees_old_on_failure)
{
    float *v1, *v2;
    atrbvh_geometry g1 = soup(&v1, 700, 13), g2 = soup(&v2, 2500, 14), bad;
    atrbvh_build_options o;
    atrbvh_error e;
    atrbvh_bvh *b = NULL, *ref;
    char msg[256];
    long k;
    int done = 0;
    atrbvh_build_options_init(&o);
    o.method = _i ? ATRBVH_METHOD_ATRBVH : ATRBVH_METHOD_LBVH;
    o.max_leaf_size = 8;
    o.threads = 2;
    ref = tu_build(&g2, &o);
    ck_assert_int_eq(atrbvh_rebuild(&g2, &o, NULL, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    atrbvh_set_allocator(sized_malloc, sized_free);
    tu_alloc.outstanding = 0;
    ck_assert_int_eq(atrbvh_rebuild(&g1, &o, &b, &e), ATRBVH_OK);
    o.threads = -1;
    ck_assert_int_eq(atrbvh_rebuild(&g1, &o, &b, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_null(b);
    ck_assert_int_eq(tu_alloc.outstanding, 0);
    o.threads = 2;
    ck_assert_int_eq(atrbvh_rebuild(&g1, &o, &b, &e), ATRBVH_OK);
    bad = g1;
    bad.primitive_count = 0;
    ck_assert_int_eq(atrbvh_rebuild(&bad, &o, &b, &e),
                     ATRBVH_ERR_NO_PRIMITIVES);
    ck_assert_ptr_null(b);
    ck_assert_int_eq(tu_alloc.outstanding, 0);
    for (k = 0; !done; k++) {
        atrbvh_device *d = NULL;
        atrbvh_status st;
        tu_count_reset(k);
        o.device = NULL;
        st = atrbvh_device_open("cpu", &d, &e);
        if (st == ATRBVH_OK)
            st = atrbvh_rebuild(&g1, &o, &b, &e);
        if (st == ATRBVH_OK)
            st = atrbvh_rebuild(&g2, &o, &b, &e);
        if (st == ATRBVH_OK) {
            o.device = d;
            st = atrbvh_rebuild(&g2, &o, &b, &e);
            if (st == ATRBVH_OK)
                st = atrbvh_rebuild(&g1, &o, &b, &e);
            if (st == ATRBVH_OK)
                st = atrbvh_rebuild(&g2, &o, &b, &e);
        }
        if (st == ATRBVH_OK) {
            done = 1;
            ck_assert_msg(tu_same_bvh(ref, b, msg, sizeof msg), "%s", msg);
        } else {
            ck_assert_msg(st == ATRBVH_ERR_NOMEM, "allocation %ld: %s", k,
                          atrbvh_strerror(st));
            ck_assert_ptr_null(b);
        }
        atrbvh_bvh_free(b);
        b = NULL;
        atrbvh_device_close(d);
        tu_alloc.countdown = -1;
        ck_assert_msg(tu_alloc.outstanding == 0,
                      "allocation %ld: %ld blocks leaked", k,
                      tu_alloc.outstanding);
    }
    ck_assert_int_gt(k, 20);
    atrbvh_set_allocator(NULL, NULL);
    atrbvh_bvh_free(ref);
    free(v1);
    free(v2);
}
END_TEST

/* ------------------------------------------------------------- threads */
typedef struct job {
    const atrbvh_geometry *g;
    atrbvh_device *shared; /* NULL: open one's own */
    const atrbvh_bvh *ref;
    int ok;
    char msg[512];
} job;

static void *worker(void *arg)
{
    job *j = arg;
    atrbvh_build_options o;
    atrbvh_device *d = j->shared;
    atrbvh_error e;
    int r;
    j->ok = 0;
    if (!d && atrbvh_device_open("cpu", &d, &e) != ATRBVH_OK) {
        snprintf(j->msg, sizeof j->msg, "open: %s", e.text);
        return NULL;
    }
    atrbvh_build_options_init(&o);
    o.device = d;
    o.threads = 1;
    for (r = 0; r < 3; r++) {
        atrbvh_bvh *b;
        if (atrbvh_build(j->g, &o, &b, &e) != ATRBVH_OK) {
            snprintf(j->msg, sizeof j->msg, "build: %s", e.text);
            break;
        }
        j->ok = tu_same_bvh(j->ref, b, j->msg, sizeof j->msg);
        atrbvh_bvh_free(b);
        if (!j->ok)
            break;
    }
    if (!j->shared)
        atrbvh_device_close(d);
    return NULL;
}

START_TEST(threads_own_and_shared_devices)
{
    float *v;
    atrbvh_geometry g = soup(&v, T, 9);
    atrbvh_build_options o;
    atrbvh_bvh *ref;
    atrbvh_device *shared;
    atrbvh_error e;
    job jobs[8];
    pthread_t th[8];
    int i;
    atrbvh_build_options_init(&o);
    ref = tu_build(&g, &o);
    ck_assert_int_eq(atrbvh_device_open("cpu", &shared, &e), ATRBVH_OK);
    for (i = 0; i < 8; i++) {
        jobs[i].g = &g;
        jobs[i].ref = ref;
        jobs[i].shared = i % 2 ? shared : NULL;
        jobs[i].msg[0] = '\0';
        ck_assert_int_eq(pthread_create(&th[i], NULL, worker, &jobs[i]), 0);
    }
    for (i = 0; i < 8; i++) {
        pthread_join(th[i], NULL);
        ck_assert_msg(jobs[i].ok, "thread %d: %s", i, jobs[i].msg);
    }
    atrbvh_device_close(shared);
    atrbvh_bvh_free(ref);
    free(v);
}
END_TEST

/* ------------------------------------------------------------ progress */
typedef struct prog_log {
    int n;
    double f[4096];
    int optimise; /* values reported by the optimise stage */
    double opt_first, opt_last;
    const char *cancel_at; /* stage name to cancel at, or NULL */
    double cancel_after;   /* or cancel when the fraction passes this */
    int cancels;
} prog_log;

static int on_progress(const char *stage, double fraction, void *user)
{
    prog_log *p = user;
    if (p->n < 4096)
        p->f[p->n++] = fraction;
    if (stage && strcmp(stage, "optimise") == 0) {
        if (!p->optimise++)
            p->opt_first = fraction;
        p->opt_last = fraction;
    }
    if ((p->cancel_at && stage && strcmp(stage, p->cancel_at) == 0) ||
        (p->cancel_after > 0.0 && fraction > p->cancel_after)) {
        p->cancels++;
        return 1;
    }
    return 0;
}

START_TEST(progress_monotone_to_one)
{
    float *v;
    atrbvh_geometry g = soup(&v, 60000, 12);
    atrbvh_build_options o;
    atrbvh_bvh *b, *ref;
    atrbvh_error e;
    prog_log p;
    char msg[256];
    int i, inside = 0;
    atrbvh_build_options_init(&o);
    o.threads = _i + 1; /* 1 and 2 threads */
    o.rounds = 3;
    ref = tu_build(&g, &o);
    memset(&p, 0, sizeof p);
    o.progress = on_progress;
    o.progress_user = &p;
    ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_OK);
    ck_assert_msg(tu_same_bvh(ref, b, msg, sizeof msg), "%s", msg);
    ck_assert_int_gt(p.n, 8);
    ck_assert(p.f[0] >= 0.0);
    for (i = 1; i < p.n; i++)
        ck_assert_msg(p.f[i] >= p.f[i - 1], "fraction %d went from %g to %g",
                      i, p.f[i - 1], p.f[i]);
    ck_assert(p.f[p.n - 1] == 1.0);
    /* Several distinct values strictly inside the optimise stage. */
    for (i = 1; i < p.n; i++)
        if (p.f[i] > p.opt_first && p.f[i] < p.opt_last &&
            p.f[i] != p.f[i - 1])
            inside++;
    ck_assert_msg(inside >= 3, "%d values inside the optimise stage (%d calls)",
                  inside, p.optimise);
    atrbvh_bvh_free(b);
    atrbvh_bvh_free(ref);
    free(v);
}
END_TEST

START_TEST(cancel_everywhere)
{
    static const char *const stages[] = {"bounds",   "morton",  "sort",
                                         "hierarchy", "refit", "optimise",
                                         "collapse", "layout"};
    float *v;
    atrbvh_geometry g = soup(&v, 20000, 13);
    atrbvh_build_options o;
    size_t s;
    atrbvh_build_options_init(&o);
    o.threads = 2;
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    for (s = 0; s <= sizeof stages / sizeof *stages; s++) {
        atrbvh_bvh *b = (atrbvh_bvh *)&o;
        atrbvh_error e;
        prog_log p;
        memset(&p, 0, sizeof p);
        if (s < sizeof stages / sizeof *stages)
            p.cancel_at = stages[s];
        else
            p.cancel_after = 0.5; /* inside the optimise stage */
        o.progress = on_progress;
        o.progress_user = &p;
        tu_alloc.outstanding = 0;
        ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_ERR_CANCELLED);
        ck_assert_ptr_null(b);
        ck_assert_int_eq(p.cancels, 1);
        ck_assert_int_eq(e.status, ATRBVH_ERR_CANCELLED);
        ck_assert_msg(strstr(e.text, "cancel"), "%s", e.text);
        ck_assert_msg(tu_alloc.outstanding == 0, "cancel at %s: %ld leaked",
                      p.cancel_at ? p.cancel_at : "0.5", tu_alloc.outstanding);
    }
    atrbvh_set_allocator(NULL, NULL);
    free(v);
}
END_TEST

/* -------------------------------------------------- structs that grow */
START_TEST(stats_by_size)
{
    float *v;
    atrbvh_geometry g = soup(&v, 300, 14);
    atrbvh_build_options o;
    atrbvh_stats st, st2;
    atrbvh_bvh *b;
    int k;
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    b = tu_build(&g, &o);
    ck_assert_int_eq(atrbvh_bvh_stats(b, &st), ATRBVH_OK);
    ck_assert_uint_eq(st.primitives, 300);
    memset(&st2, 0xab, sizeof st2);
    ck_assert_int_eq(atrbvh_bvh_stats_sized(b, &st2, sizeof st2), ATRBVH_OK);
    ck_assert(memcmp(&st, &st2, sizeof st) == 0);
    /* Smaller than the first version, larger than this one, NULL:
     * refused, untouched. */
    memset(&st2, 0xab, sizeof st2);
    ck_assert_int_eq(atrbvh_bvh_stats_sized(b, &st2, sizeof st2 - 1),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_bvh_stats_sized(b, &st2, 8),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_bvh_stats_sized(b, &st2, sizeof st2 + 8),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(((unsigned char *)&st2)[0], 0xab);
    ck_assert_int_eq(atrbvh_bvh_stats(NULL, &st2),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    /* Stage times by accessor: LBVH runs no optimise stage. */
    ck_assert(atrbvh_bvh_stage_ms(b, ATRBVH_STAGE_OPTIMISE) == 0.0);
    for (k = 0; k < ATRBVH_STAGE_COUNT; k++)
        ck_assert(atrbvh_bvh_stage_ms(b, (atrbvh_stage)k) >= 0.0);
    ck_assert(atrbvh_bvh_stage_ms(b, ATRBVH_STAGE_COUNT) == 0.0);
    ck_assert(atrbvh_bvh_stage_ms(NULL, ATRBVH_STAGE_SORT) == 0.0);
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

START_TEST(geometry_size_field)
{
    float *v;
    atrbvh_geometry g = soup(&v, 10, 15), h;
    atrbvh_bvh *b;
    atrbvh_error e;
    ck_assert_uint_eq(g.size, sizeof g);
    h = g;
    h.size = 0; /* a hand-made struct that forgot it */
    ck_assert_int_eq(atrbvh_build(&h, NULL, &b, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_msg(strstr(e.text, "geometry.size"), "%s", e.text);
    h.size = sizeof h + 4;
    ck_assert_int_eq(atrbvh_build(&h, NULL, &b, &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_int_eq(atrbvh_build(&g, NULL, &b, &e), ATRBVH_OK);
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

/* ------------------------------------------------------ stage capture */
typedef struct cap_log {
    int calls;
    char names[16][32];
    uint64_t sum[16]; /* FNV-1a over every array's name, shape and bytes */
    int sorted_ok, layout_ok;
    const atrbvh_node *nodes; /* to compare the layout arrays with */
    int stop_at;              /* cancel at this call (0: never) */
} cap_log;

static size_t dtype_size(atrbvh_dtype d)
{
    return d == ATRBVH_DTYPE_U32 || d == ATRBVH_DTYPE_F32 ? 4 : 8;
}

static int on_capture(const atrbvh_stage_output *out, void *user)
{
    cap_log *c = user;
    uint64_t h = 1469598103934665603ull;
    size_t a, i;
    ck_assert_uint_eq(out->size, sizeof *out);
    if (c->calls < 16)
        snprintf(c->names[c->calls], sizeof c->names[0], "%s", out->name);
    for (a = 0; a < out->array_count; a++) {
        const atrbvh_array *x = &out->arrays[a];
        const unsigned char *b = x->data;
        size_t bytes = x->rows * x->cols * dtype_size(x->dtype);
        for (i = 0; x->name[i]; i++)
            h = (h ^ (unsigned char)x->name[i]) * 1099511628211ull;
        h = (h ^ x->rows) * 1099511628211ull;
        h = (h ^ x->cols) * 1099511628211ull;
        for (i = 0; i < bytes; i++)
            h = (h ^ b[i]) * 1099511628211ull;
        if (strcmp(x->name, "sorted_keys") == 0) {
            const uint64_t *k = x->data;
            c->sorted_ok = 1;
            for (i = 1; i < x->rows; i++)
                if (k[i - 1] > k[i])
                    c->sorted_ok = 0;
        }
    }
    if (c->calls < 16)
        c->sum[c->calls] = h;
    c->calls++;
    return c->stop_at && c->calls == c->stop_at;
}

START_TEST(capture_every_stage)
{
    static const char *const expect[] = {
        "bounds",   "morton",   "sort",
        "hierarchy", "refit",   "optimise_round1",
        "optimise_round2", "optimise", "collapse",
        "layout"};
    float *v;
    atrbvh_geometry g = soup(&v, 5000, 21);
    atrbvh_build_options o;
    atrbvh_bvh *b, *ref;
    atrbvh_error e;
    cap_log c1, c2;
    char msg[256];
    size_t i;
    atrbvh_build_options_init(&o);
    o.max_leaf_size = 8;
    ref = tu_build(&g, &o);
    memset(&c1, 0, sizeof c1);
    memset(&c2, 0, sizeof c2);
    o.capture = on_capture;
    o.capture_user = &c1;
    o.threads = 1;
    ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_OK);
    ck_assert_msg(tu_same_bvh(ref, b, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_free(b);
    ck_assert_int_eq(c1.calls, (int)(sizeof expect / sizeof *expect));
    for (i = 0; i < sizeof expect / sizeof *expect; i++)
        ck_assert_str_eq(c1.names[i], expect[i]);
    ck_assert(c1.sorted_ok);
    /* The same bytes for another thread count. */
    o.capture_user = &c2;
    o.threads = 2;
    ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_OK);
    atrbvh_bvh_free(b);
    ck_assert_int_eq(c2.calls, c1.calls);
    for (i = 0; i < (size_t)c1.calls; i++)
        ck_assert_msg(c1.sum[i] == c2.sum[i], "stage %s differs with 2 threads",
                      c1.names[i]);
    /* The same bytes on an OpenCL device, when there is one. */
    {
        atrbvh_device *cl = NULL;
        const atrbvh_status st = atrbvh_device_open("opencl", &cl, &e);
        ck_assert_msg(st == ATRBVH_OK || tu_opencl_may_skip(st),
                      "the OpenCL backend failed: %s", e.text);
        if (st == ATRBVH_OK) {
            cap_log c4;
            memset(&c4, 0, sizeof c4);
            o.device = cl;
            o.capture_user = &c4;
            ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_OK);
            atrbvh_bvh_free(b);
            o.device = NULL;
            atrbvh_device_close(cl);
            ck_assert_int_eq(c4.calls, c1.calls);
            for (i = 0; i < (size_t)c1.calls; i++)
                ck_assert_msg(c1.sum[i] == c4.sum[i],
                              "stage %s differs on OpenCL", c1.names[i]);
        } else {
            fprintf(stderr, "SKIP capture on OpenCL: %s\n", e.text);
        }
    }
    /* The callback can cancel, after any stage; nothing leaks. */
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    for (i = 1; i <= sizeof expect / sizeof *expect; i++) {
        cap_log c3;
        memset(&c3, 0, sizeof c3);
        c3.stop_at = (int)i;
        o.capture_user = &c3;
        tu_alloc.outstanding = 0;
        ck_assert_int_eq(atrbvh_build(&g, &o, &b, &e), ATRBVH_ERR_CANCELLED);
        ck_assert_ptr_null(b);
        ck_assert_msg(strstr(e.text, expect[i - 1]), "%s", e.text);
        ck_assert_int_eq(tu_alloc.outstanding, 0);
    }
    atrbvh_set_allocator(NULL, NULL);
    atrbvh_bvh_free(ref);
    free(v);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("device");
    TCase *t = tcase_create("device");
    tcase_set_timeout(t, 600);
    tcase_add_test(t, open_specs);
    tcase_add_test(t, reuse_allocates_no_scratch);
    tcase_add_test(t, lbvh_outputs_own_their_nodes);
    tcase_add_test(t, lbvh_handle_learns_node_count);
    tcase_add_loop_test(t, allocation_failure_open_build_close, 0, 2);
    tcase_add_loop_test(t, peak_memory_lbvh, 0, 3);
    tcase_add_loop_test(t, peak_memory_optimised, 0, 3);
    tcase_add_test(t, large_leaves_gathered_alike);
    tcase_add_loop_test(t, allocation_failure_lbvh_and_invalid, 0, 2);
    tcase_add_loop_test(t, rebuild_same_tree_fewer_bytes, 0, 4);
    tcase_add_test(t, rebuild_leaves_room);
    tcase_add_loop_test(t, rebuild_reads_old_nodes, 0, 2);
    tcase_add_loop_test(t, rebuild_frees_old_on_failure, 0, 2);
    tcase_add_test(t, threads_own_and_shared_devices);
    tcase_add_loop_test(t, progress_monotone_to_one, 0, 2);
    tcase_add_test(t, cancel_everywhere);
    tcase_add_test(t, stats_by_size);
    tcase_add_test(t, geometry_size_field);
    tcase_add_test(t, capture_every_stage);
    suite_add_tcase(s, t);
    return s;
}

int main(void)
{
    return tu_run(suite());
}
