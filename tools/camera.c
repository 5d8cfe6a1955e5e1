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
    tan_v = tan(0.5 * VFOV_DEGREES * PI / 180.0);
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
