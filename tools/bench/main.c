/*
 * main.c - `atrbvh bench`: the command line (options, configuration
 * lists, help).  The measurement itself is in run.c, sweep.c and scaling.c.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "bench.h"
#include "memtrack.h"
#include "outfile.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define MAX_SIDE 4096u
#define MAX_REPEAT 1000u
#define MAX_VIEWPOINTS 64u
#define MAX_SPP 64u
#define MAX_QUALITIES 8
#define DEFAULT_CONFIGS "lbvh,trbvh:7:3,atrbvh:9:2,high,embree"
#define DEFAULT_SCALING_CONFIGS "lbvh,atrbvh:9:2"
#define DEFAULT_SCENE "builtin:city:100000"
#define DEFAULT_SIZES "10000,100000,1000000,10000000"
const char *bench_backend_name(atrbvh_backend b)
{
    return b == ATRBVH_BACKEND_OPENCL ? "opencl" : "cpu";
}

const char *row_method(const row *r)
{
    return r->c.embree ? embree_quality_name(r->c.eq)
                       : cli_method_name(r->c.method);
}

void config_label(const config *c, unsigned treelet, unsigned rounds,
                  char *buf, size_t n)
{
    char tb[16], sp[48] = "";
    if (c->split > 0.0)
        snprintf(sp, sizeof sp, "+split%g%s%s", c->split,
                 c->split_rule >= 0 ? "/" : "",
                 cli_split_rule_name(c->split_rule));
    if (c->embree)
        snprintf(buf, n, "%s", embree_quality_name(c->eq));
    else if (c->method == ATRBVH_METHOD_LBVH)
        snprintf(buf, n, "LBVH%s%s", sp,
                 c->backend == ATRBVH_BACKEND_OPENCL ? "/cl" : "");
    else
        snprintf(buf, n, "%s(%s,%u)%s%s",
                 c->method == ATRBVH_METHOD_TRBVH ? "TRBVH" : "ATRBVH",
                 cli_treelet_text(treelet, tb), rounds, sp,
                 c->backend == ATRBVH_BACKEND_OPENCL ? "/cl" : "");
}

static int add_config(bench_args *a, const config *c)
{
    int k;
    for (k = 0; k < a->nconfigs; k++)
        if (memcmp(&a->configs[k], c, sizeof *c) == 0)
            return 0; /* once each */
    if (a->nconfigs == MAX_CONFIGS)
        return cli_usage("bench", "more than %d configurations",
                         MAX_CONFIGS), -1;
    a->configs[a->nconfigs++] = *c;
    return 0;
}

static int parse_uint_list(const char *opt, const char *s, unsigned long max,
                           unsigned long *out, int *n, int cap)
{
    char buf[512], *tok, *save = NULL;
    if (strlen(s) >= sizeof buf)
        return cli_usage("bench", "%s: list too long", opt), -1;
    strcpy(buf, s);
    *n = 0;
    for (tok = strtok_r(buf, ",", &save); tok;
         tok = strtok_r(NULL, ",", &save)) {
        if (*n == cap)
            return cli_usage("bench", "%s: more than %d values", opt, cap),
                   -1;
        if (!cli_parse_ulong(tok, max, &out[*n]))
            return cli_usage("bench", "%s: '%s' is not a whole number from "
                             "0 to %lu", opt, tok, max), -1;
        (*n)++;
    }
    if (*n == 0)
        return cli_usage("bench", "%s: empty list", opt), -1;
    return 0;
}

/* "lbvh", "trbvh[:N[:R]]", "atrbvh[:N[:R]]", "fast|balanced|high",
 * "embree" (the first three), "embree_low|medium|high|split"; the
 * library's configurations with an optional "+split=B" (the split budget,
 * as build --split) or "+split=B/RULE" (and --split-rule RULE), and then
 * "@opencl" or "@cpu". */
