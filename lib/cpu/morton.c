/*
 * cpu/morton.c - stage "morton": a 63-bit Morton key (21 bits per axis, x
 * the most significant of each triplet) for the centre of each primitive
 * box, normalised to the centroid box (Lauterbach et al. 2009; Karras
 * 2012).  The frame (lo, scale) is the pipeline's, computed once on the
 * host for every backend; the per-item rule is shared/arith.h's.  The
 * same sweep writes the sort's values (the build indices, as the OpenCL
 * morton kernel does) and the OR and AND of all keys, from which the sort
 * knows the bits that vary without reading the keys again.
 *
 * The sweep also counts the sort's MSD digits (sort.c), per block of the
 * sort's own block ranges, on a guess of the digit: the top varying bit
 * of the keys is nearly always that of the first axis whose centroid
 * extent is not zero (x, bit 62; y, 61; z, 60), as the centroids at the
 * box's two ends quantise to 0 and 2^21-1 on it.  The sort checks the
 * guess against the real varying bits and counts again when it is wrong
 * (its result is the same either way); when right, the pass between
 * counting and scattering - a barrier, a thread hand-over - is saved.
 */
#include "config.h"

#include "cpu.h"
#include "shared/sort.h"

#include <string.h>

atrbvh_status atrbvh_i_cpu_morton(atrbvh_device *dev, atrbvh_i_run *run,
                                  atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    const atrbvh_box *const boxes = c->boxes;
    const double lo0 = run->morton_lo[0], lo1 = run->morton_lo[1],
                 lo2 = run->morton_lo[2], s0 = run->morton_scale[0],
                 s1 = run->morton_scale[1], s2 = run->morton_scale[2];
    const uint32_t n = run->n;
    const int blocks = (int)atrbvh_i_sort_blocks(n, run->cfg->threads);
    uint64_t *keys, key_or = 0, key_and = ~(uint64_t)0;
    uint32_t *order, *counts = NULL;
    atrbvh_u32 sh = 0, bi = 1; /* (no guess: a 2-entry dummy row) */
    uint32_t shift, bits;
    int b, top = -1;
    (void)dev;
    keys = c->keys = atrbvh_i_scratch_get(c->scratch, CPU_KEYS, run->n,
                                          sizeof *c->keys);
    order = c->order = atrbvh_i_scratch_get(c->scratch, CPU_ORDER, run->n,
                                            sizeof *c->order);
    if (!keys || !order)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate Morton keys for %lu primitives",
                             (unsigned long)run->n);
    /* The guess of the top varying bit (the file's comment). */
    if (s0 > 0.0)
        top = 62;
    else if (s1 > 0.0)
        top = 61;
    else if (s2 > 0.0)
        top = 60;
    atrbvh_i_free(c->msd_counts);
    c->msd_counts = NULL;
    if (n >= 2 && top >= 0) {
        atrbvh_sort_msd(n, (uint64_t)1 << top, &sh, &bi);
        counts = atrbvh_i_alloc_array((size_t)blocks << bi, sizeof *counts);
        if (!counts)
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                                 "cannot allocate sort counters for %lu "
                                 "primitives",
                                 (unsigned long)run->n);
    }
    /* (copies: the region reads the variables whose addresses were taken
     * through pointers, again after every store of a key) */
    shift = sh;
    bits = bi;
#ifdef _OPENMP
#pragma omp parallel for num_threads(blocks) schedule(static, 1) \
    reduction(| : key_or) reduction(& : key_and)
#endif
    for (b = 0; b < blocks; b++) {
        uint32_t dummy[2], *cnt = counts ? counts + ((size_t)b << bits) : dummy;
        uint32_t lo, hi;
        int64_t i;
        atrbvh_block_range(n, (atrbvh_u32)b, (atrbvh_u32)blocks, &lo, &hi);
        memset(cnt, 0, ((size_t)1 << bits) * sizeof *cnt);
        for (i = lo; i < (int64_t)hi; i++) {
            const atrbvh_box bx = boxes[i];
            const uint64_t key = atrbvh_morton_key(
                atrbvh_morton_quantise(atrbvh_box_centre(bx, 0), lo0, s0),
                atrbvh_morton_quantise(atrbvh_box_centre(bx, 1), lo1, s1),
                atrbvh_morton_quantise(atrbvh_box_centre(bx, 2), lo2, s2));
            keys[i] = key;
            order[i] = (uint32_t)i;
            cnt[atrbvh_sort_digit_bits(key, shift, bits)]++;
            key_or |= key;
            key_and &= key;
        }
    }
    c->key_varying = key_or ^ key_and;
    c->msd_counts = counts;
    c->msd_blocks = (uint32_t)blocks;
    c->msd_shift = shift;
    c->msd_bits = bits;
    return ATRBVH_OK;
}
