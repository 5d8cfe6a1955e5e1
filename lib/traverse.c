/*
 * traverse.c - ray queries over a built BVH: closest hit and any hit, single
 * rays and OpenMP batches.
 *
 * Robustness (see atrbvh(3), "Ray queries"):
 *
 *  - Ray/node test: the slab test with 1/dir, where a zero direction
 *    component gives 1/dir = +-inf.  The near and far distances of each
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
 *  - Closest hit: t in (tmin, tmax], t finite; equal t goes to the lower
 *    primitive index, so the result does not depend on traversal order.
 *    Any hit: t in [tmin, tmax].
 *
 *  - Box primitives are surfaces: the ray hits a box where it enters it and,
 *    when the origin is inside, where it leaves it (u = v = 0).
 *
 *  - Rays with a NaN or infinite origin or direction, an all-zero direction,
 *    or a NaN tmin/tmax hit nothing.
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

#include <float.h>
#include <math.h>
#include <string.h>

#define TRAVERSE_STACK 256

/* 1 + 2*gamma(3) and 1 - 2*gamma(3), gamma(n) = n*u / (1 - n*u), u = 2^-24,
 * rounded outwards. */
#define WIDEN_UP 1.00000036f
#define WIDEN_DOWN 0.99999964f
/* Relative slack on the closest-hit distance when pruning (2^-12). */
#define PRUNE_SLACK (1.0f / 4096.0f)
/* Relative slack on the near end of a triangle's own box (within_own_box):
 * covers the float rounding of t (2^-24) with a wide margin. */
#define OWN_BOX_SLACK (1.0 / 1048576.0)

typedef struct ray_pre {
    float idir[3];
    double orgd[3];  /* the slab tests run in double: see node_hit */
    double idird[3];
    int sign[3]; /* 1 when idir[k] < 0 (direction -0 included) */
    float tmin, tmax;
    /* watertight triangle test, in double */
    double o[3];
    int kx, ky, kz;
    double sx, sy, sz;
} ray_pre;

typedef struct best_hit {
    float t, u, v;
    uint32_t prim;
    float tlim; /* node pruning bound: t widened by PRUNE_SLACK */
} best_hit;

static float widen_limit(float t)
{
    /* t + |t| * slack; inf stays inf, -inf stays -inf. */
    float r = t + fabsf(t) * PRUNE_SLACK;
    return r == r ? r : t;
}

static int ray_setup(const atrbvh_ray *ray, ray_pre *r)
{
    int k;
    double ad[3];
    if (!(ray->tmin == ray->tmin) || !(ray->tmax == ray->tmax))
        return 0;
    for (k = 0; k < 3; k++) {
        if (!isfinite(ray->origin[k]) || !isfinite(ray->dir[k]))
            return 0;
    }
    if (ray->dir[0] == 0.0f && ray->dir[1] == 0.0f && ray->dir[2] == 0.0f)
        return 0;
    if (!(ray->tmin <= ray->tmax))
        return 0;
    for (k = 0; k < 3; k++) {
        r->idir[k] = 1.0f / ray->dir[k]; /* +-inf for +-0 */
        r->orgd[k] = (double)ray->origin[k];
        /* finite for every nonzero float, subnormals included (a float
         * reciprocal overflows to inf below 2^-128) */
        r->idird[k] = 1.0 / (double)ray->dir[k];
        r->sign[k] = r->idir[k] < 0.0f;
        r->o[k] = (double)ray->origin[k];
        ad[k] = fabs((double)ray->dir[k]);
    }
    r->tmin = ray->tmin;
    r->tmax = ray->tmax;
    /* The largest component becomes z (the first on a tie). */
    r->kz = 0;
    if (ad[1] > ad[r->kz])
        r->kz = 1;
    if (ad[2] > ad[r->kz])
        r->kz = 2;
    r->kx = (r->kz + 1) % 3;
    r->ky = (r->kx + 1) % 3;
    if (ray->dir[r->kz] < 0.0f) { /* keep the winding */
        int s = r->kx;
        r->kx = r->ky;
        r->ky = s;
    }
    r->sx = (double)ray->dir[r->kx] / (double)ray->dir[r->kz];
    r->sy = (double)ray->dir[r->ky] / (double)ray->dir[r->kz];
    r->sz = 1.0 / (double)ray->dir[r->kz];
    return 1;
}

