/*
 * io.c - saving and loading a BVH in the atrbvh(5) file format, and
 * comparing two BVHs.
 *
 * The format is little-endian, written and read byte by byte (so the code
 * is the same on any host):
 *
 *   offset  size  field
 *        0     8  magic "ATRBVH\0\n"
 *        8     4  u32 format version (1)
 *       12     4  u32 header size (96)
 *       16     4  u32 flags (0; any set bit is rejected)
 *       20     4  u32 method (0 lbvh, 1 trbvh, 2 atrbvh)
 *       24     4  u32 treelet size
 *       28     4  u32 rounds
 *       32     8  u64 node count N
 *       40     8  u64 primitive index count P
 *       48     8  u64 primitives in the input (before invalid ones were
 *                 left out): every primitive index is below it
 *       56     8  f64 ci
 *       64     8  f64 ct
 *       72     8  f64 SAH cost as built (informative)
 *       80     4  u32 backend (0 cpu, 1 opencl)
 *       84     4  u32 reserved, 0
 *       88     8  u64 reserved, 0
 *       96  32*N  nodes: f32 min[3], f32 max[3], u32 index, u32 count
 *   96+32N   4*P  primitive indices, u32
 *   ...        4  u32 CRC-32 (IEEE 802.3, as zlib's crc32) of every byte
 *                 before it
 *
 * Loading trusts nothing: the size the counts imply (computed without
 * overflow) must equal the data's size before anything is allocated, and
 * nothing allocated is larger than the data.  Then the checksum, then the
 * structure (see check_body).
 */
#include "config.h"

#include "internal.h"

#include <errno.h>
#include <stdarg.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define FILE_VERSION 1u
#define HEADER_SIZE 96u
#define NODE_SIZE 32u
#define CRC_SIZE 4u

static const unsigned char file_magic[8] = {'A', 'T', 'R', 'B',
                                            'V', 'H', '\0', '\n'};

