/*
 * test_optimise.c - treelet restructuring (issue 3).
 *
 *  - TRBVH is optimal: the subset DP's cost equals an exhaustive
 *    enumeration of every binary tree on the treelet's leaves (written
 *    here, by leaf insertion), collapse on and off.
 *  - ATRBVH is the plain greedy clustering: a naive, uncached version
 *    written here makes the same merges with the same costs.
 *  - On whole trees: every round leaves a valid, consistent tree whose
 *    cost never rises; the result is the same bits for 1 to 4 threads.
 *  - Through atrbvh_build: identical node arrays for 1 to 4 threads, and
 *    a clear SAH gain over LBVH on the real scenes.
 *
 * Links the static core, so it calls the shared treelet functions and
 * atrbvh_i_optimise directly.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "cpu/cpu.h"
#include "shared/treelet.h"
#include "testutil.h"

/* ------------------------------------------------------------ helpers */
typedef struct rng {
    uint64_t s;
} rng;

static uint64_t rng_next(rng *r)
{
    /* xorshift64* */
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return r->s * 0x2545F4914F6CDD1Dull;
}

static void rng_seed(rng *r, uint64_t seed)
{
    r->s = seed * 0x9E3779B97F4A7C15ull + 1u;
    rng_next(r);
}

static float rng_float(rng *r) /* [0, 1) */
{
    return (float)(rng_next(r) >> 40) * (1.0f / 16777216.0f);
}

static uint32_t rng_below(rng *r, uint32_t n)
{
    return (uint32_t)(rng_next(r) % n);
}

/* The SAH node cost, written out here independently of arith.h:
 * ci*A + left + right (in that order), or ct*A*N when collapsing is
 * allowed and strictly cheaper. */
static double ref_area(const atrbvh_box *b)
{
    double dx = (double)b->max[0] - (double)b->min[0];
    double dy = (double)b->max[1] - (double)b->min[1];
    double dz = (double)b->max[2] - (double)b->min[2];
    double s = dx * dy;
    s = s + dy * dz;
    s = s + dz * dx;
    return 2.0 * s;
}

static atrbvh_box ref_union(const atrbvh_box *a, const atrbvh_box *b)
{
    atrbvh_box r;
    int k;
    for (k = 0; k < 3; k++) {
        r.min[k] = fminf(a->min[k], b->min[k]);
        r.max[k] = fmaxf(a->max[k], b->max[k]);
    }
    return r;
}

static double ref_node_cost(const atrbvh_cost_params *p, double area,
                            uint32_t count, double cl, double cr)
{
    double c = p->ci * area;
    c = c + cl;
    c = c + cr;
    if (p->collapse && (p->max_leaf == 0 || count <= p->max_leaf)) {
        double flat = p->ct * area;
        flat = flat * (double)count;
        if (flat < c)
            return flat;
    }
    return c;
}

