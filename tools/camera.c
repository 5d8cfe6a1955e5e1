/*
 * camera.c - deterministic viewpoints framing a box, and primary rays.
 *
 * Viewpoint k looks at the centre c of the box from the direction
 *     azimuth   30 + 45 k degrees about the vertical (y) axis, measured
 *               from +z towards +x (k = 0: in front, a little to the right;
 *               eight steps go once around);
 *     elevation 25, 10, 40 degrees above the horizontal for k mod 3 = 0,
 *               1, 2 (never below, so terrains are seen from above);
 * at 1.05 times the nearest distance from which all eight corners of the
 * box are in the picture (vertical field of view 50 degrees, horizontal
 * from the aspect ratio), and never nearer than 1.05 times the radius r of
 * the box's bounding sphere (half its diagonal).  So the eye is always
 * outside the box and the whole box is in the picture.
 * This is what atrbvh(1) documents under CAMERAS; keep the two in step.
 */
#include "config.h"

#include "scene.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
#define VFOV_DEGREES 50.0

static const double elevations[3] = {25.0, 10.0, 40.0};

void camera_frame(const float lo[3], const float hi[3], unsigned which,
                  float aspect, camera *cam)
{
    camera_frame_fov(lo, hi, which, aspect, VFOV_DEGREES, cam);
}

void camera_frame_fov(const float lo[3], const float hi[3], unsigned which,
                      float aspect, double fov, camera *cam)
{
    double c[3], r = 0.0, az, el, tan_v, tan_h, dist, f[3], rt[3], up[3],
           len, span = 0.0;
    int k;
    memset(cam, 0, sizeof *cam);
    if (!(aspect > 0.0f && aspect <= FLT_MAX))
        aspect = 1.0f;
    for (k = 0; k < 3; k++) {
        double l = lo[k], h = hi[k];
        if (!(l <= h) || !isfinite(l) || !isfinite(h))
            l = h = 0.0;
        c[k] = 0.5 * l + 0.5 * h;
        r += (h - l) * (h - l);
        if (fabs(c[k]) > span)
            span = fabs(c[k]);
    }
    r = 0.5 * sqrt(r);
    /* A point (or empty) scene still needs a finite, nonzero distance, on
     * the scale of its coordinates so the eye is not lost in rounding. */
    if (!(r > 0.0))
        r = span > 0.0 ? span * 1e-3 : 1.0;
    az = (30.0 + 45.0 * (double)(which % 8u)) * PI / 180.0;
    el = elevations[which % 3u] * PI / 180.0;
    if (!(fov > 0.0 && fov < 180.0))
        fov = VFOV_DEGREES;
    tan_v = tan(0.5 * fov * PI / 180.0);
    tan_h = tan_v * (double)aspect;
    f[0] = -sin(az) * cos(el);
    f[1] = -sin(el);
    f[2] = -cos(az) * cos(el);
    /* right = forward x world up (0, 1, 0), normalised; |f| = 1 already. */
    rt[0] = -f[2];
    rt[1] = 0.0;
    rt[2] = f[0];
    len = sqrt(rt[0] * rt[0] + rt[2] * rt[2]);
    rt[0] /= len;
    rt[2] /= len;
    up[0] = rt[1] * f[2] - rt[2] * f[1];
    up[1] = rt[2] * f[0] - rt[0] * f[2];
    up[2] = rt[0] * f[1] - rt[1] * f[0];
    /* The nearest distance at which all eight corners are in the picture:
     * a corner at (x, y, z) in the camera frame, relative to the centre,
     * needs |x| <= tan_h (dist + z) and |y| <= tan_v (dist + z). */
    dist = 0.0;
    for (k = 0; k < 8; k++) {
        double q[3], x = 0.0, y = 0.0, z = 0.0, need;
        int a;
        for (a = 0; a < 3; a++) {
            double l = lo[a], h = hi[a];
            if (!(l <= h) || !isfinite(l) || !isfinite(h))
                l = h = 0.0;
            q[a] = ((k >> a) & 1 ? h : l) - c[a];
            x += q[a] * rt[a];
            y += q[a] * up[a];
            z += q[a] * f[a];
        }
        need = fabs(x) / tan_h - z;
        if (fabs(y) / tan_v - z > need)
            need = fabs(y) / tan_v - z;
        if (need > dist)
            dist = need;
    }
    /* A margin of 5%; and never closer than the bounding sphere, so the eye
     * is outside the box whatever the rounding. */
    dist *= 1.05;
    if (dist < 1.05 * r)
        dist = 1.05 * r;
    /* A scene near the end of the float range (a box of 3e38): the eye as
     * far as floats reach, nearer than the whole box needs, so that the
     * eye is a float and the hits' distances are (a hit beyond FLT_MAX
     * is none: before, no primary ray hit such a scene) */
    if (dist + r > 0.999 * FLT_MAX)
        dist = 0.999 * FLT_MAX - r;
    for (k = 0; k < 3; k++)
        if (fabs(f[k]) > 0.0 &&
            fabs(c[k]) + dist * fabs(f[k]) > 0.999 * FLT_MAX)
            dist = (0.999 * FLT_MAX - fabs(c[k])) / fabs(f[k]);
    if (!(dist > 0.0))
        dist = 0.0;
    for (k = 0; k < 3; k++) {
        cam->eye[k] = (float)(c[k] - dist * f[k]);
        cam->forward[k] = (float)f[k];
        cam->right[k] = (float)(rt[k] * tan_h);
        cam->up[k] = (float)(up[k] * tan_v);
    }
    /* Twice the diagonal (what diffuse rays use), or more when the eye is
     * so far out that primary rays need it to cross the whole box. */
    cam->far_distance = (float)(dist + 2.0 * r > 4.0 * r ? dist + 2.0 * r
                                                          : 4.0 * r);
    if (!(cam->far_distance <= FLT_MAX)) /* (rays to the end of floats) */
        cam->far_distance = FLT_MAX;
}

