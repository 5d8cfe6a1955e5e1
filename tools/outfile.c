/*
 * outfile.c - atomic output files for the atrbvh tool (see outfile.h): a
 * FILE * over lib/atomicfile.c, its error lines, and the removal of
 * temporary files on a fatal signal.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "outfile.h"

#include "cli.h"

#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* ------------------------------------------- cleanup on a fatal signal */
/* The temporary files being written, so that a signal that ends the
 * process (Ctrl-C, kill, SIGXFSZ past a file size limit, a lost terminal)
 * removes them rather than leaving a partial file behind: the handler
 * unlinks each, then removes each that is a folder (the folders made for
 * gnuplot, cli_out_track; both calls async-signal-safe), restores the
 * default action and raises the signal again (after a group's renames,
 * when it comes during them: committing, below).  Room for every file of
 * the largest stage dump (tools/cli_stages.c: 961) with the hard link
 * its commit makes to each target (cli_out_commit_all), and a plot
 * folder. */
#define MAX_ACTIVE 2048
static char *volatile active[MAX_ACTIVE];
/* A child writing into tracked paths (gnuplot), ended and reaped before
 * they are removed: otherwise it could go on writing after the cleanup
 * and leave its folder behind.  0: none. */
static volatile pid_t writer;
static int handlers_installed;
static const int fatal_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT,
                                    SIGXFSZ};

/* A group's renames (cli_out_commit_all) are not cut short by the
 * cleanup: there the renamed targets are new, the others old, and the
 * tracked links hold the old content of the renamed ones, which the
 * cleanup would remove.  While `committing` is set a fatal signal is only
 * noted (`deferred`); the commit, once its renames are all done or all
 * undone, runs the cleanup itself and raises the signal again.  The
 * handler may run on another thread (the tool's OpenMP workers), so the
 * two sides use Dekker's flags with a full fence between the write of
 * one's flag and the read of the other's: either the handler sees
 * `committing`, or the commit sees `handling` (a cleanup under way that
 * is about to end the process) and starts no rename. */
static volatile sig_atomic_t committing, handling, deferred;
#if defined(__GNUC__) || defined(__clang__)
#define OUT_FENCE() __sync_synchronize()
#else
#define OUT_FENCE() ((void)0)
#endif

/* Removes what is tracked (after ending the writer), restores the
 * signal's default action and raises it again. */
