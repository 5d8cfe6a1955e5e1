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
 * below it, roots of disjoint subtrees.  One parallel loop (dynamic, one
 * subtree at a time) walks each frontier subtree in post-order; then the
 * calling thread walks the top in post-order.  Each walk is a stackless
 * serial post-order walk over the parent pointers - the treelet root keeps
 * its id and parent, so the walk's way up stays valid, and a frontier
 * root keeps its primitives, so the top does not move under the loop.
 * One hand-over between threads per round, where post-order tasks woke a
 * sleeping thread at every spawn and taskwait (on a virtual machine with
 * passive waiting, each wake-up is tens to hundreds of microseconds).
 * Scratch is per thread, allocated once per build.
 */
#include "cpu.h"
#include "shared/treelet.h"

/* One thread's scratch, allocated once per build (never per treelet). */
typedef struct opt_worker {
    atrbvh_trbvh_scratch trbvh; /* 2^n entries each (TRBVH)             */
    atrbvh_agg_scratch agg;     /* ATRBVH above 32 leaves or adaptive:
                                   distances (= dist) and the treelet's
                                   arrays, atrbvh_agg_layout            */
    double *dist;               /* n(n-1)/2 distances (ATRBVH)          */
    uint64_t treelets;          /* treelets processed                   */
    uint64_t applied;           /* of which restructured                */
    uint64_t skipped;           /* known unchanged, not processed       */
} opt_worker;

#include <string.h>

/* The skip marks hold a round + 1 in a byte. */
#if ATRBVH_ROUNDS_MAX > 254
#error "optimise.c: rounds no longer fit the byte marks"
#endif
/* The adaptive sizes take process()'s fixed-size path. */
#if ATRBVH_AUTO_MAX > ATRBVH_TREELET_MAX
#error "optimise.c: the adaptive size exceeds the fixed-size path"
#endif

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
    /* Progress inside a round: treelets done of about `crown`; only the
     * calling thread (OpenMP thread 0) reports, every `step` treelets.
     * Progress and cancellation never change what a treelet computes. */
    atrbvh_i_run *run;
    uint64_t done, crown, step, next, round, rounds;
    int cancel; /* set by thread 0 when the user cancels: skip the rest */
} walk_ctx;

/* Counts a treelet done; thread 0 reports progress now and then.  Inlined
 * into both of its callers (process, process_agg): a call per treelet
 * shows in the instruction count of the small treelets. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void progress(walk_ctx *c)
{
    uint64_t done;
    int cancel;
#ifdef _OPENMP
#pragma omp atomic capture
#endif
    done = ++c->done;
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
        w->dist, c->marks, (atrbvh_u32)c->round);
    if (applied == ATRBVH_TREELET_SKIPPED) {
        w->skipped++;
    } else {
        w->treelets++;
        w->applied += (uint64_t)applied;
    }
    progress(c);
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
    progress(c);
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
 * below s; lo = the cut: the top, whose frontier is already done. */
static void walk_serial(walk_ctx *c, uint32_t s, uint32_t lo)
{
    const atrbvh_treelet_tree *t = &c->t;
    uint32_t x = s;
    for (;;) {
        for (;;) {
            if (at_least(t, t->left[x], lo))
                x = t->left[x];
            else if (at_least(t, t->right[x], lo))
                x = t->right[x];
            else
                break;
        }
        for (;;) {
            uint32_t parent;
            visit(c, x);
            if (x == s)
                return;
            parent = t->parent[x];
            if (t->left[parent] == x && at_least(t, t->right[parent], lo)) {
                x = t->right[parent];
                break; /* descend into the right subtree */
            }
            x = parent;
        }
    }
}

/* The frontier of the top (the internal nodes of at least `cut`
 * primitives, the root among them): the crown nodes below `cut` whose
 * parent is in the top, into out[0 ..], in pre-order of the top.  Returns
 * their number, or cap + 1 when they do not fit. */
