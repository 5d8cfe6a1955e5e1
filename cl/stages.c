/*
 * cl/stages.c - the OpenCL backend's stage table: one short function per
 * stage (upload what the stage reads for the first time, queue its
 * kernel(s) with one argument struct), plus begin/end, set_prims,
 * capture and kernel_time.
 *
 * The host waits twice per build: the collapse stage's root size (the
 * output's node count, which the pipeline allocates; the bounds record,
 * with the count of invalid primitives, the hierarchy's status (keys out
 * of order: a failed sort) and the optimise stage's counts are read in
 * the same wait, queued before it) and the layout's output
 * (the nodes' read queued, the primitives' read blocking).  On a device
 * that shares the host's memory (opencl.h's host_memory) the geometry is
 * read and the output written in place, through buffers made over the
 * caller's arrays for the build (wraps), and those reads copy nothing.
 * The Morton
 * frame is the bounds kernel's, computed on the device from the united
 * centroid box by the host's function.  The bounds stage reads its
 * record at once only when the pipeline needs it then (a capture,
 * triangle splitting, skip_invalid, a reoptimise).  Every other launch
 * is queued behind the previous one on the in-order queue, so a stage's
 * wall time in the pipeline is mostly its queueing and its kernels'
 * time shows in the next wait (atrbvh_bvh_kernel_time has each kernel's
 * own, read from the profiling events after the last wait, without a
 * clFinish).
 *
 * The per-item work is in cl/kernels.cl, thin
 * wrappers around lib/shared/; the sequencing, timing, progress between
 * stages and the exact error for an invalid primitive are the pipeline's
 * (lib/pipeline.c).
 *
 * Buffers live on the device handle (cl/memory.c) and stay there between
 * builds; the pipeline holds the handle's lock around every build, so one
 * build at a time uses them.
 */
#include "config.h"

#include "opencl.h"
#include "shared/treelet.h"

#include <string.h>

#define ALIGN64(x) (((x) + 63u) & ~(size_t)63u)

static atrbvh_cl_device *cl_of(atrbvh_device *dev)
{
    return (atrbvh_cl_device *)dev->impl;
}

static size_t tree_nodes(const atrbvh_i_run *run)
{
    return 2 * (size_t)run->n - 1;
}

static size_t tree_inner(const atrbvh_i_run *run)
{
    return run->n > 1 ? (size_t)run->n - 1 : 1;
}

static atrbvh_kargs_tree tree_args(const atrbvh_cl_device *c,
                                   const atrbvh_i_run *run)
{
    atrbvh_kargs_tree a;
    memset(&a, 0, sizeof a);
    a.ci = run->cfg->cost.ci;
    a.ct = run->cfg->cost.ct;
    a.n = run->n;
    a.collapse = run->cfg->cost.collapse != 0;
    a.max_leaf = run->cfg->cost.max_leaf;
    a.has_ids = c->has_ids;
    /* An LBVH from the hierarchy: a subtree's leaves are the sorted
     * positions of its primitives' output range, in order (the CPU's
     * layout uses the same fact, lib/cpu/layout.c's ranges). */
    a.ranges = c->ranges && run->cfg->method == ATRBVH_METHOD_LBVH;
    return a;
}

/* ------------------------------------------------------------ begin/end */
static atrbvh_status cl_begin(atrbvh_device *dev, atrbvh_i_run *run,
                              atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    size_t n = run->in.g->primitive_count;
    CL_CHECK(atrbvh_i_cl_usable(c, error));
    /* 2n - 1 tree nodes must fit the kernels' u32 ids. */
    if (n == 0 || n > 0x7fffffffu)
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, ATRBVH_CL_NO_INDEX,
                             "OpenCL: %lu primitives (1 to 2^31-1 supported)",
                             (unsigned long)n);
    memset(&c->build_times, 0, sizeof c->build_times);
    c->times = &c->build_times;
    c->has_ids = 0;
    c->ranges = 0;
    c->counted = 0;
    c->counters_zero = 0;
    c->refitted = 0;
    c->flags = 0;
    c->prims_set = 0;
    c->laid_out = 0;
    c->tally_late = 0;
    c->opt_treelets = c->opt_applied = c->opt_skipped = 0;
    c->n_launches = c->n_writes = c->n_fills = c->n_reads = 0;
    c->n_finishes = c->n_queued_reads = 0;
    c->n_wraps = 0;
    run->state = c;
    return ATRBVH_OK;
}

static void cl_end(atrbvh_device *dev, atrbvh_i_run *run)
{
    atrbvh_cl_device *c = cl_of(dev);
    atrbvh_error ignored;
    /* A failed stage may leave commands queued (launches, the geometry's
     * queued copy from the caller's arrays): wait for them (their buffers
     * stay on the handle for the next build). */
    if (c->event_count || c->pending)
        (void)atrbvh_i_cl_finish(c, &ignored);
    atrbvh_i_cl_unwrap(c); /* the caller's arrays are theirs again */
    run->state = NULL;
}

/* --------------------------------------------------------------- bounds */
/* The caller's geometry arrays go to the device in place on a device
 * that shares the host's memory (read-only wraps: the device never
 * writes them), else by queued copies into the handle's buffers
 * (atrbvh_i_cl_input).  Either way the caller's arrays stay as they are
 * during the build, and the build's end waits for the queue before it
 * gives them back. */
static atrbvh_status upload_geometry(atrbvh_cl_device *c,
                                     const atrbvh_i_input *in,
                                     atrbvh_kargs_bounds *a,
                                     atrbvh_error *error)
{
    const atrbvh_geometry *g = in->g;
    size_t bytes, n = g->primitive_count;
    if (g->type == ATRBVH_GEOMETRY_TRIANGLES) {
        int indexed = g->indices != NULL;
        if (!atrbvh_i_mul_size(g->vertex_count - 1, in->vstride, &bytes))
            return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE,
                                 ATRBVH_CL_NO_INDEX, "vertices overflow");
        bytes += 3 * sizeof(float);
        CL_CHECK(atrbvh_i_cl_input(c, B_GEOMETRY, g->vertices, bytes, CL_FALSE,
                                   "vertices", error));
        bytes = 4;
        if (indexed) {
            if (!atrbvh_i_mul_size(n - 1, in->istride, &bytes))
                return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE,
                                     ATRBVH_CL_NO_INDEX, "indices overflow");
            bytes += 3 * sizeof(uint32_t);
        }
        if (indexed)
            CL_CHECK(atrbvh_i_cl_input(c, B_INDICES, g->indices, bytes,
                                       CL_FALSE, "indices", error));
        else /* (a kernel argument all the same) */
            CL_CHECK(atrbvh_i_cl_buffer(c, B_INDICES, bytes, 1, "indices",
                                        error));
        a->vstride = in->vstride / sizeof(float);
        a->istride = in->istride / sizeof(uint32_t);
        a->vertex_count = g->vertex_count;
        a->indexed = (atrbvh_u32)indexed;
        return ATRBVH_OK;
    }
    if (!atrbvh_i_mul_size(n - 1, in->bstride, &bytes))
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, ATRBVH_CL_NO_INDEX,
                             "boxes overflow");
    bytes += 6 * sizeof(float);
    CL_CHECK(atrbvh_i_cl_input(c, B_GEOMETRY, g->boxes, bytes, CL_FALSE,
                               "input boxes", error));
    a->bstride = in->bstride / sizeof(float);
    return ATRBVH_OK;
}

