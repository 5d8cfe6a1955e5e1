/*
 * shared/types.h - the plain-data types both sides exchange, defined once.
 *
 * The public header lib/atrbvh.h is the definition of atrbvh_node,
 * atrbvh_ray and atrbvh_hit for C; OpenCL C cannot include it (it pulls
 * in <stdint.h> and <stddef.h> and declares host functions), so this
 * header repeats their fields for OpenCL C only, and the layout block at
 * the end - compiled on BOTH sides, as C99 and as OpenCL C - pins sizes
 * and field offsets to the same numbers.  A change to either definition
 * that moves a byte fails to compile on one side (host: `make`; device:
 * the program build at atrbvh_device_open), so the two cannot drift.
 * Every other shared struct that crosses the host/device boundary (the
 * kernel arguments, shared/kargs.h) uses the same assertion macro.
 */
#ifndef ATRBVH_SHARED_TYPES_H
#define ATRBVH_SHARED_TYPES_H

#include "arith.h"

#ifdef __OPENCL_VERSION__
typedef struct atrbvh_node {
    float min[3];
    float max[3];
    atrbvh_u32 index;
    atrbvh_u32 count;
} atrbvh_node;
typedef struct atrbvh_ray {
    float origin[3];
    float dir[3];
    float tmin, tmax;
} atrbvh_ray;
typedef struct atrbvh_hit {
    float t, u, v;
    atrbvh_u32 primitive;
} atrbvh_hit;
#define ATRBVH_NO_HIT 0xffffffffu
#define ATRBVH_OFFSETOF(type, field) __builtin_offsetof(type, field)
#else
#include <stddef.h>
#include "atrbvh.h"
#define ATRBVH_OFFSETOF(type, field) offsetof(type, field)
#endif

/* A compile-time check that works in C99 and OpenCL C 1.2 alike (a
 * negative array size is an error in both). */
#define ATRBVH_STATIC_ASSERT(cond, name)                                       \
    typedef char atrbvh_static_assert_##name[(cond) ? 1 : -1]

ATRBVH_STATIC_ASSERT(sizeof(atrbvh_box) == 24, box_size);
ATRBVH_STATIC_ASSERT(sizeof(atrbvh_node) == 32, node_size);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_node, max) == 12, node_max);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_node, index) == 24, node_index);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_node, count) == 28, node_count);
ATRBVH_STATIC_ASSERT(sizeof(atrbvh_ray) == 32, ray_size);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_ray, dir) == 12, ray_dir);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_ray, tmin) == 24, ray_tmin);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_ray, tmax) == 28, ray_tmax);
ATRBVH_STATIC_ASSERT(sizeof(atrbvh_hit) == 16, hit_size);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_hit, u) == 4, hit_u);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_hit, v) == 8, hit_v);
ATRBVH_STATIC_ASSERT(ATRBVH_OFFSETOF(atrbvh_hit, primitive) == 12,
                     hit_primitive);

#endif
