/*
 * optimise.c - stage "optimise": treelet restructuring of the whole tree,
 * TRBVH (Karras & Aila 2013) or ATRBVH (Domingues & Pedrini 2015).
 *
 * Rounds r = 0 .. rounds-1 with gamma_r = gamma * 2^r (saturating): in a
 * round, every internal node whose subtree holds at least gamma_r
 * primitives (the "crown": counts only grow upwards, so it is a connected
 * top part of the tree) is a treelet root, processed in post-order - a
 * node only after its whole subtree is final.  Each treelet is then a
 * pure function of that subtree, so the result is the same, bit for bit,
 * for any thread count and any schedule.
 *
 * Consistency: a treelet write-back leaves boxes, counts and costs of the
 * treelet's nodes exact (atrbvh_node_cost, as refit computes them); the
 * root of every crown node is refreshed (its cost recomputed from its
 * children, left first) before its treelet is formed, because the
 * subtrees below may have become cheaper.  Nodes outside the crown are not
 * touched, so after each round the tree is as refit would leave it.
 *
 * Scheduling on the CPU, per round: the "top" is the crown nodes of at
 * least `cut` primitives (cpu.h's atrbvh_i_frontier_cut), a
 * connected top part of the crown; the "frontier" is the crown nodes just
 * below it, roots of disjoint subtrees.  One parallel loop (dynamic, a
 * chunk of neighbouring frontier subtrees at a time: FRONTIER_CHUNK) walks
 * the frontier subtrees, and a top node is processed by the thread that
 * completes the last of its subtrees (top_arrive; on one thread, the
 * calling thread walks the top after the loop).  Each
 * walk follows a stackless serial post-order walk over the parent
 * pointers - the treelet root keeps its id and parent, so the walk's way
 * up stays valid, and a frontier root keeps its primitives, so the top
 * does not move under the loop.
 * One hand-over between threads per round, where post-order tasks woke a
 * sleeping thread at every spawn and taskwait (on a virtual machine with
 * passive waiting, each wake-up is tens to hundreds of microseconds).
 * Scratch is per thread, allocated once per build.
 *
 * Within a chunk of frontier subtrees, and in the top (walk_lanes; on
 * one thread too), the crown nodes go by height instead of in post-order
 * - any order that takes a node after the crown nodes below it gives the
 * same tree - so that
 * treelets of disjoint subtrees run side by side: their formations
 * interleaved (each a chain of dependent loads), and TRBVH's DP and
 * ATRBVH's agglomerations in the lanes of one vector register
 * (shared/treelet.h's atrbvh_trbvh_costs4 and atrbvh_agglomerate4, four
 * with AVX, chosen at run time; opt_lanes).  Measured on sibenik at one
 * thread, callgrind: the TRBVH(7,3) optimise stage went from 439M to 279M
 * instructions per build with four lanes; ATRBVH(9,2)'s from 117M to 125M
 * with its formations side by side (the listing), but faster (their loads
 * overlap), and its agglomerations in lanes cut the mispredicted branches
 * five-fold (docs/optimisers.md).
 */
#include "cpu.h"
#include "shared/treelet.h"

/* One thread's scratch, allocated once per build (never per treelet). */
typedef struct opt_worker {
    atrbvh_trbvh_scratch trbvh; /* 2^n entries each (TRBVH)             */
    /* TRBVH in lanes (walk_lanes): lane[0] = trbvh, lanes 1..3 their
     * splits; the four lanes' interleaved tables (pack,
     * ATRBVH_TRBVH_QUAD_DOUBLES * 2^n doubles); a frontier
     * subtree's crown nodes in post-order (list), then by height */
    atrbvh_trbvh_scratch lane[4];
    double *pack;
    uint32_t *list, *order;
    atrbvh_agg_scratch agg;     /* ATRBVH: the distances and the
                                   agglomeration's arrays (and above 32
                                   leaves the treelet's),
                                   atrbvh_agg_layout                    */
    double *dist4;              /* ATRBVH in lanes: four interleaved
                                   matrices (atrbvh_agglomerate4)       */
    uint64_t treelets;          /* treelets processed                   */
    uint64_t applied;           /* of which restructured                */
    uint64_t skipped;           /* known unchanged, not processed       */
    uint64_t unreported;        /* treelets not yet in the round's count
                                   (progress)                           */
} opt_worker;

#include <stdlib.h>
#include <string.h>

/* The skip marks hold a round + 1 in a byte. */
#if ATRBVH_ROUNDS_MAX > 254
#error "optimise.c: rounds no longer fit the byte marks"
#endif
/* The adaptive sizes take process()'s fixed-size path. */
#if ATRBVH_AUTO_MAX > ATRBVH_TREELET_MAX
#error "optimise.c: the adaptive size exceeds the fixed-size path"
#endif

/* The most treelets formed side by side (lane_batch) where ATRBVH's
 * agglomerations or TRBVH's DP go in lanes: two groups of four.  Eight
 * formations overlap more of their loads than four: dabrovic_sponza's
 * optimise stage 1.0-1.7% faster for ATRBVH(9,2) at one thread, 1.1-1.6%
 * for TRBVH(7,3) at two, Intel host (docs/bench/abpair.c); sixteen
 * gained 0.3-1% more. */
#define FORM_MAX 8u