/* ------------------------------------------------------------- CRC-32 */
static const uint32_t crc_table[256] = {
    0x00000000u, 0x77073096u, 0xee0e612cu, 0x990951bau, 0x076dc419u, 0x706af48fu,
    0xe963a535u, 0x9e6495a3u, 0x0edb8832u, 0x79dcb8a4u, 0xe0d5e91eu, 0x97d2d988u,
    0x09b64c2bu, 0x7eb17cbdu, 0xe7b82d07u, 0x90bf1d91u, 0x1db71064u, 0x6ab020f2u,
    0xf3b97148u, 0x84be41deu, 0x1adad47du, 0x6ddde4ebu, 0xf4d4b551u, 0x83d385c7u,
    0x136c9856u, 0x646ba8c0u, 0xfd62f97au, 0x8a65c9ecu, 0x14015c4fu, 0x63066cd9u,
    0xfa0f3d63u, 0x8d080df5u, 0x3b6e20c8u, 0x4c69105eu, 0xd56041e4u, 0xa2677172u,
    0x3c03e4d1u, 0x4b04d447u, 0xd20d85fdu, 0xa50ab56bu, 0x35b5a8fau, 0x42b2986cu,
    0xdbbbc9d6u, 0xacbcf940u, 0x32d86ce3u, 0x45df5c75u, 0xdcd60dcfu, 0xabd13d59u,
    0x26d930acu, 0x51de003au, 0xc8d75180u, 0xbfd06116u, 0x21b4f4b5u, 0x56b3c423u,
    0xcfba9599u, 0xb8bda50fu, 0x2802b89eu, 0x5f058808u, 0xc60cd9b2u, 0xb10be924u,
    0x2f6f7c87u, 0x58684c11u, 0xc1611dabu, 0xb6662d3du, 0x76dc4190u, 0x01db7106u,
    0x98d220bcu, 0xefd5102au, 0x71b18589u, 0x06b6b51fu, 0x9fbfe4a5u, 0xe8b8d433u,
    0x7807c9a2u, 0x0f00f934u, 0x9609a88eu, 0xe10e9818u, 0x7f6a0dbbu, 0x086d3d2du,
    0x91646c97u, 0xe6635c01u, 0x6b6b51f4u, 0x1c6c6162u, 0x856530d8u, 0xf262004eu,
    0x6c0695edu, 0x1b01a57bu, 0x8208f4c1u, 0xf50fc457u, 0x65b0d9c6u, 0x12b7e950u,
    0x8bbeb8eau, 0xfcb9887cu, 0x62dd1ddfu, 0x15da2d49u, 0x8cd37cf3u, 0xfbd44c65u,
    0x4db26158u, 0x3ab551ceu, 0xa3bc0074u, 0xd4bb30e2u, 0x4adfa541u, 0x3dd895d7u,
    0xa4d1c46du, 0xd3d6f4fbu, 0x4369e96au, 0x346ed9fcu, 0xad678846u, 0xda60b8d0u,
    0x44042d73u, 0x33031de5u, 0xaa0a4c5fu, 0xdd0d7cc9u, 0x5005713cu, 0x270241aau,
    0xbe0b1010u, 0xc90c2086u, 0x5768b525u, 0x206f85b3u, 0xb966d409u, 0xce61e49fu,
    0x5edef90eu, 0x29d9c998u, 0xb0d09822u, 0xc7d7a8b4u, 0x59b33d17u, 0x2eb40d81u,
    0xb7bd5c3bu, 0xc0ba6cadu, 0xedb88320u, 0x9abfb3b6u, 0x03b6e20cu, 0x74b1d29au,
    0xead54739u, 0x9dd277afu, 0x04db2615u, 0x73dc1683u, 0xe3630b12u, 0x94643b84u,
    0x0d6d6a3eu, 0x7a6a5aa8u, 0xe40ecf0bu, 0x9309ff9du, 0x0a00ae27u, 0x7d079eb1u,
    0xf00f9344u, 0x8708a3d2u, 0x1e01f268u, 0x6906c2feu, 0xf762575du, 0x806567cbu,
    0x196c3671u, 0x6e6b06e7u, 0xfed41b76u, 0x89d32be0u, 0x10da7a5au, 0x67dd4accu,
    0xf9b9df6fu, 0x8ebeeff9u, 0x17b7be43u, 0x60b08ed5u, 0xd6d6a3e8u, 0xa1d1937eu,
    0x38d8c2c4u, 0x4fdff252u, 0xd1bb67f1u, 0xa6bc5767u, 0x3fb506ddu, 0x48b2364bu,
    0xd80d2bdau, 0xaf0a1b4cu, 0x36034af6u, 0x41047a60u, 0xdf60efc3u, 0xa867df55u,
    0x316e8eefu, 0x4669be79u, 0xcb61b38cu, 0xbc66831au, 0x256fd2a0u, 0x5268e236u,
    0xcc0c7795u, 0xbb0b4703u, 0x220216b9u, 0x5505262fu, 0xc5ba3bbeu, 0xb2bd0b28u,
    0x2bb45a92u, 0x5cb36a04u, 0xc2d7ffa7u, 0xb5d0cf31u, 0x2cd99e8bu, 0x5bdeae1du,
    0x9b64c2b0u, 0xec63f226u, 0x756aa39cu, 0x026d930au, 0x9c0906a9u, 0xeb0e363fu,
    0x72076785u, 0x05005713u, 0x95bf4a82u, 0xe2b87a14u, 0x7bb12baeu, 0x0cb61b38u,
    0x92d28e9bu, 0xe5d5be0du, 0x7cdcefb7u, 0x0bdbdf21u, 0x86d3d2d4u, 0xf1d4e242u,
    0x68ddb3f8u, 0x1fda836eu, 0x81be16cdu, 0xf6b9265bu, 0x6fb077e1u, 0x18b74777u,
    0x88085ae6u, 0xff0f6a70u, 0x66063bcau, 0x11010b5cu, 0x8f659effu, 0xf862ae69u,
    0x616bffd3u, 0x166ccf45u, 0xa00ae278u, 0xd70dd2eeu, 0x4e048354u, 0x3903b3c2u,
    0xa7672661u, 0xd06016f7u, 0x4969474du, 0x3e6e77dbu, 0xaed16a4au, 0xd9d65adcu,
    0x40df0b66u, 0x37d83bf0u, 0xa9bcae53u, 0xdebb9ec5u, 0x47b2cf7fu, 0x30b5ffe9u,
    0xbdbdf21cu, 0xcabac28au, 0x53b39330u, 0x24b4a3a6u, 0xbad03605u, 0xcdd70693u,
    0x54de5729u, 0x23d967bfu, 0xb3667a2eu, 0xc4614ab8u, 0x5d681b02u, 0x2a6f2b94u,
    0xb40bbe37u, 0xc30c8ea1u, 0x5a05df1bu, 0x2d02ef8du,
};

