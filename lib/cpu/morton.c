/*
 * cpu/morton.c - stage "morton": a 63-bit Morton key (21 bits per axis, x
 * the most significant of each triplet) for the centre of each primitive
 * box, normalised to the centroid box (Lauterbach et al. 2009; Karras
 * 2012).  The frame (lo, scale) is the pipeline's, computed once on the
 * host for every backend; the per-item rule is shared/arith.h's.  The
 * same sweep writes the sort's values (the build indices, as the OpenCL
 * morton kernel does) and the OR and AND of all keys, from which the sort
 * knows the bits that vary without reading the keys again.
 */
#include "config.h"

#include "cpu.h"

atrbvh_status atrbvh_i_cpu_morton(atrbvh_device *dev, atrbvh_i_run *run,
                                  atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    const atrbvh_box *const boxes = c->boxes;
    const double lo0 = run->morton_lo[0], lo1 = run->morton_lo[1],
                 lo2 = run->morton_lo[2], s0 = run->morton_scale[0],
                 s1 = run->morton_scale[1], s2 = run->morton_scale[2];
    const int64_t n = run->n;
    uint64_t *keys, key_or = 0, key_and = ~(uint64_t)0;
    uint32_t *order;
    int64_t i;
    (void)dev;
    keys = c->keys = atrbvh_i_scratch_get(c->scratch, CPU_KEYS, run->n,
                                          sizeof *c->keys);
    order = c->order = atrbvh_i_scratch_get(c->scratch, CPU_ORDER, run->n,
                                            sizeof *c->order);
    if (!keys || !order)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate Morton keys for %lu primitives",
                             (unsigned long)run->n);
#ifdef _OPENMP
#pragma omp parallel for num_threads(run->cfg->threads) schedule(static) \
    reduction(| : key_or) reduction(& : key_and)
#endif
    for (i = 0; i < n; i++) {
        const atrbvh_box b = boxes[i];
        const uint64_t key = atrbvh_morton_key(
            atrbvh_morton_quantise(atrbvh_box_centre(b, 0), lo0, s0),
            atrbvh_morton_quantise(atrbvh_box_centre(b, 1), lo1, s1),
            atrbvh_morton_quantise(atrbvh_box_centre(b, 2), lo2, s2));
        keys[i] = key;
        order[i] = (uint32_t)i;
        key_or |= key;
        key_and &= key;
    }
    c->key_varying = key_or ^ key_and;
    return ATRBVH_OK;
}
