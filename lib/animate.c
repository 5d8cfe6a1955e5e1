/*
 * animate.c - animation: atrbvh_refit (new positions, same topology) and
 * atrbvh_reoptimise (treelet rounds on the existing tree, then collapse
 * and layout).
 *
 * Refit works on the output node array itself: a leaf's box is the union
 * of its primitives' boxes (shared/stages.h's atrbvh_prim_box_triangle /
 * _box, the very rule the bounds stage uses), an internal node's the union
 * of its children's.  In depth-first order children come after their
 * parent, so one pass in reverse order meets every child before its
 * parent.  Min/max only: any order and any thread count give the same
 * bits.  The boxes are computed into the device's scratch and copied into
 * the tree only once every primitive was found valid, so a failure leaves
 * the tree as it was; on an open device nothing is allocated once the
 * scratch is large enough.  It runs on the host for every device (its
 * work is a few memory passes; the arrays are the host's).
 *
 * Re-optimise turns the output back into a binary tree - every leaf of k
 * primitives becomes a balanced subtree over its primitives in index
 * order (the range [lo, hi) splits at lo + (hi - lo) / 2) - and runs the
 * pipeline's own stages on it through the backend table: bounds (the
 * new positions), set_tree (this topology instead of morton, sort and
 * hierarchy), refit, optimise, collapse, layout.  Every output leaf of the
 * old tree is a node of that binary tree whose collapsed cost collapse
 * considers, and treelets only write back strictly cheaper topologies, so
 * with the build's cost constants the SAH never rises (up to the summation
 * order of atrbvh_sah).
 */
#include "config.h"

#include "internal.h"

#include <string.h>

#define NO_INDEX ((uint64_t)-1)

/* The library's scratch slots (backend.h: ATRBVH_I_SCRATCH_LIB on). */
enum {
    SLOT_BOX = ATRBVH_I_SCRATCH_LIB, /* node boxes of a refit            */
    SLOT_MAP,                        /* output node -> binary node       */
    SLOT_LEFT,                       /* the binary tree of reoptimise    */
    SLOT_RIGHT,
    SLOT_NODES,                      /* reoptimise's output, before copy */
    SLOT_PRIMS,
    SLOT_DEPTH                       /* node depths (statistics)         */
};
ATRBVH_STATIC_ASSERT(SLOT_DEPTH < ATRBVH_I_SCRATCH_SLOTS, lib_slots_fit);

/* Node-sized scratch is taken for the largest tree of the primitive count
 * (2n - 1 nodes), so that frames whose node count grows allocate
 * nothing. */
#define NODES_MOST(b) (2 * (b)->prim_count - 1)

/* The device of the options (a temporary CPU one when none), locked. */
typedef struct anim_dev {
    atrbvh_device temp, *dev;
    int opened; /* a temporary OpenCL device to close */
} anim_dev;

static atrbvh_status dev_get(anim_dev *a, const atrbvh_i_request *req,
                             int need_backend, atrbvh_error *error)
{
    a->opened = 0;
    a->dev = req->device;
    if (!a->dev && need_backend && req->backend == ATRBVH_BACKEND_OPENCL) {
#ifdef ATRBVH_HAVE_OPENCL
        atrbvh_status st = atrbvh_i_device_open_backend(
            &atrbvh_i_cl_backend, req->opencl_device, &a->dev, error);
        if (st != ATRBVH_OK)
            return st;
        a->opened = 1;
#else
        return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, NO_INDEX,
                             "this build of atrbvh has no OpenCL backend "
                             "(configure --enable-opencl)");
#endif
    } else if (!a->dev) {
        atrbvh_i_device_cpu_temp(&a->temp);
        a->dev = &a->temp;
    }
    atrbvh_i_device_lock(a->dev);
    return ATRBVH_OK;
}

static void dev_put(anim_dev *a)
{
    atrbvh_i_device_unlock(a->dev);
    if (a->dev == &a->temp)
        atrbvh_i_scratch_free(&a->temp.scratch);
    else if (a->opened)
        atrbvh_device_close(a->dev);
}

/* The arguments every call checks: options, geometry, and that the
 * geometry is the one the tree was built over (its primitive count; every
 * primitive index of the tree in range). */
