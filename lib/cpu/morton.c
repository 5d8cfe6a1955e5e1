/*
 * cpu/morton.c - stage "morton": a 63-bit Morton key (21 bits per axis, x
 * the most significant of each triplet) for the centre of each primitive
 * box, normalised to the centroid box (Lauterbach et al. 2009; Karras
 * 2012).  The frame (lo, scale) is the pipeline's, computed once on the
 * host for every backend; the per-item rule is shared/arith.h's.  The
 * same sweep writes the sort's values (the build indices, as the OpenCL
 * morton kernel does) and the OR and AND of all keys, from which the sort
 * knows the bits that vary without reading the keys again.
 *
 * The sweep also counts the sort's MSD digits (sort.c), per block of the
 * sort's own block ranges, on a guess of the digit: the top varying bit
 * of the keys is nearly always that of the first axis whose centroid
 * extent is not zero (x, bit 62; y, 61; z, 60), as the centroids at the
 * box's two ends quantise to 0 and 2^21-1 on it.  The sort checks the
 * guess against the real varying bits and counts again when it is wrong
 * (its result is the same either way); when right, the pass between
 * counting and scattering - a barrier, a thread hand-over - is saved.
 */
#include "config.h"

#include "cpu.h"
#include "shared/sort.h"

#include <string.h>

