/*
 * build.c - atrbvh_build: the pipeline, stage after stage.
 *
 *   bounds -> morton -> sort -> hierarchy -> refit -> optimise -> collapse
 *   -> layout
 *
 * Every buffer is allocated here, up front per stage, through the
 * replaceable allocator, and released as soon as the last stage that reads
 * it is done; no stage allocates per node or per primitive.
 */
#include "config.h"

#include "internal.h"

#include <string.h>

static void progress(const __atrbvh_config *cfg, atrbvh_stage stage)
{
    if (cfg->progress)
        cfg->progress(atrbvh_stage_name(stage),
                      (double)stage / (double)ATRBVH_STAGE_COUNT,
                      cfg->progress_user);
}

#define NOMEM(what)                                                            \
    __atrbvh_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,                      \
                  "cannot allocate " what " for %lu primitives",               \
                  (unsigned long)n)

atrbvh_status atrbvh_build(const atrbvh_geometry *geometry,
                           const atrbvh_build_options *options,
                           atrbvh_bvh **out, atrbvh_error *error)
{
    __atrbvh_config cfg;
    __atrbvh_prims prims;
    __atrbvh_tree tree;
    uint64_t *keys = NULL, *tmp_keys = NULL;
    uint32_t *order = NULL, *tmp_order = NULL;
    atrbvh_bvh *bvh = NULL;
    atrbvh_status st;
    double ms[ATRBVH_STAGE_COUNT], t0, t;
    uint32_t n, i;
    int s;

    __atrbvh_clear_error(error);
    memset(&prims, 0, sizeof prims);
    memset(&tree, 0, sizeof tree);
    memset(ms, 0, sizeof ms);
    if (!out)
        return __atrbvh_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "the output pointer is NULL");
    *out = NULL;
    st = __atrbvh_resolve_options(options, &cfg, error);
    if (st != ATRBVH_OK)
        return st;
    if (cfg.backend == ATRBVH_BACKEND_OPENCL)
        return __atrbvh_fail(error, ATRBVH_ERR_UNSUPPORTED, (uint64_t)-1,
                             "this build of atrbvh has no OpenCL backend");

    t0 = __atrbvh_now_ms();
    progress(&cfg, ATRBVH_STAGE_BOUNDS);
    st = __atrbvh_bounds(geometry, &cfg, &prims, error);
    if (st != ATRBVH_OK)
        return st;
    n = prims.count;
    t = __atrbvh_now_ms();
    ms[ATRBVH_STAGE_BOUNDS] = t - t0;

    progress(&cfg, ATRBVH_STAGE_MORTON);
    keys = __atrbvh_alloc_array(n, sizeof *keys);
    order = __atrbvh_alloc_array(n, sizeof *order);
    if (!keys || !order) {
        st = NOMEM("Morton keys");
        goto fail;
    }
    __atrbvh_morton(&prims, keys, cfg.threads);
    ms[ATRBVH_STAGE_MORTON] = __atrbvh_now_ms() - t;
    t = __atrbvh_now_ms();

    progress(&cfg, ATRBVH_STAGE_SORT);
    tmp_keys = __atrbvh_alloc_array(n, sizeof *tmp_keys);
    tmp_order = __atrbvh_alloc_array(n, sizeof *tmp_order);
    if (!tmp_keys || !tmp_order) {
        st = NOMEM("sort buffers");
        goto fail;
    }
    for (i = 0; i < n; i++)
        order[i] = i;
    if (__atrbvh_radix_sort(keys, order, tmp_keys, tmp_order, n,
                            cfg.threads) != ATRBVH_OK) {
        st = NOMEM("sort counters");
        goto fail;
    }
    __atrbvh_free(tmp_keys);
    __atrbvh_free(tmp_order);
    tmp_keys = NULL;
    tmp_order = NULL;
    ms[ATRBVH_STAGE_SORT] = __atrbvh_now_ms() - t;
    t = __atrbvh_now_ms();

    progress(&cfg, ATRBVH_STAGE_HIERARCHY);
    if (__atrbvh_tree_alloc(&tree, n) != ATRBVH_OK) {
        st = NOMEM("the tree");
        goto fail;
    }
    __atrbvh_hierarchy(keys, &tree, cfg.threads);
    __atrbvh_free(keys);
    keys = NULL;
    for (i = 0; i < n; i++)
        tree.leaf_prim[i] = prims.ids ? prims.ids[order[i]] : order[i];
    ms[ATRBVH_STAGE_HIERARCHY] = __atrbvh_now_ms() - t;
    t = __atrbvh_now_ms();

    progress(&cfg, ATRBVH_STAGE_REFIT);
    __atrbvh_refit(&tree, prims.boxes, order, &cfg.cost, cfg.threads);
    __atrbvh_free(order);
    order = NULL;
    __atrbvh_prims_free(&prims);
    ms[ATRBVH_STAGE_REFIT] = __atrbvh_now_ms() - t;
    t = __atrbvh_now_ms();

    if (cfg.method != ATRBVH_METHOD_LBVH) {
        progress(&cfg, ATRBVH_STAGE_OPTIMISE);
        st = __atrbvh_optimise(&tree, &cfg, error);
        if (st != ATRBVH_OK)
            goto fail;
    }
    ms[ATRBVH_STAGE_OPTIMISE] = __atrbvh_now_ms() - t;

    progress(&cfg, ATRBVH_STAGE_COLLAPSE);
    bvh = __atrbvh_bvh_alloc(0, 0);
    if (!bvh) {
        st = NOMEM("the BVH object");
        goto fail;
    }
    st = __atrbvh_collapse_layout(&tree, &cfg, bvh, &ms[ATRBVH_STAGE_COLLAPSE],
                                  &ms[ATRBVH_STAGE_LAYOUT], error);
    if (st != ATRBVH_OK)
        goto fail;
    __atrbvh_tree_free(&tree);

    bvh->stats.invalid_skipped = prims.invalid;
    bvh->stats.ci = cfg.cost.ci;
    bvh->stats.ct = cfg.cost.ct;
    bvh->stats.method = cfg.method;
    bvh->stats.treelet_size = cfg.treelet_size;
    bvh->stats.rounds = cfg.rounds;
    bvh->stats.backend = cfg.backend;
    bvh->stats.threads = cfg.threads;
    st = __atrbvh_bvh_measure(bvh);
    if (st != ATRBVH_OK) {
        st = st == ATRBVH_ERR_NOMEM
                 ? NOMEM("statistics scratch")
                 : __atrbvh_fail(error, ATRBVH_ERR_BACKEND, (uint64_t)-1,
                                 "internal error: the built tree is invalid");
        goto fail;
    }
#ifdef ATRBVH_DEBUG_CHECKS
    st = __atrbvh_bvh_check(bvh, 1, error);
    if (st != ATRBVH_OK)
        goto fail;
#endif
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
        bvh->stats.stage_ms[s] = ms[s];
    bvh->stats.build_ms = __atrbvh_now_ms() - t0;
    *out = bvh;
    return ATRBVH_OK;

fail:
    __atrbvh_free(keys);
    __atrbvh_free(tmp_keys);
    __atrbvh_free(order);
    __atrbvh_free(tmp_order);
    __atrbvh_prims_free(&prims);
    __atrbvh_tree_free(&tree);
    atrbvh_bvh_free(bvh);
    return st;
}
