/*
 * test_opencl.c - the OpenCL backend against the CPU reference, stage by
 * stage (atrbvh_validate_backends compares the captured output of every
 * stage bit for bit), on generated scenes, the extremes, and the scenes of
 * $ATRBVH_SCENES; the error paths.  Every test skips, saying so, when no
 * OpenCL device (or no OpenCL support) is there; any other failure of the
 * first build - the kernels not compiling - fails it (tu_opencl_may_skip).
 * All of it twice: in place on a device that shares the host's memory,
 * with several treelets a work-item on a CPU device (opt_round4), then
 * with ATRBVH_CL_COPY and ATRBVH_CL_WALKS=1 (copies, and one treelet a
 * work-item, as on a GPU with its own memory).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h" /* ATRBVH_KERNEL_SOURCE_OVERRIDE */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atrbvh.h"
#include "testutil.h"

static int have_device = -1;
static atrbvh_status why_st; /* the first build's status, when it failed */
static char why_not[ATRBVH_ERROR_TEXT_LENGTH];

/* 1 when an OpenCL build of one box works; else 0, status in why_st and
 * reason in why_not. */
static int device_available(void)
{
    if (have_device < 0) {
        static const float box[6] = {0, 0, 0, 1, 1, 1};
        atrbvh_geometry g = atrbvh_geometry_boxes(box, 1);
        atrbvh_build_options o;
        atrbvh_bvh *b = NULL;
        atrbvh_error e;
        atrbvh_status st;
        atrbvh_build_options_init(&o);
        o.backend = ATRBVH_BACKEND_OPENCL;
        st = atrbvh_build(&g, &o, &b, &e);
        have_device = st == ATRBVH_OK;
        why_st = st;
        if (!have_device)
            snprintf(why_not, sizeof why_not, "%s", e.text);
        atrbvh_bvh_free(b);
    }
    return have_device;
}

#define REQUIRE_DEVICE()                                                       \
    do {                                                                       \
        if (!device_available()) {                                             \
            ck_assert_msg(tu_opencl_may_skip(why_st),                          \
                          "the OpenCL backend failed: %s", why_not);           \
            fprintf(stderr, "SKIP %s: no OpenCL device (%s)\n", __func__,      \
                    why_not);                                                  \
            return;                                                            \
        }                                                                      \
    } while (0)

/* One configuration of the matrix. */
typedef struct config {
    atrbvh_method method;
    unsigned treelet, rounds;
    int collapse;
} config;

static void expect_identical(const atrbvh_geometry *g, const config *c,
                             const char *what)
{
    atrbvh_build_options o;
    atrbvh_error e;
    atrbvh_status st;
    int identical = 0;
    atrbvh_build_options_init(&o);
    o.method = c->method;
    o.treelet_size = c->treelet;
    o.rounds = c->rounds;
    o.collapse = c->collapse;
    o.threads = 2;
    st = atrbvh_validate_backends(g, &o, &identical, &e);
    ck_assert_msg(st == ATRBVH_OK, "%s: validate failed: %s", what, e.text);
    ck_assert_msg(identical,
                  "%s (method %d, treelet %u, rounds %u, collapse %d): %s",
                  what, (int)c->method, c->treelet, c->rounds, c->collapse,
                  e.text);
}

/* The whole matrix of the issue: lbvh; trbvh n in {5,7,8}; atrbvh n in
 * {4,9,16,32}; rounds 1..3; with and without collapse. */
static size_t full_matrix(config *out)
{
    static const unsigned tr[] = {5, 7, 8}, at[] = {4, 9, 16, 32};
    size_t k = 0, i;
    unsigned r;
    int col;
    for (col = 0; col < 2; col++) {
        config c = {ATRBVH_METHOD_LBVH, 0, 0, col};
        out[k++] = c;
        for (r = 1; r <= 3; r++) {
            for (i = 0; i < 3; i++) {
                config t = {ATRBVH_METHOD_TRBVH, tr[i], r, col};
                out[k++] = t;
            }
            for (i = 0; i < 4; i++) {
                config a = {ATRBVH_METHOD_ATRBVH, at[i], r, col};
                out[k++] = a;
            }
        }
    }
    return k;
}

/* A small sample: one configuration of each kind. */
static const config sample[] = {
    {ATRBVH_METHOD_LBVH, 0, 0, 1},   {ATRBVH_METHOD_TRBVH, 7, 3, 1},
    {ATRBVH_METHOD_TRBVH, 5, 1, 0},  {ATRBVH_METHOD_ATRBVH, 9, 2, 1},
    {ATRBVH_METHOD_ATRBVH, 32, 1, 0}};
#define SAMPLE_COUNT (sizeof sample / sizeof sample[0])

/* ------------------------------------------------------------ generated */
START_TEST(generated_full_matrix)
{
    config m[64];
    size_t k, count;
    float *v;
    atrbvh_geometry g;
    REQUIRE_DEVICE();
    v = tu_random_triangles(1500, 42, 10.0f, -5.0f);
    g = atrbvh_geometry_triangles(v, 4500, NULL, 1500);
    count = full_matrix(m);
    for (k = 0; k < count; k++)
        expect_identical(&g, &m[k], "1500 random triangles");
    free(v);
}
END_TEST

START_TEST(generated_builtin_scenes)
{
    static const char *names[] = {"builtin:sphere:20000", "builtin:terrain:20000",
                                  "builtin:city:20000"};
    size_t s, k;
    REQUIRE_DEVICE();
    for (s = 0; s < 3; s++) {
        scene sc;
        char err[256];
        atrbvh_geometry g;
        ck_assert_msg(scene_load(names[s], &sc, err, sizeof err) == 0, "%s",
                      err);
        g = scene_geometry(&sc);
        for (k = 0; k < SAMPLE_COUNT; k++)
            expect_identical(&g, &sample[k], names[s]);
        scene_free(&sc);
    }
}
END_TEST

/* ATRBVH above 32 leaves (the scratch path) and the adaptive size: the
 * OpenCL kernel carves the same scratch layout and gives the same bits. */
START_TEST(large_and_auto_treelets)
{
    static const config big[] = {
        {ATRBVH_METHOD_ATRBVH, 48, 2, 1},
        {ATRBVH_METHOD_ATRBVH, 128, 1, 0},
        {ATRBVH_METHOD_ATRBVH, ATRBVH_TREELET_AUTO, 2, 1}};
    size_t k;
    float *v;
    atrbvh_geometry g;
    REQUIRE_DEVICE();
    v = tu_random_triangles(20000, 77, 10.0f, -5.0f);
    g = atrbvh_geometry_triangles(v, 60000, NULL, 20000);
    for (k = 0; k < sizeof big / sizeof big[0]; k++)
        expect_identical(&g, &big[k], "20000 random triangles");
    free(v);
}
END_TEST

