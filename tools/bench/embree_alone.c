/*
 * embree_alone.c - a standalone timing of Embree's rtcBuildBVH, to
 * cross-check the Embree rows of `atrbvh bench` (issue 11).
 *
 *   embree-alone SCENE [THREADS [REPEAT]]
 *
 * Written the way Embree's own builder tutorial uses the API, with nothing
 * of atrbvh in the timed part: the device and one BVH object are created
 * once; each build refills the primitive array (rtcBuildBVH reorders it)
 * and calls rtcBuildBVH with the smallest callbacks that keep the tree
 * (nodes from rtcThreadLocalAlloc, two child pointers and boxes per inner
 * node, primitive ids in leaves).  Binary tree, at most 8 primitives per
 * leaf, traversal cost 1.2, intersection cost 1, no spatial splits: the
 * settings of `atrbvh bench`.  Prints the median of REPEAT builds (after
 * one warm-up) per quality, in milliseconds, wall clock.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "scene.h"

#include <embree3/rtcore.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct node {
    void *child[2];
    struct RTCBounds box[2];
} node;

typedef struct leaf {
    unsigned count;
    unsigned id[8];
} leaf;

static void *create_node(RTCThreadLocalAllocator alloc, unsigned count,
                         void *user)
{
    node *n = rtcThreadLocalAlloc(alloc, sizeof *n, 16);
    (void)count, (void)user;
    n->child[0] = n->child[1] = NULL;
    return n;
}

static void set_children(void *p, void **children, unsigned count, void *user)
{
    node *n = p;
    unsigned k;
    (void)user;
    for (k = 0; k < count && k < 2; k++)
        n->child[k] = children[k];
}

static void set_bounds(void *p, const struct RTCBounds **b, unsigned count,
                       void *user)
{
    node *n = p;
    unsigned k;
    (void)user;
    for (k = 0; k < count && k < 2; k++)
        n->box[k] = *b[k];
}

static void *create_leaf(RTCThreadLocalAllocator alloc,
                         const struct RTCBuildPrimitive *prims, size_t count,
                         void *user)
{
    leaf *l = rtcThreadLocalAlloc(alloc, sizeof *l, 16);
    size_t k;
    (void)user;
    l->count = (unsigned)count;
    for (k = 0; k < count && k < 8; k++)
        l->id[k] = prims[k].primID;
    return l;
}

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static void fill(const scene *sc, struct RTCBuildPrimitive *p)
{
    size_t i;
    for (i = 0; i < sc->triangle_count; i++) {
        const uint32_t *t = sc->indices + 3 * i;
        const float *v[3];
        int k, a;
        float lo[3], hi[3];
        for (k = 0; k < 3; k++)
            v[k] = sc->vertices + 3 * (size_t)t[k];
        for (a = 0; a < 3; a++) {
            lo[a] = hi[a] = v[0][a];
            for (k = 1; k < 3; k++) {
                lo[a] = v[k][a] < lo[a] ? v[k][a] : lo[a];
                hi[a] = v[k][a] > hi[a] ? v[k][a] : hi[a];
            }
        }
        p[i].lower_x = lo[0], p[i].lower_y = lo[1], p[i].lower_z = lo[2];
        p[i].upper_x = hi[0], p[i].upper_y = hi[1], p[i].upper_z = hi[2];
        p[i].geomID = 0;
        p[i].primID = (unsigned)i;
    }
}

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    static const char *names[3] = {"low", "medium", "high"};
    static const enum RTCBuildQuality q[3] = {
        RTC_BUILD_QUALITY_LOW, RTC_BUILD_QUALITY_MEDIUM,
        RTC_BUILD_QUALITY_HIGH};
    scene sc;
    char err[512], config[64];
    int threads = argc > 2 ? atoi(argv[2]) : 0;
    int repeat = argc > 3 ? atoi(argv[3]) : 5, k, j;
    RTCDevice dev;
    RTCBVH bvh;
    struct RTCBuildPrimitive *prims;
    double *ms;
    if (argc < 2 || repeat < 1 || repeat > 1000 || threads < 0) {
        fprintf(stderr, "usage: embree-alone SCENE [THREADS [REPEAT]]\n");
        return 2;
    }
    if (scene_load(argv[1], &sc, err, sizeof err) != 0) {
        fprintf(stderr, "embree-alone: %s\n", err);
        return 1;
    }
    if (threads > 0)
        snprintf(config, sizeof config, "threads=%d", threads);
    else
        config[0] = '\0';
    dev = rtcNewDevice(config);
    bvh = dev ? rtcNewBVH(dev) : NULL;
    prims = malloc(sc.triangle_count * sizeof *prims);
    ms = malloc((size_t)repeat * sizeof *ms);
    if (!dev || !bvh || !prims || !ms) {
        fprintf(stderr, "embree-alone: cannot set up Embree or memory\n");
        return 1;
    }
    printf("# embree-alone %s: %zu triangles, threads %s, median of %d "
           "after a warm-up, %s\n",
           argv[1], sc.triangle_count, threads ? argv[2] : "all", repeat,
           RTC_VERSION_STRING);
    for (j = 0; j < 3; j++) {
        for (k = -1; k < repeat; k++) {
            struct RTCBuildArguments a = rtcDefaultBuildArguments();
            double t0 = now_ms();
            void *root;
            fill(&sc, prims);
            a.byteSize = sizeof a;
            a.buildQuality = q[j];
            a.maxBranchingFactor = 2;
            a.maxDepth = 1024;
            a.sahBlockSize = 1;
            a.minLeafSize = 1;
            a.maxLeafSize = 8;
            a.traversalCost = 1.2f;
            a.intersectionCost = 1.0f;
            a.bvh = bvh;
            a.primitives = prims;
            a.primitiveCount = sc.triangle_count;
            a.primitiveArrayCapacity = sc.triangle_count;
            a.createNode = create_node;
            a.setNodeChildren = set_children;
            a.setNodeBounds = set_bounds;
            a.createLeaf = create_leaf;
            root = rtcBuildBVH(&a);
            if (!root) {
                fprintf(stderr, "embree-alone: rtcBuildBVH failed (%d)\n",
                        (int)rtcGetDeviceError(dev));
                return 1;
            }
            if (k >= 0)
                ms[k] = now_ms() - t0;
        }
        qsort(ms, (size_t)repeat, sizeof *ms, cmp);
        printf("embree_%s %.3f ms\n", names[j], ms[repeat / 2]);
    }
    rtcReleaseBVH(bvh);
    rtcReleaseDevice(dev);
    free(prims);
    free(ms);
    scene_free(&sc);
    return 0;
}
