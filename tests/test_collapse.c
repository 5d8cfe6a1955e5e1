/*
 * test_collapse.c - collapsing leaves by SAH never raises the cost, respects
 * the maximum leaf size, and finds the cheapest of ALL the trees obtainable
 * by collapsing subtrees of the binary tree, checked by enumerating every cut
 * explicitly on small trees.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "shared/arith.h" /* atrbvh_node_cost: the rule itself */

/* The collapse stage's size of a node emitted as a leaf (lib/shared's
 * ATRBVH_SIZE_LEAF, a flag over the subtree's output node count). */
#define SIZE_LEAF 0x80000000u
#define SIZE_MASK 0x7fffffffu

static long double area(const atrbvh_node *n)
{
    long double dx = (long double)n->max[0] - n->min[0],
                dy = (long double)n->max[1] - n->min[1],
                dz = (long double)n->max[2] - n->min[2];
    return 2.0L * (dx * dy + dy * dz + dz * dx);
}

/* Every way to cut the binary subtree at `i`, as a list of unnormalised
 * costs (ci * internal areas + ct * leaf area * count).  Returns the number
 * of options written to out (grows with the product of the children's). */
typedef struct opt {
    long double cost;
    unsigned prims;
} opt;

static size_t cuts(const atrbvh_node *nodes, size_t i, long double ci,
                   long double ct, unsigned max_leaf, opt **out)
{
    const atrbvh_node *n = &nodes[i];
    opt *l, *r, *res;
    size_t nl, nr, a, b, k = 0;
    if (n->count) {
        *out = malloc(sizeof **out);
        (*out)[0].cost = ct * area(n) * n->count;
        (*out)[0].prims = n->count;
        return 1;
    }
    nl = cuts(nodes, i + 1, ci, ct, max_leaf, &l);
    nr = cuts(nodes, n->index, ci, ct, max_leaf, &r);
    res = malloc(sizeof *res * (nl * nr + 1));
    for (a = 0; a < nl; a++)
        for (b = 0; b < nr; b++) {
            res[k].cost = ci * area(n) + l[a].cost + r[b].cost;
            res[k].prims = l[a].prims + r[b].prims;
            k++;
        }
    /* Or the whole subtree as one leaf. */
    if (max_leaf == 0 || res[0].prims <= max_leaf) {
        res[k].cost = ct * area(n) * res[0].prims;
        res[k].prims = res[0].prims;
        k++;
    }
    free(l);
    free(r);
    *out = res;
    return k;
}

static void exhaustive(size_t t, uint64_t seed, double ci, double ct,
                       unsigned max_leaf, int identical)
{
    float *v = tu_random_triangles(t, seed, 1.0f, 0.0f);
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_bvh *bin, *col;
    atrbvh_stats sb, sc;
    const atrbvh_node *nodes;
    opt *all;
    size_t n, i;
    long double best = INFINITY, root;
    char msg[256];
    if (identical)
        for (i = 1; i < t; i++)
            memcpy(&v[9 * i], v, 9 * sizeof *v);
    g = atrbvh_geometry_triangles(v, 3 * t, NULL, t);
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    o.ci = ci;
    o.ct = ct;
    o.collapse = 0;
    bin = tu_build(&g, &o);
    o.collapse = 1;
    o.max_leaf_size = max_leaf;
    col = tu_build(&g, &o);
    ck_assert_msg(tu_check_bvh(col, &g, msg, sizeof msg), "%s", msg);
    atrbvh_bvh_stats(bin, &sb);
    atrbvh_bvh_stats(col, &sc);
    nodes = atrbvh_bvh_nodes(bin, NULL);
    n = cuts(nodes, 0, ci, ct, max_leaf, &all);
    for (i = 0; i < n; i++)
        if (all[i].cost < best)
            best = all[i].cost;
    root = area(&nodes[0]);
    if (root > 0)
        best /= root;
    else
        best = 0;
    ck_assert_msg(fabsl(best - sc.sah) <= 1e-9L * (best > 1 ? best : 1),
                  "%zu triangles (seed %lu, max leaf %u): collapsed SAH %.17g, "
                  "best of %zu cuts %.17Lg",
                  t, (unsigned long)seed, max_leaf, sc.sah, n, best);
    ck_assert_msg(sc.sah <= sb.sah * (1 + 1e-12), "collapse raised the SAH");
    if (max_leaf)
        ck_assert_uint_le(sc.max_leaf_primitives, max_leaf);
    free(all);
    atrbvh_bvh_free(bin);
    atrbvh_bvh_free(col);
    free(v);
}

