/*
 * cli_file.c - `atrbvh info FILE` and `atrbvh compare A B`: saved BVH
 * files (atrbvh(5)), through atrbvh_load only, so that the tool checks
 * files exactly as strictly as the library does.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"

#include <string.h>

static int info_json;
static const cli_opt info_opts[] = {
    {.name = "--json", .kind = CLI_OPT_FLAG, .dest = &info_json,
     .flag_value = 1, .help = "print one JSON object"},
    {.name = NULL}};
static const cli_opt compare_opts[] = {{.name = NULL}};

static void info_help(FILE *f)
{
    fputs("Usage: atrbvh info FILE [--json]\n"
          "Print the statistics of a BVH file saved by 'atrbvh build "
          "--output'.\n"
          "\n",
          f);
    cli_opts_help(f, info_opts);
    cli_common_help(f, "0 success, 1 bad input or failure, 2 usage error");
}

static void compare_help(FILE *f)
{
    fputs("Usage: atrbvh compare A B\n"
          "Compare two BVH files: exit 0 when they are identical (constants, "
          "nodes\n"
          "bit for bit, primitive indices); otherwise exit 1 naming the first "
          "difference.\n"
          "\n",
          f);
    cli_opts_help(f, compare_opts);
    cli_common_help(f, "0 identical, 1 different, 2 trouble (usage error, "
                       "a file that cannot\nbe read)");
}

/* The positional arguments of info/compare. */
static int collect(const char *cmd, int argc, char **argv,
                   const cli_opt *opts, const char **pos, int want)
{
    const cli_opt *tables[2];
    int n;
    tables[0] = opts;
    tables[1] = NULL;
    if (cli_parse(cmd, argc, argv, tables, NULL, pos, want, &n, "FILE") != 0)
        return CLI_USAGE;
    if (n < want)
        return cli_usage(cmd, want == 1 ? "no FILE given"
                                        : "needs two files, A and B");
    return CLI_OK;
}

static int load(const char *path, atrbvh_bvh **out)
{
    atrbvh_error e;
    atrbvh_status st;
    memset(&e, 0, sizeof e);
    st = atrbvh_load(path, out, &e);
    if (st != ATRBVH_OK) {
        const char *text = e.text[0] ? e.text : atrbvh_strerror(st);
        *out = NULL;
        if (strstr(text, path))
            cli_error("%s", text);
        else
            cli_error("%s: %s", path, text);
        return CLI_FAIL;
    }
    return CLI_OK;
}

int cli_info(int argc, char **argv)
{
    const char *path = NULL;
    int json = 0, rc;
    atrbvh_bvh *bvh;
    atrbvh_stats s;
    size_t refs = 0;
    if ((rc = cli_help_or_version(argc, argv, info_help)) >= 0)
        return rc;
    info_json = 0;
    if ((rc = collect("info", argc, argv, info_opts, &path, 1)) != CLI_OK)
        return rc;
    json = info_json;
    if (load(path, &bvh) != CLI_OK)
        return CLI_FAIL;
    atrbvh_bvh_stats(bvh, &s);
    (void)atrbvh_bvh_primitive_indices(bvh, &refs); /* split: more */
    if (json) {
        json_writer w;
        json_init(&w, stdout);
        json_begin_object(&w);
        json_kv_string(&w, "file", path);
        json_kv_uint(&w, "primitives", s.primitives);
        if (refs != s.primitives)
            json_kv_uint(&w, "references", refs);
        json_kv_string(&w, "method", cli_method_name(s.method));
        if (s.treelet_size == ATRBVH_TREELET_AUTO)
            json_kv_string(&w, "treelet_size", "auto");
        else
            json_kv_uint(&w, "treelet_size", s.treelet_size);
        json_kv_uint(&w, "rounds", s.rounds);
        json_kv_double(&w, "ci", s.ci);
        json_kv_double(&w, "ct", s.ct);
        json_kv_double(&w, "sah", s.sah);
        json_kv_uint(&w, "nodes", s.nodes);
        json_kv_uint(&w, "leaves", s.leaves);
        json_kv_uint(&w, "max_depth", s.max_depth);
        json_kv_uint(&w, "max_leaf_primitives", s.max_leaf_primitives);
        json_end_object(&w);
    } else {
        printf("file             %s\n", path);
        printf("primitives       %zu\n", s.primitives);
        if (refs != s.primitives)
            printf("references       %zu (triangle splitting)\n", refs);
        printf("method           %s", cli_method_name(s.method));
        if (s.method != ATRBVH_METHOD_LBVH)
        {
            char tb[16];
            printf(" (treelet %s, %u rounds)",
                   cli_treelet_text(s.treelet_size, tb), s.rounds);
        }
        putchar('\n');
        printf("SAH              %.6g (ci %g, ct %g)\n", s.sah, s.ci, s.ct);
        printf("nodes            %zu\n", s.nodes);
        printf("leaves           %zu\n", s.leaves);
        printf("max depth        %u\n", s.max_depth);
        printf("largest leaf     %u\n", s.max_leaf_primitives);
    }
    atrbvh_bvh_free(bvh);
    return CLI_OK;
}

int cli_compare(int argc, char **argv)
{
    const char *pos[2] = {NULL, NULL};
    int rc;
    atrbvh_bvh *a, *b;
    atrbvh_error e;
    if ((rc = cli_help_or_version(argc, argv, compare_help)) >= 0)
        return rc;
    if ((rc = collect("compare", argc, argv, compare_opts, pos, 2)) != CLI_OK)
        return rc;
    /* As cmp: a file that cannot be read is trouble (2), not a
     * difference (1). */
    if (load(pos[0], &a) != CLI_OK)
        return CLI_USAGE;
    if (load(pos[1], &b) != CLI_OK) {
        atrbvh_bvh_free(a);
        return CLI_USAGE;
    }
    memset(&e, 0, sizeof e);
    if (atrbvh_compare(a, b, &e) != 0) {
        cli_error("%s and %s differ: %s", pos[0], pos[1],
                  e.text[0] ? e.text : "(no detail given)");
        rc = CLI_FAIL;
    } else {
        printf("%s and %s are identical\n", pos[0], pos[1]);
        rc = CLI_OK;
    }
    atrbvh_bvh_free(a);
    atrbvh_bvh_free(b);
    return rc;
}
