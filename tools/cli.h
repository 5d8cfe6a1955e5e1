/*
 * cli.h - what the subcommands of the atrbvh tool share.
 *
 * Exit status: CLI_OK; CLI_FAIL for bad input or a failure, after exactly
 * one line "atrbvh: ..." on stderr (cli_error); CLI_USAGE for a command
 * line that cannot be understood (cli_usage).
 */
#ifndef ATRBVH_TOOLS_CLI_H
#define ATRBVH_TOOLS_CLI_H

#include <stdio.h>

#include "atrbvh.h"
#include "json.h"
#include "options.h"
#include "scene.h"

#define CLI_OK 0
#define CLI_FAIL 1
#define CLI_USAGE 2

/* The most threads the tool asks for; the library defines the limit (a
 * larger count is an invalid argument there). */
#ifndef ATRBVH_MAX_THREADS
#define ATRBVH_MAX_THREADS 1024
#endif

/* Both print one line to stderr, prefixed "atrbvh: ". */
void cli_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* Adds a pointer to `atrbvh CMD --help`; returns CLI_USAGE. */
int cli_usage(const char *cmd, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

void cli_print_version(FILE *f);

/* Scans argv[1..] (up to "--") for --help/-h and --version: prints the
 * help or the version and returns CLI_OK; -1 when neither is there.  They
 * win over every other argument, wherever they stand. */
int cli_help_or_version(int argc, char **argv, void (*help)(FILE *));

/* The --help and --version lines of every command's help, and its exit
 * status line. */
void cli_common_help(FILE *f, const char *exit_status);

/* Wall clock in milliseconds, monotonic. */
double cli_now_ms(void);

/* "dir/name" in a new malloc'ed string, or NULL when out of memory. */
char *cli_join(const char *dir, const char *name);

const char *cli_method_name(atrbvh_method m);

/* ------------------------------- build options (build, trace, render,
 * validate) */
typedef struct cli_build_args {
    const char *scene;
    atrbvh_build_options options;
    int json;
    const char *output;
    int method, backend; /* CLI_OPT_ENUM indices, applied to options */
    int device_given;
    int tuned;       /* --treelet or --rounds given after the last
                        --quality (LBVH takes neither)              */
    int quiet;       /* --quiet: no progress on stderr */
    const char *cmd; /* the subcommand, for usage messages */
} cli_build_args;

/* Which build options a command takes. */
#define CLI_BUILD_CORE 1u    /* method, quality, treelet, rounds, threads,
                                collapse, leaves, costs, skip-invalid */
#define CLI_BUILD_BACKEND 2u /* --backend */
#define CLI_BUILD_DEVICE 4u  /* --device */
#define CLI_BUILD_OUTPUT 8u  /* -o, --output: save the BVH */
#define CLI_BUILD_JSON 16u   /* --json */
#define CLI_BUILD_ALL 31u
#define CLI_BUILD_MAX_OPTS 24

void cli_build_args_init(cli_build_args *a);
/* The build options of `groups` as an option table writing into `a`
 * (table has room for CLI_BUILD_MAX_OPTS + 1 entries). */
void cli_build_opts(cli_build_args *a, unsigned groups, cli_opt *table);
/* The whole command line of build, trace, render and validate: `extra`
 * (the command's own options, may be NULL), the build options of
 * `groups`, one SCENE.  Then the option values are checked against each
 * other and against the library's limits before anything is loaded (an
 * out-of-range value is a usage error naming the option).  CLI_OK or
 * CLI_USAGE (after the message). */
int cli_build_parse(const char *cmd, int argc, char **argv,
                    const cli_opt *extra, unsigned groups, cli_build_args *a);
/* "Usage" text, the command's own options under `title`, the build
 * options of `groups`, --help/--version and the exit status. */
void cli_build_help(FILE *f, const char *intro, const char *title,
                    const cli_opt *extra, unsigned groups,
                    const char *exit_status);

typedef struct cli_built {
    scene sc;
    atrbvh_geometry geometry;
    atrbvh_bvh *bvh;
    atrbvh_stats stats;
    double load_ms;
    atrbvh_device *device; /* opened once for --backend opencl (builds and
                              device ray batches), else NULL */
} cli_built;

/* Loads the scene, builds, saves when asked; CLI_OK, or CLI_FAIL after an
 * error line (CLI_USAGE for a device that is not there).  Free with cli_built_free either way. */
int cli_load_and_build(const cli_build_args *a, cli_built *b);
/* 1 when the library's answer (st, text) says that the OpenCL device
 * asked for is not there: a usage error naming --device. */
int cli_bad_device(const cli_build_args *a, atrbvh_status st,
                   const char *text);
void cli_built_free(cli_built *b);

/* The build's keys, inside an object the caller opened. */
void cli_build_json(json_writer *w, const cli_build_args *a,
                    const cli_built *b);
void cli_build_text(FILE *f, const cli_build_args *a, const cli_built *b);

/* --quality presets (docs/benchmarks.md has the measurements behind
 * them): fast = LBVH, balanced = ATRBVH(9,2), high = ATRBVH with these.
 * 1 and the method, treelet size and rounds for a known name, else 0. */
#define CLI_QUALITY_HIGH_TREELET ATRBVH_TREELET_AUTO
#define CLI_QUALITY_HIGH_ROUNDS 4u
/* A treelet size as text: the number, or "auto" for ATRBVH_TREELET_AUTO
 * (buf of at least 16 chars). */
const char *cli_treelet_text(unsigned size, char *buf);
/* --treelet's value: "auto" or a whole number; 0 when malformed. */
int cli_parse_treelet(const char *s, unsigned *out);
int cli_quality_preset(const char *name, atrbvh_method *m, unsigned *treelet,
                       unsigned *rounds);
/* A split rule's name as --split-rule takes it ("tree", "priority",
 * "sah"), or "" for a value outside the ATRBVH_SPLIT_ ones. */
const char *cli_split_rule_name(int rule);

/* An 8-bit RGB PNG (libpng; without HAVE_PNG always fails).  0, or -1
 * after an error line. */
int cli_png_write(const char *path, unsigned width, unsigned height,
                  const unsigned char *rgb);
/* 1 when built with libpng. */
int cli_png_available(void);

/* --------------------------------------------------------- subcommands */
int cli_build(int argc, char **argv);
int cli_trace(int argc, char **argv);
int cli_info(int argc, char **argv);
int cli_compare(int argc, char **argv);
int cli_validate(int argc, char **argv);
int cli_bench(int argc, char **argv);
int cli_render(int argc, char **argv);
int cli_stages(int argc, char **argv);
int cli_check(int argc, char **argv);
int cli_animate(int argc, char **argv);

#endif