/* The bounds kernel's blocks: a few per compute unit, at most 256. */
#define BOUNDS_PARTS_MAX 256u

/* The bounds record's results for the pipeline (scene, centroid boxes,
 * and `bad` when some primitive is invalid: the pipeline then finds the
 * error, or compacts and calls set_prims). */
static void bounds_results(atrbvh_cl_device *c, atrbvh_i_run *run)
{
    run->scene = c->bounds_rec.scene;
    run->centroids = c->bounds_rec.centroids;
    run->bad = c->bounds_rec.invalid != 0u;
    run->bounds_deferred = 0;
}

/* One launch: the boxes and, by its last block, the bounds record
 * (kernels.cl: the united boxes, the invalid count, the Morton frame,
 * which the morton kernel reads on the device).  The host reads the
 * record here when the pipeline needs it now (run->bounds_late_ok
 * unset: a capture, triangle splitting, skip_invalid, a reoptimise);
 * otherwise the collapse stage reads it in the wait it makes anyway
 * (run->bounds_deferred), and the host waits for nothing here. */
static atrbvh_status st_bounds(atrbvh_device *dev, atrbvh_i_run *run,
                               atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    atrbvh_kargs_bounds a;
    size_t partial_bytes;
    memset(&a, 0, sizeof a);
    a.n = (atrbvh_u32)run->in.g->primitive_count;
    a.parts = c->compute_units * 8u;
    if (a.parts > BOUNDS_PARTS_MAX)
        a.parts = BOUNDS_PARTS_MAX;
    if (a.parts > a.n)
        a.parts = a.n;
    /* the record, 2 boxes per block, one u32 per block */
    partial_bytes = sizeof(atrbvh_bounds_record) +
                    2u * (size_t)a.parts * sizeof(atrbvh_box) +
                    (size_t)a.parts * sizeof(cl_uint);
    CL_CHECK(atrbvh_i_cl_buffer(c, B_BOXES, a.n, sizeof(atrbvh_box),
                                "primitive boxes", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_PARTIAL, partial_bytes, 1,
                                "partial boxes", error));
    CL_CHECK(atrbvh_i_cl_sync(c, error));
    CL_CHECK(upload_geometry(c, &run->in, &a, error));
    if (run->in.g->type == ATRBVH_GEOMETRY_TRIANGLES)
        CL_RUN(c, K_BOUNDS_TRIANGLES, a.parts, error, CL_BUF(B_GEOMETRY),
               CL_BUF(B_INDICES), CL_BUF(B_BOXES), CL_BUF(B_PARTIAL),
               CL_BUF(B_SYNC), CL_VAL(a));
    else
        CL_RUN(c, K_BOUNDS_BOXES, a.parts, error, CL_BUF(B_GEOMETRY),
               CL_BUF(B_BOXES), CL_BUF(B_PARTIAL), CL_BUF(B_SYNC),
               CL_VAL(a));
    run->n = a.n;
    if (run->bounds_late_ok) {
        run->bounds_deferred = 1;
        return ATRBVH_OK;
    }
    CL_CHECK(atrbvh_i_cl_download(c, B_PARTIAL, &c->bounds_rec,
                                  sizeof c->bounds_rec, "bounds record",
                                  error));
    bounds_results(c, run);
    return ATRBVH_OK;
}

/* After an invalid primitive: the host's boxes (and kept ids). */
static atrbvh_status cl_set_prims(atrbvh_device *dev, atrbvh_i_run *run,
                                  const atrbvh_box *boxes, const uint32_t *ids,
                                  atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    c->has_ids = 0;
    c->prims_set = 1; /* the host's Morton frame from here on */
    if (run->n == 0)
        return ATRBVH_OK;
    CL_CHECK(atrbvh_i_cl_buffer(c, B_BOXES, run->n, sizeof(atrbvh_box),
                                "primitive boxes", error));
    CL_CHECK(atrbvh_i_cl_upload(c, B_BOXES, boxes,
                                (size_t)run->n * sizeof(atrbvh_box),
                                "primitive boxes", error));
    if (ids) {
        CL_CHECK(atrbvh_i_cl_buffer(c, B_IDS, run->n, sizeof(cl_uint),
                                    "kept ids", error));
        CL_CHECK(atrbvh_i_cl_upload(c, B_IDS, ids,
                                    (size_t)run->n * sizeof(cl_uint),
                                    "kept ids", error));
        c->has_ids = 1;
    }
    return ATRBVH_OK;
}

/* --------------------------------------------------------------- morton */
/* The sort's blocks (the morton kernel finds the varying bits by them)
 * and the most buckets its MSD pass can make for n keys (the digit
 * itself depends on the keys: the kernels find it, atrbvh_sort_msd). */
/* The fewest primitives whose sort looks for big buckets (big_buckets). */
#define ATRBVH_CL_SPLIT_MIN 131072u

static atrbvh_kargs_sort sort_args(const atrbvh_cl_device *c,
                                   const atrbvh_i_run *run)
{
    atrbvh_kargs_sort a;
    atrbvh_u32 shift, bits;
    memset(&a, 0, sizeof a);
    a.n = run->n;
    a.blocks = c->compute_units * 32u;
    if (a.blocks > 256u)
        a.blocks = 256u;
    if (a.blocks > a.n)
        a.blocks = a.n;
    atrbvh_sort_msd(a.n, ~(atrbvh_u64)0, &shift, &bits);
    a.buckets = 1u << bits;
    a.entries = a.buckets * a.blocks; /* at most 2048 x 256 */
    /* (a device of one compute unit splits them too: the split's passes
     * cost about what the bucket's own first level does) */
    a.big = a.n >= ATRBVH_CL_SPLIT_MIN
                ? atrbvh_sort_big(a.n, c->compute_units > 2u ? c->compute_units
                                                             : 2u)
                : ATRBVH_U32_MAX;
    a.into = 1;
    return a;
}

