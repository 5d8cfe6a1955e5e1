/*
 * pipeline.c - atrbvh_build: the one sequencer.
 *
 *   bounds -> morton -> sort -> hierarchy -> refit -> optimise -> collapse
 *   -> layout
 *
 * It runs the stages of a backend's table (backend.h) in this order on a
 * device, and owns what is not per-item work: the options and the
 * geometry's metadata, the exact error for an invalid primitive (found on
 * the host, the same way for every backend), the Morton frame (host
 * constants that steer decisions), timing, progress and cancellation,
 * stage capture, and the output object.  Scratch memory is the device's:
 * a handle opened once keeps it between builds; a build without one gets
 * a temporary device freed when it ends.
 */
#include "config.h"

#include "internal.h"

#include <string.h>

#define NO_INDEX ((uint64_t)-1)

/* Share of the whole build each stage reports under (the optimise stage
 * only when it runs): rough typical times, so the fraction moves with the
 * work; progress never changes the tree. */
static const double stage_weight[ATRBVH_STAGE_COUNT] = {
    5.0, 3.0, 10.0, 7.0, 8.0, 50.0, 4.0, 5.0};

typedef struct progress_state {
    atrbvh_progress_fn fn;
    void *user;
    atrbvh_stage stage;
    double base, span, last;
    int cancelled;
    /* the public capture callback, and what a round's capture needs */
    atrbvh_capture_fn capture;
    void *capture_user;
    atrbvh_device *dev;
    atrbvh_status failed; /* a round's capture failed: this, with `why` */
    atrbvh_error why;
} progress_state;

/* The output of `stage` (round: the optimise round just done, else 0)
 * through the public capture callback. */
static atrbvh_status emit(progress_state *p, atrbvh_i_run *run,
                          atrbvh_stage stage, unsigned round,
                          atrbvh_error *error)
{
    atrbvh_i_capture c;
    atrbvh_status st;
    memset(&c, 0, sizeof c);
    c.n = run->n;
    st = p->dev->backend->capture(p->dev, run, stage, &c, error);
    if (st == ATRBVH_OK)
        st = atrbvh_i_capture_emit(p->capture, p->capture_user, stage, round,
                                   &c, run, error);
    atrbvh_i_capture_free(&c);
    return st;
}

int atrbvh_i_stage_round(atrbvh_i_run *run, unsigned round)
{
    progress_state *p = run->pipeline;
    atrbvh_status st;
    if (!p || !p->capture || p->failed != ATRBVH_OK)
        return p && p->failed != ATRBVH_OK;
    st = emit(p, run, ATRBVH_STAGE_OPTIMISE, round, &p->why);
    if (st != ATRBVH_OK)
        p->failed = st;
    return st != ATRBVH_OK;
}

int atrbvh_i_stage_progress(atrbvh_i_run *run, uint64_t done, uint64_t total)
{
    progress_state *p = run->pipeline;
    double f;
    if (!p || !p->fn)
        return 0;
    if (p->cancelled)
        return 1;
    if (done > total)
        done = total;
    f = p->base + (total ? p->span * (double)done / (double)total : 0.0);
    if (f < p->last)
        f = p->last;
    if (f > 1.0)
        f = 1.0;
    p->last = f;
    if (p->fn(atrbvh_stage_name(p->stage), f, p->user) != 0)
        p->cancelled = 1;
    return p->cancelled;
}

static atrbvh_status cancelled(atrbvh_error *error, atrbvh_stage stage)
{
    return atrbvh_i_fail(error, ATRBVH_ERR_CANCELLED, NO_INDEX,
                         "cancelled by the progress callback before the %s "
                         "stage",
                         atrbvh_stage_name(stage));
}

/* After bounds found an invalid primitive: the exact error, or (with
 * skip_invalid) the compacted primitives for the backend. */
static atrbvh_status invalid_prims(atrbvh_device *dev, atrbvh_i_run *run,
                                   atrbvh_error *error)
{
    atrbvh_box *boxes = NULL;
    uint32_t *ids = NULL, kept = 0;
    atrbvh_status st = atrbvh_i_scan_prims(&run->in, run->cfg, &boxes, &ids,
                                           &kept, &run->scene,
                                           &run->centroids, &run->invalid,
                                           error);
    if (st == ATRBVH_OK) {
        run->n = kept;
        run->bad = 0;
        st = dev->backend->set_prims(dev, run, boxes, ids, error);
    }
    atrbvh_i_free(boxes);
    atrbvh_i_free(ids);
    return st;
}

/* The bounds stage's invalid count arrived late (run->bounds_deferred):
 * the host's scan gives the exact error (never skip_invalid here). */