START_TEST(matches_exhaustive_search)
{
    size_t t;
    uint64_t seed;
    for (t = 1; t <= 14; t++)
        for (seed = 0; seed < 12; seed++) {
            exhaustive(t, seed, 1.2, 1.0, 0, 0);
            exhaustive(t, seed, 1.2, 1.0, 3, 0);
            exhaustive(t, seed, 0.3, 2.0, 0, 0); /* collapsing rarely pays */
            exhaustive(t, seed, 5.0, 0.5, 4, 0); /* collapsing often pays */
        }
    /* Identical triangles: one leaf is best when allowed. */
    exhaustive(9, 1, 1.2, 1.0, 0, 1);
    exhaustive(9, 1, 1.2, 1.0, 2, 1);
}
END_TEST

START_TEST(never_raises_sah)
{
    static const unsigned leaves[] = {0, 1, 2, 4, 8, 16};
    atrbvh_method m;
    size_t li;
    float *v = tu_random_triangles(20000, 4, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 60000, NULL, 20000);
    for (m = ATRBVH_METHOD_LBVH; m <= ATRBVH_METHOD_ATRBVH; m++) {
        atrbvh_build_options o;
        atrbvh_bvh *bin, *col;
        atrbvh_stats sb, sc;
        atrbvh_build_options_init(&o);
        o.method = m;
        o.collapse = 0;
        bin = tu_build(&g, &o);
        atrbvh_bvh_stats(bin, &sb);
        for (li = 0; li < sizeof leaves / sizeof *leaves; li++) {
            char msg[256];
            o.collapse = 1;
            o.max_leaf_size = leaves[li];
            col = tu_build(&g, &o);
            ck_assert_msg(tu_check_bvh(col, &g, msg, sizeof msg), "%s", msg);
            atrbvh_bvh_stats(col, &sc);
            /* For LBVH the topology is the same, so this is exact; the
             * optimisers restructure against the collapsed cost, so their
             * collapsed tree must be no worse than their binary one. */
            ck_assert_msg(sc.sah <= sb.sah * (1 + 1e-12),
                          "method %d max leaf %u: %.9g > %.9g", (int)m,
                          leaves[li], sc.sah, sb.sah);
            if (leaves[li])
                ck_assert_uint_le(sc.max_leaf_primitives, leaves[li]);
            if (leaves[li] == 1)
                ck_assert_uint_eq(sc.nodes, sb.nodes);
            atrbvh_bvh_free(col);
        }
        atrbvh_bvh_free(bin);
    }
    free(v);
}
END_TEST

/* ------------------------------------------ an optimised tree's decisions */
/* The optimise stage's final tree and the collapse stage's sizes, as a
 * build's capture gives them. */
typedef struct captured {
    size_t nodes;
    uint32_t *left, *right, *count, *size;
    atrbvh_box *box;
    double *cost;
} captured;

static void *copy_of(const atrbvh_array *a, size_t item)
{
    void *p = malloc(a->rows * a->cols * item);
    ck_assert(p != NULL);
    memcpy(p, a->data, a->rows * a->cols * item);
    return p;
}

static int keep_stages(const atrbvh_stage_output *o, void *user)
{
    captured *c = user;
    size_t k;
    for (k = 0; k < o->array_count; k++) {
        const atrbvh_array *a = &o->arrays[k];
        if (o->stage == ATRBVH_STAGE_OPTIMISE && o->round == 0) {
            if (!strcmp(a->name, "left"))
                c->left = copy_of(a, 4);
            else if (!strcmp(a->name, "right"))
                c->right = copy_of(a, 4);
            else if (!strcmp(a->name, "count")) {
                c->count = copy_of(a, 4);
                c->nodes = a->rows;
            } else if (!strcmp(a->name, "box"))
                c->box = copy_of(a, 4);
            else if (!strcmp(a->name, "cost"))
                c->cost = copy_of(a, 8);
        } else if (o->stage == ATRBVH_STAGE_COLLAPSE &&
                   !strcmp(a->name, "collapse_size")) {
            c->size = copy_of(a, 4);
        }
    }
    return 0;
}

/* Node x's size decided from the captured costs, as a collapse stage that
 * keeps nothing decides it (every node, also below a collapsed one). */
static uint32_t decided_size(const captured *c, const atrbvh_cost_params *p,
                             uint32_t x, uint32_t *out)
{
    const size_t inner = (c->nodes - 1) / 2;
    uint32_t l, r, sl, sr;
    int collapsed;
    if (x >= inner)
        return out[x] = 1u | SIZE_LEAF;
    l = c->left[x];
    r = c->right[x];
    sl = decided_size(c, p, l, out);
    sr = decided_size(c, p, r, out);
    (void)atrbvh_node_cost(p, atrbvh_box_area(c->box[x]), c->count[x],
                           c->cost[l], c->cost[r], &collapsed);
    return out[x] = collapsed ? 1u | SIZE_LEAF
                              : 1u + (sl & SIZE_MASK) + (sr & SIZE_MASK);
}

