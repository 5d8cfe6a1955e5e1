/*
 * cli_trace.c - `atrbvh trace`: build, then measure ray throughput.
 *
 * Primary rays through the pixel centres from camera viewpoint 0; from each
 * primary hit, --spp ambient-occlusion rays (any hit, 0.1 x the scene
 * diagonal) and --spp diffuse rays (closest hit, 2 x the diagonal), both
 * cosine-distributed about the geometric normal turned towards the viewer.
 * Sample directions come from a hash of (pixel, sample) (rng.h), so the
 * rays, and the hit counts, do not depend on threads or timing; the rays
 * are those of rays.h (bench's, viewpoint 0).  Only the batch
 * calls are timed: ray generation is not what is being measured.  The
 * batches are the counting ones (atrbvh_*_batch_stats), so each kind also
 * reports its exact cost: node boxes and primitives tested per ray.
 *
 * --backend opencl traces on the device too (atrbvh_intersect_batch_device,
 * atrbvh_occluded_batch_device: the same results, bit for bit): the rate
 * is then also reported from the kernels' profiling events ("kernel"),
 * beside the wall time of the calls (which includes the device setup and
 * the transfers of each call).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"
#include "rays.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Secondary rays go to the library in batches of this many, so memory
 * stays bounded whatever --spp is. */
#define CHUNK ((size_t)1 << 20)
#define MAX_SIDE 16384u
#define MAX_PIXELS ((size_t)1 << 25)
#define MAX_SPP 1024u

typedef struct ray_stats {
    size_t count, hits;
    double ms;        /* wall time of the batch calls */
    double kernel_ms; /* OpenCL: the kernels' device time */
    uint64_t box_tests, prim_tests; /* exact, from atrbvh_trace_stats */
} ray_stats;

typedef struct tracer {
    const cli_built *b;
    int threads;
    int device;              /* trace with the OpenCL kernels */
    atrbvh_ray *rays;
    atrbvh_hit *hits;
    uint8_t *occluded;
} tracer;

static int run_batch(tracer *tr, size_t n, int any_hit, ray_stats *rs)
{
    atrbvh_error e;
    atrbvh_status st;
    atrbvh_trace_stats ts;
    atrbvh_device *dev = tr->device ? tr->b->device : NULL;
    int threads = tr->device ? 0 : tr->threads;
    double t0;
    size_t i;
    memset(&e, 0, sizeof e);
    atrbvh_trace_stats_init(&ts);
    t0 = cli_now_ms();
    /* The counting calls: the same results as the plain batches, and the
     * counts cost two additions per test (the rates stay comparable). */
    if (any_hit)
        st = atrbvh_occluded_batch_stats(dev, tr->b->bvh, &tr->b->geometry,
                                         tr->rays, n, tr->occluded, threads,
                                         &ts, &e);
    else
        st = atrbvh_intersect_batch_stats(dev, tr->b->bvh, &tr->b->geometry,
                                          tr->rays, n, tr->hits, threads, &ts,
                                          &e);
    rs->ms += cli_now_ms() - t0;
    if (st != ATRBVH_OK) {
        cli_error("tracing %s rays%s: %s", any_hit ? "occlusion" : "diffuse",
                  tr->device ? " on the OpenCL device" : "",
                  e.text[0] ? e.text : atrbvh_strerror(st));
        return -1;
    }
    rs->kernel_ms += ts.kernel_ms;
    rs->box_tests += ts.box_tests;
    rs->prim_tests += ts.prim_tests;
    rs->count += n;
    for (i = 0; i < n; i++)
        rs->hits += any_hit ? tr->occluded[i] != 0
                            : tr->hits[i].primitive != ATRBVH_NO_HIT;
    return 0;
}

static double per_ray(uint64_t tests, size_t count)
{
    return count > 0 ? (double)tests / (double)count : NAN;
}

static double mrays(size_t count, double ms)
{
    return ms > 0.0 ? (double)count / (ms * 1e3) : NAN;
}

