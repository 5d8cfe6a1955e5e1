/*
 * animated.c - the animated built-in scenes (animated.h).
 *
 *  wave     a cloth-like grid over [-1, 1]^2 (y up) under two travelling
 *           waves and a bump that circles the middle: smooth deformation,
 *           neighbours stay neighbours (refitting's good case).
 *  shatter  builtin:sphere with its triangles unshared, in fragments of
 *           FRAGMENT consecutive triangles (neighbouring patches) that fly
 *           outwards from frame 0, each at its own speed, spinning about
 *           its own axis, under gravity (refitting's bad case: every box
 *           grows and overlaps).
 *  traffic  builtin:city (three quarters of N) with vehicles (boxes,
 *           12 triangles each, the last quarter) driving along the
 *           streets at their own speeds and wrapping around at the city's
 *           edge (a few jump across the city each second).
 *
 * A frame is a pure function of (N, frame): the only randomness is a hash
 * of indices (rng.h), time is frame / 30 seconds.
 */
#include "config.h"

#include "animated.h"
#include "loader.h"
#include "rng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FRAGMENT 24 /* shatter: triangles per fragment */
#define VEHICLE_SHARE 0.25

static double hash01(uint64_t seed, uint64_t i)
{
    return rng_unit(rng_mix64(rng_mix64(seed * 0x9e3779b97f4a7c15ull) + i));
}

static void put(float *v, size_t i, double x, double y, double z)
{
    v[3 * i] = (float)x;
    v[3 * i + 1] = (float)y;
    v[3 * i + 2] = (float)z;
}

/* ----------------------------------------------------------------- wave */
static int open_wave(size_t n, anim_scene *a, char *err, size_t err_len)
{
    scene *s = &a->s;
    size_t gx, gz, i, j, t = 0;
    gx = (size_t)(sqrt((double)n / 2.0) + 0.5);
    if (gx < 1)
        gx = 1;
    gz = (size_t)((double)n / (2.0 * (double)gx) + 0.5);
    if (gz < 1)
        gz = 1;
    memset(s, 0, sizeof *s);
    s->vertex_count = (gx + 1) * (gz + 1);
    s->triangle_count = 2 * gx * gz;
    s->vertices = malloc(s->vertex_count * 3 * sizeof(float));
    s->indices = malloc(s->triangle_count * 3 * sizeof(uint32_t));
    if (!s->vertices || !s->indices)
        return scene_fail(err, err_len, "builtin:wave: out of memory");
    snprintf(s->name, sizeof s->name, "builtin:wave");
    for (j = 0; j <= gz; j++)
        for (i = 0; i <= gx; i++)
            put(s->vertices, j * (gx + 1) + i,
                -1.0 + 2.0 * (double)i / (double)gx, 0.0,
                -1.0 + 2.0 * (double)j / (double)gz);
    for (j = 0; j < gz; j++)
        for (i = 0; i < gx; i++) {
            uint32_t q = (uint32_t)(j * (gx + 1) + i), r = q + 1,
                     c = (uint32_t)(q + gx + 1), d = c + 1;
            uint32_t *x = s->indices + 3 * t;
            x[0] = q, x[1] = c, x[2] = r, x[3] = r, x[4] = c, x[5] = d;
            t += 2;
        }
    a->gx = gx;
    a->gz = gz;
    return 0;
}

static void frame_wave(anim_scene *a, double t)
{
    const double cx = 0.6 * cos(0.7 * t), cz = 0.6 * sin(0.9 * t);
    size_t v;
    for (v = 0; v < a->s.vertex_count; v++) {
        const double x = a->base[3 * v], z = a->base[3 * v + 2];
        const double dx = x - cx, dz = z - cz;
        double y = 0.12 * sin(4.0 * x - 2.0 * t) * cos(3.0 * z + 1.3 * t) +
                   0.04 * sin(11.0 * (x + z) - 5.0 * t) +
                   0.35 * exp(-(dx * dx + dz * dz) / 0.04);
        put(a->s.vertices, v, x + 0.06 * sin(2.0 * z + t), y,
            z + 0.06 * sin(2.5 * x - 0.8 * t));
    }
}

/* -------------------------------------------------------------- shatter */
static int open_shatter(size_t n, anim_scene *a, char *err, size_t err_len)
{
    scene sphere, *s = &a->s;
    size_t t;
    if (scene_builtin("sphere", n, &sphere, err, err_len) != 0)
        return -1;
    memset(s, 0, sizeof *s);
    s->triangle_count = sphere.triangle_count;
    s->vertex_count = 3 * sphere.triangle_count;
    s->vertices = malloc(s->vertex_count * 3 * sizeof(float));
    s->indices = malloc(s->triangle_count * 3 * sizeof(uint32_t));
    if (!s->vertices || !s->indices) {
        scene_free(&sphere);
        return scene_fail(err, err_len, "builtin:shatter: out of memory");
    }
    snprintf(s->name, sizeof s->name, "builtin:shatter");
    for (t = 0; t < 3 * s->triangle_count; t++) {
        memcpy(s->vertices + 3 * t, sphere.vertices + 3 * sphere.indices[t],
               3 * sizeof(float));
        s->indices[t] = (uint32_t)t;
    }
    scene_free(&sphere);
    a->first = FRAGMENT;
    return 0;
}

