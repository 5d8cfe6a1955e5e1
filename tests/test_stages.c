/*
 * test_stages.c - internal stages checked on their own (links the static
 * core): the radix sort against an independent stable reference, the
 * hierarchy against the per-node Karras search, its refit in the same
 * pass against the refit's climb, the Morton key properties, and the
 * statistics walk after a build on trees deeper than its stack.
 */
#include "config.h" /* ATRBVH_DEBUG_CHECKS */

#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "cpu/cpu.h"
#include "testutil.h"
#include "scene.h"

typedef struct pair {
    uint64_t k;
    uint32_t v;
} pair;

/* Stable by construction: values are the input positions, compared last. */
static int cmp_pair(const void *a, const void *b)
{
    const pair *x = a, *y = b;
    if (x->k != y->k)
        return x->k < y->k ? -1 : 1;
    return x->v < y->v ? -1 : x->v > y->v;
}

static int cmp_u64(const void *a, const void *b)
{
    const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* kind 0: random 63-bit; 1: few distinct keys (long runs of equal keys);
 * 2: skewed (most keys in one top bucket); 3: only low bits vary;
 * 4: already sorted descending; 5: all keys equal; 6: random but with
 * constant middle bits (digits no key changes between varying ones);
 * 7: random full 64-bit keys. */
static void fill(uint64_t *k, uint32_t n, int kind, tu_rng *r)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        uint64_t x = tu_rng_next(r) >> 1;
        switch (kind) {
        case 1: x = (x % 7) << 40; break;
        case 2: x = (i % 10) ? (x & 0xfffff) : x; break;
        case 3: x = 0x5555000000000000ull | (x & 0x3ff); break;
        case 4: x = (uint64_t)(n - i) << 20; break;
        case 5: x = 0x123456789abcull; break;
        case 6: x = (x & 0x7ff00000000000ffull) | 0x0000abcdef000000ull; break;
        case 7: x = tu_rng_next(r); break;
        /* One set bit, in random places: every bucket pass separates only
         * a few keys from the rest (the bucket sort's deepest recursion). */
        case 8: x = 1ull << (tu_rng_next(r) % 64); break;
        default: break;
        }
        k[i] = x;
    }
}

START_TEST(radix_sort_is_stable_and_sorted)
{
    static const uint32_t sizes[] = {1,  2,    3,    31,    32,    33,   47,
                                     48, 49,   1000, 4099,  70001, 300000};
    size_t si;
    int kind, threads;
    tu_rng r;
    tu_rng_seed(&r, 1234);
    for (si = 0; si < sizeof sizes / sizeof *sizes; si++)
        for (kind = 0; kind < 9; kind++)
            for (threads = 1; threads <= 4; threads *= 2) {
                const uint32_t n = sizes[si];
                uint64_t *k = malloc(n * sizeof *k), *tk = malloc(n * sizeof *k);
                uint32_t *v = malloc(n * sizeof *v), *tv = malloc(n * sizeof *v);
                pair *ref = malloc(n * sizeof *ref);
                uint32_t i;
                fill(k, n, kind, &r);
                for (i = 0; i < n; i++) {
                    v[i] = i;
                    ref[i].k = k[i];
                    ref[i].v = i;
                }
                qsort(ref, n, sizeof *ref, cmp_pair);
                ck_assert_int_eq(atrbvh_i_radix_sort(k, v, tk, tv, n, threads),
                                 ATRBVH_OK);
                for (i = 0; i < n; i++)
                    ck_assert_msg(k[i] == ref[i].k && v[i] == ref[i].v,
                                  "n %u kind %d threads %d: item %u is "
                                  "(%llx, %u), expected (%llx, %u)",
                                  n, kind, threads, i, (unsigned long long)k[i],
                                  v[i], (unsigned long long)ref[i].k, ref[i].v);
                free(k);
                free(tk);
                free(v);
                free(tv);
                free(ref);
            }
}
END_TEST

/* The hierarchy stage against atrbvh_karras_node (Karras 2012's per-node
 * search, the definition of the numbering): every child,
 * parent and count, for every block split of the CPU's stack passes,
 * over keys with long runs of equal keys (the position tie rule), few
 * distinct bits, and random keys. */
START_TEST(hierarchy_is_karras)
{
    static const uint32_t sizes[] = {1, 2, 3, 4, 5, 17, 64, 1000, 65537};
    static const int threads[] = {1, 2, 3, 7, 16, 40};
    size_t si, ti;
    int kind;
    tu_rng r;
    tu_rng_seed(&r, 99);
    for (si = 0; si < sizeof sizes / sizeof *sizes; si++)
        for (kind = 0; kind < 4; kind++) {
            const uint32_t n = sizes[si];
            uint64_t *k = malloc(n * sizeof *k);
            uint32_t i;
            for (i = 0; i < n; i++) {
                uint64_t x = tu_rng_next(&r) >> 1;
                k[i] = kind == 0   ? x
                       : kind == 1 ? (x % 5) << 30 /* long equal runs */
                       : kind == 2 ? x & 0x7 /* few bits, many equal */
                                   : 42; /* all equal */
            }
            qsort(k, n, sizeof *k, cmp_u64);
            for (ti = 0; ti < sizeof threads / sizeof *threads; ti++) {
                atrbvh_i_tree t;
                ck_assert_int_eq(atrbvh_i_tree_alloc(&t, n, 1), ATRBVH_OK);
                memset(t.parent, 0xab, (2 * (size_t)n - 1) * sizeof *t.parent);
                memset(t.count, 0xab, (2 * (size_t)n - 1) * sizeof *t.count);
                atrbvh_i_hierarchy(k, &t, threads[ti]);
                ck_assert_uint_eq(t.parent[0], ATRBVH_NONE);
                for (i = 0; i + 1 < n; i++) {
                    atrbvh_u32 l, rr, c;
                    atrbvh_karras_node(k, n, i, &l, &rr, &c);
                    ck_assert_msg(t.left[i] == l && t.right[i] == rr &&
                                      t.count[i] == c,
                                  "n %u kind %d threads %d node %u: (%u, %u, "
                                  "%u) vs Karras (%u, %u, %u)",
                                  n, kind, threads[ti], i, t.left[i],
                                  t.right[i], t.count[i], l, rr, c);
                    ck_assert_uint_eq(t.parent[l], i);
                    ck_assert_uint_eq(t.parent[rr], i);
                }
                for (i = n - 1; i < 2 * n - 1; i++)
                    ck_assert_uint_eq(t.count[i], 1);
                atrbvh_i_tree_free(&t);
            }
            free(k);
        }
}
END_TEST

/* The hierarchy stage's refit in the same pass (atrbvh_i_hierarchy_refit)
 * against the separate refit's climb (atrbvh_i_refit_sizes for an LBVH,
 * atrbvh_i_refit with costs): the same topology, and every box, count,
 * collapse size and cost to the bit, for every block split of the stack
 * passes, over random boxes in a random build order and keys with runs of
 * equal keys. */
