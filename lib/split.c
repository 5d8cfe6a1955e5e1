/*
 * split.c - triangle splitting, a host pre-process between the bounds and
 * the Morton stage (Karras and Aila, HPG 2013, "triangle splitting"; the
 * older form is Ernst and Greiner's early split clipping).
 *
 * A triangle that alone makes the nodes above it large (a long thin
 * diagonal sliver, a large triangle among small ones) gets several
 * references instead of one, each with the box of the part of the
 * triangle inside one cell of a binary subdivision; the backends then
 * build over references exactly as over primitives (set_prims: a box and
 * the original primitive id per reference), so every backend gives the
 * same tree by construction.
 *
 * Choosing what to split, under a budget of B = budget * n extra
 * references (docs/splitting.md):
 *  - ATRBVH_SPLIT_TREE: a first LBVH of the unsplit triangles
 *    (CPU, one primitive per leaf) is read per triangle: what taking it
 *    out saves (its leaf, its parent, the ancestors shrunk to the rest of
 *    their subtrees) less what its pieces cost where their Morton keys
 *    land (cut_gain), for 1, 3 and 7 splits; a triangle is cut only
 *    where that gain is positive, and the budget, when it does not hold
 *    every such cut, goes to the highest gain per split;
 *  - ATRBVH_SPLIT_PRIORITY (Karras-Aila): p = (2^-d * (A_box -
 *    A_ideal))^(1/3), A_box the box's surface area, A_ideal = 2 (|c_x| +
 *    |c_y| + |c_z|) with c the edge cross product, d the depth of the most
 *    important grid plane crossing the box; s = floor(D * p) splits with
 *    the largest D whose total is within B;
 *  - by those two the totals are integer sums found by bisection on a
 *    scale, so the result does not depend on the thread count;
 *  - ATRBVH_SPLIT_SAH (default): top down over the grid's cells, a cell's
 *    triangles judged together, cut at the cell's midplane where that
 *    lowers the SAH of its halves (sah_refs, below); per level, the
 *    nodes on the threads, the budget handed out serially in cell order
 *    (the same references for any thread count);
 *  - each split (tree and priority rules) cuts the current piece at the most important grid plane
 *    crossing its box, the triangle clipped exactly to both halves (in
 *    double, rounded outward to float), and the remaining splits are
 *    shared between the halves in proportion to their longest extent.
 * The grid is at the Morton stage's resolution (2^21 per axis), over the
 * scene box (tree and priority rules) or the triangles' centroid box, the
 * Morton frame (SAH rule), so cuts fall on (or near) the planes the LBVH
 * splits at.  Ties go to the lower axis (x before y before z, as in the
 * Morton key).
 *
 * Leaves may then reference a primitive more than once: the layout's
 * output is post-processed here (atrbvh_i_split_merge) so that no leaf
 * lists a primitive twice.
 */
#include "config.h"

#include "internal.h"
#include "shared/sort.h"

#include <math.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#define NO_INDEX ((uint64_t)-1)
/* The most references a build may have: 2n - 1 nodes fit in u32 ids. */
#define MAX_REFS 0x7fffffffu
/* The most splits one triangle gets by the priority rule (its pieces
 * then number at most one more). */
#define MAX_SPLITS 4096u

typedef struct grid {
    double lo[3], scale[3]; /* cells = (x - lo) * scale, 2^21 per axis */
    double step[3];         /* extent / 2^21 */
} grid;

/* The grid over box fr, 2^21 cells per axis (none on a flat axis). */
static void grid_over(const atrbvh_box *fr, grid *g)
{
    int k;
    atrbvh_morton_frame(*fr, g->lo, g->scale); /* the Morton stage's */
    for (k = 0; k < 3; k++)
        g->step[k] = ((double)fr->max[k] - (double)fr->min[k]) /
                     (double)(1u << ATRBVH_MORTON_BITS);
}

static uint32_t quant(const grid *g, int k, float x)
{
    return atrbvh_morton_quantise(x, g->lo[k], g->scale[k]);
}

/* The most important grid plane strictly inside box b on axis k: its
 * coordinate and its Morton bit level (62 most important), or -1. */
static int axis_plane(const grid *g, const atrbvh_box *b, int k, float *at)
{
    uint32_t qa, qb, cell;
    int h = 0;
    float x = 0.0f;
    if (g->scale[k] == 0.0)
        return -1;
    qa = quant(g, k, b->min[k]);
    qb = quant(g, k, b->max[k]);
    /* the highest plane between the ends' cells; one that falls on the
     * box's end (rounding, or max exactly on a plane) gives way to the
     * next one below it */
    for (;;) {
        if (qa >= qb)
            break;
        h = atrbvh_sort_highest_bit(qa ^ qb);
        cell = (qb >> h) << h;
        x = (float)(g->lo[k] + (double)cell * g->step[k]);
        if (x >= b->max[k]) {
            qb = cell - 1;
            continue;
        }
        if (!(x > b->min[k]))
            qa = qb; /* no plane strictly inside */
        break;
    }
    if (qa >= qb)
        return -1;
    *at = x;
    return 3 * h + (2 - k);
}

/* The most important grid plane strictly inside box b over the three
 * axes (Morton bit order), or -1. */
static int best_plane(const grid *g, const atrbvh_box *b, int *axis,
                      float *at)
{
    int k, best = -1;
    for (k = 0; k < 3; k++) {
        float x;
        const int level = axis_plane(g, b, k, &x);
        if (level > best) {
            best = level;
            *axis = k;
            *at = x;
        }
    }
    return best;
}

/* The Karras-Aila priority (ATRBVH_SPLIT_PRIORITY): (2^(level - 62) *
 * (A_box - A_ideal))^(1/3), 0 for a box no grid plane crosses. */
static double priority(const grid *g, double v[3][3],
                       const atrbvh_box *b)
{
    double e1[3], e2[3], cx, cy, cz, ideal, excess;
    int axis, level;
    float at;
    int k;
    level = best_plane(g, b, &axis, &at);
    if (level < 0)
        return 0.0;
    for (k = 0; k < 3; k++) {
        e1[k] = v[1][k] - v[0][k];
        e2[k] = v[2][k] - v[0][k];
    }
    cx = e1[1] * e2[2] - e1[2] * e2[1];
    cy = e1[2] * e2[0] - e1[0] * e2[2];
    cz = e1[0] * e2[1] - e1[1] * e2[0];
    ideal = 2.0 * (fabs(cx) + fabs(cy) + fabs(cz));
    excess = atrbvh_box_area(*b) - ideal;
    if (!(excess > 0.0))
        return 0.0;
    return cbrt(ldexp(excess, level - 62));
}

/* The least total surface area boxes around the pieces of a triangle can
 * have: each face pair of a box covers the piece's projection, and the
 * projections of the pieces add up to the triangle's: |c_x| + |c_y| +
 * |c_z| with c the edge cross product. */
static double min_area(double v[3][3])
{
    double e1[3], e2[3];
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = v[1][k] - v[0][k];
        e2[k] = v[2][k] - v[0][k];
    }
    return fabs(e1[1] * e2[2] - e1[2] * e2[1]) +
           fabs(e1[2] * e2[0] - e1[0] * e2[2]) +
           fabs(e1[0] * e2[1] - e1[1] * e2[0]);
}

static void tri_vertices(const atrbvh_i_input *in, uint32_t id, double v[3][3])
{
    const atrbvh_geometry *g = in->g;
    int c, k;
    for (c = 0; c < 3; c++) {
        float p[3];
        atrbvh_u64 vid = atrbvh_fetch_vertex_id(
            g->indices, in->istride / sizeof(uint32_t), g->indices != NULL,
            id, c);
        atrbvh_fetch_vertex(g->vertices, in->vstride / sizeof(float), vid, p);
        for (k = 0; k < 3; k++)
            v[c][k] = (double)p[k];
    }
}

/* Floats bounding [lo, hi] from outside, one ulp wider still. */
static float down(double d)
{
    float f = (float)d;
    if ((double)f > d)
        f = nextafterf(f, -INFINITY);
    return nextafterf(f, -INFINITY);
}

static float up(double d)
{
    float f = (float)d;
    if ((double)f < d)
        f = nextafterf(f, INFINITY);
    return nextafterf(f, INFINITY);
}

/* The box of the triangle clipped to region r, within `clamp` (the
 * triangle's own box); 0 when the clipped part is empty. */
