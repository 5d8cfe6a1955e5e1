/*
 * gnuplot.h - gnuplot for the tool's plots (bench --plot, animate --plot):
 * started without a shell, its pictures and messages written into a
 * folder of its own inside the plot folder, and put in place only when it
 * succeeded.
 */
#ifndef ATRBVH_TOOLS_GNUPLOT_H
#define ATRBVH_TOOLS_GNUPLOT_H

#include <stddef.h>
#include <stdio.h>

/* Runs `gnuplot -e "outdir = 'SUB/'" SCRIPT` in `dir`, SUB a folder the
 * call makes in `dir` (.atrbvh-gnuplot-XXXXXX, mkdtemp) and removes
 * before it returns; stdin is /dev/null.  A script writes each picture to
 * outdir.NAME, with outdir '' when a user runs it by hand.  When gnuplot
 * exits 0, each of the n pictures names[k] (relative to dir) is synced
 * and renamed from SUB over dir/names[k] (only a regular file, or
 * nothing, is replaced); gnuplot's messages become dir/gnuplot.log either
 * way.  Nothing in `dir` but those names is written, truncated or
 * removed.  0, or -1 after one error line naming dir/script (gnuplot not
 * found, failed, a picture not put in place). */
int cli_gnuplot(const char *dir, const char *script,
                const char *const *names, size_t n);

/* Writes `s` as a gnuplot single-quoted string ('' for a quote; line
 * breaks become spaces). */
void cli_gnuplot_string(FILE *g, const char *s);

#endif
