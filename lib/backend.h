/*
 * backend.h - the one interface between the pipeline (lib/pipeline.c) and a
 * backend (lib/cpu/: OpenMP; cl/: OpenCL).
 *
 * The pipeline runs the stages in order and owns everything that is not
 * per-item work: option checks, the geometry's metadata checks, the exact
 * error for an invalid primitive, the host constants that steer decisions
 * (the Morton frame), timing, progress, cancellation, stage capture and
 * the output object.  A backend holds only the mapping of each stage onto
 * its hardware (scheduling, memory movement, synchronisation); the
 * per-item arithmetic is lib/shared/'s, compiled for both.
 *
 * A backend sees nothing of lib/ but this header (and lib/shared/): no
 * include or call circle.  The helpers it may call are declared below
 * (allocation, errors, clock).
 */
#ifndef ATRBVH_BACKEND_H
#define ATRBVH_BACKEND_H

#include "atrbvh.h"
#include "shared/arith.h"
#include "shared/stages.h"

#include <pthread.h>
#include <stddef.h>
#include <stdint.h>

/* ---------------------------------------------------- library services */
void *atrbvh_i_malloc(size_t size);
void atrbvh_i_free(void *ptr);
/* count * size into *out; 0 (and *out = 0) on overflow. */
int atrbvh_i_mul_size(size_t count, size_t size, size_t *out);
/* count * size bytes; NULL on overflow or allocator failure.  An array of
 * 8 MiB or more gets atrbvh_i_advise_huge. */
void *atrbvh_i_alloc_array(size_t count, size_t size);
/* Transparent huge pages advised (Linux) over the 2 MiB-aligned part of a
 * block of `bytes` at p from the C library's malloc, when 8 MiB or more;
 * nothing otherwise (a replaced allocator's blocks, other systems). */
void atrbvh_i_advise_huge(void *p, size_t bytes);
/* Whether the CPU paths with AVX2 may run: the CPU (and the system)
 * support AVX2, and the environment variable ATRBVH_NO_AVX2 is unset,
 * empty or "0".  Every such path gives the bits of the one it replaces
 * (the tests run both): the batch ray queries' node test (traverse.c),
 * the bounds sweep (prims.c) and the Morton keys (cpu/morton.c). */