static uint32_t crc32_update(uint32_t crc, const unsigned char *p, size_t n)
{
    size_t i;
    crc = ~crc;
    for (i = 0; i < n; i++)
        crc = crc_table[(crc ^ p[i]) & 0xffu] ^ (crc >> 8);
    return ~crc;
}

/* ------------------------------------------------- little-endian bytes */
static void put_u32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v & 0xffu);
    p[1] = (unsigned char)((v >> 8) & 0xffu);
    p[2] = (unsigned char)((v >> 16) & 0xffu);
    p[3] = (unsigned char)((v >> 24) & 0xffu);
}

static void put_u64(unsigned char *p, uint64_t v)
{
    put_u32(p, (uint32_t)(v & 0xffffffffu));
    put_u32(p + 4, (uint32_t)(v >> 32));
}

static void put_f32(unsigned char *p, float f)
{
    uint32_t v;
    memcpy(&v, &f, sizeof v);
    put_u32(p, v);
}

static void put_f64(unsigned char *p, double d)
{
    uint64_t v;
    memcpy(&v, &d, sizeof v);
    put_u64(p, v);
}

static uint32_t get_u32(const unsigned char *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) |
           ((uint32_t)p[3] << 24);
}

static uint64_t get_u64(const unsigned char *p)
{
    return (uint64_t)get_u32(p) | ((uint64_t)get_u32(p + 4) << 32);
}

static float get_f32(const unsigned char *p)
{
    uint32_t v = get_u32(p);
    float f;
    memcpy(&f, &v, sizeof f);
    return f;
}

static double get_f64(const unsigned char *p)
{
    uint64_t v = get_u64(p);
    double d;
    memcpy(&d, &v, sizeof d);
    return d;
}

