/*
 * minibuilder.c - a small, independent BVH builder in plain C99 that
 * writes its stage outputs in the format of atrbvh-stages(7), so that
 * `atrbvh check` can compare it with the reference stage by stage.
 *
 * It does not link libatrbvh: every rule below is written from
 * docs/stages.md - bounds, Morton keys in the host frame, a stable sort,
 * Karras' hierarchy with the index tie rule, refit with SAH costs, the
 * treelet rounds (formation by largest area; TRBVH's subset DP or
 * ATRBVH's agglomerative clustering; the id renumbering), the collapse
 * decision and the depth-first layout.  Plain and slow on purpose
 * (recursion, O(m^3) clustering): it is a readable second
 * implementation, not a fast one.
 *
 *   minibuilder --scene FILE.obj [N]   writes a test scene: an N x N grid
 *                                      of quads, each triangle twice (equal
 *                                      Morton keys and equal boxes on
 *                                      purpose)
 *   minibuilder [--atrbvh|--trbvh] [--collapse] FILE.obj DIR
 *                                      builds (LBVH by default; ATRBVH
 *                                      with treelet 9, 2 rounds; TRBVH
 *                                      with treelet 7, 3 rounds) and dumps
 *                                      every stage to DIR
 *
 * Planted bugs, for the demonstration (check-demo.sh):
 *   -DPLANTED_BUG=1  the sort puts equal keys in descending index order
 *                    (what an unstable GPU radix sort does)
 *   -DPLANTED_BUG=2  ATRBVH clustering lets the last of equal distances
 *                    win instead of the first
 *   -DPLANTED_BUG=3  the TRBVH DP lets the last of equal splits win
 */
#include <errno.h>
#include <float.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct box {
    float lo[3], hi[3];
} box;

static void die(const char *what)
{
    fprintf(stderr, "minibuilder: %s\n", what);
    exit(1);
}

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p)
        die("out of memory");
    return p;
}

/* ------------------------------------------------------------- scene */
static void write_scene(const char *path, int n)
{
    FILE *f = fopen(path, "w");
    int x, z, copy;
    if (!f)
        die("cannot write the scene");
    /* vertices on a grid of 1/4 steps: exact in any float parser */
    for (z = 0; z <= n; z++)
        for (x = 0; x <= n; x++)
            fprintf(f, "v %g %g %g\n", x * 0.25, ((x * 7 + z * 3) % 5) * 0.25,
                    z * 0.25);
    for (copy = 0; copy < 2; copy++)
        for (z = 0; z < n; z++)
            for (x = 0; x < n; x++) {
                int a = z * (n + 1) + x + 1, b = a + 1, c = a + n + 1,
                    d = c + 1;
                fprintf(f, "f %d %d %d\nf %d %d %d\n", a, b, d, a, d, c);
            }
    if (fclose(f) != 0)
        die("cannot write the scene");
}

static void read_obj(const char *path, float **vout, size_t *nv,
                     uint32_t **iout, size_t *nt)
{
    FILE *f = fopen(path, "r");
    char line[256];
    size_t rv = 64, rt = 64;
    float *v = xmalloc(rv * 3 * sizeof *v);
    uint32_t *t = xmalloc(rt * 3 * sizeof *t);
    *nv = *nt = 0;
    if (!f)
        die("cannot read the scene");
    while (fgets(line, sizeof line, f)) {
        if (line[0] == 'v' && line[1] == ' ') {
            if (*nv == rv) {
                rv *= 2;
                v = realloc(v, rv * 3 * sizeof *v);
                if (!v)
                    die("out of memory");
            }
            if (sscanf(line + 2, "%f %f %f", &v[3 * *nv], &v[3 * *nv + 1],
                       &v[3 * *nv + 2]) != 3)
                die("bad vertex line");
            (*nv)++;
        } else if (line[0] == 'f' && line[1] == ' ') {
            unsigned a, b, c;
            if (*nt == rt) {
                rt *= 2;
                t = realloc(t, rt * 3 * sizeof *t);
                if (!t)
                    die("out of memory");
            }
            if (sscanf(line + 2, "%u %u %u", &a, &b, &c) != 3 || !a || !b ||
                !c)
                die("bad face line (triangles, 1-based indices only)");
            t[3 * *nt] = a - 1;
            t[3 * *nt + 1] = b - 1;
            t[3 * *nt + 2] = c - 1;
            (*nt)++;
        }
    }
    fclose(f);
    *vout = v;
    *iout = t;
}

