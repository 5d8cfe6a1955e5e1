/*
 * split.c - triangle splitting, a host pre-process between the bounds and
 * the Morton stage (Karras and Aila, HPG 2013, "triangle splitting"; the
 * older form is Ernst and Greiner's early split clipping).
 *
 * A triangle whose box is much larger than its area suggests (a long thin
 * diagonal sliver, a large slanted quad half) makes every node above it
 * large.  Such a triangle gets several references instead of one, each
 * with the box of the part of the triangle inside one cell of a binary
 * subdivision; the backends then build over references exactly as over
 * primitives (set_prims: a box and the original primitive id per
 * reference), so every backend gives the same tree by construction.
 *
 * Choosing what to split, under a budget of B = budget * n extra
 * references:
 *  - priority p = (2^-d * (A_box - A_ideal))^(1/3), where A_box is the
 *    box's surface area, A_ideal = 2 (|c_x| + |c_y| + |c_z|) with c the
 *    edge cross product (no box around the triangle, nor any set of boxes
 *    around its pieces, has less total area), and d the depth of the most
 *    important plane of the Morton grid that crosses the box (the highest
 *    bit where the quantised box ends differ, in Morton bit order: a plane
 *    near the root of the LBVH weighs most);
 *  - splits per triangle s = floor(D * p) with the largest D whose total
 *    is within B (bisection on D; the totals are integer sums, so the
 *    result does not depend on the thread count);
 *  - each split cuts the current piece at the most important grid plane
 *    crossing its box, the triangle clipped exactly to both halves (in
 *    double, rounded outward to float), and the remaining splits are
 *    shared between the halves in proportion to their longest extent.
 * The grid is the scene box's, at the Morton stage's resolution (2^21 per
 * axis), so cuts fall on the planes the LBVH splits at.  Ties go to the
 * lower axis (x before y before z, as in the Morton key).
 *
 * Leaves may then reference a primitive more than once: the layout's
 * output is post-processed here (atrbvh_i_split_merge) so that no leaf
 * lists a primitive twice.
 */
#include "config.h"

#include "internal.h"

#include <math.h>
#include <string.h>

#define NO_INDEX ((uint64_t)-1)
/* The most splits one triangle gets (its pieces then number at most one
 * more); also bounds the recursion's stack. */
#define MAX_SPLITS 4096u
/* The most references a build may have: 2n - 1 nodes fit in u32 ids. */
#define MAX_REFS 0x7fffffffu

typedef struct grid {
    double lo[3], scale[3]; /* cells = (x - lo) * scale, 2^21 per axis */
    double step[3];         /* extent / 2^21 */
} grid;

static uint32_t quant(const grid *g, int k, float x)
{
    double t = ((double)x - g->lo[k]) * g->scale[k];
    if (!(t > 0.0))
        return 0u;
    if (t >= (double)ATRBVH_MORTON_MAX)
        return ATRBVH_MORTON_MAX;
    return (uint32_t)t;
}

static int high_bit(uint32_t x)
{
    int h = 0;
    while (x >>= 1)
        h++;
    return h;
}

/* The most important grid plane strictly inside box b: its axis, its
 * coordinate and its Morton bit level (62 most important), or -1. */
static int best_plane(const grid *g, const atrbvh_box *b, int *axis,
                      float *at)
{
    int k, best = -1;

    for (k = 0; k < 3; k++) {
        uint32_t qa, qb, cell;
        int h, level;
        float x;
        if (g->scale[k] == 0.0)
            continue;

        qa = quant(g, k, b->min[k]);
        qb = quant(g, k, b->max[k]);
        /* the highest plane between the ends' cells; one that falls on
         * the box's end (rounding, or max exactly on a plane) gives way
         * to the next one below it */
        for (;;) {
            if (qa >= qb)
                break;
            h = high_bit(qa ^ qb);
            cell = (qb >> h) << h;
            x = (float)(g->lo[k] + (double)cell * g->step[k]);
            if (x >= b->max[k]) {
                qb = cell - 1;
                continue;
            }
            if (!(x > b->min[k]))
                qa = qb; /* no plane strictly inside */
            break;
        }
        if (qa >= qb)
            continue;
        level = 3 * h + (2 - k);
        if (level > best) {
            best = level;
            *axis = k;
            *at = x;
        }
    }
    return best;
}

static void tri_vertices(const atrbvh_i_input *in, uint32_t id, double v[3][3])
{
    const atrbvh_geometry *g = in->g;
    int c, k;
    for (c = 0; c < 3; c++) {
        float p[3];
        atrbvh_u64 vid = atrbvh_fetch_vertex_id(
            g->indices, in->istride / sizeof(uint32_t), g->indices != NULL,
            id, c);
        atrbvh_fetch_vertex(g->vertices, in->vstride / sizeof(float), vid, p);
        for (k = 0; k < 3; k++)
            v[c][k] = (double)p[k];
    }
}