/* ---------------------------------------------------------------- save */
static atrbvh_status serialise(const atrbvh_bvh *bvh, unsigned char **data,
                               size_t *size, atrbvh_error *error)
{
    size_t total, nodes_bytes, prims_bytes, i;
    unsigned char *buf, *p;
    uint64_t input;
    if (bvh->node_count == 0 || bvh->prim_count == 0 || !bvh->nodes ||
        !bvh->prim_indices)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "the BVH is empty");
    if (!atrbvh_i_mul_size(bvh->node_count, NODE_SIZE, &nodes_bytes) ||
        !atrbvh_i_mul_size(bvh->prim_count, 4, &prims_bytes) ||
        nodes_bytes > SIZE_MAX - HEADER_SIZE - CRC_SIZE ||
        prims_bytes > SIZE_MAX - HEADER_SIZE - CRC_SIZE - nodes_bytes)
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, (uint64_t)-1,
                             "the BVH (%lu nodes, %lu primitives) is too "
                             "large to save in memory",
                             (unsigned long)bvh->node_count,
                             (unsigned long)bvh->prim_count);
    total = HEADER_SIZE + nodes_bytes + prims_bytes + CRC_SIZE;
    buf = (unsigned char *)atrbvh_i_malloc(total);
    if (!buf)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "out of memory for a %lu-byte BVH file image",
                             (unsigned long)total);
    input = (uint64_t)bvh->stats.primitives + bvh->stats.invalid_skipped;
    if (input < bvh->prim_count)
        input = bvh->prim_count;
    memset(buf, 0, HEADER_SIZE);
    memcpy(buf, file_magic, sizeof file_magic);
    put_u32(buf + 8, FILE_VERSION);
    put_u32(buf + 12, HEADER_SIZE);
    put_u32(buf + 16, 0);
    put_u32(buf + 20, (uint32_t)bvh->stats.method);
    put_u32(buf + 24, bvh->stats.treelet_size);
    put_u32(buf + 28, bvh->stats.rounds);
    put_u64(buf + 32, (uint64_t)bvh->node_count);
    put_u64(buf + 40, (uint64_t)bvh->prim_count);
    put_u64(buf + 48, input);
    put_f64(buf + 56, bvh->stats.ci);
    put_f64(buf + 64, bvh->stats.ct);
    put_f64(buf + 72, bvh->stats.sah);
    put_u32(buf + 80, (uint32_t)bvh->stats.backend);
    p = buf + HEADER_SIZE;
    for (i = 0; i < bvh->node_count; i++, p += NODE_SIZE) {
        const atrbvh_node *n = &bvh->nodes[i];
        int k;
        for (k = 0; k < 3; k++) {
            put_f32(p + 4 * k, n->min[k]);
            put_f32(p + 12 + 4 * k, n->max[k]);
        }
        put_u32(p + 24, n->index);
        put_u32(p + 28, n->count);
    }
    for (i = 0; i < bvh->prim_count; i++, p += 4)
        put_u32(p, bvh->prim_indices[i]);
    put_u32(p, crc32_update(0, buf, total - CRC_SIZE));
    *data = buf;
    *size = total;
    return ATRBVH_OK;
}

atrbvh_status atrbvh_save_memory(const atrbvh_bvh *bvh, void **data,
                                 size_t *size, atrbvh_error *error)
{
    unsigned char *buf = NULL;
    size_t n = 0;
    atrbvh_status st;
    if (data)
        *data = NULL;
    if (size)
        *size = 0;
    if (!bvh || !data || !size)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "atrbvh_save_memory: %s is NULL",
                             !bvh ? "bvh" : !data ? "data" : "size");
    st = serialise(bvh, &buf, &n, error);
    if (st != ATRBVH_OK)
        return st;
    *data = buf;
    *size = n;
    atrbvh_i_clear_error(error);
    return ATRBVH_OK;
}

atrbvh_status atrbvh_save(const atrbvh_bvh *bvh, const char *path,
                          atrbvh_error *error)
{
    unsigned char *buf = NULL;
    size_t n = 0, written;
    atrbvh_status st;
    FILE *f;
    int failed;
    if (!bvh || !path)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "atrbvh_save: %s is NULL", !bvh ? "bvh" : "path");
    st = serialise(bvh, &buf, &n, error);
    if (st != ATRBVH_OK)
        return st;
    errno = 0;
    f = fopen(path, "wb");
    if (!f) {
        int e = errno;
        atrbvh_i_free(buf);
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)-1,
                             "%s: cannot open for writing: %s", path,
                             e ? strerror(e) : "unknown error");
    }
    written = fwrite(buf, 1, n, f);
    failed = written != n;
    if (fclose(f) != 0)
        failed = 1;
    atrbvh_i_free(buf);
    if (failed) {
        int e = errno;
        remove(path);
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)written,
                             "%s: write failed after %lu of %lu bytes: %s",
                             path, (unsigned long)written, (unsigned long)n,
                             e ? strerror(e) : "unknown error");
    }
    atrbvh_i_clear_error(error);
    return ATRBVH_OK;
}

