/*
 * bvh.c - the BVH object: lifetime, accessors, statistics and stage times,
 * and the device record of an OpenCL build.
 */
#include "config.h"

#include "internal.h"

#include <stdint.h>
#include <string.h>

/* Whether *block (bytes long) holds count entries of `size` bytes. */
static int holds(void *const *block, size_t bytes, size_t count, size_t size)
{
    return block && *block && count <= bytes / size;
}

/* *block for `count` entries of `size` bytes when it holds them (*block
 * then NULL), else a new array; its bytes into *got (0 on failure). */
static void *take_or_alloc(void **block, size_t bytes, size_t count,
                           size_t size, size_t *got)
{
    void *p;
    if (holds(block, bytes, count, size)) {
        p = *block;
        *block = NULL;
        *got = bytes;
        return p;
    }
    p = atrbvh_i_alloc_array(count, size);
    *got = p ? count * size : 0; /* (alloc_array checked the product) */
    return p;
}

atrbvh_bvh *atrbvh_i_bvh_alloc_in(size_t node_count, size_t prim_count,
                                  const atrbvh_i_blocks *blocks)
{
    static const atrbvh_i_blocks none;
    atrbvh_bvh *b = atrbvh_i_malloc(sizeof *b);
    if (!b)
        return NULL;
    memset(b, 0, sizeof *b);
    if (!blocks)
        blocks = &none;
    if (node_count) {
        void **nb = blocks->nodes;
        size_t nbytes = blocks->node_bytes, unused, room = node_count;
        if (!holds(nb, nbytes, node_count, sizeof *b->nodes)) {
            nb = blocks->nodes2;
            nbytes = blocks->node_bytes2;
            /* A rebuild whose old nodes are too few for this tree: room
             * for an eighth more, so that the next frames, whose node
             * counts move a little either way, find the array large
             * enough (atrbvh_reoptimise keeps room for the largest tree
             * for the same reason).  Without the room where the sum
             * would overflow. */
            if (nb && *nb && !holds(nb, nbytes, node_count, sizeof *b->nodes) &&
                node_count / 8u <= SIZE_MAX - node_count)
                room = node_count + node_count / 8u;
        }
        b->nodes = take_or_alloc(nb, nbytes, room, sizeof *b->nodes,
                                 &b->node_bytes);
        b->prim_indices = take_or_alloc(blocks->indices, blocks->index_bytes,
                                        prim_count, sizeof *b->prim_indices,
                                        &unused);
        if (!b->nodes || !b->prim_indices) {
            atrbvh_bvh_free(b);
            return NULL;
        }
        b->node_count = node_count;
        b->prim_count = prim_count;
    }
    return b;
}

atrbvh_bvh *atrbvh_i_bvh_alloc(size_t node_count, size_t prim_count)
{
    return atrbvh_i_bvh_alloc_in(node_count, prim_count, NULL);
}

/* The statistics with the SAH already summed (atrbvh_sah's value). */
static void set_stats_sah(atrbvh_bvh *b, size_t leaves, unsigned depth,
                          unsigned largest, double sah)
{
    b->stats.nodes = b->node_count;
    b->stats.leaves = leaves;
    /* a split tree references some primitives more than once */
    b->stats.primitives = b->split_prims ? b->split_prims : b->prim_count;
    b->stats.max_depth = depth;
    b->stats.max_leaf_primitives = largest;
    b->stats.sah = sah;
    b->stats.sah_built = sah; /* atrbvh_refit's drift reference */
}

/* Right children still to be reached in a walk of measure_built, at most
 * (a deeper tree is measured by the general walk, check.c). */
#define MEASURE_STACK 512
/* measure_built's subtrees: how many the top is cut into per thread (a
 * thread takes the next when done, so a few each evens out their sizes),
 * the most there can be, and the smallest array worth threads. */
#define MEASURE_PER_THREAD 8
#define MEASURE_PIECES 256
#define MEASURE_PARALLEL_MIN 65536u

/* A subtree of the depth-first array: nodes at .. end-1, its root at
 * depth `depth`. */
