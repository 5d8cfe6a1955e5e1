/*
 * traverse.c - ray queries over a built BVH: closest hit and any hit, single
 * rays and OpenMP batches.
 *
 * Robustness (see atrbvh(3), "Ray queries"):
 *
 *  - Ray/node test: the slab test with 1/dir, in single precision (SSE on
 *    the CPU, two children at once) for rays whose direction components
 *    are all nonzero normal floats within 2^+-125, whose origin and the
 *    root box lie within +-2^126 and whose tmin >= 0 (then (b - o) * (1/d)
 *    cannot overflow before the product, nor give NaN), with the far end
 *    widened by 1 + 2^-21 and 2^-146 (shared/traverse.h,
 *    atrbvh_trav_node_hit_f); in double for every other ray, below.
 *    Double: a zero direction component gives 1/dir = +-inf.  The near and far distances of each
 *    slab are chosen by the sign of 1/dir, and folded into the interval with
 *    comparisons written so that a NaN (0 * inf: the origin lies exactly on
 *    a slab plane of a zero-direction axis) is dropped, i.e. that axis puts
 *    no constraint on the ray (conservative).  The far distance is widened
 *    by the factor 1 + 2*gamma(3) of Ize, "Robust BVH ray traversal" (JCGT
 *    2013), which bounds the rounding of (b - o) * (1/d), so a box the ray
 *    really crosses is never rejected.
 *
 *  - Pruning against the closest hit so far uses t_best widened by a
 *    relative 2^-12, so a node holding a primitive whose computed t is
 *    slightly below its true t is still visited: the traversal then returns
 *    the same hit as testing every primitive would.
 *
 *  - Ray/triangle: the watertight test of Woop, Benthin and Wald (JCGT
 *    2013): translate to the ray origin, permute the axes so that z is the
 *    largest direction component, shear so the ray becomes the +z axis, and
 *    evaluate the three 2D edge functions.  The paper computes in float and
 *    recomputes an edge function in double when it is exactly 0; here the
 *    transformed vertices and the edge functions are computed in double
 *    throughout (as fast as float for scalar code, and no overflow for any
 *    finite float input).  An edge shared by two triangles gives the two
 *    triangles edge functions that are exact negations of each other (the
 *    same two rounded products, subtracted in the other order), so a ray
 *    through the edge or a vertex is claimed by at least one of them: no
 *    ray falls through a closed mesh.  A ray lying in a triangle's plane
 *    (determinant 0) does not hit it.
 *
 *  - Both queries accept t in the closed interval [tmin, tmax], t finite
 *    (a hit exactly at tmin counts, as in Embree).  Closest hit: equal t
 *    goes to the lower primitive index, so the result does not depend on
 *    traversal order.
 *
 *  - Box primitives are surfaces: the ray hits a box where it enters it and,
 *    when the origin is inside, where it leaves it (u = v = 0).
 *
 *  - Rays with a NaN or infinite origin or direction, an all-zero direction,
 *    or a NaN tmin/tmax hit nothing.
 *
 * The per-ray arithmetic (ray setup, slab test, triangle and box tests,
 * the traversal loop) is in shared/traverse.h, which the OpenCL kernels
 * intersect_closest and intersect_any compile too: a ray gets the same
 * result, bit for bit, on both.
 *
 * Traversal: depth-first with a fixed stack of TRAVERSE_STACK entries on the
 * C stack (no allocation).  At an internal node both children are tested,
 * the nearer (by entry distance; the left on a tie) is visited first and the
 * other pushed with its entry distance, skipped on pop when it starts
 * beyond the closest hit.  The stack holds at most one entry per level of
 * the current path, so a tree of depth < TRAVERSE_STACK never overflows it;
 * the library's builds are far shallower (Karras hierarchies over 63-bit
 * keys plus index tie-breaks: about 100 levels at most).  A deeper tree
 * (possible only from a hand-made file) does not fail: on overflow the
 * query finishes by a linear pass over every leaf whose box the ray hits,
 * which finds the same hit.
 */
#include "config.h"

#include "internal.h"
#include "shared/traverse.h"

#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The shared header's view of a BVH and its geometry; 0 when the geometry
 * cannot be read (no data pointer, or a byte stride that is not a multiple
 * of 4: the build rejects those, so no BVH is built over such a
 * geometry). */
static int trav_scene(const atrbvh_bvh *bvh, const atrbvh_geometry *g,
                      atrbvh_trav_scene *s)
{
    memset(s, 0, sizeof *s);
    s->nodes = bvh->nodes;
    s->node_count = bvh->node_count;
    s->prim_indices = bvh->prim_indices;
    s->prim_count = bvh->prim_count;
    s->primitive_count = g->primitive_count;
    /* the CPU keeps subnormals (IEEE arithmetic, no flush to zero) */
    s->float_slabs = atrbvh_trav_scene_float(s, 1);
    if (g->type == ATRBVH_GEOMETRY_TRIANGLES) {
        size_t vs = g->vertex_stride ? g->vertex_stride : 3 * sizeof(float);
        size_t is = g->index_stride ? g->index_stride : 3 * sizeof(uint32_t);
        if (!g->vertices || vs % sizeof(float) ||
            (g->indices && is % sizeof(uint32_t)))
            return 0;
        s->boxes = 0;
        s->vertices = g->vertices;
        s->vertex_count = g->vertex_count;
        s->vertex_stride = vs / sizeof(float);
        s->indices = g->indices;
        s->indexed = g->indices != NULL;
        s->index_stride = is / sizeof(uint32_t);
        return 1;
    }
    if (g->type == ATRBVH_GEOMETRY_BOXES) {
        size_t bs = g->box_stride ? g->box_stride : 6 * sizeof(float);
        if (!g->boxes || bs % sizeof(float))
            return 0;
        s->boxes = 1;
        s->box_data = g->boxes;
        s->box_stride = bs / sizeof(float);
        return 1;
    }
    return 0;
}

static int geometry_usable(const atrbvh_geometry *g)
{
    if (g->type == ATRBVH_GEOMETRY_TRIANGLES)
        return g->vertices != NULL;
    if (g->type == ATRBVH_GEOMETRY_BOXES)
        return g->boxes != NULL;
    return 0;
}

static void closest(const atrbvh_trav_scene *s, const atrbvh_ray *ray,
                    atrbvh_hit *hit)
{
    atrbvh_trav_closest(s, ray->origin, ray->dir, ray->tmin, ray->tmax,
                        &hit->t, &hit->u, &hit->v, &hit->primitive);
}

/* ------------------------------------------------------------ 8-wide
 * The uncounted batch calls (atrbvh_intersect_batch, atrbvh_occluded_batch)
 * trace the rays that take the single-precision node test over an 8-wide copy
 * of the tree, made on first use and kept: each wide node holds up to eight
 * nodes of the binary tree (a node and its descendants, the internal one with
 * the largest box opened first), their boxes laid out so that one AVX2
 * operation (two SSE2 ones on CPUs without AVX2: wide_avx2) takes the same slab
 * of all eight.  Against a 4-wide copy, half the wide levels: half the
 * dependent node loads, which dominate incoherent rays on large scenes.  Every
 * box is tested with exactly the operations of atrbvh_trav_box2_f on the same
 * floats (subtraction, multiplication, min, max, the same widening), so a box
 * is hit in the wide traversal exactly when it is hit in the binary one; the
 * boxes are all finite (else no wide copy is made; an unused lane's empty box
 * of infinities meets only finite origins and reciprocals), so no NaN arises
 * and the order of the min/max reductions does not change their values.  The
 * leaves are the binary tree's references, kept in the wide node itself (first,
 * count), tested by atrbvh_trav_leaf or, over triangles, from a copy of their
 * vertices (wide_leaf_tris, below).  The hit does not depend on the order in
 * which nodes are visited (closest hit: smallest t, ties to the lower index;
 * any hit: whether one exists), so the wide traversal returns the binary one's
 * hit, bit for bit.  The counted calls (the _stats ones) keep the binary
 * traversal: box_tests and prim_tests count its work.  Without SSE, for rays
 * that take the double test, trees with a non-finite box, deeper than
 * WIDE_MAX_DEPTH wide levels, or malformed (a child index out of order), and
 * when memory is short, the binary traversal runs. */