static atrbvh_status invalid_late(atrbvh_i_run *run, atrbvh_error *error)
{
    atrbvh_box *boxes = NULL, scene, centroids;
    uint32_t *ids = NULL, kept = 0;
    size_t invalid = 0;
    atrbvh_status st = atrbvh_i_scan_prims(&run->in, run->cfg, &boxes, &ids,
                                           &kept, &scene, &centroids,
                                           &invalid, error);
    atrbvh_i_free(boxes);
    atrbvh_i_free(ids);
    return st != ATRBVH_OK
               ? st
               : atrbvh_i_fail(error, ATRBVH_ERR_BACKEND, NO_INDEX,
                               "internal error: the device found an invalid "
                               "primitive that the host did not");
}

/* A build failed (or was cancelled) while the bounds' invalid count was
 * still on the device: an invalid primitive's error comes first, as when
 * the bounds stage reports it at once. */
static atrbvh_status invalid_first(atrbvh_i_run *run, atrbvh_status st,
                                   atrbvh_error *error)
{
    atrbvh_error mine;
    atrbvh_status bad = invalid_late(run, &mine);
    if (bad == ATRBVH_ERR_BACKEND || bad == ATRBVH_ERR_NOMEM)
        return st; /* none found (or no memory to look) */
    if (error)
        *error = mine;
    return bad;
}

/* The tree's counts and how it was built, the device record, stage times
 * (the statistics of a pass over the nodes wait: lib/bvh.c). */
static atrbvh_status finish(atrbvh_bvh *bvh, atrbvh_device *dev,
                            const atrbvh_i_run *run, const double *stage_ms,
                            double t0, atrbvh_error *error)
{
    const atrbvh_i_config *cfg = run->cfg;
    int s;
    bvh->stats.invalid_skipped = run->invalid;
    bvh->stats.ci = cfg->cost.ci;
    bvh->stats.ct = cfg->cost.ct;
    bvh->stats.method = cfg->method;
    bvh->stats.treelet_size = cfg->treelet_size;
    bvh->stats.rounds = cfg->rounds;
    bvh->stats.backend = dev->backend->kind;
    bvh->stats.threads = cfg->threads;
    /* The counts a reader can have at once; the rest (a pass over the
     * nodes: 7-10% of an LBVH on 2 threads) waits for the first request
     * (atrbvh_bvh_stats, lib/bvh.c), as the tree's users need none of
     * it to trace. */
    bvh->stats.nodes = bvh->node_count;
    bvh->stats.primitives = bvh->split_prims ? bvh->split_prims
                                             : bvh->prim_count;
    bvh->stats_pending = 1;
#ifdef ATRBVH_DEBUG_CHECKS
    {
        /* measured at once: the walk checks the layout's order too */
        atrbvh_status st = atrbvh_i_bvh_settle_stats(bvh);
        if (st != ATRBVH_OK)
            return st == ATRBVH_ERR_NOMEM
                       ? atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                       "cannot allocate statistics scratch "
                                       "for %lu nodes",
                                       (unsigned long)bvh->node_count)
                       : atrbvh_i_fail(error, ATRBVH_ERR_BACKEND, NO_INDEX,
                                       "internal error: the built tree is "
                                       "invalid");
        st = atrbvh_i_bvh_check(bvh, 1, error);
        if (st != ATRBVH_OK)
            return st;
    }
#endif
    if (dev->backend->kind != ATRBVH_BACKEND_CPU) {
        const char *name;
        double ms;
        size_t k;
        bvh->device = atrbvh_i_malloc(sizeof *bvh->device);
        if (!bvh->device)
            return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                 "cannot allocate the device information");
        memset(bvh->device, 0, sizeof *bvh->device);
        memcpy(bvh->device->name, dev->name, sizeof bvh->device->name);
        for (k = 0; dev->backend->kernel_time &&
                    dev->backend->kernel_time(dev, k, &name, &ms);
             k++)
            atrbvh_i_bvh_add_kernel_time(bvh, name, ms);
    }
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
        bvh->stage_ms[s] = stage_ms[s];
    bvh->stats.build_ms = atrbvh_i_now_ms() - t0;
    return ATRBVH_OK;
}

