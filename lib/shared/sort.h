/*
 * shared/sort.h - the per-item rules of the sort stage's radix passes,
 * written once for the CPU (lib/cpu/sort.c) and the OpenCL kernels
 * (morton and sort_count, whose last block scans, and sort_scatter).
 *
 * A pass is stable: the n items are cut into `blocks` contiguous blocks
 * (atrbvh_block_range); each block counts its digits; one exclusive scan
 * over the counts in digit-major order (digit d, block b at
 * atrbvh_sort_slot(d, b, blocks)) gives every (digit, block) its first
 * output position; each block then places its items in input order, the
 * k-th item of digit d at that position + k (atrbvh_sort_place).  Items
 * of equal digits thus keep their order, whatever the block count.
 */
#ifndef ATRBVH_SHARED_SORT_H
#define ATRBVH_SHARED_SORT_H

#include "arith.h"

/* The device passes: 8-bit digits, 256 buckets. */
#define ATRBVH_SORT_BITS 8
#define ATRBVH_SORT_RADIX 256u

/* The digit of `key` at bit `shift`, `bits` wide (1..31). */
ATRBVH_FN atrbvh_u32 atrbvh_sort_digit_bits(atrbvh_u64 key, atrbvh_u32 shift,
                                            atrbvh_u32 bits)
{
    return (atrbvh_u32)(key >> shift) & ((1u << bits) - 1u);
}

/* The 8-bit digit of `key` at bit `shift`. */
ATRBVH_FN atrbvh_u32 atrbvh_sort_digit(atrbvh_u64 key, atrbvh_u32 shift)
{
    return atrbvh_sort_digit_bits(key, shift, ATRBVH_SORT_BITS);
}

/* The [lo, hi) range of block b of `blocks` over n items. */
ATRBVH_FN void atrbvh_block_range(atrbvh_u32 n, atrbvh_u32 b,
                                  atrbvh_u32 blocks, atrbvh_u32 *lo,
                                  atrbvh_u32 *hi)
{
    *lo = (atrbvh_u32)((atrbvh_u64)n * (atrbvh_u64)b / (atrbvh_u64)blocks);
    *hi = (atrbvh_u32)((atrbvh_u64)n * (atrbvh_u64)(b + 1u) /
                       (atrbvh_u64)blocks);
}

/* Where the count of digit d in block b lives (digit-major). */
ATRBVH_FN atrbvh_u32 atrbvh_sort_slot(atrbvh_u32 d, atrbvh_u32 b,
                                      atrbvh_u32 blocks)
{
    return d * blocks + b;
}

/* Exclusive prefix sum of counts[0 .. entries) in place; returns the
 * total.  (On the device the counts are other work-items' writes: the
 * kernels' last arrival reads them through a volatile pointer.)  Eight
 * entries are read before any is written, so the eight reads can be in
 * flight together: on a GPU each volatile read goes to memory, and the
 * one item that scans 256 x 256 entries per sort pass took 5.7 ms per
 * pass on an H200 reading and writing one at a time. */
#define ATRBVH_SORT_SCAN_CHUNK 8u
ATRBVH_FN atrbvh_u32 atrbvh_sort_scan(ATRBVH_SHARED_GLOBAL atrbvh_u32 *counts,
                                      atrbvh_u32 entries)
{
    atrbvh_u32 i = 0, k, total = 0, t[ATRBVH_SORT_SCAN_CHUNK];
    for (; i + ATRBVH_SORT_SCAN_CHUNK <= entries; i += ATRBVH_SORT_SCAN_CHUNK) {
        for (k = 0; k < ATRBVH_SORT_SCAN_CHUNK; k++)
            t[k] = counts[i + k];
        for (k = 0; k < ATRBVH_SORT_SCAN_CHUNK; k++) {
            counts[i + k] = total;
            total += t[k];
        }
    }
    for (; i < entries; i++) {
        atrbvh_u32 u = counts[i];
        counts[i] = total;
        total += u;
    }
    return total;
}

/* The output position of the next item of digit d: next[d], which then
 * moves on (next[] starts as the block's scanned offsets). */
ATRBVH_FN atrbvh_u32 atrbvh_sort_place(atrbvh_u32 *next, atrbvh_u32 d)
{
    return next[d]++;
}

#endif
