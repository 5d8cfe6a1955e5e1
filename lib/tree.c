/*
 * tree.c - the binary tree's arrays outside a build (stage capture): alloc,
 * copy, free; and the capture's release.
 */
#include "config.h"

#include "internal.h"

#include <stdlib.h>
#include <string.h>

atrbvh_status atrbvh_i_tree_alloc(atrbvh_i_tree *t, uint32_t n, int values)
{
    size_t nodes = 2 * (size_t)n - 1, inner = n > 1 ? (size_t)n - 1 : 1;
    memset(t, 0, sizeof *t);
    t->n = n;
    t->left = atrbvh_i_alloc_array(inner, sizeof *t->left);
    t->right = atrbvh_i_alloc_array(inner, sizeof *t->right);
    t->parent = atrbvh_i_alloc_array(nodes, sizeof *t->parent);
    t->count = atrbvh_i_alloc_array(nodes, sizeof *t->count);
    t->leaf_prim = atrbvh_i_alloc_array(n, sizeof *t->leaf_prim);
    if (values) {
        t->box = atrbvh_i_alloc_array(nodes, sizeof *t->box);
        t->cost = atrbvh_i_alloc_array(nodes, sizeof *t->cost);
    }
    if (!t->left || !t->right || !t->parent || !t->count || !t->leaf_prim ||
        (values && (!t->box || !t->cost))) {
        atrbvh_i_tree_free(t);
        return ATRBVH_ERR_NOMEM;
    }
    return ATRBVH_OK;
}

void atrbvh_i_tree_free(atrbvh_i_tree *t)
{
    atrbvh_i_free(t->left);
    atrbvh_i_free(t->right);
    atrbvh_i_free(t->parent);
    atrbvh_i_free(t->count);
    atrbvh_i_free(t->box);
    atrbvh_i_free(t->cost);
    atrbvh_i_free(t->leaf_prim);
    memset(t, 0, sizeof *t);
}

atrbvh_status atrbvh_i_tree_copy(atrbvh_i_tree *dst, const atrbvh_i_tree *src,
                                 int values)
{
    size_t n = src->n, nodes = 2 * n - 1, inner = n > 1 ? n - 1 : 1;
    values = values && src->box != NULL && src->cost != NULL;
    if (atrbvh_i_tree_alloc(dst, src->n, values) != ATRBVH_OK)
        return ATRBVH_ERR_NOMEM;
    memcpy(dst->left, src->left, inner * sizeof *dst->left);
    memcpy(dst->right, src->right, inner * sizeof *dst->right);
    memcpy(dst->parent, src->parent, nodes * sizeof *dst->parent);
    memcpy(dst->count, src->count, nodes * sizeof *dst->count);
    memcpy(dst->leaf_prim, src->leaf_prim, n * sizeof *dst->leaf_prim);
    if (values) {
        memcpy(dst->box, src->box, nodes * sizeof *dst->box);
        memcpy(dst->cost, src->cost, nodes * sizeof *dst->cost);
    }
    return ATRBVH_OK;
}

uint32_t *atrbvh_i_sizes_counted(const uint32_t *left, const uint32_t *right,
                                 const unsigned char *flat, uint32_t n)
{
    const size_t nodes = 2 * (size_t)n - 1;
    uint32_t *size = atrbvh_i_alloc_array(nodes, sizeof *size);
    uint32_t *queue = atrbvh_i_alloc_array(nodes, sizeof *queue);
    size_t head = 0, tail = 0;
    if (!size || !queue) {
        atrbvh_i_free(size);
        atrbvh_i_free(queue);
        return NULL;
    }
    queue[tail++] = 0;
    while (head < tail) { /* (every node once: the tree's) */
        const uint32_t x = queue[head++];
        if (x < n - 1) {
            queue[tail++] = left[x];
            queue[tail++] = right[x];
        }
    }
    while (tail > 0) {
        const uint32_t x = queue[--tail];
        size[x] = x < n - 1 ? atrbvh_size_counted(flat[x], size[left[x]],
                                                  size[right[x]])
                            : 1u | ATRBVH_SIZE_LEAF;
    }
    atrbvh_i_free(queue);
    return size;
}

void atrbvh_i_capture_free(atrbvh_i_capture *c)
{
    atrbvh_i_free(c->prim_boxes);
    atrbvh_i_free(c->keys);
    atrbvh_i_free(c->sorted_keys);
    atrbvh_i_free(c->order);
    atrbvh_i_free(c->collapse_size);
    atrbvh_i_tree_free(&c->hierarchy);
    atrbvh_i_tree_free(&c->refit);
    atrbvh_i_tree_free(&c->optimise);
    memset(c, 0, sizeof *c);
}

/* ------------------------------------------------------------ scratch */
static unsigned home_of(const atrbvh_i_scratch *s, unsigned role)
{
    return s->home[role] ? (unsigned)s->home[role] - 1u : role;
}

