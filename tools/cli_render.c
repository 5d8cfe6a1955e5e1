/*
 * cli_render.c - `atrbvh render`: a shaded picture of a scene through a
 * BVH, or a heat map of traversal work per pixel, as PNG.
 *
 * The primary rays go through the library's closest-hit batch
 * (atrbvh_intersect_batch_stats): the shading uses its hits, and the heat
 * map its exact per-ray count of the node boxes the traversal tested (the
 * same count bench and trace report, on every backend).  The heat map
 * carries its colour scale, with numbers, along its bottom edge when the
 * picture is large enough (at least 96 x 64).
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
#define RAY_CHUNK ((size_t)1 << 20)

static void heat_color(double x, unsigned char *c);

/* Digits 0-9 in 3 x 5 pixels, one row per 3 bits (top row first). */
static const unsigned char digit_rows[10][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7},
    {5, 5, 7, 1, 1}, {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1},
    {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};

static void put_px(unsigned char *rgb, unsigned w, unsigned h, long x, long y,
                   const unsigned char c[3])
{
    if (x < 0 || y < 0 || (unsigned long)x >= w || (unsigned long)y >= h)
        return;
    memcpy(rgb + 3 * ((size_t)y * w + (size_t)x), c, 3);
}

/* The decimal text of v at (x, y) (top left), pixels s x s; its width. */
static long draw_number(unsigned char *rgb, unsigned w, unsigned h, long x,
                        long y, unsigned v, int s, int draw)
{
    static const unsigned char white[3] = {255, 255, 255};
    char text[16];
    int i, n = snprintf(text, sizeof text, "%u", v), r, c, dy, dx;
    long x0 = x;
    for (i = 0; i < n; i++) {
        const unsigned char *g = digit_rows[text[i] - '0'];
        for (r = 0; r < 5 && draw; r++)
            for (c = 0; c < 3; c++)
                if (g[r] & (4 >> c))
                    for (dy = 0; dy < s; dy++)
                        for (dx = 0; dx < s; dx++)
                            put_px(rgb, w, h, x + c * s + dx,
                                   y + r * s + dy, white);
        x += 4 * s;
    }
    return x - x0 - s;
}

/* The heat map's scale: a bar from 0 to `top` along the bottom edge, with
 * 0, top/4, top/2, 3top/4 and top written above it, on a darkened band. */
