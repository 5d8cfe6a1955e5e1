/*
 * cpu/layout.c - stage "layout": the public depth-first node array and the
 * primitive index array, top-down from the collapse decisions: a node's
 * left child follows it, its right child comes after the left subtree, so
 * every offset is known before descending.  On the threads: the "top"
 * (the internal nodes of more than `cut` primitives, cpu.h's
 * atrbvh_i_frontier_cut) is placed first, top-down on the
 * calling thread, which lists the subtrees just below it (the frontier)
 * with their positions; one parallel loop (dynamic, a subtree at a time)
 * emits those, then the calling thread writes the top's nodes bottom-up.
 * One hand-over between threads, where tasks woke a sleeping thread at
 * every spawn (optimise.c says why that costs).
 *
 * An LBVH from the hierarchy stage (cpu.h's ranges) needs no tree walk
 * for a leaf: its primitives are the sorted positions prim_at ..
 * prim_at+count-1, in order, so they are copied from leaf_prim and their
 * boxes folded in that order (the parent links are released then,
 * collapse.c); other trees are walked (gather()).  Such a subtree of up
 * to SMALL_MAX primitives without kept boxes is emitted by one loop
 * (emit_small) and its internal boxes by one backward pass over its
 * output: measured on the dragon, one thread, callgrind, the layout went
 * from about 269 to 134 instructions per triangle with the range copy,
 * the lean triangle box and this loop together.
 *
 * The node boxes of an LBVH without kept ids: the collapse stage released
 * the node box array (the memory plan, backend.c), so the layout makes
 * them again, bottom-up: a leaf's primitive box from the geometry by the
 * shared rule the bounds stage used, an internal node's the union of its
 * children's, left first, as the refit computed it.  The union of a
 * collapsed leaf's primitives folded left to right is the same box: per
 * coordinate a union keeps the second operand on equal values (-0 and
 * +0), so any bracketing of the same sequence keeps the value of the last
 * primitive reaching the extreme (and the empty box is its identity).
 * Otherwise the array is kept and read: with kept ids (skip_invalid,
 * split references) a leaf's box need not be its primitive's, and after
 * the optimise stage a treelet root keeps the box of its old children,
 * which can differ from the union of the new ones in the sign of a zero.
 * An optimised tree without kept ids keeps only the internal boxes there
 * (the sizes took the leaves' half): its leaves' boxes are recomputed.
 */
#include "config.h"

#include "cpu.h"

/* The largest subtree emit_small takes (its list of internal nodes). */
#define SMALL_MAX 4096u
/* Trees smaller than this are laid out on one thread. */
#define PARALLEL_MIN 4096u

typedef struct layout_ctx {
    const atrbvh_i_tree *t;
    const uint32_t *size; /* collapse: nodes of the subtree | leaf flag */
    atrbvh_node *nodes;
    uint32_t *prims;
    /* NULL: the boxes from the geometry below */
    const atrbvh_box *box;
    int leaf_boxes; /* box holds the leaves' boxes too */
    int ranges;     /* subtrees are position ranges (cpu.h) */
    const atrbvh_geometry *g;
    atrbvh_u64 vstride, istride, bstride; /* in elements */
} layout_ctx;

/* Triangle `prim`'s box, known valid (the bounds stage checked every
 * primitive of the tree): atrbvh_prim_box_triangle's common case without
 * its checks, by the same comparisons in the same order - the same bits. */