static atrbvh_status st_morton(atrbvh_device *dev, atrbvh_i_run *run,
                               atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    atrbvh_kargs_sort sa = sort_args(c, run);
    atrbvh_kargs_morton a;
    int k;
    memset(&a, 0, sizeof a);
    for (k = 0; k < 3; k++) {
        a.lo[k] = run->morton_lo[k];
        a.scale[k] = run->morton_scale[k];
    }
    a.n = run->n;
    a.blocks = sa.blocks;
    /* The bounds record's frame (the same function of the same centroid
     * box as the host's: the same bits), unless the host replaced the
     * boxes (an invalid primitive left out, triangle splitting): then
     * the pipeline's frame of its centroid box. */
    a.device_frame = !c->prims_set;
    CL_CHECK(atrbvh_i_cl_buffer(c, B_KEYS, a.n, sizeof(cl_ulong), "keys",
                                error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_ORDER, a.n, sizeof(cl_uint), "order",
                                error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_VARY, 2u * (size_t)a.blocks + 1u,
                                sizeof(cl_ulong), "key bits", error));
    CL_CHECK(atrbvh_i_cl_sync(c, error));
    c->counters_zero = 0; /* B_KEYS is B_COUNTER's home */
    CL_RUN(c, K_MORTON, a.blocks, error, CL_BUF(B_BOXES), CL_BUF(B_KEYS),
           CL_BUF(B_ORDER), CL_BUF(B_VARY), CL_BUF(B_SYNC), CL_BUF(B_PARTIAL),
           CL_VAL(a));
    c->counted = 1;
    return ATRBVH_OK;
}

/* ----------------------------------------------------------------- sort */
/* One MSD pass over a's keys (the whole array, or one big bucket's
 * positions): its digit's counts and scan (sort_count) in the pair
 * (src_k, src_v), its stable scatter into (dst_k, dst_v) (sort_scatter),
 * and each bucket's sort from there (sort_buckets: into src when a.into,
 * else in place with src as the scratch). */
static atrbvh_status sort_pass(atrbvh_cl_device *c, const atrbvh_kargs_sort *ap,
                               int src_k, int src_v, int dst_k, int dst_v,
                               atrbvh_error *error)
{
    const atrbvh_kargs_sort a = *ap;
    CL_RUN(c, K_SORT_COUNT, a.blocks, error, CL_BUF(src_k), CL_BUF(B_HIST),
           CL_BUF(B_VARY), CL_BUF(B_SYNC), CL_VAL(a));
    CL_RUN(c, K_SORT_SCATTER, a.blocks, error, CL_BUF(src_k), CL_BUF(src_v),
           CL_BUF(dst_k), CL_BUF(dst_v), CL_BUF(B_HIST), CL_BUF(B_VARY),
           CL_VAL(a));
    CL_RUN(c, K_SORT_BUCKETS, a.buckets, error, CL_BUF(dst_k), CL_BUF(dst_v),
           CL_BUF(src_k), CL_BUF(src_v), CL_BUF(B_HIST), CL_BUF(B_VARY),
           CL_VAL(a));
    return ATRBVH_OK;
}

/* One big bucket (big_buckets), its positions in b: its own varying bits
 * (sort_vary), then a pass from the scratch pair back into (B_KEYS,
 * B_ORDER), its sub-buckets sorted there in place. */
static atrbvh_status split_bucket(atrbvh_cl_device *c,
                                  const atrbvh_kargs_sort *bp,
                                  atrbvh_error *error)
{
    const atrbvh_kargs_sort b = *bp;
    CL_RUN(c, K_SORT_VARY, b.blocks, error, CL_BUF(B_KEYS_TMP), CL_BUF(B_VARY),
           CL_BUF(B_SYNC), CL_VAL(b));
    return sort_pass(c, &b, B_KEYS_TMP, B_ORDER_TMP, B_KEYS, B_ORDER, error);
}

/* The buckets of the first pass that sort_buckets left alone, those of
 * more than a.big keys (shared/sort.h's atrbvh_sort_big), each split by
 * a pass of its own on all blocks, as lib/cpu/sort.c's sort_big: its
 * varying bits (sort_vary), its digit's counts and scan (sort_count),
 * its scatter from the scratch pair back into (B_KEYS, B_ORDER)
 * (sort_scatter), and its sub-buckets sorted in place (sort_buckets,
 * a.into = 0).  The host reads the first pass's digit (the morton
 * kernel's varying bits) and its bucket starts (the scanned counts of
 * block 0) to find them: two blocking reads, so only for builds of at
 * least ATRBVH_CL_SPLIT_MIN primitives (conference's 331,179 keys: one
 * bucket of 206,564 on one work-item took 6.6-8.6 ms on PoCL at 2 cores),
 * where a wait of tens of microseconds is small beside the sort; smaller
 * builds keep the pipeline's two waits, and their big buckets (at most
 * a few tens of thousands of keys) stay on one work-item each. */
static atrbvh_status big_buckets(atrbvh_cl_device *c, const atrbvh_kargs_sort *a,
                                 atrbvh_error *error)
{
    atrbvh_u64 *vary;
    atrbvh_u32 *hist, shift, bits, d;
    atrbvh_status st = ATRBVH_OK;
    vary = atrbvh_i_alloc_array(2u * (size_t)a->blocks + 1u, sizeof *vary);
    if (!vary)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, ATRBVH_CL_NO_INDEX,
                             "OpenCL sort: cannot allocate %lu varying words",
                             (unsigned long)(2u * a->blocks + 1u));
    st = atrbvh_i_cl_download(c, B_VARY, vary,
                              (2u * (size_t)a->blocks + 1u) * sizeof *vary,
                              "varying key bits", error);
    if (st != ATRBVH_OK) {
        atrbvh_i_free(vary);
        return st;
    }
    atrbvh_sort_msd(a->n, vary[2u * a->blocks], &shift, &bits);
    atrbvh_i_free(vary);
    hist = atrbvh_i_alloc_array(((size_t)1 << bits) * a->blocks, sizeof *hist);
    if (!hist)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, ATRBVH_CL_NO_INDEX,
                             "OpenCL sort: cannot allocate %lu bucket starts",
                             (unsigned long)(((size_t)1 << bits) * a->blocks));
    st = atrbvh_i_cl_download(c, B_HIST, hist,
                              ((size_t)1 << bits) * a->blocks * sizeof *hist,
                              "bucket starts", error);
    for (d = 0; st == ATRBVH_OK && d < (1u << bits); d++) {
        const atrbvh_u32 s = hist[atrbvh_sort_slot(d, 0u, a->blocks)];
        const atrbvh_u32 e = d + 1u < (1u << bits)
                                 ? hist[atrbvh_sort_slot(d + 1u, 0u, a->blocks)]
                                 : a->n;
        atrbvh_kargs_sort b = *a;
        atrbvh_u32 sh, bi;
        if (e - s <= a->big)
            continue;
        b.off = s;
        b.n = e - s;
        if (b.blocks > b.n)
            b.blocks = b.n;
        atrbvh_sort_msd(b.n, ~(atrbvh_u64)0, &sh, &bi);
        b.buckets = 1u << bi;
        b.entries = b.buckets * b.blocks; /* within B_HIST: fewer keys */
        b.big = ATRBVH_U32_MAX;
        b.into = 0;
        /* (its pass reuses B_VARY and B_HIST: the next big bucket's
         * start is in the host's copy, read before) */
        st = split_bucket(c, &b, error);
    }
    atrbvh_i_free(hist);
    return st;
}