static int clip_box(double v[3][3], const atrbvh_box *r,
                    const atrbvh_box *clamp, atrbvh_box *out)
{
    double a[12][3], b[12][3];
    int na = 3, nb, i, k, side;
    double lo[3], hi[3];
    memcpy(a, v, 3 * sizeof a[0]);
    for (k = 0; k < 3; k++) {
        for (side = 0; side < 2; side++) {
            const double x = side ? (double)r->max[k] : (double)r->min[k];
            nb = 0;
            for (i = 0; i < na; i++) {
                const double *p = a[i], *q = a[(i + 1) % na];
                int pin = side ? p[k] <= x : p[k] >= x;
                int qin = side ? q[k] <= x : q[k] >= x;
                if (pin)
                    memcpy(b[nb++], p, sizeof b[0]);
                if (pin != qin) {
                    double t = (x - p[k]) / (q[k] - p[k]);
                    int j;
                    for (j = 0; j < 3; j++)
                        b[nb][j] = p[j] + t * (q[j] - p[j]);
                    b[nb][k] = x;
                    nb++;
                }
            }
            na = nb;
            if (na == 0)
                return 0;
            memcpy(a, b, (size_t)na * sizeof a[0]);
        }
    }
    for (k = 0; k < 3; k++) {
        lo[k] = hi[k] = a[0][k];
        for (i = 1; i < na; i++) {
            if (a[i][k] < lo[k])
                lo[k] = a[i][k];
            if (a[i][k] > hi[k])
                hi[k] = a[i][k];
        }
        out->min[k] = down(lo[k]);
        out->max[k] = up(hi[k]);
        if (out->min[k] < r->min[k])
            out->min[k] = r->min[k];
        if (out->min[k] < clamp->min[k])
            out->min[k] = clamp->min[k];
        if (out->max[k] > r->max[k])
            out->max[k] = r->max[k];
        if (out->max[k] > clamp->max[k])
            out->max[k] = clamp->max[k];
        if (out->min[k] > out->max[k])
            return 0;
    }
    return 1;
}

static double longest(const atrbvh_box *b)
{
    double e = 0.0;
    int k;
    for (k = 0; k < 3; k++) {
        double d = (double)b->max[k] - (double)b->min[k];
        if (d > e)
            e = d;
    }
    return e;
}

typedef struct piece {
    atrbvh_box region, box;
    uint32_t splits;
} piece;

/* The pieces of one triangle (at most splits + 1 boxes into out, in a
 * fixed depth-first order); returns their count.  stack: room for
 * splits + 2 pieces. */
static uint32_t split_one(const grid *g, double v[3][3],
                          const atrbvh_box *box, uint32_t splits,
                          piece *stack, atrbvh_box *out)
{
    uint32_t sp = 0, count = 0;
    stack[sp].region = *box;
    stack[sp].box = *box;
    stack[sp++].splits = splits;
    while (sp) {
        piece cur = stack[--sp], l, r;
        int axis = 0, hl, hr;
        float at = 0.0f;
        if (cur.splits == 0 || best_plane(g, &cur.box, &axis, &at) < 0) {
            out[count++] = cur.box;
            continue;
        }
        l.region = cur.region;
        r.region = cur.region;
        l.region.max[axis] = at;
        r.region.min[axis] = at;
        hl = clip_box(v, &l.region, box, &l.box);
        hr = clip_box(v, &r.region, box, &r.box);
        if (!hl || !hr) { /* rounding left one side empty: keep one */
            cur.splits = hl || hr ? cur.splits - 1 : 0;
            if (hl)
                cur.region = l.region, cur.box = l.box;
            else if (hr)
                cur.region = r.region, cur.box = r.box;
            stack[sp++] = cur;
            continue;
        }
        {
            const uint32_t rest = cur.splits - 1;
            const double wl = longest(&l.box), wr = longest(&r.box);
            uint32_t sl = wl + wr > 0.0
                              ? (uint32_t)floor((double)rest * wl / (wl + wr) +
                                                0.5)
                              : rest / 2;
            if (sl > rest)
                sl = rest;
            l.splits = sl;
            r.splits = rest - sl;
        }
        stack[sp++] = r; /* the left piece first */
        stack[sp++] = l;
    }
    return count;
}

#define GAIN_DEPTH 256 /* the deepest path the gain estimate follows */
#define GAIN_SPLITS 7u  /* the most splits the tree rule gives a triangle */

/* The first tree of the tree rule and what the gain estimate reads
 * of it. */
typedef struct first_tree {
    atrbvh_bvh *t;
    uint32_t *parent;   /* per node (the root's: 0) */
    uint32_t *lfirst;   /* per node: its first leaf's position */
    uint32_t *llast;    /* per node: its last leaf's position */
    uint32_t *leaf_of;  /* per primitive id: its leaf node */
    uint64_t *keys;     /* per leaf position: the Morton key */
    uint32_t leaves;
    double lo[3], scale[3];
} first_tree;

static uint64_t box_key(const first_tree *f, const atrbvh_box *b)
{
    uint32_t q[3];
    int k;
    for (k = 0; k < 3; k++)
        q[k] = atrbvh_morton_quantise(atrbvh_box_centre(*b, k), f->lo[k],
                                      f->scale[k]);
    return atrbvh_morton_key(q[0], q[1], q[2]);
}

static atrbvh_box node_box(const atrbvh_node *n)
{
    atrbvh_box b;
    memcpy(b.min, n->min, sizeof b.min);
    memcpy(b.max, n->max, sizeof b.max);
    return b;
}

/* A triangle's way up the first tree: its ancestors bottom up, each with
 * the box of the rest of its subtree (the triangle left out), and what
 * taking the triangle out saves (x SA(root)): its leaf, its parent (the
 * other child takes its place) and, above, each ancestor shrunk to the
 * rest. */
typedef struct tri_path {
    uint32_t node[GAIN_DEPTH];
    atrbvh_box rest[GAIN_DEPTH];
    int depth;
    double removal, above; /* above: the ancestors' part of removal */
} tri_path;

/* 0 when the way is deeper than GAIN_DEPTH (no estimate). */
static int walk_up(const first_tree *f, const atrbvh_i_config *cfg,
                   uint32_t leaf, tri_path *w)
{
    const atrbvh_node *nodes = f->t->nodes;
    uint32_t c = leaf;
    int d = 0;
    w->removal = cfg->cost.ct * atrbvh_box_area(node_box(&nodes[leaf]));
    w->above = 0.0;
    while (c != 0) {
        const uint32_t p = f->parent[c];
        const atrbvh_node *a = &nodes[p];
        const atrbvh_box sb = node_box(&nodes[c == p + 1 ? a->index : p + 1]);
        const atrbvh_box ab = node_box(a);
        if (d == GAIN_DEPTH)
            return 0;
        w->rest[d] = d ? atrbvh_box_union(w->rest[d - 1], sb) : sb;
        w->node[d] = p;
        if (d && memcmp(&w->rest[d], &ab, sizeof ab) == 0)
            break; /* this node and every one above keep their boxes */
        if (d)
            w->above += cfg->cost.ci * (atrbvh_box_area(ab) -
                                        atrbvh_box_area(w->rest[d]));
        else
            w->removal += cfg->cost.ci * atrbvh_box_area(ab);
        d++;
        c = p;
    }
    w->depth = d;
    w->removal += w->above;
    return d > 0;
}

/* What cutting the triangle of path w into pieces pc[0..np) saves in the
 * first tree's SAH (x SA(root); may be negative): its removal, less the
 * pieces' cost: the ancestors hold the pieces that land in their
 * subtree (a piece lands beside the leaf its Morton key sorts to), the
 * nodes on a piece's way down below them grow to hold it, and each piece
 * adds a leaf, and a parent beside the leaf it lands at (the first to
 * land at the triangle's own leaf takes its place instead). */