static inline atrbvh_box triangle_box(const layout_ctx *c, atrbvh_u64 prim)
{
    const atrbvh_geometry *g = c->g;
    const float *v = g->vertices;
    atrbvh_u64 v0, v1, v2;
    const float *a, *b, *d;
    atrbvh_box out;
    float lo, hi;
    if (g->indices) {
        const uint32_t *ix = g->indices + prim * c->istride;
        v0 = ix[0];
        v1 = ix[1];
        v2 = ix[2];
    } else {
        v0 = 3u * prim;
        v1 = v0 + 1u;
        v2 = v0 + 2u;
    }
    a = v + v0 * c->vstride;
    b = v + v1 * c->vstride;
    d = v + v2 * c->vstride;
    lo = b[0] < a[0] ? b[0] : a[0];
    hi = b[0] > a[0] ? b[0] : a[0];
    out.min[0] = d[0] < lo ? d[0] : lo;
    out.max[0] = d[0] > hi ? d[0] : hi;
    lo = b[1] < a[1] ? b[1] : a[1];
    hi = b[1] > a[1] ? b[1] : a[1];
    out.min[1] = d[1] < lo ? d[1] : lo;
    out.max[1] = d[1] > hi ? d[1] : hi;
    lo = b[2] < a[2] ? b[2] : a[2];
    hi = b[2] > a[2] ? b[2] : a[2];
    out.min[2] = d[2] < lo ? d[2] : lo;
    out.max[2] = d[2] > hi ? d[2] : hi;
    return out;
}

/* The box of leaf `leaf` of the tree: stored, or its primitive's. */
static inline atrbvh_box leaf_box(const layout_ctx *c, uint32_t leaf)
{
    const atrbvh_i_tree *t = c->t;
    const atrbvh_geometry *g = c->g;
    atrbvh_u64 prim;
    atrbvh_box b;
    if (c->leaf_boxes)
        return c->box[leaf];
    prim = t->leaf_prim[leaf - (t->n - 1)];
    /* Valid: the bounds stage checked every primitive of the tree.  A
     * triangle's by triangle_box, in registers: the checked function
     * stored the box float by float, and its caller's reload of the
     * box in wider pieces waited for those stores (perf, emit()). */
    if (g->type != ATRBVH_GEOMETRY_BOXES)
        return triangle_box(c, prim);
    (void)atrbvh_prim_box_box(g->boxes, c->bstride, prim, &b);
    return b;
}

/* Sorted positions ahead of the current one whose triangle is prefetched:
 * its vertices at PREFETCH, its index triple at twice that (read back at
 * PREFETCH for the vertices' addresses).  The layout visits positions in
 * increasing order, and the triangles of neighbouring positions are
 * scattered over the vertex and index arrays (perf, dragon: most of
 * range_leaf's samples were on the index and vertex loads).  Dragon, two
 * threads, this loaded machine, fastest of 12 interleaved builds: the
 * stage 54.7 -> 46.8 ns per triangle (8 ahead); 16 measured the same. */
#define PREFETCH 16

/* Always inlined: GCC 12 takes a function of nothing but prefetches for
 * one without side effects and drops its calls. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((always_inline))
#endif
static inline void prefetch_triangle(const uint32_t *leaf_prim, int64_t n,
                                     const float *v, atrbvh_u64 vstride,
                                     const uint32_t *indices,
                                     atrbvh_u64 istride, int64_t pos)
{
#if defined(__GNUC__) || defined(__clang__)
    if (pos + 2 * PREFETCH < n && indices)
        __builtin_prefetch(indices + leaf_prim[pos + 2 * PREFETCH] * istride);
    if (pos + PREFETCH < n) {
        if (indices) {
            const uint32_t *ix =
                indices + leaf_prim[pos + PREFETCH] * istride;
            __builtin_prefetch(v + ix[0] * vstride);
            __builtin_prefetch(v + ix[1] * vstride);
            __builtin_prefetch(v + ix[2] * vstride);
        } else {
            __builtin_prefetch(
                v + 3u * (atrbvh_u64)leaf_prim[pos + PREFETCH] * vstride);
        }
    }
#else
    (void)leaf_prim;
    (void)n;
    (void)v;
    (void)vstride;
    (void)indices;
    (void)istride;
    (void)pos;
#endif
}

/* Writes the primitives under `node`, left to right, from prims[at], and
 * returns their box (the fold of the leaves' boxes when the node boxes
 * are not kept).  A walk by the parent links, so any depth is fine; or,
 * where the collapse released them (a collapsed leaf then holds at most
 * ATRBVH_I_GATHER_MAX primitives, cpu.h), the k-th leaf found from the
 * top by the primitive counts, left when k is below the left child's,
 * for each k: the same leaves in the same order, at most 64 x 63 steps
 * for a leaf.  (A stack of the right children still to take made GCC
 * keep this function out of line, and the layout stage 3-6% slower on
 * the bunny and dabrovic_sponza; this one is inlined, as the walk was,
 * and measured within 1.5% of it.) */
