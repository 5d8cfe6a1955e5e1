/*
 * cpu/backend.c - the CPU backend's table: a build's arrays live in the
 * device's scratch (kept between builds), the stages are the OpenMP files
 * beside this one.  Ray batches run the OpenMP queries of lib/traverse.c.
 */
#include "config.h"

#include "cpu.h"

#include <string.h>

#define NO_INDEX ((uint64_t)-1)

static atrbvh_status cpu_open(atrbvh_device *dev, const char *spec,
                              atrbvh_error *error)
{
    atrbvh_i_cpu_device *d;
    if (spec && *spec)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "the CPU device takes no name (got \"%s\")",
                             spec);
    d = atrbvh_i_malloc(sizeof *d);
    if (!d)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate the CPU device's state");
    memset(d, 0, sizeof *d);
    dev->impl = d;
    strcpy(dev->name, "cpu");
    return ATRBVH_OK;
}

static void cpu_close(atrbvh_device *dev)
{
    atrbvh_i_free(dev->impl);
    dev->impl = NULL;
}

/* The memory plan of a build of up to n primitives, in bytes per
 * primitive (a box is 24 bytes, the output 32 per node plus 4 per
 * primitive, about 35-39 with max leaf 8):
 *
 *   stage      live                                            LBVH  TRBVH
 *   bounds     primitive boxes, in the node box array (its
 *              slot reserved for 2n-1 boxes; for an LBVH n +
 *              3072, below)                                      24     48
 *   morton     + keys, in the cost slot (reserved: n keys for
 *              an LBVH, 2n-1 costs otherwise)                    32     64
 *   sort       + order 4, sort temporaries 12 in the parent
 *              and left slots, count 8 (its buckets' phase
 *              gathers the leaf boxes - not an LBVH's - and
 *              writes the deltas for the hierarchy, sort.c)      56     88
 *   hierarchy  + left, right 8, parent 8, count 8 (leaf_prim is
 *              the order array); the refit in the same pass
 *              (hierarchy.c): node boxes 48 (the primitive boxes
 *              gathered in place into the leaves; an LBVH reads
 *              them in place and writes none), costs 16 (none
 *              for an LBVH: its slot takes the collapse sizes),
 *              both into the slot of the keys once read; for a
 *              tree to optimise the collapse decisions 2 (their
 *              own slot, CPU_FLAT)                               60     94
 *   refit      (nothing left to compute; a caller's tree,
 *              set_tree, is refitted here, without decisions:
 *              92) tree 28                                       60     94
 *   optimise   the same, per-thread treelet scratch, marks and
 *              lists (about 5; a transient scratch frees them
 *              when the stage ends)                               -     99
 *   collapse   sizes 8 into the cost slot, counted from the
 *              decisions, which are then freed (a caller's tree:
 *              decided from recomputed costs)                    60     94
 *   layout     tree 28, the output; an LBVH's node boxes were
 *              released at the end of the collapse (the layout
 *              recomputes them; when in place, the slot's block
 *              became the output's nodes: collapse.c, below), and
 *              its parent links (the
 *              hierarchy's tree needs none, layout.c) on a
 *              transient scratch, and its sizes are in the cost
 *              slot 8; an optimised tree's sizes moved into the
 *              leaves' half of the node boxes and the cost slot
 *              was freed (on a handle it stays: 92+out), and
 *              on a transient scratch its parent links too when
 *              its collapsed leaves are small (cpu.h's
 *              ATRBVH_I_GATHER_MAX: max leaf 1 to 64)       28+out 68+out
 *
 * Roles never live together share a slot, so what a device handle keeps
 * between builds is not more than the peak: the slots an LBVH's layout
 * still reads (about 36; the node box array, the largest, is released
 * before the output is allocated on every build, as a handle keeping it
 * would hold it beside the output).  A transient scratch frees each slot
 * when its last role is done, and all at the end of the layout.  With
 * kept ids (skip_invalid), leaf_prim and the ids take their own slots
 * (+8) and the node boxes are kept to the layout (layout.c).
 *
 * An LBVH's column is that of one without kept ids and of
 * ATRBVH_I_HIER_BY_ORDER_MIN primitives or more, which writes no leaf or
 * internal box (its hierarchy pass reads the primitive boxes in place:
 * hierarchy.c, cpu.h): its node box slot holds the n primitive boxes and
 * the pass's leftovers, at most 3072 more (atrbvh_i_node_boxes).  Its
 * peak is then the layout's, 28 + out (about 63-70 bytes per triangle
 * with max leaf 8; 71-78 on a handle, which keeps the parent links: 8
 * more); it was 84 and more at the hierarchy, where the slot held 2n-1
 * boxes, as it still does for kept ids, a caller's tree
 * (atrbvh_i_cpu_all_node_boxes) and fewer primitives (+24).
 *
 * That LBVH's node box slot is allocated with room for its output's
 * nodes, n of them or as many per primitive as the handle's last LBVH
 * made (32 bytes per primitive for most scenes, of which the bounds stage
 * writes 24), and the output's nodes take its block when they fill seven
 * eighths of it or more (collapse.c): the layout then writes into pages
 * the build already touched, not fresh ones the system must zero.  On a
 * handle's repeated builds the peak is the same; a first build's, or one
 * without a handle, is larger by what the block has to spare (1-5 bytes
 * per primitive: test_device's scenes). */