#ifdef ATRBVH_TRAV_SSE
/* The AVX2 node test, chosen at run time (wide_avx2). */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define WIDE_AVX2 1
#include <immintrin.h>
#else
#define WIDE_AVX2 0
#endif
/* Lanes per wide node: a multiple of 4 (the SSE2 node test takes four
 * lanes at a time, the AVX2 one eight), at most 8 (masks in 8 bits). */
#define WIDE_W 8
typedef struct wide_node {
    /* b[WIDE_W * axis + lane]: the lanes' minima; b[3 * WIDE_W + WIDE_W *
     * axis + lane]: their maxima; an unused lane has an empty box (minima
     * +inf, maxima -inf), which no ray hits (wide_run) */
    float b[6 * WIDE_W];
    /* >= 0: a wide node; < 0: a leaf, ~(count << 32 | first): the binary
     * leaf's references prim_indices[first, first + count) (see
     * WIDE_LEAF).  While the copy is made, child[0] holds the binary
     * node's index and (above bit 32) the wide depth. */
    int64_t child[WIDE_W];
} wide_node;

/* A leaf entry of wide_node.child. */
#define WIDE_LEAF(first, count)                                                \
    (~(int64_t)((uint64_t)(count) << 32 | (uint64_t)(first)))

/* A wide node pushes at most WIDE_W - 1 entries and pops one: (WIDE_W -
 * 1) * depth + 1 entries for a tree of wide depth `depth`. */
#define WIDE_MAX_DEPTH 80
#define WIDE_STACK ((WIDE_W - 1) * WIDE_MAX_DEPTH + WIDE_W)
/* Batches below this many rays take the binary traversal (the copy costs
 * about as much as tracing a few rays per node). */
#define WIDE_MIN_RAYS 1024u

/* Whether the six floats of a box are finite: x - x is 0 for a finite x
 * and NaN for an infinite or NaN one, and NaN survives the sum. */
static int box_finite(const atrbvh_node *n)
{
    float z = (n->min[0] - n->min[0]) + (n->min[1] - n->min[1]) +
              (n->min[2] - n->min[2]) + (n->max[0] - n->max[0]) +
              (n->max[1] - n->max[1]) + (n->max[2] - n->max[2]);
    return z == 0.0f;
}

/* Whether box a lies inside box b (the library's trees: a child's box
 * inside its parent's, exactly).  Then the rounded slab distances of a's
 * planes lie within b's (x -> (x - o) * id rounded is monotone), so a ray
 * that misses b misses a too: wide_run does not test the root's box. */
static int box_inside(const atrbvh_node *a, const atrbvh_node *b)
{
    int k;
    for (k = 0; k < 3; k++)
        if (!(a->min[k] >= b->min[k] && a->max[k] <= b->max[k]))
            return 0;
    return 1;
}

/* Room for `count` wide nodes starting on a 64-byte boundary (a node then
 * fills four cache lines, not five): one node more than asked, the block
 * as allocated (what atrbvh_i_free takes and bvh->wide holds), or NULL.
 * wide_nodes gives the first node. */
static void *wide_alloc(size_t count)
{
    if (count >= SIZE_MAX / sizeof(wide_node))
        return NULL;
    return atrbvh_i_alloc_array(count + 1u, sizeof(wide_node));
}

static wide_node *wide_nodes(void *block)
{
    uintptr_t a = (uintptr_t)block;
    return (wide_node *)((unsigned char *)block + ((64u - a % 64u) % 64u));
}

/* The 8-wide copy of a binary tree whose root is internal, as allocated
 * (wide_alloc), or NULL (see above; *nomem 1 when memory was short).  Wide
 * nodes are numbered breadth first; while being filled, child[] holds
 * binary indices. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline)) /* its own entry in profiles */
#endif
static void *wide_make(const atrbvh_node *nodes, size_t node_count,
                       size_t prim_count, int *nomem)
{
    size_t internal = 0, i, n_wide = 1, cap;
    wide_node *w;
    void *block;
    *nomem = 0;
    if (node_count < 3 || nodes[0].count != 0u)
        return NULL;
    for (i = 0; i < node_count; i++) {
        /* finite and min <= max: the near plane of each axis is then
         * known from the direction's sign (wide_run) */
        if (!box_finite(&nodes[i]) || !(nodes[i].min[0] <= nodes[i].max[0]) ||
            !(nodes[i].min[1] <= nodes[i].max[1]) ||
            !(nodes[i].min[2] <= nodes[i].max[2]))
            return NULL;
        if (nodes[i].count == 0u) {
            if ((size_t)nodes[i].index <= i + 1 ||
                (size_t)nodes[i].index >= node_count ||
                !box_inside(&nodes[i + 1], &nodes[i]) ||
                !box_inside(&nodes[nodes[i].index], &nodes[i]))
                return NULL;
            internal++;
        } else if ((size_t)nodes[i].index > prim_count ||
                   (size_t)nodes[i].count > prim_count - nodes[i].index) {
            /* a leaf's references (first, count) lie within prim_indices
             * (atrbvh_trav_leaf skips the others) */
            return NULL;
        }
    }
    if (node_count > (size_t)INT32_MAX)
        return NULL;
    /* a wide node has WIDE_W lanes, holding WIDE_W - 1 internal nodes of
     * its own (none shared), or fewer lanes, then all leaves (at least
     * two of its own): at most internal / (WIDE_W - 1) + (internal + 1) /
     * 2 wide nodes in a tree (more: malformed, below) */
    cap = internal / (WIDE_W - 1) + (internal + 1) / 2 + 1;
    if (cap > internal)
        cap = internal;
    block = wide_alloc(cap);
    if (!block) {
        *nomem = 1;
        return NULL;
    }
    w = wide_nodes(block);
    w[0].child[0] = (int64_t)1 << 32; /* binary node 0, depth 1 */
    for (i = 0; i < n_wide; i++) {
        uint32_t list[WIDE_W];
        int lanes = 2, lane, axis;
        uint32_t b = (uint32_t)w[i].child[0];
        int64_t depth = w[i].child[0] >> 32;
        list[0] = b + 1u;
        list[1] = nodes[b].index;
        while (lanes < WIDE_W) {
            int best = -1;
            double best_area = -1.0;
            for (lane = 0; lane < lanes; lane++) {
                double a;
                if (nodes[list[lane]].count != 0u)
                    continue;
                a = atrbvh_i_node_area(&nodes[list[lane]]);
                if (a > best_area) {
                    best_area = a;
                    best = lane;
                }
            }
            if (best < 0)
                break;
            b = list[best];
            list[best] = b + 1u;
            list[lanes++] = nodes[b].index;
        }
        for (lane = 0; lane < WIDE_W; lane++) {
            const atrbvh_node *c = &nodes[list[lane < lanes ? lane : 0]];
            for (axis = 0; axis < 3; axis++) {
                w[i].b[WIDE_W * axis + lane] =
                    lane < lanes ? c->min[axis] : INFINITY;
                w[i].b[3 * WIDE_W + WIDE_W * axis + lane] =
                    lane < lanes ? c->max[axis] : -INFINITY;
            }
        }
        for (lane = 0; lane < WIDE_W; lane++) {
            const atrbvh_node *c;
            if (lane >= lanes) {
                w[i].child[lane] = 0;
                continue;
            }
            c = &nodes[list[lane]];
            if (c->count != 0u) {
                w[i].child[lane] = WIDE_LEAF(c->index, c->count);
                continue;
            }
            /* more wide nodes than `cap` means a malformed tree (a node
             * reached twice) */
            if (n_wide >= cap || depth >= WIDE_MAX_DEPTH) {
                atrbvh_i_free(block);
                return NULL;
            }
            w[n_wide].child[0] = (depth + 1) << 32 | (int64_t)list[lane];
            w[i].child[lane] = (int64_t)n_wide;
            n_wide++;
        }
    }
    /* the copy has fewer nodes than `cap`: keep only those when memory
     * allows */
    if (n_wide < cap) {
        void *fit = wide_alloc(n_wide);
        if (fit) {
            memcpy(wide_nodes(fit), w, n_wide * sizeof *w);
            atrbvh_i_free(block);
            block = fit;
        }
    }
    return block;
}