/* The slab distance (b - o) / d, in double: b - o cannot overflow (it
 * can in float near FLT_MAX) and 1/d is finite for every nonzero float
 * direction (in float it overflows for subnormal components, which made
 * boxes the ray crosses look infinitely far).  A zero direction gives
 * +-inf, or NaN when b == o (dropped by the comparisons below). */
static inline double slab_t(float b, const ray_pre *r, int k)
{
    return ((double)b - r->orgd[k]) * r->idird[k];
}

/* double to float for distances: beyond the float range is +-inf. */
static inline float dist_float(double d)
{
    if (d > (double)FLT_MAX)
        return INFINITY;
    if (d < -(double)FLT_MAX)
        return -INFINITY;
    return (float)d;
}

/* Conservative ray/node test.  Hit when the slab interval, far end widened,
 * meets [tlo, thi]; *tnear is where it starts.  In double the interval is
 * exact to a few units of 2^-53; widening by the float factor covers that
 * with a wide margin. */
static inline int node_hit(const atrbvh_node *n, const ray_pre *r, float tlo,
                           float thi, float *tnear)
{
    double lo = -INFINITY, hi = INFINITY;
    int k;
    for (k = 0; k < 3; k++) {
        float bn = r->sign[k] ? n->max[k] : n->min[k];
        float bf = r->sign[k] ? n->min[k] : n->max[k];
        double tn = slab_t(bn, r, k);
        double tf = slab_t(bf, r, k);
        /* NaN (0 * inf) fails the comparison and is dropped. */
        lo = tn > lo ? tn : lo;
        hi = tf < hi ? tf : hi;
    }
    hi = hi * (hi > 0.0 ? (double)WIDEN_UP : (double)WIDEN_DOWN);
    if ((double)tlo > lo)
        lo = tlo;
    if ((double)thi < hi)
        hi = thi;
    *tnear = dist_float(lo);
    return lo <= hi;
}

/* Exact ray/box primitive test: entry and exit distances. */
static inline int box_interval(const float *b, const ray_pre *r, float *t0,
                               float *t1)
{
    double lo = -INFINITY, hi = INFINITY;
    int k;
    for (k = 0; k < 3; k++) {
        float bn = r->sign[k] ? b[3 + k] : b[k];
        float bf = r->sign[k] ? b[k] : b[3 + k];
        double tn = slab_t(bn, r, k);
        double tf = slab_t(bf, r, k);
        lo = tn > lo ? tn : lo;
        hi = tf < hi ? tf : hi;
    }
    *t0 = dist_float(lo);
    *t1 = dist_float(hi);
    return lo <= hi;
}

static inline void load3(const void *p, float out[3])
{
    memcpy(out, p, 3 * sizeof(float));
}

/* The three vertices of triangle `prim`; 0 if an index is out of range. */
static inline int triangle_vertices(const atrbvh_geometry *g, uint32_t prim,
                                    float v[3][3])
{
    size_t vs = g->vertex_stride ? g->vertex_stride : 3 * sizeof(float);
    const char *base = (const char *)g->vertices;
    size_t id[3];
    int k;
    if (g->indices) {
        size_t is = g->index_stride ? g->index_stride : 3 * sizeof(uint32_t);
        uint32_t tri[3];
        memcpy(tri, (const char *)g->indices + (size_t)prim * is, sizeof tri);
        for (k = 0; k < 3; k++)
            id[k] = tri[k];
    } else {
        for (k = 0; k < 3; k++)
            id[k] = 3 * (size_t)prim + (size_t)k;
    }
    for (k = 0; k < 3; k++) {
        if (id[k] >= g->vertex_count)
            return 0;
        load3(base + id[k] * vs, v[k]);
    }
    return 1;
}

/* Whether distance t lies where the ray crosses the triangle's own box,
 * both ends widened a little (float rounding of t, a few ulps of the double
 * slab distances).  A true hit point lies in the triangle, so inside its
 * box: this only rejects hits the edge functions got wrong, which happens
 * for slivers mixing coordinates of wildly different magnitudes (1e36 next
 * to 1e-28: the double edge functions cancel).  It also makes the answer
 * independent of the tree: every node containing the triangle contains its
 * box, so a hit accepted here is never behind a node the traversal skips
 * (found by fuzz_build: tests/fuzz/corpus/build/regress-sliver-*). */
