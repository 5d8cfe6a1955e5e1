/*
 * api.c - version, errors, the replaceable allocator, option defaults and
 * validation, and the small helpers every stage uses.
 */
#if defined(__linux__)
#define _DEFAULT_SOURCE /* madvise, MADV_HUGEPAGE (atrbvh_i_advise_huge) */
#endif
#include "config.h"

#include "internal.h"
#include "shared/treelet.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

/* ----------------------------------------------------------------- version */
unsigned atrbvh_version(void)
{
    return ATRBVH_VERSION_HEX;
}

const char *atrbvh_version_string(void)
{
    return ATRBVH_VERSION_STRING;
}

/* ------------------------------------------------------------------ errors */
const char *atrbvh_strerror(atrbvh_status status)
{
    switch (status) {
    case ATRBVH_OK:
        return "success";
    case ATRBVH_ERR_INVALID_ARGUMENT:
        return "invalid argument";
    case ATRBVH_ERR_NO_PRIMITIVES:
        return "no primitives";
    case ATRBVH_ERR_NONFINITE:
        return "NaN or infinite coordinate";
    case ATRBVH_ERR_INDEX_RANGE:
        return "vertex index out of range";
    case ATRBVH_ERR_TOO_LARGE:
        return "too large";
    case ATRBVH_ERR_NOMEM:
        return "out of memory";
    case ATRBVH_ERR_IO:
        return "input/output error";
    case ATRBVH_ERR_FORMAT:
        return "invalid file format";
    case ATRBVH_ERR_UNSUPPORTED:
        return "not supported by this build";
    case ATRBVH_ERR_BACKEND:
        return "compute backend failure";
    case ATRBVH_ERR_CANCELLED:
        return "cancelled";
    }
    return "unknown status";
}

atrbvh_status atrbvh_i_fail(atrbvh_error *error, atrbvh_status status,
                            uint64_t index, const char *fmt, ...)
{
    if (error) {
        va_list ap;
        error->status = status;
        error->index = index;
        va_start(ap, fmt);
        vsnprintf(error->text, sizeof error->text, fmt, ap);
        va_end(ap);
    }
    return status;
}

void atrbvh_i_clear_error(atrbvh_error *error)
{
    if (error) {
        error->status = ATRBVH_OK;
        error->index = (uint64_t)-1;
        error->text[0] = '\0';
    }
}

/* --------------------------------------------------------------- allocator */
static atrbvh_malloc_fn user_malloc = NULL;
static atrbvh_free_fn user_free = NULL;

void atrbvh_set_allocator(atrbvh_malloc_fn malloc_fn, atrbvh_free_fn free_fn)
{
    if (malloc_fn && free_fn) {
        user_malloc = malloc_fn;
        user_free = free_fn;
    } else {
        user_malloc = NULL;
        user_free = NULL;
    }
}

void atrbvh_get_allocator(atrbvh_malloc_fn *malloc_fn, atrbvh_free_fn *free_fn)
{
    if (malloc_fn)
        *malloc_fn = user_malloc ? user_malloc : malloc;
    if (free_fn)
        *free_fn = user_free ? user_free : free;
}

void *atrbvh_i_malloc(size_t size)
{
    if (size == 0)
        size = 1;
    return user_malloc ? user_malloc(size) : malloc(size);
}

void atrbvh_i_free(void *ptr)
{
    if (!ptr)
        return;
    if (user_free)
        user_free(ptr);
    else
        free(ptr);
}

void atrbvh_free(void *ptr)
{
    atrbvh_i_free(ptr);
}

int atrbvh_i_mul_size(size_t count, size_t size, size_t *out)
{
    if (size != 0 && count > SIZE_MAX / size) {
        *out = 0;
        return 0;
    }
    *out = count * size;
    return 1;
}

/* Large arrays are fresh memory: the C library maps a block of more than
 * its threshold (at most 32 MiB) at every allocation and unmaps it when
 * freed, so every build of a large scene first touched its scratch and its
 * output (the nodes, 32 bytes each) 4 KiB per page fault, again and again
 * on a reused device.  Advising transparent huge pages over the 2 MiB-
 * aligned part makes that 512 times fewer faults where the system allows
 * it; the advice changes no contents and its failure nothing. */
