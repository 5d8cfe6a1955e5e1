/*
 * cl/kernels.cl - the OpenCL backend's kernels, one (or a short fixed
 * sequence) per stage, with the same names as the CPU stages.  OpenCL C
 * 1.2.  The host prepends the lib/shared headers (the per-item
 * arithmetic the CPU backend compiles as C99, and the argument structs of
 * kargs.h), so the two backends run the same code per item; only the
 * parallel mapping differs.  Every kernel is a thin wrapper: it reads its item, calls the
 * shared function, writes the result.  Scalars come in one struct per
 * stage (shared/kargs.h), by value.
 *
 * Bottom-up passes (a caller's tree's refit, optimise, collapse) use an
 * atomic counter per node: each work-item writes its node, fences,
 * increments the parent's counter; the first arrival stops, the last
 * continues upwards after a fence and sets the counter back to zero, so
 * the next pass needs no fill (a fill, or opt_prepare, zeroes them
 * first).  The hierarchy kernel's tree needs none: it is refitted in
 * the kernel's own post-order pass.  Whole launches end the
 * same way where a step needs everything before it (last_arrival): the
 * sort's scan, the hierarchy's merge.  No work-item ever waits for another (no spinning, no lock-step
 * assumption, no barrier across work-groups), so the passes are correct
 * under any scheduling.  Values written by another work-item are read
 * through volatile pointers after the fence.
 */
#pragma OPENCL FP_CONTRACT OFF
#pragma OPENCL EXTENSION cl_khr_fp64 : enable

/* The fence of the hand-overs between work-items of different
 * work-groups (the bottom-up passes, last_arrival): our writes before
 * the atomic that hands over, the others' writes after the atomic that
 * takes over.  OpenCL 1.2's mem_fence only has to order them for the
 * work-group, and NVIDIA's compiler takes it at its word: it emits
 * membar.cta (seen in the PTX of an H200's driver), under which the refit
 * read a sibling's stale box now and then (test_opencl real_scenes
 * failed on every run there).  On NVIDIA the device-wide membar.gl, by
 * inline PTX; elsewhere mem_fence (PoCL's CPU device: x86 keeps stores
 * in order and its atomics are full barriers). */
#if defined(__NV_CL_C_VERSION) || defined(cl_nv_device_attribute_query)
#define ATRBVH_CL_FENCE() asm volatile("membar.gl;" ::: "memory")
#else
#define ATRBVH_CL_FENCE() mem_fence(CLK_GLOBAL_MEM_FENCE)
#endif

static atrbvh_box load_box_v(__global const atrbvh_box *b, uint i)
{
    volatile __global const float *f = (volatile __global const float *)(b + i);
    atrbvh_box r;
    r.min[0] = f[0];
    r.min[1] = f[1];
    r.min[2] = f[2];
    r.max[0] = f[3];
    r.max[1] = f[4];
    r.max[2] = f[5];
    return r;
}

static uint load_u32_v(__global const uint *p, uint i)
{
    return ((volatile __global const uint *)p)[i];
}

static ulong load_ulong_v(__global const ulong *p, uint i)
{
    return ((volatile __global const ulong *)p)[i];
}

static double load_f64_v(__global const double *p, uint i)
{
    return ((volatile __global const double *)p)[i];
}

/* --------------------------------------------------------- last arrival */
/* A launch's last work-item to finish its share continues alone (the
 * bottom-up passes' pattern for a whole launch): each of `items` items
 * writes its results, fences and counts itself in sync[0]; the one that
 * counts last fences again, resets the word for the next launch (the host
 * zeroes it once, when the buffer is made) and returns true.  The others
 * have written everything it reads (through volatile pointers).  No item
 * waits for another. */
static int last_arrival(__global uint *sync, uint items)
{
    ATRBVH_CL_FENCE(); /* our writes before the count */
    if (atomic_inc(&sync[0]) + 1u < items)
        return 0;
    ATRBVH_CL_FENCE(); /* the others' writes after it */
    sync[0] = 0u;
    return 1;
}

/* ------------------------------------------------------------------ bounds */
/* Item w of a.parts: the box of each primitive of block w
 * (atrbvh_prim_box_triangle / _box, the CPU's functions, in index order),
 * and the block's scene and centroid boxes (atrbvh_scene_add) and count
 * of invalid primitives (NaN/Inf, an index out of range, an inverted
 * box), after the record (kargs.h atrbvh_bounds_record) at the start of
 * `rec`'s buffer: the boxes of block w at 2w and 2w + 1, then one count
 * per block.  The last block to finish (last_arrival) unites them in
 * block order (min/max) into the record, with the count of invalid
 * primitives and the Morton frame of the centroid box
 * (atrbvh_morton_frame, the host's function), which the morton kernel
 * reads: the host waits for nothing here, and reads the record in one
 * read when it needs it (cl/stages.c).  When some primitive is invalid
 * the pipeline finds the exact error on the host, or compacts and hands
 * the boxes back (set_prims); an invalid primitive's box here is the
 * zero box, so the kernels that run before the host has read the count
 * see finite boxes only (the build then fails, or its boxes are
 * replaced). */
static __global atrbvh_box *bounds_boxes_of(__global atrbvh_bounds_record *rec)
{
    return (__global atrbvh_box *)(rec + 1);
}

static void bounds_part(__global atrbvh_bounds_record *rec,
                        __global uint *sync, uint w, uint parts,
                        atrbvh_box scene, atrbvh_box centroids, uint bad)
{
    __global atrbvh_box *partial = bounds_boxes_of(rec);
    __global uint *counts = (__global uint *)(partial + 2u * parts);
    uint u;
    partial[2u * w] = scene;
    partial[2u * w + 1u] = centroids;
    counts[w] = bad;
    if (!last_arrival(sync, parts))
        return;
    scene = load_box_v(partial, 0u);
    centroids = load_box_v(partial, 1u);
    bad = load_u32_v(counts, 0u);
    for (u = 1u; u < parts; u++) {
        scene = atrbvh_box_union(scene, load_box_v(partial, 2u * u));
        centroids = atrbvh_box_union(centroids,
                                     load_box_v(partial, 2u * u + 1u));
        bad += load_u32_v(counts, u);
    }
    {
        double lo[3], scale[3];
        uint k;
        atrbvh_morton_frame(centroids, lo, scale);
        for (k = 0u; k < 3u; k++) {
            rec->lo[k] = lo[k];
            rec->scale[k] = scale[k];
        }
    }
    rec->scene = scene;
    rec->centroids = centroids;
    rec->invalid = bad;
}

static atrbvh_box bounds_zero_box(void)
{
    atrbvh_box z;
    z.min[0] = z.min[1] = z.min[2] = 0.0f;
    z.max[0] = z.max[1] = z.max[2] = 0.0f;
    return z;
}

/* Triangles j .. j+7 by atrbvh_prim_box_triangle's common case, lane k
 * triangle j+k, when all eight take it (their indices in range, their
 * nine coordinates' sum finite): the loads, a lane at a time, and the
 * stores here, the rule and atrbvh_scene_add's into the lanes of acc in
 * shared/lanes.h's atrbvh_tri8_boxes, which the CPU's eight-wide sweep
 * (lib/prims.c, tri8_avx2) runs too.  Returns 1 with the eight boxes
 * written, or 0 with nothing written (the caller takes the eight one at a
 * time). */
