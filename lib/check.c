/*
 * check.c - the structural walk of a node array: the check used on load
 * and, with --enable-debug-checks, after every build; and the statistics
 * measured on the array built (depth, leaves, SAH).
 */
#include "config.h"

#include "internal.h"

#include <math.h>
#include <string.h>

/* Walks the depth-first array with an explicit stack of pending right
 * children; in a valid array the walk visits 0, 1, 2, ... in order.
 * `depth_out` receives the maximum depth. Returns ATRBVH_OK or a
 * description of the first violation. */
static atrbvh_status walk(const atrbvh_bvh *b, int check_boxes,
                          unsigned *depth_out, atrbvh_error *error)
{
    uint32_t *stack_node, *stack_depth, *parent_of;
    size_t sp = 0, next = 0;
    uint32_t cur = 0, depth = 0, max_depth = 0;
    atrbvh_status st = ATRBVH_OK;
    const size_t n = b->node_count;

    if (n == 0)
        return atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, (uint64_t)-1,
                             "the BVH has no nodes");
    stack_node = atrbvh_i_alloc_array(n, sizeof *stack_node);
    stack_depth = atrbvh_i_alloc_array(n, sizeof *stack_depth);
    parent_of = atrbvh_i_alloc_array(n, sizeof *parent_of);
    if (!stack_node || !stack_depth || !parent_of) {
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                           "cannot allocate %lu nodes of scratch",
                           (unsigned long)n);
        goto done;
    }
    parent_of[0] = ATRBVH_NONE;
    for (;;) {
        const atrbvh_node *nd;
        int k;
        if (cur != next) {
            st = atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, cur,
                               "node %lu is reached where node %lu was "
                               "expected (not a depth-first layout)",
                               (unsigned long)cur, (unsigned long)next);
            goto done;
        }
        next++;
        nd = &b->nodes[cur];
        for (k = 0; k < 3; k++) {
            if (!isfinite(nd->min[k]) || !isfinite(nd->max[k]) ||
                nd->min[k] > nd->max[k]) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, cur,
                                   "node %lu has an invalid box on axis %d",
                                   (unsigned long)cur, k);
                goto done;
            }
            if (check_boxes && parent_of[cur] != ATRBVH_NONE) {
                const atrbvh_node *pa = &b->nodes[parent_of[cur]];
                if (nd->min[k] < pa->min[k] || nd->max[k] > pa->max[k]) {
                    st = atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, cur,
                                       "node %lu sticks out of its parent "
                                       "%lu on axis %d",
                                       (unsigned long)cur,
                                       (unsigned long)parent_of[cur], k);
                    goto done;
                }
            }
        }
        if (depth > max_depth)
            max_depth = depth;
        if (nd->count == 0) {
            if ((size_t)cur + 1 >= n || nd->index <= cur + 1 ||
                nd->index >= n) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, cur,
                                   "internal node %lu has right child %lu "
                                   "out of range",
                                   (unsigned long)cur,
                                   (unsigned long)nd->index);
                goto done;
            }
            if (sp >= n) { /* cannot happen in a valid walk */
                st = atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, cur,
                                   "node %lu: the tree is deeper than its "
                                   "node count",
                                   (unsigned long)cur);
                goto done;
            }
            parent_of[cur + 1] = cur;
            parent_of[nd->index] = cur;
            stack_node[sp] = nd->index;
            stack_depth[sp++] = depth + 1;
            cur = cur + 1;
            depth++;
        } else {
            if (nd->index > b->prim_count ||
                nd->count > b->prim_count - nd->index) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, cur,
                                   "leaf %lu references primitives %lu..%lu "
                                   "of %lu",
                                   (unsigned long)cur,
                                   (unsigned long)nd->index,
                                   (unsigned long)nd->index + nd->count - 1,
                                   (unsigned long)b->prim_count);
                goto done;
            }
            if (sp == 0)
                break;
            cur = stack_node[--sp];
            depth = stack_depth[sp];
        }
    }
    if (next != n)
        st = atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, next,
                           "only %lu of %lu nodes are reachable from the "
                           "root",
                           (unsigned long)next, (unsigned long)n);
    *depth_out = max_depth;
