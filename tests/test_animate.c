/*
 * test_animate.c - atrbvh_refit and atrbvh_reoptimise: refitted boxes
 * equal the boxes recomputed by brute force from the primitives (and
 * refitting to the built positions gives the built tree back), topology
 * kept; re-optimising never raises the SAH and gives the same bits for any
 * thread count; a primitive count, index or coordinate fault is an error
 * with the tree unchanged; every allocation failing in turn leaves the
 * tree as it was and nothing leaked; on an open device a frame allocates
 * no scratch.  tests/test_opencl.c-style cross-backend frames are in
 * cross_backend (skipped without OpenCL).
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atrbvh.h"
#include "testutil.h"

enum { T = 3000 };

/* A deforming soup: frame 0 is tu_random_triangles; frame f moves every
 * vertex by a smooth field plus a per-triangle drift (so that the tree
 * goes stale). */
static void frame_of(const float *base, float *out, size_t tris, int f)
{
    size_t i;
    for (i = 0; i < tris * 9; i += 3) {
        const size_t t = i / 9;
        const float s = 0.05f * (float)f;
        const float x = base[i], y = base[i + 1], z = base[i + 2];
        out[i] = x + 0.1f * sinf(6.0f * y + s) + s * (float)(t % 7) * 0.02f;
        out[i + 1] = y + 0.1f * cosf(5.0f * z + s);
        out[i + 2] = z + 0.1f * sinf(4.0f * x - s) - s * (float)(t % 5) * 0.02f;
    }
}

static void options(atrbvh_build_options *o, int threads)
{
    atrbvh_build_options_init(o);
    o->collapse = 1;
    o->max_leaf_size = 8;
    o->threads = threads;
}

static void tri_box(const float *v, uint32_t t, float mn[3], float mx[3])
{
    int c, k;
    for (k = 0; k < 3; k++) {
        mn[k] = INFINITY;
        mx[k] = -INFINITY;
    }
    for (c = 0; c < 3; c++)
        for (k = 0; k < 3; k++) {
            float x = v[9 * (size_t)t + 3 * (size_t)c + (size_t)k];
            if (x < mn[k])
                mn[k] = x;
            if (x > mx[k])
                mx[k] = x;
        }
}

/* Brute force: node i's box is the union of the boxes of every primitive
 * in its subtree (the leaves reached from it, found with a stack). */
static int boxes_exact(const atrbvh_bvh *b, const float *v, char *msg,
                       size_t len)
{
    size_t count, pc, i;
    const atrbvh_node *n = atrbvh_bvh_nodes(b, &count);
    const uint32_t *p = atrbvh_bvh_primitive_indices(b, &pc);
    size_t *stack = malloc(count * sizeof *stack);
    for (i = 0; i < count; i++) {
        float mn[3] = {INFINITY, INFINITY, INFINITY};
        float mx[3] = {-INFINITY, -INFINITY, -INFINITY};
        size_t top = 0;
        int k;
        stack[top++] = i;
        while (top) {
            const size_t j = stack[--top];
            if (n[j].count == 0) {
                stack[top++] = j + 1;
                stack[top++] = n[j].index;
                continue;
            }
            {
                uint32_t q;
                for (q = 0; q < n[j].count; q++) {
                    float a[3], z[3];
                    tri_box(v, p[n[j].index + q], a, z);
                    for (k = 0; k < 3; k++) {
                        mn[k] = a[k] < mn[k] ? a[k] : mn[k];
                        mx[k] = z[k] > mx[k] ? z[k] : mx[k];
                    }
                }
            }
        }
        for (k = 0; k < 3; k++)
            if (n[i].min[k] != mn[k] || n[i].max[k] != mx[k]) {
                snprintf(msg, len, "node %lu axis %d: [%g, %g], brute force "
                         "[%g, %g]",
                         (unsigned long)i, k, n[i].min[k], n[i].max[k], mn[k],
                         mx[k]);
                free(stack);
                return 0;
            }
    }
    free(stack);
    return 1;
}

