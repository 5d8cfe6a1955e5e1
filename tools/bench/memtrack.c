/*
 * memtrack.c - a size-tracking allocator for atrbvh_set_allocator: each
 * block carries its size in a header, so the bytes the library holds at
 * any moment, and the peak since the last reset, are known exactly.
 */
#include "config.h"

#include "memtrack.h"

#include <stdlib.h>

typedef union header {
    size_t size;
    long double align_ld;
    void *align_p;
    long long align_ll;
} header;

static size_t current, peak;

static void *track_malloc(size_t size)
{
    header *h;
    if (size > (size_t)-1 - sizeof *h)
        return NULL;
    h = malloc(sizeof *h + size);
    if (!h)
        return NULL;
    h->size = size;
#ifdef _OPENMP
#pragma omp critical(atrbvh_tool_memtrack)
#endif
    {
        current += size;
        if (current > peak)
            peak = current;
    }
    return h + 1;
}

static void track_free(void *p)
{
    header *h;
    if (!p)
        return;
    h = (header *)p - 1;
#ifdef _OPENMP
#pragma omp critical(atrbvh_tool_memtrack)
#endif
    current -= h->size;
    free(h);
}

void memtrack_install(void)
{
    atrbvh_set_allocator(track_malloc, track_free);
}

void memtrack_uninstall(void)
{
    atrbvh_set_allocator(NULL, NULL);
}

void memtrack_reset_peak(void)
{
    peak = current;
}

size_t memtrack_current(void)
{
    return current;
}

size_t memtrack_peak(void)
{
    return peak;
}
