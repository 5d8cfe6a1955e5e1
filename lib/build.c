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

static void progress(const atrbvh_i_config *cfg, atrbvh_stage stage)
{
    if (cfg->progress)
        cfg->progress(atrbvh_stage_name(stage),
                      (double)stage / (double)ATRBVH_STAGE_COUNT,
                      cfg->progress_user);
}

#define NOMEM(what)                                                            \
    atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,                      \
                  "cannot allocate " what " for %lu primitives",               \
                  (unsigned long)n)

/* Copies n items of `size` bytes into a new array at *dst (capture). */
static int capture_copy(void *dst_ptr, const void *src, size_t n, size_t size)
{
    void **dst = (void **)dst_ptr;
    *dst = atrbvh_i_alloc_array(n, size);
    if (!*dst)
        return 0;
    memcpy(*dst, src, n * size);
    return 1;
}

atrbvh_status atrbvh_build(const atrbvh_geometry *geometry,
                           const atrbvh_build_options *options,
                           atrbvh_bvh **out, atrbvh_error *error)
{
    return atrbvh_i_build_run(geometry, options, out, NULL, error);
}

atrbvh_status atrbvh_i_build_run(const atrbvh_geometry *geometry,
                                 const atrbvh_build_options *options,
                                 atrbvh_bvh **out, atrbvh_i_capture *cap,
                                 atrbvh_error *error)
{
    atrbvh_i_config cfg;
    atrbvh_i_prims prims;
    atrbvh_i_tree tree;
    uint64_t *keys = NULL, *tmp_keys = NULL;
    uint32_t *order = NULL, *tmp_order = NULL;
    atrbvh_bvh *bvh = NULL;
    atrbvh_status st;
    double ms[ATRBVH_STAGE_COUNT], t0, t;
    uint32_t n, i;

    atrbvh_i_clear_error(error);
    memset(&prims, 0, sizeof prims);
    memset(&tree, 0, sizeof tree);
    memset(ms, 0, sizeof ms);
    if (!out)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, (uint64_t)-1,
                             "the output pointer is NULL");
    *out = NULL;
    st = atrbvh_i_resolve_options(options, &cfg, error);
    if (st != ATRBVH_OK)
        return st;
    if (cfg.backend == ATRBVH_BACKEND_OPENCL)
#ifdef ATRBVH_HAVE_OPENCL
        return atrbvh_i_cl_build(geometry, &cfg, out, cap, error);
#else
        return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, (uint64_t)-1,
                             "this build of atrbvh has no OpenCL backend "
                             "(configure --enable-opencl)");
#endif

    t0 = atrbvh_i_now_ms();
    progress(&cfg, ATRBVH_STAGE_BOUNDS);
    st = atrbvh_i_bounds(geometry, &cfg, &prims, error);
    if (st != ATRBVH_OK)
        return st;
    n = prims.count;
    t = atrbvh_i_now_ms();
    ms[ATRBVH_STAGE_BOUNDS] = t - t0;
    if (cap) {
        cap->n = n;
        cap->scene = prims.scene;
        cap->centroids = prims.centroids;
        if (!capture_copy(&cap->prim_boxes, prims.boxes, n, sizeof *prims.boxes)) {
            st = NOMEM("the capture");
            goto fail;
        }
    }

    progress(&cfg, ATRBVH_STAGE_MORTON);
    keys = atrbvh_i_alloc_array(n, sizeof *keys);
    order = atrbvh_i_alloc_array(n, sizeof *order);
    if (!keys || !order) {
        st = NOMEM("Morton keys");
        goto fail;
    }
    atrbvh_i_morton(&prims, keys, cfg.threads);
    if (cap && !capture_copy(&cap->keys, keys, n, sizeof *keys)) {
        st = NOMEM("the capture");
        goto fail;
    }
    ms[ATRBVH_STAGE_MORTON] = atrbvh_i_now_ms() - t;
    t = atrbvh_i_now_ms();

    progress(&cfg, ATRBVH_STAGE_SORT);
    tmp_keys = atrbvh_i_alloc_array(n, sizeof *tmp_keys);
    tmp_order = atrbvh_i_alloc_array(n, sizeof *tmp_order);
    if (!tmp_keys || !tmp_order) {
        st = NOMEM("sort buffers");
        goto fail;
    }
    for (i = 0; i < n; i++)
        order[i] = i;
    if (atrbvh_i_radix_sort(keys, order, tmp_keys, tmp_order, n,
                            cfg.threads) != ATRBVH_OK) {
        st = NOMEM("sort counters");
        goto fail;
    }
    atrbvh_i_free(tmp_keys);
    atrbvh_i_free(tmp_order);
    tmp_keys = NULL;
    tmp_order = NULL;
    if (cap && (!capture_copy(&cap->sorted_keys, keys, n, sizeof *keys) ||
                !capture_copy(&cap->order, order, n, sizeof *order))) {
        st = NOMEM("the capture");
        goto fail;
    }
    ms[ATRBVH_STAGE_SORT] = atrbvh_i_now_ms() - t;
    t = atrbvh_i_now_ms();

    progress(&cfg, ATRBVH_STAGE_HIERARCHY);
    if (atrbvh_i_tree_alloc(&tree, n) != ATRBVH_OK) {
        st = NOMEM("the tree");
        goto fail;
    }
    atrbvh_i_hierarchy(keys, &tree, cfg.threads);
    atrbvh_i_free(keys);
    keys = NULL;
    for (i = 0; i < n; i++)
        tree.leaf_prim[i] = prims.ids ? prims.ids[order[i]] : order[i];
    if (cap && atrbvh_i_tree_copy(&cap->hierarchy, &tree) != ATRBVH_OK) {
        st = NOMEM("the capture");
        goto fail;
    }
    ms[ATRBVH_STAGE_HIERARCHY] = atrbvh_i_now_ms() - t;
    t = atrbvh_i_now_ms();

    progress(&cfg, ATRBVH_STAGE_REFIT);
    atrbvh_i_refit(&tree, prims.boxes, order, &cfg.cost, cfg.threads);
    atrbvh_i_free(order);
    order = NULL;
    atrbvh_i_prims_free(&prims);
    if (cap && atrbvh_i_tree_copy(&cap->refit, &tree) != ATRBVH_OK) {
        st = NOMEM("the capture");
        goto fail;
    }
    ms[ATRBVH_STAGE_REFIT] = atrbvh_i_now_ms() - t;
    t = atrbvh_i_now_ms();

    if (cfg.method != ATRBVH_METHOD_LBVH) {
        progress(&cfg, ATRBVH_STAGE_OPTIMISE);
        st = atrbvh_i_optimise(&tree, &cfg, error);
        if (st != ATRBVH_OK)
            goto fail;
    }
    ms[ATRBVH_STAGE_OPTIMISE] = atrbvh_i_now_ms() - t;
    if (cap && atrbvh_i_tree_copy(&cap->optimise, &tree) != ATRBVH_OK) {
        st = NOMEM("the capture");
        goto fail;
    }

    progress(&cfg, ATRBVH_STAGE_COLLAPSE);
    bvh = atrbvh_i_bvh_alloc(0, 0);
    if (!bvh) {
        st = NOMEM("the BVH object");
        goto fail;
    }
    st = atrbvh_i_collapse_layout(&tree, &cfg, bvh, &ms[ATRBVH_STAGE_COLLAPSE],
                                  &ms[ATRBVH_STAGE_LAYOUT],
                                  cap ? &cap->collapse_size : NULL, error);
    if (st != ATRBVH_OK)
        goto fail;
    atrbvh_i_tree_free(&tree);

    st = atrbvh_i_build_finish(bvh, &cfg, prims.invalid, ms, t0, error);
    if (st != ATRBVH_OK)
        goto fail;
    *out = bvh;
    return ATRBVH_OK;