/* Node array and SAH snapshot. */
typedef struct snap {
    atrbvh_node *nodes;
    uint32_t *prims;
    size_t count, pc;
    double sah;
} snap;
static void snap_take(snap *s, const atrbvh_bvh *b)
{
    const atrbvh_node *n = atrbvh_bvh_nodes(b, &s->count);
    const uint32_t *p = atrbvh_bvh_primitive_indices(b, &s->pc);
    atrbvh_stats st;
    s->nodes = malloc(s->count * sizeof *n);
    s->prims = malloc(s->pc * sizeof *p);
    memcpy(s->nodes, n, s->count * sizeof *n);
    memcpy(s->prims, p, s->pc * sizeof *p);
    atrbvh_bvh_stats(b, &st);
    s->sah = st.sah;
}
static int snap_same(const snap *s, const atrbvh_bvh *b)
{
    size_t count, pc;
    const atrbvh_node *n = atrbvh_bvh_nodes(b, &count);
    const uint32_t *p = atrbvh_bvh_primitive_indices(b, &pc);
    atrbvh_stats st;
    atrbvh_bvh_stats(b, &st);
    return count == s->count && pc == s->pc &&
           memcmp(n, s->nodes, count * sizeof *n) == 0 &&
           memcmp(p, s->prims, pc * sizeof *p) == 0 && st.sah == s->sah;
}
static void snap_free(snap *s)
{
    free(s->nodes);
    free(s->prims);
}

START_TEST(refit_equals_brute_force)
{
    float *base = tu_random_triangles(T, 11, 1.0f, 0.0f);
    float *v = malloc((size_t)T * 9 * sizeof *v);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    atrbvh_build_options o;
    atrbvh_bvh *b, *fresh;
    atrbvh_error e;
    atrbvh_stats st;
    char msg[256];
    snap built;
    int f;
    size_t i;
    options(&o, 2);
    frame_of(base, v, T, 0);
    b = tu_build(&g, &o);
    snap_take(&built, b);
    for (f = 1; f <= 5; f++) {
        const atrbvh_node *n;
        size_t count;
        frame_of(base, v, T, 7 * f);
        ck_assert_int_eq(atrbvh_refit(b, &g, &o, &e), ATRBVH_OK);
        n = atrbvh_bvh_nodes(b, &count);
        ck_assert_uint_eq(count, built.count);
        for (i = 0; i < count; i++) { /* topology kept */
            ck_assert_uint_eq(n[i].index, built.nodes[i].index);
            ck_assert_uint_eq(n[i].count, built.nodes[i].count);
        }
        ck_assert_msg(boxes_exact(b, v, msg, sizeof msg), "frame %d: %s", f,
                      msg);
        ck_assert_msg(tu_check_bvh(b, &g, msg, sizeof msg), "%s", msg);
        atrbvh_bvh_stats(b, &st);
        ck_assert(st.sah_built == built.sah);
        ck_assert(st.sah != built.sah);
    }
    /* Back to the built positions: the built tree, bit for bit. */
    frame_of(base, v, T, 0);
    ck_assert_int_eq(atrbvh_refit(b, &g, NULL, &e), ATRBVH_OK);
    ck_assert(snap_same(&built, b));
    fresh = tu_build(&g, &o);
    ck_assert_msg(tu_same_bvh(fresh, b, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_free(fresh);
    snap_free(&built);
    atrbvh_bvh_free(b);
    free(base);
    free(v);
}
END_TEST

/* Above 2^17 primitives the refit's leaf pass runs on several threads:
 * the same boxes as one thread, and the lowest faulty primitive named. */
START_TEST(refit_parallel_pass)
{
    enum { N = 300000 };
    float *base = tu_random_triangles(N, 18, 1.0f, 0.0f);
    float *v = malloc((size_t)N * 9 * sizeof *v);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * (size_t)N, NULL, N);
    atrbvh_build_options o1, o3;
    atrbvh_bvh *a, *b;
    atrbvh_error e;
    char msg[256];
    snap s;
    float keep1, keep2;
    options(&o1, 1);
    options(&o3, 3);
    o1.method = o3.method = ATRBVH_METHOD_LBVH;
    frame_of(base, v, N, 0);
    a = tu_build(&g, &o1);
    b = tu_build(&g, &o1);
    frame_of(base, v, N, 8);
    ck_assert_int_eq(atrbvh_refit(a, &g, &o1, &e), ATRBVH_OK);
    ck_assert_int_eq(atrbvh_refit(b, &g, &o3, &e), ATRBVH_OK);
    ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg), "%s", msg);
    ck_assert_msg(tu_check_bvh(b, &g, msg, sizeof msg), "%s", msg);
    snap_take(&s, b);
    keep1 = v[9 * 250000 + 1];
    keep2 = v[9 * 1000 + 8];
    v[9 * 250000 + 1] = NAN;
    v[9 * 1000 + 8] = -INFINITY;
    ck_assert_int_eq(atrbvh_refit(b, &g, &o3, &e), ATRBVH_ERR_NONFINITE);
    ck_assert_uint_eq(e.index, 1000);
    ck_assert(snap_same(&s, b));
    v[9 * 250000 + 1] = keep1;
    v[9 * 1000 + 8] = keep2;
    snap_free(&s);
    atrbvh_bvh_free(a);
    atrbvh_bvh_free(b);
    free(base);
    free(v);
}
END_TEST