static double priority(const grid *g, double v[3][3],
                       const atrbvh_box *b)
{
    double e1[3], e2[3], cx, cy, cz, ideal, excess;
    int axis, level;
    float at;
    int k;
    level = best_plane(g, b, &axis, &at);
    if (level < 0)
        return 0.0;
    for (k = 0; k < 3; k++) {
        e1[k] = v[1][k] - v[0][k];
        e2[k] = v[2][k] - v[0][k];
    }
    cx = e1[1] * e2[2] - e1[2] * e2[1];
    cy = e1[2] * e2[0] - e1[0] * e2[2];
    cz = e1[0] * e2[1] - e1[1] * e2[0];
    ideal = 2.0 * (fabs(cx) + fabs(cy) + fabs(cz));
    excess = atrbvh_box_area(*b) - ideal;
    if (!(excess > 0.0))
        return 0.0;
    return cbrt(ldexp(excess, level - 62));
}

/* Floats bounding [lo, hi] from outside, one ulp wider still. */
static float down(double d)
{
    float f = (float)d;
    if ((double)f > d)
        f = nextafterf(f, -INFINITY);
    return nextafterf(f, -INFINITY);
}

static float up(double d)
{
    float f = (float)d;
    if ((double)f < d)
        f = nextafterf(f, INFINITY);
    return nextafterf(f, INFINITY);
}

/* The box of the triangle clipped to region r, within `clamp` (the
 * triangle's own box); 0 when the clipped part is empty. */
static int clip_box(double v[3][3], const atrbvh_box *r,
                    const atrbvh_box *clamp, atrbvh_box *out)
{
    double a[12][3], b[12][3];
    int na = 3, nb, i, k, side;
    double lo[3], hi[3];
    memcpy(a, v, 3 * sizeof a[0]);
    for (k = 0; k < 3; k++) {
        for (side = 0; side < 2; side++) {
            const double x = side ? (double)r->max[k] : (double)r->min[k];
            nb = 0;
            for (i = 0; i < na; i++) {
                const double *p = a[i], *q = a[(i + 1) % na];
                int pin = side ? p[k] <= x : p[k] >= x;
                int qin = side ? q[k] <= x : q[k] >= x;
                if (pin)
                    memcpy(b[nb++], p, sizeof b[0]);
                if (pin != qin) {
                    double t = (x - p[k]) / (q[k] - p[k]);
                    int j;
                    for (j = 0; j < 3; j++)
                        b[nb][j] = p[j] + t * (q[j] - p[j]);
                    b[nb][k] = x;
                    nb++;
                }
            }
            na = nb;
            if (na == 0)
                return 0;
            memcpy(a, b, (size_t)na * sizeof a[0]);
        }
    }
    for (k = 0; k < 3; k++) {
        lo[k] = hi[k] = a[0][k];
        for (i = 1; i < na; i++) {
            if (a[i][k] < lo[k])
                lo[k] = a[i][k];
            if (a[i][k] > hi[k])
                hi[k] = a[i][k];
        }
        out->min[k] = down(lo[k]);
        out->max[k] = up(hi[k]);
        if (out->min[k] < r->min[k])
            out->min[k] = r->min[k];
        if (out->min[k] < clamp->min[k])
            out->min[k] = clamp->min[k];
        if (out->max[k] > r->max[k])
            out->max[k] = r->max[k];
        if (out->max[k] > clamp->max[k])
            out->max[k] = clamp->max[k];
        if (out->min[k] > out->max[k])
            return 0;
    }
    return 1;
}

static double longest(const atrbvh_box *b)
{
    double e = 0.0;
    int k;
    for (k = 0; k < 3; k++) {
        double d = (double)b->max[k] - (double)b->min[k];
        if (d > e)
            e = d;
    }
    return e;
}

typedef struct piece {
    atrbvh_box region, box;
    uint32_t splits;
} piece;

/* The pieces of one triangle (at most splits + 1 boxes into out, in a
 * fixed depth-first order); returns their count.  stack: room for
 * MAX_SPLITS + 2 pieces. */
