/*
 * trbvh.c - one TRBVH treelet on the CPU (Karras & Aila 2013, "Fast
 * Parallel Construction of High-Quality Bounding Volume Hierarchies",
 * HPG 2013): form, optimal topology by subset DP, write back if strictly
 * cheaper.  The arithmetic, and the sequence, is shared/treelet.h's
 * atrbvh_treelet_process, which the OpenCL kernel calls too.
 */
#include "optimise.h"

int atrbvh_i_trbvh_treelet(const atrbvh_treelet_tree *t,
                           const atrbvh_cost_params *p, uint32_t root,
                           unsigned n, atrbvh_i_opt_worker *w)
{
    int applied = atrbvh_treelet_process(t, p, root, n, 0, w->trbvh, w->dist);
    w->treelets++;
    w->applied += (uint64_t)applied;
    return applied;
}
