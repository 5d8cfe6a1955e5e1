/*
 * cl/backend.c - the OpenCL backend: device choice, program build, buffers,
 * and the pipeline, one kernel (or a short fixed sequence) per stage with
 * the CPU's stage names (cl/kernels.cl).  OpenCL 1.2 through the ICD
 * loader.
 *
 * Every CL object is recorded in a cl_env and released on every path;
 * every CL call's failure becomes an atrbvh_error naming the call and the
 * error code.  Buffer sizes are checked against CL_DEVICE_MAX_MEM_ALLOC_SIZE
 * before they are created.
 */
#include "config.h"

#include "backend.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kernels_embedded.h"

#define NO_INDEX ((uint64_t)-1)

/* ------------------------------------------------------------- kernels */
enum {
    K_BOUNDS_TRIANGLES,
    K_BOUNDS_BOXES,
    K_BOUNDS_REDUCE,
    K_MORTON,
    K_SORT_COUNT,
    K_SORT_SCAN,
    K_SORT_SCATTER,
    K_HIERARCHY,
    K_REFIT,
    K_OPT_PREPARE,
    K_OPT_ROUND,
    K_COLLAPSE,
    K_LAYOUT,
    K_INTERSECT_CLOSEST,
    K_INTERSECT_ANY,
    K_COUNT
};

static const char *const kernel_names[K_COUNT] = {
    "bounds_triangles", "bounds_boxes", "bounds_reduce", "morton",
    "sort_count",       "sort_scan",    "sort_scatter",  "hierarchy",
    "refit",            "opt_prepare",  "opt_round",     "collapse",
    "layout",           "intersect_closest", "intersect_any"};

#define MAX_EVENTS 256
#define MAX_BUFFERS 40

/* ------------------------------------------------------------ the env */
typedef struct cl_env {
    cl_device_id device;
    cl_context ctx;
    cl_command_queue queue;
    cl_program program;
    cl_kernel kernel[K_COUNT];
    cl_mem buffers[MAX_BUFFERS];
    int buffer_count;
    cl_event events[MAX_EVENTS];
    const char *event_name[MAX_EVENTS];
    int event_count;
    char device_name[128];
    cl_ulong max_alloc;
    cl_uint compute_units;
    /* per-kernel device times, filled from the events */
    unsigned time_count;
    const char *time_name[ATRBVH_MAX_KERNEL_TIMES];
    double time_ms[ATRBVH_MAX_KERNEL_TIMES];
} cl_env;

const char *atrbvh_i_cl_error_name(cl_int err)
{
    switch (err) {
#define E(x) \
    case x:  \
        return #x;
        E(CL_SUCCESS)
        E(CL_DEVICE_NOT_FOUND)
        E(CL_DEVICE_NOT_AVAILABLE)
        E(CL_COMPILER_NOT_AVAILABLE)
        E(CL_MEM_OBJECT_ALLOCATION_FAILURE)
        E(CL_OUT_OF_RESOURCES)
        E(CL_OUT_OF_HOST_MEMORY)
        E(CL_PROFILING_INFO_NOT_AVAILABLE)
        E(CL_MEM_COPY_OVERLAP)
        E(CL_IMAGE_FORMAT_MISMATCH)
        E(CL_IMAGE_FORMAT_NOT_SUPPORTED)
        E(CL_BUILD_PROGRAM_FAILURE)
        E(CL_MAP_FAILURE)
        E(CL_MISALIGNED_SUB_BUFFER_OFFSET)
        E(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST)
        E(CL_COMPILE_PROGRAM_FAILURE)
        E(CL_LINKER_NOT_AVAILABLE)
        E(CL_LINK_PROGRAM_FAILURE)
        E(CL_DEVICE_PARTITION_FAILED)
        E(CL_KERNEL_ARG_INFO_NOT_AVAILABLE)
        E(CL_INVALID_VALUE)
        E(CL_INVALID_DEVICE_TYPE)
        E(CL_INVALID_PLATFORM)
        E(CL_INVALID_DEVICE)
        E(CL_INVALID_CONTEXT)
        E(CL_INVALID_QUEUE_PROPERTIES)
        E(CL_INVALID_COMMAND_QUEUE)
        E(CL_INVALID_HOST_PTR)
        E(CL_INVALID_MEM_OBJECT)
        E(CL_INVALID_IMAGE_FORMAT_DESCRIPTOR)
        E(CL_INVALID_IMAGE_SIZE)
        E(CL_INVALID_SAMPLER)
        E(CL_INVALID_BINARY)
        E(CL_INVALID_BUILD_OPTIONS)
        E(CL_INVALID_PROGRAM)
        E(CL_INVALID_PROGRAM_EXECUTABLE)
        E(CL_INVALID_KERNEL_NAME)
        E(CL_INVALID_KERNEL_DEFINITION)
        E(CL_INVALID_KERNEL)
        E(CL_INVALID_ARG_INDEX)
        E(CL_INVALID_ARG_VALUE)
        E(CL_INVALID_ARG_SIZE)
        E(CL_INVALID_KERNEL_ARGS)
        E(CL_INVALID_WORK_DIMENSION)
        E(CL_INVALID_WORK_GROUP_SIZE)
        E(CL_INVALID_WORK_ITEM_SIZE)
        E(CL_INVALID_GLOBAL_OFFSET)
        E(CL_INVALID_EVENT_WAIT_LIST)
        E(CL_INVALID_EVENT)
        E(CL_INVALID_OPERATION)
        E(CL_INVALID_GL_OBJECT)
        E(CL_INVALID_BUFFER_SIZE)
        E(CL_INVALID_MIP_LEVEL)
        E(CL_INVALID_GLOBAL_WORK_SIZE)
        E(CL_INVALID_PROPERTY)
        E(CL_INVALID_IMAGE_DESCRIPTOR)
        E(CL_INVALID_COMPILER_OPTIONS)
        E(CL_INVALID_LINKER_OPTIONS)
        E(CL_INVALID_DEVICE_PARTITION_COUNT)
#undef E
    case -1001:
        return "CL_PLATFORM_NOT_FOUND_KHR";
    default:
        return "unknown OpenCL error";
    }
}

atrbvh_status atrbvh_i_cl_fail(atrbvh_error *error, cl_int err,
                               const char *call, const char *what)
{
    atrbvh_status st = ATRBVH_ERR_BACKEND;
    if (err == CL_OUT_OF_HOST_MEMORY || err == CL_MEM_OBJECT_ALLOCATION_FAILURE)
        st = ATRBVH_ERR_NOMEM;
    return atrbvh_i_fail(error, st, NO_INDEX, "OpenCL: %s failed%s%s: %s (%d)",
                         call, what ? " for " : "", what ? what : "",
                         atrbvh_i_cl_error_name(err), (int)err);
}