int atrbvh_i_avx2(void);
/* Fills `error` (may be NULL) and returns `status`; printf-style text. */
atrbvh_status atrbvh_i_fail(atrbvh_error *error, atrbvh_status status,
                            uint64_t index, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
double atrbvh_i_now_ms(void);

/* The end of one thread's share of a parallel region (every thread of
 * the team calls it once, right before the region's implied barrier, on
 * a zeroed atrbvh_i_join shared by the team).  The master thread - the
 * one that goes on after the region - then waits for the others by
 * spinning, at most ATRBVH_I_JOIN_SPIN pauses (about 60 us here), instead
 * of sleeping in the barrier: under a passive wait policy (the tool's) a
 * sleeping master is woken 40-60 us after the last thread arrives, on a
 * virtual machine, and that is on the build's critical path at every
 * region.  The others do not spin (they arrive at the barrier and sleep
 * as before), so no thread spins between regions, nor on a thread that
 * has not started; the spin covers only the tail of the work that the
 * other threads are doing.  Without OpenMP, a no-op. */
typedef struct atrbvh_i_join {
    int done;
} atrbvh_i_join;
#define ATRBVH_I_JOIN_SPIN 2048
void atrbvh_i_join_arrive(atrbvh_i_join *j);

/* Scratch that outlives one build: slot k keeps its largest allocation
 * until the device is closed, so repeated builds of similar sizes
 * allocate nothing new.  A build without a device handle uses a scratch
 * that the pipeline frees when the build ends.
 *
 * Roles and slots: every scratch_get/done names a role; by default role
 * k lives in slot k, but a backend may plan, before a build's first get,
 * that a role shares another role's slot (scratch_share): arrays never
 * live at the same time then take the same memory, so the bytes a build
 * holds at its peak are also all that a device handle keeps.  A slot may
 * be reserved (scratch_reserve): it is allocated at least that large, so
 * a later, larger role finds the contents of an earlier one in place, and
 * scratch_done of its roles does not free it (scratch_release does). */
#define ATRBVH_I_SCRATCH_SLOTS 24
/* Slots from this one on are the library's own (lib/animate.c); a
 * backend uses the ones below it. */
#define ATRBVH_I_SCRATCH_LIB 17
typedef struct atrbvh_i_scratch {
    void *ptr[ATRBVH_I_SCRATCH_SLOTS];
    size_t bytes[ATRBVH_I_SCRATCH_SLOTS];
    size_t reserve[ATRBVH_I_SCRATCH_SLOTS]; /* per slot, this build       */
    unsigned char home[ATRBVH_I_SCRATCH_SLOTS]; /* role -> slot + 1; 0: own */
    uint32_t live;  /* roles got and not done, this build                 */
    int transient; /* a build without a handle: nothing to keep for */
} atrbvh_i_scratch;
/* At least count * size bytes for role `slot` (contents undefined; those
 * of an earlier role of a reserved slot stay when it is large enough);
 * NULL on overflow or allocation failure (the slot is then empty). */
void *atrbvh_i_scratch_get(atrbvh_i_scratch *s, unsigned slot, size_t count,
                           size_t size);
void atrbvh_i_scratch_free(atrbvh_i_scratch *s);
/* A role the build no longer reads: its slot is freed at once when the
 * scratch is transient (lower peak memory), no other live role shares it
 * and it is not reserved; kept for the next build otherwise. */
void atrbvh_i_scratch_done(atrbvh_i_scratch *s, unsigned slot);
/* The slot of role `slot` freed now, also on a device handle (keeping it
 * would raise the next stages' peak), its reserve dropped. */
void atrbvh_i_scratch_release(atrbvh_i_scratch *s, unsigned slot);
/* The block of role `slot` handed to the caller, who then owns it
 * (atrbvh_i_free), with its size in *bytes; the slot is left empty as by
 * scratch_release.  NULL (and 0) when the slot holds nothing. */
void *atrbvh_i_scratch_take(atrbvh_i_scratch *s, unsigned slot,
                            size_t *bytes);
/* The reverse: block p, `bytes` long and of the library's allocator,
 * becomes the block of role `slot`'s slot, which then owns it, when the
 * slot is reserved, p holds its reserve, the slot's own block does not
 * (it is freed) and no role in it is live; returns 1 then, else 0 (p is
 * left to the caller). */
int atrbvh_i_scratch_adopt(atrbvh_i_scratch *s, unsigned slot, void *p,
                           size_t bytes);
/* A build's plan: every role in its own slot, no reserve, nothing live;
 * then role `role` in the slot of role `slot`, and slot `slot` at least
 * `bytes` when allocated (0 on overflow: no reserve). */
void atrbvh_i_scratch_plan_reset(atrbvh_i_scratch *s);
void atrbvh_i_scratch_share(atrbvh_i_scratch *s, unsigned role,
                            unsigned slot);
void atrbvh_i_scratch_reserve(atrbvh_i_scratch *s, unsigned slot,
                              size_t count, size_t size);

/* ------------------------------------------------------- a build's data */
/* The geometry after its metadata checks: strides in bytes. */
typedef struct atrbvh_i_input {
    const atrbvh_geometry *g;
    size_t vstride, istride, bstride;
} atrbvh_i_input;

/* One sweep over the primitives (the CPU bounds stage, and the host's
 * scan below): every box (boxes[j].min[0] NaN for a non-finite one, left
 * unwritten for a fatal one), the scene and centroid boxes of the valid
 * primitives (+-INFINITY when none), the count of non-finite ones, and
 * the lowest-indexed problem (a bad index or inverted box before any
 * NaN/Inf; first_bad -1 when none).  OpenMP-parallel; the per-item rules
 * are shared/stages.h's atrbvh_prim_box_* and atrbvh_scene_add. */
typedef struct atrbvh_i_prims_scan {
    atrbvh_box scene, centroids;
    size_t invalid;
    int64_t first_bad;
    int bad_kind; /* ATRBVH_PRIM_* of first_bad */
    uint32_t bad_value;
} atrbvh_i_prims_scan;
void atrbvh_i_prims_sweep(const atrbvh_i_input *in, int threads,
                          atrbvh_box *boxes, atrbvh_i_prims_scan *out);
/* The same with vector_ok 0: every triangle one at a time (where the CPU
 * has AVX2 the sweep takes full groups of eight triangles at once, with
 * the same results: tests/test_stages.c). */
void atrbvh_i_prims_sweep_with(const atrbvh_i_input *in, int threads,
                               int vector_ok, atrbvh_box *boxes,
                               atrbvh_i_prims_scan *out);

/* Options after validation and default resolution. */
typedef struct atrbvh_i_config {
    atrbvh_method method;
    unsigned treelet_size; /* resolved, 0 for LBVH */
    unsigned rounds;       /* resolved, 0 for LBVH */
    unsigned gamma;        /* resolved first-round gamma */
    atrbvh_cost_params cost; /* ci, ct, collapse, max_leaf */
    int threads;
    int skip_invalid;
    double split_budget; /* 0: no triangle splitting (lib/split.c)   */
    int split_rule;      /* ATRBVH_SPLIT_TREE or _PRIORITY            */
} atrbvh_i_config;

typedef struct atrbvh_i_run atrbvh_i_run;

/* Reports progress inside a stage: `done` of `total` items of the current
 * stage (pass / round granularity is enough).  Call it from the thread
 * that runs the stage function only.  Returns nonzero when the user asked
 * to cancel: the stage then returns ATRBVH_ERR_CANCELLED (through
 * atrbvh_i_fail) after releasing nothing it does not own; the pipeline
 * frees the rest. */
int atrbvh_i_stage_progress(atrbvh_i_run *run, uint64_t done, uint64_t total);

/* Called by a backend's optimise stage after each round (round 1, 2, ...),
 * from the thread that runs the stage, with the tree consistent: the
 * pipeline may capture it (backend->capture of ATRBVH_STAGE_OPTIMISE).
 * Nonzero: stop the stage and return ATRBVH_ERR_CANCELLED (the pipeline
 * reports the real error). */
int atrbvh_i_stage_round(atrbvh_i_run *run, unsigned round);

/* One build, shared by the pipeline and the backend.  Fields are written by
 * the stage named beside them and read by later ones. */
struct atrbvh_i_run {
    atrbvh_i_input in;
    const atrbvh_i_config *cfg;
    /* bounds: primitives in the build, scene and centroid boxes; `bad`
     * set when some primitive is invalid (NaN/Inf, a bad index, an
     * inverted box) - the pipeline then finds the exact error on the
     * host (or compacts, skip_invalid) and calls backend->set_prims. */
    uint32_t n;
    atrbvh_box scene, centroids;
    int bad;
    size_t invalid; /* primitives left out (skip_invalid)            */
    /* pipeline, before bounds: nothing reads scene, centroids and bad
     * before the collapse stage (no capture, splitting or skip_invalid),
     * so a backend may report them late: it then sets bounds_deferred
     * in bounds, computes the Morton frame itself, and its collapse
     * stage sets the three (and `bad` then fails the build with the
     * host's exact error) and clears bounds_deferred. */
    int bounds_late_ok;
    int bounds_deferred;
    /* pipeline: the stages' results may be captured (backend->capture
     * after each stage), so a backend keeps what its capture reads */
    int captured;
    /* pipeline, with triangle splitting (lib/split.c): the primitives
     * kept; n is then the number of references, each with the id of
     * its primitive (set_prims). 0: no splitting. */
    uint32_t split_prims;
    /* pipeline, before morton: the Morton frame of the centroid box
     * (lib/shared/stages.h atrbvh_morton_quantise's lo and scale). */
    double morton_lo[3], morton_scale[3];
    /* collapse: output nodes (the root's ATRBVH_SIZE_MASK part). */
    uint32_t node_count;
    /* collapse: a block of out_block_bytes (at least node_count nodes)
     * that the output's nodes take instead of a new allocation, its pages
     * already touched by the build (a CPU LBVH's node box slot, which the
     * layout does not read); else NULL.  The backend's end frees it when
     * the output did not take it. */
    void *out_block;
    size_t out_block_bytes;
    /* atrbvh_rebuild: the old tree's node array (recycled_node_bytes
     * long) and index array, the library's now, or NULL.  The backend's
     * begin may take the node block (into its scratch, or to free it: the
     * CPU's, lest it raise the peak of the stages before the output) and
     * set it NULL; the pipeline gives the output what is left when large
     * enough, and frees the rest when the build ends. */
    void *recycled_nodes;
    size_t recycled_node_bytes;
    void *recycled_indices;
    size_t recycled_index_bytes;
    /* pipeline, after collapse: the output; layout fills nodes and
     * prim_indices (node_count and n entries). */
    atrbvh_node *nodes;
    uint32_t *prim_indices;
    /* the backend's per-build state (begin/end) */
    void *state;
    /* pipeline-private (progress, cancellation) */
    void *pipeline;
};

/* ------------------------------------------------------- stage capture */
/* The tree as the stages leave it (structure of arrays; n leaves,
 * internal nodes 0..n-2 with the root at 0, leaves n-1..2n-2). */
typedef struct atrbvh_i_tree {
    uint32_t n;
    uint32_t *left;      /* n-1 entries: child of internal node i       */
    uint32_t *right;     /* n-1 entries                                 */
    uint32_t *parent;    /* 2n-1 entries, ATRBVH_U32_MAX for the root    */
    uint32_t *count;     /* 2n-1: primitives under the node             */
    atrbvh_box *box;     /* 2n-1                                        */
    double *cost;        /* 2n-1: unnormalised SAH cost of the subtree  */
    uint32_t *leaf_prim; /* n: leaf n-1+p -> original primitive index   */
} atrbvh_i_tree;

/* Copies of every stage's output (atrbvh_validate_backends compares two;
 * stage dumps write them).  Arrays are the library allocator's. */
typedef struct atrbvh_i_capture {
    uint32_t n;
    atrbvh_box *prim_boxes;   /* bounds: n boxes in build order        */
    atrbvh_box scene, centroids;
    uint64_t *keys;           /* morton: n keys in build order         */
    uint64_t *sorted_keys;    /* sort: keys and build indices, sorted  */
    uint32_t *order;
    atrbvh_i_tree hierarchy;  /* left, right, parent, count, leaf_prim */
    atrbvh_i_tree refit;      /* + box, count, cost                    */
    atrbvh_i_tree optimise;   /* the same after the optimise stage     */
    uint32_t *collapse_size;  /* collapse: output nodes per subtree    */
} atrbvh_i_capture;

/* Allocates every array of a tree of n leaves (values = 0: box and cost
 * stay NULL), with the library's allocator; tree_free releases them. */
atrbvh_status atrbvh_i_tree_alloc(atrbvh_i_tree *t, uint32_t n, int values);
void atrbvh_i_tree_free(atrbvh_i_tree *t);
/* A deep copy of src's arrays (box and cost only with values, when src
 * has them); ATRBVH_ERR_NOMEM with dst empty on failure. */
atrbvh_status atrbvh_i_tree_copy(atrbvh_i_tree *dst, const atrbvh_i_tree *src,
                                 int values);
/* Every node's collapse size of a tree of n >= 1 leaves from every
 * node's kept decision (flat, 2n-1 bytes: an optimised tree's, which the
 * collapse stages count from, down to the collapsed nodes only), into a
 * new array of 2n-1 (the library's allocator; NULL when out of memory):
 * the collapse stage's capture, which holds every node's size, as a
 * tree decided from its costs has them.  Children before parents (a
 * breadth-first order backwards), no recursion. */
uint32_t *atrbvh_i_sizes_counted(const uint32_t *left, const uint32_t *right,
                                 const unsigned char *flat, uint32_t n);

/* ---------------------------------------------------------- the backend */
typedef struct atrbvh_i_backend atrbvh_i_backend;

/* What every device handle holds; `impl` is the backend's (context,
 * program, device buffers). */
struct atrbvh_device {
    const atrbvh_i_backend *backend;
    char name[128];
    atrbvh_i_scratch scratch; /* host scratch kept between builds */
    void *impl;
    /* Held by the pipeline around every build and ray batch on this
     * handle: a backend never sees two calls on one device at once. */
    pthread_mutex_t lock;
    int temporary; /* a handle made for one call (no lock taken) */
};

typedef atrbvh_status (*atrbvh_i_stage_fn)(atrbvh_device *dev,
                                           atrbvh_i_run *run,
                                           atrbvh_error *error);

struct atrbvh_i_backend {
    const char *name; /* "cpu", "opencl" */
    atrbvh_backend kind;
    /* Select the device named by `spec` (backend-specific; NULL or "" the
     * first), set dev->name, create what every build reuses (context,
     * queue, program).  Thread-safe. */
    atrbvh_status (*open)(atrbvh_device *dev, const char *spec,
                          atrbvh_error *error);
    void (*close)(atrbvh_device *dev);
    /* Per-build state into run->state (buffers for run->in.g's
     * primitive_count); end releases what begin made (scratch kept on the
     * device stays).  end is called on every path once begin succeeded. */
    atrbvh_status (*begin)(atrbvh_device *dev, atrbvh_i_run *run,
                           atrbvh_error *error);
    void (*end)(atrbvh_device *dev, atrbvh_i_run *run);
    /* The stages, by atrbvh_stage.  bounds sets n, scene, centroids (or
     * bad); morton reads morton_lo/scale; collapse sets node_count;
     * layout writes run->nodes and run->prim_indices. */
    atrbvh_i_stage_fn stage[ATRBVH_STAGE_COUNT];
    /* After an invalid primitive: the boxes (n, build order) and, with
     * skip_invalid, the kept ids (NULL: the identity) the pipeline
     * computed on the host replace the bounds stage's output. */
    atrbvh_status (*set_prims)(atrbvh_device *dev, atrbvh_i_run *run,
                               const atrbvh_box *boxes, const uint32_t *ids,
                               atrbvh_error *error);
    /* Copies the output of `stage` (just run) into `cap`. */
    atrbvh_status (*capture)(atrbvh_device *dev, atrbvh_i_run *run,
                             atrbvh_stage stage, atrbvh_i_capture *cap,
                             atrbvh_error *error);
    /* Ray queries over a built tree (arguments checked by the caller):
     * closest hits into `hits`, or any hits into `occluded` when it is
     * non-NULL.  cost (may be NULL): each ray's box and primitive tests
     * (shared/traverse.h's _cost queries).  *kernel_ms (may be NULL):
     * device time, when known. */
    atrbvh_status (*trace)(atrbvh_device *dev, const atrbvh_node *nodes,
                           size_t node_count, const uint32_t *prim_indices,
                           size_t prim_count, const atrbvh_i_input *in,
                           const atrbvh_ray *rays, size_t count,
                           atrbvh_hit *hits, uint8_t *occluded,
                           atrbvh_ray_cost *cost, int threads,
                           double *kernel_ms, atrbvh_error *error);
    /* Per-kernel device times of the last build (i-th; 0 past the last). */
    int (*kernel_time)(atrbvh_device *dev, size_t i, const char **name,
                       double *ms);
    /* atrbvh_reoptimise (lib/animate.c), after bounds, in place of morton,
     * sort and hierarchy: installs the binary tree of run->n leaves
     * (left/right: n-1 entries, internal nodes 0..n-2 with the root at 0,
     * leaves n-1..2n-2) whose leaf n-1+p holds input primitive
     * leaf_prim[p] (its box: the bounds stage's entry leaf_prim[p]; no
     * kept ids).  NULL: the backend cannot (ATRBVH_ERR_UNSUPPORTED). */
    atrbvh_status (*set_tree)(atrbvh_device *dev, atrbvh_i_run *run,
                              const uint32_t *left, const uint32_t *right,
                              const uint32_t *leaf_prim,
                              atrbvh_error *error);
};

extern const atrbvh_i_backend atrbvh_i_cpu_backend;
#ifdef ATRBVH_HAVE_OPENCL
extern const atrbvh_i_backend atrbvh_i_cl_backend;
#endif

#endif
