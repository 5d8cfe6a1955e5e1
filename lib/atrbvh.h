/*
 * atrbvh.h - the public API of libatrbvh.
 *
 * libatrbvh builds bounding volume hierarchies for ray tracing: LBVH (Karras
 * 2012), optionally optimised by treelet restructuring (TRBVH, Karras & Aila
 * 2013; ATRBVH, Domingues & Pedrini 2015), with leaves collapsed by SAH cost.
 * The output is the same, bit for bit, for any thread count.
 *
 * Conventions (jansson/libuv style):
 *  - every public name starts with atrbvh_ or ATRBVH_;
 *  - functions that can fail return an atrbvh_status and take an optional
 *    atrbvh_error* that receives a message naming what is wrong and where;
 *  - the library never aborts, exits or prints.
 */
#ifndef ATRBVH_H
#define ATRBVH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ export */
#if defined(_WIN32) && defined(ATRBVH_BUILDING_DLL)
#define ATRBVH_API __declspec(dllexport)
#elif defined(__GNUC__) && __GNUC__ >= 4
#define ATRBVH_API __attribute__((visibility("default")))
#else
#define ATRBVH_API
#endif

/* ----------------------------------------------------------------- version */
#define ATRBVH_VERSION_MAJOR 0
#define ATRBVH_VERSION_MINOR 1
#define ATRBVH_VERSION_PATCH 0
#define ATRBVH_VERSION_STRING "0.1.0"
/* (major << 16) | (minor << 8) | patch, comparable as a number. */
#define ATRBVH_VERSION_HEX                                                     \
    ((ATRBVH_VERSION_MAJOR << 16) | (ATRBVH_VERSION_MINOR << 8) |              \
     ATRBVH_VERSION_PATCH)

/* The version of the library actually linked, as ATRBVH_VERSION_HEX. */
ATRBVH_API unsigned atrbvh_version(void);
/* The version of the library actually linked, as "MAJOR.MINOR.PATCH". */
ATRBVH_API const char *atrbvh_version_string(void);

/* ------------------------------------------------------------------ errors */
typedef enum atrbvh_status {
    ATRBVH_OK = 0,
    ATRBVH_ERR_INVALID_ARGUMENT = 1, /* null pointer, bad option value      */
    ATRBVH_ERR_NO_PRIMITIVES = 2,    /* zero primitives (or none valid)     */
    ATRBVH_ERR_NONFINITE = 3,        /* NaN or Inf coordinate in the input  */
    ATRBVH_ERR_INDEX_RANGE = 4,      /* a vertex index out of range         */
    ATRBVH_ERR_TOO_LARGE = 5,        /* count beyond the documented limit,
                                        or a size computation overflows     */
    ATRBVH_ERR_NOMEM = 6,            /* the allocator returned NULL         */
    ATRBVH_ERR_IO = 7,               /* reading or writing a file failed    */
    ATRBVH_ERR_FORMAT = 8,           /* a file is not a valid BVH file      */
    ATRBVH_ERR_UNSUPPORTED = 9,      /* feature not built in (e.g. OpenCL)  */
    ATRBVH_ERR_BACKEND = 10,         /* the compute backend failed          */
    ATRBVH_ERR_CANCELLED = 11        /* the progress callback asked to stop */
} atrbvh_status;

/* A short, static description of a status code ("out of memory", ...). */
ATRBVH_API const char *atrbvh_strerror(atrbvh_status status);

#define ATRBVH_ERROR_TEXT_LENGTH 256
/* Filled by a failing call when the caller passes a non-NULL pointer.
 * `index` is the offending primitive (or byte offset, for files), or
 * (uint64_t)-1 when not applicable. */
typedef struct atrbvh_error {
    atrbvh_status status;
    uint64_t index;
    char text[ATRBVH_ERROR_TEXT_LENGTH];
} atrbvh_error;

/* --------------------------------------------------------------- allocator */
typedef void *(*atrbvh_malloc_fn)(size_t size);
typedef void (*atrbvh_free_fn)(void *ptr);
/* Replace the allocator used for every allocation the library makes (pass
 * NULL, NULL to restore malloc/free). Not thread-safe: call it before any
 * other function, or while no other call is running. */
ATRBVH_API void atrbvh_set_allocator(atrbvh_malloc_fn malloc_fn,
                                     atrbvh_free_fn free_fn);