static atrbvh_box gather(const layout_ctx *c, uint32_t node, uint32_t *out)
{
    const atrbvh_i_tree *t = c->t;
    uint32_t cur = node, k = 0;
    atrbvh_box acc = atrbvh_box_empty();
    if (!t->parent) {
        const uint32_t total = t->count[node];
        for (k = 0; k < total; k++) {
            uint32_t r = k;
            cur = node;
            while (!atrbvh_i_is_leaf(t, cur)) {
                const uint32_t l = t->left[cur], cl = t->count[l];
                if (r < cl) {
                    cur = l;
                } else {
                    r -= cl;
                    cur = t->right[cur];
                }
            }
            out[k] = t->leaf_prim[cur - (t->n - 1)];
            if (!c->box)
                acc = atrbvh_box_union(acc, leaf_box(c, cur));
        }
        return acc;
    }
    for (;;) {
        while (!atrbvh_i_is_leaf(t, cur))
            cur = t->left[cur];
        out[k++] = t->leaf_prim[cur - (t->n - 1)];
        if (!c->box)
            acc = atrbvh_box_union(acc, leaf_box(c, cur));
        /* Climb while we are a right child, then step to the sibling. */
        for (;;) {
            uint32_t up;
            if (cur == node)
                return acc;
            up = t->parent[cur];
            if (t->left[up] == cur) {
                cur = t->right[up];
                break;
            }
            cur = up;
        }
    }
}

/* Ranges (cpu.h): emitted leaf `node` at `at`, the leaves of positions
 * prim_at .. prim_at+count-1, in order: the same primitives and the same
 * fold as gather()'s walk. */
static inline void range_leaf(layout_ctx *c, uint32_t node, uint32_t at,
                              uint32_t prim_at)
{
    const atrbvh_i_tree *t = c->t;
    const uint32_t cnt = t->count[node];
    const uint32_t *src = t->leaf_prim + prim_at;
    uint32_t *dst = c->prims + prim_at;
    uint32_t k;
    atrbvh_box b;
    if (c->box) {
        for (k = 0; k < cnt; k++)
            dst[k] = src[k];
        b = atrbvh_i_is_leaf(t, node) ? leaf_box(c, node) : c->box[node];
    } else if (c->g->type != ATRBVH_GEOMETRY_BOXES) {
        /* (in locals: the stores to dst could alias the fields) */
        const uint32_t *const leaf_prim = t->leaf_prim;
        const int64_t n = t->n;
        const float *const v = c->g->vertices;
        const uint32_t *const indices = c->g->indices;
        const atrbvh_u64 vstride = c->vstride, istride = c->istride;
        dst[0] = src[0];
        prefetch_triangle(leaf_prim, n, v, vstride, indices, istride, prim_at);
        b = triangle_box(c, src[0]);
        for (k = 1; k < cnt; k++) {
            dst[k] = src[k];
            prefetch_triangle(leaf_prim, n, v, vstride, indices, istride,
                              (int64_t)prim_at + k);
            b = atrbvh_box_union(b, triangle_box(c, src[k]));
        }
    } else {
        for (k = 0; k < cnt; k++)
            dst[k] = src[k];
        b = leaf_box(c, t->n - 1 + prim_at);
        for (k = 1; k < cnt; k++)
            b = atrbvh_box_union(b, leaf_box(c, t->n - 1 + prim_at + k));
    }
    atrbvh_layout_write(&c->nodes[at], b, c->size[node], cnt, at, prim_at, 0);
}

