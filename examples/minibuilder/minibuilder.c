/*
 * minibuilder.c - a small, independent LBVH builder in plain C99 that
 * writes its stage outputs in the format of atrbvh-stages(7), so that
 * `atrbvh check` can compare it with the reference stage by stage.
 *
 * It does not link libatrbvh: every rule below is written from
 * docs/stages.md (bounds, Morton keys in the host frame, a stable sort,
 * Karras' hierarchy with the index tie rule, refit with SAH costs).
 * Only LBVH without collapsing: the stages bounds, morton, sort,
 * hierarchy and refit.
 *
 *   minibuilder --scene FILE.obj [N]   writes a test scene: an N x N grid
 *                                      of quads, each triangle twice (equal
 *                                      Morton keys on purpose)
 *   minibuilder FILE.obj DIR           builds and dumps to DIR
 *
 * Built with -DPLANTED_BUG, the sort breaks ties between equal keys by
 * the larger primitive index first (an unstable GPU radix sort does
 * this): `atrbvh check` then names the sort stage and the first wrong
 * item.
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
#ifdef PLANTED_BUG
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

int main(int argc, char **argv)
{
    const double ci = 1.2, ct = 1.0;
    float *v;
    uint32_t *tri, *order, *tmp, *left, *right, *parent, *count, *leaf;
    size_t nv, nt, i;
    int64_t n;
    box *prim, scene = empty_box(), cent = empty_box(), *nb;
    uint64_t *keys, *sorted;
    double frame[6], *cost;
    int k;
    char path[1024];

    if (argc >= 3 && strcmp(argv[1], "--scene") == 0) {
        write_scene(argv[2], argc > 3 ? atoi(argv[3]) : 24);
        return 0;
    }
    if (argc != 3)
        die("usage: minibuilder FILE.obj DIR | --scene FILE.obj [N]");
    read_obj(argv[1], &v, &nv, &tri, &nt);
    if (nt == 0)
        die("no triangles");
    n = (int64_t)nt;
    outdir = argv[2];

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
    /* hierarchy: internal 0 .. n-2 (root 0), leaves n-1 .. 2n-2 */
    left = xmalloc(nt * sizeof *left);
    right = xmalloc(nt * sizeof *right);
    parent = xmalloc(2 * nt * sizeof *parent);
    count = xmalloc(2 * nt * sizeof *count);
    leaf = xmalloc(nt * sizeof *leaf);
    parent[0] = 0xffffffffu;
    for (i = 0; i + 1 < nt; i++) {
        karras(sorted, n, (int64_t)i, &left[i], &right[i]);
        parent[left[i]] = parent[right[i]] = (uint32_t)i;
    }
    for (i = 0; i < nt; i++)
        leaf[i] = order[i];
    /* refit: bottom-up in post-order (a child's index may be larger or
     * smaller than its parent's), children before their parent */
    nb = xmalloc(2 * nt * sizeof *nb);
    cost = xmalloc(2 * nt * sizeof *cost);
    for (i = 0; i < nt; i++) {
        size_t node = (size_t)n - 1 + i;
        nb[node] = prim[order[i]];
        count[node] = 1;
        cost[node] = ct * area(nb[node]);
    }
    if (nt > 1) {
        uint32_t *stack = xmalloc(2 * nt * sizeof *stack);
        unsigned char *done = calloc(nt, 1);
        size_t sp = 0;
        if (!done)
            die("out of memory");
        stack[sp++] = 0;
        while (sp) {
            uint32_t node = stack[sp - 1], l = left[node], r = right[node];
            int ready = 1;
            if (!done[node]) {
                if (l < nt - 1 && !done[l]) {
                    stack[sp++] = l;
                    ready = 0;
                }
                if (r < nt - 1 && !done[r]) {
                    stack[sp++] = r;
                    ready = 0;
                }
                if (!ready)
                    continue;
                nb[node] = merge(nb[l], nb[r]);
                count[node] = count[l] + count[r];
                cost[node] = ci * area(nb[node]);
                cost[node] = cost[node] + cost[l];
                cost[node] = cost[node] + cost[r];
                done[node] = 1;
            }
            sp--;
        }
        free(stack);
        free(done);
    }

    snprintf(path, sizeof path, "%s/manifest.json", outdir);
    manifest = fopen(path, "w");
    if (!manifest)
        die("cannot write the manifest (does DIR exist?)");
    fprintf(manifest,
            "{\n  \"format\": \"atrbvh-stages\",\n  \"version\": 1,\n"
            "  \"scene\": {\"name\": \"%s\", \"triangles\": %lu},\n"
            "  \"options\": {\"method\": \"lbvh\", \"ci\": 1.2, \"ct\": 1,"
            " \"collapse\": false, \"max_leaf_size\": 0},\n"
            "  \"stages\": [",
            argv[1], (unsigned long)nt);
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
    {
        static const char *const names[2] = {"hierarchy", "refit"};
        int s;
        for (s = 0; s < 2; s++) {
            stage_begin(names[s], 0);
            npy(names[s], "left", "<u4", nt - 1, 0, left, 4);
            npy(names[s], "right", "<u4", nt - 1, 0, right, 4);
            npy(names[s], "parent", "<u4", 2 * nt - 1, 0, parent, 4);
            npy(names[s], "count", "<u4", 2 * nt - 1, 0, count, 4);
            npy(names[s], "leaf_prim", "<u4", nt, 0, leaf, 4);
            if (s == 1) {
                npy(names[s], "box", "<f4", 2 * nt - 1, 6, nb, 4);
                npy(names[s], "cost", "<f8", 2 * nt - 1, 0, cost, 8);
            }
            stage_end();
        }
    }
    fprintf(manifest, "\n  ]\n}\n");
    if (fclose(manifest) != 0)
        die("cannot write the manifest");
    printf("minibuilder: %lu triangles, 5 stages written to %s\n",
           (unsigned long)nt, outdir);
    free(v);
    free(tri);
    free(prim);
    free(keys);
    free(order);
    free(tmp);
    free(sorted);
    free(left);
    free(right);
    free(parent);
    free(count);
    free(leaf);
    free(nb);
    free(cost);
    return 0;
}