static int bounds_tri8(__global const float *vertices, ulong vstride,
                       ulong vcount, __global const uint *indices,
                       ulong istride, int indexed, uint j,
                       __global atrbvh_box *boxes, atrbvh_f8 *acc)
{
    ulong at[3][8];
    atrbvh_f8 c[3][3], mn[3], mx[3];
    int corner, k, l;
    for (corner = 0; corner < 3; corner++)
        for (l = 0; l < 8; l++) {
            at[corner][l] = atrbvh_fetch_vertex_id(
                indices, istride, indexed, (ulong)j + (ulong)l, corner);
            if (at[corner][l] >= vcount)
                return 0;
            at[corner][l] *= vstride;
        }
    for (corner = 0; corner < 3; corner++)
        for (k = 0; k < 3; k++)
            c[corner][k] = (float8)(
                vertices[at[corner][0] + k], vertices[at[corner][1] + k],
                vertices[at[corner][2] + k], vertices[at[corner][3] + k],
                vertices[at[corner][4] + k], vertices[at[corner][5] + k],
                vertices[at[corner][6] + k], vertices[at[corner][7] + k]);
    if (!atrbvh_tri8_boxes(c, mn, mx, acc))
        return 0;
    {
        float t[6][8]; /* (a vector's lanes take constant subscripts) */
        for (k = 0; k < 3; k++) {
            vstore8(mn[k], 0, t[k]);
            vstore8(mx[k], 0, t[3 + k]);
        }
        for (l = 0; l < 8; l++) {
            atrbvh_box b;
            for (k = 0; k < 3; k++) {
                b.min[k] = t[k][l];
                b.max[k] = t[3 + k][l];
            }
            boxes[j + (uint)l] = b;
        }
    }
    return 1;
}

__kernel void bounds_triangles(__global const float *vertices,
                               __global const uint *indices,
                               __global atrbvh_box *boxes,
                               __global atrbvh_bounds_record *rec,
                               __global uint *sync, atrbvh_kargs_bounds a)
{
    uint w = (uint)get_global_id(0), lo, hi, i, top, bad = 0u, why, l;
    atrbvh_box scene, centroids, b;
    atrbvh_f8 acc[ATRBVH_TRI8_ACC];
    int k;
    if (w >= a.parts)
        return;
    atrbvh_block_range(a.n, w, a.parts, &lo, &hi);
    scene = atrbvh_box_empty();
    centroids = atrbvh_box_empty();
    atrbvh_tri8_acc_init(acc);
    /* (i = top: i + 8 could wrap past a block ending near 2^32) */
    for (i = lo; i < hi; i = top) {
        uint j;
        top = hi - i < 8u ? hi : i + 8u;
        if (top - i == 8u &&
            bounds_tri8(vertices, a.vstride, a.vertex_count, indices,
                        a.istride, (int)a.indexed, i, boxes, acc))
            continue;
        for (j = i; j < top; j++) {
            why = 0u;
            if (atrbvh_prim_box_triangle(vertices, a.vstride, a.vertex_count,
                                         indices, a.istride, (int)a.indexed,
                                         (ulong)j, &b,
                                         &why) != ATRBVH_PRIM_OK) {
                bad++;
                b = bounds_zero_box();
            } else {
                atrbvh_scene_add(&scene, &centroids, b);
            }
            boxes[j] = b;
        }
    }
    /* the lanes into the boxes (shared/lanes.h) */
    {
        float t[ATRBVH_TRI8_ACC][8];
        for (k = 0; k < ATRBVH_TRI8_ACC; k++)
            vstore8(acc[k], 0, t[k]);
        atrbvh_tri8_acc_unite(t, &scene, &centroids);
    }
    bounds_part(rec, sync, w, a.parts, scene, centroids, bad);
}

__kernel void bounds_boxes(__global const float *in, __global atrbvh_box *boxes,
                           __global atrbvh_bounds_record *rec,
                           __global uint *sync, atrbvh_kargs_bounds a)
{
    uint w = (uint)get_global_id(0), lo, hi, i, bad = 0u;
    atrbvh_box scene, centroids, b;
    if (w >= a.parts)
        return;
    atrbvh_block_range(a.n, w, a.parts, &lo, &hi);
    scene = atrbvh_box_empty();
    centroids = atrbvh_box_empty();
    for (i = lo; i < hi; i++) {
        if (atrbvh_prim_box_box(in, a.bstride, (ulong)i, &b) !=
            ATRBVH_PRIM_OK) {
            bad++;
            b = bounds_zero_box();
        } else {
            atrbvh_scene_add(&scene, &centroids, b);
        }
        boxes[i] = b;
    }
    bounds_part(rec, sync, w, a.parts, scene, centroids, bad);
}

/* -------------------------------------------------------------------- sort */
/* The CPU's sort (lib/cpu/sort.c), kernel for kernel (shared/sort.h):
 * one stable pass on the most significant varying bits into buckets of
 * about ATRBVH_SORT_BUCKET_TARGET items (sort_count, whose last block
 * scans, and sort_scatter), then sort_buckets, one item per bucket
 * running the CPU's atrbvh_sort_bucket.  The varying bits are the morton
 * kernel's: each block's OR and AND of its keys, united by the last
 * block (vary[2 * blocks] = OR ^ AND: the bits that differ). */
static ulong sort_varying(__global const ulong *vary, uint blocks)
{
    return load_ulong_v(vary, 2u * blocks);
}

/* Block b of `blocks` leaves the OR and AND of its keys in vary[2b] and
 * vary[2b + 1]; the last block to finish unites them: vary[2 * blocks] =
 * OR ^ AND, the bits that differ (morton: the first pass's; sort_vary: a
 * big bucket's). */
static void vary_block(__global ulong *vary, __global uint *sync, uint b,
                       uint blocks, ulong any, ulong all)
{
    vary[2u * b] = any;
    vary[2u * b + 1u] = all;
    if (last_arrival(sync, blocks)) {
        for (b = 0; b < blocks; b++) {
            any |= load_ulong_v(vary, 2u * b);
            all &= load_ulong_v(vary, 2u * b + 1u);
        }
        vary[2u * blocks] = any ^ all;
    }
}

/* ------------------------------------------------------------------ morton */
/* Item b of the sort's a.blocks: the key of each primitive of block b
 * (atrbvh_morton_quantise, atrbvh_morton_key in the bounds record's
 * frame, or the host's after it replaced the boxes), the
 * identity order (the sort's values: build indices), and the OR and AND
 * of the block's keys; the last block unites them (sort_varying). */
__kernel void morton(__global const atrbvh_box *boxes, __global ulong *keys,
                     __global uint *order, __global ulong *vary,
                     __global uint *sync,
                     __global const atrbvh_bounds_record *rec,
                     atrbvh_kargs_morton a)
{
    uint b = (uint)get_global_id(0), lo, hi, i;
    ulong any = 0ul, all = ~0ul;
    double lo0 = a.lo[0], lo1 = a.lo[1], lo2 = a.lo[2], s0 = a.scale[0],
           s1 = a.scale[1], s2 = a.scale[2];
    if (b >= a.blocks)
        return;
    if (a.device_frame) { /* the bounds kernel's (an earlier launch) */
        lo0 = rec->lo[0];
        lo1 = rec->lo[1];
        lo2 = rec->lo[2];
        s0 = rec->scale[0];
        s1 = rec->scale[1];
        s2 = rec->scale[2];
    }
    atrbvh_block_range(a.n, b, a.blocks, &lo, &hi);
    for (i = lo; i < hi; i++) {
        atrbvh_box x = boxes[i];
        ulong k = atrbvh_morton_key(
            atrbvh_morton_quantise(atrbvh_box_centre(x, 0), lo0, s0),
            atrbvh_morton_quantise(atrbvh_box_centre(x, 1), lo1, s1),
            atrbvh_morton_quantise(atrbvh_box_centre(x, 2), lo2, s2));
        keys[i] = k;
        order[i] = i;
        any |= k;
        all &= k;
    }
    vary_block(vary, sync, b, a.blocks, any, all);
}

/* A big bucket's varying bits (the host's big_buckets, cl/stages.c; the
 * morton kernel finds the first pass's): item b of a.blocks, the OR and
 * AND of block b of the keys from a.off, then the last block unites them
 * (vary[2 * blocks] = OR ^ AND), as lib/cpu/sort.c's sort_big. */
__kernel void sort_vary(__global const ulong *keys, __global ulong *vary,
                        __global uint *sync, atrbvh_kargs_sort a)
{
    uint b = (uint)get_global_id(0), lo, hi, i;
    ulong any = 0ul, all = ~0ul;
    if (b >= a.blocks)
        return;
    keys += a.off;
    atrbvh_block_range(a.n, b, a.blocks, &lo, &hi);
    for (i = lo; i < hi; i++) {
        any |= keys[i];
        all &= keys[i];
    }
    vary_block(vary, sync, b, a.blocks, any, all);
}