static uint32_t split_one(const grid *g, double v[3][3],
                          const atrbvh_box *box, uint32_t splits,
                          piece *stack, atrbvh_box *out)
{
    uint32_t sp = 0, count = 0;
    stack[sp].region = *box;
    stack[sp].box = *box;
    stack[sp++].splits = splits;
    while (sp) {
        piece cur = stack[--sp], l, r;
        int axis = 0, hl, hr;
        float at = 0.0f;
        if (cur.splits == 0 || best_plane(g, &cur.box, &axis, &at) < 0) {
            out[count++] = cur.box;
            continue;
        }
        l.region = cur.region;
        r.region = cur.region;
        l.region.max[axis] = at;
        r.region.min[axis] = at;
        hl = clip_box(v, &l.region, box, &l.box);
        hr = clip_box(v, &r.region, box, &r.box);
        if (!hl || !hr) { /* rounding left one side empty: keep one */
            cur.splits = hl || hr ? cur.splits - 1 : 0;
            if (hl)
                cur.region = l.region, cur.box = l.box;
            else if (hr)
                cur.region = r.region, cur.box = r.box;
            stack[sp++] = cur;
            continue;
        }
        {
            const uint32_t rest = cur.splits - 1;
            const double wl = longest(&l.box), wr = longest(&r.box);
            uint32_t sl = wl + wr > 0.0
                              ? (uint32_t)floor((double)rest * wl / (wl + wr) +
                                                0.5)
                              : rest / 2;
            if (sl > rest)
                sl = rest;
            l.splits = sl;
            r.splits = rest - sl;
        }
        stack[sp++] = r; /* the left piece first */
        stack[sp++] = l;
    }
    return count;
}

/* Sum over triangles of min(floor(d * p), MAX_SPLITS): integer, so the
 * same for any thread count. */
static uint64_t total_splits(const double *p, size_t n, double d, int threads)
{
    uint64_t sum = 0;
    int64_t i;
    (void)threads;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) reduction(+ : sum)
#endif
    for (i = 0; i < (int64_t)n; i++) {
        double s = floor(d * p[i]);
        sum += s >= (double)MAX_SPLITS ? MAX_SPLITS : (uint64_t)s;
    }
    return sum;
}

atrbvh_status atrbvh_i_split_prims(atrbvh_device *dev, atrbvh_i_run *run,
                                   atrbvh_error *error)
{
    const atrbvh_i_config *cfg = run->cfg;
    const int threads = cfg->threads;
    atrbvh_box *boxes = NULL, *refs = NULL, scene, centroids;
    uint32_t *ids = NULL, *ref_ids = NULL, *count = NULL, kept = 0;
    double *prio = NULL;
    uint64_t *offset = NULL, budget, total = 0, want;
    size_t invalid = 0, i;
    atrbvh_status st;
    grid g;
    int k, failed = 0;
    double d, d_lo, d_hi, psum = 0.0;

    st = atrbvh_i_scan_prims(&run->in, cfg, &boxes, &ids, &kept, &scene,
                             &centroids, &invalid, error);
    if (st != ATRBVH_OK)
        return st;
    run->invalid = invalid;
    run->bad = 0;
    run->split_prims = kept;
    for (k = 0; k < 3; k++) {
        const atrbvh_box fr = scene;
        double extent = (double)fr.max[k] - (double)fr.min[k];
        g.lo[k] = (double)fr.min[k];
        g.scale[k] = extent > 0.0
                         ? (double)(1u << ATRBVH_MORTON_BITS) / extent
                         : 0.0;
        g.step[k] = extent / (double)(1u << ATRBVH_MORTON_BITS);
    }
    want = (uint64_t)floor(cfg->split_budget * (double)kept);
    budget = MAX_REFS - (uint64_t)kept;
    if (want < budget)
        budget = want;

    prio = atrbvh_i_alloc_array(kept, sizeof *prio);
    count = atrbvh_i_alloc_array(kept, sizeof *count);
    offset = atrbvh_i_alloc_array((size_t)kept + 1, sizeof *offset);
    if (!prio || !count || !offset) {
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                           "cannot allocate the split priorities of %lu "
                           "triangles",
                           (unsigned long)kept);
        goto done;
    }
    {
        int64_t j;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static)
