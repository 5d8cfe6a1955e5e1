/*
 * gnuplot.c - gnuplot started with fork/execvp (no shell: a folder name
 * can hold any character) and waited for, writing into a folder of its
 * own (see gnuplot.h).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"
#include "gnuplot.h"
#include "outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* The private folder's name in the plot folder (mkdtemp's template). */
#define SUB_TEMPLATE ".atrbvh-gnuplot-XXXXXX"
#define LOG_NAME "gnuplot.log"

/* gnuplot run in `dir` with outdir = 'sub/' and its stderr in
 * sub/gnuplot.log.  0 when it exited 0, else -1 after the error line. */
static int run(const char *dir, const char *script, const char *sub)
{
    char outdir[64], log[64];
    pid_t pid, got;
    int st, e;
    snprintf(outdir, sizeof outdir, "outdir = '%s/'", sub);
    snprintf(log, sizeof log, "%s/" LOG_NAME, sub);
    fflush(NULL);
    pid = fork();
    if (pid < 0) {
        cli_error("%s/%s: cannot start gnuplot: %s", dir, script,
                  strerror(errno));
        return -1;
    }
    if (pid == 0) {
        char *argv[5];
        int fd;
        if (chdir(dir) != 0)
            _exit(126);
        /* (sub is new and ours: O_EXCL) */
        fd = open(log, O_WRONLY | O_CREAT | O_EXCL, 0666);
        if (fd >= 0) {
            dup2(fd, STDERR_FILENO);
            close(fd);
        }
        fd = open("/dev/null", O_RDONLY);
        if (fd >= 0) {
            dup2(fd, STDIN_FILENO);
            close(fd);
        }
        argv[0] = (char *)"gnuplot";
        argv[1] = (char *)"-e";
        argv[2] = outdir;
        argv[3] = (char *)script;
        argv[4] = NULL;
        execvp(argv[0], argv);
        _exit(127);
    }
    cli_out_track_writer(pid);
    while ((got = waitpid(pid, &st, 0)) < 0 && errno == EINTR)
        ;
    e = errno;
    cli_out_track_writer(0);
    if (got < 0) {
        cli_error("%s/%s: waiting for gnuplot: %s", dir, script,
                  strerror(e));
        return -1;
    }
    if (WIFEXITED(st) && WEXITSTATUS(st) == 127) {
        cli_error("%s/%s: gnuplot not found (install gnuplot to get the "
                  "pictures; the data and script are there)", dir, script);
        return -1;
    }
    if (!WIFEXITED(st) || WEXITSTATUS(st) != 0) {
        cli_error("%s/%s: gnuplot failed (see %s/" LOG_NAME ")", dir,
                  script, dir);
        return -1;
    }
    return 0;
}

/* Moves `from` (in the private folder) over `to`: synced first, and
 * only a regular file, or nothing, replaced.  0, or the errno (EISDIR for
 * a target that is not a regular file). */
static int put(const char *from, const char *to)
{
    struct stat st;
    int fd, e = 0;
    if (lstat(to, &st) == 0 && !S_ISREG(st.st_mode))
        return EISDIR;
    fd = open(from, O_RDONLY);
    if (fd < 0)
        return errno;
    if (fsync(fd) != 0)
        e = errno;
    if (close(fd) != 0 && e == 0)
        e = errno;
    if (e == 0 && rename(from, to) != 0)
        e = errno;
    return e;
}

/* Frees the n + 1 paths in the private folder, no longer tracked. */
static void free_paths(char **from, size_t n)
{
    size_t k;
    for (k = 0; from && k <= n; k++) {
        cli_out_untrack(from[k]);
        free(from[k]);
    }
    free(from);
}

int cli_gnuplot(const char *dir, const char *script,
                const char *const *names, size_t n)
{
    char *sub_path = cli_join(dir, SUB_TEMPLATE), *to = NULL;
    /* the pictures' paths in the private folder, then the log's */
    char **from = n < (size_t)-1 / sizeof *from - 1
                      ? calloc(n + 1, sizeof *from)
                      : NULL;
    const char *sub;
    size_t k;
    int rc, e;
    if (!sub_path || !from) {
        cli_error("%s: out of memory", dir);
        free(sub_path);
        free(from);
        return -1;
    }
    if (!mkdtemp(sub_path)) {
        cli_error("%s: cannot make a folder for gnuplot's output: %s", dir,
                  strerror(errno));
        free(sub_path);
        free(from);
        return -1;
    }
    /* A fatal signal removes what gnuplot wrote there, then the folder. */
    for (k = 0; k <= n; k++)
        if ((from[k] = cli_join(sub_path, k < n ? names[k] : LOG_NAME)))
            cli_out_track(from[k]);
    cli_out_track(sub_path);
    sub = sub_path + strlen(dir) + 1;
    rc = run(dir, script, sub);
    /* the pictures (dropped after a failure, and after the first that
     * cannot be put in place), then the log, whatever happened */
    for (k = 0; k <= n; k++) {
        const char *name = k < n ? names[k] : LOG_NAME;
        free(to);
        to = cli_join(dir, name);
        if (!from[k] || !to) {
            if (rc == 0)
                cli_error("%s: out of memory", dir);
            rc = -1;
            continue;
        }
        if (rc == 0 || k == n) {
            e = put(from[k], to);
            if (e != 0 && rc == 0) {
                cli_error("%s: %s", to,
                          e == EISDIR ? "not a regular file, not replaced"
                                      : strerror(e));
                rc = -1;
            }
        }
        unlink(from[k]); /* (ENOENT after a rename: nothing to do) */
    }
    free(to);
    free_paths(from, n);
    cli_out_untrack(sub_path);
    if (rmdir(sub_path) != 0 && rc == 0) {
        /* something else was written there: left for the user */
        cli_error("%s: cannot remove gnuplot's folder: %s", sub_path,
                  strerror(errno));
        rc = -1;
    }
    free(sub_path);
    return rc;
}

void cli_gnuplot_string(FILE *g, const char *s)
{
    fputc('\'', g);
    for (; *s; s++) {
        if (*s == '\'')
            fputc('\'', g);
        fputc(*s == '\n' || *s == '\r' ? ' ' : *s, g);
    }
    fputc('\'', g);
}
