/*
 * cpu/morton.c - stage "morton": a 63-bit Morton key (21 bits per axis, x
 * the most significant of each triplet) for the centre of each primitive
 * box, normalised to the centroid box (Lauterbach et al. 2009; Karras
 * 2012).  The frame (lo, scale) is the pipeline's, computed once on the
 * host for every backend; the per-item rule is shared/arith.h's.
 */
#include "config.h"

#include "cpu.h"

atrbvh_status atrbvh_i_cpu_morton(atrbvh_device *dev, atrbvh_i_run *run,
                                  atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    const atrbvh_box *boxes = c->boxes;
    const double *lo = run->morton_lo, *scale = run->morton_scale;
    const int64_t n = run->n;
    uint64_t *keys;
    int64_t i;
    (void)dev;
    keys = c->keys = atrbvh_i_scratch_get(c->scratch, CPU_KEYS, run->n,
                                          sizeof *c->keys);
    if (!keys)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate Morton keys for %lu primitives",
                             (unsigned long)run->n);
#ifdef _OPENMP
#pragma omp parallel for num_threads(run->cfg->threads) schedule(static)
#endif
    for (i = 0; i < n; i++) {
        const atrbvh_box b = boxes[i];
        atrbvh_u32 q[3];
        int a;
        for (a = 0; a < 3; a++)
            q[a] = atrbvh_morton_quantise(atrbvh_box_centre(b, a), lo[a],
                                          scale[a]);
        keys[i] = atrbvh_morton_key(q[0], q[1], q[2]);
    }
    return ATRBVH_OK;
}