/* ------------------------------------------------------------- extremes */
static void extreme(const float *v, size_t tris, const char *what)
{
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * tris, NULL, tris);
    size_t k;
    for (k = 0; k < SAMPLE_COUNT; k++)
        expect_identical(&g, &sample[k], what);
}

START_TEST(extremes_flat_and_coincident)
{
    enum { N = 600 };
    float *v = tu_random_triangles(N, 7, 4.0f, -2.0f);
    float *w = malloc(sizeof(float) * 9 * N);
    size_t i, k;
    int axes;
    REQUIRE_DEVICE();
    ck_assert_ptr_nonnull(w);
    /* Flat on 1, 2 and 3 axes (a plane, a line, a point). */
    for (axes = 1; axes <= 3; axes++) {
        char what[64];
        memcpy(w, v, sizeof(float) * 9 * N);
        for (i = 0; i < 3 * N; i++)
            for (k = 0; k < (size_t)axes; k++)
                w[3 * i + 2 - k] = 1.5f;
        snprintf(what, sizeof what, "flat on %d axes", axes);
        extreme(w, N, what);
    }
    /* Coincident centroids: triangles symmetric about (1, 2, 3). */
    for (i = 0; i < N; i++) {
        float dx = v[9 * i], dy = v[9 * i + 1], dz = v[9 * i + 2];
        float c[3] = {1.0f, 2.0f, 3.0f}, d[3];
        d[0] = dx;
        d[1] = dy;
        d[2] = dz;
        for (k = 0; k < 3; k++) {
            w[9 * i + k] = c[k] - d[k];
            w[9 * i + 3 + k] = c[k] + d[k];
            w[9 * i + 6 + k] = c[k];
        }
    }
    extreme(w, N, "coincident centroids");
    /* Identical triangles. */
    for (i = 0; i < N; i++)
        memcpy(w + 9 * i, v, 9 * sizeof(float));
    extreme(w, N, "identical triangles");
    /* One and two primitives. */
    extreme(v, 1, "one triangle");
    extreme(v, 2, "two triangles");
    free(v);
    free(w);
}
END_TEST

START_TEST(extremes_boxes_and_invalid)
{
    enum { N = 300 };
    float b[6 * N], *v;
    size_t i, k;
    tu_rng r;
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_error e1, e2;
    atrbvh_bvh *x = NULL, *y = NULL;
    atrbvh_status s1, s2;
    int identical = 0;
    REQUIRE_DEVICE();
    tu_rng_seed(&r, 3);
    for (i = 0; i < N; i++)
        for (k = 0; k < 3; k++) {
            float lo = tu_rng_float(&r) * 100.0f - 50.0f;
            b[6 * i + k] = lo;
            b[6 * i + 3 + k] = lo + tu_rng_float(&r) * (k == 1 ? 0.0f : 3.0f);
        }
    g = atrbvh_geometry_boxes(b, N);
    for (k = 0; k < SAMPLE_COUNT; k++)
        expect_identical(&g, &sample[k], "boxes, flat in y");

    /* NaN primitives: the same error as the CPU, and with skip_invalid the
     * same compaction (the host bounds path) and tree. */
    v = tu_random_triangles(500, 11, 1.0f, 0.0f);
    v[9 * 123 + 4] = 0.0f / 0.0f;
    v[9 * 321 + 0] = 1.0f / 0.0f;
    g = atrbvh_geometry_triangles(v, 1500, NULL, 500);
    atrbvh_build_options_init(&o);
    s1 = atrbvh_build(&g, &o, &x, &e1);
    o.backend = ATRBVH_BACKEND_OPENCL;
    s2 = atrbvh_build(&g, &o, &y, &e2);
    ck_assert_int_eq(s1, ATRBVH_ERR_NONFINITE);
    ck_assert_int_eq(s2, s1);
    ck_assert_str_eq(e1.text, e2.text);
    ck_assert(e1.index == 123 && e2.index == 123);
    o.skip_invalid = 1;
    ck_assert_int_eq(atrbvh_validate_backends(&g, &o, &identical, &e1),
                     ATRBVH_OK);
    ck_assert_msg(identical, "skip_invalid: %s", e1.text);
    free(v);
}
END_TEST

/* The bounds kernel takes eight triangles at a time when all eight are
 * in the common case, else one at a time (cl/kernels.cl, bounds_tri8):
 * every stage's output the CPU's (atrbvh_validate_backends) for a packed
 * soup and for strided indices and vertices, with counts that leave
 * partial groups at the ends of the kernel's blocks, and with skip_invalid
 * where NaN and infinite coordinates fall at every lane of a group. */
START_TEST(bounds_eight_at_a_time)
{
    static const size_t counts[] = {7, 8, 9, 1003};
    size_t c, i, k;
    REQUIRE_DEVICE();
    for (c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        const size_t n = counts[c];
        float *v = tu_random_triangles(n, 40 + c, 4.0f, -2.0f);
        float *sv = malloc(3 * n * 5 * sizeof *sv); /* 5 floats a vertex */
        uint32_t *idx = malloc(n * 4 * sizeof *idx); /* 4 words a triangle */
        atrbvh_geometry g;
        atrbvh_build_options o;
        atrbvh_error e;
        int identical = 0;
        char what[64];
        ck_assert(sv != NULL && idx != NULL);
        for (i = 0; i < 3 * n; i++) /* vertex i of the soup at 3n-1-i */
            for (k = 0; k < 5; k++)
                sv[5 * (3 * n - 1 - i) + k] = k < 3 ? v[3 * i + k] : -7.0f;
        for (i = 0; i < n; i++) {
            for (k = 0; k < 3; k++)
                idx[4 * i + k] = (uint32_t)(3 * n - 1 - (3 * i + k));
            idx[4 * i + 3] = 0xdeadbeefu;
        }
        snprintf(what, sizeof what, "%lu packed", (unsigned long)n);
        g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
        expect_identical(&g, &sample[0], what);
        expect_identical(&g, &sample[3], what);
        snprintf(what, sizeof what, "%lu strided", (unsigned long)n);
        g = atrbvh_geometry_triangles(sv, 3 * n, idx, n);
        g.vertex_stride = 5 * sizeof(float);
        g.index_stride = 4 * sizeof(uint32_t);
        expect_identical(&g, &sample[0], what);
        if (n >= 16) {
            /* a bad coordinate in lane k of group k, for every lane */
            for (k = 0; k < 8; k++)
                v[9 * (8 * k + k) + k % 9] =
                    k % 2 ? 1.0f / 0.0f : 0.0f / 0.0f;
            g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
            atrbvh_build_options_init(&o);
            o.method = ATRBVH_METHOD_LBVH;
            o.skip_invalid = 1;
            o.threads = 2;
            ck_assert_int_eq(atrbvh_validate_backends(&g, &o, &identical, &e),
                             ATRBVH_OK);
            ck_assert_msg(identical, "%lu, skip_invalid: %s",
                          (unsigned long)n, e.text);
        }
        free(v);
        free(sv);
        free(idx);
    }
}
END_TEST

