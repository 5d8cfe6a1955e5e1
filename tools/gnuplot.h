/*
 * gnuplot.h - gnuplot for the tool's plots (bench --plot, animate --plot):
 * started without a shell, its script's pictures written as NAME.part and
 * renamed by the caller only when it succeeded.
 */
#ifndef ATRBVH_TOOLS_GNUPLOT_H
#define ATRBVH_TOOLS_GNUPLOT_H

#include <stdio.h>

/* Runs `gnuplot -e "outsuffix = '.part'" SCRIPT` in `dir` (stdin from
 * /dev/null, stderr to dir/gnuplot.log).  0 when it exited 0; else -1
 * after one error line naming dir/script (not found, failed, ...). */
int cli_gnuplot(const char *dir, const char *script);

/* The picture `final` gnuplot wrote as final.part: renamed over `final`
 * when ok (only a regular file, or nothing, is replaced), else removed.
 * 0, or -1 after an error line. */
int cli_gnuplot_picture(const char *final, int ok);

/* Writes `s` as a gnuplot single-quoted string ('' for a quote; line
 * breaks become spaces). */
void cli_gnuplot_string(FILE *g, const char *s);

#endif
