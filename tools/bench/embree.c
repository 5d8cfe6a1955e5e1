/*
 * embree.c - Embree 3 beside atrbvh (see embree.h).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "embree.h"

#include "cli.h"

#include <stdlib.h>
#include <string.h>

const char *embree_quality_name(embree_quality q)
{
    return q == EMBREE_LOW      ? "embree_low"
           : q == EMBREE_MEDIUM ? "embree_medium"
           : q == EMBREE_HIGH   ? "embree_high"
                                : "embree_split";
}

#ifndef HAVE_EMBREE

int embree_available(void) { return 0; }
const char *embree_version(void) { return NULL; }
embree_ctx *embree_open(int threads)
{
    (void)threads;
    cli_error("not built with Embree");
    return NULL;
}
void embree_close(embree_ctx *ctx) { (void)ctx; }
int embree_build(embree_ctx *ctx, const scene *sc, embree_quality q,
                 unsigned max_leaf, double ci, double ct, int measure_memory,
                 int keep_tree, embree_build_result *res)
{
    (void)ctx, (void)sc, (void)q, (void)max_leaf, (void)ci, (void)ct;
    (void)measure_memory, (void)keep_tree;
    memset(res, 0, sizeof *res);
    cli_error("not built with Embree");
    return -1;
}
int embree_trace(embree_ctx *ctx, const scene *sc, embree_quality q,
                 const ray_set *rays, int threads, double ms[3],
                 double *commit_ms)
{
    (void)ctx, (void)sc, (void)q, (void)rays, (void)threads, (void)ms;
    (void)commit_ms;
    cli_error("not built with Embree");
    return -1;
}

#else

#include <embree3/rtcore.h>
#include <float.h>
#include <math.h>
#ifdef _OPENMP
#include <omp.h>
#endif

/* What an Embree user keeps between builds: the device, one BVH object
 * (its node allocator and temporary arrays are reused by the next
 * rtcBuildBVH) and the primitive array (refilled by every build, which
 * reorders it). */
struct embree_ctx {
    RTCDevice device;
    RTCBVH bvh;
    struct RTCBuildPrimitive *prims;
    size_t prims_cap;
    long current, peak; /* Embree's memory monitor, bytes */
};

int embree_available(void) { return 1; }

const char *embree_version(void) { return RTC_VERSION_STRING; }

static bool monitor(void *user, ssize_t bytes, bool post)
{
    embree_ctx *c = user;
    long now = __sync_add_and_fetch(&c->current, (long)bytes), p;
    (void)post;
    while ((p = c->peak) < now)
        if (__sync_bool_compare_and_swap(&c->peak, p, now))
            break;
    return true;
}

embree_ctx *embree_open(int threads)
{
    char config[64];
    embree_ctx *c = calloc(1, sizeof *c);
    if (!c) {
        cli_error("out of memory");
        return NULL;
    }
    if (threads > 0)
        snprintf(config, sizeof config, "threads=%d", threads);
    else
        config[0] = '\0';
    c->device = rtcNewDevice(config);
    if (!c->device) {
        cli_error("Embree: rtcNewDevice failed (error %d)",
                  (int)rtcGetDeviceError(NULL));
        free(c);
        return NULL;
    }
    c->bvh = rtcNewBVH(c->device);
    if (!c->bvh) {
        cli_error("Embree: rtcNewBVH failed (error %d)",
                  (int)rtcGetDeviceError(c->device));
        rtcReleaseDevice(c->device);
        free(c);
        return NULL;
    }
    return c;
}

void embree_close(embree_ctx *ctx)
{
    if (!ctx)
        return;
    rtcReleaseBVH(ctx->bvh);
    rtcReleaseDevice(ctx->device);
    free(ctx->prims);
    free(ctx);
}

/* The tree the callbacks make: an inner node has two children and their
 * boxes; a leaf its primitive ids. */
typedef struct enode {
    unsigned count; /* 0: inner */
    struct enode *child[2];
    float lo[2][3], hi[2][3];
    uint32_t prim[1]; /* count of them (allocated longer) */
} enode;