/* The CPU's sort, kernel for kernel (kernels.cl): the MSD pass from
 * (keys, order) into the scratch pair (sort_count, whose last block
 * scans, and sort_scatter), then sort_buckets sorts each bucket back
 * into B_KEYS and B_ORDER, but for big ones (big_buckets).  Three
 * launches when no bucket can be big; the digit is found on the device
 * from the morton kernel's varying bits (the host does not wait for
 * them unless a bucket can be big). */
static atrbvh_status st_sort(atrbvh_device *dev, atrbvh_i_run *run,
                             atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    atrbvh_kargs_sort a = sort_args(c, run);
    if (run->n < 2)
        return ATRBVH_OK;
    if (!c->counted)
        return atrbvh_i_fail(error, ATRBVH_ERR_BACKEND, ATRBVH_CL_NO_INDEX,
                             "OpenCL sort: no keys (the morton stage did "
                             "not run)");
    CL_CHECK(atrbvh_i_cl_buffer(c, B_KEYS_TMP, a.n, sizeof(cl_ulong),
                                "keys (scratch)", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_ORDER_TMP, a.n, sizeof(cl_uint),
                                "order (scratch)", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_HIST, a.entries, sizeof(cl_uint),
                                "digit counts", error));
    CL_CHECK(atrbvh_i_cl_sync(c, error));
    CL_CHECK(sort_pass(c, &a, B_KEYS, B_ORDER, B_KEYS_TMP, B_ORDER_TMP,
                       error));
    if (a.big != ATRBVH_U32_MAX)
        return big_buckets(c, &a, error);
    return ATRBVH_OK;
}

/* ------------------------------------------------------------ hierarchy */
/* The topology and the refit in one launch (kernels.cl: the CPU's pass):
 * boxes, counts and costs of every node and, for an LBVH, the collapse
 * sizes (st_refit and st_collapse then launch nothing).  The sizes' home
 * is the sort's scratch keys, not the keys the kernel reads (memory.c). */
static atrbvh_status st_hierarchy(atrbvh_device *dev, atrbvh_i_run *run,
                                  atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    atrbvh_kargs_tree a = tree_args(c, run);
    size_t nodes = tree_nodes(run), inner = tree_inner(run);
    cl_uint blocks;
    CL_CHECK(atrbvh_i_cl_buffer(c, B_LEFT, inner, 4, "left", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_RIGHT, inner, 4, "right", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_PARENT, nodes, 4, "parent", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_COUNT, nodes, 4, "count", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_LEAF_PRIM, run->n, 4, "leaf primitives",
                                error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_BOX, nodes, sizeof(atrbvh_box),
                                "node boxes", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_COST, nodes, sizeof(double),
                                "node costs", error));
    /* (an optimised tree's sizes come from the collapse: passed unused;
     * its collapse decisions, kept by the optimise stage, into B_FLAT) */
    CL_CHECK(atrbvh_i_cl_buffer(c, B_SIZE, nodes, 4, "subtree sizes", error));
    c->flags = run->cfg->method != ATRBVH_METHOD_LBVH;
    if (c->flags)
        CL_CHECK(atrbvh_i_cl_buffer(c, B_FLAT, nodes, 1,
                                    "collapse decisions", error));
    CL_CHECK(atrbvh_i_cl_sync(c, error));
    /* Blocks: enough items for every compute unit (one block of no split
     * for a single primitive); their leftovers (ATRBVH_CL_HIER_OVER words
     * each, then the counts) in B_JUMP, which layout reuses later. */
    blocks = c->compute_units * 16u;
    if (blocks > 256u)
        blocks = 256u;
    if (blocks > run->n - 1u)
        blocks = run->n > 1 ? run->n - 1u : 1u;
    CL_CHECK(atrbvh_i_cl_buffer(c, B_JUMP,
                                (size_t)blocks * (ATRBVH_CL_HIER_OVER + 2u),
                                4, "hierarchy leftovers", error));
    /* B_FLAG's second word: the keys' order, read in the collapse stage's
     * wait (st_collapse). */
    CL_CHECK(atrbvh_i_cl_buffer(c, B_FLAG, 2, 4, "hierarchy status",
                                error));
    a.sizes = c->flags ? 2u : 1u;
    /* ids: read only when has_ids; B_ORDER stands in otherwise, and
     * B_SIZE for B_FLAT. */
    CL_RUN(c, K_HIERARCHY, blocks, error, CL_BUF(B_KEYS), CL_BUF(B_LEFT),
           CL_BUF(B_RIGHT), CL_BUF(B_PARENT), CL_BUF(B_COUNT),
           CL_BUF(B_LEAF_PRIM), CL_BUF(B_ORDER),
           CL_BUF(c->has_ids ? B_IDS : B_ORDER), CL_BUF(B_JUMP),
           CL_BUF(B_BOX), CL_BUF(B_COST), CL_BUF(B_SIZE),
           CL_BUF(c->flags ? B_FLAT : B_SIZE), CL_BUF(B_BOXES),
           CL_BUF(B_SYNC), CL_BUF(B_FLAG), CL_VAL(blocks), CL_VAL(a));
    c->ranges = 1;
    c->refitted = 1;
    return ATRBVH_OK;
}