/* Stands for "no wide copy can be made of this tree" in bvh->wide. */
static const wide_node wide_none;

/* The tree's wide copy, made on first use and kept in bvh->wide (a
 * batch running on another thread may make it at the same time: the first
 * to store it wins, the other frees its own); NULL when the tree cannot
 * have one or memory is short. */
static const wide_node *wide_get(const atrbvh_bvh *bvh)
{
#if defined(__GNUC__) || defined(__clang__)
    /* the object is never const: the API's const says that the tree the
     * caller sees does not change, which holds */
    void **slot = &((atrbvh_bvh *)(uintptr_t)bvh)->wide;
    void *w = __atomic_load_n(slot, __ATOMIC_ACQUIRE), *expected = NULL;
    int nomem;
    if (!w) {
        w = wide_make(bvh->nodes, bvh->node_count, bvh->prim_count, &nomem);
        if (!w) {
            if (nomem)
                return NULL;
            w = (void *)(uintptr_t)&wide_none;
        }
        if (!__atomic_compare_exchange_n(slot, &expected, w, 0,
                                         __ATOMIC_ACQ_REL,
                                         __ATOMIC_ACQUIRE)) {
            if (w != (const void *)&wide_none)
                atrbvh_i_free(w);
            w = expected;
        }
    }
    return w == (const void *)&wide_none ? NULL : wide_nodes(w);
#else
    (void)bvh;
    return NULL;
#endif
}

/* The lowest lane of a nonzero mask. */
static inline unsigned wide_ctz(unsigned m)
{
#if defined(__GNUC__) || defined(__clang__)
    return (unsigned)__builtin_ctz(m);
#else
    unsigned l = 0;
    while (!(m >> l & 1u))
        l++;
    return l;
#endif
}

/* ------------------------------------------------- triangles of a leaf
 * Beside the wide nodes, the uncounted batches over triangles keep the
 * triangles' vertices in the order of the tree's references (entry j of
 * prim_indices), in pairs laid out for SSE2: a leaf then reads one
 * contiguous block instead of prim_indices, the index buffer and three
 * vertices per triangle.  The block holds copies of the caller's floats
 * (atrbvh_trav_triangle_vertices), 9 floats (36 bytes) per reference; a
 * reference whose primitive is past the geometry's count or whose vertex
 * ids are out of range holds NaN, which no test hits (as atrbvh_trav_leaf
 * skips it).  The geometry is the caller's, passed per call: the block is
 * made for one geometry (its pointers, counts and strides: the key) and
 * used only by calls given the same ones; a call given another geometry
 * reads the caller's arrays as before.  Vertex values changed in place
 * without atrbvh_refit (which drops the block with the wide nodes) are not
 * seen: atrbvh(3) says so.
 *
 * A leaf tests its triangles two at a time: the translated and sheared
 * vertices, the three edge functions, their sum (det) and the distance tt
 * of atrbvh_trav_triangle_hit, with the same double operations in the
 * same order on the same operands (the floats converted exactly; SSE2
 * lanes round as scalar SSE2 does, no contraction), so each lane's values
 * are the scalar test's, bit for bit.  A lane is dropped where the scalar
 * test rejects (edge functions of both signs; det 0 or NaN; tt below
 * tmin) or where its hit could not be taken (t = (float)tt above the
 * closest hit so far, or above tmax for any hit: atrbvh_trav_leaf's
 * choice); the few others finish the scalar test on the lane's values
 * (the range of t, atrbvh_trav_within_own_box, u and v). */
typedef struct wide_tris {
    /* the geometry the block was made from */
    const float *vertices;
    uint64_t vertex_count, vertex_stride;
    const uint32_t *indices;
    uint64_t index_stride;
    int indexed;
    uint64_t primitive_count;
    /* reference j: pair j / 2, lane j % 2; coordinate a of corner k of
     * pair p at c[18 * p + 6 * k + 2 * a + lane] */
    float *c;
} wide_tris;

/* Whether block t was made from the geometry of scene s. */
static int wide_tris_match(const wide_tris *t, const atrbvh_trav_scene *s)
{
    return t->vertices == s->vertices && t->vertex_count == s->vertex_count &&
           t->vertex_stride == s->vertex_stride && t->indexed == s->indexed &&
           (!s->indexed || (t->indices == s->indices &&
                            t->index_stride == s->index_stride)) &&
           t->primitive_count == s->primitive_count;
}

static void wide_tris_free(wide_tris *t)
{
    if (t) {
        atrbvh_i_free(t->c);
        atrbvh_i_free(t);
    }
}

/* The block of the tree's references over the triangles of s; NULL when
 * memory is short. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline)) /* its own entry in profiles */
#endif
static wide_tris *wide_tris_make(const atrbvh_bvh *bvh,
                                 const atrbvh_trav_scene *s, int threads)
{
    size_t pairs = bvh->prim_count / 2u + 1u;
    long long p, n = (long long)pairs;
    wide_tris *t = atrbvh_i_malloc(sizeof *t);
#ifdef _OPENMP
    int nt = atrbvh_i_resolve_threads(threads);
#else
    (void)threads;
#endif
    if (!t)
        return NULL;
    /* references numbered in 32 bits (wide_leaf_tris) */
    if (bvh->prim_count > (size_t)INT32_MAX) {
        atrbvh_i_free(t);
        return NULL;
    }
    t->c = atrbvh_i_alloc_array(pairs, 18u * sizeof(float));
    if (!t->c || pairs > (size_t)LLONG_MAX) {
        wide_tris_free(t);
        return NULL;
    }
    t->vertices = s->vertices;
    t->vertex_count = s->vertex_count;
    t->vertex_stride = s->vertex_stride;
    t->indices = s->indices;
    t->index_stride = s->index_stride;
    t->indexed = s->indexed;
    t->primitive_count = s->primitive_count;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(nt)
#endif
    for (p = 0; p < n; p++) {
        float *c = t->c + 18 * (size_t)p;
        int lane, k, a;
        for (lane = 0; lane < 2; lane++) {
            size_t j = 2u * (size_t)p + (size_t)lane;
            float v[3][3];
            uint32_t prim = j < bvh->prim_count ? bvh->prim_indices[j] : 0u;
            int ok = j < bvh->prim_count &&
                     (uint64_t)prim < s->primitive_count &&
                     atrbvh_trav_triangle_vertices(s, prim, v);
            for (k = 0; k < 3; k++)
                for (a = 0; a < 3; a++)
                    c[6 * k + 2 * a + lane] = ok ? v[k][a] : NAN;
        }
    }
    return t;
}

/* The block for scene s (made on first use and kept in bvh->wide_tris,
 * like the wide nodes), or NULL: none for another geometry than the one
 * it was made for, or memory short. */
static const wide_tris *wide_tris_get(const atrbvh_bvh *bvh,
                                      const atrbvh_trav_scene *s, int threads)
{
#if defined(__GNUC__) || defined(__clang__)
    void **slot = &((atrbvh_bvh *)(uintptr_t)bvh)->wide_tris;
    wide_tris *t = __atomic_load_n(slot, __ATOMIC_ACQUIRE);
    void *expected = NULL;
    if (!t) {
        t = wide_tris_make(bvh, s, threads);
        if (!t)
            return NULL;
        if (!__atomic_compare_exchange_n(slot, &expected, (void *)t, 0,
                                         __ATOMIC_ACQ_REL,
                                         __ATOMIC_ACQUIRE)) {
            wide_tris_free(t);
            t = expected;
        }
    }
    return wide_tris_match(t, s) ? t : NULL;
#else
    (void)bvh;
    (void)s;
    (void)threads;
    return NULL;
#endif
}

