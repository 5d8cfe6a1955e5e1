/*
 * atomicfile.c - writing a file so that nothing is lost (see atomicfile.h
 * for the rules and why each exists).
 */
#define _POSIX_C_SOURCE 200809L
#ifdef HAVE_CONFIG_H
#include "config.h" /* large-file settings, like the rest of the build */
#endif

#include "atomicfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#define MAX_LINK_HOPS 40
/* How much of the target's name the temporary file's name repeats (the
 * whole name could exceed NAME_MAX once decorated). */
#define TMP_BASE_MAX 64
#define TMP_ATTEMPTS 1000 /* names tried before giving up */
/* One write() at most this long (some systems refuse larger counts). */
#define WRITE_CHUNK ((size_t)1 << 30)

enum target_kind { TARGET_NEW, TARGET_REPLACE, TARGET_IN_PLACE };

/* Length of the directory part of `p` including its final '/', or 0 when
 * `p` has none (then the directory is "."). */
static size_t dir_len(const char *p)
{
    const char *slash = strrchr(p, '/');
    return slash ? (size_t)(slash - p) + 1 : 0;
}

static char *copy_string(const char *s, const atrbvh_i_atomicfile_alloc *a)
{
    size_t n = strlen(s) + 1;
    char *d = (char *)a->malloc_fn(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

/* The target of the symbolic link `cur`, as a path (relative links are
 * relative to the link's directory): 0 and *next (allocated), or an
 * errno value.  `size` is lstat's st_size, a hint only. */
static int follow_link(const char *cur, off_t size, char **next,
                       const atrbvh_i_atomicfile_alloc *a)
{
    size_t cap = size > 0 && (uintmax_t)size < 65536u ? (size_t)size + 1 : 256;
    size_t dl;
    char *link;
    ssize_t n;
    for (;;) {
        link = (char *)a->malloc_fn(cap);
        if (!link)
            return ENOMEM;
        n = readlink(cur, link, cap);
        if (n < 0) {
            int e = errno;
            a->free_fn(link);
            return e;
        }
        if ((size_t)n < cap)
            break;
        /* truncated (the link changed since lstat): a larger buffer */
        a->free_fn(link);
        if (cap > (size_t)-1 / 2)
            return ENAMETOOLONG;
        cap *= 2;
    }
    link[n] = '\0';
    dl = link[0] == '/' ? 0 : dir_len(cur);
    *next = (char *)a->malloc_fn(dl + (size_t)n + 1);
    if (!*next) {
        a->free_fn(link);
        return ENOMEM;
    }
    memcpy(*next, cur, dl);
    memcpy(*next + dl, link, (size_t)n + 1);
    a->free_fn(link);
    return 0;
}

/* How `path` is to be written, following symbolic links by hand (so that
 * a link is never replaced by the rename, its target is, and so that
 * /proc's magic links are written in place): 0 and *kind (with *target,
 * allocated, for TARGET_NEW and TARGET_REPLACE; *st the existing file for
 * TARGET_REPLACE), or an errno value. */
static int resolve(const char *path, enum target_kind *kind, char **target,
                   struct stat *st, const atrbvh_i_atomicfile_alloc *a)
{
    struct stat proc_st;
    int have_proc = stat("/proc", &proc_st) == 0;
    char *cur = copy_string(path, a);
    int hops;
    *target = NULL;
    if (!cur)
        return ENOMEM;
    if (!*cur) {
        a->free_fn(cur);
        return ENOENT;
    }
    for (hops = 0;; hops++) {
        char *next = NULL;
        int e;
        if (lstat(cur, st) != 0) {
            e = errno;
            if (e == ENOENT) { /* new (possibly through a dangling link) */
                *kind = TARGET_NEW;
                *target = cur;
                return 0;
            }
            a->free_fn(cur);
            return e;
        }
        if (have_proc && st->st_dev == proc_st.st_dev) {
            /* /proc/self/fd/N and the like: what it names is not ours to
             * replace (stdout redirected to a file is still stdout). */
            a->free_fn(cur);
            *kind = TARGET_IN_PLACE;
            return 0;
        }
        if (!S_ISLNK(st->st_mode))
            break;
        if (hops >= MAX_LINK_HOPS) {
            a->free_fn(cur);
            return ELOOP;
        }
        e = follow_link(cur, st->st_size, &next, a);
        a->free_fn(cur);
        if (e != 0)
            return e;
        cur = next;
    }
    if (S_ISDIR(st->st_mode)) {
        a->free_fn(cur);
        return EISDIR;
    }
    if (!S_ISREG(st->st_mode)) { /* device, FIFO, socket */
        a->free_fn(cur);
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
static int create_temp(const char *target, const void *salt, char **name,
                       const atrbvh_i_atomicfile_alloc *a)
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
    tmp = (char *)a->malloc_fn(cap);
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
            a->free_fn(tmp);
            errno = e;
            return -1;
        }
    }
    a->free_fn(tmp);
    errno = EEXIST;
    return -1;
}

static void release(atomicfile *af, const atrbvh_i_atomicfile_alloc *a)
{
    if (af->target)
        a->free_fn(af->target);
    if (af->tmp)
        a->free_fn(af->tmp);
    af->target = NULL;
    af->tmp = NULL;
    af->fd = -1;
}

int atrbvh_i_atomicfile_begin(atomicfile *af, const char *path, const void *salt,
                     const atrbvh_i_atomicfile_alloc *alloc)
{
    enum target_kind kind = TARGET_NEW;
    struct stat old;
    int e;
    af->fd = -1;
    af->target = NULL;
    af->tmp = NULL;
    e = resolve(path, &kind, &af->target, &old, alloc);
    if (e != 0 || kind == TARGET_IN_PLACE)
        return e;
    if (kind == TARGET_REPLACE && access(af->target, W_OK) != 0 &&
        errno == EACCES) {
        /* a file its owner made read-only is not replaced behind its back */
        release(af, alloc);
        return EACCES;
    }
    af->fd = create_temp(af->target, salt, &af->tmp, alloc);
    if (af->fd < 0) {
        e = errno;
        release(af, alloc);
        return e;
    }
    if (kind == TARGET_REPLACE) { /* the replaced file's owner and mode */
        if (fchown(af->fd, old.st_uid, old.st_gid) != 0) {
            /* not permitted unless root or already the owner: keep ours */
        }
        if (fchmod(af->fd, old.st_mode & 07777) != 0) {
            e = errno;
            atrbvh_i_atomicfile_abort(af, alloc);
            return e;
        }
    }
    return 0;
}

int atrbvh_i_atomicfile_open_in_place(const char *path)
{
    struct stat st;
    int flags = O_WRONLY;
    if (stat(path, &st) == 0 && S_ISREG(st.st_mode))
        flags |= O_APPEND;
    return open(path, flags);
}

int atrbvh_i_atomicfile_write_all(int fd, const void *p, size_t n, size_t *done)
{
    const unsigned char *b = (const unsigned char *)p;
    *done = 0;
    while (*done < n) {
        size_t chunk = n - *done < WRITE_CHUNK ? n - *done : WRITE_CHUNK;
        ssize_t w = write(fd, b + *done, chunk);
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
static void sync_dir(const char *path, const atrbvh_i_atomicfile_alloc *a)
{
    size_t dl = dir_len(path);
    char *dir = (char *)a->malloc_fn(dl + 2);
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
    a->free_fn(dir);
}

int atrbvh_i_atomicfile_commit(atomicfile *af, const atrbvh_i_atomicfile_alloc *alloc)
{
    int e = 0;
    if (!af->tmp) { /* in place: nothing to rename */
        release(af, alloc);
        return 0;
    }
    if (rename(af->tmp, af->target) != 0) {
        e = errno;
        atrbvh_i_atomicfile_abort(af, alloc);
        return e;
    }
    sync_dir(af->target, alloc);
    release(af, alloc);
    return 0;
}

void atrbvh_i_atomicfile_abort(atomicfile *af, const atrbvh_i_atomicfile_alloc *alloc)
{
    if (!af)
        return;
    if (af->fd >= 0)
        close(af->fd);
    if (af->tmp)
        unlink(af->tmp); /* ours: created with O_EXCL */
    release(af, alloc);
}
