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
#include "scene.h"

#define CLI_OK 0
#define CLI_FAIL 1
#define CLI_USAGE 2

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

/* Strict number parsing: the whole string, decimal, within [min, max].
 * 1 on success. */
int cli_parse_ulong(const char *s, unsigned long max, unsigned long *out);
int cli_parse_long(const char *s, long min, long max, long *out);
int cli_parse_double(const char *s, double *out);

/* If argv[*i] is the option `name` ("--name VALUE" or "--name=VALUE"),
 * sets *value, advances *i past it and returns 1; returns 0 when argv[*i]
 * is another argument, and CLI_USAGE's negative (-1) after a usage
 * message when the value is missing. */
int cli_option(const char *cmd, int argc, char **argv, int *i,
               const char *name, const char **value);

/* Scans argv[1..] (up to "--") for --help/-h and --version: prints the
 * help or the version and returns CLI_OK; -1 when neither is there.  They
 * win over every other argument, wherever they stand. */
int cli_help_or_version(int argc, char **argv, void (*help)(FILE *));

/* Wall clock in milliseconds, monotonic. */
double cli_now_ms(void);

const char *cli_method_name(atrbvh_method m);

/* ------------------------------------------ build options (build, trace) */
typedef struct cli_build_args {
    const char *scene;
    atrbvh_build_options options;
    int json;
    const char *output;
} cli_build_args;

void cli_build_args_init(cli_build_args *a);
/* Consumes argv[*i] if it is a build option: 1 consumed, 0 not a build
 * option, -1 usage error (already printed). */
int cli_build_option(const char *cmd, int argc, char **argv, int *i,
                     cli_build_args *a);
/* The build options' lines of a --help text. */
void cli_build_options_help(FILE *f);

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
 * error line.  Free with cli_built_free either way. */
int cli_load_and_build(const cli_build_args *a, cli_built *b);
void cli_built_free(cli_built *b);

/* The build's keys, inside an object the caller opened. */
void cli_build_json(json_writer *w, const cli_build_args *a,
                    const cli_built *b);
void cli_build_text(FILE *f, const cli_build_args *a, const cli_built *b);

/* --quality presets (docs/benchmarks.md has the measurements behind
 * them): fast = LBVH, balanced = ATRBVH(9,2), high = ATRBVH with these.
 * 1 and the method, treelet size and rounds for a known name, else 0. */
#define CLI_QUALITY_HIGH_TREELET 20u
#define CLI_QUALITY_HIGH_ROUNDS 3u
int cli_quality_preset(const char *name, atrbvh_method *m, unsigned *treelet,
                       unsigned *rounds);

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

#endif
