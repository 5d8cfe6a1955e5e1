/*
 * main.c - the atrbvh tool: subcommand dispatch and the helpers every
 * subcommand uses (messages, strict number parsing, options, the clock).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"

#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* The message must stay one line even when a file name holds a newline:
 * control characters are shown as '?'. */
static void put_line(const char *text)
{
    const unsigned char *p = (const unsigned char *)text;
    for (; *p; p++)
        fputc(*p < 0x20 || *p == 0x7f ? '?' : (int)*p, stderr);
    fputc('\n', stderr);
}

void cli_error(const char *fmt, ...)
{
    char text[1024];
    va_list ap;
    fflush(stdout);
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    fputs("atrbvh: ", stderr);
    put_line(text);
}

int cli_usage(const char *cmd, const char *fmt, ...)
{
    char text[1024];
    size_t n;
    va_list ap;
    fflush(stdout);
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    n = strlen(text);
    snprintf(text + n, sizeof text - n, " (try 'atrbvh%s%s --help')",
             cmd ? " " : "", cmd ? cmd : "");
    fputs("atrbvh: ", stderr);
    if (cmd)
        fprintf(stderr, "%s: ", cmd);
    put_line(text);
    return CLI_USAGE;
}

void cli_print_version(FILE *f)
{
    fprintf(f, "atrbvh %s (libatrbvh %s)\n", ATRBVH_VERSION_STRING,
            atrbvh_version_string());
    fprintf(f, "Optional parts: OpenMP %s, OpenCL %s, Embree %s, PNG %s\n",
#ifdef _OPENMP
            "yes",
#else
            "no",
#endif
#ifdef ATRBVH_HAVE_OPENCL
            "yes",
#else
            "no",
#endif
#ifdef HAVE_EMBREE
            "yes",
#else
            "no",
#endif
#ifdef HAVE_PNG
            "yes"
#else
            "no"
#endif
    );
    fputs("Copyright (c) 2026 The atrbvh developers.\n"
          "MIT License: free to use, copy, modify and distribute; no "
          "warranty (see COPYING).\n",
          f);
}

double cli_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

char *cli_join(const char *dir, const char *name)
{
    size_t n = strlen(dir) + strlen(name) + 2;
    char *p = malloc(n);
    if (p)
        snprintf(p, n, "%s/%s", dir, name);
    return p;
}

const char *cli_method_name(atrbvh_method m)
{
    switch (m) {
    case ATRBVH_METHOD_LBVH:
        return "lbvh";
    case ATRBVH_METHOD_TRBVH:
        return "trbvh";
    case ATRBVH_METHOD_ATRBVH:
        return "atrbvh";
    }
    return "unknown";
}

static void usage(FILE *f)
{
    fputs("Usage: atrbvh COMMAND [ARGS...]\n"
          "Build bounding volume hierarchies for ray tracing (LBVH, TRBVH, "
          "ATRBVH).\n"
          "\n"
          "Commands:\n"
          "  build SCENE [OPTIONS]    build a BVH and print its statistics\n"
          "  trace SCENE [OPTIONS]    build, then trace primary, ambient-"
          "occlusion\n"
          "                           and diffuse rays; report rays per "
          "second\n"
          "  info FILE                statistics of a saved BVH file\n"
          "  compare A B              compare two saved BVH files\n"
          "  validate SCENE [OPTIONS] build on the CPU and on OpenCL and "
          "compare\n"
          "                           every stage's output\n"
          "  bench [SCENE...]         build time, SAH, memory and rays per "
          "second of\n"
          "                           many configurations, beside Embree; "
          "plots\n"
          "  render SCENE --output F  a shaded PNG, or a heat map of "
          "traversal steps\n"
          "  stages SCENE --dump DIR  every stage's output as .npy files "
          "and a manifest\n"
          "  check DIR                compare stage dumps with the "
          "reference (the first\n"
          "                           differing stage and item)\n"
          "  animate SCENE [OPTIONS]  an animated built-in scene: the BVH "
          "refitted,\n"
          "                           re-optimised or rebuilt every frame; "
          "SAH, time\n"
          "  help [COMMAND]           this help, or that command's\n"
          "\n"
          "SCENE is a .ply or .obj file, or builtin:NAME[:N] with NAME one "
          "of\n"
          "sphere, terrain, city and N roughly the triangle count (default "
          "100000).\n"
          "\n"
          "  -h, --help               this help ('atrbvh help COMMAND' or\n"
          "                           'atrbvh COMMAND --help' for a "
          "command)\n"
          "  --version                the version, the optional parts "
          "built in and\n"
          "                           the licence\n"
          "\n"
          "Exit status: 0 success, 1 bad input or failure, 2 usage error;\n"
          "compare, validate and check: 0 same, 1 different, 2 trouble.\n"
          "See atrbvh(1).\n",
          f);
}

