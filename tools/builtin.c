/*
 * builtin.c - generated scenes: sphere, terrain, city.
 *
 * Deterministic: the only randomness is an integer hash of (seed, index),
 * so a scene is a pure function of its name and N, whatever the platform's
 * rand().  N is matched roughly; every scene has at least a handful of
 * triangles however small N is.
 */
#include "config.h"

#include "loader.h"
#include "rng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* Uniform in [0, 1), 53 bits: hash(seed, i) and hash(seed, i + 1) are
 * unrelated (rng.h's splitmix64 finaliser). */
static double hash01(uint64_t seed, uint64_t i)
{
    return rng_unit(rng_mix64(rng_mix64(seed * 0x9e3779b97f4a7c15ull) + i));
}

static size_t round_size(double x)
{
    return x < 0.5 ? 0 : (size_t)(x + 0.5);
}

/* Allocates the scene's arrays; sizes are checked by the callers' limits
 * (N <= SCENE_BUILTIN_MAX keeps every product far from overflow) and again
 * here. */
static int alloc_scene(scene *s, size_t vertices, size_t triangles,
                       const char *name, char *err, size_t err_len)
{
    memset(s, 0, sizeof *s);
    if (vertices > UINT32_MAX || vertices > SIZE_MAX / (3 * sizeof(float)) ||
        triangles > SIZE_MAX / (3 * sizeof(uint32_t)))
        return scene_fail(err, err_len, "builtin:%s: too large", name);
    s->vertices = malloc(vertices * 3 * sizeof(float));
    s->indices = malloc(triangles * 3 * sizeof(uint32_t));
    if (!s->vertices || !s->indices) {
        free(s->vertices);
        free(s->indices);
        s->vertices = NULL;
        s->indices = NULL;
        return scene_fail(err, err_len, "builtin:%s: out of memory for %zu "
                          "triangles", name, triangles);
    }
    s->vertex_count = vertices;
    s->triangle_count = triangles;
    snprintf(s->name, sizeof s->name, "builtin:%s", name);
    return 0;
}

static void set_v(scene *s, size_t v, double x, double y, double z)
{
    s->vertices[v * 3 + 0] = (float)x;
    s->vertices[v * 3 + 1] = (float)y;
    s->vertices[v * 3 + 2] = (float)z;
}

static void set_t(scene *s, size_t t, size_t a, size_t b, size_t c)
{
    s->indices[t * 3 + 0] = (uint32_t)a;
    s->indices[t * 3 + 1] = (uint32_t)b;
    s->indices[t * 3 + 2] = (uint32_t)c;
}

/* UV sphere of radius 1 at the origin: `stacks` latitude bands (the two
 * polar ones are fans), `slices` longitudes; 2 * slices * (stacks - 1)
 * triangles, the smallest being a 6-triangle bipyramid. */
static int make_sphere(size_t n, scene *s, char *err, size_t err_len)
{
    size_t stacks, slices, rings, v, t, i, j;
    stacks = round_size(sqrt((double)n / 4.0));
    if (stacks < 2)
        stacks = 2;
    slices = round_size((double)n / (2.0 * (double)(stacks - 1)));
    if (slices < 3)
        slices = 3;
    rings = stacks - 1;
    if (alloc_scene(s, 2 + rings * slices, 2 * slices * rings, "sphere", err,
                    err_len) != 0)
        return -1;
    set_v(s, 0, 0.0, 1.0, 0.0);
    for (i = 0; i < rings; i++) {
        double theta = PI * (double)(i + 1) / (double)stacks;
        for (j = 0; j < slices; j++) {
            double phi = 2.0 * PI * (double)j / (double)slices;
            set_v(s, 1 + i * slices + j, sin(theta) * cos(phi), cos(theta),
                  sin(theta) * sin(phi));
        }
    }
    v = 1 + rings * slices;
    set_v(s, v, 0.0, -1.0, 0.0);
    t = 0;
    for (j = 0; j < slices; j++) {
        size_t j1 = (j + 1) % slices;
        set_t(s, t++, 0, 1 + j1, 1 + j);
    }
    for (i = 0; i + 1 < rings; i++) {
        size_t r0 = 1 + i * slices, r1 = r0 + slices;
        for (j = 0; j < slices; j++) {
            size_t j1 = (j + 1) % slices;
            set_t(s, t++, r0 + j, r0 + j1, r1 + j);
            set_t(s, t++, r0 + j1, r1 + j1, r1 + j);
        }
    }
    for (j = 0; j < slices; j++) {
        size_t j1 = (j + 1) % slices, r = 1 + (rings - 1) * slices;
        set_t(s, t++, v, r + j, r + j1);
    }
    return 0;
}

/* Height field over [-1, 1]^2 in x and z, y up: two sinusoid octaves and
 * per-vertex hash noise, 2 * gx * gz triangles (at least 2). */
static int make_terrain(size_t n, scene *s, char *err, size_t err_len)
{
    size_t gx, gz, i, j, t = 0;
    gx = round_size(sqrt((double)n / 2.0));
    if (gx < 1)
        gx = 1;
    gz = round_size((double)n / (2.0 * (double)gx));
    if (gz < 1)
        gz = 1;
    if (alloc_scene(s, (gx + 1) * (gz + 1), 2 * gx * gz, "terrain", err,
                    err_len) != 0)
        return -1;
    for (j = 0; j <= gz; j++) {
        for (i = 0; i <= gx; i++) {
            double x = -1.0 + 2.0 * (double)i / (double)gx;
            double z = -1.0 + 2.0 * (double)j / (double)gz;
            double y = 0.15 * sin(2.7 * x + 0.3) * cos(3.1 * z) +
                       0.05 * sin(9.3 * x + 6.1 * z) +
                       0.02 * (hash01(0x7e44a1u, j * (gx + 1) + i) - 0.5);
            set_v(s, j * (gx + 1) + i, x, y, z);
        }
    }
    for (j = 0; j < gz; j++) {
        for (i = 0; i < gx; i++) {
            size_t a = j * (gx + 1) + i, b = a + 1, c = a + gx + 1,
                   d = c + 1;
            set_t(s, t++, a, c, b);
            set_t(s, t++, b, c, d);
        }
    }
    return 0;
}

/* 8 corners, 12 triangles. */
static void add_box(scene *s, size_t box, const double lo[3],
                    const double hi[3])
{
    static const unsigned char faces[12][3] = {
        {0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    size_t v = box * 8, t = box * 12, k;
    for (k = 0; k < 8; k++)
        set_v(s, v + k, (k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1],
              (k & 4) ? hi[2] : lo[2]);
    for (k = 0; k < 12; k++)
        set_t(s, t + k, v + faces[k][0], v + faces[k][1], v + faces[k][2]);
}

/* Boxes on a square grid of unit cells, centred on the origin, y up: box 0
 * is the ground slab under the whole grid, box 1 the tallest skyscraper,
 * then about 1% skyscrapers (8 to 25 cells tall), 14% mid-rise blocks,
 * 10% tiny details (a few hundredths of a cell) and the rest small
 * buildings, so box sizes span about four orders of magnitude - the case
 * where SAH-driven restructuring matters. */
static int make_city(size_t n, scene *s, char *err, size_t err_len)
{
    size_t boxes = round_size((double)n / 12.0), cells, b;
    double half;
    if (boxes < 1)
        boxes = 1;
    if (alloc_scene(s, boxes * 8, boxes * 12, "city", err, err_len) != 0)
        return -1;
    cells = (size_t)ceil(sqrt((double)(boxes > 1 ? boxes - 1 : 1)));
    half = 0.5 * (double)cells;
    {
        double lo[3] = {-half, -0.05, -half}, hi[3] = {half, 0.0, half};
        add_box(s, 0, lo, hi);
    }
    for (b = 1; b < boxes; b++) {
        size_t cell = b - 1;
        double cx = -half + (double)(cell % cells) + 0.5;
        double cz = -half + (double)(cell / cells) + 0.5;
        double kind = b == 1 ? 0.0 : hash01(0xc17u, b * 4);
        double r1 = hash01(0xc17u, b * 4 + 1), r2 = hash01(0xc17u, b * 4 + 2);
        double r3 = hash01(0xc17u, b * 4 + 3);
        double w, d, h, lo[3], hi[3];
        if (kind < 0.01) {
            w = 0.6 + 0.3 * r1;
            d = 0.6 + 0.3 * r2;
            h = b == 1 ? 25.0 : 8.0 + 17.0 * r3;
        } else if (kind < 0.15) {
            w = 0.4 + 0.4 * r1;
            d = 0.4 + 0.4 * r2;
            h = 1.0 + 2.0 * r3;
        } else if (kind < 0.25) {
            w = 0.01 + 0.03 * r1;
            d = 0.01 + 0.03 * r2;
            h = 0.01 + 0.04 * r3;
        } else {
            w = 0.1 + 0.4 * r1;
            d = 0.1 + 0.4 * r2;
            h = 0.05 + 0.6 * r3;
        }
        /* Off-centre within the cell, never across its border. */
        cx += (r2 - 0.5) * (1.0 - w);
        cz += (r1 - 0.5) * (1.0 - d);
        lo[0] = cx - 0.5 * w;
        hi[0] = cx + 0.5 * w;
        lo[1] = 0.0;
        hi[1] = h;
        lo[2] = cz - 0.5 * d;
        hi[2] = cz + 0.5 * d;
        add_box(s, b, lo, hi);
    }
    return 0;
}

int scene_builtin(const char *name, size_t approx_triangles, scene *out,
                  char *err, size_t err_len)
{
    scene s;
    int rc;
    if (err && err_len > 0)
        err[0] = '\0';
    if (!name || !out)
        return scene_fail(err, err_len, "scene_builtin: no scene given");
    if (approx_triangles < 1 || approx_triangles > SCENE_BUILTIN_MAX)
        return scene_fail(err, err_len, "builtin:%s: N must be from 1 to "
                          "%zu (got %zu)", name, SCENE_BUILTIN_MAX,
                          approx_triangles);
    if (strcmp(name, "sphere") == 0)
        rc = make_sphere(approx_triangles, &s, err, err_len);
    else if (strcmp(name, "terrain") == 0)
        rc = make_terrain(approx_triangles, &s, err, err_len);
    else if (strcmp(name, "city") == 0)
        rc = make_city(approx_triangles, &s, err, err_len);
    else
        return scene_fail(err, err_len, "builtin:%s: unknown built-in scene "
                          "(sphere, terrain or city)", name);
    if (rc != 0)
        return -1;
    *out = s;
    return 0;
}
