/*
 * compare.c - atrbvh_compare: two BVHs bit for bit (constants, nodes,
 * primitive indices), naming the first difference.
 */
#include "config.h"

#include "internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static int same_bits_f32(float a, float b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

static int same_bits_f64(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

static int differ(atrbvh_error *error, uint64_t index, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int differ(atrbvh_error *error, uint64_t index, const char *fmt, ...)
{
    if (error) {
        va_list ap;
        error->status = ATRBVH_OK;
        error->index = index;
        va_start(ap, fmt);
        vsnprintf(error->text, sizeof error->text, fmt, ap);
        va_end(ap);
    }
    return 1;
}

static int differ_f32(atrbvh_error *error, size_t node, const char *field,
                      int k, float a, float b)
{
    uint32_t ba, bb;
    memcpy(&ba, &a, sizeof ba);
    memcpy(&bb, &b, sizeof bb);
    if (a == b || (a != a && b != b)) /* same value, other bits */
        return differ(error, node,
                      "node %lu differs: %s[%d] %.9g vs %.9g (bits 0x%08lx "
                      "vs 0x%08lx)",
                      (unsigned long)node, field, k, (double)a, (double)b,
                      (unsigned long)ba, (unsigned long)bb);
    return differ(error, node, "node %lu differs: %s[%d] %.9g vs %.9g",
                  (unsigned long)node, field, k, (double)a, (double)b);
}

int atrbvh_compare(const atrbvh_bvh *a, const atrbvh_bvh *b,
                   atrbvh_error *error)
{
    size_t i;
    if (!a || !b) {
        atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                      "atrbvh_compare: %s is NULL", !a ? "a" : "b");
        return -1;
    }
    if (!same_bits_f64(a->stats.ci, b->stats.ci))
        return differ(error, (uint64_t)-1, "ci differs: %.17g vs %.17g",
                      a->stats.ci, b->stats.ci);
    if (!same_bits_f64(a->stats.ct, b->stats.ct))
        return differ(error, (uint64_t)-1, "ct differs: %.17g vs %.17g",
                      a->stats.ct, b->stats.ct);
    if (a->node_count != b->node_count)
        return differ(error, (uint64_t)-1, "node count differs: %lu vs %lu",
                      (unsigned long)a->node_count,
                      (unsigned long)b->node_count);
    if (a->prim_count != b->prim_count)
        return differ(error, (uint64_t)-1,
                      "primitive index count differs: %lu vs %lu",
                      (unsigned long)a->prim_count,
                      (unsigned long)b->prim_count);
    for (i = 0; i < a->node_count; i++) {
        const atrbvh_node *x = &a->nodes[i], *y = &b->nodes[i];
        int k;
        for (k = 0; k < 3; k++)
            if (!same_bits_f32(x->min[k], y->min[k]))
                return differ_f32(error, i, "min", k, x->min[k], y->min[k]);
        for (k = 0; k < 3; k++)
            if (!same_bits_f32(x->max[k], y->max[k]))
                return differ_f32(error, i, "max", k, x->max[k], y->max[k]);
        if (x->count != y->count)
            return differ(error, i, "node %lu differs: count %lu vs %lu",
                          (unsigned long)i, (unsigned long)x->count,
                          (unsigned long)y->count);
        if (x->index != y->index)
            return differ(error, i, "node %lu differs: %s %lu vs %lu",
                          (unsigned long)i,
                          x->count ? "first primitive" : "right child",
                          (unsigned long)x->index, (unsigned long)y->index);
    }
    for (i = 0; i < a->prim_count; i++)
        if (a->prim_indices[i] != b->prim_indices[i])
            return differ(error, i, "primitive index %lu differs: %lu vs %lu",
                          (unsigned long)i, (unsigned long)a->prim_indices[i],
                          (unsigned long)b->prim_indices[i]);
    atrbvh_i_clear_error(error);
    return 0;
}
