/*
 * fuzz_build.c - libFuzzer harness for atrbvh_build on arbitrary input.
 *
 * The first 8 bytes choose the geometry kind (unindexed triangles, indexed
 * triangles, boxes), the method, collapse, the largest leaf, skip_invalid,
 * treelet size and rounds; the rest are raw floats (any bit pattern: NaN,
 * Inf, subnormals) and, for indexed triangles, indices taken modulo a
 * little more than the vertex count (so some are out of range).  A build
 * must either succeed with a tree that passes tu_check_bvh (the tests'
 * independent checker) and answers rays exactly like a brute-force scan
 * over one-primitive BVHs, or fail with a clean status and message.
 */
#include "fuzz_common.h"
#include "testutil.h"

#define MAX_PRIMS 64

static void brute(atrbvh_bvh *const *singles, const atrbvh_geometry *sg,
                  size_t n, const atrbvh_ray *r, atrbvh_hit *best, int *occ)
{
    size_t i;
    best->primitive = ATRBVH_NO_HIT;
    best->t = INFINITY;
    *occ = 0;
    for (i = 0; i < n; i++) {
        atrbvh_hit h;
        if (!singles[i])
            continue;
        if (atrbvh_occluded(singles[i], &sg[i], r))
            *occ = 1;
        if (atrbvh_intersect(singles[i], &sg[i], r, &h) &&
            (best->primitive == ATRBVH_NO_HIT || h.t < best->t)) {
            *best = h;
            best->primitive = (uint32_t)i;
        }
    }
}

/* The uncounted batch calls trace an 8-wide copy of the tree, and over
 * triangles a copy of the leaves' vertices made by a batch of 1024 rays or
 * more (lib/traverse.c): the same rays, repeated to that size, must give
 * the single-ray calls' answers bit for bit. */