/* ---------------------------------------------------------------- refit */
static atrbvh_status st_refit(atrbvh_device *dev, atrbvh_i_run *run,
                              atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    atrbvh_kargs_tree a = tree_args(c, run);
    size_t nodes = tree_nodes(run);
    if (c->refitted)
        return ATRBVH_OK; /* the hierarchy kernel's pass did it */
    CL_CHECK(atrbvh_i_cl_buffer(c, B_BOX, nodes, sizeof(atrbvh_box),
                                "node boxes", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_COST, nodes, sizeof(double),
                                "node costs", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_COUNTER, nodes, 4, "node counters",
                                error));
    if (!c->counters_zero)
        CL_CHECK(atrbvh_i_cl_zero(c, B_COUNTER, nodes * 4, "node counters",
                                  error));
    c->counters_zero = 1; /* the kernel leaves them zero */
    /* A caller's tree (set_tree): the climb.  An LBVH's collapse sizes
     * in the same climb (st_collapse then only reads the root's; an
     * optimised tree's refit passes them unused). */
    a.sizes = run->cfg->method == ATRBVH_METHOD_LBVH;
    CL_CHECK(atrbvh_i_cl_buffer(c, B_SIZE, nodes, 4, "subtree sizes", error));
    CL_RUN(c, K_REFIT, run->n, error, CL_BUF(B_BOX), CL_BUF(B_COUNT),
           CL_BUF(B_COST), CL_BUF(B_LEFT), CL_BUF(B_RIGHT), CL_BUF(B_PARENT),
           CL_BUF(B_BOXES), CL_BUF(B_ORDER), CL_BUF(B_COUNTER), CL_BUF(B_SIZE),
           CL_VAL(a));
    return ATRBVH_OK;
}

/* ------------------------------------------------------------- optimise */
/* Per-worker scratch: the TRBVH subset tables (2^n entries) or the
 * ATRBVH distance matrix (n(n-1)/2) and the agglomeration's arrays
 * (atrbvh_agg_layout, as the kernel carves them; for
 * ATRBVH_TREELET_AUTO the rule's largest size), each 64-byte aligned;
 * for opt_round4 (a->walks) then the four lanes' interleaved matrices or
 * tables (off_dist4) and TRBVH's lanes 1-3's splits (off_lanes, each
 * off_dist - off_split bytes; lane 0's tables at 0). */
static void scratch_layout(const atrbvh_i_config *cfg,
                           atrbvh_kargs_optimise *a)
{
    size_t subsets = 0, agg = 0, four = 0, lanes = 0, n = cfg->treelet_size;
    if (a->agglomerative) {
        const atrbvh_u32 nmax =
            n == ATRBVH_TREELET_AUTO ? ATRBVH_AUTO_MAX : (atrbvh_u32)n;
        agg = (size_t)atrbvh_agg_layout(NULL, nmax, NULL);
        /* opt_round4: the four interleaved matrices of its
         * agglomerations side by side (atrbvh_agglomerate4) */
        if (a->walks && nmax <= ATRBVH_TREELET_MAX)
            four = (size_t)atrbvh_agglomerate4_doubles(nmax) * sizeof(double);
    } else {
        subsets = (size_t)1 << n;
        /* opt_round4: the DP's four lanes' interleaved tables
         * (atrbvh_trbvh_costs4) and lanes 1-3's splits */
        if (a->walks)
            four = ATRBVH_TRBVH_QUAD_DOUBLES * subsets * sizeof(double);
    }
    a->off_cost = ALIGN64(subsets * sizeof(atrbvh_box));
    a->off_count = a->off_cost + ALIGN64(subsets * sizeof(double));
    a->off_split = a->off_count + ALIGN64(subsets * sizeof(uint32_t));
    a->off_dist = a->off_split + ALIGN64(subsets * sizeof(uint32_t));
    a->off_dist4 = a->off_dist + ALIGN64(agg);
    a->off_lanes = a->off_dist4 + ALIGN64(four);
    if (a->walks && !a->agglomerative)
        lanes = 3u * (size_t)(a->off_dist - a->off_split);
    a->stride = a->off_lanes + lanes;
}