static const atrbvh_method methods[3] = {
    ATRBVH_METHOD_ATRBVH, ATRBVH_METHOD_TRBVH, ATRBVH_METHOD_LBVH};

START_TEST(reoptimise_never_raises_sah)
{
    float *base = tu_random_triangles(T, 12, 1.0f, 0.0f);
    float *v = malloc((size_t)T * 9 * sizeof *v);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    atrbvh_build_options o;
    atrbvh_bvh *b;
    atrbvh_error e;
    char msg[256];
    int f, lowered = 0;
    options(&o, 2);
    frame_of(base, v, T, 0);
    b = tu_build(&g, &o);
    o.method = methods[_i];
    o.rounds = 1;
    for (f = 1; f <= 8; f++) {
        atrbvh_stats before, after;
        frame_of(base, v, T, 6 * f);
        ck_assert_int_eq(atrbvh_refit(b, &g, &o, &e), ATRBVH_OK);
        atrbvh_bvh_stats(b, &before);
        ck_assert_msg(atrbvh_reoptimise(b, &g, &o, &e) == ATRBVH_OK, "%s",
                      e.text);
        atrbvh_bvh_stats(b, &after);
        ck_assert_msg(tu_check_bvh(b, &g, msg, sizeof msg), "%s", msg);
        ck_assert_msg(boxes_exact(b, v, msg, sizeof msg), "%s", msg);
        /* atrbvh_sah sums in node order: allow its last bits. */
        ck_assert_msg(after.sah <= before.sah * (1.0 + 1e-12),
                      "frame %d: SAH %.17g after re-optimising, %.17g before",
                      f, after.sah, before.sah);
        ck_assert(after.sah_built == after.sah);
        lowered += after.sah < before.sah * (1.0 - 1e-6);
    }
    /* The treelets found something to improve (not a no-op). */
    if (methods[_i] != ATRBVH_METHOD_LBVH)
        ck_assert_int_gt(lowered, 4);
    atrbvh_bvh_free(b);
    free(base);
    free(v);
}
END_TEST

/* Same frames with 1 and 3 threads: the same bits. */
START_TEST(reoptimise_thread_count)
{
    float *base = tu_random_triangles(T, 13, 1.0f, 0.0f);
    float *v = malloc((size_t)T * 9 * sizeof *v);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    atrbvh_build_options o1, o3;
    atrbvh_bvh *a, *b;
    atrbvh_error e;
    char msg[256];
    int f;
    options(&o1, 1);
    options(&o3, 3);
    frame_of(base, v, T, 0);
    a = tu_build(&g, &o1);
    b = tu_build(&g, &o3);
    for (f = 1; f <= 4; f++) {
        frame_of(base, v, T, 9 * f);
        ck_assert_int_eq(atrbvh_refit(a, &g, &o1, &e), ATRBVH_OK);
        ck_assert_int_eq(atrbvh_refit(b, &g, &o3, &e), ATRBVH_OK);
        ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg), "%s", msg);
        ck_assert_int_eq(atrbvh_reoptimise(a, &g, &o1, &e), ATRBVH_OK);
        ck_assert_int_eq(atrbvh_reoptimise(b, &g, &o3, &e), ATRBVH_OK);
        ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg), "%s", msg);
    }
    atrbvh_bvh_free(a);
    atrbvh_bvh_free(b);
    free(base);
    free(v);
}
END_TEST

/* tu_chain_bvh_bytes's chain, loaded. */
static atrbvh_bvh *chain_bvh(const float *v, size_t leaves)
{
    size_t n;
    unsigned char *d = tu_chain_bvh_bytes(v, leaves, &n);
    atrbvh_bvh *b = NULL;
    atrbvh_error e;
    ck_assert(d);
    ck_assert_msg(atrbvh_load_memory(d, n, &b, &e) == ATRBVH_OK, "%s", e.text);
    free(d);
    return b;
}

