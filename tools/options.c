/*
 * options.c - the table-driven option parser of the atrbvh tool (see
 * options.h).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "options.h"

#include "cli.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HELP_COLUMN 23

int cli_parse_ulong(const char *s, unsigned long max, unsigned long *out)
{
    char *end;
    unsigned long v;
    /* strtoul accepts leading blanks and a minus sign (negating): reject
     * both, a number is digits only. */
    if (!s || *s < '0' || *s > '9')
        return 0;
    errno = 0;
    v = strtoul(s, &end, 10);
    if (errno == ERANGE || *end != '\0' || v > max)
        return 0;
    *out = v;
    return 1;
}

int cli_parse_long(const char *s, long min, long max, long *out)
{
    char *end;
    long v;
    if (!s || !(*s == '-' || *s == '+' || (*s >= '0' && *s <= '9')))
        return 0;
    errno = 0;
    v = strtol(s, &end, 10);
    if (errno == ERANGE || end == s || *end != '\0' || v < min || v > max)
        return 0;
    *out = v;
    return 1;
}

int cli_parse_double(const char *s, double *out)
{
    char *end;
    double v;
    if (!s || *s == '\0' || *s == ' ' || *s == '\t' || *s == '\n')
        return 0;
    errno = 0;
    v = strtod(s, &end);
    /* Overflow is out of range; underflow gives a usable tiny value. */
    if (end == s || *end != '\0' || (errno == ERANGE && (v > 1.0 || v < -1.0)))
        return 0;
    *out = v;
    return 1;
}

/* "a, b or c" */
static void choices_text(const char *const *choices, const char *sep,
                         const char *last_sep, char *buf, size_t n)
{
    size_t used = 0;
    int k, count = 0;
    while (choices[count])
        count++;
    buf[0] = '\0';
    for (k = 0; k < count && used < n; k++) {
        int w = snprintf(buf + used, n - used, "%s%s",
                         k == 0 ? "" : k == count - 1 ? last_sep : sep,
                         choices[k]);
        if (w < 0)
            break;
        used += (size_t)w;
    }
}

static int whole_number(const char *cmd, const cli_opt *o, const char *v,
                        long *out)
{
    long lo = (long)o->min, hi = (long)o->max;
    if (cli_parse_long(v, lo, hi, out) &&
        !(o->kind == CLI_OPT_UINT && (*v == '+' || *v == '-')))
        return 0;
    if (hi >= (long)UINT_MAX) /* no upper limit of its own */
        return cli_usage(cmd, "%s: '%s' is not a whole number, %ld or more",
                         o->name, v, lo);
    return cli_usage(cmd, "%s: '%s' is not a whole number from %ld to %ld",
                     o->name, v, lo, hi);
}

static int apply(const char *cmd, const cli_opt *o, const char *v,
                 void *user)
{
    long l;
    double d;
    int k;
    char text[256];
    if (o->seen)
        *o->seen = 1;
    switch (o->kind) {
    case CLI_OPT_FLAG:
        *(int *)o->dest = o->flag_value;
        return 0;
    case CLI_OPT_INT:
        if (whole_number(cmd, o, v, &l) != 0)
            return CLI_USAGE;
        *(int *)o->dest = (int)l;
        return 0;
    case CLI_OPT_UINT:
        if (whole_number(cmd, o, v, &l) != 0)
            return CLI_USAGE;
        *(unsigned *)o->dest = (unsigned)l;
        return 0;
    case CLI_OPT_DOUBLE:
        if (!cli_parse_double(v, &d) || !isfinite(d) ||
            (o->min_open ? !(d > o->min) : !(d >= o->min)) || d > o->max)
            return cli_usage(cmd, "%s: '%s' is not a number %s %g and at "
                             "most %g", o->name, v,
                             o->min_open ? "above" : "from", o->min,
                             o->max);
        *(double *)o->dest = d;
        return 0;
    case CLI_OPT_STRING:
        if (*v == '\0')
            return cli_usage(cmd, "%s: empty value", o->name);
        *(const char **)o->dest = v;
        return 0;
    case CLI_OPT_ENUM:
        for (k = 0; o->choices[k]; k++)
            if (strcmp(v, o->choices[k]) == 0) {
                *(int *)o->dest = k;
                return 0;
            }
        choices_text(o->choices, ", ", " or ", text, sizeof text);
        return cli_usage(cmd, "%s: '%s' is not %s", o->name, v, text);
    case CLI_OPT_CALL:
        return o->call(cmd, o, v, user);
    }
    return CLI_USAGE;
}