/* The MSD pass's counts: block b's digits (atrbvh_sort_msd's) of the keys
 * from a.off in hist[atrbvh_sort_slot(d, b, blocks)]; the last block
 * scans them. */
__kernel void sort_count(__global const ulong *keys, __global uint *hist,
                         __global const ulong *vary, __global uint *sync,
                         atrbvh_kargs_sort a)
{
    uint b = (uint)get_global_id(0), lo, hi, j, d, shift, bits;
    uint c[ATRBVH_SORT_MSD_RADIX];
    if (b >= a.blocks)
        return;
    keys += a.off;
    atrbvh_sort_msd(a.n, sort_varying(vary, a.blocks), &shift, &bits);
    for (d = 0; d < (1u << bits); d++)
        c[d] = 0u;
    atrbvh_block_range(a.n, b, a.blocks, &lo, &hi);
    for (j = lo; j < hi; j++)
        c[atrbvh_sort_digit_bits(keys[j], shift, bits)]++;
    for (d = 0; d < (1u << bits); d++)
        hist[atrbvh_sort_slot(d, b, a.blocks)] = c[d];
    if (last_arrival(sync, a.blocks))
        (void)atrbvh_sort_scan(hist, (1u << bits) * a.blocks);
}

/* The MSD pass: block b places its pairs from (src_k, src_v) into the
 * buckets in (dst_k, dst_v), both from a.off. */
__kernel void sort_scatter(__global const ulong *src_k,
                           __global const uint *src_v, __global ulong *dst_k,
                           __global uint *dst_v, __global const uint *hist,
                           __global const ulong *vary, atrbvh_kargs_sort a)
{
    uint b = (uint)get_global_id(0), lo, hi, j, d, shift, bits;
    uint next[ATRBVH_SORT_MSD_RADIX];
    if (b >= a.blocks)
        return;
    src_k += a.off;
    src_v += a.off;
    dst_k += a.off;
    dst_v += a.off;
    atrbvh_sort_msd(a.n, sort_varying(vary, a.blocks), &shift, &bits);
    for (d = 0; d < (1u << bits); d++)
        next[d] = hist[atrbvh_sort_slot(d, b, a.blocks)];
    atrbvh_block_range(a.n, b, a.blocks, &lo, &hi);
    for (j = lo; j < hi; j++) {
        ulong k = src_k[j];
        uint at = atrbvh_sort_place(next, atrbvh_sort_digit_bits(k, shift,
                                                                 bits));
        dst_k[at] = k;
        dst_v[at] = src_v[j];
    }
}

/* Item d of a.buckets (the most any n-key sort has): bucket d of the keys
 * from a.off, from (tmp_k, tmp_v) into (keys, order) at the same
 * positions when a.into, else sorted in place with (keys, order) as its
 * scratch (the scanned counts of block 0 are where the buckets start);
 * a bucket of more than a.big keys is left to the host's big_buckets. */
__kernel void sort_buckets(__global ulong *tmp_k, __global uint *tmp_v,
                           __global ulong *keys, __global uint *order,
                           __global const uint *hist,
                           __global const ulong *vary, atrbvh_kargs_sort a)
{
    uint d = (uint)get_global_id(0), shift, bits, start, end;
    if (d >= a.buckets)
        return;
    atrbvh_sort_msd(a.n, sort_varying(vary, a.blocks), &shift, &bits);
    if (d >= (1u << bits))
        return;
    start = hist[atrbvh_sort_slot(d, 0u, a.blocks)];
    end = d + 1u < (1u << bits) ? hist[atrbvh_sort_slot(d + 1u, 0u, a.blocks)]
                                : a.n;
    start += a.off;
    end += a.off;
    if (end > start && end - start <= a.big)
        atrbvh_sort_bucket(tmp_k + start, tmp_v + start, keys + start,
                           order + start, end - start, (int)a.into,
                           (int)shift);
}

/* --------------------------------------------------------------- hierarchy */
/* The CPU's algorithm (lib/cpu/hierarchy.c), in one launch, the refit
 * included: the node whose split is s spans from its nearest split to the
 * left with a smaller delta to the nearest one to the right; each item
 * (one per contiguous block of splits) finds them with a stack, writes
 * every node whose two neighbours lie in its block and leaves the rest
 * (its prefix minima and its final stack, both strictly monotone in
 * delta, so at most ATRBVH_CL_HIER_SIDE each) in `over`; the last item to
 * finish (last_arrival) runs the same stack over all blocks' leftovers in
 * position order.  The tree is Karras's (atrbvh_karras_delta's tie rule),
 * identical for any block count.
 *
 * The refit in the same pass, as on the CPU: the stack pops nodes in
 * post-order, so each entry carries its left subtree's box, cost and
 * collapse size, the item carries the subtree finished last (its right
 * subtree), and every node is computed from the two in registers by the
 * refit's rule (shared/stages.h: atrbvh_refit_node_size for an LBVH,
 * a.sizes, atrbvh_refit_node otherwise; atrbvh_refit_leaf_cost for a
 * leaf), left first: the bits of the CPU's pass and of the refit kernel's
 * climb, with no arrival counter.  A leftover is recorded with the root
 * of the subtree between the previous leftover and it (written to the
 * tree by its block, as every node is): the merge reads its box, cost
 * and size back after last_arrival's fence, through volatile loads, as
 * the CPU's second pass reads them from its tree.  The refit stage then
 * has nothing to launch (st_refit). */

/* The pass's helpers are specialised in place (PoCL's compiler left
 * hier_emit a call otherwise: callgrind counted it apart). */
#define HIER_INLINE inline __attribute__((always_inline))

/* A finished subtree: its root and its values. */
typedef struct hier_sub {
    atrbvh_box box;
    double cost;
    uint node, size;
} hier_sub;

/* A stack entry: split s, its delta, and the subtree ending at leaf s
 * (s's left child). */
typedef struct hier_entry {
    hier_sub left;
    uint s;
    int d;
} hier_entry;

/* The tree the pass writes, and the build's constants. */
typedef struct hier_tree {
    __global uint *left, *right, *parent, *count, *size;
    __global uchar *flat;
    __global atrbvh_box *box;
    __global double *cost;
    long n;
    atrbvh_cost_params p;
    uint sizes; /* 1 (an LBVH): the collapse sizes too; 2 (a tree to
                   optimise): the collapse decisions (flat) */
} hier_tree;

/* Leaf position i as a finished subtree, its box b (its primitive's)
 * already in t->box: its count, cost and (an LBVH) size, written. */
static HIER_INLINE void hier_leaf(const hier_tree *t, long i, atrbvh_box b,
                                  hier_sub *out)
{
    const uint id = (uint)(t->n - 1 + i);
    const double co = atrbvh_refit_leaf_cost(&t->p, b);
    const uint size = 1u | ATRBVH_SIZE_LEAF;
    /* (results in registers first, then the stores: PoCL's CPU code has
     * one address space, so a value read back after a global store would
     * be loaded again) */
    t->count[id] = 1u;
    t->cost[id] = co;
    if (t->sizes == 1u)
        t->size[id] = size;
    else if (t->sizes == 2u)
        t->flat[id] = 1; /* (a leaf: one output leaf) */
    out->box = b;
    out->cost = co;
    out->node = id;
    out->size = size;
}

/* Internal node id with children lc, rc and its values (count c, box b,
 * cost co, an LBVH's size): the tree's stores, then *r becomes the node
 * (hier_emit's and hier_chain's). */
static HIER_INLINE void hier_store(const hier_tree *t, uint id, uint lc,
                                   uint rc, uint c, atrbvh_box b, double co,
                                   uint size, hier_sub *r)
{
    t->left[id] = lc;
    t->right[id] = rc;
    t->count[id] = c;
    t->parent[lc] = id;
    t->parent[rc] = id;
    t->box[id] = b;
    t->cost[id] = co;
    if (t->sizes == 1u)
        t->size[id] = size;
    else if (t->sizes == 2u) /* (the size's flag: the cost's choice) */
        t->flat[id] = (uchar)(size >> 31);
    r->box = b;
    r->cost = co;
    r->size = size;
    r->node = id;
}

