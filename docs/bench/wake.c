/*
 * wake.c - what a 2-thread OpenMP region costs on this machine, and
 * where the guest puts its threads after the process slept: the program
 * behind "The master's spin at a region's end, and where the two
 * threads run" in docs/bench/log.md (4 December).  Not built by the
 * project (Linux: sched_getcpu):
 *
 *   cc -O2 -fopenmp -o /tmp/wake docs/bench/wake.c
 *   OMP_WAIT_POLICY=passive /tmp/wake [ITEMS [REPS]]
 *
 * Part 1: an empty region after 100 us of the master's busy work, with
 * the master sleeping in the region's end barrier (as libgomp does under
 * passive waiting) or spinning until the other thread arrived first (as
 * the library's atrbvh_i_join_arrive does); printed: the region's mean
 * time and when the other thread started in it.
 * Part 2: regions of ITEMS (default 400000) multiply-adds, split
 * statically, each after the master slept 0 (busy waiting instead), 1 or
 * 50 ms; printed: the share of regions whose two threads ran on one CPU
 * (sched_getcpu at the start and the end of each thread's share), the
 * region's time, and each thread's own time in it.
 */
#define _GNU_SOURCE
#include <omp.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now_us(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e6 + (double)t.tv_nsec * 1e-3;
}

static void idle(long us)
{
    if (us > 0) {
        struct timespec s;
        s.tv_sec = us / 1000000;
        s.tv_nsec = (us % 1000000) * 1000;
        nanosleep(&s, NULL);
    } else { /* busy: 100 us */
        const double t0 = now_us();
        while (now_us() - t0 < 100.0)
            ;
    }
}

int main(int argc, char **argv)
{
    const long items = argc > 1 ? atol(argv[1]) : 400000;
    const int reps = argc > 2 ? atoi(argv[2]) : 200;
    static const long sleeps[3] = {0, 1000, 50000};
    float *a = malloc((size_t)items * sizeof *a);
    int spin, s, r;
    long i;
    if (!a || items < 2 || reps < 1)
        return 2;
    for (i = 0; i < items; i++)
        a[i] = (float)i;
#pragma omp parallel num_threads(2)
    {
    }
    for (spin = 0; spin < 2; spin++) {
        double region = 0.0, start = 0.0;
        for (r = 0; r < reps; r++) {
            int arrived = 0;
            double t0, other = 0.0;
            idle(0);
            t0 = now_us();
#pragma omp parallel num_threads(2)
            {
                if (omp_get_thread_num() == 1) {
                    other = now_us();
#pragma omp atomic write
                    arrived = 1;
                } else if (spin) {
                    int seen = 0;
                    while (!seen) {
#pragma omp atomic read
                        seen = arrived;
                    }
                }
            }
            region += now_us() - t0;
            start += other - t0;
        }
        printf("empty region, master %s: %.1f us, the other thread "
               "started after %.1f us\n",
               spin ? "spinning for the other" : "sleeping in the barrier",
               region / reps, start / reps);
    }
    for (s = 0; s < 3; s++) {
        int shared = 0, n = 0;
        double region = 0.0, own[2] = {0.0, 0.0};
        for (r = 0; r < reps / 10 + 1; r++) {
            int k;
            idle(sleeps[s]);
            for (k = 0; k < 6; k++) { /* six regions after each idle spell */
                int cpu[2][2] = {{-1, -1}, {-2, -2}};
                double mine[2] = {0.0, 0.0}, t0 = now_us();
#pragma omp parallel num_threads(2)
                {
                    const int me = omp_get_thread_num();
                    const double m0 = now_us();
                    long j;
                    cpu[me][0] = sched_getcpu();
#pragma omp for schedule(static) nowait
                    for (j = 0; j < items; j++)
                        a[j] = a[j] * 1.0001f + 0.5f;
                    cpu[me][1] = sched_getcpu();
                    mine[me] = now_us() - m0;
                }
                region += now_us() - t0;
                own[0] += mine[0];
                own[1] += mine[1];
                shared += cpu[0][0] == cpu[1][0] || cpu[0][1] == cpu[1][1];
                n++;
            }
        }
        printf("after %s: %d of %d regions with both threads on one CPU; "
               "region %.0f us, the threads' own %.0f and %.0f us\n",
               s == 0 ? "100 us busy" : s == 1 ? "1 ms asleep" : "50 ms asleep",
               shared, n, region / n, own[0] / n, own[1] / n);
    }
    free(a);
    return 0;
}
