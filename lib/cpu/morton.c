/*
 * morton.c - stage "morton": a 63-bit Morton key (21 bits per axis, x the
 * most significant of each triplet) for the centre of each primitive box,
 * normalised to the centroid box (Lauterbach et al. 2009; Karras 2012).
 *
 * The per-axis scale is computed once here, on the host, and is the only
 * input besides the boxes, so every backend quantises identically.  A
 * zero-extent axis gets scale 0: all its coordinates quantise to 0 rather
 * than to 0/0.
 */
#include "config.h"

#include "internal.h"

void atrbvh_i_morton_frame(const atrbvh_box *centroids, double lo[3],
                           double scale[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        double extent = (double)centroids->max[k] - (double)centroids->min[k];
        lo[k] = (double)centroids->min[k];
        scale[k] = extent > 0.0 ? (double)(1u << ATRBVH_MORTON_BITS) / extent
                                : 0.0;
    }
}

void atrbvh_i_morton(const atrbvh_i_prims *p, uint64_t *keys, int threads)
{
    double lo[3], scale[3];
    int64_t i;
    atrbvh_i_morton_frame(&p->centroids, lo, scale);
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static)
#else
    (void)threads;
#endif
    for (i = 0; i < (int64_t)p->count; i++) {
        const atrbvh_box b = p->boxes[i];
        atrbvh_u32 q[3];
        int a;
        for (a = 0; a < 3; a++)
            q[a] = atrbvh_morton_quantise(atrbvh_box_centre(b, a), lo[a],
                                          scale[a]);
        keys[i] = atrbvh_morton_key(q[0], q[1], q[2]);
    }
}
