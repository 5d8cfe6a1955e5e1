/*
 * test_filefault.c - saving and loading when the system calls under them
 * fail.
 *
 * The library's core and the scene loaders (tools/libscene) are linked
 * with ld --wrap for their file calls (Makefile.am), so the k-th of them
 * can fail: EIO (odd k) or ENOSPC (even k), the call not made (close and
 * fclose are made, then reported failed, as Linux does).
 *
 * atrbvh_save, for every k up to the calls a save makes - of a new file,
 * over an existing file (mode 0640), through a symbolic link to one, and
 * in place to /dev/null:
 *
 *   - the save fails with ATRBVH_ERR_IO, its message naming the path, the
 *     step (write, fsync, close, rename) and the error, and the folder is
 *     as it was: the old file byte for byte with its mode, the link a
 *     link to it, no temporary file; or, for the calls it can do without
 *     (the /proc check, the owner, the folder's fsync), it succeeds with
 *     the new bytes;
 *   - no file descriptor is left open.
 *
 * And short writes (at most 1000 bytes a call) and writes interrupted
 * every other call (EINTR) still give the whole file.
 *
 * The tool's output files (tools/outfile.c: cli_out_usable, then
 * cli_out_open, fwrite and cli_out_commit, as `atrbvh build --output`
 * does), in the same four cases and with the same checks; its message is
 * exactly one error line, and every stream it opened is closed.  (Its
 * FILE's own writes are made inside the C library, out of the wrapper's
 * reach: fflush and fclose stand for them.)  And three of its files put
 * in place as one (cli_out_commit_all, as `atrbvh stages --dump` does):
 * a failure before the renames leaves every file as it was.
 *
 * atrbvh_load of a BVH file, and scene_load of a PLY and an OBJ file
 * (the tool's loaders), for every k up to the calls a load makes: the
 * load fails, naming the path and the error, with nothing returned; or
 * it does without the call (closing a file it has read) and returns what
 * a clean load does.  Every stream opened is closed either way.
 *
 * Skips when the library's calls are not the wrapped names on this
 * system.
 */
#define _POSIX_C_SOURCE 200809L
#include <check.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <signal.h>
#include <unistd.h>

#include "atrbvh.h"
#include "cli.h"
#include "outfile.h"
#include "scene.h"
#include "testutil.h"

/* ------------------------------------------------------------ the wrappers */
static int armed;             /* counting (around the call tested)    */
static unsigned long calls;   /* wrapped calls since arm()            */
static unsigned long fail_at; /* the call that fails (0: none)        */
static const char *failed;    /* its name, once it has failed         */
static int fail_errno;
static size_t write_limit;   /* nonzero: no write passes more        */
static int interrupt_writes; /* every other write: EINTR, nothing written */
static unsigned long writes; /* write calls while armed               */

/* double_fault: the rename after a failed one fails as well (with the
 * same errno): a group's rename back (cli_out_commit_all) */
static int double_fault, rename_fails_next;

static void arm(unsigned long k)
{
    calls = 0;
    writes = 0;
    fail_at = k;
    failed = NULL;
    fail_errno = k % 2 ? EIO : ENOSPC;
    rename_fails_next = 0;
    armed = 1;
}

/* Whether this call is the one that fails (errno then set). */
static int fails(const char *name)
{
    if (!armed || ++calls != fail_at)
        return 0;
    failed = name;
    errno = fail_errno;
    return 1;
}