/* Frontier subtrees a thread takes at a time (walk_round, walk_lanes):
 * neighbours in the frontier's order, up to FRONTIER_CHUNK of them while
 * they hold fewer than CHUNK_PRIMS primitives together (one, however
 * large, always).  Their crowns go through the lanes together, so that
 * the few nodes of a small subtree's upper heights fill lanes beside
 * another's instead of taking the scalar path; the primitive budget keeps
 * a chunk's nodes in the cache (the dragon's subtrees, 13,600 primitives
 * each at two threads, were 5% slower eight at a time). */
#define FRONTIER_CHUNK 8u
#define CHUNK_PRIMS 8192u
/* The last TAIL_SUBTREES subtrees a thread of the frontier go
 * TAIL_CHUNK at a time: the thread that runs out of chunks first takes
 * the top's nodes as they become ready (top_arrive) and then waits for
 * the other's last chunk, about half a chunk on average (0.2 ms of
 * dabrovic_sponza's first ATRBVH(9,2) round at two threads with chunks
 * of eight).  Builds 0.990-0.995 (docs/bench/abpair.c); before the
 * arrivals, smaller last chunks gained nothing. */
#define TAIL_SUBTREES 8u
#define TAIL_CHUNK 2u

/* Trees smaller than this are optimised on one thread. */
#define PARALLEL_MIN 2048u

typedef struct walk_ctx {
    atrbvh_treelet_tree t;
    const atrbvh_cost_params *cost;
    atrbvh_method method;
    unsigned n;
    uint32_t gamma;
    opt_worker *workers;
    /* TRBVH and ATRBVH up to ATRBVH_TREELET_MAX leaves or adaptive (NULL
     * otherwise): per internal node, the last round + 1 in which its
     * subtree changed (chg) and in which it was processed without a
     * change since (same), 0 for never; see shared/treelet.h's
     * atrbvh_treelet_process_marked. */
    atrbvh_treelet_marks marks;
    /* Unless in post-order (opt_lanes 1): the frontier subtrees'
     * treelets `lanes` at a time (walk_lanes), with each internal node's
     * height in the crown (hgt, saturating at 255); NULL otherwise. */
    unsigned char *hgt;
    /* On threads: per internal node, the arrivals of the top (a byte,
     * top_arrive); the same bytes as hgt where there are heights (those
     * are written below a round's cut only, these above it). */
    unsigned char *arr;
    unsigned lanes;
    /* ATRBVH in lanes, where the CPU has AVX: the agglomerations side by
     * side too (atrbvh_agglomerate4), not only the formations */
    int agg4;
    /* Progress inside a round: treelets done of about `crown`; only the
     * calling thread (OpenMP thread 0) reports, every `step` treelets.
     * Progress and cancellation never change what a treelet computes. */
    atrbvh_i_run *run;
    uint64_t done, crown, step, next, round, rounds;
    int cancel; /* set by thread 0 when the user cancels: skip the rest */
} walk_ctx;

/* Treelets a worker counts before it adds them to the round's count. */
#define PROGRESS_BATCH 64u

/* Counts a treelet done; thread 0 reports progress now and then.  Each
 * worker adds its count to the shared one PROGRESS_BATCH treelets at a
 * time: an atomic add per treelet was half of lane_done's samples at one
 * thread (perf), and at two it moved the context's cache line, which
 * every treelet reads, between the cores.  Inlined into its callers: a
 * call per treelet shows in the instruction count of the small
 * treelets. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void progress(walk_ctx *c, opt_worker *w)
{
    uint64_t done, add;
    int cancel;
    if (++w->unreported < PROGRESS_BATCH)
        return;
    add = w->unreported;
    w->unreported = 0;
#ifdef _OPENMP
#pragma omp atomic capture
#endif
    done = c->done += add;
    if (!c->run)
        return;
#ifdef _OPENMP
    if (omp_get_thread_num() != 0)
        return;
#endif
    if (done < c->next)
        return;
    c->next = done + c->step;
    cancel = atrbvh_i_stage_progress(c->run, c->round * c->crown + done,
                                     c->rounds * c->crown);
    if (cancel) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
        c->cancel = 1;
    }
}

/* An internal node of at least lo primitives. */
static int at_least(const atrbvh_treelet_tree *t, uint32_t node, uint32_t lo)
{
    return node < t->n_internal && t->count[node] >= lo;
}

static int in_crown(const walk_ctx *c, uint32_t node)
{
    return at_least(&c->t, node, c->gamma);
}

/* This thread's worker, or NULL when the build is being cancelled. */
static opt_worker *worker(walk_ctx *c)
{
    int cancel;
#ifdef _OPENMP
#pragma omp atomic read
#endif
    cancel = c->cancel;
    if (cancel)
        return NULL;
#ifdef _OPENMP
    return c->workers + omp_get_thread_num();
#else
    return c->workers;
#endif
}

static void process(walk_ctx *c, uint32_t node, unsigned n)
{
    opt_worker *w = worker(c);
    int applied;
    if (!w)
        return; /* the build is being cancelled: its tree is dropped */
    /* One treelet: form, new topology (TRBVH: the subset DP of Karras &
     * Aila 2013; ATRBVH: the agglomerative clustering of Domingues &
     * Pedrini 2015), write back if strictly cheaper, or skip it when the
     * marks say that it would change nothing - all of it shared/treelet.h's
     * atrbvh_treelet_process_marked, which the OpenCL kernel calls too. */
    applied = atrbvh_treelet_process_marked(
        &c->t, c->cost, node, n, c->method == ATRBVH_METHOD_ATRBVH, w->trbvh,
        &w->agg, c->marks, (atrbvh_u32)c->round);
    if (applied == ATRBVH_TREELET_SKIPPED) {
        w->skipped++;
    } else {
        w->treelets++;
        w->applied += (uint64_t)applied;
    }
    progress(c, w);
}