void *atrbvh_i_scratch_get(atrbvh_i_scratch *s, unsigned slot, size_t count,
                           size_t size)
{
    size_t bytes;
    unsigned k;
    if (slot >= ATRBVH_I_SCRATCH_SLOTS || !atrbvh_i_mul_size(count, size, &bytes))
        return NULL;
    k = home_of(s, slot);
    s->live |= (uint32_t)1 << slot;
    if (bytes == 0)
        bytes = 1;
    if (s->ptr[k] && s->bytes[k] >= bytes)
        return s->ptr[k];
    if (bytes < s->reserve[k])
        bytes = s->reserve[k];
    {
        /* Another live role in the slot (outside the plan: more
         * primitives than planned for): its contents move along. */
        unsigned r;
        for (r = 0; r < ATRBVH_I_SCRATCH_SLOTS; r++)
            if (r != slot && ((s->live >> r) & 1u) && home_of(s, r) == k &&
                s->ptr[k]) {
                void *grown = atrbvh_i_malloc(bytes);
                if (!grown)
                    return NULL; /* the old contents stay */
                atrbvh_i_advise_huge(grown, bytes);
                memcpy(grown, s->ptr[k], s->bytes[k]);
                atrbvh_i_free(s->ptr[k]);
                s->ptr[k] = grown;
                s->bytes[k] = bytes;
                return grown;
            }
    }
    atrbvh_i_free(s->ptr[k]);
    s->ptr[k] = atrbvh_i_malloc(bytes);
    s->bytes[k] = s->ptr[k] ? bytes : 0;
    if (s->ptr[k])
        atrbvh_i_advise_huge(s->ptr[k], bytes);
    return s->ptr[k];
}

static void free_slot(atrbvh_i_scratch *s, unsigned k)
{
    unsigned r;
    for (r = 0; r < ATRBVH_I_SCRATCH_SLOTS; r++)
        if (home_of(s, r) == k)
            s->live &= ~((uint32_t)1 << r);
    atrbvh_i_free(s->ptr[k]);
    s->ptr[k] = NULL;
    s->bytes[k] = 0;
    s->reserve[k] = 0;
}

void atrbvh_i_scratch_done(atrbvh_i_scratch *s, unsigned slot)
{
    unsigned k, r;
    if (slot >= ATRBVH_I_SCRATCH_SLOTS)
        return;
    s->live &= ~((uint32_t)1 << slot);
    k = home_of(s, slot);
    if (!s->transient || s->reserve[k])
        return;
    for (r = 0; r < ATRBVH_I_SCRATCH_SLOTS; r++)
        if (((s->live >> r) & 1u) && home_of(s, r) == k)
            return; /* another role still reads the slot */
    free_slot(s, k);
}

void atrbvh_i_scratch_release(atrbvh_i_scratch *s, unsigned slot)
{
    if (slot < ATRBVH_I_SCRATCH_SLOTS)
        free_slot(s, home_of(s, slot));
}

void *atrbvh_i_scratch_take(atrbvh_i_scratch *s, unsigned slot,
                            size_t *bytes)
{
    unsigned k;
    void *p;
    *bytes = 0;
    if (slot >= ATRBVH_I_SCRATCH_SLOTS)
        return NULL;
    k = home_of(s, slot);
    p = s->ptr[k];
    if (p)
        *bytes = s->bytes[k];
    s->ptr[k] = NULL; /* free_slot then frees nothing */
    free_slot(s, k);
    return p;
}

int atrbvh_i_scratch_adopt(atrbvh_i_scratch *s, unsigned slot, void *p,
                           size_t bytes)
{
    unsigned k, r;
    if (slot >= ATRBVH_I_SCRATCH_SLOTS || !p)
        return 0;
    k = home_of(s, slot);
    if (!s->reserve[k] || bytes < s->reserve[k] ||
        (s->ptr[k] && s->bytes[k] >= s->reserve[k]))
        return 0;
    for (r = 0; r < ATRBVH_I_SCRATCH_SLOTS; r++)
        if (((s->live >> r) & 1u) && home_of(s, r) == k)
            return 0;
    atrbvh_i_free(s->ptr[k]);
    s->ptr[k] = p;
    s->bytes[k] = bytes;
    return 1;
}

void atrbvh_i_scratch_plan_reset(atrbvh_i_scratch *s)
{
    memset(s->home, 0, sizeof s->home);
    memset(s->reserve, 0, sizeof s->reserve);
    s->live = 0;
}

void atrbvh_i_scratch_share(atrbvh_i_scratch *s, unsigned role, unsigned slot)
{
    if (role < ATRBVH_I_SCRATCH_SLOTS && slot < ATRBVH_I_SCRATCH_SLOTS)
        s->home[role] = (unsigned char)(home_of(s, slot) + 1u);
}

void atrbvh_i_scratch_reserve(atrbvh_i_scratch *s, unsigned slot,
                              size_t count, size_t size)
{
    size_t bytes;
    if (slot < ATRBVH_I_SCRATCH_SLOTS)
        s->reserve[home_of(s, slot)] =
            atrbvh_i_mul_size(count, size, &bytes) ? bytes : 0;
}

void atrbvh_i_scratch_free(atrbvh_i_scratch *s)
{
    unsigned k;
    for (k = 0; k < ATRBVH_I_SCRATCH_SLOTS; k++)
        atrbvh_i_free(s->ptr[k]);
    memset(s, 0, sizeof *s);
}
