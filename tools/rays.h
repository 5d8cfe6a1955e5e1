/*
 * rays.h - the fixed ray sets `atrbvh bench` traces through every tree of a
 * scene: primary rays from viewpoints 0..V-1 (camera_frame), then from each
 * primary hit `spp` ambient-occlusion rays (any hit, 0.1 x the scene
 * diagonal) and `spp` diffuse rays (closest hit, 2 x the diagonal),
 * cosine-distributed about the normal turned towards the viewer, the
 * directions from a hash of (viewpoint, pixel, sample).  The same
 * definitions as `atrbvh trace` (which uses viewpoint 0 only).  The
 * secondary rays start from the hits through a reference tree, and every
 * tree then traces the same arrays.
 */
#ifndef ATRBVH_TOOLS_RAYS_H
#define ATRBVH_TOOLS_RAYS_H

#include <stddef.h>

#include "atrbvh.h"
#include "scene.h"

typedef struct ray_set {
    atrbvh_ray *primary, *ao, *diffuse;
    size_t n_primary, n_ao, n_diffuse;
} ray_set;

/* 0 on success; -1 after a cli_error line.  `ref` is any BVH of `sc`.
 * Viewpoint v is camera_viewpoint(v) (inside cameras for rooms,
 * scene_is_room); `view` (may be NULL) the user's --eye/--look-at/--fov. */
int ray_set_make(const scene *sc, const atrbvh_bvh *ref, unsigned width,
                 unsigned height, unsigned viewpoints, unsigned spp,
                 int threads, const camera_view *view, ray_set *rs);

/* The camera options every ray command takes (--eye, --look-at, --fov),
 * written into out[0..RAYS_CAMERA_OPTS-1], their values into *v. */
#define RAYS_CAMERA_OPTS 3
struct cli_opt;
void rays_camera_opts(camera_view *v, struct cli_opt *out);
/* After parsing: a usage error (CLI_USAGE after its line) for --look-at
 * without --eye, or an eye equal to the look-at point; else 0. */
int rays_camera_check(const char *cmd, const camera_view *v);
/* Viewpoint `which` of scene sc (box and room rule computed here). */
int rays_camera(const scene *sc, unsigned which, const camera_view *v,
                float aspect, camera *cam);
void ray_set_free(ray_set *rs);

/* The seeds of the secondary rays (rng.h), shared with `atrbvh trace`. */
#define RAYS_SEED_AO 0x61u
#define RAYS_SEED_DIFFUSE 0xd1u

/* Where a secondary ray starts (the hit point moved off the surface along
 * the normal turned towards the viewer), and the frame around that normal. */
typedef struct ray_surface {
    double p[3], n[3], t[3], b[3];
} ray_surface;

/* The surface of `hit` (a hit of `ray` in `sc`); eps_scale is the scene's
 * part of the offset (the tool uses 1e-5 x the scene diagonal). */
void rays_surface(const scene *sc, const atrbvh_ray *ray,
                  const atrbvh_hit *hit, double eps_scale, ray_surface *s);
/* A cosine-distributed ray about the surface's normal, of `length`; its
 * direction is rng_pair(seed, item, sample). */
void rays_cosine(const ray_surface *s, uint64_t seed, uint64_t item,
                 unsigned sample, float length, atrbvh_ray *r);

/* Unit normal of triangle `prim` turned against `dir` (or -dir when the
 * triangle has no area). */
void rays_normal(const scene *sc, uint32_t prim, const float dir[3],
                 double n[3]);

#endif
