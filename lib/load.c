/*
 * load.c - a BVH from the atrbvh(5) file format (format.h), in memory or
 * from a file.  Loading trusts nothing: the size the header's counts imply
 * must equal the data's size before anything is allocated, then the
 * checksum, then the tree's structure (decode_body).
 */
#include "config.h"

#include "format.h"
#include "internal.h"
#include "shared/treelet.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct file_header {
    uint32_t method, treelet_size, rounds, backend;
    uint64_t node_count, prim_count, input_count;
    double ci, ct, sah;
    uint64_t total; /* the size the counts imply */
    int split;      /* version 2, FILE_FLAG_SPLIT: references may repeat */
} file_header;

#define FAIL_AT(off, ...)                                                      \
    atrbvh_i_fail(error, ATRBVH_ERR_FORMAT, (uint64_t)(off), __VA_ARGS__)

/* Parses and checks the fixed header; `have` bytes of it are present (at
 * least the 96 bytes), `size` is the size of the whole data. */
static atrbvh_status parse_header(const unsigned char *h, uint64_t size,
                                  file_header *fh, atrbvh_error *error)
{
    uint32_t version, header_size, flags;
    uint64_t nodes_bytes, prims_bytes;
    if (size < HEADER_SIZE)
        return FAIL_AT(size,
                       "truncated: %llu bytes, less than the %u-byte header",
                       (unsigned long long)size, HEADER_SIZE);
    if (memcmp(h, FILE_MAGIC, FILE_MAGIC_SIZE) != 0)
        return FAIL_AT(0, "byte 0: not an atrbvh BVH file (bad magic)");
    version = get_u32(h + 8);
    if (version != FILE_VERSION && version != FILE_VERSION_SPLIT)
        return FAIL_AT(8, "byte 8: format version %u is not supported "
                          "(this library reads versions %u and %u)",
                       version, FILE_VERSION, FILE_VERSION_SPLIT);
    header_size = get_u32(h + 12);
    if (header_size != HEADER_SIZE)
        return FAIL_AT(12, "byte 12: header size %u, version %u has %u",
                       header_size, version, HEADER_SIZE);
    flags = get_u32(h + 16);
    if (version == FILE_VERSION ? flags != 0 : (flags & ~FILE_FLAG_SPLIT) != 0)
        return FAIL_AT(16, "byte 16: unknown flags 0x%08x for version %u",
                       flags, version);
    /* One encoding per tree: a tree without splitting is version 1, so a
     * version 2 file has the split flag (and saving what was loaded gives
     * the same bytes back). */
    if (version == FILE_VERSION_SPLIT && !(flags & FILE_FLAG_SPLIT))
        return FAIL_AT(16, "byte 16: version 2 without the split flag (a "
                           "tree without splitting is version 1)");
    fh->split = (flags & FILE_FLAG_SPLIT) != 0;
    fh->method = get_u32(h + 20);
    if (fh->method > (uint32_t)ATRBVH_METHOD_ATRBVH)
        return FAIL_AT(20, "byte 20: method %u is not 0, 1 or 2", fh->method);
    fh->treelet_size = get_u32(h + 24);
    fh->rounds = get_u32(h + 28);
    /* what a build records (api.c resolves 0 to the method's default):
     * LBVH 0 and 0; TRBVH 3 to 10; ATRBVH 3 to 128 or auto; 1 to 64
     * rounds */
    if (fh->method == (uint32_t)ATRBVH_METHOD_LBVH
            ? fh->treelet_size != 0
            : fh->method == (uint32_t)ATRBVH_METHOD_TRBVH
                  ? fh->treelet_size < ATRBVH_TRBVH_MIN ||
                        fh->treelet_size > ATRBVH_TRBVH_MAX
                  : fh->treelet_size != ATRBVH_TREELET_AUTO &&
                        (fh->treelet_size < ATRBVH_ATRBVH_MIN ||
                         fh->treelet_size > ATRBVH_ATRBVH_MAX))
        return FAIL_AT(24, "byte 24: treelet size %u is not one a build of "
                           "method %u records (LBVH 0, TRBVH %u to %u, "
                           "ATRBVH %u to %u or 0x%08x)",
                       fh->treelet_size, fh->method, ATRBVH_TRBVH_MIN,
                       ATRBVH_TRBVH_MAX, ATRBVH_ATRBVH_MIN,
                       ATRBVH_ATRBVH_MAX, ATRBVH_TREELET_AUTO);
    if (fh->method == (uint32_t)ATRBVH_METHOD_LBVH
            ? fh->rounds != 0
            : fh->rounds < 1 || fh->rounds > ATRBVH_ROUNDS_MAX)
        return FAIL_AT(28, "byte 28: %u rounds is not what a build of "
                           "method %u records (LBVH 0, else 1 to %u)",
                       fh->rounds, fh->method, ATRBVH_ROUNDS_MAX);
    fh->node_count = get_u64(h + 32);
    fh->prim_count = get_u64(h + 40);
    fh->input_count = get_u64(h + 48);
    if (fh->node_count == 0)
        return FAIL_AT(32, "byte 32: node count is 0");
    if (fh->prim_count == 0)
        return FAIL_AT(40, "byte 40: primitive index count is 0");
    /* a split tree's references: below 2^31 (2P - 1 nodes fit u32) */
    if (fh->prim_count > (fh->split ? (uint64_t)0x7fffffffu
                                    : (uint64_t)ATRBVH_MAX_PRIMITIVES))
        return FAIL_AT(40, "byte 40: primitive index count %llu is beyond "
                           "the limit of %llu",
                       (unsigned long long)fh->prim_count,
                       (unsigned long long)(fh->split
                                                ? (uint64_t)0x7fffffffu
                                                : (uint64_t)
                                                      ATRBVH_MAX_PRIMITIVES));
    if (fh->node_count > 2 * fh->prim_count - 1)
        return FAIL_AT(32, "byte 32: node count %llu is more than a tree over "
                           "%llu primitives can have (%llu)",
                       (unsigned long long)fh->node_count,
                       (unsigned long long)fh->prim_count,
                       (unsigned long long)(2 * fh->prim_count - 1));
    if ((!fh->split && fh->input_count < fh->prim_count) ||
        fh->input_count == 0 ||
        fh->input_count > (uint64_t)ATRBVH_MAX_PRIMITIVES)
        return FAIL_AT(48, "byte 48: input primitive count %llu is not "
                           "between the index count %llu and %llu",
                       (unsigned long long)fh->input_count,
                       (unsigned long long)fh->prim_count,
                       (unsigned long long)ATRBVH_MAX_PRIMITIVES);
    /* Counts are bounded above, so these cannot overflow; checked anyway. */
    if (fh->node_count > UINT64_MAX / NODE_SIZE ||
        fh->prim_count > UINT64_MAX / 4)
        return FAIL_AT(32, "byte 32: counts overflow");
    nodes_bytes = fh->node_count * NODE_SIZE;
    prims_bytes = fh->prim_count * 4;
    if (nodes_bytes > UINT64_MAX - HEADER_SIZE - CRC_SIZE - prims_bytes)
        return FAIL_AT(32, "byte 32: counts overflow");
    fh->total = HEADER_SIZE + nodes_bytes + prims_bytes + CRC_SIZE;
    if (fh->total != size)
        return FAIL_AT(size < fh->total ? size : fh->total,
                       "%s: the counts (%llu nodes, %llu primitive indices) "
                       "make a %llu-byte file, the data has %llu bytes",
                       size < fh->total ? "truncated" : "trailing data",
                       (unsigned long long)fh->node_count,
                       (unsigned long long)fh->prim_count,
                       (unsigned long long)fh->total,
                       (unsigned long long)size);
    fh->ci = get_f64(h + 56);
    fh->ct = get_f64(h + 64);
    fh->sah = get_f64(h + 72);
    if (!(fh->ci > 0.0 && fh->ci <= 1e30))
        return FAIL_AT(56, "byte 56: ci %g is not positive and finite",
                       fh->ci);
    if (!(fh->ct > 0.0 && fh->ct <= 1e30))
        return FAIL_AT(64, "byte 64: ct %g is not positive and finite",
                       fh->ct);
    if (!(fh->sah >= 0.0 && fh->sah <= 1e300))
        return FAIL_AT(72, "byte 72: SAH %g is not finite and >= 0", fh->sah);
    fh->backend = get_u32(h + 80);
    if (fh->backend > (uint32_t)ATRBVH_BACKEND_OPENCL)
        return FAIL_AT(80, "byte 80: backend %u is not 0 or 1", fh->backend);
    if (get_u32(h + 84) != 0)
        return FAIL_AT(84, "byte 84: reserved field is not 0");
    if (get_u64(h + 88) != 0)
        return FAIL_AT(88, "byte 88: reserved field is not 0");
    return ATRBVH_OK;
}