static void cleanup_and_raise(int sig)
{
    const pid_t w = writer;
    int i;
    if (w > 0) {
        /* its output is dropped anyway: SIGKILL, which it cannot delay;
         * (a waitpid of the main thread may reap it first: ECHILD) */
        kill(w, SIGKILL);
        while (waitpid(w, NULL, 0) < 0 && errno == EINTR)
            ;
    }
    for (i = 0; i < MAX_ACTIVE; i++) {
        char *t = active[i];
        if (t)
            unlink(t);
    }
    for (i = 0; i < MAX_ACTIVE; i++) {
        char *t = active[i];
        if (t)
            rmdir(t); /* (fails on what was a file: gone already) */
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

static void on_fatal_signal(int sig)
{
    handling = 1;
    OUT_FENCE();
    if (committing) {
        deferred = sig;
        handling = 0;
        return;
    }
    cleanup_and_raise(sig);
}

/* The start and end of a group's renames (see committing above). */
static void renames_begin(void)
{
    committing = 1;
    OUT_FENCE();
    while (handling)
        sleep(1); /* a handler's cleanup is ending the process */
}

static void renames_end(void)
{
    int sig;
    committing = 0;
    OUT_FENCE();
    sig = deferred;
    if (sig)
        cleanup_and_raise(sig);
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

void cli_out_track(char *tmp)
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

void cli_out_track_writer(pid_t pid)
{
    install_handlers();
    writer = pid;
}

void cli_out_untrack(const char *tmp)
{
    int i;
    for (i = 0; tmp && i < MAX_ACTIVE; i++)
        if (active[i] == tmp)
            active[i] = NULL;
}

/* The tool's memory is plain malloc's. */
static const atrbvh_i_atomicfile_alloc out_alloc = {malloc, free};

static char *dup_str(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = (char *)malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

int cli_out_check(const char *path, const char **err)
{
    atomicfile af;
    int e;
    if (!path) {
        if (err)
            *err = strerror(EINVAL);
        return -1;
    }
    /* For a regular target this creates the temporary file and removes it
     * again: the directory is writable and has room for a name. */
    e = atrbvh_i_atomicfile_begin(&af, path, path, &out_alloc);
    if (e == 0 && !af.tmp && access(path, W_OK) != 0)
        e = errno; /* in place */
    if (e == 0)
        atrbvh_i_atomicfile_abort(&af, &out_alloc);
    if (e != 0) {
        if (err)
            *err = strerror(e);
        return -1;
    }
    return 0;
}

FILE *cli_out_open(const char *path, cli_out *h)
{
    int e, fd;
    memset(h, 0, sizeof *h);
    h->af.fd = -1;
    if (!path) {
        cli_error("no output file name");
        return NULL;
    }
    h->name = dup_str(path);
    if (!h->name) {
        cli_error("%s: out of memory", path);
        return NULL;
    }
    e = atrbvh_i_atomicfile_begin(&h->af, path, h, &out_alloc);
    if (e != 0) {
        cli_error("%s: cannot write: %s", path, strerror(e));
        cli_out_abort(h);
        return NULL;
    }
    if (!h->af.tmp) {
        /* In place.  When it is our stdout (/dev/stdout, or stdout
         * redirected to this device or FIFO), write through a duplicate of
         * descriptor 1, so that what the tool prints there and the file
         * share one offset and come out in order. */
        struct stat ps, os;
        fflush(stdout);
        if (stat(path, &ps) == 0 && fstat(STDOUT_FILENO, &os) == 0 &&
            ps.st_dev == os.st_dev && ps.st_ino == os.st_ino)
            fd = dup(STDOUT_FILENO);
        else
            fd = atrbvh_i_atomicfile_open_in_place(path);
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
    cli_out_track(h->af.tmp);
    if (!(h->f = fdopen(h->af.fd, "wb"))) {
        e = errno;
        cli_error("%s: cannot write: %s", path, strerror(e));
        cli_out_abort(h);
        return NULL;
    }
    h->af.fd = -1; /* the FILE * owns it now */
    return h->f;
}

void cli_out_abort(cli_out *h)
{
    if (!h)
        return;
    if (h->f)
        fclose(h->f);
    cli_out_untrack(h->af.tmp);
    atrbvh_i_atomicfile_abort(&h->af, &out_alloc); /* removes only our temporary */
    free(h->name);
    memset(h, 0, sizeof *h);
    h->af.fd = -1;
}

/* The step of a commit that failed, for its message (as the library's
 * atrbvh_save names it). */
enum commit_step { STEP_WRITE, STEP_FSYNC, STEP_CLOSE, STEP_RENAME };
static const char *const step_words[] = {
    "write failed", "written, but flushing it to disk (fsync) failed",
    "written, but closing the file failed",
    "written, but renaming the temporary file over it failed"};

/* Flushes, fsyncs (a temporary file) and closes h's FILE *: 0, or the
 * errno with *step.  The temporary file, if any, stays to be renamed. */
static int finish(cli_out *h, enum commit_step *step)
{
    FILE *f = h->f;
    int e = 0;
    h->f = NULL;
    *step = STEP_WRITE;
    errno = 0; /* ferror alone (an earlier write failed) sets none */
    if (fflush(f) != 0 || ferror(f))
        e = errno ? errno : EIO;
    if (e == 0 && h->af.tmp && fsync(fileno(f)) != 0) {
        e = errno;
        *step = STEP_FSYNC;
    }
    errno = 0;
    if (fclose(f) != 0 && e == 0) {
        e = errno ? errno : EIO;
        *step = STEP_CLOSE;
    }
    return e;
}

/* A group's way back (cli_out_commit_all): for each file renamed in
 * place, what puts its target back as it was should a later rename of
 * the group fail.  `old`: a hard link to the target made before the first
 * rename (beside it, named after the temporary file, tracked for the
 * signal handler), renamed back over it; NULL with `fresh` when there was
 * no target (the renamed file is ours to remove), NULL without when the
 * link could not be made (a file system without hard links: that target
 * cannot be put back). */
typedef struct undo {
    char *target, *old;
    int fresh;
} undo;

/* The links for h[0..n-1], made before any rename; 0, or -1 when out of
 * memory (nothing made).  A link that cannot be made is not an error:
 * only that file's way back is lost. */
static int undo_prepare(const cli_out *h, size_t n, undo *u)
{
    size_t i;
    for (i = 0; i < n; i++) {
        const atomicfile *af = &h[i].af;
        size_t len;
        if (!af->tmp)
            continue; /* in place: written already, nothing to put back */
        len = strlen(af->tmp);
        u[i].target = dup_str(af->target);
        u[i].old = (char *)malloc(len + sizeof ".old");
        if (!u[i].target || !u[i].old)
            return -1;
        memcpy(u[i].old, af->tmp, len);
        memcpy(u[i].old + len, ".old", sizeof ".old");
        if (link(af->target, u[i].old) == 0) {
            cli_out_track(u[i].old);
            continue;
        }
        u[i].fresh = errno == ENOENT;
        free(u[i].old);
        u[i].old = NULL;
    }
    return 0;
}

/* Frees u[0..n-1] and removes their links, but for those of the first
 * `kept` entries: after undo_apply(u, kept), a link still there is one
 * that could not be renamed back, and holds the old content.  (The links
 * from `kept` on are those of the failed rename and after: their targets
 * were not touched.) */
static void undo_release(undo *u, size_t n, size_t kept)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (u[i].old && i >= kept) {
            cli_out_untrack(u[i].old);
            unlink(u[i].old);
        }
        free(u[i].old);
        free(u[i].target);
        u[i].old = u[i].target = NULL;
    }
}

/* Puts the targets of u[0..done-1] back as they were, last first.  The
 * number that could not be: a target with no link, or whose link or new
 * file could not be renamed or removed (the old content then stays in its
 * link, named in *kept, and is not removed). */
static size_t undo_apply(undo *u, size_t done, const char **kept)
{
    size_t i = done, lost = 0;
    *kept = NULL;
    while (i-- > 0) {
        if (!u[i].target)
            continue;
        if (u[i].old) {
            if (rename(u[i].old, u[i].target) == 0) {
                cli_out_untrack(u[i].old);
                free(u[i].old);
                u[i].old = NULL;
                continue;
            }
            cli_out_untrack(u[i].old); /* the old content: keep it */
            *kept = u[i].old;
            lost++;
        } else if (!u[i].fresh || unlink(u[i].target) != 0) {
            lost++;
        }
    }
    return lost;
}

int cli_out_commit_all(cli_out *h, size_t n)
{
    enum commit_step step = STEP_WRITE;
    size_t i, bad = n, lost = 0;
    const char *kept = NULL;
    undo *u = NULL;
    int e = 0, nomem = 0;
    for (i = 0; i < n; i++)
        if (!h[i].f) {
            cli_error("%s: not open for writing",
                      h[i].name ? h[i].name : "?");
            cli_out_abort_all(h, n);
            return -1;
        }
    /* Everything that can fail for want of room or an I/O error, for
     * every file, before any target is replaced. */
    for (i = 0; i < n && bad == n; i++)
        if ((e = finish(&h[i], &step)) != 0)
            bad = i;
    /* A group of several: the way back, should a rename fail part way */
    if (bad == n && n > 1 &&
        (!(u = (undo *)calloc(n, sizeof *u)) || undo_prepare(h, n, u))) {
        nomem = 1;
        bad = 0;
    }
    /* From the first rename to the last link's removal a fatal signal
     * waits (renames_begin): the group ends all new, or all as it was as
     * far as a failed rename's way back allows, and only then does the
     * signal end the process. */
    renames_begin();
    for (i = 0; i < n && bad == n; i++) {
        /* From here the temporary name is the target's: no longer ours
         * to remove on a signal. */
        cli_out_untrack(h[i].af.tmp);
        if ((e = atrbvh_i_atomicfile_commit(&h[i].af, &out_alloc)) != 0) {
            step = STEP_RENAME;
            bad = i;
            break;
        }
        free(h[i].name);
        memset(&h[i], 0, sizeof h[i]);
        h[i].af.fd = -1;
    }
    if (u && bad < n)
        lost = undo_apply(u, bad, &kept);
    if (bad < n) {
        /* what became of the files renamed before the failed one */
        char back[112] = "";
        if (u && bad > 0 && lost == 0)
            snprintf(back, sizeof back, "; the %s before it put back",
                     bad == 1 ? "file" : "files");
        else if (u && bad > 0 && lost == bad)
            snprintf(back, sizeof back, "; the %s before it could not be "
                     "put back", bad == 1 ? "file" : "files");
        else if (u && bad > 0)
            snprintf(back, sizeof back, "; %lu of the %lu files before it "
                     "could not be put back", (unsigned long)lost,
                     (unsigned long)bad);
        if (nomem)
            cli_error("%s: out of memory", h[bad].name);
        else
            cli_error("%s: %s: %s%s%s%s%s", h[bad].name, step_words[step],
                      strerror(e), back,
                      kept ? " (an old one is kept as " : "",
                      kept ? kept : "", kept ? ")" : "");
    }
    if (u) {
        undo_release(u, n, bad < n ? bad : 0);
        free(u);
    }
    renames_end();
    if (bad < n) {
        cli_out_abort_all(h, n);
        return -1;
    }
    return 0;
}

int cli_out_commit(cli_out *h)
{
    if (!h) {
        cli_error("?: not open for writing");
        return -1;
    }
    return cli_out_commit_all(h, 1);
}

void cli_out_abort_all(cli_out *h, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        cli_out_abort(&h[i]);
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