done:
    atrbvh_i_free(stack_node);
    atrbvh_i_free(stack_depth);
    atrbvh_i_free(parent_of);
    return st;
}

/* The primitive indices of a built tree (debug builds, after stats are
 * measured): each below the input count, none listed twice - or, in a
 * split tree, none twice within one leaf and as many distinct ones as
 * the pipeline kept (every kept primitive referenced at least once). */
static atrbvh_status check_indices(const atrbvh_bvh *b, atrbvh_error *error)
{
    const size_t input = b->stats.primitives + b->stats.invalid_skipped;
    size_t i, distinct = 0;
    atrbvh_status st = ATRBVH_OK;
    uint32_t *stamp = atrbvh_i_alloc_array(input, sizeof *stamp);
    if (!stamp)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate %lu primitive stamps",
                             (unsigned long)input);
    memset(stamp, 0xff, input * sizeof *stamp);
    for (i = 0; i < b->node_count && st == ATRBVH_OK; i++) {
        const atrbvh_node *nd = &b->nodes[i];
        uint32_t j;
        for (j = 0; j < nd->count; j++) {
            const uint32_t p = b->prim_indices[nd->index + j];
            if (p >= input) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, i,
                                   "leaf %lu lists primitive %lu of %lu",
                                   (unsigned long)i, (unsigned long)p,
                                   (unsigned long)input);
                break;
            }
            if (stamp[p] != ATRBVH_NONE &&
                (!b->split_prims || stamp[p] == (uint32_t)i)) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, i,
                                   "leaf %lu lists primitive %lu, listed "
                                   "already by leaf %lu",
                                   (unsigned long)i, (unsigned long)p,
                                   (unsigned long)stamp[p]);
                break;
            }
            distinct += stamp[p] == ATRBVH_NONE;
            stamp[p] = (uint32_t)i;
        }
    }
    if (st == ATRBVH_OK && b->split_prims && distinct != b->split_prims)
        st = atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, (uint64_t)-1,
                           "the split tree lists %lu primitives, %lu were "
                           "kept",
                           (unsigned long)distinct,
                           (unsigned long)b->split_prims);
    atrbvh_i_free(stamp);
    return st;
}

atrbvh_status atrbvh_i_bvh_check(const atrbvh_bvh *b, int check_boxes,
                                 atrbvh_error *error)
{
    unsigned depth;
    atrbvh_status st = walk(b, check_boxes, &depth, error);
    size_t i, covered = 0;
    if (st != ATRBVH_OK)
        return st;
    for (i = 0; i < b->node_count; i++)
        covered += b->nodes[i].count;
    if (covered != b->prim_count)
        return atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, (uint64_t)-1,
                             "leaves hold %lu primitive slots, the index "
                             "array has %lu",
                             (unsigned long)covered,
                             (unsigned long)b->prim_count);
    /* In a depth-first layout the leaves' ranges tile the index array in
     * order; anything else means overlapping or missing slots. */
    covered = 0;
    for (i = 0; i < b->node_count; i++) {
        if (!b->nodes[i].count)
            continue;
        if (b->nodes[i].index != covered)
            return atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, i,
                                 "leaf %lu starts at primitive slot %lu, "
                                 "expected %lu",
                                 (unsigned long)i,
                                 (unsigned long)b->nodes[i].index,
                                 (unsigned long)covered);
        covered += b->nodes[i].count;
    }
    return check_indices(b, error);
}

atrbvh_status atrbvh_i_bvh_measure(atrbvh_bvh *b)
{
    unsigned depth = 0;
    size_t i, leaves = 0;
    unsigned largest = 0;
    atrbvh_status st = walk(b, 0, &depth, NULL);
    if (st != ATRBVH_OK)
        return st;
    for (i = 0; i < b->node_count; i++)
        if (b->nodes[i].count) {
            leaves++;
            if (b->nodes[i].count > largest)
                largest = b->nodes[i].count;
        }
    atrbvh_i_bvh_set_stats(b, leaves, depth, largest);
    return ATRBVH_OK;
}