ATRBVH_API void atrbvh_get_allocator(atrbvh_malloc_fn *malloc_fn,
                                     atrbvh_free_fn *free_fn);

/* ---------------------------------------------------------------- geometry */
typedef enum atrbvh_geometry_type {
    ATRBVH_GEOMETRY_TRIANGLES = 0,
    ATRBVH_GEOMETRY_BOXES = 1
} atrbvh_geometry_type;

/* Describes the caller's memory; nothing is copied.
 *
 * Triangles: `vertices` points at the x of vertex 0; vertex v's x, y, z are
 * the three floats at byte offset v * vertex_stride (0 means 12, packed).
 * If `indices` is non-NULL, triangle i uses vertices indices[0..2] found at
 * byte offset i * index_stride (0 means 12, packed); otherwise triangle i is
 * vertices 3i, 3i+1, 3i+2 and vertex_count must be at least 3 *
 * primitive_count.
 *
 * Boxes: box i is six floats (min x, y, z, max x, y, z) at byte offset
 * i * box_stride (0 means 24, packed); min must not exceed max.
 */
typedef struct atrbvh_geometry {
    size_t size; /* sizeof(atrbvh_geometry): the initialisers below set it;
                    fields past the caller's size take their defaults, so
                    the struct can grow without breaking old callers     */
    atrbvh_geometry_type type;
    size_t primitive_count;
    const float *vertices;
    size_t vertex_count;
    size_t vertex_stride;
    const uint32_t *indices;
    size_t index_stride;
    const float *boxes;
    size_t box_stride;
} atrbvh_geometry;

/* Convenience initialisers (strides 0 = packed). */
ATRBVH_API atrbvh_geometry atrbvh_geometry_triangles(const float *vertices,
                                                     size_t vertex_count,
                                                     const uint32_t *indices,
                                                     size_t triangle_count);
ATRBVH_API atrbvh_geometry atrbvh_geometry_boxes(const float *boxes,
                                                 size_t box_count);

/* The most primitives one build accepts. */
#define ATRBVH_MAX_PRIMITIVES ((size_t)1 << 30)

/* The most threads a build (options.threads) or a batch ray query (its
 * threads argument) accepts: more is ATRBVH_ERR_INVALID_ARGUMENT.  The
 * OpenMP default (0, e.g. from OMP_NUM_THREADS) is held to it too. */
#define ATRBVH_MAX_THREADS 1024

/* ----------------------------------------------------------------- options */
typedef enum atrbvh_method {
    ATRBVH_METHOD_LBVH = 0,   /* Karras 2012 only                        */
    ATRBVH_METHOD_TRBVH = 1,  /* + Karras & Aila 2013 treelet DP         */
    ATRBVH_METHOD_ATRBVH = 2  /* + Domingues & Pedrini 2015 agglomerative */
} atrbvh_method;

typedef enum atrbvh_backend {
    ATRBVH_BACKEND_CPU = 0,
    ATRBVH_BACKEND_OPENCL = 1
} atrbvh_backend;

/* ------------------------------------------------------------------ device */
/* A compute device, opened once and reused by any number of builds and ray
 * batches: opening selects the device, creates its context and compiles
 * its program (OpenCL), and the handle keeps scratch memory between builds.
 * `spec`: "cpu" (or NULL); "opencl" (the first OpenCL device); "opencl:P:D" (device D
 * of platform P); or "opencl:NAME", a case-insensitive substring of the
 * device or platform name.  Thread-safe.  One build or ray batch runs on a
 * handle at a time (calls on the same handle from several threads wait for
 * each other). */
typedef struct atrbvh_device atrbvh_device;
ATRBVH_API atrbvh_status atrbvh_device_open(const char *spec,
                                            atrbvh_device **out,
                                            atrbvh_error *error);
ATRBVH_API void atrbvh_device_close(atrbvh_device *device);
/* "cpu", or the OpenCL device's name. */
ATRBVH_API const char *atrbvh_device_name(const atrbvh_device *device);
ATRBVH_API atrbvh_backend atrbvh_device_backend(const atrbvh_device *device);

/* Called from the thread that called atrbvh_build: at every stage's start
 * and, inside the long stages, as work is done (fraction of the whole
 * build, from 0 to 1, never decreasing; 1 once the build is complete).
 * Return 0 to go on; a nonzero return cancels the build, which then
 * returns ATRBVH_ERR_CANCELLED with everything freed.  Progress never
 * changes the tree. */