static double cut_gain(const first_tree *f, const atrbvh_i_config *cfg,
                       const tri_path *w, uint32_t leaf,
                       const atrbvh_box *pc, int np)
{
    const atrbvh_node *nodes = f->t->nodes;
    const double ci = cfg->cost.ci, ct = cfg->cost.ct;
    atrbvh_box in[GAIN_DEPTH], first = pc[0];
    unsigned char has_in[GAIN_DEPTH];
    int d, i, replaced = 0;
    double gain = w->removal;
    const uint32_t tpos = f->lfirst[leaf];

    memset(has_in, 0, (size_t)w->depth);
    for (i = 0; i < np; i++) {
        const uint64_t key = box_key(f, &pc[i]);
        uint32_t lo = 0, hi = f->leaves, n = 0;
        d = w->depth - 1; /* the root's entry */
        while (lo < hi) { /* the first leaf whose key is not below */
            const uint32_t mid = lo + (hi - lo) / 2;
            if (f->keys[mid] < key)
                lo = mid + 1;
            else
                hi = mid;
        }
        if (lo == f->leaves)
            lo--;
        while (nodes[n].count == 0) {
            const atrbvh_node *a = &nodes[n];
            if (f->lfirst[n] <= tpos && tpos <= f->llast[n]) {
                /* an ancestor: holds the piece (no change above the
                 * walk's end: its box held the whole triangle) */
                if (d >= 0 && w->node[d] == n) {
                    in[d] = has_in[d] ? atrbvh_box_union(in[d], pc[i])
                                      : pc[i];
                    has_in[d] = 1;
                    d--;
                }
            } else {
                const atrbvh_box ab = node_box(a);
                gain -= ci * (atrbvh_box_area(atrbvh_box_union(ab, pc[i])) -
                              atrbvh_box_area(ab));
            }
            n = lo <= f->llast[n + 1] ? n + 1 : a->index;
        }
        if (n == leaf && !replaced) { /* in the triangle's place */
            replaced = 1;
            first = pc[i];
        } else {
            gain -= ci * atrbvh_box_area(atrbvh_box_union(
                             n == leaf ? first : node_box(&nodes[n]), pc[i]));
        }
        gain -= ct * atrbvh_box_area(pc[i]);
    }
    if (replaced) /* the parent stays, holding rest and pieces */
        gain -= ci * atrbvh_box_area(atrbvh_box_union(w->rest[0], in[0]));
    for (d = 1; d < w->depth; d++)
        if (has_in[d])
            gain -= ci * (atrbvh_box_area(atrbvh_box_union(w->rest[d], in[d])) -
                          atrbvh_box_area(w->rest[d]));
    return gain;
}

static void first_tree_free(first_tree *f)
{
    atrbvh_i_free(f->parent);
    atrbvh_i_free(f->lfirst);
    atrbvh_i_free(f->llast);
    atrbvh_i_free(f->leaf_of);
    atrbvh_i_free(f->keys);
    atrbvh_bvh_free(f->t);
    memset(f, 0, sizeof *f);
}

/* The first tree: LBVH over the triangles, unsplit and not collapsed
 * (a leaf per primitive, leaves in Morton order), on the CPU backend
 * whatever the build's backend is, with what cut_gain reads of it. */
static atrbvh_status first_tree_open(const atrbvh_i_run *run,
                                     const atrbvh_box *centroids,
                                     first_tree *f, atrbvh_error *error)
{
    const atrbvh_i_config *cfg = run->cfg;
    atrbvh_build_options o;
    atrbvh_status st;
    size_t i, nn;
    uint32_t leaves = 0;

    memset(f, 0, sizeof *f);
    atrbvh_build_options_init(&o);
    o.method = ATRBVH_METHOD_LBVH;
    o.collapse = 0;
    o.ci = cfg->cost.ci;
    o.ct = cfg->cost.ct;
    o.threads = cfg->threads;
    o.skip_invalid = cfg->skip_invalid;
    st = atrbvh_build(run->in.g, &o, &f->t, error);
    if (st != ATRBVH_OK)
        return st;
    nn = f->t->node_count;
    f->parent = atrbvh_i_alloc_array(nn, sizeof *f->parent);
    f->lfirst = atrbvh_i_alloc_array(nn, sizeof *f->lfirst);
    f->llast = atrbvh_i_alloc_array(nn, sizeof *f->llast);
    f->leaf_of = atrbvh_i_alloc_array(run->in.g->primitive_count,
                                      sizeof *f->leaf_of);
    f->keys = atrbvh_i_alloc_array(nn, sizeof *f->keys);
    if (!f->parent || !f->lfirst || !f->llast || !f->leaf_of || !f->keys) {
        first_tree_free(f);
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate the split priorities' first "
                             "tree (%lu nodes)",
                             (unsigned long)nn);
    }
    atrbvh_i_morton_frame(centroids, f->lo, f->scale);
    f->parent[0] = 0;
    for (i = 0; i < nn; i++) {
        const atrbvh_node *nd = &f->t->nodes[i];
        f->lfirst[i] = leaves;
        if (nd->count) {
            const atrbvh_box b = node_box(nd);
            f->leaf_of[f->t->prim_indices[nd->index]] = (uint32_t)i;
            f->keys[leaves++] = box_key(f, &b);
        } else {
            f->parent[i + 1] = (uint32_t)i;
            f->parent[nd->index] = (uint32_t)i;
        }
    }
    f->leaves = leaves;
    for (i = nn; i-- > 0;) {
        const atrbvh_node *nd = &f->t->nodes[i];
        f->llast[i] = nd->count ? f->lfirst[i] : f->llast[nd->index];
    }
    return ATRBVH_OK;
}

/* The splits of triangle i at scale d: by the tree rule (chosen) all its
 * chosen ones when its gain per split p reaches 1 / d, else none; by the
 * priority rule floor(d p), at most MAX_SPLITS. */
static uint32_t splits_of(double d, double p, const uint32_t *chosen,
                          size_t i)
{
    double s;
    if (chosen)
        return d * p >= 1.0 ? chosen[i] : 0u;
    s = floor(d * p);
    if (!(s >= 1.0))
        return 0u; /* also NaN: d 0 against an infinite priority (a box
                      whose area overflows float) */
    return s >= (double)MAX_SPLITS ? MAX_SPLITS : (uint32_t)s;
}

/* Sum over triangles of splits_of: integer, so the same for any thread
 * count. */
static uint64_t total_splits(const double *p, const uint32_t *chosen,
                             size_t n, double d, int threads)
{
    uint64_t sum = 0;
    int64_t i;
    (void)threads;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) reduction(+ : sum)
#endif
    for (i = 0; i < (int64_t)n; i++)
        sum += splits_of(d, p[i], chosen, (size_t)i);
    return sum;
}

/* ---- The SAH rule (ATRBVH_SPLIT_SAH) -------------------------------- *
 * Top down over the cells of the grid (over the centroids' box: the
 * Morton frame before splitting), level by level in Morton bit
 * order (x before y before z), each node holding the references whose
 * centroids fall in its cell (what the LBVH groups).  At a node the
 * plane is the cell's midplane on the level's axis: the references on
 * one side go there; a straddler either goes whole to the side of its
 * centroid (the object partition the LBVH makes) or is cut in two, the
 * triangle clipped to each half.  The node is cut where the SAH of the
 * two halves, A(L) nL + A(R) nR, is lower with the straddlers cut than
 * without; before that, each straddler stays whole where that is
 * cheaper still (reference unsplitting, Stich et al. 2009).  Judging a
 * node's straddlers together is what cuts two large triangles that
 * share one box (a quad's halves), which a rule judging each triangle
 * alone never does (Ganestam and Doggett 2016 decide top down per
 * node in the same spirit).  The budget goes level by level, each
 * level's nodes in cell order, so the top levels get it first; once it
 * is spent the nodes left are emitted as they are.
 *
 * On the threads: a node's partition and weighing (is it a candidate,
 * how many straddlers its cut takes, does the cut pay) are a pure
 * function of the node, whatever budget is left, so a level's nodes are
 * weighed in parallel, a large node's partition, clipping (most of the
 * work) and writing in pieces (spiece), so that the few nodes of the
 * top levels, which hold every reference, are shared too; only the
 * budget rule (a cut is taken where it pays and fits what the nodes
 * before it left), the output positions (prefix sums of the nodes' and
 * pieces' counts) and the unsplitting within a node (each straddler's
 * decision sees the ones before it) are serial, in order, as in one
 * loop; the references are then written in parallel, each node or piece
 * to its own range.  So the references are the same, in the same order,
 * for any thread count.  One thread (or a level of few references)
 * weighs each node only while budget is left, as before. */

typedef struct sref {
    atrbvh_box box;
    uint32_t j; /* the triangle: its index among the kept ones */
} sref;

typedef struct snode {
    uint32_t first, count;
    uint32_t qlo[3]; /* the cell's low corner in grid units */
} snode;

/* A node of at most SAH_STOP references is not cut further; a node is
 * weighed for cutting only where its object partition's halves overlap
 * by more than SAH_ALPHA times the scene box's area (SBVH's alpha; 1e-2
 * rather than their 1e-5 spends the budget where the overlap is large:
 * on the shared scenes fewer references, the same SAH, a lower ray
 * cost, docs/splitting.md). */
#define SAH_STOP 4u
#define SAH_ALPHA 1e-2