/* Positions ahead of a node of emit_small whose tree entries are
 * prefetched. */
#define TREE_AHEAD 64

/* Depth of the explicit stack of emit_small (a Karras tree of 64-bit keys
 * is far shallower; deeper subtrees go on by recursion). */
#define SMALL_STACK 128

static void emit(layout_ctx *c, uint32_t node, uint32_t at, uint32_t prim_at);
static void emit_inner(layout_ctx *c, uint32_t node, uint32_t at,
                       uint32_t prim_at);

/* Ranges without kept boxes: the subtree of `node` at `at` in one
 * preorder loop (each internal node's right child is pushed, its left
 * taken next), every node written but an internal node's box; then its
 * internal nodes backwards, where both children of each are done: the
 * box, the union of the left's and the right's as emit() takes it.  The
 * loop lists the internal nodes' positions as it writes them, so the
 * backward pass visits only those: it used to walk every output
 * position and test each for a leaf, a branch with no pattern to
 * predict (one thread, fastest of 100 builds: the layout 17.4 -> 15.5
 * ns per triangle on the bunny, 16.9 -> 14.7 on sibenik). */
static void emit_small(layout_ctx *c, uint32_t node, uint32_t at,
                       uint32_t prim_at)
{
    const atrbvh_i_tree *t = c->t;
    struct {
        uint32_t node, at, prim;
    } st[SMALL_STACK];
    /* Its internal nodes' output positions, in preorder (at most
     * SMALL_MAX primitives below it: fewer internal nodes). */
    uint32_t inner[SMALL_MAX];
    int sp = 0;
    uint32_t q = 0, pf = prim_at; /* pf: the next position to prefetch */
    for (;;) {
        const uint32_t size = c->size[node];
        if (size & ATRBVH_SIZE_LEAF) {
            range_leaf(c, node, at, prim_at);
            if (sp == 0)
                break;
            sp--;
            node = st[sp].node;
            at = st[sp].at;
            prim_at = st[sp].prim;
        } else {
            const uint32_t l = t->left[node], r = t->right[node];
            const uint32_t right_at = atrbvh_layout_right_pos(at, c->size[l]);
#if defined(__GNUC__) || defined(__clang__)
            /* The nodes ahead: a preorder meets ids of increasing
             * positions (internal ids are positions, leaves n-1 after),
             * in jumps the hardware prefetchers follow badly (perf: the
             * loads of left, size and count were the loop's stalls).
             * One line (16 entries) of each array at a time, up to
             * TREE_AHEAD positions ahead. */
            while (pf < prim_at + TREE_AHEAD && pf < t->n) {
                const uint32_t leaf = t->n - 1 + pf;
                __builtin_prefetch(&t->left[pf]);
                __builtin_prefetch(&t->right[pf]);
                __builtin_prefetch(&t->count[pf]);
                __builtin_prefetch(&c->size[pf]);
                __builtin_prefetch(&t->count[leaf]);
                __builtin_prefetch(&c->size[leaf]);
                pf += 16;
            }
#endif
            const uint32_t right_prim =
                atrbvh_layout_right_prim(prim_at, t->count[l]);
            atrbvh_node *o = &c->nodes[at];
            o->index = right_at;
            o->count = 0u;
            inner[q++] = at;
            if (sp == SMALL_STACK) {
                emit(c, r, right_at, right_prim);
            } else {
                st[sp].node = r;
                st[sp].at = right_at;
                st[sp].prim = right_prim;
                sp++;
            }
            node = l;
            at = at + 1;
        }
    }
    while (q-- > 0) {
        atrbvh_node *o = &c->nodes[inner[q]];
        const atrbvh_node *nl = o + 1, *nr = &c->nodes[o->index];
        int k;
        for (k = 0; k < 3; k++) {
            /* atrbvh_box_union(left, right), coordinate by coordinate */
            o->min[k] = nl->min[k] < nr->min[k] ? nl->min[k] : nr->min[k];
            o->max[k] = nl->max[k] > nr->max[k] ? nl->max[k] : nr->max[k];
        }
    }
}