typedef int (*atrbvh_progress_fn)(const char *stage, double fraction,
                                  void *user);

/* ------------------------------------------------------------------ stages */
typedef enum atrbvh_stage {
    ATRBVH_STAGE_BOUNDS = 0,
    ATRBVH_STAGE_MORTON,
    ATRBVH_STAGE_SORT,
    ATRBVH_STAGE_HIERARCHY,
    ATRBVH_STAGE_REFIT,
    ATRBVH_STAGE_OPTIMISE,
    ATRBVH_STAGE_COLLAPSE,
    ATRBVH_STAGE_LAYOUT,
    ATRBVH_STAGE_COUNT
} atrbvh_stage;

/* "bounds", "morton", ...; NULL when out of range. */
ATRBVH_API const char *atrbvh_stage_name(atrbvh_stage stage);

/* ---------------------------------------------------------- stage capture */
/* Every stage's output, handed to a callback as it is produced, so that a
 * test harness can compare its own builder with this one in memory
 * (docs/stages.md and atrbvh-stages(7) say what each array holds). */
typedef enum atrbvh_dtype {
    ATRBVH_DTYPE_U32 = 0,
    ATRBVH_DTYPE_U64 = 1,
    ATRBVH_DTYPE_F32 = 2,
    ATRBVH_DTYPE_F64 = 3
} atrbvh_dtype;

/* A row-major array of rows x cols elements (cols 1 for a vector). */
typedef struct atrbvh_array {
    const char *name; /* "prim_boxes", "keys", "left", ... */
    atrbvh_dtype dtype;
    size_t rows, cols;
    const void *data; /* valid during the callback only */
} atrbvh_array;

typedef struct atrbvh_stage_output {
    size_t size;        /* sizeof(atrbvh_stage_output): it can grow      */
    atrbvh_stage stage;
    unsigned round;     /* optimise: 1, 2, ... after each round, 0 for the
                           stage's final output; 0 for other stages      */
    const char *name;   /* "bounds", ..., "optimise_round1", "optimise",
                           ..., "layout": unique within a build          */
    size_t array_count;
    const atrbvh_array *arrays;
} atrbvh_stage_output;

/* Called from the thread that called atrbvh_build after each stage (and
 * each optimise round); return 0 to go on, nonzero to cancel the build
 * (ATRBVH_ERR_CANCELLED).  Capturing never changes the tree. */
typedef int (*atrbvh_capture_fn)(const atrbvh_stage_output *output,
                                 void *user);

/* atrbvh_build_options.treelet_size for ATRBVH: the size chosen per
 * treelet root from its primitive count (9, 16 or 32; atrbvh(3)); its
 * default rounds are 4.  Stats and saved files report it as this value. */
#define ATRBVH_TREELET_AUTO 0xffffffffu

/* Set `size` to sizeof(atrbvh_build_options) (atrbvh_build_options_init
 * does); fields beyond the size the caller was compiled with take their
 * defaults, so the struct can grow without breaking old callers. */
typedef struct atrbvh_build_options {
    size_t size;
    atrbvh_method method;        /* default ATRBVH_METHOD_ATRBVH          */
    unsigned treelet_size;       /* 0 = method default (TRBVH 7, ATRBVH 9);
                                    TRBVH 3 to 10, ATRBVH 3 to 128 or
                                    ATRBVH_TREELET_AUTO                   */
    unsigned rounds;             /* 0 = method default (TRBVH 3, ATRBVH 2,
                                    ATRBVH_TREELET_AUTO 4)                */
    unsigned gamma;              /* first round's minimum subtree size,
                                    0 = treelet_size; doubles each round  */
    double ci;                   /* internal node cost, default 1.2       */
    double ct;                   /* primitive cost, default 1.0           */
    int collapse;                /* nonzero: multi-primitive leaves by SAH */
    unsigned max_leaf_size;      /* 0 = no limit                          */
    int threads;                 /* 0 = OpenMP default; at most
                                    ATRBVH_MAX_THREADS                    */
    int skip_invalid;            /* nonzero: leave out NaN/Inf primitives
                                    (counted) instead of failing          */
    atrbvh_backend backend;      /* used when device is NULL: default CPU;
                                    OPENCL opens a device for this one
                                    build (prefer atrbvh_device_open)    */
    const char *opencl_device;   /* with backend OPENCL and no device: the
                                    device spec after "opencl:" (NULL:
                                    the first device)                    */
    atrbvh_progress_fn progress; /* may be NULL                           */
    void *progress_user;
    atrbvh_device *device;       /* an open device (atrbvh_device_open),
                                    reused build after build; NULL: as
                                    `backend` says                       */
    atrbvh_capture_fn capture;   /* every stage's output; may be NULL    */
    void *capture_user;
    /* added with triangle splitting: */
    double split_budget;         /* 0 (default): off.  Triangles whose box
                                    is much larger than their area
                                    suggests get split boxes before the
                                    Morton stage, at most split_budget *
                                    primitives extra references (0 to 4;
                                    boxes geometry is never split).  A
                                    leaf may then share a primitive with
                                    another leaf (atrbvh(3))             */
    int split_rule;              /* which triangles split_budget splits:
                                    ATRBVH_SPLIT_SAH (default),
                                    ATRBVH_SPLIT_TREE or
                                    ATRBVH_SPLIT_PRIORITY (atrbvh(3))     */
} atrbvh_build_options;

