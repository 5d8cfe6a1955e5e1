/*
 * plots.c - the --plot output of `atrbvh bench`: gnuplot data, scripts,
 * and their PNG and SVG pictures.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "bench.h"
#include "gnuplot.h"
#include "outfile.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* The scene's name without directories or extension, for file names. */
static void scene_tag(const char *spec, char *buf, size_t n)
{
    const char *s = strrchr(spec, '/');
    size_t k = 0;
    s = s ? s + 1 : spec;
    for (; *s && k + 1 < n; s++) {
        if (*s == '.' && strchr(s + 1, '.') == NULL)
            break;
        buf[k++] = isalnum((unsigned char)*s) ? *s : '_';
    }
    buf[k] = '\0';
}

/* DIR/NAME through outfile.h (a temporary file renamed when complete). */
static FILE *open_in(const char *dir, const char *name, cli_out *h)
{
    char path[4200];
    int w = snprintf(path, sizeof path, "%s/%s", dir, name);
    if (w < 0 || (size_t)w >= sizeof path) {
        cli_error("%s: folder name too long", dir);
        return NULL;
    }
    return cli_out_open(path, h);
}

/* The pictures a script makes, STEM.png and STEM.svg for each stem:
 * gnuplot writes them into its own folder (the script prefixes the
 * variable outdir, which the tool sets and a user running the script does
 * not), and cli_gnuplot puts them in place only once it has succeeded. */
typedef struct pictures {
    char (*name)[168];
    int n, cap, oom;
} pictures;

static void pictures_add(pictures *p, const char *stem)
{
    static const char *const ext[2] = {"png", "svg"};
    int e;
    if (p->n + 2 > p->cap) {
        int cap = p->cap ? 2 * p->cap : 8;
        char(*m)[168] = realloc(p->name, (size_t)cap * sizeof *m);
        if (!m) {
            p->oom = 1;
            return;
        }
        p->name = m;
        p->cap = cap;
    }
    for (e = 0; e < 2; e++)
        snprintf(p->name[p->n++], sizeof p->name[0], "%s.%s", stem, ext[e]);
}

/* gnuplot SCRIPT in DIR, then the pictures put in place (or dropped). */
static int run_gnuplot(const char *dir, const char *script, pictures *pics)
{
    const char **names = malloc((size_t)(pics->n ? pics->n : 1) *
                                sizeof *names);
    int k, rc;
    if (!names) {
        cli_error("out of memory");
        return -1;
    }
    for (k = 0; k < pics->n; k++)
        names[k] = pics->name[k];
    rc = cli_gnuplot(dir, script, names, (size_t)pics->n);
    free(names);
    return rc;
}

/* Both terminals for the plot commands written by `body`. */
static void gp_both(FILE *g, pictures *pics, const char *stem,
                    void (*body)(FILE *g, const void *ctx), const void *ctx)
{
    pictures_add(pics, stem);
    fprintf(g, "set terminal pngcairo size 900,600 font 'sans,10'\n"
               "set output outdir.'%s.png'\n",
            stem);
    body(g, ctx);
    fprintf(g, "set terminal svg size 900,600 dynamic font 'sans,10'\n"
               "set output outdir.'%s.svg'\nreplot\nunset output\nreset\n",
            stem);
}

/* The first lines of every script. */
static void gp_preamble(FILE *g, const char *name)
{
    fprintf(g, "# regenerate: gnuplot %s (in this folder)\n"
               "if (!exists('outdir')) outdir = ''\n",
            name);
}

/* Puts the script in place and runs it.  0, or -1 after an error line. */
static int finish_script(const char *dir, const char *name, cli_out *go,
                         pictures *pics)
{
    if (pics->oom) {
        cli_out_abort(go);
        cli_error("out of memory");
        return -1;
    }
    if (cli_out_commit(go) != 0)
        return -1;
    return run_gnuplot(dir, name, pics);
}

/* ------------------------------------------------------ label placement
 * Every point gets its label once, placed where it overlaps the fewest
 * other labels and points: the plot's ranges are set by the script, so
 * positions on the page are known here.  The page model: a plot area of
 * AREA_W x AREA_H pixels, label text CHAR_W pixels a character. */