#endif
        for (j = 0; j < (int64_t)kept; j++) {
            double v[3][3];
            tri_vertices(&run->in, ids ? ids[j] : (uint32_t)j, v);
            prio[j] = priority(&g, v, &boxes[j]);
        }
    }
    for (i = 0; i < kept; i++) /* in index order: the same bits always */
        psum += prio[i];

    /* The largest scale d whose total is within the budget. */
    d = 0.0;
    if (budget > 0 && psum > 0.0) {
        d_lo = (double)budget / psum; /* sum floor(d p) <= d sum p = B */
        d_hi = d_lo;
        for (k = 0; k < 64; k++) {
            d_hi *= 2.0;
            if (total_splits(prio, kept, d_hi, threads) > budget)
                break;
            d_lo = d_hi;
        }
        /* until the total is the budget exactly or the bracket is
         * 2^-24 wide (a fixed sequence of steps: the same everywhere) */
        if (k < 64)
            for (k = 0; k < 24; k++) {
                double mid = 0.5 * (d_lo + d_hi);
                uint64_t t = total_splits(prio, kept, mid, threads);
                if (t > budget) {
                    d_hi = mid;
                } else {
                    d_lo = mid;
                    if (t == budget)
                        break;
                }
            }
        d = d_lo;
    }
    offset[0] = 0;
    for (i = 0; i < kept; i++) {
        double s = floor(d * prio[i]);
        uint32_t si = s >= (double)MAX_SPLITS ? MAX_SPLITS : (uint32_t)s;
        offset[i + 1] = offset[i] + si + 1;
    }
    total = offset[kept];

    refs = atrbvh_i_alloc_array((size_t)total, sizeof *refs);
    ref_ids = atrbvh_i_alloc_array((size_t)total, sizeof *ref_ids);
    if (!refs || !ref_ids) {
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                           "cannot allocate %llu split references",
                           (unsigned long long)total);
        goto done;
    }
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
        piece *stack = atrbvh_i_alloc_array(MAX_SPLITS + 2, sizeof *stack);
        int64_t j;
        if (!stack) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            failed = 1;
        }
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 256)
#endif
        for (j = 0; j < (int64_t)kept; j++) {
            const uint32_t splits =
                (uint32_t)(offset[j + 1] - offset[j] - 1);
            if (!stack)
                continue;
            if (splits == 0) {
                refs[offset[j]] = boxes[j];
                count[j] = 1;
            } else {
                double v[3][3];
                tri_vertices(&run->in, ids ? ids[j] : (uint32_t)j, v);
                count[j] = split_one(&g, v, &boxes[j], splits, stack,
                                     &refs[offset[j]]);
            }
        }
        atrbvh_i_free(stack);
    }
    if (failed) {
        st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                           "cannot allocate the splitting stacks");
        goto done;
    }
    /* Compact in triangle order (a triangle may have found fewer planes
     * than splits), ids alongside; centroids over the references. */
    total = 0;
    centroids.min[0] = centroids.min[1] = centroids.min[2] = INFINITY;
    centroids.max[0] = centroids.max[1] = centroids.max[2] = -INFINITY;
    for (i = 0; i < kept; i++) {
        uint32_t c;
        for (c = 0; c < count[i]; c++) {
            const atrbvh_box b = refs[offset[i] + c];
            refs[total] = b;
            ref_ids[total] = ids ? ids[i] : (uint32_t)i;
            for (k = 0; k < 3; k++) {
                float m = atrbvh_box_centre(b, k);
                if (m < centroids.min[k])
                    centroids.min[k] = m;
                if (m > centroids.max[k])
                    centroids.max[k] = m;
            }
            total++;
        }
    }
    run->n = (uint32_t)total;
    if (total == kept) /* nothing split: an ordinary tree */
        run->split_prims = 0;
    run->scene = scene;
    run->centroids = centroids;
    st = dev->backend->set_prims(dev, run, refs, ref_ids, error);
done:
    atrbvh_i_free(boxes);
    atrbvh_i_free(ids);
    atrbvh_i_free(prio);
    atrbvh_i_free(count);
    atrbvh_i_free(offset);
    atrbvh_i_free(refs);
    atrbvh_i_free(ref_ids);
    return st;
}

/* No leaf lists a primitive twice: within each leaf the first reference
 * of each primitive stays (the order kept), the index array is compacted
 * and the leaves' ranges moved down.  Boxes stay (a leaf's box covers its
 * references, so also the ones kept).  Linear: a stamp per input
 * primitive holds the last leaf that listed it. */
atrbvh_status atrbvh_i_split_merge(atrbvh_bvh *bvh, size_t input_count,
                                   atrbvh_error *error)
{
    size_t i, out = 0;
    uint32_t *stamp = atrbvh_i_alloc_array(input_count, sizeof *stamp);
    if (!stamp)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate %lu primitive stamps",
                             (unsigned long)input_count);
    memset(stamp, 0xff, input_count * sizeof *stamp);
    for (i = 0; i < bvh->node_count; i++) {
        atrbvh_node *nd = &bvh->nodes[i];
        uint32_t a, first = nd->index, kept = 0;
        if (!nd->count)
            continue;
        for (a = 0; a < nd->count; a++) {
            const uint32_t p = bvh->prim_indices[first + a];
            if (stamp[p] == (uint32_t)i)
                continue;
            stamp[p] = (uint32_t)i;
            bvh->prim_indices[out + kept++] = p;
        }
        nd->index = (uint32_t)out;
        nd->count = kept;
        out += kept;
    }
    bvh->prim_count = out;
    atrbvh_i_free(stamp);
    return ATRBVH_OK;
}