/* ---------------------------------------------------------------- load */
typedef struct file_header {
    uint32_t method, treelet_size, rounds, backend;
    uint64_t node_count, prim_count, input_count;
    double ci, ct, sah;
    uint64_t total; /* the size the counts imply */
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
    if (memcmp(h, file_magic, sizeof file_magic) != 0)
        return FAIL_AT(0, "byte 0: not an atrbvh BVH file (bad magic)");
    version = get_u32(h + 8);
    if (version != FILE_VERSION)
        return FAIL_AT(8, "byte 8: format version %u is not supported "
                          "(this library reads version %u)",
                       version, FILE_VERSION);
    header_size = get_u32(h + 12);
    if (header_size != HEADER_SIZE)
        return FAIL_AT(12, "byte 12: header size %u, version 1 has %u",
                       header_size, HEADER_SIZE);
    flags = get_u32(h + 16);
    if (flags != 0)
        return FAIL_AT(16, "byte 16: unknown flags 0x%08x", flags);
    fh->method = get_u32(h + 20);
    if (fh->method > (uint32_t)ATRBVH_METHOD_ATRBVH)
        return FAIL_AT(20, "byte 20: method %u is not 0, 1 or 2", fh->method);
    fh->treelet_size = get_u32(h + 24);
    fh->rounds = get_u32(h + 28);
    fh->node_count = get_u64(h + 32);
    fh->prim_count = get_u64(h + 40);
    fh->input_count = get_u64(h + 48);
    if (fh->node_count == 0)
        return FAIL_AT(32, "byte 32: node count is 0");
    if (fh->prim_count == 0)
        return FAIL_AT(40, "byte 40: primitive index count is 0");
    if (fh->prim_count > (uint64_t)ATRBVH_MAX_PRIMITIVES)
        return FAIL_AT(40, "byte 40: primitive index count %llu is beyond "
                           "the limit of %llu",
                       (unsigned long long)fh->prim_count,
                       (unsigned long long)ATRBVH_MAX_PRIMITIVES);
    if (fh->node_count > 2 * fh->prim_count - 1)
        return FAIL_AT(32, "byte 32: node count %llu is more than a tree over "
                           "%llu primitives can have (%llu)",
                       (unsigned long long)fh->node_count,
                       (unsigned long long)fh->prim_count,
                       (unsigned long long)(2 * fh->prim_count - 1));
    if (fh->input_count < fh->prim_count ||
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

/* Decodes the body into bvh and checks the structure:
 *  - boxes finite with min <= max;
 *  - depth-first layout: node 0 spans nodes [0, N); an internal node i
 *    spanning [i, e) has its right child r with i + 1 < r < e, its left
 *    subtree spans [i + 1, r) and its right [r, e); a leaf spans exactly
 *    [i, i + 1).  So every node is reached once and N = 2 * leaves - 1;
 *  - every leaf's range lies within the P index slots, no slot is in two
 *    leaves and the leaves cover all P;
 *  - every primitive index is below the input count and none repeats.
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
        for (i = 1; i < p; i++) {
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
    actual = crc32_update(0, d, size - CRC_SIZE);
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
    bvh->stats.primitives = (size_t)fh.prim_count;
    bvh->stats.invalid_skipped = (size_t)(fh.input_count - fh.prim_count);
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
    got = fread(header, 1, sizeof header, f);
    if (got < sizeof header && ferror(f)) {
        fclose(f);
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)got,
                             "%s: read error at byte %lu", path,
                             (unsigned long)got);
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
    got = fread(buf + sizeof header, 1, (size_t)fh.total - sizeof header, f);
    if (got != (size_t)fh.total - sizeof header) {
        int bad = ferror(f);
        fclose(f);
        atrbvh_i_free(buf);
        return atrbvh_i_fail(error, bad ? ATRBVH_ERR_IO : ATRBVH_ERR_FORMAT,
                             (uint64_t)(sizeof header + got),
                             "%s: %s at byte %lu", path,
                             bad ? "read error" : "truncated",
                             (unsigned long)(sizeof header + got));
    }
    fclose(f);
    st = atrbvh_load_memory(buf, (size_t)fh.total, out, error);
    atrbvh_i_free(buf);
    if (st != ATRBVH_OK)
        prefix_path(error, path);
    return st;
}

/* ------------------------------------------------------------- compare */
static int same_bits_f32(float a, float b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

static int same_bits_f64(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

static int differ(atrbvh_error *error, uint64_t index, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int differ(atrbvh_error *error, uint64_t index, const char *fmt, ...)
{
    if (error) {
        va_list ap;
        error->status = ATRBVH_OK;
        error->index = index;
        va_start(ap, fmt);
        vsnprintf(error->text, sizeof error->text, fmt, ap);
        va_end(ap);
    }
    return 1;
}

static int differ_f32(atrbvh_error *error, size_t node, const char *field,
                      int k, float a, float b)
{
    uint32_t ba, bb;
    memcpy(&ba, &a, sizeof ba);
    memcpy(&bb, &b, sizeof bb);
    if (a == b || (a != a && b != b)) /* same value, other bits */
        return differ(error, node,
                      "node %lu differs: %s[%d] %.9g vs %.9g (bits 0x%08lx "
                      "vs 0x%08lx)",
                      (unsigned long)node, field, k, (double)a, (double)b,
                      (unsigned long)ba, (unsigned long)bb);
    return differ(error, node, "node %lu differs: %s[%d] %.9g vs %.9g",
                  (unsigned long)node, field, k, (double)a, (double)b);
}

int atrbvh_compare(const atrbvh_bvh *a, const atrbvh_bvh *b,
                   atrbvh_error *error)
{
    size_t i;
    if (!a || !b) {
        atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                      "atrbvh_compare: %s is NULL", !a ? "a" : "b");
        return -1;
    }
    if (!same_bits_f64(a->stats.ci, b->stats.ci))
        return differ(error, (uint64_t)-1, "ci differs: %.17g vs %.17g",
                      a->stats.ci, b->stats.ci);
    if (!same_bits_f64(a->stats.ct, b->stats.ct))
        return differ(error, (uint64_t)-1, "ct differs: %.17g vs %.17g",
                      a->stats.ct, b->stats.ct);
    if (a->node_count != b->node_count)
        return differ(error, (uint64_t)-1, "node count differs: %lu vs %lu",
                      (unsigned long)a->node_count,
                      (unsigned long)b->node_count);
    if (a->prim_count != b->prim_count)
        return differ(error, (uint64_t)-1,
                      "primitive index count differs: %lu vs %lu",
                      (unsigned long)a->prim_count,
                      (unsigned long)b->prim_count);
    for (i = 0; i < a->node_count; i++) {
        const atrbvh_node *x = &a->nodes[i], *y = &b->nodes[i];
        int k;
        for (k = 0; k < 3; k++)
            if (!same_bits_f32(x->min[k], y->min[k]))
                return differ_f32(error, i, "min", k, x->min[k], y->min[k]);
        for (k = 0; k < 3; k++)
            if (!same_bits_f32(x->max[k], y->max[k]))
                return differ_f32(error, i, "max", k, x->max[k], y->max[k]);
        if (x->count != y->count)
            return differ(error, i, "node %lu differs: count %lu vs %lu",
                          (unsigned long)i, (unsigned long)x->count,
                          (unsigned long)y->count);
        if (x->index != y->index)
            return differ(error, i, "node %lu differs: %s %lu vs %lu",
                          (unsigned long)i,
                          x->count ? "first primitive" : "right child",
                          (unsigned long)x->index, (unsigned long)y->index);
    }
    for (i = 0; i < a->prim_count; i++)
        if (a->prim_indices[i] != b->prim_indices[i])
            return differ(error, i, "primitive index %lu differs: %lu vs %lu",
                          (unsigned long)i, (unsigned long)a->prim_indices[i],
                          (unsigned long)b->prim_indices[i]);
    atrbvh_i_clear_error(error);
    return 0;
}