/* ATRBVH treelets above 32 leaves: process()'s
 * bookkeeping around atrbvh_atrbvh_process (shared/treelet.h, which the
 * OpenCL kernel calls too).  Kept out of process() so that the fixed-size
 * path's code and registers stay what they were. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void process_agg(walk_ctx *c, uint32_t node)
{
    opt_worker *w = worker(c);
    int applied;
    if (!w)
        return; /* the build is being cancelled: its tree is dropped */
    applied = atrbvh_atrbvh_process(&c->t, c->cost, node, c->n, c->gamma,
                                    w->trbvh, &w->agg);
    w->treelets++;
    w->applied += (uint64_t)applied;
    progress(c, w);
}

/* One crown node: up to ATRBVH_TREELET_MAX leaves and the adaptive size
 * (9, 16 or 32 leaves: atrbvh_atrbvh_process's choice, the same
 * fixed-size path) process(), above process_agg(). */
static void visit(walk_ctx *c, uint32_t node)
{
    if (c->n <= ATRBVH_TREELET_MAX)
        process(c, node, c->n);
    else if (c->n == ATRBVH_TREELET_AUTO)
        process(c, node,
                atrbvh_treelet_auto_size(c->t.count[node], c->gamma));
    else
        process_agg(c, node);
}

/* Post-order over the crown nodes of at least `lo` primitives (lo >=
 * gamma) below and including crown node s, without a stack: descend to
 * the first such node with no such child, process, then go to the right
 * sibling's subtree or up to the parent.  lo = gamma: the whole crown
 * below s; lo = the cut: the top, whose frontier is already done.
 * post_first: the first node of that post-order below x. */
static uint32_t post_first(const atrbvh_treelet_tree *t, uint32_t x,
                           uint32_t lo)
{
    for (;;) {
        if (at_least(t, t->left[x], lo))
            x = t->left[x];
        else if (at_least(t, t->right[x], lo))
            x = t->right[x];
        else
            return x;
    }
}

/* The node after x in that post-order below s, or ATRBVH_U32_MAX after s
 * itself; read after x is processed (a treelet root keeps its id and
 * parent, so the way up stays valid). */
static uint32_t post_next(const atrbvh_treelet_tree *t, uint32_t s,
                          uint32_t x, uint32_t lo)
{
    uint32_t parent;
    if (x == s)
        return ATRBVH_U32_MAX;
    parent = t->parent[x];
    if (t->left[parent] == x && at_least(t, t->right[parent], lo))
        return post_first(t, t->right[parent], lo); /* the right subtree */
    return parent;
}

static void walk_serial(walk_ctx *c, uint32_t s, uint32_t lo)
{
    uint32_t x;
    for (x = post_first(&c->t, s, lo); x != ATRBVH_U32_MAX;
         x = post_next(&c->t, s, x, lo))
        visit(c, x);
}

/* One treelet of walk_lanes done, written back (applied) or not: its
 * marks, the worker's counts, the progress. */
static void lane_done(walk_ctx *c, opt_worker *w, uint32_t node,
                      const atrbvh_treelet *tl, int applied)
{
    atrbvh_treelet_marks_done(c->marks, tl, node, applied,
                              (uint32_t)c->round);
    w->treelets++;
    w->applied += (uint64_t)applied;
    progress(c, w);
}


#ifdef ATRBVH_AGG_QUADS
/* The agglomerations of `ready` (2 to 4) formed ATRBVH treelets of
 * lane_batch, side by side where they can be (shared/treelet.h's
 * atrbvh_agglomerate_side, which the opt_round4 kernel calls too), then
 * each one's marks and counts. */
static void lane_agg(walk_ctx *c, opt_worker *w, unsigned ready,
                     const uint32_t *root, const atrbvh_treelet *tl)
{
    int applied[4];
    unsigned l;
    atrbvh_agglomerate_side(&c->t, c->cost, ready, root, tl, &w->agg,
                            w->dist4, applied);
    for (l = 0; l < ready; l++)
        lane_done(c, w, root[l], &tl[l], applied[l]);
}
#endif

/* `ready` (1 to c->lanes) treelet roots of one height (disjoint
 * subtrees, none skipped): each root refreshed, the treelets formed side
 * by side (one expansion of each in turn, so that their loads overlap: a
 * formation is a chain of dependent loads), then each treelet's
 * topology.  ATRBVH: the agglomerations four at a time side by side with
 * AVX (lane_agg; FORM_MAX formations, two groups), else one by one
 * (atrbvh_atrbvh_keep, as process() does).  TRBVH: the full treelets' DP
 * four at a time together (atrbvh_trbvh_ready; FORM_MAX formations with
 * AVX, two groups); one alone, or one of fewer than n leaves
 * (not one of a crown node, which holds at least n primitives; kept for
 * safety), by the scalar DP. */
