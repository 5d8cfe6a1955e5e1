/*
 * fuzz_common.h - what the libFuzzer harnesses share (tests/fuzz/run.sh
 * builds each harness from its .c and the library and tool sources, with
 * clang -fsanitize=fuzzer,address,undefined).  A failed check aborts, which
 * libFuzzer reports as a crash with the input saved.
 */
#ifndef ATRBVH_FUZZ_COMMON_H
#define ATRBVH_FUZZ_COMMON_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atrbvh.h"
#include "loader.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_CHECK(cond, ...)                                                  \
    do {                                                                       \
        if (!(cond)) {                                                         \
            fprintf(stderr, "fuzz check failed: %s: ", #cond);                 \
            fprintf(stderr, __VA_ARGS__);                                      \
            fputc('\n', stderr);                                               \
            abort();                                                           \
        }                                                                      \
    } while (0)

typedef int (*fuzz_parser)(const char *path, const unsigned char *data,
                           size_t size, scene *out, char *err, size_t err_len);

/* A loaded scene is consistent and buildable (or the build fails
 * cleanly); a failure is one line naming the file and where. */
static inline void fuzz_scene(const uint8_t *data, size_t size,
                              fuzz_parser parse, const char *name)
{
    scene s;
    char err[512];
    size_t i;
    memset(&s, 0, sizeof s);
    err[0] = '\0';
    if (parse(name, data, size, &s, err, sizeof err) != 0) {
        FUZZ_CHECK(err[0] != '\0', "no message");
        FUZZ_CHECK(strchr(err, '\n') == NULL, "two lines: %s", err);
        FUZZ_CHECK(strncmp(err, name, strlen(name)) == 0, "%s", err);
        FUZZ_CHECK(strstr(err, "line ") || strstr(err, "byte offset ") ||
                       strstr(err, "out of memory"),
                   "no location: %s", err);
        return;
    }
    FUZZ_CHECK(s.triangle_count == 0 || s.indices, "no indices");
    for (i = 0; i < 3 * s.triangle_count; i++)
        FUZZ_CHECK(s.indices[i] < s.vertex_count, "index %u of %zu",
                   s.indices[i], s.vertex_count);
    /* the tool's path: build what loaded (small scenes only) */
    if (s.triangle_count > 0 && s.triangle_count < 4096) {
        atrbvh_geometry g = scene_geometry(&s);
        atrbvh_build_options o;
        atrbvh_bvh *b = NULL;
        atrbvh_error e;
        atrbvh_status st;
        atrbvh_build_options_init(&o);
        o.threads = 1;
        o.skip_invalid = 1;
        st = atrbvh_build(&g, &o, &b, &e);
        FUZZ_CHECK(st == ATRBVH_OK || st == ATRBVH_ERR_NO_PRIMITIVES,
                   "build: %s", e.text);
        atrbvh_bvh_free(b);
    }
    scene_free(&s);
}

#endif
