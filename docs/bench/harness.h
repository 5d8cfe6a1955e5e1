/*
 * harness.h - what the standalone timing programs of docs/bench share
 * (kernels.c, inplace.c, modes.c, stagetimes.c): a monotonic clock in
 * milliseconds and a comparison of doubles for qsort.  Not part of the
 * library; each program includes it after defining _POSIX_C_SOURCE (for
 * clock_gettime) and is compiled as its header says.
 */
#ifndef ATRBVH_BENCH_HARNESS_H
#define ATRBVH_BENCH_HARNESS_H

#include <time.h>

static inline double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* Ascending, for qsort over doubles. */
static inline int by_value(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

#endif