static void plan(atrbvh_i_scratch *s, const atrbvh_i_cpu_device *d,
                 size_t n, atrbvh_method method, int kept_ids)
{
    const size_t nodes = n ? 2 * n - 1 : 1;
    size_t boxes = n ? atrbvh_i_node_boxes(method, n, kept_ids) : nodes;
    atrbvh_i_scratch_plan_reset(s);
    atrbvh_i_scratch_share(s, CPU_BOXES, CPU_BOX);
    atrbvh_i_scratch_share(s, CPU_KEYS, CPU_COST);
    atrbvh_i_scratch_share(s, CPU_SIZE, CPU_COST);
    atrbvh_i_scratch_share(s, CPU_TMP_KEYS, CPU_PARENT);
    atrbvh_i_scratch_share(s, CPU_TMP_ORDER, CPU_LEFT);
    /* 2n-1 fits in size_t whenever n boxes did (the geometry's check).
     * An LBVH reading its leaf boxes in place: n + 3072 (cpu.h). */
    if (n && atrbvh_i_lbvh_in_place(method, n, kept_ids)) {
        /* Its block becomes the output's nodes (collapse.c): room for as
         * many per primitive as the handle's last LBVH output had (and
         * what the count's rounding dropped), else n (most scenes need
         * 0.9n to n with max leaf 8), as boxes (4 per 3 nodes) when that
         * is more than the slot needs (at most 2n - 1 nodes). */
        const uint64_t per = d && d->lbvh_nodes_per_1024
                                 ? d->lbvh_nodes_per_1024 + 1u
                                 : 1024u;
        uint64_t want = (uint64_t)n * per / 1024;
        if (want > nodes)
            want = nodes;
        want += (want + 2) / 3;
        if (want > boxes && want <= SIZE_MAX)
            boxes = (size_t)want;
    }
    atrbvh_i_scratch_reserve(s, CPU_BOX, boxes, sizeof(atrbvh_box));
    /* An LBVH keeps no costs: the slot takes the keys, then the sizes. */
    if (method == ATRBVH_METHOD_LBVH)
        atrbvh_i_scratch_reserve(s, CPU_COST, n ? n : 1, sizeof(uint64_t));
    else
        atrbvh_i_scratch_reserve(s, CPU_COST, nodes, sizeof(double));
}

static atrbvh_status cpu_begin(atrbvh_device *dev, atrbvh_i_run *run,
                               atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = atrbvh_i_malloc(sizeof *c);
    if (!c)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate the build state");
    memset(c, 0, sizeof *c);
    c->scratch = &dev->scratch;
    c->device = dev->impl;
    run->state = c;
    plan(c->scratch, c->device, run->in.g->primitive_count,
         run->cfg->method, 0);
    if (run->recycled_nodes) {
        /* atrbvh_rebuild: the old tree's nodes become the node box slot
         * when they hold its reserve (an LBVH of the same scene's: the
         * block then goes on to the new output, collapse.c).  Else, on a
         * handle, an optimised tree's output may take them (the pipeline):
         * its layout holds the handle's slots, about as much as the
         * stages before it (the plan above), so holding them that long
         * hardly raises the peak; otherwise they go now, as held to the
         * output they would raise the peak of those stages by their
         * size. */
        if (atrbvh_i_scratch_adopt(c->scratch, CPU_BOX, run->recycled_nodes,
                                   run->recycled_node_bytes))
            run->recycled_nodes = NULL;
        else if (c->scratch->transient ||
                 run->cfg->method == ATRBVH_METHOD_LBVH) {
            atrbvh_i_free(run->recycled_nodes);
            run->recycled_nodes = NULL;
        }
    }
    return ATRBVH_OK;
}