/* A ray's part of the paired triangle test: its origin along the
 * sheared axes and shear factors in both lanes, and where the
 * coordinates kx, ky, kz of corner 0 lie in a pair. */
typedef struct wide_tri_ray {
    __m128d ox, oy, oz, sx, sy, sz, tmin;
    int ax, ay, az;
} wide_tri_ray;

static inline void wide_tri_ray_make(const atrbvh_trav_ray *r,
                                     wide_tri_ray *q)
{
    q->ox = _mm_set1_pd(r->orgd[r->kx]);
    q->oy = _mm_set1_pd(r->orgd[r->ky]);
    q->oz = _mm_set1_pd(r->orgd[r->kz]);
    q->sx = _mm_set1_pd(r->sx);
    q->sy = _mm_set1_pd(r->sy);
    q->sz = _mm_set1_pd(r->sz);
    q->tmin = _mm_set1_pd((double)r->tmin);
    q->ax = 2 * r->kx;
    q->ay = 2 * r->ky;
    q->az = 2 * r->kz;
}

/* Two floats as two doubles (exact). */
static inline __m128d wide_load2(const float *f)
{
    return _mm_cvtps_pd(
        _mm_castsi128_ps(_mm_loadl_epi64((const __m128i *)(const void *)f)));
}

/* atrbvh_trav_leaf for the references [first, first + count) of a tree
 * over triangles, from block c: the same hits, the same choice among them
 * (see above).  Made into one function per query kind, any constant
 * (wide_leaf_closest, wide_leaf_any). */
ATRBVH_TRAV_HOT int wide_leaf_tris(const atrbvh_trav_scene *s,
                                   const float *c, uint32_t first,
                                   uint32_t count, const atrbvh_trav_ray *r,
                                   const wide_tri_ray *q, int any,
                                   atrbvh_trav_best *best)
{
    uint32_t end = first + count; /* <= prim_count: see wide_make */
    uint32_t p, pe = end / 2u + (end & 1u);
    __m128d zero = _mm_setzero_pd();
    double ttl[2], e1l[2], e2l[2], detl[2];
    for (p = first / 2u; p < pe; p++) {
        const float *f = c + 18 * (size_t)p;
#if defined(__GNUC__) || defined(__clang__)
        /* the ray's values are read per pair from q, not hoisted: leaves
         * hold one or two pairs, and hoisting them spilled them all to
         * the stack at each call */
        __asm__("" : : : "memory");
#endif
        __m128d az = _mm_sub_pd(wide_load2(f + q->az), q->oz);
        __m128d bz = _mm_sub_pd(wide_load2(f + 6 + q->az), q->oz);
        __m128d cz = _mm_sub_pd(wide_load2(f + 12 + q->az), q->oz);
        __m128d ax = _mm_sub_pd(_mm_sub_pd(wide_load2(f + q->ax), q->ox),
                                _mm_mul_pd(q->sx, az));
        __m128d ay = _mm_sub_pd(_mm_sub_pd(wide_load2(f + q->ay), q->oy),
                                _mm_mul_pd(q->sy, az));
        __m128d bx = _mm_sub_pd(_mm_sub_pd(wide_load2(f + 6 + q->ax), q->ox),
                                _mm_mul_pd(q->sx, bz));
        __m128d by = _mm_sub_pd(_mm_sub_pd(wide_load2(f + 6 + q->ay), q->oy),
                                _mm_mul_pd(q->sy, bz));
        __m128d cx = _mm_sub_pd(_mm_sub_pd(wide_load2(f + 12 + q->ax), q->ox),
                                _mm_mul_pd(q->sx, cz));
        __m128d cy = _mm_sub_pd(_mm_sub_pd(wide_load2(f + 12 + q->ay), q->oy),
                                _mm_mul_pd(q->sy, cz));
        __m128d e0 = _mm_sub_pd(_mm_mul_pd(cx, by), _mm_mul_pd(cy, bx));
        __m128d e1 = _mm_sub_pd(_mm_mul_pd(ax, cy), _mm_mul_pd(ay, cx));
        __m128d e2 = _mm_sub_pd(_mm_mul_pd(bx, ay), _mm_mul_pd(by, ax));
        __m128d neg = _mm_or_pd(_mm_or_pd(_mm_cmplt_pd(e0, zero),
                                          _mm_cmplt_pd(e1, zero)),
                                _mm_cmplt_pd(e2, zero));
        __m128d pos = _mm_or_pd(_mm_or_pd(_mm_cmpgt_pd(e0, zero),
                                          _mm_cmpgt_pd(e1, zero)),
                                _mm_cmpgt_pd(e2, zero));
        __m128d det = _mm_add_pd(_mm_add_pd(e0, e1), e2);
        __m128d keep = _mm_andnot_pd(_mm_and_pd(neg, pos),
                                     _mm_and_pd(_mm_cmpneq_pd(det, zero),
                                                _mm_cmpord_pd(det, det)));
        __m128d tt;
        int m = _mm_movemask_pd(keep);
        if (2u * p < first)
            m &= 2;
        if (2u * p + 1u >= end)
            m &= 1;
        if (!m) /* most pairs */
            continue;
        /* the distance, as the scalar test computes it */
        tt = _mm_add_pd(_mm_add_pd(_mm_mul_pd(e0, _mm_mul_pd(q->sz, az)),
                                   _mm_mul_pd(e1, _mm_mul_pd(q->sz, bz))),
                        _mm_mul_pd(e2, _mm_mul_pd(q->sz, cz)));
        tt = _mm_div_pd(tt, det);
        m &= _mm_movemask_pd(_mm_cmpge_pd(tt, q->tmin)) &
             _mm_movemask_ps(_mm_cmple_ps(
                 _mm_cvtpd_ps(tt), _mm_set1_ps(any ? r->tmax : best->t)));
        if (!m)
            continue;
        _mm_storeu_pd(ttl, tt);
        _mm_storeu_pd(e1l, e1);
        _mm_storeu_pd(e2l, e2);
        _mm_storeu_pd(detl, det);
        while (m) {
            int lane = m & 1 ? 0 : 1, k, a;
            uint32_t j = 2u * p + (uint32_t)lane;
            uint32_t prim = s->prim_indices[j];
            float v[3][3], t, u, w;
            m &= m - 1;
            for (k = 0; k < 3; k++)
                for (a = 0; a < 3; a++)
                    v[k][a] = f[6 * k + 2 * a + lane];
            /* the rest of atrbvh_trav_triangle_hit, on this lane's values
             * (tt >= tmin is tested above) */
            if (!(atrbvh_trav_abs(ttl[lane]) <= (double)ATRBVH_TRAV_FLT_MAX))
                continue;
            t = (float)ttl[lane];
            if (!(atrbvh_trav_absf(t) <= ATRBVH_TRAV_FLT_MAX) ||
                !atrbvh_trav_within_own_box(v, r, t))
                continue;
            u = (float)(e1l[lane] / detl[lane]);
            w = (float)(e2l[lane] / detl[lane]);
            /* as atrbvh_trav_leaf takes a triangle's hit */
            if (any) {
                if (t >= r->tmin && t <= r->tmax)
                    return 1;
                continue;
            }
            if (t >= r->tmin &&
                (t < best->t || (t == best->t && prim < best->prim))) {
                best->t = t;
                best->u = u;
                best->v = w;
                best->prim = prim;
                best->tlim = atrbvh_trav_widen_limit(t);
            }
        }
    }
    return 0;
}

/* The leaf tests stay out of line, out of the node loop's registers. */
#if defined(__GNUC__) || defined(__clang__)
#define WIDE_NOINLINE __attribute__((noinline))
#else
#define WIDE_NOINLINE
#endif

static WIDE_NOINLINE int wide_leaf_closest(const atrbvh_trav_scene *s,
                                           const float *c, uint32_t first,
                                           uint32_t count,
                                           const atrbvh_trav_ray *r,
                                           const wide_tri_ray *q,
                                           atrbvh_trav_best *best)
{
    return wide_leaf_tris(s, c, first, count, r, q, 0, best);
}