static void *create_node(RTCThreadLocalAllocator alloc, unsigned child_count,
                         void *user)
{
    enode *n = rtcThreadLocalAlloc(alloc, sizeof *n, 16);
    (void)user;
    (void)child_count; /* maxBranchingFactor 2 */
    n->count = 0;
    n->child[0] = n->child[1] = NULL;
    return n;
}

static void set_children(void *node, void **children, unsigned count,
                         void *user)
{
    enode *n = node;
    unsigned k;
    (void)user;
    for (k = 0; k < count && k < 2; k++)
        n->child[k] = children[k];
}

static void set_bounds(void *node, const struct RTCBounds **b, unsigned count,
                       void *user)
{
    enode *n = node;
    unsigned k;
    (void)user;
    for (k = 0; k < count && k < 2; k++) {
        n->lo[k][0] = b[k]->lower_x;
        n->lo[k][1] = b[k]->lower_y;
        n->lo[k][2] = b[k]->lower_z;
        n->hi[k][0] = b[k]->upper_x;
        n->hi[k][1] = b[k]->upper_y;
        n->hi[k][2] = b[k]->upper_z;
    }
}

static void *create_leaf(RTCThreadLocalAllocator alloc,
                         const struct RTCBuildPrimitive *prims, size_t count,
                         void *user)
{
    enode *n = rtcThreadLocalAlloc(
        alloc, sizeof *n + (count ? count - 1 : 0) * sizeof(uint32_t), 16);
    size_t k;
    (void)user;
    n->count = (unsigned)count;
    for (k = 0; k < count; k++)
        n->prim[k] = prims[k].primID;
    return n;
}

/* Embree's spatial split callback (EMBREE_SPLIT): the parts of the
 * triangle on each side of the plane x[dim] = pos, each clipped to the
 * reference's box.  The triangle's vertices and its edges' crossings of
 * the plane are gathered per side in double and rounded outward to float,
 * so each part's box holds that part of the triangle (a side the triangle
 * does not reach gets a point on the plane inside the reference's box: it
 * holds nothing and costs only a test). */
static float f_down(double d)
{
    float f = (float)d;
    return (double)f > d ? nextafterf(f, -FLT_MAX) : f;
}

static float f_up(double d)
{
    float f = (float)d;
    return (double)f < d ? nextafterf(f, FLT_MAX) : f;
}

static void split_prim(const struct RTCBuildPrimitive *prim, unsigned dim,
                       float pos, struct RTCBounds *left,
                       struct RTCBounds *right, void *user)
{
    const scene *sc = user;
    const uint32_t *t = sc->indices + 3 * (size_t)prim->primID;
    const float plo[3] = {prim->lower_x, prim->lower_y, prim->lower_z};
    const float phi[3] = {prim->upper_x, prim->upper_y, prim->upper_z};
    double v[3][3], lo[2][3], hi[2][3];
    int side, k, e;
    for (e = 0; e < 3; e++)
        for (k = 0; k < 3; k++)
            v[e][k] = sc->vertices[3 * (size_t)t[e] + (size_t)k];
    for (side = 0; side < 2; side++)
        for (k = 0; k < 3; k++) {
            lo[side][k] = DBL_MAX;
            hi[side][k] = -DBL_MAX;
        }
#define ADD(s, p)                                                              \
    for (k = 0; k < 3; k++) {                                                  \
        lo[s][k] = (p)[k] < lo[s][k] ? (p)[k] : lo[s][k];                      \
        hi[s][k] = (p)[k] > hi[s][k] ? (p)[k] : hi[s][k];                      \
    }
    for (e = 0; e < 3; e++) {
        const double *a = v[e], *b = v[(e + 1) % 3];
        if (a[dim] <= pos)
            ADD(0, a)
        if (a[dim] >= pos)
            ADD(1, a)
        if ((a[dim] < pos && b[dim] > pos) || (a[dim] > pos && b[dim] < pos)) {
            const double f = (pos - a[dim]) / (b[dim] - a[dim]);
            double x[3];
            for (k = 0; k < 3; k++)
                x[k] = a[k] + (b[k] - a[k]) * f;
            x[dim] = pos;
            ADD(0, x)
            ADD(1, x)
        }
    }
#undef ADD
    for (side = 0; side < 2; side++) {
        struct RTCBounds *o = side ? right : left;
        float ol[3], oh[3];
        for (k = 0; k < 3; k++) {
            float l = f_down(lo[side][k]), h = f_up(hi[side][k]);
            if (side == 0 && (unsigned)k == dim && h > pos)
                h = pos;
            if (side == 1 && (unsigned)k == dim && l < pos)
                l = pos;
            ol[k] = l > plo[k] ? l : plo[k];
            oh[k] = h < phi[k] ? h : phi[k];
        }
        if (!(ol[0] <= oh[0] && ol[1] <= oh[1] && ol[2] <= oh[2]))
            for (k = 0; k < 3; k++) {
                float c = (unsigned)k == dim ? pos
                                             : plo[k] + 0.5f * (phi[k] - plo[k]);
                ol[k] = oh[k] = c;
            }
        o->lower_x = ol[0];
        o->lower_y = ol[1];
        o->lower_z = ol[2];
        o->upper_x = oh[0];
        o->upper_y = oh[1];
        o->upper_z = oh[2];
        o->align0 = o->align1 = 0.0f;
    }
}

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)v;
    p[1] = (unsigned char)(v >> 8);
    p[2] = (unsigned char)(v >> 16);
    p[3] = (unsigned char)(v >> 24);
}