static inline int within_own_box(float v[3][3], const ray_pre *r, float t)
{
    double lo = -INFINITY, hi = INFINITY;
    int k;
    for (k = 0; k < 3; k++) {
        float mn = v[0][k], mx = v[0][k];
        double tn, tf;
        if (v[1][k] < mn)
            mn = v[1][k];
        if (v[2][k] < mn)
            mn = v[2][k];
        if (v[1][k] > mx)
            mx = v[1][k];
        if (v[2][k] > mx)
            mx = v[2][k];
        tn = slab_t(r->sign[k] ? mx : mn, r, k);
        tf = slab_t(r->sign[k] ? mn : mx, r, k);
        /* NaN (0 * inf: origin on the plane of a zero direction) drops */
        lo = tn > lo ? tn : lo;
        hi = tf < hi ? tf : hi;
    }
    hi = hi * (hi > 0.0 ? (double)WIDEN_UP : (double)WIDEN_DOWN);
    lo = lo * (lo > 0.0 ? 1.0 - OWN_BOX_SLACK : 1.0 + OWN_BOX_SLACK);
    return (double)t >= lo && (double)t <= hi;
}

/* Watertight ray/triangle test (Woop, Benthin, Wald 2013), in double.
 * On a hit with a finite t returns 1 with t and the barycentrics of
 * vertices 1 and 2. */
static inline int triangle_hit(float v[3][3], const ray_pre *r,
                               float *t, float *u, float *w)
{
    double a[3], b[3], c[3];
    double ax, ay, bx, by, cx, cy, e0, e1, e2, det, tt;
    int k;
    for (k = 0; k < 3; k++) {
        a[k] = (double)v[0][k] - r->o[k];
        b[k] = (double)v[1][k] - r->o[k];
        c[k] = (double)v[2][k] - r->o[k];
    }
    ax = a[r->kx] - r->sx * a[r->kz];
    ay = a[r->ky] - r->sy * a[r->kz];
    bx = b[r->kx] - r->sx * b[r->kz];
    by = b[r->ky] - r->sy * b[r->kz];
    cx = c[r->kx] - r->sx * c[r->kz];
    cy = c[r->ky] - r->sy * c[r->kz];
    /* e0 weighs vertex 0 (edge 1-2), e1 vertex 1, e2 vertex 2. */
    e0 = cx * by - cy * bx;
    e1 = ax * cy - ay * cx;
    e2 = bx * ay - by * ax;
    if ((e0 < 0.0 || e1 < 0.0 || e2 < 0.0) &&
        (e0 > 0.0 || e1 > 0.0 || e2 > 0.0))
        return 0;
    det = e0 + e1 + e2;
    if (det == 0.0 || !(det == det))
        return 0;
    tt = e0 * (r->sz * a[r->kz]);
    tt = tt + e1 * (r->sz * b[r->kz]);
    tt = tt + e2 * (r->sz * c[r->kz]);
    tt = tt / det;
    if (!(fabs(tt) <= (double)FLT_MAX))
        return 0;
    *t = (float)tt;
    if (!(fabsf(*t) <= FLT_MAX) || !within_own_box(v, r, *t))
        return 0;
    *u = (float)(e1 / det);
    *w = (float)(e2 / det);
    return 1;
}

/* Tests the primitives of a leaf.  Returns 1 when `any` and something was
 * hit (the query is over). */
static int leaf_test(const atrbvh_bvh *bvh, const atrbvh_geometry *g,
                     const atrbvh_node *n, const ray_pre *r, int any,
                     best_hit *best)
{
    uint32_t j;
    size_t first = n->index;
    if (first > bvh->prim_count || n->count > bvh->prim_count - first)
        return 0; /* never for a valid tree */
    for (j = 0; j < n->count; j++) {
        uint32_t prim = bvh->prim_indices[first + j];
        float t, u = 0.0f, v = 0.0f;
        if (prim >= g->primitive_count)
            continue;
        if (g->type == ATRBVH_GEOMETRY_TRIANGLES) {
            float vtx[3][3];
            if (!triangle_vertices(g, prim, vtx) ||
                !triangle_hit(vtx, r, &t, &u, &v))
                continue;
            if (any) {
                if (t >= r->tmin && t <= r->tmax)
                    return 1;
                continue;
            }
        } else {
            size_t bs = g->box_stride ? g->box_stride : 6 * sizeof(float);
            float box[6], t0, t1;
            memcpy(box, (const char *)g->boxes + (size_t)prim * bs, sizeof box);
            if (!box_interval(box, r, &t0, &t1))
                continue;
            if (any) {
                if ((t0 >= r->tmin && t0 <= r->tmax) ||
                    (t1 >= r->tmin && t1 <= r->tmax))
                    return 1;
                continue;
            }
            t = t0 > r->tmin ? t0 : t1;
            if (!(fabsf(t) <= FLT_MAX))
                continue;
        }
        if (t > r->tmin &&
            (t < best->t || (t == best->t && prim < best->prim))) {
            best->t = t;
            best->u = u;
            best->v = v;
            best->prim = prim;
            best->tlim = widen_limit(t);
        }
    }
    return 0;
}