static void lane_batch(walk_ctx *c, opt_worker *w, unsigned ready,
                       const uint32_t *root)
{
    atrbvh_treelet tl[FORM_MAX];
    atrbvh_treelet_leaves lv[4];
    double area[FORM_MAX][ATRBVH_TREELET_MAX];
    uint32_t size[FORM_MAX];
    int applied[4];
    unsigned l, m, first, more = 1;
    for (l = 0; l < ready; l++) {
        size[l] = c->n == ATRBVH_TREELET_AUTO
                      ? atrbvh_treelet_auto_size(c->t.count[root[l]], c->gamma)
                      : c->n;
        atrbvh_treelet_refresh(&c->t, c->cost, root[l]);
        atrbvh_treelet_form_first(&c->t, root[l], &tl[l]);
    }
    for (m = 2; more; m++) {
        more = 0;
        for (l = 0; l < ready; l++)
            if (tl[l].n == m && m < size[l] &&
                atrbvh_treelet_form_next(&c->t, &tl[l], area[l]))
                more = 1;
    }
    if (c->method == ATRBVH_METHOD_ATRBVH) {
        unsigned g;
        for (l = 0; l < ready; l += g) {
            g = ready - l < 4u ? ready - l : 4u;
#ifdef ATRBVH_AGG_QUADS
            if (c->agg4 && g > 1u) {
                lane_agg(c, w, g, root + l, tl + l);
                continue;
            }
#endif
            g = 1u;
            lane_done(c, w, root[l], &tl[l],
                      tl[l].n >= 3u ? atrbvh_atrbvh_keep(&c->t, c->cost,
                                                         root[l], &tl[l],
                                                         &w->agg)
                                    : 0);
        }
        return;
    }
    /* TRBVH: the full treelets' DP together, in lanes (with AVX: opt_lanes
     * takes TRBVH one at a time without), the others one by one
     * (shared/treelet.h's atrbvh_trbvh_ready, which the opt_round4 kernel
     * calls too) */
    for (first = 0; first < ready; first += 4u) {
        const unsigned g = ready - first < 4u ? ready - first : 4u;
        atrbvh_trbvh_ready(&c->t, c->cost, c->n, g, root + first, tl + first,
                           lv, w->lane, w->pack, applied);
        for (l = 0; l < g; l++)
            lane_done(c, w, root[first + l], &tl[first + l], applied[l]);
    }
}

/* The crown nodes of at least `lo` primitives (lo >= gamma) below and
 * including roots[0 .. count-1]: lo = gamma, the crowns of frontier
 * subtrees; lo = the cut, the top (walk_round).  c->lanes treelets at a
 * time (lane_batch).  A treelet is a pure function of its root's final
 * subtree, so any order that takes a node after every crown node below it
 * gives the post-order's tree, bit for bit: the nodes are listed in
 * post-order with their height (0 for a node with no such child, else one
 * more than its highest such child), sorted by height (stable), and each
 * height is taken in turn -
 * nodes of one height have disjoint subtrees, so several of them form,
 * run and write back side by side; the subtrees of a chunk are listed one
 * after the other and sorted together, so that the few nodes of a
 * subtree's upper heights fill lanes beside another's (alone, they took
 * the scalar agglomeration).  Heights saturate at 255: the nodes of
 * height 255 or more, still in post-order among themselves within each
 * subtree, go one at a time.  Returns 0, with nothing done, when the
 * crowns do not fit the worker's lists (cap entries): the caller then
 * walks them in post-order. */
static int walk_lanes(walk_ctx *c, const uint32_t *roots, size_t count,
                      uint32_t lo, size_t cap)
{
    const atrbvh_treelet_tree *t = &c->t;
    const unsigned lanes = c->lanes;
    opt_worker *w = worker(c);
    unsigned char *hgt = c->hgt;
    size_t start[257], k = 0, i, h, j;
    uint32_t x;
    if (!w)
        return 1; /* the build is being cancelled: its tree is dropped */
    memset(start, 0, sizeof start);
    /* walk_serial's post-order, listing instead of visiting */
    for (j = 0; j < count; j++) {
        for (x = post_first(t, roots[j], lo); x != ATRBVH_U32_MAX;
             x = post_next(t, roots[j], x, lo)) {
            const uint32_t l = t->left[x], r = t->right[x];
            unsigned hx = 0;
            if (at_least(t, l, lo))
                hx = hgt[l] + 1u;
            if (at_least(t, r, lo) && hgt[r] + 1u > hx)
                hx = hgt[r] + 1u;
            if (hx > 255u)
                hx = 255u;
            if (k == cap)
                return 0;
            hgt[x] = (unsigned char)hx;
            w->list[k++] = x;
            start[hx + 1u]++;
        }
    }
    for (h = 1; h < 257u; h++)
        start[h] += start[h - 1u];
    for (i = 0; i < k; i++)
        w->order[start[hgt[w->list[i]]]++] = w->list[i];
    /* start[h] is now the end of height h */
    i = 0;
    for (h = 0; h < 256u && i < k; h++) {
        /* one at a time from 255 on: post-order among themselves */
        const unsigned most = h < 255u ? lanes : 1u;
        const size_t end = start[h];
        uint32_t node[FORM_MAX];
        unsigned ready = 0;
        for (; i < end; i++) {
            if (!(w = worker(c)))
                return 1;
            node[ready] = w->order[i];
            if (atrbvh_treelet_marks_skip(t, c->marks, node[ready])) {
                w->skipped++;
                progress(c, w);
                continue;
            }
            if (++ready == most) {
                lane_batch(c, w, ready, node);
                ready = 0;
            }
        }
        if (ready > 0u) /* the height's last ones */
            lane_batch(c, w, ready, node);
    }
    return 1;
}

