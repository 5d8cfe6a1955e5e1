/*
 * cli_trace.c - `atrbvh trace`: build, then measure ray throughput.
 *
 * Primary rays through the pixel centres from camera viewpoint 0; from each
 * primary hit, --spp ambient-occlusion rays (any hit, 0.1 x the scene
 * diagonal) and --spp diffuse rays (closest hit, 2 x the diagonal), both
 * cosine-distributed about the geometric normal turned towards the viewer.
 * Sample directions come from a hash of (pixel, sample), so the rays, and
 * the hit counts, do not depend on threads or timing.  Only the batch
 * calls are timed: ray generation is not what is being measured.
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

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
/* Secondary rays go to the library in batches of this many, so memory
 * stays bounded whatever --spp is. */
#define CHUNK ((size_t)1 << 20)
#define MAX_SIDE 16384ul
#define MAX_PIXELS ((size_t)1 << 25)
#define MAX_SPP 1024ul
#define SEED_AO 0x61u
#define SEED_DIFFUSE 0xd1u

typedef struct ray_stats {
    size_t count, hits;
    double ms;        /* wall time of the batch calls */
    double kernel_ms; /* OpenCL: the kernels' device time */
} ray_stats;

static uint64_t mix64(uint64_t x)
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

/* Two uniforms in [0, 1) for (seed, pixel, sample). */
static void hash2(uint64_t seed, uint64_t pixel, uint64_t sample, double *u1,
                  double *u2)
{
    uint64_t h = mix64(mix64(mix64(seed) ^ pixel) ^ sample);
    uint64_t g = mix64(h ^ 0x9e3779b97f4a7c15ull);
    *u1 = (double)(h >> 11) * (1.0 / 9007199254740992.0);
    *u2 = (double)(g >> 11) * (1.0 / 9007199254740992.0);
}

/* Where a secondary ray starts, and the frame around the normal. */
typedef struct surface {
    double p[3], n[3], t[3], b[3];
} surface;

static void make_surface(const scene *sc, const atrbvh_ray *ray,
                         const atrbvh_hit *hit, double eps_scale,
                         surface *s)
{
    const uint32_t *tri = sc->indices + (size_t)hit->primitive * 3;
    const float *v0 = sc->vertices + (size_t)tri[0] * 3;
    const float *v1 = sc->vertices + (size_t)tri[1] * 3;
    const float *v2 = sc->vertices + (size_t)tri[2] * 3;
    double e1[3], e2[3], n[3], len, big = 0.0, eps, sign;
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = (double)v1[k] - v0[k];
        e2[k] = (double)v2[k] - v0[k];
        s->p[k] = (double)ray->origin[k] + (double)hit->t * ray->dir[k];
        if (fabs(s->p[k]) > big)
            big = fabs(s->p[k]);
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0) || !isfinite(len)) {
        /* A zero-area triangle has no normal: go back the way we came. */
        double d = sqrt((double)ray->dir[0] * ray->dir[0] +
                        (double)ray->dir[1] * ray->dir[1] +
                        (double)ray->dir[2] * ray->dir[2]);
        for (k = 0; k < 3; k++)
            n[k] = -(double)ray->dir[k] / d;
    } else {
        sign = n[0] * ray->dir[0] + n[1] * ray->dir[1] + n[2] * ray->dir[2] >
                       0.0
                   ? -1.0
                   : 1.0;
        for (k = 0; k < 3; k++)
            n[k] *= sign / len;
    }
    /* Relative offset: a fraction of the scene, plus enough float ulps at
     * this position not to land back on the surface. */
    eps = eps_scale + big * 1e-6;
    for (k = 0; k < 3; k++) {
        s->n[k] = n[k];
        s->p[k] += n[k] * eps;
    }
    /* Duff et al. 2017, "Building an orthonormal basis, revisited". */
    {
        double sg = n[2] >= 0.0 ? 1.0 : -1.0;
        double a = -1.0 / (sg + n[2]);
        double bb = n[0] * n[1] * a;
        s->t[0] = 1.0 + sg * n[0] * n[0] * a;
        s->t[1] = sg * bb;
        s->t[2] = -sg * n[0];
        s->b[0] = bb;
        s->b[1] = sg + n[1] * n[1] * a;
        s->b[2] = -n[1];
    }
}