/* In-place heapsort (no allocation) of `n` values. */
static void sift_down(uint32_t *a, size_t root, size_t n)
{
    for (;;) {
        size_t child = 2 * root + 1;
        uint32_t t;
        if (child >= n)
            return;
        if (child + 1 < n && a[child + 1] > a[child])
            child++;
        if (a[root] >= a[child])
            return;
        t = a[root];
        a[root] = a[child];
        a[child] = t;
        root = child;
    }
}

static void heapsort_u32(uint32_t *a, size_t n)
{
    size_t i;
    if (n < 2)
        return;
    for (i = n / 2; i-- > 0;)
        sift_down(a, i, n);
    for (i = n - 1; i > 0; i--) {
        uint32_t t = a[0];
        a[0] = a[i];
        a[i] = t;
        sift_down(a, 0, i);
    }
}

#define BIT_GET(b, i) (((b)[(i) >> 3] >> ((i)&7u)) & 1u)
#define BIT_SET(b, i) ((b)[(i) >> 3] |= (unsigned char)(1u << ((i)&7u)))

/* A split tree (FILE_FLAG_SPLIT): no leaf lists a primitive twice.  Each
 * leaf's range sorted in a copy of the P indices (no larger than the
 * data). */
static atrbvh_status split_leaves(const atrbvh_bvh *bvh, size_t p,
                                  atrbvh_error *error)
{
    uint32_t *copy = (uint32_t *)atrbvh_i_alloc_array(p, sizeof *copy);
    atrbvh_status st = ATRBVH_OK;
    size_t i, j;
    if (!copy)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "out of memory checking %lu primitive indices",
                             (unsigned long)p);
    memcpy(copy, bvh->prim_indices, p * sizeof *copy);
    for (i = 0; i < bvh->node_count && st == ATRBVH_OK; i++) {
        const atrbvh_node *nd = &bvh->nodes[i];
        if (!nd->count)
            continue;
        heapsort_u32(copy + nd->index, nd->count);
        for (j = 1; j < nd->count; j++)
            if (copy[nd->index + j] == copy[nd->index + j - 1]) {
                st = FAIL_AT(HEADER_SIZE + (uint64_t)i * NODE_SIZE,
                             "node %lu: leaf lists primitive %lu twice",
                             (unsigned long)i,
                             (unsigned long)copy[nd->index + j]);
                break;
            }
    }
    atrbvh_i_free(copy);
    return st;
}

