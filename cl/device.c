/*
 * cl/device.c - opening an OpenCL device: choice by spec, context, queue
 * (profiling on), the program built once, every kernel created once;
 * closing releases all of it and the buffers kept between builds.
 *
 * Thread safety.  PoCL (and other ICDs) are not safe when several threads
 * discover platforms, create contexts or build programs at once, first use
 * in the process included: every open and close runs under one
 * process-wide mutex.  After that, the pipeline's per-handle lock
 * (atrbvh_device.lock, held around every build and ray batch) lets one
 * call at a time use a handle's queue and buffers; different handles run
 * concurrently.
 */
#include "config.h"

#include "opencl.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static pthread_mutex_t cl_global_lock = PTHREAD_MUTEX_INITIALIZER;

const char *const atrbvh_i_cl_kernel_names[K_COUNT] = {
    "bounds_triangles", "bounds_boxes", "morton",
    "sort_count",       "sort_scatter", "sort_buckets", "sort_vary",
    "hierarchy",
    "refit",            "opt_prepare",  "opt_round",     "opt_round4",
    "collapse",         "collapse_count",
    "layout_top",       "layout",
    "intersect_closest", "intersect_any"};

/* ------------------------------------------------------ device choice */
static void info_string(cl_device_id d, cl_platform_id p, char *buf,
                        size_t size)
{
    cl_int e = d ? clGetDeviceInfo(d, CL_DEVICE_NAME, size, buf, NULL)
                 : clGetPlatformInfo(p, CL_PLATFORM_NAME, size, buf, NULL);
    if (e != CL_SUCCESS)
        snprintf(buf, size, "(unnamed)");
    buf[size - 1] = '\0';
}

/* "P:D" with decimal indices. */
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

/* Case-insensitive (ASCII) substring. */
static int contains_nocase(const char *hay, const char *needle)
{
    size_t i, j;
    for (i = 0; hay[i]; i++) {
        for (j = 0; needle[j] && hay[i + j]; j++)
            if (tolower((unsigned char)hay[i + j]) !=
                tolower((unsigned char)needle[j]))
                break;
        if (!needle[j])
            return 1;
    }
    return !*needle;
}

#define MAX_PLATFORMS 16
#define MAX_DEVICES 64

/* The device named by spec: NULL or "" the first device of the first
 * platform that has one; "P:D" by indices; else the first device whose
 * name or platform name contains spec (case-insensitive). */
static atrbvh_status select_device(const char *spec, cl_device_id *out,
                                   char *name, size_t name_size,
                                   atrbvh_error *error)
{
    cl_platform_id platforms[MAX_PLATFORMS];
    cl_uint np = 0, p;
    unsigned want_p = 0, want_d = 0;
    int by_index = 0;
    char list[200];
    size_t used = 0;
    cl_int err;

    if (spec && !*spec)
        spec = NULL;
    if (spec)
        by_index = parse_index_pair(spec, &want_p, &want_d);
    err = clGetPlatformIDs(MAX_PLATFORMS, platforms, &np);
    if (err == -1001 /* CL_PLATFORM_NOT_FOUND_KHR */ ||
        (err == CL_SUCCESS && np == 0))
        return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, ATRBVH_CL_NO_INDEX,
                             "OpenCL: no platform found (is an ICD such as "
                             "pocl-opencl-icd installed?)");
    if (err != CL_SUCCESS)
        return atrbvh_i_cl_error(error, err, "clGetPlatformIDs", NULL);
    if (np > MAX_PLATFORMS)
        np = MAX_PLATFORMS;
    list[0] = '\0';
    for (p = 0; p < np; p++) {
        cl_device_id devs[MAX_DEVICES];
        cl_uint nd = 0, d;
        char pn[128];
        err = clGetDeviceIDs(platforms[p], CL_DEVICE_TYPE_ALL, MAX_DEVICES,
                             devs, &nd);
        if (err == CL_DEVICE_NOT_FOUND)
            continue;
        if (err != CL_SUCCESS)
            return atrbvh_i_cl_error(error, err, "clGetDeviceIDs", NULL);
        if (nd > MAX_DEVICES)
            nd = MAX_DEVICES;
        info_string(NULL, platforms[p], pn, sizeof pn);
        for (d = 0; d < nd; d++) {
            char dn[128];
            int match;
            info_string(devs[d], NULL, dn, sizeof dn);
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
                match = contains_nocase(dn, spec) || contains_nocase(pn, spec);
            if (match) {
                *out = devs[d];
                snprintf(name, name_size, "%s", dn);
                return ATRBVH_OK;
            }
        }
    }
    if (!spec)
        return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, ATRBVH_CL_NO_INDEX,
                             "OpenCL: no device found on %u platform%s",
                             (unsigned)np, np == 1 ? "" : "s");
    return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                         ATRBVH_CL_NO_INDEX,
                         "OpenCL: no device matches \"%.40s\" (want "
                         "PLATFORM:DEVICE or a device or platform name "
                         "substring; devices: %s)",
                         spec, list[0] ? list : "none");
}