/* atrbvh_build_options.split_rule: cut where a first LBVH of the unsplit
 * triangles says the cut lowers its SAH, by the Karras-Aila priority
 * (box area above the triangle's own, weighted by the Morton level of the
 * grid plane crossing it), or top down per Morton grid cell where cutting
 * the cell's straddlers at its mid plane lowers the SAH of its halves. */
enum { ATRBVH_SPLIT_TREE = 0, ATRBVH_SPLIT_PRIORITY = 1, ATRBVH_SPLIT_SAH = 2 };

ATRBVH_API void atrbvh_build_options_init(atrbvh_build_options *options);


/* -------------------------------------------------------------------- BVH */
/* A node of the output, in depth-first order; the root is node 0.
 * Internal node (count == 0): the left child is the next node, the right
 * child is node `index`.  Leaf (count > 0): its primitives are
 * primitive_indices[index .. index + count - 1]. */
typedef struct atrbvh_node {
    float min[3];
    float max[3];
    uint32_t index;
    uint32_t count;
} atrbvh_node;

typedef struct atrbvh_bvh atrbvh_bvh;

/* Statistics of a BVH.  The struct can grow: atrbvh_bvh_stats passes the
 * caller's sizeof(atrbvh_stats), and the library fills only that much. */
typedef struct atrbvh_stats {
    size_t primitives;       /* primitives in the tree                   */
    size_t invalid_skipped;  /* primitives left out (skip_invalid)       */
    size_t nodes;
    size_t leaves;
    unsigned max_depth;      /* root = depth 0                          */
    unsigned max_leaf_primitives;
    double sah;              /* SAH cost of the tree as built           */
    double ci, ct;           /* the constants the SAH uses              */
    atrbvh_method method;
    unsigned treelet_size;   /* 0 for LBVH                              */
    unsigned rounds;         /* 0 for LBVH                              */
    atrbvh_backend backend;
    int threads;             /* threads the build ran with              */
    double build_ms;         /* whole build, wall clock (not the
                                measure of atrbvh_bvh_stats)            */
    /* added with animation (atrbvh_refit): */
    double sah_built;        /* SAH when built, loaded or re-optimised;
                                sah / sah_built is a refitted tree's
                                drift (atrbvh_refit(3))                 */
    double refit_ms;         /* the last atrbvh_refit or
                                atrbvh_reoptimise, wall clock (0: none) */
} atrbvh_stats;

/* Build a BVH over `geometry`. `options` may be NULL (defaults). On
 * success *out owns a new BVH (free it with atrbvh_bvh_free); on failure
 * *out is NULL and `error`, if non-NULL, says what and where. */
ATRBVH_API atrbvh_status atrbvh_build(const atrbvh_geometry *geometry,
                                      const atrbvh_build_options *options,
                                      atrbvh_bvh **out, atrbvh_error *error);

/* atrbvh_build into the memory of *bvh, a BVH the caller is done with
 * (NULL: a plain build), for a caller that builds again and again (a
 * frame at a time, as an Embree user rebuilds into one BVH object).  Its
 * node and index arrays are reused where they are large enough (the
 * build's own arrays or the output's; atrbvh_rebuild(3)), so that the
 * build writes into memory already in use rather than new pages, which
 * the system zeroes as they are first written; the tree is the one
 * atrbvh_build makes, to the bit.  The old BVH is freed whatever the
 * call returns, and must not be used once it is called: on success *bvh
 * is the new BVH, on failure NULL.  If the geometry lies in the old BVH's
 * arrays (boxes read from its nodes), they are not reused and are freed
 * after the build. */