/* The stages on an open device, locked. */
static atrbvh_status run_stages(atrbvh_device *dev, atrbvh_i_run *run,
                                progress_state *prog, atrbvh_i_capture *cap,
                                atrbvh_bvh **out, double t0,
                                atrbvh_error *error)
{
    const atrbvh_i_backend *be = dev->backend;
    double ms[ATRBVH_STAGE_COUNT], total = 0.0;
    atrbvh_bvh *bvh = NULL;
    atrbvh_status st;
    int s;

    memset(ms, 0, sizeof ms);
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++)
        if (s != ATRBVH_STAGE_OPTIMISE || run->cfg->method != ATRBVH_METHOD_LBVH)
            total += stage_weight[s];

    st = be->begin(dev, run, error);
    if (st != ATRBVH_OK)
        return st;
    for (s = 0; s < ATRBVH_STAGE_COUNT; s++) {
        const atrbvh_stage stage = (atrbvh_stage)s;
        const int runs = stage != ATRBVH_STAGE_OPTIMISE ||
                         run->cfg->method != ATRBVH_METHOD_LBVH;
        double t;
        prog->stage = stage;
        prog->span = runs ? stage_weight[s] / total : 0.0;
        if (atrbvh_i_stage_progress(run, 0, 1)) {
            st = cancelled(error, stage);
            break;
        }
        t = atrbvh_i_now_ms();
        if (stage == ATRBVH_STAGE_LAYOUT) {
            /* The output object, sized by the collapse stage, in blocks
             * the build has already touched where they hold it. */
            atrbvh_i_blocks blocks;
            blocks.nodes = &run->out_block;
            blocks.node_bytes = run->out_block_bytes;
            blocks.nodes2 = &run->recycled_nodes;
            blocks.node_bytes2 = run->recycled_node_bytes;
            blocks.indices = &run->recycled_indices;
            blocks.index_bytes = run->recycled_index_bytes;
            bvh = atrbvh_i_bvh_alloc_in(run->node_count, run->n, &blocks);
            if (!bvh) {
                st = atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                                   "cannot allocate the output (%lu nodes)",
                                   (unsigned long)run->node_count);
                break;
            }
            run->nodes = bvh->nodes;
            run->prim_indices = bvh->prim_indices;
        }
        st = runs ? be->stage[s](dev, run, error) : ATRBVH_OK;
        if (st == ATRBVH_OK && stage == ATRBVH_STAGE_LAYOUT &&
            run->split_prims) { /* split.c: no leaf lists one twice */
            bvh->split_prims = run->split_prims;
            st = atrbvh_i_split_merge(bvh, run->in.g->primitive_count, error);
        }
        if (st == ATRBVH_OK && stage == ATRBVH_STAGE_BOUNDS) {
            if (run->cfg->split_budget > 0.0 &&
                run->in.g->type == ATRBVH_GEOMETRY_TRIANGLES)
                st = atrbvh_i_split_prims(dev, run, error); /* split.c */
            else if (run->bad)
                st = invalid_prims(dev, run, error);
            if (st == ATRBVH_OK && !run->bounds_deferred)
                atrbvh_i_morton_frame(&run->centroids, run->morton_lo,
                                      run->morton_scale);
        } else if (st == ATRBVH_OK && run->bad) {
            st = invalid_late(run, error); /* from bounds_deferred */
        }
        ms[s] = runs ? atrbvh_i_now_ms() - t : 0.0;
        if (prog->failed != ATRBVH_OK) {
            /* a round's capture failed inside the stage: its error */
            st = prog->failed;
            if (error)
                *error = prog->why;
        }
        if (st == ATRBVH_OK && cap)
            st = be->capture(dev, run, stage, cap, error);
        if (st == ATRBVH_OK && prog->capture)
            st = emit(prog, run, stage, 0, error);
        if (st != ATRBVH_OK)
            break;
        prog->base += prog->span;
    }
    if (st != ATRBVH_OK && run->bounds_deferred)
        st = invalid_first(run, st, error);
    if (st == ATRBVH_OK)
        st = finish(bvh, dev, run, ms, t0, error);
    be->end(dev, run);
    if (st == ATRBVH_OK && prog->fn) {
        prog->stage = ATRBVH_STAGE_LAYOUT;
        prog->base = 1.0;
        prog->span = 0.0;
        (void)atrbvh_i_stage_progress(run, 1, 1); /* done: no cancelling */
    }
    if (st != ATRBVH_OK) {
        atrbvh_bvh_free(bvh);
        return st;
    }
    *out = bvh;
    return ATRBVH_OK;
}

/* Whether the n bytes at p and the m bytes at q share one. */
static int bytes_meet(const void *p, size_t n, const void *q, size_t m)
{
    const uintptr_t a = (uintptr_t)p, b = (uintptr_t)q;
    return p && q && n && m && a < b + m && b < a + n;
}

/* Whether the caller's arrays that the build reads (the geometry, past
 * its checks: no sum below overflows) share a byte with the m at q. */
static int input_meets(const atrbvh_i_input *in, const void *q, size_t m)
{
    const atrbvh_geometry *g = in->g;
    const size_t n = g->primitive_count;
    if (g->type == ATRBVH_GEOMETRY_BOXES)
        return bytes_meet(g->boxes, (n - 1) * in->bstride + 6 * sizeof(float),
                          q, m);
    return bytes_meet(g->vertices,
                      (g->vertex_count - 1) * in->vstride + 3 * sizeof(float),
                      q, m) ||
           (g->indices &&
            bytes_meet(g->indices,
                       (n - 1) * in->istride + 3 * sizeof(uint32_t), q, m));
}

