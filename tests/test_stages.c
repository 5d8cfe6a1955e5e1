/*
 * test_stages.c - internal stages checked on their own (links the static
 * core): the radix sort against an independent stable reference, and the
 * Morton key properties.
 */
#include <check.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "cpu/cpu.h"
#include "testutil.h"

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

/* kind 0: random 63-bit; 1: few distinct keys (long runs of equal keys);
 * 2: skewed (most keys in one top bucket); 3: only low bits vary;
 * 4: already sorted descending. */
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
        default: break;
        }
        k[i] = x;
    }
}

START_TEST(radix_sort_is_stable_and_sorted)
{
    static const uint32_t sizes[] = {2, 3, 47, 48, 49, 1000, 4099, 70001, 300000};
    size_t si;
    int kind, threads;
    tu_rng r;
    tu_rng_seed(&r, 1234);
    for (si = 0; si < sizeof sizes / sizeof *sizes; si++)
        for (kind = 0; kind < 5; kind++)
            for (threads = 1; threads <= 4; threads += 3) {
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

int main(void)
{
    Suite *s = suite_create("stages");
    TCase *tc = tcase_create("stages");
    SRunner *sr;
    int failed;
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, radix_sort_is_stable_and_sorted);
    tcase_add_test(tc, morton_keys);
    suite_add_tcase(s, tc);
    sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