/* The surface area of the overlap of a and b (0 when they are apart). */
static double overlap_area(const atrbvh_box *a, const atrbvh_box *b)
{
    atrbvh_box o;
    int k;
    for (k = 0; k < 3; k++) {
        o.min[k] = a->min[k] > b->min[k] ? a->min[k] : b->min[k];
        o.max[k] = a->max[k] < b->max[k] ? a->max[k] : b->max[k];
        if (!(o.min[k] <= o.max[k]))
            return 0.0;
    }
    return atrbvh_box_area(o);
}

static double side_cost(const atrbvh_box *b, uint64_t n)
{
    return n ? atrbvh_box_area(*b) * (double)n : 0.0;
}

/* side[] of a reference in the node being cut */
#define S_RIGHT 1u    /* else left (its centroid's side if it straddles) */
#define S_STRADDLE 4u /* crosses the plane */
#define S_CUT 2u      /* cut into both halves */

/* Reference f's triangle clipped to both sides of the plane x on axis k,
 * within f's box: 1 with both halves' boxes, 0 when rounding leaves one
 * side empty.  The halves are kept (sah_ctx.halves) from the weighing
 * to the writing, rather than clipped twice. */
static int cut_ref(const atrbvh_i_run *run, const uint32_t *ids,
                   const atrbvh_box *boxes, const sref *f, int k, float x,
                   atrbvh_box *l, atrbvh_box *r)
{
    double v[3][3];
    atrbvh_box rl = f->box, rr = f->box;
    rl.max[k] = x;
    rr.min[k] = x;
    tri_vertices(&run->in, ids ? ids[f->j] : f->j, v);
    return clip_box(v, &rl, &boxes[f->j], l) &&
           clip_box(v, &rr, &boxes[f->j], r);
}

/* What the SAH rule knows of one node (a cell) of the current level.
 * Partition, join and weigh fill it in on any thread, a pure function of
 * the cell; place then hands out the budget and the output positions
 * serially, in cell order, and write moves the references. */
typedef struct scell {
    atrbvh_box lo, ro; /* the references wholly left, right of the plane */
    atrbvh_box ls, rs; /* the straddlers whole at their centroid's side */
    uint64_t nl, nr, nls, nrs; /* their counts */
    uint64_t cut, cutl; /* straddlers cut (of them centroid-left) */
    size_t piece0, pieces; /* a large node's pieces in sah_ctx.pieces */
    size_t slot0; /* its straddlers' first slot in sah_ctx.halves */
    size_t nxt_at, out_at; /* place's: where its output goes */
    size_t half_out[2]; /* place's: a half that goes out: where, else
                           NO_OUT */
    unsigned char stop; /* no overlap below can pass: emitted whole */
    unsigned char cand; /* weighed for a spatial split */
    unsigned char pays; /* the cut lowers the halves' SAH */
    unsigned char taken; /* place's: the budget took the cut */
} scell;

#define NO_OUT ((size_t)-1)

/* A piece of a large node (over SAH_PIECE references): SAH_PIECE of its
 * references in order (the last one the rest), the unit of the
 * partition, the clipping and the writing, so that the few nodes of
 * the top levels, which hold every reference, are spread over the
 * threads too.  The pieces' boxes and counts are joined in piece order:
 * a union keeps the later of two equal bounds (+0 and -0), so joined in
 * order they are the bits of one loop over the node. */
typedef struct spiece {
    uint32_t node;         /* its node in cn */
    uint32_t first, count; /* its positions in cur */
    atrbvh_box lo, ro, ls, rs;
    uint32_t nl, nr, nls, nrs;
    uint32_t cut, cutl;    /* weigh's */
    size_t at[2];          /* place's: where its left and right go */
    size_t slot0;          /* its straddlers' first slot in halves */
} spiece;

#define SAH_PIECE 2048u

/* The state of sah_refs shared by the per-cell steps. */
typedef struct sah_ctx {
    const atrbvh_i_run *run;
    const grid *g;
    const atrbvh_box *boxes; /* per kept triangle */
    const uint32_t *ids;     /* kept triangle -> primitive id (or NULL) */
    double min_overlap;
    sref *cur, *nxt;
    snode *cn, *nn;
    scell *cells;          /* per node of cn */
    spiece *pieces;        /* the large nodes' pieces, in node order */
    unsigned char *side;   /* per position in cur */
    atrbvh_box *halves;    /* per straddler slot: its halves (the slots
                              of a level's straddlers in order, compact:
                              the pages touched are the straddlers') */
    atrbvh_box *out;
    uint32_t *out_ids;
    int k;                 /* the level's axis */
    uint32_t half;         /* half the level's cell width, grid units */
} sah_ctx;

#define S_CLIPPED 8u /* cut_ref gave both halves (at its slot in halves) */

/* GCC's SLP vectoriser packs a box that a loop grows and then stores
 * into vector registers, shuffling them at every step (callgrind,
 * conference --split 0.1, one thread: the partition 116M instructions
 * with it, 78M without, as the single function before it had). */
#if defined(__GNUC__) && !defined(__clang__)
#define NO_SLP __attribute__((optimize("no-tree-slp-vectorize")))
#else
#define NO_SLP
#endif

/* The plane of node nd at the level: its cell's midplane. */
static float sah_plane(const sah_ctx *s, const snode *nd)
{
    const uint32_t mid = nd->qlo[s->k] + s->half;
    return (float)(s->g->lo[s->k] + (double)mid * s->g->step[s->k]);
}

/* The object partition (straddlers whole at their centroid's side) of
 * positions [p, p + n) of node nd: side[] of each, and the boxes and
 * counts of the four kinds (wholly left, wholly right, straddlers left,
 * straddlers right) into bx and cnt. */
NO_SLP static void sah_partition(const sah_ctx *s, const snode *nd,
                                 size_t p, size_t n, atrbvh_box bx[4],
                                 uint64_t cnt[4])
{
    const sref *r = s->cur + p;
    unsigned char *side = s->side + p;
    const int k = s->k;
    const float x = sah_plane(s, nd);
    atrbvh_box lo = atrbvh_box_empty(), ro = atrbvh_box_empty();
    atrbvh_box ls = lo, rs = ro;
    uint64_t nl = 0, nr = 0, nls = 0, nrs = 0;
    size_t a;
    for (a = 0; a < n; a++) {
        const atrbvh_box *b = &r[a].box;
        if (b->max[k] <= x) {
            side[a] = 0;
            lo = atrbvh_box_union(lo, *b);
            nl++;
        } else if (b->min[k] >= x) {
            side[a] = S_RIGHT;
            ro = atrbvh_box_union(ro, *b);
            nr++;
        } else if (atrbvh_box_centre(*b, k) >= x) {
            side[a] = S_STRADDLE | S_RIGHT;
            rs = atrbvh_box_union(rs, *b);
            nrs++;
        } else {
            side[a] = S_STRADDLE;
            ls = atrbvh_box_union(ls, *b);
            nls++;
        }
    }
    bx[0] = lo;
    bx[1] = ro;
    bx[2] = ls;
    bx[3] = rs;
    cnt[0] = nl;
    cnt[1] = nr;
    cnt[2] = nls;
    cnt[3] = nrs;
}

/* Node c's object partition, or a large node's piece i of it. */
static void sah_partition_node(const sah_ctx *s, size_t c)
{
    scell *e = &s->cells[c];
    atrbvh_box bx[4];
    uint64_t cnt[4];
    sah_partition(s, &s->cn[c], s->cn[c].first, s->cn[c].count, bx, cnt);
    e->lo = bx[0], e->ro = bx[1], e->ls = bx[2], e->rs = bx[3];
    e->nl = cnt[0], e->nr = cnt[1], e->nls = cnt[2], e->nrs = cnt[3];
}

static void sah_partition_piece(const sah_ctx *s, size_t i)
{
    spiece *pc = &s->pieces[i];
    atrbvh_box bx[4];
    uint64_t cnt[4];
    sah_partition(s, &s->cn[pc->node], pc->first, pc->count, bx, cnt);
    pc->lo = bx[0], pc->ro = bx[1], pc->ls = bx[2], pc->rs = bx[3];
    pc->nl = (uint32_t)cnt[0], pc->nr = (uint32_t)cnt[1];
    pc->nls = (uint32_t)cnt[2], pc->nrs = (uint32_t)cnt[3];
    pc->cut = pc->cutl = 0;
}

