/*
 * inplace.c - OpenCL builds (or ray batches) in place against copying, in
 * one process: the program behind "The caller's memory in place" in
 * docs/opencl.md and the 5 December section of docs/bench/log.md.  It
 * opens a CPU handle, an OpenCL handle and a second OpenCL handle with
 * ATRBVH_CL_COPY=1 (on a device that shares the host's memory, such as
 * PoCL's, the first works in place and the second copies), then takes
 * turns: one build on each, BUILDS times after two untimed turns, and
 * prints each handle's median and the OpenCL / CPU ratios.  Taking turns
 * in one process puts a process's PoCL mode (docs/opencl.md) on all
 * three alike.  Not built by the project; from the source tree, after
 * sh setup.sh:
 *
 *   cc -O2 -std=c99 -I lib -I _build -I _build/lib -I tools \
 *      -o /tmp/inplace docs/bench/inplace.c _build/tools/.libs/libscene.a \
 *      -L_build/lib/.libs -latrbvh -lm
 *   LD_LIBRARY_PATH=_build/lib/.libs OMP_WAIT_POLICY=passive \
 *       POCL_AFFINITY=1 /tmp/inplace SCENE BUILDS [lbvh|atrbvh|rays]
 *
 * lbvh (default): LBVH builds, 2 threads; atrbvh: ATRBVH(9, 2); rays:
 * one CPU build, then 100 000 random closest-hit rays per batch through
 * atrbvh_intersect_batch_device on the two OpenCL handles.
 */
#define _POSIX_C_SOURCE 200809L
#include "atrbvh.h"
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "harness.h"

#define RAYS 100000

static double median(double *t, int n)
{
    qsort(t, (size_t)n, sizeof *t, by_value);
    return t[n / 2];
}

/* RAYS rays from random points of the scene's box in random directions. */
static atrbvh_ray *random_rays(const atrbvh_geometry *g)
{
    atrbvh_ray *r = malloc(RAYS * sizeof *r);
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    size_t i;
    int k;
    if (!r)
        return NULL;
    for (i = 0; i < g->vertex_count; i++)
        for (k = 0; k < 3; k++) {
            const float v = g->vertices[3 * i + (size_t)k];
            lo[k] = v < lo[k] ? v : lo[k];
            hi[k] = v > hi[k] ? v : hi[k];
        }
    srand(1);
    for (i = 0; i < RAYS; i++) {
        for (k = 0; k < 3; k++) {
            r[i].origin[k] =
                lo[k] + (hi[k] - lo[k]) * (float)(rand() / (double)RAND_MAX);
            r[i].dir[k] = (float)(rand() / (double)RAND_MAX - 0.5);
        }
        r[i].tmin = 0.0f;
        r[i].tmax = 1e30f;
    }
    return r;
}

int main(int argc, char **argv)
{
    const char *mode = argc > 3 ? argv[3] : "lbvh";
    const int rays = strcmp(mode, "rays") == 0;
    atrbvh_device *dev[3] = {NULL, NULL, NULL};
    double *t[3];
    atrbvh_ray *ray = NULL;
    atrbvh_hit *hit = NULL;
    atrbvh_bvh *tree = NULL;
    atrbvh_geometry g;
    atrbvh_error e;
    char why[256];
    scene s;
    int n, i, k;
    if (argc < 3 || (n = atoi(argv[2])) < 1) {
        fprintf(stderr, "usage: %s SCENE BUILDS [lbvh|atrbvh|rays]\n",
                argv[0]);
        return 2;
    }
    if (scene_load(argv[1], &s, why, sizeof why) != 0) {
        fprintf(stderr, "%s\n", why);
        return 1;
    }
    g = scene_geometry(&s);
    if (atrbvh_device_open("cpu", &dev[0], &e) != ATRBVH_OK ||
        atrbvh_device_open("opencl", &dev[1], &e) != ATRBVH_OK ||
        setenv("ATRBVH_CL_COPY", "1", 1) != 0 ||
        atrbvh_device_open("opencl", &dev[2], &e) != ATRBVH_OK) {
        fprintf(stderr, "%s\n", e.text);
        return 1;
    }
    if (rays) {
        ray = random_rays(&g);
        hit = malloc(RAYS * sizeof *hit);
        if (!ray || !hit || atrbvh_build(&g, NULL, &tree, &e) != ATRBVH_OK) {
            fprintf(stderr, "rays: %s\n", ray && hit ? e.text : "no memory");
            return 1;
        }
    }
    for (k = 0; k < 3; k++)
        if (!(t[k] = malloc((size_t)n * sizeof *t[k])))
            return 1;
    for (i = -2; i < n; i++)
        for (k = rays; k < 3; k++) {
            atrbvh_build_options o;
            atrbvh_bvh *b = NULL;
            atrbvh_status st;
            double t0;
            atrbvh_build_options_init(&o);
            o.threads = 2;
            o.device = dev[k];
            if (strcmp(mode, "atrbvh") == 0) {
                o.method = ATRBVH_METHOD_ATRBVH;
                o.treelet_size = 9;
                o.rounds = 2;
            } else {
                o.method = ATRBVH_METHOD_LBVH;
            }
            t0 = now_ms();
            st = rays ? atrbvh_intersect_batch_device(dev[k], tree, &g, ray,
                                                      RAYS, hit, NULL, &e)
                      : atrbvh_build(&g, &o, &b, &e);
            if (st != ATRBVH_OK) {
                fprintf(stderr, "%s\n", e.text);
                return 1;
            }
            if (i >= 0)
                t[k][i] = now_ms() - t0;
            atrbvh_bvh_free(b);
        }
    if (rays) {
        printf("%s, %d ray batches of %d: in place %.2f ms, copying %.2f ms "
               "(medians)\n",
               argv[1], n, RAYS, median(t[1], n), median(t[2], n));
    } else {
        const double c = median(t[0], n), a = median(t[1], n),
                     b = median(t[2], n);
        printf("%s, %s, %d builds each: CPU %.3f ms, OpenCL in place %.3f "
               "ms (%.3f), copying %.3f ms (%.3f)\n",
               argv[1], mode, n, c, a, a / c, b, b / c);
    }
    for (k = 0; k < 3; k++) {
        free(t[k]);
        atrbvh_device_close(dev[k]);
    }
    atrbvh_bvh_free(tree);
    free(ray);
    free(hit);
    scene_free(&s);
    return 0;
}
