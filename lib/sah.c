/*
 * sah.c - the SAH cost of a node array (the slides' equation 1), measured
 * on the tree actually built, never an estimate; and the sums behind it,
 * which the statistics pass over a built tree (bvh.c) shares.
 *
 * The two sums (internal areas; leaf areas times their counts) are taken
 * in node order, serially: the same bits on every run, for any thread
 * count.  They are a chain of dependent additions, so the pass can go no
 * faster than one addition per node and sum; what it can shed is the rest:
 * the areas and the branch on the node's kind.  With AVX (x86, chosen at
 * run time) four nodes' areas are computed at once, lane by lane the
 * operations of atrbvh_i_node_area in its order (the float-to-double
 * conversions, the differences, the products and sums: IEEE, no FMA, the
 * library compiles with -ffp-contract=off), and each node then adds its
 * area to one sum and +0.0 to the other, which leaves that sum's bits: a
 * sum that starts at +0.0 never becomes -0.0, and x + 0.0 is x for every
 * other x, infinities included (a NaN stays a NaN; which NaN an addition
 * of two returns is the compiler's operand order, in either loop).
 * Measured (dragon LBVH, 909,967 nodes, this 2-core machine): 2.8-3.7 ms
 * for the branching loop, 1.2 ms for this one, the same bits.
 */
#include "config.h"

#include "internal.h"

#if (defined(__GNUC__) || defined(__clang__)) &&                            \
    (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define SAH_AVX 1
#endif

static void sums_scalar(const atrbvh_node *nodes, size_t from, size_t m,
                        atrbvh_i_sah_sums *s)
{
    double inner = s->inner, leaves = s->leaf_sum;
    size_t i, count = s->leaves;
    uint32_t largest = s->largest;
    for (i = from; i < m; i++) {
        const double a = atrbvh_i_node_area(&nodes[i]);
        const uint32_t c = nodes[i].count;
        if (c) {
            leaves += a * (double)c;
            count++;
            largest = c > largest ? c : largest;
        } else {
            inner += a;
        }
    }
    s->inner = inner;
    s->leaf_sum = leaves;
    s->leaves = count;
    s->largest = largest;
}

#ifdef SAH_AVX
/* The areas of nodes n[0..3], lane k node k: atrbvh_i_node_area's
 * operations.  Each node's min and max are loaded as four floats (min
 * with max[0], max with index: the fourth lane is not used). */
__attribute__((target("avx"))) static inline __m256d
areas4(const atrbvh_node *n)
{
    const __m256d d0 = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(n[0].max)),
                                     _mm256_cvtps_pd(_mm_loadu_ps(n[0].min)));
    const __m256d d1 = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(n[1].max)),
                                     _mm256_cvtps_pd(_mm_loadu_ps(n[1].min)));
    const __m256d d2 = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(n[2].max)),
                                     _mm256_cvtps_pd(_mm_loadu_ps(n[2].min)));
    const __m256d d3 = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(n[3].max)),
                                     _mm256_cvtps_pd(_mm_loadu_ps(n[3].min)));
    /* (dx dy dz -) of four nodes into dx, dy, dz of the four */
    const __m256d xz01 = _mm256_unpacklo_pd(d0, d1); /* x0 x1 z0 z1 */
    const __m256d y01 = _mm256_unpackhi_pd(d0, d1);  /* y0 y1 - -   */
    const __m256d xz23 = _mm256_unpacklo_pd(d2, d3);
    const __m256d y23 = _mm256_unpackhi_pd(d2, d3);
    const __m256d dx = _mm256_permute2f128_pd(xz01, xz23, 0x20);
    const __m256d dz = _mm256_permute2f128_pd(xz01, xz23, 0x31);
    const __m256d dy = _mm256_permute2f128_pd(y01, y23, 0x20);
    __m256d s = _mm256_mul_pd(dx, dy);
    s = _mm256_add_pd(s, _mm256_mul_pd(dy, dz));
    s = _mm256_add_pd(s, _mm256_mul_pd(dz, dx));
    return _mm256_mul_pd(_mm256_set1_pd(2.0), s);
}

