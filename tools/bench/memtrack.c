/*
 * memtrack.c - a size-tracking allocator for atrbvh_set_allocator: each
 * block carries its size in a header, so the bytes the library holds at
 * any moment, and the peak since the last reset, are known exactly.
 * Otherwise it does what the library's default allocator does, so that
 * the builds the bench times are the builds users get: large blocks are
 * advised for transparent huge pages as the library advises its own
 * (atrbvh_i_advise_huge; it leaves a replaced allocator's blocks alone).
 */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE /* madvise, MADV_HUGEPAGE */
#endif
#include "config.h"

#include "memtrack.h"

#include <stdint.h>
#include <stdlib.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

/* The library's rule: the 2 MiB-aligned interior of blocks of 8 MiB or
 * more. */
static void advise_huge(void *p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const uintptr_t huge = (uintptr_t)1 << 21;
    const uintptr_t lo = ((uintptr_t)p + huge - 1) & ~(huge - 1),
                    hi = ((uintptr_t)p + bytes) & ~(huge - 1);
    if (bytes >= 4 * huge && hi > lo)
        (void)madvise((void *)lo, (size_t)(hi - lo), MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

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
    advise_huge(h + 1, size);
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
