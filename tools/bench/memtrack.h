/*
 * memtrack.h - peak bytes the library allocates (atrbvh_set_allocator).
 * Install before the first library call and uninstall only after every
 * BVH made meanwhile is freed.
 */
#ifndef ATRBVH_TOOLS_MEMTRACK_H
#define ATRBVH_TOOLS_MEMTRACK_H

#include <stddef.h>

#include "atrbvh.h"

void memtrack_install(void);
void memtrack_uninstall(void);
/* The peak restarts from the bytes held now. */
void memtrack_reset_peak(void);
size_t memtrack_current(void);
size_t memtrack_peak(void);

#endif
