/*
 * cl/opencl.h - what the OpenCL backend's files share (internal to cl/).
 *
 *   device.c   device choice by spec, context, queue, program (built once
 *              at open), kernels; the locks; open/close
 *   source.c   the kernel source: the embedded files, or (configure
 *              --enable-kernel-source-override only) files from
 *              $ATRBVH_CL_SOURCE_DIR
 *   memory.c   device buffers kept between builds, transfers, launches,
 *              profiling times
 *   stages.c   one short function per stage, begin/end, set_prims,
 *              capture: the backend table atrbvh_i_cl_backend
 *   trace.c    ray batches on the opened device
 *   error.c    CL error codes as atrbvh errors
 *
 * cl/ sees nothing of lib/ but lib/backend.h (the interface and the
 * library's services), lib/atrbvh.h and lib/shared/.
 */
#ifndef ATRBVH_CL_OPENCL_H
#define ATRBVH_CL_OPENCL_H

#include "backend.h"
#include "shared/kargs.h"
#include "shared/sort.h"

#ifndef CL_TARGET_OPENCL_VERSION
#define CL_TARGET_OPENCL_VERSION 120
#endif
#include <CL/cl.h>
#include <pthread.h>

#define ATRBVH_CL_NO_INDEX ((uint64_t)-1)
/* collapse_count's smallest cut: its frontier subtrees hold at least
 * this many primitives (cl/stages.c, st_collapse) */
#define ATRBVH_CL_COUNT_CUT_MIN 256u

/* ------------------------------------------------------------- kernels */
enum {
    K_BOUNDS_TRIANGLES,
    K_BOUNDS_BOXES,
    K_MORTON,
    K_SORT_COUNT,
    K_SORT_SCATTER,
    K_SORT_BUCKETS,
    K_SORT_VARY,
    K_HIERARCHY,
    K_REFIT,
    K_OPT_PREPARE,
    K_OPT_ROUND,
    K_OPT_ROUND4,
    K_COLLAPSE,
    K_COLLAPSE_COUNT,
    K_LAYOUT_TOP,
    K_LAYOUT,
    K_INTERSECT_CLOSEST,
    K_INTERSECT_ANY,
    K_COUNT
};
extern const char *const atrbvh_i_cl_kernel_names[K_COUNT];

/* ------------------------------------------------------------- buffers */
/* Device buffers by role.  Each keeps its largest size until the device
 * is closed, so a second build of similar size creates no buffer. */
enum {
    B_GEOMETRY,   /* vertices or input boxes             */
    B_INDICES,    /* triangle indices (or a dummy)        */
    B_BOXES,      /* primitive boxes, build order         */
    B_PARTIAL,    /* bounds: the record (kargs.h
                     atrbvh_bounds_record), the blocks'
                     scene/centroid boxes, their invalid
                     primitive counts                     */
    B_KEYS,
    B_KEYS_TMP,
    B_ORDER,
    B_ORDER_TMP,
    B_HIST,       /* sort: digit counts per block         */
    B_VARY,       /* sort: the keys' OR and AND per block,
                     then their varying bits (morton)     */
    B_IDS,        /* kept primitive ids (skip_invalid)    */
    B_LEFT,
    B_RIGHT,
    B_PARENT,
    B_COUNT,
    B_BOX,
    B_COST,
    B_LEAF_PRIM,
    B_COUNTER,    /* bottom-up arrival counters           */
    B_NEEDED,     /* optimise: crown children per node,
                     the walks' starts marked             */
    B_SCRATCH,    /* optimise: per-worker treelet tables  */
    B_MARKS,      /* optimise: skip marks, 2 bytes a node */
    B_TALLY,      /* optimise: treelet counts             */
    B_SIZE,       /* collapse: output nodes per subtree   */
    B_FLAT,       /* an optimised tree's collapse
                     decisions, a byte a node            */
    B_JUMP,       /* hierarchy leftovers; layout subtrees */
    B_FLAG,       /* layout: their count; then the
                     hierarchy's status (keys out of order) */
    B_OUT_NODES,
    B_OUT_PRIMS,
    B_SYNC,       /* last_arrival's word (kernels.cl): zeroed
                     once when made, left zero by every
                     launch that counts in it            */
    /* ray batches */
    B_T_NODES,
    B_T_PRIMS,
    B_T_VERTICES,
    B_T_INDICES,
    B_T_BOXES,
    B_T_RAYS,
    B_T_OUT,
    B_T_COST,     /* per-ray box and primitive tests      */
    B_SLOTS
};
/* (c->wrapped has a bit per slot) */
ATRBVH_STATIC_ASSERT(B_SLOTS <= 64, cl_slots_fit);