/* Internal node of split s from its neighbours ps (-1: none) and ns (n-1:
 * none) with their deltas (shared/arith.h's atrbvh_hier_node), its left
 * subtree *l and its right subtree *r; *r becomes the node. */
static HIER_INLINE void hier_emit(const hier_tree *t, long s, long ps,
                                  int dps, long ns, int dns,
                                  const hier_sub *l, hier_sub *r)
{
    uint lc, rc, c, cnt, size = 0u;
    const uint id =
        atrbvh_hier_node(t->n, s, ps, dps, ns, dns, &lc, &rc, &c);
    atrbvh_box b;
    double co;
    if (t->sizes)
        size = atrbvh_refit_node_size(
            &t->p, l->box, (uint)(s - ps), l->cost, l->size, r->box,
            (uint)(ns - s), r->cost, r->size, &b, &cnt, &co);
    else
        atrbvh_refit_node(&t->p, l->box, (uint)(s - ps), l->cost, r->box,
                          (uint)(ns - s), r->cost, &b, &cnt, &co);
    /* (every result computed, then the stores: see hier_leaf) */
    hier_store(t, id, lc, rc, c, b, co, size, r);
}

/* Keys out of order (a sort that failed: the hierarchy is Karras's only
 * over sorted keys, and from unsorted ones the blocks write a graph that
 * is no tree, which the kernels queued behind this one would follow out
 * of bounds): every block's nodes replaced by a valid stand-in, internal
 * node i with leaf i on its left and node i + 1 on its right (the last
 * one leaf n - 1), refitted by the pass's rules, so that everything
 * queued behind stays in bounds until the host reads the status and
 * fails the build (cl/stages.c, st_collapse).  Serial, in the last
 * item: the failure path only. */
static void hier_chain(const hier_tree *t,
                       __global const atrbvh_box *prim_boxes,
                       __global const uint *order)
{
    long n = t->n, i;
    hier_sub r;
    t->box[2 * n - 2] = prim_boxes[order[n - 1]];
    hier_leaf(t, n - 1, t->box[2 * n - 2], &r);
    for (i = n - 2; i >= 0; i--) {
        const uint l = (uint)(n - 1 + i), id = (uint)i;
        atrbvh_box b;
        uint c, size = 0u;
        double co;
        if (t->sizes)
            size = atrbvh_refit_node_size(
                &t->p, load_box_v(t->box, l), 1u, load_f64_v(t->cost, l),
                1u | ATRBVH_SIZE_LEAF, r.box, (uint)(n - 1 - i), r.cost,
                r.size, &b, &c, &co);
        else
            atrbvh_refit_node(&t->p, load_box_v(t->box, l), 1u,
                              load_f64_v(t->cost, l), r.box,
                              (uint)(n - 1 - i), r.cost, &b, &c, &co);
        hier_store(t, id, l, r.node, c, b, co, size, &r);
    }
    t->parent[0] = ATRBVH_U32_MAX;
}

/* The merge over every block's leftovers (other items' writes: volatile),
 * then the last leaf and the root; `st` is the caller's stack, free.
 * Keys out of order in any block (its word after the counts): the
 * stand-in tree instead (hier_chain), its position + 1 in *status (0:
 * in order). */
static HIER_INLINE void hier_merge(const hier_tree *t,
                                   __global const ulong *keys,
                                   __global uint *leaf_prim,
                                   __global const atrbvh_box *prim_boxes,
                                   __global const uint *order,
                                   __global const uint *ids,
                                   volatile __global const uint *over,
                                   uint blocks, uint has_ids, hier_entry *st,
                                   __global uint *status)
{
    long n = t->n;
    uint sp = 0u, b, k, bad = 0u;
    hier_sub carry;
    t->parent[0] = ATRBVH_U32_MAX;
    leaf_prim[n - 1] = has_ids ? ids[order[n - 1]] : order[n - 1];
    for (b = 0u; b < blocks && bad == 0u; b++)
        bad = over[(size_t)blocks * (ATRBVH_CL_HIER_OVER + 1u) + b];
    *status = bad;
    if (bad != 0u) {
        hier_chain(t, prim_boxes, order);
        return;
    }
    if (n > 1) {
        for (b = 0u; b < blocks; b++) {
            volatile __global const uint *in =
                over + (size_t)b * ATRBVH_CL_HIER_OVER;
            uint m = over[(size_t)blocks * ATRBVH_CL_HIER_OVER + b];
            for (k = 0u; k < m; k++) {
                long s = (long)in[2u * k];
                int d = atrbvh_karras_delta(keys, n, s, s + 1);
                carry.node = in[2u * k + 1u];
                carry.box = load_box_v(t->box, carry.node);
                carry.cost = load_f64_v(t->cost, carry.node);
                carry.size =
                    t->sizes == 1u ? load_u32_v(t->size, carry.node) : 0u;
                while (sp > 0u && st[sp - 1u].d > d) {
                    sp--;
                    if (sp > 0u)
                        hier_emit(t, (long)st[sp].s, (long)st[sp - 1u].s,
                                  st[sp - 1u].d, s, d, &st[sp].left, &carry);
                    else
                        hier_emit(t, (long)st[sp].s, -1, 0, s, d,
                                  &st[sp].left, &carry);
                }
                if (sp == ATRBVH_CL_HIER_SIDE)
                    continue; /* keys out of order (cannot happen sorted) */
                st[sp].s = (uint)s;
                st[sp].d = d;
                st[sp++].left = carry;
            }
        }
    }
    t->box[2 * n - 2] = prim_boxes[order[n - 1]];
    hier_leaf(t, n - 1, t->box[2 * n - 2], &carry);
    while (sp > 0u) {
        sp--;
        if (sp > 0u)
            hier_emit(t, (long)st[sp].s, (long)st[sp - 1u].s, st[sp - 1u].d,
                      n - 1, 0, &st[sp].left, &carry);
        else
            hier_emit(t, (long)st[sp].s, -1, 0, n - 1, 0, &st[sp].left,
                      &carry);
    }
}

/* `over`: ATRBVH_CL_HIER_OVER words per block (2 * ATRBVH_CL_HIER_SIDE
 * leftovers: split position, subtree root), then the blocks' leftover
 * counts, then each block's first pair of keys out of order + 1 (0: in
 * order; a failed sort, hier_chain).  `blocks` >= 1 (one block of no
 * split when n == 1).  `size` is read only for an LBVH (a.sizes). */