/* A large node's partition: its pieces' joined in piece order. */
static void sah_join(const sah_ctx *s, size_t c)
{
    scell *e = &s->cells[c];
    size_t i;
    e->lo = e->ro = e->ls = e->rs = atrbvh_box_empty();
    e->nl = e->nr = e->nls = e->nrs = 0;
    for (i = e->piece0; i < e->piece0 + e->pieces; i++) {
        const spiece *pc = &s->pieces[i];
        e->lo = atrbvh_box_union(e->lo, pc->lo);
        e->ro = atrbvh_box_union(e->ro, pc->ro);
        e->ls = atrbvh_box_union(e->ls, pc->ls);
        e->rs = atrbvh_box_union(e->rs, pc->rs);
        e->nl += pc->nl;
        e->nr += pc->nr;
        e->nls += pc->nls;
        e->nrs += pc->nrs;
    }
}

/* Whether node c, partitioned, stops here or is weighed for a spatial
 * split (given budget left: place refuses the cut otherwise). */
static void sah_judge(const sah_ctx *s, size_t c)
{
    scell *e = &s->cells[c];
    const atrbvh_box lobj = atrbvh_box_union(e->ls, e->lo),
                     robj = atrbvh_box_union(e->rs, e->ro);
    e->cut = e->cutl = 0;
    e->pays = e->taken = 0;
    /* no overlap below can pass: every box below lies in this node's,
     * so nothing more is cut here */
    e->stop = !(atrbvh_box_area(atrbvh_box_union(lobj, robj)) >
                s->min_overlap);
    e->cand = !e->stop && e->nls + e->nrs && e->nl + e->nls &&
              e->nr + e->nrs && overlap_area(&lobj, &robj) > s->min_overlap;
}

/* The straddlers at positions [p0, p1) of cur, in weighed node c,
 * clipped to both sides of its plane, their halves at slots slot0 on
 * (the expensive part: any range on any thread; each position is
 * written by one call). */
static void sah_clip(const sah_ctx *s, size_t c, size_t p0, size_t p1,
                     size_t slot0)
{
    const snode nd = s->cn[c];
    const float x = sah_plane(s, &nd);
    size_t p, slot = slot0;
    for (p = p0; p < p1; p++) {
        if (!(s->side[p] & S_STRADDLE))
            continue;
        if (cut_ref(s->run, s->ids, s->boxes, &s->cur[p], s->k, x,
                    &s->halves[2 * slot], &s->halves[2 * slot + 1]))
            s->side[p] |= S_CLIPPED;
        slot++;
    }
}

/* Weighed node c, its straddlers clipped (by sah_clip before, or here
 * when clip is set: one pass over the node instead of two on one
 * thread): every straddler cut, then each kept whole at its centroid's
 * side where that costs no more (in reference order: each decision sees
 * the ones before), and whether the cut lowers the halves' SAH; a large
 * node's pieces count their cuts. */
NO_SLP static void sah_weigh(const sah_ctx *s, size_t c, int clip)
{
    const snode nd = s->cn[c];
    const sref *r = s->cur + nd.first;
    unsigned char *side = s->side + nd.first;
    scell *e = &s->cells[c];
    const atrbvh_box *hv = s->halves + 2 * e->slot0;
    const atrbvh_box lobj = atrbvh_box_union(e->ls, e->lo),
                     robj = atrbvh_box_union(e->rs, e->ro);
    atrbvh_box lsp = e->lo, rsp = e->ro;
    uint64_t nls = e->nl, nrs = e->nr, cut = 0, cutl = 0;
    size_t slot = 0;
    uint32_t a;
    for (a = 0; a < nd.count; a++) {
        if (!(side[a] & S_STRADDLE))
            continue;
        if (clip)
            sah_clip(s, c, (size_t)nd.first + a, (size_t)nd.first + a + 1,
                     e->slot0 + slot);
        if (side[a] & S_CLIPPED) {
            side[a] |= S_CUT;
            lsp = atrbvh_box_union(lsp, hv[2 * slot]);
            rsp = atrbvh_box_union(rsp, hv[2 * slot + 1]);
            nls++;
            nrs++;
        } else if (side[a] & S_RIGHT) { /* rounding: whole */
            rsp = atrbvh_box_union(rsp, r[a].box);
            nrs++;
        } else {
            lsp = atrbvh_box_union(lsp, r[a].box);
            nls++;
        }
        slot++;
    }
    for (a = 0; a < nd.count; a++) {
        double split_c, whole_c;
        atrbvh_box wb;
        if (!(side[a] & S_CUT))
            continue;
        split_c = side_cost(&lsp, nls) + side_cost(&rsp, nrs);
        if (side[a] & S_RIGHT) {
            wb = atrbvh_box_union(rsp, r[a].box);
            whole_c = side_cost(&lsp, nls - 1) + side_cost(&wb, nrs);
        } else {
            wb = atrbvh_box_union(lsp, r[a].box);
            whole_c = side_cost(&wb, nls) + side_cost(&rsp, nrs - 1);
        }
        if (whole_c <= split_c) {
            side[a] &= (unsigned char)~S_CUT;
            if (side[a] & S_RIGHT)
                rsp = wb, nls--;
            else
                lsp = wb, nrs--;
        } else {
            cut++;
            cutl += !(side[a] & S_RIGHT);
            if (e->pieces) {
                spiece *pc = &s->pieces[e->piece0 + a / SAH_PIECE];
                pc->cut++;
                pc->cutl += !(side[a] & S_RIGHT);
            }
        }
    }
    e->cut = cut;
    e->cutl = cutl;
    e->pays = cut && side_cost(&lsp, nls) + side_cost(&rsp, nrs) <
                         side_cost(&lobj, e->nl + e->nls) +
                             side_cost(&robj, e->nr + e->nrs);
}

/* Where node c's output goes, serially in cell order (what makes the
 * result the same for any thread count): the budget takes its cut if it
 * pays and fits what is left; its halves go to nxt at *pos, those still
 * to cut becoming nodes of nn at *nnext, the rest also to out at *total;
 * a large node's pieces each after the ones before them. */
static void sah_place(const sah_ctx *s, size_t c, int level,
                      uint64_t *remaining, uint64_t *total, size_t *pos,
                      size_t *nnext)
{
    const snode nd = s->cn[c];
    scell *e = &s->cells[c];
    uint64_t nh[2];
    size_t at[2], i;
    int h;
    if (e->stop) {
        e->out_at = (size_t)*total;
        *total += nd.count;
        return;
    }
    if (e->cand && e->pays && *remaining && e->cut <= *remaining) {
        *remaining -= e->cut;
        e->taken = 1;
    } else {
        e->cut = e->cutl = 0;
    }
    nh[0] = e->nl + e->nls + e->cut - e->cutl;
    nh[1] = e->nr + e->nrs + e->cutl;
    e->nxt_at = *pos;
    for (h = 0; h < 2; h++) {
        const size_t first = h ? *pos + (size_t)nh[0] : *pos;
        e->half_out[h] = NO_OUT;
        if (!nh[h])
            continue;
        if (nh[h] > SAH_STOP && level > 0) {
            snode *m = &s->nn[(*nnext)++];
            *m = nd;
            m->first = (uint32_t)first;
            m->count = (uint32_t)nh[h];
            if (h)
                m->qlo[s->k] = nd.qlo[s->k] + s->half;
        } else {
            e->half_out[h] = (size_t)*total;
            *total += nh[h];
        }
    }
    at[0] = *pos;
    at[1] = *pos + (size_t)nh[0];
    *pos += (size_t)(nh[0] + nh[1]);
    for (i = e->piece0; i < e->piece0 + e->pieces; i++) {
        spiece *pc = &s->pieces[i];
        const uint32_t cut = e->taken ? pc->cut : 0,
                       cutl = e->taken ? pc->cutl : 0;
        pc->at[0] = at[0];
        pc->at[1] = at[1];
        at[0] += pc->nl + pc->nls + cut - cutl;
        at[1] += pc->nr + pc->nrs + cutl;
    }
}

/* Entries [f, f + n) of refs to out from position o on: their boxes,
 * and their primitive ids to out_ids. */
static void sah_emit(const sah_ctx *s, const sref *refs, size_t f,
                     size_t n, size_t o)
{
    size_t e;
    for (e = f; e < f + n; e++, o++) {
        s->out[o] = refs[e].box;
        s->out_ids[o] = s->ids ? s->ids[refs[e].j] : refs[e].j;
    }
}

/* Positions [p, p + n) of node c where place put them (left at at[0]
 * on, right at at[1] on, each in the references' order); the part of a
 * half that goes out is copied there too. */
