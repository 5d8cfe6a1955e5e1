/*
 * cl/memory.c - the device memory of an open handle and the launches.
 *
 * Buffers are kept by role (opencl.h's B_* slots) until the device is
 * closed: a slot is created, or replaced by a larger one, only when a
 * build or ray batch needs more than it holds, so repeated builds of
 * similar size create no buffer.  Sizes are checked for overflow and
 * against CL_DEVICE_MAX_MEM_ALLOC_SIZE before anything is created.
 *
 * Roles never live at once share one buffer (home_of): the sort's
 * scratch pair is dead once the keys are sorted, the keys once the
 * hierarchy is built, so the collapse sizes (which an LBVH's hierarchy
 * kernel writes while it reads the keys) and the optimise stage's skip
 * marks take the scratch keys' buffer, the optimise stage's crown
 * children the scratch order's, and the bottom-up arrival counters
 * (optimise, collapse, a caller's tree's refit) the keys'; a handle keeps
 * 20 bytes per primitive less and a build touches that much less
 * memory.
 *
 * On a device that shares the host's memory, the geometry and output
 * slots hold instead, for one build, buffers made over the caller's own
 * arrays (atrbvh_i_cl_wrap, CL_MEM_USE_HOST_PTR), released at the build's
 * end (atrbvh_i_cl_unwrap): nothing is copied, and the handle keeps no
 * buffer for them.
 *
 * Every launch records a profiling event; atrbvh_i_cl_finish waits for the
 * queue and adds each launch's device time to the current time table (the
 * build's, for atrbvh_bvh_kernel_time, or a ray batch's).
 */
#include "config.h"

#include "opencl.h"

#include <stdio.h>
#include <string.h>

/* The buffer that holds role `slot`. */
static int home_of(int slot)
{
    switch (slot) {
    case B_COUNTER: /* after the hierarchy */
        return B_KEYS; /* morton to hierarchy */
    case B_NEEDED: /* the optimise stage */
        return B_ORDER_TMP; /* the sort only */
    case B_SIZE: /* from the hierarchy (LBVH) or the collapse on */
    case B_MARKS: /* the optimise stage */
        return B_KEYS_TMP; /* the sort only */
    default:
        return slot;
    }
}

/* Whether one buffer of `bytes` is allowed on the device. */
static atrbvh_status fits(const atrbvh_cl_device *c, size_t bytes,
                          const char *what, atrbvh_error *error)
{
    if ((cl_ulong)bytes <= c->max_alloc)
        return ATRBVH_OK;
    return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, ATRBVH_CL_NO_INDEX,
                         "OpenCL buffer %s of %lu bytes exceeds the "
                         "device's largest allocation "
                         "(CL_DEVICE_MAX_MEM_ALLOC_SIZE %lu)",
                         what, (unsigned long)bytes,
                         (unsigned long)c->max_alloc);
}

/* count x item bytes into *bytes, or an error if that overflows. */
static atrbvh_status size_of(size_t count, size_t item, size_t *bytes,
                             const char *what, atrbvh_error *error)
{
    if (atrbvh_i_mul_size(count, item, bytes))
        return ATRBVH_OK;
    return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, ATRBVH_CL_NO_INDEX,
                         "OpenCL buffer %s: size overflows", what);
}

/* Empties buffer `home` (a home_of slot).  Kernels queued on the buffer
 * keep it alive until they are done (CL reference counting). */
static void drop(atrbvh_cl_device *c, int home)
{
    if (c->buf[home])
        clReleaseMemObject(c->buf[home]);
    c->buf[home] = NULL;
    c->buf_bytes[home] = 0;
    c->wrapped &= ~((uint64_t)1 << home);
}

atrbvh_status atrbvh_i_cl_buffer(atrbvh_cl_device *c, int slot, size_t count,
                                 size_t item, const char *what,
                                 atrbvh_error *error)
{
    size_t bytes;
    cl_int err;
    slot = home_of(slot);
    CL_CHECK(size_of(count ? count : 1, item, &bytes, what, error));
    if (c->buf[slot] && c->buf_bytes[slot] >= bytes)
        return ATRBVH_OK;
    CL_CHECK(fits(c, bytes, what, error));
    drop(c, slot);
    c->buf[slot] = clCreateBuffer(c->ctx, CL_MEM_READ_WRITE, bytes, NULL, &err);
    if (!c->buf[slot])
        return atrbvh_i_cl_error(error, err, "clCreateBuffer", what);
    c->buf_bytes[slot] = bytes;
    c->buffers_created++;
    if (slot == home_of(B_COUNTER))
        c->counters_zero = 0; /* a new buffer holds anything */
    return ATRBVH_OK;
}

