/*
 * cli_render.c - `atrbvh render`: a shaded picture of a scene through a
 * BVH, or a heat map of traversal steps per pixel, as PNG.
 *
 * The heat map counts the nodes whose box a primary ray is tested against
 * in a closest-hit traversal of the public node array (atrbvh_bvh_nodes):
 * front-to-back by the near child's entry distance, a leaf's triangles by
 * Moller-Trumbore.  The library's traverser has no counter (and the ABI is
 * not changed for one), so the tool walks the tree itself; its hits agree
 * with the library's up to ties.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"
#include "outfile.h"
#include "rays.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SIDE 16384u
#define MAX_PIXELS ((size_t)1 << 26)
#define STACK 256

static int box_hit(const atrbvh_node *n, const float o[3], const float inv[3],
                   float tmin, float tmax, float *tnear)
{
    int k;
    for (k = 0; k < 3; k++) {
        float t0 = (n->min[k] - o[k]) * inv[k];
        float t1 = (n->max[k] - o[k]) * inv[k];
        if (t0 > t1) {
            float t = t0;
            t0 = t1;
            t1 = t;
        }
        /* NaN (0 * inf) compares false and leaves the bound as it was */
        if (t0 > tmin)
            tmin = t0;
        if (t1 < tmax)
            tmax = t1;
    }
    *tnear = tmin;
    return tmin <= tmax;
}

static int tri_hit(const scene *sc, uint32_t prim, const atrbvh_ray *r,
                   float *t)
{
    const uint32_t *tri = sc->indices + (size_t)prim * 3;
    const float *a = sc->vertices + (size_t)tri[0] * 3;
    const float *b = sc->vertices + (size_t)tri[1] * 3;
    const float *c = sc->vertices + (size_t)tri[2] * 3;
    double e1[3], e2[3], p[3], q[3], s[3], det, inv, u, v, tt;
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = (double)b[k] - a[k];
        e2[k] = (double)c[k] - a[k];
        s[k] = (double)r->origin[k] - a[k];
    }
    p[0] = r->dir[1] * e2[2] - r->dir[2] * e2[1];
    p[1] = r->dir[2] * e2[0] - r->dir[0] * e2[2];
    p[2] = r->dir[0] * e2[1] - r->dir[1] * e2[0];
    det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (det == 0.0)
        return 0;
    inv = 1.0 / det;
    u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) * inv;
    if (u < 0.0 || u > 1.0)
        return 0;
    q[0] = s[1] * e1[2] - s[2] * e1[1];
    q[1] = s[2] * e1[0] - s[0] * e1[2];
    q[2] = s[0] * e1[1] - s[1] * e1[0];
    v = (r->dir[0] * q[0] + r->dir[1] * q[1] + r->dir[2] * q[2]) * inv;
    if (v < 0.0 || u + v > 1.0)
        return 0;
    tt = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) * inv;
    if (!(tt >= r->tmin && tt <= *t)) /* [tmin, tmax], as the library */
        return 0;
    *t = (float)tt;
    return 1;
}

/* Closest hit; returns the nodes visited, *prim the hit (or NO_HIT). */
static unsigned count_trace(const atrbvh_node *nodes, const uint32_t *ids,
                            const scene *sc, const atrbvh_ray *r,
                            uint32_t *prim, float *t_hit)
{
    uint32_t stack[STACK];
    int sp = 0, k;
    unsigned steps = 0;
    float inv[3], t = r->tmax, tn;
    uint32_t cur = 0;
    *prim = ATRBVH_NO_HIT;
    for (k = 0; k < 3; k++)
        inv[k] = 1.0f / r->dir[k];
    steps++;
    if (!box_hit(&nodes[0], r->origin, inv, r->tmin, t, &tn))
        return steps;
    for (;;) {
        const atrbvh_node *n = &nodes[cur];
        if (n->count) {
            uint32_t j;
            for (j = 0; j < n->count; j++)
                if (tri_hit(sc, ids[n->index + j], r, &t))
                    *prim = ids[n->index + j];
        } else {
            uint32_t l = cur + 1, rr = n->index;
            float tl, tr;
            int hl, hr;
            steps += 2;
            hl = box_hit(&nodes[l], r->origin, inv, r->tmin, t, &tl);
            hr = box_hit(&nodes[rr], r->origin, inv, r->tmin, t, &tr);
            if (hl && hr) {
                uint32_t near = tl <= tr ? l : rr, far = tl <= tr ? rr : l;
                if (sp < STACK)
                    stack[sp++] = far;
                cur = near;
                continue;
            }
            if (hl || hr) {
                cur = hl ? l : rr;
                continue;
            }
        }
        /* pop, skipping nodes now beyond the closest hit */
        for (;;) {
            if (sp == 0) {
                *t_hit = t;
                return steps;
            }
            cur = stack[--sp];
            if (box_hit(&nodes[cur], r->origin, inv, r->tmin, t, &tn))
                break;
        }
    }
}