static HIER_INLINE void hier_pass(
    __global const ulong *keys, __global uint *left, __global uint *right,
    __global uint *parent, __global uint *count, __global uint *leaf_prim,
    __global const uint *order, __global const uint *ids, __global uint *over,
    __global atrbvh_box *box, __global double *cost, __global uint *size,
    __global uchar *flat, __global const atrbvh_box *prim_boxes,
    __global uint *sync, __global uint *status, uint blocks,
    atrbvh_kargs_tree a, uint sizes)
{
    uint b = (uint)get_global_id(0), sp = 0u, nout = 0u, k, bad = 0u;
    long lo, hi, s;
    hier_entry st[ATRBVH_CL_HIER_SIDE];
    hier_sub carry;
    hier_tree t;
    __global uint *out;
    if (b >= blocks)
        return;
    t.left = left;
    t.right = right;
    t.parent = parent;
    t.count = count;
    t.size = size;
    t.flat = flat;
    t.box = box;
    t.cost = cost;
    t.n = (long)a.n;
    t.p = atrbvh_kargs_cost(a.ci, a.ct, a.collapse, a.max_leaf);
    t.sizes = sizes;
    out = over + (size_t)b * ATRBVH_CL_HIER_OVER;
    lo = (long)((ulong)(t.n - 1) * (ulong)b / (ulong)blocks);
    hi = (long)((ulong)(t.n - 1) * (ulong)(b + 1u) / (ulong)blocks);
    /* The block's leaf boxes gathered first, in a loop of their own: its
     * random reads are in flight together (PoCL's prefetch() is a no-op,
     * and the leaf loop below, with them, stalled on each: half of this
     * kernel's time on conference); the loop then reads them in order. */
    for (s = lo; s < hi; s++)
        box[t.n - 1 + s] = prim_boxes[order[s]];
    for (s = lo; s < hi; s++) {
        int d = atrbvh_karras_delta(keys, t.n, s, s + 1);
        if (bad == 0u && keys[s] > keys[s + 1])
            bad = (uint)s + 1u; /* the first pair out of order */
        leaf_prim[s] = a.has_ids ? ids[order[s]] : order[s];
        hier_leaf(&t, s, box[t.n - 1 + s], &carry);
        while (sp > 0u && st[sp - 1u].d > d) {
            sp--;
            /* (the bottom entry is a prefix minimum, already out) */
            if (sp > 0u)
                hier_emit(&t, (long)st[sp].s, (long)st[sp - 1u].s,
                          st[sp - 1u].d, s, d, &st[sp].left, &carry);
        }
        if (sp == 0u && nout < ATRBVH_CL_HIER_SIDE) { /* a prefix minimum */
            out[2u * nout] = (uint)s;
            out[2u * nout + 1u] = carry.node;
            nout++;
        }
        if (sp == ATRBVH_CL_HIER_SIDE)
            continue; /* keys out of order: cannot happen when sorted */
        st[sp].s = (uint)s;
        st[sp].d = d;
        st[sp++].left = carry;
    }
    /* st[0] is the last prefix minimum, already out. */
    for (k = 1u; k < sp; k++) {
        out[2u * nout] = st[k].s;
        out[2u * nout + 1u] = st[k].left.node;
        nout++;
    }
    over[(size_t)blocks * ATRBVH_CL_HIER_OVER + b] = nout;
    over[(size_t)blocks * (ATRBVH_CL_HIER_OVER + 1u) + b] = bad;
    if (last_arrival(sync, blocks))
        hier_merge(&t, keys, leaf_prim, prim_boxes, order, ids, over, blocks,
                   a.has_ids, st, status);
}

/* One copy of the pass for each mode (the constant `sizes` folds its
 * branches away). */
__kernel void hierarchy(__global const ulong *keys, __global uint *left,
                        __global uint *right, __global uint *parent,
                        __global uint *count, __global uint *leaf_prim,
                        __global const uint *order, __global const uint *ids,
                        __global uint *over, __global atrbvh_box *box,
                        __global double *cost, __global uint *size,
                        __global uchar *flat,
                        __global const atrbvh_box *prim_boxes,
                        __global uint *sync, __global uint *flag,
                        uint blocks, atrbvh_kargs_tree a)
{
    /* flag[1]: the keys' order (hier_merge); flag[0] is the layout's */
    if (a.sizes == 1u)
        hier_pass(keys, left, right, parent, count, leaf_prim, order, ids,
                  over, box, cost, size, flat, prim_boxes, sync, flag + 1,
                  blocks, a, 1u);
    else if (a.sizes == 2u)
        hier_pass(keys, left, right, parent, count, leaf_prim, order, ids,
                  over, box, cost, size, flat, prim_boxes, sync, flag + 1,
                  blocks, a, 2u);
    else
        hier_pass(keys, left, right, parent, count, leaf_prim, order, ids,
                  over, box, cost, size, flat, prim_boxes, sync, flag + 1,
                  blocks, a, 0u);
}

/* ------------------------------------------------------------------- refit */
/* One item per leaf: set the leaf, then walk up; at each parent the second
 * arrival computes it from both children. `counter` zeroed by the host.
 * a.sizes (an LBVH): the collapse sizes in the same climb
 * (atrbvh_refit_node_size; the collapse kernel is not launched), as the
 * CPU's refit does. */
__kernel void refit(__global atrbvh_box *box, __global uint *count,
                    __global double *cost, __global const uint *left,
                    __global const uint *right, __global const uint *parent,
                    __global const atrbvh_box *prim_boxes,
                    __global const uint *order, __global uint *counter,
                    __global uint *size, atrbvh_kargs_tree a)
{
    uint i = (uint)get_global_id(0), node;
    atrbvh_cost_params p = atrbvh_kargs_cost(a.ci, a.ct, a.collapse,
                                             a.max_leaf);
    atrbvh_box b;
    if (i >= a.n)
        return;
    node = a.n - 1u + i;
    b = prim_boxes[order[i]];
    box[node] = b;
    count[node] = 1u;
    cost[node] = atrbvh_refit_leaf_cost(&p, b);
    if (a.sizes)
        size[node] = 1u | ATRBVH_SIZE_LEAF;
    while (node != 0u) {
        uint up = parent[node], l, r, c;
        double co;
        ATRBVH_CL_FENCE(); /* our writes before the count */
        if (atomic_inc(&counter[up]) == 0u)
            return; /* the sibling's item continues */
        ATRBVH_CL_FENCE(); /* the sibling's writes after */
        counter[up] = 0u; /* no one else comes: zero for the next pass */
        l = left[up];
        r = right[up];
        if (a.sizes)
            size[up] = atrbvh_refit_node_size(
                &p, load_box_v(box, l), load_u32_v(count, l),
                load_f64_v(cost, l), load_u32_v(size, l), load_box_v(box, r),
                load_u32_v(count, r), load_f64_v(cost, r),
                load_u32_v(size, r), &b, &c, &co);
        else
            atrbvh_refit_node(&p, load_box_v(box, l), load_u32_v(count, l),
                              load_f64_v(cost, l), load_box_v(box, r),
                              load_u32_v(count, r), load_f64_v(cost, r), &b,
                              &c, &co);
        box[up] = b;
        count[up] = c;
        cost[up] = co;
        node = up;
    }
}

/* ---------------------------------------------------------------- optimise */
/* Round preparation (a separate launch, so it sees the tree as the round
 * starts): for each internal node, how many of its children are in the
 * crown (subtree count >= gamma), with ATRBVH_CL_START set on the crown
 * nodes with no crown child, where the walks start. */
#define ATRBVH_CL_START 0x80000000u
__kernel void opt_prepare(__global const uint *left, __global const uint *right,
                          __global const uint *count, __global uint *needed,
                          __global uint *counter, atrbvh_kargs_optimise a)
{
    uint i = (uint)get_global_id(0), l, r, k;
    if (i >= a.n_internal)
        return;
    l = left[i];
    r = right[i];
    k = (uint)(l < a.n_internal && count[l] >= a.gamma) +
        (uint)(r < a.n_internal && count[r] >= a.gamma);
    needed[i] = count[i] >= a.gamma && k == 0u ? ATRBVH_CL_START : k;
    counter[i] = 0u;
}

/* One round: `workers` persistent items take contiguous shares of the
 * internal nodes, in node order, and walk up from the start nodes in
 * theirs (opt_prepare's marks: neighbouring nodes, whose walks meet soon
 * on data still in cache, as the CPU's post-order walk of a subtree
 * does); a crown node is processed (atrbvh_treelet_process, the CPU's
 * function) by the item whose arrival completes its crown children, i.e.
 * only after its whole subtree is final.  The treelet root keeps its id and
 * parent, so the walk's way up stays valid.  The tree arrays are read and
 * written through t's volatile pointers (ATRBVH_SHARED_GLOBAL, treelet.h):
 * they hold nodes other items wrote in this launch.  Scratch: a.stride
 * bytes per worker. */
/* Item w's view of a round: the cost model, the tree, its scratch, the
 * skip marks. */
typedef struct opt_view {
    atrbvh_cost_params p;
    atrbvh_treelet_tree t;
    atrbvh_trbvh_scratch s;
    atrbvh_agg_scratch agg;
    atrbvh_treelet_marks m;
    /* opt_round4: ATRBVH's four interleaved matrices, or TRBVH's four
     * lanes' interleaved tables (the same place) and the four lanes'
     * splits (s the first, whose tables the scalar DP takes) */
    __global double *dist4;
    atrbvh_trbvh_scratch lane[4];
} opt_view;