#define AREA_W 760.0
#define AREA_H 430.0
#define CHAR_W 6.6
#define LINE_H 12.5
#define MARK 7.0

typedef struct point {
    double x, y; /* data */
    double px, py; /* page, pixels */
    const char *label;
    double lx0, ly0, lx1, ly1; /* the label's box, pixels */
    double ax, ay;             /* its anchor, pixels */
    int right_aligned;
} point;

typedef struct frame {
    int logx;
    double x0, x1, y0, y1; /* the ranges set (log10 for a log axis) */
} frame;

static double page_x(const frame *fr, double x)
{
    double v = fr->logx ? log10(x) : x;
    return (v - fr->x0) / (fr->x1 - fr->x0) * AREA_W;
}

static double page_y(const frame *fr, double y)
{
    return (y - fr->y0) / (fr->y1 - fr->y0) * AREA_H;
}

static double data_x(const frame *fr, double px)
{
    double v = fr->x0 + px / AREA_W * (fr->x1 - fr->x0);
    return fr->logx ? pow(10.0, v) : v;
}

static double data_y(const frame *fr, double py)
{
    return fr->y0 + py / AREA_H * (fr->y1 - fr->y0);
}

static double overlap(double ax0, double ay0, double ax1, double ay1,
                      double bx0, double by0, double bx1, double by1)
{
    double w = fmin(ax1, bx1) - fmax(ax0, bx0);
    double h = fmin(ay1, by1) - fmax(ay0, by0);
    return w > 0.0 && h > 0.0 ? w * h : 0.0;
}

/* Ranges with room around the points (and to the right for labels). */
static frame frame_for(const point *p, int n, int logx)
{
    frame fr;
    double lo = HUGE_VAL, hi = -HUGE_VAL, ylo = HUGE_VAL, yhi = -HUGE_VAL, s;
    int i;
    fr.logx = logx;
    for (i = 0; i < n; i++) {
        double v = logx ? log10(p[i].x) : p[i].x;
        lo = fmin(lo, v);
        hi = fmax(hi, v);
        ylo = fmin(ylo, p[i].y);
        yhi = fmax(yhi, p[i].y);
    }
    s = hi - lo;
    if (!(s > 1e-9))
        s = logx ? 0.5 : fabs(hi) * 0.2 + 1.0;
    fr.x0 = lo - 0.12 * s;
    fr.x1 = hi + 0.30 * s;
    s = yhi - ylo;
    if (!(s > 1e-12))
        s = fabs(yhi) * 0.1 + 1.0;
    fr.y0 = ylo - 0.12 * s;
    if (ylo >= 0.0 && fr.y0 < 0.0)
        fr.y0 = 0.0; /* no negative throughput on the axis */
    fr.y1 = yhi + 0.15 * s;
    return fr;
}

static void place_labels(const frame *fr, point *p, int n)
{
    /* anchor offsets (pixels) and alignment: right, upper right, lower
     * right, left, upper left, lower left, above, below */
    static const double cand[][3] = {
        {9, 0, 0},   {7, 11, 0},  {7, -11, 0}, {-9, 0, 1}, {-7, 11, 1},
        {-7, -11, 1}, {0, 14, 2}, {0, -14, 2}, {9, 22, 0}, {9, -22, 0},
        {-9, 22, 1}, {-9, -22, 1}};
    int i, j, c;
    for (i = 0; i < n; i++) {
        p[i].px = page_x(fr, p[i].x);
        p[i].py = page_y(fr, p[i].y);
    }
    for (i = 0; i < n; i++) {
        double w = CHAR_W * (double)strlen(p[i].label) + 2.0, best = HUGE_VAL;
        for (c = 0; c < (int)(sizeof cand / sizeof cand[0]); c++) {
            double ax = p[i].px + cand[c][0], ay = p[i].py + cand[c][1];
            double x0 = cand[c][2] == 0   ? ax
                        : cand[c][2] == 1 ? ax - w
                                          : ax - w / 2;
            double y0 = ay - LINE_H / 2, x1 = x0 + w, y1 = y0 + LINE_H;
            double cost = 0.0;
            for (j = 0; j < n; j++) {
                cost += 4.0 * overlap(x0, y0, x1, y1, p[j].px - MARK,
                                      p[j].py - MARK, p[j].px + MARK,
                                      p[j].py + MARK);
                if (j < i)
                    cost += 4.0 * overlap(x0, y0, x1, y1, p[j].lx0,
                                          p[j].ly0, p[j].lx1, p[j].ly1);
            }
            /* outside the plot area */
            cost += 2.0 * (w * LINE_H -
                           overlap(x0, y0, x1, y1, 0, 0, AREA_W, AREA_H));
            cost += c * 0.5; /* prefer the first candidates */
            if (cost < best) {
                best = cost;
                p[i].lx0 = x0;
                p[i].ly0 = y0;
                p[i].lx1 = x1;
                p[i].ly1 = y1;
                p[i].ax = x0;
                p[i].ay = ay;
                p[i].right_aligned = 0;
            }
        }
    }
}