#define ATRBVH_CL_MAX_EVENTS 256
#define ATRBVH_CL_MAX_TIMES 32

/* Per-kernel device times (summed over launches). */
typedef struct atrbvh_cl_times {
    unsigned count;
    const char *name[ATRBVH_CL_MAX_TIMES];
    double ms[ATRBVH_CL_MAX_TIMES];
} atrbvh_cl_times;

/* The backend's part of an atrbvh_device (dev->impl). */
typedef struct atrbvh_cl_device {
    cl_device_id device;
    cl_context ctx;
    cl_command_queue queue;
    cl_program program;
    cl_kernel kernel[K_COUNT];
    size_t kernel_wg[K_COUNT]; /* CL_KERNEL_WORK_GROUP_SIZE (at least 1) */
    cl_ulong max_alloc;
    cl_uint compute_units;
    cl_mem buf[B_SLOTS];
    size_t buf_bytes[B_SLOTS];
    unsigned long buffers_created; /* clCreateBuffer calls (tests) */
    /* The current build's commands (reset by begin; tests and
     * docs/opencl.md): kernel launches, host-to-device writes, fills,
     * blocking device-to-host reads (each one a wait), queued ones (no
     * wait: a later blocking read on the in-order queue completes them)
     * and clFinish waits. */
    unsigned long n_launches, n_writes, n_fills, n_reads, n_finishes;
    unsigned long n_queued_reads;
    /* ... and the buffers made over the caller's memory (wraps). */
    unsigned long n_wraps;
    /* The device shares the host's memory (CL_DEVICE_HOST_UNIFIED_MEMORY,
     * a CPU device such as PoCL's, an integrated GPU) and
     * ATRBVH_CL_COPY is unset: a build reads the caller's geometry and
     * writes the output in place, through buffers made over them for the
     * build (atrbvh_i_cl_wrap), instead of copying them through buffers
     * of the handle. */
    cl_uint host_memory;
    /* A CPU device (CL_DEVICE_TYPE_CPU) and ATRBVH_CL_WALKS is not "1":
     * the optimise stage's items take several treelets at once
     * (opt_round4, as the CPU's walk_lanes does); else one at a time
     * (opt_round: a GPU's many items have no room to spare). */
    cl_uint several_walks;
    uint64_t wrapped; /* slots holding a wrap (bit per slot), released
                         by atrbvh_i_cl_unwrap at the build's end */
    cl_event events[ATRBVH_CL_MAX_EVENTS];
    int event_kernel[ATRBVH_CL_MAX_EVENTS];
    int event_count;
    int pending; /* commands queued since the last wait (finish or a
                    blocking transfer) */
    /* 0, or the codes of a wait for the queue that failed and of the
     * second wait after it, which failed too (atrbvh_i_cl_finish): the
     * queue's commands are in an unknown state and may still run, so
     * every later build and ray batch on the handle is refused
     * (atrbvh_i_cl_usable); only its close is left. */
    cl_int lost, lost_again;
    atrbvh_cl_times *times; /* where finished launches are added */
    atrbvh_cl_times build_times; /* the last build's */
    cl_uint has_ids;        /* this build: B_IDS maps leaves   */
    cl_uint ranges;         /* this build: the hierarchy stage's
                               tree (set_tree's is not)          */
    cl_uint counted;        /* this build: the morton kernel found
                               the keys' varying bits (B_VARY)   */
    cl_uint counters_zero;  /* B_COUNTER is all zero (a fill, the
                               optimise rounds and every bottom-up
                               launch leave it so)               */
    cl_uint refitted;       /* this build: the hierarchy kernel
                               refitted its tree (no refit launch) */
    cl_uint flags;          /* this build: B_FLAT holds the collapse
                               decisions, kept by the optimise stage
                               (the collapse counts the sizes)     */
    cl_uint prims_set;      /* this build: set_prims replaced the
                               bounds kernel's boxes (the host's
                               Morton frame then)                 */
    cl_uint tally_late;     /* this build: `tally` is being read  */
    cl_uint laid_out;       /* this build: the layout kernels are
                               queued (by the collapse stage)     */
    cl_uint tally[3];       /* the optimise stage's counts, read
                               without a wait                     */
    cl_uint hier_flag[2];   /* B_FLAG read in the collapse stage's
                               wait: [1] the hierarchy's status,
                               the first key out of order + 1 (0:
                               in order)                          */
    atrbvh_bounds_record bounds_rec; /* read from B_PARTIAL        */
    /* The last build's optimise stage (tests, measurements): treelets
     * processed, of which written back, and treelets skipped by the skip
     * marks (atrbvh_treelet_process_marked). */
    cl_uint opt_treelets, opt_applied, opt_skipped;
} atrbvh_cl_device;

