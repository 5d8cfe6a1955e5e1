/*
 * cl/kernels.cl - the OpenCL backend's kernels, one (or a short fixed
 * sequence) per stage, with the same names as the CPU stages.  OpenCL C
 * 1.2.  The host prepends lib/shared/arith.h, treelet.h and stages.h (the
 * per-item arithmetic the CPU backend compiles as C99), so the two
 * backends run the same code per item; only the parallel mapping differs.
 *
 * Bottom-up passes (refit, optimise, collapse) use an atomic counter per
 * node: each work-item writes its node, fences, increments the parent's
 * counter; the first arrival stops, the last continues upwards after a
 * fence.  No work-item ever waits for another (no spinning, no lock-step
 * assumption, no barrier across work-groups), so the passes are correct
 * under any scheduling.  Values written by another work-item are read
 * through volatile pointers after the fence.
 */
#pragma OPENCL FP_CONTRACT OFF
#pragma OPENCL EXTENSION cl_khr_fp64 : enable

static atrbvh_cost_params cost_params(double ci, double ct, int collapse,
                                      uint max_leaf)
{
    atrbvh_cost_params p;
    p.ci = ci;
    p.ct = ct;
    p.collapse = collapse;
    p.max_leaf = max_leaf;
    return p;
}

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

static double load_f64_v(__global const double *p, uint i)
{
    return ((volatile __global const double *)p)[i];
}

/* ------------------------------------------------------------------ bounds */
/* One box per triangle; `problems` counts primitives with a NaN/Inf
 * coordinate or an index out of range (the host then runs the CPU bounds
 * stage, which reports the error or compacts, exactly). Strides in
 * elements. */
__kernel void bounds_triangles(__global const float *vertices, ulong vstride,
                               ulong vertex_count,
                               __global const uint *indices, ulong istride,
                               int indexed, uint n,
                               __global atrbvh_box *boxes,
                               __global uint *problems)
{
    uint i = (uint)get_global_id(0);
    atrbvh_box b;
    int c, ok = 1;
    if (i >= n)
        return;
    b = atrbvh_box_empty();
    for (c = 0; c < 3 && ok; c++) {
        ulong v;
        __global const float *p;
        if (indexed) {
            v = indices[(ulong)i * istride + (ulong)c];
            if (v >= vertex_count) {
                ok = 0;
                break;
            }
        } else {
            v = 3ul * (ulong)i + (ulong)c;
        }
        p = vertices + v * vstride;
        ok = atrbvh_box_grow(&b, p[0], p[1], p[2]);
    }
    boxes[i] = b;
    if (!ok)
        atomic_inc(problems);
}

__kernel void bounds_boxes(__global const float *in, ulong bstride, uint n,
                           __global atrbvh_box *boxes,
                           __global uint *problems)
{
    uint i = (uint)get_global_id(0);
    float f[6];
    atrbvh_box b;
    int k;
    if (i >= n)
        return;
    for (k = 0; k < 6; k++)
        f[k] = in[(ulong)i * bstride + (ulong)k];
    b = atrbvh_box_empty();
    if (atrbvh_prim_box_from_box(f, &b) != ATRBVH_PRIM_OK)
        atomic_inc(problems);
    boxes[i] = b;
}

/* Partial scene and centroid boxes: item w reduces its contiguous range;
 * the host unites the partials (min/max: order-independent). */
__kernel void bounds_reduce(__global const atrbvh_box *boxes, uint n,
                            uint parts, __global atrbvh_box *partial)
{
    uint w = (uint)get_global_id(0), lo, hi, i;
    atrbvh_box scene, centroids;
    if (w >= parts)
        return;
    lo = (uint)((ulong)n * w / parts);
    hi = (uint)((ulong)n * (w + 1u) / parts);
    scene = atrbvh_box_empty();
    centroids = atrbvh_box_empty();
    for (i = lo; i < hi; i++)
        atrbvh_scene_add(&scene, &centroids, boxes[i]);
    partial[2u * w] = scene;
    partial[2u * w + 1u] = centroids;
}

/* ------------------------------------------------------------------ morton */
__kernel void morton(__global const atrbvh_box *boxes, uint n, double lo0,
                     double lo1, double lo2, double s0, double s1, double s2,
                     __global ulong *keys, __global uint *order)
{
    uint i = (uint)get_global_id(0);
    atrbvh_box b;
    if (i >= n)
        return;
    b = boxes[i];
    keys[i] = atrbvh_morton_key(
        atrbvh_morton_quantise(atrbvh_box_centre(b, 0), lo0, s0),
        atrbvh_morton_quantise(atrbvh_box_centre(b, 1), lo1, s1),
        atrbvh_morton_quantise(atrbvh_box_centre(b, 2), lo2, s2));
    order[i] = i; /* the sort's values: build indices */
}

