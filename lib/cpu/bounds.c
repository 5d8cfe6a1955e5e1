/*
 * cpu/bounds.c - stage "bounds": one box per primitive, the scene box and
 * the centroid box.  The geometry is read in place (strides).  A primitive
 * that is invalid (NaN/Inf, a bad index, an inverted box) only sets
 * run->bad: the pipeline then finds the exact error on the host, the same
 * way for every backend.  The reduction is min/max only, so its order
 * cannot change the result.
 */
#include "config.h"

#include "cpu.h"

#include <math.h>

atrbvh_status atrbvh_i_cpu_bounds(atrbvh_device *dev, atrbvh_i_run *run,
                                  atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    const atrbvh_geometry *g = run->in.g;
    const int64_t n = (int64_t)g->primitive_count;
    /* Strides in elements, as the shared fetch takes them. */
    const atrbvh_u64 vstride = run->in.vstride / sizeof(float),
                     istride = run->in.istride / sizeof(uint32_t),
                     bstride = run->in.bstride / sizeof(float);
    atrbvh_box *boxes;
    float smin0, smin1, smin2, smax0, smax1, smax2;
    float cmin0, cmin1, cmin2, cmax0, cmax1, cmax2;
    int bad = 0;
    int64_t j;
    (void)dev;
    boxes = c->boxes = atrbvh_i_scratch_get(c->scratch, CPU_BOXES, (size_t)n,
                                            sizeof *c->boxes);
    if (!boxes)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate %lu primitive boxes",
                             (unsigned long)n);
    c->ids = NULL;
    c->kept_ids = 0;
    smin0 = smin1 = smin2 = cmin0 = cmin1 = cmin2 = INFINITY;
    smax0 = smax1 = smax2 = cmax0 = cmax1 = cmax2 = -INFINITY;
#ifdef _OPENMP
#pragma omp parallel for num_threads(run->cfg->threads) schedule(static) \
    reduction(min : smin0, smin1, smin2, cmin0, cmin1, cmin2)          \
    reduction(max : smax0, smax1, smax2, cmax0, cmax1, cmax2)          \
    reduction(| : bad)
#endif
    for (j = 0; j < n; j++) {
        atrbvh_box b;
        uint32_t value;
        float c0, c1, c2;
        const int r =
            g->type == ATRBVH_GEOMETRY_BOXES
                ? atrbvh_prim_box_box(g->boxes, bstride, (atrbvh_u64)j, &b)
                : atrbvh_prim_box_triangle(g->vertices, vstride,
                                           g->vertex_count, g->indices,
                                           istride, g->indices != NULL,
                                           (atrbvh_u64)j, &b, &value);
        if (r != ATRBVH_PRIM_OK) {
            bad = 1;
            continue;
        }
        boxes[j] = b;
        c0 = atrbvh_box_centre(b, 0);
        c1 = atrbvh_box_centre(b, 1);
        c2 = atrbvh_box_centre(b, 2);
        smin0 = b.min[0] < smin0 ? b.min[0] : smin0;
        smin1 = b.min[1] < smin1 ? b.min[1] : smin1;
        smin2 = b.min[2] < smin2 ? b.min[2] : smin2;
        smax0 = b.max[0] > smax0 ? b.max[0] : smax0;
        smax1 = b.max[1] > smax1 ? b.max[1] : smax1;
        smax2 = b.max[2] > smax2 ? b.max[2] : smax2;
        cmin0 = c0 < cmin0 ? c0 : cmin0;
        cmin1 = c1 < cmin1 ? c1 : cmin1;
        cmin2 = c2 < cmin2 ? c2 : cmin2;
        cmax0 = c0 > cmax0 ? c0 : cmax0;
        cmax1 = c1 > cmax1 ? c1 : cmax1;
        cmax2 = c2 > cmax2 ? c2 : cmax2;
    }
    run->bad = bad;
    run->n = (uint32_t)n;
    run->scene.min[0] = smin0;
    run->scene.min[1] = smin1;
    run->scene.min[2] = smin2;
    run->scene.max[0] = smax0;
    run->scene.max[1] = smax1;
    run->scene.max[2] = smax2;
    run->centroids.min[0] = cmin0;
    run->centroids.min[1] = cmin1;
    run->centroids.min[2] = cmin2;
    run->centroids.max[0] = cmax0;
    run->centroids.max[1] = cmax1;
    run->centroids.max[2] = cmax2;
    return ATRBVH_OK;
}
