/*
 * sahgap.c - where the SAH gap between an atrbvh tree and Embree's lies:
 * in the top of the tree (its large subtrees) or in the bottom.  The
 * program behind "Where the scans' SAH gap lies" in docs/benchmarks.md.
 * Not built by the project; from the source tree, after sh setup.sh
 * (Embree found by configure):
 *
 *   cc -O2 -std=c99 -fopenmp -I lib -I _build -I _build/lib -I tools \
 *      -I tools/bench -o /tmp/sahgap docs/bench/sahgap.c \
 *      tools/bench/embree.c _build/tools/.libs/libscene.a \
 *      -L_build/lib/.libs -latrbvh -lembree3 -lm
 *   LD_LIBRARY_PATH=_build/lib/.libs /tmp/sahgap SCENE [SIZE ROUNDS]
 *
 * It builds the scene with atrbvh (ATRBVH, default 16 leaves, 3 rounds;
 * SAHGAP_METHOD=trbvh for TRBVH, size at most 10) and with Embree medium
 * (rtcBuildBVH, binned SAH), both with leaves of at most 8 primitives
 * and the SAH costs Ci 1.2, Ct 1 (tools/bench's Embree builder, laid out
 * as atrbvh nodes).  Then, for cut sizes S, the hybrids: one tree's top
 * (its nodes above the largest subtrees of at most S primitives) with
 * each of those subtrees rebuilt by the other builder from the same
 * primitives.  The hybrid's SAH is the top's internal nodes' cost plus
 * each rebuilt subtree's own cost, over the whole tree's root area (a
 * subtree's box is its primitives' box under either builder).  An atrbvh
 * rebuild of fewer primitives than the treelet size makes them one
 * treelet (a smaller size), else no treelet would form.
 *
 * Read: "embree" rows, Embree's top with atrbvh's subtrees; "atrbvh"
 * rows the other way.  Where the first stays at Embree's SAH down to a
 * small S and the second at atrbvh's, the gap is made above S.  One
 * thread for the subtree builds (their order and results fixed).
 */
#define _POSIX_C_SOURCE 199309L
#include "atrbvh.h"
#include "cli.h"
#include "embree.h"
#include "scene.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define CI 1.2
#define CT 1.0
#define MAX_LEAF 8u

/* The ATRBVH treelet size and rounds (the whole build's and the subtree
 * builds'). */
static unsigned tl_size = 16, tl_rounds = 3;
/* ATRBVH, or TRBVH with SAHGAP_METHOD=trbvh (size at most 10). */
static atrbvh_method tl_method = ATRBVH_METHOD_ATRBVH;


