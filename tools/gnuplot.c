/*
 * gnuplot.c - gnuplot started with fork/execvp (no shell: a folder name
 * can hold any character) and waited for.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"
#include "gnuplot.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

int cli_gnuplot(const char *dir, const char *script)
{
    pid_t pid;
    int st;
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
        fd = open("gnuplot.log", O_WRONLY | O_CREAT | O_TRUNC, 0666);
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
        argv[2] = (char *)"outsuffix = '.part'";
        argv[3] = (char *)script;
        argv[4] = NULL;
        execvp(argv[0], argv);
        _exit(127);
    }
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR) {
            cli_error("%s/%s: waiting for gnuplot: %s", dir, script,
                      strerror(errno));
            return -1;
        }
    if (WIFEXITED(st) && WEXITSTATUS(st) == 127) {
        cli_error("%s/%s: gnuplot not found (install gnuplot to get the "
                  "pictures; the data and script are there)", dir, script);
        return -1;
    }
    if (!WIFEXITED(st) || WEXITSTATUS(st) != 0) {
        cli_error("%s/%s: gnuplot failed (see %s/gnuplot.log)", dir, script,
                  dir);
        return -1;
    }
    return 0;
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

int cli_gnuplot_picture(const char *final, int ok)
{
    size_t n = strlen(final);
    char *part = malloc(n + 6);
    struct stat st;
    int rc = 0;
    if (!part) {
        cli_error("%s: out of memory", final);
        return -1;
    }
    memcpy(part, final, n);
    memcpy(part + n, ".part", 6);
    if (!ok) {
        remove(part);
    } else if (lstat(final, &st) == 0 && !S_ISREG(st.st_mode)) {
        cli_error("%s: not a regular file, not replaced (the picture is in "
                  "%s)", final, part);
        rc = -1;
    } else if (rename(part, final) != 0) {
        cli_error("%s: %s", final, strerror(errno));
        remove(part);
        rc = -1;
    }
    free(part);
    return rc;
}