typedef struct measure_piece {
    uint32_t at, end, depth;
} measure_piece;

enum { WALK_OK, WALK_BAD, WALK_DEEP };

/* One forward walk over the subtree p: node i+1 must be i's left child
 * when i is internal, else the right child last put aside (the stack),
 * every right child lies after its parent and inside the subtree, a
 * leaf's primitives inside the index array, and the subtree ends at its
 * last leaf.  Its deepest node's depth into *deepest.
 *
 * Without a branch on the node kind (which no predictor guesses: about
 * half the walk's time went to it): both moves are computed and the kind
 * selects, with the stack's top in a register and each entry its
 * position and depth in one word.  At the bottom, below the subtree's
 * root, sits the position after the subtree: the last leaf must pop it,
 * and only the last.  Dragon LBVH, 909,967 nodes, one thread: 3.0 -> 2.4
 * ms (conference 1.05 -> 0.87). */
static int walk_piece(const atrbvh_node *nodes, size_t prims,
                      measure_piece p, unsigned *deepest)
{
    /* below the top: stk[1 .. sp] (stk[0] read, never used, at the end) */
    uint64_t stk[MEASURE_STACK + 2];
    uint64_t top = p.end, bad = 0;
    size_t i, sp = 0;
    uint32_t depth = p.depth, most = p.depth;
    stk[0] = 0;
    for (i = p.at; i < p.end; i++) {
        const atrbvh_node *v = &nodes[i];
        const uint32_t c = v->count, x = v->index;
        const uint64_t leaf = c != 0, lm = 0 - leaf; /* all ones: a leaf */
        const uint64_t pushed = ((uint64_t)(depth + 1u) << 32) | x;
        const uint64_t below = stk[sp];
        most = depth > most ? depth : most;
        /* a leaf: its primitives, and the position due next; internal:
         * its right child after its left one, inside the subtree */
        bad |= lm & ((uint64_t)(x > prims) | (uint64_t)(c > prims - x) |
                     (uint64_t)((uint32_t)top != i + 1));
        bad |= ~lm & ((uint64_t)(x <= i + 1) | (uint64_t)(x >= p.end));
        stk[sp + 1] = top; /* (a leaf's store is above the stack) */
        depth = (uint32_t)(((top >> 32) & lm) | ((depth + 1u) & ~lm));
        top = (below & lm) | (pushed & ~lm);
        sp = sp + 1 - 2 * (size_t)leaf; /* the last leaf: (size_t)-1 */
        if (bad | (uint64_t)(sp > MEASURE_STACK))
            break;
    }
    if (bad)
        return WALK_BAD;
    if (sp == (size_t)-1 && i + 1 == p.end) {
        *deepest = most;
        return WALK_OK;
    }
    /* more right children pending than the stack holds, or the
     * subtree not closed at its end */
    return i < p.end ? WALK_DEEP : WALK_BAD;
}

/* The whole tree in piece[0] cut into subtrees of at most `cut` nodes
 * (fewer where a list would overflow: those subtrees stay larger), into
 * piece[0 .. *count); WALK_BAD when a top node's right child is not
 * inside its subtree. */
static int cut_pieces(const atrbvh_node *nodes, uint32_t cut,
                      measure_piece *piece, size_t cap, size_t *count)
{
    size_t k = 0, n = 1;
    while (k < n) {
        const measure_piece p = piece[k];
        const atrbvh_node *v = &nodes[p.at];
        if (p.end - p.at <= cut || v->count || n == cap) {
            k++;
            continue;
        }
        if (v->index <= p.at + 1 || v->index >= p.end)
            return WALK_BAD;
        /* the node's left subtree in its place (looked at again), its
         * right one at the end */
        piece[k].at = p.at + 1;
        piece[k].end = v->index;
        piece[k].depth = p.depth + 1;
        piece[n].at = v->index;
        piece[n].end = p.end;
        piece[n].depth = p.depth + 1;
        n++;
    }
    *count = n;
    return WALK_OK;
}

