/*
 * fuzz_build.c - libFuzzer harness for atrbvh_build on arbitrary input.
 *
 * The first 8 bytes choose the geometry kind (unindexed triangles, indexed
 * triangles, boxes), the method, collapse, the largest leaf, skip_invalid,
 * treelet size and rounds, and triangle splitting (split_budget and
 * split_rule, set only when bit 6 of byte 6 is: see split_options); the
 * rest are raw floats (any bit pattern: NaN, Inf, subnormals) and, for
 * indexed triangles, indices taken modulo a little more than the vertex
 * count (so some are out of range).  A build must either succeed with a
 * tree that passes tu_check_bvh, or tu_check_bvh_split with splitting on
 * (the tests' independent checkers), saves and loads back equal, and
 * answers rays exactly like a brute-force scan over one-primitive BVHs
 * (over split triangles, a ray with a roundoff hit outside the pieces'
 * boxes only one-sidedly: unseen_hit), or fail with a clean status and
 * message: an invalid split_budget or split_rule is
 * ATRBVH_ERR_INVALID_ARGUMENT whatever the geometry.
 */
#include "fuzz_common.h"
#include "testutil.h"

#include <float.h>
#include <limits.h>

#define MAX_PRIMS 64

/* Byte 6: bit 6 turns the splitting options on (the seeds from before
 * them have it clear); its low 6 bits pick the budget: below 16 from the
 * table (the edges, and invalid values: negative, NaN, infinite, above 4,
 * the double just above 4), else 0 to 4 in 47 steps.  Byte 7: the rule,
 * valid (0, 1, 2) half the time, else out of range. */
static void split_options(const uint8_t *head, atrbvh_build_options *o)
{
    static const double budgets[16] = {0.0,  0.05,      0.1,  0.25,
                                       0.5,  1.0,       2.0,  4.0,
                                       -0.1, NAN,       4.5,  -0.0,
                                       3.0,  -INFINITY, INFINITY,
                                       4.0 + 4.0 * DBL_EPSILON};
    static const int rules[8] = {ATRBVH_SPLIT_TREE, ATRBVH_SPLIT_PRIORITY,
                                 ATRBVH_SPLIT_SAH,  ATRBVH_SPLIT_SAH,
                                 3,                 -1,
                                 INT_MAX,           INT_MIN};
    unsigned s = head[6] & 0x3Fu;
    if (!(head[6] & 0x40u))
        return;
    o->split_budget = s < 16 ? budgets[s] : (double)(s - 16) * 4.0 / 47.0;
    o->split_rule = rules[head[7] % 8];
}

/* Saved to memory and loaded back: the same tree, which passes the same
 * checker; a tree with repeated references is format version 2 (version 1
 * rejects them).  Returns the version written (0: out of memory). */
static unsigned round_trip(const atrbvh_bvh *b, const atrbvh_geometry *g,
                           int split, double budget)
{
    void *mem = NULL;
    size_t size, np;
    atrbvh_bvh *l = NULL;
    atrbvh_stats st;
    atrbvh_error e;
    char msg[256];
    unsigned version;
    atrbvh_status s = atrbvh_save_memory(b, &mem, &size, &e);
    if (s == ATRBVH_ERR_NOMEM)
        return 0; /* -malloc_limit_mb: allocator_may_return_null */
    FUZZ_CHECK(s == ATRBVH_OK && size >= 12, "save_memory: %s", e.text);
    atrbvh_bvh_stats(b, &st);
    (void)atrbvh_bvh_primitive_indices(b, &np);
    version = tu_rd32((const unsigned char *)mem + 8);
    FUZZ_CHECK(version == 2 || (version == 1 && np == st.primitives),
               "format version %u for %lu references of %lu primitives",
               version, (unsigned long)np, (unsigned long)st.primitives);
    s = atrbvh_load_memory(mem, size, &l, &e);
    atrbvh_free(mem);
    if (s == ATRBVH_ERR_NOMEM)
        return 0;
    FUZZ_CHECK(s == ATRBVH_OK, "load_memory: %s", e.text);
    FUZZ_CHECK(tu_same_bvh(b, l, msg, sizeof msg), "loaded: %s", msg);
    FUZZ_CHECK(split ? tu_check_bvh_split(l, g, budget, msg, sizeof msg)
                     : tu_check_bvh(l, g, msg, sizeof msg),
               "loaded: %s", msg);
    atrbvh_bvh_free(l);
    return version;
}

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

/* Whether some ray's hit of a primitive (by its one-primitive BVH) lies
 * in no leaf box of b listing that primitive.  A split tree only tests a
 * triangle where the ray meets one of its pieces' boxes, which cover the
 * triangle but not all of its box: over extreme coordinates (subnormal
 * and 1e37 in one triangle) the triangle test can report a hit off the
 * triangle (roundoff, e.g. t = -0 at the ray's origin) inside the
 * triangle's box, which a one-primitive BVH accepts and the pieces never
 * see.  Only such a ray may differ from the brute force, and only so far
 * (a real hit is inside a piece box). */