static atrbvh_status check_args(const char *fn, const atrbvh_bvh *bvh,
                                const atrbvh_geometry *geometry,
                                const atrbvh_build_options *options,
                                atrbvh_i_request *req, atrbvh_i_input *in,
                                atrbvh_error *error)
{
    atrbvh_status st;
    size_t expect, i;
    atrbvh_i_clear_error(error);
    if (!bvh)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "%s: the BVH is NULL", fn);
    st = atrbvh_i_resolve_options(options, req, error);
    if (st != ATRBVH_OK)
        return st;
    st = atrbvh_i_check_geometry(geometry, in, error);
    if (st != ATRBVH_OK)
        return st;
    if (bvh->split_prims) /* references of one primitive: not refittable */
        return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, NO_INDEX,
                             "%s: the BVH was built with triangle splitting "
                             "(split_budget); rebuild it instead", fn);
    expect = bvh->prim_count + bvh->stats.invalid_skipped;
    if (geometry->primitive_count != expect)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "%s: the geometry has %lu primitives, the BVH "
                             "was built over %lu (same primitives, new "
                             "positions only)",
                             fn, (unsigned long)geometry->primitive_count,
                             (unsigned long)expect);
    if (bvh->node_count == 0 || bvh->prim_count == 0)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "%s: the BVH is empty", fn);
    for (i = 0; i < bvh->prim_count; i++)
        if (bvh->prim_indices[i] >= geometry->primitive_count)
            return atrbvh_i_fail(
                error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)i,
                "%s: the BVH's primitive index %lu (entry %lu) is past the "
                "geometry's %lu primitives",
                fn, (unsigned long)bvh->prim_indices[i], (unsigned long)i,
                (unsigned long)geometry->primitive_count);
    return ATRBVH_OK;
}

/* Box of input primitive j; ATRBVH_PRIM_OK or the kind of fault. */
static int prim_box(const atrbvh_i_input *in, uint64_t j, atrbvh_box *b,
                    uint32_t *value)
{
    const atrbvh_geometry *g = in->g;
    if (g->type == ATRBVH_GEOMETRY_BOXES)
        return atrbvh_prim_box_box(g->boxes, in->bstride / sizeof(float), j,
                                   b);
    return atrbvh_prim_box_triangle(
        g->vertices, in->vstride / sizeof(float), g->vertex_count,
        g->indices, in->istride / sizeof(uint32_t), g->indices != NULL, j, b,
        value);
}

static atrbvh_status prim_error(const atrbvh_i_input *in, uint64_t j,
                                const char *fn, atrbvh_error *error)
{
    atrbvh_box b;
    uint32_t value = 0;
    switch (prim_box(in, j, &b, &value)) {
    case ATRBVH_PRIM_BAD_INDEX:
        return atrbvh_i_fail(error, ATRBVH_ERR_INDEX_RANGE, j,
                             "%s: triangle %lu uses vertex %lu, past the %lu "
                             "vertices",
                             fn, (unsigned long)j, (unsigned long)value,
                             (unsigned long)in->g->vertex_count);
    case ATRBVH_PRIM_INVERTED:
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, j,
                             "%s: box %lu has a minimum above its maximum",
                             fn, (unsigned long)j);
    default:
        return atrbvh_i_fail(error, ATRBVH_ERR_NONFINITE, j,
                             "%s: primitive %lu has a NaN or infinite "
                             "coordinate",
                             fn, (unsigned long)j);
    }
}

#define PRIMS_PER_THREAD ((size_t)1 << 17)

/* The leaf boxes of the tree over the new positions into `box` (entries
 * of leaf nodes only); the lowest invalid primitive is an error. */
static atrbvh_status leaf_boxes(const atrbvh_bvh *bvh,
                                const atrbvh_i_input *in, atrbvh_box *box,
                                int threads, const char *fn,
                                atrbvh_error *error)
{
    const atrbvh_node *nodes = bvh->nodes;
    const int64_t count = (int64_t)bvh->node_count;
    uint64_t bad = NO_INDEX;
    int64_t i;
    /* One thread per PRIMS_PER_THREAD primitives at most: a refit is a few
     * milliseconds of memory traffic, and on a loaded machine waking a
     * thread costs more than the work it would take (measured in
     * docs/animation.md).  Min/max only: the result is the same. */
    if ((size_t)threads > bvh->prim_count / PRIMS_PER_THREAD + 1)
        threads = (int)(bvh->prim_count / PRIMS_PER_THREAD + 1);
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1024) \
    reduction(min : bad)
#else
    (void)threads;