/* The frontier of the top (the internal nodes of at least `cut`
 * primitives, the root among them): the crown nodes below `cut` whose
 * parent is in the top, into out[0 ..], in pre-order of the top.  Returns
 * their number, or cap + 1 when they do not fit.  With `arr`, each top
 * node's arrival count too (top_arrive): 2 less its crown children; with
 * cut >= 2 gamma every top node has one (a child of at least gamma), so
 * every top node is reached by the arrivals from the frontier. */
static size_t frontier(const walk_ctx *c, uint32_t cut, uint32_t *out,
                       size_t cap, unsigned char *arr)
{
    const atrbvh_treelet_tree *t = &c->t;
    size_t k = 0;
    uint32_t x = 0;
    for (;;) {
        const uint32_t l = t->left[x], r = t->right[x];
        const int top_l = at_least(t, l, cut), top_r = at_least(t, r, cut);
        if (arr)
            arr[x] = (unsigned char)(2 - in_crown(c, l) - in_crown(c, r));
        if (!top_l && in_crown(c, l)) {
            if (k == cap)
                return cap + 1;
            out[k++] = l;
        }
        if (!top_r && in_crown(c, r)) {
            if (k == cap)
                return cap + 1;
            out[k++] = r;
        }
        if (top_l) {
            x = l;
            continue;
        }
        if (top_r) {
            x = r;
            continue;
        }
        /* up to the nearest ancestor whose right child is a top node not
         * yet entered (entered from its left) */
        for (;;) {
            uint32_t parent;
            if (x == 0)
                return k;
            parent = t->parent[x];
            if (t->left[parent] == x && at_least(t, t->right[parent], cut)) {
                x = t->right[parent];
                break;
            }
            x = parent;
        }
    }
}

/* The crowns of frontier subtrees roots[0 .. count-1]: in lanes
 * (walk_lanes) when the build takes them and the crowns fit the worker's
 * lists of pcap entries, else each in post-order. */
static void walk_frontier(walk_ctx *c, const uint32_t *roots, size_t count,
                          size_t pcap)
{
    size_t j;
    if (c->hgt && walk_lanes(c, roots, count, c->gamma, pcap))
        return;
    for (j = 0; j < count; j++)
        walk_serial(c, roots[j], c->gamma);
}

/* The top by arrivals (threads, walk_round): each top node counts its
 * crown children done (c->arr, from frontier()'s 2 - the number of crown
 * children), and the thread that completes the last of them processes
 * it (visit, in post-order's way: a node after its whole subtree) and
 * goes on to its parent; a node whose other child is still being
 * processed is left to the thread that finishes that one.  So the top
 * is done on the threads as its subtrees complete, in the time the
 * first thread done used to wait for the other, instead of on the
 * calling thread after the loop (0.1 ms a round there, and the wait for
 * the last chunk, 0.05-0.2 ms: dabrovic_sponza, ATRBVH(9,2), two
 * threads).  The order changes nothing: a treelet is a pure function of
 * its root's final subtree.  x keeps its id and parent when processed
 * (a treelet root does), and its parent's children change only when the
 * parent is processed, after both have arrived; the add is acquire and
 * release, so the thread that processes a node sees the other child's
 * subtree as its thread left it. */
static void top_arrive(walk_ctx *c, uint32_t x)
{
    while (x != 0u) {
        const uint32_t up = c->t.parent[x];
        if (__atomic_add_fetch(&c->arr[up], (unsigned char)1u,
                               __ATOMIC_ACQ_REL) < 2u)
            return; /* its other crown child is not done yet */
        visit(c, up);
        x = up;
    }
}

/* One round over the crown: the frontier subtrees on the threads, then
 * the top, by arrivals on the threads (top_arrive) or on this thread; the
 * whole crown on this thread when the tree is
 * small, or its frontier does not fit. */
static void walk_round(walk_ctx *c, int threads, uint32_t *list, size_t cap,
                       size_t pcap)
{
    const uint32_t root_count = c->t.count[0];
    uint32_t cut = atrbvh_i_frontier_cut(root_count, threads);
    atrbvh_i_join join = {0};
    size_t k = 0;
    int64_t i, chunks;
    int arrive;
    /* above gamma, so that every top node is a crown node (gamma is at
     * most the root's count: no overflow) */
    if (cut <= c->gamma)
        cut = c->gamma + 1u;
    /* the top by arrivals on the threads where every top node has a crown
     * child (cut >= 2 gamma: frontier()) */
    arrive = threads > 1 && c->arr && cut / 2u >= c->gamma;
    /* (one thread too when treelets go in pairs: the pairs are formed
     * within the frontier subtrees) */
    if ((threads > 1 || c->hgt) && root_count >= PARALLEL_MIN &&
        root_count >= cut)
        k = frontier(c, cut, list, cap, arrive ? c->arr : NULL);
    if (k < 2u || k > cap) {
        walk_serial(c, 0, c->gamma);
        return;
    }
    /* the chunks: their first roots' places in list[cap ..], then k */
    {
        uint32_t *const start = list + cap;
        size_t j, in = 0;
        uint64_t prims = 0;
        chunks = 0;
        for (j = 0; j < k; j++) {
            const uint32_t here = c->t.count[list[j]];
            if (in > 0u &&
                (in == FRONTIER_CHUNK || prims + here > CHUNK_PRIMS ||
                 (threads > 1 && k - j <= TAIL_SUBTREES * (size_t)threads &&
                  in >= TAIL_CHUNK))) {
                in = 0;
                prims = 0;
            }
            if (in++ == 0u)
                start[chunks++] = (uint32_t)j;
            prims += here;
        }
        start[chunks] = (uint32_t)k;
    }
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1) nowait
#endif
        for (i = 0; i < chunks; i++) {
            const uint32_t *roots = list + list[cap + (size_t)i];
            const size_t count =
                list[cap + (size_t)i + 1u] - list[cap + (size_t)i];
            size_t j;
            walk_frontier(c, roots, count, pcap);
            for (j = 0; arrive && j < count; j++)
                top_arrive(c, roots[j]);
        }
        atrbvh_i_join_arrive(&join);
    }
    /* else the top: in lanes too (its few nodes of a height side by
     * side) */
    if (!arrive) {
        const uint32_t top = 0;
        if (!c->hgt || !walk_lanes(c, &top, 1u, cut, pcap))
            walk_serial(c, 0, cut);
    }
}