/* ---------------------------------------------------------- real scenes */
START_TEST(real_scenes)
{
    char *paths[32];
    size_t n = tu_scene_paths(paths, 32), s, k;
    REQUIRE_DEVICE();
    if (n == 0) {
        fprintf(stderr, "SKIP real_scenes: no scenes in $ATRBVH_SCENES (%s)\n",
                getenv("ATRBVH_SCENES") ? getenv("ATRBVH_SCENES") : "unset");
        return;
    }
    for (s = 0; s < n; s++) {
        scene sc;
        char err[256];
        atrbvh_geometry g;
        ck_assert_msg(scene_load(paths[s], &sc, err, sizeof err) == 0, "%s",
                      err);
        g = scene_geometry(&sc);
        /* Large scenes (dragon) get one configuration, the default
         * (atrbvh 9, 2 rounds, collapse); the others the sample. */
        for (k = 0; k < SAMPLE_COUNT; k++) {
            if (sc.triangle_count > 300000 && k != 3)
                continue;
            expect_identical(&g, &sample[k], paths[s]);
        }
        scene_free(&sc);
    }
    tu_free_paths(paths, n);
}
END_TEST

/* --------------------------------------------------------------- errors */
START_TEST(bad_device_string)
{
    static const float box[6] = {0, 0, 0, 1, 1, 1};
    atrbvh_geometry g = atrbvh_geometry_boxes(box, 1);
    atrbvh_build_options o;
    atrbvh_bvh *b = (atrbvh_bvh *)&o;
    atrbvh_error e;
    atrbvh_status st;
    REQUIRE_DEVICE();
    atrbvh_build_options_init(&o);
    o.backend = ATRBVH_BACKEND_OPENCL;
    o.opencl_device = "no such device, surely";
    st = atrbvh_build(&g, &o, &b, &e);
    ck_assert_int_eq(st, ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_null(b);
    ck_assert_msg(strstr(e.text, "no device matches"), "%s", e.text);
    o.opencl_device = "7:7";
    st = atrbvh_build(&g, &o, &b, &e);
    ck_assert_int_eq(st, ATRBVH_ERR_INVALID_ARGUMENT);
    o.opencl_device = "0:0";
    st = atrbvh_build(&g, &o, &b, &e);
    ck_assert_int_eq(st, ATRBVH_OK);
    ck_assert_ptr_nonnull(atrbvh_bvh_device(b));
    ck_assert_str_ne(atrbvh_bvh_device(b), "cpu");
    atrbvh_bvh_free(b);
}
END_TEST

/* atrbvh_device_open("opencl") with a kernel folder of its own in
 * $ATRBVH_CL_SOURCE_DIR, its kernels.cl the concatenation of `head`
 * (head_len bytes), `insert` and `tail` (NULL: nothing), and with
 * $ATRBVH_OPENCL_DEVICE set to `device_env` (NULL: left alone); the
 * folder and the variables are gone when it returns. */
static atrbvh_status open_with_kernels(const char *head, size_t head_len,
                                       const char *insert, const char *tail,
                                       const char *device_env,
                                       atrbvh_device **dev, atrbvh_error *e)
{
    char dir[] = "/tmp/atrbvh-cl-XXXXXX", path[64];
    atrbvh_status st;
    FILE *f;
    ck_assert_ptr_nonnull(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/kernels.cl", dir);
    f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    ck_assert_uint_eq(fwrite(head, 1, head_len, f), head_len);
    if (insert)
        fputs(insert, f);
    if (tail)
        fputs(tail, f);
    ck_assert_int_eq(fclose(f), 0);
    setenv("ATRBVH_CL_SOURCE_DIR", dir, 1);
    if (device_env)
        setenv("ATRBVH_OPENCL_DEVICE", device_env, 1);
    st = atrbvh_device_open("opencl", dev, e);
    unsetenv("ATRBVH_CL_SOURCE_DIR");
    if (device_env)
        unsetenv("ATRBVH_OPENCL_DEVICE");
    remove(path);
    rmdir(dir);
    return st;
}

/* A kernel that does not compile: the compiler log reaches the error text
 * of atrbvh_device_open (the program is built there, once).  Needs a
 * library configured with --enable-kernel-source-override (the configs
 * stage builds one); a normal build reads no environment variable. */
START_TEST(broken_kernel_source)
{
#ifdef ATRBVH_KERNEL_SOURCE_OVERRIDE
    static const char src[] = "__kernel void bounds_boxes(__global float *x)\n"
                              "{\n    x[0] = this_is_not_defined;\n}\n";
    atrbvh_device *dev = (atrbvh_device *)&dev;
    atrbvh_error e;
    atrbvh_status st;
    REQUIRE_DEVICE();
    st = open_with_kernels(src, sizeof src - 1, NULL, NULL, NULL, &dev, &e);
    ck_assert_int_eq(st, ATRBVH_ERR_BACKEND);
    ck_assert_ptr_null(dev);
    ck_assert_msg(strstr(e.text, "kernel build failed"), "%s", e.text);
    /* The compiler log: the file and the undeclared name. */
    ck_assert_msg(strstr(e.text, "kernels.cl"), "%s", e.text);
    ck_assert_msg(strstr(e.text, "this_is_not_defined"), "%s", e.text);
#else
    fprintf(stderr, "SKIP broken_kernel_source: configured without "
                    "--enable-kernel-source-override\n");
#endif
}
END_TEST

/* Without the override switch the library reads no environment variable:
 * a kernel folder in $ATRBVH_CL_SOURCE_DIR changes nothing, and
 * $ATRBVH_OPENCL_DEVICE does not choose the device. */
START_TEST(no_environment)
{
#ifndef ATRBVH_KERNEL_SOURCE_OVERRIDE
    static const char src[] = "this is not OpenCL\n";
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    atrbvh_status st;
    REQUIRE_DEVICE();
    st = open_with_kernels(src, sizeof src - 1, NULL, NULL,
                           "no such device, surely", &dev, &e);
    ck_assert_msg(st == ATRBVH_OK, "%s", e.text);
    atrbvh_device_close(dev);
#else
    fprintf(stderr, "SKIP no_environment: configured with "
                    "--enable-kernel-source-override\n");
#endif
}
END_TEST

/* The device handle: spec forms, and builds on one open handle that match
 * the CPU's, build after build (the buffers kept on the device between
 * builds of different sizes must not leak one build into the next). */
START_TEST(device_handle)
{
    atrbvh_device *dev = NULL, *again = NULL, *bad = (atrbvh_device *)&bad;
    atrbvh_build_options o;
    atrbvh_error e;
    char msg[256], upper[128];
    const char *name;
    size_t k;
    int round;
    REQUIRE_DEVICE();
    ck_assert_int_eq(atrbvh_device_open("opencl", &dev, &e), ATRBVH_OK);
    ck_assert_int_eq(atrbvh_device_backend(dev), ATRBVH_BACKEND_OPENCL);
    name = atrbvh_device_name(dev);
    ck_assert(name && *name);
    /* "opencl:0:0" is the first device too; a name substring in another
     * case finds it again. */
    ck_assert_int_eq(atrbvh_device_open("opencl:0:0", &again, &e), ATRBVH_OK);
    ck_assert_str_eq(atrbvh_device_name(again), name);
    atrbvh_device_close(again);
    again = NULL;
    for (k = 0; name[k] && k + 1 < sizeof upper; k++)
        upper[k] = (char)(name[k] >= 'a' && name[k] <= 'z' ? name[k] - 32
                                                           : name[k]);
    upper[k] = '\0';
    snprintf(msg, sizeof msg, "opencl:%.100s", upper);
    ck_assert_msg(atrbvh_device_open(msg, &again, &e) == ATRBVH_OK, "%s: %s",
                  msg, e.text);
    ck_assert_str_eq(atrbvh_device_name(again), name);
    atrbvh_device_close(again);
    ck_assert_int_eq(atrbvh_device_open("opencl:no such device, surely", &bad,
                                        &e),
                     ATRBVH_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_null(bad);
    ck_assert_msg(strstr(e.text, "no device matches"), "%s", e.text);
    for (round = 0; round < 3; round++) {
        static const unsigned sizes[] = {3000, 700, 3001};
        unsigned n = sizes[round];
        float *v = tu_random_triangles(n, 17 + (unsigned)round, 4.0f, -2.0f);
        atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
        atrbvh_bvh *x, *y;
        atrbvh_build_options_init(&o);
        x = tu_build(&g, &o);
        o.device = dev;
        y = tu_build(&g, &o);
        ck_assert_str_eq(atrbvh_bvh_device(y), name);
        ck_assert_msg(atrbvh_compare(x, y, &e) == 0, "round %d: %s", round,
                      e.text);
        atrbvh_bvh_free(x);
        atrbvh_bvh_free(y);
        free(v);
    }
    atrbvh_device_close(dev);
}
END_TEST

/* atrbvh_rebuild on an OpenCL handle: the tree the CPU builds, in rounds
 * of 3000, 3000, 700 and 3001 triangles (the same twice, then from a
 * larger old tree and a smaller one).  When the old tree is of the same
 * triangles, its node and index arrays become the new one's (the host
 * side of an OpenCL build holds nothing of the primitive count before the
 * output, so the nodes wait for it: lib/pipeline.c), and the rebuild
 * allocates at least their bytes less than a build on a second handle
 * after freeing its last tree. */
START_TEST(rebuild_on_device)
{
    static const unsigned sizes[] = {3000, 3000, 700, 3001};
    atrbvh_device *dev[2] = {NULL, NULL};
    atrbvh_bvh *plain = NULL, *re = NULL;
    atrbvh_build_options o;
    atrbvh_error e;
    char msg[256];
    unsigned round;
    REQUIRE_DEVICE();
    ck_assert_int_eq(atrbvh_device_open("opencl", &dev[0], &e), ATRBVH_OK);
    ck_assert_int_eq(atrbvh_device_open("opencl", &dev[1], &e), ATRBVH_OK);
    for (round = 0; round < 8; round++) {
        const unsigned n = sizes[round % 4];
        float *v = tu_random_triangles(n, 40 + n, 4.0f, -2.0f);
        atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
        atrbvh_bvh *ref;
        size_t plain_bytes, re_bytes, nodes = 0, prims = 0, reused = 0;
        atrbvh_build_options_init(&o);
        o.method = round < 4 ? ATRBVH_METHOD_LBVH : ATRBVH_METHOD_ATRBVH;
        o.max_leaf_size = 8;
        ref = tu_build(&g, &o);
        atrbvh_bvh_nodes(re, &nodes);
        atrbvh_bvh_primitive_indices(re, &prims);
        if (prims == n) /* (the same triangles: as many nodes) */
            reused = nodes * sizeof(atrbvh_node) + prims * sizeof(uint32_t);
        atrbvh_set_allocator(tu_count_malloc, tu_count_free);
        atrbvh_bvh_free(plain);
        tu_count_reset(-1);
        o.device = dev[0];
        ck_assert_int_eq(atrbvh_build(&g, &o, &plain, &e), ATRBVH_OK);
        plain_bytes = tu_alloc.total_bytes;
        tu_count_reset(-1);
        o.device = dev[1];
        ck_assert_int_eq(atrbvh_rebuild(&g, &o, &re, &e), ATRBVH_OK);
        re_bytes = tu_alloc.total_bytes;
        atrbvh_set_allocator(NULL, NULL);
        ck_assert_msg(atrbvh_compare(ref, plain, &e) == 0 &&
                          tu_same_bvh(ref, re, msg, sizeof msg),
                      "round %u: %s %s", round, e.text, msg);
        ck_assert_msg(re_bytes + reused <= plain_bytes,
                      "round %u: built with %lu bytes, rebuilt with %lu, "
                      "the old tree's arrays %lu",
                      round, (unsigned long)plain_bytes,
                      (unsigned long)re_bytes, (unsigned long)reused);
        atrbvh_bvh_free(ref);
        free(v);
    }
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    atrbvh_bvh_free(plain);
    atrbvh_bvh_free(re);
    atrbvh_set_allocator(NULL, NULL);
    atrbvh_device_close(dev[0]);
    atrbvh_device_close(dev[1]);
}
END_TEST

START_TEST(kernel_times_and_device)
{
    float *v = tu_random_triangles(2000, 5, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 6000, NULL, 2000);
    atrbvh_build_options o;
    atrbvh_bvh *b = NULL, *c = NULL;
    const char *name;
    double ms;
    size_t i;
    int seen_sort = 0;
    char msg[256];
    REQUIRE_DEVICE();
    atrbvh_build_options_init(&o);
    o.backend = ATRBVH_BACKEND_OPENCL;
    b = tu_build(&g, &o);
    ck_assert_msg(tu_check_bvh(b, &g, msg, sizeof msg), "%s", msg);
    for (i = 0; atrbvh_bvh_kernel_time(b, i, &name, &ms); i++) {
        ck_assert(ms >= 0.0);
        seen_sort |= strcmp(name, "sort_scatter") == 0;
    }
    ck_assert(seen_sort);
    o.backend = ATRBVH_BACKEND_CPU;
    c = tu_build(&g, &o);
    ck_assert_str_eq(atrbvh_bvh_device(c), "cpu");
    ck_assert_int_eq(atrbvh_bvh_kernel_time(c, 0, &name, &ms), 0);
    ck_assert_msg(tu_same_bvh(b, c, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_free(b);
    atrbvh_bvh_free(c);
    free(v);
}
END_TEST

/* An LBVH's collapse sizes come out of the hierarchy kernel's refit
 * (atrbvh_refit_node_size), as on the CPU: neither the refit nor a
 * collapse kernel is launched, and the tree is the CPU's, with and
 * without collapse and with a leaf limit; an optimised build counts its
 * sizes from the decisions the hierarchy kernel made and the optimise
 * kernels kept (collapse_count, not the climb that decides from the
 * costs; its refit is the hierarchy kernel's too). */
static int launched(const atrbvh_bvh *b, const char *kernel)
{
    const char *name;
    double ms;
    size_t i;
    for (i = 0; atrbvh_bvh_kernel_time(b, i, &name, &ms); i++)
        if (strcmp(name, kernel) == 0)
            return 1;
    return 0;
}

START_TEST(lbvh_refit_takes_the_collapse)
{
    float *v = tu_random_triangles(30000, 11, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 90000, NULL, 30000);
    atrbvh_build_options o;
    atrbvh_bvh *b, *c;
    char msg[256];
    int k;
    REQUIRE_DEVICE();
    for (k = 0; k < 4; k++) {
        atrbvh_build_options_init(&o);
        o.method = k < 3 ? ATRBVH_METHOD_LBVH : ATRBVH_METHOD_ATRBVH;
        o.collapse = k != 1;
        if (k == 2)
            o.max_leaf_size = 2;
        b = tu_build(&g, &o);
        o.backend = ATRBVH_BACKEND_OPENCL;
        c = tu_build(&g, &o);
        ck_assert_msg(tu_same_bvh(b, c, msg, sizeof msg), "case %d: %s", k,
                      msg);
        ck_assert_msg(!launched(c, "refit"), "case %d: refit launched", k);
        ck_assert_msg(!launched(c, "collapse"),
                      "case %d: collapse kernel launched", k);
        ck_assert_msg(launched(c, "collapse_count") == (k == 3),
                      "case %d: collapse_count kernel %slaunched", k,
                      k == 3 ? "not " : "");
        atrbvh_bvh_free(b);
        atrbvh_bvh_free(c);
    }
    free(v);
}
END_TEST

/* The device sort (the MSD pass and sort_buckets, cl/kernels.cl) against
 * the CPU's on keys that stress the buckets, stage by stage (the sorted
 * keys and build indices are compared bit for bit): keys that differ in
 * 3 bits only, one bucket holding nearly all keys (many equal) beside a
 * few others, nested clusters that take a bucket many levels deep (more
 * than the levels whose counters are kept), all keys equal in a bucket
 * bigger than the MSD target, and n = 1, 2, 3.  Boxes in shuffled order,
 * so that equal keys must keep their input order. */
static void box_at(float *b, float x, float y, float z)
{
    const float h = 0.001f;
    b[0] = x - h;
    b[1] = y - h;
    b[2] = z - h;
    b[3] = x + h;
    b[4] = y + h;
    b[5] = z + h;
}

static void sorted_like_the_cpu(float *b, size_t n, tu_rng *r,
                                const char *what)
{
    static const config lbvh = {ATRBVH_METHOD_LBVH, 0, 0, 1};
    atrbvh_geometry g;
    size_t i;
    for (i = n; i > 1; i--) { /* shuffle */
        size_t j = (size_t)(tu_rng_next(r) % i), k;
        for (k = 0; k < 6; k++) {
            float t = b[6 * (i - 1) + k];
            b[6 * (i - 1) + k] = b[6 * j + k];
            b[6 * j + k] = t;
        }
    }
    g = atrbvh_geometry_boxes(b, n);
    expect_identical(&g, &lbvh, what);
}

START_TEST(device_sort_adversarial_keys)
{
    enum { N = 6000 };
    float *b = malloc(sizeof(float) * 6 * N);
    tu_rng r;
    size_t i, n;
    int k;
    REQUIRE_DEVICE();
    ck_assert_ptr_nonnull(b);
    tu_rng_seed(&r, 77);
    /* Keys in 8 values (a 2 x 2 x 2 grid): 3 varying bits. */
    for (i = 0; i < N; i++)
        box_at(b + 6 * i, (float)(tu_rng_next(&r) & 1u),
               (float)(tu_rng_next(&r) & 1u), (float)(tu_rng_next(&r) & 1u));
    sorted_like_the_cpu(b, N, &r, "3 varying bits");
    /* One crowded bucket: 5800 equal keys beside 200 random ones. */
    for (i = 0; i < N; i++)
        if (i < 200)
            box_at(b + 6 * i, tu_rng_float(&r), tu_rng_float(&r),
                   tu_rng_float(&r));
        else
            box_at(b + 6 * i, 0.5f, 0.5f, 0.5f);
    sorted_like_the_cpu(b, N, &r, "one crowded bucket");
    /* Nested clusters: 60 boxes at each of 2^-k (1, 1, 1), k = 0..21,
     * and the corner 0: each level of a bucket splits off one cluster. */
    n = 0;
    for (k = 0; k <= 21; k++)
        for (i = 0; i < 60; i++, n++) {
            const float x = 1.0f / (float)(1ul << k);
            box_at(b + 6 * n, x, x, x);
        }
    box_at(b + 6 * n++, 0.0f, 0.0f, 0.0f);
    sorted_like_the_cpu(b, n, &r, "nested clusters");
    /* All keys equal, more than a bucket's target. */
    for (i = 0; i < N; i++)
        box_at(b + 6 * i, 0.25f, 0.5f, 0.75f);
    sorted_like_the_cpu(b, N, &r, "all keys equal");
    /* n = 1, 2, 3, and 3 equal. */
    for (n = 1; n <= 3; n++) {
        for (i = 0; i < n; i++)
            box_at(b + 6 * i, tu_rng_float(&r), tu_rng_float(&r),
                   tu_rng_float(&r));
        sorted_like_the_cpu(b, n, &r, "1 to 3 boxes");
        for (i = 0; i < n; i++)
            box_at(b + 6 * i, 0.5f, 0.5f, 0.5f);
        sorted_like_the_cpu(b, n, &r, "1 to 3 equal boxes");
    }
    free(b);
}
END_TEST

/* A bucket of the first sort pass holding most keys (atrbvh_sort_big:
 * more than 17500 of 140000 on any device; cl/stages.c looks from 131072
 * primitives) is split by a pass of its own on every block (big_buckets,
 * sort_vary first), as the CPU's sort_big does, and the sort stays the
 * CPU's bit for bit: a dense cluster of distinct keys, and the same many
 * keys all equal (its own varying bits none); spread keys launch no
 * split. */
START_TEST(device_sort_splits_big_buckets)
{
    enum { N = 140000, DENSE = 126000 };
    float *b = malloc(sizeof(float) * 6 * N);
    atrbvh_build_options o;
    tu_rng r;
    size_t i;
    int pass;
    REQUIRE_DEVICE();
    ck_assert_ptr_nonnull(b);
    tu_rng_seed(&r, 99);
    for (pass = 0; pass < 3; pass++) {
        static const char *const what[3] = {"a dense cluster",
                                            "equal keys in one bucket",
                                            "spread keys"};
        atrbvh_geometry g;
        atrbvh_bvh *bvh;
        for (i = 0; i < N; i++) {
            const float d = pass == 0 ? 1e-3f * tu_rng_float(&r) : 0.0f;
            /* (away from the cell planes of the first pass's digit) */
            if (i < DENSE && pass < 2)
                box_at(b + 6 * i, 0.3f + d, 0.6f + 1e-3f * tu_rng_float(&r) *
                                                      (pass == 0),
                       0.7f + d * 0.5f);
            else
                box_at(b + 6 * i, tu_rng_float(&r), tu_rng_float(&r),
                       tu_rng_float(&r));
        }
        sorted_like_the_cpu(b, N, &r, what[pass]);
        g = atrbvh_geometry_boxes(b, N);
        atrbvh_build_options_init(&o);
        o.method = ATRBVH_METHOD_LBVH;
        o.backend = ATRBVH_BACKEND_OPENCL;
        bvh = tu_build(&g, &o);
        ck_assert_msg(launched(bvh, "sort_vary") == (pass < 2),
                      "%s: sort_vary %slaunched", what[pass],
                      pass < 2 ? "not " : "");
        atrbvh_bvh_free(bvh);
    }
    free(b);
}
END_TEST

#ifdef ATRBVH_KERNEL_SOURCE_OVERRIDE
/* A capture callback: the stages it was handed, as bits of *user. */
static int stages_seen(const atrbvh_stage_output *output, void *user)
{
    *(unsigned *)user |= 1u << output->stage;
    return 0;
}
#endif

/* A sort kernel that fails (sort_buckets returning at once, read from a
 * kernel folder as broken_kernel_source does): the hierarchy kernel finds
 * the keys out of order, and the build fails with ATRBVH_ERR_BACKEND and
 * the position, every method, build after build on the handle, instead of
 * the kernels behind it following a graph that is no tree out of bounds
 * (a SIGSEGV inside the build before).  Needs
 * --enable-kernel-source-override (the configs stage) and the source tree
 * ($ATRBVH_SRCDIR, from make check). */
START_TEST(sort_failure_is_an_error)
{
#ifdef ATRBVH_KERNEL_SOURCE_OVERRIDE
    static const atrbvh_method methods[] = {
        ATRBVH_METHOD_LBVH, ATRBVH_METHOD_ATRBVH, ATRBVH_METHOD_TRBVH};
    const char *srcdir = getenv("ATRBVH_SRCDIR");
    char path[1024];
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    atrbvh_status st;
    char *text, *at, *brace;
    long size;
    size_t i, k;
    float *b = malloc(sizeof(float) * 6 * 20000);
    tu_rng r;
    FILE *f;
    REQUIRE_DEVICE();
    ck_assert_ptr_nonnull(b);
    if (!srcdir) {
        fprintf(stderr, "SKIP sort_failure_is_an_error: ATRBVH_SRCDIR "
                        "unset (run it through make check)\n");
        free(b);
        return;
    }
    snprintf(path, sizeof path, "%s/cl/kernels.cl", srcdir);
    f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "%s", path);
    ck_assert_int_eq(fseek(f, 0, SEEK_END), 0);
    size = ftell(f);
    ck_assert_int_gt(size, 0);
    rewind(f);
    text = malloc((size_t)size + 1);
    ck_assert_ptr_nonnull(text);
    ck_assert_uint_eq(fread(text, 1, (size_t)size, f), (size_t)size);
    text[size] = '\0';
    fclose(f);
    at = strstr(text, "__kernel void sort_buckets(");
    ck_assert_ptr_nonnull(at);
    brace = strstr(at, "\n{\n");
    ck_assert_ptr_nonnull(brace);
    st = open_with_kernels(
        text, (size_t)(brace - text) + 3,
        "    if (get_global_id(0) < 0xffffffffu)\n        return;\n",
        brace + 3, NULL, &dev, &e);
    free(text);
    ck_assert_msg(st == ATRBVH_OK, "%s", e.text);
    tu_rng_seed(&r, 5);
    for (i = 0; i < 20000; i++)
        box_at(b + 6 * i, tu_rng_float(&r), tu_rng_float(&r),
               tu_rng_float(&r));
    for (k = 0; k < 2 * sizeof methods / sizeof methods[0]; k++) {
        atrbvh_geometry g = atrbvh_geometry_boxes(b, 20000);
        atrbvh_build_options o;
        atrbvh_bvh *bvh = (atrbvh_bvh *)&o;
        atrbvh_build_options_init(&o);
        o.method = methods[k % 3];
        o.device = dev;
        memset(&e, 0, sizeof e);
        st = atrbvh_build(&g, &o, &bvh, &e);
        ck_assert_msg(st == ATRBVH_ERR_BACKEND, "method %d: status %d: %s",
                      (int)o.method, (int)st, e.text);
        ck_assert_ptr_null(bvh);
        ck_assert_msg(strstr(e.text, "out of order at position"), "%s",
                      e.text);
        ck_assert_uint_lt(e.index, 20000);
    }
    {
        /* With a capture: the same error, and no stage from the
         * hierarchy on reaches the callback (the stand-in tree is not
         * the scene's hierarchy). */
        atrbvh_geometry g = atrbvh_geometry_boxes(b, 20000);
        atrbvh_build_options o;
        atrbvh_bvh *bvh = (atrbvh_bvh *)&o;
        unsigned seen = 0;
        atrbvh_build_options_init(&o);
        o.device = dev;
        o.capture = stages_seen;
        o.capture_user = &seen;
        st = atrbvh_build(&g, &o, &bvh, &e);
        ck_assert_msg(st == ATRBVH_ERR_BACKEND, "status %d: %s", (int)st,
                      e.text);
        ck_assert_ptr_null(bvh);
        ck_assert_msg(strstr(e.text, "out of order at position"), "%s",
                      e.text);
        ck_assert_uint_eq(seen, (1u << ATRBVH_STAGE_BOUNDS) |
                                    (1u << ATRBVH_STAGE_MORTON) |
                                    (1u << ATRBVH_STAGE_SORT));
    }
    atrbvh_device_close(dev);
    free(b);
#else
    fprintf(stderr, "SKIP sort_failure_is_an_error: configured without "
                    "--enable-kernel-source-override\n");
#endif
}
END_TEST

/* The refit in the hierarchy kernel's pass (cl/kernels.cl, as
 * lib/cpu/hierarchy.c): boxes, counts, costs and an LBVH's collapse sizes
 * of every node equal to the CPU's at every stage, where the blocks'
 * leftovers carry their subtrees to the merge: fewer splits than blocks
 * (one split a block), clusters of equal keys (deep stacks, the deltas
 * 64 .. 95) beside spread ones, boxes of random sizes (so that a box
 * taken from the wrong subtree shows); and no refit launch. */
START_TEST(hierarchy_refits_in_its_pass)
{
    static const size_t sizes[] = {2, 3, 5, 17, 33, 34, 100, 2500};
    static const config cfgs[] = {{ATRBVH_METHOD_LBVH, 0, 0, 1},
                                  {ATRBVH_METHOD_LBVH, 0, 0, 0},
                                  {ATRBVH_METHOD_ATRBVH, 9, 2, 1}};
    float *b = malloc(sizeof(float) * 6 * 2500);
    tu_rng r;
    size_t s, i, k, c;
    REQUIRE_DEVICE();
    ck_assert_ptr_nonnull(b);
    tu_rng_seed(&r, 4242);
    for (s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        const size_t n = sizes[s];
        atrbvh_geometry g;
        atrbvh_build_options o;
        atrbvh_bvh *bvh;
        char what[64];
        for (i = 0; i < n; i++) {
            /* a third at one of 3 points, the rest spread */
            float p[3], h;
            const unsigned pick = (unsigned)(tu_rng_next(&r) % 9u);
            for (k = 0; k < 3; k++)
                p[k] = pick < 3 ? 0.25f * (float)(pick + 1)
                                : tu_rng_float(&r);
            h = 0.001f + 0.05f * tu_rng_float(&r);
            for (k = 0; k < 3; k++) {
                b[6 * i + k] = p[k] - h * (float)(k + 1);
                b[6 * i + 3 + k] = p[k] + h;
            }
        }
        g = atrbvh_geometry_boxes(b, n);
        for (c = 0; c < sizeof cfgs / sizeof cfgs[0]; c++) {
            snprintf(what, sizeof what, "%lu clustered boxes",
                     (unsigned long)n);
            expect_identical(&g, &cfgs[c], what);
            atrbvh_build_options_init(&o);
            o.method = cfgs[c].method;
            o.treelet_size = cfgs[c].treelet;
            o.rounds = cfgs[c].rounds;
            o.collapse = cfgs[c].collapse;
            o.backend = ATRBVH_BACKEND_OPENCL;
            bvh = tu_build(&g, &o);
            ck_assert_msg(!launched(bvh, "refit") && launched(bvh, "hierarchy"),
                          "%s: refit launched", what);
            atrbvh_bvh_free(bvh);
        }
    }
    free(b);
}
END_TEST

/* ------------------------------------------------ invalid primitives, late */
/* Cancels at the stage named by `user` (the bounds stage has run). */
static int cancel_at(const char *stage, double fraction, void *user)
{
    (void)fraction;
    return strcmp(stage, (const char *)user) == 0;
}

/* One build of g on the CPU and on dev (no capture: on the device the
 * bounds stage leaves its invalid count on the device and the collapse
 * stage's read brings it, cl/stages.c): the same status, index and text. */
static void same_error(const atrbvh_geometry *g, atrbvh_build_options *o,
                       atrbvh_device *dev, atrbvh_status want,
                       const char *what)
{
    atrbvh_error e1, e2;
    atrbvh_bvh *x = NULL, *y = NULL;
    atrbvh_status s1, s2;
    o->device = NULL;
    s1 = atrbvh_build(g, o, &x, &e1);
    o->device = dev;
    s2 = atrbvh_build(g, o, &y, &e2);
    ck_assert_msg(s1 == want, "%s: the CPU gave %s (%s)", what,
                  atrbvh_strerror(s1), e1.text);
    ck_assert_msg(s2 == s1, "%s: %s (%s) on the device, %s on the CPU", what,
                  atrbvh_strerror(s2), e2.text, atrbvh_strerror(s1));
    ck_assert_msg(strcmp(e1.text, e2.text) == 0 && e1.index == e2.index,
                  "%s: \"%s\" at %lu on the device, \"%s\" at %lu on "
                  "the CPU",
                  what, e2.text, (unsigned long)e2.index, e1.text,
                  (unsigned long)e1.index);
    ck_assert_ptr_null(x);
    ck_assert_ptr_null(y);
}

/* Since the Morton frame is the device's, an invalid primitive is found
 * after the build's first wait (the root size), not after bounds: the
 * error must still be the CPU's (code, index, text) for NaN/Inf, a bad
 * vertex index, an inverted box, for an LBVH and an optimised build,
 * also when the build is cancelled or fails before that wait (the host
 * then looks first), and the handle builds the next scene as the CPU. */
START_TEST(invalid_found_late)
{
    enum { N = 2000 };
    atrbvh_device *dev = NULL;
    atrbvh_build_options o;
    atrbvh_geometry g;
    atrbvh_error e;
    atrbvh_bvh *x, *y;
    float *v, b[6 * 64];
    uint32_t *idx;
    size_t k;
    int m;
    REQUIRE_DEVICE();
    ck_assert_int_eq(atrbvh_device_open("opencl", &dev, &e), ATRBVH_OK);
    v = tu_random_triangles(N, 29, 2.0f, -1.0f);
    idx = malloc(3 * (size_t)N * sizeof *idx);
    ck_assert_ptr_nonnull(idx);
    for (k = 0; k < 3 * (size_t)N; k++)
        idx[k] = (uint32_t)k;
    for (m = 0; m < 2; m++) {
        atrbvh_build_options_init(&o);
        o.method = m ? ATRBVH_METHOD_ATRBVH : ATRBVH_METHOD_LBVH;
        v[9 * 1500 + 2] = 0.0f / 0.0f; /* NaN, then Inf lower down */
        v[9 * 777 + 7] = -1.0f / 0.0f;
        g = atrbvh_geometry_triangles(v, 3 * N, NULL, N);
        same_error(&g, &o, dev, ATRBVH_ERR_NONFINITE, "NaN and Inf");
        o.progress = cancel_at;
        o.progress_user = (void *)"morton";
        same_error(&g, &o, dev, ATRBVH_ERR_NONFINITE, "cancelled at morton");
        o.progress_user = (void *)"collapse";
        same_error(&g, &o, dev, ATRBVH_ERR_NONFINITE,
                   "cancelled at collapse");
        o.progress = NULL;
        v[9 * 1500 + 2] = 0.5f;
        v[9 * 777 + 7] = 0.5f;
        idx[3 * 1234 + 1] = 3 * N + 5; /* a bad index, and NaN above it */
        v[9 * 1600 + 4] = 0.0f / 0.0f;
        g = atrbvh_geometry_triangles(v, 3 * N, idx, N);
        same_error(&g, &o, dev, ATRBVH_ERR_INDEX_RANGE, "bad index");
        idx[3 * 1234 + 1] = 3 * 1234 + 1;
        v[9 * 1600 + 4] = 0.5f;
        for (k = 0; k < 64; k++)
            box_at(b + 6 * k, (float)k, (float)(k % 5), 1.0f);
        b[6 * 40 + 1] = b[6 * 40 + 4] + 1.0f; /* min above max */
        g = atrbvh_geometry_boxes(b, 64);
        same_error(&g, &o, dev, ATRBVH_ERR_INVALID_ARGUMENT, "inverted box");
        /* valid again: the handle's next build is the CPU's */
        g = atrbvh_geometry_triangles(v, 3 * N, idx, N);
        o.device = NULL;
        x = tu_build(&g, &o);
        o.device = dev;
        y = tu_build(&g, &o);
        ck_assert_msg(atrbvh_compare(x, y, &e) == 0, "after the errors: %s",
                      e.text);
        atrbvh_bvh_free(x);
        atrbvh_bvh_free(y);
    }
    free(idx);
    free(v);
    atrbvh_device_close(dev);
}
END_TEST

static Suite *opencl_suite(void)
{
    Suite *s = suite_create("opencl");
    TCase *tc;
    tc = tcase_create("generated");
    tcase_add_test(tc, generated_full_matrix);
    tcase_add_test(tc, generated_builtin_scenes);
    tcase_add_test(tc, large_and_auto_treelets);
    tcase_set_timeout(tc, 300);
    suite_add_tcase(s, tc);
    tc = tcase_create("extremes");
    tcase_add_test(tc, extremes_flat_and_coincident);
    tcase_add_test(tc, extremes_boxes_and_invalid);
    tcase_add_test(tc, bounds_eight_at_a_time);
    tcase_add_test(tc, device_sort_adversarial_keys);
    tcase_set_timeout(tc, 300);
    suite_add_tcase(s, tc);
    tc = tcase_create("scenes");
    tcase_add_test(tc, real_scenes);
    tcase_set_timeout(tc, 600);
    suite_add_tcase(s, tc);
    tc = tcase_create("errors");
    tcase_add_test(tc, bad_device_string);
    tcase_add_test(tc, broken_kernel_source);
    tcase_add_test(tc, no_environment);
    tcase_add_test(tc, sort_failure_is_an_error);
    tcase_add_test(tc, device_handle);
    tcase_add_test(tc, kernel_times_and_device);
    tcase_add_test(tc, rebuild_on_device);
    tcase_add_test(tc, lbvh_refit_takes_the_collapse);
    tcase_add_test(tc, device_sort_splits_big_buckets);
    tcase_add_test(tc, hierarchy_refits_in_its_pass);
    tcase_add_test(tc, invalid_found_late);
    tcase_set_timeout(tc, 120);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    /* Twice: on a device that shares the host's memory (PoCL's) a build
     * reads the geometry and writes the output in place, and with
     * ATRBVH_CL_COPY set when a test opens the device it copies them as
     * on a device with its own memory (cl/stages.c).  On a CPU device
     * the optimise stage's items take several treelets at once
     * (opt_round4); the second pass sets ATRBVH_CL_WALKS=1 too, so a GPU's
     * kernel (opt_round, one at a time) keeps its coverage on PoCL. */
    int failed = 0, pass;
    for (pass = 0; pass < 2; pass++) {
        SRunner *sr = srunner_create(opencl_suite());
        if (pass == 1 && (setenv("ATRBVH_CL_COPY", "1", 1) != 0 ||
                          setenv("ATRBVH_CL_WALKS", "1", 1) != 0))
            return 1;
        srunner_run_all(sr, CK_ENV);
        failed += srunner_ntests_failed(sr);
        srunner_free(sr);
    }
    return failed ? 1 : 0;
}
