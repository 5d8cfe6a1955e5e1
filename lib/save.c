/*
 * save.c - a BVH to the atrbvh(5) file format: in memory, or to a file
 * written so that nothing is lost (a temporary file beside the target,
 * renamed over it only when complete).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "atomicfile.h"
#include "format.h"
#include "internal.h"

#include <errno.h>
#include <string.h>
#include <unistd.h>

static atrbvh_status serialise(const atrbvh_bvh *bvh, unsigned char **data,
                               size_t *size, atrbvh_error *error)
{
    size_t total, nodes_bytes, prims_bytes, i;
    unsigned char *buf, *p;
    uint64_t input;
    atrbvh_stats stats;
    atrbvh_status st;
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
    /* the header's statistics, its SAH measured here when the build left
     * it to its first reader (bvh.c) */
    st = atrbvh_i_bvh_stats_of(bvh, &stats);
    if (st != ATRBVH_OK)
        return atrbvh_i_fail(error, st, (uint64_t)-1,
                             "cannot measure the BVH's SAH (%s)",
                             atrbvh_strerror(st));
    total = HEADER_SIZE + nodes_bytes + prims_bytes + CRC_SIZE;
    buf = (unsigned char *)atrbvh_i_malloc(total);
    if (!buf)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "out of memory for a %lu-byte BVH file image",
                             (unsigned long)total);
    input = (uint64_t)stats.primitives + stats.invalid_skipped;
    if (input < bvh->prim_count && !bvh->split_prims)
        input = bvh->prim_count;
    memset(buf, 0, HEADER_SIZE);
    memcpy(buf, FILE_MAGIC, FILE_MAGIC_SIZE);
    /* version 1 unless the tree is split: old readers keep working */
    put_u32(buf + 8, bvh->split_prims ? FILE_VERSION_SPLIT : FILE_VERSION);
    put_u32(buf + 12, HEADER_SIZE);
    put_u32(buf + 16, bvh->split_prims ? FILE_FLAG_SPLIT : 0u);
    put_u32(buf + 20, (uint32_t)stats.method);
    put_u32(buf + 24, stats.treelet_size);
    put_u32(buf + 28, stats.rounds);
    put_u64(buf + 32, (uint64_t)bvh->node_count);
    put_u64(buf + 40, (uint64_t)bvh->prim_count);
    put_u64(buf + 48, input);
    put_f64(buf + 56, stats.ci);
    put_f64(buf + 64, stats.ct);
    put_f64(buf + 72, stats.sah);
    put_u32(buf + 80, (uint32_t)stats.backend);
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
    put_u32(p, atrbvh_i_crc32(0, buf, total - CRC_SIZE));
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

/* ------------------------------------------------------ writing a file */
/* Nothing is lost: lib/atomicfile.c writes a regular file (or a new one)
 * to a temporary file beside it, renamed over it only when complete; a
 * failure removes only that temporary file.  Symbolic links are followed
 * (the link stays, the file it names is replaced).  A target that is not
 * a regular file (a device, a FIFO, a socket, or anything reached through
 * /proc's magic links such as /dev/stdout) is written in place and never
 * removed.  The path given is never removed.  This file keeps the
 * messages. */

/* Every allocation of the library goes through its replaceable allocator
 * (the allocation-failure tests count them). */
static const atrbvh_i_atomicfile_alloc save_alloc = {atrbvh_i_malloc, atrbvh_i_free};

/* What failed, for the message: the file could not be started (resolving
 * the path, the temporary file), written, flushed, closed or renamed
 * into place. */
enum io_step { IO_BEGIN, IO_WRITE, IO_FSYNC, IO_CLOSE, IO_RENAME };

static atrbvh_status io_fail(atrbvh_error *error, const char *path,
                             enum io_step step, size_t written, size_t total,
                             int e)
{
    if (e == ENOMEM) /* ours (the allocator) or the OS's */
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "%s: out of memory writing it", path);
    switch (step) {
    case IO_BEGIN:
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)-1,
                             "%s: cannot write: %s", path, strerror(e));
    case IO_WRITE:
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)written,
                             "%s: write failed after %lu of %lu bytes: %s",
                             path, (unsigned long)written,
                             (unsigned long)total, strerror(e));
    case IO_FSYNC:
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)written,
                             "%s: all %lu bytes written, but flushing them "
                             "to disk (fsync) failed: %s", path,
                             (unsigned long)total, strerror(e));
    case IO_CLOSE:
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)written,
                             "%s: all %lu bytes written, but closing the "
                             "file failed: %s", path, (unsigned long)total,
                             strerror(e));
    default:
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)written,
                             "%s: all %lu bytes written, but renaming the "
                             "temporary file over it failed: %s", path,
                             (unsigned long)total, strerror(e));
    }
}

static atrbvh_status write_file(const char *path, const unsigned char *buf,
                                size_t n, atrbvh_error *error)
{
    atomicfile af;
    size_t done = 0;
    enum io_step step = IO_WRITE;
    int e = atrbvh_i_atomicfile_begin(&af, path, buf, &save_alloc);
    if (e != 0)
        return io_fail(error, path, IO_BEGIN, 0, 0, e);
    if (!af.tmp) { /* in place: not a regular file of ours to replace */
        int fd = atrbvh_i_atomicfile_open_in_place(path);
        atrbvh_i_atomicfile_abort(&af, &save_alloc); /* nothing to remove */
        if (fd < 0)
            return io_fail(error, path, IO_BEGIN, 0, 0, errno);
        e = atrbvh_i_atomicfile_write_all(fd, buf, n, &done);
        if (close(fd) != 0 && e == 0) {
            e = errno;
            step = IO_CLOSE;
        }
        return e != 0 ? io_fail(error, path, step, done, n, e) : ATRBVH_OK;
    }
    e = atrbvh_i_atomicfile_write_all(af.fd, buf, n, &done);
    if (e == 0 && fsync(af.fd) != 0) {
        e = errno;
        step = IO_FSYNC;
    }
    if (close(af.fd) != 0 && e == 0) {
        e = errno;
        step = IO_CLOSE;
    }
    af.fd = -1;
    if (e == 0) {
        e = atrbvh_i_atomicfile_commit(&af, &save_alloc);
        step = IO_RENAME;
    } else {
        atrbvh_i_atomicfile_abort(&af, &save_alloc);
    }
    return e != 0 ? io_fail(error, path, step, done, n, e) : ATRBVH_OK;
}

atrbvh_status atrbvh_save(const atrbvh_bvh *bvh, const char *path,
                          atrbvh_error *error)
{
    unsigned char *buf = NULL;
    size_t n = 0;
    atrbvh_status st;
    if (!bvh || !path)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "atrbvh_save: %s is NULL", !bvh ? "bvh" : "path");
    st = serialise(bvh, &buf, &n, error);
    if (st != ATRBVH_OK)
        return st;
    st = write_file(path, buf, n, error);
    atrbvh_i_free(buf);
    if (st == ATRBVH_OK)
        atrbvh_i_clear_error(error);
    return st;
}
