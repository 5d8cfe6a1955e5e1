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
 * Parallel shape (as on a GPU): for the MSD pass the input is cut into
 * fixed contiguous blocks (ATRBVH_I_BLOCKS_PER_THREAD a thread, taken in
 * turn: cpu.h), the digits of each block are counted, an exclusive scan
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
    const uint32_t blocks = (uint32_t)atrbvh_i_blocks_for(threads, MAX_BLOCKS);
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

/* What the buckets' phase prepares for the hierarchy stage (hierarchy.c)
 * as each bucket's positions become final, so that its region needs no
 * barrier between that sweep and its block passes: leaf n-1+i of `box`
 * (whose entries 0 .. n-1 are the primitive boxes) takes box[order[i]],
 * in place (entry n-1, both primitive n-1 and leaf 0, read into `last`
 * before any leaf is written), and delta[i] the Karras delta of split i
 * (the hierarchy reads it from the leaves' half of the count array).
 * With box NULL, the deltas only: an LBVH's hierarchy pass reads each
 * leaf's box at its primitive's (cpu.h, leaf_boxes_by_order). */
typedef struct sort_leaves {
    atrbvh_box *box;
    atrbvh_box last;
    uint32_t *delta;
} sort_leaves;

/* Sorted positions lo .. hi-1 (one bucket): their leaves, and the deltas
 * of the splits between them; the split after hi-1, whose right key is
 * another bucket's, waits for the end of the phase (msd_sort).  The
 * prefetch stays inside the bucket (other buckets' orders may still be
 * moving). */
static void bucket_leaves(const uint64_t *keys, const uint32_t *order,
                          uint32_t n_, uint32_t lo, uint32_t hi_,
                          const sort_leaves *lv)
{
    /* (64-bit indices, the last box in a local: as the hierarchy's own
     * sweep, cpu.h's atrbvh_i_gather_leaf, runs them) */
    atrbvh_box *const box = lv->box;
    uint32_t *const delta = lv->delta;
    const atrbvh_box last = lv->last;
    const int64_t n = n_, hi = hi_;
    int64_t i;
    if (!box) {
        for (i = lo; i + 1 < hi; i++)
            delta[i] = (uint32_t)atrbvh_karras_delta(keys, n, i, i + 1);
        return;
    }
    for (i = lo; i < hi; i++) {
        const uint32_t k = order[i];
#if defined(__GNUC__) || defined(__clang__)
        if (i + 16 < hi)
            __builtin_prefetch(&box[order[i + 16]]);
#endif
        box[n - 1 + i] = k == (uint32_t)(n - 1) ? last : box[k];
        if (i + 1 < hi)
            delta[i] = (uint32_t)atrbvh_karras_delta(keys, n, i, i + 1);
    }
}

/* Block b of `blocks` over keys[0 .. n): its counts of the digit of
 * `bits` bits at `shift`, into c[0 .. 2^bits). */
static void count_block(const uint64_t *keys, uint32_t n, int b, int blocks,
                        uint32_t shift, uint32_t bits, uint32_t *c)
{
    uint32_t lo, hi, j;
    atrbvh_block_range(n, (atrbvh_u32)b, (atrbvh_u32)blocks, &lo, &hi);
    memset(c, 0, ((size_t)1 << bits) * sizeof *c);
    for (j = lo; j < hi; j++)
        c[atrbvh_sort_digit_bits(keys[j], shift, bits)]++;
}

/* Block b's part of a pass over (k, v)[0 .. n) into (dk, dv), from every
 * block's counts (blocks x 2^bits, block-major).  No serial scan between
 * counting and scattering (it cost a barrier, a thread hand-over): each
 * block scans the counts itself, read only by then, for its own output
 * offsets - digit d of block b starts after every smaller digit of all
 * blocks and digit d of the blocks before b (atrbvh_sort_slot's
 * digit-major order) - and block 0's offsets are the buckets' starts,
 * into start[0 .. 2^bits] with the total.  The scan is blocks x buckets
 * additions per block, integers: the same offsets as one scan. */
static void scatter_block(const uint32_t *counts, int b, int blocks,
                          const uint64_t *k, const uint32_t *v, uint64_t *dk,
                          uint32_t *dv, uint32_t n, uint32_t shift,
                          uint32_t bits, uint32_t *start)
{
    const uint32_t buckets = 1u << bits;
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
    scatter(k, v, dk, dv, lo, hi, shift, bits, next);
}

/* Bucket [s, s+len) of the first pass, in (tmp_keys, tmp_values), sorted
 * into (keys, values) on `blocks` threads (the OpenCL host's big_buckets
 * launches the same steps: cl/stages.c): the first pass's shape again
 * over the bucket (its varying bits, an MSD digit for sub-buckets of
 * about ATRBVH_SORT_BUCKET_TARGET keys, digit counts per block, each block
 * scanning them, a stable scatter into keys), then each sub-bucket sorted
 * in cache (atrbvh_sort_bucket, back into keys) and its leaves (lv), and
 * the deltas of the splits between sub-buckets.  A stable sort has one
 * result, so the keys and values are those of atrbvh_sort_bucket on the
 * whole bucket, for any blocks. */
