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

int main(void)
{
    Suite *s = suite_create("collapse");
    TCase *tc = tcase_create("collapse");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, matches_exhaustive_search);
    tcase_add_test(tc, never_raises_sah);
    suite_add_tcase(s, tc);
    return tu_run(s);
}