/* A TRBVH scratch (atrbvh_trbvh_scratch) from `base`. */
static atrbvh_trbvh_scratch opt_tables(__global uchar *base,
                                       const atrbvh_kargs_optimise *a)
{
    atrbvh_trbvh_scratch s;
    s.box = (__global float *)base;
    s.cost = (__global double *)(base + a->off_cost);
    s.count = (__global uint *)(base + a->off_count);
    s.split = (__global uint *)(base + a->off_split);
    return s;
}

static void opt_item(__global uint *left, __global uint *right,
                     __global uint *parent, __global uint *count,
                     __global atrbvh_box *box, __global double *cost,
                     __global uchar *scratch, __global uchar *marks,
                     __global uchar *flat, const atrbvh_kargs_optimise *a,
                     uint w, opt_view *v)
{
    __global uchar *base = scratch + (ulong)w * a->stride;
    uint l;
    v->p = atrbvh_kargs_cost(a->ci, a->ct, a->collapse, a->max_leaf);
    v->s = opt_tables(base, a);
    v->lane[0] = v->s;
    for (l = 1u; l < 4u; l++) { /* (opt_round4, TRBVH; unused otherwise) */
        /* only the split: the rest is in the interleaved tables */
        v->lane[l].box = (__global float *)0;
        v->lane[l].cost = (__global double *)0;
        v->lane[l].count = (__global uint *)0;
        v->lane[l].split =
            (__global uint *)(base + a->off_lanes +
                              (l - 1u) * (a->off_dist - a->off_split));
    }
    /* ATRBVH: the distances and the agglomeration's arrays, laid out
     * for the largest size (the host sized them alike; TRBVH: none, the
     * pointers unused). */
    atrbvh_agg_layout(base + a->off_dist,
                      a->treelet_size == ATRBVH_TREELET_AUTO
                          ? (uint)ATRBVH_AUTO_MAX
                          : a->agglomerative ? a->treelet_size : 2u,
                      &v->agg);
    v->dist4 = (__global double *)(base + a->off_dist4);
    v->t.left = left;
    v->t.right = right;
    v->t.parent = parent;
    v->t.count = count;
    v->t.box = box;
    v->t.cost = cost;
    v->t.flat = a->flags ? (ATRBVH_SHARED_GLOBAL uchar *)flat
                         : (ATRBVH_SHARED_GLOBAL uchar *)0;
    v->t.n_internal = a->n_internal;
    /* The skip marks: chg, then same, one byte per internal node each
     * (a.marks: TRBVH, ATRBVH up to 32 leaves or adaptive, as on the
     * CPU; a one-word dummy otherwise). */
    v->m.chg = marks;
    v->m.same = marks + (a->marks ? a->n_internal : 0u);
}

/* The round's treelet counts of one item into the build's (the host
 * zeroes them per build). */
static void opt_tally(__global uint *tally, uint done, uint applied,
                      uint skipped)
{
    atomic_add(&tally[0], done);
    atomic_add(&tally[1], applied);
    atomic_add(&tally[2], skipped);
}

__kernel void opt_round(__global uint *left, __global uint *right,
                        __global uint *parent, __global uint *count,
                        __global atrbvh_box *box, __global double *cost,
                        __global const uint *needed, __global uint *counter,
                        __global uchar *scratch, __global uchar *marks,
                        __global uchar *flat, __global uint *tally,
                        atrbvh_kargs_optimise a)
{
    uint w = (uint)get_global_id(0), k, done = 0u, applied = 0u,
         skipped = 0u;
    opt_view v;
    if (w >= a.workers)
        return;
    opt_item(left, right, parent, count, box, cost, scratch, marks, flat, &a,
             w, &v);
    /* (the marks are read from `needed`, which no item writes in a round:
     * the same start nodes whatever the other items have restructured) */
    for (k = (uint)((ulong)a.n_internal * w / a.workers);
         k < (uint)((ulong)a.n_internal * (w + 1u) / a.workers); k++) {
        uint x = k;
        if (!(needed[k] & ATRBVH_CL_START))
            continue;
        for (;;) {
            uint up;
            int r;
            if (a.marks)
                r = atrbvh_treelet_process_marked(
                    &v.t, &v.p, x,
                    a.treelet_size == ATRBVH_TREELET_AUTO
                        ? atrbvh_treelet_auto_size(v.t.count[x], a.gamma)
                        : a.treelet_size,
                    (int)a.agglomerative, v.s, &v.agg, v.m, a.round);
            else
                r = atrbvh_atrbvh_process(&v.t, &v.p, x, a.treelet_size,
                                          a.gamma, v.s, &v.agg);
            if (r == ATRBVH_TREELET_SKIPPED) {
                skipped++;
            } else {
                done++;
                applied += (uint)r;
            }
            if (x == 0u)
                break;
            up = v.t.parent[x]; /* volatile, as every tree read here */
            /* our treelet's writes before the count ... */
            ATRBVH_CL_FENCE();
            /* (up has a crown child: never a start, no mark) */
            if (atomic_inc(&counter[up]) + 1u < needed[up])
                break;
            /* ... the other arrivals' writes after it (the reads go
             * through t's volatile pointers, never a stale cache line) */
            ATRBVH_CL_FENCE();
            counter[up] = 0u; /* the last arrival: zero for the collapse */
            x = up;
        }
    }
    opt_tally(tally, done, applied, skipped);
}

/* opt_round on a CPU device (the host's choice, cl/stages.c), where the
 * skip marks are kept: each item walks up to ATRBVH_CL_WALKS walks at
 * once, as the CPU's walk_lanes takes up to four treelets of one height
 * (lib/cpu/optimise.c).  Each step takes the treelet at every walk's
 * node: the skipped ones as atrbvh_treelet_process_marked skips them, the
 * others refreshed and formed side by side, one expansion of each in
 * turn (atrbvh_treelet_form's steps: a formation is a chain of dependent
 * loads, and those of several treelets overlap), then each one's
 * topology and write-back side by side in a double4's lanes (ATRBVH's
 * agglomerations, atrbvh_agglomerate_side; TRBVH's DP, atrbvh_trbvh_ready)
 * and its marks; then every walk climbs as opt_round's does, and the walks that
 * stop make room for the item's next start nodes.  The walks' nodes are
 * crown nodes none of which is below another (a node is walked only once
 * every crown node below it is done), so their treelets' subtrees are
 * disjoint: none reads what another writes back, and each treelet is the
 * pure function of its subtree that opt_round computes - the same tree,
 * bit for bit. */