/* Re-optimising a chain 6000 levels deep: the same bits for 1 to 4
 * threads.  The collapse and layout stages cut the tree at a top of about
 * n / (32 x threads) primitives and run the subtrees below it on the
 * threads; on the chain (LBVH: no treelet rounds, the chain stays) those
 * subtrees, one leaf per top node, are more than their lists hold (512
 * per thread), so each stage takes its one-thread walk, with several
 * threads; ATRBVH and TRBVH restructure the chain first (the optimise
 * stage's frontier then has one subtree: its one-thread walk too). */
START_TEST(reoptimise_chain)
{
    const size_t leaves = 6001;
    float *v = tu_random_triangles((uint32_t)leaves, 31, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * leaves, NULL,
                                                  leaves);
    atrbvh_bvh *ref = NULL;
    atrbvh_error e;
    char msg[256];
    int m, threads;
    for (m = 0; m < 3; m++) {
        for (threads = 1; threads <= 4; threads++) {
            atrbvh_build_options o;
            atrbvh_bvh *b = chain_bvh(v, leaves);
            atrbvh_stats st;
            atrbvh_bvh_stats(b, &st);
            ck_assert_uint_eq(st.max_depth, leaves - 1);
            options(&o, threads);
            o.method = m == 0   ? ATRBVH_METHOD_LBVH
                       : m == 1 ? ATRBVH_METHOD_ATRBVH
                                : ATRBVH_METHOD_TRBVH;
            ck_assert_msg(atrbvh_reoptimise(b, &g, &o, &e) == ATRBVH_OK, "%s",
                          e.text);
            atrbvh_bvh_stats(b, &st);
            ck_assert_uint_eq(st.primitives, leaves);
            /* LBVH: still a chain (the collapse only ends it in leaves of
             * up to 8), so the lists overflowed */
            if (m == 0)
                ck_assert_uint_gt(st.max_depth, leaves - 10);
            if (threads == 1) {
                ref = b;
                continue;
            }
            ck_assert_msg(tu_same_bvh(ref, b, msg, sizeof msg),
                          "%s, %d threads: %s",
                          m == 0 ? "LBVH" : m == 1 ? "ATRBVH" : "TRBVH",
                          threads, msg);
            atrbvh_bvh_free(b);
        }
        atrbvh_bvh_free(ref);
        ref = NULL;
    }
    free(v);
}
END_TEST

/* Count, index and coordinate faults: a clear error, the tree as it was. */
START_TEST(faults_leave_tree)
{
    float *v = tu_random_triangles(T, 14, 1.0f, 0.0f);
    uint32_t *idx = malloc((size_t)T * 3 * sizeof *idx);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T), h;
    atrbvh_build_options o;
    atrbvh_bvh *b;
    atrbvh_error e;
    snap s;
    int which;
    size_t i;
    options(&o, 2);
    b = tu_build(&g, &o);
    snap_take(&s, b);
    for (which = 0; which < 2; which++) {
        atrbvh_status (*fn)(atrbvh_bvh *, const atrbvh_geometry *,
                            const atrbvh_build_options *, atrbvh_error *) =
            which ? atrbvh_reoptimise : atrbvh_refit;
        float keep, keep2;
        h = g;
        h.primitive_count = T - 1;
        ck_assert_int_eq(fn(b, &h, &o, &e), ATRBVH_ERR_INVALID_ARGUMENT);
        ck_assert_ptr_nonnull(strstr(e.text, "primitives"));
        ck_assert(snap_same(&s, b));
        ck_assert_int_eq(fn(NULL, &g, &o, &e), ATRBVH_ERR_INVALID_ARGUMENT);
        keep = v[9 * 123 + 4];
        v[9 * 123 + 4] = NAN;
        keep2 = v[9 * 2000];
        v[9 * 2000] = INFINITY;
        ck_assert_int_eq(fn(b, &g, &o, &e), ATRBVH_ERR_NONFINITE);
        ck_assert_uint_eq(e.index, 123);
        ck_assert(snap_same(&s, b));
        v[9 * 123 + 4] = keep;
        v[9 * 2000] = keep2;
        /* Indexed: a vertex index past the end. */
        for (i = 0; i < 3 * (size_t)T; i++)
            idx[i] = (uint32_t)i;
        h = atrbvh_geometry_triangles(v, 3 * T, idx, T);
        idx[3 * 77 + 2] = 3 * T;
        ck_assert_int_eq(fn(b, &h, &o, &e), ATRBVH_ERR_INDEX_RANGE);
        ck_assert_uint_eq(e.index, 77);
        ck_assert(snap_same(&s, b));
    }
    snap_free(&s);
    atrbvh_bvh_free(b);
    free(idx);
    free(v);
}
END_TEST