int main(int argc, char **argv)
{
    /* cmp: 0 same, 1 different, 2 trouble (as cmp(1)) */
    static const struct {
        const char *name;
        int (*run)(int, char **);
        int cmp;
    } commands[] = {{"build", cli_build, 0},
                    {"trace", cli_trace, 0},
                    {"info", cli_info, 0},
                    {"compare", cli_compare, 1},
                    {"validate", cli_validate, 1},
                    {"bench", cli_bench, 0},
                    {"render", cli_render, 0},
                    {"stages", cli_stages, 0},
                    {"check", cli_check, 1},
                    {"animate", cli_animate, 0}};
    size_t k;
    int rc, cmp = 0;
    const char *cmd;
    /* OpenMP threads wait passively (sleep) at barriers unless the user set
     * OMP_WAIT_POLICY: spinning makes builds 10x slower on a loaded machine
     * (docs/openmp.md).  libgomp reads it before main(), hence the exec. */
#ifdef _OPENMP
    if (!getenv("OMP_WAIT_POLICY") &&
        setenv("OMP_WAIT_POLICY", "passive", 1) == 0)
        execv("/proc/self/exe", argv); /* on failure, go on as we are */
#endif
    if (argc < 2)
        return cli_usage(NULL, "no command given");
    cmd = argv[1];
    if (strcmp(cmd, "help") == 0 && argc > 2) {
        /* atrbvh help COMMAND: that command's --help */
        char *args[3];
        if (argc > 3)
            return cli_usage(NULL, "help: one COMMAND at a time");
        for (k = 0; k < sizeof commands / sizeof commands[0]; k++)
            if (strcmp(argv[2], commands[k].name) == 0)
                break;
        if (k == sizeof commands / sizeof commands[0])
            return cli_usage(NULL, "help: unknown command '%s'", argv[2]);
        args[0] = argv[2];
        args[1] = (char *)"--help";
        args[2] = NULL;
        rc = commands[k].run(2, args);
    } else if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 ||
        strcmp(cmd, "help") == 0) {
        usage(stdout);
        rc = CLI_OK;
    } else if (strcmp(cmd, "--version") == 0) {
        cli_print_version(stdout);
        rc = CLI_OK;
    } else {
        for (k = 0; k < sizeof commands / sizeof commands[0]; k++)
            if (strcmp(cmd, commands[k].name) == 0)
                break;
        if (k == sizeof commands / sizeof commands[0]) {
            if (cmd[0] == '-')
                return cli_usage(NULL, "unknown option '%s'", cmd);
            return cli_usage(NULL, "unknown command '%s'", cmd);
        }
        rc = commands[k].run(argc - 1, argv + 1);
        cmp = commands[k].cmp;
    }
    /* A full disk or closed pipe must not pass for success, nor, for the
     * commands that compare, for an answer ("different"): trouble. */
    if ((rc == CLI_OK || (cmp && rc == CLI_FAIL)) &&
        (fflush(stdout) != 0 || ferror(stdout))) {
        fprintf(stderr, "atrbvh: writing standard output: %s\n",
                strerror(errno));
        return cmp ? CLI_USAGE : CLI_FAIL;
    }
    return rc;
}