static void cpu_end(atrbvh_device *dev, atrbvh_i_run *run)
{
    atrbvh_i_cpu_run *c = run->state;
    (void)dev;
    if (c) /* (a build that stopped between morton and sort) */
        atrbvh_i_free(c->msd_counts);
    atrbvh_i_free(run->out_block); /* (the output did not take it) */
    run->out_block = NULL;
    atrbvh_i_free(run->state);
    run->state = NULL;
}

atrbvh_status atrbvh_i_cpu_all_node_boxes(atrbvh_i_cpu_run *c,
                                          atrbvh_i_run *run,
                                          atrbvh_error *error)
{
    const size_t nodes = 2 * (size_t)run->n - 1;
    if (!atrbvh_i_lbvh_in_place(run->cfg->method,
                                run->in.g->primitive_count, 0))
        return ATRBVH_OK; /* (planned so) */
    /* The slot's reserve only: plan() would forget which roles are live,
     * and the slot would then grow without the primitive boxes that the
     * bounds stage wrote (a live role's contents move along). */
    atrbvh_i_scratch_reserve(c->scratch, CPU_BOX, nodes, sizeof *c->boxes);
    c->boxes = atrbvh_i_scratch_get(c->scratch, CPU_BOX, nodes,
                                    sizeof *c->boxes);
    if (!c->boxes)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate %lu node boxes",
                             (unsigned long)nodes);
    atrbvh_i_scratch_done(c->scratch, CPU_BOX);
    return ATRBVH_OK;
}

static atrbvh_status cpu_set_prims(atrbvh_device *dev, atrbvh_i_run *run,
                                   const atrbvh_box *boxes,
                                   const uint32_t *ids, atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    (void)dev;
    if (run->n > run->in.g->primitive_count) {
        /* Split references: more than the plan was made for.  Plan again
         * for them and make the node box slot its new size now, before
         * c->boxes points into it (a slot growing later would move the
         * boxes under that pointer).  The references are copied below
         * from the pipeline's own array. */
        plan(c->scratch, c->device, run->n, run->cfg->method, ids != NULL);
        if (!atrbvh_i_scratch_get(c->scratch, CPU_BOX, 2 * (size_t)run->n - 1,
                                  sizeof(atrbvh_box)))
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                 "cannot allocate %lu node boxes",
                                 (unsigned long)(2 * (size_t)run->n - 1));
        atrbvh_i_scratch_done(c->scratch, CPU_BOX);
        c->boxes = NULL;
    } else if (ids) {
        /* Kept ids: the leaf boxes are gathered after all (cpu.h) */
        const int in_slot = boxes == c->boxes;
        const atrbvh_status st = atrbvh_i_cpu_all_node_boxes(c, run, error);
        if (st != ATRBVH_OK)
            return st;
        if (in_slot)
            boxes = c->boxes;
    }
    /* The pipeline's boxes may be the scratch the bounds stage wrote;
     * memmove keeps that case right.  Other boxes may be more than the
     * bounds stage's (split references): the slot grows. */
    if (boxes != c->boxes) {
        c->boxes = atrbvh_i_scratch_get(c->scratch, CPU_BOXES, run->n,
                                        sizeof *c->boxes);
        if (!c->boxes)
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                 "cannot allocate %lu primitive boxes",
                                 (unsigned long)run->n);
    }
    memmove(c->boxes, boxes, (size_t)run->n * sizeof *boxes);
    c->ids = NULL;
    c->kept_ids = ids != NULL;
    if (ids) {
        c->ids = atrbvh_i_scratch_get(c->scratch, CPU_IDS, run->n,
                                      sizeof *c->ids);
        if (!c->ids)
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                 "cannot allocate %lu kept primitive ids",
                                 (unsigned long)run->n);
        memcpy(c->ids, ids, (size_t)run->n * sizeof *ids);
    }
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cpu_tree_arrays(atrbvh_i_cpu_run *c, uint32_t n,
                                       atrbvh_error *error)
{
    atrbvh_i_scratch *s = c->scratch;
    atrbvh_i_tree *t = &c->tree;
    const size_t nodes = 2 * (size_t)n - 1, inner = n > 1 ? n - 1 : 1;
    t->n = n;
    /* The hierarchy stage comes after the morton stage; set_tree (a
     * caller's topology) has no keys. */
    c->ranges = c->keys != NULL;
    t->left = atrbvh_i_scratch_get(s, CPU_LEFT, inner, sizeof *t->left);
    t->right = atrbvh_i_scratch_get(s, CPU_RIGHT, inner, sizeof *t->right);
    t->parent = atrbvh_i_scratch_get(s, CPU_PARENT, nodes, sizeof *t->parent);
    t->count = atrbvh_i_scratch_get(s, CPU_COUNT, nodes, sizeof *t->count);
    t->box = NULL; /* atrbvh_i_cpu_tree_values (refit) */
    t->cost = NULL;
    /* Without kept ids leaf p's primitive is the sort's order[p]: the
     * same array. */
    t->leaf_prim = atrbvh_i_scratch_get(s, c->ids ? CPU_LEAF_PRIM : CPU_ORDER,
                                        n, sizeof *t->leaf_prim);
    if (!t->left || !t->right || !t->parent || !t->count || !t->leaf_prim)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate the tree for %lu primitives",
                             (unsigned long)n);
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cpu_tree_values(atrbvh_i_cpu_run *c, int costs,
                                       atrbvh_error *error)
{
    atrbvh_i_scratch *s = c->scratch;
    atrbvh_i_tree *t = &c->tree;
    /* (fewer for an LBVH that reads its leaf boxes in place: cpu.h) */
    const size_t nodes = c->leaf_boxes_by_order
                             ? (size_t)t->n + ATRBVH_I_HIER_LEFTOVERS
                             : 2 * (size_t)t->n - 1;
    t->box = atrbvh_i_scratch_get(s, CPU_BOX, nodes, sizeof *t->box);
    t->cost = costs ? atrbvh_i_scratch_get(s, CPU_COST, nodes, sizeof *t->cost)
                    : NULL;
    if (!t->box || (costs && !t->cost))
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate the node boxes and costs for "
                             "%lu primitives",
                             (unsigned long)t->n);
    /* The primitive boxes are the first n entries (moved along if the
     * slot had to grow). */
    c->boxes = t->box;
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cpu_tree_sizes(atrbvh_i_cpu_run *c,
                                      atrbvh_error *error)
{
    c->size = atrbvh_i_scratch_get(c->scratch, CPU_SIZE,
                                   2 * (size_t)c->tree.n - 1, sizeof *c->size);
    if (!c->size)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate the collapse sizes for %lu "
                             "primitives",
                             (unsigned long)c->tree.n);
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cpu_tree_flags(atrbvh_i_cpu_run *c,
                                      atrbvh_error *error)
{
    c->flat = atrbvh_i_scratch_get(c->scratch, CPU_FLAT,
                                   2 * (size_t)c->tree.n - 1, 1);
    if (!c->flat)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate the collapse decisions for "
                             "%lu primitives",
                             (unsigned long)c->tree.n);
    return ATRBVH_OK;
}