#define FAIL_OR(name) \
    if (fails(#name)) \
    return -1

int __real_open(const char *path, int flags, ...);
int __wrap_open(const char *path, int flags, ...);
int __wrap_open(const char *path, int flags, ...)
{
    mode_t mode = 0;
    if (flags & O_CREAT) {
        va_list ap;
        va_start(ap, flags);
        mode = (mode_t)va_arg(ap, int);
        va_end(ap);
    }
    FAIL_OR(open);
    return __real_open(path, flags, mode);
}

#ifdef __GLIBC__
/* glibc's _FORTIFY_SOURCE turns an open() whose flags are not a constant
 * into __open_2 (a distribution's build flags do). */
int __real___open_2(const char *path, int flags);
int __wrap___open_2(const char *path, int flags);
int __wrap___open_2(const char *path, int flags)
{
    FAIL_OR(open);
    return __real___open_2(path, flags);
}
#endif

ssize_t __real_write(int fd, const void *b, size_t n);
ssize_t __wrap_write(int fd, const void *b, size_t n);
ssize_t __wrap_write(int fd, const void *b, size_t n)
{
    FAIL_OR(write);
    if (armed) {
        writes++;
        if (interrupt_writes && writes % 2) {
            errno = EINTR;
            return -1;
        }
        if (write_limit && n > write_limit)
            n = write_limit;
    }
    return __real_write(fd, b, n);
}

int __real_fsync(int fd);
int __wrap_fsync(int fd);
int __wrap_fsync(int fd)
{
    FAIL_OR(fsync);
    return __real_fsync(fd);
}

int __real_close(int fd);
int __wrap_close(int fd);
int __wrap_close(int fd)
{
    if (fails("close")) { /* closed all the same, as on Linux */
        (void)__real_close(fd);
        errno = fail_errno;
        return -1;
    }
    return __real_close(fd);
}

/* signal_at_rename: SIGTERM sent to the process just before the rename
 * of that number (1, 2, ... since renames was zeroed); rename_fails_at:
 * that rename fails with ENOSPC (signal_waits_for_the_group) */
static unsigned long renames, signal_at_rename, rename_fails_at;
int __real_rename(const char *from, const char *to);
int __wrap_rename(const char *from, const char *to);
int __wrap_rename(const char *from, const char *to)
{
    renames++;
    if (renames == signal_at_rename)
        kill(getpid(), SIGTERM);
    if (renames == rename_fails_at) {
        errno = ENOSPC;
        return -1;
    }
    if (armed && rename_fails_next) {
        rename_fails_next = 0;
        errno = fail_errno;
        return -1;
    }
    if (fails("rename")) {
        rename_fails_next = double_fault;
        return -1;
    }
    return __real_rename(from, to);
}

int __real_fchmod(int fd, mode_t mode);
int __wrap_fchmod(int fd, mode_t mode);
int __wrap_fchmod(int fd, mode_t mode)
{
    FAIL_OR(fchmod);
    return __real_fchmod(fd, mode);
}

int __real_fchown(int fd, uid_t uid, gid_t gid);
int __wrap_fchown(int fd, uid_t uid, gid_t gid);
int __wrap_fchown(int fd, uid_t uid, gid_t gid)
{
    FAIL_OR(fchown);
    return __real_fchown(fd, uid, gid);
}

int __real_stat(const char *path, struct stat *st);
int __wrap_stat(const char *path, struct stat *st);
int __wrap_stat(const char *path, struct stat *st)
{
    FAIL_OR(stat);
    return __real_stat(path, st);
}

int __real_lstat(const char *path, struct stat *st);
int __wrap_lstat(const char *path, struct stat *st);
int __wrap_lstat(const char *path, struct stat *st)
{
    FAIL_OR(lstat);
    return __real_lstat(path, st);
}

int __real_access(const char *path, int how);
int __wrap_access(const char *path, int how);
int __wrap_access(const char *path, int how)
{
    FAIL_OR(access);
    return __real_access(path, how);
}

/* no_links: a file system without hard links (EPERM for a file that
 * exists) */
static int no_links;
int __real_link(const char *from, const char *to);
int __wrap_link(const char *from, const char *to);
int __wrap_link(const char *from, const char *to)
{
    FAIL_OR(link);
    if (no_links && __real_access(from, F_OK) == 0) {
        errno = EPERM;
        return -1;
    }
    return __real_link(from, to);
}

ssize_t __real_readlink(const char *path, char *buf, size_t size);
ssize_t __wrap_readlink(const char *path, char *buf, size_t size);
ssize_t __wrap_readlink(const char *path, char *buf, size_t size)
{
    FAIL_OR(readlink);
    return __real_readlink(path, buf, size);
}

/* Streams: how many are open, those the code tested opened (only their
 * flushes are counted: Check's own, made inside the armed region by a
 * passing ck_assert, are not), and those whose read was made to fail
 * (ferror then says so, as for a real read error). */
static long open_streams;
static FILE *our_stream[4], *bad_stream[4];

/* The slot of `set` holding f (NULL: a free slot), or -1. */
static int stream_slot(FILE *const *set, const FILE *f)
{
    int i;
    for (i = 0; i < 4; i++)
        if (set[i] == f)
            return i;
    return -1;
}

static void stream_add(FILE **set, FILE *f)
{
    int i = stream_slot(set, NULL);
    if (i >= 0)
        set[i] = f;
}

static int stream_in(FILE *const *set, FILE *f)
{
    return f && stream_slot(set, f) >= 0;
}

/* 1 when f was in the set (now taken out), else 0. */
static int stream_drop(FILE **set, FILE *f)
{
    int i = f ? stream_slot(set, f) : -1;
    if (i < 0)
        return 0;
    set[i] = NULL;
    return 1;
}

/* f, counted when opened by the code tested */
static FILE *ours(FILE *f)
{
    if (armed && f) {
        open_streams++;
        stream_add(our_stream, f);
    }
    return f;
}

FILE *__real_fopen(const char *path, const char *mode);
FILE *__wrap_fopen(const char *path, const char *mode);
FILE *__wrap_fopen(const char *path, const char *mode)
{
    if (fails("fopen"))
        return NULL;
    return ours(__real_fopen(path, mode));
}

FILE *__real_fdopen(int fd, const char *mode);
FILE *__wrap_fdopen(int fd, const char *mode);
FILE *__wrap_fdopen(int fd, const char *mode)
{
    if (fails("fdopen"))
        return NULL;
    return ours(__real_fdopen(fd, mode));
}

/* fails with the buffer kept (the fclose after it writes it) */
int __real_fflush(FILE *f);
int __wrap_fflush(FILE *f);
int __wrap_fflush(FILE *f)
{
    if (stream_in(our_stream, f) && fails("fflush"))
        return EOF;
    return __real_fflush(f);
}

int __real_fclose(FILE *f);
int __wrap_fclose(FILE *f);
int __wrap_fclose(FILE *f)
{
    int r;
    (void)stream_drop(bad_stream, f);
    open_streams -= stream_drop(our_stream, f);
    r = __real_fclose(f);
    if (fails("fclose")) { /* closed all the same */
        errno = fail_errno;
        return EOF;
    }
    return r;
}

size_t __real_fread(void *p, size_t size, size_t n, FILE *f);
size_t __wrap_fread(void *p, size_t size, size_t n, FILE *f);
size_t __wrap_fread(void *p, size_t size, size_t n, FILE *f)
{
    if (fails("fread")) {
        stream_add(bad_stream, f);
        return 0;
    }
    return __real_fread(p, size, n, f);
}

#ifdef __GLIBC__
/* glibc's _FORTIFY_SOURCE reads into an array of known size with it */
size_t __real___fread_chk(void *p, size_t room, size_t size, size_t n,
                          FILE *f);
size_t __wrap___fread_chk(void *p, size_t room, size_t size, size_t n,
                          FILE *f);
size_t __wrap___fread_chk(void *p, size_t room, size_t size, size_t n,
                          FILE *f)
{
    if (fails("fread")) {
        stream_add(bad_stream, f);
        return 0;
    }
    return __real___fread_chk(p, room, size, n, f);
}
#endif

int __real_ferror(FILE *f);
int __wrap_ferror(FILE *f);
int __wrap_ferror(FILE *f)
{
    return stream_in(bad_stream, f) || __real_ferror(f);
}

int __real_fseek(FILE *f, long off, int whence);
int __wrap_fseek(FILE *f, long off, int whence);
int __wrap_fseek(FILE *f, long off, int whence)
{
    FAIL_OR(fseek);
    return __real_fseek(f, off, whence);
}

long __real_ftell(FILE *f);
long __wrap_ftell(FILE *f);
long __wrap_ftell(FILE *f)
{
    FAIL_OR(ftell);
    return __real_ftell(f);
}

int __real_fstat(int fd, struct stat *st);
int __wrap_fstat(int fd, struct stat *st);
int __wrap_fstat(int fd, struct stat *st)
{
    FAIL_OR(fstat);
    return __real_fstat(fd, st);
}

/* ---------------------------------------------------------------- checks */
/* The lowest free descriptor (a leaked one takes it). */
static int lowest_free_fd(void)
{
    int fd = dup(0);
    ck_assert_int_ge(fd, 0);
    ck_assert_int_eq(close(fd), 0);
    return fd;
}

static mode_t mode_of(const char *path)
{
    struct stat st;
    ck_assert_int_eq(stat(path, &st), 0);
    return st.st_mode & 07777;
}

/* The words a failure of `call` must put in the message. */
static const char *step_words(const char *call)
{
    if (!strcmp(call, "write"))
        return "write failed after";
    if (!strcmp(call, "fsync"))
        return "(fsync) failed";
    if (!strcmp(call, "fflush"))
        return "write failed:";
    if (!strcmp(call, "close") || !strcmp(call, "fclose"))
        return "closing the file failed";
    if (!strcmp(call, "rename"))
        return "renaming the temporary file over it failed";
    return "cannot write";
}

/* The calls that failed the save, and those it did without, for the log
 * and the checks: " name name ... ", each name once. */
static char refused[256], done_without[256];

static void note(char *list, size_t size, const char *name)
{
    char word[32];
    size_t used = strlen(list);
    snprintf(word, sizeof word, " %s ", name);
    if (!strstr(list, word) && used + strlen(word) < size)
        snprintf(list + used, size - used, "%s ", name);
}

static atrbvh_bvh *bvh;
static unsigned char *image, *old_image;
static size_t image_n, old_n;
static float *tris;

static void make_bvhs(void)
{
    atrbvh_build_options o;
    atrbvh_geometry g;
    atrbvh_bvh *old;
    atrbvh_error e;
    void *d;
    if (bvh)
        return;
    tris = tu_random_triangles(3000, 3, 1.0f, 0.0f);
    g = atrbvh_geometry_triangles(tris, 9000, NULL, 3000);
    atrbvh_build_options_init(&o);
    bvh = tu_build(&g, &o);
    ck_assert_int_eq(atrbvh_save_memory(bvh, &d, &image_n, &e), ATRBVH_OK);
    image = d;
    g = atrbvh_geometry_triangles(tris, 300, NULL, 100);
    old = tu_build(&g, &o);
    ck_assert_int_eq(atrbvh_save_memory(old, &d, &old_n, &e), ATRBVH_OK);
    old_image = d;
    atrbvh_bvh_free(old);
}

enum save_case { NEW_FILE, REPLACE, THROUGH_LINK, IN_PLACE };
static const char *const scene_name[] = {"a new file", "over a file",
                                         "through a link", "to /dev/null"};

/* Sets the folder up for `sc`: `file` absent, or holding the old
 * bytes with mode 0640 (and `link` naming it). */
static void set_up(enum save_case sc, const char *file, const char *link)
{
    remove(file);
    if (sc == NEW_FILE || sc == IN_PLACE)
        return;
    tu_write_bytes(file, old_image, old_n);
    ck_assert_int_eq(chmod(file, 0640), 0);
    if (sc == THROUGH_LINK) {
        remove(link);
        ck_assert_int_eq(symlink("scene.bvh", link), 0);
    }
}

/* The tool's error lines (tools/outfile.c prints with cli_error): how
 * many since tool_save began, and the last. */
static int tool_lines;
static char tool_msg[1024];

void cli_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(tool_msg, sizeof tool_msg, fmt, ap);
    va_end(ap);
    tool_lines++;
}

/* What `atrbvh build --output target` does with the saved image: the
 * check before the build, then the writing.  0 or -1. */
static int tool_save(const char *target)
{
    cli_out out;
    FILE *f;
    tool_lines = 0;
    tool_msg[0] = '\0';
    if (cli_out_usable(target, NULL) != 0)
        return -1;
    f = cli_out_open(target, &out);
    if (!f)
        return -1;
    if (fwrite(image, 1, image_n, f) != image_n) {
        cli_out_abort(&out);
        cli_error("%s: fwrite failed", target);
        return -1;
    }
    return cli_out_commit(&out);
}

enum saver { LIBRARY, TOOL };

/* Every call of a save in `sc` by `who` failed in turn. */
static void save_fails_cleanly(enum save_case sc, enum saver who)
{
    char *dir = tu_make_temp_dir("test_filefault_");
    char file[700], link[700], target[700], before[512], after[512];
    const char *what = scene_name[sc];
    /* the calls that stand for the writes and the closing */
    const char *write_call = who == TOOL ? " fflush " : " write ";
    const char *close_call = who == TOOL ? " fclose " : " close ";
    unsigned long n, k;
    atrbvh_error e;
    int rc;
    make_bvhs();
    snprintf(file, sizeof file, "%s/scene.bvh", dir);
    snprintf(link, sizeof link, "%s/link.bvh", dir);
    snprintf(target, sizeof target, "%s",
             sc == THROUGH_LINK ? link : sc == IN_PLACE ? "/dev/null" : file);
    /* a clean save: its calls */
    set_up(sc, file, link);
    arm(0);
    rc = who == TOOL ? tool_save(target)
                     : atrbvh_save(bvh, target, &e) == ATRBVH_OK ? 0 : -1;
    armed = 0;
    ck_assert_msg(rc == 0, "%s: %s", what, who == TOOL ? tool_msg : e.text);
    n = calls;
    if (n == 0) {
        fprintf(stderr, "SKIP %s: the %s's file calls are not the wrapped "
                "names here\n", what, who == TOOL ? "tool" : "library");
        goto done;
    }
    ck_assert(sc == IN_PLACE || tu_holds(file, image, image_n));
    strcpy(refused, " ");
    strcpy(done_without, " ");
    for (k = 1; k <= n; k++) {
        int fd0;
        atrbvh_status st = ATRBVH_OK;
        const char *msg = who == TOOL ? tool_msg : e.text;
        set_up(sc, file, link);
        tu_list_dir(dir, before, sizeof before);
        fd0 = lowest_free_fd();
        memset(&e, 0, sizeof e);
        open_streams = 0;
        arm(k);
        if (who == TOOL)
            rc = tool_save(target);
        else
            rc = (st = atrbvh_save(bvh, target, &e)) == ATRBVH_OK ? 0 : -1;
        armed = 0;
        ck_assert_msg(failed != NULL, "%s: call %lu of %lu never made", what,
                      k, n);
        ck_assert_msg(lowest_free_fd() == fd0,
                      "%s, %s (call %lu) failed: a descriptor left open",
                      what, failed, k);
        ck_assert_msg(open_streams == 0, "%s, %s (call %lu) failed: %ld "
                      "stream(s) left open", what, failed, k, open_streams);
        if (who == TOOL)
            ck_assert_msg(tool_lines == (rc != 0), "%s, %s (call %lu) "
                          "failed: %d error lines for a %s", what, failed, k,
                          tool_lines, rc ? "failure" : "success");
        if (rc == 0) {
            note(done_without, sizeof done_without, failed);
            if (sc == IN_PLACE)
                continue;
            ck_assert_msg(tu_holds(file, image, image_n),
                          "%s survived %s (call %lu) without the new bytes",
                          what, failed, k);
            if (sc != NEW_FILE)
                ck_assert_uint_eq(mode_of(file), 0640);
            continue;
        }
        note(refused, sizeof refused, failed);
        ck_assert_msg(who == TOOL || (st == ATRBVH_ERR_IO &&
                                      e.status == ATRBVH_ERR_IO),
                      "%s, %s (call %lu) failed: status %d (%s)", what,
                      failed, k, (int)st, e.text);
        ck_assert_msg(strstr(msg, target) &&
                          strstr(msg, strerror(fail_errno)) &&
                          strstr(msg, step_words(failed)),
                      "%s, %s (call %lu) failed with %s: \"%s\" does not "
                      "name the path, the step (\"%s\") and the error",
                      what, failed, k, strerror(fail_errno), msg,
                      step_words(failed));
        tu_list_dir(dir, after, sizeof after);
        ck_assert_msg(!strcmp(before, after), "%s, %s (call %lu) failed: "
                      "the folder held \"%s\", now \"%s\"", what, failed, k,
                      before, after);
        if (sc == NEW_FILE || sc == IN_PLACE)
            continue;
        ck_assert_msg(tu_holds(file, old_image, old_n),
                      "%s, %s (call %lu) failed: the old file changed", what,
                      failed, k);
        ck_assert_uint_eq(mode_of(file), 0640);
        if (sc == THROUGH_LINK) {
            char got[64];
            ssize_t r = readlink(link, got, sizeof got - 1);
            ck_assert_int_gt(r, 0);
            got[r] = '\0';
            ck_assert_str_eq(got, "scene.bvh");
        }
    }
    fprintf(stderr, "%s save %s: %lu calls, each failed in turn; "
            "refused: %s; done without:%s\n",
            who == TOOL ? "the tool's" : "atrbvh_save's", what, n,
            refused + 1, done_without);
    /* the steps that must have been tried (in place: no temporary file,
     * so no fsync or rename) */
    ck_assert_msg(strstr(refused, " open ") && strstr(refused, write_call) &&
                      strstr(refused, close_call) &&
                      (who == LIBRARY || strstr(refused, " fdopen ")) &&
                      (sc == IN_PLACE || (strstr(refused, " fsync ") &&
                                          strstr(refused, " rename "))),
                  "%s: refused only %s", what, refused);
    if (sc == REPLACE || sc == THROUGH_LINK)
        ck_assert_msg(strstr(refused, " fchmod "), "%s: refused only %s",
                      what, refused);
    if (sc == THROUGH_LINK)
        ck_assert_msg(strstr(refused, " readlink "), "%s: refused only %s",
                      what, refused);
done:
    remove(link);
    remove(file);
    ck_assert_int_eq(rmdir(dir), 0);
    free(dir);
}

/* _i: the save case (enum save_case); LIBRARY, then TOOL */
START_TEST(library_save_fails_cleanly_at_each_call)
{
    save_fails_cleanly((enum save_case)_i, LIBRARY);
}
END_TEST

START_TEST(tool_output_fails_cleanly_at_each_call)
{
    save_fails_cleanly((enum save_case)_i, TOOL);
}
END_TEST

/* The tool's files written as one (cli_out_commit_all, as `atrbvh stages
 * --dump` puts its arrays and manifest in place): a.npy over an old one,
 * b.npy new, manifest.json over an old one, last.  For every k, the run
 * succeeds with every new file (a hard link that cannot be made is done
 * without), or fails with one error line naming a file, its step and the
 * reason, and then the folder is exactly as it was, a failed rename's
 * files before it put back (the message says so).  Then again on a file
 * system without hard links (_i 1): a failed rename leaves a.npy
 * replaced when it came before (the message says it could not be put
 * back), b.npy removed, and the rest as they were.  Then (_i 2) with hard
 * links again but the rename after a failed one failing too, which is
 * a.npy's rename back: a.npy is left new, its old content kept in the
 * link the message names, b.npy removed, the rest as they were.  No
 * other temporary file is left either way. */
START_TEST(tool_files_committed_as_one)
{
    static const char *const names[3] = {"a.npy", "b.npy", "manifest.json"};
    char *dir = tu_make_temp_dir("test_filefault_");
    char path[3][700], before[512], after[512];
    /* old and new contents: slices of the two images */
    const unsigned char *old_of[3], *new_of[3];
    size_t old_len[3], new_len[3];
    unsigned long n = 0, k, kept_seen = 0;
    int i;
    make_bvhs();
    no_links = _i == 1;
    double_fault = _i == 2;
    for (i = 0; i < 3; i++) {
        snprintf(path[i], sizeof path[i], "%s/%s", dir, names[i]);
        old_of[i] = i == 1 ? NULL : old_image + (size_t)i * 100;
        old_len[i] = 200;
        new_of[i] = image + (size_t)i * 1000;
        new_len[i] = image_n / 2;
    }
    strcpy(refused, " ");
    strcpy(done_without, " ");
    for (k = 0; k == 0 || k <= n; k++) {
        cli_out out[3];
        int fd0, rc = 0, opened = 0, named, renamed, placed;
        for (i = 0; i < 3; i++) {
            remove(path[i]);
            if (old_of[i])
                tu_write_bytes(path[i], old_of[i], old_len[i]);
        }
        tu_list_dir(dir, before, sizeof before);
        fd0 = lowest_free_fd();
        open_streams = 0;
        tool_lines = 0;
        arm(k);
        for (i = 0; i < 3 && rc == 0; i++) {
            FILE *f = cli_out_open(path[i], &out[i]);
            if (!f)
                rc = -1;
            else if (opened++,
                     fwrite(new_of[i], 1, new_len[i], f) != new_len[i])
                ck_abort_msg("fwrite");
        }
        if (rc == 0)
            rc = cli_out_commit_all(out, 3);
        else
            cli_out_abort_all(out, (size_t)opened);
        armed = 0;
        if (k == 0) {
            ck_assert_msg(rc == 0, "a clean run failed: %s", tool_msg);
            n = calls;
            if (n == 0) {
                fprintf(stderr, "SKIP tool_files_committed_as_one: the "
                        "tool's file calls are not the wrapped names here\n");
                break;
            }
        } else {
            ck_assert_msg(failed != NULL, "call %lu of %lu never made", k,
                          n);
        }
        ck_assert_msg(lowest_free_fd() == fd0 && open_streams == 0,
                      "%s (call %lu) failed: a descriptor or stream left "
                      "open", failed, k);
        ck_assert_msg(tool_lines == (rc != 0), "%s (call %lu) failed: %d "
                      "error lines", failed, k, tool_lines);
        if (rc == 0) {
            if (k)
                note(done_without, sizeof done_without, failed);
            for (i = 0; i < 3; i++)
                ck_assert_msg(tu_holds(path[i], new_of[i], new_len[i]),
                              "%s survived %s (call %lu) without its new "
                              "bytes", names[i], failed, k);
            tu_list_dir(dir, after, sizeof after);
            ck_assert_msg(!strstr(after, ".tmp"), "%s (call %lu) done "
                          "without: a temporary file or link is left: %s",
                          failed ? failed : "nothing", k, after);
            continue;
        }
        note(refused, sizeof refused, failed);
        ck_assert_msg(strstr(tool_msg, strerror(fail_errno)) &&
                          strstr(tool_msg, step_words(failed)),
                      "%s (call %lu) failed with %s: \"%s\" does not name "
                      "the step (\"%s\") and the error", failed, k,
                      strerror(fail_errno), tool_msg, step_words(failed));
        /* the file the message names, and the files renamed before it
         * when it was a rename that failed: put back, but for a.npy
         * without hard links (placed: those left new or removed) */
        for (named = 0; named < 3 && !strstr(tool_msg, path[named]);
             named++)
            ;
        ck_assert_msg(named < 3, "\"%s\" names none of the files",
                      tool_msg);
        renamed = strcmp(failed, "rename") ? 0 : named;
        placed = no_links || double_fault ? renamed : 0;
        ck_assert_msg(renamed == 0 ? !strstr(tool_msg, "put back")
                                   : strstr(tool_msg,
                                            placed ? "could not be put "
                                                     "back"
                                                   : "before it put back") !=
                                         NULL,
                      "%s (call %lu) failed: \"%s\" does not say what "
                      "became of the %d file(s) renamed before it", failed,
                      k, tool_msg, renamed);
        for (i = 0; i < 3; i++) {
            const int is_new = i < placed && old_of[i];
            ck_assert_msg(is_new ? tu_holds(path[i], new_of[i], new_len[i])
                          : old_of[i] ? tu_holds(path[i], old_of[i],
                                                 old_len[i])
                                      : access(path[i], F_OK) != 0,
                          "%s (call %lu) failed: %s is not %s (%s)", failed,
                          k, names[i], is_new ? "new" : "as it was",
                          tool_msg);
        }
        if (double_fault && placed) {
            /* a.npy's old content, in the link the message names */
            const char *kept = strstr(tool_msg, "an old one is kept as ");
            char keep[700];
            size_t len;
            ck_assert_msg(kept != NULL, "%s (call %lu) and the rename back "
                          "failed: \"%s\" names no file kept", failed, k,
                          tool_msg);
            kept += strlen("an old one is kept as ");
            len = strcspn(kept, ")");
            ck_assert(len < sizeof keep);
            memcpy(keep, kept, len);
            keep[len] = '\0';
            ck_assert_msg(strncmp(keep, path[0], strlen(dir) + 1) == 0 &&
                              tu_holds(keep, old_of[0], old_len[0]),
                          "%s (call %lu) and the rename back failed: %s "
                          "does not hold a.npy's old bytes beside it (%s)",
                          failed, k, keep, tool_msg);
            ck_assert_int_eq(remove(keep), 0);
            kept_seen++;
        }
        tu_list_dir(dir, after, sizeof after);
        ck_assert_msg(placed > 0 || !strcmp(before, after), "%s (call %lu) "
                      "failed: the folder held \"%s\", now \"%s\"", failed,
                      k, before, after);
        ck_assert_msg(!strstr(after, ".tmp"), "%s (call %lu) failed: a "
                      "temporary file is left: %s", failed, k, after);
    }
    if (n)
        fprintf(stderr, "the tool's three files as one%s: %lu calls, each "
                "failed in turn; refused: %s; done without:%s\n",
                _i == 1   ? " without hard links"
                : _i == 2 ? ", the rename back failing too"
                          : "",
                n, refused + 1, done_without);
    /* (the renames of b.npy and of manifest.json failed, each with a.npy
     * renamed before it) */
    ck_assert_msg(!n || !double_fault || kept_seen == 2,
                  "the rename back failed %lu times, not twice", kept_seen);
    no_links = double_fault = 0;
    ck_assert_msg(!n || (strstr(refused, " fflush ") &&
                         strstr(refused, " fsync ") &&
                         strstr(refused, " fclose ") &&
                         strstr(refused, " rename ")),
                  "refused only %s", refused);
    ck_assert_msg(!n || strstr(done_without, " link "),
                  "a failed hard link failed the files: done without only "
                  "%s", done_without);
    for (i = 0; i < 3; i++)
        remove(path[i]);
    ck_assert_int_eq(rmdir(dir), 0);
    free(dir);
}
END_TEST

/* A fatal signal (SIGTERM, which the tool's cleanup handles) arriving
 * during the tool's group of three files (as in
 * tool_files_committed_as_one) just before its first, second or third
 * rename, in a child process: the child dies of the signal, but only
 * once the renames are over: every file is new and nothing else is in
 * the folder; or, when the third rename fails (ENOSPC), every file is as
 * it was (the first two put back).  Before, the cleanup ran at once: the
 * files renamed before the signal were left new, the rest old, and the
 * hard links holding the renamed ones' old content were removed. */
START_TEST(signal_waits_for_the_group)
{
    static const char *const names[3] = {"a.npy", "b.npy", "manifest.json"};
    char *dir = tu_make_temp_dir("test_filefault_");
    char path[3][700], before[512], after[512];
    int r, fail3, i;
    make_bvhs();
    for (i = 0; i < 3; i++)
        snprintf(path[i], sizeof path[i], "%s/%s", dir, names[i]);
    for (fail3 = 0; fail3 <= 1; fail3++)
        for (r = 1; r <= 3; r++) {
            int status;
            pid_t pid;
            for (i = 0; i < 3; i++) {
                remove(path[i]);
                if (i != 1)
                    tu_write_bytes(path[i], old_image + (size_t)i * 100, 200);
            }
            tu_list_dir(dir, before, sizeof before);
            fflush(NULL);
            pid = fork();
            ck_assert(pid >= 0);
            if (pid == 0) {
                cli_out out[3];
                int rc;
                for (i = 0; i < 3; i++) {
                    FILE *f = cli_out_open(path[i], &out[i]);
                    if (!f || fwrite(image + (size_t)i * 1000, 1, image_n / 2,
                                     f) != image_n / 2)
                        _exit(3);
                }
                renames = 0;
                signal_at_rename = (unsigned long)r;
                rename_fails_at = fail3 ? 3 : 0;
                rc = cli_out_commit_all(out, 3);
                _exit(rc == 0 ? 0 : 1); /* (the signal ends it first) */
            }
            ck_assert(waitpid(pid, &status, 0) == pid);
            ck_assert_msg(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM,
                          "SIGTERM before rename %d%s: the child %s %d", r,
                          fail3 ? " (the third failing)" : "",
                          WIFSIGNALED(status) ? "died of signal"
                                              : "exited with",
                          WIFSIGNALED(status) ? WTERMSIG(status)
                                              : WEXITSTATUS(status));
            for (i = 0; i < 3; i++) {
                const int want_new = !fail3;
                ck_assert_msg(want_new ? tu_holds(path[i],
                                                  image + (size_t)i * 1000,
                                                  image_n / 2)
                              : i == 1 ? access(path[i], F_OK) != 0
                                       : tu_holds(path[i],
                                                  old_image + (size_t)i * 100,
                                                  200),
                              "SIGTERM before rename %d%s: %s is not %s", r,
                              fail3 ? " (the third failing)" : "", names[i],
                              want_new ? "new" : "as it was");
            }
            tu_list_dir(dir, after, sizeof after);
            ck_assert_msg(!strstr(after, ".tmp") &&
                              (!fail3 || !strcmp(before, after)),
                          "SIGTERM before rename %d%s: the folder held "
                          "\"%s\", now \"%s\"", r,
                          fail3 ? " (the third failing)" : "", before, after);
        }
    for (i = 0; i < 3; i++)
        remove(path[i]);
    ck_assert_int_eq(rmdir(dir), 0);
    free(dir);
}
END_TEST

/* Writes that take part of what they are given, or are interrupted
 * before writing anything, still give the whole file. */
START_TEST(short_and_interrupted_writes_complete)
{
    char *dir = tu_make_temp_dir("test_filefault_");
    char file[700];
    atrbvh_error e;
    int how;
    make_bvhs();
    snprintf(file, sizeof file, "%s/scene.bvh", dir);
    for (how = 0; how < 2; how++) {
        write_limit = how == 0 ? 1000 : 0;
        interrupt_writes = how == 1;
        arm(0);
        ck_assert_msg(atrbvh_save(bvh, file, &e) == ATRBVH_OK, "%s: %s",
                      how ? "interrupted writes" : "short writes", e.text);
        armed = 0;
        write_limit = 0;
        interrupt_writes = 0;
        if (calls == 0) {
            fprintf(stderr, "SKIP short_and_interrupted_writes_complete: "
                    "the library's file calls are not the wrapped names "
                    "here\n");
            break;
        }
        ck_assert_msg(tu_holds(file, image, image_n), "%s: other bytes",
                      how ? "interrupted writes" : "short writes");
        /* (one write would have done: the cut did happen) */
        ck_assert_uint_ge(writes, how == 0 ? (image_n + 999) / 1000 : 2);
        fprintf(stderr, "%s: %lu bytes in %lu write calls\n",
                how ? "interrupted writes" : "short writes",
                (unsigned long)image_n, writes);
        ck_assert_int_eq(remove(file), 0);
    }
    ck_assert_int_eq(rmdir(dir), 0);
    free(dir);
}
END_TEST

/* ---------------------------------------------------------------- loads */
enum load_case { LOAD_BVH, LOAD_PLY, LOAD_OBJ };
static const char *const load_name[] = {"atrbvh_load", "a PLY scene",
                                        "an OBJ scene"};

/* One load of `path`: 0 and a description of what was loaded (its node
 * count and SAH, or its triangle count and first and last vertex), or -1
 * with the error in msg. */
static int load_once(enum load_case lc, const char *path, char *what,
                     size_t what_len, char *msg, size_t msg_len)
{
    if (lc == LOAD_BVH) {
        atrbvh_bvh *b = (atrbvh_bvh *)&lc; /* must be set to NULL */
        atrbvh_error e;
        atrbvh_status st = atrbvh_load(path, &b, &e);
        atrbvh_stats stats;
        if (st != ATRBVH_OK) {
            ck_assert_msg(b == NULL, "a failed load left *out set");
            ck_assert_msg(st == ATRBVH_ERR_IO, "load status %d: %s", (int)st,
                          e.text);
            snprintf(msg, msg_len, "%s", e.text);
            return -1;
        }
        atrbvh_bvh_stats(b, &stats);
        snprintf(what, what_len, "%lu nodes, SAH %.17g",
                 (unsigned long)stats.nodes, stats.sah);
        atrbvh_bvh_free(b);
    } else {
        scene sc;
        atrbvh_geometry g;
        if (scene_load(path, &sc, msg, msg_len) != 0)
            return -1;
        g = scene_geometry(&sc);
        snprintf(what, what_len, "%lu triangles, %g %g %g .. %g",
                 (unsigned long)g.primitive_count, g.vertices[0],
                 g.vertices[1], g.vertices[2],
                 g.vertices[3 * g.vertex_count - 1]);
        scene_free(&sc);
    }
    return 0;
}

/* Writes the file `lc` loads: a BVH file, or a strip of triangles as
 * ASCII PLY (over 4 KB, so that the body is read after the header) or
 * OBJ. */
static void write_load_file(enum load_case lc, const char *path)
{
    enum { V = 600 };
    FILE *f;
    int i;
    if (lc == LOAD_BVH) {
        make_bvhs();
        tu_write_bytes(path, image, image_n);
        return;
    }
    f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    if (lc == LOAD_PLY)
        fprintf(f, "ply\nformat ascii 1.0\nelement vertex %d\n"
                "property float x\nproperty float y\nproperty float z\n"
                "element face %d\nproperty list uchar int vertex_indices\n"
                "end_header\n", V, V - 2);
    for (i = 0; i < V; i++)
        fprintf(f, "%s%d %d %d.5\n", lc == LOAD_OBJ ? "v " : "", i / 2,
                i % 2, i % 7);
    for (i = 0; i + 2 < V; i++) {
        if (lc == LOAD_PLY)
            fprintf(f, "3 %d %d %d\n", i, i + 1, i + 2);
        else
            fprintf(f, "f %d %d %d\n", i + 1, i + 2, i + 3);
    }
    ck_assert_int_eq(fclose(f), 0);
}

static void load_fails_cleanly(enum load_case lc)
{
    static const char *const ext[] = {"bvh", "ply", "obj"};
    char *dir = tu_make_temp_dir("test_filefault_");
    char path[700], want[128], got[128], msg[ATRBVH_ERROR_TEXT_LENGTH + 256];
    const char *what = load_name[lc];
    unsigned long n, k;
    snprintf(path, sizeof path, "%s/scene.%s", dir, ext[lc]);
    write_load_file(lc, path);
    arm(0);
    open_streams = 0;
    ck_assert_msg(load_once(lc, path, want, sizeof want, msg, sizeof msg) ==
                      0,
                  "%s: %s", what, msg);
    armed = 0;
    n = calls;
    if (n == 0) {
        fprintf(stderr, "SKIP %s: the loader's file calls are not the "
                "wrapped names here\n", what);
        goto done;
    }
    strcpy(refused, " ");
    strcpy(done_without, " ");
    for (k = 1; k <= n; k++) {
        int rc;
        open_streams = 0;
        arm(k);
        rc = load_once(lc, path, got, sizeof got, msg, sizeof msg);
        armed = 0;
        ck_assert_msg(failed != NULL, "%s: call %lu of %lu never made", what,
                      k, n);
        ck_assert_msg(open_streams == 0, "%s, %s (call %lu) failed: %ld "
                      "stream%s left open", what, failed, k, open_streams,
                      open_streams == 1 ? "" : "s");
        if (rc == 0) {
            note(done_without, sizeof done_without, failed);
            ck_assert_msg(!strcmp(want, got), "%s survived %s (call %lu) "
                          "with %s, not %s", what, failed, k, got, want);
            continue;
        }
        note(refused, sizeof refused, failed);
        ck_assert_msg(strstr(msg, path) && strstr(msg, strerror(fail_errno)),
                      "%s, %s (call %lu) failed with %s: \"%s\" does not "
                      "name the path and the error", what, failed, k,
                      strerror(fail_errno), msg);
    }
    fprintf(stderr, "%s: %lu calls, each failed in turn; refused: %s; "
            "done without:%s\n", what, n, refused + 1, done_without);
    ck_assert_msg(strstr(refused, " fopen ") && strstr(refused, " fread "),
                  "%s: refused only %s", what, refused);
done:
    ck_assert_int_eq(remove(path), 0);
    ck_assert_int_eq(rmdir(dir), 0);
    free(dir);
}

START_TEST(bvh_load_fails_cleanly_at_each_call)
{
    load_fails_cleanly(LOAD_BVH);
}
END_TEST

START_TEST(ply_load_fails_cleanly_at_each_call)
{
    load_fails_cleanly(LOAD_PLY);
}
END_TEST

START_TEST(obj_load_fails_cleanly_at_each_call)
{
    load_fails_cleanly(LOAD_OBJ);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("filefault");
    TCase *tc = tcase_create("faults");
    int rc;
    tcase_add_loop_test(tc, library_save_fails_cleanly_at_each_call,
                        NEW_FILE, IN_PLACE + 1);
    tcase_add_loop_test(tc, tool_output_fails_cleanly_at_each_call,
                        NEW_FILE, IN_PLACE + 1);
    tcase_add_loop_test(tc, tool_files_committed_as_one, 0, 3);
    tcase_add_test(tc, signal_waits_for_the_group);
    tcase_add_test(tc, short_and_interrupted_writes_complete);
    tcase_add_test(tc, bvh_load_fails_cleanly_at_each_call);
    tcase_add_test(tc, ply_load_fails_cleanly_at_each_call);
    tcase_add_test(tc, obj_load_fails_cleanly_at_each_call);
    suite_add_tcase(s, tc);
    rc = tu_run(s);
    atrbvh_bvh_free(bvh);
    atrbvh_free(image);
    atrbvh_free(old_image);
    free(tris);
    return rc;
}