ATRBVH_API atrbvh_status atrbvh_rebuild(const atrbvh_geometry *geometry,
                                        const atrbvh_build_options *options,
                                        atrbvh_bvh **bvh,
                                        atrbvh_error *error);

ATRBVH_API void atrbvh_bvh_free(atrbvh_bvh *bvh);

ATRBVH_API const atrbvh_node *atrbvh_bvh_nodes(const atrbvh_bvh *bvh,
                                               size_t *count);
ATRBVH_API const uint32_t *atrbvh_bvh_primitive_indices(const atrbvh_bvh *bvh,
                                                        size_t *count);
/* Fills the first `size` bytes of *stats (size: the caller's
 * sizeof(atrbvh_stats); the atrbvh_bvh_stats macro passes it).  A build
 * leaves leaves, max_depth, max_leaf_primitives and the SAH to this call,
 * which measures them (a pass over the nodes, every call until the tree
 * is refitted or re-optimised; not in build_ms).  Returns
 * ATRBVH_ERR_INVALID_ARGUMENT, *stats untouched, when a pointer is NULL or
 * size is not the size of a version of the struct (the first, ending
 * with build_ms, or this one); ATRBVH_ERR_NOMEM or ATRBVH_ERR_BACKEND,
 * *stats untouched, when that measure fails (atrbvh_bvh_stats(3)). */
ATRBVH_API atrbvh_status atrbvh_bvh_stats_sized(const atrbvh_bvh *bvh,
                                                atrbvh_stats *stats,
                                                size_t size);
#define atrbvh_bvh_stats(bvh, stats)                                           \
    atrbvh_bvh_stats_sized((bvh), (stats), sizeof *(stats))
/* Animation (atrbvh_refit(3)).  `geometry`: the same primitives as the
 * build (count, and the tree's primitive indices in range) at new
 * positions.  atrbvh_refit recomputes every node box bottom-up, keeping
 * the topology, and updates stats.sah (stats.sah_built stays: their ratio
 * is the drift).  atrbvh_reoptimise runs options' treelet rounds (method,
 * treelet size, rounds) on the existing tree at the new positions, then
 * the SAH collapse and layout; with the build's cost options it never
 * raises the SAH; stats.sah_built becomes the new SAH.  Both run on
 * options->device (NULL: as options->backend says), allocate nothing on
 * an open device once its scratch is large enough, give the same bits for
 * any thread count and backend, and leave the tree unchanged on failure.
 * `options` may be NULL (defaults). */
ATRBVH_API atrbvh_status atrbvh_refit(atrbvh_bvh *bvh,
                                      const atrbvh_geometry *geometry,
                                      const atrbvh_build_options *options,
                                      atrbvh_error *error);
ATRBVH_API atrbvh_status atrbvh_reoptimise(atrbvh_bvh *bvh,
                                           const atrbvh_geometry *geometry,
                                           const atrbvh_build_options *options,
                                           atrbvh_error *error);
/* Wall-clock milliseconds of one stage of the build (0 for a loaded BVH,
 * a stage that did not run, or a stage out of range). */
ATRBVH_API double atrbvh_bvh_stage_ms(const atrbvh_bvh *bvh,
                                      atrbvh_stage stage);

/* The device a BVH was built on: "cpu", or the OpenCL device's name. */
ATRBVH_API const char *atrbvh_bvh_device(const atrbvh_bvh *bvh);
/* Device time of the i-th kernel of an OpenCL build (from profiling
 * events, summed over every launch of that kernel): returns 1 and sets
 * *name ("morton", "sort_count", ...) and *ms, or 0 when i is past the
 * last (always 0 for CPU builds and loaded BVHs). */
ATRBVH_API int atrbvh_bvh_kernel_time(const atrbvh_bvh *bvh, size_t i,
                                      const char **name, double *ms);

/* Builds `geometry` on the CPU and on the OpenCL backend with the same
 * options (options->backend is ignored) and compares every stage's output
 * bit for bit: the primitive boxes, the Morton keys, the sorted keys and
 * order, the topology, boxes, counts and costs after refit and after
 * optimise, the collapse decisions, and the final node and index arrays.
 * On ATRBVH_OK, *identical is 1 when everything matches; otherwise 0 and
 * error->text names the first differing stage and item ("stage refit,
 * node 1234: box differs ...") with error->status ATRBVH_OK.  A failing
 * build returns its status (ATRBVH_ERR_UNSUPPORTED without OpenCL). */
