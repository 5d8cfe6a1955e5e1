/*
 * trbvh.c - one TRBVH treelet on the CPU (Karras & Aila 2013, "Fast
 * Parallel Construction of High-Quality Bounding Volume Hierarchies",
 * HPG 2013): form, optimal topology by subset DP, write back if strictly
 * cheaper.  The arithmetic is shared/treelet.h's.
 */
#include "optimise.h"

int __atrbvh_trbvh_treelet(const atrbvh_treelet_tree *t,
                           const atrbvh_cost_params *p, uint32_t root,
                           unsigned n, __atrbvh_opt_worker *w)
{
    atrbvh_treelet tl;
    atrbvh_treelet_leaves lv;
    atrbvh_treelet_topo topo;
    double cost;
    w->treelets++;
    if (atrbvh_treelet_form(t, root, n, &tl) < 3u)
        return 0;
    atrbvh_treelet_gather(t, &tl, &lv);
    /* A quick reject: the DP's optimum is what evaluate recomputes (the
     * same sums in the same order), so nothing strictly cheaper exists
     * when the DP finds none. */
    if (!(atrbvh_trbvh_dp(p, tl.n, &lv, w->trbvh, &topo) < t->cost[root]))
        return 0;
    cost = atrbvh_treelet_evaluate(p, tl.n, &lv, &topo);
    if (!(cost < t->cost[root]))
        return 0;
    atrbvh_treelet_write(t, &tl, &topo);
    w->applied++;
    return 1;
}