/* ------------------------------------------------------------ program */
/* The code and the compiler log, on one line, as much as fits the error
 * text; ATRBVH_ERR_NOMEM when the compiler ran out of memory. */
static atrbvh_status build_failed(atrbvh_cl_device *c, cl_int err,
                                  atrbvh_error *error)
{
    char log[4096];
    size_t k;
    log[0] = '\0';
    if (clGetProgramBuildInfo(c->program, c->device, CL_PROGRAM_BUILD_LOG,
                              sizeof log - 1, log, NULL) != CL_SUCCESS)
        snprintf(log, sizeof log, "(no build log)");
    log[sizeof log - 1] = '\0';
    for (k = 0; log[k]; k++)
        if (log[k] == '\n' || log[k] == '\r' || log[k] == '\t')
            log[k] = ' ';
    return atrbvh_i_fail(error, atrbvh_i_cl_status(err), ATRBVH_CL_NO_INDEX,
                         "OpenCL kernel build failed: %s (%d): %s",
                         atrbvh_i_cl_code_name(err), (int)err, log);
}

static atrbvh_status build_program(atrbvh_cl_device *c, atrbvh_error *error)
{
    char *src = atrbvh_i_cl_source();
    const char *srcs[1];
    size_t len;
    cl_int err;
    int k;
    if (!src)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, ATRBVH_CL_NO_INDEX,
                             "cannot allocate the OpenCL kernel source");
    srcs[0] = src;
    len = strlen(src);
    c->program = clCreateProgramWithSource(c->ctx, 1, srcs, &len, &err);
    atrbvh_i_free(src);
    if (!c->program)
        return atrbvh_i_cl_error(error, err, "clCreateProgramWithSource",
                                 NULL);
    /* No -cl-fast-relaxed-math, no -cl-mad-enable: bit-for-bit with C. */
    err = clBuildProgram(c->program, 1, &c->device, "-cl-std=CL1.2", NULL,
                         NULL);
    if (err != CL_SUCCESS)
        return build_failed(c, err, error);
    for (k = 0; k < K_COUNT; k++) {
        c->kernel[k] = clCreateKernel(c->program, atrbvh_i_cl_kernel_names[k],
                                      &err);
        if (!c->kernel[k])
            return atrbvh_i_cl_error(error, err, "clCreateKernel",
                                     atrbvh_i_cl_kernel_names[k]);
        /* The launches' work-group sizes stay within it (memory.c). */
        if (clGetKernelWorkGroupInfo(c->kernel[k], c->device,
                                     CL_KERNEL_WORK_GROUP_SIZE,
                                     sizeof c->kernel_wg[k], &c->kernel_wg[k],
                                     NULL) != CL_SUCCESS ||
            c->kernel_wg[k] < 1)
            c->kernel_wg[k] = 1;
    }
    return ATRBVH_OK;
}

/* Everything but the mutex and the struct itself. */
static void release_all(atrbvh_cl_device *c)
{
    int k;
    atrbvh_i_cl_drop_events(c);
    atrbvh_i_cl_buffers_release(c);
    for (k = 0; k < K_COUNT; k++)
        if (c->kernel[k])
            clReleaseKernel(c->kernel[k]);
    if (c->program)
        clReleaseProgram(c->program);
    if (c->queue)
        clReleaseCommandQueue(c->queue);
    if (c->ctx)
        clReleaseContext(c->ctx);
}

/* Whether builds read the geometry and write the output in place
 * (opencl.h, host_memory): the device says it shares the host's memory
 * (CL_DEVICE_HOST_UNIFIED_MEMORY, deprecated by OpenCL 2.0 but answered
 * by every 1.2 platform) and ATRBVH_CL_COPY is unset, empty or "0" (as
 * ATRBVH_NO_AVX2 is read); set, it asks for the copies through the
 * handle's buffers that a device with its own memory gets (tests run
 * both ways on one device). */