static int same_box(const atrbvh_box *a, const atrbvh_box *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

/* Cost models the tests sweep: binary, collapse unbounded, collapse with
 * a maximum leaf size. */
static atrbvh_cost_params cost_model(int which)
{
    atrbvh_cost_params p;
    p.ci = 1.2;
    p.ct = 1.0;
    p.collapse = which > 0;
    p.max_leaf = which == 2 ? 6u : 0u;
    return p;
}

/* Leaf data of a random treelet.  mode 0: random boxes; 1: all identical;
 * 2: unit boxes on a 3x3x3 grid (many equal distances); 3: flat boxes
 * (zero area) mixed with random ones; 4: each leaf one of three boxes. */
static void random_leaves(rng *r, unsigned n, int mode,
                          const atrbvh_cost_params *p,
                          atrbvh_treelet_leaves *lv)
{
    unsigned k;
    for (k = 0; k < n; k++) {
        atrbvh_box b;
        int a;
        for (a = 0; a < 3; a++) {
            float lo, ext;
            switch (mode) {
            case 1:
                lo = 0.25f;
                ext = 0.5f;
                break;
            case 2:
                lo = (float)rng_below(r, 3);
                ext = 1.0f;
                break;
            case 4: {
                /* one of three boxes, picked per leaf: very many exactly
                 * equal distances in every row and column */
                static const float los[3] = {0.0f, 0.5f, 0.25f};
                static const float exts[3] = {1.0f, 0.5f, 1.0f};
                unsigned pick = (unsigned)(rng_next(r) >> 33) % 3u;
                lo = los[pick];
                ext = exts[pick];
                break;
            }
            case 3:
                lo = rng_float(r);
                ext = (k % 3u == 0u && a == 1) ? 0.0f : rng_float(r) * 0.4f;
                break;
            default:
                lo = rng_float(r);
                ext = rng_float(r) * 0.4f;
                break;
            }
            b.min[a] = lo;
            b.max[a] = lo + ext;
        }
        lv->box[k] = b;
        lv->count[k] = 1u + rng_below(r, 5);
        /* A subtree costs at least ct*A*N/... - any positive value is a
         * valid input to the optimisers; keep it near the real range. */
        lv->cost[k] = p->ct * ref_area(&b) * (double)lv->count[k] *
                          (0.3 + 0.7 * (double)rng_float(r)) +
                      (mode == 1 ? 0.0 : 1e-3 * (double)rng_float(r));
    }
}

/* A topology is a tree on the leaves: each leaf and each non-root local
 * node used as a child exactly once. */
static void check_topology(unsigned n, const atrbvh_treelet_topo *topo)
{
    unsigned used[2 * ATRBVH_TREELET_MAX];
    unsigned k;
    memset(used, 0, sizeof used);
    ck_assert_uint_lt(topo->root, n - 1);
    for (k = 0; k + 1 < n; k++) {
        ck_assert_uint_lt(topo->left[k], 2 * n - 1);
        ck_assert_uint_lt(topo->right[k], 2 * n - 1);
        used[topo->left[k]]++;
        used[topo->right[k]]++;
    }
    for (k = 0; k < 2 * n - 1; k++)
        ck_assert_uint_eq(used[k], k == n + topo->root ? 0u : 1u);
}

/* ------------------------------------------- exhaustive tree enumeration */
/* Every binary tree on leaves 0..n-1 arises exactly once by inserting
 * leaf k, for k = 1 .. n-1, above any node of the tree on leaves 0..k-1
 * (a new internal node with the old node and leaf k as children).  Nodes:
 * leaves 0..n-1, internal nodes n.. in creation order. */
typedef struct enum_state {
    unsigned n;
    const atrbvh_treelet_leaves *lv;
    const atrbvh_cost_params *p;
    unsigned child[2 * ATRBVH_TRBVH_MAX][2];
    unsigned parent[2 * ATRBVH_TRBVH_MAX];
    unsigned root;
    double best_canonical; /* child with the lowest leaf on the right */
    double best_other;     /* child with the lowest leaf on the left  */
    unsigned long trees;
} enum_state;

/* Cost of the subtree at `node`; lowest_right: the child holding the
 * lower leaf index is the right child (the DP's orientation). */
static double enum_eval(const enum_state *s, unsigned node, int lowest_right,
                        atrbvh_box *box, uint32_t *count, unsigned *lowest)
{
    atrbvh_box b0, b1;
    uint32_t n0, n1;
    unsigned m0, m1;
    double c0, c1, cl, cr;
    if (node < s->n) {
        *box = s->lv->box[node];
        *count = s->lv->count[node];
        *lowest = node;
        return s->lv->cost[node];
    }
    c0 = enum_eval(s, s->child[node][0], lowest_right, &b0, &n0, &m0);
    c1 = enum_eval(s, s->child[node][1], lowest_right, &b1, &n1, &m1);
    *box = ref_union(&b0, &b1);
    *count = n0 + n1;
    *lowest = m0 < m1 ? m0 : m1;
    if ((m0 < m1) == (lowest_right != 0)) {
        cl = c1;
        cr = c0;
    } else {
        cl = c0;
        cr = c1;
    }
    return ref_node_cost(s->p, ref_area(box), *count, cl, cr);
}

static void enum_trees(enum_state *s, unsigned k)
{
    unsigned nodes, x;
    if (k == s->n) {
        atrbvh_box b;
        uint32_t c;
        unsigned m;
        double a = enum_eval(s, s->root, 1, &b, &c, &m);
        double o = enum_eval(s, s->root, 0, &b, &c, &m);
        if (s->trees == 0 || a < s->best_canonical)
            s->best_canonical = a;
        if (s->trees == 0 || o < s->best_other)
            s->best_other = o;
        s->trees++;
        return;
    }
    /* Existing nodes: leaves 0..k-1 and internal n .. n+k-2. */
    nodes = 2 * k - 1;
    for (x = 0; x < nodes; x++) {
        unsigned node = x < k ? x : s->n + (x - k);
        unsigned y = s->n + k - 1; /* the new internal node */
        unsigned par = node == s->root ? ATRBVH_U32_MAX : s->parent[node];
        s->child[y][0] = node;
        s->child[y][1] = k;
        s->parent[node] = y;
        s->parent[k] = y;
        if (par == ATRBVH_U32_MAX) {
            s->root = y;
        } else {
            unsigned side = s->child[par][0] == node ? 0u : 1u;
            s->child[par][side] = y;
            s->parent[y] = par;
        }
        enum_trees(s, k + 1);
        /* undo */
        if (par == ATRBVH_U32_MAX) {
            s->root = node;
        } else {
            unsigned side = s->child[par][0] == y ? 0u : 1u;
            s->child[par][side] = node;
        }
        s->parent[node] = par;
    }
}

static unsigned long double_factorial_odd(unsigned n) /* (2n-3)!! */
{
    unsigned long r = 1;
    unsigned k;
    for (k = 3; k + 3 <= 2 * n; k += 2)
        r *= k;
    return r;
}

START_TEST(trbvh_is_optimal)
{
    static float sbox[6u << ATRBVH_TRBVH_MAX];
    static double scost[1u << ATRBVH_TRBVH_MAX];
    static uint32_t scount[1u << ATRBVH_TRBVH_MAX];
    static uint32_t ssplit[1u << ATRBVH_TRBVH_MAX];
    atrbvh_trbvh_scratch s;
    rng r;
    unsigned n, trial;
    int model, mode;
    s.box = sbox;
    s.cost = scost;
    s.count = scount;
    s.split = ssplit;
    rng_seed(&r, 7);
    for (model = 0; model < 3; model++) {
        atrbvh_cost_params p = cost_model(model);
        for (n = 3; n <= 7; n++) {
            for (trial = 0; trial < (n < 7 ? 12u : 4u); trial++) {
                atrbvh_treelet_leaves lv;
                atrbvh_treelet_topo topo;
                enum_state es;
                double dp, ev;
                mode = (int)(trial % 4u);
                random_leaves(&r, n, mode, &p, &lv);
                dp = atrbvh_trbvh_dp(&p, n, &lv, s, &topo);
                check_topology(n, &topo);
                ev = atrbvh_treelet_evaluate(&p, n, &lv, &topo);
                /* The extracted topology costs exactly what the DP says. */
                ck_assert_msg(ev == dp, "n %u: evaluate %.17g != dp %.17g",
                              n, ev, dp);
                memset(&es, 0, sizeof es);
                es.n = n;
                es.lv = &lv;
                es.p = &p;
                es.root = 0;
                enum_trees(&es, 1);
                ck_assert_uint_eq(es.trees, double_factorial_odd(n));
                /* Exactly the optimum in the DP's child orientation (the
                 * sums are the same, and rounding is monotone)... */
                ck_assert_msg(dp == es.best_canonical,
                              "model %d n %u mode %d: dp %.17g, exhaustive "
                              "%.17g",
                              model, n, mode, dp, es.best_canonical);
                /* ...and the optimum in the other orientation up to the
                 * rounding of the left/right sum order. */
                ck_assert_msg(fabs(dp - es.best_other) <=
                                  1e-12 * fabs(es.best_other),
                              "n %u: dp %.17g vs %.17g", n, dp,
                              es.best_other);
            }
        }
    }
}
END_TEST

/* n = 8 .. 10 too: the DP (u32 masks) must still match the enumeration
 * for n = 8 (135135 trees); 9 and 10 are checked for self-consistency. */
START_TEST(trbvh_large_n)
{
    static float sbox[6u << ATRBVH_TRBVH_MAX];
    static double scost[1u << ATRBVH_TRBVH_MAX];
    static uint32_t scount[1u << ATRBVH_TRBVH_MAX];
    static uint32_t ssplit[1u << ATRBVH_TRBVH_MAX];
    atrbvh_trbvh_scratch s;
    rng r;
    unsigned n;
    int model;
    s.box = sbox;
    s.cost = scost;
    s.count = scount;
    s.split = ssplit;
    rng_seed(&r, 8);
    for (model = 0; model < 3; model++) {
        atrbvh_cost_params p = cost_model(model);
        for (n = 8; n <= ATRBVH_TRBVH_MAX; n++) {
            atrbvh_treelet_leaves lv;
            atrbvh_treelet_topo topo;
            double dp;
            random_leaves(&r, n, 0, &p, &lv);
            dp = atrbvh_trbvh_dp(&p, n, &lv, s, &topo);
            check_topology(n, &topo);
            ck_assert(atrbvh_treelet_evaluate(&p, n, &lv, &topo) == dp);
            if (n == 8) {
                enum_state es;
                memset(&es, 0, sizeof es);
                es.n = n;
                es.lv = &lv;
                es.p = &p;
                enum_trees(&es, 1);
                ck_assert(dp == es.best_canonical);
            }
        }
    }
}
END_TEST

/* ------------------------------------------------- plain subset DP */
/* The subset DP written the plain way (one subset at a time: its box as
 * atrbvh_box_union(box of S minus its highest leaf, that leaf), every
 * partition P = (P - delta) & S in turn, strict <): atrbvh_trbvh_dp
 * computes its tables differently (boxes, areas and counts in a separate
 * pass, four subsets at a time on x86; the partition loop over costs
 * only, by pairs P = E, E|lb, the complement's cost from a mirror kept in
 * the box planes, the splits found again for the extracted subsets only)
 * and must fill them with exactly these bits: every cost, and the split
 * of every subset of the topology, ties included (swapping a pair's
 * order fails here). */
static void plain_dp(const atrbvh_cost_params *p, unsigned n,
                     const atrbvh_treelet_leaves *lv, double *cost,
                     uint32_t *split)
{
    static atrbvh_box box[1u << ATRBVH_TRBVH_MAX];
    static uint32_t cnt[1u << ATRBVH_TRBVH_MAX];
    uint32_t k, S;
    for (k = 0; k < n; k++) {
        uint32_t bit = 1u << k;
        box[bit] = lv->box[k];
        cnt[bit] = lv->count[k];
        cost[bit] = lv->cost[k];
        split[bit] = 0;
        for (S = bit + 1u; S < 2u * bit; S++) {
            uint32_t delta = (S - 1u) & S, P = (0u - delta) & S, bestp;
            double area, base, best;
            box[S] = atrbvh_box_union(box[S ^ bit], lv->box[k]);
            cnt[S] = cnt[S ^ bit] + lv->count[k];
            area = atrbvh_box_area(box[S]);
            base = p->ci * area;
            best = base + cost[P];
            best = best + cost[S ^ P];
            bestp = P;
            for (P = (P - delta) & S; P; P = (P - delta) & S) {
                double c = base + cost[P];
                c = c + cost[S ^ P];
                if (c < best) {
                    best = c;
                    bestp = P;
                }
            }
            if (atrbvh_may_collapse(p, cnt[S])) {
                double flat = p->ct * area;
                flat = flat * (double)cnt[S];
                if (flat < best)
                    best = flat;
            }
            cost[S] = best;
            split[S] = bestp;
        }
    }
}

START_TEST(trbvh_matches_plain_dp)
{
    static float sbox[6u << ATRBVH_TRBVH_MAX];
    static double scost[1u << ATRBVH_TRBVH_MAX];
    static uint32_t scount[1u << ATRBVH_TRBVH_MAX];
    static uint32_t ssplit[1u << ATRBVH_TRBVH_MAX];
    static double rcost[1u << ATRBVH_TRBVH_MAX];
    static uint32_t rsplit[1u << ATRBVH_TRBVH_MAX];
    atrbvh_trbvh_scratch s;
    rng r;
    unsigned n, trial, ties = 0;
    int model;
    s.box = sbox;
    s.cost = scost;
    s.count = scount;
    s.split = ssplit;
    rng_seed(&r, 12);
    for (model = 0; model < 3; model++) {
        atrbvh_cost_params p = cost_model(model);
        for (n = ATRBVH_TRBVH_MIN; n <= ATRBVH_TRBVH_MAX; n++) {
            for (trial = 0; trial < 10u; trial++) {
                atrbvh_treelet_leaves lv;
                atrbvh_treelet_topo topo;
                uint32_t S, P;
                double dp;
                random_leaves(&r, n, (int)(trial % 5u), &p, &lv);
                if (trial >= 5u) {
                    /* equal leaf costs: many partitions tie exactly */
                    for (S = 0; S < n; S++)
                        lv.cost[S] = (double)(1u + S % 2u);
                }
                dp = atrbvh_trbvh_dp(&p, n, &lv, s, &topo);
                plain_dp(&p, n, &lv, rcost, rsplit);
                for (S = 1; S < (1u << n); S++) {
                    ck_assert_msg(memcmp(&scost[S], &rcost[S],
                                         sizeof(double)) == 0,
                                  "model %d n %u trial %u subset %#x: cost "
                                  "%.17g, plain %.17g",
                                  model, n, trial, S, scost[S], rcost[S]);
                    /* count subsets where a later partition ties */
                    if ((S & (S - 1u)) != 0u) {
                        uint32_t delta = (S - 1u) & S;
                        for (P = (0u - delta) & S; P; P = (P - delta) & S) {
                            if (P > rsplit[S] && !(rcost[P] + rcost[S ^ P] !=
                                                   rcost[rsplit[S]] +
                                                       rcost[S ^ rsplit[S]]))
                                ties++;
                        }
                    }
                }
                ck_assert(memcmp(&dp, &rcost[(1u << n) - 1u], sizeof dp) ==
                          0);
                /* The split of every subset of the extracted topology
                 * (the only ones atrbvh_trbvh_extract sets), from the
                 * root down the plain DP's splits. */
                {
                    uint32_t stack[ATRBVH_TRBVH_MAX], sp = 0, seen = 0;
                    stack[sp++] = (1u << n) - 1u;
                    while (sp > 0u) {
                        S = stack[--sp];
                        seen++;
                        ck_assert_msg(ssplit[S] == rsplit[S],
                                      "model %d n %u trial %u subset %#x: "
                                      "split %#x, plain %#x",
                                      model, n, trial, S, ssplit[S],
                                      rsplit[S]);
                        P = rsplit[S];
                        if ((P & (P - 1u)) != 0u)
                            stack[sp++] = P;
                        if (((S ^ P) & ((S ^ P) - 1u)) != 0u)
                            stack[sp++] = S ^ P;
                    }
                    ck_assert_uint_eq(seen, n - 1u);
                }
            }
        }
    }
    /* the sweep did exercise ties (the first of equal minima is kept) */
    ck_assert_uint_gt(ties, 1000u);
}
END_TEST

/* ----------------------------------------------- naive greedy clustering */
/* Plain greedy clustering, no cache: every step recomputes every pair's
 * union area over the live slots 0..m-1 in linear order (row i = 1..m-1,
 * column j = 0..i-1), keeps the first minimum, merges into slot j (left =
 * slot j, right = slot i) and moves the last slot into slot i.  Records
 * each merge's children codes and cost. */
static void naive_greedy(const atrbvh_cost_params *p, unsigned n,
                         const atrbvh_treelet_leaves *lv, unsigned *left,
                         unsigned *right, double *cost)
{
    atrbvh_box box[ATRBVH_TREELET_MAX];
    double c[ATRBVH_TREELET_MAX];
    uint32_t cnt[ATRBVH_TREELET_MAX];
    unsigned code[ATRBVH_TREELET_MAX];
    unsigned m, i, j, q = 0;
    for (i = 0; i < n; i++) {
        box[i] = lv->box[i];
        c[i] = lv->cost[i];
        cnt[i] = lv->count[i];
        code[i] = i;
    }
    for (m = n; m > 1; m--) {
        unsigned bi = 1, bj = 0;
        double best = 0.0;
        int first = 1;
        atrbvh_box u;
        for (i = 1; i < m; i++)
            for (j = 0; j < i; j++) {
                atrbvh_box b = ref_union(&box[i], &box[j]);
                double d = ref_area(&b);
                if (first || d < best) {
                    best = d;
                    bi = i;
                    bj = j;
                    first = 0;
                }
            }
        u = ref_union(&box[bj], &box[bi]);
        left[q] = code[bj];
        right[q] = code[bi];
        cost[q] = ref_node_cost(p, ref_area(&u), cnt[bj] + cnt[bi], c[bj],
                                c[bi]);
        box[bj] = u;
        c[bj] = cost[q];
        cnt[bj] += cnt[bi];
        code[bj] = n + q;
        box[bi] = box[m - 1];
        c[bi] = c[m - 1];
        cnt[bi] = cnt[m - 1];
        code[bi] = code[m - 1];
        q++;
    }
}

/* A worker's ATRBVH scratch for treelets of up to ATRBVH_TREELET_MAX
 * leaves, laid out as the drivers lay it out (atrbvh_agg_layout), 64-byte
 * aligned. */
static atrbvh_agg_scratch agg_scratch(void)
{
    static unsigned char block[65536 + 64];
    unsigned char *base =
        (unsigned char *)(((uintptr_t)block + 63u) & ~(uintptr_t)63u);
    atrbvh_agg_scratch s;
    ck_assert_uint_le(atrbvh_agg_layout(NULL, ATRBVH_TREELET_MAX, NULL),
                      65536);
    atrbvh_agg_layout(base, ATRBVH_TREELET_MAX, &s);
    return s;
}

/* atrbvh_agg_layout: the size it returns (which the CPU driver and the
 * OpenCL host allocate per worker) holds every array it carves (which the
 * kernel and the driver write), each 64-byte aligned and apart from the
 * others; the formation's and write-back's arrays are there above
 * ATRBVH_TREELET_MAX leaves (atrbvh_agg_process_large writes them) and
 * null up to it (the private path keeps them). */
START_TEST(agg_layout_fits)
{
    static unsigned char block[131072 + 64];
    static const atrbvh_u32 sizes[] = {3, 9, 16, 31, 32, 33, 48, 128};
    unsigned char *base =
        (unsigned char *)(((uintptr_t)block + 63u) & ~(uintptr_t)63u);
    unsigned i, a, b;
    for (i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        const atrbvh_u32 n = sizes[i];
        const size_t total = (size_t)atrbvh_agg_layout(NULL, n, NULL);
        const int large = n > ATRBVH_TREELET_MAX;
        atrbvh_agg_scratch s;
        struct {
            const void *p;
            size_t bytes;
        } part[23];
        unsigned np = 0;
        ck_assert_uint_le(total, sizeof block - 64u);
        memset(&s, 0xA5, sizeof s);
        ck_assert_uint_eq(atrbvh_agg_layout(base, n, &s), total);
        ck_assert_uint_eq(s.w, n + ATRBVH_SOA_PAD);
#define PART(f, entries)                                                      \
    do {                                                                      \
        part[np].p = (const void *)s.f;                                       \
        part[np++].bytes = (size_t)(entries) * sizeof s.f[0];                 \
    } while (0)
        PART(dist, n * (n - 1u) / 2u);
        PART(leaf, n);
        PART(box, n);
        PART(cost, n);
        PART(count, n);
        PART(code, n);
        PART(rmin, n);
        PART(rcol, n);
        PART(soa, 6u * s.w);
        PART(area_of, s.w);
        PART(left, n);
        PART(right, n);
        PART(tbox, n);
        PART(tcount, n);
        PART(tcost, n);
        PART(flat, n);
        if (large) {
            PART(internal, n);
            PART(area, n);
            PART(order, n);
            PART(ids, n);
            PART(node_of, 2u * n);
            PART(stack, n);
        } else {
            ck_assert_ptr_null(s.internal);
            ck_assert_ptr_null(s.area);
            ck_assert_ptr_null(s.order);
            ck_assert_ptr_null(s.ids);
            ck_assert_ptr_null(s.node_of);
            ck_assert_ptr_null(s.stack);
        }
#undef PART
        for (a = 0; a < np; a++) {
            const unsigned char *p = (const unsigned char *)part[a].p;
            ck_assert_ptr_nonnull(p);
            ck_assert_uint_eq((uintptr_t)p % 64u, 0);
            ck_assert(p >= base && p + part[a].bytes <= base + total);
            for (b = 0; b < a; b++) {
                const unsigned char *q = (const unsigned char *)part[b].p;
                ck_assert_msg(p + part[a].bytes <= q ||
                                  q + part[b].bytes <= p,
                              "n %u: parts %u and %u overlap", n, a, b);
            }
        }
    }
}
END_TEST

/* The agglomeration of gathered leaves: a tree of just those leaves
 * (nodes 0 .. n-1, as the agglomeration reads them) and a treelet of
 * them in slot order. */
static double agglomerate_leaves(const atrbvh_cost_params *p, unsigned n,
                                 const atrbvh_treelet_leaves *lv,
                                 const atrbvh_agg_scratch *s,
                                 atrbvh_treelet_topo *topo)
{
    static atrbvh_box box[ATRBVH_TREELET_MAX];
    static double cost[ATRBVH_TREELET_MAX];
    static atrbvh_u32 count[ATRBVH_TREELET_MAX];
    atrbvh_treelet_tree t;
    atrbvh_treelet tl;
    unsigned a;
    memset(&t, 0, sizeof t);
    t.box = box;
    t.cost = cost;
    t.count = count;
    tl.n = n;
    for (a = 0; a < n; a++) {
        box[a] = lv->box[a];
        cost[a] = lv->cost[a];
        count[a] = lv->count[a];
        tl.leaf[a] = a;
    }
    return atrbvh_agglomerate_at(p, &t, &tl, s, topo);
}

START_TEST(atrbvh_is_naive_greedy)
{
    const atrbvh_agg_scratch agg = agg_scratch();
    rng r;
    unsigned n, trial;
    int model, ties = 0;
    rng_seed(&r, 11);
    for (model = 0; model < 3; model++) {
        atrbvh_cost_params p = cost_model(model);
        for (n = 3; n <= ATRBVH_TREELET_MAX; n++) {
            for (trial = 0; trial < 20; trial++) {
                atrbvh_treelet_leaves lv;
                atrbvh_treelet_topo topo;
                unsigned left[ATRBVH_TREELET_MAX], right[ATRBVH_TREELET_MAX];
                double cost[ATRBVH_TREELET_MAX], root;
                unsigned q;
                int mode = (int)(trial % 5u);
                random_leaves(&r, n, mode, &p, &lv);
                atrbvh_treelet_topo merged;
                root = agglomerate_leaves(&p, n, &lv, &agg, &topo);
                check_topology(n, &topo);
                ck_assert_uint_eq(topo.root, n - 2);
                /* the agglomeration leaves each merge's box, count and cost
                 * (atrbvh_treelet_process skips evaluate on that
                 * promise): bit for bit what evaluate computes. */
                merged = topo;
                ck_assert(atrbvh_treelet_evaluate(&p, n, &lv, &topo) == root);
                ck_assert(memcmp(merged.box, topo.box,
                                 (n - 1) * sizeof topo.box[0]) == 0);
                ck_assert(memcmp(merged.count, topo.count,
                                 (n - 1) * sizeof topo.count[0]) == 0);
                ck_assert(memcmp(merged.cost, topo.cost,
                                 (n - 1) * sizeof topo.cost[0]) == 0);
                naive_greedy(&p, n, &lv, left, right, cost);
                for (q = 0; q + 1 < n; q++) {
                    ck_assert_msg(topo.left[q] == left[q] &&
                                      topo.right[q] == right[q],
                                  "model %d n %u mode %d merge %u: (%u, %u) "
                                  "vs naive (%u, %u)",
                                  model, n, mode, q, topo.left[q],
                                  topo.right[q], left[q], right[q]);
                    /* evaluate gives each local node's cost */
                    ck_assert_msg(topo.cost[q] == cost[q],
                                  "merge %u cost %.17g vs %.17g", q,
                                  topo.cost[q], cost[q]);
                }
                ck_assert(root == cost[n - 2]);
                if (mode == 1 || mode == 2 || mode == 4)
                    ties++;
            }
        }
    }
    ck_assert_int_gt(ties, 0);
}
END_TEST

#ifdef ATRBVH_AGG_QUADS
/* The agglomerations in AVX's lanes (atrbvh_agglomerate4, the CPU's path
 * for treelets side by side) give each lane exactly what
 * atrbvh_agglomerate_at gives its treelet: the merges, boxes, counts and
 * costs bit for bit, and the root's cost.  Four different treelets (a
 * different leaf mode each, ties among them), or lanes repeating the
 * first as lane_batch fills them, for every size and cost model. */
START_TEST(atrbvh_lanes_are_scalar)
{
    enum { M = ATRBVH_TREELET_MAX };
    static atrbvh_box box[4 * M];
    static double cost[4 * M];
    static atrbvh_u32 count[4 * M];
    static double dist4[4 * M * (M - 1) / 2 + 4];
    const atrbvh_agg_scratch agg = agg_scratch();
    /* 32-byte aligned, as the driver's scratch */
    double *d4 = (double *)(void *)(((uintptr_t)dist4 + 31u) & ~(uintptr_t)31u);
    atrbvh_treelet_tree t;
    rng r;
    unsigned n, trial, l, a, q, ties = 0;
    int model;
    if (!__builtin_cpu_supports("avx")) {
        fprintf(stderr, "test_optimise: no AVX here, lanes not tested\n");
        return;
    }
    memset(&t, 0, sizeof t);
    t.box = box;
    t.cost = cost;
    t.count = count;
    rng_seed(&r, 29);
    for (model = 0; model < 3; model++) {
        atrbvh_cost_params p = cost_model(model);
        for (n = 3; n <= M; n++)
            for (trial = 0; trial < 12; trial++) {
                atrbvh_treelet tl[4];
                const atrbvh_treelet *in[4];
                atrbvh_treelet_topo topo[4], ref;
                atrbvh_treelet_topo *out[4];
                double found[4], root;
                /* trials 8 and up: lanes 1.. repeat lane 0 (2, 3 or 4
                 * treelets used) */
                const unsigned used = trial < 8u ? 4u : 2u + trial % 3u;
                for (l = 0; l < 4u; l++) {
                    atrbvh_treelet_leaves lv;
                    const int mode = (int)((trial + l) % 5u);
                    random_leaves(&r, n, mode, &p, &lv);
                    ties += mode == 1 || mode == 2 || mode == 4;
                    /* trials 3 and 7: zeros of both signs in the boxes,
                     * where only the unions' operand order says which
                     * one a merged box holds */
                    if (trial % 4u == 3u)
                        for (a = 0; a < n; a++) {
                            const unsigned bits = rng_below(&r, 8);
                            lv.box[a].min[bits % 3u] = bits & 4u ? -0.0f : 0.0f;
                            lv.box[a].max[bits % 3u] = bits & 4u ? 0.0f : -0.0f;
                        }
                    tl[l].n = n;
                    for (a = 0; a < n; a++) {
                        /* leaf ids in no particular order */
                        const atrbvh_u32 id = l * M + (a * 7u + trial) % n;
                        tl[l].leaf[a] = id;
                        box[id] = lv.box[a];
                        cost[id] = lv.cost[a];
                        count[id] = lv.count[a];
                    }
                    in[l] = l < used ? &tl[l] : &tl[0];
                    out[l] = &topo[l];
                }
                atrbvh_agglomerate4(&p, n, &t, in, d4, out, found);
                for (l = 0; l < 4u; l++) {
                    root = atrbvh_agglomerate_at(&p, &t, in[l], &agg, &ref);
                    ck_assert_msg(memcmp(&found[l], &root, sizeof root) == 0,
                                  "model %d n %u trial %u lane %u: root cost "
                                  "%.17g, scalar %.17g",
                                  model, n, trial, l, found[l], root);
                    ck_assert_uint_eq(topo[l].root, ref.root);
                    /* the collapse decisions recorded, lane for lane */
                    ck_assert_uint_eq(topo[l].flat, ref.flat);
                    for (q = 0; q + 1u < n; q++) {
                        ck_assert_msg(topo[l].left[q] == ref.left[q] &&
                                          topo[l].right[q] == ref.right[q],
                                      "model %d n %u trial %u lane %u merge "
                                      "%u: (%u, %u), scalar (%u, %u)",
                                      model, n, trial, l, q, topo[l].left[q],
                                      topo[l].right[q], ref.left[q],
                                      ref.right[q]);
                        ck_assert(same_box(&topo[l].box[q], &ref.box[q]));
                        ck_assert_uint_eq(topo[l].count[q], ref.count[q]);
                        ck_assert(memcmp(&topo[l].cost[q], &ref.cost[q],
                                         sizeof ref.cost[q]) == 0);
                    }
                }
            }
    }
    ck_assert_uint_gt(ties, 100u);
}
END_TEST
#endif

/* Treelet formation on a hand-made tree: the largest-area expandable leaf
 * goes first, ties to the lowest slot, real leaves never expand. */
START_TEST(formation_rule)
{
    /* 5 leaves (ids 4..8), internal 0..3:
     *        0
     *      1    2
     *     4 5  3  6
     *         7 8
     * areas: node 1 area 6 (box 1x1x1 -> 6), node 2 the same (tie),
     * node 3 smaller. */
    atrbvh_u32 left[4] = {1, 4, 3, 7}, right[4] = {2, 5, 6, 8};
    atrbvh_u32 parent[9], count[9] = {5, 2, 3, 2, 1, 1, 1, 1, 1};
    atrbvh_box box[9];
    double cost[9] = {0};
    atrbvh_treelet_tree t;
    atrbvh_treelet tl;
    int k;
    for (k = 0; k < 9; k++) {
        box[k].min[0] = box[k].min[1] = box[k].min[2] = 0.0f;
        box[k].max[0] = box[k].max[1] = box[k].max[2] =
            k == 0 ? 2.0f : k <= 2 ? 1.0f : 0.5f;
        /* leaves bigger than internal node 3: must still not expand */
        if (k >= 4)
            box[k].max[0] = 0.9f;
    }
    parent[0] = ATRBVH_U32_MAX;
    t.left = left;
    t.right = right;
    t.parent = parent;
    t.count = count;
    t.box = box;
    t.cost = cost;
    t.flat = NULL;
    t.n_internal = 4;
    ck_assert_uint_eq(atrbvh_treelet_form(&t, 0, 3, &tl), 3);
    /* slot 0 (node 1) and 1 (node 2) tie: slot 0 expands. */
    ck_assert_uint_eq(tl.internal[1], 1);
    ck_assert_uint_eq(tl.leaf[0], 4);
    ck_assert_uint_eq(tl.leaf[1], 2);
    ck_assert_uint_eq(tl.leaf[2], 5);
    ck_assert_uint_eq(atrbvh_treelet_form(&t, 0, 5, &tl), 5);
    /* then node 2 (slot 1), then node 3 (its left took slot 1) */
    ck_assert_uint_eq(tl.internal[2], 2);
    ck_assert_uint_eq(tl.internal[3], 3);
    ck_assert_uint_eq(tl.leaf[0], 4);
    ck_assert_uint_eq(tl.leaf[1], 7);
    ck_assert_uint_eq(tl.leaf[2], 5);
    ck_assert_uint_eq(tl.leaf[3], 6);
    ck_assert_uint_eq(tl.leaf[4], 8);
    /* only 5 leaves exist: asking for 6 stops at 5 */
    ck_assert_uint_eq(atrbvh_treelet_form(&t, 0, 6, &tl), 5);
}
END_TEST

/* ------------------------------------------------------------ whole trees */
typedef struct test_tree {
    atrbvh_i_tree t;
    uint32_t *storage;
    atrbvh_box *boxes;
    double *costs;
} test_tree;

static void tree_free(test_tree *tt)
{
    free(tt->storage);
    free(tt->boxes);
    free(tt->costs);
    memset(tt, 0, sizeof *tt);
}

static void tree_alloc(test_tree *tt, uint32_t n)
{
    size_t nodes = 2 * (size_t)n - 1;
    memset(tt, 0, sizeof *tt);
    tt->storage = malloc(sizeof(uint32_t) * (2 * (n - 1) + 2 * nodes + n));
    tt->boxes = malloc(sizeof(atrbvh_box) * nodes);
    tt->costs = malloc(sizeof(double) * nodes);
    ck_assert(tt->storage && tt->boxes && tt->costs);
    tt->t.n = n;
    tt->t.left = tt->storage;
    tt->t.right = tt->t.left + (n - 1);
    tt->t.parent = tt->t.right + (n - 1);
    tt->t.count = tt->t.parent + nodes;
    tt->t.leaf_prim = tt->t.count + nodes;
    tt->t.box = tt->boxes;
    tt->t.cost = tt->costs;
}

static void tree_copy(test_tree *dst, const test_tree *src)
{
    uint32_t n = src->t.n;
    size_t nodes = 2 * (size_t)n - 1;
    tree_alloc(dst, n);
    memcpy(dst->storage, src->storage,
           sizeof(uint32_t) * (2 * (n - 1) + 2 * nodes + n));
    memcpy(dst->boxes, src->boxes, sizeof(atrbvh_box) * nodes);
    memcpy(dst->costs, src->costs, sizeof(double) * nodes);
}

static int tree_same(const test_tree *a, const test_tree *b)
{
    uint32_t n = a->t.n;
    size_t nodes = 2 * (size_t)n - 1;
    return a->t.n == b->t.n &&
           memcmp(a->storage, b->storage,
                  sizeof(uint32_t) * (2 * (n - 1) + 2 * nodes + n)) == 0 &&
           memcmp(a->boxes, b->boxes, sizeof(atrbvh_box) * nodes) == 0 &&
           memcmp(a->costs, b->costs, sizeof(double) * nodes) == 0;
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* A random tree over n random leaf boxes: leaves sorted along x, the
 * ranges split at random points (a poor but coherent tree, so there is
 * much to restructure).  Internal ids in creation order (parents before
 * children), boxes, counts and costs filled bottom-up as refit would.
 * box_mode 0: random boxes; 1: unit boxes on a small grid (ties). */
static void tree_shaped(test_tree *tt, uint32_t n, uint64_t seed,
                        int box_mode, uint32_t teeth,
                        const atrbvh_cost_params *p);

static void tree_random(test_tree *tt, uint32_t n, uint64_t seed,
                        int box_mode, const atrbvh_cost_params *p)
{
    tree_shaped(tt, n, seed, box_mode, 0, p);
}

/* tree_random's tree, or with teeth > 0 a comb: a range of more than
 * `teeth` leaves splits off its first `teeth` (the left child, a tooth),
 * a smaller one in halves. */
static void tree_shaped(test_tree *tt, uint32_t n, uint64_t seed,
                        int box_mode, uint32_t teeth,
                        const atrbvh_cost_params *p)
{
    rng r;
    uint32_t i, next = 1, sp = 0;
    uint32_t *stack;
    float *keys;
    atrbvh_i_tree *t;
    rng_seed(&r, seed);
    tree_alloc(tt, n);
    t = &tt->t;
    keys = malloc(sizeof(float) * n * 2);
    stack = malloc(sizeof(uint32_t) * 3 * (size_t)n);
    ck_assert(keys && stack);
    for (i = 0; i < n; i++) {
        /* key = x then an index so the sort is total */
        keys[2 * i] = box_mode ? (float)rng_below(&r, 8) : rng_float(&r);
        keys[2 * i + 1] = (float)i;
    }
    qsort(keys, n, 2 * sizeof(float), cmp_float);
    for (i = 0; i < n; i++) {
        atrbvh_box *b = &t->box[n - 1 + i];
        int a;
        for (a = 0; a < 3; a++) {
            float lo = a == 0 ? keys[2 * i]
                              : box_mode ? (float)rng_below(&r, 4)
                                         : rng_float(&r);
            float ext = box_mode ? 1.0f : 0.002f + 0.02f * rng_float(&r);
            b->min[a] = lo;
            b->max[a] = lo + ext;
        }
        t->count[n - 1 + i] = 1;
        t->cost[n - 1 + i] = p->ct * ref_area(b);
        t->leaf_prim[i] = i;
    }
    t->parent[n > 1 ? 0 : 0] = ATRBVH_NONE;
    if (n > 1) {
        /* (node, lo, hi): internal node over leaves lo..hi-1 */
        stack[0] = 0;
        stack[1] = 0;
        stack[2] = n;
        sp = 1;
        while (sp > 0) {
            uint32_t node, lo, hi, mid, side;
            sp--;
            node = stack[3 * sp];
            lo = stack[3 * sp + 1];
            hi = stack[3 * sp + 2];
            if (teeth == 0)
                mid = lo + 1 + rng_below(&r, hi - lo - 1);
            else
                mid = hi - lo > teeth ? lo + teeth : lo + (hi - lo) / 2;
            for (side = 0; side < 2; side++) {
                uint32_t a = side ? mid : lo, b = side ? hi : mid, child;
                if (b - a == 1) {
                    child = n - 1 + a;
                } else {
                    child = next++;
                    stack[3 * sp] = child;
                    stack[3 * sp + 1] = a;
                    stack[3 * sp + 2] = b;
                    sp++;
                }
                if (side)
                    t->right[node] = child;
                else
                    t->left[node] = child;
                t->parent[child] = node;
            }
        }
        ck_assert_uint_eq(next, n - 1);
        /* parents have smaller ids than their internal children */
        for (i = n - 1; i-- > 0;) {
            uint32_t l = t->left[i], rr = t->right[i];
            t->box[i] = ref_union(&t->box[l], &t->box[rr]);
            t->count[i] = t->count[l] + t->count[rr];
            t->cost[i] = ref_node_cost(p, ref_area(&t->box[i]), t->count[i],
                                       t->cost[l], t->cost[rr]);
        }
    }
    free(keys);
    free(stack);
}

/* The invariants of the tree after any round: every node reachable from
 * the root exactly once, parents consistent, leaves untouched (compared
 * with `orig`), every internal box the exact union of its children's,
 * counts the sum, costs exactly ref_node_cost of the children. */
static void tree_check(const test_tree *tt, const test_tree *orig,
                       const atrbvh_cost_params *p)
{
    const atrbvh_i_tree *t = &tt->t;
    uint32_t n = t->n, nodes = 2 * n - 1, sp = 0, seen = 0, i;
    uint32_t *stack = malloc(sizeof(uint32_t) * nodes);
    unsigned char *visited = calloc(nodes, 1);
    ck_assert(stack && visited);
    ck_assert_uint_eq(t->parent[0], ATRBVH_NONE);
    stack[sp++] = 0;
    while (sp > 0) {
        uint32_t x = stack[--sp];
        ck_assert_uint_lt(x, nodes);
        ck_assert_msg(!visited[x], "node %u reached twice", x);
        visited[x] = 1;
        seen++;
        if (x < n - 1) {
            uint32_t l = t->left[x], r = t->right[x];
            atrbvh_box u;
            ck_assert_uint_lt(l, nodes);
            ck_assert_uint_lt(r, nodes);
            ck_assert_msg(t->parent[l] == x && t->parent[r] == x,
                          "parents of the children of %u", x);
            u = ref_union(&t->box[l], &t->box[r]);
            ck_assert_msg(same_box(&u, &t->box[x]), "box of %u", x);
            ck_assert_uint_eq(t->count[x], t->count[l] + t->count[r]);
            ck_assert_msg(t->cost[x] == ref_node_cost(p, ref_area(&u),
                                                      t->count[x],
                                                      t->cost[l],
                                                      t->cost[r]),
                          "cost of %u", x);
            stack[sp++] = l;
            stack[sp++] = r;
        }
    }
    ck_assert_uint_eq(seen, nodes);
    for (i = n - 1; i < nodes; i++) {
        ck_assert(same_box(&t->box[i], &orig->t.box[i]));
        ck_assert(t->count[i] == 1 && t->cost[i] == orig->t.cost[i]);
    }
    ck_assert(memcmp(t->leaf_prim, orig->t.leaf_prim,
                     sizeof(uint32_t) * n) == 0);
    free(stack);
    free(visited);
}

static atrbvh_i_config config(atrbvh_method method, unsigned n,
                              unsigned rounds, unsigned gamma,
                              const atrbvh_cost_params *p, int threads)
{
    atrbvh_i_config c;
    memset(&c, 0, sizeof c);
    c.method = method;
    c.treelet_size = n;
    c.rounds = rounds;
    c.gamma = gamma;
    c.cost = *p;
    c.threads = threads;
    return c;
}

/* Round by round (a round r of a run is one round with gamma * 2^r):
 * valid tree, cost never up; and the rounds together are one run. */
static void rounds_case(atrbvh_method method, unsigned n, unsigned rounds,
                        uint32_t prims, int box_mode, int model)
{
    atrbvh_cost_params p = cost_model(model);
    test_tree orig, t, whole;
    atrbvh_error err;
    atrbvh_i_config c;
    unsigned r;
    double before, first;
    tree_random(&orig, prims, 1000u + prims + (uint64_t)box_mode, box_mode,
                &p);
    tree_check(&orig, &orig, &p);
    tree_copy(&t, &orig);
    first = before = t.t.cost[0];
    for (r = 0; r < rounds; r++) {
        c = config(method, n, 1, n << r, &p, 1);
        ck_assert_int_eq(atrbvh_i_optimise(&t.t, NULL, &c, NULL, NULL, &err), ATRBVH_OK);
        tree_check(&t, &orig, &p);
        ck_assert_msg(t.t.cost[0] <= before,
                      "round %u raised the cost %.17g -> %.17g", r, before,
                      t.t.cost[0]);
        before = t.t.cost[0];
    }
    /* a random tree always has something to gain */
    ck_assert_msg(before < 0.95 * first, "cost %.6g -> %.6g", first, before);
    tree_copy(&whole, &orig);
    c = config(method, n, rounds, n, &p, 2);
    ck_assert_int_eq(atrbvh_i_optimise(&whole.t, NULL, &c, NULL, NULL, &err), ATRBVH_OK);
    ck_assert(tree_same(&whole, &t));
    tree_free(&orig);
    tree_free(&t);
    tree_free(&whole);
}

START_TEST(trbvh_rounds)
{
    int model = _i % 3;
    unsigned n = _i < 3 ? 7u : _i < 6 ? 3u : 10u;
    rounds_case(ATRBVH_METHOD_TRBVH, n, 3, _i < 6 ? 5000u : 1500u, _i & 1,
                model);
}
END_TEST

START_TEST(atrbvh_rounds)
{
    static const unsigned sizes[] = {9, 3, 5, 16, 32, 7};
    int model = _i % 3;
    rounds_case(ATRBVH_METHOD_ATRBVH, sizes[_i], _i == 5 ? 3u : 2u, 5000u,
                _i & 1, model);
}
END_TEST

/* `orig` optimised with 1..4 threads (treelet size and gamma n): a valid,
 * cheaper tree, the same bits for every thread count.  Frees orig. */
static void threads_same(test_tree *orig, atrbvh_method method, unsigned n,
                         unsigned rounds, const atrbvh_cost_params *p)
{
    test_tree ref, t;
    atrbvh_error err;
    atrbvh_i_config c;
    int threads;
    for (threads = 1; threads <= 4; threads++) {
        test_tree *dst = threads == 1 ? &ref : &t;
        tree_copy(dst, orig);
        c = config(method, n, rounds, n, p, threads);
        ck_assert_int_eq(atrbvh_i_optimise(&dst->t, NULL, &c, NULL, NULL, &err), ATRBVH_OK);
        if (threads == 1) {
            tree_check(&ref, orig, p);
            ck_assert(ref.t.cost[0] < orig->t.cost[0]);
        } else {
            ck_assert_msg(tree_same(&ref, &t), "%d threads differ", threads);
            tree_free(&t);
        }
    }
    tree_free(&ref);
    tree_free(orig);
}

/* 1..4 threads, the same bits (large enough for the parallel walk). */
static void threads_case(atrbvh_method method, unsigned n, unsigned rounds,
                         int model, int box_mode)
{
    atrbvh_cost_params p = cost_model(model);
    test_tree orig;
    tree_random(&orig, 70000, 77u + (uint64_t)box_mode, box_mode, &p);
    threads_same(&orig, method, n, rounds, &p);
}

START_TEST(threads_trbvh)
{
    threads_case(ATRBVH_METHOD_TRBVH, 7, 3, 1, _i);
}
END_TEST

START_TEST(threads_atrbvh)
{
    threads_case(ATRBVH_METHOD_ATRBVH, _i ? 16 : 9, 2, _i ? 0 : 1, _i);
}
END_TEST

/* A comb of 1200 teeth of 16 leaves: the optimise stage's frontier (the
 * crown's subtrees below a top of n / (32 x threads) primitives) is about
 * 1180 teeth, more than its list holds at 2 threads (1024: the one-thread
 * walk) and fewer than at 3 and 4 (the parallel loop); the same bits for
 * 1 to 4 threads either way, and a cheaper tree. */
START_TEST(threads_comb)
{
    atrbvh_cost_params p = cost_model(1);
    test_tree orig;
    tree_shaped(&orig, 1200 * 16, 91, 0, 16, &p);
    tree_check(&orig, &orig, &p);
    threads_same(&orig, _i ? ATRBVH_METHOD_TRBVH : ATRBVH_METHOD_ATRBVH,
                 _i ? 7 : 9, 2, &p);
}
END_TEST

/* Tiny and trivial trees: nothing to do, nothing breaks. */
START_TEST(small_trees)
{
    atrbvh_cost_params p = cost_model(1);
    uint32_t n;
    for (n = 1; n <= 20; n++) {
        test_tree orig, t;
        atrbvh_error err;
        atrbvh_i_config c;
        int m;
        tree_random(&orig, n, n, 0, &p);
        for (m = 0; m < 2; m++) {
            tree_copy(&t, &orig);
            c = config(m ? ATRBVH_METHOD_ATRBVH : ATRBVH_METHOD_TRBVH, 3, 4,
                       3, &p, 2);
            ck_assert_int_eq(atrbvh_i_optimise(&t.t, NULL, &c, NULL, NULL, &err), ATRBVH_OK);
            if (n > 1)
                tree_check(&t, &orig, &p);
            ck_assert(t.t.cost[0] <= orig.t.cost[0]);
            tree_free(&t);
        }
        tree_free(&orig);
    }
}
END_TEST

/* Allocation failure: ATRBVH_ERR_NOMEM, tree untouched, nothing leaked. */
static int fail_after = -1;
static long live_allocs = 0;
static void *counting_malloc(size_t size)
{
    if (fail_after == 0)
        return NULL;
    if (fail_after > 0)
        fail_after--;
    live_allocs++;
    return malloc(size);
}
static void counting_free(void *ptr)
{
    if (ptr)
        live_allocs--;
    free(ptr);
}

START_TEST(nomem)
{
    atrbvh_cost_params p = cost_model(1);
    test_tree orig, t;
    atrbvh_error err;
    atrbvh_i_config c;
    int k, m;
    tree_random(&orig, 500, 5, 0, &p);
    atrbvh_set_allocator(counting_malloc, counting_free);
    for (m = 0; m < 2; m++) {
        for (k = 0; k < 2; k++) {
            tree_copy(&t, &orig);
            fail_after = k;
            live_allocs = 0;
            c = config(m ? ATRBVH_METHOD_ATRBVH : ATRBVH_METHOD_TRBVH, 7, 2,
                       7, &p, 2);
            ck_assert_int_eq(atrbvh_i_optimise(&t.t, NULL, &c, NULL, NULL, &err),
                             ATRBVH_ERR_NOMEM);
            ck_assert_int_eq(err.status, ATRBVH_ERR_NOMEM);
            ck_assert_int_eq(live_allocs, 0);
            ck_assert(tree_same(&t, &orig));
            tree_free(&t);
        }
    }
    fail_after = -1;
    atrbvh_set_allocator(NULL, NULL);
    tree_free(&orig);
}
END_TEST


/* --------------------------------------------------- through atrbvh_build */
static atrbvh_build_options build_options(atrbvh_method method, unsigned n,
                                          unsigned rounds, int threads)
{
    atrbvh_build_options o;
    atrbvh_build_options_init(&o);
    o.method = method;
    o.treelet_size = n;
    o.rounds = rounds;
    o.threads = threads;
    return o;
}

static void check_built(const atrbvh_bvh *b, const atrbvh_geometry *g)
{
    char msg[256];
    ck_assert_msg(tu_check_bvh(b, g, msg, sizeof msg), "%s", msg);
}

/* Builds with 1..4 threads: the same node array, index array and SAH. */
static void same_for_threads(const atrbvh_geometry *g, atrbvh_method method,
                             unsigned n, unsigned rounds, double *sah)
{
    atrbvh_build_options o = build_options(method, n, rounds, 1);
    atrbvh_bvh *ref = tu_build(g, &o), *b;
    atrbvh_stats st;
    int threads;
    check_built(ref, g);
    for (threads = 2; threads <= 4; threads++) {
        char msg[256];
        size_t na, nb;
        const atrbvh_node *a, *bn;
        o.threads = threads;
        b = tu_build(g, &o);
        a = atrbvh_bvh_nodes(ref, &na);
        bn = atrbvh_bvh_nodes(b, &nb);
        ck_assert_msg(na == nb && memcmp(a, bn, na * sizeof *a) == 0,
                      "method %d n %u: node arrays differ with %d threads",
                      (int)method, n, threads);
        ck_assert_msg(tu_same_bvh(ref, b, msg, sizeof msg), "%d threads: %s",
                      threads, msg);
        atrbvh_bvh_free(b);
    }
    atrbvh_bvh_stats(ref, &st);
    *sah = st.sah;
    atrbvh_bvh_free(ref);
}

START_TEST(build_threads_random)
{
    size_t tris = 60000;
    float *v = tu_random_triangles(tris, 3u + (uint64_t)_i, 1.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 3 * tris, NULL, tris);
    atrbvh_build_options o = build_options(ATRBVH_METHOD_LBVH, 0, 0, 2);
    atrbvh_bvh *lbvh;
    atrbvh_stats st;
    double sah_t, sah_a;
    ck_assert_ptr_nonnull(v);
    lbvh = tu_build(&g, &o);
    atrbvh_bvh_stats(lbvh, &st);
    atrbvh_bvh_free(lbvh);
    same_for_threads(&g, ATRBVH_METHOD_TRBVH, _i ? 5u : 7u, _i ? 2u : 3u,
                     &sah_t);
    same_for_threads(&g, ATRBVH_METHOD_ATRBVH, _i ? 16u : 9u, 2, &sah_a);
    ck_assert(sah_t < st.sah && sah_a < st.sah);
    free(v);
}
END_TEST

/* The canonical PLY of ../shared/scenes (MANIFEST.md: float xyz vertices,
 * uchar-counted uint triangles), read here so the test needs no loader. */
typedef struct ply_mesh {
    float *v;
    uint32_t *idx;
    size_t nv, nt;
} ply_mesh;

static int ply_read(const char *path, ply_mesh *m)
{
    FILE *f = fopen(path, "rb");
    char line[256];
    size_t i;
    unsigned long nv = 0, nt = 0;
    int ok = 1;
    memset(m, 0, sizeof *m);
    if (!f)
        return 0;
    while (fgets(line, sizeof line, f)) {
        sscanf(line, "element vertex %lu", &nv);
        sscanf(line, "element face %lu", &nt);
        if (strncmp(line, "end_header", 10) == 0)
            break;
    }
    m->nv = nv;
    m->nt = nt;
    m->v = malloc(12 * (nv ? nv : 1));
    m->idx = malloc(12 * (nt ? nt : 1));
    if (!m->v || !m->idx || fread(m->v, 12, nv, f) != nv)
        ok = 0;
    for (i = 0; ok && i < nt; i++) {
        unsigned char c;
        if (fread(&c, 1, 1, f) != 1 || c != 3 ||
            fread(m->idx + 3 * i, 4, 3, f) != 3)
            ok = 0;
    }
    fclose(f);
    if (!ok) {
        free(m->v);
        free(m->idx);
        memset(m, 0, sizeof *m);
    }
    return ok;
}

/* The smaller real scenes (the dragon and the conference room are left to
 * the benchmark to keep the suite quick on a 2-core machine). */
static const char *const real_scenes[] = {"bunny", "sibenik",
                                          "dabrovic_sponza"};

START_TEST(real_scenes_fn)
{
    const char *dir = tu_scenes_dir();
    char path[4096];
    ply_mesh m;
    atrbvh_geometry g;
    atrbvh_build_options o;
    atrbvh_bvh *b;
    atrbvh_stats st;
    double lbvh, trbvh, atrbvh;
    if (!dir) {
        fprintf(stderr, "test_optimise: no $ATRBVH_SCENES, real scenes "
                        "skipped\n");
        return;
    }
    snprintf(path, sizeof path, "%s/%s.ply", dir, real_scenes[_i]);
    if (!ply_read(path, &m)) {
        fprintf(stderr, "test_optimise: %s not readable, skipped\n", path);
        return;
    }
    g = atrbvh_geometry_triangles(m.v, m.nv, m.idx, m.nt);
    o = build_options(ATRBVH_METHOD_LBVH, 0, 0, 2);
    b = tu_build(&g, &o);
    check_built(b, &g);
    atrbvh_bvh_stats(b, &st);
    lbvh = st.sah;
    atrbvh_bvh_free(b);
    same_for_threads(&g, ATRBVH_METHOD_ATRBVH, 9, 2, &atrbvh);
    o = build_options(ATRBVH_METHOD_TRBVH, 7, 3, 2);
    b = tu_build(&g, &o);
    check_built(b, &g);
    atrbvh_bvh_stats(b, &st);
    trbvh = st.sah;
    atrbvh_bvh_free(b);
    /* Measured (collapsed SAH, ci 1.2, ct 1, defaults):
     *   bunny            LBVH 43.37  TRBVH(7,3) 38.43  ATRBVH(9,2) 38.74
     *   sibenik          LBVH 67.04  TRBVH(7,3) 52.33  ATRBVH(9,2) 52.98
     *   dabrovic_sponza  LBVH 103.02 TRBVH(7,3) 70.01  ATRBVH(9,2) 71.64
     * i.e. gains of 11% to 32% over LBVH.  Asserting 6% leaves headroom for
     * changes in the earlier stages (Morton precision, tie rules) that
     * move the LBVH and both optimisers by a little, while any real
     * regression of an optimiser (a broken DP, a treelet never applied)
     * loses far more than 6%.  ATRBVH stays within 3% of TRBVH (measured
     * 0.8% to 2.3%). */
    ck_assert_msg(trbvh <= 0.94 * lbvh, "%s: TRBVH %.4f vs LBVH %.4f",
                  real_scenes[_i], trbvh, lbvh);
    ck_assert_msg(atrbvh <= 0.94 * lbvh, "%s: ATRBVH %.4f vs LBVH %.4f",
                  real_scenes[_i], atrbvh, lbvh);
    ck_assert_msg(atrbvh <= 1.03 * trbvh, "%s: ATRBVH %.4f vs TRBVH %.4f",
                  real_scenes[_i], atrbvh, trbvh);
    free(m.v);
    free(m.idx);
}
END_TEST

/* ---------------------------------------------------------------- suite */
static Suite *optimise_suite(void)
{
    Suite *s = suite_create("optimise");
    TCase *tc;

    tc = tcase_create("treelet");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, formation_rule);
    tcase_add_test(tc, trbvh_is_optimal);
    tcase_add_test(tc, trbvh_large_n);
    tcase_add_test(tc, trbvh_matches_plain_dp);
    tcase_add_test(tc, agg_layout_fits);
    tcase_add_test(tc, atrbvh_is_naive_greedy);
#ifdef ATRBVH_AGG_QUADS
    tcase_add_test(tc, atrbvh_lanes_are_scalar);
#endif
    suite_add_tcase(s, tc);

    tc = tcase_create("tree");
    tcase_set_timeout(tc, 120);
    tcase_add_loop_test(tc, trbvh_rounds, 0, 9);
    tcase_add_loop_test(tc, atrbvh_rounds, 0, 6);
    tcase_add_test(tc, small_trees);
    tcase_add_test(tc, nomem);
    suite_add_tcase(s, tc);

    tc = tcase_create("threads");
    tcase_set_timeout(tc, 120);
    tcase_add_loop_test(tc, threads_trbvh, 0, 2);
    tcase_add_loop_test(tc, threads_atrbvh, 0, 2);
    tcase_add_loop_test(tc, threads_comb, 0, 2);
    suite_add_tcase(s, tc);

    tc = tcase_create("build");
    tcase_set_timeout(tc, 300);
    tcase_add_loop_test(tc, build_threads_random, 0, 2);
    tcase_add_loop_test(tc, real_scenes_fn, 0,
                        (int)(sizeof real_scenes / sizeof real_scenes[0]));
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return tu_run(optimise_suite());
}