static const cli_opt *find(const cli_opt *const *tables, const char *arg,
                           size_t len)
{
    int t;
    const cli_opt *o;
    for (t = 0; tables[t]; t++)
        for (o = tables[t]; o->name; o++)
            if ((strlen(o->name) == len && strncmp(arg, o->name, len) == 0) ||
                (o->alias && strlen(o->alias) == len &&
                 strncmp(arg, o->alias, len) == 0))
                return o;
    return NULL;
}

static int takes_value(const cli_opt *o)
{
    return o->kind != CLI_OPT_FLAG && !(o->kind == CLI_OPT_CALL && !o->arg);
}

int cli_parse(const char *cmd, int argc, char **argv,
              const cli_opt *const *tables, void *user, const char **pos,
              int maxpos, int *npos, const char *what)
{
    int i = 1, dashdash = 0;
    *npos = 0;
    while (i < argc) {
        const char *arg = argv[i], *eq, *value = NULL;
        const cli_opt *o;
        size_t len;
        if (dashdash || arg[0] != '-' || arg[1] == '\0') {
            if (*npos == maxpos) {
                if (maxpos == 1)
                    return cli_usage(cmd, "more than one %s ('%s', '%s')",
                                     what, pos[0], arg);
                return cli_usage(cmd, "too many arguments ('%s')", arg);
            }
            pos[(*npos)++] = arg;
            i++;
            continue;
        }
        if (strcmp(arg, "--") == 0) {
            dashdash = 1;
            i++;
            continue;
        }
        eq = arg[1] == '-' ? strchr(arg, '=') : NULL;
        len = eq ? (size_t)(eq - arg) : strlen(arg);
        o = find(tables, arg, len);
        if (!o)
            return cli_usage(cmd, "unknown option '%s'", arg);
        if (!takes_value(o)) {
            if (eq)
                return cli_usage(cmd, "%s takes no value", o->name);
            i++;
        } else if (eq) {
            value = eq + 1;
            i++;
        } else {
            if (i + 1 >= argc)
                return cli_usage(cmd, "%s needs a value", o->name);
            value = argv[i + 1];
            i += 2;
        }
        if (apply(cmd, o, value, user) != 0)
            return CLI_USAGE;
    }
    return 0;
}

void cli_opts_help(FILE *f, const cli_opt *table)
{
    const cli_opt *o;
    for (; table->name; table++) {
        char lhs[128], arg[128];
        const char *h;
        int n;
        o = table;
        arg[0] = '\0';
        if (o->kind == CLI_OPT_ENUM && !o->arg)
            choices_text(o->choices, "|", "|", arg, sizeof arg);
        else if (takes_value(o) && o->arg)
            snprintf(arg, sizeof arg, "%s", o->arg);
        n = snprintf(lhs, sizeof lhs, "  %s%s%s%s%s", o->alias ? o->alias : "",
                     o->alias ? ", " : "", o->name, arg[0] ? " " : "", arg);
        fputs(lhs, f);
        if (n + 2 > HELP_COLUMN)
            fputs("  ", f);
        else
            fprintf(f, "%*s", HELP_COLUMN - n, "");
        for (h = o->help; *h; h++) {
            fputc(*h, f);
            if (*h == '\n')
                fprintf(f, "%*s", HELP_COLUMN, "");
        }
        fputc('\n', f);
    }
}
