/*
 * atomicfile.h - writing a file so that nothing is lost: the mechanics
 * shared by the library (lib/save.c, atrbvh_save) and the tool
 * (tools/outfile.c, every file it writes).  POSIX and C99 only, no atrbvh
 * type: compiled into both (the library's copy is hidden by
 * -fvisibility=hidden, so the tool links its own).
 *
 * The rules:
 *  - A regular file (or a path that does not exist yet) is written to a
 *    new temporary file in the target's directory (created with O_EXCL, so
 *    nothing that exists is ever opened), fsync'ed and renamed over the
 *    target only when complete; a failure removes only that temporary
 *    file, so the target is untouched.
 *  - Symbolic links are followed by hand: the link stays, the file it
 *    names is replaced (a rename over the link would replace the link).
 *  - A target that is not a regular file (a device, a FIFO, a socket, or
 *    anything reached through /proc's magic links such as /dev/stdout ->
 *    /proc/self/fd/1, even when that is a regular file the shell opened)
 *    is written in place and never removed or replaced.
 *  - A directory is refused (EISDIR); so is replacing a regular file its
 *    owner made read-only (EACCES): not behind its back.
 *  - The replacement gets the replaced file's mode and, when permitted,
 *    its owner; a new file gets 0666 less the umask.
 *  - The path given is never removed.
 *
 * Memory comes from the caller's allocator (the library's must be its
 * replaceable one); every function returns 0 or an errno value (ENOMEM
 * when the allocator failed), except where said.
 */
#ifndef ATRBVH_ATOMICFILE_H
#define ATRBVH_ATOMICFILE_H

#include <stddef.h>

typedef struct atrbvh_i_atomicfile_alloc {
    void *(*malloc_fn)(size_t size);
    void (*free_fn)(void *p);
} atrbvh_i_atomicfile_alloc;

typedef struct atomicfile {
    /* The temporary file's descriptor after atrbvh_i_atomicfile_begin (mode and
     * owner already set), -1 when writing in place.  The caller writes it
     * and closes it (directly or through a FILE *) before
     * atrbvh_i_atomicfile_commit; it sets fd to -1 once it no longer owns it. */
    int fd;
    char *target; /* the file renamed over (symbolic links followed) */
    char *tmp;    /* the temporary file; NULL: the target is written in place */
} atomicfile;

/* Starts writing `path`.  0 with either af->tmp set (a temporary file
 * created beside af->target, open as af->fd) or af->tmp NULL (write
 * `path` in place: see atrbvh_i_atomicfile_open_in_place); or an errno value with
 * nothing created and nothing to release.  `salt` varies the temporary
 * file's name (any pointer of the caller's). */
int atrbvh_i_atomicfile_begin(atomicfile *af, const char *path, const void *salt,
                     const atrbvh_i_atomicfile_alloc *alloc);

/* Opens `path` for writing in place: no O_CREAT (it exists and is not
 * ours to create), no O_TRUNC (a device or FIFO has nothing to truncate;
 * a regular file reached through /proc is appended to, as the shell
 * opened it).  A descriptor, or -1 with errno set. */
int atrbvh_i_atomicfile_open_in_place(const char *path);

/* Writes n bytes to fd, retrying after EINTR and short writes; 0, or an
 * errno value with *done the bytes written. */
int atrbvh_i_atomicfile_write_all(int fd, const void *p, size_t n, size_t *done);

/* Ends a write whose descriptor the caller has fsync'ed and closed:
 * renames the temporary file over the target and fsyncs the directory so
 * that the rename lasts.  0, or an errno value after removing the
 * temporary file (the target untouched).  Releases af either way. */
int atrbvh_i_atomicfile_commit(atomicfile *af, const atrbvh_i_atomicfile_alloc *alloc);

/* Gives up: closes af->fd when not -1, removes the temporary file (ours:
 * created with O_EXCL) and releases af.  Safe on a released af. */
void atrbvh_i_atomicfile_abort(atomicfile *af, const atrbvh_i_atomicfile_alloc *alloc);

#endif
