/*
 * ply.c - PLY reader (ascii, binary_little_endian, binary_big_endian).
 *
 * Reads x, y, z of the "vertex" element and the vertex_indices (or
 * vertex_index) list of the "face" element; every other element and
 * property is parsed only to be skipped, so properties may be of any type
 * and in any order.  Polygons are fan-triangulated (v0, vi, vi+1).  A
 * second "vertex" or "face" element, or a second index list in the face
 * element, is an error, not skipped: it would hold geometry left out.
 *
 * The file is hostile until proven otherwise: every count the header
 * declares is checked against the bytes left before anything is allocated
 * for it, list lengths are checked against the bytes left before they are
 * walked, and every index against the vertex count.  Errors name the file
 * and the header or ASCII line, or the byte offset in binary data.
 *
 * Reading (scene_read_ply) is bounded too, so that /dev/zero or a huge
 * sparse file is refused without being read whole: the header is read
 * first, at most PLY_HEADER_MAX bytes (a first line that is not "ply" is
 * refused at once); then the sizes its elements can take, fewest and most,
 * are computed, a regular file whose size lies outside them is refused
 * before its body is read (a file too short, only above PLY_SMALL_FILE
 * bytes: a smaller one is parsed, for an error that names the line or
 * byte where the data runs out), and no more body than the most (plus
 * PLY_TRAILING_MAX) is ever read from a stream.  For the most to exist in
 * ASCII, an item (its line, with any blank lines before it) may hold at
 * most PLY_ASCII_VALUE_MAX bytes per value plus PLY_ASCII_ITEM_EXTRA.
 *
 * A UTF-8 byte-order mark before "ply" is skipped.  Coordinates are
 * rounded to float correctly (strtof for ASCII float properties, a
 * correctly rounded conversion for doubles): a value that rounds to
 * FLT_MAX is finite.  Text after the last element of an ASCII file is an
 * error rather than ignored (it is most likely data the header's counts
 * leave out); up to PLY_TRAILING_MAX bytes after the last element of a
 * binary file are ignored (padding some writers add).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "loader.h"

#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

/* Reading bounds (see the top of the file). */
#define PLY_HEADER_MAX ((size_t)1 << 20)
#define PLY_TRAILING_MAX ((uint64_t)65536)
#define PLY_ASCII_VALUE_MAX ((uint64_t)256)
#define PLY_ASCII_ITEM_EXTRA ((uint64_t)1024)
#define PLY_READ_CHUNK ((size_t)65536)
/* A file at most this large is read even when too short for its header:
 * the parser then names the line or byte offset where it runs out. */
#define PLY_SMALL_FILE ((uint64_t)16 << 20)

#define MAX_ELEMENTS 64
#define MAX_PROPERTIES 256
#define NAME_LEN 64
#define TOKEN_LEN 128

typedef enum ply_type {
    T_NONE = 0,
    T_I8,
    T_U8,
    T_I16,
    T_U16,
    T_I32,
    T_U32,
    T_F32,
    T_F64
} ply_type;

typedef enum ply_format { F_ASCII, F_LE, F_BE } ply_format;

typedef struct ply_prop {
    ply_type type;       /* scalar type, or the item type of a list */
    ply_type count_type; /* T_NONE for a scalar                     */
    char name[NAME_LEN];
} ply_prop;

typedef struct ply_element {
    char name[NAME_LEN];
    uint64_t count;
    size_t nprops;
    ply_prop props[MAX_PROPERTIES];
    unsigned header_line;
} ply_element;

typedef struct ply_value {
    int is_float;
    int64_t i;
    double f;
} ply_value;

/* All the parser's state, so that every helper can report an error. */
typedef struct ply {
    const char *path;
    const unsigned char *data;
    size_t size;
    size_t pos;
    unsigned line; /* ASCII: the line of `pos` */
    ply_format format;
    size_t nelements;
    ply_element *elements;
    char *err;
    size_t err_len;
    int need_more; /* parse_header failed only for want of more bytes */
    /* output */
    float *vertices;
    size_t vertex_count;
    uint32_t *indices; /* 3 per triangle */
    size_t triangle_count, triangle_cap;
} ply;

static const struct {
    const char *name;
    ply_type type;
} type_names[] = {
    {"char", T_I8},    {"int8", T_I8},      {"uchar", T_U8},
    {"uint8", T_U8},   {"short", T_I16},    {"int16", T_I16},
    {"ushort", T_U16}, {"uint16", T_U16},   {"int", T_I32},
    {"int32", T_I32},  {"uint", T_U32},     {"uint32", T_U32},
    {"float", T_F32},  {"float32", T_F32},  {"double", T_F64},
    {"float64", T_F64}};

