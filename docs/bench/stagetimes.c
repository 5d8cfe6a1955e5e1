/*
 * stagetimes.c - repeated CPU builds of one scene in one configuration,
 * with the builds' median and minimum and each stage's mean, median and
 * minimum: the program behind the A/B comparisons of "The Intel host
 * again" in docs/bench/log.md (5 December), which docs/bench/ab.sh runs
 * against two builds of the library in turns.  Not built by the project;
 * from the source tree, after sh setup.sh:
 *
 *   cc -O2 -std=c99 -I lib -I _build -I _build/lib -I tools \
 *      -o /tmp/stagetimes docs/bench/stagetimes.c \
 *      _build/tools/.libs/libscene.a -L_build/lib/.libs -latrbvh -lm
 *   LD_LIBRARY_PATH=_build/lib/.libs OMP_WAIT_POLICY=passive \
 *       /tmp/stagetimes SCENE BUILDS [lbvh|trbvh|atrbvh [SIZE [ROUNDS
 *       [THREADS]]]]
 *
 * Defaults: atrbvh, the method's default size and rounds (0), 1 thread.
 * STAGETIMES_DEVICE=opencl (or another device spec) times that device.
 * Two untimed builds first.  The minimum is the figure to compare on a
 * shared host whose speed drifts (docs/benchmarks.md, "The machine").
 */
#define _POSIX_C_SOURCE 199309L
#include "atrbvh.h"
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "harness.h"

int main(int argc, char **argv)
{
    scene s;
    char why[256];
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_method method = ATRBVH_METHOD_ATRBVH;
    double *t[ATRBVH_STAGE_COUNT + 1], sum[ATRBVH_STAGE_COUNT] = {0};
    int builds, i, j, size, rounds, threads;
    if (argc < 3 || (builds = atoi(argv[2])) < 1) {
        fprintf(stderr, "usage: %s SCENE BUILDS [lbvh|trbvh|atrbvh [SIZE "
                        "[ROUNDS [THREADS]]]]\n",
                argv[0]);
        return 2;
    }
    if (argc > 3 && strcmp(argv[3], "trbvh") == 0)
        method = ATRBVH_METHOD_TRBVH;
    else if (argc > 3 && strcmp(argv[3], "lbvh") == 0)
        method = ATRBVH_METHOD_LBVH;
    size = argc > 4 ? atoi(argv[4]) : 0;
    rounds = argc > 5 ? atoi(argv[5]) : 0;
    threads = argc > 6 ? atoi(argv[6]) : 1;
    if (size < 0 || rounds < 0 || threads < 1) {
        fprintf(stderr, "%s: SIZE and ROUNDS >= 0, THREADS >= 1\n", argv[0]);
        return 2;
    }
    if (scene_load(argv[1], &s, why, sizeof why) != 0) {
        fprintf(stderr, "%s: %s\n", argv[1], why);
        return 1;
    }
    if (atrbvh_device_open(getenv("STAGETIMES_DEVICE")
                               ? getenv("STAGETIMES_DEVICE")
                               : "cpu",
                           &dev, &e) != ATRBVH_OK) {
        fprintf(stderr, "%s\n", e.text);
        return 1;
    }
    for (j = 0; j <= ATRBVH_STAGE_COUNT; j++)
        if (!(t[j] = malloc((size_t)builds * sizeof *t[j])))
            return 1;
    g = scene_geometry(&s);
    for (i = -2; i < builds; i++) {
        atrbvh_bvh *b;
        double t0;
        atrbvh_build_options_init(&o);
        o.threads = threads;
        o.device = dev;
        o.method = method;
        o.treelet_size = (unsigned)size;
        o.rounds = (unsigned)rounds;
        t0 = now_ms();
        if (atrbvh_build(&g, &o, &b, &e) != ATRBVH_OK) {
            fprintf(stderr, "%s\n", e.text);
            return 1;
        }
        if (i >= 0) {
            t[ATRBVH_STAGE_COUNT][i] = now_ms() - t0;
            for (j = 0; j < ATRBVH_STAGE_COUNT; j++) {
                t[j][i] = atrbvh_bvh_stage_ms(b, (atrbvh_stage)j);
                sum[j] += t[j][i];
            }
        }
        atrbvh_bvh_free(b);
    }
    for (j = 0; j <= ATRBVH_STAGE_COUNT; j++)
        qsort(t[j], (size_t)builds, sizeof *t[j], by_value);
    printf("build median %.3f ms min %.3f\n", t[ATRBVH_STAGE_COUNT][builds / 2],
           t[ATRBVH_STAGE_COUNT][0]);
    for (j = 0; j < ATRBVH_STAGE_COUNT; j++)
        printf("  %-10s mean %8.3f median %8.3f min %8.3f\n",
               atrbvh_stage_name((atrbvh_stage)j), sum[j] / builds,
               t[j][builds / 2], t[j][0]);
    for (j = 0; j <= ATRBVH_STAGE_COUNT; j++)
        free(t[j]);
    atrbvh_device_close(dev);
    scene_free(&s);
    return 0;
}
