/*
 * abpair.c - two builds of the library compared in one process, build
 * for build: the libatrbvh.so files LIB_A and LIB_B are each loaded with
 * dlopen (copies at two paths, RTLD_LOCAL: each keeps its own symbols),
 * then PAIRS times one build with A and one with B of the same scene and
 * configuration, in turns (A first in even pairs, B first in odd ones).
 * Prints the median and minimum of each side's build and optimise stage
 * and the median of the pairs' ratios B / A: on a shared host whose
 * speed drifts by 1.5x within seconds (docs/benchmarks.md, "The
 * machine"), two builds a few milliseconds apart see the same speed, so
 * the ratio of a pair is steadier than minima of separate runs (ab.sh).
 * Not built by the project; from the source tree, after sh setup.sh:
 *
 *   cc -O2 -std=c99 -I lib -I _build -I _build/lib -I tools \
 *      -o /tmp/abpair docs/bench/abpair.c _build/tools/.libs/libscene.a \
 *      -ldl -lm
 *   OMP_WAIT_POLICY=passive /tmp/abpair LIB_A LIB_B SCENE PAIRS \
 *       [lbvh|trbvh|atrbvh [SIZE [ROUNDS [THREADS]]]]
 *
 * LIB_A and LIB_B: paths of two copies of _build/lib/.libs/libatrbvh.so
 * (before and after a change).  Compare the trees first (the test suite's
 * hashes).  Defaults: atrbvh, the method's sizes and rounds, 1 thread;
 * two untimed builds with each first.  ABPAIR_DEVICE=opencl in the
 * environment compares the OpenCL backend's builds instead (each library
 * opens its own device handle, once; POCL_AFFINITY=1 as the speed runs).
 */
#define _POSIX_C_SOURCE 199309L
#include "atrbvh.h"
#include "scene.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"

typedef struct lib {
    void *h;
    atrbvh_status (*open)(const char *, atrbvh_device **, atrbvh_error *);
    void (*close)(atrbvh_device *);
    void (*init)(atrbvh_build_options *);
    atrbvh_status (*build)(const atrbvh_geometry *,
                           const atrbvh_build_options *, atrbvh_bvh **,
                           atrbvh_error *);
    double (*stage_ms)(const atrbvh_bvh *, atrbvh_stage);
    void (*bvh_free)(atrbvh_bvh *);
    atrbvh_device *dev;
} lib;

/* dlsym's object pointer into a function pointer (POSIX allows it; C99
 * has no conversion, hence the copy). */
static int sym(void *h, const char *name, void *out, size_t size)
{
    void *p = dlsym(h, name);
    if (!p) {
        fprintf(stderr, "abpair: %s: %s\n", name, dlerror());
        return -1;
    }
    memcpy(out, &p, size);
    return 0;
}

static int load(const char *path, lib *l)
{
    atrbvh_error e;
    if (!(l->h = dlopen(path, RTLD_NOW | RTLD_LOCAL))) {
        fprintf(stderr, "abpair: %s\n", dlerror());
        return -1;
    }
    if (sym(l->h, "atrbvh_device_open", &l->open, sizeof l->open) ||
        sym(l->h, "atrbvh_device_close", &l->close, sizeof l->close) ||
        sym(l->h, "atrbvh_build_options_init", &l->init, sizeof l->init) ||
        sym(l->h, "atrbvh_build", &l->build, sizeof l->build) ||
        sym(l->h, "atrbvh_bvh_stage_ms", &l->stage_ms, sizeof l->stage_ms) ||
        sym(l->h, "atrbvh_bvh_free", &l->bvh_free, sizeof l->bvh_free))
        return -1;
    if (l->open(getenv("ABPAIR_DEVICE") ? getenv("ABPAIR_DEVICE") : "cpu",
                &l->dev, &e) != ATRBVH_OK) {
        fprintf(stderr, "abpair: %s: %s\n", path, e.text);
        return -1;
    }
    return 0;
}

/* One build: its time and its optimise stage's, in ms. */
static int one(const lib *l, const atrbvh_geometry *g,
               const atrbvh_build_options *base, double *total, double *opt)
{
    atrbvh_build_options o;
    atrbvh_bvh *b;
    atrbvh_error e;
    double t0;
    l->init(&o);
    o.threads = base->threads;
    o.method = base->method;
    o.treelet_size = base->treelet_size;
    o.rounds = base->rounds;
    o.device = l->dev;
    t0 = now_ms();
    if (l->build(g, &o, &b, &e) != ATRBVH_OK) {
        fprintf(stderr, "abpair: %s\n", e.text);
        return -1;
    }
    *total = now_ms() - t0;
    *opt = l->stage_ms(b, ATRBVH_STAGE_OPTIMISE);
    l->bvh_free(b);
    return 0;
}

