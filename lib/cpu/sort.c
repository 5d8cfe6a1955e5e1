/*
 * sort.c - stage "sort": stable radix sort of (63-bit key, 32-bit value)
 * pairs.
 *
 * One most-significant-digit pass over the top varying bits scatters the
 * pairs into buckets of about BUCKET_TARGET items; each bucket is then
 * sorted on its remaining bits, in cache, by further MSD counting passes
 * (a digit of up to 8 bits at the bucket's own top varying bit, so bits
 * that no key of the bucket changes cost nothing), recursing into the
 * sub-buckets and ping-ponging between the two buffers, with insertion
 * below INSERTION_MAX items.  Every step is stable, so the result is the
 * unique sorted order with ties in input order: it cannot depend on the
 * number of threads.
 *
 * Parallel shape (as on a GPU): for the MSD pass each thread owns a fixed
 * contiguous block of the input, counts digits in it, an exclusive scan
 * over (digit, block) gives each block its output offsets, and each block
 * scatters in order; buckets are then independent items.
 *
 * Measured on the dragon's 871,414 keys, one thread, this machine: 8 plain
 * LSD passes took ~300 ms (random stores into 512 streams, TLB-bound); the
 * MSD pass with per-bucket LSD passes ~45 ms (wall, loaded machine), and
 * the per-bucket MSD recursion runs 7% fewer instructions than that with
 * 55% fewer L1 read misses and 78% fewer L1 write misses (callgrind).
 */
#include "config.h"

#include "internal.h"

#include <string.h>

#define MAX_BLOCKS 256
#define MSD_MAX_BITS 11
#define BUCKET_TARGET 1024u
#define INSERTION_MAX 32u
#define SUB_MAX_BITS 8

/* The [lo, hi) range of block b of `blocks` over n items. */
static void block_range(uint32_t n, int b, int blocks, uint32_t *lo,
                        uint32_t *hi)
{
    *lo = (uint32_t)((uint64_t)n * (uint64_t)b / (uint64_t)blocks);
    *hi = (uint32_t)((uint64_t)n * (uint64_t)(b + 1) / (uint64_t)blocks);
}

static int highest_bit(uint64_t x)
{
    int h = 63;
    while (h > 0 && !(x >> h))
        h--;
    return h;
}

/* Stable insertion sort of k/v[0..n).  Only called on a bucket, whose
 * keys agree on every bit above the bits still to sort, so whole keys
 * compare as the masked ones would. */
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

/* Bits of the digit of a bucket of n items below the top level: about
 * n/2 .. n sub-buckets, at most SUB_MAX_BITS. */
static int sub_bits(uint32_t n)
{
    int b = highest_bit(n);
    return b < 1 ? 1 : b > SUB_MAX_BITS ? SUB_MAX_BITS : b;
}

static void sort_into(uint64_t *k, uint32_t *v, uint64_t *dk, uint32_t *dv,
                      uint32_t n, uint64_t mask);

/* Counting-sort pass of (k, v) into (dk, dv) on the digit of `bits` bits
 * that ends at the highest bit of `varying`; fills start[0 .. 2^bits] and
 * returns the digit's shift. */
static int digit_pass(const uint64_t *k, const uint32_t *v, uint64_t *dk,
                      uint32_t *dv, uint32_t n, uint64_t varying, int bits,
                      uint32_t *start)
{
    const int top = highest_bit(varying);
    const uint32_t radix = 1u << bits;
    int shift;
    uint32_t i, d, total = 0;
    if (bits > top + 1)
        bits = top + 1;
    shift = top + 1 - bits;
    memset(start, 0, (radix + 1) * sizeof *start);
    for (i = 0; i < n; i++)
        start[((k[i] >> shift) & (radix - 1)) + 1]++;
    for (d = 0; d < radix; d++) {
        total += start[d + 1];
        start[d + 1] = total;
    }
    /* start[d] is now the first slot of digit d; scatter in order. */
    {
        uint32_t next[1u << SUB_MAX_BITS];
        memcpy(next, start, radix * sizeof *next);
        for (i = 0; i < n; i++) {
            const uint32_t o = next[(k[i] >> shift) & (radix - 1)]++;
            dk[o] = k[i];
            dv[o] = v[i];
        }
    }
    return shift;
}