START_TEST(hierarchy_refit_is_the_refit)
{
    static const uint32_t sizes[] = {1, 2, 3, 5, 17, 64, 1000, 20000};
    static const int threads[] = {1, 2, 3, 7, 16, 40};
    atrbvh_cost_params p;
    size_t si, ti;
    int kind, costs;
    tu_rng r;
    tu_rng_seed(&r, 7);
    p.ci = 1.2;
    p.ct = 1.0;
    p.collapse = 1;
    p.max_leaf = 8;
    for (si = 0; si < sizeof sizes / sizeof *sizes; si++)
        for (kind = 0; kind < 3; kind++) {
            const uint32_t n = sizes[si], nodes = 2 * n - 1;
            uint64_t *k = malloc(n * sizeof *k);
            uint32_t *order = malloc(n * sizeof *order);
            atrbvh_box *prims = malloc(n * sizeof *prims);
            uint32_t *size_ref = malloc(nodes * sizeof *size_ref);
            uint32_t *size = malloc(nodes * sizeof *size);
            uint32_t i;
            ck_assert(k && order && prims && size_ref && size);
            for (i = 0; i < n; i++) {
                const uint64_t x = tu_rng_next(&r) >> 1;
                int a;
                k[i] = kind == 0 ? x : kind == 1 ? (x % 5) << 30 : x & 0x7;
                order[i] = i;
                for (a = 0; a < 3; a++) {
                    /* random sums to round (the order of the cost's
                     * terms shows), a few exact ties, zeros of both signs,
                     * flat boxes */
                    const uint64_t y = tu_rng_next(&r);
                    const float lo =
                        y % 8 == 0 ? (float)(int)(y % 64) - 32.0f
                                   : (tu_rng_float(&r) - 0.5f) * 64.0f;
                    const float w = y % 16 == 1 ? 0.0f : tu_rng_float(&r);
                    prims[i].min[a] = lo == 0.0f && (x & 1) ? -0.0f : lo;
                    prims[i].max[a] = lo + w;
                }
            }
            qsort(k, n, sizeof *k, cmp_u64);
            for (i = n; i > 1; i--) { /* the sort's build order */
                const uint32_t j = (uint32_t)(tu_rng_next(&r) % i), t = order[i - 1];
                order[i - 1] = order[j];
                order[j] = t;
            }
            for (costs = 0; costs < 2; costs++) {
                atrbvh_i_tree ref;
                double *ref_cost;
                ck_assert_int_eq(atrbvh_i_tree_alloc(&ref, n, 1), ATRBVH_OK);
                atrbvh_i_hierarchy(k, &ref, 1);
                ref_cost = ref.cost;
                if (costs) {
                    atrbvh_i_refit(&ref, prims, order, &p, 1);
                } else {
                    ref.cost = NULL;
                    atrbvh_i_refit_sizes(&ref, prims, order, &p, 1, size_ref);
                    ref.cost = ref_cost;
                }
                for (ti = 0; ti < sizeof threads / sizeof *threads; ti++) {
                    atrbvh_i_tree t;
                    double *cost;
                    ck_assert_int_eq(atrbvh_i_tree_alloc(&t, n, 1), ATRBVH_OK);
                    memset(t.box, 0xab, nodes * sizeof *t.box);
                    memset(t.count, 0xab, nodes * sizeof *t.count);
                    memset(size, 0xab, nodes * sizeof *size);
                    memcpy(t.box, prims, n * sizeof *prims);
                    cost = t.cost;
                    if (!costs)
                        t.cost = NULL;
                    atrbvh_i_hierarchy_refit(k, &t, order, &p, threads[ti],
                                             costs ? NULL : size);
                    t.cost = cost;
                    ck_assert_uint_eq(t.parent[0], ATRBVH_NONE);
                    for (i = 0; i + 1 < n; i++)
                        ck_assert_msg(t.left[i] == ref.left[i] &&
                                          t.right[i] == ref.right[i],
                                      "n %u kind %d threads %d node %u", n,
                                      kind, threads[ti], i);
                    for (i = 0; i < nodes; i++) {
                        ck_assert_msg(
                            memcmp(&t.box[i], &ref.box[i], sizeof t.box[i]) ==
                                    0 &&
                                t.count[i] == ref.count[i] &&
                                (i == 0 || t.parent[i] == ref.parent[i]),
                            "n %u kind %d costs %d threads %d node %u: box, "
                            "count or parent",
                            n, kind, costs, threads[ti], i);
                        if (costs)
                            ck_assert_msg(memcmp(&t.cost[i], &ref.cost[i],
                                                 sizeof t.cost[i]) == 0,
                                          "n %u kind %d threads %d node %u: "
                                          "cost %.17g vs %.17g",
                                          n, kind, threads[ti], i, t.cost[i],
                                          ref.cost[i]);
                        else
                            ck_assert_msg(size[i] == size_ref[i],
                                          "n %u kind %d threads %d node %u: "
                                          "size %x vs %x",
                                          n, kind, threads[ti], i, size[i],
                                          size_ref[i]);
                    }
                    atrbvh_i_tree_free(&t);
                }
                atrbvh_i_tree_free(&ref);
            }
            free(k);
            free(order);
            free(prims);
            free(size_ref);
            free(size);
        }
}
END_TEST

START_TEST(morton_keys)
{
    /* Spreading and interleaving: x is the top bit of every triplet. */
    ck_assert_uint_eq(atrbvh_morton_key(1, 0, 0), 4);
    ck_assert_uint_eq(atrbvh_morton_key(0, 1, 0), 2);
    ck_assert_uint_eq(atrbvh_morton_key(0, 0, 1), 1);
    ck_assert_uint_eq(atrbvh_morton_key(ATRBVH_MORTON_MAX, ATRBVH_MORTON_MAX,
                                        ATRBVH_MORTON_MAX),
                      0x7fffffffffffffffull);
    ck_assert_uint_eq(atrbvh_morton_spread(0x100000), 1ull << 60);
    /* The table spread is the bit-by-bit definition for every 21-bit
     * input (and ignores the bits above). */
    {
        uint64_t x;
        for (x = 0; x < (1u << ATRBVH_MORTON_BITS); x++) {
            uint64_t want = 0;
            int k;
            for (k = 0; k < ATRBVH_MORTON_BITS; k++)
                want |= ((x >> k) & 1u) << (3 * k);
            if (atrbvh_morton_spread(x) != want ||
                atrbvh_morton_spread(x | 0xffe00000ull) != want)
                ck_abort_msg("spread(%llx) is %llx, expected %llx",
                             (unsigned long long)x,
                             (unsigned long long)atrbvh_morton_spread(x),
                             (unsigned long long)want);
        }
    }
    /* Quantisation: clamped, zero-extent axes give 0, monotone. */
    ck_assert_uint_eq(atrbvh_morton_quantise(5.0f, 0.0, 0.0), 0);
    ck_assert_uint_eq(atrbvh_morton_quantise(-1.0f, 0.0, 1.0), 0);
    ck_assert_uint_eq(atrbvh_morton_quantise(1e30f, 0.0, 1.0),
                      ATRBVH_MORTON_MAX);
    {
        float x;
        atrbvh_u32 prev = 0;
        const double scale = 2097152.0 / 10.0;
        for (x = 0.0f; x <= 10.0f; x += 0.001f) {
            atrbvh_u32 q = atrbvh_morton_quantise(x, 0.0, scale);
            ck_assert_uint_ge(q, prev);
            prev = q;
        }
        /* The far end of the range is the largest code. */
        ck_assert_uint_eq(atrbvh_morton_quantise(10.0f, 0.0, scale),
                          ATRBVH_MORTON_MAX);
    }
}
END_TEST

/* The CPU's Morton sweep, eight boxes at a time where the CPU has AVX2
 * (cpu/morton.c), gives the keys of the per-item rule, bit for bit: on
 * every length modulo 8 from starts that are not multiples of 8, on
 * random boxes, and on centres at the edges of the frame (its low end,
 * just below it, the top code's threshold and just under it, beyond the
 * far end, a zero-extent axis, negative zero, infinities and NaN). */