void atrbvh_i_advise_huge(void *p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const uintptr_t huge = (uintptr_t)1 << 21;
    const uintptr_t lo = ((uintptr_t)p + huge - 1) & ~(huge - 1),
                    hi = ((uintptr_t)p + bytes) & ~(huge - 1);
    /* only memory of the C library's malloc: a replaced allocator's
     * blocks (a pool, a mapping with its own flags) are its business */
    if (p && !user_malloc && bytes >= 4 * huge && hi > lo)
        (void)madvise((void *)lo, (size_t)(hi - lo), MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

int atrbvh_i_avx2(void)
{
#if (defined(__GNUC__) || defined(__clang__)) &&                            \
    (defined(__x86_64__) || defined(__i386__))
    const char *no = getenv("ATRBVH_NO_AVX2");
    if (no && no[0] && strcmp(no, "0") != 0)
        return 0;
    return __builtin_cpu_supports("avx2");
#else
    return 0;
#endif
}

void *atrbvh_i_alloc_array(size_t count, size_t size)
{
    size_t bytes;
    void *p;
    if (!atrbvh_i_mul_size(count, size, &bytes))
        return NULL;
    p = atrbvh_i_malloc(bytes);
    atrbvh_i_advise_huge(p, bytes);
    return p;
}

/* ----------------------------------------------------------------- threads */
int atrbvh_i_resolve_threads(int requested)
{
#ifdef _OPENMP
    int n;
    if (requested > 0)
        return requested;
    /* The default (OMP_NUM_THREADS) is held to the same limit. */
    n = omp_get_max_threads();
    return n > ATRBVH_MAX_THREADS ? ATRBVH_MAX_THREADS : n;
#else
    (void)requested;
    return 1;
#endif
}

void atrbvh_i_join_arrive(atrbvh_i_join *j)
{
#ifdef _OPENMP
    const int team = omp_get_num_threads();
    int done, k;
    if (team < 2)
        return;
#pragma omp atomic capture
    done = ++j->done;
    if (omp_get_thread_num() != 0)
        return;
    for (k = 0; done < team && k < ATRBVH_I_JOIN_SPIN; k++) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
        __builtin_ia32_pause();
#endif
#pragma omp atomic read
        done = j->done;
    }
#else
    (void)j;
#endif
}

double atrbvh_i_now_ms(void)
{
#if defined(CLOCK_MONOTONIC) && _POSIX_C_SOURCE >= 199309L
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
#elif defined(_OPENMP)
    return omp_get_wtime() * 1e3;
#else
    return (double)clock() * 1e3 / CLOCKS_PER_SEC;
#endif
}

/* ------------------------------------------------------------------ stages */
const char *atrbvh_stage_name(atrbvh_stage stage)
{
    static const char *const names[ATRBVH_STAGE_COUNT] = {
        "bounds", "morton", "sort", "hierarchy",
        "refit", "optimise", "collapse", "layout"};
    if ((int)stage < 0 || stage >= ATRBVH_STAGE_COUNT)
        return NULL;
    return names[stage];
}

/* ---------------------------------------------------------------- geometry */
atrbvh_geometry atrbvh_geometry_triangles(const float *vertices,
                                          size_t vertex_count,
                                          const uint32_t *indices,
                                          size_t triangle_count)
{
    atrbvh_geometry g;
    memset(&g, 0, sizeof g);
    g.size = sizeof g;
    g.type = ATRBVH_GEOMETRY_TRIANGLES;
    g.vertices = vertices;
    g.vertex_count = vertex_count;
    g.indices = indices;
    g.primitive_count = triangle_count;
    return g;
}

atrbvh_geometry atrbvh_geometry_boxes(const float *boxes, size_t box_count)
{
    atrbvh_geometry g;
    memset(&g, 0, sizeof g);
    g.size = sizeof g;
    g.type = ATRBVH_GEOMETRY_BOXES;
    g.boxes = boxes;
    g.primitive_count = box_count;
    return g;
}

/* ----------------------------------------------------------------- options */
void atrbvh_build_options_init(atrbvh_build_options *o)
{
    if (!o)
        return;
    memset(o, 0, sizeof *o);
    o->size = sizeof *o;
    o->method = ATRBVH_METHOD_ATRBVH;
    o->treelet_size = 0;
    o->rounds = 0;
    o->gamma = 0;
    o->ci = 1.2;
    o->ct = 1.0;
    o->collapse = 1;
    o->max_leaf_size = 0;
    o->threads = 0;
    o->skip_invalid = 0;
    o->backend = ATRBVH_BACKEND_CPU;
    o->opencl_device = NULL;
    o->progress = NULL;
    o->progress_user = NULL;
    o->device = NULL;
    o->capture = NULL;
    o->capture_user = NULL;
    o->split_budget = 0.0;
    o->split_rule = ATRBVH_SPLIT_SAH;
}

atrbvh_status atrbvh_i_resolve_options(const atrbvh_build_options *user,
                                       atrbvh_i_request *r,
                                       atrbvh_error *error)
{
    atrbvh_build_options o;
    atrbvh_i_config *c = &r->cfg;
    atrbvh_build_options_init(&o);
    if (user) {
        if (user->size < offsetof(atrbvh_build_options, method) +
                             sizeof(atrbvh_method) ||
            user->size > sizeof o)
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                                 (uint64_t)-1,
                                 "options.size is %lu; set it with "
                                 "atrbvh_build_options_init()",
                                 (unsigned long)user->size);
        memcpy(&o, user, user->size);
        o.size = sizeof o;
    }
    memset(r, 0, sizeof *r);
    if ((int)o.method < ATRBVH_METHOD_LBVH || o.method > ATRBVH_METHOD_ATRBVH)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "options.method %d is not lbvh, trbvh or atrbvh",
                             (int)o.method);
    c->method = o.method;
    if (o.method == ATRBVH_METHOD_LBVH) {
        c->treelet_size = 0;
        c->rounds = 0;
        c->gamma = 0;
    } else {
        unsigned lo = o.method == ATRBVH_METHOD_TRBVH ? ATRBVH_TRBVH_MIN
                                                      : ATRBVH_ATRBVH_MIN;
        unsigned hi = o.method == ATRBVH_METHOD_TRBVH ? ATRBVH_TRBVH_MAX
                                                      : ATRBVH_ATRBVH_MAX;
        const char *name = o.method == ATRBVH_METHOD_TRBVH ? "trbvh" : "atrbvh";
        int autosize;
        c->treelet_size = o.treelet_size ? o.treelet_size
                          : o.method == ATRBVH_METHOD_TRBVH
                              ? ATRBVH_TRBVH_DEFAULT
                              : ATRBVH_ATRBVH_DEFAULT;
        autosize = o.method == ATRBVH_METHOD_ATRBVH &&
                   c->treelet_size == ATRBVH_TREELET_AUTO;
        /* The adaptive size's default rounds: 4, the fewest that come
         * within 0.5 % of the best fixed size on every shared scene
         * (docs/optimisers.md). */
        c->rounds = o.rounds     ? o.rounds
                    : autosize   ? ATRBVH_AUTO_ROUNDS_DEFAULT
                    : o.method == ATRBVH_METHOD_TRBVH
                        ? ATRBVH_TRBVH_ROUNDS_DEFAULT
                        : ATRBVH_ATRBVH_ROUNDS_DEFAULT;
        if (c->treelet_size == ATRBVH_TREELET_AUTO && !autosize)
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                                 (uint64_t)-1,
                                 "treelet size ATRBVH_TREELET_AUTO (auto) is "
                                 "for atrbvh only (trbvh takes %u to %u)",
                                 lo, hi);
        if (!autosize && (c->treelet_size < lo || c->treelet_size > hi))
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                                 (uint64_t)-1,
                                 "treelet size %u is out of range for %s "
                                 "(%u to %u)",
                                 c->treelet_size, name, lo, hi);
        if (c->rounds > ATRBVH_ROUNDS_MAX)
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                                 (uint64_t)-1,
                                 "rounds %u is out of range (1 to %u)",
                                 c->rounds, ATRBVH_ROUNDS_MAX);
        /* Auto: the smallest size the rule picks starts the crown, and
         * a smaller gamma only needs the 3 leaves of any treelet. */
        c->gamma = o.gamma       ? o.gamma
                   : autosize    ? ATRBVH_AUTO_MIN
                                 : c->treelet_size;
        if (c->gamma < (autosize ? 3u : c->treelet_size))
            return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT,
                                 (uint64_t)-1,
                                 "gamma %u is smaller than the treelet size "
                                 "%u (a treelet root needs that many "
                                 "primitives)",
                                 c->gamma, c->treelet_size);
    }
    /* NaN fails both comparisons, so it is rejected here too. */
    if (!(o.ci > 0.0 && o.ci < 1e30))
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "ci %g must be positive and finite", o.ci);
    if (!(o.ct > 0.0 && o.ct < 1e30))
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "ct %g must be positive and finite", o.ct);
    if (o.threads < 0)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "threads %d is negative", o.threads);
    if (o.threads > ATRBVH_MAX_THREADS)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "threads %d is above the limit of %d "
                             "(ATRBVH_MAX_THREADS)",
                             o.threads, ATRBVH_MAX_THREADS);
    if (o.max_leaf_size > 0 && !o.collapse)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "max_leaf_size needs collapse (leaves hold one "
                             "primitive without it)");
    if ((int)o.backend < ATRBVH_BACKEND_CPU || o.backend > ATRBVH_BACKEND_OPENCL)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "options.backend %d is not cpu or opencl",
                             (int)o.backend);
    c->cost.ci = o.ci;
    c->cost.ct = o.ct;
    c->cost.collapse = o.collapse != 0;
    c->cost.max_leaf = o.max_leaf_size;
    c->threads = atrbvh_i_resolve_threads(o.threads);
    c->skip_invalid = o.skip_invalid != 0;
    if (!(o.split_budget >= 0.0 && o.split_budget <= ATRBVH_I_SPLIT_MAX))
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "split_budget %g is not between 0 and %g",
                             o.split_budget, ATRBVH_I_SPLIT_MAX);
    c->split_budget = o.split_budget;
    if (o.split_rule != ATRBVH_SPLIT_TREE &&
        o.split_rule != ATRBVH_SPLIT_PRIORITY &&
        o.split_rule != ATRBVH_SPLIT_SAH)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "split_rule %d is not ATRBVH_SPLIT_TREE, "
                             "ATRBVH_SPLIT_PRIORITY or ATRBVH_SPLIT_SAH",
                             o.split_rule);
    c->split_rule = o.split_rule;
    r->backend = o.backend;
    r->opencl_device = o.opencl_device;
    r->progress = o.progress;
    r->progress_user = o.progress_user;
    r->device = o.device;
    r->capture = o.capture;
    r->capture_user = o.capture_user;
    return ATRBVH_OK;
}