static WIDE_NOINLINE int wide_leaf_any(const atrbvh_trav_scene *s,
                                       const float *c, uint32_t first,
                                       uint32_t count,
                                       const atrbvh_trav_ray *r,
                                       const wide_tri_ray *q,
                                       atrbvh_trav_best *best)
{
    return wide_leaf_tris(s, c, first, count, r, q, 1, best);
}

/* The node test of all WIDE_W lanes of the box block b: the mask of the
 * lanes hit, their entry distances in t.  nx, ny, nz: where each axis's
 * near planes are past its minima (0: the minima, 3 * WIDE_W: the
 * maxima, by the sign of the direction).  For a box with min <= max,
 * (min - o) * id <= (max - o) * id exactly when id > 0 (rounding is
 * monotone), so the near and far values are those the binary test's min
 * and max pick (but for the sign of a zero, which no comparison sees).
 * SSE2: four lanes at a time. */
ATRBVH_TRAV_HOT unsigned wide_hit_sse(const float *b, int nx, int ny, int nz,
                                      __m128 ox, __m128 oy, __m128 oz,
                                      __m128 ix, __m128 iy, __m128 iz,
                                      __m128 tlo4, __m128 thi4, __m128 widen,
                                      __m128 slack, float *t)
{
    unsigned m = 0;
    int h;
    for (h = 0; h < WIDE_W; h += 4) {
        const float *bx = b + h, *by = b + WIDE_W + h, *bz = b + 2 * WIDE_W + h;
        __m128 xn = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(bx + nx), ox), ix);
        __m128 xf = _mm_mul_ps(
            _mm_sub_ps(_mm_loadu_ps(bx + (3 * WIDE_W - nx)), ox), ix);
        __m128 yn = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(by + ny), oy), iy);
        __m128 yf = _mm_mul_ps(
            _mm_sub_ps(_mm_loadu_ps(by + (3 * WIDE_W - ny)), oy), iy);
        __m128 zn = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(bz + nz), oz), iz);
        __m128 zf = _mm_mul_ps(
            _mm_sub_ps(_mm_loadu_ps(bz + (3 * WIDE_W - nz)), oz), iz);
        __m128 lo = _mm_max_ps(xn, tlo4);
        __m128 hi = _mm_min_ps(xf, thi4);
        lo = _mm_max_ps(yn, lo);
        hi = _mm_min_ps(yf, hi);
        lo = _mm_max_ps(zn, lo);
        hi = _mm_min_ps(zf, hi);
        hi = _mm_add_ps(_mm_mul_ps(hi, widen), slack);
        m |= (unsigned)_mm_movemask_ps(_mm_cmple_ps(lo, hi)) << h;
        _mm_storeu_ps(t + h, lo);
    }
    return m;
}

#if WIDE_AVX2
/* wide_hit_sse with AVX2: the eight lanes at once, with the same
 * operations on the same operands lane by lane (vsubps, vmulps, vmaxps,
 * vminps, vaddps and an ordered <= round and compare as their SSE
 * forms), so the same bits.  Not always_inline (GCC refuses to inline an
 * AVX2 function into the generic wide_run); inlined into the AVX2
 * callers all the same. */
__attribute__((target("avx2"))) static inline unsigned
wide_hit_avx2(const float *b, int nx, int ny, int nz, const float *o,
              const float *id, float tlo, float thi, float *t)
{
    __m256 ox = _mm256_set1_ps(o[0]), oy = _mm256_set1_ps(o[1]);
    __m256 oz = _mm256_set1_ps(o[2]);
    __m256 ix = _mm256_set1_ps(id[0]), iy = _mm256_set1_ps(id[1]);
    __m256 iz = _mm256_set1_ps(id[2]);
    const float *by = b + 8, *bz = b + 16;
    __m256 xn = _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(b + nx), ox), ix);
    __m256 xf =
        _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(b + (24 - nx)), ox), ix);
    __m256 yn = _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(by + ny), oy), iy);
    __m256 yf =
        _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(by + (24 - ny)), oy), iy);
    __m256 zn = _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(bz + nz), oz), iz);
    __m256 zf =
        _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(bz + (24 - nz)), oz), iz);
    __m256 lo = _mm256_max_ps(xn, _mm256_set1_ps(tlo));
    __m256 hi = _mm256_min_ps(xf, _mm256_set1_ps(thi));
    lo = _mm256_max_ps(yn, lo);
    hi = _mm256_min_ps(yf, hi);
    lo = _mm256_max_ps(zn, lo);
    hi = _mm256_min_ps(zf, hi);
    hi = _mm256_add_ps(_mm256_mul_ps(hi, _mm256_set1_ps(ATRBVH_TRAV_WIDEN_F)),
                       _mm256_set1_ps(ATRBVH_TRAV_SLACK_F));
    _mm256_storeu_ps(t, lo);
    return (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(lo, hi, _CMP_LE_OS));
}
#endif

/* atrbvh_trav_run over the wide copy, for a ray with use_float; inlined
 * with `any` and `avx` (the AVX2 node test: only in functions made for
 * AVX2) constant into wide_closest_t and wide_any_t, and those into the
 * per-ray functions (the ray's fields reach it without a call). */