#define CL_TRY(call_expr, name, what)                                          \
    do {                                                                       \
        cl_int e_ = (call_expr);                                               \
        if (e_ != CL_SUCCESS)                                                  \
            return atrbvh_i_cl_fail(error, e_, name, what);                    \
    } while (0)

static void env_release(cl_env *env)
{
    int k;
    for (k = 0; k < env->event_count; k++)
        clReleaseEvent(env->events[k]);
    env->event_count = 0;
    for (k = 0; k < env->buffer_count; k++)
        if (env->buffers[k])
            clReleaseMemObject(env->buffers[k]);
    env->buffer_count = 0;
    for (k = 0; k < K_COUNT; k++)
        if (env->kernel[k])
            clReleaseKernel(env->kernel[k]);
    if (env->program)
        clReleaseProgram(env->program);
    if (env->queue)
        clReleaseCommandQueue(env->queue);
    if (env->ctx)
        clReleaseContext(env->ctx);
    memset(env, 0, sizeof *env);
}

/* ------------------------------------------------------ device choice */
static void device_name(cl_device_id d, char *buf, size_t size)
{
    buf[0] = '\0';
    if (clGetDeviceInfo(d, CL_DEVICE_NAME, size, buf, NULL) != CL_SUCCESS)
        snprintf(buf, size, "(unnamed)");
    buf[size - 1] = '\0';
}

static int parse_index_pair(const char *s, unsigned *p, unsigned *d)
{
    char *end;
    unsigned long a, b;
    if (*s < '0' || *s > '9')
        return 0;
    a = strtoul(s, &end, 10);
    if (*end != ':' || end[1] < '0' || end[1] > '9')
        return 0;
    b = strtoul(end + 1, &end, 10);
    if (*end != '\0' || a > 1000 || b > 1000)
        return 0;
    *p = (unsigned)a;
    *d = (unsigned)b;
    return 1;
}

/* Case-sensitive substring (device names are as the driver spells them). */
static int contains(const char *hay, const char *needle)
{
    return strstr(hay, needle) != NULL;
}

#define MAX_PLATFORMS 16
#define MAX_DEVICES 64

/* Picks the device: spec (options.opencl_device, else
 * $ATRBVH_OPENCL_DEVICE) "P:D" by indices, or the first device whose name
 * contains spec; with no spec the first device of the first platform that
 * has one. */
atrbvh_status atrbvh_i_cl_select(const char *spec, cl_device_id *out,
                                 char *name, size_t name_size,
                                 atrbvh_error *error)
{
    cl_platform_id platforms[MAX_PLATFORMS];
    cl_uint np = 0, p;
    unsigned want_p = 0, want_d = 0;
    int by_index = 0;
    char list[160];
    size_t used = 0;
    cl_int err;

    if (!spec || !*spec)
        spec = getenv("ATRBVH_OPENCL_DEVICE");
    if (spec && !*spec)
        spec = NULL;
    if (spec)
        by_index = parse_index_pair(spec, &want_p, &want_d);
    err = clGetPlatformIDs(MAX_PLATFORMS, platforms, &np);
    if (err == -1001 /* CL_PLATFORM_NOT_FOUND_KHR */ || (err == CL_SUCCESS && np == 0))
        return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, NO_INDEX,
                             "OpenCL: no platform found (is an ICD such as "
                             "pocl-opencl-icd installed?)");
    if (err != CL_SUCCESS)
        return atrbvh_i_cl_fail(error, err, "clGetPlatformIDs", NULL);
    if (np > MAX_PLATFORMS)
        np = MAX_PLATFORMS;
    list[0] = '\0';
    for (p = 0; p < np; p++) {
        cl_device_id devs[MAX_DEVICES];
        cl_uint nd = 0, d;
        err = clGetDeviceIDs(platforms[p], CL_DEVICE_TYPE_ALL, MAX_DEVICES, devs,
                             &nd);
        if (err == CL_DEVICE_NOT_FOUND)
            continue;
        if (err != CL_SUCCESS)
            return atrbvh_i_cl_fail(error, err, "clGetDeviceIDs", NULL);
        if (nd > MAX_DEVICES)
            nd = MAX_DEVICES;
        for (d = 0; d < nd; d++) {
            char dn[128];
            int match;
            device_name(devs[d], dn, sizeof dn);
            if (used + 1 < sizeof list) {
                int w = snprintf(list + used, sizeof list - used, "%s%u:%u %s",
                                 used ? "; " : "", p, d, dn);
                used = w < 0 ? sizeof list : used + (size_t)w;
                if (used >= sizeof list)
                    used = sizeof list - 1;
            }
            if (!spec)
                match = 1;
            else if (by_index)
                match = p == want_p && d == want_d;
            else
                match = contains(dn, spec);
            if (match) {
                *out = devs[d];
                snprintf(name, name_size, "%s", dn);
                return ATRBVH_OK;
            }
        }
    }
    if (!spec)
        return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, NO_INDEX,
                             "OpenCL: no device found on %u platform%s",
                             (unsigned)np, np == 1 ? "" : "s");
    return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                         "OpenCL: no device matches \"%.40s\" (want "
                         "PLATFORM:DEVICE or a name substring; devices: %s)",
                         spec, list[0] ? list : "none");
}

/* ------------------------------------------------------------- sources */
/* The kernel source: the embedded files in order, each overridden by the
 * file of the same name in the first folder of $ATRBVH_CL_SOURCE_DIR
 * (colon-separated) that has it; `#include "` lines are blanked (the
 * files are concatenated) and `#line` directives keep the compiler log's
 * file names and lines right. */
static char *read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long size;
    if (!f)
        return NULL;
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 ||
        fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return NULL;
    }
    buf = atrbvh_i_malloc((size_t)size + 1);
    if (!buf) {
        fclose(f);
        return NULL;
    }
    if (fread(buf, 1, (size_t)size, f) != (size_t)size) {
        atrbvh_i_free(buf);
        fclose(f);
        return NULL;
    }
    fclose(f);
    buf[size] = '\0';
    *len = (size_t)size;
    return buf;
}