static void gp_frame(FILE *g, const frame *fr)
{
    /* fixed margins, so that the plot area is the one labels were placed
     * in (in proportion) */
    fputs("set lmargin 10\nset rmargin 4\nset tmargin 3\n", g);
    if (fr->logx) {
        /* tics at 1, 2 and 5 of each decade: a range within one decade
         * still gets several */
        double d = floor(fr->x0), lo = pow(10.0, fr->x0),
               hi = pow(10.0, fr->x1);
        int first = 1;
        fprintf(g, "set logscale x\nset xrange [%.9g:%.9g]\nset xtics (",
                lo, hi);
        for (; d <= fr->x1 + 1e-9; d += 1.0) {
            static const double m[3] = {1.0, 2.0, 5.0};
            int k;
            for (k = 0; k < 3; k++) {
                double v = m[k] * pow(10.0, d);
                if (v < lo || v > hi)
                    continue;
                fprintf(g, "%s%.9g", first ? "" : ", ", v);
                first = 0;
            }
        }
        fputs(")\n", g);
    }
    else
        fprintf(g, "set xrange [%.9g:%.9g]\n", fr->x0, fr->x1);
    fprintf(g, "set yrange [%.9g:%.9g]\n", fr->y0, fr->y1);
}

static void gp_labels(FILE *g, const frame *fr, const point *p, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        fputs("set label ", g);
        cli_gnuplot_string(g, p[i].label);
        fprintf(g, " at %.9g,%.9g left font ',8' noenhanced front\n",
                data_x(fr, p[i].ax), data_y(fr, p[i].ay));
    }
}

static int is_dominated(const row *rows, int n, int i)
{
    int j;
    for (j = 0; j < n; j++)
        if (j != i && rows[j].build_ms <= rows[i].build_ms &&
            rows[j].sah <= rows[i].sah &&
            (rows[j].build_ms < rows[i].build_ms ||
             rows[j].sah < rows[i].sah))
            return 1;
    return 0;
}

static int cmp_row_time(const void *a, const void *b)
{
    const row *x = *(row *const *)a, *y = *(row *const *)b;
    return x->build_ms < y->build_ms ? -1 : x->build_ms > y->build_ms;
}

typedef struct scene_plot {
    const char *base, *tag, *what;
    const frame *fr;
    const point *p;
    int n, col; /* the data column plotted against build time */
} scene_plot;

static void body_scene(FILE *g, const void *ctx)
{
    const scene_plot *sp = ctx;
    fputs("set title ", g);
    {
        char t[512];
        snprintf(t, sizeof t, "%s: %s", sp->base, sp->what);
        cli_gnuplot_string(g, t);
    }
    fputs(" noenhanced\n"
          "set xlabel 'build time, ms (median of the timed runs; log "
          "scale)'\n",
          g);
    if (sp->col == 3)
        fputs("set ylabel 'SAH cost of the tree (collapsed, leaf limit as "
              "run)'\n",
              g);
    else if (sp->col == 5)
        fputs("set ylabel 'ray cost: ci x boxes + ct x triangles tested per "
              "ray (exact)'\n",
              g);
    else
        fputs("set ylabel 'Mrays/s, primary + AO + diffuse, all threads'\n",
              g);
    /* the key below the plot, where it covers no point */
    fputs("set grid\nset key below horizontal\n", g);
    gp_frame(g, sp->fr);
    fputs("unset label\n", g); /* the other panel's */
    gp_labels(g, sp->fr, sp->p, sp->n);
    fprintf(g, "plot ");
    if (sp->col == 3)
        fprintf(g, "'bench-%s.dat' index 2 using 2:3 with steps lw 1 lc rgb "
                   "'#999999' title 'Pareto front (no other point is both "
                   "faster and lower)', \\\n  ",
                sp->tag);
    fprintf(g, "'bench-%s.dat' index 0 using 2:%d with points pt 7 ps 1.2 "
               "lc rgb '#1f77b4' title 'atrbvh (LBVH, TRBVH, ATRBVH)', \\\n"
               "  '' index 1 using 2:%d with points pt 5 ps 1.2 lc rgb "
               "'#d62728' title '%s'\n",
            sp->tag, sp->col, sp->col,
            sp->col == 3 ? "Embree (rtcBuildBVH)"
                         : "Embree tree, our traverser");
}

