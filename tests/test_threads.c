/*
 * test_threads.c - several threads using the OpenCL backend at once, first
 * use in the process included: each opens its own device (platform
 * discovery, context, program build), builds the same scene and compares
 * the tree with a CPU build (atrbvh_compare: bit for bit), closes; then
 * several threads share one open handle (their builds serialise on it).
 * Before the process-wide lock around discovery and program builds, PoCL
 * crashed in about 2 runs of 3 here.  Skips, saying so, without an OpenCL
 * device.
 */
#define _POSIX_C_SOURCE 200809L
#include <check.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atrbvh.h"
#include "testutil.h"

/* Under AddressSanitizer (the suite's sanitizer stage): PoCL's LLVM
 * installs its own alternate signal stack, a heap block, in the thread
 * that builds a program; when that thread exits, ASan unmaps what it takes
 * for its own alternate stack and dies ("failed to deallocate 79040
 * bytes", CHECK failed in UnsetAlternateSignalStack).  ASan then must not
 * manage alternate stacks; the environment's ASAN_OPTIONS still apply on
 * top of this.  Unused without ASan. */
const char *__asan_default_options(void);
const char *__asan_default_options(void)
{
    return "use_sigaltstack=0";
}

#define THREADS 4
#define REPEATS 3

typedef struct job {
    const atrbvh_geometry *g;
    const atrbvh_bvh *ref;
    atrbvh_device *shared; /* NULL: open a device of its own */
    atrbvh_status st;
    int same;
    char text[ATRBVH_ERROR_TEXT_LENGTH + 16];
} job;

static void *work(void *arg)
{
    job *j = arg;
    atrbvh_device *dev = j->shared;
    atrbvh_build_options o;
    atrbvh_bvh *b = NULL;
    atrbvh_error e;
    j->same = 0;
    j->text[0] = '\0';
    if (!dev) {
        j->st = atrbvh_device_open("opencl", &dev, &e);
        if (j->st != ATRBVH_OK) {
            snprintf(j->text, sizeof j->text, "open: %s", e.text);
            return NULL;
        }
    }
    atrbvh_build_options_init(&o);
    o.device = dev;
    o.threads = 1;
    j->st = atrbvh_build(j->g, &o, &b, &e);
    if (j->st != ATRBVH_OK) {
        snprintf(j->text, sizeof j->text, "build: %s", e.text);
    } else {
        j->same = atrbvh_compare(j->ref, b, &e) == 0;
        if (!j->same)
            snprintf(j->text, sizeof j->text, "compare: %s", e.text);
    }
    atrbvh_bvh_free(b);
    if (!j->shared)
        atrbvh_device_close(dev);
    return NULL;
}

/* Runs THREADS jobs at once; 0 when OpenCL is unavailable (skip). */
static int run_jobs(const atrbvh_geometry *g, const atrbvh_bvh *ref,
                    atrbvh_device *shared, const char *what)
{
    pthread_t t[THREADS];
    job jobs[THREADS];
    int k, unsupported = 0;
    for (k = 0; k < THREADS; k++) {
        jobs[k].g = g;
        jobs[k].ref = ref;
        jobs[k].shared = shared;
        ck_assert_int_eq(pthread_create(&t[k], NULL, work, &jobs[k]), 0);
    }
    for (k = 0; k < THREADS; k++)
        ck_assert_int_eq(pthread_join(t[k], NULL), 0);
    for (k = 0; k < THREADS; k++)
        unsupported += jobs[k].st == ATRBVH_ERR_UNSUPPORTED;
    if (unsupported == THREADS &&
        tu_opencl_may_skip(ATRBVH_ERR_UNSUPPORTED)) {
        fprintf(stderr, "SKIP %s: no OpenCL device (%s)\n", what,
                jobs[0].text);
        return 0;
    }
    for (k = 0; k < THREADS; k++) {
        ck_assert_msg(jobs[k].st == ATRBVH_OK, "%s, thread %d: %s", what, k,
                      jobs[k].text);
        ck_assert_msg(jobs[k].same, "%s, thread %d: %s", what, k,
                      jobs[k].text);
    }
    return 1;
}

START_TEST(threads_open_build_close)
{
    float *v = tu_random_triangles(4000, 99, 8.0f, -4.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 12000, NULL, 4000);
    atrbvh_bvh *ref = tu_build(&g, NULL); /* CPU: no OpenCL call yet */
    int r;
    /* The first round is the process's first use of OpenCL. */
    for (r = 0; r < REPEATS; r++) {
        char what[64];
        snprintf(what, sizeof what, "own devices, round %d", r);
        if (!run_jobs(&g, ref, NULL, what))
            break;
    }
    atrbvh_bvh_free(ref);
    free(v);
}
END_TEST

START_TEST(threads_share_one_device)
{
    float *v = tu_random_triangles(3000, 7, 2.0f, 0.0f);
    atrbvh_geometry g = atrbvh_geometry_triangles(v, 9000, NULL, 3000);
    atrbvh_bvh *ref = tu_build(&g, NULL);
    atrbvh_device *dev = NULL;
    atrbvh_error e;
    atrbvh_status st = atrbvh_device_open("opencl", &dev, &e);
    if (tu_opencl_may_skip(st)) {
        fprintf(stderr, "SKIP threads_share_one_device: %s\n", e.text);
    } else {
        int r;
        ck_assert_msg(st == ATRBVH_OK, "%s", e.text);
        for (r = 0; r < REPEATS; r++)
            run_jobs(&g, ref, dev, "one shared device");
        atrbvh_device_close(dev);
    }
    atrbvh_bvh_free(ref);
    free(v);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("threads");
    TCase *tc = tcase_create("opencl");
    tcase_add_test(tc, threads_open_build_close);
    tcase_add_test(tc, threads_share_one_device);
    tcase_set_timeout(tc, 600);
    suite_add_tcase(s, tc);
    return tu_run(s);
}
