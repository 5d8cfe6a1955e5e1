/*
 * optimise.h - what the optimise stage's CPU files share (optimise.c, the
 * driver; trbvh.c and agglomerative.c, one treelet each).  Internal.
 */
#ifndef ATRBVH_OPTIMISE_H
#define ATRBVH_OPTIMISE_H

#include "internal.h"
#include "shared/treelet.h"

/* One thread's scratch, allocated once per build (never per treelet). */
typedef struct atrbvh_i_opt_worker {
    atrbvh_trbvh_scratch trbvh; /* 2^n entries each (TRBVH)             */
    double *dist;               /* n(n-1)/2 distances (ATRBVH)          */
    uint64_t treelets;          /* treelets processed                   */
    uint64_t applied;           /* of which restructured                */
} atrbvh_i_opt_worker;

/* Restructure the treelet rooted at internal node `root` (whose cost must
 * be current, as must everything below it).  Return 1 when the new
 * topology was strictly cheaper and written back, else 0 (tree
 * untouched). */
int atrbvh_i_trbvh_treelet(const atrbvh_treelet_tree *t,
                           const atrbvh_cost_params *p, uint32_t root,
                           unsigned n, atrbvh_i_opt_worker *w);
int atrbvh_i_atrbvh_treelet(const atrbvh_treelet_tree *t,
                            const atrbvh_cost_params *p, uint32_t root,
                            unsigned n, atrbvh_i_opt_worker *w);

#endif