/* Every allocation of a refit or a re-optimise failing in turn (without a
 * device and with one): ATRBVH_ERR_NOMEM, the tree unchanged, no leak. */
START_TEST(allocation_failure_keeps_tree)
{
    float *base = tu_random_triangles(T, 15, 1.0f, 0.0f);
    float *v = malloc((size_t)T * 9 * sizeof *v);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    atrbvh_build_options o;
    atrbvh_bvh *b;
    int which = _i & 1, with_device = _i >> 1;
    long k;
    options(&o, 2);
    frame_of(base, v, T, 0);
    b = tu_build(&g, &o);
    frame_of(base, v, T, 20);
    for (k = 0;; k++) {
        atrbvh_device *d = NULL;
        atrbvh_error e;
        atrbvh_status st;
        snap s;
        snap_take(&s, b);
        atrbvh_set_allocator(tu_count_malloc, tu_count_free);
        tu_count_reset(k);
        st = with_device ? atrbvh_device_open("cpu", &d, &e) : ATRBVH_OK;
        o.device = d;
        if (st == ATRBVH_OK)
            st = which ? atrbvh_reoptimise(b, &g, &o, &e)
                       : atrbvh_refit(b, &g, &o, &e);
        atrbvh_device_close(d);
        tu_alloc.countdown = -1;
        atrbvh_set_allocator(NULL, NULL);
        o.device = NULL;
        if (st == ATRBVH_OK) {
            char msg[256];
            ck_assert_msg(tu_check_bvh(b, &g, msg, sizeof msg), "%s", msg);
            ck_assert_int_gt(k, 0);
            snap_free(&s);
            break;
        }
        ck_assert_msg(st == ATRBVH_ERR_NOMEM, "allocation %ld: %s", k, e.text);
        ck_assert_msg(snap_same(&s, b), "allocation %ld changed the tree", k);
        ck_assert_msg(tu_alloc.outstanding == 0, "allocation %ld: %ld leaked",
                      k, tu_alloc.outstanding);
        snap_free(&s);
    }
    atrbvh_bvh_free(b);
    free(base);
    free(v);
}
END_TEST

/* On an open device, once a frame made the scratch, the next frames
 * allocate nothing (refit) or only small per-call state (re-optimise:
 * no array of the primitive count). */
START_TEST(frames_allocate_no_scratch)
{
    float *base = tu_random_triangles(T, 16, 1.0f, 0.0f);
    float *v = malloc((size_t)T * 9 * sizeof *v);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    atrbvh_build_options o;
    atrbvh_device *d;
    atrbvh_bvh *b;
    atrbvh_error e;
    size_t first;
    int f;
    options(&o, 2);
    ck_assert_int_eq(atrbvh_device_open("cpu", &d, &e), ATRBVH_OK);
    o.device = d;
    frame_of(base, v, T, 0);
    b = tu_build(&g, &o);
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    tu_alloc.total_bytes = 0;
    frame_of(base, v, T, 1);
    ck_assert_int_eq(atrbvh_refit(b, &g, &o, &e), ATRBVH_OK);
    ck_assert_uint_gt(tu_alloc.total_bytes, (size_t)T); /* the boxes' scratch */
    for (f = 2; f < 5; f++) {
        tu_alloc.total_bytes = 0;
        frame_of(base, v, T, f);
        ck_assert_int_eq(atrbvh_refit(b, &g, &o, &e), ATRBVH_OK);
        ck_assert_uint_eq(tu_alloc.total_bytes, 0);
    }
    tu_alloc.total_bytes = 0;
    ck_assert_int_eq(atrbvh_reoptimise(b, &g, &o, &e), ATRBVH_OK);
    first = tu_alloc.total_bytes;
    for (f = 5; f < 10; f++) {
        tu_alloc.total_bytes = 0;
        frame_of(base, v, T, f);
        ck_assert_int_eq(atrbvh_refit(b, &g, &o, &e), ATRBVH_OK);
        ck_assert_int_eq(atrbvh_reoptimise(b, &g, &o, &e), ATRBVH_OK);
        ck_assert_msg(tu_alloc.total_bytes < (size_t)T,
                      "frame %d allocated %lu bytes (first %lu)", f,
                      (unsigned long)tu_alloc.total_bytes,
                      (unsigned long)first);
    }
    atrbvh_set_allocator(NULL, NULL);
    atrbvh_bvh_free(b);
    atrbvh_device_close(d);
    free(base);
    free(v);
}
END_TEST