/* error.c */
const char *atrbvh_i_cl_code_name(cl_int err);
/* ATRBVH_ERR_NOMEM for the out-of-memory codes (host, or a buffer the
 * device could not allocate), else ATRBVH_ERR_BACKEND. */
atrbvh_status atrbvh_i_cl_status(cl_int err);
/* "OpenCL: CALL failed [for WHAT]: NAME (code)", with
 * atrbvh_i_cl_status(err). */
atrbvh_status atrbvh_i_cl_error(atrbvh_error *error, cl_int err,
                                const char *call, const char *what);

/* source.c: the program text (library allocator), NULL when out of
 * memory. */
char *atrbvh_i_cl_source(void);

/* device.c */
extern const atrbvh_i_backend atrbvh_i_cl_backend;
atrbvh_status atrbvh_i_cl_open(atrbvh_device *dev, const char *spec,
                               atrbvh_error *error);
void atrbvh_i_cl_close(atrbvh_device *dev);

/* trace.c: the backend table's trace (see lib/backend.h) */
atrbvh_status atrbvh_i_cl_rays(atrbvh_device *dev, const atrbvh_node *nodes,
                                size_t node_count,
                                const uint32_t *prim_indices,
                                size_t prim_count, const atrbvh_i_input *in,
                                const atrbvh_ray *rays, size_t count,
                                atrbvh_hit *hits, uint8_t *occluded,
                                atrbvh_ray_cost *cost, int threads,
                                double *kernel_ms, atrbvh_error *error);

/* set_tree.c: the backend table's set_tree (see lib/backend.h) */
atrbvh_status atrbvh_i_cl_set_tree(atrbvh_device *dev, atrbvh_i_run *run,
                                   const uint32_t *left,
                                   const uint32_t *right,
                                   const uint32_t *leaf_prim,
                                   atrbvh_error *error);

/* memory.c */
/* Buffer `slot` with at least count * item bytes (kept, grown only when
 * too small). */
atrbvh_status atrbvh_i_cl_buffer(atrbvh_cl_device *c, int slot, size_t count,
                                 size_t item, const char *what,
                                 atrbvh_error *error);
void atrbvh_i_cl_buffers_release(atrbvh_cl_device *c);
atrbvh_status atrbvh_i_cl_upload(atrbvh_cl_device *c, int slot,
                                 const void *data, size_t bytes,
                                 const char *what, atrbvh_error *error);
/* The same without waiting: `data` must stay as it is until the queue has
 * run the copy (a later blocking read, or atrbvh_i_cl_finish; the stage
 * table's end waits for the queue on every path). */
atrbvh_status atrbvh_i_cl_upload_queued(atrbvh_cl_device *c, int slot,
                                        const void *data, size_t bytes,
                                        const char *what,
                                        atrbvh_error *error);
/* Slot `slot` for this build only: a buffer made over the caller's
 * `bytes` at `data` (CL_MEM_USE_HOST_PTR with `access`, on a
 * c->host_memory device), in place of any buffer the slot held.  The
 * device never writes a buffer made CL_MEM_READ_ONLY, so `data` may be
 * read-only memory.  `data` must stay valid until the build's end waits
 * for the queue and calls atrbvh_i_cl_unwrap. */
