/*
 * options.h - the one option parser of the atrbvh tool.
 *
 * Every subcommand describes its options in a table of cli_opt (name,
 * kind, range, destination, help text); cli_parse reads the command line
 * from it and cli_opts_help prints the command's option help from the same
 * table, so the help always matches what is accepted.  A value that is
 * not of the option's kind or is out of its range is a usage error (exit
 * 2) whose message names the option.
 */
#ifndef ATRBVH_TOOLS_OPTIONS_H
#define ATRBVH_TOOLS_OPTIONS_H

#include <stdio.h>

typedef enum cli_opt_kind {
    CLI_OPT_FLAG,   /* no value: *(int *)dest = flag_value              */
    CLI_OPT_INT,    /* *(int *)dest, within [min, max]                   */
    CLI_OPT_UINT,   /* *(unsigned *)dest, within [min, max]              */
    CLI_OPT_DOUBLE, /* *(double *)dest, finite, within [min, max]        */
    CLI_OPT_STRING, /* *(const char **)dest, never empty                 */
    CLI_OPT_ENUM,   /* *(int *)dest = index of the value in choices      */
    CLI_OPT_CALL    /* call(cmd, opt, value, user): 0, or CLI_USAGE      */
} cli_opt_kind;

typedef struct cli_opt cli_opt;
struct cli_opt {
    const char *name;  /* "--threads"; NULL ends a table               */
    const char *alias; /* "-o", or NULL                                 */
    cli_opt_kind kind;
    const char *arg;   /* the value's name in the help: "N", "FILE"     */
    double min, max;   /* INT, UINT, DOUBLE (DOUBLE: min is exclusive
                          when min_open is set)                          */
    int min_open;
    void *dest;
    int flag_value;             /* FLAG                                 */
    const char *const *choices; /* ENUM: NULL-terminated                */
    int (*call)(const char *cmd, const cli_opt *opt, const char *value,
                void *user);    /* CALL (value NULL for a flag: arg NULL) */
    const char *help;  /* may hold '\n' for more lines                 */
    int *seen;         /* set to 1 when the option is given (optional)  */
};

/* Copies the option array `opts` (a literal, ended by {.name = NULL})
 * into `table`, which has room for `room` entries; fails to compile when
 * it does not fit. */
#define CLI_OPTS_COPY(table, opts, room)                                       \
    do {                                                                       \
        (void)sizeof(                                                          \
            char[sizeof(opts) / sizeof((opts)[0]) <= (room) ? 1 : -1]);        \
        memcpy((table), (opts), sizeof(opts));                                 \
    } while (0)

/* Parses argv[1..argc-1] against the NULL-name-terminated tables in
 * `tables` (a NULL-terminated array).  "--name VALUE", "--name=VALUE",
 * "-o VALUE"; "--" ends the options; "-" is a positional argument.
 * Positional arguments go to pos[0..maxpos-1] (*npos their count); more
 * than maxpos is a usage error naming `what` ("SCENE").  Returns 0, or
 * CLI_USAGE after one usage line. */
int cli_parse(const char *cmd, int argc, char **argv,
              const cli_opt *const *tables, void *user, const char **pos,
              int maxpos, int *npos, const char *what);

/* The lines of a --help text for every option of `table`. */
void cli_opts_help(FILE *f, const cli_opt *table);

/* Strict number parsing: the whole string, decimal.  1 on success. */
int cli_parse_ulong(const char *s, unsigned long max, unsigned long *out);
int cli_parse_long(const char *s, long min, long max, long *out);
int cli_parse_double(const char *s, double *out);

#endif