static int parse_configs(bench_args *a, const char *s, atrbvh_backend be)
{
    char buf[1024], *tok, *save = NULL;
    if (strlen(s) >= sizeof buf)
        return cli_usage("bench", "--configs: list too long"), -1;
    strcpy(buf, s);
    for (tok = strtok_r(buf, ",", &save); tok;
         tok = strtok_r(NULL, ",", &save)) {
        config c;
        char *at = strchr(tok, '@'), *p;
        unsigned long v;
        memset(&c, 0, sizeof c);
        c.backend = be;
        if (at) {
            *at++ = '\0';
            if (strcmp(at, "cpu") == 0)
                c.backend = ATRBVH_BACKEND_CPU;
            else if (strcmp(at, "opencl") == 0)
                c.backend = ATRBVH_BACKEND_OPENCL;
            else
                return cli_usage("bench", "--configs: unknown backend '%s'",
                                 at), -1;
        }
        if ((p = strstr(tok, "+split=")) != NULL) {
            char *end, *rule;
            double b;
            *p = '\0';
            p += 7;
            c.split_rule = -1;
            if ((rule = strchr(p, '/')) != NULL) {
                *rule++ = '\0';
                for (c.split_rule = ATRBVH_SPLIT_TREE;
                     c.split_rule <= ATRBVH_SPLIT_SAH &&
                     strcmp(rule, cli_split_rule_name(c.split_rule)) != 0;
                     c.split_rule++)
                    ;
                if (c.split_rule > ATRBVH_SPLIT_SAH)
                    return cli_usage("bench", "--configs: split rule '%s' "
                                     "is not sah, tree or priority", rule),
                           -1;
            }
            b = strtod(p, &end);
            if (end == p || *end || !(b > 0.0 && b <= 4.0))
                return cli_usage("bench", "--configs: split budget '%s' is "
                                 "not a number above 0 and at most 4", p),
                       -1;
            if (strncmp(tok, "embree", 6) == 0)
                return cli_usage("bench", "--configs: +split is for the "
                                 "library's configurations (embree_split "
                                 "is Embree's)"), -1;
            c.split = b;
        }
        if (strcmp(tok, "embree") == 0 || strncmp(tok, "embree_", 7) == 0) {
            int q, lo = 0, hi = 2;
            if (at)
                return cli_usage("bench", "--configs: '%s' takes no "
                                 "backend", tok), -1;
            if (tok[6] == '_') {
                if (strcmp(tok + 7, "low") == 0)
                    lo = hi = 0;
                else if (strcmp(tok + 7, "medium") == 0)
                    lo = hi = 1;
                else if (strcmp(tok + 7, "high") == 0)
                    lo = hi = 2;
                else if (strcmp(tok + 7, "split") == 0)
                    lo = hi = 3;
                else
                    return cli_usage("bench", "--configs: unknown '%s'", tok),
                           -1;
            }
            if (!embree_available())
                continue; /* the header says so */
            for (q = lo; q <= hi; q++) {
                memset(&c, 0, sizeof c);
                c.embree = 1;
                c.eq = (embree_quality)q;
                if (add_config(a, &c) != 0)
                    return -1;
            }
            continue;
        }
        if (cli_quality_preset(tok, &c.method, &c.treelet, &c.rounds)) {
            if (add_config(a, &c) != 0)
                return -1;
            continue;
        }
        p = strchr(tok, ':');
        if (p)
            *p++ = '\0';
        if (strcmp(tok, "lbvh") == 0)
            c.method = ATRBVH_METHOD_LBVH;
        else if (strcmp(tok, "trbvh") == 0)
            c.method = ATRBVH_METHOD_TRBVH;
        else if (strcmp(tok, "atrbvh") == 0)
            c.method = ATRBVH_METHOD_ATRBVH;
        else
            return cli_usage("bench", "--configs: unknown method '%s'", tok),
                   -1;
        if (p && c.method != ATRBVH_METHOD_LBVH) {
            char *r = strchr(p, ':');
            if (r)
                *r++ = '\0';
            if (c.method == ATRBVH_METHOD_ATRBVH && strcmp(p, "auto") == 0)
                c.treelet = ATRBVH_TREELET_AUTO;
            else if (!cli_parse_ulong(p, 128, &v) || v == 0)
                return cli_usage("bench", "--configs: treelet size '%s' is "
                                 "not a whole number from 1 to 128%s", p,
                                 c.method == ATRBVH_METHOD_ATRBVH
                                     ? " or auto" : ""), -1;
            else
                c.treelet = (unsigned)v;
            if (r) {
                if (!cli_parse_ulong(r, 64, &v) || v == 0)
                    return cli_usage("bench", "--configs: rounds '%s' is not "
                                     "a whole number from 1 to 64", r), -1;
                c.rounds = (unsigned)v;
            }
        } else if (p) {
            return cli_usage("bench", "--configs: lbvh takes no treelet "
                             "size"), -1;
        }
        if (add_config(a, &c) != 0)
            return -1;
    }
    return 0;
}

