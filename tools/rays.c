/*
 * rays.c - the ray sets of `atrbvh bench` (see rays.h).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "rays.h"

#include "cli.h"
#include "options.h"
#include "rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

void rays_normal(const scene *sc, uint32_t prim, const float dir[3],
                 double n[3])
{
    const uint32_t *tri = sc->indices + (size_t)prim * 3;
    const float *v0 = sc->vertices + (size_t)tri[0] * 3;
    const float *v1 = sc->vertices + (size_t)tri[1] * 3;
    const float *v2 = sc->vertices + (size_t)tri[2] * 3;
    double e1[3], e2[3], len, sign;
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = (double)v1[k] - v0[k];
        e2[k] = (double)v2[k] - v0[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0) || !isfinite(len)) {
        double d = sqrt((double)dir[0] * dir[0] + (double)dir[1] * dir[1] +
                        (double)dir[2] * dir[2]);
        for (k = 0; k < 3; k++)
            n[k] = -(double)dir[k] / d;
        return;
    }
    sign = n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2] > 0.0 ? -1.0 : 1.0;
    for (k = 0; k < 3; k++)
        n[k] *= sign / len;
}

void rays_surface(const scene *sc, const atrbvh_ray *ray,
                  const atrbvh_hit *hit, double eps_scale, ray_surface *s)
{
    double big = 0.0, eps;
    const double *n = s->n;
    int k;
    rays_normal(sc, hit->primitive, ray->dir, s->n);
    for (k = 0; k < 3; k++) {
        s->p[k] = (double)ray->origin[k] + (double)hit->t * ray->dir[k];
        if (fabs(s->p[k]) > big)
            big = fabs(s->p[k]);
    }
    /* Relative offset: a fraction of the scene, plus enough float ulps at
     * this position not to land back on the surface. */
    eps = eps_scale + big * 1e-6;
    for (k = 0; k < 3; k++)
        s->p[k] += n[k] * eps;
    /* Duff et al. 2017, "Building an orthonormal basis, revisited". */
    {
        double sg = n[2] >= 0.0 ? 1.0 : -1.0;
        double a = -1.0 / (sg + n[2]);
        double bb = n[0] * n[1] * a;
        s->t[0] = 1.0 + sg * n[0] * n[0] * a;
        s->t[1] = sg * bb;
        s->t[2] = -sg * n[0];
        s->b[0] = bb;
        s->b[1] = sg + n[1] * n[1] * a;
        s->b[2] = -n[1];
    }
}

void rays_cosine(const ray_surface *s, uint64_t seed, uint64_t item,
                 unsigned sample, float length, atrbvh_ray *r)
{
    double u1, u2, rad, phi, x, y, z;
    int k;
    rng_pair(seed, item, sample, &u1, &u2);
    rad = sqrt(u1);
    phi = 2.0 * PI * u2;
    x = rad * cos(phi);
    y = rad * sin(phi);
    z = sqrt(1.0 - u1);
    for (k = 0; k < 3; k++) {
        r->origin[k] = (float)s->p[k];
        r->dir[k] = (float)(x * s->t[k] + y * s->b[k] + z * s->n[k]);
    }
    r->tmin = 0.0f;
    r->tmax = length;
}

void ray_set_free(ray_set *rs)
{
    free(rs->primary);
    free(rs->ao);
    free(rs->diffuse);
    memset(rs, 0, sizeof *rs);
}

/* "X,Y,Z": three finite numbers. */
static int on_point(const char *cmd, const cli_opt *opt, const char *value,
                    void *user)
{
    float *p = opt->dest;
    char buf[256], *parts[3], *comma;
    int k;
    double d;
    (void)user;
    if (strlen(value) >= sizeof buf)
        return cli_usage(cmd, "%s: '%.40s...' is too long", opt->name, value);
    strcpy(buf, value);
    /* exactly three fields between two commas, none empty (a stray
     * comma is not skipped: "0,,0,5" is no point) */
    parts[0] = buf;
    for (k = 1; k < 3; k++) {
        comma = strchr(parts[k - 1], ',');
        if (!comma)
            break;
        *comma = '\0';
        parts[k] = comma + 1;
    }
    if (k != 3 || strchr(parts[2], ',') || strchr(value, ' ') ||
        !*parts[0] || !*parts[1] || !*parts[2])
        return cli_usage(cmd, "%s: '%s' is not X,Y,Z (three numbers, "
                         "commas, no spaces)", opt->name, value);
    for (k = 0; k < 3; k++) {
        if (!cli_parse_double(parts[k], &d) || !isfinite(d) ||
            fabs(d) > 3.4e38)
            return cli_usage(cmd, "%s: '%s' is not a finite number in '%s'",
                             opt->name, parts[k], value);
        p[k] = (float)d;
    }
    return 0;
}

