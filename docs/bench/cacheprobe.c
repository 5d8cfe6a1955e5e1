/*
 * cacheprobe.c - how busy the host's shared cache is, for the record of a
 * speed run (docs/run_benchmarks.sh speed writes its line into
 * docs/bench/speed-machine.txt before and after the builds).
 *
 * On a virtual machine the load average shows only this guest's threads;
 * the neighbours that share the host's last-level cache do not appear in
 * it.  This program walks a random cycle through a 4 MiB array (one
 * dependent load after another, so each load waits for the one before:
 * its latency, not bandwidth), SAMPLES times with a pause between, and
 * prints the time per load: about 13-20 ns when the cache holds the
 * array, 40-160 ns when the neighbours have pushed it out to memory.  It
 * measures, it decides nothing, and it does not tell a build's mode
 * (docs/benchmarks.md, "what the slow mode is"): 25 pairs of a 3-sample
 * probe and 10 sibenik LBVH builds (docs/bench/modes.c), 3 December 2026,
 * correlated at -0.11 (probe 33-124 ns, builds 3.8-8.1 ms mean).
 *
 *   cc -O2 -std=c99 -o cacheprobe docs/bench/cacheprobe.c
 *   ./cacheprobe [SAMPLES [PAUSE_MS]]          (default 10 samples, 200 ms)
 */
#define _POSIX_C_SOURCE 199309L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define ARRAY_BYTES ((size_t)4 << 20)
#define LOADS 1000000u

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    const size_t n = ARRAY_BYTES / sizeof(uint32_t);
    const long samples = argc > 1 ? strtol(argv[1], NULL, 10) : 10;
    const long pause = argc > 2 ? strtol(argv[2], NULL, 10) : 200;
    uint32_t *next = malloc(n * sizeof *next), *perm = malloc(n * sizeof *perm);
    double *ns = malloc((samples > 0 ? (size_t)samples : 1) * sizeof *ns);
    uint64_t rng = 0x9e3779b97f4a7c15u;
    uint32_t at = 0;
    volatile uint32_t sink; /* keeps the walk from being optimised away */
    size_t i;
    long s;
    if (samples < 1 || samples > 1000 || pause < 0 || pause > 10000) {
        fprintf(stderr, "usage: cacheprobe [SAMPLES (1-1000) [PAUSE_MS]]\n");
        return 2;
    }
    if (!next || !perm || !ns) {
        fprintf(stderr, "cacheprobe: out of memory\n");
        return 1;
    }
    /* One cycle through every entry in a random order (Fisher-Yates with
     * xorshift64: the same cycle in every run). */
    for (i = 0; i < n; i++)
        perm[i] = (uint32_t)i;
    for (i = n - 1; i > 0; i--) {
        size_t j;
        uint32_t t;
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        j = (size_t)(rng % (uint64_t)(i + 1));
        t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    for (i = 0; i < n; i++)
        next[perm[i]] = perm[(i + 1) % n];
    for (s = 0; s < samples; s++) {
        const struct timespec p = {pause / 1000, (pause % 1000) * 1000000L};
        double t0;
        uint32_t k;
        t0 = now_ms();
        for (k = 0; k < LOADS; k++)
            at = next[at];
        ns[s] = (now_ms() - t0) * 1e6 / LOADS;
        sink = at;
        if (s + 1 < samples)
            nanosleep(&p, NULL);
    }
    qsort(ns, (size_t)samples, sizeof *ns, cmp);
    (void)sink;
    printf("%.1f ns per load, median of %ld (%.1f-%.1f; a 4 MiB random "
           "cycle)\n",
           ns[samples / 2], samples, ns[0], ns[samples - 1]);
    free(next);
    free(perm);
    free(ns);
    return 0;
}
