/*
 * cpu/cpu.h - the CPU backend: what its stage files share.  Each stage
 * file holds only the OpenMP mapping of its stage; the per-item
 * arithmetic is lib/shared/'s.  Like every backend it sees lib/ through
 * backend.h alone.
 */
#ifndef ATRBVH_CPU_H
#define ATRBVH_CPU_H

#include "backend.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* Internal nodes 0 .. n-2, leaves n-1 .. 2n-2 (atrbvh_i_tree). */
static inline int atrbvh_i_is_leaf(const atrbvh_i_tree *t, uint32_t node)
{
    return node >= t->n - 1;
}

/* An LBVH whose hierarchy pass reads the leaf boxes where they are
 * (leaf_boxes_by_order, below) keeps its pass's leftovers' subtree boxes
 * after the n primitive boxes in the node box array: at most 16 blocks x
 * 2 x 96 of them (hierarchy.c checks it).  It takes at least one more
 * primitive than that, so that they fit in 2n-1 boxes too. */
#define ATRBVH_I_HIER_LEFTOVERS 3072u
#define ATRBVH_I_HIER_BY_ORDER_MIN (ATRBVH_I_HIER_LEFTOVERS + 1u)

/* The optimise, collapse and layout stages on the threads: a "top" of the
 * tree's nodes of more than a cut of primitives, the subtrees just below
 * it (the frontier) in one dynamic parallel loop, then the top on the
 * calling thread.  The cut leaves about ATRBVH_I_FRONTIER_PER_THREAD
 * subtrees per thread for the loop's balance; a frontier longer than
 * ATRBVH_I_FRONTIER_CAP_PER_THREAD per thread (a degenerate tree) runs on
 * one thread, with the same result. */
#define ATRBVH_I_FRONTIER_PER_THREAD 32u
#define ATRBVH_I_FRONTIER_CAP_PER_THREAD 512u

static inline uint32_t atrbvh_i_frontier_cut(uint32_t count, int threads)
{
    return (uint32_t)((uint64_t)count /
                      ((uint64_t)ATRBVH_I_FRONTIER_PER_THREAD *
                       (uint64_t)threads));
}

static inline size_t atrbvh_i_frontier_cap(int threads)
{
    return (size_t)ATRBVH_I_FRONTIER_CAP_PER_THREAD * (size_t)threads;
}

/* Leaf i of the in-place gather: the primitive boxes are entries 0 .. n-1
 * of box, leaf n-1+i takes box[order[i]]; entry n-1 is both a primitive
 * and leaf 0, so the caller reads it (`last`) before any leaf is
 * written.  The reads are random: the box 16 leaves ahead is fetched. */
static inline void atrbvh_i_gather_leaf(atrbvh_box *box,
                                        const uint32_t *order, int64_t n,
                                        int64_t i, const atrbvh_box *last)
{
    const uint32_t k = order[i];
#if defined(__GNUC__) || defined(__clang__)
    if (i + 16 < n)
        __builtin_prefetch(&box[order[i + 16]]);
#endif
    box[n - 1 + i] = k == (uint32_t)(n - 1) ? *last : box[k];
}

/* Scratch slots of the device (atrbvh_i_scratch_get) a build uses. */
enum {
    CPU_BOXES,     /* n primitive boxes, build order        */
    CPU_IDS,       /* n kept primitive ids (skip_invalid)    */
    CPU_KEYS,      /* n Morton keys                          */
    CPU_ORDER,     /* n build indices, sorted with the keys  */
    CPU_TMP_KEYS,  /* sort scratch                           */
    CPU_TMP_ORDER,
    CPU_LEFT,      /* the tree (atrbvh_i_tree)               */
    CPU_RIGHT,
    CPU_PARENT,
    CPU_COUNT,
    CPU_BOX,
    CPU_COST,
    CPU_LEAF_PRIM,
    CPU_SIZE,      /* collapse: output nodes per subtree     */
    CPU_OPTIMISE,  /* treelet scratch, per thread            */
    CPU_WORKERS,   /* per-thread treelet counters            */
    CPU_FLAT,      /* an optimised tree's collapse decisions */
    CPU_SLOTS
};
ATRBVH_STATIC_ASSERT(CPU_SLOTS <= ATRBVH_I_SCRATCH_LIB, cpu_slots_fit);

/* The CPU backend's part of a device handle (dev->impl; NULL on the
 * temporary device of a build without a handle, which keeps nothing). */