__attribute__((noinline, target("avx"))) static void
sums_avx(const atrbvh_node *nodes, size_t m, atrbvh_i_sah_sums *s)
{
    const __m128i zero = _mm_setzero_si128(), ones = _mm_set1_epi32(-1),
                  sign = _mm_set1_epi32((int)0x80000000u);
    const __m256d two31 = _mm256_set1_pd(2147483648.0);
    __m128i leaves = zero, largest = zero;
    double inner = 0.0, leaf_sum = 0.0;
    uint32_t l4[4], m4[4];
    size_t i;
    int k;
    for (i = 0; i + 4 <= m; i += 4) {
        const atrbvh_node *n = nodes + i;
        const __m256d a = areas4(n);
        const __m128i c = _mm_set_epi32((int)n[3].count, (int)n[2].count,
                                        (int)n[1].count, (int)n[0].count);
        /* the counts as doubles, exactly (unsigned: by the sign flip) */
        const __m256d cd = _mm256_add_pd(
            _mm256_cvtepi32_pd(_mm_xor_si128(c, sign)), two31);
        const __m128i in32 = _mm_cmpeq_epi32(c, zero); /* internal */
        const __m256d in = _mm256_castsi256_pd(_mm256_insertf128_si256(
            _mm256_castsi128_si256(_mm_unpacklo_epi32(in32, in32)),
            _mm_unpackhi_epi32(in32, in32), 1));
        double ia[4], la[4];
        _mm256_storeu_pd(ia, _mm256_and_pd(in, a));
        _mm256_storeu_pd(la, _mm256_andnot_pd(in, _mm256_mul_pd(a, cd)));
        inner += ia[0];
        leaf_sum += la[0];
        inner += ia[1];
        leaf_sum += la[1];
        inner += ia[2];
        leaf_sum += la[2];
        inner += ia[3];
        leaf_sum += la[3];
        leaves = _mm_sub_epi32(leaves, _mm_andnot_si128(in32, ones));
        largest = _mm_max_epu32(largest, c);
    }
    _mm_storeu_si128((__m128i *)(void *)l4, leaves);
    _mm_storeu_si128((__m128i *)(void *)m4, largest);
    s->inner = inner;
    s->leaf_sum = leaf_sum;
    s->leaves = 0;
    s->largest = 0;
    for (k = 0; k < 4; k++) {
        /* per lane at most m/4 < 2^32 leaves (m < 2^32, bvh.c) */
        s->leaves += l4[k];
        s->largest = m4[k] > s->largest ? m4[k] : s->largest;
    }
    /* (the upper YMM halves cleared before the SSE tail: cpu/morton.c) */
    _mm256_zeroupper();
    sums_scalar(nodes, i, m, s);
}
#endif

void atrbvh_i_sah_sum_with(const atrbvh_node *nodes, size_t m, int vector,
                            atrbvh_i_sah_sums *s)
{
#ifdef SAH_AVX
    /* (the lanes count leaves in 32 bits) */
    if (vector && m <= (size_t)UINT32_MAX && __builtin_cpu_supports("avx")) {
        sums_avx(nodes, m, s);
        return;
    }
#endif
    (void)vector;
    s->inner = s->leaf_sum = 0.0;
    s->leaves = 0;
    s->largest = 0;
    sums_scalar(nodes, 0, m, s);
}

void atrbvh_i_sah_sum(const atrbvh_node *nodes, size_t m,
                       atrbvh_i_sah_sums *s)
{
    atrbvh_i_sah_sum_with(nodes, m, 1, s);
}

double atrbvh_sah(const atrbvh_node *nodes, size_t node_count, double ci,
                  double ct)
{
    atrbvh_i_sah_sums s;
    double root;
    if (!nodes || node_count == 0)
        return 0.0;
    root = atrbvh_i_node_area(&nodes[0]);
    if (!(root > 0.0))
        return 0.0;
    atrbvh_i_sah_sum(nodes, node_count, &s);
    return atrbvh_i_sah_total(ci, ct, s.inner, s.leaf_sum, root);
}
