/*
 * sort.c - stage "sort": stable radix sort of (63-bit key, 32-bit value)
 * pairs.
 *
 * One most-significant-digit pass over the top varying bits scatters the
 * pairs into buckets of about BUCKET_TARGET items; each bucket is then
 * sorted in cache by further MSD passes on its own top varying bits
 * (sort_bucket), down to insertion sort for buckets of a few items.
 * Every step is stable, so the result is the unique sorted order with
 * ties in input order: it cannot depend on the number of threads.  Only
 * bits that vary are sorted on, so scenes whose keys differ in fewer bits
 * sort in fewer passes.
 *
 * Parallel shape (as on a GPU): for the MSD pass each thread owns a fixed
 * contiguous block of the input, counts digits in it, an exclusive scan
 * over (digit, block) gives each block its output offsets, and each block
 * scatters in order; buckets are then independent items.
 *
 * Measured on the dragon's 871,414 keys, one thread, this machine: 8 plain
 * LSD passes took ~300 ms (random stores into 512 streams, TLB-bound); this
 * scheme ~45 ms.
 */
#include "config.h"

#include "cpu.h"
#include "shared/sort.h"

#include <string.h>

#define MAX_BLOCKS 256
#define MSD_MAX_BITS 11
#define BUCKET_TARGET 1024u
#define INSERTION_MAX 24u
/* The passes' digits, block ranges, scan and placement are the rules of
 * shared/sort.h, the same the OpenCL kernels apply. */
/* A bucket's passes: at most BUCKET_BITS-bit digits.  Their counters
 * are on the stack, one 1 KiB array per level: every level takes at
 * least 3 bits (buckets of more than INSERTION_MAX items), so at most
 * 21 levels even for adversarial keys (11-bit digits measured only 3%
 * fewer instructions on the dragon, for 8 times the stack). */
#define BUCKET_BITS 8
#define BUCKET_RADIX (1u << BUCKET_BITS)

/* The position of the highest set bit of x (0 for x = 0). */
static int highest_bit(uint64_t x)
{
    return x ? 63 - ATRBVH_CLZ64(x) : 0;
}

/* Stable insertion sort of k/v[0..n) on the whole key (the bits above a
 * bucket's digit are equal inside it, so this is its order too). */
static void insertion_sort(uint64_t *k, uint32_t *v, uint32_t n)
{
    uint32_t i;
    for (i = 1; i < n; i++) {
        const uint64_t key = k[i];
        const uint32_t val = v[i];
        uint32_t j = i;
        while (j > 0 && k[j - 1] > key) {
            k[j] = k[j - 1];
            v[j] = v[j - 1];
            j--;
        }
        k[j] = key;
        v[j] = val;
    }
}

/* Sub-buckets of up to this many items: small_sort. */
#define SMALL_MAX 4u

/* Stable compare and exchange of two pairs in registers: a conditional
 * move, not a branch (which no predictor does better than a coin toss
 * on). */
static inline void exchange(uint64_t *a, uint64_t *b, uint32_t *va,
                            uint32_t *vb)
{
    const uint64_t x = *a, y = *b;
    const uint32_t vx = *va, vy = *vb;
    const int swap = x > y;
    *a = swap ? y : x;
    *b = swap ? x : y;
    *va = swap ? vy : vx;
    *vb = swap ? vx : vy;
}

/* (k, v)[0..n), 2 <= n <= SMALL_MAX, sorted stably into (dk, dv): a
 * bubble sort's network of neighbours' exchanges (stable: equal keys are
 * never exchanged; n = 4 is the odd-even transposition network), in
 * registers, instead of a call of sort_bucket and its insertion sort,
 * whose loop exits at a random place (sub-buckets hold about two items:
 * most are 1, 2 or 3).  One thread, fastest of 100 builds: the sort stage
 * 15.6 -> 15.1 ns per triangle on the bunny, 16.2 -> 15.8 on sibenik. */
static void small_sort(const uint64_t *k, const uint32_t *v, uint64_t *dk,
                       uint32_t *dv, uint32_t n)
{
    uint64_t k0 = k[0], k1 = k[1], k2 = 0, k3 = 0;
    uint32_t v0 = v[0], v1 = v[1], v2 = 0, v3 = 0;
    if (n > 2) {
        k2 = k[2];
        v2 = v[2];
    }
    if (n > 3) {
        k3 = k[3];
        v3 = v[3];
        exchange(&k2, &k3, &v2, &v3);
    }
    exchange(&k0, &k1, &v0, &v1);
    if (n > 2) {
        exchange(&k1, &k2, &v1, &v2);
        if (n > 3) {
            exchange(&k2, &k3, &v2, &v3);
            dk[3] = k3;
            dv[3] = v3;
        }
        exchange(&k0, &k1, &v0, &v1);
        if (n > 3)
            exchange(&k1, &k2, &v1, &v2);
        dk[2] = k2;
        dv[2] = v2;
    }
    dk[0] = k0;
    dk[1] = k1;
    dv[0] = v0;
    dv[1] = v1;
}