/* -------------------------------------------------------------------- sort */
/* Stable LSD radix sort, 8-bit digits, as the CPU: `blocks` contiguous
 * blocks; count per (digit, block), exclusive scan in digit-major order,
 * each block scatters its items in order.  hist[d * blocks + b]. */
__kernel void sort_count(__global const ulong *keys, uint n, uint shift,
                         uint blocks, __global uint *hist)
{
    uint b = (uint)get_global_id(0), lo, hi, j, d;
    uint c[256];
    if (b >= blocks)
        return;
    for (d = 0; d < 256u; d++)
        c[d] = 0;
    lo = (uint)((ulong)n * b / blocks);
    hi = (uint)((ulong)n * (b + 1u) / blocks);
    for (j = lo; j < hi; j++)
        c[(uint)(keys[j] >> shift) & 255u]++;
    for (d = 0; d < 256u; d++)
        hist[d * blocks + b] = c[d];
}

__kernel void sort_scan(__global uint *hist, uint entries)
{
    uint i, total = 0;
    if (get_global_id(0) != 0)
        return;
    for (i = 0; i < entries; i++) {
        uint t = hist[i];
        hist[i] = total;
        total += t;
    }
}

__kernel void sort_scatter(__global const ulong *src_k,
                           __global const uint *src_v, __global ulong *dst_k,
                           __global uint *dst_v, uint n, uint shift,
                           uint blocks, __global const uint *hist)
{
    uint b = (uint)get_global_id(0), lo, hi, j, d;
    uint o[256];
    if (b >= blocks)
        return;
    for (d = 0; d < 256u; d++)
        o[d] = hist[d * blocks + b];
    lo = (uint)((ulong)n * b / blocks);
    hi = (uint)((ulong)n * (b + 1u) / blocks);
    for (j = lo; j < hi; j++) {
        ulong k = src_k[j];
        uint at = o[(uint)(k >> shift) & 255u]++;
        dst_k[at] = k;
        dst_v[at] = src_v[j];
    }
}

/* --------------------------------------------------------------- hierarchy */
__kernel void hierarchy(__global const ulong *keys, uint n,
                        __global uint *left, __global uint *right,
                        __global uint *parent, __global uint *count,
                        __global uint *leaf_prim, __global const uint *order,
                        __global const uint *ids, int has_ids)
{
    uint i = (uint)get_global_id(0);
    if (i >= n)
        return;
    if (i + 1u < n) {
        uint l, r, c;
        atrbvh_karras_node(keys, (long)n, (long)i, &l, &r, &c);
        left[i] = l;
        right[i] = r;
        count[i] = c;
        parent[l] = i;
        parent[r] = i;
    }
    count[n - 1u + i] = 1u;
    leaf_prim[i] = has_ids ? ids[order[i]] : order[i];
    if (i == 0u)
        parent[0] = ATRBVH_U32_MAX;
}

/* ------------------------------------------------------------------- refit */
/* One item per leaf: set the leaf, then walk up; at each parent the second
 * arrival computes it from both children. `counter` zeroed by the host. */
__kernel void refit(__global atrbvh_box *box, __global uint *count,
                    __global double *cost, __global const uint *left,
                    __global const uint *right, __global const uint *parent,
                    __global const atrbvh_box *prim_boxes,
                    __global const uint *order, uint n, double ci, double ct,
                    int collapse, uint max_leaf, __global uint *counter)
{
    uint i = (uint)get_global_id(0), node;
    atrbvh_cost_params p = cost_params(ci, ct, collapse, max_leaf);
    atrbvh_box b;
    if (i >= n)
        return;
    node = n - 1u + i;
    b = prim_boxes[order[i]];
    box[node] = b;
    count[node] = 1u;
    cost[node] = atrbvh_refit_leaf_cost(&p, b);
    while (node != 0u) {
        uint up = parent[node], l, r, c;
        double co;
        mem_fence(CLK_GLOBAL_MEM_FENCE); /* our writes before the count */
        if (atomic_inc(&counter[up]) == 0u)
            return; /* the sibling's item continues */
        mem_fence(CLK_GLOBAL_MEM_FENCE); /* the sibling's writes after */
        l = left[up];
        r = right[up];
        atrbvh_refit_node(&p, load_box_v(box, l), load_u32_v(count, l),
                          load_f64_v(cost, l), load_box_v(box, r),
                          load_u32_v(count, r), load_f64_v(cost, r), &b, &c,
                          &co);
        box[up] = b;
        count[up] = c;
        cost[up] = co;
        node = up;
    }
}

/* ---------------------------------------------------------------- optimise */
/* Round preparation (a separate launch, so it sees the tree as the round
 * starts): for each internal node, how many of its children are in the
 * crown (subtree count >= gamma), and the list of crown nodes with no crown
 * child, where the walks start. */