/* ------------------------------------------------------------ stages */
static box empty_box(void)
{
    box b;
    int k;
    for (k = 0; k < 3; k++) {
        b.lo[k] = FLT_MAX;
        b.hi[k] = -FLT_MAX;
    }
    return b;
}

static box merge(box a, box b)
{
    int k;
    for (k = 0; k < 3; k++) {
        a.lo[k] = b.lo[k] < a.lo[k] ? b.lo[k] : a.lo[k];
        a.hi[k] = b.hi[k] > a.hi[k] ? b.hi[k] : a.hi[k];
    }
    return a;
}

static float centre(box b, int k)
{
    return 0.5f * b.lo[k] + 0.5f * b.hi[k];
}

/* Surface area in double, the terms in this order. */
static double area(box b)
{
    double dx = (double)b.hi[0] - (double)b.lo[0];
    double dy = (double)b.hi[1] - (double)b.lo[1];
    double dz = (double)b.hi[2] - (double)b.lo[2];
    double s = dx * dy;
    s = s + dy * dz;
    s = s + dz * dx;
    return 2.0 * s;
}

/* bit k of v to bit 3k, one bit at a time (slow and plain) */
static uint64_t spread(uint32_t v)
{
    uint64_t r = 0;
    int k;
    for (k = 0; k < 21; k++)
        r |= (uint64_t)((v >> k) & 1u) << (3 * k);
    return r;
}

static uint32_t quantise(float c, double lo, double scale)
{
    double t = ((double)c - lo) * scale;
    if (!(t > 0.0))
        return 0;
    if (t >= 2097151.0)
        return 2097151u;
    return (uint32_t)t;
}

/* Stable merge sort of ids by key. */
static const uint64_t *sort_keys;
static int before(uint32_t a, uint32_t b)
{
    if (sort_keys[a] != sort_keys[b])
        return sort_keys[a] < sort_keys[b];
#if defined(PLANTED_BUG) && PLANTED_BUG == 1
    return a > b; /* the bug: equal keys, larger index first */
#else
    return a < b;
#endif
}

static void merge_sort(uint32_t *ids, uint32_t *tmp, size_t n)
{
    size_t h = n / 2, i = 0, j = h, k = 0;
    if (n < 2)
        return;
    merge_sort(ids, tmp, h);
    merge_sort(ids + h, tmp, n - h);
    while (i < h && j < n)
        tmp[k++] = before(ids[j], ids[i]) ? ids[j++] : ids[i++];
    while (i < h)
        tmp[k++] = ids[i++];
    while (j < n)
        tmp[k++] = ids[j++];
    memcpy(ids, tmp, n * sizeof *ids);
}

static int clz64(uint64_t x)
{
    int n = 0;
    if (!x)
        return 64;
    while (!(x >> 63)) {
        x <<= 1;
        n++;
    }
    return n;
}

/* Karras 2012: common prefix of sorted keys i and j; equal keys are told
 * apart by their positions: 64 + the common prefix of i and j as 32-bit
 * numbers. */
static int delta(const uint64_t *k, int64_t n, int64_t i, int64_t j)
{
    if (j < 0 || j >= n)
        return -1;
    if (k[i] == k[j])
        return 64 + (clz64((uint64_t)(i ^ j)) - 32);
    return clz64(k[i] ^ k[j]);
}