static void cosine_ray(const surface *s, double u1, double u2, float length,
                       atrbvh_ray *r)
{
    double rad = sqrt(u1), phi = 2.0 * PI * u2;
    double x = rad * cos(phi), y = rad * sin(phi), z = sqrt(1.0 - u1);
    int k;
    for (k = 0; k < 3; k++) {
        r->origin[k] = (float)s->p[k];
        r->dir[k] = (float)(x * s->t[k] + y * s->b[k] + z * s->n[k]);
    }
    r->tmin = 0.0f;
    r->tmax = length;
}

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
    double t0;
    size_t i;
    memset(&e, 0, sizeof e);
    t0 = cli_now_ms();
    if (tr->device) {
        double kms = 0.0;
        if (any_hit)
            st = atrbvh_occluded_batch_device(tr->b->device, tr->b->bvh,
                                              &tr->b->geometry, tr->rays, n,
                                              tr->occluded, &kms, &e);
        else
            st = atrbvh_intersect_batch_device(tr->b->device, tr->b->bvh,
                                               &tr->b->geometry, tr->rays, n,
                                               tr->hits, &kms, &e);
        rs->kernel_ms += kms;
    } else if (any_hit) {
        st = atrbvh_occluded_batch(tr->b->bvh, &tr->b->geometry, tr->rays, n,
                                   tr->occluded, tr->threads, &e);
    } else {
        st = atrbvh_intersect_batch(tr->b->bvh, &tr->b->geometry, tr->rays,
                                    n, tr->hits, tr->threads, &e);
    }
    rs->ms += cli_now_ms() - t0;
    if (st != ATRBVH_OK) {
        cli_error("tracing %s rays%s: %s", any_hit ? "occlusion" : "diffuse",
                  tr->device ? " on the OpenCL device" : "",
                  e.text[0] ? e.text : atrbvh_strerror(st));
        return -1;
    }
    rs->count += n;
    for (i = 0; i < n; i++)
        rs->hits += any_hit ? tr->occluded[i] != 0
                            : tr->hits[i].primitive != ATRBVH_NO_HIT;
    return 0;
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
    if (device) {
        fprintf(f, " %10.3f", rs->kernel_ms);
        text_rate(f, rs->count, rs->kernel_ms);
    }
    fputc('\n', f);
}

static void trace_help(FILE *f)
{
    fputs("Usage: atrbvh trace SCENE [OPTIONS]\n"
          "Build a BVH over SCENE, then trace primary rays from camera "
          "viewpoint 0,\n"
          "ambient-occlusion rays (any hit) and diffuse rays (closest hit) "
          "from\n"
          "the primary hits, and report rays per second for each kind.\n"
          "\n"
          "Trace options:\n"
          "  --width W            image width in pixels (default 512, at "
          "most 16384)\n"
          "  --height H           image height in pixels (default 384, at "
          "most 16384)\n"
          "  --spp N              occlusion and diffuse rays per primary hit "
          "(default 4,\n"
          "                       0 to 1024)\n"
          "\n",
          f);
    cli_build_options_help(f);
    fputs("  -h, --help           this help\n"
          "  --version            the version\n"
          "\n"
          "Exit status: 0 success, 1 bad input or failure, 2 usage error.\n",
          f);
}

