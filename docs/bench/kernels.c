/*
 * kernels.c - a CPU handle's stage times beside an OpenCL handle's
 * kernel times, builds taking turns in one process: the program behind
 * "Optimise: several treelets a work-item on a CPU device" in
 * docs/opencl.md.  It opens a CPU handle and an OpenCL handle, then
 * takes turns, one build on each, BUILDS times after two untimed turns;
 * it prints both medians and their ratio (OpenCL / CPU), the mean time
 * of each CPU stage and the mean device time of each OpenCL kernel
 * (atrbvh_bvh_kernel_time).  Not built by the project; from the source
 * tree, after sh setup.sh:
 *
 *   cc -O2 -std=c99 -I lib -I _build -I _build/lib -I tools \
 *      -o /tmp/kernels docs/bench/kernels.c _build/tools/.libs/libscene.a \
 *      -L_build/lib/.libs -latrbvh -lm
 *   LD_LIBRARY_PATH=_build/lib/.libs OMP_WAIT_POLICY=passive \
 *       POCL_AFFINITY=1 /tmp/kernels SCENE BUILDS [atrbvh|trbvh|lbvh]
 *
 * atrbvh (default): ATRBVH(9, 2); trbvh: TRBVH(7, 3); lbvh: LBVH; 2
 * threads.  The
 * environment at the open chooses the OpenCL handle's kernels (for
 * example ATRBVH_CL_WALKS=1: one treelet a work-item), so two runs
 * compare two settings.
 */
#define _POSIX_C_SOURCE 200809L
#include "atrbvh.h"
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "harness.h"

#define MAX_KERNELS 64

int main(int argc, char **argv)
{
    scene s;
    char why[256];
    atrbvh_device *dev[2] = {NULL, NULL};
    atrbvh_error e;
    atrbvh_geometry g;
    atrbvh_build_options o;
    double stage[2][ATRBVH_STAGE_COUNT] = {{0}}, kernel_ms[MAX_KERNELS] = {0};
    double *t[2];
    char *kernel_name[MAX_KERNELS] = {NULL};
    atrbvh_method method = ATRBVH_METHOD_ATRBVH;
    unsigned treelet = 9, rounds = 2;
    int builds, i, k, j, kernels = 0;
    if (argc < 3 || (builds = atoi(argv[2])) < 1) {
        fprintf(stderr, "usage: %s SCENE BUILDS [atrbvh|trbvh|lbvh]\n",
                argv[0]);
        return 2;
    }
    if (argc > 3 && strcmp(argv[3], "trbvh") == 0) {
        method = ATRBVH_METHOD_TRBVH;
        treelet = 7;
        rounds = 3;
    } else if (argc > 3 && strcmp(argv[3], "lbvh") == 0) {
        method = ATRBVH_METHOD_LBVH;
    }
    if (scene_load(argv[1], &s, why, sizeof why) != 0) {
        fprintf(stderr, "%s: %s\n", argv[1], why);
        return 1;
    }
    if (atrbvh_device_open("cpu", &dev[0], &e) != ATRBVH_OK ||
        atrbvh_device_open("opencl", &dev[1], &e) != ATRBVH_OK) {
        fprintf(stderr, "%s\n", e.text);
        return 1;
    }
    g = scene_geometry(&s);
    t[0] = malloc((size_t)builds * sizeof *t[0]);
    t[1] = malloc((size_t)builds * sizeof *t[1]);
    if (!t[0] || !t[1])
        return 1;
    for (i = -2; i < builds; i++)
        for (k = 0; k < 2; k++) {
            atrbvh_bvh *b;
            const char *name;
            double t0, ms;
            atrbvh_build_options_init(&o);
            o.threads = 2;
            o.device = dev[k];
            o.method = method;
            o.treelet_size = treelet;
            o.rounds = rounds;
            t0 = now_ms();
            if (atrbvh_build(&g, &o, &b, &e) != ATRBVH_OK) {
                fprintf(stderr, "%s\n", e.text);
                return 1;
            }
            if (i >= 0) {
                t[k][i] = now_ms() - t0;
                for (j = 0; j < ATRBVH_STAGE_COUNT; j++)
                    stage[k][j] += atrbvh_bvh_stage_ms(b, (atrbvh_stage)j);
                for (j = 0; k == 1 && j < MAX_KERNELS &&
                            atrbvh_bvh_kernel_time(b, (size_t)j, &name, &ms);
                     j++) {
                    if (j >= kernels) {
                        kernel_name[j] = malloc(strlen(name) + 1);
                        if (!kernel_name[j])
                            return 1;
                        strcpy(kernel_name[j], name);
                        kernels = j + 1;
                    }
                    kernel_ms[j] += ms;
                }
            }
            atrbvh_bvh_free(b);
        }
    qsort(t[0], (size_t)builds, sizeof *t[0], by_value);
    qsort(t[1], (size_t)builds, sizeof *t[1], by_value);
    printf("median cpu %.3f ms, opencl %.3f ms, ratio %.3f\n",
           t[0][builds / 2], t[1][builds / 2],
           t[1][builds / 2] / t[0][builds / 2]);
    for (j = 0; j < ATRBVH_STAGE_COUNT; j++)
        printf("  cpu %-10s %8.3f ms   opencl (host wall) %8.3f ms\n",
               atrbvh_stage_name((atrbvh_stage)j), stage[0][j] / builds,
               stage[1][j] / builds);
    for (j = 0; j < kernels; j++) {
        printf("  kernel %-18s %8.3f ms\n", kernel_name[j],
               kernel_ms[j] / builds);
        free(kernel_name[j]);
    }
    free(t[0]);
    free(t[1]);
    atrbvh_device_close(dev[0]);
    atrbvh_device_close(dev[1]);
    scene_free(&s);
    return 0;
}