/* The statistics of the layout's depth-first array, checked as such.  Two
 * parts, which the threads share: the SAH's sums in node order, serially
 * (atrbvh_sah's, the same bits: sah.c), with the leaves and their largest
 * count; and the order check with the depths, a walk per subtree of the
 * top (walk_piece), whose results (a maximum, a verdict) do not depend on
 * the order the subtrees are walked in.  Nothing is allocated.  Measured
 * (dragon LBVH, 909,967 nodes): 4.2-5.0 ms as one serial loop with both,
 * the sums 1.2 ms alone (sah.c), the walk 2.4 (walk_piece). */
atrbvh_status atrbvh_i_bvh_measure_built(atrbvh_bvh *b, int threads)
{
    const size_t m = b->node_count;
    measure_piece piece[MEASURE_PIECES];
    atrbvh_i_sah_sums sums;
    size_t pieces = 1;
    unsigned deepest = 0;
    int verdict = WALK_OK;
    atrbvh_i_join join = {0};
    int64_t k;
    if (m == 0)
        return atrbvh_i_bvh_measure(b);
    if (m > (size_t)UINT32_MAX)
        return ATRBVH_ERR_BACKEND; /* node indices are 32 bits */
    if (threads < 1)
        threads = 1;
    if (threads > MEASURE_PIECES)
        threads = MEASURE_PIECES;
    piece[0].at = 0;
    piece[0].end = (uint32_t)m;
    piece[0].depth = 0;
    if (threads > 1 && m >= MEASURE_PARALLEL_MIN) {
        const size_t cap = (size_t)threads * MEASURE_PER_THREAD + 1u;
        if (cut_pieces(b->nodes,
                       (uint32_t)(m / ((size_t)threads * MEASURE_PER_THREAD)),
                       piece, cap < MEASURE_PIECES ? cap : MEASURE_PIECES,
                       &pieces) != WALK_OK)
            return ATRBVH_ERR_BACKEND;
    } else {
        threads = 1;
    }
    /* item -1: the sums; item k >= 0: the walk of piece k */
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if (threads > 1)
#endif
    {
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1) nowait \
    reduction(max : deepest, verdict)
#endif
        for (k = -1; k < (int64_t)pieces; k++) {
            if (k < 0) {
                atrbvh_i_sah_sum(b->nodes, m, &sums);
            } else {
                unsigned most = 0;
                const int w =
                    walk_piece(b->nodes, b->prim_count, piece[k], &most);
                if (w > verdict)
                    verdict = w;
                if (most > deepest)
                    deepest = most;
            }
        }
        atrbvh_i_join_arrive(&join);
    }
    if (verdict == WALK_DEEP)
        return atrbvh_i_bvh_measure(b); /* deeper: check.c */
    if (verdict != WALK_OK)
        return ATRBVH_ERR_BACKEND;
    set_stats_sah(b, sums.leaves, deepest, sums.largest,
                  atrbvh_i_sah_total(b->stats.ci, b->stats.ct, sums.inner,
                                     sums.leaf_sum,
                                     atrbvh_i_node_area(&b->nodes[0])));
    return ATRBVH_OK;
}

void atrbvh_i_bvh_set_stats(atrbvh_bvh *b, size_t leaves, unsigned depth,
                            unsigned largest)
{
    set_stats_sah(b, leaves, depth, largest,
                  atrbvh_sah(b->nodes, b->node_count, b->stats.ci,
                             b->stats.ct));
}

void atrbvh_bvh_free(atrbvh_bvh *bvh)
{
    if (!bvh)
        return;
    atrbvh_i_bvh_drop_wide(bvh);
    atrbvh_i_free(bvh->nodes);
    atrbvh_i_free(bvh->prim_indices);
    atrbvh_i_free(bvh->device);
    atrbvh_i_free(bvh);
}

const atrbvh_node *atrbvh_bvh_nodes(const atrbvh_bvh *bvh, size_t *count)
{
    if (count)
        *count = bvh ? bvh->node_count : 0;
    return bvh ? bvh->nodes : NULL;
}

const uint32_t *atrbvh_bvh_primitive_indices(const atrbvh_bvh *bvh,
                                             size_t *count)
{
    if (count)
        *count = bvh ? bvh->prim_count : 0;
    return bvh ? bvh->prim_indices : NULL;
}