typedef struct atrbvh_i_cpu_device {
    /* an LBVH's output nodes per 1024 primitives, the handle's last
     * LBVH's (0: none yet): the size of the node box slot that the next
     * one's output takes (backend.c's plan, collapse.c) */
    uint32_t lbvh_nodes_per_1024;
} atrbvh_i_cpu_device;

/* One build on the CPU (run->state). */
typedef struct atrbvh_i_cpu_run {
    atrbvh_i_scratch *scratch;
    atrbvh_i_cpu_device *device; /* NULL: a temporary device */
    atrbvh_box *boxes;  /* bounds (or set_prims)             */
    uint32_t *ids;      /* NULL: every input primitive kept  */
    int kept_ids; /* set_prims gave ids (skip_invalid, split): a leaf's
                     box is then kept, not recomputed (collapse.c) */
    uint64_t *keys;     /* morton, sorted by sort            */
    uint64_t key_varying; /* morton: bits where keys differ  */
    /* morton: the sort's MSD digit counts (blocks x 2^bits, block-major;
     * NULL: none), counted on its guess of the digit (morton.c); the
     * sort stage uses them when the keys' digit is that guess, and frees
     * them (else cpu_end does) */
    uint32_t *msd_counts;
    uint32_t msd_blocks, msd_shift, msd_bits;
    /* sort: the leaves of the node box array gathered in sorted order,
     * and the deltas in the leaves' half of the count array (sort.c's
     * sort_leaves); 0: the hierarchy stage does it */
    int leaves_ready;
    /* sort, with leaves_ready: the leaves' boxes were not gathered; the
     * hierarchy pass of this LBVH (atrbvh_i_lbvh_in_place) reads leaf
     * i's box at its primitive's, box[order[i]], and writes no node box:
     * the node box array, n + ATRBVH_I_HIER_LEFTOVERS boxes, keeps the
     * primitive boxes in its first n entries and the pass's leftovers
     * after them (hierarchy.c).  Nothing reads an LBVH's node boxes
     * afterwards (the layout recomputes them) but the capture of the
     * refit stage, which builds them (backend.c). */
    int leaf_boxes_by_order;
    uint32_t *order;    /* sort: build index of position p   */
    atrbvh_i_tree tree; /* hierarchy ... optimise            */
    uint32_t *size;     /* collapse                          */
    /* hierarchy ... collapse: each node's collapse decision (1: emitted
     * as a leaf when reached), kept exact by the optimise stage, from
     * which the collapse stage only counts the sizes (collapse.c); NULL
     * for an LBVH and a caller's tree (set_tree) */
    unsigned char *flat;
    /* collapse: the sizes moved into the leaves' half of tree.box, whose
     * boxes the layout then recomputes (layout.c) */
    int sizes_in_leaf_boxes;
    /* The hierarchy stage's tree, not (yet) restructured: every subtree
     * holds the leaves of a contiguous range of sorted positions, in
     * order, so a node's primitives start at its output prim_at
     * (layout.c).  Not so for set_tree's or an optimised tree. */
    int ranges;
    /* The hierarchy stage refitted its tree in the same pass
     * (hierarchy.c): the refit stage has nothing to compute. */
    int refitted;
} atrbvh_i_cpu_run;

/* The most primitives of a collapsed leaf whose primitives the layout
 * finds without the parent links (layout.c's gather: each from the top by
 * the counts, so a leaf of c primitives costs at most c(c-1) steps).  A
 * build without a handle whose collapsed leaves are held to at most this
 * many (max_leaf 1 to 64, or no collapse) releases an optimised tree's
 * parent links after the collapse (collapse.c): 8 bytes per primitive
 * fewer at the layout, the peak. */
#define ATRBVH_I_GATHER_MAX 64u

/* Whether an LBVH of n primitives reads its leaf boxes in place
 * (leaf_boxes_by_order): the method LBVH, no kept ids, at least
 * ATRBVH_I_HIER_BY_ORDER_MIN primitives. */
static inline int atrbvh_i_lbvh_in_place(atrbvh_method method, size_t n,
                                         int kept_ids)
{
    return method == ATRBVH_METHOD_LBVH && !kept_ids &&
           n >= ATRBVH_I_HIER_BY_ORDER_MIN;
}

/* The boxes of the node box slot of a build of n >= 1 primitives: the n
 * primitive boxes and the hierarchy pass's leftovers for an LBVH that
 * reads its leaf boxes in place, else the 2n-1 nodes. */