__kernel void opt_prepare(__global const uint *left, __global const uint *right,
                          __global const uint *count, uint n_internal,
                          uint gamma, __global uint *needed,
                          __global uint *counter, __global uint *list,
                          __global uint *list_count)
{
    uint i = (uint)get_global_id(0), l, r, k;
    if (i >= n_internal)
        return;
    l = left[i];
    r = right[i];
    k = (uint)(l < n_internal && count[l] >= gamma) +
        (uint)(r < n_internal && count[r] >= gamma);
    needed[i] = k;
    counter[i] = 0u;
    if (count[i] >= gamma && k == 0u)
        list[atomic_inc(list_count)] = i;
}

/* One round: `workers` persistent items take the start nodes in turn and
 * walk up; a crown node is processed (atrbvh_treelet_process, the CPU's
 * function) by the item whose arrival completes its crown children, i.e.
 * only after its whole subtree is final.  The treelet root keeps its id and
 * parent, so the walk's way up stays valid.  The tree arrays are read and
 * written through t's volatile pointers (ATRBVH_SHARED_GLOBAL, treelet.h):
 * they hold nodes other items wrote in this launch.  Scratch: `stride` bytes per
 * worker, sized once per build. */
__kernel void opt_round(__global uint *left, __global uint *right,
                        __global uint *parent, __global uint *count,
                        __global atrbvh_box *box, __global double *cost,
                        uint n_internal, __global const uint *list,
                        uint list_len, __global const uint *needed,
                        __global uint *counter, __global uchar *scratch,
                        ulong stride, ulong off_cost, ulong off_count,
                        ulong off_split, ulong off_dist, uint treelet_size,
                        int agglomerative, uint workers, double ci, double ct,
                        int collapse, uint max_leaf)
{
    uint w = (uint)get_global_id(0), k;
    atrbvh_cost_params p = cost_params(ci, ct, collapse, max_leaf);
    atrbvh_treelet_tree t;
    atrbvh_trbvh_scratch s;
    __global uchar *base;
    __global double *dist;
    if (w >= workers)
        return;
    base = scratch + (ulong)w * stride;
    s.box = (__global atrbvh_box *)base;
    s.cost = (__global double *)(base + off_cost);
    s.count = (__global uint *)(base + off_count);
    s.split = (__global uint *)(base + off_split);
    dist = (__global double *)(base + off_dist);
    t.left = left;
    t.right = right;
    t.parent = parent;
    t.count = count;
    t.box = box;
    t.cost = cost;
    t.n_internal = n_internal;
    for (k = w; k < list_len; k += workers) {
        uint x = list[k];
        for (;;) {
            uint up;
            atrbvh_treelet_process(&t, &p, x, treelet_size, agglomerative, s,
                                   dist);
            if (x == 0u)
                break;
            up = t.parent[x]; /* volatile, as every tree read here */
            /* our treelet's writes before the count ... */
            mem_fence(CLK_GLOBAL_MEM_FENCE);
            if (atomic_inc(&counter[up]) + 1u < needed[up])
                break;
            /* ... the other arrivals' writes after it (the reads go
             * through t's volatile pointers, never a stale cache line) */
            mem_fence(CLK_GLOBAL_MEM_FENCE);
            x = up;
        }
    }
}

/* ---------------------------------------------------------------- collapse */
/* Bottom-up: output size of every subtree and the leaf decision
 * (atrbvh_collapse_size, the CPU's function). */
__kernel void collapse(__global const atrbvh_box *box,
                       __global const uint *count,
                       __global const double *cost, __global const uint *left,
                       __global const uint *right,
                       __global const uint *parent, uint n, double ci,
                       double ct, int collapse, uint max_leaf,
                       __global uint *size, __global uint *counter)
{
    uint i = (uint)get_global_id(0), node;
    atrbvh_cost_params p = cost_params(ci, ct, collapse, max_leaf);
    if (i >= n)
        return;
    node = n - 1u + i;
    size[node] = 1u | ATRBVH_SIZE_LEAF;
    while (node != 0u) {
        uint up = parent[node], l, r;
        mem_fence(CLK_GLOBAL_MEM_FENCE);
        if (atomic_inc(&counter[up]) == 0u)
            return;
        mem_fence(CLK_GLOBAL_MEM_FENCE);
        l = left[up];
        r = right[up];
        size[up] = atrbvh_collapse_size(&p, box[up], count[up], cost[l],
                                        cost[r], load_u32_v(size, l),
                                        load_u32_v(size, r));
        node = up;
    }
}