/* Writes `node` at output position `at` with its primitives from
 * `prim_at` (shared/stages.h's placement rule), then its children; the
 * node's box is written after theirs. */
static void emit(layout_ctx *c, uint32_t node, uint32_t at, uint32_t prim_at)
{
    const atrbvh_i_tree *t = c->t;
    const int leaf = (c->size[node] & ATRBVH_SIZE_LEAF) != 0;
    const uint32_t l = leaf ? 0 : t->left[node], r = leaf ? 0 : t->right[node];
    atrbvh_box b;
    if (c->ranges && !c->box && t->count[node] <= SMALL_MAX) {
        emit_small(c, node, at, prim_at);
        return;
    }
    if (leaf && c->ranges) {
        range_leaf(c, node, at, prim_at);
        return;
    }
    if (leaf) {
        b = gather(c, node, c->prims + prim_at);
        if (c->box)
            b = atrbvh_i_is_leaf(t, node) ? leaf_box(c, node) : c->box[node];
        atrbvh_layout_write(&c->nodes[at], b, c->size[node], t->count[node],
                            at, prim_at, 0);
        return;
    }
    emit(c, l, at + 1, prim_at);
    emit(c, r, atrbvh_layout_right_pos(at, c->size[l]),
         atrbvh_layout_right_prim(prim_at, t->count[l]));
    emit_inner(c, node, at, prim_at);
}

/* Internal node `node` at `at`, its children written: its own node, the
 * box stored or the union of its children's (left first). */
static void emit_inner(layout_ctx *c, uint32_t node, uint32_t at,
                       uint32_t prim_at)
{
    const atrbvh_i_tree *t = c->t;
    const uint32_t l = t->left[node];
    const uint32_t right_at = atrbvh_layout_right_pos(at, c->size[l]);
    atrbvh_box b;
    if (c->box) {
        b = c->box[node];
    } else {
        const atrbvh_node *nl = &c->nodes[at + 1], *nr = &c->nodes[right_at];
        atrbvh_box bl, br;
        int k;
        for (k = 0; k < 3; k++) {
            bl.min[k] = nl->min[k];
            bl.max[k] = nl->max[k];
            br.min[k] = nr->min[k];
            br.max[k] = nr->max[k];
        }
        b = atrbvh_box_union(bl, br);
    }
    atrbvh_layout_write(&c->nodes[at], b, c->size[node], t->count[node], at,
                        prim_at, c->size[l]);
}

/* A subtree to lay out: its root, output position, first primitive. */
typedef struct layout_item {
    uint32_t node, at, prim;
} layout_item;

typedef struct layout_cut {
    uint32_t cut;
    layout_item *top, *front; /* the top in preorder; the frontier */
    size_t ntop, nfront, cap;
} layout_cut;

/* Top node `node` (internal, not collapsed, more than cut primitives) at
 * `at`: into the top list, its children into the frontier or, top nodes
 * themselves, placed the same way; 0 when a list is full. */