/* Decodes the body into bvh and checks the structure:
 *  - boxes finite with min <= max;
 *  - depth-first layout: node 0 spans nodes [0, N); an internal node i
 *    spanning [i, e) has its right child r with i + 1 < r < e, its left
 *    subtree spans [i + 1, r) and its right [r, e); a leaf spans exactly
 *    [i, i + 1).  So every node is reached once and N = 2 * leaves - 1;
 *  - every leaf's range lies within the P index slots, no slot is in two
 *    leaves and the leaves cover all P;
 *  - every primitive index is below the input count and none repeats
 *    (a split tree: none repeats within one leaf; bvh->split_prims gets
 *    the number of distinct primitives).
 * Scratch: N u32 (subtree ends) and two bitmaps, each no larger than the
 * data itself. */
static atrbvh_status decode_body(const unsigned char *data,
                                 const file_header *fh, atrbvh_bvh *bvh,
                                 atrbvh_error *error)
{
    size_t n = (size_t)fh->node_count, p = (size_t)fh->prim_count;
    size_t input = (size_t)fh->input_count;
    size_t i, leaves = 0;
    uint64_t covered = 0;
    const unsigned char *q = data + HEADER_SIZE;
    uint32_t *end = NULL;
    unsigned char *slots = NULL, *seen = NULL;
    atrbvh_status st = ATRBVH_OK;
    int ids_by_bitmap = input / 8 <= fh->total;
    size_t distinct = 0;

    end = (uint32_t *)atrbvh_i_alloc_array(n, sizeof *end);
    slots = (unsigned char *)atrbvh_i_malloc(p / 8 + 1);
    if (!end || !slots) {
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                           "out of memory checking a BVH of %lu nodes",
                           (unsigned long)n);
        goto done;
    }
    memset(end, 0, n * sizeof *end);
    memset(slots, 0, p / 8 + 1);
    end[0] = (uint32_t)n; /* n <= 2^31 - 1 */

    for (i = 0; i < n; i++, q += NODE_SIZE) {
        atrbvh_node *nd = &bvh->nodes[i];
        uint64_t off = HEADER_SIZE + (uint64_t)i * NODE_SIZE;
        int k;
        for (k = 0; k < 3; k++) {
            nd->min[k] = get_f32(q + 4 * k);
            nd->max[k] = get_f32(q + 12 + 4 * k);
        }
        nd->index = get_u32(q + 24);
        nd->count = get_u32(q + 28);
        for (k = 0; k < 3; k++) {
            if (!isfinite(nd->min[k]) || !isfinite(nd->max[k])) {
                st = FAIL_AT(off, "node %lu at byte %llu: %s[%d] is not "
                                  "finite",
                             (unsigned long)i, (unsigned long long)off,
                             isfinite(nd->min[k]) ? "max" : "min", k);
                goto done;
            }
            if (nd->min[k] > nd->max[k]) {
                st = FAIL_AT(off, "node %lu at byte %llu: min[%d] %.9g is "
                                  "above max[%d] %.9g",
                             (unsigned long)i, (unsigned long long)off, k,
                             (double)nd->min[k], k, (double)nd->max[k]);
                goto done;
            }
        }
        if (end[i] == 0) { /* cannot happen: the parent set it */
            st = FAIL_AT(off, "node %lu at byte %llu: not reached from the "
                              "root",
                         (unsigned long)i, (unsigned long long)off);
            goto done;
        }
        if (nd->count == 0) {
            uint32_t r = nd->index;
            if (!((size_t)r > i + 1 && r < end[i])) {
                st = FAIL_AT(off + 24,
                             "node %lu at byte %llu: right child %lu out of "
                             "range (the subtree spans nodes %lu..%lu, so "
                             "it must be in %lu..%lu)",
                             (unsigned long)i, (unsigned long long)off,
                             (unsigned long)r, (unsigned long)i,
                             (unsigned long)end[i] - 1, (unsigned long)i + 2,
                             (unsigned long)end[i] - 1);
                goto done;
            }
            end[i + 1] = r;
            end[r] = end[i];
        } else {
            uint64_t first = nd->index, last = first + nd->count;
            size_t s;
            if (end[i] != i + 1) {
                st = FAIL_AT(off + 28,
                             "node %lu at byte %llu: a leaf, but its subtree "
                             "should span nodes %lu..%lu",
                             (unsigned long)i, (unsigned long long)off,
                             (unsigned long)i, (unsigned long)end[i] - 1);
                goto done;
            }
            if (last > p) {
                st = FAIL_AT(off + 24,
                             "node %lu at byte %llu: leaf range %llu..%llu "
                             "beyond the %lu primitive indices",
                             (unsigned long)i, (unsigned long long)off,
                             (unsigned long long)first,
                             (unsigned long long)last - 1, (unsigned long)p);
                goto done;
            }
            for (s = (size_t)first; s < (size_t)last; s++) {
                if (BIT_GET(slots, s)) {
                    st = FAIL_AT(off + 24,
                                 "node %lu at byte %llu: leaf range "
                                 "%llu..%llu overlaps another leaf's (index "
                                 "slot %lu)",
                                 (unsigned long)i, (unsigned long long)off,
                                 (unsigned long long)first,
                                 (unsigned long long)last - 1,
                                 (unsigned long)s);
                    goto done;
                }
                BIT_SET(slots, s);
            }
            covered += nd->count;
            leaves++;
        }
    }
    if (covered != p) {
        st = FAIL_AT(HEADER_SIZE,
                     "the leaves reference %llu of the %lu primitive index "
                     "slots",
                     (unsigned long long)covered, (unsigned long)p);
        goto done;
    }
    if (n != 2 * leaves - 1) { /* implied by the walk; kept as a guard */
        st = FAIL_AT(32, "byte 32: %lu nodes for %lu leaves (need %lu)",
                     (unsigned long)n, (unsigned long)leaves,
                     (unsigned long)(2 * leaves - 1));
        goto done;
    }

    /* primitive indices */
    if (ids_by_bitmap) {
        seen = (unsigned char *)atrbvh_i_malloc(input / 8 + 1);
        if (!seen) {
            st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                               "out of memory checking %lu primitive indices",
                               (unsigned long)p);
            goto done;
        }
        memset(seen, 0, input / 8 + 1);
    }
    for (i = 0; i < p; i++, q += 4) {
        uint64_t off = HEADER_SIZE + fh->node_count * NODE_SIZE + 4 * (uint64_t)i;
        uint32_t v = get_u32(q);
        bvh->prim_indices[i] = v;
        if ((uint64_t)v >= fh->input_count) {
            st = FAIL_AT(off, "primitive index %lu at byte %llu: %lu is not "
                              "below the primitive count %llu",
                         (unsigned long)i, (unsigned long long)off,
                         (unsigned long)v,
                         (unsigned long long)fh->input_count);
            goto done;
        }
        if (seen) {
            if (fh->split) { /* count the distinct ones */
                if (!BIT_GET(seen, v)) {
                    BIT_SET(seen, v);
                    distinct++;
                }
                continue;
            }
            if (BIT_GET(seen, v)) {
                st = FAIL_AT(off, "primitive index %lu at byte %llu: "
                                  "primitive %lu is referenced twice",
                             (unsigned long)i, (unsigned long long)off,
                             (unsigned long)v);
                goto done;
            }
            BIT_SET(seen, v);
        }
    }
    if (!seen) {
        /* The input count dwarfs the file: sort a copy instead of a bitmap
         * (end[] is free now and has room when n >= p; else allocate). */
        uint32_t *copy = n >= p ? end : (uint32_t *)atrbvh_i_alloc_array(
                                            p, sizeof *copy);
        if (!copy) {
            st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                               "out of memory checking %lu primitive indices",
                               (unsigned long)p);
            goto done;
        }
        memcpy(copy, bvh->prim_indices, p * sizeof *copy);
        heapsort_u32(copy, p);
        for (i = 1; i < p && fh->split; i++) /* count the distinct ones */
            distinct += copy[i] != copy[i - 1];
        if (fh->split)
            distinct++;
        for (i = 1; i < p && !fh->split; i++) {
            if (copy[i] == copy[i - 1]) {
                st = FAIL_AT(HEADER_SIZE + fh->node_count * NODE_SIZE,
                             "primitive %lu is referenced twice",
                             (unsigned long)copy[i]);
                break;
            }
        }
        if (copy != end)
            atrbvh_i_free(copy);
    }
    if (st == ATRBVH_OK && fh->split)
        st = split_leaves(bvh, p, error);
    if (st == ATRBVH_OK && fh->split)
        bvh->split_prims = distinct;