static size_t frontier(const walk_ctx *c, uint32_t cut, uint32_t *out,
                       size_t cap)
{
    const atrbvh_treelet_tree *t = &c->t;
    size_t k = 0;
    uint32_t x = 0;
    for (;;) {
        const uint32_t l = t->left[x], r = t->right[x];
        const int top_l = at_least(t, l, cut), top_r = at_least(t, r, cut);
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

/* One round over the crown: the frontier subtrees on the threads, then
 * the top on this thread; the whole crown on this thread when the tree is
 * small, or its frontier does not fit. */
static void walk_round(walk_ctx *c, int threads, uint32_t *list, size_t cap)
{
    const uint32_t root_count = c->t.count[0];
    uint32_t cut = atrbvh_i_frontier_cut(root_count, threads);
    size_t k = 0;
    int64_t i;
    /* above gamma, so that every top node is a crown node (gamma is at
     * most the root's count: no overflow) */
    if (cut <= c->gamma)
        cut = c->gamma + 1u;
    if (threads > 1 && root_count >= PARALLEL_MIN && root_count >= cut)
        k = frontier(c, cut, list, cap);
    if (k < 2u || k > cap) {
        walk_serial(c, 0, c->gamma);
        return;
    }
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
#endif
    for (i = 0; i < (int64_t)k; i++)
        walk_serial(c, list[i], c->gamma);
    walk_serial(c, 0, cut);
}

/* Per-thread scratch layout, each part aligned to 64 bytes. */
#define ALIGN64(x) (((x) + 63u) & ~(size_t)63u)

atrbvh_status atrbvh_i_optimise(atrbvh_i_tree *t, const atrbvh_i_config *cfg,
                                atrbvh_i_scratch *scratch, atrbvh_i_run *run,
                                atrbvh_error *error)
{
    atrbvh_i_scratch own;
    walk_ctx c;
    opt_worker *workers = NULL;
    unsigned char *block;
    size_t subsets = 0, pairs = 0, stride = 0, off_cost, off_count,
           off_split, off_dist, off_list, total, marks = 0, cap;
    uint32_t *list;
    unsigned round, n = cfg->treelet_size;
    /* The largest treelet of the build (ATRBVH_TREELET_AUTO: the rule's
     * largest) and the smallest subtree that can hold a treelet. */
    unsigned nmax = n == ATRBVH_TREELET_AUTO ? ATRBVH_AUTO_MAX : n;
    unsigned nmin = n == ATRBVH_TREELET_AUTO ? cfg->gamma : n;
    int threads = cfg->threads > 0 ? cfg->threads : 1, k;

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
     * n(n-1)/2 distances and, above 32 leaves, the treelet's arrays
     * (atrbvh_agg_layout, sized from the largest size used: 84 KiB at
     * 128, 17 KiB at 48; `pairs` counts it in doubles, a multiple of 8).
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
    if (!atrbvh_i_mul_size((size_t)threads, stride, &total) ||
        marks > ((size_t)-1 - total) / 2u)
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, (uint64_t)-1,
                             "optimise: scratch size overflows");
    total += 2u * marks;
    off_list = ALIGN64(total);
    if (off_list < total || cap > ((size_t)-1 - off_list) / sizeof(uint32_t))
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, (uint64_t)-1,
                             "optimise: scratch size overflows");
    total = off_list + cap * sizeof(uint32_t);
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
    for (k = 0; k < threads; k++) {
        unsigned char *base = block + (size_t)k * stride;
        memset(&workers[k], 0, sizeof workers[k]);
        workers[k].trbvh.box = (float *)(void *)base;
        workers[k].trbvh.cost = (double *)(void *)(base + off_cost);
        workers[k].trbvh.count = (uint32_t *)(void *)(base + off_count);
        workers[k].trbvh.split = (uint32_t *)(void *)(base + off_split);
        workers[k].dist = (double *)(void *)(base + off_dist);
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

    c.t.left = t->left;
    c.t.right = t->right;
    c.t.parent = t->parent;
    c.t.count = t->count;
    c.t.box = t->box;
    c.t.cost = t->cost;
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
        walk_round(&c, threads, list, cap);
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
    (void)dev;
    return atrbvh_i_optimise(&c->tree, run->cfg, c->scratch, run, error);
}