static void sah_write(const sah_ctx *s, size_t c, size_t p, size_t n,
                      const size_t at_in[2], size_t slot0)
{
    const scell *e = &s->cells[c];
    const sref *r = s->cur + p;
    const unsigned char *side = s->side + p;
    const atrbvh_box *hv = s->halves + 2 * slot0;
    size_t at[2], a, slot = 0;
    int h;
    if (e->stop) {
        sah_emit(s, s->cur, p, n, e->out_at + (p - s->cn[c].first));
        return;
    }
    at[0] = at_in[0];
    at[1] = at_in[1];
    if (!e->taken) {
        for (a = 0; a < n; a++)
            s->nxt[at[side[a] & S_RIGHT]++] = r[a];
    } else {
        for (a = 0; a < n; a++) {
            const unsigned sd = side[a];
            if (sd & S_CUT) { /* the halves weighed */
                s->nxt[at[0]].box = hv[2 * slot];
                s->nxt[at[0]++].j = r[a].j;
                s->nxt[at[1]].box = hv[2 * slot + 1];
                s->nxt[at[1]++].j = r[a].j;
            } else {
                s->nxt[at[sd & S_RIGHT]++] = r[a];
            }
            slot += (sd & S_STRADDLE) != 0;
        }
    }
    for (h = 0; h < 2; h++)
        if (e->half_out[h] != NO_OUT) {
            const size_t half_first =
                h ? e->nxt_at + (size_t)(e->nl + e->nls + e->cut - e->cutl)
                  : e->nxt_at;
            sah_emit(s, s->nxt, at_in[h], at[h] - at_in[h],
                     e->half_out[h] + (at_in[h] - half_first));
        }
}

/* Node c written whole (a small node) or piece i (of a large one). */
static void sah_write_node(const sah_ctx *s, size_t c)
{
    const scell *e = &s->cells[c];
    const size_t nh0 = (size_t)(e->nl + e->nls + e->cut - e->cutl);
    size_t at[2];
    at[0] = e->nxt_at;
    at[1] = e->nxt_at + nh0;
    sah_write(s, c, s->cn[c].first, s->cn[c].count, at, e->slot0);
}

static void sah_write_piece(const sah_ctx *s, size_t i)
{
    const spiece *pc = &s->pieces[i];
    sah_write(s, pc->node, pc->first, pc->count, pc->at, pc->slot0);
}

/* Node c's straddlers' slots in halves from *slot on (a large node's
 * piece by piece), partitioned: in node order, compact. */
static void sah_slots(const sah_ctx *s, size_t c, size_t *slot)
{
    scell *e = &s->cells[c];
    size_t i;
    e->slot0 = *slot;
    if (!e->pieces) {
        *slot += (size_t)(e->nls + e->nrs);
        return;
    }
    for (i = e->piece0; i < e->piece0 + e->pieces; i++) {
        s->pieces[i].slot0 = *slot;
        *slot += (size_t)s->pieces[i].nls + s->pieces[i].nrs;
    }
}

/* A level is spread over the threads only when it holds this many
 * references (below, one thread is faster than the hand-overs). */
#define SAH_PAR_REFS 4096u

/* One level on the threads: partition (small nodes whole, large ones in
 * pieces), clip and weigh every node in parallel (as though the budget
 * lasted the level: a node's result does not depend on it), place
 * serially, write in parallel.  Nodes after the one that spends the
 * budget are weighed in vain: the price of not waiting for the budget,
 * one level's weighing at most, once. */
static void sah_level_parallel(const sah_ctx *s, size_t ncur, size_t npieces,
                               int level, int threads, uint64_t *remaining,
                               uint64_t *total, size_t *nnext)
{
    int64_t c;
    (void)threads;
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1) nowait
#endif
        for (c = 0; c < (int64_t)npieces; c++)
            sah_partition_piece(s, (size_t)c);
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 8)
#endif
        for (c = 0; c < (int64_t)ncur; c++)
            if (!s->cells[c].pieces)
                sah_partition_node(s, (size_t)c);
#ifdef _OPENMP
#pragma omp single
#endif
        {
            size_t i, slot = 0;
            for (i = 0; i < ncur; i++)
                sah_slots(s, i, &slot);
        }
        /* the small nodes weighed whole, the large ones' straddlers
         * clipped piece by piece */
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 8) nowait
#endif
        for (c = 0; c < (int64_t)ncur; c++) {
            if (s->cells[c].pieces)
                sah_join(s, (size_t)c);
            sah_judge(s, (size_t)c);
            if (!s->cells[c].pieces && s->cells[c].cand)
                sah_weigh(s, (size_t)c, 1);
        }
        if (npieces) {
#ifdef _OPENMP
#pragma omp barrier
#pragma omp for schedule(dynamic, 1)
#endif
            for (c = 0; c < (int64_t)npieces; c++) {
                const spiece *pc = &s->pieces[c];
                if (s->cells[pc->node].cand)
                    sah_clip(s, pc->node, pc->first,
                             (size_t)pc->first + pc->count, pc->slot0);
            }
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1) nowait
#endif
            for (c = 0; c < (int64_t)ncur; c++)
                if (s->cells[c].pieces && s->cells[c].cand)
                    sah_weigh(s, (size_t)c, 0);
        }
#ifdef _OPENMP
#pragma omp barrier
#pragma omp single
#endif
        {
            size_t i, pos = 0;
            for (i = 0; i < ncur; i++)
                sah_place(s, i, level, remaining, total, &pos, nnext);
        }
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1) nowait
#endif
        for (c = 0; c < (int64_t)npieces; c++)
            sah_write_piece(s, (size_t)c);
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 8) nowait
#endif
        for (c = 0; c < (int64_t)ncur; c++)
            if (!s->cells[c].pieces)
                sah_write_node(s, (size_t)c);
    }
}

/* The large nodes' pieces (in node order), their count. */
static size_t sah_cut_pieces(const sah_ctx *s, size_t ncur)
{
    size_t c, n = 0;
    for (c = 0; c < ncur; c++) {
        const snode *nd = &s->cn[c];
        scell *e = &s->cells[c];
        uint32_t f;
        e->piece0 = n;
        e->pieces = 0;
        if (nd->count <= SAH_PIECE)
            continue;
        for (f = 0; f < nd->count; f += SAH_PIECE) {
            spiece *pc = &s->pieces[n++];
            pc->node = (uint32_t)c;
            pc->first = nd->first + f;
            pc->count = nd->count - f < SAH_PIECE ? nd->count - f : SAH_PIECE;
            pc->cut = pc->cutl = 0;
        }
        e->pieces = n - e->piece0;
    }
    return n;
}

static atrbvh_status sah_refs(const atrbvh_i_run *run, const grid *g,
                              const atrbvh_box *boxes, const uint32_t *ids,
                              uint32_t kept, const atrbvh_box *scene,
                              uint64_t budget, atrbvh_box *out,
                              uint32_t *out_ids, uint64_t *out_total,
                              atrbvh_error *error)
{
    const int threads = run->cfg->threads;
    const size_t cap = (size_t)kept + (size_t)budget;
    /* a node that is cut further holds more than SAH_STOP references;
     * a large node, more than SAH_PIECE, has at most twice its share of
     * pieces */
    const size_t most = cap / (SAH_STOP + 1) + 1;
    const size_t most_pieces = 2 * (cap / SAH_PIECE) + 1;
    sah_ctx s;
    uint64_t remaining = budget, total = 0;
    size_t ncur = 0, i;
    int64_t j;
    int level;
    atrbvh_status st = ATRBVH_OK;

    (void)threads;
    s.run = run;
    s.g = g;
    s.boxes = boxes;
    s.ids = ids;
    s.min_overlap = SAH_ALPHA * atrbvh_box_area(*scene);
    s.out = out;
    s.out_ids = out_ids;
    s.cur = atrbvh_i_alloc_array(cap, sizeof *s.cur);
    s.nxt = atrbvh_i_alloc_array(cap, sizeof *s.nxt);
    s.cn = atrbvh_i_alloc_array(most, sizeof *s.cn);
    s.nn = atrbvh_i_alloc_array(most, sizeof *s.nn);
    s.cells = atrbvh_i_alloc_array(most, sizeof *s.cells);
    s.pieces = atrbvh_i_alloc_array(most_pieces, sizeof *s.pieces);
    s.side = atrbvh_i_alloc_array(cap, sizeof *s.side);
    s.halves = cap <= SIZE_MAX / 2
                   ? atrbvh_i_alloc_array(2 * cap, sizeof *s.halves)
                   : NULL;
    if (!s.cur || !s.nxt || !s.cn || !s.nn || !s.cells || !s.pieces ||
        !s.side || !s.halves) {
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                           "cannot allocate the SAH split of %lu "
                           "references",
                           (unsigned long)cap);
        goto done;
    }
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) \
    if (kept >= SAH_PAR_REFS)