/* ------------------------------------------------------------------ layout */
/* One item per tree node: its depth-first position and first primitive
 * follow from the path to the root (left child: parent + 1; right child:
 * parent + 1 + size(left sibling), primitives + count(left sibling)); it
 * is emitted when no proper ancestor became a leaf.  Every tree leaf
 * writes its primitive at its position, which is where a collapsed
 * ancestor's primitives go too (left to right). */
__kernel void layout(__global const atrbvh_box *box, __global const uint *count,
                     __global const uint *left, __global const uint *right,
                     __global const uint *parent, __global const uint *size,
                     __global const uint *leaf_prim, uint n,
                     __global atrbvh_node *nodes, __global uint *prims)
{
    uint x = (uint)get_global_id(0), c, pos = 0, prim = 0;
    int emitted = 1, k;
    atrbvh_node out;
    atrbvh_box b;
    if (x >= 2u * n - 1u)
        return;
    c = x;
    while (c != 0u) {
        uint up = parent[c];
        if (size[up] & ATRBVH_SIZE_LEAF)
            emitted = 0;
        if (right[up] == c) {
            uint l = left[up];
            pos += 1u + (size[l] & ATRBVH_SIZE_MASK);
            prim += count[l];
        } else {
            pos += 1u;
        }
        c = up;
    }
    if (x >= n - 1u)
        prims[prim] = leaf_prim[x - (n - 1u)];
    if (!emitted)
        return;
    b = box[x];
    for (k = 0; k < 3; k++) {
        out.min[k] = b.min[k];
        out.max[k] = b.max[k];
    }
    if (size[x] & ATRBVH_SIZE_LEAF) {
        out.index = prim;
        out.count = count[x];
    } else {
        out.index = pos + 1u + (size[left[x]] & ATRBVH_SIZE_MASK);
        out.count = 0u;
    }
    nodes[pos] = out;
}

/* ------------------------------------------------------------- ray queries */
/* One work-item per ray; the per-ray work is atrbvh_trav_closest /
 * atrbvh_trav_any (shared/traverse.h), the functions lib/traverse.c calls,
 * so every hit (primitive, t, u, v) is bit for bit the CPU's.  Geometry:
 * `boxes` 0 reads triangles from vertices (stride in floats) and, when
 * `indexed`, indices (stride in u32); 1 reads boxes (stride in floats).
 * Unused buffers are dummies. */
static atrbvh_trav_scene trav_scene(
    __global const atrbvh_node *nodes, ulong node_count,
    __global const uint *prim_indices, ulong prim_count, int boxes,
    ulong primitive_count, __global const float *vertices, ulong vertex_count,
    ulong vstride, __global const uint *indices, int indexed, ulong istride,
    __global const float *box_data, ulong bstride)
{
    atrbvh_trav_scene s;
    s.nodes = nodes;
    s.node_count = node_count;
    s.prim_indices = prim_indices;
    s.prim_count = prim_count;
    s.boxes = boxes;
    s.primitive_count = primitive_count;
    s.vertices = vertices;
    s.vertex_count = vertex_count;
    s.vertex_stride = vstride;
    s.indices = indices;
    s.indexed = indexed;
    s.index_stride = istride;
    s.box_data = box_data;
    s.box_stride = bstride;
    return s;
}

#define TRAV_PARAMS                                                            \
    __global const atrbvh_node *nodes, ulong node_count,                       \
        __global const uint *prim_indices, ulong prim_count, int boxes,        \
        ulong primitive_count, __global const float *vertices,                 \
        ulong vertex_count, ulong vstride, __global const uint *indices,       \
        int indexed, ulong istride, __global const float *box_data,            \
        ulong bstride, __global const atrbvh_ray *rays, ulong ray_count
#define TRAV_ARGS                                                              \
    nodes, node_count, prim_indices, prim_count, boxes, primitive_count,       \
        vertices, vertex_count, vstride, indices, indexed, istride, box_data,  \
        bstride

__kernel void intersect_closest(TRAV_PARAMS, __global atrbvh_hit *hits)
{
    ulong i = get_global_id(0);
    atrbvh_trav_scene s;
    atrbvh_ray ray;
    atrbvh_hit h;
    if (i >= ray_count)
        return;
    s = trav_scene(TRAV_ARGS);
    ray = rays[i];
    atrbvh_trav_closest(&s, ray.origin, ray.dir, ray.tmin, ray.tmax, &h.t,
                        &h.u, &h.v, &h.primitive);
    hits[i] = h;
}

__kernel void intersect_any(TRAV_PARAMS, __global uchar *occluded)
{
    ulong i = get_global_id(0);
    atrbvh_trav_scene s;
    atrbvh_ray ray;
    if (i >= ray_count)
        return;
    s = trav_scene(TRAV_ARGS);
    ray = rays[i];
    occluded[i] = (uchar)(atrbvh_trav_any(&s, ray.origin, ray.dir, ray.tmin,
                                          ray.tmax) != 0);
}