/* atrbvh_rebuild: the old tree's arrays into the run for reuse, the rest
 * of it freed at once; NULL then.  When the input lies in those arrays
 * the old tree is returned whole, to be freed after the build. */
static atrbvh_bvh *recycle(atrbvh_i_run *run, atrbvh_bvh *old)
{
    /* (no overflow: the index array was allocated that large) */
    const size_t node_bytes = old->node_bytes,
                 index_bytes = old->prim_count * sizeof *old->prim_indices;
    if (input_meets(&run->in, old->nodes, node_bytes) ||
        input_meets(&run->in, old->prim_indices, index_bytes))
        return old;
    run->recycled_nodes = old->nodes;
    run->recycled_node_bytes = old->nodes ? node_bytes : 0;
    run->recycled_indices = old->prim_indices;
    run->recycled_index_bytes = old->prim_indices ? index_bytes : 0;
    old->nodes = NULL;
    old->prim_indices = NULL;
    atrbvh_bvh_free(old);
    return NULL;
}

/* A build; `old` (may be NULL) is atrbvh_rebuild's, freed on every
 * path. */
static atrbvh_status build_run(const atrbvh_geometry *geometry,
                               const atrbvh_build_options *options,
                               atrbvh_bvh **out, atrbvh_bvh *old,
                               atrbvh_i_capture *cap, atrbvh_error *error)
{
    atrbvh_i_request req;
    atrbvh_i_run run;
    progress_state prog;
    atrbvh_device temp, *dev;
    atrbvh_status st;
    double t0 = atrbvh_i_now_ms();

    memset(&run, 0, sizeof run);
    st = atrbvh_i_resolve_options(options, &req, error);
    if (st != ATRBVH_OK)
        goto done;
    run.cfg = &req.cfg;
    st = atrbvh_i_check_geometry(geometry, &run.in, error);
    if (st != ATRBVH_OK)
        goto done;
    if (old)
        old = recycle(&run, old);
    memset(&prog, 0, sizeof prog);
    prog.fn = req.progress;
    prog.user = req.progress_user;
    prog.capture = req.capture;
    prog.capture_user = req.capture_user;
    run.pipeline = &prog;

    dev = req.device;
    if (!dev && req.backend == ATRBVH_BACKEND_OPENCL) {
#ifdef ATRBVH_HAVE_OPENCL
        st = atrbvh_i_device_open_backend(&atrbvh_i_cl_backend,
                                          req.opencl_device, &dev, error);
        if (st != ATRBVH_OK)
            goto done;
#else
        st = atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, NO_INDEX,
                           "this build of atrbvh has no OpenCL backend "
                           "(configure --enable-opencl)");
        goto done;
#endif
    } else if (!dev) {
        atrbvh_i_device_cpu_temp(&temp);
        dev = &temp;
    }
    prog.dev = dev;
    /* Nothing reads the bounds' results before the collapse stage:
     * a backend may report them there (backend.h). */
    run.captured = cap || prog.capture;
    run.bounds_late_ok = !cap && !prog.capture && !req.cfg.skip_invalid &&
                         !(req.cfg.split_budget > 0.0 &&
                           geometry->type == ATRBVH_GEOMETRY_TRIANGLES);
    atrbvh_i_device_lock(dev);
    st = run_stages(dev, &run, &prog, cap, out, t0, error);
    atrbvh_i_device_unlock(dev);
    if (dev != req.device)
        atrbvh_device_close(dev); /* a temporary one */
done:
    atrbvh_i_free(run.recycled_nodes); /* (what the build did not take) */
    atrbvh_i_free(run.recycled_indices);
    atrbvh_bvh_free(old);
    return st;
}

atrbvh_status atrbvh_i_build_run(const atrbvh_geometry *geometry,
                                 const atrbvh_build_options *options,
                                 atrbvh_bvh **out, atrbvh_i_capture *cap,
                                 atrbvh_error *error)
{
    atrbvh_i_clear_error(error);
    if (!out)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "the output pointer is NULL");
    *out = NULL;
    return build_run(geometry, options, out, NULL, cap, error);
}

atrbvh_status atrbvh_build(const atrbvh_geometry *geometry,
                           const atrbvh_build_options *options,
                           atrbvh_bvh **out, atrbvh_error *error)
{
    return atrbvh_i_build_run(geometry, options, out, NULL, error);
}

atrbvh_status atrbvh_rebuild(const atrbvh_geometry *geometry,
                             const atrbvh_build_options *options,
                             atrbvh_bvh **bvh, atrbvh_error *error)
{
    atrbvh_bvh *old;
    atrbvh_i_clear_error(error);
    if (!bvh)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "the BVH pointer is NULL");
    old = *bvh;
    *bvh = NULL;
    return build_run(geometry, options, bvh, old, NULL, error);
}