fail:
    atrbvh_i_free(keys);
    atrbvh_i_free(tmp_keys);
    atrbvh_i_free(order);
    atrbvh_i_free(tmp_order);
    atrbvh_i_prims_free(&prims);
    atrbvh_i_tree_free(&tree);
    atrbvh_bvh_free(bvh);
    return st;
}

atrbvh_status atrbvh_i_build_finish(atrbvh_bvh *bvh, const atrbvh_i_config *cfg,
                                    size_t invalid, const double *stage_ms,
                                    double t0, atrbvh_error *error)
{
    atrbvh_status st;
    int s;
    bvh->stats.invalid_skipped = invalid;
    bvh->stats.ci = cfg->cost.ci;
    bvh->stats.ct = cfg->cost.ct;
    bvh->stats.method = cfg->method;
    bvh->stats.treelet_size = cfg->treelet_size;
    bvh->stats.rounds = cfg->rounds;
    bvh->stats.backend = cfg->backend;
    bvh->stats.threads = cfg->threads;
    st = atrbvh_i_bvh_measure(bvh);
    if (st != ATRBVH_OK)
        return st == ATRBVH_ERR_NOMEM
                   ? atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, (uint64_t)-1,
                                   "cannot allocate statistics scratch for "
                                   "%lu nodes",
                                   (unsigned long)bvh->node_count)
                   : atrbvh_i_fail(error, ATRBVH_ERR_BACKEND, (uint64_t)-1,
                                   "internal error: the built tree is "
                                   "invalid");
#ifdef ATRBVH_DEBUG_CHECKS
    st = atrbvh_i_bvh_check(bvh, 1, error);
    if (st != ATRBVH_OK)
        return st;
#endif
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
        bvh->stats.stage_ms[s] = stage_ms[s];
    bvh->stats.build_ms = atrbvh_i_now_ms() - t0;
    return ATRBVH_OK;
}

void atrbvh_i_bvh_add_kernel_time(atrbvh_bvh *bvh, const char *name,
                                  double ms)
{
    atrbvh_i_device_info *d = bvh->device;
    unsigned k;
    if (!d)
        return;
    for (k = 0; k < d->kernel_count; k++) {
        if (strcmp(d->kernel_name[k], name) == 0) {
            d->kernel_ms[k] += ms;
            return;
        }
    }
    if (d->kernel_count == ATRBVH_MAX_KERNEL_TIMES)
        return;
    strncpy(d->kernel_name[k], name, sizeof d->kernel_name[k] - 1);
    d->kernel_name[k][sizeof d->kernel_name[k] - 1] = '\0';
    d->kernel_ms[k] = ms;
    d->kernel_count++;
}

const char *atrbvh_bvh_device(const atrbvh_bvh *bvh)
{
    if (!bvh)
        return NULL;
    return bvh->device ? bvh->device->name : "cpu";
}

int atrbvh_bvh_kernel_time(const atrbvh_bvh *bvh, size_t i, const char **name,
                           double *ms)
{
    if (!bvh || !bvh->device || i >= bvh->device->kernel_count)
        return 0;
    if (name)
        *name = bvh->device->kernel_name[i];
    if (ms)
        *ms = bvh->device->kernel_ms[i];
    return 1;
}
