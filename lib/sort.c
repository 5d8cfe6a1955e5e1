/*
 * sort.c - stage "sort": stable least-significant-digit radix sort of
 * (63-bit key, 32-bit value) pairs, 8-bit digits.
 *
 * Parallel shape (as on a GPU): each thread owns a fixed contiguous block of
 * the input; per pass it counts digits in its block, an exclusive scan over
 * (digit, block) gives every block its output offsets, and each block
 * scatters its items in order.  Stability makes the result unique — the
 * sorted order with ties in input order — so it cannot depend on the number
 * of threads.  A pass whose digit is the same for every key moves nothing
 * and is skipped: scenes whose keys vary in fewer bits sort in fewer passes.
 */
#include "config.h"

#include "internal.h"

#include <string.h>

#define RADIX_BITS 8
#define RADIX (1u << RADIX_BITS)
#define KEY_BITS 64
#define MAX_BLOCKS 256

/* The [lo, hi) range of block b of `blocks` over n items. */
static void block_range(uint32_t n, int b, int blocks, uint32_t *lo,
                        uint32_t *hi)
{
    *lo = (uint32_t)((uint64_t)n * (uint64_t)b / (uint64_t)blocks);
    *hi = (uint32_t)((uint64_t)n * (uint64_t)(b + 1) / (uint64_t)blocks);
}

atrbvh_status __atrbvh_radix_sort(uint64_t *keys, uint32_t *values,
                                  uint64_t *tmp_keys, uint32_t *tmp_values,
                                  uint32_t n, int threads)
{
    uint32_t(*counts)[RADIX]; /* counts[block][digit], then offsets */
    uint64_t *src_k = keys, *dst_k = tmp_keys;
    uint32_t *src_v = values, *dst_v = tmp_values;
    int blocks, shift;
    uint64_t varying = 0;
    uint32_t i;

    if (n < 2)
        return ATRBVH_OK;
    blocks = threads < 1 ? 1 : threads > MAX_BLOCKS ? MAX_BLOCKS : threads;
    if ((uint32_t)blocks > n)
        blocks = (int)n;
    counts = __atrbvh_alloc_array((size_t)blocks, sizeof *counts);
    if (!counts)
        return ATRBVH_ERR_NOMEM;

    /* Which bits vary at all: or of every key xor the first. */
    for (i = 1; i < n; i++)
        varying |= keys[i] ^ keys[0];

    for (shift = 0; shift < KEY_BITS; shift += RADIX_BITS) {
        uint32_t total = 0;
        if (!((varying >> shift) & (RADIX - 1)))
            continue;
#ifdef _OPENMP
#pragma omp parallel num_threads(blocks)
#endif
        {
            int b;
#ifdef _OPENMP
#pragma omp for schedule(static, 1)
#endif
            for (b = 0; b < blocks; b++) {
                uint32_t lo, hi, j;
                block_range(n, b, blocks, &lo, &hi);
                memset(counts[b], 0, sizeof counts[b]);
                for (j = lo; j < hi; j++)
                    counts[b][(src_k[j] >> shift) & (RADIX - 1)]++;
            }
#ifdef _OPENMP
#pragma omp single
#endif
            {
                unsigned d;
                int bb;
                for (d = 0; d < RADIX; d++)
                    for (bb = 0; bb < blocks; bb++) {
                        uint32_t t = counts[bb][d];
                        counts[bb][d] = total;
                        total += t;
                    }
            }
#ifdef _OPENMP
#pragma omp for schedule(static, 1)
#endif
            for (b = 0; b < blocks; b++) {
                uint32_t lo, hi, j;
                block_range(n, b, blocks, &lo, &hi);
                for (j = lo; j < hi; j++) {
                    uint32_t o = counts[b][(src_k[j] >> shift) & (RADIX - 1)]++;
                    dst_k[o] = src_k[j];
                    dst_v[o] = src_v[j];
                }
            }
        }
        {
            uint64_t *tk = src_k;
            uint32_t *tv = src_v;
            src_k = dst_k;
            src_v = dst_v;
            dst_k = tk;
            dst_v = tv;
        }
    }
    if (src_k != keys) {
        memcpy(keys, src_k, (size_t)n * sizeof *keys);
        memcpy(values, src_v, (size_t)n * sizeof *values);
    }
    __atrbvh_free(counts);
    return ATRBVH_OK;
}