static char *dev_override(const char *name, size_t *len)
{
    const char *dirs = getenv("ATRBVH_CL_SOURCE_DIR");
    char path[1024];
    while (dirs && *dirs) {
        const char *colon = strchr(dirs, ':');
        size_t dl = colon ? (size_t)(colon - dirs) : strlen(dirs);
        if (dl > 0 && dl < 900) {
            char *text;
            snprintf(path, sizeof path, "%.*s/%s", (int)dl, dirs, name);
            text = read_file(path, len);
            if (text)
                return text;
        }
        dirs = colon ? colon + 1 : NULL;
    }
    return NULL;
}

static char *kernel_source(void)
{
    char *parts[ATRBVH_CL_FILE_COUNT];
    size_t lens[ATRBVH_CL_FILE_COUNT], total = 1;
    char *src = NULL, *o;
    int k;
    for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++) {
        parts[k] = dev_override(atrbvh_cl_files[k].name, &lens[k]);
        if (!parts[k])
            lens[k] = atrbvh_cl_files[k].length;
        total += lens[k] + 64;
    }
    src = atrbvh_i_malloc(total);
    if (src) {
        o = src;
        for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++) {
            const char *t = parts[k] ? parts[k]
                                     : (const char *)atrbvh_cl_files[k].text;
            size_t i = 0;
            o += sprintf(o, "#line 1 \"%.40s\"\n", atrbvh_cl_files[k].name);
            while (i < lens[k]) {
                const char *line = t + i;
                size_t j = i;
                while (j < lens[k] && t[j] != '\n')
                    j++;
                if (j < lens[k])
                    j++; /* the newline */
                if (strncmp(line, "#include \"", 10) == 0) {
                    *o++ = '\n';
                } else {
                    memcpy(o, line, j - i);
                    o += j - i;
                }
                i = j;
            }
            *o++ = '\n';
        }
        *o = '\0';
    }
    for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++)
        atrbvh_i_free(parts[k]);
    return src;
}

/* The compiler log, on one line, as much as fits the error text. */
static atrbvh_status build_failed(cl_env *env, cl_int err, atrbvh_error *error)
{
    char log[4096];
    size_t got = 0, k;
    log[0] = '\0';
    if (clGetProgramBuildInfo(env->program, env->device, CL_PROGRAM_BUILD_LOG,
                              sizeof log - 1, log, &got) != CL_SUCCESS) {
        /* A log longer than the buffer: ask for its start only. */
        snprintf(log, sizeof log, "(no build log)");
    }
    log[sizeof log - 1] = '\0';
    for (k = 0; log[k]; k++)
        if (log[k] == '\n' || log[k] == '\r' || log[k] == '\t')
            log[k] = ' ';
    return atrbvh_i_fail(error, ATRBVH_ERR_BACKEND, NO_INDEX,
                         "OpenCL kernel build failed (%s): %s",
                         atrbvh_i_cl_error_name(err), log);
}

/* Context, queue (profiling), program, kernels. */
static atrbvh_status env_open(cl_env *env, const char *spec,
                              atrbvh_error *error)
{
    char ext[8192];
    char *src;
    const char *srcs[1];
    cl_int err;
    size_t len;
    int k;
    atrbvh_status st;

    st = atrbvh_i_cl_select(spec, &env->device, env->device_name,
                            sizeof env->device_name, error);
    if (st != ATRBVH_OK)
        return st;
    ext[0] = '\0';
    CL_TRY(clGetDeviceInfo(env->device, CL_DEVICE_EXTENSIONS, sizeof ext, ext,
                           NULL),
           "clGetDeviceInfo", "CL_DEVICE_EXTENSIONS");
    ext[sizeof ext - 1] = '\0';
    if (!strstr(ext, "cl_khr_fp64"))
        return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, NO_INDEX,
                             "OpenCL device \"%s\" lacks cl_khr_fp64: atrbvh "
                             "computes areas and costs in double precision",
                             env->device_name);
    CL_TRY(clGetDeviceInfo(env->device, CL_DEVICE_MAX_MEM_ALLOC_SIZE,
                           sizeof env->max_alloc, &env->max_alloc, NULL),
           "clGetDeviceInfo", "CL_DEVICE_MAX_MEM_ALLOC_SIZE");
    CL_TRY(clGetDeviceInfo(env->device, CL_DEVICE_MAX_COMPUTE_UNITS,
                           sizeof env->compute_units, &env->compute_units,
                           NULL),
           "clGetDeviceInfo", "CL_DEVICE_MAX_COMPUTE_UNITS");
    env->ctx = clCreateContext(NULL, 1, &env->device, NULL, NULL, &err);
    if (!env->ctx)
        return atrbvh_i_cl_fail(error, err, "clCreateContext", NULL);
    env->queue = clCreateCommandQueue(env->ctx, env->device,
                                      CL_QUEUE_PROFILING_ENABLE, &err);
    if (!env->queue)
        return atrbvh_i_cl_fail(error, err, "clCreateCommandQueue", NULL);
    src = kernel_source();
    if (!src)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate the OpenCL kernel source");
    srcs[0] = src;
    len = strlen(src);
    env->program = clCreateProgramWithSource(env->ctx, 1, srcs, &len, &err);
    atrbvh_i_free(src);
    if (!env->program)
        return atrbvh_i_cl_fail(error, err, "clCreateProgramWithSource", NULL);
    /* No -cl-fast-relaxed-math, no -cl-mad-enable: bit-for-bit with C. */
    err = clBuildProgram(env->program, 1, &env->device, "-cl-std=CL1.2", NULL,
                         NULL);
    if (err != CL_SUCCESS)
        return build_failed(env, err, error);
    for (k = 0; k < K_COUNT; k++) {
        env->kernel[k] = clCreateKernel(env->program, kernel_names[k], &err);
        if (!env->kernel[k])
            return atrbvh_i_cl_fail(error, err, "clCreateKernel",
                                    kernel_names[k]);
    }
    return ATRBVH_OK;
}