ATRBVH_TRAV_HOT int wide_run(const atrbvh_trav_scene *s, const wide_node *w,
                             const wide_tris *tris,
                             const atrbvh_trav_ray *r, int any, int avx,
                             atrbvh_trav_best *best)
{
    wide_tri_ray q;
    int64_t stack_node[WIDE_STACK];
    float stack_t[WIDE_STACK];
    float t8[WIDE_W];
    unsigned sp = 0;
    int64_t cur = 0;
    float tlo = atrbvh_trav_best_start(r, best);
    float thi;
    __m128 ox = _mm_set1_ps(r->orgf[0]), oy = _mm_set1_ps(r->orgf[1]);
    __m128 oz = _mm_set1_ps(r->orgf[2]);
    __m128 ix = _mm_set1_ps(r->idirf[0]), iy = _mm_set1_ps(r->idirf[1]);
    __m128 iz = _mm_set1_ps(r->idirf[2]);
    __m128 widen = _mm_set1_ps(ATRBVH_TRAV_WIDEN_F);
    __m128 slack = _mm_set1_ps(ATRBVH_TRAV_SLACK_F);
    __m128 tlo4, thi4;
    /* where each axis's near planes are, past its minima in wide_node.b:
     * the minima (0) or the maxima (3 * WIDE_W) by the sign of the
     * direction */
    int nxo = r->idirf[0] < 0.0f ? 3 * WIDE_W : 0;
    int nyo = r->idirf[1] < 0.0f ? 3 * WIDE_W : 0;
    int nzo = r->idirf[2] < 0.0f ? 3 * WIDE_W : 0;
    /* no test of the root's box: it holds every box of the copy (see
     * box_inside), so the first node's tests reject the rays it would */
#if defined(__GNUC__) || defined(__clang__)
    __asm__("" : "+x"(widen), "+x"(slack));
#endif
    (void)avx;
    wide_tri_ray_make(r, &q); /* used when tris */
    thi = best->tlim;
    tlo4 = _mm_set1_ps(tlo);
    thi4 = _mm_set1_ps(thi);
    for (;;) {
        if (cur < 0) {
            uint32_t first = (uint32_t)~cur, count = (uint32_t)(~cur >> 32);
            int done;
            if (tris) {
                done = any ? wide_leaf_any(s, tris->c, first, count, r, &q,
                                           best)
                           : wide_leaf_closest(s, tris->c, first, count, r,
                                               &q, best);
            } else {
                /* the binary leaf's (index, count): all atrbvh_trav_leaf
                 * reads of it */
                atrbvh_node leaf;
                leaf.index = first;
                leaf.count = count;
                done = atrbvh_trav_leaf(s, &leaf, r, any, best);
            }
            if (done)
                return 1;
            if (!any && best->tlim != thi) { /* any: never changes */
                thi = best->tlim;
                thi4 = _mm_set1_ps(thi);
            }
        } else {
            const wide_node *n = &w[cur];
            unsigned m;
#if WIDE_AVX2
            if (avx)
                m = wide_hit_avx2(n->b, nxo, nyo, nzo, r->orgf, r->idirf, tlo,
                                  thi, t8);
            else
#endif
                m = wide_hit_sse(n->b, nxo, nyo, nzo, ox, oy, oz, ix, iy, iz,
                                 tlo4, thi4, widen, slack, t8);
            if (any) {
                /* any hit: whether one exists does not depend on the
                 * order, so no sorting: the lowest hit lane's child is
                 * visited next, and the others stay with their node as
                 * one entry (the node's index above bit 8, the lanes
                 * left below), pushed without a branch, taken one at a
                 * time by the pops below.  This stack holds its entries
                 * at 1..sp, at most one per wide level. */
                unsigned rest = m & (m - 1u);
                stack_node[sp + 1u] = (int64_t)((uint64_t)cur << 8 | rest);
                sp += rest != 0u;
                if (m) {
                    cur = n->child[wide_ctz(m)];
                    continue;
                }
            } else if (m) {
                unsigned rest = m & (m - 1u);
                int64_t c[WIDE_W];
                float ct[WIDE_W];
                int cnt = 0, a;
                if (!rest) {
                    cur = n->child[wide_ctz(m)];
                    continue;
                }
                if (!(rest & (rest - 1u))) {
                    /* two hits, the most common case: the nearer
                     * visited, the other pushed */
                    unsigned l0 = wide_ctz(m), l1 = wide_ctz(rest);
                    if (t8[l1] < t8[l0]) {
                        unsigned sw = l0;
                        l0 = l1;
                        l1 = sw;
                    }
                    stack_node[sp] = n->child[l1];
                    stack_t[sp] = t8[l1];
                    sp++;
                    cur = n->child[l0];
                    continue;
                }
                for (; m; m &= m - 1u) {
                    unsigned lane = wide_ctz(m);
                    float tl = t8[lane];
                    /* insertion by descending entry distance */
                    for (a = cnt++; a > 0 && ct[a - 1] < tl; a--) {
                        ct[a] = ct[a - 1];
                        c[a] = c[a - 1];
                    }
                    ct[a] = tl;
                    c[a] = n->child[lane];
                }
                /* sp + WIDE_W - 1 <= WIDE_STACK: see WIDE_MAX_DEPTH */
                for (a = 0; a < cnt - 1; a++) {
                    stack_node[sp] = c[a];
                    stack_t[sp] = ct[a];
                    sp++;
                }
                cur = c[cnt - 1];
                continue;
            }
        }
        if (any) { /* entries at 1..sp: see above */
            uint64_t e;
            if (sp == 0u)
                return 0;
            e = (uint64_t)stack_node[sp];
            cur = w[e >> 8].child[wide_ctz((unsigned)e & 0xffu)];
            e &= e - 1u; /* that lane taken */
            stack_node[sp] = (int64_t)e;
            sp -= (e & 0xffu) == 0u;
            continue;
        }
        while (sp > 0u && !(stack_t[sp - 1u] <= thi))
            sp--;
        if (sp == 0u)
            return best->prim != ATRBVH_NO_HIT;
        sp--;
        cur = stack_node[sp];
    }
}
#endif

/* atrbvh_trav_setup for the batches over the wide copy.  A ray that takes
 * the float test (tmin >= 0 and at most tmax, every direction component
 * of magnitude within [2^-125, 2^125], the origin within +-2^126; no NaN
 * or infinity passes these comparisons) gets the same fields from the
 * same operations (the shear by atrbvh_trav_setup_shear), without the
 * loops and the finiteness tests, and without near_at and far_at, which
 * only the double node test reads (such a ray has use_float 1, and the
 * wide copy is used only for scenes that allow the float test: cpu_batch);
 * every other ray goes through atrbvh_trav_setup. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((always_inline))
#endif
static inline int wide_setup(const atrbvh_ray *ray, atrbvh_trav_ray *r)
{
    const float *o = ray->origin, *d = ray->dir;
    float a0 = fabsf(d[0]), a1 = fabsf(d[1]), a2 = fabsf(d[2]);
    const float ad[3] = {a0, a1, a2};
    double id0, id1, id2;
    if (!((ray->tmin >= 0.0f) & (ray->tmin <= ray->tmax) &
          (a0 >= ATRBVH_TRAV_F_DIR_MIN) & (a0 <= ATRBVH_TRAV_F_DIR_MAX) &
          (a1 >= ATRBVH_TRAV_F_DIR_MIN) & (a1 <= ATRBVH_TRAV_F_DIR_MAX) &
          (a2 >= ATRBVH_TRAV_F_DIR_MIN) & (a2 <= ATRBVH_TRAV_F_DIR_MAX) &
          (fabsf(o[0]) <= ATRBVH_TRAV_F_COORD_MAX) &
          (fabsf(o[1]) <= ATRBVH_TRAV_F_COORD_MAX) &
          (fabsf(o[2]) <= ATRBVH_TRAV_F_COORD_MAX)))
        return atrbvh_trav_setup(o, d, ray->tmin, ray->tmax, r);
    id0 = 1.0 / (double)d[0];
    id1 = 1.0 / (double)d[1];
    id2 = 1.0 / (double)d[2];
    r->orgf[0] = o[0];
    r->orgf[1] = o[1];
    r->orgf[2] = o[2];
    r->idirf[0] = (float)id0;
    r->idirf[1] = (float)id1;
    r->idirf[2] = (float)id2;
    r->use_float = 1;
    r->orgd[0] = (double)o[0];
    r->orgd[1] = (double)o[1];
    r->orgd[2] = (double)o[2];
    r->idird[0] = id0;
    r->idird[1] = id1;
    r->idird[2] = id2;
    r->sign[0] = id0 < 0.0;
    r->sign[1] = id1 < 0.0;
    r->sign[2] = id2 < 0.0;
    r->tmin = ray->tmin;
    r->tmax = ray->tmax;
    atrbvh_trav_setup_shear(d, ad, r);
    return 1;
}

/* atrbvh_trav_closest and atrbvh_trav_any with the wide copy `w` (NULL:
 * none) for the rays that take the float test; `avx` constant (see
 * wide_run), inlined into wide_closest, wide_any and their AVX2 forms. */
ATRBVH_TRAV_HOT void wide_closest_t(const atrbvh_trav_scene *s, const void *w,
                                    const void *tris, const atrbvh_ray *ray,
                                    atrbvh_hit *hit, int avx)
{
#ifdef ATRBVH_TRAV_SSE
    atrbvh_trav_ray r;
    atrbvh_trav_best best;
    if (w) {
        hit->t = ray->tmax;
        hit->u = hit->v = 0.0f;
        hit->primitive = ATRBVH_NO_HIT;
        if (!wide_setup(ray, &r))
            return;
        if (!(r.use_float ? wide_run(s, (const wide_node *)w,
                                     (const wide_tris *)tris, &r, 0, avx,
                                     &best)
                          : atrbvh_trav_run(s, &r, 0, &best)))
            return;
        hit->t = best.t;
        hit->u = best.u;
        hit->v = best.v;
        hit->primitive = best.prim;
        return;
    }
#else
    (void)w;
    (void)tris;
#endif
    (void)avx;
    closest(s, ray, hit);
}

ATRBVH_TRAV_HOT int wide_any_t(const atrbvh_trav_scene *s, const void *w,
                               const void *tris, const atrbvh_ray *ray,
                               int avx)
{
#ifdef ATRBVH_TRAV_SSE
    atrbvh_trav_ray r;
    atrbvh_trav_best best;
    if (w) {
        if (!wide_setup(ray, &r))
            return 0;
        return r.use_float ? wide_run(s, (const wide_node *)w,
                                      (const wide_tris *)tris, &r, 1, avx,
                                      &best)
                           : atrbvh_trav_run(s, &r, 1, &best);
    }
#else
    (void)w;
    (void)tris;
#endif
    (void)avx;
    return atrbvh_trav_any(s, ray->origin, ray->dir, ray->tmin, ray->tmax);
}