static cl_uint host_memory(cl_device_id d)
{
    cl_bool unified = CL_FALSE;
    const char *copy = getenv("ATRBVH_CL_COPY");
    if (copy && copy[0] && strcmp(copy, "0") != 0)
        return 0;
    if (clGetDeviceInfo(d, CL_DEVICE_HOST_UNIFIED_MEMORY, sizeof unified,
                        &unified, NULL) != CL_SUCCESS)
        return 0;
    return unified == CL_TRUE;
}

/* Whether the optimise stage's items walk several treelets at once
 * (opencl.h, several_walks): a CPU device, unless ATRBVH_CL_WALKS is "1"
 * (tests take the GPU's kernel on PoCL with it too). */
static cl_uint several_walks(cl_device_id d)
{
    cl_device_type type = 0;
    const char *walks = getenv("ATRBVH_CL_WALKS");
    if (walks && strcmp(walks, "1") == 0)
        return 0;
    if (clGetDeviceInfo(d, CL_DEVICE_TYPE, sizeof type, &type, NULL) !=
        CL_SUCCESS)
        return 0;
    return (type & CL_DEVICE_TYPE_CPU) != 0;
}

static atrbvh_status open_locked(atrbvh_cl_device *c, const char *spec,
                                 char *name, size_t name_size,
                                 atrbvh_error *error)
{
    char ext[8192];
    cl_int err;
    atrbvh_status st;

    st = select_device(spec, &c->device, name, name_size, error);
    if (st != ATRBVH_OK)
        return st;
    ext[0] = '\0';
    err = clGetDeviceInfo(c->device, CL_DEVICE_EXTENSIONS, sizeof ext, ext,
                          NULL);
    if (err != CL_SUCCESS)
        return atrbvh_i_cl_error(error, err, "clGetDeviceInfo",
                                 "CL_DEVICE_EXTENSIONS");
    ext[sizeof ext - 1] = '\0';
    if (!strstr(ext, "cl_khr_fp64"))
        return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, ATRBVH_CL_NO_INDEX,
                             "OpenCL device \"%s\" lacks cl_khr_fp64: atrbvh "
                             "computes areas and costs in double precision",
                             name);
    err = clGetDeviceInfo(c->device, CL_DEVICE_MAX_MEM_ALLOC_SIZE,
                          sizeof c->max_alloc, &c->max_alloc, NULL);
    if (err != CL_SUCCESS)
        return atrbvh_i_cl_error(error, err, "clGetDeviceInfo",
                                 "CL_DEVICE_MAX_MEM_ALLOC_SIZE");
    err = clGetDeviceInfo(c->device, CL_DEVICE_MAX_COMPUTE_UNITS,
                          sizeof c->compute_units, &c->compute_units, NULL);
    if (err != CL_SUCCESS)
        return atrbvh_i_cl_error(error, err, "clGetDeviceInfo",
                                 "CL_DEVICE_MAX_COMPUTE_UNITS");
    if (c->compute_units < 1)
        c->compute_units = 1;
    c->host_memory = host_memory(c->device);
    c->several_walks = several_walks(c->device);
    c->ctx = clCreateContext(NULL, 1, &c->device, NULL, NULL, &err);
    if (!c->ctx)
        return atrbvh_i_cl_error(error, err, "clCreateContext", NULL);
    c->queue = clCreateCommandQueue(c->ctx, c->device,
                                    CL_QUEUE_PROFILING_ENABLE, &err);
    if (!c->queue)
        return atrbvh_i_cl_error(error, err, "clCreateCommandQueue", NULL);
    return build_program(c, error);
}

atrbvh_status atrbvh_i_cl_open(atrbvh_device *dev, const char *spec,
                               atrbvh_error *error)
{
    atrbvh_cl_device *c = atrbvh_i_malloc(sizeof *c);
    atrbvh_status st;
    if (!c)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, ATRBVH_CL_NO_INDEX,
                             "cannot allocate the OpenCL device state");
    memset(c, 0, sizeof *c);
    c->times = &c->build_times;
    pthread_mutex_lock(&cl_global_lock);
    st = open_locked(c, spec, dev->name, sizeof dev->name, error);
    if (st != ATRBVH_OK)
        release_all(c);
    pthread_mutex_unlock(&cl_global_lock);
    if (st != ATRBVH_OK) {
        atrbvh_i_free(c);
        return st;
    }
    dev->impl = c;
    return ATRBVH_OK;
}

void atrbvh_i_cl_close(atrbvh_device *dev)
{
    atrbvh_cl_device *c = dev ? dev->impl : NULL;
    if (!c)
        return;
    pthread_mutex_lock(&cl_global_lock);
    release_all(c);
    pthread_mutex_unlock(&cl_global_lock);
    atrbvh_i_free(c);
    dev->impl = NULL;
}