#define BATCH_RAYS 1024
static void check_batches(const atrbvh_bvh *b, const atrbvh_geometry *g,
                          const atrbvh_ray *rays, const atrbvh_hit *hits,
                          const int *occs, size_t nr)
{
    atrbvh_ray *br = malloc(BATCH_RAYS * sizeof *br);
    atrbvh_hit *bh = malloc(BATCH_RAYS * sizeof *bh);
    uint8_t *bo = malloc(BATCH_RAYS);
    atrbvh_error e;
    size_t j;
    if (!br || !bh || !bo) {
        free(br);
        free(bh);
        free(bo);
        return;
    }
    for (j = 0; j < BATCH_RAYS; j++)
        br[j] = rays[j % nr];
    FUZZ_CHECK(atrbvh_intersect_batch(b, g, br, BATCH_RAYS, bh, 1, &e) ==
                   ATRBVH_OK,
               "intersect_batch: %s", e.text);
    FUZZ_CHECK(atrbvh_occluded_batch(b, g, br, BATCH_RAYS, bo, 1, &e) ==
                   ATRBVH_OK,
               "occluded_batch: %s", e.text);
    for (j = 0; j < BATCH_RAYS; j++) {
        const atrbvh_hit *want = &hits[j % nr];
        FUZZ_CHECK(bh[j].primitive == want->primitive,
                   "batch ray %lu: primitive %u, single ray %u",
                   (unsigned long)j, bh[j].primitive, want->primitive);
        if (want->primitive != ATRBVH_NO_HIT)
            FUZZ_CHECK(memcmp(&bh[j].t, &want->t, sizeof want->t) == 0 &&
                           memcmp(&bh[j].u, &want->u, sizeof want->u) == 0 &&
                           memcmp(&bh[j].v, &want->v, sizeof want->v) == 0,
                       "batch ray %lu: t, u, v %a %a %a, single ray %a %a %a",
                       (unsigned long)j, (double)bh[j].t, (double)bh[j].u,
                       (double)bh[j].v, (double)want->t, (double)want->u,
                       (double)want->v);
        FUZZ_CHECK((bo[j] != 0) == (occs[j % nr] != 0),
                   "batch ray %lu: occluded %d, single ray %d",
                   (unsigned long)j, bo[j], occs[j % nr]);
    }
    free(br);
    free(bh);
    free(bo);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    float f[MAX_PRIMS * 9 + 3];
    uint32_t idx[MAX_PRIMS * 3];
    size_t nf, n, i, nv = 0;
    atrbvh_geometry g, sg[MAX_PRIMS];
    atrbvh_build_options o;
    atrbvh_bvh *b = NULL, *singles[MAX_PRIMS];
    atrbvh_error e;
    atrbvh_status st;
    char msg[256];
    int kind;
    if (size < 8)
        return 0;
    kind = data[0] % 3;
    atrbvh_build_options_init(&o);
    o.method = (atrbvh_method)(data[1] % 3);
    o.collapse = data[2] & 1;
    o.max_leaf_size = o.collapse ? (unsigned)(data[2] >> 1) % 5 : 0;
    o.skip_invalid = data[3] & 1;
    o.threads = 1;
    if (o.method == ATRBVH_METHOD_TRBVH)
        o.treelet_size = data[4] % 9 ? 3 + (unsigned)data[4] % 8 : 0;
    else if (o.method == ATRBVH_METHOD_ATRBVH)
        o.treelet_size = data[4] % 31 ? 3 + (unsigned)data[4] % 30 : 0;
    o.rounds = (unsigned)data[5] % 5;
    data += 8;
    size -= 8;
    nf = size / 4 < sizeof f / sizeof *f ? size / 4 : sizeof f / sizeof *f;
    for (i = 0; i < nf; i++)
        memcpy(&f[i], data + 4 * i, 4);
    data += 4 * nf;
    size -= 4 * nf;
    if (kind == 0) {
        n = nf / 9;
        g = atrbvh_geometry_triangles(f, 3 * n, NULL, n);
    } else if (kind == 1) {
        nv = nf / 3;
        n = size / 3 < MAX_PRIMS ? size / 3 : MAX_PRIMS;
        for (i = 0; i < 3 * n; i++)
            idx[i] = (uint32_t)(data[i] % (nv + 2));
        g = atrbvh_geometry_triangles(f, nv, idx, n);
    } else {
        n = nf / 6;
        g = atrbvh_geometry_boxes(f, n);
    }
    if (n > MAX_PRIMS)
        n = MAX_PRIMS;
    g.primitive_count = n;
    st = atrbvh_build(&g, &o, &b, &e);
    if (st != ATRBVH_OK) {
        FUZZ_CHECK(b == NULL, "failed but returned a BVH");
        FUZZ_CHECK(st == ATRBVH_ERR_NO_PRIMITIVES ||
                       st == ATRBVH_ERR_NONFINITE ||
                       st == ATRBVH_ERR_INDEX_RANGE ||
                       st == ATRBVH_ERR_INVALID_ARGUMENT,
                   "status %d: %s", (int)st, e.text);
        FUZZ_CHECK(e.text[0] != '\0', "no message");
        if (st == ATRBVH_ERR_INVALID_ARGUMENT && n > 0)
            FUZZ_CHECK(strstr(e.text, "min greater than max") ||
                           strstr(e.text, "vertices") ||
                           strstr(e.text, "treelet") ||
                           strstr(e.text, "gamma"),
                       "unexpected: %s", e.text);
        return 0;
    }
    FUZZ_CHECK(tu_check_bvh(b, &g, msg, sizeof msg), "%s", msg);
    {
        /* every primitive alone, then rays between random points of the
         * input (finite ones) compared with the brute force */
        atrbvh_build_options one;
        size_t r, nr = 0;
        atrbvh_ray rays[8];
        atrbvh_hit rhits[8];
        int roccs[8];
        atrbvh_build_options_init(&one);
        one.method = ATRBVH_METHOD_LBVH;
        one.threads = 1;
        one.skip_invalid = 1;
        for (i = 0; i < n; i++) {
            atrbvh_error e1;
            sg[i] = g;
            sg[i].primitive_count = 1;
            if (kind == 0) {
                sg[i].vertices = f + 9 * i;
                sg[i].vertex_count = 3;
            } else if (kind == 1) {
                sg[i].indices = idx + 3 * i;
            } else {
                sg[i].boxes = f + 6 * i;
            }
            singles[i] = NULL;
            if (atrbvh_build(&sg[i], &one, &singles[i], &e1) != ATRBVH_OK)
                singles[i] = NULL; /* a non-finite primitive: skipped */
        }
        for (r = 0; r + 6 <= nf && r < 48; r += 6) {
            atrbvh_ray ray;
            atrbvh_hit h, bh;
            int k, hit, occ, bocc, ok = 1;
            for (k = 0; k < 3; k++) {
                ray.origin[k] = f[r + k];
                ray.dir[k] = f[r + 3 + k] - f[r + k];
                ok &= isfinite(ray.origin[k]) && isfinite(ray.dir[k]);
            }
            if (!ok)
                continue;
            ray.tmin = 0;
            ray.tmax = INFINITY;
            hit = atrbvh_intersect(b, &g, &ray, &h);
            occ = atrbvh_occluded(b, &g, &ray);
            brute(singles, sg, n, &ray, &bh, &bocc);
            FUZZ_CHECK(hit == (bh.primitive != ATRBVH_NO_HIT),
                       "hit %d vs brute force %u", hit, bh.primitive);
            FUZZ_CHECK(occ == bocc, "occluded %d vs brute force %d", occ,
                       bocc);
            if (hit)
                FUZZ_CHECK(h.primitive == bh.primitive &&
                               memcmp(&h.t, &bh.t, sizeof h.t) == 0,
                           "hit %u at %g, brute force %u at %g", h.primitive,
                           (double)h.t, bh.primitive, (double)bh.t);
            if (nr < 8) {
                rays[nr] = ray;
                rhits[nr] = h;
                if (!hit)
                    rhits[nr].primitive = ATRBVH_NO_HIT;
                roccs[nr] = occ;
                nr++;
            }
        }
        /* a quarter of the inputs (by length): the batches of 1024 rays
         * cost about ten times the rest of an input */
        if (nr > 0 && size % 4 == 0)
            check_batches(b, &g, rays, rhits, roccs, nr);
        for (i = 0; i < n; i++)
            atrbvh_bvh_free(singles[i]);
    }
    atrbvh_bvh_free(b);
    return 0;
}