static inline size_t atrbvh_i_node_boxes(atrbvh_method method, size_t n,
                                         int kept_ids)
{
    return atrbvh_i_lbvh_in_place(method, n, kept_ids)
               ? n + ATRBVH_I_HIER_LEFTOVERS
               : 2 * n - 1;
}

/* The tree's topology arrays for n leaves in the device's scratch slots
 * (the hierarchy stage and set_tree; leaf_prim is the order array unless
 * c->ids is set); box and cost stay NULL until tree_values (refit).  The
 * plan of which arrays share memory: backend.c. */
atrbvh_status atrbvh_i_cpu_tree_arrays(atrbvh_i_cpu_run *c, uint32_t n,
                                       atrbvh_error *error);
/* The node boxes (their slot already holds the primitive boxes in its
 * first n entries) and, with `costs`, the costs of c->tree (else NULL). */
atrbvh_status atrbvh_i_cpu_tree_values(atrbvh_i_cpu_run *c, int costs,
                                       atrbvh_error *error);
/* The collapse sizes of c->tree's nodes (c->size): the collapse stage's,
 * or an LBVH's refit, which computes them in its climb. */
atrbvh_status atrbvh_i_cpu_tree_sizes(atrbvh_i_cpu_run *c,
                                      atrbvh_error *error);
/* The collapse decisions of c->tree's nodes (c->flat): a tree to be
 * optimised, from the hierarchy stage's pass. */
atrbvh_status atrbvh_i_cpu_tree_flags(atrbvh_i_cpu_run *c,
                                      atrbvh_error *error);
/* The node box slot at 2n-1 boxes now, for a build planned as an LBVH
 * reading its leaf boxes in place (atrbvh_i_node_boxes) that will gather
 * them after all: kept ids (set_prims) or a caller's tree (set_tree).
 * The primitive boxes move along (c->boxes follows); the transient peak
 * is the bounds' boxes twice, before any other array of the build. */
atrbvh_status atrbvh_i_cpu_all_node_boxes(atrbvh_i_cpu_run *c,
                                          atrbvh_i_run *run,
                                          atrbvh_error *error);
/* After the layout: a transient scratch frees every slot of the build. */
void atrbvh_i_cpu_scratch_end(atrbvh_i_cpu_run *c);

/* The stages (backend.h's atrbvh_i_stage_fn). */
atrbvh_status atrbvh_i_cpu_bounds(atrbvh_device *, atrbvh_i_run *,
                                  atrbvh_error *);
/* The Morton keys of boxes lo .. hi-1 in the frame (lo, scale) into
 * keys[lo .. hi-1]: shared/arith.h's rule; with `vector`, eight at a
 * time where the CPU has AVX2 (the same bits). */
void atrbvh_i_morton_keys_with(const atrbvh_box *boxes, uint32_t lo,
                               uint32_t hi, const double lo3[3],
                               const double scale3[3], uint64_t *keys,
                               int vector);
atrbvh_status atrbvh_i_cpu_morton(atrbvh_device *, atrbvh_i_run *,
                                  atrbvh_error *);
atrbvh_status atrbvh_i_cpu_sort(atrbvh_device *, atrbvh_i_run *,
                                atrbvh_error *);
atrbvh_status atrbvh_i_cpu_hierarchy(atrbvh_device *, atrbvh_i_run *,
                                     atrbvh_error *);
atrbvh_status atrbvh_i_cpu_refit(atrbvh_device *, atrbvh_i_run *,
                                 atrbvh_error *);
atrbvh_status atrbvh_i_cpu_optimise(atrbvh_device *, atrbvh_i_run *,
                                    atrbvh_error *);
atrbvh_status atrbvh_i_cpu_collapse(atrbvh_device *, atrbvh_i_run *,
                                    atrbvh_error *);
atrbvh_status atrbvh_i_cpu_layout(atrbvh_device *, atrbvh_i_run *,
                                  atrbvh_error *);
/* backend.h's set_tree (lib/cpu/set_tree.c). */
atrbvh_status atrbvh_i_cpu_set_tree(atrbvh_device *, atrbvh_i_run *,
                                    const uint32_t *, const uint32_t *,
                                    const uint32_t *, atrbvh_error *);

/* The stages' algorithms, callable on plain arrays (tests use them). */
/* Stable radix sort of (keys, values) pairs; tmp_* are scratch of the
 * same length; the result ends in keys/values.  Passes whose digit is the
 * same for every key are skipped.  ATRBVH_ERR_NOMEM (nothing else) when
 * its counters cannot be had. */
