/*
 * test_clfault.c - the OpenCL backend when the OpenCL implementation fails.
 *
 * The library's core is linked with ld --wrap for every OpenCL function
 * it calls (Makefile.am; tests/symbols.sh checks the list), so its calls
 * reach the wrappers below, which forward to libOpenCL or make the k-th
 * call fail without reaching the implementation, with the (k mod 8)-th
 * code of `codes` below: the two an implementation short of memory
 * returns, the one short of device memory, four others and one no
 * version of OpenCL defines.  For every k up to the number
 * of calls a device open, a build by each method (in place on a device
 * that shares the host's memory, and through copies; the first on a
 * handle and a later one), a ray batch and a re-optimisation make:
 *
 *   - the call fails with ATRBVH_ERR_NOMEM (host or device memory) or
 *     ATRBVH_ERR_BACKEND, its message naming the failed call and the
 *     code by name and number (cl/error.c), and no BVH; or, where the
 *     backend does without the answer (a name, a kernel's largest work
 *     group, a profiling time), it succeeds with the CPU's tree or hits;
 *   - the same handle then builds (or traces) again and gives the CPU's
 *     result bit for bit: a failure leaves nothing behind that trips a
 *     later call; a refused re-optimisation leaves the tree as it was;
 *   - the failing call's geometry, rays and hits are arrays of its own,
 *     freed as soon as it returns: under ASan, a queued copy still
 *     touching them is a use-after-free; and no buffer made over them
 *     (CL_MEM_USE_HOST_PTR) outlives the call;
 *   - every OpenCL object the backend made (context, queue, program,
 *     kernels, buffers, events) is released when the handle is closed, or
 *     at once when the open fails.
 * And with every wait for the queue (clFinish) failing as well: a call
 * that waited fails, waits once more, and the handle is lost (every later
 * call refused, its close still clean); one that never waited loses
 * nothing.
 *
 * docs/opencl.md, "When an OpenCL call fails", has the counts.  Skips
 * without an OpenCL device.
 */
#define _POSIX_C_SOURCE 200809L
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atrbvh.h"
#include "testutil.h"

#ifndef CL_TARGET_OPENCL_VERSION
#define CL_TARGET_OPENCL_VERSION 120
#endif
#include <CL/cl.h>

/* ------------------------------------------------------------ the wrappers */
static unsigned long calls;   /* calls that can fail, since arm()      */
static unsigned long fail_at; /* the call that fails (0: none)         */
static const char *failed;    /* its name, once it has failed          */
static unsigned code_shift;   /* call k fails with code k + shift      */

/* The codes a failing call returns, in turn.  (Not CL_DEVICE_NOT_FOUND
 * or CL_PLATFORM_NOT_FOUND_KHR: the open takes those for "no device".) */
typedef struct fail_code {
    cl_int code;
    const char *name; /* as the message must give it */
    int nomem;        /* ATRBVH_ERR_NOMEM, else ATRBVH_ERR_BACKEND */
} fail_code;
static const fail_code *fail_with; /* the failing call's */
static const fail_code codes[8] = {
    {CL_OUT_OF_RESOURCES, "CL_OUT_OF_RESOURCES", 0},
    {CL_OUT_OF_HOST_MEMORY, "CL_OUT_OF_HOST_MEMORY", 1},
    {CL_MEM_OBJECT_ALLOCATION_FAILURE, "CL_MEM_OBJECT_ALLOCATION_FAILURE", 1},
    {CL_INVALID_VALUE, "CL_INVALID_VALUE", 0},
    {CL_DEVICE_NOT_AVAILABLE, "CL_DEVICE_NOT_AVAILABLE", 0},
    {CL_INVALID_COMMAND_QUEUE, "CL_INVALID_COMMAND_QUEUE", 0},
    {CL_INVALID_OPERATION, "CL_INVALID_OPERATION", 0},
    {-9999, "unknown OpenCL error", 0}};

/* OpenCL objects made by the backend and not yet released. */
enum { L_CONTEXT, L_QUEUE, L_PROGRAM, L_KERNEL, L_MEM, L_EVENT, L_KINDS };
static const char *const kind_name[L_KINDS] = {
    "context", "command queue", "program", "kernel", "buffer", "event"};
static long live[L_KINDS];
/* Of those buffers, the ones made over the caller's memory
 * (CL_MEM_USE_HOST_PTR): none may outlive the call that made it. */
#define MAX_OVER_CALLER 64
static cl_mem over_caller[MAX_OVER_CALLER];
static int n_over_caller;

/* Call k from now fails (0: none). */
static void arm(unsigned long k)
{
    calls = 0;
    fail_at = k;
    failed = NULL;
    fail_with = &codes[(k + code_shift) % 8];
}

/* Whether this call is the one that fails. */
static int fails(const char *name)
{
    if (++calls != fail_at)
        return 0;
    failed = name;
    return 1;
}