static int unseen_hit(const atrbvh_bvh *b, atrbvh_bvh *const *singles,
                      const atrbvh_geometry *sg, size_t n,
                      const atrbvh_ray *r)
{
    size_t nn, np, i, j, q;
    const atrbvh_node *nd = atrbvh_bvh_nodes(b, &nn);
    const uint32_t *idx = atrbvh_bvh_primitive_indices(b, &np);
    for (i = 0; i < n; i++) {
        atrbvh_hit h;
        double pt[3];
        int k, seen = 0;
        if (!singles[i] || !atrbvh_intersect(singles[i], &sg[i], r, &h))
            continue;
        for (k = 0; k < 3; k++)
            pt[k] = (double)r->origin[k] + (double)h.t * r->dir[k];
        for (j = 0; j < nn && !seen; j++) {
            int in = nd[j].count > 0;
            for (k = 0; k < 3 && in; k++)
                in = pt[k] >= nd[j].min[k] && pt[k] <= nd[j].max[k];
            for (q = 0; in && q < nd[j].count && !seen; q++)
                seen = idx[nd[j].index + q] == i;
        }
        if (!seen)
            return 1;
    }
    return 0;
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
    int kind, split, split_ok;
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
    split_options(data, &o);
    split_ok = o.split_budget >= 0.0 && o.split_budget <= 4.0 &&
               (o.split_rule == ATRBVH_SPLIT_TREE ||
                o.split_rule == ATRBVH_SPLIT_PRIORITY ||
                o.split_rule == ATRBVH_SPLIT_SAH);
    split = o.split_budget > 0.0;
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
        if (!split_ok)
            FUZZ_CHECK(st == ATRBVH_ERR_INVALID_ARGUMENT &&
                           (strstr(e.text, "split_budget") ||
                            strstr(e.text, "split_rule") ||
                            strstr(e.text, "treelet") ||
                            strstr(e.text, "gamma")),
                       "split_budget %g split_rule %d: status %d: %s",
                       o.split_budget, o.split_rule, (int)st, e.text);
        else if (st == ATRBVH_ERR_INVALID_ARGUMENT && n > 0)
            FUZZ_CHECK(strstr(e.text, "min greater than max") ||
                           strstr(e.text, "vertices") ||
                           strstr(e.text, "treelet") ||
                           strstr(e.text, "gamma"),
                       "unexpected: %s", e.text);
        return 0;
    }
    FUZZ_CHECK(split_ok, "split_budget %g split_rule %d accepted",
               o.split_budget, o.split_rule);
    if (!split)
        FUZZ_CHECK(tu_check_bvh(b, &g, msg, sizeof msg), "%s", msg);
    else
        FUZZ_CHECK(tu_check_bvh_split(b, &g, o.split_budget, msg, sizeof msg),
                   "split_budget %g split_rule %d: %s", o.split_budget,
                   o.split_rule, msg);
    if (round_trip(b, &g, split, o.split_budget) == 1 && split) {
        /* nothing split (boxes never are: version 1): the tree built
         * without splitting, bit for bit */
        atrbvh_build_options plain = o;
        atrbvh_bvh *pb = NULL;
        plain.split_budget = 0.0;
        if (atrbvh_build(&g, &plain, &pb, &e) == ATRBVH_OK) {
            FUZZ_CHECK(tu_same_bvh(b, pb, msg, sizeof msg),
                       "nothing split, yet not the unsplit tree: %s", msg);
            atrbvh_bvh_free(pb);
        }
    }
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
            if (split && kind != 2 &&
                (hit != (bh.primitive != ATRBVH_NO_HIT) || occ != bocc ||
                 (hit && (h.primitive != bh.primitive ||
                          memcmp(&h.t, &bh.t, sizeof h.t) != 0))) &&
                unseen_hit(b, singles, sg, n, &ray)) {
                /* the brute force saw a roundoff hit the pieces cannot:
                 * what the tree found is still a hit of that primitive
                 * alone, and none closer than the brute force's */
                atrbvh_hit sh;
                if (hit) {
                    FUZZ_CHECK(h.primitive < n && singles[h.primitive] &&
                                   atrbvh_intersect(singles[h.primitive],
                                                    &sg[h.primitive], &ray,
                                                    &sh) &&
                                   memcmp(&sh.t, &h.t, sizeof h.t) == 0,
                               "hit %u at %g is not its own", h.primitive,
                               (double)h.t);
                    FUZZ_CHECK(bh.primitive != ATRBVH_NO_HIT &&
                                   (bh.t < h.t || (bh.t == h.t &&
                                                   bh.primitive < h.primitive)),
                               "hit %u at %g before brute force %u at %g",
                               h.primitive, (double)h.t, bh.primitive,
                               (double)bh.t);
                }
                FUZZ_CHECK(!occ || bocc, "occluded, brute force not");
                continue;
            }
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