#if (defined(__GNUC__) || defined(__clang__)) &&                            \
    (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define MORTON_AVX2 1
#endif

/* The keys of boxes lo .. hi-1, one at a time: the per-item rule of
 * shared/arith.h, which the OpenCL morton kernel runs. */
static void keys_scalar(const atrbvh_box *boxes, uint32_t lo, uint32_t hi,
                        const double *flo, const double *fs, uint64_t *keys)
{
    uint32_t i;
    for (i = lo; i < hi; i++) {
        const atrbvh_box bx = boxes[i];
        keys[i] = atrbvh_morton_key(
            atrbvh_morton_quantise(atrbvh_box_centre(bx, 0), flo[0], fs[0]),
            atrbvh_morton_quantise(atrbvh_box_centre(bx, 1), flo[1], fs[1]),
            atrbvh_morton_quantise(atrbvh_box_centre(bx, 2), flo[2], fs[2]));
    }
}

#ifdef MORTON_AVX2
/* Floats ahead of the current eight boxes that are prefetched. */
#define MORTON_AHEAD 384

/* atrbvh_morton_spread of four 21-bit values, one per 64-bit lane: the
 * shift-and-mask ladder that test_stages checks the table against. */
__attribute__((target("avx2"))) static inline __m256i spread4(__m256i x)
{
    x = _mm256_and_si256(_mm256_or_si256(x, _mm256_slli_epi64(x, 32)),
                         _mm256_set1_epi64x(0x1f00000000ffffLL));
    x = _mm256_and_si256(_mm256_or_si256(x, _mm256_slli_epi64(x, 16)),
                         _mm256_set1_epi64x(0x1f0000ff0000ffLL));
    x = _mm256_and_si256(_mm256_or_si256(x, _mm256_slli_epi64(x, 8)),
                         _mm256_set1_epi64x(0x100f00f00f00f00fLL));
    x = _mm256_and_si256(_mm256_or_si256(x, _mm256_slli_epi64(x, 4)),
                         _mm256_set1_epi64x(0x10c30c30c30c30c3LL));
    x = _mm256_and_si256(_mm256_or_si256(x, _mm256_slli_epi64(x, 2)),
                         _mm256_set1_epi64x(0x1249249249249249LL));
    return x;
}

/* atrbvh_morton_quantise of four centres, spread: the same double
 * operations (the conversion, the difference, the product), then what
 * its two tests return - 0 where t > 0 fails (NaN included: an ordered,
 * quiet compare), 2^21 - 1 where t >= 2^21 - 1 - and the truncation of
 * the rest, which lies in (0, 2^21 - 1). */
__attribute__((target("avx2"))) static inline __m256i
quantise4(__m128 c, __m256d lo, __m256d scale)
{
    const __m256d most = _mm256_set1_pd((double)ATRBVH_MORTON_MAX);
    __m256d t = _mm256_mul_pd(_mm256_sub_pd(_mm256_cvtps_pd(c), lo), scale);
    const __m256d pos = _mm256_cmp_pd(t, _mm256_setzero_pd(), _CMP_GT_OQ);
    const __m256d big = _mm256_cmp_pd(t, most, _CMP_GE_OQ);
    t = _mm256_blendv_pd(_mm256_and_pd(t, pos), most, big);
    return spread4(_mm256_cvtepu32_epi64(_mm256_cvttpd_epi32(t)));
}

/* keys_scalar, eight boxes at a time: each coordinate of the eight
 * gathered into one vector (a box is six floats), the centres as
 * atrbvh_box_centre computes them (0.5f * min + 0.5f * max, float), then
 * four keys at a time; the last hi - lo mod 8 one at a time.  The same
 * bits (test_stages: morton_keys_vector_is_scalar). */
__attribute__((noinline, target("avx2"))) static void
keys_avx2(const atrbvh_box *boxes, uint32_t lo, uint32_t hi,
          const double *flo, const double *fs, uint64_t *keys)
{
    const __m256i idx = _mm256_setr_epi32(0, 6, 12, 18, 24, 30, 36, 42);
    const __m256 half = _mm256_set1_ps(0.5f);
    const __m256d lo0 = _mm256_set1_pd(flo[0]), lo1 = _mm256_set1_pd(flo[1]),
                  lo2 = _mm256_set1_pd(flo[2]), s0 = _mm256_set1_pd(fs[0]),
                  s1 = _mm256_set1_pd(fs[1]), s2 = _mm256_set1_pd(fs[2]);
    uint32_t i;
    for (i = lo; hi - i >= 8u; i += 8u) {
        const float *f = (const float *)(boxes + i);
        _mm_prefetch((const char *)(f + MORTON_AHEAD), _MM_HINT_T0);
        _mm_prefetch((const char *)(f + MORTON_AHEAD + 16), _MM_HINT_T0);
        _mm_prefetch((const char *)(f + MORTON_AHEAD + 32), _MM_HINT_T0);
        const __m256 cx = _mm256_add_ps(
            _mm256_mul_ps(half, _mm256_i32gather_ps(f + 0, idx, 4)),
            _mm256_mul_ps(half, _mm256_i32gather_ps(f + 3, idx, 4)));
        const __m256 cy = _mm256_add_ps(
            _mm256_mul_ps(half, _mm256_i32gather_ps(f + 1, idx, 4)),
            _mm256_mul_ps(half, _mm256_i32gather_ps(f + 4, idx, 4)));
        const __m256 cz = _mm256_add_ps(
            _mm256_mul_ps(half, _mm256_i32gather_ps(f + 2, idx, 4)),
            _mm256_mul_ps(half, _mm256_i32gather_ps(f + 5, idx, 4)));
        __m256i k;
        k = _mm256_or_si256(
            _mm256_or_si256(
                _mm256_slli_epi64(
                    quantise4(_mm256_castps256_ps128(cx), lo0, s0), 2),
                _mm256_slli_epi64(
                    quantise4(_mm256_castps256_ps128(cy), lo1, s1), 1)),
            quantise4(_mm256_castps256_ps128(cz), lo2, s2));
        _mm256_storeu_si256((__m256i *)(keys + i), k);
        k = _mm256_or_si256(
            _mm256_or_si256(
                _mm256_slli_epi64(
                    quantise4(_mm256_extractf128_ps(cx, 1), lo0, s0), 2),
                _mm256_slli_epi64(
                    quantise4(_mm256_extractf128_ps(cy, 1), lo1, s1), 1)),
            quantise4(_mm256_extractf128_ps(cz, 1), lo2, s2));
        _mm256_storeu_si256((__m256i *)(keys + i + 4), k);
    }
    /* The upper halves of the YMM registers cleared for the SSE code
     * that runs next, this library's or the caller's: GCC does it only
     * at -O2 and above, and not before a tail call such as the one below
     * (docs/architecture.md; tests/test_vecstate.c). */
    _mm256_zeroupper();
    keys_scalar(boxes, i, hi, flo, fs, keys);
}
#endif

void atrbvh_i_morton_keys_with(const atrbvh_box *boxes, uint32_t lo,
                               uint32_t hi, const double flo[3],
                               const double fs[3], uint64_t *keys,
                               int vector)
{
#ifdef MORTON_AVX2
    if (vector && __builtin_cpu_supports("avx2")) {
        keys_avx2(boxes, lo, hi, flo, fs, keys);
        return;
    }
#endif
    (void)vector;
    keys_scalar(boxes, lo, hi, flo, fs, keys);
}

/* Keys per chunk of a block's sweep: 4 KiB of keys. */
#define MORTON_CHUNK 512u

atrbvh_status atrbvh_i_cpu_morton(atrbvh_device *dev, atrbvh_i_run *run,
                                  atrbvh_error *error)
{
    atrbvh_i_cpu_run *c = run->state;
    const atrbvh_box *const boxes = c->boxes;
    const double flo[3] = {run->morton_lo[0], run->morton_lo[1],
                           run->morton_lo[2]},
                 fs[3] = {run->morton_scale[0], run->morton_scale[1],
                          run->morton_scale[2]};
    const double s0 = fs[0], s1 = fs[1], s2 = fs[2];
    const int vector = atrbvh_i_avx2();
    const uint32_t n = run->n;
    const int blocks = (int)atrbvh_i_sort_blocks(n, run->cfg->threads);
    const int team = atrbvh_i_team(blocks, run->cfg->threads);
    uint64_t *keys, key_or = 0, key_and = ~(uint64_t)0;
    atrbvh_i_join join = {0};
    uint32_t *order, *counts = NULL;
    atrbvh_u32 sh = 0, bi = 1; /* (no guess: a 2-entry dummy row) */
    uint32_t shift, bits;
    int b, top = -1;
    (void)dev;
    keys = c->keys = atrbvh_i_scratch_get(c->scratch, CPU_KEYS, run->n,
                                          sizeof *c->keys);
    order = c->order = atrbvh_i_scratch_get(c->scratch, CPU_ORDER, run->n,
                                            sizeof *c->order);
    if (!keys || !order)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                             "cannot allocate Morton keys for %lu primitives",
                             (unsigned long)run->n);
    /* The guess of the top varying bit (the file's comment). */
    if (s0 > 0.0)
        top = 62;
    else if (s1 > 0.0)
        top = 61;
    else if (s2 > 0.0)
        top = 60;
    atrbvh_i_free(c->msd_counts);
    c->msd_counts = NULL;
    if (n >= 2 && top >= 0) {
        atrbvh_sort_msd(n, (uint64_t)1 << top, &sh, &bi);
        counts = atrbvh_i_alloc_array((size_t)blocks << bi, sizeof *counts);
        if (!counts)
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                                 "cannot allocate sort counters for %lu "
                                 "primitives",
                                 (unsigned long)run->n);
    }
    /* (copies: the region reads the variables whose addresses were taken
     * through pointers, again after every store of a key) */
    shift = sh;
    bits = bi;