static void karras(const uint64_t *k, int64_t n, int64_t i, uint32_t *left,
                   uint32_t *right)
{
    int d = delta(k, n, i, i + 1) > delta(k, n, i, i - 1) ? 1 : -1;
    int dmin = delta(k, n, i, i - d), dnode;
    int64_t lmax = 2, l = 0, t, j, s = 0, split;
    while (delta(k, n, i, i + lmax * d) > dmin)
        lmax *= 2;
    for (t = lmax / 2; t >= 1; t /= 2)
        if (delta(k, n, i, i + (l + t) * d) > dmin)
            l += t;
    j = i + l * d;
    dnode = delta(k, n, i, j);
    t = l;
    do {
        t = (t + 1) / 2;
        if (delta(k, n, i, i + (s + t) * d) > dnode)
            s += t;
    } while (t > 1);
    split = i + s * d + (d < 0 ? -1 : 0);
    /* a child that covers one key is leaf (n - 1 + position) */
    *left = (uint32_t)((i < j ? i : j) == split ? split + n - 1 : split);
    *right = (uint32_t)((i < j ? j : i) == split + 1 ? split + n : split + 1);
}

/* ------------------------------------------------------------ output */
static FILE *manifest;
static const char *outdir;
static int first_file;

static void npy(const char *stage, const char *name, const char *descr,
                size_t rows, size_t cols, const void *data, size_t elem)
{
    char path[1024], dict[128];
    size_t len;
    FILE *f;
    unsigned char pre[10] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0, 0, 0};
    if (cols == 0)
        snprintf(dict, sizeof dict,
                 "{'descr': '%s', 'fortran_order': False, 'shape': (%lu,), }",
                 descr, (unsigned long)rows);
    else
        snprintf(dict, sizeof dict,
                 "{'descr': '%s', 'fortran_order': False, 'shape': (%lu, "
                 "%lu), }",
                 descr, (unsigned long)rows, (unsigned long)cols);
    len = strlen(dict);
    while ((10 + len + 1) % 64)
        dict[len++] = ' ';
    dict[len++] = '\n';
    pre[8] = (unsigned char)len;
    pre[9] = (unsigned char)(len >> 8);
    snprintf(path, sizeof path, "%s/%s-%s.npy", outdir, stage, name);
    f = fopen(path, "wb");
    if (!f || fwrite(pre, 1, 10, f) != 10 || fwrite(dict, 1, len, f) != len ||
        fwrite(data, elem, rows * (cols ? cols : 1), f) !=
            rows * (cols ? cols : 1) ||
        fclose(f) != 0)
        die("cannot write a .npy file");
    fprintf(manifest,
            "%s\n      {\"array\": \"%s\", \"file\": \"%s-%s.npy\", "
            "\"dtype\": \"%s\", \"shape\": [%lu",
            first_file ? "" : ",", name, stage, name, descr,
            (unsigned long)rows);
    if (cols)
        fprintf(manifest, ", %lu", (unsigned long)cols);
    fprintf(manifest, "]}");
    first_file = 0;
}

static void stage_begin(const char *name, int first)
{
    fprintf(manifest, "%s\n    {\"name\": \"%s\", \"files\": [",
            first ? "" : ",", name);
    first_file = 1;
}

static void stage_end(void)
{
    fprintf(manifest, "]}");
}

/* ------------------------------------------------------------ the tree */
static double ci = 1.2, ct = 1.0;
static int collapse;            /* --collapse: multi-primitive leaves   */

typedef struct tree {
    size_t n;                   /* primitives; nodes 0 .. 2n-2          */
    uint32_t *left, *right;     /* n-1 internal nodes, root 0           */
    uint32_t *parent, *count;   /* 2n-1                                  */
    uint32_t *leaf_prim;        /* n                                     */
    box *box;                   /* 2n-1                                  */
    double *cost;               /* 2n-1                                  */
} tree;

/* The node cost: ci*A + left + right, or ct*A*N when collapsing is on
 * and that is strictly cheaper. */
static double node_cost(double a, uint32_t cnt, double cl, double cr,
                        int *flat)
{
    double binary = ci * a;
    binary = binary + cl;
    binary = binary + cr;
    *flat = 0;
    if (collapse) {
        double f = ct * a;
        f = f * (double)cnt;
        if (f < binary) {
            *flat = 1;
            return f;
        }
    }
    return binary;
}

static int is_leaf(const tree *t, uint32_t node)
{
    return node >= t->n - 1;
}

