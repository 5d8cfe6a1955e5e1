/*
 * scene.c - scene_load's dispatch (file type or built-in), reading a file
 * into memory, and what the parsers share.
 *
 * Files are read whole: the parsers then check every count a header claims
 * against the bytes actually present before allocating for it, and a
 * truncated file is just a short buffer.
 */
#include "config.h"

#include "loader.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <float.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DEFAULT_BUILTIN_TRIANGLES ((size_t)100000)

int scene_fail(char *err, size_t err_len, const char *fmt, ...)
{
    if (err && err_len > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, err_len, fmt, ap);
        va_end(ap);
    }
    return -1;
}

int scene_reserve(void **p, size_t *cap, size_t need, size_t elem)
{
    size_t n;
    void *q;
    if (need <= *cap)
        return 1;
    n = *cap ? *cap : 64;
    while (n < need) {
        if (n > SIZE_MAX / 2)
            n = need;
        else
            n *= 2;
    }
    if (elem != 0 && n > SIZE_MAX / elem)
        return 0;
    q = realloc(*p, n * elem);
    if (!q)
        return 0;
    *p = q;
    *cap = n;
    return 1;
}

float scene_float(double d)
{
    /* Round to nearest: below FLT_MAX + half an ulp (0x1.ffffffp+127, the
     * tie going to even, i.e. up) a value rounds to FLT_MAX, a finite
     * float; only from there on is it infinite. */
    if (d != d)
        return (float)d;
    if (d >= 0x1.ffffffp+127)
        return HUGE_VALF;
    if (d <= -0x1.ffffffp+127)
        return -HUGE_VALF;
    return (float)d;
}

void scene_set_name(scene *s, const char *path)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    snprintf(s->name, sizeof s->name, "%s", base);
}

/* Reads the whole file; the size is what was read, not what stat claims,
 * so pipes and files that change under us are handled the same way.
 * Reading stops after a block that holds a NUL byte, which no OBJ file
 * holds (the parser reports it, with its line): an endless stream of
 * zeros (/dev/zero) is refused at once instead of filling the memory. */
static int read_file(const char *path, unsigned char **data, size_t *size,
                     char *err, size_t err_len)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf = NULL;
    size_t cap = 0, len = 0;
    if (!f)
        return scene_fail(err, err_len, "%s: cannot open: %s", path,
                          strerror(errno));
    for (;;) {
        size_t got;
        if (!scene_reserve((void **)&buf, &cap, len + 65536, 1)) {
            free(buf);
            fclose(f);
            return scene_fail(err, err_len, "%s: out of memory reading %zu "
                              "bytes", path, len);
        }
        got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0 || memchr(buf + len - got, 0, got))
            break;
    }
    if (ferror(f)) {
        int e = errno;
        free(buf);
        fclose(f);
        return scene_fail(err, err_len, "%s: read error after %zu bytes: %s",
                          path, len, strerror(e));
    }
    fclose(f);
    *data = buf;
    *size = len;
    return 0;
}

static int ends_with_ci(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix), i;
    if (n < m)
        return 0;
    for (i = 0; i < m; i++)
        if (tolower((unsigned char)s[n - m + i]) !=
            tolower((unsigned char)suffix[i]))
            return 0;
    return 1;
}

/* "builtin:NAME[:N]" */
static int load_builtin(const char *spec, scene *out, char *err,
                        size_t err_len)
{
    const char *name = spec + strlen("builtin:");
    const char *colon = strchr(name, ':');
    char buf[32];
    size_t n = DEFAULT_BUILTIN_TRIANGLES, len;
    len = colon ? (size_t)(colon - name) : strlen(name);
    if (len == 0 || len >= sizeof buf)
        return scene_fail(err, err_len, "%s: expected builtin:NAME[:N] with "
                          "NAME sphere, terrain or city", spec);
    memcpy(buf, name, len);
    buf[len] = '\0';
    if (colon) {
        const char *p = colon + 1;
        if (*p == '\0')
            return scene_fail(err, err_len, "%s: N is empty (expected "
                              "builtin:NAME:N, N from 1 to %zu)", spec,
                              SCENE_BUILTIN_MAX);
        n = 0;
        for (; *p; p++) {
            if (*p < '0' || *p > '9')
                return scene_fail(err, err_len, "%s: N is not a whole "
                                  "number", spec);
            /* Stop accumulating past the limit: never overflows. */
            if (n <= SCENE_BUILTIN_MAX)
                n = n * 10 + (size_t)(*p - '0');
        }
        if (n < 1 || n > SCENE_BUILTIN_MAX)
            return scene_fail(err, err_len, "%s: N must be from 1 to %zu",
                              spec, SCENE_BUILTIN_MAX);
    }
    return scene_builtin(buf, n, out, err, err_len);
}