/* The collapse stage of an optimised build counts its sizes from the
 * decisions the hierarchy made and the optimise stage kept through every
 * refresh and write-back (lib/cpu/collapse.c): every node's must be the
 * one decided from the optimised tree's costs.  Triangles, and boxes of
 * a few coincident points (zero areas: ties between the leaf and the
 * subtree cost, which keep the subtree); every treelet path (TRBVH, the
 * ATRBVH lanes, its large treelets, the adaptive sizes), leaf limits and
 * costs that collapse more or less, one and two threads. */
START_TEST(optimised_decisions_are_the_costs)
{
    static const struct {
        atrbvh_method method;
        unsigned size, rounds, max_leaf;
        double ct;
    } cfg[] = {
        {ATRBVH_METHOD_TRBVH, 7, 3, 8, 1.0},
        {ATRBVH_METHOD_ATRBVH, 9, 2, 8, 1.0},
        {ATRBVH_METHOD_ATRBVH, 48, 2, 8, 1.0},
        {ATRBVH_METHOD_ATRBVH, ATRBVH_TREELET_AUTO, 4, 8, 1.0},
        {ATRBVH_METHOD_ATRBVH, 9, 2, 0, 0.3},
        {ATRBVH_METHOD_TRBVH, 5, 2, 2, 4.0},
    };
    const size_t n = 20000;
    float *v = tu_random_triangles(n, 11, 1.0f, 0.0f);
    float *b = malloc(n * 6 * sizeof *b);
    size_t ci, gi, i;
    int threads;
    ck_assert(v && b);
    for (i = 0; i < n; i++) {
        /* 1400 places, each with points (a third: zero areas, ties) and
         * small boxes */
        const float x = (float)(i % 40), y = (float)(i % 7) * 0.5f,
                    z = (float)(i % 5) * 0.25f,
                    h = i % 3 == 0 ? 0.0f : 0.05f + 0.01f * (float)(i % 4);
        b[6 * i] = x - h;
        b[6 * i + 1] = y - h;
        b[6 * i + 2] = z - h;
        b[6 * i + 3] = x + h;
        b[6 * i + 4] = y + h;
        b[6 * i + 5] = z + h;
    }
    for (gi = 0; gi < 2; gi++) {
        const atrbvh_geometry g =
            gi == 0 ? atrbvh_geometry_triangles(v, 3 * n, NULL, n)
                    : atrbvh_geometry_boxes(b, n);
        for (ci = 0; ci < sizeof cfg / sizeof *cfg; ci++)
            for (threads = 1; threads <= 2; threads++) {
                atrbvh_build_options o;
                atrbvh_cost_params p;
                captured c;
                atrbvh_bvh *bvh;
                uint32_t *ref;
                size_t k, collapsed = 0;
                memset(&c, 0, sizeof c);
                atrbvh_build_options_init(&o);
                o.method = cfg[ci].method;
                o.treelet_size = cfg[ci].size;
                o.rounds = cfg[ci].rounds;
                o.max_leaf_size = cfg[ci].max_leaf;
                o.ct = cfg[ci].ct;
                o.threads = threads;
                o.capture = keep_stages;
                o.capture_user = &c;
                bvh = tu_build(&g, &o);
                ck_assert(c.left && c.right && c.count && c.box && c.cost &&
                          c.size);
                ck_assert_uint_eq(c.nodes, 2 * n - 1);
                p.ci = o.ci;
                p.ct = o.ct;
                p.collapse = 1;
                p.max_leaf = o.max_leaf_size;
                ref = malloc(c.nodes * sizeof *ref);
                ck_assert(ref != NULL);
                (void)decided_size(&c, &p, 0, ref);
                for (k = 0; k < c.nodes; k++) {
                    ck_assert_msg(ref[k] == c.size[k],
                                  "geometry %u config %u threads %d node "
                                  "%u: size %08x, decided %08x",
                                  (unsigned)gi, (unsigned)ci, threads,
                                  (unsigned)k, c.size[k], ref[k]);
                    collapsed += k < c.nodes / 2 && (ref[k] & SIZE_LEAF) != 0;
                }
                /* (the decisions tested go both ways) */
                ck_assert_uint_gt(collapsed, 0);
                ck_assert_uint_lt(collapsed, c.nodes / 2);
                free(ref);
                free(c.left);
                free(c.right);
                free(c.count);
                free(c.box);
                free(c.cost);
                free(c.size);
                atrbvh_bvh_free(bvh);
            }
    }
    free(b);
    free(v);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("collapse");
    TCase *tc = tcase_create("collapse");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, matches_exhaustive_search);
    tcase_add_test(tc, never_raises_sah);
    tcase_add_test(tc, optimised_decisions_are_the_costs);
    suite_add_tcase(s, tc);
    return tu_run(s);
}