static atrbvh_status st_optimise(atrbvh_device *dev, atrbvh_i_run *run,
                                 atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    const atrbvh_i_config *cfg = run->cfg;
    atrbvh_kargs_optimise a;
    cl_uint workers_max, round;
    size_t marks;
    if (cfg->method == ATRBVH_METHOD_LBVH || cfg->rounds == 0 ||
        run->n < 2 ||
        run->n < (cfg->treelet_size == ATRBVH_TREELET_AUTO ? cfg->gamma
                                                            : cfg->treelet_size))
        return ATRBVH_OK;
    memset(&a, 0, sizeof a);
    a.ci = cfg->cost.ci;
    a.ct = cfg->cost.ct;
    a.collapse = cfg->cost.collapse != 0;
    a.max_leaf = cfg->cost.max_leaf;
    a.n_internal = run->n - 1;
    a.treelet_size = cfg->treelet_size;
    a.agglomerative = cfg->method == ATRBVH_METHOD_ATRBVH;
    /* The skip marks where the CPU keeps them: TRBVH, ATRBVH up to
     * ATRBVH_TREELET_MAX leaves or adaptive (two bytes per internal
     * node, zero before the first round; one dummy word otherwise). */
    a.marks = !a.agglomerative || cfg->treelet_size <= ATRBVH_TREELET_MAX ||
              cfg->treelet_size == ATRBVH_TREELET_AUTO;
    if (a.marks) /* whole words for the fill: n_internal < 2^31 */
        marks = (2u * (size_t)a.n_internal + 3u) & ~(size_t)3u;
    else
        marks = 4;
    /* several treelets an item on a CPU device, where the marks are
     * kept (opt_round4) */
    a.walks = a.marks && c->several_walks;
    /* the collapse decisions kept (B_FLAT; B_MARKS stands in) */
    a.flags = c->flags;
    scratch_layout(cfg, &a);
    /* Enough persistent workers to fill the device, scratch bounded.  On
     * a CPU device (a.walks) 16 a compute unit: each item then walks the
     * starts of a range of nodes four times as long (presumably its four
     * lanes stay full longer: a short range soon leaves fewer than four
     * walks to batch; and its treelets are those of one region of the
     * tree).
     * PoCL, 2 compute units, optimise kernel time against 64 a unit:
     * ATRBVH(9,2) bunny 0.70-0.88, sibenik 0.86, dragon 0.91; TRBVH(7,3)
     * sibenik 0.93, dragon 0.87-0.99; 8 or 4 a unit were no better. */
    workers_max = c->compute_units * (a.walks ? 16u : 64u);
    if (workers_max > 4096u)
        workers_max = 4096u;
    while (workers_max > 1u &&
           (cl_ulong)workers_max * a.stride > c->max_alloc / 2u)
        workers_max /= 2u;
    CL_CHECK(atrbvh_i_cl_buffer(c, B_SCRATCH, workers_max, (size_t)a.stride,
                                "treelet scratch", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_NEEDED, a.n_internal, 4,
                                "crown children", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_MARKS, marks, 1, "skip marks", error));
    CL_CHECK(atrbvh_i_cl_zero(c, B_MARKS, marks, "skip marks", error));
    CL_CHECK(atrbvh_i_cl_buffer(c, B_TALLY, 3, 4, "treelet counts", error));
    CL_CHECK(atrbvh_i_cl_zero(c, B_TALLY, 3 * 4, "treelet counts", error));
    /* The rounds are queued without a wait: opt_round finds the walks'
     * starts in opt_prepare's marks on the device (the tree does not
     * depend on how many items share the nodes, nor on which walks first:
     * a treelet waits for its whole subtree). */
    a.workers = workers_max;
    c->counters_zero = 0; /* (the kernels' own zeroing from here on) */
    for (round = 0; round < cfg->rounds; round++) {
        cl_ulong gamma = (cl_ulong)cfg->gamma << (round < 40u ? round : 40u);
        if (atrbvh_i_stage_progress(run, round, cfg->rounds)) {
            atrbvh_i_cl_finish(c, error);
            return atrbvh_i_fail(error, ATRBVH_ERR_CANCELLED,
                                 ATRBVH_CL_NO_INDEX,
                                 "cancelled in stage optimise, round %u",
                                 (unsigned)round);
        }
        if (gamma > run->n)
            break; /* no crown left (the root's count is n) */
        a.gamma = (atrbvh_u32)gamma;
        a.round = round;
        CL_RUN(c, K_OPT_PREPARE, a.n_internal, error, CL_BUF(B_LEFT),
               CL_BUF(B_RIGHT), CL_BUF(B_COUNT), CL_BUF(B_NEEDED),
               CL_BUF(B_COUNTER), CL_VAL(a));
        CL_RUN(c, a.walks ? K_OPT_ROUND4 : K_OPT_ROUND,
               a.workers, error, CL_BUF(B_LEFT),
               CL_BUF(B_RIGHT), CL_BUF(B_PARENT), CL_BUF(B_COUNT),
               CL_BUF(B_BOX), CL_BUF(B_COST), CL_BUF(B_NEEDED),
               CL_BUF(B_COUNTER), CL_BUF(B_SCRATCH), CL_BUF(B_MARKS),
               CL_BUF(c->flags ? B_FLAT : B_MARKS), CL_BUF(B_TALLY),
               CL_VAL(a));
        /* The round's tree for the pipeline's capture (a blocking read
         * on the in-order queue sees the launch done). */
        if (atrbvh_i_stage_round(run, round + 1)) {
            atrbvh_i_cl_finish(c, error);
            return atrbvh_i_fail(error, ATRBVH_ERR_CANCELLED,
                                 ATRBVH_CL_NO_INDEX,
                                 "cancelled in stage optimise, round %u",
                                 (unsigned)round + 1);
        }
        /* opt_prepare zeroed every internal node's counter and each
         * round's last arrivals set theirs back: zero for the collapse */
        c->counters_zero = 1;
    }
    /* The counts arrive with the collapse stage's wait. */
    CL_CHECK(atrbvh_i_cl_download_queued(c, B_TALLY, c->tally,
                                         sizeof c->tally, "treelet counts",
                                         error));
    c->tally_late = 1;
    return ATRBVH_OK;
}

/* Keys out of order (a sort kernel failed; c->hier_flag[1], the
 * hierarchy kernel's status, holds the first such position + 1): the
 * hierarchy kernel built a stand-in tree so that the kernels behind it
 * stayed in bounds; there is no tree of the scene to capture or lay
 * out. */
static atrbvh_status sort_failed(const atrbvh_device *dev,
                                 const atrbvh_cl_device *c,
                                 const atrbvh_i_run *run, atrbvh_error *error)
{
    return atrbvh_i_fail(
        error, ATRBVH_ERR_BACKEND, (uint64_t)(c->hier_flag[1] - 1u),
        "OpenCL device %s: the sorted Morton keys are out of order at "
        "position %lu of %lu (a sort kernel failed); no tree was built",
        dev->name, (unsigned long)(c->hier_flag[1] - 1u),
        (unsigned long)run->n);
}

/* ------------------------------------------------------------- collapse */
static atrbvh_status queue_layout(atrbvh_cl_device *c, const atrbvh_i_run *run,
                                  atrbvh_error *error);