START_TEST(morton_keys_vector_is_scalar)
{
    static const float odd[] = {0.0f,
                                -0.0f,
                                -1e-7f,
                                7.99999618530273438f, /* t = 2^21 - 1 */
                                7.99999237060546875f, /* t = 2^21 - 2 */
                                8.0f,
                                1e30f,
                                -1e30f,
                                3.4e38f};
    /* two frames: the second has no zero-extent axis */
    const double frames[2][2][3] = {
        {{0.0, -1.0, 5.0}, {2097152.0 / 8.0, 0.0, 2097152.0 / 3.3}},
        {{0.0, -0.25, 5.5},
         {2097152.0 / 3.3, 2097152.0 / 0.9, 2097152.0 / 8.0}}};
    const double *lo, *scale;
    int f;
    const uint32_t total = 1000;
    atrbvh_box *box = malloc(total * sizeof *box);
    uint64_t *v = malloc(total * sizeof *v), *w = malloc(total * sizeof *w);
    unsigned seed = 7u;
    uint32_t i, a, b, differ = 0;
    int k;
    ck_assert_ptr_nonnull(box);
    ck_assert_ptr_nonnull(v);
    ck_assert_ptr_nonnull(w);
    for (i = 0; i < total; i++)
        for (k = 0; k < 3; k++) {
            float c;
            seed = seed * 1103515245u + 12345u;
            if ((seed >> 28) < 4) {
                /* a centre of odd[], as min = max (x's values; on the
                 * other axes around their low ends) */
                c = odd[(seed >> 8) % 9u];
                if (k == 2)
                    c = c + 5.0f;
            } else {
                c = (float)((seed >> 8) % 100000u) * 0.0000913f - 0.5f;
            }
            box[i].min[k] = c;
            box[i].max[k] = c;
            seed = seed * 1103515245u + 12345u;
            if ((seed >> 29) == 0) /* an extent, whose centre rounds */
                box[i].max[k] = c + (float)((seed >> 8) % 1000u) * 0.0037f;
        }
    box[17].min[0] = box[17].max[0] = 1.0f / 0.0f;
    box[18].min[1] = box[18].max[1] = -1.0f / 0.0f;
    box[19].min[2] = box[19].max[2] = 0.0f / 0.0f;
    box[20].min[0] = 0.0f / 0.0f;
    for (f = 1; f >= 0; f--) { /* (frame 0 last: checked below) */
        lo = frames[f][0];
        scale = frames[f][1];
        for (a = 0; a < 11; a++)
            for (b = a; b < a + 70 && b <= total; b++) {
                memset(v, 0xa5, total * sizeof *v);
                memset(w, 0xa5, total * sizeof *w);
                atrbvh_i_morton_keys_with(box, a, b, lo, scale, v, 1);
                atrbvh_i_morton_keys_with(box, a, b, lo, scale, w, 0);
                ck_assert_mem_eq(v, w, total * sizeof *v);
            }
        atrbvh_i_morton_keys_with(box, 3, total, lo, scale, v, 1);
        atrbvh_i_morton_keys_with(box, 3, total, lo, scale, w, 0);
        ck_assert_mem_eq(v, w, total * sizeof *v);
    }
    /* The keys are the per-item rule's, and the edges were reached. */
    for (i = 3; i < total; i++) {
        const atrbvh_u32 qx = atrbvh_morton_quantise(
            atrbvh_box_centre(box[i], 0), lo[0], scale[0]);
        ck_assert_uint_eq(w[i],
                          atrbvh_morton_key(
                              qx,
                              atrbvh_morton_quantise(
                                  atrbvh_box_centre(box[i], 1), lo[1],
                                  scale[1]),
                              atrbvh_morton_quantise(
                                  atrbvh_box_centre(box[i], 2), lo[2],
                                  scale[2])));
        differ |= 1u << (qx == 0 ? 0 : qx == ATRBVH_MORTON_MAX ? 1
                         : qx == ATRBVH_MORTON_MAX - 1u ? 2 : 3);
    }
    ck_assert_uint_eq(differ, 15u);
    free(box);
    free(v);
    free(w);
}
END_TEST

/* The bounds sweep, eight triangles at a time where the CPU has AVX2
 * (lib/prims.c), gives what the one-at-a-time rule gives: the boxes bit
 * for bit, the scene and centroid boxes, the count of non-finite
 * triangles and the first problem - on strided and packed, indexed and
 * unindexed triangles, counts that are not multiples of 8, 1 to 3
 * threads, with indices out of range, NaN and infinite coordinates,
 * finite ones whose sum overflows, and signed zeros. */
START_TEST(prims_sweep_vector_is_scalar)
{
    enum { V = 600, N = 203, VS = 4, IS = 5 };
    static float vert[V * VS];
    static uint32_t idx[N * IS];
    static const float odd[] = {0.0f, -0.0f, 3.4e38f, -3.4e38f, 1e-40f};
    atrbvh_box *bv = malloc(3 * V * sizeof *bv), *bs = malloc(3 * V * sizeof *bs);
    unsigned seed = 3u;
    int kase, bad, threads, i;
    ck_assert_ptr_nonnull(bv);
    ck_assert_ptr_nonnull(bs);
    for (kase = 0; kase < 3; kase++)      /* strided, packed, unindexed */
        for (bad = 0; bad < 3; bad++) {   /* none, zeros, all kinds */
            atrbvh_geometry g;
            atrbvh_i_input in;
            atrbvh_error err;
            const int vs = kase == 0 ? VS : 3;
            int n = kase == 2 ? V / 3 - 1 : N;
            for (i = 0; i < V * vs; i++) {
                seed = seed * 1103515245u + 12345u;
                vert[i] = (float)((seed >> 8) % 20000u) * 0.00113f - 9.0f;
                /* signed zeros in a quarter of the coordinates (bad 1:
                 * where only the operand order of a comparison tells
                 * them apart), then all of odd[] */
                if (bad == 1 && (seed >> 30) == 0)
                    vert[i] = (seed >> 9) & 1u ? 0.0f : -0.0f;
                if (bad == 2 && (seed >> 28) == 0)
                    vert[i] = odd[(seed >> 9) % 5u];
            }
            if (bad == 2) {
                vert[7 * vs + 1] = 1.0f / 0.0f;
                vert[101 * vs + 2] = 0.0f / 0.0f;
                vert[150 * vs] = -1.0f / 0.0f;
            }
            for (i = 0; i < N * IS; i++) {
                seed = seed * 1103515245u + 12345u;
                idx[i] = (seed >> 8) % V;
                if (bad == 2 && (seed >> 27) == 0)
                    idx[i] = (seed >> 26) & 1u ? V + 5u : 0xffffffffu;
            }
            g = atrbvh_geometry_triangles(vert, V, kase == 2 ? NULL : idx,
                                          (size_t)n);
            if (kase == 0) {
                g.vertex_stride = VS * sizeof(float);
                g.index_stride = IS * sizeof(uint32_t);
            }
            for (; n >= N - 9 || (kase == 2 && n >= V / 3 - 10); n--) {
                g.primitive_count = (size_t)n;
                ck_assert_int_eq(atrbvh_i_check_geometry(&g, &in, &err),
                                 ATRBVH_OK);
                for (threads = 1; threads <= 3; threads++) {
                    atrbvh_i_prims_scan v, sc;
                    int k;
                    memset(bv, 0xa5, 3 * V * sizeof *bv);
                    memset(bs, 0xa5, 3 * V * sizeof *bs);
                    atrbvh_i_prims_sweep_with(&in, threads, 1, bv, &v);
                    atrbvh_i_prims_sweep_with(&in, 1, 0, bs, &sc);
                    ck_assert_mem_eq(bv, bs, 3 * V * sizeof *bv);
                    for (k = 0; k < 3; k++) {
                        ck_assert(v.scene.min[k] == sc.scene.min[k]);
                        ck_assert(v.scene.max[k] == sc.scene.max[k]);
                        ck_assert(v.centroids.min[k] == sc.centroids.min[k]);
                        ck_assert(v.centroids.max[k] == sc.centroids.max[k]);
                    }
                    ck_assert_uint_eq(v.invalid, sc.invalid);
                    ck_assert_int_eq(v.first_bad, sc.first_bad);
                    ck_assert_int_eq(v.bad_kind, sc.bad_kind);
                    ck_assert_uint_eq(v.bad_value, sc.bad_value);
                    /* each kind of input was reached */
                    if (bad == 0)
                        ck_assert_int_eq(sc.first_bad, -1);
                    if (bad == 2 && kase != 2)
                        ck_assert_int_eq(sc.bad_kind, ATRBVH_PRIM_BAD_INDEX);
                    if (bad == 2 && kase == 2)
                        ck_assert_int_eq(sc.bad_kind, ATRBVH_PRIM_NONFINITE);
                }
            }
        }
    free(bv);
    free(bs);
}
END_TEST

/* A caterpillar of `spine` internal nodes in the layout's depth-first
 * order: spine node s (index s) has the next spine node as its left child
 * and a leaf as its right one, so the walk after a build has `spine` right
 * children pending at the deepest node.  Leaves hold 1, 2 or 3 primitives
 * and boxes of unequal sizes, so counts and areas weigh in the SAH. */
static atrbvh_bvh *caterpillar(size_t spine)
{
    const size_t m = 2 * spine + 1, leaves = spine + 1;
    size_t i, prims = 0, j;
    atrbvh_bvh *b;
    for (i = 0; i < leaves; i++)
        prims += 1 + i % 3;
    b = atrbvh_i_bvh_alloc(m, prims);
    ck_assert_ptr_nonnull(b);
    b->stats.ci = 1.2;
    b->stats.ct = 1.0;
    for (i = 0; i < spine; i++) {
        atrbvh_node *n = &b->nodes[i];
        float e = 2.0f + (float)(spine - i) * 0.25f;
        n->min[0] = n->min[1] = n->min[2] = -e;
        n->max[0] = e;
        n->max[1] = e * 1.5f;
        n->max[2] = e * 2.0f;
        n->count = 0;
        n->index = (uint32_t)(2 * spine - i); /* the right child */
    }
    /* leaves in depth-first order: the deepest node's left child, then
     * the right children from the bottom of the spine up */
    prims = 0;
    for (j = 0; j < leaves; j++) {
        atrbvh_node *n = &b->nodes[spine + j];
        float e = 0.5f + (float)(j % 7) * 0.125f;
        n->min[0] = n->min[1] = n->min[2] = -e;
        n->max[0] = n->max[1] = n->max[2] = e;
        n->count = (uint32_t)(1 + j % 3);
        n->index = (uint32_t)prims;
        prims += n->count;
    }
    for (i = 0; i < prims; i++)
        b->prim_indices[i] = (uint32_t)i;
    return b;
}