#endif
    for (j = 0; j < (int64_t)kept; j++) {
        s.cur[j].box = boxes[j];
        s.cur[j].j = (uint32_t)j;
    }
    if (kept > SAH_STOP) {
        s.cn[0].first = 0;
        s.cn[0].count = kept;
        s.cn[0].qlo[0] = s.cn[0].qlo[1] = s.cn[0].qlo[2] = 0;
        ncur = 1;
    } else {
        sah_emit(&s, s.cur, 0, kept, 0);
        total = kept;
    }
    /* once the budget is spent, nothing more can be cut: the nodes left
     * are emitted as they are */
    for (level = 3 * ATRBVH_MORTON_BITS - 1; level >= 0 && ncur && remaining;
         level--) {
        const size_t refs = (size_t)s.cn[ncur - 1].first +
                            s.cn[ncur - 1].count - s.cn[0].first;
        size_t nnext = 0, npieces;
        s.k = 2 - level % 3;
        s.half = 1u << (level / 3);
        if (g->scale[s.k] == 0.0)
            continue; /* the centroids are flat on this axis: no plane */
        npieces = sah_cut_pieces(&s, ncur);
        if (threads > 1 && refs >= SAH_PAR_REFS) {
            sah_level_parallel(&s, ncur, npieces, level, threads, &remaining,
                               &total, &nnext);
        } else {
            /* one node after the other, each weighed only while budget
             * is left (the same result, no weighing in vain) */
            size_t c, pos = 0, slot = 0;
            for (c = 0; c < ncur; c++) {
                const scell *e = &s.cells[c];
                if (e->pieces) {
                    for (i = e->piece0; i < e->piece0 + e->pieces; i++)
                        sah_partition_piece(&s, i);
                    sah_slots(&s, c, &slot);
                    sah_join(&s, c);
                } else {
                    sah_partition_node(&s, c);
                    sah_slots(&s, c, &slot);
                }
                sah_judge(&s, c);
                if (e->cand && remaining)
                    sah_weigh(&s, c, 1);
                sah_place(&s, c, level, &remaining, &total, &pos, &nnext);
            }
            for (i = 0; i < npieces; i++)
                sah_write_piece(&s, i);
            for (c = 0; c < ncur; c++)
                if (!s.cells[c].pieces)
                    sah_write_node(&s, c);
        }
        {
            sref *t = s.cur;
            snode *tn = s.cn;
            s.cur = s.nxt;
            s.nxt = t;
            s.cn = s.nn;
            s.nn = tn;
        }
        ncur = nnext;
    }
    /* the nodes left, in order */
    for (i = 0; i < ncur; i++) {
        s.cells[i].out_at = (size_t)total;
        total += s.cn[i].count;
    }
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64) \
    if (total >= SAH_PAR_REFS)
#endif
    for (j = 0; j < (int64_t)ncur; j++)
        sah_emit(&s, s.cur, s.cn[j].first, s.cn[j].count, s.cells[j].out_at);
    *out_total = total;
done:
    atrbvh_i_free(s.cur);
    atrbvh_i_free(s.nxt);
    atrbvh_i_free(s.cn);
    atrbvh_i_free(s.nn);
    atrbvh_i_free(s.cells);
    atrbvh_i_free(s.pieces);
    atrbvh_i_free(s.side);
    atrbvh_i_free(s.halves);
    return st;
}

/* The box of the references' centroids (from atrbvh_box_empty), on the
 * threads: each thread's contiguous part (schedule static: parts in
 * thread order), the parts joined in thread order (ordered), so that
 * among equal extremes (+0 and -0) the first in reference order wins,
 * as in one loop over them: the same bits for any thread count. */
NO_SLP static atrbvh_box centroid_box(const atrbvh_box *refs, size_t n,
                               int threads)
{
    atrbvh_box c = atrbvh_box_empty();
    (void)threads;
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if (n >= SAH_PAR_REFS)
#endif
    {
        atrbvh_box part = atrbvh_box_empty();
        int64_t i;
        int t, k, nt = 1;
#ifdef _OPENMP
        nt = omp_get_num_threads();
#pragma omp for schedule(static) nowait
#endif
        for (i = 0; i < (int64_t)n; i++) {
            /* written out per axis (GCC -O2 keeps a 3-iteration loop) */
            const float m0 = atrbvh_box_centre(refs[i], 0),
                        m1 = atrbvh_box_centre(refs[i], 1),
                        m2 = atrbvh_box_centre(refs[i], 2);
            part.min[0] = m0 < part.min[0] ? m0 : part.min[0];
            part.min[1] = m1 < part.min[1] ? m1 : part.min[1];
            part.min[2] = m2 < part.min[2] ? m2 : part.min[2];
            part.max[0] = m0 > part.max[0] ? m0 : part.max[0];
            part.max[1] = m1 > part.max[1] ? m1 : part.max[1];
            part.max[2] = m2 > part.max[2] ? m2 : part.max[2];
        }
#ifdef _OPENMP
#pragma omp for ordered schedule(static, 1)
#endif
        for (t = 0; t < nt; t++) {
#ifdef _OPENMP
#pragma omp ordered
#endif
            for (k = 0; k < 3; k++) {
                if (part.min[k] < c.min[k])
                    c.min[k] = part.min[k];
                if (part.max[k] > c.max[k])
                    c.max[k] = part.max[k];
            }
        }
    }
    return c;
}

atrbvh_status atrbvh_i_split_prims(atrbvh_device *dev, atrbvh_i_run *run,
                                   atrbvh_error *error)
{
    const atrbvh_i_config *cfg = run->cfg;
    const int threads = cfg->threads;
    atrbvh_box *boxes = NULL, *refs = NULL, scene, centroids;
    uint32_t *ids = NULL, *ref_ids = NULL, *count = NULL, kept = 0;
    double *prio = NULL;
    first_tree ft;
    uint32_t *chosen = NULL;
    const int tree = cfg->split_rule == ATRBVH_SPLIT_TREE;
    const size_t stack_len = (size_t)(tree ? GAIN_SPLITS : MAX_SPLITS) + 2;
    piece *stacks = NULL;
    uint64_t *offset = NULL, budget, total = 0, want;
    size_t invalid = 0, i;
    atrbvh_status st;
    grid g;
    int k, failed = 0;
    double d, d_lo, d_hi, psum = 0.0;

    memset(&ft, 0, sizeof ft);
    st = atrbvh_i_scan_prims(&run->in, cfg, &boxes, &ids, &kept, &scene,
                             &centroids, &invalid, error);
    if (st != ATRBVH_OK)
        return st;
    run->invalid = invalid;
    run->bad = 0;
    run->split_prims = kept;
    /* the SAH rule models the LBVH's partitions, so its grid is the
     * Morton frame's (the centroids' box); the others cut on the scene
     * box's grid */
    grid_over(cfg->split_rule == ATRBVH_SPLIT_SAH ? &centroids : &scene, &g);
    want = (uint64_t)floor(cfg->split_budget * (double)kept);
    budget = MAX_REFS - (uint64_t)kept;
    if (want < budget)
        budget = want;

    if (cfg->split_rule == ATRBVH_SPLIT_SAH) {
        const size_t cap = (size_t)kept + (size_t)budget;
        refs = atrbvh_i_alloc_array(cap, sizeof *refs);
        ref_ids = atrbvh_i_alloc_array(cap, sizeof *ref_ids);
        if (!refs || !ref_ids) {
            st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                               "cannot allocate %lu split references",
                               (unsigned long)cap);
            goto done;
        }
        st = sah_refs(run, &g, boxes, ids, kept, &scene, budget, refs,
                      ref_ids, &total, error);
        if (st != ATRBVH_OK)
            goto done;
        if (total == kept) {
            /* nothing cut: the triangles in index order, as without
             * splitting (the recursion's order would change how the
             * Morton sort breaks ties, so not the ordinary tree) */
            int64_t j;
            memcpy(refs, boxes, (size_t)kept * sizeof *refs);
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) \
    if (kept >= SAH_PAR_REFS)
#endif
            for (j = 0; j < (int64_t)kept; j++)
                ref_ids[j] = ids ? ids[j] : (uint32_t)j;
        }
        centroids = centroid_box(refs, (size_t)total, threads);
        goto emit;
    }
    prio = atrbvh_i_alloc_array(kept, sizeof *prio);
    if (tree)
        chosen = atrbvh_i_alloc_array(kept, sizeof *chosen);
    count = atrbvh_i_alloc_array(kept, sizeof *count);
    offset = atrbvh_i_alloc_array((size_t)kept + 1, sizeof *offset);
    if (!prio || (tree && !chosen) || !count || !offset) {
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                           "cannot allocate the split priorities of %lu "
                           "triangles",
                           (unsigned long)kept);
        goto done;
    }
    if (tree && budget > 0) {
        st = first_tree_open(run, &centroids, &ft, error);
        if (st != ATRBVH_OK)
            goto done;
    }
    {
        int64_t j;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1024)
