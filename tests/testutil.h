/*
 * testutil.h - what the Check suites share: an independent checker of the
 * structural invariants, the scene folder, and small generators.
 */
#ifndef ATRBVH_TESTUTIL_H
#define ATRBVH_TESTUTIL_H

#include <check.h>
#include <stddef.h>
#include <stdint.h>

#include "atrbvh.h"
#include "scene.h"

/* Checks, independently of the library: every input primitive (minus
 * `skipped`, given as a sorted list of skipped ids or NULL) referenced
 * exactly once; child boxes inside parent boxes; each leaf box contains
 * its primitives' boxes; node/leaf/depth counts equal the reported stats;
 * the SAH recomputed here (long double) equals stats.sah to 1e-9
 * relative.  Returns 1 when all hold; else 0 with the reason in msg. */
int tu_check_bvh(const atrbvh_bvh *bvh, const atrbvh_geometry *g, char *msg,
                 size_t msg_len);

/* The same for a tree built with split_budget `budget` (triangle
 * splitting): every valid primitive referenced at least once, none twice
 * in one leaf, at most budget * (valid primitives) extra references, and
 * boxes geometry never split (each box exactly once, its leaf box around
 * it).  Each triangle reference's leaf box meets the triangle (the
 * triangle clipped to the box is not empty), a leaf of one reference lies
 * inside its triangle's box, and each vertex and the centroid of every
 * triangle lie in the box of a leaf listing it.  Node boxes nested,
 * counts and SAH as tu_check_bvh; stats.primitives counts the distinct
 * (valid) primitives, not the references. */
int tu_check_bvh_split(const atrbvh_bvh *bvh, const atrbvh_geometry *g,
                       double budget, char *msg, size_t msg_len);

/* Whether triangle (a, b, c) meets the box [lo, hi]: the triangle clipped
 * by the box's six planes (in double, boundaries included, each plane
 * moved out by 2^-40 of the triangle's largest coordinate on its axis for
 * the clip's rounding) is not empty. */
int tu_triangle_meets_box(const float *a, const float *b, const float *c,
                          const float lo[3], const float hi[3]);

/* Primitive i of g as the library reads it (strides, indices): vertex c
 * (0..2) of a triangle, or the box's 6 floats (min x, y, z, max x, y, z). */
const float *tu_vertex(const atrbvh_geometry *g, size_t i, int c);
const float *tu_box(const atrbvh_geometry *g, size_t i);
/* The box around every primitive of g (NaN coordinates ignored). */
void tu_bounds(const atrbvh_geometry *g, float lo[3], float hi[3]);

/* Bit-for-bit equality of two builds (nodes, indices, SAH); 1 if equal,
 * else 0 with the first difference in msg. */
int tu_same_bvh(const atrbvh_bvh *a, const atrbvh_bvh *b, char *msg,
                size_t msg_len);

/* $ATRBVH_SCENES when it names a readable folder holding *.ply, else NULL. */
const char *tu_scenes_dir(void);
/* Fills `paths` (up to max) with the .ply files of tu_scenes_dir(), sorted;
 * returns how many.  Strings are malloc'd: free with tu_free_paths. */
size_t tu_scene_paths(char **paths, size_t max);
void tu_free_paths(char **paths, size_t n);

/* xorshift64* random numbers, deterministic per seed. */
typedef struct tu_rng {
    uint64_t s;
} tu_rng;
void tu_rng_seed(tu_rng *r, uint64_t seed);
uint64_t tu_rng_next(tu_rng *r);
float tu_rng_float(tu_rng *r); /* [0, 1) */

/* n random triangles in the unit cube scaled by `scale` and translated by
 * `offset` (packed vertices, 9 floats per triangle, caller frees). */
float *tu_random_triangles(size_t n, uint64_t seed, float scale, float offset);

/* Builds with options (threads set), failing the current test on error. */
atrbvh_bvh *tu_build(const atrbvh_geometry *g, const atrbvh_build_options *o);

/* A counting allocator, to pass to atrbvh_set_allocator(tu_count_malloc,
 * tu_count_free), counting into tu_alloc.  A request fails (NULL) when the
 * countdown is at 0; one that does not fail by it counts in allocations,
 * largest and total_bytes, and a block returned in outstanding until freed.
 * The library's allocator is process-wide: set it only around the code
 * measured, and back to atrbvh_set_allocator(NULL, NULL) after. */
typedef struct tu_alloc_counts {
    long outstanding;   /* blocks allocated and not yet freed */
    long countdown;     /* requests left before they fail; -1: none fails */
    long allocations;   /* requests that did not fail by the countdown */
    size_t largest;     /* the largest of those requests, in bytes */
    size_t total_bytes; /* their bytes, all together */
} tu_alloc_counts;
extern tu_alloc_counts tu_alloc;
void *tu_count_malloc(size_t n);
void tu_count_free(void *p);
/* All counts to zero; the countdown as given (-1: no request fails). */
void tu_count_reset(long countdown);

/* Little-endian 32-bit words of the file formats, and their CRC-32
 * (IEEE, bitwise), written here independently of the library. */
uint32_t tu_rd32(const unsigned char *p);
void tu_wr32(unsigned char *p, uint32_t v);
uint32_t tu_crc32(const unsigned char *p, size_t n);
/* Rewrites the last 4 bytes of d[0..n) as the CRC-32 of those before. */
void tu_fix_crc(unsigned char *d, size_t n);
/* The atrbvh(5) bytes (version 1) of a chain BVH over the `leaves`
 * triangles of v (9 floats each, no indices): internal node j < k =
 * leaves - 1 has node j + 1 on its left and leaf j (node 2k - j) on its
 * right, node k is leaf k, slot i lists triangle i; internal boxes the box
 * of every vertex (loose but valid), leaf boxes the triangles'.  Depth k.
 * malloc'd, *size bytes; NULL when out of memory. */
unsigned char *tu_chain_bvh_bytes(const float *v, size_t leaves,
                                  size_t *size);

/* Files.  A new folder "$ATRBVH_BUILDDIR/<prefix>XXXXXX" (or under ".")
 * made by mkdtemp (malloc'd name); every name in `dir` other than . and
 * .., as one string "a b c "; a file of n bytes d (written with stdio);
 * whether `path` holds exactly n bytes d (0 when it cannot be read).
 * Each fails the current test when a call it makes fails. */
char *tu_make_temp_dir(const char *prefix);
void tu_list_dir(const char *dir, char *out, size_t len);
void tu_write_bytes(const char *path, const unsigned char *d, size_t n);
int tu_holds(const char *path, const unsigned char *d, size_t n);

/* Whether a test that needs the OpenCL backend may skip, saying so, after
 * `st`, the failed status of its first call on it: only for
 * ATRBVH_ERR_UNSUPPORTED (a library without OpenCL, or a system without
 * an OpenCL platform or device), and not even then when
 * $ATRBVH_TEST_REQUIRE_OPENCL is set (to anything but "" or "0": the
 * check stage of tests/suite.d, which installs PoCL).  Anything else -
 * the kernels failing to compile, a device that fails - is a failure of
 * the test, not a reason to skip it. */
int tu_opencl_may_skip(atrbvh_status st);

/* Runs every test of s (verbosity CK_VERBOSITY, default normal);
 * EXIT_SUCCESS when all passed, else EXIT_FAILURE. */
int tu_run(Suite *s);

#endif