/* The statistics of a (measured by the pass after a build) are those of g
 * (measured by the general walk), and both SAHs are `sah` to the bit. */
static void assert_same_stats(const atrbvh_bvh *a, const atrbvh_bvh *g,
                              double sah, const char *what)
{
    ck_assert_uint_eq(a->stats.nodes, g->stats.nodes);
    ck_assert_uint_eq(a->stats.leaves, g->stats.leaves);
    ck_assert_uint_eq(a->stats.max_depth, g->stats.max_depth);
    ck_assert_uint_eq(a->stats.max_leaf_primitives,
                      g->stats.max_leaf_primitives);
    ck_assert_uint_eq(a->stats.primitives, g->stats.primitives);
    ck_assert_msg(memcmp(&a->stats.sah, &sah, sizeof sah) == 0 &&
                      memcmp(&g->stats.sah, &sah, sizeof sah) == 0,
                  "%s: SAH %.17g (built) %.17g (general), atrbvh_sah %.17g",
                  what, a->stats.sah, g->stats.sah, sah);
}

/* The statistics pass after a build (atrbvh_i_bvh_measure_built) keeps at
 * most 512 pending right children and hands deeper trees to the general
 * walk of check.c.  Around and past that bound its statistics must be the
 * general walk's, and the SAH atrbvh_sah's to the bit. */
START_TEST(measure_walk_deep_trees)
{
    static const size_t spines[] = {1, 100, 511, 512, 513, 514, 1500};
    size_t t;
    for (t = 0; t < sizeof spines / sizeof spines[0]; t++) {
        atrbvh_bvh *a = caterpillar(spines[t]);
        atrbvh_bvh *g = caterpillar(spines[t]);
        double sah = atrbvh_sah(a->nodes, a->node_count, 1.2, 1.0);
        char what[32];
        ck_assert_int_eq(atrbvh_i_bvh_measure_built(a, 1), ATRBVH_OK);
        ck_assert_int_eq(atrbvh_i_bvh_measure(g), ATRBVH_OK);
        ck_assert_uint_eq(a->stats.nodes, 2 * spines[t] + 1);
        ck_assert_uint_eq(a->stats.leaves, spines[t] + 1);
        ck_assert_uint_eq(a->stats.max_depth, spines[t]);
        ck_assert_uint_eq(a->stats.max_leaf_primitives,
                          spines[t] >= 2 ? 3 : 2);
        snprintf(what, sizeof what, "spine %lu", (unsigned long)spines[t]);
        assert_same_stats(a, g, sah, what);
        /* a right child out of place deep down is refused by both */
        if (spines[t] >= 2) {
            atrbvh_bvh *bad = caterpillar(spines[t]);
            atrbvh_bvh *badg = caterpillar(spines[t]);
            bad->nodes[spines[t] - 2].index++;
            badg->nodes[spines[t] - 2].index++;
            ck_assert_int_ne(atrbvh_i_bvh_measure_built(bad, 1), ATRBVH_OK);
            ck_assert_int_ne(atrbvh_i_bvh_measure(badg), ATRBVH_OK);
            atrbvh_bvh_free(bad);
            atrbvh_bvh_free(badg);
        }
        atrbvh_bvh_free(a);
        atrbvh_bvh_free(g);
    }
}
END_TEST

/* A depth-first array of a tree of `leaves` leaves split unevenly (the
 * left part takes about a third), with boxes and counts of many sizes:
 * node `at` on, primitives from *prims; returns the position after it. */
static size_t uneven(atrbvh_node *nodes, size_t at, size_t leaves,
                     size_t *prims, unsigned *seed)
{
    atrbvh_node *n = &nodes[at];
    float e;
    *seed = *seed * 1103515245u + 12345u;
    e = 0.25f + (float)((*seed >> 8) % 1000u) * 0.01f + (float)leaves;
    n->min[0] = -e;
    n->min[1] = -e * 0.5f;
    n->min[2] = -e * 0.75f;
    n->max[0] = e;
    n->max[1] = e * 1.25f;
    n->max[2] = e * 0.5f;
    if (leaves == 1) {
        n->count = 1u + (*seed >> 4) % 8u;
        n->index = (uint32_t)*prims;
        *prims += n->count;
        return at + 1;
    }
    {
        const size_t left = leaves / 3 ? leaves / 3 : 1;
        const size_t right_at = uneven(nodes, at + 1, left, prims, seed);
        n->count = 0;
        n->index = (uint32_t)right_at;
        return uneven(nodes, right_at, leaves - left, prims, seed);
    }
}

static atrbvh_bvh *uneven_tree(size_t leaves)
{
    const size_t m = 2 * leaves - 1;
    atrbvh_bvh *b = atrbvh_i_bvh_alloc(m, 8 * leaves);
    size_t prims = 0, i;
    unsigned seed = 7u;
    ck_assert_ptr_nonnull(b);
    ck_assert_uint_eq(uneven(b->nodes, 0, leaves, &prims, &seed), m);
    b->prim_count = prims;
    for (i = 0; i < prims; i++)
        b->prim_indices[i] = (uint32_t)i;
    b->stats.ci = 1.2;
    b->stats.ct = 1.0;
    return b;
}

/* A build leaves its statistics of a pass over the nodes (leaves, depth,
 * largest leaf, SAH) to their first reader (lib/bvh.c): the getter
 * measures them into its copy, keeping nothing in the const tree, and
 * gives what the general walk and atrbvh_sah give, the same at every
 * call; settling them into the tree gives the same again.  Trees of
 * more than 65,536 nodes, so that the measure runs on its threads. */
