/*
 * loader.h - what scene.c, ply.c, obj.c and builtin.c share; private to
 * libscene (the tool and the tests use scene.h).
 */
#ifndef ATRBVH_TOOLS_LOADER_H
#define ATRBVH_TOOLS_LOADER_H

#include <stddef.h>
#include <stdint.h>

#include "scene.h"

/* The largest N of builtin:NAME:N. */
#define SCENE_BUILTIN_MAX ((size_t)50000000)

/* Parsers over a whole file in memory.  `path` only names the file in
 * messages.  On failure: -1, *out untouched, one line in err. */
int scene_parse_ply(const char *path, const unsigned char *data, size_t size,
                    scene *out, char *err, size_t err_len);
int scene_parse_obj(const char *path, const unsigned char *data, size_t size,
                    scene *out, char *err, size_t err_len);

/* Reads a PLY file for scene_parse_ply without trusting it (ply.c): the
 * header first (bounded), then only as much body as its elements can take;
 * a regular file whose size cannot match the header is refused before its
 * body is read.  0 and a malloc'ed *data, or -1 with one line in err. */
int scene_read_ply(const char *path, unsigned char **data, size_t *size,
                   char *err, size_t err_len);

/* snprintf into err (when err_len > 0); returns -1 for `return
 * scene_fail(...)`. */
int scene_fail(char *err, size_t err_len, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Makes room for `need` elements of `elem` bytes in *p (capacity *cap),
 * growing geometrically; 0 on overflow or out of memory (*p unchanged). */
int scene_reserve(void **p, size_t *cap, size_t need, size_t elem);

/* A coordinate read as double, as float, rounded to nearest: values that
 * round beyond FLT_MAX become +-Inf explicitly (a plain conversion of an
 * out-of-range value would be undefined), NaN stays NaN, so the library
 * reports them as non-finite; values that round to FLT_MAX stay finite. */
float scene_float(double d);
/* Reports loading progress (scene_set_progress), `done` of `total` in the
 * half `phase` (0 reading, 1 parsing); cheap when nobody listens. */
void scene_progress(int phase, uint64_t done, uint64_t total);

/* Copies the base name of `path` into name (truncated, always terminated). */
void scene_set_name(scene *s, const char *path);

#endif