/* refit of one internal node from its children */
static void refit_node(tree *t, uint32_t node)
{
    uint32_t l = t->left[node], r = t->right[node];
    int flat;
    t->box[node] = merge(t->box[l], t->box[r]);
    t->count[node] = t->count[l] + t->count[r];
    t->cost[node] = node_cost(area(t->box[node]), t->count[node],
                              t->cost[l], t->cost[r], &flat);
}

static void refit(tree *t, uint32_t node)
{
    if (is_leaf(t, node))
        return;
    refit(t, t->left[node]);
    refit(t, t->right[node]);
    refit_node(t, node);
}

/* ------------------------------------------------ ATRBVH treelets */
#define MAXT 32

/* One treelet at root R with (at most) tn leaves: formation by largest
 * area, agglomerative clustering, write-back when strictly cheaper. */
/* TRBVH: the subset DP's tables (treelets of at most 10 leaves) */
static box dp_box[1 << 10];
static uint32_t dp_count[1 << 10], dp_split[1 << 10];
static double dp_cost[1 << 10];
static int trbvh;

static unsigned low_bit(uint32_t x)
{
    unsigned k = 0;
    while (!(x & 1u)) {
        x >>= 1;
        k++;
    }
    return k;
}

static void treelet(tree *t, uint32_t R, unsigned tn)
{
    uint32_t leaf[MAXT], internal[MAXT], code[MAXT], lc[MAXT], rc[MAXT];
    uint32_t cnt[MAXT], order[MAXT], id_of[MAXT], ids[MAXT], stack[MAXT];
    uint32_t ncnt[MAXT];
    double ar[MAXT], cst[MAXT], ncost[MAXT];
    box bx[MAXT], nbox[MAXT];
    unsigned m = 2, live, k, q, sp, i, j, root;
    int flat;
    /* refresh the root's cost (its subtree may be cheaper now) */
    t->cost[R] = node_cost(area(t->box[R]), t->count[R],
                           t->cost[t->left[R]], t->cost[t->right[R]], &flat);
    /* formation */
    internal[0] = R;
    leaf[0] = t->left[R];
    leaf[1] = t->right[R];
    ar[0] = area(t->box[leaf[0]]);
    ar[1] = area(t->box[leaf[1]]);
    while (m < tn) {
        int best = -1;
        uint32_t node;
        for (k = 0; k < m; k++)
            if (!is_leaf(t, leaf[k]) && (best < 0 || ar[k] > ar[best]))
                best = (int)k;
        if (best < 0)
            break;
        node = leaf[best];
        internal[m - 1] = node;
        leaf[best] = t->left[node];
        ar[best] = area(t->box[leaf[best]]);
        leaf[m] = t->right[node];
        ar[m] = area(t->box[leaf[m]]);
        m++;
    }
    if (m < 3)
        return;
    if (trbvh) {
        /* subset DP: S = 2^k | rest, every proper subset done before S */
        uint32_t full = (1u << m) - 1u, mask[MAXT], node[MAXT];
        unsigned next = 1;
        for (k = 0; k < m; k++) {
            uint32_t bit = 1u << k, rest;
            dp_box[bit] = t->box[leaf[k]];
            dp_count[bit] = t->count[leaf[k]];
            dp_cost[bit] = t->cost[leaf[k]];
            for (rest = 1; rest < bit; rest++) {
                uint32_t S = bit | rest, delta = (S - 1u) & S;
                uint32_t P = (0u - delta) & S, bestp = P;
                box b = merge(dp_box[rest], t->box[leaf[k]]);
                uint32_t c = dp_count[rest] + t->count[leaf[k]];
                double a = area(b), base = ci * a, best, x;
                best = base + dp_cost[P];
                best = best + dp_cost[S ^ P];
                for (P = (P - delta) & S; P; P = (P - delta) & S) {
                    x = base + dp_cost[P];
                    x = x + dp_cost[S ^ P];
#if defined(PLANTED_BUG) && PLANTED_BUG == 3
                    if (x <= best) { /* the bug: the last of equal splits */
#else
                    if (x < best) {
#endif
                        best = x;
                        bestp = P;
                    }
                }
                if (collapse) {
                    x = ct * a;
                    x = x * (double)c;
                    if (x < best)
                        best = x;
                }
                dp_box[S] = b;
                dp_count[S] = c;
                dp_cost[S] = best;
                dp_split[S] = bestp;
            }
        }
        /* the topology, top-down: P is the left child */
        root = 0;
        sp = 0;
        mask[sp] = full;
        node[sp++] = 0;
        while (sp) {
            uint32_t S = mask[--sp], nd = node[sp], P = dp_split[S];
            uint32_t side[2];
            side[0] = P;
            side[1] = S ^ P;
            for (k = 0; k < 2; k++) {
                uint32_t code;
                if (!(side[k] & (side[k] - 1u))) {
                    code = low_bit(side[k]);
                } else {
                    code = m + next;
                    mask[sp] = side[k];
                    node[sp++] = next++;
                }
                if (k == 0)
                    lc[nd] = code;
                else
                    rc[nd] = code;
            }
        }
    } else {
    /* agglomerative clustering: slots 0 .. live-1 */
        for (k = 0; k < m; k++) {
            bx[k] = t->box[leaf[k]];
            cst[k] = t->cost[leaf[k]];
            cnt[k] = t->count[leaf[k]];
            code[k] = k;
        }
        for (live = m, q = 0; live > 1; live--, q++) {
            double best = 0.0;
            unsigned bi = 0, bj = 0, last = live - 1;
            box u;
            for (i = 1; i < live; i++)
                for (j = 0; j < i; j++) {
                    double d = area(merge(bx[j], bx[i]));
#if defined(PLANTED_BUG) && PLANTED_BUG == 2
                    /* the bug: among equal distances the last pair wins */
                    if ((i == 1 && j == 0) || d <= best) {
#else
                    if ((i == 1 && j == 0) || d < best) {
#endif
                        best = d;
                        bi = i;
                        bj = j;
                    }
                }
            lc[q] = code[bj];
            rc[q] = code[bi];
            u = merge(bx[bj], bx[bi]);
            cst[bj] = node_cost(area(u), cnt[bj] + cnt[bi], cst[bj], cst[bi],
                                &flat);
            bx[bj] = u;
            cnt[bj] += cnt[bi];
            code[bj] = m + q;
            if (bi != last) {
                bx[bi] = bx[last];
                cst[bi] = cst[last];
                cnt[bi] = cnt[last];
                code[bi] = code[last];
            }
        }
        root = m - 2;
    }
    /* pre-order of the local nodes (root m-2), then bottom-up values */
    sp = 0;
    k = 0;
    stack[sp++] = root;
    while (sp) {
        uint32_t node = stack[--sp];
        order[k++] = node;
        if (rc[node] >= m)
            stack[sp++] = rc[node] - m;
        if (lc[node] >= m)
            stack[sp++] = lc[node] - m;
    }
    for (k = m - 1; k-- > 0;) {
        uint32_t node = order[k], l = lc[node], r = rc[node];
        box bl = l < m ? t->box[leaf[l]] : nbox[l - m];
        box br = r < m ? t->box[leaf[r]] : nbox[r - m];
        uint32_t nl = l < m ? t->count[leaf[l]] : ncnt[l - m];
        uint32_t nr = r < m ? t->count[leaf[r]] : ncnt[r - m];
        double cl = l < m ? t->cost[leaf[l]] : ncost[l - m];
        double cr = r < m ? t->cost[leaf[r]] : ncost[r - m];
        nbox[node] = merge(bl, br);
        ncnt[node] = nl + nr;
        ncost[node] = node_cost(area(nbox[node]), nl + nr, cl, cr, &flat);
    }
    if (!(ncost[root] < t->cost[R]))
        return;
    /* write back: R keeps its id; the other ids, ascending, in pre-order */
    for (k = 0; k + 2 < m; k++)
        ids[k] = internal[k + 1];
    for (k = 1; k + 2 < m; k++) /* insertion sort */
        for (j = k; j > 0 && ids[j - 1] > ids[j]; j--) {
            uint32_t x = ids[j];
            ids[j] = ids[j - 1];
            ids[j - 1] = x;
        }
    id_of[order[0]] = R;
    for (k = 1; k + 1 < m; k++)
        id_of[order[k]] = ids[k - 1];
    for (k = 0; k + 1 < m; k++) {
        uint32_t id = id_of[k];
        uint32_t l = lc[k] < m ? leaf[lc[k]] : id_of[lc[k] - m];
        uint32_t r = rc[k] < m ? leaf[rc[k]] : id_of[rc[k] - m];
        t->left[id] = l;
        t->right[id] = r;
        t->parent[l] = id;
        t->parent[r] = id;
        t->box[id] = nbox[k];
        t->count[id] = ncnt[k];
        t->cost[id] = ncost[k];
    }
}

/* post-order over the crown: internal nodes holding >= g primitives */
static void crown(tree *t, uint32_t node, uint64_t g, unsigned tn)
{
    if (is_leaf(t, node) || t->count[node] < g)
        return;
    crown(t, t->left[node], g, tn);
    crown(t, t->right[node], g, tn);
    treelet(t, node, tn);
}

/* ------------------------------------------------- collapse, layout */
#define LEAF_FLAG 0x80000000u

static void decide(const tree *t, uint32_t node, uint32_t *size)
{
    uint32_t l, r;
    int flat;
    if (is_leaf(t, node)) {
        size[node] = 1u | LEAF_FLAG;
        return;
    }
    l = t->left[node];
    r = t->right[node];
    decide(t, l, size);
    decide(t, r, size);
    (void)node_cost(area(t->box[node]), t->count[node], t->cost[l],
                    t->cost[r], &flat);
    size[node] = flat ? 1u | LEAF_FLAG
                      : 1u + (size[l] & ~LEAF_FLAG) + (size[r] & ~LEAF_FLAG);
}

static void gather(const tree *t, uint32_t node, uint32_t *out, size_t *k)
{
    if (is_leaf(t, node)) {
        out[(*k)++] = t->leaf_prim[node - (t->n - 1)];
        return;
    }
    gather(t, t->left[node], out, k);
    gather(t, t->right[node], out, k);
}

static void emit(const tree *t, const uint32_t *size, uint32_t node,
                 uint32_t pos, uint32_t prim, float *nb, uint32_t *ic,
                 uint32_t *prims)
{
    int k;
    for (k = 0; k < 3; k++) {
        nb[6 * pos + k] = t->box[node].lo[k];
        nb[6 * pos + 3 + k] = t->box[node].hi[k];
    }
    if (size[node] & LEAF_FLAG) {
        size_t at = prim;
        ic[2 * pos] = prim;
        ic[2 * pos + 1] = t->count[node];
        gather(t, node, prims, &at);
    } else {
        uint32_t l = t->left[node];
        uint32_t rpos = pos + 1 + (size[l] & ~LEAF_FLAG);
        ic[2 * pos] = rpos;
        ic[2 * pos + 1] = 0;
        emit(t, size, l, pos + 1, prim, nb, ic, prims);
        emit(t, size, t->right[node], rpos, prim + t->count[l], nb, ic,
             prims);
    }
}

static void dump_tree(const char *stage, const tree *t, int values)
{
    size_t n = t->n;
    stage_begin(stage, 0);
    npy(stage, "left", "<u4", n - 1, 0, t->left, 4);
    npy(stage, "right", "<u4", n - 1, 0, t->right, 4);
    npy(stage, "parent", "<u4", 2 * n - 1, 0, t->parent, 4);
    npy(stage, "count", "<u4", 2 * n - 1, 0, t->count, 4);
    npy(stage, "leaf_prim", "<u4", n, 0, t->leaf_prim, 4);
    if (values) {
        npy(stage, "box", "<f4", 2 * n - 1, 6, t->box, 4);
        npy(stage, "cost", "<f8", 2 * n - 1, 0, t->cost, 8);
    }
    stage_end();
}

int main(int argc, char **argv)
{
    float *v;
    uint32_t *tri, *order, *tmp, *size, *ic, *prims;
    size_t nv, nt, i;
    int64_t n;
    box *prim, scene = empty_box(), cent = empty_box();
    uint64_t *keys, *sorted;
    double frame[6];
    float *nb;
    tree t;
    int k, agglomerative = 0, a = 1;
    unsigned tn = 9, rounds = 2, r;
    char path[1024];

    if (argc >= 3 && strcmp(argv[1], "--scene") == 0) {
        write_scene(argv[2], argc > 3 ? atoi(argv[3]) : 24);
        return 0;
    }
    for (; a < argc && argv[a][0] == '-'; a++) {
        if (strcmp(argv[a], "--atrbvh") == 0)
            agglomerative = 1;
        else if (strcmp(argv[a], "--trbvh") == 0)
            trbvh = 1;
        else if (strcmp(argv[a], "--collapse") == 0)
            collapse = 1;
        else
            die("unknown option");
    }
    if (argc - a != 2 || (trbvh && agglomerative))
        die("usage: minibuilder [--atrbvh|--trbvh] [--collapse] FILE.obj "
            "DIR | --scene FILE.obj [N]");
    if (trbvh) {
        tn = 7;
        rounds = 3;
    }
    read_obj(argv[a], &v, &nv, &tri, &nt);
    if (nt < 2)
        die("fewer than two triangles");
    n = (int64_t)nt;
    outdir = argv[a + 1];

    /* bounds */
    prim = xmalloc(nt * sizeof *prim);
    for (i = 0; i < nt; i++) {
        box b = empty_box();
        int c;
        for (c = 0; c < 3; c++) {
            uint32_t id = tri[3 * i + c];
            box p;
            if (id >= nv)
                die("vertex index out of range");
            for (k = 0; k < 3; k++)
                p.lo[k] = p.hi[k] = v[3 * id + k];
            b = merge(b, p);
        }
        prim[i] = b;
        scene = merge(scene, b);
        for (k = 0; k < 3; k++) {
            float c2 = centre(b, k);
            cent.lo[k] = c2 < cent.lo[k] ? c2 : cent.lo[k];
            cent.hi[k] = c2 > cent.hi[k] ? c2 : cent.hi[k];
        }
    }
    /* morton: the frame on the host, in double */
    for (k = 0; k < 3; k++) {
        double extent = (double)cent.hi[k] - (double)cent.lo[k];
        frame[k] = (double)cent.lo[k];
        frame[3 + k] = extent > 0.0 ? 2097152.0 / extent : 0.0;
    }
    keys = xmalloc(nt * sizeof *keys);
    for (i = 0; i < nt; i++) {
        uint32_t q[3];
        for (k = 0; k < 3; k++)
            q[k] = quantise(centre(prim[i], k), frame[k], frame[3 + k]);
        keys[i] = spread(q[0]) << 2 | spread(q[1]) << 1 | spread(q[2]);
    }
    /* sort */
    order = xmalloc(nt * sizeof *order);
    tmp = xmalloc(nt * sizeof *tmp);
    sorted = xmalloc(nt * sizeof *sorted);
    for (i = 0; i < nt; i++)
        order[i] = (uint32_t)i;
    sort_keys = keys;
    merge_sort(order, tmp, nt);
    for (i = 0; i < nt; i++)
        sorted[i] = keys[order[i]];

    snprintf(path, sizeof path, "%s/manifest.json", outdir);
    manifest = fopen(path, "w");
    if (!manifest)
        die("cannot write the manifest (does DIR exist?)");
    fprintf(manifest,
            "{\n  \"format\": \"atrbvh-stages\",\n  \"version\": 1,\n"
            "  \"scene\": {\"name\": \"%s\", \"triangles\": %lu},\n"
            "  \"options\": {\"method\": \"%s\", \"treelet_size\": %u, "
            "\"rounds\": %u, \"gamma\": %u, \"ci\": 1.2, \"ct\": 1, "
            "\"collapse\": %s, \"max_leaf_size\": 0},\n"
            "  \"stages\": [",
            argv[a], (unsigned long)nt,
            agglomerative ? "atrbvh" : trbvh ? "trbvh" : "lbvh",
            agglomerative || trbvh ? tn : 0,
            agglomerative || trbvh ? rounds : 0,
            agglomerative || trbvh ? tn : 0, collapse ? "true" : "false");
    stage_begin("bounds", 1);
    npy("bounds", "prim_boxes", "<f4", nt, 6, prim, sizeof(float));
    npy("bounds", "scene_box", "<f4", 1, 6, &scene, sizeof(float));
    npy("bounds", "centroid_box", "<f4", 1, 6, &cent, sizeof(float));
    stage_end();
    stage_begin("morton", 0);
    npy("morton", "morton_frame", "<f8", 2, 3, frame, sizeof(double));
    npy("morton", "keys", "<u8", nt, 0, keys, sizeof(uint64_t));
    stage_end();
    stage_begin("sort", 0);
    npy("sort", "sorted_keys", "<u8", nt, 0, sorted, sizeof(uint64_t));
    npy("sort", "order", "<u4", nt, 0, order, sizeof(uint32_t));
    stage_end();

    /* hierarchy: internal 0 .. n-2 (root 0), leaves n-1 .. 2n-2 */
    t.n = nt;
    t.left = xmalloc(nt * sizeof *t.left);
    t.right = xmalloc(nt * sizeof *t.right);
    t.parent = xmalloc(2 * nt * sizeof *t.parent);
    t.count = xmalloc(2 * nt * sizeof *t.count);
    t.leaf_prim = xmalloc(nt * sizeof *t.leaf_prim);
    t.box = xmalloc(2 * nt * sizeof *t.box);
    t.cost = xmalloc(2 * nt * sizeof *t.cost);
    t.parent[0] = 0xffffffffu;
    for (i = 0; i + 1 < nt; i++) {
        karras(sorted, n, (int64_t)i, &t.left[i], &t.right[i]);
        t.parent[t.left[i]] = t.parent[t.right[i]] = (uint32_t)i;
    }
    for (i = 0; i < nt; i++) {
        size_t node = nt - 1 + i;
        t.leaf_prim[i] = order[i];
        t.box[node] = prim[order[i]];
        t.count[node] = 1;
        t.cost[node] = ct * area(t.box[node]);
    }
    refit(&t, 0); /* the counts, for the hierarchy dump too */
    dump_tree("hierarchy", &t, 0);
    dump_tree("refit", &t, 1);

    /* optimise: rounds with gamma * 2^r, the crown in post-order */
    if (agglomerative || trbvh)
        for (r = 0; r < rounds; r++) {
            uint64_t g = (uint64_t)tn << (r < 40 ? r : 40);
            char name[32];
            if (g > t.count[0])
                break;
            crown(&t, 0, g, tn);
            snprintf(name, sizeof name, "optimise_round%u", r + 1);
            dump_tree(name, &t, 1);
        }
    dump_tree("optimise", &t, 1);

    /* collapse, layout */
    size = xmalloc((2 * nt - 1) * sizeof *size);
    decide(&t, 0, size);
    stage_begin("collapse", 0);
    npy("collapse", "collapse_size", "<u4", 2 * nt - 1, 0, size, 4);
    stage_end();
    {
        size_t m = size[0] & ~LEAF_FLAG;
        nb = xmalloc(m * 6 * sizeof *nb);
        ic = xmalloc(m * 2 * sizeof *ic);
        prims = xmalloc(nt * sizeof *prims);
        emit(&t, size, 0, 0, 0, nb, ic, prims);
        stage_begin("layout", 0);
        npy("layout", "node_boxes", "<f4", m, 6, nb, 4);
        npy("layout", "node_index_count", "<u4", m, 2, ic, 4);
        npy("layout", "prim_indices", "<u4", nt, 0, prims, 4);
        stage_end();
    }
    fprintf(manifest, "\n  ]\n}\n");
    if (fclose(manifest) != 0)
        die("cannot write the manifest");
    printf("minibuilder: %lu triangles (%s%s), stages written to %s\n",
           (unsigned long)nt,
           agglomerative ? "ATRBVH" : trbvh ? "TRBVH" : "LBVH",
           collapse ? ", collapsed" : "", outdir);
    return 0;
}