ATRBVH_API atrbvh_status atrbvh_validate_backends(
    const atrbvh_geometry *geometry, const atrbvh_build_options *options,
    int *identical, atrbvh_error *error);

/* SAH cost of a node array: (ci * sum of internal areas + ct * sum over
 * leaves of area * count) / root area, areas in double precision.  0 when
 * the root's area is 0 (every box degenerate). */
ATRBVH_API double atrbvh_sah(const atrbvh_node *nodes, size_t node_count,
                             double ci, double ct);

/* ------------------------------------------------------------- ray queries */
typedef struct atrbvh_ray {
    float origin[3];
    float dir[3];
    float tmin, tmax;
} atrbvh_ray;

#define ATRBVH_NO_HIT UINT32_MAX
typedef struct atrbvh_hit {
    float t;            /* distance along dir (dir need not be unit)     */
    float u, v;         /* barycentrics of vertices 1 and 2 (triangles) */
    uint32_t primitive; /* ATRBVH_NO_HIT when nothing was hit            */
} atrbvh_hit;

/* Closest hit with tmin <= t <= tmax (both ends included, as for
 * atrbvh_occluded), see atrbvh_intersect(3).  `geometry` must be the one
 * the BVH was built from: checked as the batch calls check it, and when it
 * fails (a NULL pointer, an unusable geometry, fewer primitives than the
 * BVH was built over) the call returns 0 with *hit a miss, reading
 * nothing.  Returns nonzero on a hit. */
ATRBVH_API int atrbvh_intersect(const atrbvh_bvh *bvh,
                                const atrbvh_geometry *geometry,
                                const atrbvh_ray *ray, atrbvh_hit *hit);
/* Any hit with tmin <= t <= tmax: nonzero if anything is hit; 0 when the
 * arguments fail the batch calls' checks. */
ATRBVH_API int atrbvh_occluded(const atrbvh_bvh *bvh,
                               const atrbvh_geometry *geometry,
                               const atrbvh_ray *ray);
/* Batched versions, OpenMP-parallel over rays (threads 0 = default, at
 * most ATRBVH_MAX_THREADS).  occluded[i] is set to 0 or 1. */
ATRBVH_API atrbvh_status atrbvh_intersect_batch(
    const atrbvh_bvh *bvh, const atrbvh_geometry *geometry,
    const atrbvh_ray *rays, size_t count, atrbvh_hit *hits, int threads,
    atrbvh_error *error);
ATRBVH_API atrbvh_status atrbvh_occluded_batch(
    const atrbvh_bvh *bvh, const atrbvh_geometry *geometry,
    const atrbvh_ray *rays, size_t count, uint8_t *occluded, int threads,
    atrbvh_error *error);

/* The same queries on an open device (atrbvh_device_open): on an OpenCL
 * device one work-item per ray, for measuring rays per second on a device
 * and checking a device against the CPU; on a "cpu" device the OpenMP
 * batches above with the default thread count.  The kernels run the very
 * functions the CPU queries run (one source compiled as C99 and OpenCL C),
 * so every result is bit for bit the one atrbvh_intersect/atrbvh_occluded
 * give (primitive, t, u, v).  The BVH may have been built on either
 * backend or loaded.  Each call uploads the tree and the geometry, then
 * the rays in chunks (the device's program and context are the handle's,
 * made once); *kernel_ms (may be NULL) receives the kernels' device time
 * from profiling events, without the transfers (0 on the CPU).  count 0
 * returns ATRBVH_OK once the arguments are checked.  Errors: as the CPU batch functions for the
 * arguments (a NULL device is ATRBVH_ERR_INVALID_ARGUMENT);
 * ATRBVH_ERR_BACKEND or ATRBVH_ERR_NOMEM when the device fails. */
ATRBVH_API atrbvh_status atrbvh_intersect_batch_device(
    atrbvh_device *device, const atrbvh_bvh *bvh,
    const atrbvh_geometry *geometry, const atrbvh_ray *rays, size_t count,
    atrbvh_hit *hits, double *kernel_ms, atrbvh_error *error);
ATRBVH_API atrbvh_status atrbvh_occluded_batch_device(
    atrbvh_device *device, const atrbvh_bvh *bvh,
    const atrbvh_geometry *geometry, const atrbvh_ray *rays, size_t count,
    uint8_t *occluded, double *kernel_ms, atrbvh_error *error);