#define ATRBVH_CL_WALKS 4u
__kernel void opt_round4(__global uint *left, __global uint *right,
                         __global uint *parent, __global uint *count,
                         __global atrbvh_box *box, __global double *cost,
                         __global const uint *needed, __global uint *counter,
                         __global uchar *scratch, __global uchar *marks,
                         __global uchar *flat, __global uint *tally,
                         atrbvh_kargs_optimise a)
{
    uint w = (uint)get_global_id(0), k, end, done = 0u, applied = 0u,
         skipped = 0u, walks = 0u, l, ready, more, step;
    uint at[ATRBVH_CL_WALKS], root[ATRBVH_CL_WALKS], size[ATRBVH_CL_WALKS];
    int r[ATRBVH_CL_WALKS];
    atrbvh_treelet tl[ATRBVH_CL_WALKS];
    atrbvh_treelet_leaves lv[ATRBVH_CL_WALKS];
    double area[ATRBVH_CL_WALKS][ATRBVH_TREELET_MAX];
    opt_view v;
    if (w >= a.workers)
        return;
    opt_item(left, right, parent, count, box, cost, scratch, marks, flat, &a,
             w, &v);
    k = (uint)((ulong)a.n_internal * w / a.workers);
    end = (uint)((ulong)a.n_internal * (w + 1u) / a.workers);
    for (;;) {
        /* the item's next start nodes (opt_prepare's marks) */
        for (; walks < ATRBVH_CL_WALKS && k < end; k++)
            if (needed[k] & ATRBVH_CL_START)
                at[walks++] = k;
        if (walks == 0u)
            break;
        /* the treelets not skipped, refreshed and formed side by side */
        ready = 0u;
        for (l = 0u; l < walks; l++) {
            const uint x = at[l];
            if (atrbvh_treelet_marks_skip(&v.t, v.m, x)) {
                skipped++;
                continue;
            }
            root[ready] = x;
            size[ready] = a.treelet_size == ATRBVH_TREELET_AUTO
                              ? atrbvh_treelet_auto_size(v.t.count[x], a.gamma)
                              : a.treelet_size;
            atrbvh_treelet_refresh(&v.t, &v.p, x);
            atrbvh_treelet_form_first(&v.t, x, &tl[ready]);
            ready++;
        }
        for (step = 2u, more = 1u; more; step++) {
            more = 0u;
            for (l = 0u; l < ready; l++)
                if (tl[l].n == step && step < size[l] &&
                    atrbvh_treelet_form_next(&v.t, &tl[l], area[l]))
                    more = 1u;
        }
        /* the topologies side by side in a double4's lanes, as the CPU's
         * walk_lanes: ATRBVH's agglomerations (atrbvh_agglomerate_side),
         * TRBVH's DP (atrbvh_trbvh_ready) */
        if (!a.agglomerative)
            atrbvh_trbvh_ready(&v.t, &v.p, a.treelet_size, ready, root, tl,
                               lv, v.lane, v.dist4, r);
        else if (ready > 0u) /* (one alone: atrbvh_atrbvh_keep) */
            atrbvh_agglomerate_side(&v.t, &v.p, ready, root, tl, &v.agg,
                                    v.dist4, r);
        for (l = 0u; l < ready; l++) {
            atrbvh_treelet_marks_done(v.m, &tl[l], root[l], r[l], a.round);
            done++;
            applied += (uint)r[l];
        }
        /* every walk one step up, as opt_round's (the last arrival goes
         * on; the others stop) */
        ready = 0u;
        for (l = 0u; l < walks; l++) {
            const uint x = at[l];
            uint up;
            if (x == 0u)
                continue;
            up = v.t.parent[x];
            ATRBVH_CL_FENCE();
            if (atomic_inc(&counter[up]) + 1u < needed[up])
                continue;
            ATRBVH_CL_FENCE();
            counter[up] = 0u;
            at[ready++] = up;
        }
        walks = ready;
    }
    opt_tally(tally, done, applied, skipped);
}

/* ---------------------------------------------------------------- collapse */
/* Bottom-up: output size of every subtree and the leaf decision
 * (atrbvh_collapse_size, the CPU's function): a caller's tree (set_tree);
 * an optimised tree's sizes are counted (collapse_count below). */
__kernel void collapse(__global const atrbvh_box *box,
                       __global const uint *count,
                       __global const double *cost, __global const uint *left,
                       __global const uint *right,
                       __global const uint *parent, __global uint *size,
                       __global uint *counter, atrbvh_kargs_tree a)
{
    uint i = (uint)get_global_id(0), node;
    atrbvh_cost_params p = atrbvh_kargs_cost(a.ci, a.ct, a.collapse,
                                             a.max_leaf);
    if (i >= a.n)
        return;
    node = a.n - 1u + i;
    size[node] = 1u | ATRBVH_SIZE_LEAF;
    while (node != 0u) {
        uint up = parent[node], l, r;
        ATRBVH_CL_FENCE();
        if (atomic_inc(&counter[up]) == 0u)
            return;
        ATRBVH_CL_FENCE();
        counter[up] = 0u; /* zero for the next pass */
        l = left[up];
        r = right[up];
        size[up] = atrbvh_collapse_size(&p, box[up], count[up], cost[l],
                                        cost[r], load_u32_v(size, l),
                                        load_u32_v(size, r));
        node = up;
    }
}

/* With the decisions kept (an optimised tree from the hierarchy stage:
 * `flat`, a byte a node, tree leaves 1): the sizes counted as the CPU's
 * collapse counts them (lib/cpu/collapse.c's count_out), down to the
 * collapsed nodes only.  The "top" is the internal nodes of more than
 * `cut` primitives that do not collapse; the subtrees just below it (the
 * frontier, in pre-order) go to the `items` work-items in turn (subtree
 * j to item j mod items), each counted by a stackless post-order walk
 * (parent links; any depth); the last item to finish (last_arrival)
 * then counts the top the same way over the frontier's sizes.  Every
 * item walks the top to find its subtrees: the host sizes the cut so
 * that the top stays small (cl/stages.c).  Integer arithmetic only
 * (atrbvh_size_counted, the CPU's): the sizes are the CPU's exactly. */
static int count_top(__global const uint *count, __global const uchar *flat,
                     uint x, uint cut)
{
    return !flat[x] && count[x] > cut; /* (tree leaves are flat) */
}

/* The sizes of the subtree of `root`, every node of it above its
 * collapsed ones, by a stackless post-order walk; a node of at most
 * `done` primitives that does not collapse was counted already (the
 * frontier, for the top: `done` the cut; 0 for a frontier subtree), as
 * the CPU's count_out.  Sizes counted by other items are read volatile. */
static void count_walk(__global const uint *count, __global const uint *left,
                       __global const uint *right,
                       __global const uint *parent,
                       __global const uchar *flat, __global uint *size,
                       uint root, uint done)
{
    uint cur = root;
    for (;;) {
        while (count_top(count, flat, cur, done))
            cur = left[cur];
        if (flat[cur])
            size[cur] = 1u | ATRBVH_SIZE_LEAF;
        for (;;) {
            uint up;
            if (cur == root)
                return;
            up = parent[cur];
            if (left[up] == cur) {
                cur = right[up];
                break; /* down its right subtree */
            }
            size[up] = atrbvh_size_counted(0u, load_u32_v(size, left[up]),
                                           load_u32_v(size, right[up]));
            cur = up;
        }
    }
}

__kernel void collapse_count(__global const uint *count,
                             __global const uint *left,
                             __global const uint *right,
                             __global const uint *parent,
                             __global const uchar *flat, __global uint *size,
                             __global uint *sync, uint cut, uint items)
{
    const uint w = (uint)get_global_id(0);
    uint cur, j = 0u;
    if (w >= items)
        return;
    /* the frontier in pre-order: down the top's left spines, each
     * frontier root met in turn (the root alone when it is no top node) */
    if (!count_top(count, flat, 0u, cut)) {
        if (w == 0u)
            count_walk(count, left, right, parent, flat, size, 0u, 0u);
        return;
    }
    cur = left[0];
    for (;;) {
        while (count_top(count, flat, cur, cut))
            cur = left[cur];
        if (j++ % items == w)
            count_walk(count, left, right, parent, flat, size, cur, 0u);
        /* up while a right child, then over to the right sibling */
        for (;;) {
            uint up = parent[cur];
            if (left[up] == cur) {
                cur = right[up];
                break;
            }
            cur = up;
            if (cur == 0u)
                break;
        }
        if (cur == 0u)
            break;
    }
    /* the top, over the frontier's sizes, by the last item to finish */
    if (last_arrival(sync, items))
        count_walk(count, left, right, parent, flat, size, 0u, cut);
}

/* ------------------------------------------------------------------ layout */
/* The CPU's top-down emission (lib/cpu/layout.c), split where the CPU
 * stops spawning tasks: layout_top (one work-item) emits the nodes above
 * the cut (more than ATRBVH_CL_LAYOUT_CUT primitives, not a collapsed
 * leaf) and lists every subtree hanging below it with its output
 * position and first primitive; layout (a few items sharing the listed
 * subtrees) emits each depth-first, as the CPU's emit/gather do.  Both
 * walks are stackless: going up, a node's position and first primitive
 * follow back from its child's by the placement rule (shared/stages.h:
 * a left child sits at pos + 1 with the same primitives, a right child at
 * atrbvh_layout_right_pos / _right_prim of its parent's), so any depth
 * is fine.  Integer arithmetic only: the output is the CPU's exactly. */
#define ATRBVH_CL_LAYOUT_CUT 256u

/* From child `cur` (at `*pos`, `*prim`) up to its parent: false at `root`;
 * when `cur` is a left child, moves to its right sibling instead (true),
 * else to the parent and goes on climbing. */
