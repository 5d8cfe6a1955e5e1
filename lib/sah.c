/*
 * sah.c - the SAH cost of a node array (the slides' equation 1), measured
 * on the tree actually built, never an estimate.
 */
#include "config.h"

#include "internal.h"

double atrbvh_sah(const atrbvh_node *nodes, size_t node_count, double ci,
                  double ct)
{
    /* Summed in node order, serially: the same bits on every run. */
    double inner = 0.0, leaves = 0.0, root;
    size_t i;
    if (!nodes || node_count == 0)
        return 0.0;
    root = atrbvh_i_node_area(&nodes[0]);
    if (!(root > 0.0))
        return 0.0;
    for (i = 0; i < node_count; i++) {
        double a = atrbvh_i_node_area(&nodes[i]);
        if (nodes[i].count)
            leaves += a * (double)nodes[i].count;
        else
            inner += a;
    }
    return atrbvh_i_sah_total(ci, ct, inner, leaves, root);
}