static scene_progress_fn progress_fn;
static void *progress_user;

void scene_set_progress(scene_progress_fn fn, void *user)
{
    progress_fn = fn;
    progress_user = user;
}

void scene_progress(int phase, uint64_t done, uint64_t total)
{
    if (progress_fn && total > 0)
        progress_fn(0.5 * (double)phase +
                        0.5 * (double)(done < total ? done : total) /
                            (double)total,
                    progress_user);
}

int scene_load(const char *spec, scene *out, char *err, size_t err_len)
{
    unsigned char *data = NULL;
    size_t size = 0;
    int rc;
    scene s;
    if (err && err_len > 0)
        err[0] = '\0';
    if (!spec || !out)
        return scene_fail(err, err_len, "scene_load: no scene given");
    memset(out, 0, sizeof *out);
    if (strncmp(spec, "builtin:", 8) == 0)
        return load_builtin(spec, out, err, err_len);
    if (!ends_with_ci(spec, ".ply") && !ends_with_ci(spec, ".obj"))
        return scene_fail(err, err_len, "%s: unknown scene type (expected a "
                          ".ply or .obj file, or builtin:NAME[:N])", spec);
    if ((ends_with_ci(spec, ".ply")
             ? scene_read_ply(spec, &data, &size, err, err_len)
             : read_file(spec, &data, &size, err, err_len)) != 0)
        return -1;
    memset(&s, 0, sizeof s);
    if (ends_with_ci(spec, ".ply"))
        rc = scene_parse_ply(spec, data, size, &s, err, err_len);
    else
        rc = scene_parse_obj(spec, data, size, &s, err, err_len);
    free(data);
    if (rc != 0)
        return -1;
    scene_set_name(&s, spec);
    *out = s;
    return 0;
}

void scene_free(scene *s)
{
    if (!s)
        return;
    free(s->vertices);
    free(s->indices);
    memset(s, 0, sizeof *s);
}

atrbvh_geometry scene_geometry(const scene *s)
{
    return atrbvh_geometry_triangles(s->vertices, s->vertex_count, s->indices,
                                     s->triangle_count);
}

/* Only referenced vertices count: files may carry unused vertices (the
 * bunny has 1,113) that would otherwise widen the camera's framing.
 * Non-finite coordinates are left out so that a scene that is built with
 * --skip-invalid still gets a finite box. */
void scene_bounds(const scene *s, float lo[3], float hi[3])
{
    size_t t, k;
    int any = 0;
    for (k = 0; k < 3; k++) {
        lo[k] = HUGE_VALF;
        hi[k] = -HUGE_VALF;
    }
    for (t = 0; t < s->triangle_count * 3; t++) {
        uint32_t v = s->indices[t];
        const float *p;
        if (v >= s->vertex_count)
            continue;
        p = s->vertices + (size_t)v * 3;
        if (!(fabsf(p[0]) <= FLT_MAX && fabsf(p[1]) <= FLT_MAX &&
              fabsf(p[2]) <= FLT_MAX))
            continue;
        for (k = 0; k < 3; k++) {
            if (p[k] < lo[k])
                lo[k] = p[k];
            if (p[k] > hi[k])
                hi[k] = p[k];
        }
        any = 1;
    }
    if (!any)
        for (k = 0; k < 3; k++)
            lo[k] = hi[k] = 0.0f;
}