void rays_camera_opts(camera_view *v, cli_opt *out)
{
    const cli_opt opts[] = {
        {.name = "--eye", .kind = CLI_OPT_CALL, .arg = "X,Y,Z",
         .dest = v->eye, .call = on_point, .seen = &v->have_eye,
         .help = "a camera at X,Y,Z instead of the default viewpoints"},
        {.name = "--look-at", .kind = CLI_OPT_CALL, .arg = "X,Y,Z",
         .dest = v->at, .call = on_point, .seen = &v->have_at,
         .help = "where the --eye camera looks (default: the centre\n"
                 "of the scene's box)"},
        {.name = "--fov", .kind = CLI_OPT_DOUBLE, .arg = "DEG", .min = 0.0,
         .min_open = 1, .max = 170.0, .dest = &v->fov,
         .help = "vertical field of view in degrees (default 50, 70\n"
                 "for the inside cameras of rooms)"}};
    memcpy(out, opts, sizeof opts);
}

int rays_camera_check(const char *cmd, const camera_view *v)
{
    if (v->have_at && !v->have_eye)
        return cli_usage(cmd, "--look-at needs --eye");
    if (v->have_eye && v->have_at && v->eye[0] == v->at[0] &&
        v->eye[1] == v->at[1] && v->eye[2] == v->at[2])
        return cli_usage(cmd, "--eye and --look-at are the same point");
    return 0;
}

int rays_camera(const scene *sc, unsigned which, const camera_view *v,
                float aspect, camera *cam)
{
    float lo[3], hi[3];
    int room = 0;
    scene_bounds(sc, lo, hi);
    if (!v || !v->have_eye)
        room = scene_is_room(sc, lo, hi, NULL);
    return camera_viewpoint(lo, hi, room, which, v, aspect, cam);
}

int ray_set_make(const scene *sc, const atrbvh_bvh *ref, unsigned width,
                 unsigned height, unsigned viewpoints, unsigned spp,
                 int threads, const camera_view *view, ray_set *rs)
{
    int room = 0;
    atrbvh_geometry g = scene_geometry(sc);
    atrbvh_hit *hits = NULL;
    atrbvh_error e;
    float lo[3], hi[3];
    double diag = 0.0;
    size_t pixels = (size_t)width * height, n, i, hitcount = 0;
    unsigned v, x, y, s;
    int k;
    memset(rs, 0, sizeof *rs);
    n = pixels * viewpoints;
    rs->primary = malloc((n ? n : 1) * sizeof *rs->primary);
    hits = malloc((n ? n : 1) * sizeof *hits);
    if (!rs->primary || !hits) {
        cli_error("out of memory for %zu rays", n);
        goto fail;
    }
    scene_bounds(sc, lo, hi);
    for (k = 0; k < 3; k++)
        diag += ((double)hi[k] - lo[k]) * ((double)hi[k] - lo[k]);
    diag = sqrt(diag);
    if (!view || !view->have_eye)
        room = scene_is_room(sc, lo, hi, NULL);
    for (v = 0, i = 0; v < viewpoints; v++) {
        camera cam;
        if (camera_viewpoint(lo, hi, room, v, view,
                             (float)width / (float)height, &cam) != 0) {
            cli_error("the camera's eye is its look-at point");
            goto fail;
        }
        for (y = 0; y < height; y++)
            for (x = 0; x < width; x++, i++)
                camera_ray(&cam, width, height, x, y, 0.5f, 0.5f,
                           &rs->primary[i]);
    }
    rs->n_primary = n;
    memset(&e, 0, sizeof e);
    if (atrbvh_intersect_batch(ref, &g, rs->primary, n, hits, threads, &e) !=
        ATRBVH_OK) {
        cli_error("tracing primary rays: %s", e.text);
        goto fail;
    }
    for (i = 0; i < n; i++)
        hitcount += hits[i].primitive != ATRBVH_NO_HIT;
    if (spp > 0 && hitcount > 0) {
        size_t m = hitcount * spp, a = 0;
        rs->ao = malloc(m * sizeof *rs->ao);
        rs->diffuse = malloc(m * sizeof *rs->diffuse);
        if (!rs->ao || !rs->diffuse) {
            cli_error("out of memory for %zu rays", 2 * m);
            goto fail;
        }
        for (i = 0; i < n; i++) {
            if (hits[i].primitive == ATRBVH_NO_HIT)
                continue;
            ray_surface surf;
            rays_surface(sc, &rs->primary[i], &hits[i], diag * 1e-5, &surf);
            for (s = 0; s < spp; s++, a++) {
                rays_cosine(&surf, RAYS_SEED_AO, i, s, (float)(0.1 * diag),
                            &rs->ao[a]);
                rays_cosine(&surf, RAYS_SEED_DIFFUSE, i, s,
                            (float)(2.0 * diag), &rs->diffuse[a]);
            }
        }
        rs->n_ao = rs->n_diffuse = m;
    }
    free(hits);
    return 0;
fail:
    free(hits);
    ray_set_free(rs);
    return -1;
}