done:
    atrbvh_i_free(end);
    atrbvh_i_free(slots);
    atrbvh_i_free(seen);
    return st;
}

atrbvh_status atrbvh_load_memory(const void *data, size_t size,
                                 atrbvh_bvh **out, atrbvh_error *error)
{
    const unsigned char *d = (const unsigned char *)data;
    file_header fh;
    atrbvh_bvh *bvh;
    atrbvh_status st;
    uint32_t stored, actual;
    if (out)
        *out = NULL;
    if (!out || (!data && size > 0))
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "atrbvh_load_memory: %s is NULL",
                             !out ? "out" : "data");
    if (!data)
        return FAIL_AT(0, "truncated: 0 bytes, less than the %u-byte header",
                       HEADER_SIZE);
    st = parse_header(d, (uint64_t)size, &fh, error);
    if (st != ATRBVH_OK)
        return st;
    stored = get_u32(d + size - CRC_SIZE);
    actual = atrbvh_i_crc32(0, d, size - CRC_SIZE);
    if (stored != actual)
        return FAIL_AT(size - CRC_SIZE,
                       "byte %lu: checksum 0x%08x, the data's is 0x%08x "
                       "(the file is corrupt)",
                       (unsigned long)(size - CRC_SIZE), stored, actual);
    bvh = atrbvh_i_bvh_alloc((size_t)fh.node_count, (size_t)fh.prim_count);
    if (!bvh)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "out of memory for a BVH of %llu nodes",
                             (unsigned long long)fh.node_count);
    st = decode_body(d, &fh, bvh, error);
    if (st != ATRBVH_OK) {
        atrbvh_bvh_free(bvh);
        return st;
    }
    memset(&bvh->stats, 0, sizeof bvh->stats);
    bvh->stats.primitives =
        bvh->split_prims ? bvh->split_prims : (size_t)fh.prim_count;
    bvh->stats.invalid_skipped =
        (size_t)(fh.input_count - (uint64_t)bvh->stats.primitives);
    bvh->stats.ci = fh.ci;
    bvh->stats.ct = fh.ct;
    bvh->stats.method = (atrbvh_method)fh.method;
    bvh->stats.treelet_size = fh.treelet_size;
    bvh->stats.rounds = fh.rounds;
    bvh->stats.backend = (atrbvh_backend)fh.backend;
    bvh->stats.threads = 0;
    st = atrbvh_i_bvh_measure(bvh);
    if (st != ATRBVH_OK) { /* only out of memory, after the checks above */
        atrbvh_bvh_free(bvh);
        return atrbvh_i_fail(error, st, (uint64_t)-1,
                             "%s measuring the loaded BVH",
                             st == ATRBVH_ERR_NOMEM ? "out of memory"
                                                    : "invalid tree");
    }
    *out = bvh;
    atrbvh_i_clear_error(error);
    return ATRBVH_OK;
}