START_TEST(stats_measured_when_first_read)
{
    static const atrbvh_method methods[] = {ATRBVH_METHOD_LBVH,
                                            ATRBVH_METHOD_ATRBVH,
                                            ATRBVH_METHOD_TRBVH};
    static const int threads[] = {1, 3};
    const size_t T = 40000;
    float *v = tu_random_triangles(T, 77, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    size_t m, t;
    for (m = 0; m < 3; m++)
        for (t = 0; t < 2; t++) {
            atrbvh_build_options o;
            atrbvh_stats x, y;
            atrbvh_bvh *b, general;
            double sah;
            char what[48];
            atrbvh_build_options_init(&o);
            o.method = methods[m];
            o.max_leaf_size = 1;
            o.threads = threads[t];
            b = tu_build(&g, &o);
            ck_assert_uint_gt(b->node_count, 65536);
#ifndef ATRBVH_DEBUG_CHECKS
            ck_assert_int_eq(b->stats_pending, 1); /* (debug: measured) */
#endif
            ck_assert_int_eq(atrbvh_bvh_stats(b, &x), ATRBVH_OK);
            ck_assert_int_eq(atrbvh_bvh_stats(b, &y), ATRBVH_OK);
            ck_assert(memcmp(&x, &y, sizeof x) == 0);
#ifndef ATRBVH_DEBUG_CHECKS
            ck_assert_int_eq(b->stats_pending, 1);
#endif
            sah = atrbvh_sah(b->nodes, b->node_count, x.ci, x.ct);
            ck_assert(memcmp(&x.sah_built, &x.sah, sizeof sah) == 0);
            general = *b; /* the general walk into a copy of the stats */
            ck_assert_int_eq(atrbvh_i_bvh_measure(&general), ATRBVH_OK);
            ck_assert_uint_eq(x.nodes, b->node_count);
            ck_assert_uint_eq(x.primitives, T);
            ck_assert_uint_eq(x.leaves, general.stats.leaves);
            ck_assert_uint_eq(x.max_depth, general.stats.max_depth);
            ck_assert_uint_eq(x.max_leaf_primitives,
                              general.stats.max_leaf_primitives);
            snprintf(what, sizeof what, "method %d, %d threads",
                     (int)methods[m], threads[t]);
            ck_assert_msg(memcmp(&x.sah, &sah, sizeof sah) == 0 &&
                              memcmp(&general.stats.sah, &sah,
                                     sizeof sah) == 0,
                          "%s: SAH %.17g (read) %.17g (general), atrbvh_sah "
                          "%.17g",
                          what, x.sah, general.stats.sah, sah);
            ck_assert_int_eq(atrbvh_i_bvh_settle_stats(b), ATRBVH_OK);
            ck_assert_int_eq(b->stats_pending, 0);
            ck_assert(memcmp(&b->stats, &x, sizeof x) == 0);
            ck_assert_int_eq(atrbvh_bvh_stats(b, &y), ATRBVH_OK);
            ck_assert(memcmp(&x, &y, sizeof x) == 0);
            atrbvh_bvh_free(b);
        }
    free(v);
}
END_TEST

/* The statistics pass on trees large enough for its threads (the top cut
 * into subtrees walked side by side, the sums beside them): for 1, 2, 3
 * and 8 threads the statistics of the general walk (check.c) and the SAH
 * of atrbvh_sah to the bit; a right child out of place anywhere (deep in
 * a subtree, at the root, at a node the top cut splits), a leaf's
 * primitives past the index array, or the array cut short is refused by
 * every thread count. */
START_TEST(measure_built_threads)
{
    static const int threads[] = {1, 2, 3, 8};
    const size_t leaves = 100000;
    atrbvh_bvh *g = uneven_tree(leaves);
    size_t t;
    double sah;
    ck_assert_int_eq(atrbvh_i_bvh_measure(g), ATRBVH_OK);
    sah = atrbvh_sah(g->nodes, g->node_count, 1.2, 1.0);
    ck_assert_uint_eq(g->stats.leaves, leaves);
    for (t = 0; t < sizeof threads / sizeof threads[0]; t++) {
        atrbvh_bvh *a = uneven_tree(leaves);
        size_t at[4], c;
        char what[32];
        ck_assert_int_eq(atrbvh_i_bvh_measure_built(a, threads[t]),
                         ATRBVH_OK);
        snprintf(what, sizeof what, "%d threads", threads[t]);
        assert_same_stats(a, g, sah, what);
        /* internal nodes: the root, one a few levels down (inside the
         * top), and two deep ones */
        at[0] = 0;
        at[1] = a->nodes[a->nodes[0].index].index;
        at[2] = a->node_count / 2;
        at[3] = a->node_count - 40;
        for (c = 0; c < 4; c++) {
            size_t i = at[c];
            while (a->nodes[i].count)
                i++; /* the next internal node */
            a->nodes[i].index++;
            ck_assert_msg(atrbvh_i_bvh_measure_built(a, threads[t]) !=
                              ATRBVH_OK,
                          "%d threads: right child of node %lu moved",
                          threads[t], (unsigned long)i);
            a->nodes[i].index--;
        }
        {
            size_t i = a->node_count - 1; /* the last leaf */
            a->nodes[i].count += 1000;
            ck_assert_int_ne(atrbvh_i_bvh_measure_built(a, threads[t]),
                             ATRBVH_OK);
            a->nodes[i].count -= 1000;
        }
        a->node_count--;
        ck_assert_int_ne(atrbvh_i_bvh_measure_built(a, threads[t]),
                         ATRBVH_OK);
        a->node_count++;
        ck_assert_int_eq(atrbvh_i_bvh_measure_built(a, threads[t]),
                         ATRBVH_OK);
        atrbvh_bvh_free(a);
    }
    atrbvh_bvh_free(g);
    /* deeper than the walk's stack, on threads: the general walk's */
    {
        atrbvh_bvh *a = caterpillar(40000), *c = caterpillar(40000);
        ck_assert_int_eq(atrbvh_i_bvh_measure_built(a, 2), ATRBVH_OK);
        ck_assert_int_eq(atrbvh_i_bvh_measure(c), ATRBVH_OK);
        ck_assert_uint_eq(a->stats.max_depth, 40000);
        assert_same_stats(a, c, atrbvh_sah(c->nodes, c->node_count, 1.2, 1.0),
                          "spine 40000, 2 threads");
        atrbvh_bvh_free(a);
        atrbvh_bvh_free(c);
    }
}
END_TEST

/* The same bits, or both NaN (which NaN an operation on two returns is the
 * compiler's choice of operand order, not C's). */
static int same_or_nans(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0 || (a != a && b != b);
}

/* The SAH's sums (sah.c): four nodes at a time where AVX is there, and
 * the scalar loop, on arrays of every length modulo 4 with boxes that
 * give infinite, NaN, -0 and huge areas and counts of 2^31 and more: the
 * same bits in every field (NaN for NaN). */
START_TEST(sah_sums_vector_is_scalar)
{
    static const float odd[] = {0.0f, -0.0f, 1e30f, -1e30f, 3.4e38f,
                                -3.4e38f, 1e-30f, 0.1f};
    size_t m;
    unsigned seed = 1u;
    for (m = 0; m < 203; m++) {
        atrbvh_node *n = malloc((m ? m : 1) * sizeof *n);
        atrbvh_i_sah_sums v, s;
        size_t i;
        int k;
        ck_assert_ptr_nonnull(n);
        for (i = 0; i < m; i++) {
            for (k = 0; k < 3; k++) {
                int special;
                seed = seed * 1103515245u + 12345u;
                /* fractions of unlike sizes (sums that round), in a third
                 * of the arrays some odd values */
                special = m % 3 == 1 && (seed >> 28) < 3;
                n[i].min[k] = special
                                  ? odd[(seed >> 8) % 8u]
                                  : (float)((seed >> 8) % 1000u) * 0.0137f;
                seed = seed * 1103515245u + 12345u;
                n[i].max[k] = special
                                  ? odd[(seed >> 8) % 8u]
                                  : n[i].min[k] + (float)((seed >> 8) %
                                                          100000u) *
                                                      0.00071f;
            }
            /* and in those NaN and infinities, which then take over the
             * sums */
            if (m % 3 == 1 && i % 37 == 5)
                n[i].min[1] = NAN;
            if (m % 3 == 1 && i % 41 == 7)
                n[i].max[2] = INFINITY;
            seed = seed * 1103515245u + 12345u;
            n[i].count = (seed >> 29) < 3   ? 0u
                         : (seed >> 29) < 6 ? (seed >> 8) % 9u
                                            : 0x80000000u + (seed >> 8);
            n[i].index = seed;
        }
        atrbvh_i_sah_sum_with(n, m, 1, &v);
        atrbvh_i_sah_sum_with(n, m, 0, &s);
        ck_assert_msg(same_or_nans(v.inner, s.inner) &&
                          same_or_nans(v.leaf_sum, s.leaf_sum),
                      "%lu nodes: inner %.17g / %.17g, leaves %.17g / %.17g",
                      (unsigned long)m, v.inner, s.inner, v.leaf_sum,
                      s.leaf_sum);
        ck_assert_uint_eq(v.leaves, s.leaves);
        ck_assert_uint_eq(v.largest, s.largest);
        free(n);
    }
}
END_TEST

/* Whether the mapping holding `addr` has transparent huge pages advised
 * (VmFlags "hg" in /proc/self/smaps): 1 yes, 0 no, -1 unknown (no smaps,
 * or a kernel without transparent huge pages). */
static int huge_advised(const void *addr)
{
    FILE *f;
    char line[512];
    int in = 0, found = -1;
    const unsigned long a = (unsigned long)(size_t)addr;
    f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (!f)
        return -1;
    fclose(f);
    f = fopen("/proc/self/smaps", "r");
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        unsigned long lo, hi;
        char dash;
        if (sscanf(line, "%lx%c%lx ", &lo, &dash, &hi) == 3 && dash == '-') {
            in = a >= lo && a < hi;
            continue;
        }
        if (in && strncmp(line, "VmFlags:", 8) == 0) {
            found = strstr(line, " hg") != NULL;
            break;
        }
    }
    fclose(f);
    return found;
}

/* Arrays of 8 MiB and more (atrbvh_i_alloc_array: the output BVH of a
 * large build, captured trees) are fresh mappings of the C library at
 * every allocation: they get transparent huge pages advised over their
 * 2 MiB-aligned interior, as the scratch does, so a build of 10^7
 * triangles no longer takes ~85000 page faults on its output at every
 * build. */
START_TEST(large_arrays_advise_huge_pages)
{
    const size_t big = (size_t)16 << 20;
    unsigned char *p = atrbvh_i_alloc_array(big, 1);
    scene sc;
    char err[256];
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_bvh *bvh;
    const atrbvh_node *nodes;
    size_t count;
    int advised;
    ck_assert_ptr_nonnull(p);
    advised = huge_advised(p + big / 2);
    if (advised < 0) {
        atrbvh_i_free(p);
        return; /* nothing to see on this system */
    }
    /* a build's output: 2n-1 nodes of 32 bytes, 16 MiB for 262144 */
    ck_assert_int_eq(scene_builtin("sphere", 300000, &sc, err, sizeof err), 0);
    g = scene_geometry(&sc);
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    o.collapse = 0;
    o.threads = 2;
    bvh = tu_build(&g, &o);
    nodes = atrbvh_bvh_nodes(bvh, &count);
    ck_assert_uint_ge(count * sizeof *nodes, (size_t)12 << 20);
    ck_assert_int_eq(huge_advised((const char *)nodes +
                                  count * sizeof *nodes / 2), 1);
    atrbvh_bvh_free(bvh);
    scene_free(&sc);
    ck_assert_int_eq(advised, 1);
    atrbvh_i_free(p);
}
END_TEST