/* ---------------------------------------------------------------- main */
typedef struct bench_cl {
    bench_args a;
    const char *configs, *methods, *treelets, *rounds, *backends, *sizes;
    const char *qualities[MAX_QUALITIES];
    int nq, no_rays;
} bench_cl;

static int on_quality(const char *cmd, const cli_opt *o, const char *v,
                      void *user)
{
    bench_cl *b = user;
    atrbvh_method m;
    unsigned t, r;
    (void)o;
    if (!cli_quality_preset(v, &m, &t, &r))
        return cli_usage(cmd, "--quality: '%s' is not fast, balanced or high",
                         v);
    if (b->nq == MAX_QUALITIES)
        return cli_usage(cmd, "--quality: more than %d", MAX_QUALITIES);
    b->qualities[b->nq++] = v;
    return 0;
}

#define BENCH_OPTS (26 + RAYS_CAMERA_OPTS)
static void bench_opts(bench_cl *b, cli_opt *table)
{
    bench_args *a = &b->a;
    const cli_opt opts[] = {
        {.name = "--configs", .kind = CLI_OPT_STRING, .arg = "LIST",
         .dest = &b->configs,
         .help = "comma-separated: lbvh, trbvh[:N[:R]],\n"
                 "atrbvh[:N[:R]] (N a size or auto), fast,\n"
                 "balanced, high, embree (low, medium and\n"
                 "high), embree_low, embree_medium,\n"
                 "embree_high, embree_split (high with\n"
                 "spatial splits, 20% more references);\n"
                 "+split=B[/RULE] after a library one splits\n"
                 "triangles (as build --split B --split-rule\n"
                 "RULE); @cpu or\n"
                 "@opencl after one picks its backend\n"
                 "(default " DEFAULT_CONFIGS ")"},
        {.name = "--methods", .kind = CLI_OPT_STRING, .arg = "LIST",
         .dest = &b->methods,
         .help = "instead of --configs: methods (lbvh, trbvh,\n"
                 "atrbvh, embree) crossed with --treelet and --rounds"},
        {.name = "--treelet", .kind = CLI_OPT_STRING, .arg = "LIST",
         .dest = &b->treelets, .help = "treelet sizes for --methods"},
        {.name = "--rounds", .kind = CLI_OPT_STRING, .arg = "LIST",
         .dest = &b->rounds, .help = "rounds for --methods"},
        {.name = "--backend", .kind = CLI_OPT_STRING, .arg = "LIST",
         .dest = &b->backends,
         .help = "cpu, opencl or cpu,opencl (default cpu); OpenCL\n"
                 "rows fail the run when there is no OpenCL device"},
        {.name = "--quality", .kind = CLI_OPT_CALL, .arg = "PRESET",
         .call = on_quality,
         .help = "add fast, balanced or high to the list (repeatable)"},
        {.name = "--repeat", .kind = CLI_OPT_UINT, .arg = "K", .min = 1,
         .max = MAX_REPEAT, .dest = &a->repeat,
         .help = "timed runs per configuration after one warm-up\n"
                 "(median; default 3)"},
        {.name = "--threads", .kind = CLI_OPT_INT, .arg = "N", .min = 0,
         .max = ATRBVH_MAX_THREADS, .dest = &a->base.threads,
         .help = "threads for builds and tracing (default: all)"},
        {.name = "--max-leaf", .kind = CLI_OPT_UINT, .arg = "N", .min = 0,
         .max = 1024, .dest = &a->base.max_leaf_size,
         .help = "leaf limit on both sides (default 8)"},
        {.name = "--ci", .kind = CLI_OPT_DOUBLE, .arg = "X", .min = 0.0,
         .min_open = 1, .max = 1e30, .dest = &a->base.ci,
         .help = "SAH cost of an internal node (default 1.2)"},
        {.name = "--ct", .kind = CLI_OPT_DOUBLE, .arg = "X", .min = 0.0,
         .min_open = 1, .max = 1e30, .dest = &a->base.ct,
         .help = "SAH cost of a primitive (default 1.0)"},
        {.name = "--width", .kind = CLI_OPT_UINT, .arg = "W", .min = 1,
         .max = MAX_SIDE, .dest = &a->width,
         .help = "image width per viewpoint (default 256)"},
        {.name = "--height", .kind = CLI_OPT_UINT, .arg = "H", .min = 1,
         .max = MAX_SIDE, .dest = &a->height,
         .help = "image height per viewpoint (default 192)"},
        {.name = "--viewpoints", .kind = CLI_OPT_UINT, .arg = "V", .min = 1,
         .max = MAX_VIEWPOINTS, .dest = &a->viewpoints,
         .help = "cameras 0..V-1 (default 3; see CAMERAS in atrbvh(1))"},
        {.name = "--spp", .kind = CLI_OPT_UINT, .arg = "N", .min = 0,
         .max = MAX_SPP, .dest = &a->spp,
         .help = "AO and diffuse rays per primary hit (default 2)"},
        {.name = "--no-rays", .kind = CLI_OPT_FLAG, .dest = &b->no_rays,
         .flag_value = 1, .help = "builds only"},
        {.name = "--fresh", .kind = CLI_OPT_FLAG, .dest = &a->fresh,
         .flag_value = 1,
         .help = "free the last tree before each build\n"
                 "(default: atrbvh_rebuild into it)"},
        {.name = "--csv", .kind = CLI_OPT_STRING, .arg = "FILE",
         .dest = &a->csv,
         .help = "one row per configuration (columns: atrbvh(1))"},
        {.name = "--builds", .kind = CLI_OPT_STRING, .arg = "FILE",
         .dest = &a->builds,
         .help = "one row per build, in the order they ran\n"
                 "(warm-up, untimed, timed in turns, binary;\n"
                 "columns: atrbvh(1))"},
        {.name = "--plot", .kind = CLI_OPT_STRING, .arg = "DIR",
         .dest = &a->plot, .help = "gnuplot data, scripts, PNG and SVG plots "
                                   "into DIR"},
        {.name = "--scaling", .kind = CLI_OPT_FLAG, .dest = &a->scaling,
         .flag_value = 1,
         .help = "build time per stage and peak bytes against\n"
                 "triangle count; SCENEs are the bases (builtin:NAME\n"
                 "regenerated, files cut or replicated in a grid);\n"
                 "default builtin:sphere builtin:city, configs\n"
                 DEFAULT_SCALING_CONFIGS},
        {.name = "--sizes", .kind = CLI_OPT_STRING, .arg = "LIST",
         .dest = &b->sizes,
         .help = "triangle counts for --scaling (default " DEFAULT_SIZES
                 ")"},
        {.name = NULL}};
    size_t n = sizeof opts / sizeof opts[0];
    CLI_OPTS_COPY(table, opts, BENCH_OPTS - RAYS_CAMERA_OPTS);
    /* the camera options before the terminator */
    rays_camera_opts(&a->view, table + n - 1);
    table[n - 1 + RAYS_CAMERA_OPTS] = opts[n - 1];
}