#ifdef _OPENMP
#pragma omp parallel num_threads(team)
#endif
    {
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1) nowait \
    reduction(| : key_or) reduction(& : key_and)
#endif
        for (b = 0; b < blocks; b++) {
            uint32_t dummy[2],
                *cnt = counts ? counts + ((size_t)b << bits) : dummy;
            uint32_t lo, hi, c0, c1;
            int64_t i;
            atrbvh_block_range(n, (atrbvh_u32)b, (atrbvh_u32)blocks, &lo,
                               &hi);
            memset(cnt, 0, ((size_t)1 << bits) * sizeof *cnt);
            /* A chunk's keys (vector where the CPU can), then, while they
             * are in the first-level cache, the rest of the sweep over
             * them. */
            for (c0 = lo; c0 < hi; c0 = c1) {
                c1 = hi - c0 > MORTON_CHUNK ? c0 + MORTON_CHUNK : hi;
                atrbvh_i_morton_keys_with(boxes, c0, c1, flo, fs, keys,
                                          vector);
                for (i = c0; i < (int64_t)c1; i++) {
                    const uint64_t key = keys[i];
                    order[i] = (uint32_t)i;
                    cnt[atrbvh_sort_digit_bits(key, shift, bits)]++;
                    key_or |= key;
                    key_and &= key;
                }
            }
        }
        atrbvh_i_join_arrive(&join);
    }
    c->key_varying = key_or ^ key_and;
    c->msd_counts = counts;
    c->msd_blocks = (uint32_t)blocks;
    c->msd_shift = shift;
    c->msd_bits = bits;
    return ATRBVH_OK;
}