#endif
    for (i = 0; i < count; i++) {
        atrbvh_box acc = atrbvh_box_empty();
        uint32_t k;
        if (nodes[i].count == 0)
            continue;
        for (k = 0; k < nodes[i].count; k++) {
            const uint64_t j = bvh->prim_indices[nodes[i].index + k];
            atrbvh_box b;
            uint32_t value;
            if (prim_box(in, j, &b, &value) != ATRBVH_PRIM_OK) {
                if (j < bad)
                    bad = j;
                continue;
            }
            acc = atrbvh_box_union(acc, b);
        }
        box[i] = acc;
    }
    if (bad != NO_INDEX)
        return prim_error(in, bad, fn, error);
    return ATRBVH_OK;
}

/* Every node box of the tree from the leaf boxes: children follow their
 * parent in depth-first order, so the reverse order meets them first.
 * Writes the tree's nodes (nothing can fail any more). */
static void write_boxes(atrbvh_bvh *bvh, const atrbvh_box *box)
{
    atrbvh_node *nodes = bvh->nodes;
    size_t i = bvh->node_count;
    while (i-- > 0) {
        atrbvh_node *v = &nodes[i];
        int k;
        if (v->count) {
            for (k = 0; k < 3; k++) {
                v->min[k] = box[i].min[k];
                v->max[k] = box[i].max[k];
            }
        } else {
            const atrbvh_node *l = &nodes[i + 1], *r = &nodes[v->index];
            for (k = 0; k < 3; k++) {
                v->min[k] = l->min[k] < r->min[k] ? l->min[k] : r->min[k];
                v->max[k] = l->max[k] > r->max[k] ? l->max[k] : r->max[k];
            }
        }
    }
}

atrbvh_status atrbvh_refit(atrbvh_bvh *bvh, const atrbvh_geometry *geometry,
                           const atrbvh_build_options *options,
                           atrbvh_error *error)
{
    static const char fn[] = "atrbvh_refit";
    atrbvh_i_request req;
    atrbvh_i_input in;
    anim_dev a;
    atrbvh_box *box;
    atrbvh_status st;
    double t0 = atrbvh_i_now_ms();

    st = check_args(fn, bvh, geometry, options, &req, &in, error);
    if (st != ATRBVH_OK)
        return st;
    /* sah_built, the drift's reference, is the SAH of the nodes as built */
    st = atrbvh_i_bvh_settle_stats(bvh);
    if (st != ATRBVH_OK)
        return atrbvh_i_fail(error, st, NO_INDEX,
                             "%s: cannot measure the tree as built (%s)", fn,
                             atrbvh_strerror(st));
    atrbvh_i_bvh_drop_wide(bvh); /* the nodes change */
    st = dev_get(&a, &req, 0, error);
    if (st != ATRBVH_OK)
        return st;
    box = atrbvh_i_scratch_get(&a.dev->scratch, SLOT_BOX, NODES_MOST(bvh),
                               sizeof *box);
    if (!box)
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                           "%s: cannot allocate %lu node boxes", fn,
                           (unsigned long)bvh->node_count);
    else
        st = leaf_boxes(bvh, &in, box, req.cfg.threads, fn, error);
    if (st == ATRBVH_OK) {
        write_boxes(bvh, box);
        bvh->stats.sah = atrbvh_sah(bvh->nodes, bvh->node_count,
                                    bvh->stats.ci, bvh->stats.ct);
        bvh->stats.refit_ms = atrbvh_i_now_ms() - t0;
    }
    dev_put(&a);
    return st;
}

/* ------------------------------------------------------------ reoptimise */

/* The binary tree of the output (n leaves; internal nodes 0..n-2, root 0,
 * leaf n-1+p for primitive position p): left/right (n-1 entries each),
 * map (node_count entries) scratch. */
static void expand(const atrbvh_bvh *bvh, uint32_t *left, uint32_t *right,
                   uint32_t *map)
{
    const atrbvh_node *nodes = bvh->nodes;
    const uint32_t n = (uint32_t)bvh->prim_count;
    uint32_t next = 0;
    size_t i;
#define ASSIGN(node)                                                           \
    ((node).count == 1 ? n - 1 + (node).index : next++)
    map[0] = ASSIGN(nodes[0]);
    for (i = 0; i < bvh->node_count; i++) {
        const atrbvh_node *v = &nodes[i];
        if (v->count == 0) {
            const uint32_t b = map[i];
            map[i + 1] = ASSIGN(nodes[i + 1]);
            map[v->index] = ASSIGN(nodes[v->index]);
            left[b] = map[i + 1];
            right[b] = map[v->index];
        } else if (v->count > 1) {
            /* A balanced subtree over positions [index, index + count). */
            uint32_t stack[3 * 64], top = 0;
            stack[top++] = v->index;
            stack[top++] = v->index + v->count;
            stack[top++] = map[i];
            while (top) {
                const uint32_t id = stack[--top], hi = stack[--top],
                               lo = stack[--top];
                const uint32_t mid = lo + (hi - lo) / 2;
                uint32_t half[2][2];
                int h;
                half[0][0] = lo;
                half[0][1] = mid;
                half[1][0] = mid;
                half[1][1] = hi;
                for (h = 0; h < 2; h++) {
                    const uint32_t a = half[h][0], z = half[h][1];
                    uint32_t child;
                    if (z - a == 1) {
                        child = n - 1 + a;
                    } else {
                        child = next++;
                        stack[top++] = a;
                        stack[top++] = z;
                        stack[top++] = child;
                    }
                    if (h == 0)
                        left[id] = child;
                    else
                        right[id] = child;
                }
            }
        }
    }
#undef ASSIGN
}

