/*
 * animated.h - animated built-in scenes for `atrbvh animate` and the
 * tests: builtin:wave, builtin:shatter, builtin:traffic, each a pure
 * function of (N, frame), with a fixed topology (the same triangles and
 * indices at every frame; only positions move).
 */
#ifndef ATRBVH_TOOLS_ANIMATED_H
#define ATRBVH_TOOLS_ANIMATED_H

#include <stddef.h>

#include "scene.h"

typedef struct anim_scene {
    scene s;          /* the current frame's positions             */
    float *base;      /* frame 0's vertices (3 floats per vertex)   */
    int kind;         /* 0 wave, 1 shatter, 2 traffic              */
    size_t first;     /* traffic: first vehicle vertex; shatter:
                         triangles per fragment                     */
    double extent;    /* traffic: half the city's width             */
    size_t gx, gz;    /* wave: grid cells                           */
} anim_scene;

/* The animated built-ins' names, for help texts. */
#define ANIM_SCENE_NAMES "builtin:wave, builtin:shatter, builtin:traffic"

/* Opens "builtin:NAME[:N]" (N: roughly the triangle count, default
 * 100000) at frame 0; 0, or -1 with one line in err. */
int anim_scene_open(const char *spec, anim_scene *out, char *err,
                    size_t err_len);
/* Moves the vertices to `frame` (frames are 1/30 s apart). */
void anim_scene_frame(anim_scene *a, unsigned frame);
void anim_scene_free(anim_scene *a);

#endif
