/*
 * agglomerative.c - one ATRBVH treelet on the CPU (Domingues & Pedrini
 * 2015, "Bounding Volume Hierarchy Optimization through Agglomerative
 * Treelet Restructuring", HPG 2015): form, greedy agglomerative
 * clustering with a cached distance matrix (Gu et al. 2013), write back
 * if strictly cheaper.  The arithmetic is shared/treelet.h's.
 */
#include "optimise.h"

int __atrbvh_atrbvh_treelet(const atrbvh_treelet_tree *t,
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
    /* The merge costs are atrbvh_node_cost over the same operands as
     * evaluate's, so the root's merge cost is the exact new cost. */
    if (!(atrbvh_agglomerate(p, tl.n, &lv, w->dist, &topo) < t->cost[root]))
        return 0;
    cost = atrbvh_treelet_evaluate(p, tl.n, &lv, &topo);
    if (!(cost < t->cost[root]))
        return 0;
    atrbvh_treelet_write(t, &tl, &topo);
    w->applied++;
    return 1;
}
