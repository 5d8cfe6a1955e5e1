/*
 * sort.c - stage "sort": stable radix sort of (63-bit key, 32-bit value)
 * pairs.
 *
 * One most-significant-digit pass over the top varying bits scatters the
 * pairs into buckets of about ATRBVH_SORT_BUCKET_TARGET items; each bucket
 * is then sorted in cache by further MSD passes on its own top varying bits
 * (atrbvh_sort_bucket, shared/sort.h: the OpenCL sort_buckets kernel runs
 * the same code), down to insertion sort for buckets of a few items.
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
 * Thread hand-overs: the tool's threads sleep at a barrier (passive
 * wait), and each wake-up costs tens of microseconds on a loaded
 * machine, so the stage keeps to the barriers the data needs.  The
 * counts come from the morton stage's sweep when its guess of the digit
 * holds (morton.c), each block scans them itself instead of one thread
 * between two barriers, and the buckets wait for the scatter only: one
 * barrier per sort where there were three (LD_PRELOAD count of
 * GOMP_barrier, bunny and dragon, 2 threads).
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
/* The passes' digits, block ranges, scan and placement, the MSD digit's
 * width (atrbvh_sort_msd) and the buckets' sort (atrbvh_sort_bucket) are
 * the code of shared/sort.h, the same the OpenCL kernels run. */

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

uint32_t atrbvh_i_sort_blocks(uint32_t n, int threads)
{
    uint32_t blocks = threads < 1                ? 1u
                      : threads > MAX_BLOCKS ? MAX_BLOCKS
                                                 : (uint32_t)threads;
    return blocks > n ? (n ? n : 1u) : blocks;
}

/* Not inlined: in the region's function the loop reloaded its pointers,
 * shift and mask from the stack at every item (callgrind, dragon: 4 more
 * instructions per key); as a call they stay in registers. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static void scatter(const uint64_t *keys, const uint32_t *values,
                    uint64_t *tmp_keys, uint32_t *tmp_values, uint32_t lo,
                    uint32_t hi, uint32_t shift, uint32_t bits,
                    uint32_t *next)
{
    uint32_t j;
    for (j = lo; j < hi; j++) {
        const uint32_t o = atrbvh_sort_place(
            next, atrbvh_sort_digit_bits(keys[j], shift, bits));
        tmp_keys[o] = keys[j];
        tmp_values[o] = values[j];
    }
}

/* The MSD pass and the buckets' sort over `blocks` blocks, on the digit
 * of `bits` bits at `shift`.  `counted`: each block's digit counts
 * (blocks x 2^bits, block-major) when the morton stage counted them in
 * its sweep (morton.c); NULL: counted here, first. */