void atrbvh_i_cpu_scratch_end(atrbvh_i_cpu_run *c)
{
    unsigned k;
    if (!c->scratch->transient)
        return;
    for (k = 0; k < CPU_SLOTS; k++)
        atrbvh_i_scratch_release(c->scratch, k);
}

static atrbvh_status nomem(atrbvh_error *error)
{
    return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                         "cannot allocate the capture");
}

/* A copy of n items of `size` bytes into a new array at *dst. */
static int copy_out(void *dst_ptr, const void *src, size_t n, size_t size)
{
    void **dst = (void **)dst_ptr;
    *dst = atrbvh_i_alloc_array(n, size);
    if (!*dst)
        return 0;
    memcpy(*dst, src, n * size);
    return 1;
}

/* The tree after the refit (or the optimise stage, which an LBVH skips);
 * an LBVH's refit keeps no costs: the copy gets them as the refit
 * computes them (shared/stages.h), bottom-up.  `by_order`: the LBVH's
 * pass wrote no node box either (cpu.h, leaf_boxes_by_order): src->box
 * holds the primitive boxes, and the copy gets the boxes as the refit
 * computes them too: leaf i's is primitive leaf_prim[i]'s, a node's the
 * union of its children's, left first. */
static atrbvh_status capture_refit(atrbvh_i_tree *dst,
                                   const atrbvh_i_tree *src,
                                   const atrbvh_cost_params *p, int by_order)
{
    const size_t n = src->n, nodes = 2 * n - 1;
    uint8_t *arrived;
    size_t i;
    if (src->cost || !src->box)
        return atrbvh_i_tree_copy(dst, src, 1);
    if (atrbvh_i_tree_copy(dst, src, 0) != ATRBVH_OK)
        return ATRBVH_ERR_NOMEM;
    dst->box = atrbvh_i_alloc_array(nodes, sizeof *dst->box);
    dst->cost = atrbvh_i_alloc_array(nodes, sizeof *dst->cost);
    arrived = atrbvh_i_alloc_array(nodes, 1);
    if (!dst->box || !dst->cost || !arrived) {
        atrbvh_i_free(arrived);
        atrbvh_i_tree_free(dst);
        return ATRBVH_ERR_NOMEM;
    }
    /* (by_order: src->box holds n + 3072 boxes, and every one of dst's
     * is computed below) */
    if (!by_order)
        memcpy(dst->box, src->box, nodes * sizeof *dst->box);
    memset(arrived, 0, nodes);
    for (i = n - 1; i < nodes; i++) {
        uint32_t node = (uint32_t)i, up;
        if (by_order)
            dst->box[i] = src->box[src->leaf_prim[i - (n - 1)]];
        dst->cost[i] = atrbvh_refit_leaf_cost(p, dst->box[i]);
        while ((up = dst->parent[node]) != ATRBVH_U32_MAX &&
               arrived[up]++ == 1) {
            const uint32_t l = dst->left[up], r = dst->right[up];
            int collapsed;
            if (by_order)
                dst->box[up] = atrbvh_box_union(dst->box[l], dst->box[r]);
            dst->cost[up] = atrbvh_node_cost(
                p, atrbvh_box_area(dst->box[up]), dst->count[up],
                dst->cost[l], dst->cost[r], &collapsed);
            node = up;
        }
    }
    atrbvh_i_free(arrived);
    return ATRBVH_OK;
}

