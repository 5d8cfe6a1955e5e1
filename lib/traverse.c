/* placeholder: ray queries */
#include "internal.h"
int atrbvh_intersect(const atrbvh_bvh *bvh, const atrbvh_geometry *geometry,
                     const atrbvh_ray *ray, atrbvh_hit *hit)
{ (void)bvh; (void)geometry; (void)ray; hit->primitive = ATRBVH_NO_HIT; return 0; }
int atrbvh_occluded(const atrbvh_bvh *bvh, const atrbvh_geometry *geometry,
                    const atrbvh_ray *ray)
{ (void)bvh; (void)geometry; (void)ray; return 0; }