/* Sorts (k, v) in place on the bits in `mask`, (tk, tv) as scratch: one
 * MSD digit at the top varying bit, the sub-buckets sorted back into
 * (k, v) by sort_into; insertion below INSERTION_MAX. */
static void sort_inplace(uint64_t *k, uint32_t *v, uint64_t *tk,
                         uint32_t *tv, uint32_t n, uint64_t mask)
{
    uint32_t start[(1u << SUB_MAX_BITS) + 1], d, radix;
    uint64_t varying = 0;
    uint32_t i;
    int bits, shift;
    for (i = 1; i < n; i++)
        varying |= k[i] ^ k[0];
    varying &= mask;
    if (!varying)
        return;
    if (n <= INSERTION_MAX) {
        insertion_sort(k, v, n);
        return;
    }
    bits = sub_bits(n);
    shift = digit_pass(k, v, tk, tv, n, varying, bits, start);
    radix = 1u << (highest_bit(varying) + 1 - shift);
    for (d = 0; d < radix; d++) {
        const uint32_t s = start[d], len = start[d + 1] - s;
        if (len)
            sort_into(tk + s, tv + s, k + s, v + s, len,
                      mask & (((uint64_t)1 << shift) - 1));
    }
}

/* Sorts (k, v) on the bits in `mask` into (dk, dv); (k, v) is scratch. */
static void sort_into(uint64_t *k, uint32_t *v, uint64_t *dk, uint32_t *dv,
                      uint32_t n, uint64_t mask)
{
    uint32_t start[(1u << SUB_MAX_BITS) + 1], d, radix;
    uint64_t varying = 0;
    uint32_t i;
    int bits, shift;
    for (i = 1; i < n; i++)
        varying |= k[i] ^ k[0];
    varying &= mask;
    if (!varying || n <= INSERTION_MAX) {
        memcpy(dk, k, (size_t)n * sizeof *k);
        memcpy(dv, v, (size_t)n * sizeof *v);
        if (varying)
            insertion_sort(dk, dv, n);
        return;
    }
    bits = sub_bits(n);
    shift = digit_pass(k, v, dk, dv, n, varying, bits, start);
    radix = 1u << (highest_bit(varying) + 1 - shift);
    for (d = 0; d < radix; d++) {
        const uint32_t s = start[d], len = start[d + 1] - s;
        if (len)
            sort_inplace(dk + s, dv + s, k + s, v + s, len,
                         mask & (((uint64_t)1 << shift) - 1));
    }
}

atrbvh_status atrbvh_i_radix_sort(uint64_t *keys, uint32_t *values,
                                  uint64_t *tmp_keys, uint32_t *tmp_values,
                                  uint32_t n, int threads)
{
    uint32_t *counts, *start;
    uint64_t varying = 0, low_mask;
    int blocks, top, bits, shift;
    uint32_t buckets, target;
    int64_t i;

    if (n < 2)
        return ATRBVH_OK;
    blocks = threads < 1 ? 1 : threads > MAX_BLOCKS ? MAX_BLOCKS : threads;
    if ((uint32_t)blocks > n)
        blocks = (int)n;

#ifdef _OPENMP
#pragma omp parallel for num_threads(blocks) schedule(static) \
    reduction(| : varying)
#endif
    for (i = 1; i < (int64_t)n; i++)
        varying |= keys[i] ^ keys[0];
    if (!varying)
        return ATRBVH_OK; /* all keys equal: the input order is sorted */

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
    low_mask = shift ? (((uint64_t)1 << shift) - 1) : 0;

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
            block_range(n, b, blocks, &lo, &hi);
            memset(c, 0, buckets * sizeof *c);
            for (j = lo; j < hi; j++)
                c[(keys[j] >> shift) & (buckets - 1)]++;
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
            block_range(n, b, blocks, &lo, &hi);
            for (j = lo; j < hi; j++) {
                uint32_t o = c[(keys[j] >> shift) & (buckets - 1)]++;
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
                sort_into(tmp_keys + s, tmp_values + s, keys + s,
                          values + s, len, low_mask);
        }
    }
    atrbvh_i_free(counts);
    atrbvh_i_free(start);
    return ATRBVH_OK;
}