/* The fallback for trees deeper than the stack: every leaf, in order. */
static int linear_pass(const atrbvh_bvh *bvh, const atrbvh_geometry *g,
                       const ray_pre *r, int any, best_hit *best,
                       float tlo)
{
    size_t i;
    for (i = 0; i < bvh->node_count; i++) {
        const atrbvh_node *n = &bvh->nodes[i];
        float tn;
        if (n->count == 0 || !node_hit(n, r, tlo, best->tlim, &tn))
            continue;
        if (leaf_test(bvh, g, n, r, any, best))
            return 1;
    }
    return 0;
}

typedef struct stack_entry {
    uint32_t node;
    float tnear;
} stack_entry;

/* Returns, for `any`, whether anything was hit; otherwise fills best. */
static int traverse(const atrbvh_bvh *bvh, const atrbvh_geometry *g,
                    const ray_pre *r, int any, best_hit *best)
{
    stack_entry stack[TRAVERSE_STACK];
    unsigned sp = 0;
    const atrbvh_node *nodes = bvh->nodes;
    size_t count = bvh->node_count;
    /* the lower end of the node interval, widened like the upper one */
    float tlo = r->tmin - fabsf(r->tmin) * PRUNE_SLACK;
    uint32_t cur = 0;
    float tn;

    if (!(tlo == tlo))
        tlo = r->tmin;
    best->t = r->tmax;
    best->u = best->v = 0.0f;
    best->prim = ATRBVH_NO_HIT;
    best->tlim = widen_limit(r->tmax);
    if (count == 0 || !node_hit(&nodes[0], r, tlo, best->tlim, &tn))
        return 0;
    for (;;) {
        const atrbvh_node *n = &nodes[cur];
        int descended = 0;
        if (n->count > 0) {
            if (leaf_test(bvh, g, n, r, any, best))
                return 1;
        } else {
            uint32_t l = cur + 1, rr = n->index;
            float nl, nr;
            int hl, hr;
            if (rr <= l || (size_t)rr >= count) /* never for a valid tree */
                goto pop;
            hl = node_hit(&nodes[l], r, tlo, best->tlim, &nl);
            hr = node_hit(&nodes[rr], r, tlo, best->tlim, &nr);
            if (hl && hr) {
                uint32_t near_node = l, far_node = rr;
                float far_t = nr;
                if (nr < nl) {
                    near_node = rr;
                    far_node = l;
                    far_t = nl;
                }
                if (sp == TRAVERSE_STACK) {
                    if (linear_pass(bvh, g, r, any, best, tlo))
                        return 1;
                    return any ? 0 : best->prim != ATRBVH_NO_HIT;
                }
                stack[sp].node = far_node;
                stack[sp].tnear = far_t;
                sp++;
                cur = near_node;
                descended = 1;
            } else if (hl) {
                cur = l;
                descended = 1;
            } else if (hr) {
                cur = rr;
                descended = 1;
            }
        }
        if (descended)
            continue;
    pop:
        for (;;) {
            if (sp == 0)
                return any ? 0 : best->prim != ATRBVH_NO_HIT;
            sp--;
            if (stack[sp].tnear <= best->tlim) {
                cur = stack[sp].node;
                break;
            }
        }
    }
}

static int geometry_usable(const atrbvh_geometry *g)
{
    if (g->type == ATRBVH_GEOMETRY_TRIANGLES)
        return g->vertices != NULL;
    if (g->type == ATRBVH_GEOMETRY_BOXES)
        return g->boxes != NULL;
    return 0;
}

int atrbvh_intersect(const atrbvh_bvh *bvh, const atrbvh_geometry *geometry,
                     const atrbvh_ray *ray, atrbvh_hit *hit)
{
    ray_pre r;
    best_hit best;
    if (hit) {
        hit->t = ray ? ray->tmax : 0.0f;
        hit->u = hit->v = 0.0f;
        hit->primitive = ATRBVH_NO_HIT;
    }
    if (!bvh || !geometry || !ray || !hit || !geometry_usable(geometry) ||
        !ray_setup(ray, &r))
        return 0;
    if (!traverse(bvh, geometry, &r, 0, &best))
        return 0;
    hit->t = best.t;
    hit->u = best.u;
    hit->v = best.v;
    hit->primitive = best.prim;
    return 1;
}

