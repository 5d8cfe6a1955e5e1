/*
 * testutil.c - helpers the suites share.  The checker here is written
 * independently of the library: it walks the node array itself, recomputes
 * primitive boxes from the geometry and recomputes the SAH in long double.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include "testutil.h"

#include <check.h>
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int failf(char *msg, size_t len, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, len, fmt, ap);
    va_end(ap);
    return 0;
}

const float *tu_vertex(const atrbvh_geometry *g, size_t i, int c)
{
    size_t vs = g->vertex_stride ? g->vertex_stride : 12;
    size_t is = g->index_stride ? g->index_stride : 12;
    size_t v = g->indices
                   ? ((const uint32_t *)((const char *)g->indices + i * is))[c]
                   : 3 * i + (size_t)c;
    return (const float *)((const char *)g->vertices + v * vs);
}

const float *tu_box(const atrbvh_geometry *g, size_t i)
{
    size_t bs = g->box_stride ? g->box_stride : 24;
    return (const float *)((const char *)g->boxes + i * bs);
}

/* Box of primitive i, straight from the geometry. */
static void prim_box(const atrbvh_geometry *g, size_t i, float lo[3],
                     float hi[3])
{
    int k, c;
    if (g->type == ATRBVH_GEOMETRY_BOXES) {
        const float *b = tu_box(g, i);
        for (k = 0; k < 3; k++) {
            lo[k] = b[k];
            hi[k] = b[k + 3];
        }
        return;
    }
    for (k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (c = 0; c < 3; c++) {
        const float *p = tu_vertex(g, i, c);
        for (k = 0; k < 3; k++) {
            if (p[k] < lo[k])
                lo[k] = p[k];
            if (p[k] > hi[k])
                hi[k] = p[k];
        }
    }
}

void tu_bounds(const atrbvh_geometry *g, float lo[3], float hi[3])
{
    size_t i;
    int k;
    for (k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (i = 0; i < g->primitive_count; i++) {
        float plo[3], phi[3];
        prim_box(g, i, plo, phi);
        for (k = 0; k < 3; k++) {
            if (plo[k] < lo[k])
                lo[k] = plo[k];
            if (phi[k] > hi[k])
                hi[k] = phi[k];
        }
    }
}

static long double area_ld(const float lo[3], const float hi[3])
{
    long double dx = (long double)hi[0] - lo[0], dy = (long double)hi[1] - lo[1],
                dz = (long double)hi[2] - lo[2];
    return 2.0L * (dx * dy + dy * dz + dz * dx);
}

/* Valid means every coordinate the primitive reads is finite (the
 * min/max in prim_box would silently drop a NaN). */
static int prim_valid(const atrbvh_geometry *g, size_t i)
{
    int k, c;
    if (g->type == ATRBVH_GEOMETRY_BOXES) {
        const float *b = tu_box(g, i);
        for (k = 0; k < 6; k++)
            if (!isfinite(b[k]))
                return 0;
        return 1;
    }
    for (c = 0; c < 3; c++) {
        const float *p = tu_vertex(g, i, c);
        for (k = 0; k < 3; k++)
            if (!isfinite(p[k]))
                return 0;
    }
    return 1;
}

int tu_triangle_meets_box(const float *a, const float *b, const float *c,
                          const float lo[3], const float hi[3])
{
    /* Sutherland-Hodgman in double: each of the six planes adds at most
     * one vertex to the polygon, so 9 is the most it can have.  A
     * triangle may touch the box only on its boundary (a split piece
     * ending on a cell's face), where the clip's rounding would lose the
     * contact: the planes move out by 2^-40 of the triangle's largest
     * coordinate on that axis, far above the clip's rounding (a few
     * 2^-53 of it) and far below a float's ulp (2^-24). */
    double p[9][3], q[9][3], tol[3];
    const float *v[3];
    int np = 3, nq, i, j, k, side;
    v[0] = a;
    v[1] = b;
    v[2] = c;
    for (k = 0; k < 3; k++)
        tol[k] = 0.0;
    for (i = 0; i < 3; i++)
        for (k = 0; k < 3; k++) {
            p[i][k] = v[i][k];
            if (fabs(p[i][k]) > tol[k])
                tol[k] = fabs(p[i][k]);
        }
    for (k = 0; k < 3; k++)
        tol[k] = ldexp(tol[k], -40);
    for (k = 0; k < 3; k++)
        for (side = 0; side < 2; side++) {
            double x = side ? hi[k] + tol[k] : lo[k] - tol[k];
            nq = 0;
            for (i = 0; i < np; i++) {
                const double *s = p[i], *e = p[(i + 1) % np];
                int s_in = side ? s[k] <= x : s[k] >= x;
                int e_in = side ? e[k] <= x : e[k] >= x;
                if (s_in)
                    memcpy(q[nq++], s, sizeof q[0]);
                if (s_in != e_in) {
                    double t = (x - s[k]) / (e[k] - s[k]);
                    for (j = 0; j < 3; j++)
                        q[nq][j] = s[j] + t * (e[j] - s[j]);
                    q[nq][k] = x;
                    nq++;
                }
            }
            if (nq == 0)
                return 0;
            np = nq;
            memcpy(p, q, (size_t)np * sizeof p[0]);
        }
    return 1;
}

static int node_holds(const atrbvh_node *n, const double p[3])
{
    int k;
    for (k = 0; k < 3; k++)
        if (!(p[k] >= n->min[k] && p[k] <= n->max[k]))
            return 0;
    return 1;
}

/* seen[] bits: referenced, then (split triangles) vertex 0, 1, 2 and the
 * centroid found in the box of a leaf listing the triangle. */
#define SEEN_REF 1u
#define SEEN_COVERED 30u

/* The checker of tu_check_bvh (split 0) and tu_check_bvh_split (split 1,
 * with the budget). */
static int check_tree(const atrbvh_bvh *bvh, const atrbvh_geometry *g,
                      int split, double budget, char *msg, size_t len)
{
    size_t nn, np, i, valid = 0, leaves = 0, sp = 0;
    const atrbvh_node *nodes = atrbvh_bvh_nodes(bvh, &nn);
    const uint32_t *idx = atrbvh_bvh_primitive_indices(bvh, &np);
    atrbvh_stats st;
    unsigned char *seen;
    size_t *stack, *depth, *last;
    unsigned max_depth = 0, largest = 0;
    long double inner = 0, leafsum = 0, sah;
    int ok = 1;
    int pieces = split && g->type == ATRBVH_GEOMETRY_TRIANGLES;

    atrbvh_bvh_stats(bvh, &st);
    if (!nodes || nn == 0 || !idx)
        return failf(msg, len, "empty BVH");
    for (i = 0; i < g->primitive_count; i++)
        valid += (size_t)prim_valid(g, i);
    if (!split && np != valid)
        return failf(msg, len, "%zu primitive slots for %zu valid primitives",
                     np, valid);
    /* boxes are never split; triangles get at most budget * valid more */
    if (split && (np < valid || (!pieces && np != valid) ||
                  !((double)(np - valid) <= budget * (double)valid)))
        return failf(msg, len,
                     "%zu references for %zu valid primitives (budget %g)",
                     np, valid, budget);
    if (st.invalid_skipped != g->primitive_count - valid)
        return failf(msg, len, "stats say %zu skipped, %zu are invalid",
                     st.invalid_skipped, g->primitive_count - valid);
    seen = calloc(g->primitive_count, 1);
    last = calloc(g->primitive_count, sizeof *last);
    stack = malloc(sizeof *stack * (nn + 1));
    depth = malloc(sizeof *depth * (nn + 1));
    if (!seen || !last || !stack || !depth) {
        free(seen);
        free(last);
        free(stack);
        free(depth);
        return failf(msg, len, "test out of memory");
    }
    /* Walk from the root; every node must be reached exactly once. */
    {
        unsigned char *reached = calloc(nn, 1);
        stack[sp] = 0;
        depth[sp++] = 0;
        while (ok && sp) {
            size_t cur = stack[--sp], d = depth[sp];
            const atrbvh_node *n = &nodes[cur];
            if (reached[cur]) {
                ok = failf(msg, len, "node %zu reached twice", cur);
                break;
            }
            reached[cur] = 1;
            if (d > max_depth)
                max_depth = (unsigned)d;
            if (n->count == 0) {
                size_t kids[2] = {cur + 1, n->index};
                int c, k;
                inner += area_ld(n->min, n->max);
                for (c = 0; c < 2; c++) {
                    const atrbvh_node *ch;
                    if (kids[c] >= nn) {
                        ok = failf(msg, len, "node %zu: child %zu out of range",
                                   cur, kids[c]);
                        break;
                    }
                    ch = &nodes[kids[c]];
                    for (k = 0; k < 3; k++)
                        if (ch->min[k] < n->min[k] || ch->max[k] > n->max[k]) {
                            ok = failf(msg, len,
                                       "node %zu not inside parent %zu (axis %d)",
                                       kids[c], cur, k);
                            break;
                        }
                    stack[sp] = kids[c];
                    depth[sp++] = d + 1;
                }
            } else {
                size_t j;
                leaves++;
                if (n->count > largest)
                    largest = n->count;
                leafsum += area_ld(n->min, n->max) * n->count;
                if (n->index + (size_t)n->count > np) {
                    ok = failf(msg, len, "leaf %zu range out of bounds", cur);
                    break;
                }
                for (j = n->index; ok && j < n->index + n->count; j++) {
                    float lo[3], hi[3];
                    int k;
                    uint32_t p = idx[j];
                    if (p >= g->primitive_count || !prim_valid(g, p)) {
                        ok = failf(msg, len, "leaf %zu holds bad primitive %u",
                                   cur, p);
                        break;
                    }
                    if (split && last[p] == cur + 1) {
                        ok = failf(msg, len, "leaf %zu lists primitive %u twice",
                                   cur, p);
                        break;
                    }
                    if (!split && (seen[p] & SEEN_REF)) {
                        ok = failf(msg, len, "primitive %u referenced twice", p);
                        break;
                    }
                    last[p] = cur + 1;
                    seen[p] |= SEEN_REF;
                    if (pieces) {
                        /* the leaf box holds a part of the triangle; which
                         * of the vertices and the centroid it holds */
                        const float *v[3];
                        double pt[3];
                        int c;
                        for (c = 0; c < 3; c++)
                            v[c] = tu_vertex(g, p, c);
                        if (!tu_triangle_meets_box(v[0], v[1], v[2], n->min,
                                                   n->max)) {
                            ok = failf(msg, len,
                                       "leaf %zu lists triangle %u, which "
                                       "does not meet its box",
                                       cur, p);
                            break;
                        }
                        /* pieces are clamped to the triangle's box: a
                         * leaf of one triangle lies inside it */
                        prim_box(g, p, lo, hi);
                        for (k = 0; k < 3 && n->count == 1; k++)
                            if (n->min[k] < lo[k] || n->max[k] > hi[k]) {
                                ok = failf(msg, len,
                                           "leaf %zu of triangle %u outside "
                                           "the triangle's box (axis %d)",
                                           cur, p, k);
                                break;
                            }
                        if (!ok)
                            break;
                        for (c = 0; c < 3; c++) {
                            for (k = 0; k < 3; k++)
                                pt[k] = v[c][k];
                            if (node_holds(n, pt))
                                seen[p] |= (unsigned char)(2u << c);
                        }
                        for (k = 0; k < 3; k++)
                            pt[k] = ((double)v[0][k] + v[1][k] + v[2][k]) / 3;
                        if (node_holds(n, pt))
                            seen[p] |= 16u;
                        continue;
                    }
                    prim_box(g, p, lo, hi);
                    for (k = 0; k < 3; k++)
                        if (lo[k] < n->min[k] || hi[k] > n->max[k]) {
                            ok = failf(msg, len,
                                       "primitive %u outside its leaf %zu", p,
                                       cur);
                            break;
                        }
                }
            }
        }
        for (i = 0; ok && i < nn; i++)
            if (!reached[i])
                ok = failf(msg, len, "node %zu unreachable", i);
        free(reached);
    }
    for (i = 0; ok && i < g->primitive_count; i++) {
        if (!prim_valid(g, i))
            continue;
        if (!(seen[i] & SEEN_REF))
            ok = failf(msg, len, "primitive %zu missing", i);
        else if (pieces && (seen[i] & SEEN_COVERED) != SEEN_COVERED)
            ok = failf(msg, len,
                       "triangle %zu: its %s is in no leaf box listing it", i,
                       !(seen[i] & 2u)   ? "vertex 0"
                       : !(seen[i] & 4u) ? "vertex 1"
                       : !(seen[i] & 8u) ? "vertex 2"
                                         : "centroid");
    }
    free(seen);
    free(last);
    free(stack);
    free(depth);
    if (!ok)
        return 0;
    if (nn != 2 * leaves - 1)
        return failf(msg, len, "%zu nodes for %zu leaves", nn, leaves);
    if (st.nodes != nn || st.leaves != leaves || st.max_depth != max_depth ||
        st.max_leaf_primitives != largest || st.primitives != valid)
        return failf(msg, len,
                     "stats (nodes %zu leaves %zu depth %u largest %u "
                     "primitives %zu) vs measured (%zu %zu %u %u %zu)",
                     st.nodes, st.leaves, st.max_depth, st.max_leaf_primitives,
                     st.primitives, nn, leaves, max_depth, largest, valid);
    {
        long double root = area_ld(nodes[0].min, nodes[0].max);
        sah = root > 0 ? (st.ci * inner + st.ct * leafsum) / root : 0;
        if (!isfinite(st.sah) ||
            fabsl(sah - st.sah) > 1e-9L * (fabsl(sah) > 1 ? fabsl(sah) : 1))
            return failf(msg, len, "SAH %.17g reported, %.17Lg recomputed",
                         st.sah, sah);
    }
    return 1;
}

int tu_check_bvh(const atrbvh_bvh *bvh, const atrbvh_geometry *g, char *msg,
                 size_t len)
{
    return check_tree(bvh, g, 0, 0.0, msg, len);
}

int tu_check_bvh_split(const atrbvh_bvh *bvh, const atrbvh_geometry *g,
                       double budget, char *msg, size_t len)
{
    return check_tree(bvh, g, 1, budget, msg, len);
}

int tu_same_bvh(const atrbvh_bvh *a, const atrbvh_bvh *b, char *msg,
                size_t len)
{
    size_t na, nb, pa, pb, i;
    const atrbvh_node *x = atrbvh_bvh_nodes(a, &na), *y = atrbvh_bvh_nodes(b, &nb);
    const uint32_t *ia = atrbvh_bvh_primitive_indices(a, &pa),
                   *ib = atrbvh_bvh_primitive_indices(b, &pb);
    atrbvh_stats sa, sb;
    if (na != nb)
        return failf(msg, len, "node counts %zu vs %zu", na, nb);
    if (pa != pb)
        return failf(msg, len, "index counts %zu vs %zu", pa, pb);
    for (i = 0; i < na; i++)
        if (memcmp(&x[i], &y[i], sizeof x[i]))
            return failf(msg, len, "node %zu differs", i);
    for (i = 0; i < pa; i++)
        if (ia[i] != ib[i])
            return failf(msg, len, "primitive index %zu differs: %u vs %u", i,
                         ia[i], ib[i]);
    atrbvh_bvh_stats(a, &sa);
    atrbvh_bvh_stats(b, &sb);
    if (memcmp(&sa.sah, &sb.sah, sizeof sa.sah))
        return failf(msg, len, "SAH %.17g vs %.17g", sa.sah, sb.sah);
    return 1;
}

int tu_opencl_may_skip(atrbvh_status st)
{
    const char *req = getenv("ATRBVH_TEST_REQUIRE_OPENCL");
    if (req && *req && strcmp(req, "0") != 0)
        return 0;
    return st == ATRBVH_ERR_UNSUPPORTED;
}

const char *tu_scenes_dir(void)
{
    const char *d = getenv("ATRBVH_SCENES");
    char **p;
    size_t n;
    DIR *dir;
    struct dirent *e;
    if (!d || !*d)
        return NULL;
    dir = opendir(d);
    if (!dir)
        return NULL;
    n = 0;
    while ((e = readdir(dir)) != NULL) {
        size_t l = strlen(e->d_name);
        if (l > 4 && strcmp(e->d_name + l - 4, ".ply") == 0)
            n++;
    }
    closedir(dir);
    (void)p;
    return n ? d : NULL;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

size_t tu_scene_paths(char **paths, size_t max)
{
    const char *d = tu_scenes_dir();
    DIR *dir;
    struct dirent *e;
    size_t n = 0;
    if (!d || !(dir = opendir(d)))
        return 0;
    while (n < max && (e = readdir(dir)) != NULL) {
        size_t l = strlen(e->d_name);
        if (l > 4 && strcmp(e->d_name + l - 4, ".ply") == 0) {
            paths[n] = malloc(strlen(d) + l + 2);
            if (!paths[n])
                break;
            sprintf(paths[n], "%s/%s", d, e->d_name);
            n++;
        }
    }
    closedir(dir);
    qsort(paths, n, sizeof *paths, cmp_str);
    return n;
}

void tu_free_paths(char **paths, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        free(paths[i]);
}

void tu_rng_seed(tu_rng *r, uint64_t seed)
{
    r->s = seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull;
    if (!r->s)
        r->s = 1;
}

uint64_t tu_rng_next(tu_rng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return r->s * 0x2545F4914F6CDD1Dull;
}

float tu_rng_float(tu_rng *r)
{
    return (float)(tu_rng_next(r) >> 40) * (1.0f / 16777216.0f);
}

float *tu_random_triangles(size_t n, uint64_t seed, float scale, float offset)
{
    tu_rng r;
    size_t i;
    float *v = malloc(n * 9 * sizeof *v);
    if (!v)
        return NULL;
    tu_rng_seed(&r, seed);
    for (i = 0; i < n; i++) {
        float c[3];
        int k, j;
        for (k = 0; k < 3; k++)
            c[k] = tu_rng_float(&r);
        for (j = 0; j < 3; j++)
            for (k = 0; k < 3; k++)
                v[9 * i + 3 * j + k] =
                    (c[k] + 0.05f * (tu_rng_float(&r) - 0.5f)) * scale + offset;
    }
    return v;
}

atrbvh_bvh *tu_build(const atrbvh_geometry *g, const atrbvh_build_options *o)
{
    atrbvh_bvh *b = NULL;
    atrbvh_error e;
    atrbvh_status s = atrbvh_build(g, o, &b, &e);
    ck_assert_msg(s == ATRBVH_OK, "build failed: %s (%s)", atrbvh_strerror(s),
                  e.text);
    return b;
}

tu_alloc_counts tu_alloc = {0, -1, 0, 0, 0};

void *tu_count_malloc(size_t n)
{
    void *p;
    if (tu_alloc.countdown == 0)
        return NULL;
    if (tu_alloc.countdown > 0)
        tu_alloc.countdown--;
    tu_alloc.allocations++;
    if (n > tu_alloc.largest)
        tu_alloc.largest = n;
    tu_alloc.total_bytes += n;
    p = malloc(n);
    if (p)
        tu_alloc.outstanding++;
    return p;
}

void tu_count_free(void *p)
{
    if (p)
        tu_alloc.outstanding--;
    free(p);
}

void tu_count_reset(long countdown)
{
    tu_alloc.outstanding = 0;
    tu_alloc.countdown = countdown;
    tu_alloc.allocations = 0;
    tu_alloc.largest = 0;
    tu_alloc.total_bytes = 0;
}

uint32_t tu_rd32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
           (uint32_t)p[3] << 24;
}

void tu_wr32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)v;
    p[1] = (unsigned char)(v >> 8);
    p[2] = (unsigned char)(v >> 16);
    p[3] = (unsigned char)(v >> 24);
}