/* ------------------------------------------------------------- buffers */
static atrbvh_status buffer(cl_env *env, size_t count, size_t item,
                            const char *what, cl_mem *out, atrbvh_error *error)
{
    size_t bytes;
    cl_int err;
    *out = NULL;
    if (!atrbvh_i_mul_size(count ? count : 1, item, &bytes))
        return atrbvh_i_fail(error, ATRBVH_ERR_TOO_LARGE, NO_INDEX,
                             "OpenCL buffer %s: size overflows", what);
    if ((cl_ulong)bytes > env->max_alloc)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "OpenCL buffer %s of %lu bytes exceeds the "
                             "device's largest allocation "
                             "(CL_DEVICE_MAX_MEM_ALLOC_SIZE %lu)",
                             what, (unsigned long)bytes,
                             (unsigned long)env->max_alloc);
    if (env->buffer_count == MAX_BUFFERS)
        return atrbvh_i_fail(error, ATRBVH_ERR_BACKEND, NO_INDEX,
                             "OpenCL: too many buffers (internal)");
    *out = clCreateBuffer(env->ctx, CL_MEM_READ_WRITE, bytes, NULL, &err);
    if (!*out)
        return atrbvh_i_cl_fail(error, err, "clCreateBuffer", what);
    env->buffers[env->buffer_count++] = *out;
    return ATRBVH_OK;
}

static void buffer_drop(cl_env *env, cl_mem *b)
{
    int k;
    if (!*b)
        return;
    for (k = 0; k < env->buffer_count; k++)
        if (env->buffers[k] == *b) {
            clReleaseMemObject(*b);
            env->buffers[k] = env->buffers[--env->buffer_count];
            break;
        }
    *b = NULL;
}

static atrbvh_status upload(cl_env *env, cl_mem b, const void *data,
                            size_t bytes, const char *what, atrbvh_error *error)
{
    if (bytes == 0)
        return ATRBVH_OK;
    CL_TRY(clEnqueueWriteBuffer(env->queue, b, CL_TRUE, 0, bytes, data, 0,
                                NULL, NULL),
           "clEnqueueWriteBuffer", what);
    return ATRBVH_OK;
}

static atrbvh_status download(cl_env *env, cl_mem b, void *data, size_t bytes,
                              const char *what, atrbvh_error *error)
{
    if (bytes == 0)
        return ATRBVH_OK;
    CL_TRY(clEnqueueReadBuffer(env->queue, b, CL_TRUE, 0, bytes, data, 0, NULL,
                               NULL),
           "clEnqueueReadBuffer", what);
    return ATRBVH_OK;
}

static atrbvh_status zero(cl_env *env, cl_mem b, size_t bytes,
                          const char *what, atrbvh_error *error)
{
    cl_uint z = 0;
    CL_TRY(clEnqueueFillBuffer(env->queue, b, &z, sizeof z, 0, bytes, 0, NULL,
                               NULL),
           "clEnqueueFillBuffer", what);
    return ATRBVH_OK;
}

/* --------------------------------------------------------------- launch */
static atrbvh_status harvest(cl_env *env, atrbvh_error *error)
{
    int k;
    CL_TRY(clFinish(env->queue), "clFinish", NULL);
    for (k = 0; k < env->event_count; k++) {
        cl_ulong a = 0, b = 0;
        unsigned i;
        double ms;
        if (clGetEventProfilingInfo(env->events[k], CL_PROFILING_COMMAND_START,
                                    sizeof a, &a, NULL) != CL_SUCCESS ||
            clGetEventProfilingInfo(env->events[k], CL_PROFILING_COMMAND_END,
                                    sizeof b, &b, NULL) != CL_SUCCESS)
            a = b = 0;
        ms = b > a ? (double)(b - a) * 1e-6 : 0.0;
        for (i = 0; i < env->time_count; i++)
            if (strcmp(env->time_name[i], env->event_name[k]) == 0)
                break;
        if (i == env->time_count && i < ATRBVH_MAX_KERNEL_TIMES) {
            env->time_name[i] = env->event_name[k];
            env->time_ms[i] = 0.0;
            env->time_count++;
        }
        if (i < env->time_count)
            env->time_ms[i] += ms;
        clReleaseEvent(env->events[k]);
    }
    env->event_count = 0;
    return ATRBVH_OK;
}

/* Launches kernel k over `items` work-items (rounded up to a multiple of
 * 64; every kernel checks its range); the work-group size is the
 * implementation's choice except for the ray kernels. */
static atrbvh_status launch(cl_env *env, int k, size_t items,
                            atrbvh_error *error)
{
    size_t global = (items + 63u) / 64u * 64u, local = 0;
    cl_event ev = NULL;
    cl_int err;
    atrbvh_status st;
    if (items == 0)
        return ATRBVH_OK;
    if (env->event_count == MAX_EVENTS) {
        st = harvest(env, error);
        if (st != ATRBVH_OK)
            return st;
    }
    if (k == K_INTERSECT_CLOSEST || k == K_INTERSECT_ANY) {
        /* An explicit work-group size: left to itself PoCL picks groups
         * of 4096 for a large launch and runs out of stack with the
         * traversal's private arrays (2 KB per item).  64, or the largest
         * power of two the kernel allows below it (global is a multiple
         * of 64, so it divides it). */
        size_t max_wg = 0;
        local = 64;
        if (clGetKernelWorkGroupInfo(env->kernel[k], env->device,
                                     CL_KERNEL_WORK_GROUP_SIZE, sizeof max_wg,
                                     &max_wg, NULL) == CL_SUCCESS &&
            max_wg > 0)
            while (local > max_wg)
                local /= 2;
    }
    err = clEnqueueNDRangeKernel(env->queue, env->kernel[k], 1, NULL, &global,
                                 local ? &local : NULL, 0, NULL, &ev);
    if (err != CL_SUCCESS)
        return atrbvh_i_cl_fail(error, err, "clEnqueueNDRangeKernel",
                                kernel_names[k]);
    env->events[env->event_count] = ev;
    env->event_name[env->event_count++] = kernel_names[k];
    return ATRBVH_OK;
}

/* Kernel arguments: a list of (size, pointer) set in order. */
typedef struct karg {
    size_t size;
    const void *ptr;
} karg;

static atrbvh_status set_args(cl_env *env, int k, const karg *a, int count,
                              atrbvh_error *error)
{
    int i;
    for (i = 0; i < count; i++) {
        cl_int err = clSetKernelArg(env->kernel[k], (cl_uint)i, a[i].size,
                                    a[i].ptr);
        if (err != CL_SUCCESS) {
            char what[64];
            snprintf(what, sizeof what, "%s argument %d", kernel_names[k], i);
            return atrbvh_i_cl_fail(error, err, "clSetKernelArg", what);
        }
    }
    return ATRBVH_OK;
}