/* The box with non-finite or reversed extents made a point at 0. */
static void sane_box(const float lo[3], const float hi[3], double l[3],
                     double h[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        l[k] = lo[k];
        h[k] = hi[k];
        if (!(l[k] <= h[k]) || !isfinite(l[k]) || !isfinite(h[k]))
            l[k] = h[k] = 0.0;
    }
}

/* The frame of a camera looking along f (unit), world up +y (+z when f is
 * vertical), and its ray length: to the box's farthest corner and back
 * (twice), at least 4 x the bounding sphere's radius. */
static void set_frame(const double eye[3], const double f[3], double fov,
                      float aspect, const float lo[3], const float hi[3],
                      camera *cam)
{
    double rt[3], up[3], len, tan_v, tan_h, l[3], h[3], far2 = 0.0, r = 0.0;
    int k, c;
    if (!(aspect > 0.0f && aspect <= FLT_MAX))
        aspect = 1.0f;
    tan_v = tan(0.5 * fov * PI / 180.0);
    tan_h = tan_v * (double)aspect;
    /* right = forward x up */
    rt[0] = -f[2];
    rt[1] = 0.0;
    rt[2] = f[0];
    len = sqrt(rt[0] * rt[0] + rt[2] * rt[2]);
    if (!(len > 1e-9)) { /* looking straight up or down: up is +z */
        rt[0] = f[1];
        rt[1] = -f[0];
        rt[2] = 0.0;
        len = sqrt(rt[0] * rt[0] + rt[1] * rt[1]);
        if (!(len > 0.0)) {
            rt[0] = 1.0;
            len = 1.0;
        }
    }
    for (k = 0; k < 3; k++)
        rt[k] /= len;
    up[0] = rt[1] * f[2] - rt[2] * f[1];
    up[1] = rt[2] * f[0] - rt[0] * f[2];
    up[2] = rt[0] * f[1] - rt[1] * f[0];
    sane_box(lo, hi, l, h);
    for (k = 0; k < 3; k++)
        r += (h[k] - l[k]) * (h[k] - l[k]);
    r = 0.5 * sqrt(r);
    for (c = 0; c < 8; c++) {
        double d2 = 0.0;
        for (k = 0; k < 3; k++) {
            double q = ((c >> k) & 1 ? h[k] : l[k]) - eye[k];
            d2 += q * q;
        }
        if (d2 > far2)
            far2 = d2;
    }
    memset(cam, 0, sizeof *cam);
    for (k = 0; k < 3; k++) {
        cam->eye[k] = (float)eye[k];
        cam->forward[k] = (float)f[k];
        cam->right[k] = (float)(rt[k] * tan_h);
        cam->up[k] = (float)(up[k] * tan_v);
    }
    far2 = 2.0 * sqrt(far2);
    cam->far_distance = (float)(far2 > 4.0 * r ? far2 : 4.0 * r);
    if (!(cam->far_distance > 0.0f))
        cam->far_distance = 1.0f;
}

int camera_look(const float eye[3], const float at[3], double fov,
                float aspect, const float lo[3], const float hi[3],
                camera *cam)
{
    double e[3], f[3], len = 0.0;
    int k;
    for (k = 0; k < 3; k++) {
        e[k] = eye[k];
        f[k] = (double)at[k] - e[k];
        len += f[k] * f[k];
    }
    len = sqrt(len);
    if (!(len > 0.0) || !isfinite(len))
        return -1;
    for (k = 0; k < 3; k++)
        f[k] /= len;
    if (!(fov > 0.0 && fov < 180.0))
        fov = VFOV_DEGREES;
    set_frame(e, f, fov, aspect, lo, hi, cam);
    return 0;
}

#define INSIDE_FOV 70.0
#define INSIDE_PITCH 10.0