atrbvh_status atrbvh_i_cl_wrap(atrbvh_cl_device *c, int slot,
                               const void *data, size_t bytes,
                               cl_mem_flags access, const char *what,
                               atrbvh_error *error);
/* One of the caller's arrays that kernels read, in slot `slot`: a wrap
 * (in place) on a c->host_memory device, else the handle's buffer and a
 * copy into it (blocking or queued). */
atrbvh_status atrbvh_i_cl_input(atrbvh_cl_device *c, int slot,
                                const void *data, size_t bytes,
                                cl_bool blocking, const char *what,
                                atrbvh_error *error);
/* One of the caller's arrays that kernels write (count items of `item`
 * bytes), in slot `slot`: a wrap on a c->host_memory device, else the
 * handle's buffer, made for at least `keep` items (>= count: what later
 * calls of the same size will need); either way read back with
 * atrbvh_i_cl_download into `data` (no copy in place). */
atrbvh_status atrbvh_i_cl_output(atrbvh_cl_device *c, int slot, void *data,
                                 size_t count, size_t keep, size_t item,
                                 const char *what, atrbvh_error *error);
/* Releases the wraps of a build or ray batch (after the queue is done
 * with them). */
void atrbvh_i_cl_unwrap(atrbvh_cl_device *c);
/* B_SYNC, made and zeroed the first time. */
atrbvh_status atrbvh_i_cl_sync(atrbvh_cl_device *c, atrbvh_error *error);
atrbvh_status atrbvh_i_cl_download(atrbvh_cl_device *c, int slot, void *data,
                                   size_t bytes, const char *what,
                                   atrbvh_error *error);
/* The same without waiting: `data` must stay valid until a later
 * blocking read or atrbvh_i_cl_finish (the in-order queue completes it
 * before them). */
atrbvh_status atrbvh_i_cl_download_queued(atrbvh_cl_device *c, int slot,
                                          void *data, size_t bytes,
                                          const char *what,
                                          atrbvh_error *error);
atrbvh_status atrbvh_i_cl_zero(atrbvh_cl_device *c, int slot, size_t bytes,
                               const char *what, atrbvh_error *error);
/* A kernel argument: a buffer slot, or a value of `size` bytes. */
typedef struct atrbvh_cl_arg {
    int slot; /* -1: value */
    size_t size;
    const void *value;
} atrbvh_cl_arg;
#define CL_BUF(s) {(s), 0, NULL}
#define CL_VAL(v) {-1, sizeof(v), &(v)}
/* Sets the arguments of kernel k in order and launches it over `items`
 * work-items (0: nothing). */
atrbvh_status atrbvh_i_cl_run(atrbvh_cl_device *c, int k, size_t items,
                              const atrbvh_cl_arg *args, int count,
                              atrbvh_error *error);
/* Waits for the queue and adds the finished launches' device times to
 * c->times. */
atrbvh_status atrbvh_i_cl_finish(atrbvh_cl_device *c, atrbvh_error *error);
/* The finished launches' device times into c->times, waiting only when
 * something is still queued (atrbvh_i_cl_finish); after a blocking read
 * every launch before it is done on the in-order queue. */
atrbvh_status atrbvh_i_cl_collect(atrbvh_cl_device *c, atrbvh_error *error);
/* ATRBVH_OK, or ATRBVH_ERR_BACKEND when the handle is lost (lost above),
 * with a message saying so and what to do. */
atrbvh_status atrbvh_i_cl_usable(const atrbvh_cl_device *c,
                                 atrbvh_error *error);
/* Releases pending events without reading them. */
void atrbvh_i_cl_drop_events(atrbvh_cl_device *c);

#define CL_RUN(c, k, items, error, ...)                                        \
    do {                                                                       \
        const atrbvh_cl_arg args_[] = {__VA_ARGS__};                           \
        atrbvh_status st_ = atrbvh_i_cl_run(                                   \
            (c), (k), (items), args_, (int)(sizeof args_ / sizeof args_[0]),  \
            (error));                                                          \
        if (st_ != ATRBVH_OK)                                                  \
            return st_;                                                        \
    } while (0)
#define CL_CHECK(expr)                                                         \
    do {                                                                       \
        atrbvh_status st_ = (expr);                                            \
        if (st_ != ATRBVH_OK)                                                  \
            return st_;                                                        \
    } while (0)

#endif
