/*
 * obj.c - Wavefront OBJ reader: `v x y z [w]` and `f a b c ...` with the
 * a, a/b, a/b/c and a//c forms, negative (relative) indices, polygons
 * fan-triangulated.  The other statements of the OBJ specification (vn,
 * vt, g, o, s, usemtl, l, p, curves and surfaces, ...) are ignored.  Any
 * other first word is an error, not ignored: it could be a vertex or face
 * whose keyword was damaged (a byte-order mark glued to the first "v", say),
 * and dropping a vertex silently would shift every later index and build
 * the wrong triangles; with no warning channel, refusing is the only way to
 * say so.  A UTF-8 byte-order mark at the start of the file is skipped.
 * Coordinates are rounded to float once, from the decimal (strtof), so
 * "3.4028235e+38" is FLT_MAX; only values that round to infinity are
 * infinite.  Errors name the file and the line.
 */
#include "config.h"

#include "loader.h"

#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOKEN_LEN 128

typedef struct obj {
    const char *path;
    unsigned long line;
    char *err;
    size_t err_len;
    float *vertices;
    size_t vertex_count, vertex_cap;
    uint32_t *indices;
    size_t triangle_count, triangle_cap;
} obj;

static int obj_fail(obj *o, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static int obj_fail(obj *o, const char *fmt, ...)
{
    char what[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return scene_fail(o->err, o->err_len, "%s: line %lu: %s", o->path,
                      o->line, what);
}

/* Next whitespace-separated token of [*s, end) into tok; 0 when none. */
static int next_token(obj *o, const char **s, const char *end, char *tok,
                      int *status)
{
    const char *p = *s;
    size_t len = 0;
    *status = 0;
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\f' ||
                       *p == '\v'))
        p++;
    if (p == end) {
        *s = p;
        return 0;
    }
    while (p < end && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\f' &&
           *p != '\v') {
        if (*p == '\0') {
            *status = obj_fail(o, "NUL byte");
            return 0;
        }
        if (len + 1 == TOKEN_LEN) {
            *status = obj_fail(o, "token too long");
            return 0;
        }
        tok[len++] = *p++;
    }
    tok[len] = '\0';
    *s = p;
    return 1;
}

static int parse_float(const char *tok, double *out)
{
    char *end;
    *out = strtod(tok, &end);
    return end != tok && *end == '\0';
}

/* A coordinate: rounded to float once, correctly (ERANGE is fine: an
 * overflow is +-inf, reported by the library as non-finite). */
static int parse_coordinate(const char *tok, float *out)
{
    char *end;
    *out = strtof(tok, &end);
    return end != tok && *end == '\0';
}

/* The statements of the OBJ specification that carry nothing this loader
 * uses; they are skipped.  Every other keyword but v and f is an error. */
static const char *const ignored_statements[] = {
    "vt", "vn", "vp", "cstype", "deg", "bmat", "step", "p", "l", "curv",
    "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con",
    "g", "s", "mg", "o", "bevel", "c_interp", "d_interp", "lod", "usemtl",
    "mtllib", "shadow_obj", "trace_obj", "ctech", "stech", "maplib",
    "usemap", "call", "csh"};

static int ignored_statement(const char *kw)
{
    size_t i;
    for (i = 0; i < sizeof ignored_statements / sizeof *ignored_statements;
         i++)
        if (strcmp(kw, ignored_statements[i]) == 0)
            return 1;
    return 0;
}

static int add_vertex(obj *o, const char *s, const char *end)
{
    char tok[TOKEN_LEN];
    float c[3];
    int k, st;
    float *v;
    for (k = 0; k < 3; k++) {
        if (!next_token(o, &s, end, tok, &st))
            return st ? st
                      : obj_fail(o, "a vertex needs three coordinates, found %d",
                             k);
        if (!parse_coordinate(tok, &c[k]))
            return obj_fail(o, "vertex coordinate \"%s\" is not a number", tok);
    }
    /* An optional w, or the common r g b extension: numbers, ignored. */
    while (next_token(o, &s, end, tok, &st)) {
        double ignored;
        if (!parse_float(tok, &ignored))
            return obj_fail(o, "vertex value \"%s\" is not a number", tok);
    }
    if (st)
        return st;
    if (o->vertex_count == UINT32_MAX)
        return obj_fail(o, "more vertices than 32-bit indices can address");
    if (!scene_reserve((void **)&o->vertices, &o->vertex_cap,
                       o->vertex_count + 1, 3 * sizeof(float)))
        return obj_fail(o, "out of memory at %zu vertices", o->vertex_count);
    v = o->vertices + o->vertex_count * 3;
    for (k = 0; k < 3; k++)
        v[k] = c[k];
    o->vertex_count++;
    return 0;
}