/* Sorts the bucket (k, v)[0..n) stably, with (tk, tv) as scratch of the
 * same length; the result ends in (tk, tv) when `to_tmp`, else in (k, v).
 *
 * Bits >= hi are the same in every key of the bucket.  Most-significant
 * digit first: one stable counting pass on the top varying bits of the
 * bucket (at most BUCKET_BITS of them, fewer for a small bucket, so that
 * its sub-buckets hold a few items each), then each sub-bucket the same
 * way with the roles of the two arrays swapped, down to insertion sort.  Every sub-bucket's keys share the digit's bits and
 * all above, so the recursion moves down at least `bits` (>= 3) bits per
 * level, and in practice 1 or 2 levels below the stage's first pass.
 * Measured on the dragon (callgrind, one thread), the whole stage: 8-bit
 * LSD passes over each bucket's remaining ~53 varying bits cost about
 * 190 instructions per key; this about 120. */
static void sort_bucket(uint64_t *k, uint32_t *v, uint64_t *tk, uint32_t *tv,
                        uint32_t n, int to_tmp, int hi)
{
    uint32_t c[BUCKET_RADIX], start, i, d, radix;
    int bits, shift, guessed = 1;
    if (n <= INSERTION_MAX) {
        insertion_sort(k, v, n);
        goto done;
    }
    /* About n / 2 sub-buckets: 2^bits with bits = floor(log2 n) - 1. */
    bits = highest_bit((uint64_t)n) - 1;
    if (bits > BUCKET_BITS)
        bits = BUCKET_BITS;
    /* The digit just below the bits known equal (>= hi): those below the
     * parent's digit mostly vary.  When it does not (every key has the
     * first key's digit), the bits that vary are looked up once and the
     * digit placed at the top of them. */
    for (;;) {
        if (hi <= 0)
            goto done; /* all keys equal */
        if (bits > hi)
            bits = hi;
        shift = hi - bits;
        radix = 1u << bits;
        memset(c, 0, radix * sizeof *c);
        for (i = 0; i < n; i++)
            c[atrbvh_sort_digit_bits(k[i], (atrbvh_u32)shift,
                                     (atrbvh_u32)bits)]++;
        if (c[atrbvh_sort_digit_bits(k[0], (atrbvh_u32)shift,
                                     (atrbvh_u32)bits)] != n)
            break;
        if (guessed) {
            uint64_t varying = 0;
            const uint64_t first = k[0];
            for (i = 1; i < n; i++)
                varying |= k[i] ^ first;
            if (!varying)
                goto done;
            hi = highest_bit(varying) + 1;
            guessed = 0;
        } else {
            hi = shift; /* cannot happen: the top varying bit is in it */
        }
    }
    (void)atrbvh_sort_scan(c, radix);
    for (i = 0; i < n; i++) {
        const uint64_t key = k[i];
        const uint32_t o = atrbvh_sort_place(
            c, atrbvh_sort_digit_bits(key, (atrbvh_u32)shift, (atrbvh_u32)bits));
        tk[o] = key;
        tv[o] = v[i];
    }
    /* c[d] is now the end of sub-bucket d. */
    for (d = 0, start = 0; d < radix; d++) {
        const uint32_t len = c[d] - start;
        if (len == 1) {
            /* Sorted; where it must end (the common case: no call). */
            if (!to_tmp) {
                k[start] = tk[start];
                v[start] = tv[start];
            }
        } else if (len > 1 && len <= SMALL_MAX) {
            small_sort(tk + start, tv + start, (to_tmp ? tk : k) + start,
                       (to_tmp ? tv : v) + start, len);
        } else if (len) {
            sort_bucket(tk + start, tv + start, k + start, v + start, len,
                        !to_tmp, shift);
        }
        start = c[d];
    }
    return;
done:
    if (to_tmp) {
        memcpy(tk, k, (size_t)n * sizeof *k);
        memcpy(tv, v, (size_t)n * sizeof *v);
    }
}

atrbvh_status atrbvh_i_radix_sort(uint64_t *keys, uint32_t *values,
                                  uint64_t *tmp_keys, uint32_t *tmp_values,
                                  uint32_t n, int threads)
{
    uint64_t varying = 0;
    int64_t i;
    if (n < 2)
        return ATRBVH_OK;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads < 1 ? 1 : threads) \
    schedule(static) reduction(| : varying)
#endif
    for (i = 1; i < (int64_t)n; i++)
        varying |= keys[i] ^ keys[0];
    return atrbvh_i_radix_sort_varying(keys, values, tmp_keys, tmp_values, n,
                                       threads, varying);
}