/* black - purple - red - orange - yellow - white */
static void heat_color(double x, unsigned char *c)
{
    static const double stops[6][3] = {{0, 0, 0},      {0.35, 0.05, 0.55},
                                       {0.85, 0.1, 0.2}, {1, 0.5, 0},
                                       {1, 0.9, 0.1},   {1, 1, 1}};
    double f;
    int i, k;
    if (!(x > 0.0))
        x = 0.0;
    if (x > 1.0)
        x = 1.0;
    f = x * 5.0;
    i = (int)f;
    if (i > 4)
        i = 4;
    f -= i;
    for (k = 0; k < 3; k++)
        c[k] = (unsigned char)(255.0 * (stops[i][k] * (1 - f) +
                                        stops[i + 1][k] * f) + 0.5);
}

static int cmp_unsigned(const void *a, const void *b)
{
    unsigned x = *(const unsigned *)a, y = *(const unsigned *)b;
    return x < y ? -1 : x > y;
}

#define RENDER_OPTS 7

typedef struct render_args {
    unsigned width, height, view, heat_top;
    int heatmap;
    const char *output;
} render_args;

static void render_opts(render_args *r, cli_opt *table)
{
    const cli_opt opts[] = {
        {.name = "--output", .alias = "-o", .kind = CLI_OPT_STRING,
         .arg = "FILE", .dest = &r->output,
         .help = "the PNG to write (required)"},
        {.name = "--heatmap", .kind = CLI_OPT_FLAG, .dest = &r->heatmap,
         .flag_value = 1, .help = "traversal steps per pixel instead of "
                                  "shading"},
        {.name = "--width", .kind = CLI_OPT_UINT, .arg = "W", .min = 1,
         .max = MAX_SIDE, .dest = &r->width,
         .help = "image width (default 640, at most 16384)"},
        {.name = "--height", .kind = CLI_OPT_UINT, .arg = "H", .min = 1,
         .max = MAX_SIDE, .dest = &r->height,
         .help = "image height (default 480, at most 16384)"},
        {.name = "--viewpoint", .kind = CLI_OPT_UINT, .arg = "V", .min = 0,
         .max = 1000000, .dest = &r->view,
         .help = "camera viewpoint (default 0; see CAMERAS in atrbvh(1))"},
        {.name = "--heat-top", .kind = CLI_OPT_UINT, .arg = "N", .min = 1,
         .max = 1000000, .dest = &r->heat_top,
         .help = "the heat map's white: N nodes (default: the 99th\n"
                 "percentile), to compare trees on one scale"},
        {.name = NULL}};
    CLI_OPTS_COPY(table, opts, RENDER_OPTS);
}
/* -o names the picture here, and there is no JSON output. */
#define RENDER_BUILD_OPTS (CLI_BUILD_CORE | CLI_BUILD_BACKEND | CLI_BUILD_DEVICE)

static void render_help(FILE *f)
{
    render_args r;
    cli_opt table[RENDER_OPTS];
    render_opts(&r, table);
    cli_build_help(f,
                   "Usage: atrbvh render SCENE --output FILE.png [OPTIONS]\n"
                   "Build a BVH over SCENE and write a picture of it from a "
                   "camera\n"
                   "viewpoint: shaded (the default), or with --heatmap the "
                   "number of\n"
                   "BVH nodes each primary ray visits (black few, white "
                   "many; the\n"
                   "scale's top is the 99th percentile, printed).\n",
                   "Render", table, RENDER_BUILD_OPTS,
                   "0 success, 1 bad input or failure, 2 usage error");
}