/* Whether every leaf box of b is exactly the box of its triangles (v: 9
 * floats each), as a refit computes it (min and max of the corners). */
static int leaf_boxes_exact(const atrbvh_bvh *b, const float *v)
{
    size_t count, np, i;
    const atrbvh_node *nodes = atrbvh_bvh_nodes(b, &count);
    const uint32_t *prims = atrbvh_bvh_primitive_indices(b, &np);
    for (i = 0; i < count; i++) {
        const atrbvh_node *nd = &nodes[i];
        float lo[3] = {INFINITY, INFINITY, INFINITY},
              hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        uint32_t k;
        int c, a;
        if (nd->count == 0)
            continue;
        for (k = nd->index; k < nd->index + nd->count; k++)
            for (c = 0; c < 3; c++)
                for (a = 0; a < 3; a++) {
                    const float x = v[9 * (size_t)prims[k] + 3 * c + a];
                    lo[a] = x < lo[a] ? x : lo[a];
                    hi[a] = x > hi[a] ? x : hi[a];
                }
        for (a = 0; a < 3; a++)
            if (nd->min[a] != lo[a] || nd->max[a] != hi[a])
                return 0;
    }
    return 1;
}

/* An LBVH of 3073 primitives or more reads its leaf boxes in place and
 * writes no node box (lib/cpu/hierarchy.c, cpu.h's leaf_boxes_by_order),
 * in a node box slot of n + 3072 boxes; with kept ids (skip_invalid that
 * left something out) the same build gathers them into the whole 2n-1,
 * as every build did before.  So the scene with one NaN triangle appended
 * and skip_invalid set must give the scene's own tree, node for node:
 * random triangles (the sort's buckets), and coincident ones (every key
 * equal: the sort writes the deltas alone), at 1 and 2 threads, with
 * and without collapsing, at the threshold and above it.  A caller's
 * tree (atrbvh_reoptimise as an LBVH) gathers them too, in a slot grown
 * with its primitive boxes: the same tree as where no slot had to grow. */
START_TEST(lbvh_leaf_boxes_in_place)
{
    static const size_t sizes[] = {3073, 5000};
    size_t si;
    int coincident, threads, collapse;
    for (si = 0; si < sizeof sizes / sizeof *sizes; si++)
        for (coincident = 0; coincident < 2; coincident++)
            for (threads = 1; threads <= 2; threads++)
                for (collapse = 0; collapse < 2; collapse++) {
                const size_t n = sizes[si];
                float *v = tu_random_triangles(n + 1, 31 + si, 4.0f, -2.0f);
                atrbvh_geometry g;
                atrbvh_build_options o;
                atrbvh_bvh *a, *b;
                char msg[256];
                size_t i;
                if (coincident)
                    for (i = 1; i <= n; i++)
                        memcpy(v + 9 * i, v, 9 * sizeof *v);
                v[9 * n + 4] = NAN; /* the appended triangle */
                atrbvh_build_options_init(&o);
                o.method = ATRBVH_METHOD_LBVH;
                o.threads = threads;
                o.collapse = collapse; /* (off: the whole topology shows) */
                g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
                a = tu_build(&g, &o); /* in place */
                ck_assert_msg(tu_check_bvh(a, &g, msg, sizeof msg),
                              "n %zu, coincident %d, %d threads, collapse "
                              "%d: %s", n, coincident, threads, collapse, msg);
                o.skip_invalid = 1;
                g = atrbvh_geometry_triangles(v, 3 * (n + 1), NULL, n + 1);
                b = tu_build(&g, &o); /* kept ids: gathered */
                ck_assert_msg(tu_same_bvh(a, b, msg, sizeof msg),
                              "n %zu, coincident %d, %d threads, collapse "
                              "%d: %s", n, coincident, threads, collapse, msg);
                if (!coincident) {
                    /* A caller's tree (set_tree) gathers its leaf boxes
                     * (cpu.h), its slot grown to 2n-1 with the primitive
                     * boxes in it: re-optimised as an LBVH without a
                     * handle, the tree of the same re-optimisation on a
                     * handle whose slot a TRBVH build made that large
                     * already, and a valid tree. */
                    atrbvh_error e;
                    atrbvh_device *d;
                    atrbvh_bvh *t, *a2;
                    g = atrbvh_geometry_triangles(v, 3 * n, NULL, n);
                    o.skip_invalid = 0;
                    a2 = tu_build(&g, &o);
                    ck_assert_int_eq(atrbvh_device_open("cpu", &d, &e),
                                     ATRBVH_OK);
                    o.device = d;
                    o.method = ATRBVH_METHOD_TRBVH;
                    t = tu_build(&g, &o);
                    o.method = ATRBVH_METHOD_LBVH;
                    ck_assert_msg(atrbvh_reoptimise(a2, &g, &o, &e) ==
                                      ATRBVH_OK,
                                  "%s", e.text);
                    o.device = NULL;
                    ck_assert_msg(atrbvh_reoptimise(a, &g, &o, &e) ==
                                      ATRBVH_OK,
                                  "%s", e.text);
                    ck_assert_msg(tu_same_bvh(a, a2, msg, sizeof msg),
                                  "n %zu, %d threads, collapse %d: "
                                  "re-optimised: %s",
                                  n, threads, collapse, msg);
                    atrbvh_bvh_free(t);
                    atrbvh_bvh_free(a2);
                    atrbvh_device_close(d);
                    ck_assert_msg(tu_check_bvh(a, &g, msg, sizeof msg), "%s",
                                  msg);
                    ck_assert_msg(leaf_boxes_exact(a, v), "n %zu, %d threads,"
                                  " collapse %d: a leaf box of the "
                                  "re-optimised tree is not its triangles'",
                                  n, threads, collapse);
                }
                atrbvh_bvh_free(a);
                atrbvh_bvh_free(b);
                free(v);
            }
}
END_TEST

/* A copy of a built tree's arrays, `extra` nodes longer (zeroed), that a
 * test may corrupt. */
static atrbvh_bvh *tree_copy(const atrbvh_bvh *b, size_t extra)
{
    atrbvh_bvh *c = atrbvh_i_bvh_alloc(b->node_count + extra, b->prim_count);
    ck_assert_ptr_nonnull(c);
    memset(c->nodes, 0, (b->node_count + extra) * sizeof *c->nodes);
    memcpy(c->nodes, b->nodes, b->node_count * sizeof *b->nodes);
    memcpy(c->prim_indices, b->prim_indices,
           b->prim_count * sizeof *b->prim_indices);
    c->prim_count = b->prim_count;
    c->stats = b->stats;
    c->split_prims = b->split_prims;
    return c;
}

/* atrbvh_i_bvh_check on t must refuse it as ATRBVH_ERR_FORMAT at `index`
 * with a text that holds `text`; t is freed. */
static void expect_fault(atrbvh_bvh *t, int check_boxes, uint64_t index,
                         const char *text)
{
    atrbvh_error e;
    memset(&e, 0, sizeof e);
    ck_assert_msg(atrbvh_i_bvh_check(t, check_boxes, &e) ==
                          ATRBVH_ERR_FORMAT &&
                      e.status == ATRBVH_ERR_FORMAT,
                  "expected a format error with \"%s\", got %d \"%s\"", text,
                  (int)e.status, e.text);
    ck_assert_msg(e.index == index && strstr(e.text, text),
                  "expected \"%s\" at %llu, got \"%s\" at %llu", text,
                  (unsigned long long)index, e.text,
                  (unsigned long long)e.index);
    atrbvh_bvh_free(t);
}

/* The leaf of t that holds primitive slot `slot`. */
static size_t leaf_of_slot(const atrbvh_bvh *t, size_t slot)
{
    size_t i;
    for (i = 0; i < t->node_count; i++)
        if (t->nodes[i].count && slot >= t->nodes[i].index &&
            slot - t->nodes[i].index < t->nodes[i].count)
            return i;
    ck_abort_msg("no leaf holds slot %lu", (unsigned long)slot);
    return 0;
}

