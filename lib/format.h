/*
 * format.h - the atrbvh(5) file format's layout, shared by save.c and
 * load.c: constants, the checksum and little-endian byte order.
 *
 * The format is little-endian, written and read byte by byte (so the code
 * is the same on any host):
 *
 *   offset  size  field
 *        0     8  magic "ATRBVH\0\n"
 *        8     4  u32 format version (1 or 2)
 *       12     4  u32 header size (96)
 *       16     4  u32 flags: version 1 has none (0); version 2 may set
 *                 FILE_FLAG_SPLIT; any other set bit is rejected
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
 * Version 2 is version 1 plus the flags.  FILE_FLAG_SPLIT: a tree built
 * with triangle splitting, whose leaves may reference one primitive more
 * than once between them (never twice in one leaf); the input count at
 * byte 48 is then the input's primitive count, not the index count's
 * bound.  A tree without splitting is written as version 1, which every
 * reader takes; version 1 files load as before.
 *
 * Loading trusts nothing: the size the counts imply (computed without
 * overflow) must equal the data's size before anything is allocated, and
 * nothing allocated is larger than the data.  Then the checksum, then the
 * structure (load.c, decode_body).
 */
#ifndef ATRBVH_FORMAT_H
#define ATRBVH_FORMAT_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define FILE_VERSION 1u       /* a tree without splitting            */
#define FILE_VERSION_SPLIT 2u /* the newest version this library reads */
#define FILE_FLAG_SPLIT 1u    /* version 2: references may repeat      */
#define HEADER_SIZE 96u
#define NODE_SIZE 32u
#define CRC_SIZE 4u
/* The 8-byte magic (the literal's terminating NUL is not part of it). */
#define FILE_MAGIC "ATRBVH\0\n"
#define FILE_MAGIC_SIZE 8u

/* CRC-32 (IEEE 802.3, as zlib's crc32) of n bytes, continuing from crc
 * (0 to start); crc32.c. */
uint32_t atrbvh_i_crc32(uint32_t crc, const unsigned char *p, size_t n);

/* ------------------------------------------------- little-endian bytes */
static inline void put_u32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v & 0xffu);
    p[1] = (unsigned char)((v >> 8) & 0xffu);
    p[2] = (unsigned char)((v >> 16) & 0xffu);
    p[3] = (unsigned char)((v >> 24) & 0xffu);
}

static inline void put_u64(unsigned char *p, uint64_t v)
{
    put_u32(p, (uint32_t)(v & 0xffffffffu));
    put_u32(p + 4, (uint32_t)(v >> 32));
}

static inline void put_f32(unsigned char *p, float f)
{
    uint32_t v;
    memcpy(&v, &f, sizeof v);
    put_u32(p, v);
}

static inline void put_f64(unsigned char *p, double d)
{
    uint64_t v;
    memcpy(&v, &d, sizeof v);
    put_u64(p, v);
}

static inline uint32_t get_u32(const unsigned char *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) |
           ((uint32_t)p[3] << 24);
}

static inline uint64_t get_u64(const unsigned char *p)
{
    return (uint64_t)get_u32(p) | ((uint64_t)get_u32(p + 4) << 32);
}

static inline float get_f32(const unsigned char *p)
{
    uint32_t v = get_u32(p);
    float f;
    memcpy(&f, &v, sizeof f);
    return f;
}

static inline double get_f64(const unsigned char *p)
{
    uint64_t v = get_u64(p);
    double d;
    memcpy(&d, &v, sizeof d);
    return d;
}

#endif