#endif
        for (j = 0; j < (int64_t)kept; j++) {
            const uint32_t id = ids ? ids[j] : (uint32_t)j;
            piece stack[GAIN_SPLITS + 2];
            atrbvh_box pieces[GAIN_SPLITS + 1];
            double v[3][3], best = 0.0;
            uint32_t s, np, best_s = 0;
            tri_path w;
            if (!tree) {
                tri_vertices(&run->in, id, v);
                prio[j] = priority(&g, v, &boxes[j]);
                continue;
            }
            if (budget > 0 && walk_up(&ft, cfg, ft.leaf_of[id], &w)) {
                tri_vertices(&run->in, id, v);
                /* only a triangle that makes the nodes above its parent
                 * larger by more than its own box's area (a large one
                 * among small ones) is weighed, and none whose removal
                 * saves less than the least area boxes around its
                 * pieces can have (each face pair at least the
                 * triangle's projection) */
                if (w.above > cfg->cost.ci * atrbvh_box_area(boxes[j]) &&
                    w.removal > (cfg->cost.ci + cfg->cost.ct) * min_area(v))
                    /* 1, 3, 7 splits: more only while the gain per split
                     * holds */
                    for (s = 1; s <= GAIN_SPLITS; s = 2 * s + 1) {
                        double gain;
                        np = split_one(&g, v, &boxes[j], s, stack, pieces);
                        if (np < 2 || np - 1 <= best_s)
                            break;
                        gain = cut_gain(&ft, cfg, &w, ft.leaf_of[id], pieces,
                                        (int)np);
                        if (!(gain > 0.0) ||
                            (best_s && gain * best_s < best * (np - 1)))
                            break;
                        best = gain;
                        best_s = np - 1;
                    }
            }
            chosen[j] = best_s;
            prio[j] = best_s ? best / (double)best_s : 0.0;
        }
    }
    for (i = 0; i < kept; i++) /* in index order: the same bits always */
        psum += prio[i] * (chosen ? (double)chosen[i] : 1.0);

    /* The largest scale d whose total is within the budget. */
    d = 0.0;
    if (budget > 0 && psum > 0.0 &&
        total_splits(prio, chosen, kept, INFINITY, threads) <= budget) {
        d = INFINITY; /* every cut that pays fits */
    } else if (budget > 0 && psum > 0.0) {
        /* sum of s_i over d p_i >= 1 <= d sum p_i s_i = B */
        d_lo = (double)budget / psum;
        d_hi = d_lo;
        for (k = 0; k < 64; k++) {
            d_hi *= 2.0;
            if (total_splits(prio, chosen, kept, d_hi, threads) > budget)
                break;
            d_lo = d_hi;
        }
        /* until the total is the budget exactly or the bracket is
         * 2^-24 wide (a fixed sequence of steps: the same everywhere) */
        if (k < 64)
            for (k = 0; k < 24; k++) {
                double mid = 0.5 * (d_lo + d_hi);
                uint64_t t = total_splits(prio, chosen, kept, mid, threads);
                if (t > budget) {
                    d_hi = mid;
                } else {
                    d_lo = mid;
                    if (t == budget)
                        break;
                }
            }
        d = d_lo;
    }
    offset[0] = 0;
    for (i = 0; i < kept; i++) {
        uint32_t si = splits_of(d, prio[i], chosen, i);
        offset[i + 1] = offset[i] + si + 1;
    }
    total = offset[kept];

    refs = atrbvh_i_alloc_array((size_t)total, sizeof *refs);
    ref_ids = atrbvh_i_alloc_array((size_t)total, sizeof *ref_ids);
    if (!refs || !ref_ids) {
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                           "cannot allocate %llu split references",
                           (unsigned long long)total);
        goto done;
    }
    /* Each thread's stack of pieces, all allocated here: the caller's
     * allocator (atrbvh_set_allocator) is never called from several
     * threads at once. */
    stacks = atrbvh_i_alloc_array((size_t)threads * stack_len,
                                  sizeof *stacks);
    if (!stacks) {
        failed = 1;
        goto stacks_done;
    }
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
#ifdef _OPENMP
        piece *stack = stacks + (size_t)omp_get_thread_num() * stack_len;
#else
        piece *stack = stacks;
#endif
        int64_t j;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 256)
#endif
        for (j = 0; j < (int64_t)kept; j++) {
            const uint32_t splits =
                (uint32_t)(offset[j + 1] - offset[j] - 1);
            if (splits == 0) {
                refs[offset[j]] = boxes[j];
                count[j] = 1;
            } else { /* by the tree rule, the pieces cut_gain weighed */
                double v[3][3];
                tri_vertices(&run->in, ids ? ids[j] : (uint32_t)j, v);
                count[j] = split_one(&g, v, &boxes[j], splits, stack,
                                     &refs[offset[j]]);
            }
        }
    }
    atrbvh_i_free(stacks);
stacks_done:
    if (failed) {
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                           "cannot allocate the splitting stacks");
        goto done;
    }
    /* Compact in triangle order (a triangle may have found fewer planes
     * than splits), ids alongside; centroids over the references. */
    total = 0;
    centroids.min[0] = centroids.min[1] = centroids.min[2] = INFINITY;
    centroids.max[0] = centroids.max[1] = centroids.max[2] = -INFINITY;
    for (i = 0; i < kept; i++) {
        uint32_t c;
        for (c = 0; c < count[i]; c++) {
            const atrbvh_box b = refs[offset[i] + c];
            refs[total] = b;
            ref_ids[total] = ids ? ids[i] : (uint32_t)i;
            for (k = 0; k < 3; k++) {
                float m = atrbvh_box_centre(b, k);
                if (m < centroids.min[k])
                    centroids.min[k] = m;
                if (m > centroids.max[k])
                    centroids.max[k] = m;
            }
            total++;
        }
    }
emit:
    run->n = (uint32_t)total;
    if (total == kept) /* nothing split: an ordinary tree */
        run->split_prims = 0;
    run->scene = scene;
    run->centroids = centroids;
    st = dev->backend->set_prims(dev, run, refs, ref_ids, error);
done:
    atrbvh_i_free(boxes);
    atrbvh_i_free(ids);
    atrbvh_i_free(prio);
    first_tree_free(&ft);
    atrbvh_i_free(chosen);
    atrbvh_i_free(count);
    atrbvh_i_free(offset);
    atrbvh_i_free(refs);
    atrbvh_i_free(ref_ids);
    return st;
}

/* No leaf lists a primitive twice: within each leaf the first reference
 * of each primitive stays (the order kept), the index array is compacted
 * and the leaves' ranges moved down.  Boxes stay (a leaf's box covers its
 * references, so also the ones kept).  Linear: a stamp per input
 * primitive holds the last leaf that listed it. */
atrbvh_status atrbvh_i_split_merge(atrbvh_bvh *bvh, size_t input_count,
                                   atrbvh_error *error)
{
    size_t i, out = 0;
    uint32_t *stamp = atrbvh_i_alloc_array(input_count, sizeof *stamp);
    if (!stamp)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate %lu primitive stamps",
                             (unsigned long)input_count);
    memset(stamp, 0xff, input_count * sizeof *stamp);
    for (i = 0; i < bvh->node_count; i++) {
        atrbvh_node *nd = &bvh->nodes[i];
        uint32_t a, first = nd->index, kept = 0;
        if (!nd->count)
            continue;
        for (a = 0; a < nd->count; a++) {
            const uint32_t p = bvh->prim_indices[first + a];
            if (stamp[p] == (uint32_t)i)
                continue;
            stamp[p] = (uint32_t)i;
            bvh->prim_indices[out + kept++] = p;
        }
        nd->index = (uint32_t)out;
        nd->count = kept;
        out += kept;
    }
    bvh->prim_count = out;
    atrbvh_i_free(stamp);
    return ATRBVH_OK;
}