static void frame_shatter(anim_scene *a, double t)
{
    const size_t tris = a->s.triangle_count, per = a->first;
    size_t f;
    for (f = 0; f * per < tris; f++) {
        const size_t v0 = 3 * f * per,
                     v1 = 3 * (f * per + per < tris ? f * per + per : tris);
        double c[3] = {0, 0, 0}, len, dir[3], ax[3], speed, w, cs, sn;
        size_t v;
        int k;
        for (v = v0; v < v1; v++)
            for (k = 0; k < 3; k++)
                c[k] += a->base[3 * v + k];
        for (k = 0; k < 3; k++)
            c[k] /= (double)(v1 - v0);
        len = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        for (k = 0; k < 3; k++)
            dir[k] = len > 0 ? c[k] / len : (k == 1);
        speed = 0.3 + 0.9 * hash01(0x5ba7u, 4 * f);
        w = 1.0 + 4.0 * hash01(0x5ba7u, 4 * f + 1);
        {
            double z = 2.0 * hash01(0x5ba7u, 4 * f + 2) - 1.0;
            double phi = 6.283185307179586 * hash01(0x5ba7u, 4 * f + 3);
            double r = sqrt(1.0 - z * z);
            ax[0] = r * cos(phi);
            ax[1] = r * sin(phi);
            ax[2] = z;
        }
        cs = cos(w * t);
        sn = sin(w * t);
        for (v = v0; v < v1; v++) {
            double p[3], q[3], d;
            for (k = 0; k < 3; k++)
                p[k] = a->base[3 * v + k] - c[k];
            /* Rodrigues: p cos + (ax x p) sin + ax (ax . p)(1 - cos). */
            d = ax[0] * p[0] + ax[1] * p[1] + ax[2] * p[2];
            q[0] = p[0] * cs + (ax[1] * p[2] - ax[2] * p[1]) * sn +
                   ax[0] * d * (1 - cs);
            q[1] = p[1] * cs + (ax[2] * p[0] - ax[0] * p[2]) * sn +
                   ax[1] * d * (1 - cs);
            q[2] = p[2] * cs + (ax[0] * p[1] - ax[1] * p[0]) * sn +
                   ax[2] * d * (1 - cs);
            put(a->s.vertices, v, c[0] + q[0] + dir[0] * speed * t,
                c[1] + q[1] + dir[1] * speed * t - 0.3 * t * t,
                c[2] + q[2] + dir[2] * speed * t);
        }
    }
}