#define A(x) {sizeof(x), &(x)}
#define RUN(k, items, ...)                                                     \
    do {                                                                       \
        const karg args_[] = {__VA_ARGS__};                                    \
        st = set_args(&env, k, args_, (int)(sizeof args_ / sizeof args_[0]),   \
                      error);                                                  \
        if (st == ATRBVH_OK)                                                   \
            st = launch(&env, k, items, error);                                \
        if (st != ATRBVH_OK)                                                   \
            goto done;                                                         \
    } while (0)
#define CHECK(expr)                                                            \
    do {                                                                       \
        st = (expr);                                                           \
        if (st != ATRBVH_OK)                                                   \
            goto done;                                                         \
    } while (0)

/* Ends a stage: waits, collects kernel times, records the wall time. */
static atrbvh_status stage_end(cl_env *env, double *ms, double *t,
                               atrbvh_error *error)
{
    atrbvh_status st = harvest(env, error);
    double now = atrbvh_i_now_ms();
    *ms += now - *t;
    *t = now;
    return st;
}

/* Reads the tree arrays back into a new host tree (the capture). */
static atrbvh_status read_tree(cl_env *env, uint32_t n, cl_mem left,
                               cl_mem right, cl_mem parent, cl_mem count,
                               cl_mem box, cl_mem cost, cl_mem leaf_prim,
                               int values, atrbvh_i_tree *out,
                               atrbvh_error *error)
{
    size_t nodes = 2 * (size_t)n - 1, inner = n > 1 ? (size_t)n - 1 : 0;
    atrbvh_status st;
    if (atrbvh_i_tree_alloc(out, n) != ATRBVH_OK)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate the capture");
    st = download(env, left, out->left, inner * 4, "left", error);
    if (st == ATRBVH_OK)
        st = download(env, right, out->right, inner * 4, "right", error);
    if (st == ATRBVH_OK)
        st = download(env, parent, out->parent, nodes * 4, "parent", error);
    if (st == ATRBVH_OK)
        st = download(env, count, out->count, nodes * 4, "count", error);
    if (st == ATRBVH_OK)
        st = download(env, leaf_prim, out->leaf_prim, (size_t)n * 4,
                      "leaf_prim", error);
    if (st == ATRBVH_OK && values)
        st = download(env, box, out->box, nodes * sizeof(atrbvh_box), "box",
                      error);
    if (st == ATRBVH_OK && values)
        st = download(env, cost, out->cost, nodes * sizeof(double), "cost",
                      error);
    return st;
}

#define ALIGN64(x) (((x) + 63u) & ~(size_t)63u)