int cli_render(int argc, char **argv)
{
    cli_build_args a;
    cli_built b;
    render_args ra;
    cli_opt table[RENDER_OPTS];
    unsigned width, height, view, heat_top;
    int heatmap, rc;
    const char *output;
    if ((rc = cli_help_or_version(argc, argv, render_help)) >= 0)
        return rc;
    memset(&ra, 0, sizeof ra);
    ra.width = 640;
    ra.height = 480;
    render_opts(&ra, table);
    cli_build_args_init(&a);
    if (cli_build_parse("render", argc, argv, table, RENDER_BUILD_OPTS, &a) !=
        0)
        return CLI_USAGE;
    width = ra.width;
    height = ra.height;
    view = ra.view;
    heat_top = ra.heat_top;
    heatmap = ra.heatmap;
    output = ra.output;
    if (!output)
        return cli_usage("render", "no --output FILE.png given");
    if ((size_t)width * height > MAX_PIXELS)
        return cli_usage("render", "%ux%u is more than %zu pixels", width,
                         height, MAX_PIXELS);
    if (!cli_png_available()) {
        cli_error("render: this atrbvh was built without libpng (configure "
                  "found none), so it cannot write PNG");
        return CLI_FAIL;
    }
    /* before the build: an unwritable PNG or one naming the scene */
    if (cli_out_usable(output, a.scene) != 0)
        return CLI_FAIL;
    rc = cli_load_and_build(&a, &b);
    if (rc == CLI_OK) {
        size_t pixels = (size_t)width * height, p;
        unsigned char *rgb = malloc(pixels * 3);
        unsigned *steps = malloc(pixels * sizeof *steps);
        unsigned *sorted = malloc(pixels * sizeof *sorted);
        const atrbvh_node *nodes;
        const uint32_t *ids;
        size_t nn, ni;
        camera cam;
        float lo[3], hi[3];
        double light[3], ll, sum = 0.0;
        unsigned top, maxs = 0;
        long y;
        int k;
        if (!rgb || !steps || !sorted) {
            cli_error("out of memory for a %ux%u picture", width, height);
            rc = CLI_FAIL;
            goto out;
        }
        nodes = atrbvh_bvh_nodes(b.bvh, &nn);
        ids = atrbvh_bvh_primitive_indices(b.bvh, &ni);
        scene_bounds(&b.sc, lo, hi);
        camera_frame(lo, hi, (unsigned)view, (float)width / (float)height,
                     &cam);
        /* a light over the viewer's left shoulder */
        {
            double ul = 0.0, rl = 0.0;
            for (k = 0; k < 3; k++) {
                ul += (double)cam.up[k] * cam.up[k];
                rl += (double)cam.right[k] * cam.right[k];
            }
            ul = ul > 0.0 ? sqrt(ul) : 1.0;
            rl = rl > 0.0 ? sqrt(rl) : 1.0;
            for (k = 0; k < 3; k++)
                light[k] = -cam.forward[k] + 0.6 * cam.up[k] / ul -
                           0.4 * cam.right[k] / rl;
        }
        ll = sqrt(light[0] * light[0] + light[1] * light[1] +
                  light[2] * light[2]);
        for (k = 0; k < 3; k++)
            light[k] /= ll;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 4)
#endif
        for (y = 0; y < (long)height; y++) {
            unsigned x;
            for (x = 0; x < width; x++) {
                atrbvh_ray r;
                uint32_t prim;
                float t = 0.0f;
                size_t q = (size_t)y * width + x;
                camera_ray(&cam, (unsigned)width, (unsigned)height, x,
                           (unsigned)y, 0.5f, 0.5f, &r);
                steps[q] = count_trace(nodes, ids, &b.sc, &r, &prim, &t);
                if (!heatmap) {
                    unsigned char *c = rgb + 3 * q;
                    if (prim == ATRBVH_NO_HIT) {
                        double g = 0.25 + 0.2 * (double)y / (double)height;
                        c[0] = c[1] = (unsigned char)(255 * g);
                        c[2] = (unsigned char)(255 * (g + 0.08));
                    } else {
                        double n[3], d, amb = 0.18;
                        rays_normal(&b.sc, prim, r.dir, n);
                        d = n[0] * light[0] + n[1] * light[1] +
                            n[2] * light[2];
                        if (d < 0.0)
                            d = 0.0;
                        d = amb + (1.0 - amb) * d;
                        c[0] = (unsigned char)(255 * d * 0.92);
                        c[1] = (unsigned char)(255 * d * 0.86);
                        c[2] = (unsigned char)(255 * d * 0.74);
                    }
                }
            }
        }
        memcpy(sorted, steps, pixels * sizeof *sorted);
        qsort(sorted, pixels, sizeof *sorted, cmp_unsigned);
        top = sorted[(size_t)((double)(pixels - 1) * 0.99)];
        if (top == 0)
            top = 1;
        {
            unsigned pct = top;
            if (heat_top)
                top = (unsigned)heat_top;
        for (p = 0; p < pixels; p++) {
            sum += steps[p];
            if (steps[p] > maxs)
                maxs = steps[p];
            if (heatmap)
                heat_color((double)steps[p] / top, rgb + 3 * p);
        }
            top = pct;
        }
        if (cli_png_write(output, (unsigned)width, (unsigned)height, rgb) !=
            0) {
            rc = CLI_FAIL;
        } else {
            printf("%s: %ux%u %s, SAH %.6g, nodes visited per pixel: mean "
                   "%.1f, 99th percentile %u, max %u\n",
                   output, width, height, heatmap ? "heat map" : "shaded",
                   b.stats.sah, sum / (double)pixels, top, maxs);
        }
    out:
        free(rgb);
        free(steps);
        free(sorted);
    }
    cli_built_free(&b);
    return rc;
}