/* -------------------------------------------------------------- traffic */
static const unsigned char box_faces[12][3] = {
    {0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};

static int open_traffic(size_t n, anim_scene *a, char *err, size_t err_len)
{
    scene city, *s = &a->s;
    size_t cars = (size_t)((double)n * VEHICLE_SHARE / 12.0 + 0.5), c, k;
    size_t city_n = n > 12 * cars ? n - 12 * cars : 12;
    float lo[3], hi[3];
    if (cars < 1)
        cars = 1;
    if (scene_builtin("city", city_n, &city, err, err_len) != 0)
        return -1;
    memset(s, 0, sizeof *s);
    s->vertex_count = city.vertex_count + 8 * cars;
    s->triangle_count = city.triangle_count + 12 * cars;
    s->vertices = malloc(s->vertex_count * 3 * sizeof(float));
    s->indices = malloc(s->triangle_count * 3 * sizeof(uint32_t));
    if (!s->vertices || !s->indices) {
        scene_free(&city);
        return scene_fail(err, err_len, "builtin:traffic: out of memory");
    }
    snprintf(s->name, sizeof s->name, "builtin:traffic");
    memcpy(s->vertices, city.vertices, city.vertex_count * 3 * sizeof(float));
    memcpy(s->indices, city.indices,
           city.triangle_count * 3 * sizeof(uint32_t));
    for (c = 0; c < cars; c++)
        for (k = 0; k < 12; k++) {
            uint32_t *x = s->indices + 3 * (city.triangle_count + 12 * c + k);
            x[0] = (uint32_t)(city.vertex_count + 8 * c + box_faces[k][0]);
            x[1] = (uint32_t)(city.vertex_count + 8 * c + box_faces[k][1]);
            x[2] = (uint32_t)(city.vertex_count + 8 * c + box_faces[k][2]);
        }
    scene_bounds(&city, lo, hi);
    a->first = city.vertex_count;
    a->extent = hi[0] > -lo[0] ? hi[0] : -lo[0];
    scene_free(&city);
    return 0;
}

static void frame_traffic(anim_scene *a, double t)
{
    const size_t cars = (a->s.vertex_count - a->first) / 8;
    const double half = a->extent, span = 2.0 * half;
    const size_t lines = (size_t)(span + 0.5) + 1;
    size_t c, k;
    for (c = 0; c < cars; c++) {
        const int along_x = hash01(0x7aa1u, 4 * c) < 0.5;
        const double line =
            -half + (double)(size_t)(hash01(0x7aa1u, 4 * c + 1) *
                                     (double)lines);
        const double dirn = hash01(0x7aa1u, 4 * c + 2) < 0.5 ? -1.0 : 1.0;
        const double speed = 0.5 + 1.5 * hash01(0x7aa1u, 4 * c + 3);
        double pos = -half + span * hash01(0x7aa1u, 4 * c + 5) +
                     dirn * speed * t;
        double lo[3], hi[3], lane = dirn * 0.08;
        pos = fmod(pos + half, span);
        if (pos < 0)
            pos += span;
        pos -= half;
        if (along_x) {
            lo[0] = pos - 0.15, hi[0] = pos + 0.15;
            lo[2] = line + lane - 0.06, hi[2] = line + lane + 0.06;
        } else {
            lo[2] = pos - 0.15, hi[2] = pos + 0.15;
            lo[0] = line + lane - 0.06, hi[0] = line + lane + 0.06;
        }
        lo[1] = 0.0;
        hi[1] = 0.12;
        for (k = 0; k < 8; k++)
            put(a->s.vertices, a->first + 8 * c + k,
                (k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1],
                (k & 4) ? hi[2] : lo[2]);
    }
}

/* ------------------------------------------------------------------ API */
int anim_scene_open(const char *spec, anim_scene *out, char *err,
                    size_t err_len)
{
    const char *name, *colon;
    size_t n = 100000, len;
    int rc;
    memset(out, 0, sizeof *out);
    if (strncmp(spec, "builtin:", 8) != 0)
        return scene_fail(err, err_len, "%s: not an animated scene (%s, "
                          "with an optional :TRIANGLES)", spec,
                          ANIM_SCENE_NAMES);
    name = spec + 8;
    colon = strchr(name, ':');
    len = colon ? (size_t)(colon - name) : strlen(name);
    if (colon) {
        const char *p = colon + 1;
        n = 0;
        if (!*p)
            return scene_fail(err, err_len, "%s: TRIANGLES is empty", spec);
        for (; *p; p++) {
            if (*p < '0' || *p > '9')
                return scene_fail(err, err_len, "%s: TRIANGLES is not a "
                                  "whole number", spec);
            if (n <= SCENE_BUILTIN_MAX)
                n = n * 10 + (size_t)(*p - '0');
        }
        if (n < 1 || n > SCENE_BUILTIN_MAX)
            return scene_fail(err, err_len, "%s: TRIANGLES must be from 1 "
                              "to %zu", spec, SCENE_BUILTIN_MAX);
    }
    if (len == 4 && strncmp(name, "wave", 4) == 0) {
        out->kind = 0;
        rc = open_wave(n, out, err, err_len);
    } else if (len == 7 && strncmp(name, "shatter", 7) == 0) {
        out->kind = 1;
        rc = open_shatter(n, out, err, err_len);
    } else if (len == 7 && strncmp(name, "traffic", 7) == 0) {
        out->kind = 2;
        rc = open_traffic(n, out, err, err_len);
    } else {
        return scene_fail(err, err_len, "%s: unknown animated scene (%s)",
                          spec, ANIM_SCENE_NAMES);
    }
    if (rc == 0) {
        size_t bytes = out->s.vertex_count * 3 * sizeof(float);
        out->base = malloc(bytes);
        if (!out->base)
            rc = scene_fail(err, err_len, "%s: out of memory", spec);
        else
            memcpy(out->base, out->s.vertices, bytes);
    }
    if (rc != 0) {
        scene_free(&out->s);
        memset(out, 0, sizeof *out);
        return -1;
    }
    anim_scene_frame(out, 0);
    return 0;
}

void anim_scene_frame(anim_scene *a, unsigned frame)
{
    const double t = (double)frame / 30.0;
    switch (a->kind) {
    case 0:
        frame_wave(a, t);
        break;
    case 1:
        frame_shatter(a, t);
        break;
    default:
        frame_traffic(a, t);
        break;
    }
}

void anim_scene_free(anim_scene *a)
{
    scene_free(&a->s);
    free(a->base);
    memset(a, 0, sizeof *a);
}
