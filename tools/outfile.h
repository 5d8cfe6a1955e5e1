/*
 * outfile.h - every file the atrbvh tool writes goes through here, so that
 * nothing is ever lost or left half written.
 *
 * A regular file (or a path that does not exist yet) is written to a
 * temporary file beside its target (created with O_EXCL in the target's
 * directory), flushed, fsync'ed and renamed over the target only when
 * complete; on any failure the temporary file is removed and the target is
 * untouched (the mechanics are lib/atomicfile.c's, shared with the
 * library; this file adds the FILE *, the messages and the signals).  A
 * symbolic link is followed: the file it names is replaced, the link
 * stays.  A target that is not a regular file - a device, a FIFO, a
 * socket, /dev/stdout or /dev/fd/N (anything reached through /proc's magic
 * links), or a symbolic link to one of those - is written in place and is
 * never removed or replaced.  A directory is refused.  "-" has no special
 * meaning (the tool has no such convention): it is a file named "-".
 * Replacing a file gives the path a new file: other hard links to the old
 * one keep the old content.  While a temporary file exists, SIGINT,
 * SIGTERM, SIGHUP, SIGQUIT and SIGXFSZ (unless ignored) remove it before
 * the process ends (handlers installed at the first cli_out_open).
 *
 * Typical use:
 *
 *     cli_out out;
 *     FILE *f = cli_out_open(path, &out);
 *     if (!f)
 *         return CLI_FAIL;                  (the error line is printed)
 *     ... fprintf(f, ...) ...
 *     if (something_failed) {
 *         cli_out_abort(&out);              (silent; target untouched)
 *         return CLI_FAIL;
 *     }
 *     if (cli_out_commit(&out) != 0)        (prints the error line)
 *         return CLI_FAIL;
 *
 * Every cli_out_open that returned a FILE * must be ended by exactly one
 * cli_out_commit or cli_out_abort; both close the FILE * and free the
 * handle's memory, whatever the outcome.
 */
#ifndef ATRBVH_TOOLS_OUTFILE_H
#define ATRBVH_TOOLS_OUTFILE_H

#include <stdio.h>
#include <sys/types.h>

#include "atomicfile.h"

typedef struct cli_out {
    FILE *f;
    char *name;    /* the path as given, for messages */
    atomicfile af; /* the target and the temporary file (lib/atomicfile.h);
                      af.tmp NULL when writing in place */
} cli_out;

/* Whether `path` can be written, without writing it: 0 when it can, else
 * -1 with *err (when err is not NULL) set to a short reason such as
 * strerror's ("No such file or directory" for a missing directory, "Is a
 * directory", "Permission denied").  For a regular target it creates and
 * removes a temporary file in the target's directory.  Prints nothing:
 * call it before a long computation and report with
 * cli_error("%s: %s", path, err). */
int cli_out_check(const char *path, const char **err);

/* Starts writing `path`: a FILE * open for binary writing, or NULL after
 * one error line "atrbvh: PATH: ..." (cli_error).  *h need not be
 * initialised. */
FILE *cli_out_open(const char *path, cli_out *h);

/* Finishes: flushes, fsyncs and renames the temporary file over the
 * target (in place: flushes and closes).  0, or -1 after one error line
 * naming the path, the step that failed (the write, the fsync, the close
 * or the rename) and the system's reason; the temporary file removed, the
 * target untouched. */
int cli_out_commit(cli_out *h);

/* Finishes the n files h[0..n-1] as one: flushes, fsyncs and closes
 * every one of them (the steps that fail for want of room or an I/O
 * error), and only when all of that succeeded renames them over their
 * targets, in order.  0, or -1 after one error line naming the file, the
 * step and the reason; every handle is ended either way.  A failure
 * before the renames leaves every target as it was.  So does a failed
 * rename (rare: each temporary file is in its target's directory): the
 * targets before it are put back, from hard links to them made before
 * the first rename (removed after the last) or, for a target that did
 * not exist, by removing the new file; the error line says so.  Where a
 * link cannot be made (a file system without hard links) that target
 * cannot be put back, and the line says how many could not: write the
 * file that names the others (a manifest) last.  A fatal signal that
 * arrives during the renames (outfile.c: committing) waits until they
 * are all done, or all undone, then ends the process as it would have. */
int cli_out_commit_all(cli_out *h, size_t n);

/* Gives up: closes and removes the temporary file; the target is
 * untouched (in place: only closes).  Prints nothing.  Safe on a handle
 * whose open failed or that was already ended. */
void cli_out_abort(cli_out *h);

/* cli_out_abort on each of h[0..n-1]. */
void cli_out_abort_all(cli_out *h, size_t n);

/* Adds `path` (kept, not copied) to what a fatal signal removes: a file
 * the tool is making (unlinked), or a folder it made (removed once the
 * files in it are, when they are all tracked too); until
 * cli_out_untrack(path).  For the files gnuplot writes (tools/gnuplot.c);
 * cli_out_open tracks its own. */
void cli_out_track(char *path);
void cli_out_untrack(const char *path);

/* The child process writing the tracked files (gnuplot), 0 for none: a
 * fatal signal ends it (SIGKILL) and reaps it before removing them, so
 * that it cannot write again after the cleanup.  One at a time. */
void cli_out_track_writer(pid_t pid);

/* 1 when both paths exist and name the same file (same device and inode,
 * symbolic links followed), else 0.  For refusing an output that would
 * replace the input. */
int cli_out_same_file(const char *a, const char *b);

/* Both checks before a long computation: 0 when `output` can be written
 * and is not the file `input` (NULL: no input to protect); else -1 after
 * one error line "atrbvh: OUTPUT: ...". */
int cli_out_usable(const char *output, const char *input);

#endif