static void wide_closest(const atrbvh_trav_scene *s, const void *w,
                         const void *tris, const atrbvh_ray *ray,
                         atrbvh_hit *hit)
{
    wide_closest_t(s, w, tris, ray, hit, 0);
}

static int wide_any(const atrbvh_trav_scene *s, const void *w,
                    const void *tris, const atrbvh_ray *ray)
{
    return wide_any_t(s, w, tris, ray, 0);
}

#if defined(ATRBVH_TRAV_SSE) && WIDE_AVX2
/* (each clears the upper halves of the YMM registers on its way back to
 * the batch loop's SSE code: GCC does only at -O2 and above, and not
 * before a tail call; tests/test_vecstate.c) */
__attribute__((target("avx2"))) static void
wide_closest_avx2(const atrbvh_trav_scene *s, const void *w, const void *tris,
                  const atrbvh_ray *ray, atrbvh_hit *hit)
{
    wide_closest_t(s, w, tris, ray, hit, 1);
    _mm256_zeroupper();
}

__attribute__((target("avx2"))) static int
wide_any_avx2(const atrbvh_trav_scene *s, const void *w, const void *tris,
              const atrbvh_ray *ray)
{
    const int any = wide_any_t(s, w, tris, ray, 1);
    _mm256_zeroupper();
    return any;
}

/* Whether the wide batches take the AVX2 node test: the CPU (and the
 * system) support AVX2, and the environment variable ATRBVH_NO_AVX2 is
 * unset, empty or "0" (set: the SSE2 node test, which gives the same
 * bits; the tests run both). */
static int wide_avx2(void)
{
    return atrbvh_i_avx2(); /* (api.c) */
}
#endif

void atrbvh_i_bvh_drop_wide(atrbvh_bvh *bvh)
{
#ifdef ATRBVH_TRAV_SSE
    if (bvh->wide && bvh->wide != (const void *)&wide_none)
        atrbvh_i_free(bvh->wide);
    wide_tris_free(bvh->wide_tris);
#else
    atrbvh_i_free(bvh->wide);
#endif
    bvh->wide = NULL;
    bvh->wide_tris = NULL;
}

/* The single-ray calls make the batch calls' checks (one ray, the output
 * pointer, threads 0), with no error to fill: a failed check is a miss. */
int atrbvh_intersect(const atrbvh_bvh *bvh, const atrbvh_geometry *geometry,
                     const atrbvh_ray *ray, atrbvh_hit *hit)
{
    atrbvh_trav_scene s;
    if (hit) {
        hit->t = ray ? ray->tmax : 0.0f;
        hit->u = hit->v = 0.0f;
        hit->primitive = ATRBVH_NO_HIT;
    }
    if (!ray || !hit ||
        atrbvh_i_trav_check(bvh, geometry, ray, 1, hit, 0,
                            "atrbvh_intersect", NULL) != ATRBVH_OK ||
        !trav_scene(bvh, geometry, &s))
        return 0;
    closest(&s, ray, hit);
    return hit->primitive != ATRBVH_NO_HIT;
}

int atrbvh_occluded(const atrbvh_bvh *bvh, const atrbvh_geometry *geometry,
                    const atrbvh_ray *ray)
{
    atrbvh_trav_scene s;
    if (!ray ||
        atrbvh_i_trav_check(bvh, geometry, ray, 1, ray, 0, "atrbvh_occluded",
                            NULL) != ATRBVH_OK ||
        !trav_scene(bvh, geometry, &s))
        return 0;
    return atrbvh_trav_any(&s, ray->origin, ray->dir, ray->tmin, ray->tmax);
}

/* The checks both batch functions make. */
atrbvh_status atrbvh_i_trav_check(const atrbvh_bvh *bvh,
                                  const atrbvh_geometry *g,
                                 const atrbvh_ray *rays, size_t count,
                                 const void *out, int threads,
                                 const char *fn, atrbvh_error *error)
{
    size_t needed;
    if (!bvh)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: bvh is NULL", fn);
    if (!g)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: geometry is NULL", fn);
    if (count > 0 && !rays)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: rays is NULL", fn);
    if (count > 0 && !out)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: the output array is NULL", fn);
    if (threads < 0)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: threads %d is negative", fn, threads);
    if (threads > ATRBVH_MAX_THREADS)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: threads %d is above the limit of %d "
                             "(ATRBVH_MAX_THREADS)",
                             fn, threads, ATRBVH_MAX_THREADS);
    if (g->type != ATRBVH_GEOMETRY_TRIANGLES &&
        g->type != ATRBVH_GEOMETRY_BOXES)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: geometry type %d is not triangles or boxes",
                             fn, (int)g->type);
    if (!geometry_usable(g))
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: geometry.%s is NULL", fn,
                             g->type == ATRBVH_GEOMETRY_TRIANGLES ? "vertices"
                                                                  : "boxes");
    {
        atrbvh_trav_scene s;
        if (!trav_scene(bvh, g, &s))
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                                 (uint64_t)-1,
                                 "%s: a geometry byte stride is not a "
                                 "multiple of 4", fn);
    }
    needed = bvh->stats.primitives + bvh->stats.invalid_skipped;
    if (needed < bvh->prim_count && !bvh->split_prims)
        needed = bvh->prim_count;
    if (g->primitive_count < needed)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                             (uint64_t)g->primitive_count,
                             "%s: the geometry has %lu primitives but the BVH "
                             "was built over %lu",
                             fn, (unsigned long)g->primitive_count,
                             (unsigned long)needed);
    return ATRBVH_OK;
}

/* One batch on the CPU: closest hits into `hits` or any hits into
 * `occluded`; with `cost` each ray's counts, and the sums into *boxes and
 * *prims (integer sums: the same for every thread count). */
static void cpu_batch(const atrbvh_bvh *bvh, const atrbvh_trav_scene *s,
                      const atrbvh_ray *rays,
                      size_t count, atrbvh_hit *hits, uint8_t *occluded,
                      atrbvh_ray_cost *cost, int threads, uint64_t *boxes,
                      uint64_t *prims)
{
    long long i, n = (long long)count;
    uint64_t nb = 0, np = 0;
#ifdef _OPENMP
    int nt = atrbvh_i_resolve_threads(threads);
#else
    (void)threads;
#endif
    if (!boxes) {
        const void *w = NULL, *tris = NULL;
#if WIDE_AVX2
        int avx = 0;
#endif
#ifdef ATRBVH_TRAV_SSE
        if (s->float_slabs && count >= WIDE_MIN_RAYS)
            w = wide_get(bvh);
        if (w && !s->boxes)
            tris = wide_tris_get(bvh, s, threads);
#if WIDE_AVX2
        avx = w && wide_avx2();
#endif
#else
        (void)bvh;
#endif
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 64) num_threads(nt)
#endif
        for (i = 0; i < n; i++) {
            const atrbvh_ray *r = &rays[i];
#if WIDE_AVX2
            if (avx) {
                if (hits)
                    wide_closest_avx2(s, w, tris, r, &hits[i]);
                else
                    occluded[i] = (uint8_t)(wide_any_avx2(s, w, tris, r) != 0);
                continue;
            }
#endif
            if (hits)
                wide_closest(s, w, tris, r, &hits[i]);
            else
                occluded[i] = (uint8_t)(wide_any(s, w, tris, r) != 0);
        }
        return;
    }
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 64) num_threads(nt)                \
    reduction(+ : nb, np)
#endif
    for (i = 0; i < n; i++) {
        const atrbvh_ray *r = &rays[i];
        atrbvh_u32 b, p;
        if (hits)
            atrbvh_trav_closest_cost(s, r->origin, r->dir, r->tmin, r->tmax,
                                     &hits[i].t, &hits[i].u, &hits[i].v,
                                     &hits[i].primitive, &b, &p);
        else
            occluded[i] = (uint8_t)(atrbvh_trav_any_cost(
                                        s, r->origin, r->dir, r->tmin,
                                        r->tmax, &b, &p) != 0);
        if (cost) {
            cost[i].box_tests = b;
            cost[i].prim_tests = p;
        }
        nb += b;
        np += p;
    }
    *boxes = nb;
    *prims = np;
}