/* The first version's atrbvh_stats ends with build_ms; the second
 * (animation) with refit_ms.  Only a version's size is accepted. */
#define STATS_SIZE_V1 (offsetof(atrbvh_stats, build_ms) + sizeof(double))
#define STATS_SIZE_V2 (offsetof(atrbvh_stats, refit_ms) + sizeof(double))

/* A build's statistics of a pass over the nodes are measured when first
 * read, not in the build (lib/pipeline.c): the tree's users need none of
 * them to trace, and on 2 threads the pass and its thread hand-over took
 * 7-10% of an LBVH (bunny, dabrovic_sponza: 3.5 -> 3.2 ms).  The getter
 * takes a const tree that several threads may read at once, so it
 * measures into a copy each time and keeps nothing; the library's own
 * readers that may change the tree settle them into it first. */
atrbvh_status atrbvh_i_bvh_stats_of(const atrbvh_bvh *b, atrbvh_stats *out)
{
    atrbvh_bvh copy;
    atrbvh_status st;
    if (!b->stats_pending) {
        *out = b->stats;
        return ATRBVH_OK;
    }
    copy = *b; /* measure_built reads the arrays, writes only stats */
    st = atrbvh_i_bvh_measure_built(
        &copy, atrbvh_i_resolve_threads(b->stats.threads));
    if (st == ATRBVH_OK)
        *out = copy.stats;
    return st;
}

atrbvh_status atrbvh_i_bvh_settle_stats(atrbvh_bvh *b)
{
    atrbvh_status st;
    if (!b->stats_pending)
        return ATRBVH_OK;
    /* (stats_of measures into its copy before it writes *out) */
    st = atrbvh_i_bvh_stats_of(b, &b->stats);
    if (st == ATRBVH_OK)
        b->stats_pending = 0;
    return st;
}

atrbvh_status atrbvh_bvh_stats_sized(const atrbvh_bvh *bvh,
                                     atrbvh_stats *stats, size_t size)
{
    atrbvh_stats all;
    atrbvh_status st;
    if (!bvh || !stats ||
        (size != STATS_SIZE_V1 && size != STATS_SIZE_V2))
        return ATRBVH_ERR_INVALID_ARGUMENT;
    st = atrbvh_i_bvh_stats_of(bvh, &all);
    if (st != ATRBVH_OK)
        return st;
    memcpy(stats, &all, size);
    return ATRBVH_OK;
}

double atrbvh_bvh_stage_ms(const atrbvh_bvh *bvh, atrbvh_stage stage)
{
    if (!bvh || (int)stage < 0 || stage >= ATRBVH_STAGE_COUNT)
        return 0.0;
    return bvh->stage_ms[stage];
}

void atrbvh_i_bvh_add_kernel_time(atrbvh_bvh *bvh, const char *name,
                                  double ms)
{
    atrbvh_i_device_info *d = bvh->device;
    unsigned k;
    if (!d)
        return;
    for (k = 0; k < d->kernel_count; k++) {
        if (strcmp(d->kernel_name[k], name) == 0) {
            d->kernel_ms[k] += ms;
            return;
        }
    }
    if (d->kernel_count == ATRBVH_MAX_KERNEL_TIMES)
        return;
    strncpy(d->kernel_name[k], name, sizeof d->kernel_name[k] - 1);
    d->kernel_name[k][sizeof d->kernel_name[k] - 1] = '\0';
    d->kernel_ms[k] = ms;
    d->kernel_count++;
}

const char *atrbvh_bvh_device(const atrbvh_bvh *bvh)
{
    if (!bvh)
        return NULL;
    return bvh->device ? bvh->device->name : "cpu";
}

int atrbvh_bvh_kernel_time(const atrbvh_bvh *bvh, size_t i, const char **name,
                           double *ms)
{
    if (!bvh || !bvh->device || i >= bvh->device->kernel_count)
        return 0;
    if (name)
        *name = bvh->device->kernel_name[i];
    if (ms)
        *ms = bvh->device->kernel_ms[i];
    return 1;
}