/* An optional index after a '/': empty or an integer (not used). */
static int check_optional_index(const char *s, const char *stop)
{
    const char *p = s;
    if (p == stop)
        return 1;
    if (*p == '-' || *p == '+')
        p++;
    if (p == stop)
        return 0;
    for (; p < stop; p++)
        if (*p < '0' || *p > '9')
            return 0;
    return 1;
}

/* "a", "a/b", "a/b/c" or "a//c": the vertex index a, resolved. */
static int parse_ref(obj *o, const char *tok, uint32_t *out)
{
    const char *slash = strchr(tok, '/');
    char num[TOKEN_LEN], *end;
    size_t len = slash ? (size_t)(slash - tok) : strlen(tok);
    long long a;
    memcpy(num, tok, len);
    num[len] = '\0';
    if (slash) {
        const char *s2 = strchr(slash + 1, '/');
        const char *e1 = s2 ? s2 : slash + strlen(slash);
        if (!check_optional_index(slash + 1, e1) ||
            (s2 && (!check_optional_index(s2 + 1, s2 + strlen(s2)) ||
                    strchr(s2 + 1, '/'))))
            return obj_fail(o, "face vertex \"%s\" is not of the form a, a/b, "
                        "a/b/c or a//c", tok);
    }
    errno = 0;
    a = len ? strtoll(num, &end, 10) : 0;
    if (len == 0 || *end != '\0')
        return obj_fail(o, "face vertex index \"%s\" is not an integer", num);
    if (errno == ERANGE || a == 0 || (a > 0 && (unsigned long long)a >
                                                   o->vertex_count) ||
        (a < 0 && (a == LLONG_MIN ||
                   (unsigned long long)(-a) > o->vertex_count)))
        return obj_fail(o, "face vertex index %s out of range (%zu vertices so "
                    "far; indices start at 1, negative ones count back)",
                    num, o->vertex_count);
    *out = a > 0 ? (uint32_t)(a - 1)
                 : (uint32_t)(o->vertex_count - (size_t)(-a));
    return 0;
}

static int add_face(obj *o, const char *s, const char *end)
{
    char tok[TOKEN_LEN];
    uint32_t first = 0, prev = 0, cur = 0;
    size_t n = 0;
    int st;
    while (next_token(o, &s, end, tok, &st)) {
        if (parse_ref(o, tok, &cur) != 0)
            return -1;
        if (n == 0) {
            first = cur;
        } else if (n >= 2) {
            uint32_t *t;
            if (!scene_reserve((void **)&o->indices, &o->triangle_cap,
                               o->triangle_count + 1, 3 * sizeof(uint32_t)))
                return obj_fail(o, "out of memory at %zu triangles",
                            o->triangle_count);
            t = o->indices + o->triangle_count * 3;
            t[0] = first;
            t[1] = prev;
            t[2] = cur;
            o->triangle_count++;
        }
        prev = cur;
        n++;
    }
    if (st)
        return st;
    if (n < 3)
        return obj_fail(o, "a face needs at least 3 vertices, found %zu", n);
    return 0;
}

int scene_parse_obj(const char *path, const unsigned char *data, size_t size,
                    scene *out, char *err, size_t err_len)
{
    obj o;
    const char *p = (const char *)data, *stop = p + size;
    memset(&o, 0, sizeof o);
    o.path = path;
    o.err = err;
    o.err_len = err_len;
    if (size >= 3 && memcmp(p, "\xef\xbb\xbf", 3) == 0)
        p += 3; /* a UTF-8 byte-order mark */
    while (p < stop) {
        const char *nl = memchr(p, '\n', (size_t)(stop - p));
        const char *end = nl ? nl : stop, *hash, *s = p;
        char kw[TOKEN_LEN];
        int st, rc = 0;
        if ((++o.line & 0xffffu) == 0)
            scene_progress(1, (uint64_t)(p - (const char *)data), size);
        hash = memchr(p, '#', (size_t)(end - p));
        if (hash)
            end = hash;
        if (next_token(&o, &s, end, kw, &st)) {
            if (strcmp(kw, "v") == 0)
                rc = add_vertex(&o, s, end);
            else if (strcmp(kw, "f") == 0)
                rc = add_face(&o, s, end);
            else if (!ignored_statement(kw))
                rc = obj_fail(&o, "unknown statement \"%.40s\" (not an OBJ "
                              "keyword; refused rather than skipped, as it "
                              "could be a damaged vertex or face)",
                              kw);
        } else {
            rc = st;
        }
        if (rc != 0) {
            free(o.vertices);
            free(o.indices);
            return -1;
        }
        p = nl ? nl + 1 : stop;
    }
    out->vertices = o.vertices;
    out->vertex_count = o.vertex_count;
    out->indices = o.indices;
    out->triangle_count = o.triangle_count;
    return 0;
}