/* How many treelets walk_lanes takes at a time (lane_batch), 1 for the
 * post-order walk.  TRBVH: 4 where the CPU has AVX (its DP in
 * atrbvh_trbvh_costs4's lanes; atrbvh_i_optimise then forms FORM_MAX),
 * else 1.  ATRBVH of up to
 * ATRBVH_TREELET_MAX leaves or adaptive: 4 formations side by side, and
 * where the CPU has AVX the agglomerations too (atrbvh_agglomerate4's
 * lanes, and then FORM_MAX formations: atrbvh_i_optimise; without AVX
 * one by one); larger treelets go in post-order
 * (process_agg).  ATRBVH_CPU_LANES=1 or 2 in the environment asks for
 * fewer (tests/test_hashes.c builds every tree each way: the same bits). */
static unsigned opt_lanes(atrbvh_method method, unsigned n)
{
    const char *env = getenv("ATRBVH_CPU_LANES");
    unsigned most = 1u;
    if (method == ATRBVH_METHOD_TRBVH) {
#ifdef ATRBVH_TRBVH_QUADS
        if (__builtin_cpu_supports("avx"))
            most = 4u;
#endif
    } else if (n <= ATRBVH_TREELET_MAX || n == ATRBVH_TREELET_AUTO) {
        most = 4u;
    }
    if (env && (env[0] == '1' || env[0] == '2') && env[1] == '\0' &&
        (unsigned)(env[0] - '0') < most)
        most = (unsigned)(env[0] - '0');
    return most;
}

/* Per-thread scratch layout, each part aligned to 64 bytes. */
#define ALIGN64(x) (((x) + 63u) & ~(size_t)63u)