atrbvh_status atrbvh_i_radix_sort(uint64_t *keys, uint32_t *values,
                                  uint64_t *tmp_keys, uint32_t *tmp_values,
                                  uint32_t n, int threads);
/* The blocks (contiguous ranges of atrbvh_block_range) of the Morton
 * sweep and the sort's MSD pass over n keys with `threads` threads: one
 * without threads to share them, else ATRBVH_I_BLOCKS_PER_THREAD a
 * thread (at most 256, at most n), which the threads take in turn
 * (dynamic): the master, which starts a region while a sleeping thread
 * is still waking (passive wait, the tool's; 20-70 us on this VM), takes
 * more of them meanwhile.  The sort's result is the same for any number
 * of blocks. */
#define ATRBVH_I_BLOCKS_PER_THREAD 4
uint32_t atrbvh_i_sort_blocks(uint32_t n, int threads);
/* Blocks for `threads` threads by that rule, at most `most`: one for a
 * single thread, else ATRBVH_I_BLOCKS_PER_THREAD a thread (the sort's
 * and the hierarchy's block passes). */
static inline int atrbvh_i_blocks_for(int threads, int most)
{
    return threads < 2 ? 1
           : threads > most / ATRBVH_I_BLOCKS_PER_THREAD
               ? most
               : threads * ATRBVH_I_BLOCKS_PER_THREAD;
}
/* The team of a region over `blocks` blocks: no more threads than
 * blocks, at least one. */
static inline int atrbvh_i_team(int blocks, int threads)
{
    return threads < 1 ? 1 : threads < blocks ? threads : blocks;
}
/* The same, told the bits where the keys differ (the OR of all keys XOR
 * their AND; a superset is also right, only slower). */
atrbvh_status atrbvh_i_radix_sort_varying(uint64_t *keys, uint32_t *values,
                                          uint64_t *tmp_keys,
                                          uint32_t *tmp_values, uint32_t n,
                                          int threads, uint64_t varying);
/* Karras 2012: topology from sorted keys (left, right, parent, and count
 * of internal nodes). */
void atrbvh_i_hierarchy(const uint64_t *sorted_keys, atrbvh_i_tree *t,
                        int threads);
/* The same tree refitted in the same pass (the hierarchy stage's):
 * t->box holds the primitive boxes in its first n entries (build order),
 * gathered in place into the leaves by `order`; then every node's box
 * and count, and its collapse size into `size` (2n-1 entries) or, when
 * `size` is NULL, its cost into t->cost: the values atrbvh_i_refit_sizes
 * (atrbvh_i_refit) gives.  sorted_keys is read first and may then take
 * the sizes or costs (the LBVH's memory plan, backend.c). */
void atrbvh_i_hierarchy_refit(const uint64_t *sorted_keys, atrbvh_i_tree *t,
                              const uint32_t *order,
                              const atrbvh_cost_params *p, int threads,
                              uint32_t *size);
/* Leaf n-1+p gets prim_boxes[order[p]], then boxes, counts and costs
 * bottom-up.  Sets every field but left/right/parent/leaf_prim (cost
 * only when t->cost is not NULL).  prim_boxes may be t->box: the
 * primitive boxes in its first n entries, gathered in place. */
void atrbvh_i_refit(atrbvh_i_tree *t, const atrbvh_box *prim_boxes,
                    const uint32_t *order, const atrbvh_cost_params *cost,
                    int threads);
/* The same without costs (t->cost NULL), and the collapse sizes of every
 * node into `size` (2n-1 entries; cpu/collapse.c's rule and arithmetic):
 * the LBVH's refit and collapse in one climb. */
void atrbvh_i_refit_sizes(atrbvh_i_tree *t, const atrbvh_box *prim_boxes,
                          const uint32_t *order, const atrbvh_cost_params *p,
                          int threads, uint32_t *size);
/* TRBVH or ATRBVH treelet restructuring in place; per-thread scratch from
 * slot CPU_OPTIMISE of `scratch`.  Progress by round through `run` (may
 * be NULL).  `flat`: every node's collapse decision, kept exact (NULL:
 * none kept, the collapse stage decides them). */
atrbvh_status atrbvh_i_optimise(atrbvh_i_tree *t, unsigned char *flat,
                                const atrbvh_i_config *cfg,
                                atrbvh_i_scratch *scratch, atrbvh_i_run *run,
                                atrbvh_error *error);

#endif