static void put64(unsigned char *p, uint64_t v)
{
    put32(p, (uint32_t)v);
    put32(p + 4, (uint32_t)(v >> 32));
}

static void putf32(unsigned char *p, float f)
{
    uint32_t v;
    memcpy(&v, &f, 4);
    put32(p, v);
}

static void putf64(unsigned char *p, double d)
{
    uint64_t v;
    memcpy(&v, &d, 8);
    put64(p, v);
}

static uint32_t crc32_ieee(const unsigned char *p, size_t n)
{
    static uint32_t table[256];
    static int ready;
    uint32_t c = 0xffffffffu;
    size_t i;
    if (!ready) {
        uint32_t k, j;
        for (k = 0; k < 256; k++) {
            uint32_t v = k;
            for (j = 0; j < 8; j++)
                v = v & 1 ? 0xedb88320u ^ (v >> 1) : v >> 1;
            table[k] = v;
        }
        ready = 1;
    }
    for (i = 0; i < n; i++)
        c = table[(c ^ p[i]) & 0xff] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

typedef struct work {
    const enode *n;
    float lo[3], hi[3];
    size_t patch; /* the parent whose index is this node's position */
    int is_right;
} work;

/* Depth-first layout (left child next, right child at `index`), written
 * straight into the atrbvh(5) file format and loaded: the library checks
 * the structure. */
static int convert(const enode *root, const float rlo[3], const float rhi[3],
                   size_t prims, size_t refs_cap, double ci, double ct,
                   atrbvh_bvh **out, size_t *refs)
{
    size_t cap = 2 * refs_cap, n = 0, p = 0, sp = 0, size, k;
    atrbvh_node *nodes = malloc(cap * sizeof *nodes);
    uint32_t *ids = malloc(refs_cap * sizeof *ids);
    int repeated = 0;
    work *stack = malloc((cap + 2) * sizeof *stack);
    unsigned char *buf = NULL, *q;
    atrbvh_error e;
    int rc = -1;
    if (!nodes || !ids || !stack) {
        cli_error("out of memory converting an Embree tree");
        goto done;
    }
    stack[sp].n = root;
    memcpy(stack[sp].lo, rlo, sizeof stack[sp].lo);
    memcpy(stack[sp].hi, rhi, sizeof stack[sp].hi);
    stack[sp].is_right = 0;
    sp++;
    while (sp > 0) {
        work w = stack[--sp];
        atrbvh_node *nd;
        if (n >= cap) {
            cli_error("Embree tree: more nodes than expected");
            goto done;
        }
        nd = &nodes[n];
        memcpy(nd->min, w.lo, sizeof nd->min);
        memcpy(nd->max, w.hi, sizeof nd->max);
        if (w.is_right)
            nodes[w.patch].index = (uint32_t)n;
        if (w.n->count) {
            unsigned j, m;
            if (p + w.n->count > refs_cap) {
                cli_error("Embree tree: more references than its array");
                goto done;
            }
            nd->index = (uint32_t)p;
            /* Two parts of one split triangle in one leaf (the library
             * refuses that): the first is kept. */
            for (j = 0; j < w.n->count; j++) {
                for (m = 0; m < j && w.n->prim[m] != w.n->prim[j]; m++)
                    ;
                if (m == j)
                    ids[p++] = w.n->prim[j];
            }
            nd->count = (uint32_t)(p - nd->index);
            repeated |= p - nd->index != w.n->count;
        } else {
            int c;
            nd->index = 0;
            nd->count = 0;
            for (c = 1; c >= 0; c--) { /* right first: left is popped next */
                work *x = &stack[sp++];
                x->n = w.n->child[c];
                memcpy(x->lo, w.n->lo[c], sizeof x->lo);
                memcpy(x->hi, w.n->hi[c], sizeof x->hi);
                x->patch = n;
                x->is_right = c == 1;
            }
        }
        n++;
    }
    if (p < prims || (p > prims && refs_cap == prims)) {
        cli_error("Embree tree: %zu references to %zu primitives", p, prims);
        goto done;
    }
    repeated |= p > prims; /* every triangle is listed (the loader checks) */
    size = 96 + 32 * n + 4 * p + 4;
    buf = calloc(1, size);
    if (!buf) {
        cli_error("out of memory converting an Embree tree");
        goto done;
    }
    memcpy(buf, "ATRBVH\0\n", 8);
    put32(buf + 8, repeated ? 2 : 1); /* atrbvh(5): version 2, SPLIT */
    put32(buf + 12, 96);
    put32(buf + 16, repeated ? 1 : 0);
    put64(buf + 32, n);
    put64(buf + 40, p);
    put64(buf + 48, prims);
    putf64(buf + 56, ci);
    putf64(buf + 64, ct);
    putf64(buf + 72, atrbvh_sah(nodes, n, ci, ct));
    for (k = 0, q = buf + 96; k < n; k++, q += 32) {
        int a;
        for (a = 0; a < 3; a++) {
            putf32(q + 4 * a, nodes[k].min[a]);
            putf32(q + 12 + 4 * a, nodes[k].max[a]);
        }
        put32(q + 24, nodes[k].index);
        put32(q + 28, nodes[k].count);
    }
    for (k = 0; k < p; k++, q += 4)
        put32(q, ids[k]);
    put32(q, crc32_ieee(buf, size - 4));
    memset(&e, 0, sizeof e);
    if (atrbvh_load_memory(buf, size, out, &e) != ATRBVH_OK) {
        cli_error("Embree tree: %s", e.text);
        goto done;
    }
    *refs = p;
    rc = 0;
done:
    free(nodes);
    free(ids);
    free(stack);
    free(buf);
    return rc;
}

static enum RTCBuildQuality rtc_quality(embree_quality q)
{
    return q == EMBREE_LOW ? RTC_BUILD_QUALITY_LOW
           : q == EMBREE_MEDIUM ? RTC_BUILD_QUALITY_MEDIUM
                                : RTC_BUILD_QUALITY_HIGH; /* and SPLIT */
}

int embree_build(embree_ctx *ctx, const scene *sc, embree_quality q,
                 unsigned max_leaf, double ci, double ct, int measure_memory,
                 int keep_tree, embree_build_result *res)
{
    size_t n = sc->triangle_count, i, cap;
    struct RTCBuildPrimitive *prims;
    struct RTCBuildArguments args;
    RTCBVH bvh = ctx->bvh;
    enode *root;
    float rlo[3] = {FLT_MAX, FLT_MAX, FLT_MAX};
    float rhi[3] = {-FLT_MAX, -FLT_MAX, -FLT_MAX};
    double t0, t1;
    int rc;
    memset(res, 0, sizeof *res);
    if (n == 0 || n > UINT32_MAX) {
        cli_error("Embree: %zu triangles", n);
        return -1;
    }
    /* Spatial splits need room for the extra references. */
    cap = q == EMBREE_SPLIT ? n + (size_t)((double)n * EMBREE_SPLIT_BUDGET)
                            : n;
    if (cap > ctx->prims_cap) {
        free(ctx->prims);
        ctx->prims_cap = 0;
        ctx->prims = cap <= SIZE_MAX / sizeof *prims
                         ? malloc(cap * sizeof *prims) : NULL;
        if (!ctx->prims) {
            cli_error("out of memory for %zu Embree primitives", cap);
            return -1;
        }
        ctx->prims_cap = cap;
    }
    prims = ctx->prims;
    /* The memory monitor is a callback on every allocation: only on a
     * build whose time is not taken, into a new BVH object (a used one
     * would reuse its blocks and hide them from the monitor). */
    if (measure_memory) {
        RTCBVH fresh = rtcNewBVH(ctx->device);
        if (!fresh) {
            cli_error("Embree: rtcNewBVH failed (error %d)",
                      (int)rtcGetDeviceError(ctx->device));
            return -1;
        }
        rtcReleaseBVH(ctx->bvh);
        bvh = ctx->bvh = fresh;
    }
    ctx->current = ctx->peak = 0;
    rtcSetDeviceMemoryMonitorFunction(ctx->device,
                                      measure_memory ? monitor : NULL,
                                      measure_memory ? ctx : NULL);
    t0 = cli_now_ms();
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for (i = 0; i < n; i++) {
        const uint32_t *t = sc->indices + 3 * i;
        const float *a = sc->vertices + 3 * (size_t)t[0];
        const float *b = sc->vertices + 3 * (size_t)t[1];
        const float *c = sc->vertices + 3 * (size_t)t[2];
        float lo[3], hi[3];
        int k;
        for (k = 0; k < 3; k++) {
            lo[k] = a[k] < b[k] ? a[k] : b[k];
            lo[k] = c[k] < lo[k] ? c[k] : lo[k];
            hi[k] = a[k] > b[k] ? a[k] : b[k];
            hi[k] = c[k] > hi[k] ? c[k] : hi[k];
        }
        prims[i].lower_x = lo[0];
        prims[i].lower_y = lo[1];
        prims[i].lower_z = lo[2];
        prims[i].geomID = 0;
        prims[i].upper_x = hi[0];
        prims[i].upper_y = hi[1];
        prims[i].upper_z = hi[2];
        prims[i].primID = (unsigned)i;
    }
    args = rtcDefaultBuildArguments();
    args.byteSize = sizeof args;
    args.buildFlags = RTC_BUILD_FLAG_NONE;
    args.buildQuality = rtc_quality(q);
    args.maxBranchingFactor = 2;
    args.maxDepth = 1024;
    args.sahBlockSize = 1;
    args.minLeafSize = 1;
    args.maxLeafSize = max_leaf ? max_leaf : 1;
    args.traversalCost = (float)ci;
    args.intersectionCost = (float)ct;
    args.bvh = bvh;
    args.primitives = prims;
    args.primitiveCount = n;
    args.primitiveArrayCapacity = cap; /* n: no room, no spatial splits */
    args.createNode = create_node;
    args.setNodeChildren = set_children;
    args.setNodeBounds = set_bounds;
    args.createLeaf = create_leaf;
    args.splitPrimitive = q == EMBREE_SPLIT ? split_prim : NULL;
    args.buildProgress = NULL;
    args.userPtr = (void *)sc;
    root = rtcBuildBVH(&args);
    t1 = cli_now_ms();
    res->build_ms = t1 - t0;
    if (measure_memory) {
        res->peak_bytes =
            n * sizeof *prims + (size_t)(ctx->peak > 0 ? ctx->peak : 0);
        rtcSetDeviceMemoryMonitorFunction(ctx->device, NULL, NULL);
    }
    if (!root) {
        cli_error("Embree: rtcBuildBVH failed (error %d)",
                  (int)rtcGetDeviceError(ctx->device));
        return -1;
    }
    if (!keep_tree)
        return 0;
    /* The root's box: the union of every triangle's (the build reorders
     * the primitive array and, with splits, leaves parts of triangles in
     * it). */
    for (i = 0; i < 3 * n; i++) {
        const float *v = sc->vertices + 3 * (size_t)sc->indices[i];
        int k;
        for (k = 0; k < 3; k++) {
            if (v[k] < rlo[k])
                rlo[k] = v[k];
            if (v[k] > rhi[k])
                rhi[k] = v[k];
        }
    }
    rc = convert(root, rlo, rhi, n, cap, ci, ct, &res->bvh,
                 &res->references);
    res->convert_ms = cli_now_ms() - t1;
    return rc;
}

int embree_trace(embree_ctx *ctx, const scene *sc, embree_quality q,
                 const ray_set *rays, int threads, double ms[3],
                 double *commit_ms)
{
    RTCScene s;
    RTCGeometry g;
    float *vb;
    unsigned *ib;
    double t0;
    int kind;
    (void)threads;
    s = rtcNewScene(ctx->device);
    rtcSetSceneBuildQuality(s, rtc_quality(q));
    g = rtcNewGeometry(ctx->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    vb = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                 RTC_FORMAT_FLOAT3, 12, sc->vertex_count);
    ib = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0,
                                 RTC_FORMAT_UINT3, 12, sc->triangle_count);
    if (!vb || !ib) {
        cli_error("Embree: no memory for the scene's buffers");
        rtcReleaseGeometry(g);
        rtcReleaseScene(s);
        return -1;
    }
    memcpy(vb, sc->vertices, sc->vertex_count * 12);
    memcpy(ib, sc->indices, sc->triangle_count * 12);
    rtcSetGeometryBuildQuality(g, rtc_quality(q));
    rtcCommitGeometry(g);
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
    t0 = cli_now_ms();
    rtcCommitScene(s);
    *commit_ms = cli_now_ms() - t0;
    if (rtcGetDeviceError(ctx->device) != RTC_ERROR_NONE) {
        cli_error("Embree: rtcCommitScene failed");
        rtcReleaseScene(s);
        return -1;
    }
    for (kind = 0; kind < 3; kind++) {
        const atrbvh_ray *r = kind == 0   ? rays->primary
                              : kind == 1 ? rays->ao
                                          : rays->diffuse;
        long n = (long)(kind == 0   ? rays->n_primary
                        : kind == 1 ? rays->n_ao
                                    : rays->n_diffuse),
             i;
        long hits = 0;
        t0 = cli_now_ms();
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1024) reduction(+ : hits) \
    num_threads(threads > 0 ? threads : omp_get_max_threads())
#endif
        for (i = 0; i < n; i++) {
            struct RTCIntersectContext c;
            struct RTCRayHit rh;
            rtcInitIntersectContext(&c);
            rh.ray.org_x = r[i].origin[0];
            rh.ray.org_y = r[i].origin[1];
            rh.ray.org_z = r[i].origin[2];
            rh.ray.dir_x = r[i].dir[0];
            rh.ray.dir_y = r[i].dir[1];
            rh.ray.dir_z = r[i].dir[2];
            rh.ray.tnear = r[i].tmin;
            rh.ray.tfar = r[i].tmax;
            rh.ray.time = 0.0f;
            rh.ray.mask = 0xffffffffu;
            rh.ray.id = 0;
            rh.ray.flags = 0;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            if (kind == 1) {
                rtcOccluded1(s, &c, &rh.ray);
                hits += rh.ray.tfar < 0.0f;
            } else {
                rtcIntersect1(s, &c, &rh);
                hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            }
        }
        ms[kind] = cli_now_ms() - t0;
        (void)hits;
    }
    rtcReleaseScene(s);
    return 0;
}
#endif
