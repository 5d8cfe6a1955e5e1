/*
 * save.c - a BVH to the atrbvh(5) file format: in memory, or to a file
 * written so that nothing is lost (a temporary file beside the target,
 * renamed over it only when complete).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "format.h"
#include "internal.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

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
    memcpy(buf, FILE_MAGIC, FILE_MAGIC_SIZE);
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
/* Nothing is lost: a regular file (or a new one) is written to a temporary
 * file in the target's directory, fsync'ed and renamed over the target
 * only when complete; a failure removes only that temporary file.  Symbolic
 * links are followed (the link stays, the file it names is replaced).  A
 * target that is not a regular file (a device, a FIFO, a socket, or
 * anything reached through /proc's magic links such as /dev/stdout) is
 * written in place and never removed.  The path given is never removed. */

enum target_kind { TARGET_NEW, TARGET_REPLACE, TARGET_IN_PLACE };

#define MAX_LINK_HOPS 40
#define TMP_BASE_MAX 64   /* of the target's name, in the temporary's */
#define TMP_ATTEMPTS 1000 /* names tried before giving up */
#define WRITE_CHUNK ((size_t)1 << 30)

/* Length of the directory part of `p` with its final '/', 0 for none. */
static size_t dir_len(const char *p)
{
    const char *slash = strrchr(p, '/');
    return slash ? (size_t)(slash - p) + 1 : 0;
}

static char *copy_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = (char *)atrbvh_i_malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

/* How `path` is to be written, following symbolic links by hand: 0 and
 * *kind (with *target, allocated, for TARGET_NEW and TARGET_REPLACE; *st
 * the existing file for TARGET_REPLACE), or an errno value. */
static int resolve_target(const char *path, enum target_kind *kind,
                          char **target, struct stat *st)
{
    struct stat proc_st;
    int have_proc = stat("/proc", &proc_st) == 0;
    char *cur = copy_string(path);
    int hops;
    *target = NULL;
    if (!cur)
        return ENOMEM;
    if (!*cur) {
        atrbvh_i_free(cur);
        return ENOENT;
    }
    for (hops = 0;; hops++) {
        char *link, *next;
        ssize_t n;
        size_t cap, dl;
        if (lstat(cur, st) != 0) {
            int e = errno;
            if (e == ENOENT) { /* new (possibly through a dangling link) */
                *kind = TARGET_NEW;
                *target = cur;
                return 0;
            }
            atrbvh_i_free(cur);
            return e;
        }
        if (have_proc && st->st_dev == proc_st.st_dev) {
            /* /proc/self/fd/N: what it names is not the library's to
             * replace (stdout redirected to a file is still stdout). */
            atrbvh_i_free(cur);
            *kind = TARGET_IN_PLACE;
            return 0;
        }
        if (!S_ISLNK(st->st_mode))
            break;
        if (hops >= MAX_LINK_HOPS) {
            atrbvh_i_free(cur);
            return ELOOP;
        }
        cap = st->st_size > 0 && (uintmax_t)st->st_size < 65536u
                  ? (size_t)st->st_size + 1
                  : 4096;
        link = (char *)atrbvh_i_malloc(cap);
        if (!link) {
            atrbvh_i_free(cur);
            return ENOMEM;
        }
        n = readlink(cur, link, cap);
        if (n < 0 || (size_t)n >= cap) {
            int e = n < 0 ? errno : ENAMETOOLONG;
            atrbvh_i_free(link);
            atrbvh_i_free(cur);
            return e;
        }
        link[n] = '\0';
        dl = link[0] == '/' ? 0 : dir_len(cur);
        next = (char *)atrbvh_i_malloc(dl + (size_t)n + 1);
        if (!next) {
            atrbvh_i_free(link);
            atrbvh_i_free(cur);
            return ENOMEM;
        }
        memcpy(next, cur, dl);
        memcpy(next + dl, link, (size_t)n + 1);
        atrbvh_i_free(link);
        atrbvh_i_free(cur);
        cur = next;
    }
    if (S_ISDIR(st->st_mode)) {
        atrbvh_i_free(cur);
        return EISDIR;
    }
    if (!S_ISREG(st->st_mode)) {
        atrbvh_i_free(cur);
        *kind = TARGET_IN_PLACE;
        return 0;
    }
    *kind = TARGET_REPLACE;
    *target = cur;
    return 0;
}

/* Creates a new temporary file beside `target` (O_EXCL, so nothing that
 * exists is ever opened; mode 0666 less the umask): its descriptor and
 * *name, or -1 with errno set. */
static int create_temp(const char *target, const void *salt, char **name)
{
    size_t dl = dir_len(target), bl = strlen(target) - dl, cap;
    unsigned long pid = (unsigned long)getpid();
    unsigned long mix = (unsigned long)(uintptr_t)salt;
    char *tmp;
    int attempt;
    *name = NULL;
    if (bl > TMP_BASE_MAX)
        bl = TMP_BASE_MAX;
    cap = dl + 1 + bl + 64;
    tmp = (char *)atrbvh_i_malloc(cap);
    if (!tmp) {
        errno = ENOMEM;
        return -1;
    }
    memcpy(tmp, target, dl);
    tmp[dl] = '.';
    memcpy(tmp + dl + 1, target + dl, bl);
    for (attempt = 0; attempt < TMP_ATTEMPTS; attempt++) {
        int fd;
        mix = mix * 6364136223846793005ul + 1442695040888963407ul +
              (unsigned long)attempt;
        snprintf(tmp + dl + 1 + bl, cap - dl - 1 - bl, ".%lu-%08lx.tmp", pid,
                 (mix >> 16) & 0xfffffffful);
        fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL, 0666);
        if (fd >= 0) {
            *name = tmp;
            return fd;
        }
        if (errno != EEXIST) {
            int e = errno;
            atrbvh_i_free(tmp);
            errno = e;
            return -1;
        }
    }
    atrbvh_i_free(tmp);
    errno = EEXIST;
    return -1;
}

