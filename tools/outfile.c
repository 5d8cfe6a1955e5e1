/*
 * outfile.c - atomic output files for the atrbvh tool (see outfile.h).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "outfile.h"

#include "cli.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#define MAX_LINK_HOPS 40
/* How much of the target's name the temporary file's name repeats (the
 * whole name could exceed NAME_MAX once decorated). */
#define TMP_BASE_MAX 64

/* ------------------------------------------- cleanup on a fatal signal */
/* The temporary files being written, so that a signal that ends the
 * process (Ctrl-C, kill, SIGXFSZ past a file size limit, a lost terminal)
 * removes them rather than leaving a partial file behind: the handler
 * unlinks each (async-signal-safe), restores the default action and
 * raises the signal again. */
#define MAX_ACTIVE 16
static char *volatile active[MAX_ACTIVE];
static int handlers_installed;
static const int fatal_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT,
                                    SIGXFSZ};

static void on_fatal_signal(int sig)
{
    int i;
    for (i = 0; i < MAX_ACTIVE; i++) {
        char *t = active[i];
        if (t)
            unlink(t);
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

static void install_handlers(void)
{
    size_t i;
    if (handlers_installed)
        return;
    handlers_installed = 1;
    for (i = 0; i < sizeof fatal_signals / sizeof *fatal_signals; i++) {
        struct sigaction sa, old;
        /* A signal the caller ignores (trap '' XFSZ: writes then fail with
         * EFBIG instead) stays ignored. */
        if (sigaction(fatal_signals[i], NULL, &old) != 0 ||
            old.sa_handler == SIG_IGN)
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_fatal_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(fatal_signals[i], &sa, NULL);
    }
}

static void track(char *tmp)
{
    int i;
    install_handlers();
    for (i = 0; i < MAX_ACTIVE; i++)
        if (!active[i]) {
            active[i] = tmp;
            return;
        }
    /* more than MAX_ACTIVE at once: still written, just not cleaned up on
     * a signal */
}

static void untrack(const char *tmp)
{
    int i;
    for (i = 0; tmp && i < MAX_ACTIVE; i++)
        if (active[i] == tmp)
            active[i] = NULL;
}

static char *dup_str(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = (char *)malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

/* Length of the directory part of `p` including its final '/', or 0 when
 * `p` has none (then the directory is "."). */
static size_t dir_len(const char *p)
{
    const char *slash = strrchr(p, '/');
    return slash ? (size_t)(slash - p) + 1 : 0;
}

/* How a path is to be written. */
enum out_kind { OUT_NEW, OUT_REPLACE, OUT_IN_PLACE };

typedef struct resolved {
    enum out_kind kind;
    char *target;   /* OUT_NEW/OUT_REPLACE: the path to rename over */
    struct stat st; /* OUT_REPLACE: the existing target */
} resolved;

/* Follows symbolic links by hand, so that a link is never replaced by the
 * rename (its target is) and so that /proc's magic links (/dev/stdout ->
 * /proc/self/fd/1 -> whatever stdout is, even a regular file opened by the
 * shell) are written in place, not replaced.  0, or an errno value. */
static int resolve(const char *path, resolved *r)
{
    struct stat proc_st, st;
    int have_proc = stat("/proc", &proc_st) == 0;
    char *cur = dup_str(path);
    int hops;
    r->target = NULL;
    if (!cur)
        return ENOMEM;
    if (!*cur) {
        free(cur);
        return ENOENT;
    }
    for (hops = 0;; hops++) {
        char *link, *next;
        ssize_t n;
        size_t cap, dl;
        if (lstat(cur, &st) != 0) {
            int e = errno;
            if (e == ENOENT) { /* a new file (possibly a dangling link's) */
                r->kind = OUT_NEW;
                r->target = cur;
                return 0;
            }
            free(cur);
            return e;
        }
        if (have_proc && st.st_dev == proc_st.st_dev) {
            /* /proc/self/fd/N and the like: whatever it names is not ours
             * to replace. */
            free(cur);
            r->kind = OUT_IN_PLACE;
            return 0;
        }
        if (!S_ISLNK(st.st_mode))
            break;
        if (hops >= MAX_LINK_HOPS) {
            free(cur);
            return ELOOP;
        }
        cap = st.st_size > 0 ? (size_t)st.st_size + 1 : 256;
        for (;;) {
            link = (char *)malloc(cap);
            if (!link) {
                free(cur);
                return ENOMEM;
            }
            n = readlink(cur, link, cap);
            if (n < 0) {
                int e = errno;
                free(link);
                free(cur);
                return e;
            }
            if ((size_t)n < cap)
                break;
            free(link);
            if (cap > (size_t)-1 / 2) {
                free(cur);
                return ENAMETOOLONG;
            }
            cap *= 2;
        }
        link[n] = '\0';
        dl = link[0] == '/' ? 0 : dir_len(cur);
        next = (char *)malloc(dl + (size_t)n + 1);
        if (!next) {
            free(link);
            free(cur);
            return ENOMEM;
        }
        memcpy(next, cur, dl);
        memcpy(next + dl, link, (size_t)n + 1);
        free(link);
        free(cur);
        cur = next;
    }
    if (S_ISDIR(st.st_mode)) {
        free(cur);
        return EISDIR;
    }
    if (!S_ISREG(st.st_mode)) { /* device, FIFO, socket */
        free(cur);
        r->kind = OUT_IN_PLACE;
        return 0;
    }
    r->kind = OUT_REPLACE;
    r->target = cur;
    r->st = st;
    return 0;
}

/* Creates the temporary file beside `target`: its descriptor, or -1 with
 * errno set; *tmp_out the name (malloc'ed). */
static int make_temp(const char *target, char **tmp_out)
{
    size_t dl = dir_len(target), bl = strlen(target) - dl;
    const char *suffix = ".tmpXXXXXX";
    char *tmp;
    int fd;
    *tmp_out = NULL;
    if (bl > TMP_BASE_MAX)
        bl = TMP_BASE_MAX;
    tmp = (char *)malloc(dl + 1 + bl + strlen(suffix) + 1);
    if (!tmp) {
        errno = ENOMEM;
        return -1;
    }
    memcpy(tmp, target, dl);
    tmp[dl] = '.';
    memcpy(tmp + dl + 1, target + dl, bl);
    strcpy(tmp + dl + 1 + bl, suffix);
    fd = mkstemp(tmp);
    if (fd < 0) {
        int e = errno;
        free(tmp);
        errno = e;
        return -1;
    }
    *tmp_out = tmp;
    return fd;
}

static mode_t new_file_mode(void)
{
    mode_t mask = umask(0);
    umask(mask);
    return (mode_t)(0666 & ~mask);
}

int cli_out_check(const char *path, const char **err)
{
    resolved r;
    int e, fd;
    char *tmp;
    if (!path) {
        if (err)
            *err = strerror(EINVAL);
        return -1;
    }
    e = resolve(path, &r);
    if (e == 0 && r.kind == OUT_IN_PLACE) {
        if (access(path, W_OK) != 0)
            e = errno;
    } else if (e == 0) {
        if (r.kind == OUT_REPLACE && access(r.target, W_OK) != 0 &&
            errno == EACCES)
            e = EACCES; /* a read-only file is not replaced behind its back */
        else if ((fd = make_temp(r.target, &tmp)) < 0)
            e = errno;
        else {
            close(fd);
            unlink(tmp);
            free(tmp);
        }
        free(r.target);
    }
    if (e != 0) {
        if (err)
            *err = strerror(e);
        return -1;
    }
    return 0;
}

FILE *cli_out_open(const char *path, cli_out *h)
{
    resolved r;
    int e, fd;
    memset(h, 0, sizeof *h);
    if (!path) {
        cli_error("no output file name");
        return NULL;
    }
    h->name = dup_str(path);
    if (!h->name) {
        cli_error("%s: out of memory", path);
        return NULL;
    }
    e = resolve(path, &r);
    if (e != 0) {
        cli_error("%s: cannot write: %s", path, strerror(e));
        cli_out_abort(h);
        return NULL;
    }
    if (r.kind == OUT_IN_PLACE) {
        /* No O_CREAT, no O_TRUNC: it exists and is not ours to replace.
         * When it is our stdout (/dev/stdout, or stdout redirected to this
         * device or FIFO), write through a duplicate of descriptor 1, so
         * that what the tool prints there and the file share one offset
         * and come out in order; a regular file reached through /proc (a
         * redirection) is appended to, never overwritten from byte 0. */
        struct stat ps, os;
        fflush(stdout);
        if (stat(path, &ps) == 0 && fstat(STDOUT_FILENO, &os) == 0 &&
            ps.st_dev == os.st_dev && ps.st_ino == os.st_ino)
            fd = dup(STDOUT_FILENO);
        else
            fd = open(path, O_WRONLY | (stat(path, &ps) == 0 &&
                                                S_ISREG(ps.st_mode)
                                            ? O_APPEND
                                            : 0));
        if (fd < 0 || !(h->f = fdopen(fd, "wb"))) {
            e = errno;
            if (fd >= 0)
                close(fd);
            cli_error("%s: cannot write: %s", path, strerror(e));
            cli_out_abort(h);
            return NULL;
        }
        return h->f;
    }
    h->target = r.target;
    if (r.kind == OUT_REPLACE && access(r.target, W_OK) != 0 &&
        errno == EACCES) {
        cli_error("%s: cannot write: %s", path, strerror(EACCES));
        cli_out_abort(h);
        return NULL;
    }
    fd = make_temp(r.target, &h->tmp);
    if (fd < 0) {
        e = errno;
        cli_error("%s: cannot write: %s", path, strerror(e));
        cli_out_abort(h);
        return NULL;
    }
    track(h->tmp);
    /* mkstemp makes 0600: give the file the mode (and, when permitted, the
     * owner) the target has, or a new file's mode. */
    if (r.kind == OUT_REPLACE) {
        if (fchown(fd, r.st.st_uid, r.st.st_gid) != 0) {
            /* not permitted unless root or already the owner: keep ours */
        }
        e = fchmod(fd, r.st.st_mode & 07777);
    } else {
        e = fchmod(fd, new_file_mode());
    }
    if (e != 0 || !(h->f = fdopen(fd, "wb"))) {
        e = errno;
        close(fd);
        cli_error("%s: cannot write: %s", path, strerror(e));
        cli_out_abort(h);
        return NULL;
    }
    return h->f;
}

static void release(cli_out *h)
{
    untrack(h->tmp);
    free(h->name);
    free(h->target);
    free(h->tmp);
    memset(h, 0, sizeof *h);
}

void cli_out_abort(cli_out *h)
{
    if (!h)
        return;
    if (h->f)
        fclose(h->f);
    untrack(h->tmp);
    if (h->tmp)
        unlink(h->tmp); /* ours: mkstemp made it */
    release(h);
}

/* fsync of the directory holding `path`, so that the rename is durable;
 * best effort (some file systems refuse it). */
static void sync_dir(const char *path)
{
    size_t dl = dir_len(path);
    char *dir = (char *)malloc(dl + 2);
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
            /* not supported here: the rename is still atomic */
        }
        close(fd);
    }
    free(dir);
}

int cli_out_commit(cli_out *h)
{
    int e = 0;
    FILE *f;
    if (!h || !h->f) {
        cli_error("%s: not open for writing", h && h->name ? h->name : "?");
        if (h)
            cli_out_abort(h);
        return -1;
    }
    f = h->f;
    h->f = NULL;
    if (fflush(f) != 0 || ferror(f))
        e = errno ? errno : EIO;
    if (e == 0 && h->tmp && fsync(fileno(f)) != 0)
        e = errno;
    if (fclose(f) != 0 && e == 0)
        e = errno ? errno : EIO;
    if (e == 0 && h->tmp) {
        /* From here the temporary name is the target's: no longer ours to
         * remove on a signal. */
        untrack(h->tmp);
        if (rename(h->tmp, h->target) != 0)
            e = errno;
    }
    if (e != 0) {
        cli_error("%s: write failed: %s", h->name, strerror(e));
        cli_out_abort(h);
        return -1;
    }
    if (h->tmp)
        sync_dir(h->target);
    release(h);
    return 0;
}

int cli_out_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    if (!a || !b || stat(a, &sa) != 0 || stat(b, &sb) != 0)
        return 0;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

int cli_out_usable(const char *output, const char *input)
{
    const char *why = NULL;
    if (input && cli_out_same_file(output, input)) {
        cli_error("%s: the output is the input '%s'; refusing to overwrite "
                  "it",
                  output, input);
        return -1;
    }
    if (cli_out_check(output, &why) != 0) {
        cli_error("%s: cannot write: %s", output, why);
        return -1;
    }
    return 0;
}