/* The exact cost of ray queries: how many node boxes and how many
 * primitives (triangles or boxes) each ray tested.  The counts come from
 * the traversal itself (the same code on every backend), so they are the
 * same for every run, thread count and backend: a measure of a tree's
 * quality for rays that timing noise does not touch.  A ray that can hit
 * nothing (NaN or infinite origin or direction, zero direction, NaN or
 * reversed interval) costs 0; a ray missing the root box costs 1 box and
 * 0 primitives.  An any-hit query stops at its first hit, so it counts
 * up to there.  See atrbvh_intersect_batch_stats(3). */
typedef struct atrbvh_ray_cost {
    uint32_t box_tests;  /* nodes whose box the ray was tested against  */
    uint32_t prim_tests; /* primitives the ray was tested against       */
} atrbvh_ray_cost;

/* In and out of the _stats batch calls.  Set `size` to
 * sizeof(atrbvh_trace_stats) (atrbvh_trace_stats_init does): the struct
 * can grow, fields past the caller's size are neither read nor written. */
typedef struct atrbvh_trace_stats {
    size_t size;
    atrbvh_ray_cost *per_ray; /* in: NULL, or `count` entries that receive
                                 each ray's cost                          */
    uint64_t rays;            /* out: rays in the batch                   */
    uint64_t box_tests;       /* out: sums over the batch's rays          */
    uint64_t prim_tests;
    double kernel_ms;         /* out: device batches, the kernels' device
                                 time (0 on the CPU)                      */
} atrbvh_trace_stats;

ATRBVH_API void atrbvh_trace_stats_init(atrbvh_trace_stats *stats);

/* atrbvh_intersect_batch and atrbvh_occluded_batch (device NULL: OpenMP
 * over `threads`) or their _device versions (device non-NULL, threads
 * must be 0), giving the same results bit for bit, and also filling
 * *stats (may be NULL).  ATRBVH_ERR_INVALID_ARGUMENT when stats->size is
 * below the first version's struct. */
ATRBVH_API atrbvh_status atrbvh_intersect_batch_stats(
    atrbvh_device *device, const atrbvh_bvh *bvh,
    const atrbvh_geometry *geometry, const atrbvh_ray *rays, size_t count,
    atrbvh_hit *hits, int threads, atrbvh_trace_stats *stats,
    atrbvh_error *error);
ATRBVH_API atrbvh_status atrbvh_occluded_batch_stats(
    atrbvh_device *device, const atrbvh_bvh *bvh,
    const atrbvh_geometry *geometry, const atrbvh_ray *rays, size_t count,
    uint8_t *occluded, int threads, atrbvh_trace_stats *stats,
    atrbvh_error *error);

/* ----------------------------------------------------------- save and load */
/* The file format is documented in atrbvh(5).  atrbvh_save writes a
 * temporary file beside `path` and renames it over `path` only when
 * complete; on failure `path` is untouched.  A path that is not a regular
 * file (device, FIFO, /dev/stdout) is written in place and never removed
 * (atrbvh_save(3)). */
ATRBVH_API atrbvh_status atrbvh_save(const atrbvh_bvh *bvh, const char *path,
                                     atrbvh_error *error);
ATRBVH_API atrbvh_status atrbvh_load(const char *path, atrbvh_bvh **out,
                                     atrbvh_error *error);
/* Same, to and from memory (atrbvh_save_memory's buffer is allocated with
 * the library's allocator: release it with atrbvh_free). */
ATRBVH_API atrbvh_status atrbvh_save_memory(const atrbvh_bvh *bvh,
                                            void **data, size_t *size,
                                            atrbvh_error *error);
ATRBVH_API atrbvh_status atrbvh_load_memory(const void *data, size_t size,
                                            atrbvh_bvh **out,
                                            atrbvh_error *error);
ATRBVH_API void atrbvh_free(void *ptr);

/* Compare two BVHs: 0 when identical (constants, nodes bit for bit,
 * primitive indices); otherwise nonzero, with `error` text naming the first
 * difference ("node 12 differs: ..."). */
ATRBVH_API int atrbvh_compare(const atrbvh_bvh *a, const atrbvh_bvh *b,
                              atrbvh_error *error);

#ifdef __cplusplus
}
#endif
#endif /* ATRBVH_H */