static void json_rays(json_writer *w, const char *key, const ray_stats *rs,
                      int device)
{
    json_key(w, key);
    json_begin_object(w);
    json_kv_uint(w, "count", rs->count);
    json_kv_uint(w, "hits", rs->hits);
    json_kv_double(w, "ms", rs->ms);
    json_kv_double(w, "mrays", mrays(rs->count, rs->ms));
    json_kv_uint(w, "box_tests", rs->box_tests);
    json_kv_uint(w, "tri_tests", rs->prim_tests);
    json_kv_double(w, "box_tests_per_ray", per_ray(rs->box_tests, rs->count));
    json_kv_double(w, "tri_tests_per_ray", per_ray(rs->prim_tests, rs->count));
    if (device) {
        json_kv_double(w, "kernel_ms", rs->kernel_ms);
        json_kv_double(w, "kernel_mrays", mrays(rs->count, rs->kernel_ms));
    }
    json_end_object(w);
}

static void text_rate(FILE *f, size_t count, double ms)
{
    if (ms > 0.0)
        fprintf(f, " %10.3f", mrays(count, ms));
    else
        fprintf(f, " %10s", "n/a");
}

static void text_rays(FILE *f, const char *name, const ray_stats *rs,
                      int device)
{
    fprintf(f, "  %-9s %12zu %12zu %10.3f", name, rs->count, rs->hits,
            rs->ms);
    text_rate(f, rs->count, rs->ms);
    fprintf(f, " %8.2f %8.2f", per_ray(rs->box_tests, rs->count),
            per_ray(rs->prim_tests, rs->count));
    if (device) {
        fprintf(f, " %10.3f", rs->kernel_ms);
        text_rate(f, rs->count, rs->kernel_ms);
    }
    fputc('\n', f);
}

#define TRACE_OPTS (4 + RAYS_CAMERA_OPTS)

typedef struct trace_args {
    unsigned width, height, spp;
    camera_view view;
} trace_args;

static void trace_opts(trace_args *t, cli_opt *table)
{
    const cli_opt opts[] = {
        {.name = "--width", .kind = CLI_OPT_UINT, .arg = "W", .min = 1,
         .max = MAX_SIDE, .dest = &t->width,
         .help = "image width in pixels (default 512, at most 16384)"},
        {.name = "--height", .kind = CLI_OPT_UINT, .arg = "H", .min = 1,
         .max = MAX_SIDE, .dest = &t->height,
         .help = "image height in pixels (default 384, at most 16384)"},
        {.name = "--spp", .kind = CLI_OPT_UINT, .arg = "N", .min = 0,
         .max = MAX_SPP, .dest = &t->spp,
         .help = "occlusion and diffuse rays per primary hit (default 4,\n"
                 "0 to 1024)"},
        {.name = NULL}};
    CLI_OPTS_COPY(table, opts, TRACE_OPTS - RAYS_CAMERA_OPTS);
    /* the camera options before the terminator */
    rays_camera_opts(&t->view, table + 3);
    table[TRACE_OPTS - 1] = opts[3];
}

static void trace_help(FILE *f)
{
    trace_args t;
    cli_opt table[TRACE_OPTS];
    trace_opts(&t, table);
    cli_build_help(f,
                   "Usage: atrbvh trace SCENE [OPTIONS]\n"
                   "Build a BVH over SCENE, then trace primary rays from "
                   "camera viewpoint 0\n"
                   "(inside the scene for rooms; see CAMERAS in atrbvh(1)) "
                   "or --eye,\n"
                   "ambient-occlusion rays (any hit) and diffuse rays "
                   "(closest hit) from\n"
                   "the primary hits, and report rays per second for each "
                   "kind and the\n"
                   "exact ray cost (boxes and triangles tested per ray).\n",
                   "Trace", table, CLI_BUILD_ALL,
                   "0 success, 1 bad input or failure, 2 usage error");
}