/* SAH and ray cost against build time side by side (one wide picture). */
static void body_trade(FILE *g, const void *ctx)
{
    const scene_plot *sp = ctx;
    fputs("set multiplot layout 1,2\n", g);
    body_scene(g, &sp[0]);
    body_scene(g, &sp[1]);
    fputs("unset multiplot\n", g);
}

static void gp_wide(FILE *g, pictures *pics, const char *stem,
                    const scene_plot *two)
{
    pictures_add(pics, stem);
    fprintf(g, "set terminal pngcairo size 1800,600 font 'sans,10'\n"
               "set output outdir.'%s.png'\n",
            stem);
    body_trade(g, two);
    fprintf(g, "unset output\nreset\n"
               "set terminal svg size 1800,600 dynamic font 'sans,10'\n"
               "set output outdir.'%s.svg'\n",
            stem);
    body_trade(g, two);
    fputs("unset output\nreset\n", g);
}

int plot_scene(const char *dir, const char *spec, const row *rows, int n,
               int have_rays)
{
    char tag[64], name[128], stem[160];
    char (*labels)[64] = NULL;
    FILE *f = NULL, *g = NULL;
    cli_out fo, go;
    pictures pics = {NULL, 0, 0, 0};
    const row **front = NULL;
    point *pts = NULL;
    int i, nf = 0, pass, np, rc = -1;
    frame fr, fr2, fr3;
    scene_plot sp, two[2];
    point *pts2 = NULL, *pts3 = NULL;
    const char *base = strrchr(spec, '/') ? strrchr(spec, '/') + 1 : spec;
    scene_tag(spec, tag, sizeof tag);
    labels = malloc((size_t)(n ? n : 1) * sizeof *labels);
    pts = malloc((size_t)(n ? n : 1) * sizeof *pts);
    front = malloc((size_t)(n ? n : 1) * sizeof *front);
    pts2 = malloc((size_t)(n ? n : 1) * sizeof *pts2);
    pts3 = malloc((size_t)(n ? n : 1) * sizeof *pts3);
    if (!labels || !pts || !front || !pts2 || !pts3) {
        cli_error("out of memory");
        goto done;
    }
    for (i = 0; i < n; i++)
        config_label(&rows[i].c, rows[i].treelet, rows[i].rounds, labels[i],
                     sizeof labels[i]);
    snprintf(name, sizeof name, "bench-%s.dat", tag);
    if (!(f = open_in(dir, name, &fo)))
        goto done;
    /* index 0: atrbvh configurations, 1: Embree, 2: the Pareto front */
    for (pass = 0; pass < 2; pass++) {
        fprintf(f, "# %s\n# label build_ms sah total_mrays ray_cost\n",
                pass ? "embree" : "atrbvh");
        for (i = 0; i < n; i++)
            if (rows[i].c.embree == pass)
                fprintf(f, "\"%s\" %.6g %.9g %.6g %.9g\n", labels[i],
                        rows[i].build_ms, rows[i].sah,
                        isfinite(rows[i].total_mrays) ? rows[i].total_mrays
                                                      : 0.0,
                        isfinite(rows[i].ray_cost) ? rows[i].ray_cost : 0.0);
        fputs("\n\n", f);
    }
    for (i = 0; i < n; i++)
        if (!is_dominated(rows, n, i))
            front[nf++] = &rows[i];
    qsort(front, (size_t)nf, sizeof *front, cmp_row_time);
    fputs("# pareto front\n", f);
    for (i = 0; i < nf; i++)
        fprintf(f, "\"-\" %.6g %.9g 0\n", front[i]->build_ms, front[i]->sah);
    f = NULL;
    if (cli_out_commit(&fo) != 0)
        goto done;
    snprintf(name, sizeof name, "bench-%s.gp", tag);
    if (!(g = open_in(dir, name, &go)))
        goto done;
    gp_preamble(g, name);
    sp.base = base;
    sp.tag = tag;
    sp.fr = &fr;
    sp.p = pts;
    /* col 3: SAH (pareto-), col 4: rays per second (rays-), col 5: the
     * exact ray cost (cost-); then SAH and ray cost side by side
     * (trade-) */
    for (sp.col = 3; sp.col <= (have_rays ? 5 : 3); sp.col++) {
        point *pp = sp.col == 3 ? pts : (sp.col == 5 ? pts2 : pts3);
        frame *ff = sp.col == 3 ? &fr : (sp.col == 5 ? &fr2 : &fr3);
        for (i = 0, np = 0; i < n; i++) {
            double y = sp.col == 3   ? rows[i].sah
                       : sp.col == 4 ? rows[i].total_mrays
                                     : rows[i].ray_cost;
            if (!(rows[i].build_ms > 0.0) || !isfinite(y) ||
                (sp.col != 3 && !(y > 0.0)))
                continue;
            pp[np].x = rows[i].build_ms;
            pp[np].y = y;
            pp[np++].label = labels[i];
        }
        if (np == 0)
            continue;
        *ff = frame_for(pp, np, 1);
        place_labels(ff, pp, np);
        sp.n = np;
        sp.p = pp;
        sp.fr = ff;
        sp.what = sp.col == 3
                      ? "build time against SAH cost, each configuration "
                        "once (lower left is better)"
                  : sp.col == 4
                      ? "ray throughput of each tree through our traverser "
                        "against its build time (upper left is better)"
                      : "exact ray cost (boxes and triangles tested per ray) "
                        "against build time (lower left is better)";
        snprintf(stem, sizeof stem, "%s-%s",
                 sp.col == 3 ? "pareto" : (sp.col == 4 ? "rays" : "cost"),
                 tag);
        gp_both(g, &pics, stem, body_scene, &sp);
        if (sp.col == 3)
            two[0] = sp;
        if (sp.col == 5) {
            two[1] = sp;
            two[0].what = "SAH cost against build time";
            two[1].what = "exact ray cost against build time";
            snprintf(stem, sizeof stem, "trade-%s", tag);
            gp_wide(g, &pics, stem, two);
        }
    }
    g = NULL;
    rc = finish_script(dir, name, &go, &pics);
done:
    if (f)
        cli_out_abort(&fo);
    if (g)
        cli_out_abort(&go);
    free(pics.name);
    free(labels);
    free(pts);
    free(pts2);
    free(pts3);
    free(front);
    return rc;
}

