/*
 * rebuildpair.c - atrbvh_build after freeing the last tree against
 * atrbvh_rebuild into it, build for build, in one process: two CPU device
 * handles (one per side, so that each keeps only its own scratch), one
 * untimed build each, then PAIRS times one build of each side in turns
 * (the plain side first in even pairs).  Prints the medians of each
 * side's build time and of its bounds and layout stages (the two that
 * write the blocks a rebuild reuses: lib/cpu/backend.c's begin,
 * collapse.c), and the ratio of the build medians, rebuild / plain.  The
 * trees are the same (test_device's rebuild tests); this measures only
 * where the memory comes from.  Not built by the project; from the
 * source tree, after sh setup.sh:
 *
 *   cc -O2 -std=c99 -I lib -I _build -I _build/lib -I tools \
 *      -o /tmp/rebuildpair docs/bench/rebuildpair.c \
 *      _build/tools/.libs/libscene.a -L_build/lib/.libs -latrbvh -lm \
 *      -Wl,-rpath,$PWD/_build/lib/.libs
 *   OMP_WAIT_POLICY=passive /tmp/rebuildpair SCENE PAIRS \
 *       [lbvh|trbvh|atrbvh [SIZE [ROUNDS [THREADS]]]]
 *
 * Defaults: lbvh, the method's size and rounds, 2 threads; max leaf 8.
 */
#include "atrbvh.h"
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_PAIRS 1000

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int main(int argc, char **argv)
{
    static double ms[2][3][MAX_PAIRS]; /* side, (build, bounds, layout) */
    const char *what[2] = {"build after free", "rebuild"};
    scene sc;
    char why[256];
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_error e;
    atrbvh_device *dev[2] = {NULL, NULL};
    atrbvh_bvh *bvh[2] = {NULL, NULL};
    double med[2][3];
    int pairs, k, side, i;
    if (argc < 3) {
        fprintf(stderr, "usage: rebuildpair SCENE PAIRS [lbvh|trbvh|atrbvh "
                        "[SIZE [ROUNDS [THREADS]]]]\n");
        return 2;
    }
    pairs = atoi(argv[2]);
    if (pairs < 1 || pairs > MAX_PAIRS) {
        fprintf(stderr, "PAIRS: 1 to %d\n", MAX_PAIRS);
        return 2;
    }
    if (scene_load(argv[1], &sc, why, sizeof why) != 0) {
        fprintf(stderr, "%s: %s\n", argv[1], why);
        return 1;
    }
    g = scene_geometry(&sc);
    atrbvh_build_options_init(&o);
    o.method = argc > 3 && strcmp(argv[3], "atrbvh") == 0 ? ATRBVH_METHOD_ATRBVH
               : argc > 3 && strcmp(argv[3], "trbvh") == 0
                   ? ATRBVH_METHOD_TRBVH
                   : ATRBVH_METHOD_LBVH;
    o.treelet_size = argc > 4 ? (unsigned)strtoul(argv[4], NULL, 10) : 0;
    o.rounds = argc > 5 ? (unsigned)strtoul(argv[5], NULL, 10) : 0;
    o.threads = argc > 6 ? atoi(argv[6]) : 2;
    o.max_leaf_size = 8;
    for (side = 0; side < 2; side++)
        if (atrbvh_device_open("cpu", &dev[side], &e) != ATRBVH_OK) {
            fprintf(stderr, "%s\n", e.text);
            return 1;
        }
    for (k = -1; k < pairs; k++) {
        for (i = 0; i < 2; i++) {
            atrbvh_status st;
            atrbvh_stats s;
            side = k % 2 ? 1 - i : i; /* (k = -1: the rebuild first) */
            o.device = dev[side];
            if (side == 0) {
                atrbvh_bvh_free(bvh[0]);
                bvh[0] = NULL;
                st = atrbvh_build(&g, &o, &bvh[0], &e);
            } else {
                st = atrbvh_rebuild(&g, &o, &bvh[1], &e);
            }
            if (st != ATRBVH_OK || atrbvh_bvh_stats(bvh[side], &s) !=
                                       ATRBVH_OK) {
                fprintf(stderr, "%s: %s\n", what[side], e.text);
                return 1;
            }
            if (k < 0)
                continue;
            ms[side][0][k] = s.build_ms;
            ms[side][1][k] = atrbvh_bvh_stage_ms(bvh[side],
                                                 ATRBVH_STAGE_BOUNDS);
            ms[side][2][k] = atrbvh_bvh_stage_ms(bvh[side],
                                                 ATRBVH_STAGE_LAYOUT);
        }
    }
    for (side = 0; side < 2; side++)
        for (i = 0; i < 3; i++)
            med[side][i] = median(ms[side][i], pairs);
    printf("%s, %lu primitives, %s, %d threads, %d pairs (medians, ms):\n",
           argv[1], (unsigned long)g.primitive_count,
           argc > 3 ? argv[3] : "lbvh", o.threads, pairs);
    for (side = 0; side < 2; side++)
        printf("  %-16s build %9.2f  bounds %8.2f  layout %8.2f\n",
               what[side], med[side][0], med[side][1], med[side][2]);
    printf("  rebuild / plain: %.3f\n", med[1][0] / med[0][0]);
    for (side = 0; side < 2; side++) {
        atrbvh_bvh_free(bvh[side]);
        atrbvh_device_close(dev[side]);
    }
    scene_free(&sc);
    return 0;
}