/* atrbvh_i_bvh_measure's statistics without its allocations (the tree is
 * the layout stage's, valid by construction): children follow their
 * parent, so depths propagate in one forward pass. */
static atrbvh_status measure(atrbvh_bvh *b, atrbvh_i_scratch *s,
                             const char *fn, atrbvh_error *error)
{
    uint32_t *depth = atrbvh_i_scratch_get(s, SLOT_DEPTH, NODES_MOST(b),
                                           sizeof *depth);
    size_t i, leaves = 0;
    unsigned largest = 0, deepest = 0;
    if (!depth)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "%s: cannot allocate statistics scratch for "
                             "%lu nodes",
                             fn, (unsigned long)b->node_count);
    depth[0] = 0;
    for (i = 0; i < b->node_count; i++) {
        const atrbvh_node *v = &b->nodes[i];
        if (v->count) {
            leaves++;
            if (v->count > largest)
                largest = v->count;
        } else {
            depth[i + 1] = depth[i] + 1;
            depth[v->index] = depth[i] + 1;
        }
        if (depth[i] > deepest)
            deepest = depth[i];
    }
    b->stats.nodes = b->node_count;
    b->stats.leaves = leaves;
    b->stats.primitives = b->prim_count;
    b->stats.max_depth = deepest;
    b->stats.max_leaf_primitives = largest;
    b->stats.sah = atrbvh_sah(b->nodes, b->node_count, b->stats.ci,
                              b->stats.ct);
    b->stats.sah_built = b->stats.sah;
    return ATRBVH_OK;
}

/* The stages from set_tree on, on a locked device; the output into the
 * scratch slots, measured, in *out (arrays not owned). */
static atrbvh_status reopt_run(atrbvh_device *dev, const atrbvh_bvh *bvh,
                               const atrbvh_i_input *in,
                               const atrbvh_i_config *cfg, atrbvh_bvh *out,
                               atrbvh_error *error)
{
    static const char fn[] = "atrbvh_reoptimise";
    const atrbvh_i_backend *be = dev->backend;
    atrbvh_i_scratch *s = &dev->scratch;
    const uint32_t n = (uint32_t)bvh->prim_count;
    const size_t inner = n > 1 ? n - 1 : 1;
    uint32_t *left, *right, *map;
    atrbvh_box *box;
    atrbvh_i_run run;
    atrbvh_status st;
    int s_i;

    if (!be->set_tree)
        return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, NO_INDEX,
                             "%s: the %s backend cannot install a tree yet",
                             fn, be->name);
    left = atrbvh_i_scratch_get(s, SLOT_LEFT, inner, sizeof *left);
    right = atrbvh_i_scratch_get(s, SLOT_RIGHT, inner, sizeof *right);
    map = atrbvh_i_scratch_get(s, SLOT_MAP, NODES_MOST(bvh), sizeof *map);
    if (!left || !right || !map)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "%s: cannot allocate the tree of %lu "
                             "primitives",
                             fn, (unsigned long)n);
    expand(bvh, left, right, map);

    memset(&run, 0, sizeof run);
    run.in = *in;
    run.cfg = cfg;
    st = be->begin(dev, &run, error);
    if (st != ATRBVH_OK)
        return st;
    st = be->stage[ATRBVH_STAGE_BOUNDS](dev, &run, error);
    if (st == ATRBVH_OK && run.bad) {
        /* Some primitive is invalid: the exact error when it is one of
         * the tree's (as refit gives it); one the build left out
         * (skip_invalid) is read by no later stage. */
        box = atrbvh_i_scratch_get(s, SLOT_BOX, NODES_MOST(bvh),
                                   sizeof *box);
        st = box ? leaf_boxes(bvh, in, box, cfg->threads, fn, error)
                 : atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                 "%s: cannot allocate %lu node boxes", fn,
                                 (unsigned long)bvh->node_count);
    }
    run.bad = 0;
    run.n = n;
    if (st == ATRBVH_OK)
        st = be->set_tree(dev, &run, left, right, bvh->prim_indices, error);
    for (s_i = ATRBVH_STAGE_REFIT; st == ATRBVH_OK && s_i < ATRBVH_STAGE_COUNT;
         s_i++) {
        if (s_i == ATRBVH_STAGE_OPTIMISE && cfg->method == ATRBVH_METHOD_LBVH)
            continue;
        if (s_i == ATRBVH_STAGE_LAYOUT) {
            run.nodes = atrbvh_i_scratch_get(s, SLOT_NODES, NODES_MOST(bvh),
                                             sizeof *run.nodes);
            run.prim_indices = atrbvh_i_scratch_get(s, SLOT_PRIMS, n,
                                                    sizeof *run.prim_indices);
            if (!run.nodes || !run.prim_indices) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                   "%s: cannot allocate the output (%lu "
                                   "nodes)",
                                   fn, (unsigned long)run.node_count);
                break;
            }
        }
        st = be->stage[s_i](dev, &run, error);
    }
    be->end(dev, &run);
    if (st != ATRBVH_OK)
        return st;
    memset(out, 0, sizeof *out);
    out->nodes = run.nodes;
    out->node_count = run.node_count;
    out->prim_indices = run.prim_indices;
    out->prim_count = n;
    out->stats = bvh->stats;
    out->stats.ci = cfg->cost.ci;
    out->stats.ct = cfg->cost.ct;
    return measure(out, s, fn, error);
}