static int trace(const cli_build_args *a, const cli_built *b,
                 unsigned width, unsigned height, unsigned spp)
{
    tracer tr;
    camera cam;
    float lo[3], hi[3];
    double diag = 0.0, eps_scale;
    size_t pixels = (size_t)width * height, i, n, p;
    unsigned s, x, y;
    ray_stats prim, ao, dif;
    surface *surf = NULL;
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
    camera_frame(lo, hi, 0, (float)width / (float)height, &cam);

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
            make_surface(&b->sc, &tr.rays[i], &tr.hits[i], eps_scale,
                         &surf[nsurf]);
            surf_pixel[nsurf++] = i;
        }
    }
    for (k = 0; k < 2; k++) {
        int any_hit = k == 0;
        uint64_t seed = any_hit ? SEED_AO : SEED_DIFFUSE;
        float length = (float)(any_hit ? 0.1 * diag : 2.0 * diag);
        ray_stats *rs = any_hit ? &ao : &dif;
        n = 0;
        for (p = 0; p < nsurf; p++) {
            for (s = 0; s < spp; s++) {
                double u1, u2;
                hash2(seed, surf_pixel[p], s, &u1, &u2);
                cosine_ray(&surf[p], u1, u2, length, &tr.rays[n++]);
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
        json_end_object(&w);
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
            printf("  %-9s %12s %12s %10s %10s %10s %10s\n", "rays", "count",
                   "hits", "ms", "Mrays/s", "kernel ms", "Mrays/s");
        } else {
            printf("  %-9s %12s %12s %10s %10s\n", "rays", "count", "hits",
                   "ms", "Mrays/s");
        }
        text_rays(stdout, "primary", &prim, tr.device);
        text_rays(stdout, "ao", &ao, tr.device);
        text_rays(stdout, "diffuse", &dif, tr.device);
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
    unsigned long width = 512, height = 384, spp = 4;
    int i = 1, rc, dashdash = 0;
    if ((rc = cli_help_or_version(argc, argv, trace_help)) >= 0)
        return rc;
    cli_build_args_init(&a);
    while (i < argc) {
        const char *arg = argv[i], *v;
        if (!dashdash && arg[0] == '-' && arg[1] != '\0') {
            int r;
            if (strcmp(arg, "--") == 0) {
                dashdash = 1;
                i++;
                continue;
            }
            if ((r = cli_option("trace", argc, argv, &i, "--width", &v)) !=
                0) {
                if (r < 0)
                    return CLI_USAGE;
                if (!cli_parse_ulong(v, MAX_SIDE, &width) || width == 0)
                    return cli_usage("trace", "--width: '%s' is not a whole "
                                     "number from 1 to %lu", v, MAX_SIDE);
                continue;
            }
            if ((r = cli_option("trace", argc, argv, &i, "--height", &v)) !=
                0) {
                if (r < 0)
                    return CLI_USAGE;
                if (!cli_parse_ulong(v, MAX_SIDE, &height) || height == 0)
                    return cli_usage("trace", "--height: '%s' is not a whole "
                                     "number from 1 to %lu", v, MAX_SIDE);
                continue;
            }
            if ((r = cli_option("trace", argc, argv, &i, "--spp", &v)) != 0) {
                if (r < 0)
                    return CLI_USAGE;
                if (!cli_parse_ulong(v, MAX_SPP, &spp))
                    return cli_usage("trace", "--spp: '%s' is not a whole "
                                     "number from 0 to %lu", v, MAX_SPP);
                continue;
            }
            r = cli_build_option("trace", argc, argv, &i, &a);
            if (r < 0)
                return CLI_USAGE;
            if (r == 0)
                return cli_usage("trace", "unknown option '%s'", arg);
            continue;
        }
        if (a.scene)
            return cli_usage("trace", "more than one SCENE ('%s', '%s')",
                             a.scene, arg);
        a.scene = arg;
        i++;
    }
    if (!a.scene)
        return cli_usage("trace", "no SCENE given");
    if ((size_t)width * height > MAX_PIXELS)
        return cli_usage("trace", "%lux%lu is more than %zu pixels", width,
                         height, MAX_PIXELS);
    rc = cli_load_and_build(&a, &b);
    if (rc == CLI_OK)
        rc = trace(&a, &b, (unsigned)width, (unsigned)height, (unsigned)spp);
    cli_built_free(&b);
    return rc;
}