/* CPU and OpenCL: the same tree after every frame's refit and
 * re-optimise. */
START_TEST(cross_backend)
{
    float *base = tu_random_triangles(T, 17, 1.0f, 0.0f);
    float *v = malloc((size_t)T * 9 * sizeof *v);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    atrbvh_build_options oc, og;
    atrbvh_device *dc, *dg = NULL;
    atrbvh_bvh *a, *b;
    atrbvh_error e;
    atrbvh_status st;
    char msg[256];
    int f;
    st = atrbvh_device_open("opencl", &dg, &e);
    if (st != ATRBVH_OK) {
        ck_assert_msg(tu_opencl_may_skip(st), "the OpenCL backend failed: %s",
                      e.text);
        fprintf(stderr, "cross_backend: no OpenCL device (%s), skipped\n",
                e.text);
        free(base);
        free(v);
        return;
    }
    ck_assert_int_eq(atrbvh_device_open("cpu", &dc, &e), ATRBVH_OK);
    options(&oc, 2);
    options(&og, 2);
    oc.device = dc;
    og.device = dg;
    frame_of(base, v, T, 0);
    a = tu_build(&g, &oc);
    b = tu_build(&g, &og);
    ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg), "%s", msg);
    for (f = 1; f <= 10; f++) {
        frame_of(base, v, T, 5 * f);
        ck_assert_int_eq(atrbvh_refit(a, &g, &oc, &e), ATRBVH_OK);
        ck_assert_int_eq(atrbvh_refit(b, &g, &og, &e), ATRBVH_OK);
        ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg), "refit %d: %s", f,
                      msg);
        ck_assert_int_eq(atrbvh_reoptimise(a, &g, &oc, &e), ATRBVH_OK);
        ck_assert_msg(atrbvh_reoptimise(b, &g, &og, &e) == ATRBVH_OK, "%s",
                      e.text);
        ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg), "reoptimise %d: %s",
                      f, msg);
        if (f >= 2) {
            /* The OpenCL device's frames allocate no host array of the
             * primitive count either. */
            frame_of(base, v, T, 5 * f + 1);
            atrbvh_set_allocator(tu_count_malloc, tu_count_free);
            tu_alloc.total_bytes = 0;
            ck_assert_int_eq(atrbvh_refit(b, &g, &og, &e), ATRBVH_OK);
            ck_assert_uint_eq(tu_alloc.total_bytes, 0);
            ck_assert_int_eq(atrbvh_reoptimise(b, &g, &og, &e), ATRBVH_OK);
            atrbvh_set_allocator(NULL, NULL);
            ck_assert_msg(tu_alloc.total_bytes < (size_t)T,
                          "OpenCL frame %d allocated %lu bytes", f,
                          (unsigned long)tu_alloc.total_bytes);
            ck_assert_int_eq(atrbvh_refit(a, &g, &oc, &e), ATRBVH_OK);
            ck_assert_int_eq(atrbvh_reoptimise(a, &g, &oc, &e), ATRBVH_OK);
            ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg), "%s", msg);
        }
    }
    atrbvh_bvh_free(a);
    atrbvh_bvh_free(b);
    atrbvh_device_close(dc);
    atrbvh_device_close(dg);
    free(base);
    free(v);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("animate");
    TCase *t = tcase_create("animate");
    tcase_set_timeout(t, 600);
    tcase_add_test(t, refit_equals_brute_force);
    tcase_add_test(t, refit_parallel_pass);
    tcase_add_loop_test(t, reoptimise_never_raises_sah, 0, 3);
    tcase_add_test(t, reoptimise_thread_count);
    tcase_add_test(t, reoptimise_chain);
    tcase_add_test(t, faults_leave_tree);
    tcase_add_loop_test(t, allocation_failure_keeps_tree, 0, 4);
    tcase_add_test(t, frames_allocate_no_scratch);
    tcase_add_test(t, cross_backend);
    suite_add_tcase(s, t);
    return s;
}

int main(void)
{
    return tu_run(suite());
}