static atrbvh_status st_collapse(atrbvh_device *dev, atrbvh_i_run *run,
                                 atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    atrbvh_kargs_tree a = tree_args(c, run);
    size_t nodes = tree_nodes(run);
    cl_uint root_size = 0;
    CL_CHECK(atrbvh_i_cl_buffer(c, B_SIZE, nodes, 4, "subtree sizes", error));
    if (run->cfg->method != ATRBVH_METHOD_LBVH) {
        /* (an LBVH's refit computed the sizes: st_refit) */
        if (c->flags) {
            /* An optimised tree from the hierarchy stage: the sizes
             * counted from the decisions kept (B_FLAT), the subtrees
             * below a top of about 4 per item shared by `items` items,
             * then the top (kernels.cl's collapse_count) */
            cl_uint items = c->compute_units * 8u, cut;
            if (items > 256u)
                items = 256u;
            if (items > run->n)
                items = run->n;
            cut = run->n / (4u * items);
            if (cut < ATRBVH_CL_COUNT_CUT_MIN)
                cut = ATRBVH_CL_COUNT_CUT_MIN;
            CL_CHECK(atrbvh_i_cl_sync(c, error));
            CL_RUN(c, K_COLLAPSE_COUNT, items, error, CL_BUF(B_COUNT),
                   CL_BUF(B_LEFT), CL_BUF(B_RIGHT), CL_BUF(B_PARENT),
                   CL_BUF(B_FLAT), CL_BUF(B_SIZE), CL_BUF(B_SYNC),
                   CL_VAL(cut), CL_VAL(items));
        } else {
            /* a caller's tree: decided from the costs, bottom-up */
            if (!c->counters_zero)
                CL_CHECK(atrbvh_i_cl_zero(c, B_COUNTER, nodes * 4,
                                          "node counters", error));
            c->counters_zero = 1; /* the kernel leaves them zero */
            CL_RUN(c, K_COLLAPSE, run->n, error, CL_BUF(B_BOX),
                   CL_BUF(B_COUNT), CL_BUF(B_COST), CL_BUF(B_LEFT),
                   CL_BUF(B_RIGHT), CL_BUF(B_PARENT), CL_BUF(B_SIZE),
                   CL_BUF(B_COUNTER), CL_VAL(a));
        }
    }
    /* The layout's kernels first (they need nothing from the host) unless
     * they write the output in place, then
     * the host's one wait before the output: the root's size, and with
     * it (queued before it on the in-order queue) the bounds record when
     * the bounds stage left it (the pipeline then checks `bad`) and the
     * optimise stage's counts. */
    if (!c->host_memory) /* (else into the output itself: st_layout) */
        CL_CHECK(queue_layout(c, run, error));
    if (run->bounds_deferred)
        CL_CHECK(atrbvh_i_cl_download_queued(c, B_PARTIAL, &c->bounds_rec,
                                             sizeof c->bounds_rec,
                                             "bounds record", error));
    if (c->ranges)
        CL_CHECK(atrbvh_i_cl_download_queued(c, B_FLAG, c->hier_flag,
                                             sizeof c->hier_flag,
                                             "hierarchy status", error));
    CL_CHECK(atrbvh_i_cl_download(c, B_SIZE, &root_size, 4, "subtree sizes",
                                  error));
    if (c->ranges && c->hier_flag[1] != 0u)
        return sort_failed(dev, c, run, error);
    if (run->bounds_deferred)
        bounds_results(c, run);
    if (c->tally_late) {
        c->opt_treelets = c->tally[0];
        c->opt_applied = c->tally[1];
        c->opt_skipped = c->tally[2];
        c->tally_late = 0;
    }
    run->node_count = root_size & ATRBVH_SIZE_MASK;
    return ATRBVH_OK;
}

/* --------------------------------------------------------------- layout */
/* Queues layout_top and layout (kernels.cl), which read nothing from the
 * host.  Into the handle's output buffers, the collapse stage queues them
 * before its wait, so the device runs them while the host waits for the
 * root size and allocates the output, and st_layout only reads it.  On a
 * device that shares the host's memory st_layout queues them into the
 * output itself, which the pipeline has made by then: the device idles
 * while the host allocates it (tens of microseconds), and nothing is
 * copied (a tenth of a millisecond per megabyte here: docs/opencl.md). */
static atrbvh_status queue_layout(atrbvh_cl_device *c, const atrbvh_i_run *run,
                                  atrbvh_error *error)
{
    atrbvh_kargs_tree a = tree_args(c, run);
    cl_uint workers;
    /* The output object itself in place (st_layout: the pipeline has
     * made it by then), else the handle's buffers, sized for the most
     * nodes n leaves can give (2n - 1), not this tree's count: the next
     * build of n primitives then reuses them.  (In the collapse stage
     * run->nodes is not made yet, and only the handle's are used.) */
    CL_CHECK(atrbvh_i_cl_output(c, B_OUT_NODES, run->nodes, run->node_count,
                                tree_nodes(run), sizeof(atrbvh_node),
                                "output nodes", error));
    CL_CHECK(atrbvh_i_cl_output(c, B_OUT_PRIMS, run->prim_indices, run->n,
                                run->n, 4, "output primitive indices", error));
    /* At most one listed subtree per leaf: 3 words each. */
    CL_CHECK(atrbvh_i_cl_buffer(c, B_JUMP, 3 * (size_t)run->n, 4,
                                "layout subtree list", error));
    /* (two words: the second is the hierarchy's, st_hierarchy) */
    CL_CHECK(atrbvh_i_cl_buffer(c, B_FLAG, 2, 4, "layout subtree count",
                                error));
    CL_RUN(c, K_LAYOUT_TOP, 1, error, CL_BUF(B_COUNT), CL_BUF(B_LEFT),
           CL_BUF(B_RIGHT), CL_BUF(B_PARENT), CL_BUF(B_SIZE), CL_BUF(B_BOX),
           CL_BUF(B_OUT_NODES), CL_BUF(B_JUMP), CL_BUF(B_FLAG), CL_VAL(a));
    /* The listed subtrees (their count stays on the device) shared by
     * a few items per compute unit. */
    workers = c->compute_units * 64u;
    if (workers > run->n)
        workers = run->n;
    CL_RUN(c, K_LAYOUT, workers, error, CL_BUF(B_BOX), CL_BUF(B_COUNT),
           CL_BUF(B_LEFT), CL_BUF(B_RIGHT), CL_BUF(B_PARENT), CL_BUF(B_SIZE),
           CL_BUF(B_LEAF_PRIM), CL_BUF(B_JUMP), CL_BUF(B_OUT_NODES),
           CL_BUF(B_OUT_PRIMS), CL_BUF(B_FLAG), CL_VAL(workers), CL_VAL(a));
    c->laid_out = 1;
    return ATRBVH_OK;
}

static atrbvh_status st_layout(atrbvh_device *dev, atrbvh_i_run *run,
                               atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    if (!c->laid_out)
        CL_CHECK(queue_layout(c, run, error));
    /* One wait: the nodes' read queued, the primitives' read blocking
     * behind it on the in-order queue; then the launches' times, without
     * a clFinish (everything queued is done).  On a device that shares
     * the host's memory the kernels wrote the output itself, through
     * wraps of it (queue_layout): the reads are then into the wrapped
     * memory, which OpenCL allows once every command before them is done
     * (the in-order queue), and which copies nothing on such a device
     * (PoCL returns at once; another may copy a cached copy back). */
    CL_CHECK(atrbvh_i_cl_download_queued(
        c, B_OUT_NODES, run->nodes,
        (size_t)run->node_count * sizeof(atrbvh_node), "output nodes",
        error));
    CL_CHECK(atrbvh_i_cl_download(c, B_OUT_PRIMS, run->prim_indices,
                                  (size_t)run->n * 4,
                                  "output primitive indices", error));
    return atrbvh_i_cl_collect(c, error);
}

/* -------------------------------------------------------------- capture */
static atrbvh_status nomem(atrbvh_error *error)
{
    return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, ATRBVH_CL_NO_INDEX,
                         "cannot allocate the stage capture");
}