static atrbvh_status sort_big(uint64_t *keys, uint32_t *values,
                              uint64_t *tmp_keys, uint32_t *tmp_values,
                              uint32_t n, uint32_t s, uint32_t len,
                              int blocks, int threads, sort_leaves *lv)
{
    const uint64_t *bk = tmp_keys + s;
    uint64_t varying = 0;
    uint32_t shift, bits, buckets, *counts, *start, d;
    atrbvh_i_join join = {0};
    int64_t i;
#ifdef _OPENMP
#pragma omp parallel for num_threads(atrbvh_i_team(blocks, threads)) \
    schedule(static) reduction(| : varying)
#endif
    for (i = 1; i < (int64_t)len; i++)
        varying |= bk[i] ^ bk[0];
    if (!varying) { /* one key: the input order is the sorted one */
        memcpy(keys + s, bk, (size_t)len * sizeof *keys);
        memcpy(values + s, tmp_values + s, (size_t)len * sizeof *values);
        if (lv)
            bucket_leaves(keys, values, n, s, s + len, lv);
        return ATRBVH_OK;
    }
    atrbvh_sort_msd(len, varying, &shift, &bits);
    buckets = 1u << bits;
    counts = atrbvh_i_alloc_array((size_t)blocks * buckets, sizeof *counts);
    start = atrbvh_i_alloc_array((size_t)buckets + 1, sizeof *start);
    if (!counts || !start) {
        atrbvh_i_free(counts);
        atrbvh_i_free(start);
        return ATRBVH_ERR_NOMEM;
    }
#ifdef _OPENMP
#pragma omp parallel num_threads(atrbvh_i_team(blocks, threads))
#endif
    {
        int b;
        int64_t k;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
        for (b = 0; b < blocks; b++)
            count_block(bk, len, b, blocks, shift, bits,
                        counts + (size_t)b * buckets);
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
        for (b = 0; b < blocks; b++)
            scatter_block(counts, b, blocks, bk, tmp_values + s, keys + s,
                          values + s, len, shift, bits, start);
        /* the sub-buckets, in cache, back into keys */
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16) nowait
#endif
        for (k = 0; k < (int64_t)buckets; k++) {
            const uint32_t s2 = s + start[k], len2 = start[k + 1] - start[k];
            if (len2)
                atrbvh_sort_bucket(keys + s2, values + s2, tmp_keys + s2,
                                   tmp_values + s2, len2, 0, (int)shift);
            if (len2 && lv)
                bucket_leaves(keys, values, n, s2, s2 + len2, lv);
        }
        atrbvh_i_join_arrive(&join);
    }
    if (lv) /* the splits between sub-buckets (the bucket's last: msd_sort) */
        for (d = 0; d < buckets; d++) {
            const uint32_t e = s + start[d + 1];
            if (start[d + 1] > start[d] && e < s + len)
                lv->delta[e - 1] =
                    (uint32_t)atrbvh_karras_delta(keys, n, e - 1, e);
        }
    atrbvh_i_free(counts);
    atrbvh_i_free(start);
    return ATRBVH_OK;
}

/* The MSD pass and the buckets' sort over `blocks` blocks, on the digit
 * of `bits` bits at `shift`.  `counted`: each block's digit counts
 * (blocks x 2^bits, block-major) when the morton stage counted them in
 * its sweep (morton.c); NULL: counted here, first. */
