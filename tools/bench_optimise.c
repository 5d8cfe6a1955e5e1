/*
 * bench_optimise.c - build time per stage and SAH of the optimisers on
 * the canonical PLY scenes (a benchmark, not a test; issue 3).
 *
 *   make -C _build tools/bench_optimise
 *   _build/tools/bench_optimise [-v] [-r REPS] [-t THREADS,...] [-c LIST]
 *                               SCENE.ply...
 *
 * -v prints every build's stage times to stderr.
 *
 * For each scene, thread count and configuration (LBVH, TRBVH(7,3),
 * ATRBVH(9,2), ATRBVH(7,3), ATRBVH n = 5, 16, 32 with 2 rounds) it builds
 * REPS times (default 3) with collapse on and reports the median and the
 * minimum total build time, the median optimise stage, the median of the
 * other stages, the SAH of the built (collapsed) tree, and the SAH of one
 * more build with collapse off (the binary tree); the ratio columns are
 * against the first optimiser of the list ("ref", TRBVH(7,3) by default).
 * Markdown table on stdout.  -c trbvh:7:3,atrbvh:9:2,... replaces the list
 * (LBVH always comes first).
 *
 * Reads only the canonical binary PLY of ../shared/scenes (MANIFEST.md):
 * float xyz vertices, uchar-counted uint triangle lists.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atrbvh.h"

typedef struct mesh {
    float *v;
    uint32_t *idx;
    size_t nv, nt;
} mesh;

static int load_ply(const char *path, mesh *m)
{
    FILE *f = fopen(path, "rb");
    char line[256];
    size_t i;
    unsigned long nv = 0, nt = 0;
    memset(m, 0, sizeof *m);
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        sscanf(line, "element vertex %lu", &nv);
        sscanf(line, "element face %lu", &nt);
        if (strncmp(line, "end_header", 10) == 0)
            break;
    }
    m->nv = nv;
    m->nt = nt;
    m->v = malloc(12 * (nv ? nv : 1));
    m->idx = malloc(12 * (nt ? nt : 1));
    if (!m->v || !m->idx || fread(m->v, 12, nv, f) != nv)
        goto fail;
    for (i = 0; i < nt; i++) {
        unsigned char c;
        if (fread(&c, 1, 1, f) != 1 || c != 3 ||
            fread(m->idx + 3 * i, 4, 3, f) != 3)
            goto fail;
    }
    fclose(f);
    return 0;
fail:
    fclose(f);
    free(m->v);
    free(m->idx);
    return -1;
}

typedef struct bench_cfg {
    const char *name;
    atrbvh_method method;
    unsigned n, rounds;
} bench_cfg;

static bench_cfg configs[16] = {
    {"LBVH", ATRBVH_METHOD_LBVH, 0, 0},
    {"TRBVH(7,3)", ATRBVH_METHOD_TRBVH, 7, 3},
    {"ATRBVH(9,2)", ATRBVH_METHOD_ATRBVH, 9, 2},
    {"ATRBVH(7,3)", ATRBVH_METHOD_ATRBVH, 7, 3},
    {"ATRBVH(5,2)", ATRBVH_METHOD_ATRBVH, 5, 2},
    {"ATRBVH(16,2)", ATRBVH_METHOD_ATRBVH, 16, 2},
    {"ATRBVH(32,2)", ATRBVH_METHOD_ATRBVH, 32, 2},
};
static size_t nconfigs = 7;
static char names[16][32];

/* "-c trbvh:7:3,atrbvh:9:2,...": replaces the list (LBVH stays first;
 * the first optimiser given is the reference of the ratio columns). */