static void draw_scale(unsigned char *rgb, unsigned w, unsigned h,
                       unsigned top)
{
    int s = w >= 400 && h >= 200 ? 2 : 1, k;
    long bar_h = 4 * s, x0 = 4 * s, x1 = (long)w - 4 * s - 1,
         bar_y = (long)h - 3 * s - bar_h, text_y = bar_y - 7 * s,
         band_y = text_y - 2 * s, x, y;
    if (w < 96 || h < 64)
        return;
    for (y = band_y; y < (long)h; y++)
        for (x = 0; x < (long)w; x++) {
            unsigned char *p = rgb + 3 * ((size_t)y * w + (size_t)x);
            p[0] = (unsigned char)(p[0] / 4);
            p[1] = (unsigned char)(p[1] / 4);
            p[2] = (unsigned char)(p[2] / 4);
        }
    for (x = x0; x <= x1; x++) {
        unsigned char c[3];
        heat_color((double)(x - x0) / (double)(x1 - x0), c);
        for (y = bar_y; y < bar_y + bar_h; y++)
            put_px(rgb, w, h, x, y, c);
    }
    for (k = 0; k <= 4; k++) {
        unsigned v = (unsigned)(((unsigned long long)top * (unsigned)k) / 4u);
        long tx = x0 + (x1 - x0) * k / 4, tw = draw_number(rgb, w, h, 0, 0,
                                                           v, s, 0);
        tx -= k == 0 ? 0 : (k == 4 ? tw : tw / 2);
        draw_number(rgb, w, h, tx, text_y, v, s, 1);
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

#define RENDER_OPTS (7 + RAYS_CAMERA_OPTS)

typedef struct render_args {
    unsigned width, height, view, heat_top;
    int heatmap;
    const char *output;
    camera_view cam;
} render_args;

static void render_opts(render_args *r, cli_opt *table)
{
    const cli_opt opts[] = {
        {.name = "--output", .alias = "-o", .kind = CLI_OPT_STRING,
         .arg = "FILE", .dest = &r->output,
         .help = "the PNG to write (required)"},
        {.name = "--heatmap", .kind = CLI_OPT_FLAG, .dest = &r->heatmap,
         .flag_value = 1, .help = "node boxes tested per pixel instead of "
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
         .help = "the heat map's white: N node boxes (default: the\n"
                 "99th percentile), to compare trees on one scale"},
        {.name = NULL}};
    size_t n = sizeof opts / sizeof opts[0];
    CLI_OPTS_COPY(table, opts, RENDER_OPTS - RAYS_CAMERA_OPTS);
    rays_camera_opts(&r->cam, table + n - 1);
    table[n - 1 + RAYS_CAMERA_OPTS] = opts[n - 1];
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
                   "viewpoint (inside the scene for rooms: see CAMERAS in "
                   "atrbvh(1)) or\n"
                   "from --eye: shaded (the default), or with --heatmap the "
                   "number of\n"
                   "node boxes the traversal tests for each primary ray "
                   "(black few,\n"
                   "white many; the scale along the bottom, its top the "
                   "99th\n"
                   "percentile, printed).\n",
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
    if (rays_camera_check("render", &ra.cam) != 0)
        return CLI_USAGE;
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
        /* the rays go to the library in chunks of rows */
        size_t rows = RAY_CHUNK / width ? RAY_CHUNK / width : 1,
               chunk = rows * width, row0;
        atrbvh_ray *rays = malloc(chunk * sizeof *rays);
        atrbvh_hit *hits = malloc(chunk * sizeof *hits);
        atrbvh_ray_cost *cost = malloc(chunk * sizeof *cost);
        uint64_t prim_tests = 0;
        atrbvh_trace_stats ts;
        atrbvh_error e;
        atrbvh_status st;
        int on_device = a.options.backend == ATRBVH_BACKEND_OPENCL;
        camera cam;
        double light[3], ll, sum = 0.0;
        unsigned top, maxs = 0;
        int k;
        if (!rgb || !steps || !sorted || !rays || !hits || !cost) {
            cli_error("out of memory for a %ux%u picture", width, height);
            rc = CLI_FAIL;
            goto out;
        }
        if (rays_camera(&b.sc, view, &ra.cam, (float)width / (float)height,
                        &cam) != 0) {
            cli_error("the camera's eye is its look-at point");
            rc = CLI_FAIL;
            goto out;
        }
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
        for (row0 = 0; row0 < height; row0 += rows) {
            size_t nrow = height - row0 < rows ? height - row0 : rows,
                   n = nrow * width, i;
            for (i = 0; i < n; i++)
                camera_ray(&cam, (unsigned)width, (unsigned)height,
                           (unsigned)(i % width),
                           (unsigned)(row0 + i / width), 0.5f, 0.5f,
                           &rays[i]);
            atrbvh_trace_stats_init(&ts);
            ts.per_ray = cost;
            memset(&e, 0, sizeof e);
            st = atrbvh_intersect_batch_stats(
                on_device ? b.device : NULL, b.bvh, &b.geometry, rays, n,
                hits, on_device ? 0 : a.options.threads, &ts, &e);
            if (st != ATRBVH_OK) {
                cli_error("tracing primary rays: %s",
                          e.text[0] ? e.text : atrbvh_strerror(st));
                rc = CLI_FAIL;
                goto out;
            }
            prim_tests += ts.prim_tests;
            for (i = 0; i < n; i++) {
                size_t q = row0 * width + i;
                unsigned char *c = rgb + 3 * q;
                steps[q] = cost[i].box_tests;
                if (heatmap)
                    continue;
                if (hits[i].primitive == ATRBVH_NO_HIT ||
                    hits[i].primitive >= b.sc.triangle_count) {
                    double g =
                        0.25 + 0.2 * (double)(q / width) / (double)height;
                    c[0] = c[1] = (unsigned char)(255 * g);
                    c[2] = (unsigned char)(255 * (g + 0.08));
                } else {
                    double nm[3], d, amb = 0.18;
                    rays_normal(&b.sc, hits[i].primitive, rays[i].dir, nm);
                    d = nm[0] * light[0] + nm[1] * light[1] +
                        nm[2] * light[2];
                    if (d < 0.0)
                        d = 0.0;
                    d = amb + (1.0 - amb) * d;
                    c[0] = (unsigned char)(255 * d * 0.92);
                    c[1] = (unsigned char)(255 * d * 0.86);
                    c[2] = (unsigned char)(255 * d * 0.74);
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
            if (heatmap)
                draw_scale(rgb, width, height, top);
            top = pct;
        }
        if (cli_png_write(output, (unsigned)width, (unsigned)height, rgb) !=
            0) {
            rc = CLI_FAIL;
        } else {
            printf("%s: %ux%u %s, SAH %.6g, node boxes tested per pixel: "
                   "mean %.1f, 99th percentile %u, max %u; triangles "
                   "tested per pixel: mean %.2f\n",
                   output, width, height, heatmap ? "heat map" : "shaded",
                   b.stats.sah, sum / (double)pixels, top, maxs,
                   (double)prim_tests / (double)pixels);
        }
    out:
        free(rgb);
        free(steps);
        free(sorted);
        free(rays);
        free(hits);
        free(cost);
    }
    cli_built_free(&b);
    return rc;
}