static int trace(const cli_build_args *a, const cli_built *b,
                 unsigned width, unsigned height, unsigned spp,
                 const camera_view *view)
{
    tracer tr;
    camera cam;
    float lo[3], hi[3];
    double diag = 0.0, eps_scale;
    size_t pixels = (size_t)width * height, i, n, p;
    unsigned s, x, y;
    ray_stats prim, ao, dif, all;
    ray_surface *surf = NULL;
    size_t *surf_pixel = NULL, nsurf = 0;
    int rc = CLI_FAIL, k;
    memset(&prim, 0, sizeof prim);
    memset(&ao, 0, sizeof ao);
    memset(&dif, 0, sizeof dif);
    memset(&tr, 0, sizeof tr);
    tr.b = b;
    tr.threads = a->options.threads;
    tr.device = a->options.backend == ATRBVH_BACKEND_OPENCL;
    n = pixels > CHUNK ? pixels : CHUNK;
    tr.rays = malloc(n * sizeof *tr.rays);
    tr.hits = malloc(n * sizeof *tr.hits);
    tr.occluded = malloc(n);
    if (!tr.rays || !tr.hits || !tr.occluded) {
        cli_error("out of memory for %zu rays", n);
        goto done;
    }

    scene_bounds(&b->sc, lo, hi);
    for (k = 0; k < 3; k++)
        diag += ((double)hi[k] - lo[k]) * ((double)hi[k] - lo[k]);
    diag = sqrt(diag);
    eps_scale = diag * 1e-5;
    if (rays_camera(&b->sc, 0, view, (float)width / (float)height,
                    &cam) != 0) {
        cli_error("the camera's eye is its look-at point");
        goto done;
    }

    for (y = 0, i = 0; y < height; y++)
        for (x = 0; x < width; x++, i++)
            camera_ray(&cam, width, height, x, y, 0.5f, 0.5f, &tr.rays[i]);
    if (run_batch(&tr, pixels, 0, &prim) != 0)
        goto done;

    /* The primary results are overwritten by the secondary batches, so
     * keep each hit's surface first. */
    if (spp > 0 && prim.hits > 0) {
        surf = malloc(prim.hits * sizeof *surf);
        surf_pixel = malloc(prim.hits * sizeof *surf_pixel);
        if (!surf || !surf_pixel) {
            cli_error("out of memory for %zu hit points", prim.hits);
            goto done;
        }
        for (i = 0; i < pixels; i++) {
            if (tr.hits[i].primitive == ATRBVH_NO_HIT)
                continue;
            if (tr.hits[i].primitive >= b->sc.triangle_count) {
                cli_error("tracing primary rays: ray %zu hit primitive %lu, "
                          "out of range", i,
                          (unsigned long)tr.hits[i].primitive);
                goto done;
            }
            rays_surface(&b->sc, &tr.rays[i], &tr.hits[i], eps_scale,
                         &surf[nsurf]);
            surf_pixel[nsurf++] = i;
        }
    }
    for (k = 0; k < 2; k++) {
        int any_hit = k == 0;
        uint64_t seed = any_hit ? RAYS_SEED_AO : RAYS_SEED_DIFFUSE;
        float length = (float)(any_hit ? 0.1 * diag : 2.0 * diag);
        ray_stats *rs = any_hit ? &ao : &dif;
        n = 0;
        for (p = 0; p < nsurf; p++) {
            for (s = 0; s < spp; s++) {
                rays_cosine(&surf[p], seed, surf_pixel[p], s, length,
                            &tr.rays[n++]);
                if (n == CHUNK) {
                    if (run_batch(&tr, n, any_hit, rs) != 0)
                        goto done;
                    n = 0;
                }
            }
        }
        if (n > 0 && run_batch(&tr, n, any_hit, rs) != 0)
            goto done;
    }

    all = prim;
    all.count += ao.count + dif.count;
    all.hits += ao.hits + dif.hits;
    all.ms += ao.ms + dif.ms;
    all.kernel_ms += ao.kernel_ms + dif.kernel_ms;
    all.box_tests += ao.box_tests + dif.box_tests;
    all.prim_tests += ao.prim_tests + dif.prim_tests;
    if (a->json) {
        json_writer w;
        json_init(&w, stdout);
        json_begin_object(&w);
        cli_build_json(&w, a, b);
        json_kv_uint(&w, "width", width);
        json_kv_uint(&w, "height", height);
        json_kv_uint(&w, "spp", spp);
        json_kv_string(&w, "trace_device",
                       tr.device ? atrbvh_bvh_device(b->bvh) : "cpu");
        json_key(&w, "rays");
        json_begin_object(&w);
        json_rays(&w, "primary", &prim, tr.device);
        json_rays(&w, "ao", &ao, tr.device);
        json_rays(&w, "diffuse", &dif, tr.device);
        json_rays(&w, "all", &all, tr.device);
        json_end_object(&w);
        /* ci x boxes + ct x primitives per ray, over every ray */
        json_kv_double(&w, "ray_cost",
                       a->options.ci * per_ray(all.box_tests, all.count) +
                           a->options.ct * per_ray(all.prim_tests, all.count));
        json_end_object(&w);
    } else {
        cli_build_text(stdout, a, b);
        printf("image            %ux%u, %u sample%s per hit\n", width, height,
               spp, spp == 1 ? "" : "s");
        if (tr.device) {
            printf("traced on        OpenCL (kernel: device time from "
                   "profiling events; ms:\n"
                   "                 wall, with device setup and "
                   "transfers)\n");
            printf("  %-9s %12s %12s %10s %10s %8s %8s %10s %10s\n", "rays",
                   "count", "hits", "ms", "Mrays/s", "box/ray", "tri/ray",
                   "kernel ms", "Mrays/s");
        } else {
            printf("  %-9s %12s %12s %10s %10s %8s %8s\n", "rays", "count",
                   "hits", "ms", "Mrays/s", "box/ray", "tri/ray");
        }
        text_rays(stdout, "primary", &prim, tr.device);
        text_rays(stdout, "ao", &ao, tr.device);
        text_rays(stdout, "diffuse", &dif, tr.device);
        text_rays(stdout, "all", &all, tr.device);
        printf("ray cost         %.3f per ray (ci x boxes + ct x triangles "
               "tested: exact,\n"
               "                 the same on every run and backend)\n",
               a->options.ci * per_ray(all.box_tests, all.count) +
                   a->options.ct * per_ray(all.prim_tests, all.count));
    }
    rc = CLI_OK;
done:
    free(surf);
    free(surf_pixel);
    free(tr.rays);
    free(tr.hits);
    free(tr.occluded);
    return rc;
}

int cli_trace(int argc, char **argv)
{
    cli_build_args a;
    cli_built b;
    trace_args t;
    cli_opt table[TRACE_OPTS];
    int rc;
    if ((rc = cli_help_or_version(argc, argv, trace_help)) >= 0)
        return rc;
    t.width = 512;
    t.height = 384;
    t.spp = 4;
    memset(&t.view, 0, sizeof t.view);
    trace_opts(&t, table);
    cli_build_args_init(&a);
    if (cli_build_parse("trace", argc, argv, table, CLI_BUILD_ALL, &a) != 0)
        return CLI_USAGE;
    if (rays_camera_check("trace", &t.view) != 0)
        return CLI_USAGE;
    if ((size_t)t.width * t.height > MAX_PIXELS)
        return cli_usage("trace", "%ux%u is more than %zu pixels", t.width,
                         t.height, MAX_PIXELS);
    rc = cli_load_and_build(&a, &b);
    if (rc == CLI_OK)
        rc = trace(&a, &b, t.width, t.height, t.spp, &t.view);
    cli_built_free(&b);
    return rc;
}