static int place_top(const layout_ctx *c, layout_cut *k, uint32_t node,
                     uint32_t at, uint32_t prim_at)
{
    const atrbvh_i_tree *t = c->t;
    const uint32_t l = t->left[node], r = t->right[node];
    layout_item child[2];
    int side;
    if (k->ntop == k->cap)
        return 0;
    k->top[k->ntop].node = node;
    k->top[k->ntop].at = at;
    k->top[k->ntop].prim = prim_at;
    k->ntop++;
    child[0].node = l;
    child[0].at = at + 1;
    child[0].prim = prim_at;
    child[1].node = r;
    child[1].at = atrbvh_layout_right_pos(at, c->size[l]);
    child[1].prim = atrbvh_layout_right_prim(prim_at, t->count[l]);
    for (side = 0; side < 2; side++) {
        const layout_item *x = &child[side];
        if (!(c->size[x->node] & ATRBVH_SIZE_LEAF) &&
            t->count[x->node] > k->cut) {
            if (!place_top(c, k, x->node, x->at, x->prim))
                return 0;
        } else {
            if (k->nfront == k->cap)
                return 0;
            k->front[k->nfront++] = *x;
        }
    }
    return 1;
}

/* The whole tree: the frontier on the threads, then the top; on one
 * thread when the tree is small or a list does not fit. */
static atrbvh_status emit_all(layout_ctx *c, atrbvh_i_scratch *scratch,
                              int threads, atrbvh_error *error)
{
    const atrbvh_i_tree *t = c->t;
    const uint32_t root_count = t->count[0];
    layout_cut k;
    atrbvh_i_join join = {0};
    int64_t i;
    k.cut = atrbvh_i_frontier_cut(root_count, threads);
    k.cap = atrbvh_i_frontier_cap(threads);
    k.ntop = k.nfront = 0;
    if (threads < 2 || root_count < PARALLEL_MIN || k.cut < 1u ||
        (c->size[0] & ATRBVH_SIZE_LEAF)) {
        emit(c, 0, 0, 0);
        return ATRBVH_OK;
    }
    /* two lists of cap items (cap <= 2^31: no overflow) */
    k.top = atrbvh_i_scratch_get(scratch, CPU_OPTIMISE, 2 * k.cap,
                                 sizeof(layout_item));
    if (!k.top)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate the layout's frontier of %lu "
                             "subtrees",
                             (unsigned long)k.cap);
    k.front = k.top + k.cap;
    if (!place_top(c, &k, 0, 0, 0) || k.nfront < 2u) {
        emit(c, 0, 0, 0);
        return ATRBVH_OK;
    }
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1) nowait
#endif
        for (i = 0; i < (int64_t)k.nfront; i++)
            emit(c, k.front[i].node, k.front[i].at, k.front[i].prim);
        atrbvh_i_join_arrive(&join);
    }
    /* the top bottom-up: a node's children come after it in preorder */
    for (i = (int64_t)k.ntop - 1; i >= 0; i--)
        emit_inner(c, k.top[i].node, k.top[i].at, k.top[i].prim);
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cpu_layout(atrbvh_device *dev, atrbvh_i_run *run,
                                  atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    layout_ctx x;
    atrbvh_status st;
    (void)dev;
    if (c->flat) { /* (kept for the collapse stage's capture) */
        atrbvh_i_scratch_done(c->scratch, CPU_FLAT);
        c->flat = NULL;
    }
    x.t = &c->tree;
    x.size = c->size;
    x.nodes = run->nodes;
    x.prims = run->prim_indices;
    x.box = c->tree.box; /* NULL unless kept (collapse.c) */
    x.leaf_boxes = x.box && !c->sizes_in_leaf_boxes;
    x.ranges = c->ranges && run->cfg->method == ATRBVH_METHOD_LBVH;
    x.g = run->in.g;
    x.vstride = run->in.vstride / sizeof(float);
    x.istride = run->in.istride / sizeof(uint32_t);
    x.bstride = run->in.bstride / sizeof(float);
    st = emit_all(&x, c->scratch, run->cfg->threads, error);
    if (st != ATRBVH_OK)
        return st;
    /* A handle keeps the node boxes of an optimised tree (read here
     * beside the output anyway); an LBVH's collapse releases them. */
    c->tree.box = NULL;
    atrbvh_i_cpu_scratch_end(c);
    return ATRBVH_OK;
}
