/*
 * cpu/bounds.c - stage "bounds": one box per primitive, the scene box and
 * the centroid box, in one sweep over the geometry (read in place through
 * its strides): lib/prims.c's atrbvh_i_prims_sweep, the same code the
 * host's error scan runs.  A primitive that is invalid (NaN/Inf, a bad
 * index, an inverted box) only sets run->bad: the pipeline then finds the
 * exact error on the host, the same way for every backend.  The reduction
 * is min/max only, so its order cannot change the result.
 */
#include "config.h"

#include "cpu.h"

atrbvh_status atrbvh_i_cpu_bounds(atrbvh_device *dev, atrbvh_i_run *run,
                                  atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    const size_t n = run->in.g->primitive_count;
    atrbvh_i_prims_scan scan;
    (void)dev;
    c->boxes = atrbvh_i_scratch_get(c->scratch, CPU_BOXES, n, sizeof *c->boxes);
    if (!c->boxes)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate %lu primitive boxes",
                             (unsigned long)n);
    c->ids = NULL;
    c->kept_ids = 0;
    atrbvh_i_prims_sweep(&run->in, run->cfg->threads, c->boxes, &scan);
    run->bad = scan.first_bad >= 0;
    run->n = (uint32_t)n;
    run->scene = scan.scene;
    run->centroids = scan.centroids;
    return ATRBVH_OK;
}