/* Writes n bytes; 0, or an errno value with *done the bytes written. */
static int write_all(int fd, const unsigned char *p, size_t n, size_t *done)
{
    *done = 0;
    while (*done < n) {
        size_t chunk = n - *done < WRITE_CHUNK ? n - *done : WRITE_CHUNK;
        ssize_t w = write(fd, p + *done, chunk);
        if (w < 0) {
            if (errno == EINTR)
                continue;
            return errno;
        }
        if (w == 0)
            return EIO;
        *done += (size_t)w;
    }
    return 0;
}

/* fsync of the directory holding `path` so that the rename lasts; best
 * effort (some file systems refuse it; the rename is atomic anyway). */
static void sync_dir(const char *path)
{
    size_t dl = dir_len(path);
    char *dir = (char *)atrbvh_i_malloc(dl + 2);
    int fd;
    if (!dir)
        return;
    if (dl == 0)
        strcpy(dir, ".");
    else {
        memcpy(dir, path, dl);
        dir[dl] = '\0';
    }
    fd = open(dir, O_RDONLY);
    if (fd >= 0) {
        if (fsync(fd) != 0) {
            /* ignored: see above */
        }
        close(fd);
    }
    atrbvh_i_free(dir);
}

static atrbvh_status io_fail(atrbvh_error *error, const char *path,
                             size_t written, size_t total, int e)
{
    if (e == ENOMEM) /* ours (create_temp, resolve_target) or the OS's */
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "%s: out of memory writing it", path);
    if (written == 0 && total == 0)
        return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)-1,
                             "%s: cannot write: %s", path, strerror(e));
    return atrbvh_i_fail(error, ATRBVH_ERR_IO, (uint64_t)written,
                         "%s: write failed after %lu of %lu bytes: %s", path,
                         (unsigned long)written, (unsigned long)total,
                         strerror(e));
}

/* In place, for what is not a regular file of ours to replace.  Not
 * truncated (a device or FIFO has nothing to truncate; a regular file
 * reached through /dev/stdout is appended to, as the shell opened it). */
static atrbvh_status write_in_place(const char *path, const unsigned char *buf,
                                    size_t n, atrbvh_error *error)
{
    struct stat st;
    int flags = O_WRONLY, fd, e;
    size_t done = 0;
    if (stat(path, &st) == 0 && S_ISREG(st.st_mode))
        flags |= O_APPEND;
    fd = open(path, flags);
    if (fd < 0)
        return io_fail(error, path, 0, 0, errno);
    e = write_all(fd, buf, n, &done);
    if (close(fd) != 0 && e == 0)
        e = errno;
    if (e != 0)
        return io_fail(error, path, done, n, e);
    return ATRBVH_OK;
}

static atrbvh_status write_replacing(const char *path, const char *target,
                                     const struct stat *old,
                                     const unsigned char *buf, size_t n,
                                     atrbvh_error *error)
{
    char *tmp = NULL;
    size_t done = 0;
    int fd, e;
    if (old && access(target, W_OK) != 0 && errno == EACCES)
        /* a file its owner made read-only is not replaced behind its back */
        return io_fail(error, path, 0, 0, EACCES);
    fd = create_temp(target, buf, &tmp);
    if (fd < 0)
        return io_fail(error, path, 0, 0, errno);
    e = 0;
    if (old) { /* the replaced file's owner (when permitted) and mode */
        if (fchown(fd, old->st_uid, old->st_gid) != 0) {
            /* not permitted: the file is ours */
        }
        if (fchmod(fd, old->st_mode & 07777) != 0)
            e = errno;
    }
    if (e == 0)
        e = write_all(fd, buf, n, &done);
    if (e == 0 && fsync(fd) != 0)
        e = errno;
    if (close(fd) != 0 && e == 0)
        e = errno;
    if (e == 0 && rename(tmp, target) != 0)
        e = errno;
    if (e != 0) {
        unlink(tmp); /* ours: created with O_EXCL above */
        atrbvh_i_free(tmp);
        return io_fail(error, path, done, n, e);
    }
    atrbvh_i_free(tmp);
    sync_dir(target);
    return ATRBVH_OK;
}

atrbvh_status atrbvh_save(const atrbvh_bvh *bvh, const char *path,
                          atrbvh_error *error)
{
    unsigned char *buf = NULL;
    size_t n = 0;
    atrbvh_status st;
    enum target_kind kind = TARGET_NEW;
    char *target = NULL;
    struct stat old;
    int e;
    if (!bvh || !path)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "atrbvh_save: %s is NULL", !bvh ? "bvh" : "path");
    st = serialise(bvh, &buf, &n, error);
    if (st != ATRBVH_OK)
        return st;
    e = resolve_target(path, &kind, &target, &old);
    if (e != 0)
        st = io_fail(error, path, 0, 0, e);
    else if (kind == TARGET_IN_PLACE)
        st = write_in_place(path, buf, n, error);
    else
        st = write_replacing(path, target, kind == TARGET_REPLACE ? &old : NULL,
                             buf, n, error);
    atrbvh_i_free(target);
    atrbvh_i_free(buf);
    if (st == ATRBVH_OK)
        atrbvh_i_clear_error(error);
    return st;
}
