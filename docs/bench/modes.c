/*
 * modes.c - repeated LBVH builds of one scene on one device handle, with
 * each stage's mean time and, at the end, every thread's CPU time: the
 * program behind "what the slow mode is" in docs/bench/log.md (3 December).
 * Not built by the project; from the source tree, after sh setup.sh:
 *
 *   cc -O2 -std=c99 -I lib -I _build -I _build/lib -I tools \
 *      -o /tmp/modes docs/bench/modes.c _build/tools/.libs/libscene.a \
 *      -L_build/lib/.libs -latrbvh -lm
 *   LD_LIBRARY_PATH=_build/lib/.libs /tmp/modes SCENE [BUILDS [THREADS
 *       [DEVICE [PAUSE_MS [WARM]]]]]
 *
 * DEVICE: cpu (default) or opencl.  PAUSE_MS (default 0): a sleep before
 * each timed build, then WARM (default 0) untimed builds: how a build
 * fares after the threads were idle ("PoCL's workers after an idle spell"
 * in docs/opencl.md).  Run it several times: a process tends to stay in
 * one mode.  Printed: the builds' minimum, mean and quartiles, the
 * stages' and (OpenCL) the kernels' mean times, and each thread's CPU
 * time in clock ticks from /proc/self/task/ID/stat
 * (Linux).
 */
#define _POSIX_C_SOURCE 199309L
#include "atrbvh.h"
#include "scene.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "harness.h"

#define MAX_KERNELS 64

/* Each thread of this process: its user + system clock ticks. */
static void print_threads(void)
{
    DIR *d = opendir("/proc/self/task");
    struct dirent *e;
    if (!d)
        return;
    while ((e = readdir(d)) != NULL) {
        char path[300], buf[1024], *p;
        unsigned long ut = 0, st = 0;
        size_t n;
        FILE *f;
        if (e->d_name[0] == '.')
            continue;
        snprintf(path, sizeof path, "/proc/self/task/%s/stat", e->d_name);
        f = fopen(path, "r");
        if (!f)
            continue;
        n = fread(buf, 1, sizeof buf - 1, f);
        fclose(f);
        buf[n] = '\0';
        p = strrchr(buf, ')'); /* fields after the command name */
        if (p && sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u "
                               "%lu %lu", &ut, &st) == 2)
            printf("thread %s: %lu ticks\n", e->d_name, ut + st);
    }
    closedir(d);
}

static int by_time(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int main(int argc, char **argv)
{
    const char *device = argc > 4 ? argv[4] : "cpu";
    const int builds = argc > 2 ? atoi(argv[2]) : 20;
    const int threads = argc > 3 ? atoi(argv[3]) : 2;
    const long pause = argc > 5 ? atol(argv[5]) : 0;
    const int warm = argc > 6 ? atoi(argv[6]) : 0;
    double stage[ATRBVH_STAGE_COUNT] = {0}, outside = 0.0, sum = 0.0, best = 1e300;
    double *each; /* every timed build's time, sorted for the quartiles */
    /* kernels by name, in the order first seen */
    double kernel_ms[MAX_KERNELS] = {0};
    char kernel_name[MAX_KERNELS][64];
    size_t kernels = 0, q;
    atrbvh_build_options o;
    atrbvh_geometry g;
    atrbvh_device *dev;
    atrbvh_error err;
    char why[256];
    scene s;
    int r, k;
    if (argc < 2 || builds < 1 || pause < 0 || pause > 10000 || warm < 0) {
        fprintf(stderr, "usage: modes SCENE [BUILDS [THREADS [DEVICE "
                        "[PAUSE_MS [WARM]]]]]\n");
        return 2;
    }
    if (scene_load(argv[1], &s, why, sizeof why) != 0) {
        fprintf(stderr, "modes: %s\n", why);
        return 1;
    }
    if (atrbvh_device_open(device, &dev, &err) != ATRBVH_OK) {
        fprintf(stderr, "modes: %s\n", err.text);
        return 1;
    }
    each = malloc((size_t)builds * sizeof *each);
    if (!each) {
        fprintf(stderr, "modes: out of memory\n");
        return 1;
    }
    g = scene_geometry(&s);
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    o.device = dev;
    o.threads = threads;
    o.collapse = 1;
    o.max_leaf_size = 8;
    for (r = 0; r <= builds; r++) { /* build 0: the warm-up */
        atrbvh_bvh *b;
        double t;
        int w;
        if (pause > 0) {
            const struct timespec ts = {pause / 1000,
                                        (pause % 1000) * 1000000L};
            nanosleep(&ts, NULL);
        }
        for (w = 0; w < warm; w++) {
            if (atrbvh_build(&g, &o, &b, &err) != ATRBVH_OK) {
                fprintf(stderr, "modes: %s\n", err.text);
                return 1;
            }
            atrbvh_bvh_free(b);
        }
        t = now_ms();
        if (atrbvh_build(&g, &o, &b, &err) != ATRBVH_OK) {
            fprintf(stderr, "modes: %s\n", err.text);
            return 1;
        }
        t = now_ms() - t;
        if (r > 0) {
            sum += t;
            best = t < best ? t : best;
            each[r - 1] = t;
            const char *name;
            double ms;
            size_t i;
            outside += t;
            for (k = 0; k < ATRBVH_STAGE_COUNT; k++) {
                stage[k] += atrbvh_bvh_stage_ms(b, (atrbvh_stage)k);
                outside -= atrbvh_bvh_stage_ms(b, (atrbvh_stage)k);
            }
            for (i = 0; atrbvh_bvh_kernel_time(b, i, &name, &ms); i++) {
                for (q = 0; q < kernels && strcmp(kernel_name[q], name); q++)
                    ;
                if (q == kernels && kernels < MAX_KERNELS) {
                    snprintf(kernel_name[q], sizeof kernel_name[q], "%s",
                             name);
                    kernels++;
                }
                if (q < kernels)
                    kernel_ms[q] += ms;
            }
        }
        atrbvh_bvh_free(b);
    }
    printf("%s, %d builds, %d threads, %s, each after %ld ms idle and %d "
           "untimed: min %.3f ms, mean %.3f ms\n",
           argv[1], builds, threads, device, pause, warm, best, sum / builds);
    qsort(each, (size_t)builds, sizeof *each, by_time);
    printf("  quartiles %.3f / %.3f / %.3f ms (25th, median, 75th)\n",
           each[builds / 4], each[builds / 2], each[3 * builds / 4]);
    free(each);
    for (k = 0; k < ATRBVH_STAGE_COUNT; k++)
        printf("  %-10s %.3f ms\n", atrbvh_stage_name((atrbvh_stage)k),
               stage[k] / builds);
    printf("  outside the stages %.3f ms\n", outside / builds);
    for (q = 0; q < kernels; q++)
        printf("  kernel %-16s %.3f ms\n", kernel_name[q],
               kernel_ms[q] / builds);
    print_threads();
    atrbvh_device_close(dev);
    scene_free(&s);
    return 0;
}