/* A new host array of n items of `size` bytes, read from `slot`. */
static atrbvh_status copy_out(atrbvh_cl_device *c, int slot, size_t n,
                              size_t size, void *dst_ptr, const char *what,
                              atrbvh_error *error)
{
    void **dst = (void **)dst_ptr;
    *dst = atrbvh_i_alloc_array(n, size);
    if (!*dst)
        return nomem(error);
    return atrbvh_i_cl_download(c, slot, *dst, n * size, what, error);
}

/* The collapse stage's sizes of an optimised tree for its capture: every
 * node's, from the kept decisions and the topology, on the host. */
static atrbvh_status counted_sizes(atrbvh_cl_device *c,
                                   const atrbvh_i_run *run,
                                   atrbvh_i_capture *cap, atrbvh_error *error)
{
    const size_t nodes = tree_nodes(run), inner = run->n - 1u;
    uint32_t *left = atrbvh_i_alloc_array(inner ? inner : 1, 4);
    uint32_t *right = atrbvh_i_alloc_array(inner ? inner : 1, 4);
    unsigned char *flat = atrbvh_i_alloc_array(nodes, 1);
    atrbvh_status st = ATRBVH_OK;
    if (!left || !right || !flat)
        st = nomem(error);
    if (st == ATRBVH_OK && inner > 0)
        st = atrbvh_i_cl_download(c, B_LEFT, left, inner * 4, "left", error);
    if (st == ATRBVH_OK && inner > 0)
        st = atrbvh_i_cl_download(c, B_RIGHT, right, inner * 4, "right",
                                  error);
    if (st == ATRBVH_OK)
        st = atrbvh_i_cl_download(c, B_FLAT, flat, nodes,
                                  "collapse decisions", error);
    if (st == ATRBVH_OK) {
        cap->collapse_size =
            atrbvh_i_sizes_counted(left, right, flat, run->n);
        if (!cap->collapse_size)
            st = nomem(error);
    }
    atrbvh_i_free(left);
    atrbvh_i_free(right);
    atrbvh_i_free(flat);
    return st;
}

static atrbvh_status read_tree(atrbvh_cl_device *c, const atrbvh_i_run *run,
                               int values, atrbvh_i_tree *t,
                               atrbvh_error *error)
{
    size_t nodes = tree_nodes(run), inner = run->n - 1u;
    if (atrbvh_i_tree_alloc(t, run->n, values) != ATRBVH_OK)
        return nomem(error);
    CL_CHECK(atrbvh_i_cl_download(c, B_LEFT, t->left, inner * 4, "left",
                                  error));
    CL_CHECK(atrbvh_i_cl_download(c, B_RIGHT, t->right, inner * 4, "right",
                                  error));
    CL_CHECK(atrbvh_i_cl_download(c, B_PARENT, t->parent, nodes * 4, "parent",
                                  error));
    CL_CHECK(atrbvh_i_cl_download(c, B_COUNT, t->count, nodes * 4, "count",
                                  error));
    CL_CHECK(atrbvh_i_cl_download(c, B_LEAF_PRIM, t->leaf_prim,
                                  (size_t)run->n * 4, "leaf_prim", error));
    if (!values)
        return ATRBVH_OK;
    CL_CHECK(atrbvh_i_cl_download(c, B_BOX, t->box,
                                  nodes * sizeof(atrbvh_box), "box", error));
    return atrbvh_i_cl_download(c, B_COST, t->cost, nodes * sizeof(double),
                                "cost", error);
}

static atrbvh_status cl_capture(atrbvh_device *dev, atrbvh_i_run *run,
                                atrbvh_stage stage, atrbvh_i_capture *cap,
                                atrbvh_error *error)
{
    atrbvh_cl_device *c = cl_of(dev);
    size_t n = run->n;
    switch (stage) {
    case ATRBVH_STAGE_BOUNDS:
        cap->n = run->n;
        cap->scene = run->scene;
        cap->centroids = run->centroids;
        return copy_out(c, B_BOXES, n, sizeof(atrbvh_box), &cap->prim_boxes,
                        "primitive boxes", error);
    case ATRBVH_STAGE_MORTON:
        return copy_out(c, B_KEYS, n, sizeof(uint64_t), &cap->keys, "keys",
                        error);
    case ATRBVH_STAGE_SORT:
        CL_CHECK(copy_out(c, B_KEYS, n, sizeof(uint64_t), &cap->sorted_keys,
                          "keys", error));
        return copy_out(c, B_ORDER, n, sizeof(uint32_t), &cap->order, "order",
                        error);
    case ATRBVH_STAGE_HIERARCHY:
        /* The status first: a stand-in tree (a failed sort) is not the
         * hierarchy of the scene, and no capture may show it as one. */
        if (c->ranges) {
            CL_CHECK(atrbvh_i_cl_download(c, B_FLAG, c->hier_flag,
                                          sizeof c->hier_flag,
                                          "hierarchy status", error));
            if (c->hier_flag[1] != 0u)
                return sort_failed(dev, c, run, error);
        }
        return read_tree(c, run, 0, &cap->hierarchy, error);
    case ATRBVH_STAGE_REFIT:
        return read_tree(c, run, 1, &cap->refit, error);
    case ATRBVH_STAGE_OPTIMISE:
        return read_tree(c, run, 1, &cap->optimise, error);
    case ATRBVH_STAGE_COLLAPSE:
        if (c->flags) /* (collapse_count left those below a collapsed
                       * node: every node's, from the decisions) */
            return counted_sizes(c, run, cap, error);
        return copy_out(c, B_SIZE, tree_nodes(run), sizeof(uint32_t),
                        &cap->collapse_size, "subtree sizes", error);
    default:
        return ATRBVH_OK; /* layout: the output itself */
    }
}

/* The last build's per-kernel device times. */
static int cl_kernel_time(atrbvh_device *dev, size_t i, const char **name,
                          double *ms)
{
    atrbvh_cl_device *c = cl_of(dev);
    if (!c || i >= c->build_times.count)
        return 0;
    if (name)
        *name = c->build_times.name[i];
    if (ms)
        *ms = c->build_times.ms[i];
    return 1;
}

const atrbvh_i_backend atrbvh_i_cl_backend = {
    "opencl",
    ATRBVH_BACKEND_OPENCL,
    atrbvh_i_cl_open,
    atrbvh_i_cl_close,
    cl_begin,
    cl_end,
    {st_bounds, st_morton, st_sort, st_hierarchy, st_refit, st_optimise,
     st_collapse, st_layout},
    cl_set_prims,
    cl_capture,
    atrbvh_i_cl_rays,
    cl_kernel_time,
    atrbvh_i_cl_set_tree};