/* Puts "PATH: " before the error text (truncating the text's end). */
static void prefix_path(atrbvh_error *error, const char *path)
{
    size_t cap, pl, tl, shift;
    if (!error)
        return;
    cap = sizeof error->text - 1;
    pl = strlen(path);
    tl = strlen(error->text);
    shift = pl + 2;
    if (shift + 8 > cap)
        return; /* a path that long leaves no room: keep the text */
    if (tl > cap - shift)
        tl = cap - shift;
    memmove(error->text + shift, error->text, tl);
    memcpy(error->text, path, pl);
    error->text[pl] = ':';
    error->text[pl + 1] = ' ';
    error->text[shift + tl] = '\0';
}

atrbvh_status atrbvh_load(const char *path, atrbvh_bvh **out,
                          atrbvh_error *error)
{
    FILE *f;
    unsigned char header[HEADER_SIZE], *buf;
    size_t got;
    long fsize;
    file_header fh;
    atrbvh_status st;
    if (out)
        *out = NULL;
    if (!path || !out)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "atrbvh_load: %s is NULL", !path ? "path" : "out");
    errno = 0;
    f = fopen(path, "rb");
    if (!f) {
        int e = errno;
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)-1,
                             "%s: cannot open: %s", path,
                             e ? strerror(e) : "unknown error");
    }
    if (fseek(f, 0, SEEK_END) != 0 || (fsize = ftell(f)) < 0 ||
        fseek(f, 0, SEEK_SET) != 0) {
        int e = errno;
        fclose(f);
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)-1,
                             "%s: cannot determine the size: %s", path,
                             e ? strerror(e) : "not a regular file");
    }
    /* Check the header against the real size before allocating anything. */
    errno = 0;
    got = fread(header, 1, sizeof header, f);
    if (got < sizeof header && ferror(f)) {
        int e = errno;
        fclose(f);
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)got,
                             "%s: read error at byte %lu: %s", path,
                             (unsigned long)got,
                             e ? strerror(e) : "unknown error");
    }
    /* A file that gives more than its size (a device such as /dev/zero,
     * whose size reads as 0) has no size to check the header against. */
    if ((uint64_t)got > (uint64_t)fsize) {
        fclose(f);
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)-1,
                             "%s: cannot determine the size: not a regular "
                             "file (its size reads as %ld bytes, yet it "
                             "gives more)",
                             path, fsize);
    }
    st = parse_header(header,
                      got < sizeof header ? (uint64_t)got : (uint64_t)fsize,
                      &fh, error);
    if (st != ATRBVH_OK) {
        fclose(f);
        prefix_path(error, path);
        return st;
    }
    buf = (unsigned char *)atrbvh_i_malloc((size_t)fh.total);
    if (!buf) {
        fclose(f);
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "%s: out of memory for %llu bytes", path,
                             (unsigned long long)fh.total);
    }
    memcpy(buf, header, sizeof header);
    errno = 0;
    got = fread(buf + sizeof header, 1, (size_t)fh.total - sizeof header, f);
    if (got != (size_t)fh.total - sizeof header) {
        int e = errno, bad = ferror(f);
        fclose(f);
        atrbvh_i_free(buf);
        if (!bad)
            return atrbvh_i_fail(error, ATRBVH_ERR_FORMAT,
                                 (uint64_t)(sizeof header + got),
                                 "%s: truncated at byte %lu", path,
                                 (unsigned long)(sizeof header + got));
        return atrbvh_i_fail(error, ATRBVH_ERR_IO,
                             (uint64_t)(sizeof header + got),
                             "%s: read error at byte %lu: %s", path,
                             (unsigned long)(sizeof header + got),
                             e ? strerror(e) : "unknown error");
    }
    fclose(f);
    st = atrbvh_load_memory(buf, (size_t)fh.total, out, error);
    atrbvh_i_free(buf);
    if (st != ATRBVH_OK)
        prefix_path(error, path);
    return st;
}