static atrbvh_status msd_sort(uint64_t *keys, uint32_t *values,
                              uint64_t *tmp_keys, uint32_t *tmp_values,
                              uint32_t n, int blocks, uint32_t shift,
                              uint32_t bits, uint32_t *counted)
{
    const uint32_t buckets = 1u << bits;
    const int count_here = counted == NULL;
    uint32_t *counts, *start;

    counts = count_here ? atrbvh_i_alloc_array((size_t)blocks * buckets,
                                               sizeof *counts)
                        : counted;
    start = atrbvh_i_alloc_array((size_t)buckets + 1, sizeof *start);
    if (!counts || !start) {
        if (count_here)
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
        if (count_here) { /* (the same for every thread) */
#ifdef _OPENMP
#pragma omp for schedule(static, 1)
#endif
            for (b = 0; b < blocks; b++) {
                uint32_t lo, hi, j, *c = counts + (size_t)b * buckets;
                atrbvh_block_range(n, (atrbvh_u32)b, (atrbvh_u32)blocks, &lo,
                                   &hi);
                memset(c, 0, buckets * sizeof *c);
                for (j = lo; j < hi; j++)
                    c[atrbvh_sort_digit_bits(keys[j], shift, bits)]++;
            }
        }
        /* No serial scan between the passes (it cost a barrier, a
         * thread hand-over): each block scans the counts itself, read
         * only now, for its own output offsets - digit d of block b
         * starts after every smaller digit of all blocks and digit d of
         * the blocks before b (atrbvh_sort_slot's digit-major order) -
         * and block 0's offsets are the buckets' starts.  The scan is
         * blocks x buckets additions per block, integers: the same
         * offsets as one scan. */
#ifdef _OPENMP
#pragma omp for schedule(static, 1)
#endif
        for (b = 0; b < blocks; b++) {
            uint32_t next[ATRBVH_SORT_MSD_RADIX];
            uint32_t lo, hi, d, total = 0;
            int bb;
            for (d = 0; d < buckets; d++) {
                uint32_t before = 0, all;
                for (bb = 0; bb < b; bb++)
                    before += counts[(size_t)bb * buckets + d];
                all = before;
                for (; bb < blocks; bb++)
                    all += counts[(size_t)bb * buckets + d];
                next[d] = total + before;
                total += all;
            }
            if (b == 0) {
                memcpy(start, next, buckets * sizeof *start);
                start[buckets] = total;
            }
            atrbvh_block_range(n, (atrbvh_u32)b, (atrbvh_u32)blocks, &lo, &hi);
            scatter(keys, values, tmp_keys, tmp_values, lo, hi, shift, bits,
                    next);
        }
        /* Buckets are independent; the result lands back in keys/values. */
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16)
#endif
        for (bk = 0; bk < (int64_t)buckets; bk++) {
            const uint32_t s = start[bk], len = start[bk + 1] - s;
            if (len)
                atrbvh_sort_bucket(tmp_keys + s, tmp_values + s, keys + s,
                                   values + s, len, 1, (int)shift);
        }
    }
    if (count_here)
        atrbvh_i_free(counts);
    atrbvh_i_free(start);
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_radix_sort_varying(uint64_t *keys, uint32_t *values,
                                          uint64_t *tmp_keys,
                                          uint32_t *tmp_values, uint32_t n,
                                          int threads, uint64_t varying)
{
    atrbvh_u32 shift, bits;
    if (n < 2 || !varying)
        return ATRBVH_OK; /* all keys equal: the input order is sorted */
    /* MSD digit: the top `bits` varying bit positions, enough for buckets
     * of about ATRBVH_SORT_BUCKET_TARGET items. */
    atrbvh_sort_msd(n, varying, &shift, &bits);
    return msd_sort(keys, values, tmp_keys, tmp_values, n,
                    (int)atrbvh_i_sort_blocks(n, threads), shift, bits, NULL);
}

/* The stage: keys (morton) sorted with their build indices. */
atrbvh_status atrbvh_i_cpu_sort(atrbvh_device *dev, atrbvh_i_run *run,
                                atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    const uint32_t n = run->n;
    uint64_t *tmp_keys;
    uint32_t *tmp_order;
    atrbvh_status st;
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
    /* c->order holds the build indices (morton wrote them).  When the
     * morton stage's guess of the MSD digit (morton.c) is the digit of
     * the keys' varying bits, its counts are this pass's: the sort then
     * starts with the scatter, one barrier (a thread hand-over) fewer. */
    if (c->msd_counts && n >= 2 && c->key_varying) {
        atrbvh_u32 shift, bits;
        atrbvh_sort_msd(n, c->key_varying, &shift, &bits);
        if (shift == c->msd_shift && bits == c->msd_bits)
            st = msd_sort(c->keys, c->order, tmp_keys, tmp_order, n,
                          (int)c->msd_blocks, shift, bits, c->msd_counts);
        else
            st = atrbvh_i_radix_sort_varying(c->keys, c->order, tmp_keys,
                                             tmp_order, n, run->cfg->threads,
                                             c->key_varying);
    } else {
        st = atrbvh_i_radix_sort_varying(c->keys, c->order, tmp_keys,
                                         tmp_order, n, run->cfg->threads,
                                         c->key_varying);
    }
    atrbvh_i_free(c->msd_counts);
    c->msd_counts = NULL;
    if (st != ATRBVH_OK)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate sort counters for %lu "
                             "primitives",
                             (unsigned long)n);
    return ATRBVH_OK;
}