/* scene.c's scene_geometry calls atrbvh_geometry_triangles, which this
 * program is not linked against: this definition forwards to side A's
 * (a pure function that fills a struct, the same in both). */
static atrbvh_geometry (*geometry_of)(const float *, size_t, const uint32_t *,
                                      size_t);

atrbvh_geometry atrbvh_geometry_triangles(const float *vertices,
                                          size_t vertex_count,
                                          const uint32_t *indices,
                                          size_t triangle_count)
{
    return geometry_of(vertices, vertex_count, indices, triangle_count);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, by_value);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int main(int argc, char **argv)
{
    lib side[2];
    scene s;
    char why[256];
    atrbvh_geometry g;
    atrbvh_build_options o;
    double *t[2], *op[2], *rt, *ro;
    int pairs, i, k;
    if (argc < 5 || (pairs = atoi(argv[4])) < 1) {
        fprintf(stderr, "usage: %s LIB_A LIB_B SCENE PAIRS [lbvh|trbvh|atrbvh "
                        "[SIZE [ROUNDS [THREADS]]]]\n",
                argv[0]);
        return 2;
    }
    memset(&o, 0, sizeof o);
    o.method = ATRBVH_METHOD_ATRBVH;
    if (argc > 5 && strcmp(argv[5], "trbvh") == 0)
        o.method = ATRBVH_METHOD_TRBVH;
    else if (argc > 5 && strcmp(argv[5], "lbvh") == 0)
        o.method = ATRBVH_METHOD_LBVH;
    o.treelet_size = argc > 6 ? (unsigned)atoi(argv[6]) : 0u;
    o.rounds = argc > 7 ? (unsigned)atoi(argv[7]) : 0u;
    o.threads = argc > 8 ? atoi(argv[8]) : 1;
    if (o.threads < 1) {
        fprintf(stderr, "abpair: THREADS >= 1\n");
        return 2;
    }
    if (load(argv[1], &side[0]) || load(argv[2], &side[1]) ||
        sym(side[0].h, "atrbvh_geometry_triangles", &geometry_of,
            sizeof geometry_of))
        return 1;
    if (scene_load(argv[3], &s, why, sizeof why) != 0) {
        fprintf(stderr, "%s: %s\n", argv[3], why);
        return 1;
    }
    g = scene_geometry(&s);
    for (k = 0; k < 2; k++)
        if (!(t[k] = malloc((size_t)pairs * sizeof(double))) ||
            !(op[k] = malloc((size_t)pairs * sizeof(double))))
            return 1;
    if (!(rt = malloc((size_t)pairs * sizeof(double))) ||
        !(ro = malloc((size_t)pairs * sizeof(double))))
        return 1;
    for (i = -2; i < pairs; i++) {
        double bt[2], bo[2];
        for (k = 0; k < 2; k++) {
            const int x = (i & 1) ? 1 - k : k; /* B first in odd pairs */
            if (one(&side[x], &g, &o, &bt[x], &bo[x]))
                return 1;
        }
        if (i < 0)
            continue;
        for (k = 0; k < 2; k++) {
            t[k][i] = bt[k];
            op[k][i] = bo[k];
        }
        rt[i] = bt[1] / bt[0];
        ro[i] = bo[0] > 0.0 ? bo[1] / bo[0] : 1.0;
    }
    printf("pairs %d, ratio B / A: build median %.4f, optimise median %.4f\n",
           pairs, median(rt, pairs), median(ro, pairs));
    for (k = 0; k < 2; k++) {
        const double mt = median(t[k], pairs), mo = median(op[k], pairs);
        printf("%c build median %.3f min %.3f  optimise median %.3f min "
               "%.3f ms\n",
               k ? 'B' : 'A', mt, t[k][0], mo, op[k][0]);
    }
    for (k = 0; k < 2; k++) {
        side[k].close(side[k].dev);
        free(t[k]);
        free(op[k]);
    }
    free(rt);
    free(ro);
    scene_free(&s);
    return 0;
}