/* ------------------------------------------------------------- scaling */
typedef struct scaling_plot {
    const scaling_series *s;
    int n, which; /* 0 build time, 1 stages of series `one`, 2 memory */
    int one;
    char (*titles)[160];
} scaling_plot;

static void body_scaling(FILE *g, const void *ctx)
{
    const scaling_plot *sp = ctx;
    int k, s;
    fputs("set xlabel 'triangles'\nset grid\nset logscale x\n"
          "set format x '10^%L'\n",
          g);
    if (sp->which == 0) {
        fputs("set title 'Build time against triangle count (log-log; "
              "each line a base scene and configuration)'\n"
              "set ylabel 'build time, ms (median)'\nset logscale y\n"
              "set key top left\nplot ",
              g);
        for (k = 0; k < sp->n; k++) {
            fprintf(g, "%s'scaling.dat' index %d using 1:2 with linespoints "
                       "lw 2 title ",
                    k ? ", \\\n  " : "", k);
            cli_gnuplot_string(g, sp->titles[k]);
            fputs(" noenhanced", g);
        }
    } else if (sp->which == 1) {
        const scaling_series *r = &sp->s[sp->one];
        char t[256];
        snprintf(t, sizeof t, "Build time of each stage against triangle "
                              "count (log-log): %s, %s",
                 r->base, r->label);
        fputs("set title ", g);
        cli_gnuplot_string(g, t);
        fputs(" noenhanced\nset ylabel 'stage time, ms (median)'\nset logscale y\n"
              "set key top left\nplot ",
              g);
        for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
            fprintf(g, "%s'scaling.dat' index %d using 1:($%d > 0 ? $%d : "
                       "NaN) with linespoints title '%s' noenhanced",
                    s ? ", \\\n  " : "", sp->one, 3 + s, 3 + s,
                    atrbvh_stage_name((atrbvh_stage)s));
    } else {
        fputs("set title 'Peak library memory during the build, bytes per "
              "triangle (each line a base scene and configuration)'\n"
              "set ylabel 'bytes per triangle'\nset yrange [0:*]\n"
              "set key top right\nplot ",
              g);
        for (k = 0; k < sp->n; k++) {
            fprintf(g, "%s'scaling.dat' index %d using 1:%d with linespoints "
                       "lw 2 title ",
                    k ? ", \\\n  " : "", k, 3 + ATRBVH_STAGE_COUNT);
            cli_gnuplot_string(g, sp->titles[k]);
            fputs(" noenhanced", g);
        }
    }
    fputc('\n', g);
}