atrbvh_status atrbvh_intersect_batch(const atrbvh_bvh *bvh,
                                     const atrbvh_geometry *geometry,
                                     const atrbvh_ray *rays, size_t count,
                                     atrbvh_hit *hits, int threads,
                                     atrbvh_error *error)
{
    atrbvh_trav_scene s;
    atrbvh_status st;
    st = atrbvh_i_trav_check(bvh, geometry, rays, count, hits, threads,
                             "atrbvh_intersect_batch", error);
    if (st != ATRBVH_OK)
        return st;
    atrbvh_i_clear_error(error);
    trav_scene(bvh, geometry, &s); /* checked */
    cpu_batch(bvh, &s, rays, count, hits, NULL, NULL, threads, NULL, NULL);
    return ATRBVH_OK;
}

atrbvh_status atrbvh_occluded_batch(const atrbvh_bvh *bvh,
                                    const atrbvh_geometry *geometry,
                                    const atrbvh_ray *rays, size_t count,
                                    uint8_t *occluded, int threads,
                                    atrbvh_error *error)
{
    atrbvh_trav_scene s;
    atrbvh_status st;
    st = atrbvh_i_trav_check(bvh, geometry, rays, count, occluded, threads,
                             "atrbvh_occluded_batch", error);
    if (st != ATRBVH_OK)
        return st;
    atrbvh_i_clear_error(error);
    trav_scene(bvh, geometry, &s); /* checked */
    cpu_batch(bvh, &s, rays, count, NULL, occluded, NULL, threads, NULL,
                  NULL);
    return ATRBVH_OK;
}

/* The first version of atrbvh_trace_stats ends after kernel_ms. */
#define TRACE_STATS_SIZE_V1                                                    \
    (offsetof(atrbvh_trace_stats, kernel_ms) + sizeof(double))

void atrbvh_trace_stats_init(atrbvh_trace_stats *stats)
{
    if (!stats)
        return;
    memset(stats, 0, sizeof *stats);
    stats->size = sizeof *stats;
}

/* Every batch call: the checks, then the CPU batch (device NULL or a CPU
 * device) or the device's backend; the counts when stats asks. */
static atrbvh_status batch(atrbvh_device *dev, const atrbvh_bvh *bvh,
                           const atrbvh_geometry *geometry,
                           const atrbvh_ray *rays, size_t count,
                           atrbvh_hit *hits, uint8_t *occluded, int any,
                           int threads, atrbvh_trace_stats *stats,
                           double *kernel_ms, const char *fn,
                           atrbvh_error *error)
{
    atrbvh_trav_scene s;
    atrbvh_i_input in;
    atrbvh_status st;
    atrbvh_ray_cost *cost = NULL;
    uint64_t nb = 0, np = 0;
    double kms = 0.0;
    if (kernel_ms)
        *kernel_ms = 0.0;
    if (stats && stats->size < TRACE_STATS_SIZE_V1)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: stats->size %lu is below the first "
                             "version's %lu (atrbvh_trace_stats_init sets "
                             "it)",
                             fn, (unsigned long)stats->size,
                             (unsigned long)TRACE_STATS_SIZE_V1);
    if (dev && threads != 0)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: threads is %d with a device (must be 0)",
                             fn, threads);
    st = atrbvh_i_trav_check(bvh, geometry, rays, count,
                             any ? (const void *)occluded
                                 : (const void *)hits,
                             threads, fn, error);
    if (st != ATRBVH_OK)
        return st;
    atrbvh_i_clear_error(error);
    if (stats) {
        stats->rays = 0;
        stats->box_tests = stats->prim_tests = 0;
        stats->kernel_ms = 0.0;
        cost = stats->per_ray;
    }
    if (count == 0)
        return ATRBVH_OK;
    if (!dev || !dev->backend->trace) {
        trav_scene(bvh, geometry, &s); /* checked */
        cpu_batch(bvh, &s, rays, count, any ? NULL : hits, any ? occluded : NULL,
                  cost, threads, stats ? &nb : NULL, stats ? &np : NULL);
    } else {
        st = atrbvh_i_check_geometry(geometry, &in, error);
        if (st != ATRBVH_OK)
            return st;
        if (stats && !cost) {
            cost = atrbvh_i_alloc_array(count, sizeof *cost);
            if (!cost)
                return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)count,
                                     "%s: no memory for %lu ray costs", fn,
                                     (unsigned long)count);
        }
        atrbvh_i_device_lock(dev);
        st = dev->backend->trace(dev, bvh->nodes, bvh->node_count,
                                 bvh->prim_indices, bvh->prim_count, &in,
                                 rays, count, any ? NULL : hits,
                                 any ? occluded : NULL, cost, 0, &kms, error);
        atrbvh_i_device_unlock(dev);
        if (st == ATRBVH_OK && cost) {
            size_t i;
            for (i = 0; i < count; i++) {
                nb += cost[i].box_tests;
                np += cost[i].prim_tests;
            }
        }
        if (stats && cost != stats->per_ray)
            atrbvh_i_free(cost);
        if (st != ATRBVH_OK)
            return st;
        if (kernel_ms)
            *kernel_ms = kms;
    }
    if (stats) {
        stats->rays = (uint64_t)count;
        stats->box_tests = nb;
        stats->prim_tests = np;
        stats->kernel_ms = kms;
    }
    return ATRBVH_OK;
}

atrbvh_status atrbvh_intersect_batch_stats(
    atrbvh_device *device, const atrbvh_bvh *bvh,
    const atrbvh_geometry *geometry, const atrbvh_ray *rays, size_t count,
    atrbvh_hit *hits, int threads, atrbvh_trace_stats *stats,
    atrbvh_error *error)
{
    return batch(device, bvh, geometry, rays, count, hits, NULL, 0, threads,
                 stats, NULL, "atrbvh_intersect_batch_stats", error);
}

atrbvh_status atrbvh_occluded_batch_stats(
    atrbvh_device *device, const atrbvh_bvh *bvh,
    const atrbvh_geometry *geometry, const atrbvh_ray *rays, size_t count,
    uint8_t *occluded, int threads, atrbvh_trace_stats *stats,
    atrbvh_error *error)
{
    return batch(device, bvh, geometry, rays, count, NULL, occluded, 1,
                 threads, stats, NULL, "atrbvh_occluded_batch_stats", error);
}

atrbvh_status atrbvh_intersect_batch_device(atrbvh_device *device,
                                            const atrbvh_bvh *bvh,
                                            const atrbvh_geometry *geometry,
                                            const atrbvh_ray *rays,
                                            size_t count, atrbvh_hit *hits,
                                            double *kernel_ms,
                                            atrbvh_error *error)
{
    if (!device) {
        if (kernel_ms)
            *kernel_ms = 0.0;
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "atrbvh_intersect_batch_device: the device is "
                             "NULL");
    }
    return batch(device, bvh, geometry, rays, count, hits, NULL, 0, 0, NULL,
                 kernel_ms, "atrbvh_intersect_batch_device", error);
}

atrbvh_status atrbvh_occluded_batch_device(atrbvh_device *device,
                                           const atrbvh_bvh *bvh,
                                           const atrbvh_geometry *geometry,
                                           const atrbvh_ray *rays,
                                           size_t count, uint8_t *occluded,
                                           double *kernel_ms,
                                           atrbvh_error *error)
{
    if (!device) {
        if (kernel_ms)
            *kernel_ms = 0.0;
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "atrbvh_occluded_batch_device: the device is "
                             "NULL");
    }
    return batch(device, bvh, geometry, rays, count, NULL, occluded, 1, 0,
                 NULL, kernel_ms, "atrbvh_occluded_batch_device", error);
}