static void bench_help(FILE *f)
{
    static bench_cl b;
    cli_opt table[BENCH_OPTS];
    bench_opts(&b, table);
    fputs("Usage: atrbvh bench [SCENE...] [OPTIONS]\n"
          "Build every configuration on each SCENE (default " DEFAULT_SCENE
          "),\n"
          "trace the same rays through each tree, and report build time (per\n"
          "stage), SAH, nodes, peak memory and rays per second, beside "
          "Embree.\n"
          "TRBVH(7,3) is always run: the relative columns are against it.\n"
          "\n"
          "Options:\n",
          f);
    cli_opts_help(f, table);
    cli_common_help(f, "0 success, 1 bad input or failure (an OpenCL "
                       "configuration without\nan OpenCL device included), "
                       "2 usage error");
}

int cli_bench(int argc, char **argv)
{
    static bench_cl b;
    bench_args *ap = &b.a;
    cli_opt table[BENCH_OPTS];
    const cli_opt *tables[2];
    int rc, k, npos;
    FILE *csv = NULL;
    cli_out csv_out, log_out;
    static bench_log builds_log;
    atrbvh_backend be = ATRBVH_BACKEND_CPU;
    if ((rc = cli_help_or_version(argc, argv, bench_help)) >= 0)
        return rc;
    memset(&b, 0, sizeof b);
    atrbvh_build_options_init(&ap->base);
    ap->base.max_leaf_size = 8;
    ap->repeat = 3;
    ap->width = 256;
    ap->height = 192;
    ap->viewpoints = 3;
    ap->spp = 2;
    bench_opts(&b, table);
    tables[0] = table;
    tables[1] = NULL;
    if (cli_parse("bench", argc, argv, tables, &b, ap->scenes, MAX_SCENES,
                  &npos, "SCENE") != 0)
        return CLI_USAGE;
    ap->nscenes = npos;
    ap->rays = !b.no_rays;
    if (rays_camera_check("bench", &ap->view) != 0)
        return CLI_USAGE;
    /* one user camera: its viewpoints would all be the same */
    if (ap->view.have_eye)
        ap->viewpoints = 1;
    if (b.sizes) {
        unsigned long vals[MAX_SIZES];
        if (parse_uint_list("--sizes", b.sizes, 50000000ul, vals, &ap->nsizes,
                            MAX_SIZES) != 0)
            return CLI_USAGE;
        for (k = 0; k < ap->nsizes; k++) {
            if (vals[k] == 0)
                return cli_usage("bench", "--sizes: 0 triangles");
            ap->sizes[k] = vals[k];
        }
    }
    if (b.backends) {
        if (strcmp(b.backends, "cpu") == 0)
            be = ATRBVH_BACKEND_CPU;
        else if (strcmp(b.backends, "opencl") == 0)
            be = ATRBVH_BACKEND_OPENCL;
        else if (strcmp(b.backends, "cpu,opencl") != 0 &&
                 strcmp(b.backends, "opencl,cpu") != 0)
            return cli_usage("bench", "--backend: '%s' is not cpu, opencl "
                             "or cpu,opencl", b.backends);
    }
    if (b.configs && b.methods)
        return cli_usage("bench", "--configs and --methods exclude each "
                         "other");
    if ((b.treelets || b.rounds) && !b.methods)
        return cli_usage("bench", "--treelet and --rounds go with --methods");
    if (b.methods) {
        unsigned long tl[32], rl[32];
        int nt = 0, nr = 0, m, t, r2;
        char buf[512], *tok, *save = NULL, spec[64];
        if (b.treelets &&
            parse_uint_list("--treelet", b.treelets, 32, tl, &nt, 32) != 0)
            return CLI_USAGE;
        if (b.rounds && parse_uint_list("--rounds", b.rounds, 64, rl, &nr, 32) !=
                          0)
            return CLI_USAGE;
        if (strlen(b.methods) >= sizeof buf)
            return cli_usage("bench", "--methods: list too long");
        strcpy(buf, b.methods);
        for (tok = strtok_r(buf, ",", &save); tok;
             tok = strtok_r(NULL, ",", &save)) {
            if (strcmp(tok, "lbvh") == 0 || strncmp(tok, "embree", 6) == 0) {
                if (parse_configs(ap, tok, be) != 0)
                    return CLI_USAGE;
                continue;
            }
            if (strcmp(tok, "trbvh") != 0 && strcmp(tok, "atrbvh") != 0)
                return cli_usage("bench", "--methods: unknown method '%s'",
                                 tok);
            for (t = 0; t < (nt ? nt : 1); t++)
                for (r2 = 0; r2 < (nr ? nr : 1); r2++) {
                    if (nt && tl[t] == 0)
                        return cli_usage("bench", "--treelet: 0");
                    if (nr && rl[r2] == 0)
                        return cli_usage("bench", "--rounds: 0");
                    if (nt && strcmp(tok, "trbvh") == 0 && tl[t] > 10) {
                        if (r2 == 0)
                            fprintf(stderr, "atrbvh: bench: trbvh treelet %lu "
                                    "skipped (TRBVH takes 3 to 10)\n",
                                    tl[t]);
                        continue;
                    }
                    m = snprintf(spec, sizeof spec, "%s", tok);
                    if (nt)
                        m += snprintf(spec + m, sizeof spec - (size_t)m,
                                      ":%lu", tl[t]);
                    else if (nr)
                        m += snprintf(spec + m, sizeof spec - (size_t)m,
                                      ":%u", strcmp(tok, "trbvh") == 0 ? 7u
                                                                       : 9u);
                    if (nr)
                        snprintf(spec + m, sizeof spec - (size_t)m, ":%lu",
                                 rl[r2]);
                    if (parse_configs(ap, spec, be) != 0)
                        return CLI_USAGE;
                }
        }
    } else if (parse_configs(ap, b.configs ? b.configs
                                         : ap->scaling ? DEFAULT_SCALING_CONFIGS
                                                     : DEFAULT_CONFIGS,
                             be) != 0) {
        return CLI_USAGE;
    }
    for (k = 0; k < b.nq; k++)
        if (parse_configs(ap, b.qualities[k], be) != 0)
            return CLI_USAGE;
    if (b.backends && strchr(b.backends, ',')) {
        /* both backends: every library configuration again on OpenCL */
        int n0 = ap->nconfigs;
        for (k = 0; k < n0; k++) {
            config c = ap->configs[k];
            if (c.embree)
                continue;
            c.backend = ATRBVH_BACKEND_OPENCL;
            if (add_config(ap, &c) != 0)
                return CLI_USAGE;
        }
    }
    if (!ap->scaling) {
        /* the reference of the relative columns */
        config ref;
        memset(&ref, 0, sizeof ref);
        ref.method = ATRBVH_METHOD_TRBVH;
        ref.treelet = 7;
        ref.rounds = 3;
        for (k = 0; k < ap->nconfigs; k++)
            if (!ap->configs[k].embree &&
                ap->configs[k].method == ATRBVH_METHOD_TRBVH &&
                ap->configs[k].backend == ATRBVH_BACKEND_CPU &&
                ap->configs[k].split == 0.0 &&
                (ap->configs[k].treelet == 7 || ap->configs[k].treelet == 0) &&
                (ap->configs[k].rounds == 3 || ap->configs[k].rounds == 0))
                break;
        if (k == ap->nconfigs && add_config(ap, &ref) != 0)
            return CLI_USAGE;
        if (ap->nscenes == 0)
            ap->scenes[ap->nscenes++] = DEFAULT_SCENE;
    } else {
        if (ap->nsizes == 0) {
            size_t d[] = {10000, 100000, 1000000, 10000000};
            for (k = 0; k < 4; k++)
                ap->sizes[ap->nsizes++] = d[k];
        }
        for (k = 0; k < ap->nconfigs; k++)
            if (ap->configs[k].embree)
                return cli_usage("bench", "--scaling measures atrbvh "
                                 "configurations only");
    }
    if (ap->nconfigs == 0)
        return cli_usage("bench", "no configuration to run");
    /* The CSV goes to a temporary file beside it (outfile.h), renamed
     * over it when the run is complete; opened now, so that an unwritable
     * path is reported before the measurements. */
    if (ap->csv) {
        csv = cli_out_open(ap->csv, &csv_out);
        if (!csv)
            return CLI_FAIL;
        if (!ap->scaling)
            csv_header(csv);
    }
    memset(&builds_log, 0, sizeof builds_log);
    ap->log = &builds_log;
    if (ap->builds) {
        if (ap->csv && (strcmp(ap->csv, ap->builds) == 0 ||
                        cli_out_same_file(ap->csv, ap->builds))) {
            if (csv)
                cli_out_abort(&csv_out);
            return cli_usage("bench", "--builds and --csv name the same "
                             "file: %s", ap->builds);
        }
        builds_log.f = cli_out_open(ap->builds, &log_out);
        if (!builds_log.f) {
            if (csv)
                cli_out_abort(&csv_out);
            return CLI_FAIL;
        }
        csv_build_header(builds_log.f);
    }
    if (ap->plot && mkdir(ap->plot, 0777) != 0 && errno != EEXIST) {
        cli_error("%s: %s", ap->plot, strerror(errno));
        if (csv)
            cli_out_abort(&csv_out);
        if (builds_log.f)
            cli_out_abort(&log_out);
        return CLI_FAIL;
    }
    memtrack_install();
    rc = ap->scaling ? bench_scaling(ap, csv) : bench_sweep(ap, csv);
    memtrack_uninstall();
    {
        /* nothing half written, and both files or neither (each on disk
         * before either is renamed, cli_out_commit_all) */
        cli_out out[2];
        size_t n = 0;
        if (csv)
            out[n++] = csv_out;
        if (builds_log.f)
            out[n++] = log_out;
        builds_log.f = NULL;
        if (rc != CLI_OK)
            cli_out_abort_all(out, n);
        else if (n > 0 && cli_out_commit_all(out, n) != 0)
            rc = CLI_FAIL;
    }
    return rc;
}
