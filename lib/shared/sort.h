/*
 * shared/sort.h - the sort stage's code, written once for the CPU
 * (lib/cpu/sort.c) and the OpenCL kernels (sort_count, whose last block
 * scans, sort_scatter and sort_buckets): the rules of a stable counting
 * pass over blocks, the MSD digit, and the buckets' sort.
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

/* The digit of `key` at bit `shift`, `bits` wide (1..31). */
ATRBVH_FN atrbvh_u32 atrbvh_sort_digit_bits(atrbvh_u64 key, atrbvh_u32 shift,
                                            atrbvh_u32 bits)
{
    return (atrbvh_u32)(key >> shift) & ((1u << bits) - 1u);
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
 * pass on an H200 reading and writing one at a time.  The body is a
 * macro so that a work-item's own (private) counters scan the same way
 * (atrbvh_sort_scan_own: OpenCL C 1.2 has no generic address space). */
#define ATRBVH_SORT_SCAN_CHUNK 8u
#define ATRBVH_SORT_SCAN_BODY(counts, entries)                               \
    atrbvh_u32 i = 0, k, total = 0, t[ATRBVH_SORT_SCAN_CHUNK];               \
    for (; i + ATRBVH_SORT_SCAN_CHUNK <= (entries);                         \
         i += ATRBVH_SORT_SCAN_CHUNK) {                                     \
        for (k = 0; k < ATRBVH_SORT_SCAN_CHUNK; k++)                        \
            t[k] = (counts)[i + k];                                         \
        for (k = 0; k < ATRBVH_SORT_SCAN_CHUNK; k++) {                      \
            (counts)[i + k] = total;                                        \
            total += t[k];                                                  \
        }                                                                   \
    }                                                                       \
    for (; i < (entries); i++) {                                            \
        atrbvh_u32 u = (counts)[i];                                         \
        (counts)[i] = total;                                                \
        total += u;                                                         \
    }                                                                       \
    return total
ATRBVH_FN atrbvh_u32 atrbvh_sort_scan(ATRBVH_SHARED_GLOBAL atrbvh_u32 *counts,
                                      atrbvh_u32 entries)
{
    ATRBVH_SORT_SCAN_BODY(counts, entries);
}
ATRBVH_FN atrbvh_u32 atrbvh_sort_scan_own(atrbvh_u32 *counts,
                                          atrbvh_u32 entries)
{
    ATRBVH_SORT_SCAN_BODY(counts, entries);
}

/* The output position of the next item of digit d: next[d], which then
 * moves on (next[] starts as the block's scanned offsets). */
ATRBVH_FN atrbvh_u32 atrbvh_sort_place(atrbvh_u32 *next, atrbvh_u32 d)
{
    return next[d]++;
}

/* ------------------------------------------------------------ MSD + buckets
 * The stage's shape on both backends (lib/cpu/sort.c, the sort_count,
 * sort_scatter and sort_buckets kernels): ONE stable pass as above on the
 * most significant varying bits (atrbvh_sort_msd) scatters the pairs into
 * buckets of about ATRBVH_SORT_BUCKET_TARGET items, then each bucket is
 * sorted on its own (atrbvh_sort_bucket), by one thread or one work-item.
 * Every step is stable, so the result is the unique sorted order with
 * ties in input order, whatever the blocks, threads or device. */
#define ATRBVH_SORT_MSD_MAX_BITS 11
#define ATRBVH_SORT_MSD_RADIX 2048u /* 1 << ATRBVH_SORT_MSD_MAX_BITS */
#define ATRBVH_SORT_BUCKET_TARGET 1024u

/* The position of the highest set bit of x (0 for x = 0). */
ATRBVH_FN int atrbvh_sort_highest_bit(atrbvh_u64 x)
{
    return x ? 63 - ATRBVH_CLZ64(x) : 0;
}

/* The MSD pass's digit over n keys whose differing bits are `varying`:
 * the top *bits varying bit positions (at *shift), enough for buckets
 * of about ATRBVH_SORT_BUCKET_TARGET items, at most
 * ATRBVH_SORT_MSD_MAX_BITS.  varying = ~0 gives the most buckets any n
 * can have (the device's counts are sized by it). */
ATRBVH_FN void atrbvh_sort_msd(atrbvh_u32 n, atrbvh_u64 varying,
                               atrbvh_u32 *shift, atrbvh_u32 *bits)
{
    const int top = atrbvh_sort_highest_bit(varying);
    atrbvh_u32 target;
    int b = 1;
    for (target = n / ATRBVH_SORT_BUCKET_TARGET;
         target > 1u && b < ATRBVH_SORT_MSD_MAX_BITS; target >>= 1)
        b++;
    if (b > top + 1)
        b = top + 1;
    *shift = (atrbvh_u32)(top + 1 - b);
    *bits = (atrbvh_u32)b;
}

/* A bucket of the first pass is split on every thread (work-item) by a
 * pass of its own before it is sorted (lib/cpu/sort.c's sort_big, the
 * OpenCL host's big_buckets) when it holds more than this many keys
 * (ATRBVH_U32_MAX: never): more than ATRBVH_SORT_BIG_MIN and than a
 * 1 / (ATRBVH_SORT_BIG_SHARE x threads) share of them.  Sorted by one
 * thread it would leave the others idle (conference: one bucket of the
 * first pass holds 206,564 of 331,179 keys).  The sorted order is unique,
 * so the split changes no key's place, only who sorts it. */
#define ATRBVH_SORT_BIG_MIN 16384u
#define ATRBVH_SORT_BIG_SHARE 4u
ATRBVH_FN atrbvh_u32 atrbvh_sort_big(atrbvh_u32 n, atrbvh_u32 threads)
{
    if (threads < 2u)
        return ATRBVH_U32_MAX;
    return n / (ATRBVH_SORT_BIG_SHARE * threads) > ATRBVH_SORT_BIG_MIN
               ? n / (ATRBVH_SORT_BIG_SHARE * threads)
               : ATRBVH_SORT_BIG_MIN;
}

/* A bucket's passes: at most ATRBVH_SORT_BUCKET_BITS-bit digits (11-bit
 * digits measured only 3% fewer instructions on the dragon, for 8 times
 * the counters). */
#define ATRBVH_SORT_BUCKET_BITS 8
#define ATRBVH_SORT_BUCKET_RADIX 256u
/* Buckets of up to this many items: insertion sort. */
#define ATRBVH_SORT_INSERTION_MAX 24u
/* Sub-buckets of up to this many items: atrbvh_sort_small. */
#define ATRBVH_SORT_SMALL_MAX 4u
/* Levels of a bucket's passes: every level but the last two takes at
 * least 3 bits (buckets of more than ATRBVH_SORT_INSERTION_MAX items), so
 * 64-bit keys need at most 23, even adversarial ones. */
#define ATRBVH_SORT_DEPTH 24
/* Levels whose counters are kept while their sub-buckets are sorted (the
 * bucket and two below it: all that real scenes reach); deeper levels
 * find their sub-buckets' ends again from the digits. */
#define ATRBVH_SORT_KEPT 3

/* Stable insertion sort of (k, v)[0..n) on the whole key into (dk, dv),
 * which may be (k, v) (the bits above a bucket's digit are equal inside
 * it, so this is its order too).  Sorting into the other pair saves a
 * bucket's copy to where it must end. */
ATRBVH_FN void atrbvh_sort_insertion(ATRBVH_CONST_GLOBAL atrbvh_u64 *k,
                                     ATRBVH_CONST_GLOBAL atrbvh_u32 *v,
                                     ATRBVH_GLOBAL atrbvh_u64 *dk,
                                     ATRBVH_GLOBAL atrbvh_u32 *dv,
                                     atrbvh_u32 n)
{
    atrbvh_u32 i;
    dk[0] = k[0];
    dv[0] = v[0];
    for (i = 1; i < n; i++) {
        const atrbvh_u64 key = k[i];
        const atrbvh_u32 val = v[i];
        atrbvh_u32 j = i;
        while (j > 0 && dk[j - 1] > key) {
            dk[j] = dk[j - 1];
            dv[j] = dv[j - 1];
            j--;
        }
        dk[j] = key;
        dv[j] = val;
    }
}

/* (dk, dv)[0..n) = (k, v)[0..n). */
ATRBVH_FN void atrbvh_sort_copy(ATRBVH_CONST_GLOBAL atrbvh_u64 *k,
                                ATRBVH_CONST_GLOBAL atrbvh_u32 *v,
                                ATRBVH_GLOBAL atrbvh_u64 *dk,
                                ATRBVH_GLOBAL atrbvh_u32 *dv, atrbvh_u32 n)
{
#ifdef __OPENCL_VERSION__
    atrbvh_u32 i;
    for (i = 0; i < n; i++)
        dk[i] = k[i];
    for (i = 0; i < n; i++)
        dv[i] = v[i];
#else
    /* the C compiler's own copy (the loops above, 3.6 times the
     * instructions) */
    __builtin_memcpy(dk, k, sizeof *dk * n);
    __builtin_memcpy(dv, v, sizeof *dv * n);
#endif
}

/* Stable compare and exchange of two pairs in registers: a conditional
 * move, not a branch (which no predictor does better than a coin toss
 * on). */
ATRBVH_FN void atrbvh_sort_exchange(atrbvh_u64 *a, atrbvh_u64 *b,
                                    atrbvh_u32 *va, atrbvh_u32 *vb)
{
    const atrbvh_u64 x = *a, y = *b;
    const atrbvh_u32 vx = *va, vy = *vb;
    const int swap = x > y;
    *a = swap ? y : x;
    *b = swap ? x : y;
    *va = swap ? vy : vx;
    *vb = swap ? vx : vy;
}

/* (k, v)[0..n), 2 <= n <= ATRBVH_SORT_SMALL_MAX, sorted stably into
 * (dk, dv), which may be (k, v): a bubble sort's network of neighbours'
 * exchanges (stable: equal keys are never exchanged; n = 4 is the
 * odd-even transposition network), in registers, instead of a bucket
 * level and its insertion sort, whose loop exits at a random place
 * (sub-buckets hold about two items: most are 1, 2 or 3).  One thread,
 * fastest of 100 builds: the sort stage 15.6 -> 15.1 ns per triangle on
 * the bunny, 16.2 -> 15.8 on sibenik. */
ATRBVH_FN void atrbvh_sort_small(ATRBVH_CONST_GLOBAL atrbvh_u64 *k,
                                 ATRBVH_CONST_GLOBAL atrbvh_u32 *v,
                                 ATRBVH_GLOBAL atrbvh_u64 *dk,
                                 ATRBVH_GLOBAL atrbvh_u32 *dv, atrbvh_u32 n)
{
    atrbvh_u64 k0 = k[0], k1 = k[1], k2 = 0, k3 = 0;
    atrbvh_u32 v0 = v[0], v1 = v[1], v2 = 0, v3 = 0;
    if (n > 2) {
        k2 = k[2];
        v2 = v[2];
    }
    if (n > 3) {
        k3 = k[3];
        v3 = v[3];
        atrbvh_sort_exchange(&k2, &k3, &v2, &v3);
    }
    atrbvh_sort_exchange(&k0, &k1, &v0, &v1);
    if (n > 2) {
        atrbvh_sort_exchange(&k1, &k2, &v1, &v2);
        if (n > 3) {
            atrbvh_sort_exchange(&k2, &k3, &v2, &v3);
            dk[3] = k3;
            dv[3] = v3;
        }
        atrbvh_sort_exchange(&k0, &k1, &v0, &v1);
        if (n > 3)
            atrbvh_sort_exchange(&k1, &k2, &v1, &v2);
        dk[2] = k2;
        dv[2] = v2;
    }
    dk[0] = k0;
    dk[1] = k1;
    dv[0] = v0;
    dv[1] = v1;
}

/* A bucket level's pass, counting and placing (c: the level's 2^bits
 * counters).  Functions of their own on the CPU: inlined into
 * atrbvh_sort_bucket's loop, the compiler kept fewer of their values in
 * registers (callgrind: +3% for the bucket stage). */
#if defined(__OPENCL_VERSION__) || !defined(__GNUC__)
#define ATRBVH_SORT_OWN_FN ATRBVH_FN
#else
#define ATRBVH_SORT_OWN_FN static __attribute__((noinline, unused))
#endif
ATRBVH_SORT_OWN_FN void atrbvh_sort_count_own(ATRBVH_CONST_GLOBAL atrbvh_u64 *k,
                                              atrbvh_u32 n, atrbvh_u32 *c,
                                              atrbvh_u32 shift,
                                              atrbvh_u32 bits)
{
    atrbvh_u32 i;
    for (i = 0; i < (1u << bits); i++)
        c[i] = 0;
    for (i = 0; i < n; i++)
        c[atrbvh_sort_digit_bits(k[i], shift, bits)]++;
}

ATRBVH_SORT_OWN_FN void atrbvh_sort_scatter_own(
    ATRBVH_CONST_GLOBAL atrbvh_u64 *k, ATRBVH_CONST_GLOBAL atrbvh_u32 *v,
    ATRBVH_GLOBAL atrbvh_u64 *dk, ATRBVH_GLOBAL atrbvh_u32 *dv, atrbvh_u32 n,
    atrbvh_u32 *c, atrbvh_u32 shift, atrbvh_u32 bits)
{
    atrbvh_u32 i;
    for (i = 0; i < n; i++) {
        const atrbvh_u64 key = k[i];
        const atrbvh_u32 o =
            atrbvh_sort_place(c, atrbvh_sort_digit_bits(key, shift, bits));
        dk[o] = key;
        dv[o] = v[i];
    }
}

/* One level of atrbvh_sort_bucket: its range, the next sub-bucket to
 * sort and its digit (kept levels), and the level's digit. */
typedef struct atrbvh_sort_level {
    atrbvh_u32 start, end, next, d;
    int shift, bits;
} atrbvh_sort_level;

/* Sorts the bucket (ak, av)[0..n) stably, with (bk, bv) as scratch of the
 * same length; the result ends in (bk, bv) when `to_b`, else in (ak, av).
 * Bits >= hi are the same in every key of the bucket.
 *
 * Most-significant digit first: one stable counting pass on the top
 * varying bits of the bucket (at most ATRBVH_SORT_BUCKET_BITS of them,
 * fewer for a small bucket, so that its sub-buckets hold a few items
 * each) from one array into the other, then each sub-bucket the same way
 * back (a level deeper), down to insertion sort.  Every sub-bucket's keys
 * share the digit's bits and all above, so each level moves down at least
 * `bits` (>= 3) bits, and in practice 1 or 2 levels below the stage's
 * first pass.  Written as a loop over an explicit stack of levels, not
 * recursion, so that an OpenCL work-item runs the same code (the
 * sort_buckets kernel).  Measured on the dragon (callgrind, one thread),
 * the whole stage: 8-bit LSD passes over each bucket's remaining ~53
 * varying bits cost about 190 instructions per key; this about 120. */
ATRBVH_FN void atrbvh_sort_bucket(ATRBVH_GLOBAL atrbvh_u64 *ak,
                                  ATRBVH_GLOBAL atrbvh_u32 *av,
                                  ATRBVH_GLOBAL atrbvh_u64 *bk,
                                  ATRBVH_GLOBAL atrbvh_u32 *bv, atrbvh_u32 n,
                                  int to_b, int hi)
{
    atrbvh_u32 cnt[ATRBVH_SORT_KEPT + 1][ATRBVH_SORT_BUCKET_RADIX];
    atrbvh_sort_level lv[ATRBVH_SORT_DEPTH];
    atrbvh_u32 s = 0, len = n; /* the range to sort at level `depth` */
    int depth = 0;
    for (;;) {
        /* Level `depth` reads its keys from (ak, av) when even, else from
         * (bk, bv), and must leave them in the other pair when to_tmp. */
        int odd = depth & 1, to_tmp = odd != to_b;
        ATRBVH_GLOBAL atrbvh_u64 *sk = odd ? bk : ak, *dk = odd ? ak : bk;
        ATRBVH_GLOBAL atrbvh_u32 *sv = odd ? bv : av, *dv = odd ? av : bv;
        atrbvh_u32 *c =
            cnt[depth < ATRBVH_SORT_KEPT ? depth : ATRBVH_SORT_KEPT];
        atrbvh_u32 i, radix = 0;
        int bits, shift = 0, guessed = 1;
        int leaf = 0; /* 1: sorted in (sk, sv); 2: where it must end */
        if (len <= ATRBVH_SORT_INSERTION_MAX ||
            depth >= ATRBVH_SORT_DEPTH - 1) {
            /* (the depth cannot be reached: see ATRBVH_SORT_DEPTH) */
            atrbvh_sort_insertion(sk + s, sv + s, (to_tmp ? dk : sk) + s,
                                  (to_tmp ? dv : sv) + s, len);
            leaf = 2;
        } else {
            /* About len / 2 sub-buckets: 2^bits with bits = floor(log2
             * len) - 1. */
            bits = atrbvh_sort_highest_bit((atrbvh_u64)len) - 1;
            if (bits > ATRBVH_SORT_BUCKET_BITS)
                bits = ATRBVH_SORT_BUCKET_BITS;
            /* The digit just below the bits known equal (>= hi): those
             * below the parent's digit mostly vary.  When it does not
             * (every key has the first key's digit), the bits that vary
             * are looked up once and the digit placed at the top of
             * them. */
            for (;;) {
                if (hi <= 0) {
                    leaf = 1; /* all keys equal */
                    break;
                }
                if (bits > hi)
                    bits = hi;
                shift = hi - bits;
                radix = 1u << bits;
                atrbvh_sort_count_own(sk + s, len, c, (atrbvh_u32)shift,
                                      (atrbvh_u32)bits);
                if (c[atrbvh_sort_digit_bits(sk[s], (atrbvh_u32)shift,
                                             (atrbvh_u32)bits)] != len)
                    break;
                if (guessed) {
                    atrbvh_u64 varying = 0;
                    const atrbvh_u64 first = sk[s];
                    for (i = 1; i < len; i++)
                        varying |= sk[s + i] ^ first;
                    if (!varying) {
                        leaf = 1;
                        break;
                    }
                    hi = atrbvh_sort_highest_bit(varying) + 1;
                    guessed = 0;
                } else {
                    hi = shift; /* cannot happen: the top varying bit is
                                   in it */
                }
            }
        }
        if (leaf) {
            if (leaf == 1 && to_tmp)
                atrbvh_sort_copy(sk + s, sv + s, dk + s, dv + s, len);
            depth--;
        } else {
            (void)atrbvh_sort_scan_own(c, radix);
            atrbvh_sort_scatter_own(sk + s, sv + s, dk + s, dv + s, len, c,
                                    (atrbvh_u32)shift, (atrbvh_u32)bits);
            /* c[d] is now the end of sub-bucket d (from s). */
            lv[depth].start = s;
            lv[depth].end = s + len;
            lv[depth].next = s;
            lv[depth].d = 0;
            lv[depth].shift = shift;
            lv[depth].bits = bits;
        }
        /* The next sub-bucket of more than ATRBVH_SORT_SMALL_MAX items of
         * the deepest unfinished level; the smaller ones on the way are
         * finished here. */
        for (; depth >= 0; depth--) {
            atrbvh_sort_level *l = &lv[depth];
            const atrbvh_u32 start = l->start, end = l->end;
            atrbvh_u32 next = l->next, d = l->d;
            int descend = 0;
            odd = depth & 1;
            to_tmp = odd != to_b;
            sk = odd ? bk : ak;
            dk = odd ? ak : bk;
            sv = odd ? bv : av;
            dv = odd ? av : bv;
            while (next < end) {
                const atrbvh_u32 b = next;
                atrbvh_u32 e;
                if (depth < ATRBVH_SORT_KEPT) {
                    const atrbvh_u32 *cd = cnt[depth];
                    while (cd[d] == b - start)
                        d++;
                    e = start + cd[d++];
                } else {
                    const atrbvh_u32 dg = atrbvh_sort_digit_bits(
                        dk[b], (atrbvh_u32)l->shift, (atrbvh_u32)l->bits);
                    for (e = b + 1;
                         e < end &&
                         atrbvh_sort_digit_bits(dk[e], (atrbvh_u32)l->shift,
                                                (atrbvh_u32)l->bits) == dg;
                         e++)
                        ;
                }
                next = e;
                if (e - b == 1) {
                    /* Sorted; where it must end (the common case). */
                    if (!to_tmp) {
                        sk[b] = dk[b];
                        sv[b] = dv[b];
                    }
                } else if (e - b <= ATRBVH_SORT_SMALL_MAX) {
                    atrbvh_sort_small(dk + b, dv + b, (to_tmp ? dk : sk) + b,
                                      (to_tmp ? dv : sv) + b, e - b);
                } else if (e - b <= ATRBVH_SORT_INSERTION_MAX) {
                    /* a level below's leaf, without entering it */
                    atrbvh_sort_insertion(dk + b, dv + b,
                                          (to_tmp ? dk : sk) + b,
                                          (to_tmp ? dv : sv) + b, e - b);
                } else {
                    s = b; /* its own level, below */
                    len = e - b;
                    hi = l->shift;
                    descend = 1;
                    break;
                }
            }
            l->next = next;
            l->d = d;
            if (descend)
                break;
        }
        if (depth < 0)
            return;
        depth++;
    }
}

#endif