/* ------------------------------------------------------------ the build */
atrbvh_status atrbvh_i_cl_build(const atrbvh_geometry *g,
                                const atrbvh_i_config *cfg, atrbvh_bvh **out,
                                atrbvh_i_capture *cap, atrbvh_error *error)
{
    cl_env env;
    atrbvh_status st;
    atrbvh_i_prims prims;
    atrbvh_bvh *bvh = NULL;
    double ms[ATRBVH_STAGE_COUNT], t0, t;
    size_t vstride = 0, istride = 0, bstride = 0;
    cl_mem geo = NULL, geo_idx = NULL, boxes = NULL, problems = NULL,
           partial = NULL, keys = NULL, keys_tmp = NULL, order = NULL,
           order_tmp = NULL, hist = NULL, ids = NULL, left = NULL,
           right = NULL, parent = NULL, count = NULL, box = NULL, cost = NULL,
           leaf_prim = NULL, counter = NULL, needed = NULL, list = NULL,
           list_count = NULL, scratch = NULL, size = NULL, out_nodes = NULL,
           out_prims = NULL;
    cl_uint n = 0, u, has_ids = 0;
    size_t nodes, inner;
    double ci = cfg->cost.ci, ct = cfg->cost.ct;
    cl_int collapse = cfg->cost.collapse;
    cl_uint max_leaf = cfg->cost.max_leaf;
    unsigned k;

    memset(&env, 0, sizeof env);
    memset(&prims, 0, sizeof prims);
    memset(ms, 0, sizeof ms);
    t0 = atrbvh_i_now_ms();
    st = atrbvh_i_check_geometry(g, &vstride, &istride, &bstride, error);
    if (st != ATRBVH_OK)
        return st;
    st = env_open(&env, cfg->opencl_device, error);
    if (st != ATRBVH_OK)
        goto done;
    /* Device setup (program build) is part of build_ms, not of a stage. */
    t = atrbvh_i_now_ms();

    /* ------------------------------------------------------- bounds */
    {
        cl_uint nn = (cl_uint)g->primitive_count, bad = 0;
        cl_uint parts;
        atrbvh_box part[2 * 256];
        n = nn;
        CHECK(buffer(&env, n, sizeof(atrbvh_box), "primitive boxes", &boxes,
                     error));
        CHECK(buffer(&env, 1, sizeof(cl_uint), "bounds problems", &problems,
                     error));
        CHECK(zero(&env, problems, sizeof(cl_uint), "bounds problems", error));
        if (g->type == ATRBVH_GEOMETRY_TRIANGLES) {
            size_t vbytes = (g->vertex_count - 1) * vstride + 3 * sizeof(float);
            cl_ulong vs = vstride / sizeof(float), vc = g->vertex_count;
            cl_ulong is = istride / sizeof(uint32_t);
            cl_int indexed = g->indices != NULL;
            size_t ibytes = indexed ? ((size_t)n - 1) * istride + 12 : 4;
            CHECK(buffer(&env, vbytes, 1, "vertices", &geo, error));
            CHECK(upload(&env, geo, g->vertices, vbytes, "vertices", error));
            CHECK(buffer(&env, ibytes, 1, "indices", &geo_idx, error));
            if (indexed)
                CHECK(upload(&env, geo_idx, g->indices, ibytes, "indices",
                             error));
            RUN(K_BOUNDS_TRIANGLES, n, A(geo), A(vs), A(vc), A(geo_idx), A(is),
                A(indexed), A(n), A(boxes), A(problems));
        } else {
            size_t bbytes = ((size_t)n - 1) * bstride + 6 * sizeof(float);
            cl_ulong bs = bstride / sizeof(float);
            CHECK(buffer(&env, bbytes, 1, "input boxes", &geo, error));
            CHECK(upload(&env, geo, g->boxes, bbytes, "input boxes", error));
            RUN(K_BOUNDS_BOXES, n, A(geo), A(bs), A(n), A(boxes), A(problems));
        }
        CHECK(download(&env, problems, &bad, sizeof bad, "bounds problems",
                       error));
        buffer_drop(&env, &geo);
        buffer_drop(&env, &geo_idx);
        if (bad) {
            /* NaN/Inf or a bad index somewhere: the CPU stage reports the
             * exact error (the lowest index, the right kind) or, with
             * skip_invalid, compacts; its boxes are then uploaded. */
            CHECK(atrbvh_i_bounds(g, cfg, &prims, error));
            n = prims.count;
            CHECK(upload(&env, boxes, prims.boxes, (size_t)n * sizeof(atrbvh_box),
                         "primitive boxes", error));
            if (prims.ids) {
                has_ids = 1;
                CHECK(buffer(&env, n, sizeof(cl_uint), "kept ids", &ids, error));
                CHECK(upload(&env, ids, prims.ids, (size_t)n * 4, "kept ids",
                             error));
            }
        } else {
            parts = env.compute_units * 8u;
            if (parts > 256u)
                parts = 256u;
            if (parts > n)
                parts = n;
            if (parts < 1u)
                parts = 1u;
            CHECK(buffer(&env, 2u * parts, sizeof(atrbvh_box), "partial boxes",
                         &partial, error));
            RUN(K_BOUNDS_REDUCE, parts, A(boxes), A(n), A(parts), A(partial));
            CHECK(download(&env, partial, part,
                           2u * parts * sizeof(atrbvh_box), "partial boxes",
                           error));
            buffer_drop(&env, &partial);
            prims.count = n;
            prims.scene = part[0];
            prims.centroids = part[1];
            for (u = 1; u < parts; u++) {
                prims.scene = atrbvh_box_union(prims.scene, part[2 * u]);
                prims.centroids =
                    atrbvh_box_union(prims.centroids, part[2 * u + 1]);
            }
        }
        if (cap) {
            cap->n = n;
            cap->scene = prims.scene;
            cap->centroids = prims.centroids;
            cap->prim_boxes = atrbvh_i_alloc_array(n, sizeof(atrbvh_box));
            if (!cap->prim_boxes) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                   "cannot allocate the capture");
                goto done;
            }
            CHECK(download(&env, boxes, cap->prim_boxes,
                           (size_t)n * sizeof(atrbvh_box), "primitive boxes",
                           error));
        }
        CHECK(stage_end(&env, &ms[ATRBVH_STAGE_BOUNDS], &t, error));
    }
    nodes = 2 * (size_t)n - 1;
    inner = n > 1 ? (size_t)n - 1 : 1;

    /* ------------------------------------------------------- morton */
    {
        double lo[3], scale[3];
        atrbvh_i_morton_frame(&prims.centroids, lo, scale);
        CHECK(buffer(&env, n, sizeof(cl_ulong), "keys", &keys, error));
        CHECK(buffer(&env, n, sizeof(cl_uint), "order", &order, error));
        RUN(K_MORTON, n, A(boxes), A(n), A(lo[0]), A(lo[1]), A(lo[2]),
            A(scale[0]), A(scale[1]), A(scale[2]), A(keys), A(order));
        if (cap) {
            cap->keys = atrbvh_i_alloc_array(n, sizeof *cap->keys);
            if (!cap->keys) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                   "cannot allocate the capture");
                goto done;
            }
            CHECK(download(&env, keys, cap->keys, (size_t)n * 8, "keys",
                           error));
        }
        CHECK(stage_end(&env, &ms[ATRBVH_STAGE_MORTON], &t, error));
    }

    /* --------------------------------------------------------- sort */
    if (n > 1) {
        cl_uint blocks = env.compute_units * 32u, shift, entries, one = 1;
        cl_mem sk, sv, dk, dv;
        if (blocks > 256u)
            blocks = 256u;
        if (blocks > n)
            blocks = n;
        entries = 256u * blocks;
        CHECK(buffer(&env, n, sizeof(cl_ulong), "keys (scratch)", &keys_tmp,
                     error));
        CHECK(buffer(&env, n, sizeof(cl_uint), "order (scratch)", &order_tmp,
                     error));
        CHECK(buffer(&env, entries, sizeof(cl_uint), "digit counts", &hist,
                     error));
        sk = keys;
        sv = order;
        dk = keys_tmp;
        dv = order_tmp;
        /* Every pass (a pass whose digit never varies is the identity, so
         * the CPU's skipping cannot change the result). */
        for (shift = 0; shift < 64u; shift += 8u) {
            cl_mem tk, tv;
            RUN(K_SORT_COUNT, blocks, A(sk), A(n), A(shift), A(blocks),
                A(hist));
            RUN(K_SORT_SCAN, one, A(hist), A(entries));
            RUN(K_SORT_SCATTER, blocks, A(sk), A(sv), A(dk), A(dv), A(n),
                A(shift), A(blocks), A(hist));
            tk = sk;
            tv = sv;
            sk = dk;
            sv = dv;
            dk = tk;
            dv = tv;
        }
        /* Eight passes: the result is back in keys/order. */
        buffer_drop(&env, &keys_tmp);
        buffer_drop(&env, &order_tmp);
        buffer_drop(&env, &hist);
    }
    if (cap) {
        cap->sorted_keys = atrbvh_i_alloc_array(n, sizeof *cap->sorted_keys);
        cap->order = atrbvh_i_alloc_array(n, sizeof *cap->order);
        if (!cap->sorted_keys || !cap->order) {
            st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                               "cannot allocate the capture");
            goto done;
        }
        CHECK(download(&env, keys, cap->sorted_keys, (size_t)n * 8, "keys",
                       error));
        CHECK(download(&env, order, cap->order, (size_t)n * 4, "order",
                       error));
    }
    CHECK(stage_end(&env, &ms[ATRBVH_STAGE_SORT], &t, error));

    /* ---------------------------------------------------- hierarchy */
    CHECK(buffer(&env, inner, 4, "left", &left, error));
    CHECK(buffer(&env, inner, 4, "right", &right, error));
    CHECK(buffer(&env, nodes, 4, "parent", &parent, error));
    CHECK(buffer(&env, nodes, 4, "count", &count, error));
    CHECK(buffer(&env, n, 4, "leaf primitives", &leaf_prim, error));
    if (!ids)
        ids = order; /* unused when has_ids is 0 */
    RUN(K_HIERARCHY, n, A(keys), A(n), A(left), A(right), A(parent), A(count),
        A(leaf_prim), A(order), A(ids), A(has_ids));
    if (ids == order)
        ids = NULL;
    if (cap)
        CHECK(read_tree(&env, n, left, right, parent, count, NULL, NULL,
                        leaf_prim, 0, &cap->hierarchy, error));
    CHECK(stage_end(&env, &ms[ATRBVH_STAGE_HIERARCHY], &t, error));
    buffer_drop(&env, &keys);

    /* -------------------------------------------------------- refit */
    CHECK(buffer(&env, nodes, sizeof(atrbvh_box), "node boxes", &box, error));
    CHECK(buffer(&env, nodes, sizeof(double), "node costs", &cost, error));
    CHECK(buffer(&env, nodes, 4, "node counters", &counter, error));
    CHECK(zero(&env, counter, nodes * 4, "node counters", error));
    RUN(K_REFIT, n, A(box), A(count), A(cost), A(left), A(right), A(parent),
        A(boxes), A(order), A(n), A(ci), A(ct), A(collapse), A(max_leaf),
        A(counter));
    if (cap)
        CHECK(read_tree(&env, n, left, right, parent, count, box, cost,
                        leaf_prim, 1, &cap->refit, error));
    CHECK(stage_end(&env, &ms[ATRBVH_STAGE_REFIT], &t, error));
    buffer_drop(&env, &boxes);
    buffer_drop(&env, &order);
    buffer_drop(&env, &ids);

    /* ----------------------------------------------------- optimise */
    if (cfg->method != ATRBVH_METHOD_LBVH && cfg->rounds > 0 && n >= 2 &&
        n >= cfg->treelet_size) {
        cl_uint tsize = cfg->treelet_size, n_internal = n - 1, workers_max,
                round, len, zero_u = 0;
        cl_int agglomerative = cfg->method == ATRBVH_METHOD_ATRBVH;
        size_t subsets = 0, pairs = 0;
        cl_ulong off_cost, off_count, off_split, off_dist, stride;
        if (agglomerative)
            pairs = (size_t)tsize * (tsize - 1u) / 2u;
        else
            subsets = (size_t)1 << tsize;
        off_cost = ALIGN64(subsets * sizeof(atrbvh_box));
        off_count = off_cost + ALIGN64(subsets * sizeof(double));
        off_split = off_count + ALIGN64(subsets * sizeof(uint32_t));
        off_dist = off_split + ALIGN64(subsets * sizeof(uint32_t));
        stride = off_dist + ALIGN64(pairs * sizeof(double));
        /* Enough persistent workers to fill the device, scratch bounded. */
        workers_max = env.compute_units * 64u;
        if (workers_max > 4096u)
            workers_max = 4096u;
        while (workers_max > 1u &&
               (cl_ulong)workers_max * stride > env.max_alloc / 2u)
            workers_max /= 2u;
        CHECK(buffer(&env, workers_max, (size_t)stride, "treelet scratch",
                     &scratch, error));
        CHECK(buffer(&env, n_internal, 4, "crown children", &needed, error));
        CHECK(buffer(&env, n_internal, 4, "walk starts", &list, error));
        CHECK(buffer(&env, 1, 4, "walk start count", &list_count, error));
        for (round = 0; round < cfg->rounds; round++) {
            cl_ulong gl = (cl_ulong)cfg->gamma << (round < 40u ? round : 40u);
            cl_uint gamma, workers;
            if (gl > n)
                break; /* no crown left (the root's count is n) */
            gamma = (cl_uint)gl;
            CHECK(upload(&env, list_count, &zero_u, 4, "walk start count",
                         error));
            RUN(K_OPT_PREPARE, n_internal, A(left), A(right), A(count),
                A(n_internal), A(gamma), A(needed), A(counter), A(list),
                A(list_count));
            CHECK(download(&env, list_count, &len, 4, "walk start count",
                           error));
            if (len == 0)
                continue;
            workers = len < workers_max ? len : workers_max;
            RUN(K_OPT_ROUND, workers, A(left), A(right), A(parent), A(count),
                A(box), A(cost), A(n_internal), A(list), A(len), A(needed),
                A(counter), A(scratch), A(stride), A(off_cost), A(off_count),
                A(off_split), A(off_dist), A(tsize), A(agglomerative),
                A(workers), A(ci), A(ct), A(collapse), A(max_leaf));
        }
        buffer_drop(&env, &scratch);
        buffer_drop(&env, &needed);
        buffer_drop(&env, &list);
        buffer_drop(&env, &list_count);
    }
    CHECK(stage_end(&env, &ms[ATRBVH_STAGE_OPTIMISE], &t, error));
    if (cap)
        CHECK(read_tree(&env, n, left, right, parent, count, box, cost,
                        leaf_prim, 1, &cap->optimise, error));
    t = atrbvh_i_now_ms();

    /* ----------------------------------------------------- collapse */
    {
        cl_uint root_size = 0;
        CHECK(buffer(&env, nodes, 4, "subtree sizes", &size, error));
        CHECK(zero(&env, counter, nodes * 4, "node counters", error));
        RUN(K_COLLAPSE, n, A(box), A(count), A(cost), A(left), A(right),
            A(parent), A(n), A(ci), A(ct), A(collapse), A(max_leaf), A(size),
            A(counter));
        CHECK(download(&env, size, &root_size, 4, "subtree sizes", error));
        if (cap) {
            cap->collapse_size = atrbvh_i_alloc_array(nodes, 4);
            if (!cap->collapse_size) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                   "cannot allocate the capture");
                goto done;
            }
            CHECK(download(&env, size, cap->collapse_size, nodes * 4,
                           "subtree sizes", error));
        }
        CHECK(stage_end(&env, &ms[ATRBVH_STAGE_COLLAPSE], &t, error));

        /* ---------------------------------------------------- layout */
        root_size &= ATRBVH_SIZE_MASK;
        bvh = atrbvh_i_bvh_alloc(root_size, n);
        if (!bvh) {
            st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                               "cannot allocate the output (%lu nodes)",
                               (unsigned long)root_size);
            goto done;
        }
        CHECK(buffer(&env, root_size, sizeof(atrbvh_node), "output nodes",
                     &out_nodes, error));
        CHECK(buffer(&env, n, 4, "output primitive indices", &out_prims,
                     error));
        RUN(K_LAYOUT, nodes, A(box), A(count), A(left), A(right), A(parent),
            A(size), A(leaf_prim), A(n), A(out_nodes), A(out_prims));
        CHECK(download(&env, out_nodes, bvh->nodes,
                       (size_t)root_size * sizeof(atrbvh_node), "output nodes",
                       error));
        CHECK(download(&env, out_prims, bvh->prim_indices, (size_t)n * 4,
                       "output primitive indices", error));
        CHECK(stage_end(&env, &ms[ATRBVH_STAGE_LAYOUT], &t, error));
    }

    bvh->device = atrbvh_i_malloc(sizeof *bvh->device);
    if (!bvh->device) {
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                           "cannot allocate the device information");
        goto done;
    }
    memset(bvh->device, 0, sizeof *bvh->device);
    snprintf(bvh->device->name, sizeof bvh->device->name, "%s",
             env.device_name);
    for (k = 0; k < env.time_count; k++)
        atrbvh_i_bvh_add_kernel_time(bvh, env.time_name[k], env.time_ms[k]);
    st = atrbvh_i_build_finish(bvh, cfg, prims.invalid, ms, t0, error);