atrbvh_status atrbvh_i_radix_sort_varying(uint64_t *keys, uint32_t *values,
                                          uint64_t *tmp_keys,
                                          uint32_t *tmp_values, uint32_t n,
                                          int threads, uint64_t varying)
{
    uint32_t *counts, *start;
    int blocks, top, bits, shift;
    uint32_t buckets, target;

    if (n < 2 || !varying)
        return ATRBVH_OK; /* all keys equal: the input order is sorted */
    blocks = threads < 1 ? 1 : threads > MAX_BLOCKS ? MAX_BLOCKS : threads;
    if ((uint32_t)blocks > n)
        blocks = (int)n;

    /* MSD digit: the top `bits` varying bit positions, enough for buckets
     * of about BUCKET_TARGET items. */
    top = highest_bit(varying);
    bits = 1;
    for (target = n / BUCKET_TARGET; target > 1 && bits < MSD_MAX_BITS;
         target >>= 1)
        bits++;
    if (bits > top + 1)
        bits = top + 1;
    shift = top + 1 - bits;
    buckets = 1u << bits;

    counts = atrbvh_i_alloc_array((size_t)blocks * buckets, sizeof *counts);
    start = atrbvh_i_alloc_array((size_t)buckets + 1, sizeof *start);
    if (!counts || !start) {
        atrbvh_i_free(counts);
        atrbvh_i_free(start);
        return ATRBVH_ERR_NOMEM;
    }

#ifdef _OPENMP
#pragma omp parallel num_threads(blocks)
#endif
    {
        int b;
        int64_t bk;
#ifdef _OPENMP
#pragma omp for schedule(static, 1)
#endif
        for (b = 0; b < blocks; b++) {
            uint32_t lo, hi, j, *c = counts + (size_t)b * buckets;
            atrbvh_block_range(n, (atrbvh_u32)b, (atrbvh_u32)blocks, &lo, &hi);
            memset(c, 0, buckets * sizeof *c);
            for (j = lo; j < hi; j++)
                c[atrbvh_sort_digit_bits(keys[j], (atrbvh_u32)shift,
                                         (atrbvh_u32)bits)]++;
        }
#ifdef _OPENMP
#pragma omp single
#endif
        {
            uint32_t d, total = 0;
            int bb;
            for (d = 0; d < buckets; d++) {
                start[d] = total;
                for (bb = 0; bb < blocks; bb++) {
                    uint32_t t = counts[(size_t)bb * buckets + d];
                    counts[(size_t)bb * buckets + d] = total;
                    total += t;
                }
            }
            start[buckets] = total;
        }
#ifdef _OPENMP
#pragma omp for schedule(static, 1)
#endif
        for (b = 0; b < blocks; b++) {
            uint32_t lo, hi, j, *c = counts + (size_t)b * buckets;
            atrbvh_block_range(n, (atrbvh_u32)b, (atrbvh_u32)blocks, &lo, &hi);
            for (j = lo; j < hi; j++) {
                uint32_t o = atrbvh_sort_place(
                    c, atrbvh_sort_digit_bits(keys[j], (atrbvh_u32)shift,
                                              (atrbvh_u32)bits));
                tmp_keys[o] = keys[j];
                tmp_values[o] = values[j];
            }
        }
        /* Buckets are independent; the result lands back in keys/values. */
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16)
#endif
        for (bk = 0; bk < (int64_t)buckets; bk++) {
            const uint32_t s = start[bk], len = start[bk + 1] - s;
            if (len)
                sort_bucket(tmp_keys + s, tmp_values + s, keys + s,
                            values + s, len, 1, shift);
        }
    }
    atrbvh_i_free(counts);
    atrbvh_i_free(start);
    return ATRBVH_OK;
}

/* The stage: keys (morton) sorted with their build indices. */
atrbvh_status atrbvh_i_cpu_sort(atrbvh_device *dev, atrbvh_i_run *run,
                                atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    const uint32_t n = run->n;
    uint64_t *tmp_keys;
    uint32_t *tmp_order;
    (void)dev;
    tmp_keys = atrbvh_i_scratch_get(c->scratch, CPU_TMP_KEYS, n,
                                    sizeof *tmp_keys);
    tmp_order = atrbvh_i_scratch_get(c->scratch, CPU_TMP_ORDER, n,
                                     sizeof *tmp_order);
    if (!tmp_keys || !tmp_order)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate sort buffers for %lu "
                             "primitives",
                             (unsigned long)n);
    /* c->order holds the build indices (morton wrote them). */
    if (atrbvh_i_radix_sort_varying(c->keys, c->order, tmp_keys, tmp_order,
                                    n, run->cfg->threads,
                                    c->key_varying) != ATRBVH_OK)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate sort counters for %lu "
                             "primitives",
                             (unsigned long)n);
    return ATRBVH_OK;
}
