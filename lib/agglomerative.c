/*
 * agglomerative.c - one ATRBVH treelet on the CPU (Domingues & Pedrini
 * 2015, "Bounding Volume Hierarchy Optimization through Agglomerative
 * Treelet Restructuring", HPG 2015): form, greedy agglomerative
 * clustering with a cached distance matrix (Gu et al. 2013), write back
 * if strictly cheaper.  The arithmetic, and the sequence, is
 * shared/treelet.h's atrbvh_treelet_process, which the OpenCL kernel
 * calls too.
 */
#include "optimise.h"

int atrbvh_i_atrbvh_treelet(const atrbvh_treelet_tree *t,
                            const atrbvh_cost_params *p, uint32_t root,
                            unsigned n, atrbvh_i_opt_worker *w)
{
    int applied = atrbvh_treelet_process(t, p, root, n, 1, w->trbvh, w->dist);
    w->treelets++;
    w->applied += (uint64_t)applied;
    return applied;
}