int atrbvh_occluded(const atrbvh_bvh *bvh, const atrbvh_geometry *geometry,
                    const atrbvh_ray *ray)
{
    ray_pre r;
    best_hit best;
    if (!bvh || !geometry || !ray || !geometry_usable(geometry) ||
        !ray_setup(ray, &r))
        return 0;
    return traverse(bvh, geometry, &r, 1, &best);
}

/* The checks both batch functions make. */
static atrbvh_status batch_check(const atrbvh_bvh *bvh,
                                 const atrbvh_geometry *g,
                                 const atrbvh_ray *rays, size_t count,
                                 const void *out, int threads,
                                 const char *fn, atrbvh_error *error)
{
    size_t needed;
    if (!bvh)
        return __atrbvh_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: bvh is NULL", fn);
    if (!g)
        return __atrbvh_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: geometry is NULL", fn);
    if (count > 0 && !rays)
        return __atrbvh_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: rays is NULL", fn);
    if (count > 0 && !out)
        return __atrbvh_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: the output array is NULL", fn);
    if (threads < 0)
        return __atrbvh_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: threads %d is negative", fn, threads);
    if (g->type != ATRBVH_GEOMETRY_TRIANGLES &&
        g->type != ATRBVH_GEOMETRY_BOXES)
        return __atrbvh_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: geometry type %d is not triangles or boxes",
                             fn, (int)g->type);
    if (!geometry_usable(g))
        return __atrbvh_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "%s: geometry.%s is NULL", fn,
                             g->type == ATRBVH_GEOMETRY_TRIANGLES ? "vertices"
                                                                  : "boxes");
    needed = bvh->stats.primitives + bvh->stats.invalid_skipped;
    if (needed < bvh->prim_count)
        needed = bvh->prim_count;
    if (g->primitive_count < needed)
        return __atrbvh_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                             (uint64_t)g->primitive_count,
                             "%s: the geometry has %lu primitives but the BVH "
                             "was built over %lu",
                             fn, (unsigned long)g->primitive_count,
                             (unsigned long)needed);
    return ATRBVH_OK;
}

atrbvh_status atrbvh_intersect_batch(const atrbvh_bvh *bvh,
                                     const atrbvh_geometry *geometry,
                                     const atrbvh_ray *rays, size_t count,
                                     atrbvh_hit *hits, int threads,
                                     atrbvh_error *error)
{
    long long i, n = (long long)count;
    atrbvh_status st;
    st = batch_check(bvh, geometry, rays, count, hits, threads,
                     "atrbvh_intersect_batch", error);
    if (st != ATRBVH_OK)
        return st;
    __atrbvh_clear_error(error);
#ifdef _OPENMP
    {
        int nt = __atrbvh_resolve_threads(threads);
#pragma omp parallel for schedule(dynamic, 64) num_threads(nt)
        for (i = 0; i < n; i++)
            atrbvh_intersect(bvh, geometry, &rays[i], &hits[i]);
    }
#else
    for (i = 0; i < n; i++)
        atrbvh_intersect(bvh, geometry, &rays[i], &hits[i]);
#endif
    return ATRBVH_OK;
}

atrbvh_status atrbvh_occluded_batch(const atrbvh_bvh *bvh,
                                    const atrbvh_geometry *geometry,
                                    const atrbvh_ray *rays, size_t count,
                                    uint8_t *occluded, int threads,
                                    atrbvh_error *error)
{
    long long i, n = (long long)count;
    atrbvh_status st;
    st = batch_check(bvh, geometry, rays, count, occluded, threads,
                     "atrbvh_occluded_batch", error);
    if (st != ATRBVH_OK)
        return st;
    __atrbvh_clear_error(error);
#ifdef _OPENMP
    {
        int nt = __atrbvh_resolve_threads(threads);
#pragma omp parallel for schedule(dynamic, 64) num_threads(nt)
        for (i = 0; i < n; i++)
            occluded[i] =
                (uint8_t)(atrbvh_occluded(bvh, geometry, &rays[i]) != 0);
    }
#else
    for (i = 0; i < n; i++)
        occluded[i] = (uint8_t)(atrbvh_occluded(bvh, geometry, &rays[i]) != 0);
#endif
    return ATRBVH_OK;
}