static atrbvh_status msd_sort(uint64_t *keys, uint32_t *values,
                              uint64_t *tmp_keys, uint32_t *tmp_values,
                              uint32_t n, int blocks, int threads,
                              uint32_t shift, uint32_t bits,
                              uint32_t *counted, sort_leaves *lv)
{
    const uint32_t buckets = 1u << bits;
    const int count_here = counted == NULL;
    /* buckets of more than `big` keys (shared/sort.h's atrbvh_sort_big):
     * sort_big, after the others */
    const uint32_t big =
        atrbvh_sort_big(n, (uint32_t)atrbvh_i_team(blocks, threads));
    atrbvh_status st = ATRBVH_OK;
    uint32_t *counts, *start;
    atrbvh_i_join join = {0};

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
#pragma omp parallel num_threads(atrbvh_i_team(blocks, threads))
#endif
    {
        int b;
        int64_t bk;
        if (count_here) { /* (the same for every thread) */
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
            for (b = 0; b < blocks; b++)
                count_block(keys, n, b, blocks, shift, bits,
                            counts + (size_t)b * buckets);
        }
        /* each block's offsets and scatter (scatter_block) */
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
        for (b = 0; b < blocks; b++)
            scatter_block(counts, b, blocks, keys, values, tmp_keys,
                          tmp_values, n, shift, bits, start);
        /* Buckets are independent; the result lands back in keys/values. */
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16) nowait
#endif
        for (bk = 0; bk < (int64_t)buckets; bk++) {
            const uint32_t s = start[bk], len = start[bk + 1] - s;
            if (len > big)
                continue; /* sort_big, below */
            if (len)
                atrbvh_sort_bucket(tmp_keys + s, tmp_values + s, keys + s,
                                   values + s, len, 1, (int)shift);
            if (len && lv)
                bucket_leaves(keys, values, n, s, s + len, lv);
        }
        atrbvh_i_join_arrive(&join);
    }
    {
        uint32_t bk2;
        for (bk2 = 0; bk2 < buckets && st == ATRBVH_OK; bk2++)
            if (start[bk2 + 1] - start[bk2] > big)
                st = sort_big(keys, values, tmp_keys, tmp_values, n,
                              start[bk2], start[bk2 + 1] - start[bk2],
                              blocks, threads, lv);
    }
    if (st != ATRBVH_OK) {
        if (count_here)
            atrbvh_i_free(counts);
        atrbvh_i_free(start);
        return st;
    }
    if (lv) { /* the splits between buckets, all keys now in place */
        uint32_t bk2;
        for (bk2 = 0; bk2 < buckets; bk2++) {
            const uint32_t e = start[bk2 + 1];
            if (e > start[bk2] && e < n)
                lv->delta[e - 1] =
                    (uint32_t)atrbvh_karras_delta(keys, n, e - 1, e);
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
                    (int)atrbvh_i_sort_blocks(n, threads), threads, shift,
                    bits, NULL, NULL);
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
    int by_order;
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
    /* An LBVH of its own primitives (no kept ids, enough of them)
     * gathers no leaf box: its hierarchy pass reads them where they are,
     * and its node box slot holds the primitive boxes and the pass's
     * leftovers only (cpu.h; backend.c's plan). */
    by_order = atrbvh_i_lbvh_in_place(run->cfg->method, n, c->ids != NULL);
    c->leaves_ready = 0;
    c->leaf_boxes_by_order = 0;
    if ((n < 2 || !c->key_varying) && !by_order) {
        /* already sorted (build order): the hierarchy gathers */
        st = ATRBVH_OK;
    } else if (!c->key_varying) {
        /* every key equal: sorted already (build order); the deltas for
         * the hierarchy, as one bucket of the whole */
        sort_leaves lv;
        lv.box = NULL;
        lv.last = atrbvh_box_empty(); /* (not read without boxes) */
        lv.delta = atrbvh_i_scratch_get(c->scratch, CPU_COUNT,
                                        2 * (size_t)n - 1, sizeof *lv.delta);
        if (!lv.delta)
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                                 "cannot allocate the node counts for %lu "
                                 "primitives",
                                 (unsigned long)n);
        lv.delta += n - 1;
        bucket_leaves(c->keys, c->order, n, 0, n, &lv);
        c->leaves_ready = 1;
        c->leaf_boxes_by_order = 1;
        st = ATRBVH_OK;
    } else {
        /* c->order holds the build indices (morton wrote them).  When
         * the morton stage's guess of the MSD digit (morton.c) is the
         * digit of the keys' varying bits, its counts are this pass's:
         * the sort then starts with the scatter, one barrier (a thread
         * hand-over) fewer.  The buckets' phase gathers the leaf boxes
         * and writes the deltas for the hierarchy stage (sort_leaves),
         * in the node box and count arrays it would get there (the
         * memory plan, backend.c). */
        atrbvh_u32 shift, bits;
        uint32_t *counted = NULL;
        int blocks = (int)atrbvh_i_sort_blocks(n, run->cfg->threads);
        sort_leaves lv;
        const size_t nodes = 2 * (size_t)n - 1;
        lv.box = atrbvh_i_scratch_get(
            c->scratch, CPU_BOX,
            atrbvh_i_node_boxes(run->cfg->method, n, c->ids != NULL),
            sizeof *lv.box);
        lv.delta = atrbvh_i_scratch_get(c->scratch, CPU_COUNT, nodes,
                                        sizeof *lv.delta);
        if (!lv.box || !lv.delta)
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                                 "cannot allocate the node boxes and "
                                 "counts for %lu primitives",
                                 (unsigned long)n);
        c->boxes = lv.box; /* (moved along if the slot had to grow) */
        lv.last = lv.box[n - 1];
        lv.delta += n - 1;
        c->leaf_boxes_by_order = by_order;
        if (by_order)
            lv.box = NULL;
        atrbvh_sort_msd(n, c->key_varying, &shift, &bits);
        if (c->msd_counts && shift == c->msd_shift && bits == c->msd_bits) {
            counted = c->msd_counts;
            blocks = (int)c->msd_blocks;
        }
        st = msd_sort(c->keys, c->order, tmp_keys, tmp_order, n, blocks,
                      run->cfg->threads, shift, bits, counted, &lv);
        c->leaves_ready = st == ATRBVH_OK;
        c->leaf_boxes_by_order &= c->leaves_ready;
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