static atrbvh_status cpu_capture(atrbvh_device *dev, atrbvh_i_run *run,
                                 atrbvh_stage stage, atrbvh_i_capture *cap,
                                 atrbvh_error *error)
{
    const atrbvh_i_cpu_run *c = run->state;
    size_t n = run->n;
    int ok = 1;
    (void)dev;
    switch (stage) {
    case ATRBVH_STAGE_BOUNDS:
        cap->n = run->n;
        cap->scene = run->scene;
        cap->centroids = run->centroids;
        ok = copy_out(&cap->prim_boxes, c->boxes, n, sizeof *c->boxes);
        break;
    case ATRBVH_STAGE_MORTON:
        ok = copy_out(&cap->keys, c->keys, n, sizeof *c->keys);
        break;
    case ATRBVH_STAGE_SORT:
        ok = copy_out(&cap->sorted_keys, c->keys, n, sizeof *c->keys) &&
             copy_out(&cap->order, c->order, n, sizeof *c->order);
        break;
    case ATRBVH_STAGE_HIERARCHY:
        ok = atrbvh_i_tree_copy(&cap->hierarchy, &c->tree, 0) == ATRBVH_OK;
        break;
    case ATRBVH_STAGE_REFIT:
        ok = capture_refit(&cap->refit, &c->tree, &run->cfg->cost,
                           c->leaf_boxes_by_order) == ATRBVH_OK;
        break;
    case ATRBVH_STAGE_OPTIMISE:
        ok = capture_refit(&cap->optimise, &c->tree, &run->cfg->cost,
                           c->leaf_boxes_by_order) == ATRBVH_OK;
        break;
    case ATRBVH_STAGE_COLLAPSE:
        if (c->flat) {
            /* every node's (count_out leaves those below a collapsed
             * one), from the decisions (kept for it: layout.c) */
            cap->collapse_size = atrbvh_i_sizes_counted(
                c->tree.left, c->tree.right, c->flat, run->n);
            ok = cap->collapse_size != NULL;
        } else {
            ok = copy_out(&cap->collapse_size, c->size, 2 * n - 1,
                          sizeof *c->size);
        }
        break;
    default:
        break;
    }
    return ok ? ATRBVH_OK : nomem(error);
}

const atrbvh_i_backend atrbvh_i_cpu_backend = {
    "cpu",
    ATRBVH_BACKEND_CPU,
    cpu_open,
    cpu_close,
    cpu_begin,
    cpu_end,
    {atrbvh_i_cpu_bounds, atrbvh_i_cpu_morton, atrbvh_i_cpu_sort,
     atrbvh_i_cpu_hierarchy, atrbvh_i_cpu_refit, atrbvh_i_cpu_optimise,
     atrbvh_i_cpu_collapse, atrbvh_i_cpu_layout},
    cpu_set_prims,
    cpu_capture,
    NULL, /* trace: lib/traverse.c's OpenMP queries */
    NULL, /* kernel_time: none */
    atrbvh_i_cpu_set_tree
};