static int parse_configs(char *spec)
{
    char *tok = strtok(spec, ",");
    nconfigs = 1;
    while (tok && nconfigs < 16) {
        char m[16];
        unsigned n, r;
        bench_cfg *c = &configs[nconfigs];
        if (sscanf(tok, "%15[a-z]:%u:%u", m, &n, &r) != 3)
            return -1;
        c->method = strcmp(m, "trbvh") == 0 ? ATRBVH_METHOD_TRBVH
                                            : ATRBVH_METHOD_ATRBVH;
        c->n = n;
        c->rounds = r;
        snprintf(names[nconfigs], sizeof names[0], "%s(%u,%u)",
                 c->method == ATRBVH_METHOD_TRBVH ? "TRBVH" : "ATRBVH", n,
                 r);
        c->name = names[nconfigs];
        nconfigs++;
        tok = strtok(NULL, ",");
    }
    return 0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

#define MAX_REPS 15

int main(int argc, char **argv)
{
    int reps = 3, a, threads_list[8], nthreads = 0, verbose = 0;
    char *spec = NULL;
    for (a = 1; a < argc && argv[a][0] == '-'; a++) {
        if (strcmp(argv[a], "-r") == 0 && a + 1 < argc)
            reps = atoi(argv[++a]);
        else if (strcmp(argv[a], "-c") == 0 && a + 1 < argc) {
            if (parse_configs(argv[++a]) != 0) {
                fprintf(stderr, "bad -c list\n");
                return 2;
            }
        } else if (strcmp(argv[a], "-v") == 0)
            verbose = 1;
        else if (strcmp(argv[a], "-t") == 0 && a + 1 < argc)
            spec = argv[++a];
        else {
            fprintf(stderr, "usage: %s [-v] [-r REPS] [-t 1,2] [-c LIST] SCENE.ply...\n",
                    argv[0]);
            return 2;
        }
    }
    if (reps < 1 || reps > MAX_REPS)
        reps = 3;
    if (spec) {
        char *tok = strtok(spec, ",");
        while (tok && nthreads < 8) {
            threads_list[nthreads++] = atoi(tok);
            tok = strtok(NULL, ",");
        }
    } else {
        threads_list[0] = 1;
        threads_list[1] = 2;
        nthreads = 2;
    }
    printf("| scene | threads | method | total ms (median) | total ms (min) "
           "| optimise ms | other stages ms | SAH | SAH binary | total vs "
           "ref | SAH vs ref |\n");
    printf("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (; a < argc; a++) {
        mesh m;
        atrbvh_geometry g;
        const char *base = strrchr(argv[a], '/');
        int ti;
        base = base ? base + 1 : argv[a];
        if (load_ply(argv[a], &m) != 0) {
            fprintf(stderr, "cannot read %s\n", argv[a]);
            return 1;
        }
        g = atrbvh_geometry_triangles(m.v, m.nv, m.idx, m.nt);
        for (ti = 0; ti < nthreads; ti++) {
            double tr_total = 0.0, tr_sah = 0.0;
            size_t c;
            for (c = 0; c < nconfigs; c++) {
                double total[MAX_REPS], opt[MAX_REPS], other[MAX_REPS];
                double sah = 0.0, sah_bin = 0.0, mt, best = 0.0;
                atrbvh_build_options o;
                atrbvh_bvh *bvh;
                atrbvh_stats st;
                atrbvh_error err;
                int r;
                atrbvh_build_options_init(&o);
                o.method = configs[c].method;
                o.treelet_size = configs[c].n;
                o.rounds = configs[c].rounds;
                o.threads = threads_list[ti];
                for (r = 0; r < reps; r++) {
                    if (atrbvh_build(&g, &o, &bvh, &err) != ATRBVH_OK) {
                        fprintf(stderr, "%s: %s\n", base, err.text);
                        return 1;
                    }
                    atrbvh_bvh_stats(bvh, &st);
                    total[r] = st.build_ms;
                    if (r == 0 || st.build_ms < best)
                        best = st.build_ms;
                    opt[r] = st.stage_ms[ATRBVH_STAGE_OPTIMISE];
                    other[r] = st.build_ms - opt[r];
                    sah = st.sah;
                    if (verbose) {
                        int k;
                        fprintf(stderr, "%s %d %s:", base, threads_list[ti],
                                configs[c].name);
                        for (k = 0; k < ATRBVH_STAGE_COUNT; k++)
                            fprintf(stderr, " %s %.1f",
                                    atrbvh_stage_name((atrbvh_stage)k),
                                    st.stage_ms[k]);
                        fprintf(stderr, "\n");
                    }
                    atrbvh_bvh_free(bvh);
                }
                o.collapse = 0;
                if (atrbvh_build(&g, &o, &bvh, &err) != ATRBVH_OK) {
                    fprintf(stderr, "%s: %s\n", base, err.text);
                    return 1;
                }
                atrbvh_bvh_stats(bvh, &st);
                sah_bin = st.sah;
                atrbvh_bvh_free(bvh);
                mt = median(total, reps);
                if (c == 1) {
                    tr_total = mt;
                    tr_sah = sah;
                }
                printf("| %s | %d | %s | %.1f | %.1f | %.1f | %.1f | %.3f | "
                       "%.3f | ",
                       base, threads_list[ti], configs[c].name, mt, best,
                       median(opt, reps), median(other, reps), sah, sah_bin);
                if (c >= 1)
                    printf("%.3f | %.4f |\n", mt / tr_total, sah / tr_sah);
                else
                    printf("- | - |\n");
                fflush(stdout);
            }
        }
        free(m.v);
        free(m.idx);
    }
    return 0;
}