#define FAIL_OR(name) \
    if (fails(#name)) \
    return fail_with->code

/* A creation that fails sets *err and makes nothing. */
#define FAIL_CREATE_OR(name, err)         \
    if (fails(#name)) {                   \
        if (err)                          \
            *(err) = fail_with->code;     \
        return NULL;                      \
    }

/* (ld --wrap names: __wrap_X is what the library calls, __real_X the
 * implementation's X.) */
#define REAL(ret, name, params) \
    ret __real_##name params;   \
    ret __wrap_##name params

REAL(cl_int, clGetPlatformIDs,
     (cl_uint n, cl_platform_id *platforms, cl_uint *np));
cl_int __wrap_clGetPlatformIDs(cl_uint n, cl_platform_id *platforms,
                               cl_uint *np)
{
    FAIL_OR(clGetPlatformIDs);
    return __real_clGetPlatformIDs(n, platforms, np);
}

REAL(cl_int, clGetPlatformInfo,
     (cl_platform_id p, cl_platform_info what, size_t size, void *value,
      size_t *ret));
cl_int __wrap_clGetPlatformInfo(cl_platform_id p, cl_platform_info what,
                                size_t size, void *value, size_t *ret)
{
    FAIL_OR(clGetPlatformInfo);
    return __real_clGetPlatformInfo(p, what, size, value, ret);
}

REAL(cl_int, clGetDeviceIDs,
     (cl_platform_id p, cl_device_type type, cl_uint n, cl_device_id *devs,
      cl_uint *nd));
cl_int __wrap_clGetDeviceIDs(cl_platform_id p, cl_device_type type, cl_uint n,
                             cl_device_id *devs, cl_uint *nd)
{
    FAIL_OR(clGetDeviceIDs);
    return __real_clGetDeviceIDs(p, type, n, devs, nd);
}

REAL(cl_int, clGetDeviceInfo,
     (cl_device_id d, cl_device_info what, size_t size, void *value,
      size_t *ret));
cl_int __wrap_clGetDeviceInfo(cl_device_id d, cl_device_info what,
                              size_t size, void *value, size_t *ret)
{
    FAIL_OR(clGetDeviceInfo);
    return __real_clGetDeviceInfo(d, what, size, value, ret);
}

REAL(cl_context, clCreateContext,
     (const cl_context_properties *props, cl_uint n, const cl_device_id *devs,
      void(CL_CALLBACK *notify)(const char *, const void *, size_t, void *),
      void *user, cl_int *err));
cl_context __wrap_clCreateContext(
    const cl_context_properties *props, cl_uint n, const cl_device_id *devs,
    void(CL_CALLBACK *notify)(const char *, const void *, size_t, void *),
    void *user, cl_int *err)
{
    cl_context x;
    FAIL_CREATE_OR(clCreateContext, err);
    x = __real_clCreateContext(props, n, devs, notify, user, err);
    live[L_CONTEXT] += x != NULL;
    return x;
}

REAL(cl_int, clReleaseContext, (cl_context x));
cl_int __wrap_clReleaseContext(cl_context x)
{
    live[L_CONTEXT]--;
    return __real_clReleaseContext(x);
}

REAL(cl_command_queue, clCreateCommandQueue,
     (cl_context ctx, cl_device_id d, cl_command_queue_properties props,
      cl_int *err));
cl_command_queue __wrap_clCreateCommandQueue(cl_context ctx, cl_device_id d,
                                             cl_command_queue_properties props,
                                             cl_int *err)
{
    cl_command_queue x;
    FAIL_CREATE_OR(clCreateCommandQueue, err);
    x = __real_clCreateCommandQueue(ctx, d, props, err);
    live[L_QUEUE] += x != NULL;
    return x;
}

REAL(cl_int, clReleaseCommandQueue, (cl_command_queue x));
cl_int __wrap_clReleaseCommandQueue(cl_command_queue x)
{
    live[L_QUEUE]--;
    return __real_clReleaseCommandQueue(x);
}

REAL(cl_program, clCreateProgramWithSource,
     (cl_context ctx, cl_uint n, const char **srcs, const size_t *lens,
      cl_int *err));
cl_program __wrap_clCreateProgramWithSource(cl_context ctx, cl_uint n,
                                            const char **srcs,
                                            const size_t *lens, cl_int *err)
{
    cl_program x;
    FAIL_CREATE_OR(clCreateProgramWithSource, err);
    x = __real_clCreateProgramWithSource(ctx, n, srcs, lens, err);
    live[L_PROGRAM] += x != NULL;
    return x;
}

REAL(cl_int, clReleaseProgram, (cl_program x));
cl_int __wrap_clReleaseProgram(cl_program x)
{
    live[L_PROGRAM]--;
    return __real_clReleaseProgram(x);
}

REAL(cl_int, clBuildProgram,
     (cl_program prog, cl_uint n, const cl_device_id *devs,
      const char *options,
      void(CL_CALLBACK *notify)(cl_program, void *), void *user));
cl_int __wrap_clBuildProgram(cl_program prog, cl_uint n,
                             const cl_device_id *devs, const char *options,
                             void(CL_CALLBACK *notify)(cl_program, void *),
                             void *user)
{
    FAIL_OR(clBuildProgram);
    return __real_clBuildProgram(prog, n, devs, options, notify, user);
}

REAL(cl_int, clGetProgramBuildInfo,
     (cl_program prog, cl_device_id d, cl_program_build_info what,
      size_t size, void *value, size_t *ret));
cl_int __wrap_clGetProgramBuildInfo(cl_program prog, cl_device_id d,
                                    cl_program_build_info what, size_t size,
                                    void *value, size_t *ret)
{
    FAIL_OR(clGetProgramBuildInfo);
    return __real_clGetProgramBuildInfo(prog, d, what, size, value, ret);
}

REAL(cl_kernel, clCreateKernel,
     (cl_program prog, const char *name, cl_int *err));
cl_kernel __wrap_clCreateKernel(cl_program prog, const char *name,
                                cl_int *err)
{
    cl_kernel x;
    FAIL_CREATE_OR(clCreateKernel, err);
    x = __real_clCreateKernel(prog, name, err);
    live[L_KERNEL] += x != NULL;
    return x;
}

REAL(cl_int, clReleaseKernel, (cl_kernel x));
cl_int __wrap_clReleaseKernel(cl_kernel x)
{
    live[L_KERNEL]--;
    return __real_clReleaseKernel(x);
}

REAL(cl_int, clGetKernelWorkGroupInfo,
     (cl_kernel k, cl_device_id d, cl_kernel_work_group_info what,
      size_t size, void *value, size_t *ret));
cl_int __wrap_clGetKernelWorkGroupInfo(cl_kernel k, cl_device_id d,
                                       cl_kernel_work_group_info what,
                                       size_t size, void *value, size_t *ret)
{
    FAIL_OR(clGetKernelWorkGroupInfo);
    return __real_clGetKernelWorkGroupInfo(k, d, what, size, value, ret);
}

REAL(cl_int, clSetKernelArg,
     (cl_kernel k, cl_uint i, size_t size, const void *value));
cl_int __wrap_clSetKernelArg(cl_kernel k, cl_uint i, size_t size,
                             const void *value)
{
    FAIL_OR(clSetKernelArg);
    return __real_clSetKernelArg(k, i, size, value);
}

REAL(cl_mem, clCreateBuffer,
     (cl_context ctx, cl_mem_flags flags, size_t size, void *host,
      cl_int *err));
cl_mem __wrap_clCreateBuffer(cl_context ctx, cl_mem_flags flags, size_t size,
                             void *host, cl_int *err)
{
    cl_mem x;
    FAIL_CREATE_OR(clCreateBuffer, err);
    x = __real_clCreateBuffer(ctx, flags, size, host, err);
    live[L_MEM] += x != NULL;
    if (x && (flags & CL_MEM_USE_HOST_PTR)) {
        ck_assert(n_over_caller < MAX_OVER_CALLER);
        over_caller[n_over_caller++] = x;
    }
    return x;
}

REAL(cl_int, clReleaseMemObject, (cl_mem x));
cl_int __wrap_clReleaseMemObject(cl_mem x)
{
    int i;
    live[L_MEM]--;
    for (i = 0; i < n_over_caller; i++)
        if (over_caller[i] == x) {
            over_caller[i] = over_caller[--n_over_caller];
            break;
        }
    return __real_clReleaseMemObject(x);
}

REAL(cl_int, clEnqueueNDRangeKernel,
     (cl_command_queue q, cl_kernel k, cl_uint dims, const size_t *offset,
      const size_t *global, const size_t *local, cl_uint nwait,
      const cl_event *wait, cl_event *ev));
cl_int __wrap_clEnqueueNDRangeKernel(cl_command_queue q, cl_kernel k,
                                     cl_uint dims, const size_t *offset,
                                     const size_t *global,
                                     const size_t *local, cl_uint nwait,
                                     const cl_event *wait, cl_event *ev)
{
    cl_int err;
    FAIL_OR(clEnqueueNDRangeKernel);
    err = __real_clEnqueueNDRangeKernel(q, k, dims, offset, global, local,
                                        nwait, wait, ev);
    live[L_EVENT] += err == CL_SUCCESS && ev;
    return err;
}

REAL(cl_int, clReleaseEvent, (cl_event x));
cl_int __wrap_clReleaseEvent(cl_event x)
{
    live[L_EVENT]--;
    return __real_clReleaseEvent(x);
}

REAL(cl_int, clGetEventProfilingInfo,
     (cl_event ev, cl_profiling_info what, size_t size, void *value,
      size_t *ret));
cl_int __wrap_clGetEventProfilingInfo(cl_event ev, cl_profiling_info what,
                                      size_t size, void *value, size_t *ret)
{
    FAIL_OR(clGetEventProfilingInfo);
    return __real_clGetEventProfilingInfo(ev, what, size, value, ret);
}

REAL(cl_int, clEnqueueWriteBuffer,
     (cl_command_queue q, cl_mem m, cl_bool blocking, size_t offset,
      size_t size, const void *data, cl_uint nwait, const cl_event *wait,
      cl_event *ev));
cl_int __wrap_clEnqueueWriteBuffer(cl_command_queue q, cl_mem m,
                                   cl_bool blocking, size_t offset,
                                   size_t size, const void *data,
                                   cl_uint nwait, const cl_event *wait,
                                   cl_event *ev)
{
    cl_int err;
    FAIL_OR(clEnqueueWriteBuffer);
    err = __real_clEnqueueWriteBuffer(q, m, blocking, offset, size, data,
                                      nwait, wait, ev);
    live[L_EVENT] += err == CL_SUCCESS && ev;
    return err;
}

REAL(cl_int, clEnqueueReadBuffer,
     (cl_command_queue q, cl_mem m, cl_bool blocking, size_t offset,
      size_t size, void *data, cl_uint nwait, const cl_event *wait,
      cl_event *ev));
cl_int __wrap_clEnqueueReadBuffer(cl_command_queue q, cl_mem m,
                                  cl_bool blocking, size_t offset,
                                  size_t size, void *data, cl_uint nwait,
                                  const cl_event *wait, cl_event *ev)
{
    cl_int err;
    FAIL_OR(clEnqueueReadBuffer);
    err = __real_clEnqueueReadBuffer(q, m, blocking, offset, size, data,
                                     nwait, wait, ev);
    live[L_EVENT] += err == CL_SUCCESS && ev;
    return err;
}

REAL(cl_int, clEnqueueFillBuffer,
     (cl_command_queue q, cl_mem m, const void *pattern, size_t pattern_size,
      size_t offset, size_t size, cl_uint nwait, const cl_event *wait,
      cl_event *ev));
cl_int __wrap_clEnqueueFillBuffer(cl_command_queue q, cl_mem m,
                                  const void *pattern, size_t pattern_size,
                                  size_t offset, size_t size, cl_uint nwait,
                                  const cl_event *wait, cl_event *ev)
{
    cl_int err;
    FAIL_OR(clEnqueueFillBuffer);
    err = __real_clEnqueueFillBuffer(q, m, pattern, pattern_size, offset,
                                     size, nwait, wait, ev);
    live[L_EVENT] += err == CL_SUCCESS && ev;
    return err;
}

/* clFinish calls since finish_count was last zeroed; from the
 * finish_fails_from-th on (0: none) every one fails with
 * CL_OUT_OF_RESOURCES, as a queue that stays broken, after the real wait:
 * the commands of a queue that never answers again may write memory
 * the library and the test then free (the library can only refuse the
 * handle from then on; docs/opencl.md). */
static unsigned long finish_count, finish_fails_from;

REAL(cl_int, clFinish, (cl_command_queue q));
cl_int __wrap_clFinish(cl_command_queue q)
{
    FAIL_OR(clFinish);
    if (++finish_count >= finish_fails_from && finish_fails_from) {
        (void)__real_clFinish(q);
        return CL_OUT_OF_RESOURCES;
    }
    return __real_clFinish(q);
}

/* --------------------------------------------------------------- checks */
/* Every object the backend made has been released. */
static void assert_none_live(const char *when)
{
    int k;
    for (k = 0; k < L_KINDS; k++)
        ck_assert_msg(live[k] == 0, "%s: %ld %s%s not released", when,
                      live[k], kind_name[k], live[k] == 1 ? "" : "s");
}

/* No buffer over the caller's arrays is left once a call returns. */
static void assert_caller_arrays_free(const char *what, unsigned long k)
{
    ck_assert_msg(n_over_caller == 0,
                  "%s, call %lu failed: %d buffer%s over the caller's "
                  "arrays left on the handle", what, k, n_over_caller,
                  n_over_caller == 1 ? "" : "s");
}

/* A call that failed because call `failed` did: the status the code
 * asks for, and a message naming the call and the code. */
static void assert_named_failure(atrbvh_status st, const atrbvh_error *e,
                                 unsigned long k, const char *what)
{
    char code[96];
    /* (a failed program build reports the build, with its log) */
    int build = strcmp(failed, "clBuildProgram") == 0;
    atrbvh_status want = fail_with->nomem ? ATRBVH_ERR_NOMEM
                                          : ATRBVH_ERR_BACKEND;
    snprintf(code, sizeof code, "%s (%d)", fail_with->name,
             (int)fail_with->code);
    ck_assert_msg(st == want, "%s, call %lu (%s) failed with %s: status %d, "
                  "want %d (%s)", what, k, failed, code, (int)st, (int)want,
                  e->text);
    ck_assert_msg(strstr(e->text, build ? "kernel build failed" : failed) &&
                      strstr(e->text, code),
                  "%s, call %lu: the message does not name %s and %s: %s",
                  what, k, failed, code, e->text);
}

static float *tris;
static atrbvh_geometry g_scene;
enum { N_TRIS = 2500 };

/* The g_scene, and its tree built on the CPU with o's method and size. */
static atrbvh_bvh *cpu_tree(const atrbvh_build_options *o)
{
    atrbvh_build_options c = *o;
    c.device = NULL;
    c.backend = ATRBVH_BACKEND_CPU;
    return tu_build(&g_scene, &c);
}

static void make_scene(void)
{
    if (!tris) {
        tris = tu_random_triangles(N_TRIS, 7, 4.0f, 1.0f);
        g_scene = atrbvh_geometry_triangles(tris, 3 * N_TRIS, NULL, N_TRIS);
    }
}

/* Builds on dev with o; the tree must be want's. */
static void assert_builds_same(atrbvh_device *dev,
                               const atrbvh_build_options *o,
                               const atrbvh_bvh *want, const char *what,
                               unsigned long k)
{
    atrbvh_build_options d = *o;
    atrbvh_bvh *got = NULL;
    atrbvh_error e;
    char msg[256];
    atrbvh_status st;
    d.device = dev;
    st = atrbvh_build(&g_scene, &d, &got, &e);
    ck_assert_msg(st == ATRBVH_OK, "%s, after call %lu: %s", what, k, e.text);
    ck_assert_msg(tu_same_bvh(want, got, msg, sizeof msg),
                  "%s, after call %lu failed: %s", what, k, msg);
    atrbvh_bvh_free(got);
}

/* Opens the OpenCL device with nothing failing; 0 (the test skips) when
 * there is none. */
static atrbvh_device *open_or_skip(const char *test)
{
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    atrbvh_status st;
    arm(0);
    st = atrbvh_device_open("opencl", &dev, &e);
    if (st != ATRBVH_OK) {
        ck_assert_msg(tu_opencl_may_skip(st), "%s", e.text);
        fprintf(stderr, "SKIP %s: %s\n", test, e.text);
        return NULL;
    }
    return dev;
}

/* The calls done without, for the log: each name once. */
static char done_without[512];

static void note_done_without(const char *name)
{
    size_t used = strlen(done_without);
    if (strstr(done_without, name))
        return;
    snprintf(done_without + used, sizeof done_without - used, "%s%s",
             used ? ", " : "", name);
}

/* ---------------------------------------------------------------- tests */
/* Each call of a device open failed in turn. */
/* _i: the code shift; every call of an open fails with each code once
 * (an open is short, and its calls are the likeliest to fail). */
START_TEST(open_fails_cleanly_at_each_call)
{
    atrbvh_device *dev = open_or_skip(__func__);
    atrbvh_build_options o;
    atrbvh_bvh *want;
    unsigned long n, k, survived = 0;
    code_shift = (unsigned)_i;
    if (!dev)
        return;
    n = calls; /* a whole open */
    atrbvh_device_close(dev);
    assert_none_live("after a clean open and close");
    ck_assert(n > 10);
    make_scene();
    atrbvh_build_options_init(&o);
    want = cpu_tree(&o);
    done_without[0] = '\0';
    for (k = 1; k <= n; k++) {
        atrbvh_error e;
        atrbvh_status st;
        dev = (atrbvh_device *)&dev; /* must be set to NULL on failure */
        arm(k);
        st = atrbvh_device_open("opencl", &dev, &e);
        ck_assert_msg(failed != NULL, "open: call %lu of %lu never made", k,
                      n);
        if (st != ATRBVH_OK) {
            assert_named_failure(st, &e, k, "open");
            ck_assert_msg(dev == NULL, "open, call %lu: *device not NULL", k);
            assert_none_live("after a failed open");
            continue;
        }
        /* done without the answer: the device must still build right */
        survived++;
        note_done_without(failed);
        arm(0);
        assert_builds_same(dev, &o, want, "open survived", k);
        atrbvh_device_close(dev);
        assert_none_live("after a close");
    }
    /* (the device name, the platform name and each kernel's largest work
     * group are done without) */
    ck_assert_msg(survived < n, "no failure was reported");
    fprintf(stderr, "open: %lu calls, each failed in turn; %lu done "
            "without (%s)\n", n, survived, done_without);
    atrbvh_bvh_free(want);
}
END_TEST

/* Opens the device (through copies when copy is set); NULL when the
 * first open finds none (the test skips). */
static atrbvh_device *open_dev(const char *test, int copy)
{
    atrbvh_device *dev;
    if (copy)
        setenv("ATRBVH_CL_COPY", "1", 1); /* read at open */
    dev = open_or_skip(test);
    unsetenv("ATRBVH_CL_COPY");
    return dev;
}

/* Each call of a build failed in turn, with `method`; copy: the caller's
 * arrays copied through the handle's buffers.  Twice: the first build on
 * a handle (a fresh one each time: it makes the handle's buffers), then a
 * build on a handle that has built before (one handle throughout).  A
 * build's calls are counted by failing the k-th for k = 1, 2, ... until
 * a build makes fewer than k. */
static void builds_fail_cleanly(const char *test, atrbvh_method method,
                                int copy)
{
    atrbvh_device *dev = NULL;
    atrbvh_build_options o;
    atrbvh_bvh *want;
    int fresh;
    char what[64];
    make_scene();
    atrbvh_build_options_init(&o);
    o.method = method;
    o.max_leaf_size = 8;
    want = cpu_tree(&o);
    for (fresh = 1; fresh >= 0; fresh--) {
        unsigned long k, survived = 0;
        done_without[0] = '\0';
        snprintf(what, sizeof what, "%s %s build%s",
                 fresh ? "a first" : "a later",
                 method == ATRBVH_METHOD_LBVH    ? "LBVH"
                 : method == ATRBVH_METHOD_TRBVH ? "TRBVH"
                                                 : "ATRBVH",
                 copy ? " (copies)" : "");
        if (!fresh) {
            if (!(dev = open_dev(test, copy)))
                break;
            assert_builds_same(dev, &o, want, what, 0);
        }
        for (k = 1;; k++) {
            atrbvh_build_options d = o;
            atrbvh_bvh *got = (atrbvh_bvh *)&d; /* must be set to NULL */
            atrbvh_error e;
            atrbvh_status st;
            char msg[256];
            int hit;
            float *own;
            atrbvh_geometry g;
            if (fresh && !(dev = open_dev(test, copy)))
                break;
            d.device = dev;
            /* the geometry in arrays of its own, freed as soon as the
             * build returns: nothing may read them after that, failed
             * build or not (ASan sees a queued copy that does) */
            own = malloc(sizeof(float) * 9 * N_TRIS);
            ck_assert(own != NULL);
            memcpy(own, tris, sizeof(float) * 9 * N_TRIS);
            g = atrbvh_geometry_triangles(own, 3 * N_TRIS, NULL, N_TRIS);
            arm(k);
            st = atrbvh_build(&g, &d, &got, &e);
            hit = failed != NULL;
            assert_caller_arrays_free(what, k);
            memset(own, 0xff, sizeof(float) * 9 * N_TRIS); /* NaN */
            free(own);
            if (!hit) { /* made fewer than k calls */
                ck_assert_msg(st == ATRBVH_OK, "%s: %s", what, e.text);
                ck_assert_msg(tu_same_bvh(want, got, msg, sizeof msg),
                              "%s: %s", what, msg);
                atrbvh_bvh_free(got);
            } else if (st != ATRBVH_OK) {
                assert_named_failure(st, &e, k, what);
                ck_assert_msg(got == NULL, "%s, call %lu: *out not NULL",
                              what, k);
            } else {
                survived++;
                note_done_without(failed);
                ck_assert_msg(tu_same_bvh(want, got, msg, sizeof msg),
                              "%s survived call %lu (%s): %s", what, k,
                              failed, msg);
                atrbvh_bvh_free(got);
            }
            if (hit) {
                arm(0);
                assert_builds_same(dev, &o, want, what, k);
            }
            if (fresh) {
                atrbvh_device_close(dev);
                assert_none_live(what);
            }
            if (!hit)
                break;
        }
        ck_assert_msg(k > 10, "%s: only %lu OpenCL calls", what, k - 1);
        fprintf(stderr, "%s: %lu calls, each failed in turn; %lu done "
                "without (%s)\n", what, k - 1, survived, done_without);
    }
    if (fresh < 0) { /* (not skipped) */
        atrbvh_device_close(dev);
        assert_none_live(what);
    }
    atrbvh_bvh_free(want);
}

START_TEST(lbvh_build_fails_cleanly_at_each_call)
{
    builds_fail_cleanly(__func__, ATRBVH_METHOD_LBVH, 0);
}
END_TEST

START_TEST(atrbvh_build_fails_cleanly_at_each_call)
{
    builds_fail_cleanly(__func__, ATRBVH_METHOD_ATRBVH, 0);
}
END_TEST

START_TEST(trbvh_build_fails_cleanly_at_each_call)
{
    builds_fail_cleanly(__func__, ATRBVH_METHOD_TRBVH, 0);
}
END_TEST

START_TEST(copied_build_fails_cleanly_at_each_call)
{
    builds_fail_cleanly(__func__, ATRBVH_METHOD_ATRBVH, 1);
}
END_TEST

/* Each call of a closest-hit ray batch failed in turn: the first batch on
 * a handle (fresh each time), then a later one (one handle); in place,
 * then through copies.  The rays and hits of the batch that fails are
 * arrays of their own, freed as soon as it returns. */
START_TEST(ray_batch_fails_cleanly_at_each_call)
{
    enum { N_RAYS = 300 };
    atrbvh_device *dev = NULL;
    atrbvh_build_options o;
    atrbvh_bvh *bvh;
    atrbvh_ray rays[N_RAYS];
    atrbvh_hit want[N_RAYS], got[N_RAYS];
    atrbvh_error e;
    tu_rng r;
    int i, fresh, copy;
    make_scene();
    atrbvh_build_options_init(&o);
    bvh = cpu_tree(&o);
    tu_rng_seed(&r, 11);
    for (i = 0; i < N_RAYS; i++) {
        int c;
        for (c = 0; c < 3; c++) {
            rays[i].origin[c] = 1.0f + 4.0f * tu_rng_float(&r);
            rays[i].dir[c] = tu_rng_float(&r) - 0.5f;
        }
        rays[i].tmin = 0.0f;
        rays[i].tmax = 100.0f;
    }
    ck_assert_int_eq(atrbvh_intersect_batch(bvh, &g_scene, rays, N_RAYS,
                                            want, 1, &e),
                     ATRBVH_OK);
    for (copy = 0; copy <= 1; copy++) {
        for (fresh = 1; fresh >= 0; fresh--) {
            char what[64];
            unsigned long k, survived = 0;
            snprintf(what, sizeof what, "a %s ray batch%s",
                     fresh ? "first" : "later", copy ? " (copies)" : "");
            done_without[0] = '\0';
            if (!fresh) {
                if (!(dev = open_dev(__func__, copy)))
                    break;
                ck_assert_int_eq(atrbvh_intersect_batch_device(
                                     dev, bvh, &g_scene, rays, N_RAYS, got,
                                     NULL, &e),
                                 ATRBVH_OK);
            }
            for (k = 1;; k++) {
                atrbvh_status st;
                int hit;
                atrbvh_ray *own_rays;
                atrbvh_hit *own_hits;
                if (fresh && !(dev = open_dev(__func__, copy)))
                    break;
                own_rays = malloc(sizeof rays);
                own_hits = malloc(sizeof got);
                ck_assert(own_rays && own_hits);
                memcpy(own_rays, rays, sizeof rays);
                arm(k);
                st = atrbvh_intersect_batch_device(dev, bvh, &g_scene,
                                                   own_rays, N_RAYS, own_hits,
                                                   NULL, &e);
                hit = failed != NULL;
                assert_caller_arrays_free(what, k);
                if (st != ATRBVH_OK) {
                    ck_assert_msg(hit, "%s: %s", what, e.text);
                    assert_named_failure(st, &e, k, what);
                } else {
                    survived += hit;
                    if (hit)
                        note_done_without(failed);
                    ck_assert_msg(memcmp(want, own_hits, sizeof want) == 0,
                                  "%s survived call %lu (%s) with other "
                                  "hits", what, k, hit ? failed : "none");
                }
                free(own_rays);
                free(own_hits);
                if (hit) {
                    memset(got, 0xA5, sizeof got);
                    arm(0);
                    ck_assert_msg(atrbvh_intersect_batch_device(
                                      dev, bvh, &g_scene, rays, N_RAYS, got,
                                      NULL, &e) == ATRBVH_OK,
                                  "%s, after call %lu: %s", what, k, e.text);
                    ck_assert_msg(memcmp(want, got, sizeof want) == 0,
                                  "%s after call %lu failed: other hits",
                                  what, k);
                }
                if (fresh) {
                    atrbvh_device_close(dev);
                    assert_none_live(what);
                }
                if (!hit)
                    break;
            }
            ck_assert_msg(k > 5, "%s: only %lu OpenCL calls", what, k - 1);
            fprintf(stderr, "%s: %lu calls, each failed in turn; %lu done "
                    "without (%s)\n", what, k - 1, survived, done_without);
        }
        if (fresh < 0) { /* (not skipped) */
            atrbvh_device_close(dev);
            assert_none_live("rays");
        } else {
            break;
        }
    }
    atrbvh_bvh_free(bvh);
}
END_TEST

/* Each call of a re-optimisation on the device failed in turn, the
 * geometry moved: a refused call leaves the tree as it was
 * (atrbvh_refit(3)), and the same call again gives the CPU's result.  (A
 * refit runs on the host for every device: it must make no OpenCL call.) */
START_TEST(animation_fails_cleanly_at_each_call)
{
    atrbvh_device *dev = open_dev(__func__, 0);
    atrbvh_build_options o;
    atrbvh_geometry moved;
    float *v;
    size_t i;
    int which;
    if (!dev)
        return;
    make_scene();
    atrbvh_build_options_init(&o);
    o.max_leaf_size = 8;
    v = malloc(sizeof(float) * 9 * N_TRIS);
    ck_assert(v != NULL);
    for (i = 0; i < 9 * (size_t)N_TRIS; i++) /* stretched, shifted in x */
        v[i] = tris[i] * 1.25f + (i % 3 == 0 ? 0.5f : 0.0f);
    moved = atrbvh_geometry_triangles(v, 3 * N_TRIS, NULL, N_TRIS);
    for (which = 0; which < 2; which++) {
        atrbvh_status (*op)(atrbvh_bvh *, const atrbvh_geometry *,
                            const atrbvh_build_options *, atrbvh_error *) =
            which ? atrbvh_reoptimise : atrbvh_refit;
        const char *what = which ? "a re-optimisation" : "a refit";
        atrbvh_bvh *want = cpu_tree(&o), *as_built = cpu_tree(&o);
        atrbvh_bvh *b = cpu_tree(&o);
        atrbvh_error e;
        unsigned long k, survived = 0;
        char msg[256];
        ck_assert_int_eq(op(want, &moved, &o, &e), ATRBVH_OK);
        done_without[0] = '\0';
        if (!which) { /* the refit */
            atrbvh_build_options d = o;
            d.device = dev;
            arm(0);
            ck_assert_int_eq(op(b, &moved, &d, &e), ATRBVH_OK);
            ck_assert_msg(calls == 0, "a refit made %lu OpenCL calls",
                          calls);
            ck_assert_msg(tu_same_bvh(want, b, msg, sizeof msg),
                          "a refit on the device: %s", msg);
            atrbvh_bvh_free(b);
            atrbvh_bvh_free(as_built);
            atrbvh_bvh_free(want);
            continue;
        }
        for (k = 1;; k++) {
            atrbvh_build_options d = o;
            atrbvh_status st;
            int hit;
            d.device = dev;
            arm(k);
            st = op(b, &moved, &d, &e);
            hit = failed != NULL;
            assert_caller_arrays_free(what, k);
            if (st != ATRBVH_OK) {
                ck_assert_msg(hit, "%s: %s", what, e.text);
                assert_named_failure(st, &e, k, what);
                ck_assert_msg(tu_same_bvh(as_built, b, msg, sizeof msg),
                              "%s, call %lu (%s) failed: the tree changed: "
                              "%s", what, k, failed, msg);
                arm(0);
                ck_assert_msg(op(b, &moved, &d, &e) == ATRBVH_OK,
                              "%s, after call %lu: %s", what, k, e.text);
            } else if (hit) {
                survived++;
                note_done_without(failed);
            }
            ck_assert_msg(tu_same_bvh(want, b, msg, sizeof msg),
                          "%s, call %lu (%s) failed: not the CPU's tree: %s",
                          what, k, hit ? failed : "none", msg);
            if (!hit)
                break;
            atrbvh_bvh_free(b);
            b = cpu_tree(&o);
        }
        ck_assert_msg(k > 5, "%s: only %lu OpenCL calls", what, k - 1);
        fprintf(stderr, "%s: %lu calls, each failed in turn; %lu done "
                "without (%s)\n", what, k - 1, survived, done_without);
        atrbvh_bvh_free(b);
        atrbvh_bvh_free(as_built);
        atrbvh_bvh_free(want);
    }
    atrbvh_device_close(dev);
    assert_none_live("animation");
    free(v);
}
END_TEST

/* Waits for the queue (clFinish) failing for good, every one from the
 * start, while each call of a build in place, one through copies and a
 * ray batch fails in turn (and then past the last call, nothing else
 * failing).  A call that waited for the queue (the failed wait is waited
 * once more, and that fails too) fails, and the handle is lost: every
 * later build and ray batch on it is refused with a message that says so
 * (even once waits would succeed again), and its close still releases
 * everything.  A call that never waited loses nothing: the handle builds
 * the CPU's tree after it.  (One failed wait alone loses nothing either:
 * the second wait completes the queue; the tests above build again on
 * the handle.) */
static atrbvh_status lost_call(atrbvh_device *dev, int which,
                               const atrbvh_bvh *bvh, atrbvh_error *e)
{
    atrbvh_build_options o;
    atrbvh_ray ray;
    atrbvh_hit hit;
    atrbvh_bvh *got = NULL;
    atrbvh_status st;
    if (which == 2) {
        memset(&ray, 0, sizeof ray);
        ray.origin[0] = ray.origin[1] = ray.origin[2] = 3.0f;
        ray.dir[0] = 1.0f;
        ray.tmax = 100.0f;
        return atrbvh_intersect_batch_device(dev, bvh, &g_scene, &ray, 1,
                                             &hit, NULL, e);
    }
    atrbvh_build_options_init(&o);
    o.device = dev;
    st = atrbvh_build(&g_scene, &o, &got, e);
    atrbvh_bvh_free(got);
    return st;
}

START_TEST(failing_waits_lose_the_handle)
{
    static const char *const name[3] = {"an ATRBVH build",
                                         "an ATRBVH build (copies)",
                                         "a ray batch"};
    atrbvh_build_options o;
    atrbvh_bvh *bvh;
    int which;
    make_scene();
    atrbvh_build_options_init(&o);
    bvh = cpu_tree(&o);
    for (which = 0; which < 3; which++) {
        atrbvh_device *dev = NULL;
        unsigned long k, lost = 0;
        for (k = 1;; k++) {
            atrbvh_error e;
            atrbvh_status st;
            int hit, waited, again;
            const char *call; /* the failed call's name, or "none" */
            if (!dev && !(dev = open_dev(__func__, which == 1)))
                break;
            finish_count = 0;
            finish_fails_from = 1;
            arm(k);
            st = lost_call(dev, which, bvh, &e);
            finish_fails_from = 0;
            hit = failed != NULL;
            /* (a failed call k that was a clFinish is not counted) */
            waited = finish_count > 0 ||
                     (hit && strcmp(failed, "clFinish") == 0);
            call = hit ? failed : "none";
            assert_caller_arrays_free(name[which], k);
            arm(0);
            if (!waited && !hit) { /* past the last call */
                ck_assert_msg(st == ATRBVH_OK, "%s: %s", name[which],
                              e.text);
                break;
            }
            if (!waited) {
                ck_assert_msg(lost_call(dev, which, bvh, &e) == ATRBVH_OK,
                              "%s, call %lu (%s) failed, no wait: the "
                              "handle fails after it: %s",
                              name[which], k, call, e.text);
                continue;
            }
            ck_assert_msg(st != ATRBVH_OK, "%s, call %lu (%s) failed, "
                          "waits failing: the call succeeded", name[which],
                          k, call);
            ck_assert_msg(finish_count > 0, "%s, call %lu: a failed wait "
                          "not waited for again", name[which], k);
            if (!hit)
                ck_assert_msg(strstr(e.text, "clFinish") &&
                                  strstr(e.text, "CL_OUT_OF_RESOURCES (-5)"),
                              "%s, every wait failing: %s", name[which],
                              e.text);
            for (again = 0; again < 3; again += 2) { /* build, rays */
                st = lost_call(dev, again, bvh, &e);
                ck_assert_msg(st == ATRBVH_ERR_BACKEND &&
                                  strstr(e.text, "device lost") &&
                                  strstr(e.text, "CL_OUT_OF_RESOURCES") &&
                                  strstr(e.text, "close the device"),
                              "%s after %s lost the handle (call %lu, %s): "
                              "status %d: %s", name[again], name[which], k,
                              call, (int)st, e.text);
            }
            lost++;
            atrbvh_device_close(dev);
            assert_none_live(name[which]);
            dev = NULL;
            if (!hit)
                break;
        }
        if (!dev && k == 1)
            break; /* (skipped) */
        ck_assert_msg(lost > 0, "%s: no call lost the handle", name[which]);
        fprintf(stderr, "%s: %lu calls failed in turn with every wait "
                "failing; %lu lost the handle\n", name[which], k - 1, lost);
        if (dev) {
            atrbvh_device_close(dev);
            assert_none_live(name[which]);
        }
    }
    atrbvh_bvh_free(bvh);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("clfault");
    TCase *tc = tcase_create("faults");
    int rc;
    tcase_add_loop_test(tc, open_fails_cleanly_at_each_call, 0, 8);
    tcase_add_test(tc, lbvh_build_fails_cleanly_at_each_call);
    tcase_add_test(tc, atrbvh_build_fails_cleanly_at_each_call);
    tcase_add_test(tc, trbvh_build_fails_cleanly_at_each_call);
    tcase_add_test(tc, copied_build_fails_cleanly_at_each_call);
    tcase_add_test(tc, ray_batch_fails_cleanly_at_each_call);
    tcase_add_test(tc, animation_fails_cleanly_at_each_call);
    tcase_add_test(tc, failing_waits_lose_the_handle);
    tcase_set_timeout(tc, 600);
    suite_add_tcase(s, tc);
    rc = tu_run(s);
    free(tris);
    return rc;
}