uint32_t tu_crc32(const unsigned char *p, size_t n)
{
    uint32_t c = 0xffffffffu;
    size_t i;
    int k;
    for (i = 0; i < n; i++) {
        c ^= p[i];
        for (k = 0; k < 8; k++)
            c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}

void tu_fix_crc(unsigned char *d, size_t n)
{
    tu_wr32(d + n - 4, tu_crc32(d, n - 4));
}

static void wr64(unsigned char *p, uint64_t v)
{
    tu_wr32(p, (uint32_t)v);
    tu_wr32(p + 4, (uint32_t)(v >> 32));
}

static void wr_float(unsigned char *p, float f)
{
    uint32_t bits;
    memcpy(&bits, &f, 4);
    tu_wr32(p, bits);
}

unsigned char *tu_chain_bvh_bytes(const float *v, size_t leaves,
                                  size_t *size)
{
    const size_t k = leaves - 1, nn = 2 * leaves - 1;
    const size_t n = 96 + 32 * nn + 4 * leaves + 4;
    unsigned char *d = calloc(1, n);
    float lo[3] = {INFINITY, INFINITY, INFINITY},
          hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    double ci = 1.2, ct = 1.0;
    uint64_t bits;
    size_t i;
    int a, c;
    if (!d)
        return NULL;
    for (i = 0; i < 9 * leaves; i++) {
        lo[i % 3] = fminf(lo[i % 3], v[i]);
        hi[i % 3] = fmaxf(hi[i % 3], v[i]);
    }
    memcpy(d, "ATRBVH\0\n", 8);
    tu_wr32(d + 8, 1);
    tu_wr32(d + 12, 96);
    wr64(d + 32, nn);
    wr64(d + 40, leaves);
    wr64(d + 48, leaves);
    memcpy(&bits, &ci, 8);
    wr64(d + 56, bits);
    memcpy(&bits, &ct, 8);
    wr64(d + 64, bits);
    for (i = 0; i < nn; i++) {
        unsigned char *q = d + 96 + 32 * i;
        float mn[3], mx[3];
        if (i < k) {
            memcpy(mn, lo, sizeof mn);
            memcpy(mx, hi, sizeof mx);
            tu_wr32(q + 24, (uint32_t)(2 * k - i)); /* the right child */
            tu_wr32(q + 28, 0);
        } else {
            const size_t leaf = i == k ? k : 2 * k - i;
            for (a = 0; a < 3; a++) {
                mn[a] = INFINITY;
                mx[a] = -INFINITY;
                for (c = 0; c < 3; c++) {
                    mn[a] = fminf(mn[a], v[9 * leaf + 3 * c + a]);
                    mx[a] = fmaxf(mx[a], v[9 * leaf + 3 * c + a]);
                }
            }
            tu_wr32(q + 24, (uint32_t)leaf); /* its slot: triangle leaf */
            tu_wr32(q + 28, 1);
        }
        for (a = 0; a < 3; a++) {
            wr_float(q + 4 * a, mn[a]);
            wr_float(q + 12 + 4 * a, mx[a]);
        }
    }
    for (i = 0; i < leaves; i++)
        tu_wr32(d + 96 + 32 * nn + 4 * i, (uint32_t)i);
    tu_fix_crc(d, n);
    *size = n;
    return d;
}

int tu_run(Suite *s)
{
    SRunner *sr = srunner_create(s);
    int failed;
    srunner_run_all(sr, CK_ENV);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}

/* ---------------------------------------------------------------- files */
char *tu_make_temp_dir(const char *prefix)
{
    const char *base = getenv("ATRBVH_BUILDDIR");
    char *d = malloc(600);
    ck_assert_ptr_nonnull(d);
    snprintf(d, 600, "%s/%sXXXXXX", base && *base ? base : ".", prefix);
    ck_assert_msg(mkdtemp(d) != NULL, "mkdtemp %s: %s", d, strerror(errno));
    return d;
}

void tu_list_dir(const char *dir, char *out, size_t len)
{
    DIR *dp = opendir(dir);
    struct dirent *de;
    size_t used = 0;
    out[0] = '\0';
    ck_assert_ptr_nonnull(dp);
    while ((de = readdir(dp)) != NULL) {
        if (!strcmp(de->d_name, ".") || !strcmp(de->d_name, ".."))
            continue;
        used += (size_t)snprintf(out + used, used < len ? len - used : 0,
                                 "%s ", de->d_name);
    }
    closedir(dp);
}

void tu_write_bytes(const char *path, const unsigned char *d, size_t n)
{
    FILE *f = fopen(path, "wb");
    ck_assert_ptr_nonnull(f);
    ck_assert_uint_eq(fwrite(d, 1, n, f), n);
    ck_assert_int_eq(fclose(f), 0);
}

int tu_holds(const char *path, const unsigned char *d, size_t n)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf;
    size_t got;
    int same;
    if (!f)
        return 0;
    buf = malloc(n + 1);
    ck_assert_ptr_nonnull(buf);
    got = fread(buf, 1, n + 1, f);
    fclose(f);
    same = got == n && memcmp(buf, d, n) == 0;
    free(buf);
    return same;
}