static int layout_next(__global const uint *count, __global const uint *left,
                       __global const uint *right, __global const uint *parent,
                       __global const uint *size, uint root, uint *cur,
                       uint *pos, uint *prim)
{
    for (;;) {
        uint up, l;
        if (*cur == root)
            return 0;
        up = parent[*cur];
        l = left[up];
        if (l == *cur) {
            /* parent at *pos - 1; its right child after the left subtree */
            *pos = atrbvh_layout_right_pos(*pos - 1u, size[l]);
            *prim = atrbvh_layout_right_prim(*prim, count[l]);
            *cur = right[up];
            return 1;
        }
        *pos -= 1u + (size[l] & ATRBVH_SIZE_MASK);
        *prim -= count[l];
        *cur = up;
    }
}

__kernel void layout_top(__global const uint *count, __global const uint *left,
                         __global const uint *right,
                         __global const uint *parent,
                         __global const uint *size,
                         __global const atrbvh_box *box,
                         __global atrbvh_node *nodes, __global uint *list,
                         __global uint *list_len, atrbvh_kargs_tree a)
{
    uint cur = 0u, pos = 0u, prim = 0u, k = 0u;
    if (get_global_id(0) != 0)
        return;
    do {
        /* down the left spine while above the cut */
        while (!(size[cur] & ATRBVH_SIZE_LEAF) &&
               count[cur] > ATRBVH_CL_LAYOUT_CUT) {
            uint l = left[cur];
            atrbvh_layout_write(&nodes[pos], box[cur], size[cur], count[cur],
                                pos, prim, size[l]);
            cur = l;
            pos += 1u;
        }
        list[3u * k] = cur;
        list[3u * k + 1u] = pos;
        list[3u * k + 2u] = prim;
        k++;
    } while (layout_next(count, left, right, parent, size, 0u, &cur, &pos,
                         &prim));
    *list_len = k;
    (void)a;
}

/* Listed subtree i. */
static void layout_subtree(__global const atrbvh_box *box,
                           __global const uint *count,
                           __global const uint *left,
                           __global const uint *right,
                           __global const uint *parent,
                           __global const uint *size,
                           __global const uint *leaf_prim,
                           __global const uint *list,
                           __global atrbvh_node *nodes, __global uint *prims,
                           uint i, atrbvh_kargs_tree a)
{
    uint root, cur, pos, prim, first = a.n - 1u;
    root = cur = list[3u * i];
    pos = list[3u * i + 1u];
    prim = list[3u * i + 2u];
    do {
        uint s;
        /* emit down the left spine to a leaf (a collapsed one too) */
        while (!((s = size[cur]) & ATRBVH_SIZE_LEAF)) {
            uint l = left[cur];
            atrbvh_layout_write(&nodes[pos], box[cur], s, count[cur], pos,
                                prim, size[l]);
            cur = l;
            pos += 1u;
        }
        atrbvh_layout_write(&nodes[pos], box[cur], s, count[cur], pos, prim,
                            0u);
        if (cur >= first) {
            prims[prim] = leaf_prim[cur - first];
        } else if (a.ranges) {
            /* the hierarchy's tree: the leaf's primitives are those of
             * sorted positions prim .. prim + count - 1, in order */
            uint k, m = count[cur];
            for (k = 0u; k < m; k++)
                prims[prim + k] = leaf_prim[prim + k];
        } else {
            /* a collapsed leaf: its primitives left to right (the CPU's
             * gather); `pos` is the leaf's node throughout */
            uint g = cur, k = prim;
            do {
                while (g < first)
                    g = left[g];
                prims[k++] = leaf_prim[g - first];
                for (;;) {
                    uint up;
                    if (g == cur) {
                        g = ATRBVH_U32_MAX;
                        break;
                    }
                    up = parent[g];
                    if (left[up] == g) {
                        g = right[up];
                        break;
                    }
                    g = up;
                }
            } while (g != ATRBVH_U32_MAX);
        }
    } while (layout_next(count, left, right, parent, size, root, &cur, &pos,
                         &prim));
}

/* `workers` items share the listed subtrees, a contiguous run each
 * (neighbours in the output); their count is layout_top's, read here, so
 * the host queues both launches without waiting for the first. */
__kernel void layout(__global const atrbvh_box *box, __global const uint *count,
                     __global const uint *left, __global const uint *right,
                     __global const uint *parent, __global const uint *size,
                     __global const uint *leaf_prim,
                     __global const uint *list, __global atrbvh_node *nodes,
                     __global uint *prims, __global const uint *list_len,
                     uint workers, atrbvh_kargs_tree a)
{
    uint w = (uint)get_global_id(0), i, end;
    ulong len;
    if (w >= workers)
        return;
    len = (ulong)*list_len;
    end = (uint)(len * (w + 1u) / workers);
    for (i = (uint)(len * w / workers); i < end; i++)
        layout_subtree(box, count, left, right, parent, size, leaf_prim, list,
                       nodes, prims, i, a);
}

/* ------------------------------------------------------------- ray queries */
/* One work-item per ray; the per-ray work is atrbvh_trav_closest /
 * atrbvh_trav_any (shared/traverse.h), the functions lib/traverse.c calls,
 * so every hit (primitive, t, u, v) is bit for bit the CPU's.  Geometry:
 * a.boxes 0 reads triangles from vertices and, when a.indexed, indices;
 * 1 reads boxes.  Unused buffers are dummies. */
static atrbvh_trav_scene trav_scene(__global const atrbvh_node *nodes,
                                    __global const uint *prim_indices,
                                    __global const float *vertices,
                                    __global const uint *indices,
                                    __global const float *box_data,
                                    atrbvh_kargs_trace a)
{
    atrbvh_trav_scene s;
    s.nodes = nodes;
    s.node_count = a.node_count;
    s.prim_indices = prim_indices;
    s.prim_count = a.prim_count;
    s.boxes = (int)a.boxes;
    s.primitive_count = a.primitive_count;
    s.vertices = vertices;
    s.vertex_count = a.vertex_count;
    s.vertex_stride = a.vstride;
    s.indices = indices;
    s.indexed = (int)a.indexed;
    s.index_stride = a.istride;
    s.box_data = box_data;
    s.box_stride = a.bstride;
    s.float_slabs = atrbvh_trav_scene_float(&s, (int)a.float_slabs);
    return s;
}

__kernel void intersect_closest(__global const atrbvh_node *nodes,
                                __global const uint *prim_indices,
                                __global const float *vertices,
                                __global const uint *indices,
                                __global const float *box_data,
                                __global const atrbvh_ray *rays,
                                __global atrbvh_hit *hits,
                                __global uint *cost, atrbvh_kargs_trace a)
{
    ulong i = get_global_id(0);
    atrbvh_trav_scene s;
    atrbvh_ray ray;
    atrbvh_hit h;
    uint nb, np;
    if (i >= a.ray_count)
        return;
    s = trav_scene(nodes, prim_indices, vertices, indices, box_data, a);
    ray = rays[i];
    atrbvh_trav_closest_cost(&s, ray.origin, ray.dir, ray.tmin, ray.tmax,
                             &h.t, &h.u, &h.v, &h.primitive, &nb, &np);
    hits[i] = h;
    if (a.count_cost) {
        cost[2 * i] = nb;
        cost[2 * i + 1] = np;
    }
}

__kernel void intersect_any(__global const atrbvh_node *nodes,
                            __global const uint *prim_indices,
                            __global const float *vertices,
                            __global const uint *indices,
                            __global const float *box_data,
                            __global const atrbvh_ray *rays,
                            __global uchar *occluded, __global uint *cost,
                            atrbvh_kargs_trace a)
{
    ulong i = get_global_id(0);
    atrbvh_trav_scene s;
    atrbvh_ray ray;
    uint nb, np;
    if (i >= a.ray_count)
        return;
    s = trav_scene(nodes, prim_indices, vertices, indices, box_data, a);
    ray = rays[i];
    occluded[i] = (uchar)(atrbvh_trav_any_cost(&s, ray.origin, ray.dir,
                                               ray.tmin, ray.tmax, &nb,
                                               &np) != 0);
    if (a.count_cost) {
        cost[2 * i] = nb;
        cost[2 * i + 1] = np;
    }
}