/* The tree check that --enable-debug-checks runs after every build
 * (lib/check.c) passes a built tree and refuses each fault it looks for,
 * at the right node, with the message naming it; boxes are compared with
 * the parent's only when asked.  CI's debug-checks build (45-configs)
 * only ever hands it valid trees, so this is where its refusals are
 * tested. */
START_TEST(debug_check_refuses_each_fault)
{
    const size_t T = 3000;
    float *v = tu_random_triangles(T, 91, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    atrbvh_build_options o;
    atrbvh_bvh *b, *t;
    atrbvh_error e;
    size_t n, leaf = 0, wide = 0, a = 0, c = 0, input;
    uint32_t r;
    atrbvh_build_options_init(&o);
    o.max_leaf_size = 4;
    b = tu_build(&g, &o);
    ck_assert_int_eq(atrbvh_i_bvh_settle_stats(b), ATRBVH_OK);
    n = b->node_count;
    input = b->stats.primitives + b->stats.invalid_skipped;
    ck_assert_uint_eq(input, T);
    ck_assert_uint_eq(b->split_prims, 0);
    ck_assert_uint_gt(n, 64);
    ck_assert_uint_eq(b->nodes[0].count, 0);
    r = b->nodes[0].index; /* the root's right child */
    ck_assert_uint_gt(r, 2);
    ck_assert_uint_lt(r + 1, n);
    while (!b->nodes[leaf].count)
        leaf++;
    while (b->nodes[wide].count < 2)
        wide++;
    /* two leaves with the same count */
    for (a = 0; a < n; a++) {
        if (!b->nodes[a].count)
            continue;
        for (c = a + 1; c < n; c++)
            if (b->nodes[c].count == b->nodes[a].count)
                break;
        if (c < n)
            break;
    }
    ck_assert_uint_lt(c, n);

    memset(&e, 0, sizeof e);
    ck_assert_int_eq(atrbvh_i_bvh_check(b, 1, &e), ATRBVH_OK);
    t = tree_copy(b, 0);
    ck_assert_int_eq(atrbvh_i_bvh_check(t, 1, &e), ATRBVH_OK);
    atrbvh_bvh_free(t);

    t = tree_copy(b, 0); /* a NaN bound */
    t->nodes[leaf].min[1] = NAN;
    expect_fault(t, 0, leaf, "has an invalid box on axis 1");
    t = tree_copy(b, 0); /* an inverted box */
    t->nodes[r].min[2] = t->nodes[r].max[2] + 1.0f;
    expect_fault(t, 0, r, "has an invalid box on axis 2");
    t = tree_copy(b, 0); /* a child outside its parent: seen when asked */
    t->nodes[r].max[0] = b->nodes[0].max[0] + 1.0f;
    ck_assert_int_eq(atrbvh_i_bvh_check(t, 0, &e), ATRBVH_OK);
    {
        char want[64];
        snprintf(want, sizeof want, "node %lu sticks out of its parent 0 "
                 "on axis 0", (unsigned long)r);
        expect_fault(t, 1, r, want);
    }
    t = tree_copy(b, 0); /* a right child past the end, or at the left's */
    t->nodes[0].index = (uint32_t)n;
    expect_fault(t, 1, 0, "internal node 0 has right child");
    t = tree_copy(b, 0);
    t->nodes[0].index = 1;
    expect_fault(t, 1, 0, "out of range");
    t = tree_copy(b, 0); /* the right subtree one node late */
    t->nodes[0].index = r + 1;
    expect_fault(t, 0, r + 1, "is reached where node");
    t = tree_copy(b, 0); /* a leaf past the index array, ending there */
    t->nodes[leaf].index = (uint32_t)b->prim_count;
    expect_fault(t, 1, leaf, "references primitives");
    t = tree_copy(b, 0); /* or starting past it (no unsigned wrap) */
    t->nodes[leaf].index = (uint32_t)b->prim_count + 1;
    expect_fault(t, 1, leaf, "references primitives");
    t = tree_copy(b, 1); /* a node after the tree, never reached */
    t->nodes[n] = b->nodes[leaf];
    expect_fault(t, 1, n, "are reachable from the root");
    t = tree_copy(b, 0); /* a slot no leaf holds */
    t->nodes[wide].count--;
    expect_fault(t, 1, (uint64_t)-1, "primitive slots, the index array has");
    t = tree_copy(b, 0); /* two leaves' ranges swapped */
    t->nodes[a].index = b->nodes[c].index;
    t->nodes[c].index = b->nodes[a].index;
    expect_fault(t, 1, a, "starts at primitive slot");
    t = tree_copy(b, 0); /* a primitive beyond the input */
    t->prim_indices[5] = (uint32_t)input;
    expect_fault(t, 1, leaf_of_slot(b, 5), "lists primitive");
    t = tree_copy(b, 0); /* a primitive listed twice */
    t->prim_indices[7] = b->prim_indices[2];
    expect_fault(t, 1, leaf_of_slot(b, 7), "listed already by leaf");
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

/* The same check on a split tree: a primitive in two leaves is its split,
 * but not twice in one leaf, and the distinct ones must be those kept. */
START_TEST(debug_check_split_tree)
{
    const size_t T = 600, S = 30;
    float *v = malloc((T + S) * 9 * sizeof *v);
    float *small = tu_random_triangles(T, 12, 0.02f, 0.0f);
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_bvh *b, *t;
    atrbvh_error e;
    tu_rng rng;
    size_t i, k, twice = 0, dup_leaf = 0;
    uint32_t *seen;
    ck_assert_ptr_nonnull(v);
    ck_assert_ptr_nonnull(small);
    tu_rng_seed(&rng, 13);
    for (i = 0; i < T; i++) { /* small ones spread over the cube */
        const float d[3] = {tu_rng_float(&rng), tu_rng_float(&rng),
                            tu_rng_float(&rng)};
        for (k = 0; k < 9; k++)
            v[9 * i + k] = small[9 * i + k] + d[k % 3];
    }
    for (i = T; i < T + S; i++) /* long slivers across it */
        for (k = 0; k < 3; k++) {
            const float lo = tu_rng_float(&rng) * 0.1f;
            v[9 * i + k] = lo;
            v[9 * i + 3 + k] = 0.9f + lo;
            v[9 * i + 6 + k] = 0.9f + lo + (k ? 0.0f : 0.01f);
        }
    free(small);
    g = atrbvh_geometry_triangles(v, 3 * (T + S), NULL, T + S);
    atrbvh_build_options_init(&o);
    o.split_budget = 0.5;
    o.max_leaf_size = 4;
    b = tu_build(&g, &o);
    ck_assert_int_eq(atrbvh_i_bvh_settle_stats(b), ATRBVH_OK);
    ck_assert_uint_eq(b->split_prims, T + S);
    seen = calloc(T + S, sizeof *seen);
    ck_assert_ptr_nonnull(seen);
    for (i = 0; i < b->prim_count; i++)
        if (seen[b->prim_indices[i]]++)
            twice++;
    free(seen);
    ck_assert_uint_gt(twice, 0); /* a split tree, as meant */
    memset(&e, 0, sizeof e);
    ck_assert_int_eq(atrbvh_i_bvh_check(b, 1, &e), ATRBVH_OK);
    t = tree_copy(b, 0); /* one fewer kept than listed */
    t->split_prims = b->split_prims + 1;
    expect_fault(t, 1, (uint64_t)-1, "the split tree lists");
    while (b->nodes[dup_leaf].count < 2)
        dup_leaf++;
    t = tree_copy(b, 0); /* twice in one leaf */
    t->prim_indices[b->nodes[dup_leaf].index + 1] =
        b->prim_indices[b->nodes[dup_leaf].index];
    expect_fault(t, 1, dup_leaf, "listed already by leaf");
    atrbvh_bvh_free(b);
    free(v);
}
END_TEST

/* atrbvh_i_captures_differ on a copy of b: it must report a difference
 * at `index` with `text` in the message, stage order first. */
static void expect_diff(const atrbvh_i_capture *ca, const atrbvh_bvh *ba,
                        const atrbvh_i_capture *cb, const atrbvh_bvh *bb,
                        uint64_t index, const char *text)
{
    atrbvh_error e;
    memset(&e, 0, sizeof e);
    ck_assert_msg(atrbvh_i_captures_differ(&e, ca, ba, cb, bb) == 1,
                  "no difference found, expected \"%s\"", text);
    ck_assert_msg(e.index == index && strstr(e.text, text) &&
                      e.status == ATRBVH_OK,
                  "expected \"%s\" at %llu, got \"%s\" at %llu (status %d)",
                  text, (unsigned long long)index, e.text,
                  (unsigned long long)e.index, (int)e.status);
}

/* What atrbvh validate compares (lib/validate.c): two CPU builds of one
 * scene capture the same bits at every stage, and a one-item change in
 * any stage's output of the second is named - stage, item, index - and
 * an earlier stage's change is named before a later one's.  (With no
 * GPU in CI the CPU and OpenCL captures never differ there, so this is
 * where the comparison's reports are tested.) */
START_TEST(validate_names_the_first_difference)
{
    const size_t T = 700;
    float *v = tu_random_triangles(T, 31, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * T, NULL, T);
    atrbvh_build_options o;
    atrbvh_i_capture ca, cb;
    atrbvh_bvh *ba = NULL, *bb = NULL;
    atrbvh_error e;
    const size_t i = 123, m = 2 * T - 1;
    size_t leaf = 0, node;
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_ATRBVH;
    o.max_leaf_size = 4;
    o.threads = 2;
    memset(&ca, 0, sizeof ca);
    memset(&cb, 0, sizeof cb);
    ck_assert_int_eq(atrbvh_i_build_run(&g, &o, &ba, &ca, &e), ATRBVH_OK);
    o.threads = 1;
    ck_assert_int_eq(atrbvh_i_build_run(&g, &o, &bb, &cb, &e), ATRBVH_OK);
    ck_assert_uint_eq(ca.n, T);
    ck_assert_ptr_nonnull(cb.optimise.box);
    ck_assert_ptr_nonnull(cb.collapse_size);
    memset(&e, 0, sizeof e);
    ck_assert_int_eq(atrbvh_i_captures_differ(&e, &ca, ba, &cb, bb), 0);
    ck_assert_uint_gt(bb->node_count, i);
    while (!bb->nodes[leaf].count)
        leaf++;
    node = m - 5; /* a leaf of the binary trees */

/* changes lvalue, expects the report, puts lvalue back */
#define FLIP(lvalue, change, index, text)                                   \
    do {                                                                    \
        ck_assert(sizeof(lvalue) <= sizeof saved);                          \
        memcpy(&saved, &(lvalue), sizeof(lvalue));                          \
        change;                                                             \
        expect_diff(&ca, ba, &cb, bb, (index), (text));                     \
        memcpy(&(lvalue), &saved, sizeof(lvalue));                          \
    } while (0)
    {
        union {
            atrbvh_box box;
            atrbvh_node node;
            uint64_t key;
            double cost;
            size_t count;
        } saved;
        FLIP(cb.prim_boxes[i], cb.prim_boxes[i].max[1] =
                                   nextafterf(cb.prim_boxes[i].max[1], 9.0f),
             i, "stage bounds, primitive 123: box differs");
        FLIP(cb.scene, cb.scene.min[0] -= 1.0f, 0,
             "stage bounds, scene box 0: box differs");
        FLIP(cb.centroids, cb.centroids.max[2] += 1.0f, 0,
             "stage bounds, centroid box 0: box differs");
        FLIP(cb.keys[i], cb.keys[i] ^= 1u, i,
             "stage morton, primitive 123: key differs");
        { /* both values, the first build's as "cpu" */
            char want[128];
            snprintf(want, sizeof want,
                     "stage morton, primitive 0: key differs (cpu %016llx, "
                     "opencl %016llx)",
                     (unsigned long long)ca.keys[0],
                     (unsigned long long)(ca.keys[0] ^ 8u));
            FLIP(cb.keys[0], cb.keys[0] ^= 8u, 0, want);
            snprintf(want, sizeof want, "box differs (cpu [%.9g ",
                     (double)ca.prim_boxes[T - 1].min[0]);
            FLIP(cb.prim_boxes[T - 1], cb.prim_boxes[T - 1].min[0] -= 1.0f,
                 T - 1, want);
        }
        FLIP(cb.sorted_keys[i], cb.sorted_keys[i] ^= 4u, i,
             "stage sort, position 123: key differs");
        FLIP(cb.order[i], cb.order[i] ^= 1u, i,
             "stage sort, position 123: primitive differs");
        FLIP(cb.hierarchy.left[i], cb.hierarchy.left[i]++, i,
             "stage hierarchy, node 123: left child differs");
        FLIP(cb.hierarchy.parent[node], cb.hierarchy.parent[node]++, node,
             "stage hierarchy, node");
        FLIP(cb.hierarchy.leaf_prim[i], cb.hierarchy.leaf_prim[i]++, i,
             "stage hierarchy, leaf 123: primitive differs");
        FLIP(cb.refit.box[node], cb.refit.box[node].min[0] -= 1.0f, node,
             "stage refit, node");
        FLIP(cb.refit.cost[node], cb.refit.cost[node] *= 2.0, node,
             "cost differs");
        FLIP(cb.refit.count[i], cb.refit.count[i]++, i,
             "stage refit, node 123: count differs");
        FLIP(cb.optimise.right[i], cb.optimise.right[i]++, i,
             "stage optimise, node 123: right child differs");
        FLIP(cb.optimise.cost[i], cb.optimise.cost[i] += 1.0, i,
             "stage optimise, node 123: cost differs");
        FLIP(cb.optimise.leaf_prim[i], cb.optimise.leaf_prim[i]++, i,
             "stage optimise, leaf 123: primitive differs");
        FLIP(cb.collapse_size[i], cb.collapse_size[i]++, i,
             "stage collapse, node 123: output size differs");
        FLIP(cb.collapse_size[i], cb.collapse_size[i] ^= 0x80000000u, i,
             "stage collapse, node 123: leaf decision differs");
        FLIP(bb->nodes[i], bb->nodes[i].max[2] += 1.0f, i,
             "stage layout, output node 123: box differs");
        FLIP(bb->nodes[leaf], bb->nodes[leaf].count++, leaf,
             "count differs");
        FLIP(bb->prim_indices[i], bb->prim_indices[i]++, i,
             "stage layout, index array entry 123: primitive differs");
        FLIP(bb->prim_indices[0], bb->prim_indices[0]++, 0,
             "stage layout, index array entry 0: primitive differs");
        FLIP(bb->prim_indices[bb->prim_count - 1],
             bb->prim_indices[bb->prim_count - 1]++, bb->prim_count - 1,
             "stage layout, index array entry");
        FLIP(bb->nodes[bb->node_count - 1],
             bb->nodes[bb->node_count - 1].min[1] -= 1.0f,
             bb->node_count - 1, "stage layout, output node");
        FLIP(bb->node_count, bb->node_count--, 0,
             "stage layout, array 0: node count differs");
        /* two changes: the earlier stage is named */
        {
            const atrbvh_node root = bb->nodes[0];
            bb->nodes[0].max[0] += 1.0f;
            FLIP(cb.keys[i + 1], cb.keys[i + 1] ^= 2u, i + 1,
                 "stage morton, primitive 124: key differs");
            bb->nodes[0] = root;
        }
    }
#undef FLIP
    memset(&e, 0, sizeof e);
    ck_assert_int_eq(atrbvh_i_captures_differ(&e, &ca, ba, &cb, bb), 0);
    atrbvh_bvh_free(ba);
    atrbvh_bvh_free(bb);
    atrbvh_i_capture_free(&ca);
    atrbvh_i_capture_free(&cb);
    free(v);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("stages");
    TCase *tc = tcase_create("stages");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, radix_sort_is_stable_and_sorted);
    tcase_add_test(tc, morton_keys);
    tcase_add_test(tc, morton_keys_vector_is_scalar);
    tcase_add_test(tc, prims_sweep_vector_is_scalar);
    tcase_add_test(tc, hierarchy_is_karras);
    tcase_add_test(tc, hierarchy_refit_is_the_refit);
    tcase_add_test(tc, measure_walk_deep_trees);
    tcase_add_test(tc, measure_built_threads);
    tcase_add_test(tc, stats_measured_when_first_read);
    tcase_add_test(tc, sah_sums_vector_is_scalar);
    tcase_add_test(tc, large_arrays_advise_huge_pages);
    tcase_add_test(tc, lbvh_leaf_boxes_in_place);
    tcase_add_test(tc, debug_check_refuses_each_fault);
    tcase_add_test(tc, debug_check_split_tree);
    tcase_add_test(tc, validate_names_the_first_difference);
    suite_add_tcase(s, tc);
    return tu_run(s);
}