/* tools/bench/embree.c's two helpers from the tool's main.c. */
void cli_error(const char *fmt, ...)
{
    va_list ap;
    fputs("sahgap: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

double cli_now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* The options of every atrbvh build here: the method, `size` leaves a
 * treelet, the rounds, leaves of at most MAX_LEAF by SAH. */
static void options_for(atrbvh_build_options *o, unsigned size, int threads)
{
    atrbvh_build_options_init(o);
    o->method = tl_method;
    o->treelet_size = size;
    o->rounds = tl_rounds;
    o->collapse = 1;
    o->max_leaf_size = MAX_LEAF;
    o->threads = threads;
}

static double area(const atrbvh_node *n)
{
    const double dx = (double)n->max[0] - (double)n->min[0];
    const double dy = (double)n->max[1] - (double)n->min[1];
    const double dz = (double)n->max[2] - (double)n->min[2];
    return 2.0 * (dx * dy + dy * dz + dz * dx);
}

/* SAH of the subtree at node i, not normalised (area-weighted costs). */
static double raw_cost(const atrbvh_node *nodes, uint32_t i)
{
    if (nodes[i].count)
        return CT * (double)nodes[i].count * area(&nodes[i]);
    return CI * area(&nodes[i]) + raw_cost(nodes, i + 1) +
           raw_cost(nodes, nodes[i].index);
}

/* Primitives under each node (prims[i]), by a reverse sweep: children
 * come after their parent in the depth-first array. */
/* Internal nodes' and leaves' cost terms (raw), and the leaf count. */
static void split_cost(const atrbvh_node *nodes, size_t count, double *inner,
                       double *leaf, size_t *leaves)
{
    size_t i;
    *inner = *leaf = 0.0;
    *leaves = 0;
    for (i = 0; i < count; i++)
        if (nodes[i].count) {
            *leaf += CT * (double)nodes[i].count * area(&nodes[i]);
            ++*leaves;
        } else {
            *inner += CI * area(&nodes[i]);
        }
}

static uint32_t *subtree_prims(const atrbvh_node *nodes, size_t count)
{
    uint32_t *p = malloc(count * sizeof *p);
    size_t i;
    if (!p)
        return NULL;
    for (i = count; i-- > 0;)
        p[i] = nodes[i].count ? nodes[i].count
                              : p[i + 1] + p[nodes[i].index];
    return p;
}

/* The triangles of the subtree at node i appended to idx (3 per). */
static void gather(const atrbvh_bvh *b, const scene *sc, uint32_t i,
                   uint32_t *idx, size_t *k)
{
    size_t nc, pc;
    const atrbvh_node *nodes = atrbvh_bvh_nodes(b, &nc);
    const uint32_t *prims = atrbvh_bvh_primitive_indices(b, &pc);
    if (nodes[i].count) {
        uint32_t j;
        for (j = 0; j < nodes[i].count; j++) {
            const uint32_t t = prims[nodes[i].index + j];
            memcpy(idx + 3 * *k, sc->indices + 3 * (size_t)t,
                   3 * sizeof *idx);
            (*k)++;
        }
        return;
    }
    gather(b, sc, i + 1, idx, k);
    gather(b, sc, nodes[i].index, idx, k);
}

typedef struct hybrid {
    const scene *sc;
    const atrbvh_bvh *top; /* the tree whose top is kept */
    const uint32_t *under; /* its primitives per node */
    uint32_t cut;          /* S */
    int rebuild_embree;    /* the subtrees by Embree (else atrbvh) */
    embree_ctx *ectx;
    uint32_t *idx;         /* scratch: 3 indices per triangle */
    double top_cost;       /* the kept internal nodes, raw */
    double bottom_cost;    /* the rebuilt subtrees, raw */
    double old_bottom;     /* the same subtrees as they were, raw */
    size_t subtrees, top_nodes;
    int failed;
} hybrid;

static double rebuilt_cost(hybrid *h, uint32_t i)
{
    scene sub;
    size_t k = 0, nc;
    const atrbvh_node *nodes;
    double c;
    gather(h->top, h->sc, i, h->idx, &k);
    sub = *h->sc;
    sub.indices = h->idx;
    sub.triangle_count = k;
    if (h->rebuild_embree) {
        embree_build_result r;
        if (embree_build(h->ectx, &sub, EMBREE_MEDIUM, MAX_LEAF, CI, CT, 0,
                         &r) != 0) {
            h->failed = 1;
            return 0.0;
        }
        nodes = atrbvh_bvh_nodes(r.bvh, &nc);
        c = raw_cost(nodes, 0);
        atrbvh_bvh_free(r.bvh);
    } else {
        atrbvh_geometry g = scene_geometry(&sub);
        atrbvh_build_options o;
        atrbvh_bvh *b;
        atrbvh_error e;
        /* a set of fewer primitives than the treelet size is one
         * treelet of them all (else no treelet would form: a treelet
         * root needs that many) */
        options_for(&o, k >= tl_size ? tl_size : k > 3 ? (unsigned)k : 3u,
                    1);
        if (atrbvh_build(&g, &o, &b, &e) != ATRBVH_OK) {
            cli_error("subtree build: %s", e.text);
            h->failed = 1;
            return 0.0;
        }
        nodes = atrbvh_bvh_nodes(b, &nc);
        c = raw_cost(nodes, 0);
        atrbvh_bvh_free(b);
    }
    return c;
}

static void walk(hybrid *h, uint32_t i)
{
    size_t nc;
    const atrbvh_node *nodes = atrbvh_bvh_nodes(h->top, &nc);
    if (h->failed)
        return;
    if (h->under[i] <= h->cut) {
        h->subtrees++;
        h->old_bottom += raw_cost(nodes, i);
        h->bottom_cost += rebuilt_cost(h, i);
        return;
    }
    /* (a leaf holds at most MAX_LEAF <= every cut's primitives) */
    h->top_nodes++;
    h->top_cost += CI * area(&nodes[i]);
    walk(h, i + 1);
    walk(h, nodes[i].index);
}

int main(int argc, char **argv)
{
    static const uint32_t cuts[] = {16, 64, 256, 1024, 4096, 16384, 65536};
    scene sc;
    char why[256];
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_bvh *ours;
    atrbvh_error e;
    embree_build_result emb;
    embree_ctx *ectx;
    const atrbvh_bvh *trees[2];
    uint32_t *under[2];
    double root[2], sah[2];
    size_t nc, c;
    int t;
    if (argc != 2 && argc != 4) {
        fprintf(stderr, "usage: %s SCENE [SIZE ROUNDS]\n", argv[0]);
        return 2;
    }
    if (getenv("SAHGAP_METHOD") && strcmp(getenv("SAHGAP_METHOD"), "trbvh") == 0)
        tl_method = ATRBVH_METHOD_TRBVH;
    if (argc == 4) {
        tl_size = (unsigned)atoi(argv[2]);
        tl_rounds = (unsigned)atoi(argv[3]);
    }
    if (scene_load(argv[1], &sc, why, sizeof why) != 0) {
        fprintf(stderr, "%s: %s\n", argv[1], why);
        return 1;
    }
    g = scene_geometry(&sc);
    options_for(&o, tl_size, 2);
    if (atrbvh_build(&g, &o, &ours, &e) != ATRBVH_OK) {
        fprintf(stderr, "%s\n", e.text);
        return 1;
    }
    if (!(ectx = embree_open(1)))
        return 1;
    if (embree_build(ectx, &sc, EMBREE_MEDIUM, MAX_LEAF, CI, CT, 0, &emb))
        return 1;
    trees[0] = ours;
    trees[1] = emb.bvh;
    for (t = 0; t < 2; t++) {
        const atrbvh_node *nodes = atrbvh_bvh_nodes(trees[t], &nc);
        root[t] = area(&nodes[0]);
        sah[t] = raw_cost(nodes, 0) / root[t];
        if (!(under[t] = subtree_prims(nodes, nc)))
            return 1;
    }
    printf("# %s, %zu triangles: %s(%u,%u) SAH %.4f, Embree medium "
           "%.4f (%+.2f%%); leaves <= %u, Ci %.1f, Ct %.1f\n",
           sc.name, sc.triangle_count,
           tl_method == ATRBVH_METHOD_TRBVH ? "TRBVH" : "ATRBVH", tl_size, tl_rounds, sah[0], sah[1],
           100.0 * (sah[0] / sah[1] - 1.0), MAX_LEAF, CI, CT);
    for (t = 0; t < 2; t++) {
        double in, lf;
        size_t leaves;
        const atrbvh_node *nodes = atrbvh_bvh_nodes(trees[t], &nc);
        split_cost(nodes, nc, &in, &lf, &leaves);
        printf("# %s: %zu nodes, %zu leaves (%.2f primitives each), "
               "internal nodes %.4f + leaves %.4f\n",
               t == 0 ? "atrbvh" : "embree", nc, leaves,
               (double)sc.triangle_count / (double)leaves, in / root[t],
               lf / root[t]);
    }
    printf("%-7s %-8s %9s %11s %9s %9s %9s %9s\n", "cut S", "top", "top nodes",
           "subtrees", "top SAH", "bottoms", "rebuilt", "hybrid");
    for (c = 0; c < sizeof cuts / sizeof cuts[0]; c++) {
        if (cuts[c] >= sc.triangle_count)
            break;
        for (t = 0; t < 2; t++) {
            hybrid h;
            memset(&h, 0, sizeof h);
            h.sc = &sc;
            h.top = trees[t];
            h.under = under[t];
            h.cut = cuts[c];
            h.rebuild_embree = t == 0;
            h.ectx = ectx;
            h.idx = malloc(3 * sc.triangle_count * sizeof *h.idx);
            if (!h.idx)
                return 1;
            walk(&h, 0);
            free(h.idx);
            if (h.failed)
                return 1;
            /* top SAH: the kept nodes; bottoms: the subtrees as the
             * top's builder made them; rebuilt: by the other builder;
             * hybrid: top + rebuilt (all over the root's area) */
            printf("%-7u %-8s %9zu %11zu %9.4f %9.4f %9.4f %9.4f\n",
                   cuts[c], t == 0 ? "atrbvh" : "embree", h.top_nodes,
                   h.subtrees, h.top_cost / root[t], h.old_bottom / root[t],
                   h.bottom_cost / root[t],
                   (h.top_cost + h.bottom_cost) / root[t]);
        }
    }
    for (t = 0; t < 2; t++)
        free(under[t]);
    atrbvh_bvh_free(emb.bvh);
    atrbvh_bvh_free(ours);
    embree_close(ectx);
    scene_free(&sc);
    return 0;
}