void atrbvh_i_cl_buffers_release(atrbvh_cl_device *c)
{
    int k;
    for (k = 0; k < B_SLOTS; k++)
        drop(c, k);
}

/* One write into slot's buffer: blocking (everything queued before it is
 * then done too) or queued (the caller's array must stay untouched until
 * the build's end waits). */
static atrbvh_status upload(atrbvh_cl_device *c, int slot, const void *data,
                            size_t bytes, cl_bool blocking, const char *what,
                            atrbvh_error *error)
{
    cl_int err;
    if (bytes == 0)
        return ATRBVH_OK;
    c->n_writes++;
    if (!blocking)
        c->pending = 1;
    err = clEnqueueWriteBuffer(c->queue, c->buf[home_of(slot)], blocking, 0,
                               bytes, data, 0, NULL, NULL);
    if (err != CL_SUCCESS)
        return atrbvh_i_cl_error(error, err, "clEnqueueWriteBuffer", what);
    if (blocking)
        c->pending = 0;
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cl_upload(atrbvh_cl_device *c, int slot,
                                 const void *data, size_t bytes,
                                 const char *what, atrbvh_error *error)
{
    return upload(c, slot, data, bytes, CL_TRUE, what, error);
}

atrbvh_status atrbvh_i_cl_upload_queued(atrbvh_cl_device *c, int slot,
                                        const void *data, size_t bytes,
                                        const char *what, atrbvh_error *error)
{
    return upload(c, slot, data, bytes, CL_FALSE, what, error);
}

atrbvh_status atrbvh_i_cl_wrap(atrbvh_cl_device *c, int slot,
                               const void *data, size_t bytes,
                               cl_mem_flags access, const char *what,
                               atrbvh_error *error)
{
    cl_int err;
    slot = home_of(slot);
    /* (checked first: a wrap refused for its size leaves the slot's
     * kept buffer for the next build) */
    CL_CHECK(fits(c, bytes, what, error));
    drop(c, slot); /* a kept buffer (or an earlier wrap) goes */
    /* (the cast: OpenCL 1.2 takes a void *; a CL_MEM_READ_ONLY buffer is
     * never written) */
    c->buf[slot] = clCreateBuffer(c->ctx, access | CL_MEM_USE_HOST_PTR,
                                  bytes, (void *)(uintptr_t)data, &err);
    if (!c->buf[slot])
        return atrbvh_i_cl_error(error, err, "clCreateBuffer", what);
    c->buf_bytes[slot] = bytes;
    c->wrapped |= (uint64_t)1 << slot;
    c->n_wraps++;
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cl_input(atrbvh_cl_device *c, int slot,
                                const void *data, size_t bytes,
                                cl_bool blocking, const char *what,
                                atrbvh_error *error)
{
    if (c->host_memory && bytes > 0)
        return atrbvh_i_cl_wrap(c, slot, data, bytes, CL_MEM_READ_ONLY, what,
                                error);
    CL_CHECK(atrbvh_i_cl_buffer(c, slot, bytes, 1, what, error));
    return upload(c, slot, data, bytes, blocking, what, error);
}

atrbvh_status atrbvh_i_cl_output(atrbvh_cl_device *c, int slot, void *data,
                                 size_t count, size_t keep, size_t item,
                                 const char *what, atrbvh_error *error)
{
    size_t bytes;
    if (!c->host_memory || count == 0)
        return atrbvh_i_cl_buffer(c, slot, keep, item, what, error);
    CL_CHECK(size_of(count, item, &bytes, what, error));
    return atrbvh_i_cl_wrap(c, slot, data, bytes, CL_MEM_WRITE_ONLY, what,
                            error);
}

void atrbvh_i_cl_unwrap(atrbvh_cl_device *c)
{
    int k;
    for (k = 0; k < B_SLOTS && c->wrapped; k++)
        if (c->wrapped & ((uint64_t)1 << k))
            drop(c, k);
}

atrbvh_status atrbvh_i_cl_sync(atrbvh_cl_device *c, atrbvh_error *error)
{
    if (c->buf[B_SYNC])
        return ATRBVH_OK;
    atrbvh_status st;
    CL_CHECK(atrbvh_i_cl_buffer(c, B_SYNC, 1, sizeof(cl_uint), "launch sync",
                                error));
    st = atrbvh_i_cl_zero(c, B_SYNC, sizeof(cl_uint), "launch sync", error);
    if (st != ATRBVH_OK) { /* not known zero: made again next time */
        clReleaseMemObject(c->buf[B_SYNC]);
        c->buf[B_SYNC] = NULL;
        c->buf_bytes[B_SYNC] = 0;
    }
    return st;
}

/* One read from slot's buffer: blocking (everything queued before it is
 * then done too) or queued. */
static atrbvh_status download(atrbvh_cl_device *c, int slot, void *data,
                              size_t bytes, cl_bool blocking,
                              const char *what, atrbvh_error *error)
{
    cl_int err;
    if (bytes == 0)
        return ATRBVH_OK;
    if (blocking)
        c->n_reads++;
    else
        c->n_queued_reads++;
    c->pending = 1;
    err = clEnqueueReadBuffer(c->queue, c->buf[home_of(slot)], blocking, 0,
                              bytes, data, 0, NULL, NULL);
    if (err != CL_SUCCESS)
        return atrbvh_i_cl_error(error, err, "clEnqueueReadBuffer", what);
    if (blocking)
        c->pending = 0;
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cl_download(atrbvh_cl_device *c, int slot, void *data,
                                   size_t bytes, const char *what,
                                   atrbvh_error *error)
{
    return download(c, slot, data, bytes, CL_TRUE, what, error);
}

atrbvh_status atrbvh_i_cl_download_queued(atrbvh_cl_device *c, int slot,
                                          void *data, size_t bytes,
                                          const char *what,
                                          atrbvh_error *error)
{
    return download(c, slot, data, bytes, CL_FALSE, what, error);
}

atrbvh_status atrbvh_i_cl_zero(atrbvh_cl_device *c, int slot, size_t bytes,
                               const char *what, atrbvh_error *error)
{
    cl_uint z = 0;
    cl_int err;
    if (bytes == 0)
        return ATRBVH_OK;
    c->n_fills++;
    c->pending = 1;
    err = clEnqueueFillBuffer(c->queue, c->buf[home_of(slot)], &z, sizeof z, 0, bytes,
                              0, NULL, NULL);
    if (err != CL_SUCCESS)
        return atrbvh_i_cl_error(error, err, "clEnqueueFillBuffer", what);
    return ATRBVH_OK;
}

static void add_time(atrbvh_cl_times *t, const char *name, double ms)
{
    unsigned i;
    for (i = 0; i < t->count; i++)
        if (strcmp(t->name[i], name) == 0)
            break;
    if (i == t->count) {
        if (i == ATRBVH_CL_MAX_TIMES)
            return;
        t->name[i] = name;
        t->ms[i] = 0.0;
        t->count++;
    }
    t->ms[i] += ms;
}

void atrbvh_i_cl_drop_events(atrbvh_cl_device *c)
{
    int k;
    for (k = 0; k < c->event_count; k++)
        clReleaseEvent(c->events[k]);
    c->event_count = 0;
}

/* The device times of the recorded launches, all finished. */
static void add_times(atrbvh_cl_device *c)
{
    int k;
    for (k = 0; k < c->event_count; k++) {
        cl_ulong a = 0, b = 0;
        if (clGetEventProfilingInfo(c->events[k], CL_PROFILING_COMMAND_START,
                                    sizeof a, &a, NULL) != CL_SUCCESS ||
            clGetEventProfilingInfo(c->events[k], CL_PROFILING_COMMAND_END,
                                    sizeof b, &b, NULL) != CL_SUCCESS)
            a = b = 0;
        add_time(c->times, atrbvh_i_cl_kernel_names[c->event_kernel[k]],
                 b > a ? (double)(b - a) * 1e-6 : 0.0);
    }
    atrbvh_i_cl_drop_events(c);
}

atrbvh_status atrbvh_i_cl_finish(atrbvh_cl_device *c, atrbvh_error *error)
{
    cl_int err;
    c->n_finishes++;
    c->pending = 0;
    err = clFinish(c->queue);
    if (err != CL_SUCCESS) {
        /* The failed wait may have returned with commands still running
         * (a kernel writing the caller's hits, a copy reading their
         * geometry), and the caller may free those arrays as soon as this
         * call returns: wait once more.  When that wait fails too, the
         * queue's state is unknown: the handle is lost. */
        const cl_int again = clFinish(c->queue);
        if (again != CL_SUCCESS) {
            c->lost = err;
            c->lost_again = again;
        }
        atrbvh_i_cl_drop_events(c);
        return atrbvh_i_cl_error(error, err, "clFinish", NULL);
    }
    add_times(c);
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cl_usable(const atrbvh_cl_device *c,
                                 atrbvh_error *error)
{
    if (!c->lost)
        return ATRBVH_OK;
    return atrbvh_i_fail(
        error, ATRBVH_ERR_BACKEND, ATRBVH_CL_NO_INDEX,
        "OpenCL: device lost: an earlier wait for its queue failed with "
        "%s (%d) and the wait after it with %s (%d), so commands may "
        "still be running; close the device and open it again",
        atrbvh_i_cl_code_name(c->lost), (int)c->lost,
        atrbvh_i_cl_code_name(c->lost_again), (int)c->lost_again);
}

atrbvh_status atrbvh_i_cl_collect(atrbvh_cl_device *c, atrbvh_error *error)
{
    if (c->pending)
        return atrbvh_i_cl_finish(c, error);
    add_times(c);
    return ATRBVH_OK;
}

/* Launches kernel k over `items` work-items (every kernel checks its
 * range, so the global size may round up).
 *
 * Work-group sizes: a launch of few items (the per-block kernels: bounds,
 * morton, the sort's count and scatter, hierarchy, layout; a few hundred
 * items or less, each working through a block) gets small explicit
 * groups, at least 8 per compute unit: left to choose, PoCL put such a
 * launch of 64 items into one group, i.e. on one thread.  The ray
 * kernels get 64 (see below); the rest is the implementation's choice,
 * with the global size a multiple of 64. */
static atrbvh_status launch(atrbvh_cl_device *c, int k, size_t items,
                            atrbvh_error *error)
{
    const size_t groups = 8u * (size_t)c->compute_units;
    size_t global = (items + 63u) / 64u * 64u, local = 0;
    cl_event ev = NULL;
    cl_int err;
    if (c->event_count == ATRBVH_CL_MAX_EVENTS) {
        atrbvh_status st = atrbvh_i_cl_finish(c, error);
        if (st != ATRBVH_OK)
            return st;
    }
    if (k == K_INTERSECT_CLOSEST || k == K_INTERSECT_ANY) {
        /* Left to itself PoCL picks groups of 4096 for a large launch and
         * runs out of stack with the traversal's private arrays (2 KB per
         * item): 64, or the largest power of two the kernel allows below
         * it (global is a multiple of 64, so it divides it). */
        local = 64;
        while (local > c->kernel_wg[k])
            local /= 2;
    } else if (items < 64u * groups || k == K_SORT_BUCKETS) {
        /* the largest power of two up to 64 giving `groups` groups (and
         * for sort_buckets at any size: 4.6 KB of private arrays per
         * item, the stack's risk above) */
        local = 64;
        while (local > 1u && (items + local - 1u) / local < groups)
            local /= 2;
        while (local > c->kernel_wg[k])
            local /= 2;
        global = (items + local - 1u) / local * local;
    }
    c->n_launches++;
    c->pending = 1;
    err = clEnqueueNDRangeKernel(c->queue, c->kernel[k], 1, NULL, &global,
                                 local ? &local : NULL, 0, NULL, &ev);
    if (err != CL_SUCCESS)
        return atrbvh_i_cl_error(error, err, "clEnqueueNDRangeKernel",
                                 atrbvh_i_cl_kernel_names[k]);
    c->events[c->event_count] = ev;
    c->event_kernel[c->event_count++] = k;
    return ATRBVH_OK;
}

atrbvh_status atrbvh_i_cl_run(atrbvh_cl_device *c, int k, size_t items,
                              const atrbvh_cl_arg *args, int count,
                              atrbvh_error *error)
{
    int i;
    if (items == 0)
        return ATRBVH_OK;
    for (i = 0; i < count; i++) {
        cl_int err;
        if (args[i].slot >= 0)
            err = clSetKernelArg(c->kernel[k], (cl_uint)i, sizeof(cl_mem),
                                 &c->buf[home_of(args[i].slot)]);
        else
            err = clSetKernelArg(c->kernel[k], (cl_uint)i, args[i].size,
                                 args[i].value);
        if (err != CL_SUCCESS) {
            char what[64];
            snprintf(what, sizeof what, "%s argument %d",
                     atrbvh_i_cl_kernel_names[k], i);
            return atrbvh_i_cl_error(error, err, "clSetKernelArg", what);
        }
    }
    return launch(c, k, items, error);
}
