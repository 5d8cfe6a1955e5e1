/*
 * scene.h - scenes for the command-line tool and the tests: PLY (binary and
 * ASCII), OBJ, and generated built-in scenes.  Only positions are read.
 * Not part of the library: the library takes geometry, never files.
 */
#ifndef ATRBVH_TOOLS_SCENE_H
#define ATRBVH_TOOLS_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "atrbvh.h"

typedef struct scene {
    float *vertices;        /* 3 floats per vertex                        */
    size_t vertex_count;
    uint32_t *indices;      /* 3 per triangle                             */
    size_t triangle_count;
    char name[64];          /* file base name or "builtin:sphere"         */
} scene;

/* Loads `spec`: a path ending in .ply or .obj (case-insensitive), or
 * "builtin:NAME[:N]" with NAME one of sphere, terrain, city (N: roughly the
 * triangle count; default 100000).  Returns 0 on success; on failure
 * returns -1 and writes one line to err (no trailing newline) that names
 * the file and the line or byte offset of the problem. */
int scene_load(const char *spec, scene *out, char *err, size_t err_len);
void scene_free(scene *s);
/* Progress of scene_load for the tool's display: `fraction` of the file
 * read (0 .. 0.5) and parsed (0.5 .. 1), called now and then from the
 * loading thread; NULL turns it off.  Not thread-safe (one loader at a
 * time in a process that sets it). */
typedef void (*scene_progress_fn)(double fraction, void *user);
void scene_set_progress(scene_progress_fn fn, void *user);
/* The library's view of the scene (no copy). */
atrbvh_geometry scene_geometry(const scene *s);

/* Generated scenes, also used directly by the tests.  Deterministic. */
int scene_builtin(const char *name, size_t approx_triangles, scene *out,
                  char *err, size_t err_len);

/* Bounding box of all referenced vertices. */
void scene_bounds(const scene *s, float lo[3], float hi[3]);

/* -------------------------------------------------------------- cameras */
typedef struct camera {
    float eye[3], forward[3], right[3], up[3]; /* right/up scaled to the
                                                   half-extent of the image
                                                   plane at distance 1      */
    float far_distance;                         /* ray length for diffuse  */
} camera;

/* Viewpoint `which` (0, 1, 2, ...) framing the box lo..hi, deterministic:
 * see atrbvh(1), "CAMERAS". aspect = width / height. */
void camera_frame(const float lo[3], const float hi[3], unsigned which,
                  float aspect, camera *cam);
/* The primary ray through pixel (x, y) with subpixel offset (sx, sy) in
 * [0, 1). */
void camera_ray(const camera *cam, unsigned width, unsigned height,
                unsigned x, unsigned y, float sx, float sy, atrbvh_ray *ray);

#endif