int plot_scaling(const char *dir, const scaling_series *s, int n)
{
    FILE *f = NULL, *g = NULL;
    cli_out fo, go;
    pictures pics = {NULL, 0, 0, 0};
    scaling_plot sp;
    int k, i, st, rc = -1;
    char (*titles)[160] = malloc((size_t)(n ? n : 1) * sizeof *titles);
    if (!titles) {
        cli_error("out of memory");
        return -1;
    }
    if (!(f = open_in(dir, "scaling.dat", &fo)))
        goto done;
    for (k = 0; k < n; k++) {
        const char *bn = strrchr(s[k].base, '/');
        if (isfinite(s[k].slope))
            snprintf(titles[k], sizeof titles[k], "%s %s: ~N^%.2f from 1e5",
                     bn ? bn + 1 : s[k].base, s[k].label, s[k].slope);
        else
            snprintf(titles[k], sizeof titles[k], "%s %s",
                     bn ? bn + 1 : s[k].base, s[k].label);
        fprintf(f, "# %s %s (N^%.3f from 1e5)\n"
                   "# triangles build_ms stages... peak_per_tri\n",
                s[k].base, s[k].label, s[k].slope);
        for (i = 0; i < s[k].n; i++) {
            const row *r = &s[k].rows[i];
            fprintf(f, "%zu %.6g", r->triangles, r->build_ms);
            for (st = 0; st < ATRBVH_STAGE_COUNT; st++)
                fprintf(f, " %.6g", r->stage_ms[st]);
            fprintf(f, " %.6g\n", (double)r->peak / (double)r->triangles);
        }
        fputs("\n\n", f);
    }
    f = NULL;
    if (cli_out_commit(&fo) != 0)
        goto done;
    if (!(g = open_in(dir, "scaling.gp", &go)))
        goto done;
    gp_preamble(g, "scaling.gp");
    sp.s = s;
    sp.n = n;
    sp.titles = titles;
    sp.one = 0;
    sp.which = 0;
    gp_both(g, &pics, "scaling", body_scaling, &sp);
    /* one stage plot per series, named after it */
    sp.which = 1;
    for (k = 0; k < n; k++) {
        char stem[160], bt[64], ct[64];
        scene_tag(s[k].base, bt, sizeof bt);
        for (i = 0; s[k].label[i] && i + 1 < (int)sizeof ct; i++)
            ct[i] = isalnum((unsigned char)s[k].label[i]) ? s[k].label[i]
                                                           : '_';
        ct[i] = '\0';
        snprintf(stem, sizeof stem, "scaling-stages-%s-%s", bt, ct);
        sp.one = k;
        gp_both(g, &pics, stem, body_scaling, &sp);
    }
    sp.which = 2;
    gp_both(g, &pics, "scaling-memory", body_scaling, &sp);
    g = NULL;
    rc = finish_script(dir, "scaling.gp", &go, &pics);
done:
    if (f)
        cli_out_abort(&fo);
    if (g)
        cli_out_abort(&go);
    free(pics.name);
    free(titles);
    return rc;
}