static ply_type parse_type(const char *s)
{
    size_t i;
    for (i = 0; i < sizeof type_names / sizeof type_names[0]; i++)
        if (strcmp(s, type_names[i].name) == 0)
            return type_names[i].type;
    return T_NONE;
}

static size_t type_size(ply_type t)
{
    switch (t) {
    case T_I8:
    case T_U8:
        return 1;
    case T_I16:
    case T_U16:
        return 2;
    case T_I32:
    case T_U32:
    case T_F32:
        return 4;
    case T_F64:
        return 8;
    case T_NONE:
        break;
    }
    return 0;
}

static int is_integer_type(ply_type t)
{
    return t != T_NONE && t != T_F32 && t != T_F64;
}

/* ------------------------------------------------------------- errors */
/* The location as "line N" (header, ASCII) or "byte offset N" (binary). */
static int fail_at(ply *p, size_t offset, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int fail_at(ply *p, size_t offset, const char *fmt, ...)
{
    char what[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (p->format == F_ASCII)
        return scene_fail(p->err, p->err_len, "%s: line %u: %s", p->path,
                          p->line, what);
    return scene_fail(p->err, p->err_len, "%s: byte offset %zu: %s", p->path,
                      offset, what);
}

static int fail_line(ply *p, unsigned line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int fail_line(ply *p, unsigned line, const char *fmt, ...)
{
    char what[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return scene_fail(p->err, p->err_len, "%s: line %u: %s", p->path, line,
                      what);
}

/* ------------------------------------------------------------- header */
/* Splits a header line (NUL-terminated copy) into at most `max` tokens. */
static size_t split(char *line, char **tok, size_t max)
{
    size_t n = 0;
    char *s = line;
    for (;;) {
        while (*s == ' ' || *s == '\t' || *s == '\r')
            s++;
        if (!*s)
            return n;
        if (n == max)
            return max + 1;
        tok[n++] = s;
        while (*s && *s != ' ' && *s != '\t' && *s != '\r')
            s++;
        if (*s)
            *s++ = '\0';
    }
}

static int parse_u64(const char *s, uint64_t *out)
{
    uint64_t v = 0;
    if (!*s)
        return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9')
            return 0;
        if (v > (UINT64_MAX - (uint64_t)(*s - '0')) / 10)
            return 0;
        v = v * 10 + (uint64_t)(*s - '0');
    }
    *out = v;
    return 1;
}

static int parse_header(ply *p)
{
    char line[512];
    char *tok[8];
    int have_format = 0;
    ply_element *cur = NULL;
    p->line = 0;
    p->need_more = 0;
    if (p->size >= 3 && memcmp(p->data, "\xef\xbb\xbf", 3) == 0)
        p->pos = 3; /* a UTF-8 byte-order mark */
    {
        /* Whatever has arrived of the first line must begin "ply" (so that
         * /dev/zero is refused after its first bytes). */
        size_t have = p->size - p->pos < 3 ? p->size - p->pos : 3;
        if (have > 0 && memcmp(p->data + p->pos, "ply", have) != 0)
            return fail_line(p, 1, "not a PLY file (the first line is not "
                             "\"ply\")");
    }
    for (;;) {
        size_t start = p->pos, end, len, n;
        const unsigned char *nl;
        p->line++;
        if (start >= p->size) {
            p->need_more = 1;
            if (p->size == 0)
                return fail_line(p, 1, "empty file (not a PLY file)");
            return fail_line(p, p->line, "the header ends without "
                             "end_header");
        }
        nl = memchr(p->data + start, '\n', p->size - start);
        if (!nl) {
            p->need_more = 1;
            return fail_line(p, p->line, "the header ends without "
                             "end_header");
        }
        end = (size_t)(nl - p->data);
        p->pos = end + 1;
        len = end - start;
        if (len >= sizeof line) {
            /* Comments may be long; nothing else in a header need be. */
            if ((len > 8 && memcmp(p->data + start, "comment ", 8) == 0) ||
                (len > 9 && memcmp(p->data + start, "obj_info ", 9) == 0))
                continue;
            return fail_line(p, p->line, "header line too long");
        }
        memcpy(line, p->data + start, len);
        line[len] = '\0';
        if (memchr(line, '\0', len))
            return fail_line(p, p->line, "NUL byte in the header");
        if (p->line == 1) {
            n = split(line, tok, 2);
            if (n != 1 || strcmp(tok[0], "ply") != 0)
                return fail_line(p, 1, "not a PLY file (the first line is "
                                 "not \"ply\")");
            continue;
        }
        if (strncmp(line, "comment", 7) == 0 &&
            (line[7] == '\0' || line[7] == ' ' || line[7] == '\t' ||
             line[7] == '\r'))
            continue;
        if (strncmp(line, "obj_info", 8) == 0 &&
            (line[8] == '\0' || line[8] == ' ' || line[8] == '\t' ||
             line[8] == '\r'))
            continue;
        n = split(line, tok, 6);
        if (n == 0)
            continue;
        if (strcmp(tok[0], "format") == 0) {
            if (have_format)
                return fail_line(p, p->line, "a second format line");
            if (n != 3)
                return fail_line(p, p->line, "expected \"format TYPE "
                                 "1.0\"");
            if (strcmp(tok[1], "ascii") == 0)
                p->format = F_ASCII;
            else if (strcmp(tok[1], "binary_little_endian") == 0)
                p->format = F_LE;
            else if (strcmp(tok[1], "binary_big_endian") == 0)
                p->format = F_BE;
            else
                return fail_line(p, p->line, "unknown format \"%s\"",
                                 tok[1]);
            if (strcmp(tok[2], "1.0") != 0 && strcmp(tok[2], "1") != 0)
                return fail_line(p, p->line, "unsupported PLY version "
                                 "\"%s\"", tok[2]);
            have_format = 1;
        } else if (strcmp(tok[0], "element") == 0) {
            uint64_t count;
            if (n != 3)
                return fail_line(p, p->line, "expected \"element NAME "
                                 "COUNT\"");
            if (!parse_u64(tok[2], &count))
                return fail_line(p, p->line, "element count \"%s\" is not "
                                 "a whole number", tok[2]);
            if (p->nelements == MAX_ELEMENTS)
                return fail_line(p, p->line, "more than %d elements",
                                 MAX_ELEMENTS);
            cur = &p->elements[p->nelements++];
            snprintf(cur->name, sizeof cur->name, "%s", tok[1]);
            cur->count = count;
            cur->nprops = 0;
            cur->header_line = p->line;
        } else if (strcmp(tok[0], "property") == 0) {
            ply_prop *pr;
            if (!cur)
                return fail_line(p, p->line, "property before any "
                                 "element");
            if (cur->nprops == MAX_PROPERTIES)
                return fail_line(p, p->line, "more than %d properties",
                                 MAX_PROPERTIES);
            pr = &cur->props[cur->nprops];
            if (n == 5 && strcmp(tok[1], "list") == 0) {
                pr->count_type = parse_type(tok[2]);
                pr->type = parse_type(tok[3]);
                if (pr->count_type == T_NONE || pr->type == T_NONE)
                    return fail_line(p, p->line, "unknown type \"%s\"",
                                     pr->count_type == T_NONE ? tok[2]
                                                              : tok[3]);
                if (!is_integer_type(pr->count_type))
                    return fail_line(p, p->line, "list count type \"%s\" is "
                                     "not an integer type", tok[2]);
                snprintf(pr->name, sizeof pr->name, "%s", tok[4]);
            } else if (n == 3 && strcmp(tok[1], "list") != 0) {
                pr->count_type = T_NONE;
                pr->type = parse_type(tok[1]);
                if (pr->type == T_NONE)
                    return fail_line(p, p->line, "unknown type \"%s\"",
                                     tok[1]);
                snprintf(pr->name, sizeof pr->name, "%s", tok[2]);
            } else {
                return fail_line(p, p->line, "expected \"property TYPE "
                                 "NAME\" or \"property list TYPE TYPE "
                                 "NAME\"");
            }
            cur->nprops++;
        } else if (strcmp(tok[0], "end_header") == 0) {
            if (n != 1)
                return fail_line(p, p->line, "unexpected text after "
                                 "end_header");
            if (!have_format)
                return fail_line(p, p->line, "no format line before "
                                 "end_header");
            return 0;
        } else {
            return fail_line(p, p->line, "unknown header keyword \"%s\"",
                             tok[0]);
        }
    }
}

/* --------------------------------------------------------------- binary */
static int bin_read(ply *p, ply_type t, ply_value *v)
{
    size_t n = type_size(t), k;
    uint64_t u = 0;
    const unsigned char *b;
    if (p->size - p->pos < n)
        return fail_at(p, p->pos, "the file ends inside a value (truncated)");
    b = p->data + p->pos;
    for (k = 0; k < n; k++) {
        size_t shift = p->format == F_LE ? k : n - 1 - k;
        u |= (uint64_t)b[k] << (8 * shift);
    }
    p->pos += n;
    v->is_float = 0;
    switch (t) {
    case T_I8:
        v->i = u >= 0x80u ? (int64_t)u - 0x100 : (int64_t)u;
        break;
    case T_U8:
    case T_U16:
    case T_U32:
        v->i = (int64_t)u;
        break;
    case T_I16:
        v->i = u >= 0x8000u ? (int64_t)u - 0x10000 : (int64_t)u;
        break;
    case T_I32:
        v->i = u >= 0x80000000u ? (int64_t)u - 0x100000000ll : (int64_t)u;
        break;
    case T_F32: {
        uint32_t w = (uint32_t)u;
        float f;
        memcpy(&f, &w, sizeof f);
        v->is_float = 1;
        v->f = f;
        break;
    }
    case T_F64: {
        double d;
        memcpy(&d, &u, sizeof d);
        v->is_float = 1;
        v->f = d;
        break;
    }
    case T_NONE:
        break;
    }
    return 0;
}

/* ---------------------------------------------------------------- ascii */
static void ascii_skip_blanks(ply *p)
{
    while (p->pos < p->size &&
           (p->data[p->pos] == ' ' || p->data[p->pos] == '\t' ||
            p->data[p->pos] == '\r'))
        p->pos++;
}

/* Moves to the first line that is not blank; 0 at the end of the file. */
static int ascii_next_line(ply *p)
{
    for (;;) {
        ascii_skip_blanks(p);
        if (p->pos >= p->size)
            return 0;
        if (p->data[p->pos] != '\n')
            return 1;
        p->pos++;
        p->line++;
    }
}

/* Ends an element's line: nothing but blanks may follow. */
static int ascii_end_line(ply *p)
{
    ascii_skip_blanks(p);
    if (p->pos < p->size && p->data[p->pos] != '\n')
        return fail_at(p, p->pos, "more values than the header declares");
    if (p->pos < p->size) {
        p->pos++;
        p->line++;
    }
    return 0;
}

static int ascii_read(ply *p, ply_type t, ply_value *v)
{
    char tok[TOKEN_LEN], *end;
    size_t len = 0;
    ascii_skip_blanks(p);
    while (p->pos + len < p->size) {
        unsigned char c = p->data[p->pos + len];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n')
            break;
        if (len + 1 == sizeof tok)
            return fail_at(p, p->pos, "value too long");
        tok[len++] = (char)c;
    }
    if (len == 0)
        return fail_at(p, p->pos, "fewer values than the header declares");
    tok[len] = '\0';
    if (memchr(tok, '\0', len))
        return fail_at(p, p->pos, "NUL byte in the data");
    p->pos += len;
    errno = 0;
    if (is_integer_type(t)) {
        long long x = strtoll(tok, &end, 10);
        int64_t lo, hi;
        if (*end != '\0')
            return fail_at(p, p->pos, "\"%s\" is not an integer", tok);
        switch (t) {
        case T_I8: lo = -128; hi = 127; break;
        case T_U8: lo = 0; hi = 255; break;
        case T_I16: lo = -32768; hi = 32767; break;
        case T_U16: lo = 0; hi = 65535; break;
        case T_I32: lo = INT32_MIN; hi = INT32_MAX; break;
        default: lo = 0; hi = UINT32_MAX; break;
        }
        if (errno == ERANGE || x < lo || x > hi)
            return fail_at(p, p->pos, "%s is out of range for its type",
                           tok);
        v->is_float = 0;
        v->i = (int64_t)x;
    } else {
        /* ERANGE is fine: overflow gives +-HUGE_VAL (reported later as
         * non-finite by the library), underflow a tiny value.  A float
         * property is rounded to float once, from the decimal (strtof:
         * "3.4028235e+38" is FLT_MAX, not infinity); a double one to
         * double, then (scene_float) to float, as in binary files. */
        double d;
        if (t == T_F32)
            d = (double)strtof(tok, &end);
        else
            d = strtod(tok, &end);
        if (*end != '\0' || end == tok)
            return fail_at(p, p->pos, "\"%s\" is not a number", tok);
        v->is_float = 1;
        v->f = d;
    }
    return 0;
}

static int read_value(ply *p, ply_type t, ply_value *v)
{
    return p->format == F_ASCII ? ascii_read(p, t, v) : bin_read(p, t, v);
}

/* --------------------------------------------------------------- body */
/* The fewest bytes one item of `e` can take: binary, each scalar and each
 * list's count; ASCII, one character and one separator per value. */
static uint64_t min_item_bytes(const ply *p, const ply_element *e)
{
    uint64_t n = 0;
    size_t k;
    for (k = 0; k < e->nprops; k++) {
        const ply_prop *pr = &e->props[k];
        if (p->format == F_ASCII)
            n += 2;
        else
            n += type_size(pr->count_type != T_NONE ? pr->count_type
                                                    : pr->type);
    }
    return n;
}

/* The most items a list with this count type can hold. */
static uint64_t list_max(ply_type count_type)
{
    switch (count_type) {
    case T_I8: return 127u;
    case T_U8: return 255u;
    case T_I16: return 32767u;
    case T_U16: return 65535u;
    case T_I32: return 2147483647u;
    default: return 4294967295u;
    }
}

/* a + b and a * b, saturating at UINT64_MAX ("no bound"). */
static uint64_t sat_add(uint64_t a, uint64_t b)
{
    return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}

static uint64_t sat_mul(uint64_t a, uint64_t b)
{
    return a != 0 && b > UINT64_MAX / a ? UINT64_MAX : a * b;
}

/* The most bytes one item of `e` can take: binary, every list full;
 * ASCII, PLY_ASCII_VALUE_MAX per value plus PLY_ASCII_ITEM_EXTRA (the
 * parser enforces it, see read_element). */
static uint64_t max_item_bytes(const ply *p, const ply_element *e)
{
    uint64_t n = 0;
    size_t k;
    for (k = 0; k < e->nprops; k++) {
        const ply_prop *pr = &e->props[k];
        if (pr->count_type == T_NONE)
            n = sat_add(n, p->format == F_ASCII ? PLY_ASCII_VALUE_MAX
                                                : type_size(pr->type));
        else if (p->format == F_ASCII)
            n = sat_add(n, sat_mul(sat_add(list_max(pr->count_type), 1),
                                   PLY_ASCII_VALUE_MAX));
        else
            n = sat_add(n, sat_add(type_size(pr->count_type),
                                   sat_mul(list_max(pr->count_type),
                                           type_size(pr->type))));
    }
    return p->format == F_ASCII ? sat_add(n, PLY_ASCII_ITEM_EXTRA) : n;
}

/* The fewest and the most bytes the body (after end_header) can take. */
static void body_bounds(const ply *p, uint64_t *min, uint64_t *max)
{
    size_t e;
    *min = 0;
    *max = 0;
    for (e = 0; e < p->nelements; e++) {
        const ply_element *el = &p->elements[e];
        if (el->count == 0 || el->nprops == 0)
            continue;
        *min = sat_add(*min, sat_mul(el->count, min_item_bytes(p, el)));
        *max = sat_add(*max, sat_mul(el->count, max_item_bytes(p, el)));
    }
    /* ASCII: the last value of the file needs no separator. */
    if (p->format == F_ASCII && *min > 0)
        (*min)--;
}

static int push_triangle(ply *p, size_t at, uint32_t a, uint32_t b,
                         uint32_t c)
{
    uint32_t *t;
    if (!scene_reserve((void **)&p->indices, &p->triangle_cap,
                       p->triangle_count + 1, 3 * sizeof(uint32_t)))
        return fail_at(p, at, "out of memory at %zu triangles",
                       p->triangle_count);
    t = p->indices + p->triangle_count * 3;
    t[0] = a;
    t[1] = b;
    t[2] = c;
    p->triangle_count++;
    return 0;
}

/* Role of each property of the vertex or face element. */
enum { ROLE_SKIP = 0, ROLE_X, ROLE_Y, ROLE_Z, ROLE_INDICES };

static int read_element(ply *p, const ply_element *e, int is_vertex,
                        int is_face, const int *role)
{
    uint64_t i, min = min_item_bytes(p, e), max = max_item_bytes(p, e);
    size_t left = p->size - p->pos;
    if (e->count == 0 || e->nprops == 0)
        return 0;
    /* ASCII: the last value of the file needs no separator. */
    if (e->count > ((uint64_t)left + (p->format == F_ASCII)) / min)
        return fail_at(p, p->pos, "element \"%s\" declares %llu items but "
                       "only %zu bytes are left (truncated or corrupt "
                       "header)", e->name, (unsigned long long)e->count,
                       left);
    if (is_vertex) {
        if (e->count > UINT32_MAX)
            return fail_at(p, p->pos, "%llu vertices: more than 32-bit "
                           "indices can address",
                           (unsigned long long)e->count);
        if ((size_t)e->count > SIZE_MAX / (3 * sizeof(float)))
            return fail_at(p, p->pos, "too many vertices");
        p->vertices = malloc((size_t)e->count * 3 * sizeof(float));
        if (!p->vertices)
            return fail_at(p, p->pos, "out of memory for %llu vertices",
                           (unsigned long long)e->count);
        p->vertex_count = (size_t)e->count;
    }
    for (i = 0; i < e->count; i++) {
        size_t k, item_start = p->pos;
        if ((i & 0xffffu) == 0)
            scene_progress(1, p->pos, p->size);
        if (p->format == F_ASCII && !ascii_next_line(p))
            return fail_at(p, p->pos, "the file ends at %s item %llu of "
                           "%llu (truncated)", e->name,
                           (unsigned long long)i,
                           (unsigned long long)e->count);
        for (k = 0; k < e->nprops; k++) {
            const ply_prop *pr = &e->props[k];
            ply_value v;
            size_t at = p->pos;
            if (pr->count_type == T_NONE) {
                if (read_value(p, pr->type, &v) != 0)
                    return -1;
                if (is_vertex && role[k] >= ROLE_X && role[k] <= ROLE_Z)
                    p->vertices[(size_t)i * 3 + (size_t)(role[k] - ROLE_X)] =
                        scene_float(v.is_float ? v.f : (double)v.i);
            } else {
                int64_t count, j;
                uint32_t first = 0, prev = 0;
                int indices = is_face && role[k] == ROLE_INDICES;
                if (read_value(p, pr->count_type, &v) != 0)
                    return -1;
                count = v.i;
                if (count < 0)
                    return fail_at(p, at, "negative list length %lld",
                                   (long long)count);
                if (p->format != F_ASCII &&
                    (uint64_t)count > (p->size - p->pos) / type_size(pr->type))
                    return fail_at(p, at, "list of %lld values runs past the "
                                   "end of the file (truncated)",
                                   (long long)count);
                if (indices && count < 3)
                    return fail_at(p, at, "face %llu has %lld vertices (a "
                                   "face needs at least 3)",
                                   (unsigned long long)i, (long long)count);
                for (j = 0; j < count; j++) {
                    size_t vat = p->pos;
                    if (read_value(p, pr->type, &v) != 0)
                        return -1;
                    if (!indices)
                        continue;
                    if (v.is_float)
                        return fail_at(p, vat, "face %llu: vertex indices "
                                       "have a floating-point type",
                                       (unsigned long long)i);
                    if (v.i < 0 || (uint64_t)v.i >= p->vertex_count)
                        return fail_at(p, vat, "face %llu: vertex index "
                                       "%lld out of range (%zu vertices)",
                                       (unsigned long long)i,
                                       (long long)v.i, p->vertex_count);
                    if (j == 0)
                        first = (uint32_t)v.i;
                    else if (j >= 2 &&
                             push_triangle(p, vat, first, prev,
                                           (uint32_t)v.i) != 0)
                        return -1;
                    prev = (uint32_t)v.i;
                }
            }
        }
        if (p->format == F_ASCII && ascii_end_line(p) != 0)
            return -1;
        if (p->format == F_ASCII && (uint64_t)(p->pos - item_start) > max)
            return fail_at(p, item_start, "%s item %llu takes %zu bytes, "
                           "more than the %llu its values may (blank lines "
                           "and padding included)",
                           e->name, (unsigned long long)i,
                           p->pos - item_start, (unsigned long long)max);
    }
    return 0;
}

int scene_parse_ply(const char *path, const unsigned char *data, size_t size,
                    scene *out, char *err, size_t err_len)
{
    ply p;
    size_t e, vertex_el = (size_t)-1, face_el = (size_t)-1;
    int vrole[MAX_PROPERTIES], frole[MAX_PROPERTIES];
    int rc = -1;
    memset(&p, 0, sizeof p);
    p.path = path;
    p.data = data;
    p.size = size;
    p.err = err;
    p.err_len = err_len;
    /* The header is parsed as text, whatever the format. */
    p.format = F_ASCII;
    p.elements = calloc(MAX_ELEMENTS, sizeof *p.elements);
    if (!p.elements)
        return scene_fail(err, err_len, "%s: out of memory", path);
    if (parse_header(&p) != 0)
        goto done;

    memset(vrole, 0, sizeof vrole);
    memset(frole, 0, sizeof frole);
    for (e = 0; e < p.nelements; e++) {
        const ply_element *el = &p.elements[e];
        size_t k;
        int found[5] = {0, 0, 0, 0, 0};
        if ((strcmp(el->name, "vertex") == 0 && vertex_el != (size_t)-1) ||
            (strcmp(el->name, "face") == 0 && face_el != (size_t)-1)) {
            fail_line(&p, el->header_line, "a second \"%s\" element (only "
                      "one is read: its geometry would be left out)",
                      el->name);
            goto done;
        }
        if (strcmp(el->name, "vertex") == 0) {
            vertex_el = e;
            for (k = 0; k < el->nprops; k++) {
                const char *n = el->props[k].name;
                int r = strcmp(n, "x") == 0   ? ROLE_X
                        : strcmp(n, "y") == 0 ? ROLE_Y
                        : strcmp(n, "z") == 0 ? ROLE_Z
                                              : ROLE_SKIP;
                if (r == ROLE_SKIP || found[r])
                    continue;
                if (el->props[k].count_type != T_NONE) {
                    fail_line(&p, el->header_line, "vertex property \"%s\" "
                              "is a list", n);
                    goto done;
                }
                vrole[k] = r;
                found[r] = 1;
            }
            if (!found[ROLE_X] || !found[ROLE_Y] || !found[ROLE_Z]) {
                fail_line(&p, el->header_line, "the vertex element lacks "
                          "an x, y or z property");
                goto done;
            }
        } else if (strcmp(el->name, "face") == 0) {
            face_el = e;
            for (k = 0; k < el->nprops; k++) {
                const char *n = el->props[k].name;
                if (strcmp(n, "vertex_indices") != 0 &&
                    strcmp(n, "vertex_index") != 0)
                    continue;
                if (found[ROLE_INDICES]) {
                    fail_line(&p, el->header_line, "the face element has "
                              "a second vertex index list, \"%s\" (only "
                              "one is read)", n);
                    goto done;
                }
                if (el->props[k].count_type == T_NONE ||
                    !is_integer_type(el->props[k].type)) {
                    fail_line(&p, el->header_line, "face property \"%s\" is "
                              "not a list of integers", n);
                    goto done;
                }
                frole[k] = ROLE_INDICES;
                found[ROLE_INDICES] = 1;
            }
            if (!found[ROLE_INDICES]) {
                fail_line(&p, el->header_line, "the face element has no "
                          "vertex_indices list");
                goto done;
            }
        }
    }
    /* Faces are checked against the declared vertex count, so the face
     * element may come before the vertices. */
    if (vertex_el != (size_t)-1 && p.elements[vertex_el].count > UINT32_MAX) {
        fail_line(&p, p.elements[vertex_el].header_line, "%llu vertices: "
                  "more than 32-bit indices can address",
                  (unsigned long long)p.elements[vertex_el].count);
        goto done;
    }
    if (vertex_el != (size_t)-1)
        p.vertex_count = (size_t)p.elements[vertex_el].count;

    if (p.format == F_ASCII)
        p.line++; /* the line after end_header */
    for (e = 0; e < p.nelements; e++) {
        if (read_element(&p, &p.elements[e], e == vertex_el, e == face_el,
                         e == vertex_el ? vrole : frole) != 0)
            goto done;
    }
    /* Text after the last element could be data the header's counts leave
     * out (a face more than declared): say so rather than drop it. */
    if (p.format == F_ASCII && ascii_next_line(&p)) {
        fail_at(&p, p.pos, "text after the last element (the header "
                "declares fewer items than the file holds?)");
        goto done;
    }
    if (p.format != F_ASCII && (uint64_t)(p.size - p.pos) > PLY_TRAILING_MAX) {
        fail_at(&p, p.pos, "%zu bytes after the last element (more than "
                "the %llu tolerated: the header declares fewer items than "
                "the file holds?)",
                p.size - p.pos, (unsigned long long)PLY_TRAILING_MAX);
        goto done;
    }
    out->vertices = p.vertices;
    out->vertex_count = p.vertex_count;
    out->indices = p.indices;
    out->triangle_count = p.triangle_count;
    p.vertices = NULL;
    p.indices = NULL;
    rc = 0;
done:
    free(p.vertices);
    free(p.indices);
    free(p.elements);
    return rc;
}

/* -------------------------------------------------------------- reading */
/* Up to `want` more bytes of p's file onto *buf: 0, or -1 with p's
 * message set (out of memory, or a read error with the system's reason:
 * checked here, at once, so that a failed read is never taken for the end
 * of the file by the parser). */
static int read_more(FILE *f, const ply *p, unsigned char **buf,
                     size_t *cap, size_t *len, size_t want, size_t *got)
{
    if (!scene_reserve((void **)buf, cap, *len + want, 1))
        return scene_fail(p->err, p->err_len, "%s: out of memory reading "
                          "%zu bytes", p->path, *len + want);
    errno = 0;
    *got = fread(*buf + *len, 1, want, f);
    *len += *got;
    if (*got < want && ferror(f)) {
        int e = errno;
        return scene_fail(p->err, p->err_len, "%s: read error after %zu "
                          "bytes: %s", p->path, *len,
                          e ? strerror(e) : "unknown error");
    }
    return 0;
}

int scene_read_ply(const char *path, unsigned char **data, size_t *size,
                   char *err, size_t err_len)
{
    FILE *f;
    struct stat st;
    int regular;
    unsigned char *buf = NULL;
    size_t cap = 0, len = 0, got = 0, header_end;
    uint64_t min, max, limit;
    ply p;
    int eof = 0;
    f = fopen(path, "rb");
    if (!f)
        return scene_fail(err, err_len, "%s: cannot open: %s", path,
                          strerror(errno));
    regular = fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode);
    memset(&p, 0, sizeof p);
    p.path = path;
    p.err = err;
    p.err_len = err_len;
    p.elements = calloc(MAX_ELEMENTS, sizeof *p.elements);
    if (!p.elements) {
        fclose(f);
        return scene_fail(err, err_len, "%s: out of memory", path);
    }
    /* The header, a chunk at a time, parsed as it arrives. */
    for (;;) {
        size_t want = PLY_HEADER_MAX + 3 - len; /* 3: a byte-order mark */
        if (want > 4096)
            want = 4096;
        if (!eof && want > 0) {
            if (read_more(f, &p, &buf, &cap, &len, want, &got) != 0)
                goto fail;
            eof = got < want;
        }
        p.data = buf;
        p.size = len;
        p.pos = 0;
        p.nelements = 0;
        p.format = F_ASCII;
        if (parse_header(&p) == 0)
            break;
        if (!p.need_more || eof)
            goto fail; /* parse_header's message */
        if (len >= PLY_HEADER_MAX + 3) {
            scene_fail(err, err_len, "%s: no end_header in the first %zu "
                       "bytes (a PLY header is at most that long)",
                       path, PLY_HEADER_MAX);
            goto fail;
        }
    }
    header_end = p.pos;
    body_bounds(&p, &min, &max);
    limit = sat_add(max, PLY_TRAILING_MAX);
    if (regular) {
        uint64_t fsize = st.st_size > 0 ? (uint64_t)st.st_size : 0;
        uint64_t body = fsize > header_end ? fsize - header_end : 0;
        /* A small file is read anyway, for the parser's message, which
         * names the line or byte where the data runs out. */
        if (body < min && fsize > PLY_SMALL_FILE) {
            scene_fail(err, err_len, "%s: truncated: the header declares "
                       "at least %llu bytes of data, the file has %llu after "
                       "the header", path, (unsigned long long)min,
                       (unsigned long long)body);
            goto fail;
        }
        if (body > limit) {
            scene_fail(err, err_len, "%s: %llu bytes after the header, more "
                       "than the elements it declares can take (at most "
                       "%llu): corrupt header or not a PLY file", path,
                       (unsigned long long)body, (unsigned long long)max);
            goto fail;
        }
        if (body > (uint64_t)(SIZE_MAX - len)) {
            scene_fail(err, err_len, "%s: too large to read", path);
            goto fail;
        }
        /* One allocation of the file's size (plus the check byte). */
        if (!scene_reserve((void **)&buf, &cap, (size_t)fsize + 1, 1)) {
            scene_fail(err, err_len, "%s: out of memory reading %llu bytes",
                       path, (unsigned long long)fsize);
            goto fail;
        }
    }
    /* The body: never more than the elements can take, plus the slack. */
    while (!eof) {
        uint64_t body = len - header_end;
        size_t want = PLY_READ_CHUNK;
        if (body > limit) {
            scene_fail(err, err_len, "%s: more than %llu bytes after the "
                       "header, more than the elements it declares can take "
                       "(at most %llu)", path, (unsigned long long)limit,
                       (unsigned long long)max);
            goto fail;
        }
        if (limit != UINT64_MAX && (uint64_t)want > limit + 1 - body)
            want = (size_t)(limit + 1 - body);
        if (read_more(f, &p, &buf, &cap, &len, want, &got) != 0)
            goto fail;
        eof = got < want;
        if (regular)
            scene_progress(0, len, (uint64_t)st.st_size);
    }
    if ((uint64_t)(len - header_end) > limit) {
        scene_fail(err, err_len, "%s: more than %llu bytes after the header, "
                   "more than the elements it declares can take (at most "
                   "%llu)", path, (unsigned long long)limit,
                   (unsigned long long)max);
        goto fail;
    }
    fclose(f);
    free(p.elements);
    *data = buf;
    *size = len;
    return 0;
fail:
    fclose(f);
    free(p.elements);
    free(buf);
    return -1;
}