void camera_inside(const float lo[3], const float hi[3], unsigned j,
                   float aspect, double fov, camera *cam)
{
    double l[3], h[3], c[3], f[3], az, el = INSIDE_PITCH * PI / 180.0;
    int k;
    sane_box(lo, hi, l, h);
    for (k = 0; k < 3; k++)
        c[k] = 0.5 * l[k] + 0.5 * h[k];
    /* azimuth from +z towards +x: along the longer horizontal axis first */
    az = (h[0] - l[0] > h[2] - l[2] ? 90.0 : 0.0) + 90.0 * (double)(j % 4u);
    az *= PI / 180.0;
    f[0] = sin(az) * cos(el);
    f[1] = -sin(el);
    f[2] = cos(az) * cos(el);
    if (!(fov > 0.0 && fov < 180.0))
        fov = INSIDE_FOV;
    set_frame(c, f, fov, aspect, lo, hi, cam);
}

int camera_viewpoint(const float lo[3], const float hi[3], int room,
                     unsigned which, const camera_view *v, float aspect,
                     camera *cam)
{
    double fov = v ? v->fov : 0.0;
    if (v && v->have_eye) {
        float at[3];
        int k;
        if (v->have_at) {
            for (k = 0; k < 3; k++)
                at[k] = v->at[k];
        } else {
            double l[3], h[3];
            sane_box(lo, hi, l, h);
            for (k = 0; k < 3; k++)
                at[k] = (float)(0.5 * l[k] + 0.5 * h[k]);
        }
        return camera_look(v->eye, at, fov, aspect, lo, hi, cam);
    }
    if (room && which % 2u == 0u)
        camera_inside(lo, hi, which / 2u, aspect, fov, cam);
    else
        camera_frame_fov(lo, hi, room ? which / 2u : which, aspect,
                         fov > 0.0 ? fov : VFOV_DEGREES, cam);
    return 0;
}

/* Twice the area of triangle a b c projected along axis `ax`. */
static double proj_area2(const float *a, const float *b, const float *c,
                         int ax)
{
    int u = (ax + 1) % 3, w = (ax + 2) % 3;
    double x1 = (double)b[u] - a[u], y1 = (double)b[w] - a[w];
    double x2 = (double)c[u] - a[u], y2 = (double)c[w] - a[w];
    return fabs(x1 * y2 - x2 * y1);
}

int scene_is_room(const scene *s, const float lo[3], const float hi[3],
                  int *faces)
{
    double cover[6] = {0, 0, 0, 0, 0, 0}, l[3], h[3], ext[3];
    size_t i;
    int k, side, n = 0;
    sane_box(lo, hi, l, h);
    for (k = 0; k < 3; k++)
        ext[k] = h[k] - l[k];
    for (i = 0; i < s->triangle_count; i++) {
        const uint32_t *t = s->indices + 3 * i;
        const float *p[3];
        int j, ok = 1;
        for (j = 0; j < 3; j++) {
            if (t[j] >= s->vertex_count)
                ok = 0;
        }
        if (!ok)
            continue;
        for (j = 0; j < 3; j++)
            p[j] = s->vertices + 3 * (size_t)t[j];
        for (k = 0; k < 3; k++) {
            double tol = 0.02 * ext[k];
            if (!(ext[k] > 0.0))
                continue;
            for (side = 0; side < 2; side++) {
                double plane = side ? h[k] : l[k];
                int on = 1;
                for (j = 0; j < 3; j++)
                    if (!(fabs((double)p[j][k] - plane) <= tol))
                        on = 0;
                if (on)
                    cover[2 * k + side] +=
                        0.5 * proj_area2(p[0], p[1], p[2], k);
            }
        }
    }
    for (k = 0; k < 3; k++) {
        double area = ext[(k + 1) % 3] * ext[(k + 2) % 3];
        for (side = 0; side < 2; side++)
            if (area > 0.0 && cover[2 * k + side] >= 0.25 * area)
                n++;
    }
    if (faces)
        *faces = n;
    return n >= 3;
}

void camera_ray(const camera *cam, unsigned width, unsigned height,
                unsigned x, unsigned y, float sx, float sy, atrbvh_ray *ray)
{
    double u, v, d[3], len;
    int k;
    if (width == 0)
        width = 1;
    if (height == 0)
        height = 1;
    /* u to the right, v up; row 0 is the top of the image. */
    u = 2.0 * ((double)x + (double)sx) / (double)width - 1.0;
    v = 1.0 - 2.0 * ((double)y + (double)sy) / (double)height;
    for (k = 0; k < 3; k++)
        d[k] = (double)cam->forward[k] + u * (double)cam->right[k] +
               v * (double)cam->up[k];
    len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (k = 0; k < 3; k++) {
        ray->origin[k] = cam->eye[k];
        ray->dir[k] = (float)(d[k] / len);
    }
    ray->tmin = 0.0f;
    ray->tmax = cam->far_distance;
}