done:
    env_release(&env);
    atrbvh_i_prims_free(&prims);
    if (st != ATRBVH_OK) {
        atrbvh_bvh_free(bvh);
        bvh = NULL;
    }
    *out = bvh;
    return st;
}

/* ---------------------------------------------------------- ray queries */
/* The BVH and the geometry are uploaded once; the rays go in chunks that
 * fit the device's largest allocation.  One launch of intersect_closest or
 * intersect_any (shared/traverse.h per ray) per chunk. */
atrbvh_status atrbvh_i_cl_trace(const atrbvh_bvh *bvh,
                                const atrbvh_geometry *g,
                                const atrbvh_ray *rays, size_t count,
                                atrbvh_hit *hits, uint8_t *occluded,
                                const char *device, double *kernel_ms,
                                atrbvh_error *error)
{
    cl_env env;
    atrbvh_status st;
    cl_mem nodes = NULL, prims = NULL, verts = NULL, idx = NULL,
           bxs = NULL, ray_buf = NULL, out = NULL;
    cl_ulong node_count = bvh->node_count, prim_count = bvh->prim_count;
    cl_ulong primitive_count = g->primitive_count, vertex_count = 0,
             vstride = 3, istride = 3, bstride = 6, chunk, done_rays;
    cl_int boxes = g->type == ATRBVH_GEOMETRY_BOXES, indexed = 0;
    int k = occluded ? K_INTERSECT_ANY : K_INTERSECT_CLOSEST;
    size_t out_item = occluded ? 1 : sizeof(atrbvh_hit);
    unsigned i;

    memset(&env, 0, sizeof env);
    if (kernel_ms)
        *kernel_ms = 0.0;
    CHECK(env_open(&env, device, error));
    CHECK(buffer(&env, bvh->node_count, sizeof(atrbvh_node), "BVH nodes",
                 &nodes, error));
    CHECK(upload(&env, nodes, bvh->nodes,
                 bvh->node_count * sizeof(atrbvh_node), "BVH nodes", error));
    CHECK(buffer(&env, bvh->prim_count, sizeof(uint32_t),
                 "BVH primitive indices", &prims, error));
    CHECK(upload(&env, prims, bvh->prim_indices,
                 bvh->prim_count * sizeof(uint32_t), "BVH primitive indices",
                 error));
    /* Geometry: the bytes the CPU query may read (as the build uploads
     * them); the unused buffers are one-word dummies. */
    if (!boxes) {
        size_t vs = g->vertex_stride ? g->vertex_stride : 3 * sizeof(float);
        size_t is = g->index_stride ? g->index_stride : 3 * sizeof(uint32_t);
        size_t vbytes = g->vertex_count
                            ? (g->vertex_count - 1) * vs + 3 * sizeof(float)
                            : 0;
        size_t ibytes = g->indices && g->primitive_count
                            ? (g->primitive_count - 1) * is + 12
                            : 0;
        vertex_count = g->vertex_count;
        vstride = vs / sizeof(float);
        istride = is / sizeof(uint32_t);
        indexed = g->indices != NULL;
        CHECK(buffer(&env, vbytes, 1, "vertices", &verts, error));
        CHECK(upload(&env, verts, g->vertices, vbytes, "vertices", error));
        CHECK(buffer(&env, ibytes, 1, "indices", &idx, error));
        CHECK(upload(&env, idx, g->indices, ibytes, "indices", error));
        CHECK(buffer(&env, 1, 4, "boxes (unused)", &bxs, error));
    } else {
        size_t bs = g->box_stride ? g->box_stride : 6 * sizeof(float);
        size_t bbytes = g->primitive_count
                            ? (g->primitive_count - 1) * bs + 6 * sizeof(float)
                            : 0;
        bstride = bs / sizeof(float);
        CHECK(buffer(&env, bbytes, 1, "boxes", &bxs, error));
        CHECK(upload(&env, bxs, g->boxes, bbytes, "boxes", error));
        CHECK(buffer(&env, 1, 4, "vertices (unused)", &verts, error));
        CHECK(buffer(&env, 1, 4, "indices (unused)", &idx, error));
    }
    chunk = env.max_alloc / sizeof(atrbvh_ray);
    if (chunk > ((cl_ulong)1 << 24))
        chunk = (cl_ulong)1 << 24;
    if (chunk > count)
        chunk = count;
    if (chunk == 0)
        chunk = 1;
    CHECK(buffer(&env, (size_t)chunk, sizeof(atrbvh_ray), "rays", &ray_buf,
                 error));
    CHECK(buffer(&env, (size_t)chunk, out_item,
                 occluded ? "occlusion results" : "hits", &out, error));
    for (done_rays = 0; done_rays < count; done_rays += chunk) {
        cl_ulong n = count - done_rays < chunk ? count - done_rays : chunk;
        CHECK(upload(&env, ray_buf, rays + done_rays,
                     (size_t)n * sizeof(atrbvh_ray), "rays", error));
        RUN(k, (size_t)n, A(nodes), A(node_count), A(prims), A(prim_count),
            A(boxes), A(primitive_count), A(verts), A(vertex_count),
            A(vstride), A(idx), A(indexed), A(istride), A(bxs), A(bstride),
            A(ray_buf), A(n), A(out));
        if (occluded)
            CHECK(download(&env, out, occluded + done_rays, (size_t)n,
                           "occlusion results", error));
        else
            CHECK(download(&env, out, hits + done_rays,
                           (size_t)n * sizeof(atrbvh_hit), "hits", error));
        CHECK(harvest(&env, error));
    }
    if (kernel_ms)
        for (i = 0; i < env.time_count; i++)
            if (strcmp(env.time_name[i], kernel_names[k]) == 0)
                *kernel_ms += env.time_ms[i];
    st = ATRBVH_OK;
done:
    env_release(&env);
    return st;
}