atrbvh_status atrbvh_reoptimise(atrbvh_bvh *bvh,
                                const atrbvh_geometry *geometry,
                                const atrbvh_build_options *options,
                                atrbvh_error *error)
{
    static const char fn[] = "atrbvh_reoptimise";
    atrbvh_i_request req;
    atrbvh_i_input in;
    anim_dev a;
    atrbvh_bvh out;
    atrbvh_status st;
    double t0 = atrbvh_i_now_ms();

    st = check_args(fn, bvh, geometry, options, &req, &in, error);
    if (st != ATRBVH_OK)
        return st;
    atrbvh_i_bvh_drop_wide(bvh); /* the nodes change */
    if (bvh->prim_count > (size_t)ATRBVH_SIZE_MASK)
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, NO_INDEX,
                             "%s: %lu primitives", fn,
                             (unsigned long)bvh->prim_count);
    st = dev_get(&a, &req, 1, error);
    if (st != ATRBVH_OK)
        return st;
    st = reopt_run(a.dev, bvh, &in, &req.cfg, &out, error);
    if (st == ATRBVH_OK) {
        /* Into the tree: its arrays when large enough, else new ones. */
        const size_t cap = bvh->node_bytes / sizeof *bvh->nodes;
        if (cap < NODES_MOST(bvh)) {
            /* Once per tree: room for the largest tree (2n - 1 nodes),
             * so that later frames never allocate, whatever their node
             * count. */
            const size_t most = NODES_MOST(bvh);
            atrbvh_node *nodes = atrbvh_i_alloc_array(most, sizeof *nodes);
            if (!nodes) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                   "%s: cannot allocate %lu nodes", fn,
                                   (unsigned long)most);
            } else {
                atrbvh_i_free(bvh->nodes);
                bvh->nodes = nodes;
                bvh->node_bytes = most * sizeof *nodes;
            }
        }
        if (st == ATRBVH_OK) {
            memcpy(bvh->nodes, out.nodes, out.node_count * sizeof *out.nodes);
            memcpy(bvh->prim_indices, out.prim_indices,
                   out.prim_count * sizeof *out.prim_indices);
            bvh->node_count = out.node_count;
            bvh->stats = out.stats; /* measured (reopt_run) */
            bvh->stats_pending = 0;
            bvh->stats.method = req.cfg.method;
            bvh->stats.treelet_size = req.cfg.treelet_size;
            bvh->stats.rounds = req.cfg.rounds;
            bvh->stats.backend = a.dev->backend->kind;
            bvh->stats.threads = req.cfg.threads;
            bvh->stats.refit_ms = atrbvh_i_now_ms() - t0;
        }
    }
    dev_put(&a);
    return st;
}