atrbvh_status atrbvh_i_optimise(atrbvh_i_tree *t, unsigned char *flat,
                                const atrbvh_i_config *cfg,
                                atrbvh_i_scratch *scratch, atrbvh_i_run *run,
                                atrbvh_error *error)
{
    atrbvh_i_scratch own;
    walk_ctx c;
    opt_worker *workers = NULL;
    unsigned char *block;
    size_t subsets = 0, pairs = 0, stride = 0, off_cost, off_count,
           off_split, off_dist, off_list, total, marks = 0, cap;
    /* In lanes (walk_lanes), TRBVH: lanes 1 .. 3's splits from lane1
     * (lane_size bytes each), the interleaved tables at off_pack, the
     * two lists of pcap entries at off_lists; hgt: the heights */
    size_t lane_size = 0, lane1 = 0, off_pack = 0, off_lists = 0, pcap = 0,
           hgt = 0, off_dist4 = 0;
    uint32_t *list;
    unsigned round, n = cfg->treelet_size;
    unsigned lanes = opt_lanes(cfg->method, n), l;
    /* The largest treelet of the build (ATRBVH_TREELET_AUTO: the rule's
     * largest) and the smallest subtree that can hold a treelet. */
    unsigned nmax = n == ATRBVH_TREELET_AUTO ? ATRBVH_AUTO_MAX : n;
    unsigned nmin = n == ATRBVH_TREELET_AUTO ? cfg->gamma : n;
    int threads = cfg->threads > 0 ? cfg->threads : 1, k, agg4 = 0;

    if (cfg->method == ATRBVH_METHOD_LBVH || cfg->rounds == 0)
        return ATRBVH_OK;
    if (cfg->method != ATRBVH_METHOD_TRBVH &&
        cfg->method != ATRBVH_METHOD_ATRBVH)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "optimise: method %d has no treelet optimiser",
                             (int)cfg->method);
    if (n == ATRBVH_TREELET_AUTO && cfg->method == ATRBVH_METHOD_ATRBVH) {
        if (cfg->gamma < 3u)
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                                 (uint64_t)-1,
                                 "optimise: gamma %u below 3", cfg->gamma);
    } else if (n < 3u ||
               n > (cfg->method == ATRBVH_METHOD_TRBVH
                        ? (unsigned)ATRBVH_TRBVH_MAX
                        : (unsigned)ATRBVH_ATRBVH_MAX)) {
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "optimise: treelet size %u out of range", n);
    } else if (cfg->gamma < n)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "optimise: gamma %u below the treelet size %u",
                             cfg->gamma, n);
    /* A tree of fewer than n primitives has no treelet root. */
    if (t->n < 2u || t->count[0] < nmin)
        return ATRBVH_OK;

    /* Scratch: TRBVH 2^n boxes, costs, counts, splits; ATRBVH the
     * n(n-1)/2 distances and the agglomeration's arrays (atrbvh_agg_layout,
     * sized from the largest size used: 84 KiB at 128, 17 KiB at 48, 2.1
     * KiB at 9; `pairs` counts it in doubles, a multiple of 8).
     * Sizes are small but checked anyway. */
    if (cfg->method == ATRBVH_METHOD_TRBVH)
        subsets = (size_t)1 << n;
    else
        pairs = (size_t)atrbvh_agg_layout(NULL, nmax, NULL) / sizeof(double);
    off_cost = ALIGN64(subsets * sizeof(atrbvh_box));
    off_count = off_cost + ALIGN64(subsets * sizeof(double));
    off_split = off_count + ALIGN64(subsets * sizeof(uint32_t));
    off_dist = off_split + ALIGN64(subsets * sizeof(uint32_t));
    stride = off_dist + ALIGN64(pairs * sizeof(double));
    if (lanes > 1u) {
        /* A frontier subtree holds fewer primitives than the round's cut
         * (walk_round: the first cut, or gamma + 1 when that is larger),
         * so fewer crown nodes; at most 2^20 (a larger crown, from a
         * large gamma, walks in post-order). */
        uint64_t most = atrbvh_i_frontier_cut(t->count[0], threads);
        for (round = 0; round < cfg->rounds && round < 40u; round++) {
            const uint64_t g = (uint64_t)cfg->gamma << round;
            if (g > t->count[0])
                break;
            if (g + 1u > most)
                most = g + 1u;
        }
        most *= FRONTIER_CHUNK; /* (at most 2^32 before: no overflow) */
        pcap = most < ((uint64_t)1 << 20) ? (size_t)most : (size_t)1 << 20;
        /* TRBVH: lanes 1 .. 3's splits (the rest of their tables is in
         * the interleaved ones) and the four lanes' interleaved tables
         * (atrbvh_trbvh_costs4 takes four lanes however many are used;
         * subsets is 0 for ATRBVH: nothing) */
        lane_size =
            cfg->method == ATRBVH_METHOD_TRBVH ? off_dist - off_split : 0u;
        lane1 = stride;
        off_pack = lane1 + 3u * lane_size;
        off_dist4 = off_pack + ALIGN64(ATRBVH_TRBVH_QUAD_DOUBLES * subsets *
                                         sizeof(double));
        off_lists = off_dist4;
#ifdef ATRBVH_AGG_QUADS
        /* ATRBVH: the agglomerations in AVX's lanes too, their four
         * matrices (nmax is at most ATRBVH_TREELET_MAX here: opt_lanes) */
        agg4 = cfg->method == ATRBVH_METHOD_ATRBVH &&
               nmax <= ATRBVH_TREELET_MAX && __builtin_cpu_supports("avx");
        if (agg4)
            off_lists += ALIGN64((size_t)atrbvh_agglomerate4_doubles(nmax) *
                                 sizeof(double));
#endif
        stride = off_lists + ALIGN64(2u * pcap * sizeof(uint32_t));
        hgt = (size_t)(t->n - 1u);
    }
    /* After the workers' parts, two marks per internal node (chg, same:
     * atrbvh_treelet_process_marked), rounds + 1 <= 65 fitting a byte;
     * not for ATRBVH treelets above ATRBVH_TREELET_MAX leaves
     * (process_agg). */
    if (cfg->method == ATRBVH_METHOD_TRBVH || n <= ATRBVH_TREELET_MAX ||
        n == ATRBVH_TREELET_AUTO)
        marks = (size_t)(t->n - 1u);
    /* Then the frontier list of a round (walk_round), 4-byte entries
     * after the marks' bytes, aligned. */
    cap = atrbvh_i_frontier_cap(threads);
    /* the heights' bytes serve the top's arrivals too (threads) */
    if (threads > 1)
        hgt = (size_t)(t->n - 1u);
    /* (the marks and hgt are each 0 or t->n - 1 bytes) */
    if (!atrbvh_i_mul_size((size_t)threads, stride, &total) ||
        (size_t)(t->n - 1u) > ((size_t)-1 - total) / 3u)
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, (uint64_t)-1,
                             "optimise: scratch size overflows");
    total += 2u * marks + hgt;
    off_list = ALIGN64(total);
    /* the frontier's roots, then its chunks' starts (cap + 1) */
    if (off_list < total ||
        cap > ((size_t)-1 - off_list) / (2u * sizeof(uint32_t)) - 1u)
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, (uint64_t)-1,
                             "optimise: scratch size overflows");
    total = off_list + (2u * cap + 1u) * sizeof(uint32_t);
    /* 63 bytes more, so that the parts are aligned to 64 bytes in memory
     * and not only from the block's start (an allocator aligns less:
     * malloc to 16, a replaced one maybe to 8; the lanes' SSE2 and AVX
     * loads want 16 and 32) */
    if (total > (size_t)-1 - 63u)
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, (uint64_t)-1,
                             "optimise: scratch size overflows");
    total += 63u;
    if (!scratch) {
        memset(&own, 0, sizeof own);
        scratch = &own;
    }
    workers = atrbvh_i_scratch_get(scratch, CPU_WORKERS, (size_t)threads,
                                   sizeof *workers);
    block = atrbvh_i_scratch_get(scratch, CPU_OPTIMISE, total, 1);
    if (!workers || !block) {
        if (scratch == &own)
            atrbvh_i_scratch_free(&own);
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "optimise: out of memory for %d x %lu bytes of "
                             "treelet scratch",
                             threads, (unsigned long)stride);
    }
    block += (64u - (unsigned)((uintptr_t)block & 63u)) & 63u;
    for (k = 0; k < threads; k++) {
        unsigned char *base = block + (size_t)k * stride;
        memset(&workers[k], 0, sizeof workers[k]);
        workers[k].trbvh.box = (float *)(void *)base;
        workers[k].trbvh.cost = (double *)(void *)(base + off_cost);
        workers[k].trbvh.count = (uint32_t *)(void *)(base + off_count);
        workers[k].trbvh.split = (uint32_t *)(void *)(base + off_split);
        workers[k].lane[0] = workers[k].trbvh;
        for (l = 1; lane_size > 0u && l < 4u; l++) {
            unsigned char *at = base + lane1 + (l - 1u) * lane_size;
            workers[k].lane[l].box = NULL;
            workers[k].lane[l].cost = NULL;
            workers[k].lane[l].count = NULL;
            workers[k].lane[l].split = (uint32_t *)(void *)at;
        }
        if (lane_size > 0u)
            workers[k].pack = (double *)(void *)(base + off_pack);
        if (agg4)
            workers[k].dist4 = (double *)(void *)(base + off_dist4);
        if (hgt > 0u) {
            workers[k].list = (uint32_t *)(void *)(base + off_lists);
            workers[k].order = workers[k].list + pcap;
        }
        if (cfg->method == ATRBVH_METHOD_ATRBVH)
            atrbvh_agg_layout(base + off_dist, nmax, &workers[k].agg);
    }
    list = (uint32_t *)(void *)(block + off_list);
    c.marks.chg = c.marks.same = NULL;
    if (marks > 0u) {
        c.marks.chg = block + (size_t)threads * stride;
        c.marks.same = c.marks.chg + marks;
        memset(c.marks.chg, 0, 2u * marks);
    }
    /* the heights: each written before it is read (walk_lanes) */
    c.arr = hgt > 0u ? block + (size_t)threads * stride + 2u * marks : NULL;
    c.hgt = lanes > 1u ? c.arr : NULL;
    c.lanes = (agg4 || cfg->method == ATRBVH_METHOD_TRBVH) && lanes == 4u
                  ? FORM_MAX
                  : lanes;
    c.agg4 = agg4;

    c.t.left = t->left;
    c.t.right = t->right;
    c.t.parent = t->parent;
    c.t.count = t->count;
    c.t.box = t->box;
    c.t.cost = t->cost;
    c.t.flat = flat;
    c.t.n_internal = t->n - 1u;
    c.cost = &cfg->cost;
    c.method = cfg->method;
    c.n = n;
    c.workers = workers;
    c.run = run;
    c.rounds = cfg->rounds;
    c.cancel = 0;

    for (round = 0; round < cfg->rounds; round++) {
        uint64_t g = (uint64_t)cfg->gamma << (round < 40u ? round : 40u);
        if (g > t->count[0])
            break; /* no crown left: later rounds would do nothing */
        c.gamma = (uint32_t)g;
        /* About as many treelets as internal nodes holding >= gamma
         * primitives: at most n / gamma * 2 (a progress scale only). */
        c.crown = 2u * (uint64_t)t->count[0] / c.gamma + 1u;
        c.step = c.crown / 64u + 1u;
        c.done = 0;
        for (k = 0; k < threads; k++)
            workers[k].unreported = 0;
        c.next = c.step;
        c.round = round;
        if (run && atrbvh_i_stage_progress(run, round * c.crown,
                                           c.rounds * c.crown)) {
            if (scratch == &own)
                atrbvh_i_scratch_free(&own);
            return atrbvh_i_fail(error, ATRBVH_ERR_CANCELLED, (uint64_t)-1,
                                 "cancelled in the optimise stage, round %u",
                                 round + 1);
        }
        walk_round(&c, threads, list, cap, pcap);
        if (c.cancel || (run && atrbvh_i_stage_round(run, round + 1))) {
            if (scratch == &own)
                atrbvh_i_scratch_free(&own);
            return atrbvh_i_fail(error, ATRBVH_ERR_CANCELLED, (uint64_t)-1,
                                 "cancelled in the optimise stage, round %u",
                                 round + 1);
        }
    }

    if (scratch == &own)
        atrbvh_i_scratch_free(&own);
    return ATRBVH_OK;
}

/* The stage. */
atrbvh_status atrbvh_i_cpu_optimise(atrbvh_device *dev, atrbvh_i_run *run,
                                    atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    atrbvh_status st;
    (void)dev;
    st = atrbvh_i_optimise(&c->tree, c->flat, run->cfg, c->scratch, run,
                           error);
    /* Its treelet scratch, marks and lists (about 5 bytes per primitive)
     * are not needed after it: a transient scratch frees them here, so
     * that they are not live at the layout, the build's peak (the
     * collapse and the layout take a small block of the slot for their
     * frontiers); a handle keeps them for its next build. */
    atrbvh_i_scratch_done(c->scratch, CPU_OPTIMISE);
    atrbvh_i_scratch_done(c->scratch, CPU_WORKERS);
    return st;
}
