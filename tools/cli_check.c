/*
 * cli_check.c - `atrbvh check DIR [--against SCENE|DIR] [build options]
 * [--tolerance-ulps N] [--json]`: compares stage dumps (the files that
 * DIR/manifest.json lists, any subset of the stages) with the reference -
 * a build of the manifest's scene and options (command-line build options
 * replace the manifest's), or another dump folder - stage by stage in
 * pipeline order, and reports the first differing stage: its first
 * differing item with both values (floats also as the distance in ulps)
 * and its count of differing items.  Exit 0 same, 1 different, 2 trouble
 * (malformed manifest or .npy file, unreadable file, bad options, the
 * reference cannot be built).  docs/stages.md has the format.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"
#include "npy.h"

#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define CHECK_SAME 0
#define CHECK_DIFFER 1
#define CHECK_TROUBLE 2
#define MAX_ARRAYS 12
#define MANIFEST_MAX (16u << 20)

/* ============================================================ JSON reader */
/* Just enough JSON for manifests: the whole grammar (RFC 8259), strings
 * decoded to UTF-8, numbers as doubles; nesting at most 64 deep. */
typedef enum jtype { J_NULL, J_BOOL, J_NUM, J_STR, J_ARR, J_OBJ } jtype;

typedef struct jval {
    jtype type;
    int b;
    double num;
    char *str;
    size_t n;           /* items / members */
    struct jval *items; /* array items or member values */
    char **keys;        /* object member names */
} jval;

typedef struct jparser {
    const char *p, *start;
    char err[160];
    int depth;
} jparser;

static void jfree(jval *v)
{
    size_t i;
    if (!v)
        return;
    for (i = 0; i < v->n; i++) {
        jfree(&v->items[i]);
        if (v->keys)
            free(v->keys[i]);
    }
    free(v->items);
    free(v->keys);
    free(v->str);
    memset(v, 0, sizeof *v);
}

static int jfail(jparser *j, const char *what)
{
    if (!j->err[0])
        snprintf(j->err, sizeof j->err, "%s at byte %ld", what,
                 (long)(j->p - j->start));
    return -1;
}

static void jspace(jparser *j)
{
    while (*j->p == ' ' || *j->p == '\t' || *j->p == '\n' || *j->p == '\r')
        j->p++;
}

static int hex4(const char *p, unsigned *out)
{
    unsigned v = 0;
    int k;
    for (k = 0; k < 4; k++) {
        char c = p[k];
        v <<= 4;
        if (c >= '0' && c <= '9')
            v |= (unsigned)(c - '0');
        else if (c >= 'a' && c <= 'f')
            v |= (unsigned)(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F')
            v |= (unsigned)(c - 'A' + 10);
        else
            return -1;
    }
    *out = v;
    return 0;
}

static int jstring(jparser *j, char **out)
{
    size_t room = 16, n = 0;
    char *s = malloc(room);
    if (!s)
        return jfail(j, "out of memory");
    j->p++; /* the opening quote */
    for (;;) {
        unsigned char c = (unsigned char)*j->p;
        unsigned cp = 0;
        char enc[4];
        int m = 1, k;
        if (c == '"') {
            j->p++;
            break;
        }
        if (c < 0x20) {
            free(s);
            return jfail(j, c ? "control character in a string"
                              : "unterminated string");
        }
        if (c == '\\') {
            char e = j->p[1];
            j->p += 2;
            switch (e) {
            case '"': enc[0] = '"'; break;
            case '\\': enc[0] = '\\'; break;
            case '/': enc[0] = '/'; break;
            case 'b': enc[0] = '\b'; break;
            case 'f': enc[0] = '\f'; break;
            case 'n': enc[0] = '\n'; break;
            case 'r': enc[0] = '\r'; break;
            case 't': enc[0] = '\t'; break;
            case 'u':
                if (hex4(j->p, &cp) != 0) {
                    free(s);
                    return jfail(j, "bad \\u escape");
                }
                j->p += 4;
                if (cp >= 0xd800 && cp < 0xdc00 && j->p[0] == '\\' &&
                    j->p[1] == 'u') {
                    unsigned lo;
                    if (hex4(j->p + 2, &lo) == 0 && lo >= 0xdc00 &&
                        lo < 0xe000) {
                        cp = 0x10000 + ((cp - 0xd800) << 10) + (lo - 0xdc00);
                        j->p += 6;
                    }
                }
                if (cp == 0 || (cp >= 0xd800 && cp < 0xe000))
                    cp = 0xfffd;
                if (cp < 0x80) {
                    enc[0] = (char)cp;
                } else if (cp < 0x800) {
                    enc[0] = (char)(0xc0 | cp >> 6);
                    enc[1] = (char)(0x80 | (cp & 0x3f));
                    m = 2;
                } else if (cp < 0x10000) {
                    enc[0] = (char)(0xe0 | cp >> 12);
                    enc[1] = (char)(0x80 | ((cp >> 6) & 0x3f));
                    enc[2] = (char)(0x80 | (cp & 0x3f));
                    m = 3;
                } else {
                    enc[0] = (char)(0xf0 | cp >> 18);
                    enc[1] = (char)(0x80 | ((cp >> 12) & 0x3f));
                    enc[2] = (char)(0x80 | ((cp >> 6) & 0x3f));
                    enc[3] = (char)(0x80 | (cp & 0x3f));
                    m = 4;
                }
                break;
            default:
                free(s);
                return jfail(j, "bad escape in a string");
            }
        } else {
            enc[0] = (char)c;
            j->p++;
        }
        if (n + (size_t)m + 1 > room) {
            char *t;
            room *= 2;
            t = realloc(s, room);
            if (!t) {
                free(s);
                return jfail(j, "out of memory");
            }
            s = t;
        }
        for (k = 0; k < m; k++)
            s[n++] = enc[k];
    }
    s[n] = '\0';
    *out = s;
    return 0;
}

static int jvalue(jparser *j, jval *v);

static int jpush(jparser *j, jval *v, size_t *room, char *key)
{
    if (v->n == *room) {
        size_t r = *room ? *room * 2 : 8;
        jval *items = realloc(v->items, r * sizeof *items);
        if (!items)
            return jfail(j, "out of memory");
        v->items = items;
        if (v->type == J_OBJ) {
            char **keys = realloc(v->keys, r * sizeof *keys);
            if (!keys)
                return jfail(j, "out of memory");
            v->keys = keys;
        }
        *room = r;
    }
    memset(&v->items[v->n], 0, sizeof v->items[0]);
    if (v->type == J_OBJ)
        v->keys[v->n] = key;
    v->n++;
    return 0;
}

static int jcontainer(jparser *j, jval *v, char close)
{
    size_t room = 0;
    if (++j->depth > 64)
        return jfail(j, "nesting too deep");
    j->p++;
    jspace(j);
    if (*j->p == close) {
        j->p++;
        j->depth--;
        return 0;
    }
    for (;;) {
        char *key = NULL;
        jspace(j);
        if (close == '}') {
            if (*j->p != '"')
                return jfail(j, "member name expected");
            if (jstring(j, &key) != 0)
                return -1;
            jspace(j);
            if (*j->p != ':') {
                free(key);
                return jfail(j, "':' expected");
            }
            j->p++;
        }
        if (jpush(j, v, &room, key) != 0) {
            free(key);
            return -1;
        }
        if (jvalue(j, &v->items[v->n - 1]) != 0)
            return -1;
        jspace(j);
        if (*j->p == ',') {
            j->p++;
            continue;
        }
        if (*j->p == close) {
            j->p++;
            break;
        }
        return jfail(j, close == '}' ? "',' or '}' expected"
                                     : "',' or ']' expected");
    }
    j->depth--;
    return 0;
}

static int jvalue(jparser *j, jval *v)
{
    jspace(j);
    memset(v, 0, sizeof *v);
    switch (*j->p) {
    case '{':
        v->type = J_OBJ;
        return jcontainer(j, v, '}');
    case '[':
        v->type = J_ARR;
        return jcontainer(j, v, ']');
    case '"':
        v->type = J_STR;
        return jstring(j, &v->str);
    case 't':
        if (strncmp(j->p, "true", 4) != 0)
            return jfail(j, "bad literal");
        v->type = J_BOOL;
        v->b = 1;
        j->p += 4;
        return 0;
    case 'f':
        if (strncmp(j->p, "false", 5) != 0)
            return jfail(j, "bad literal");
        v->type = J_BOOL;
        j->p += 5;
        return 0;
    case 'n':
        if (strncmp(j->p, "null", 4) != 0)
            return jfail(j, "bad literal");
        j->p += 4;
        return 0;
    default: {
        /* RFC 8259 number syntax, then strtod for the value */
        const char *q = j->p;
        char *end;
        if (*q == '-')
            q++;
        if (*q == '0')
            q++;
        else if (*q >= '1' && *q <= '9')
            while (*q >= '0' && *q <= '9')
                q++;
        else
            return jfail(j, "value expected");
        if (*q == '.') {
            q++;
            if (*q < '0' || *q > '9')
                return jfail(j, "bad number");
            while (*q >= '0' && *q <= '9')
                q++;
        }
        if (*q == 'e' || *q == 'E') {
            q++;
            if (*q == '+' || *q == '-')
                q++;
            if (*q < '0' || *q > '9')
                return jfail(j, "bad number");
            while (*q >= '0' && *q <= '9')
                q++;
        }
        v->type = J_NUM;
        v->num = strtod(j->p, &end);
        if (end != q)
            return jfail(j, "bad number");
        j->p = q;
        return 0;
    }
    }
}

static const jval *jget(const jval *o, const char *key)
{
    size_t i;
    if (!o || o->type != J_OBJ)
        return NULL;
    for (i = 0; i < o->n; i++)
        if (strcmp(o->keys[i], key) == 0)
            return &o->items[i];
    return NULL;
}

/* A whole number 0 .. max held exactly by the double. */
static int jsize(const jval *v, double max, size_t *out)
{
    if (!v || v->type != J_NUM || !(v->num >= 0.0) || v->num > max ||
        v->num != (double)(uint64_t)v->num)
        return -1;
    *out = (size_t)v->num;
    return 0;
}

/* ============================================================== the dumps */
typedef struct arr {
    char name[32];
    char file[128];
    atrbvh_dtype dtype;
    int ndim;
    size_t rows, cols;
    void *data;
} arr;

typedef struct stg {
    char name[32];
    int rank;
    unsigned round;
    size_t count;
    arr a[MAX_ARRAYS];
} stg;

typedef struct dump {
    stg *s;
    size_t count, room;
    int failed; /* capture: out of memory */
} dump;

static void dump_free(dump *d)
{
    size_t i, k;
    for (i = 0; i < d->count; i++)
        for (k = 0; k < d->s[i].count; k++)
            free(d->s[i].a[k].data);
    free(d->s);
    memset(d, 0, sizeof *d);
}

static stg *dump_add(dump *d, const char *name)
{
    stg *s;
    if (d->count == d->room) {
        size_t r = d->room ? d->room * 2 : 16;
        stg *t = realloc(d->s, r * sizeof *t);
        if (!t)
            return NULL;
        d->s = t;
        d->room = r;
    }
    s = &d->s[d->count++];
    memset(s, 0, sizeof *s);
    snprintf(s->name, sizeof s->name, "%s", name);
    s->rank = npy_stage_rank(name, &s->round);
    return s;
}

static stg *dump_find(const dump *d, const char *name)
{
    size_t i;
    for (i = 0; i < d->count; i++)
        if (strcmp(d->s[i].name, name) == 0)
            return &d->s[i];
    return NULL;
}

static arr *stg_find(stg *s, const char *name)
{
    size_t k;
    for (k = 0; k < s->count; k++)
        if (strcmp(s->a[k].name, name) == 0)
            return &s->a[k];
    return NULL;
}

/* The reference build's capture: a copy of every array. */
static int on_capture(const atrbvh_stage_output *o, void *user)
{
    dump *d = user;
    stg *s = dump_add(d, o->name);
    size_t k;
    if (!s || o->array_count > MAX_ARRAYS) {
        d->failed = 1;
        return 1;
    }
    for (k = 0; k < o->array_count; k++) {
        const atrbvh_array *a = &o->arrays[k];
        arr *e = &s->a[s->count++];
        size_t bytes, cols;
        atrbvh_dtype dt;
        snprintf(e->name, sizeof e->name, "%s", a->name);
        snprintf(e->file, sizeof e->file, "%s-%s.npy", o->name, a->name);
        e->dtype = a->dtype;
        if (npy_array_schema(a->name, &dt, &e->ndim, &cols) != 0)
            e->ndim = a->cols == 1 ? 1 : 2;
        e->rows = a->rows;
        e->cols = a->cols;
        bytes = a->rows * a->cols * npy_dtype_size(a->dtype);
        e->data = malloc(bytes ? bytes : 1);
        if (!e->data) {
            d->failed = 1;
            return 1;
        }
        if (bytes)
            memcpy(e->data, a->data, bytes);
    }
    return 0;
}

/* What a manifest says besides its files. */
typedef struct manifest {
    char *scene;
    int has_options;
    atrbvh_method method;
    unsigned treelet, rounds, gamma, max_leaf;
    double ci, ct;
    int collapse, skip_invalid;
} manifest;

static int trouble(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
static int trouble(const char *fmt, ...)
{
    char text[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    cli_error("%s", text);
    return -1;
}

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    size_t n = 0, room = 4096;
    char *s;
    if (!f) {
        trouble("%s: %s", path, strerror(errno));
        return NULL;
    }
    s = malloc(room);
    for (;;) {
        size_t got;
        if (!s) {
            fclose(f);
            trouble("%s: out of memory", path);
            return NULL;
        }
        got = fread(s + n, 1, room - n - 1, f);
        n += got;
        if (n < room - 1)
            break;
        if (room >= MANIFEST_MAX) {
            free(s);
            fclose(f);
            trouble("%s: larger than %u bytes", path, MANIFEST_MAX);
            return NULL;
        }
        {
            char *t = realloc(s, room * 2);
            if (!t)
                free(s);
            s = t;
            room *= 2;
        }
    }
    if (ferror(f)) {
        free(s);
        fclose(f);
        trouble("%s: read error", path);
        return NULL;
    }
    fclose(f);
    s[n] = '\0';
    if (strlen(s) != n) {
        free(s);
        trouble("%s: not JSON (a NUL byte)", path);
        return NULL;
    }
    return s;
}

static int method_of(const char *s, atrbvh_method *m)
{
    if (strcmp(s, "lbvh") == 0)
        *m = ATRBVH_METHOD_LBVH;
    else if (strcmp(s, "trbvh") == 0)
        *m = ATRBVH_METHOD_TRBVH;
    else if (strcmp(s, "atrbvh") == 0)
        *m = ATRBVH_METHOD_ATRBVH;
    else
        return -1;
    return 0;
}

/* The manifest's "options": method required, the others optional. */
static int read_options(const char *mp, const jval *o, manifest *m)
{
    static const char *const uints[] = {"treelet_size", "rounds", "gamma",
                                        "max_leaf_size"};
    unsigned *dest[4];
    const jval *v;
    size_t k, x;
    dest[0] = &m->treelet;
    dest[1] = &m->rounds;
    dest[2] = &m->gamma;
    dest[3] = &m->max_leaf;
    if (o->type != J_OBJ)
        return trouble("%s: 'options' is not an object", mp);
    v = jget(o, "method");
    if (!v)
        return trouble("%s: missing key 'options.method'", mp);
    if (v->type != J_STR || method_of(v->str, &m->method) != 0)
        return trouble("%s: options.method is not lbvh, trbvh or atrbvh", mp);
    for (k = 0; k < 4; k++) {
        v = jget(o, uints[k]);
        if (!v)
            continue;
        if (jsize(v, (double)UINT_MAX, &x) != 0)
            return trouble("%s: options.%s is not a whole number", mp,
                           uints[k]);
        *dest[k] = (unsigned)x;
    }
    if ((v = jget(o, "ci")) != NULL) {
        if (v->type != J_NUM || !(v->num > 0.0))
            return trouble("%s: options.ci is not a positive number", mp);
        m->ci = v->num;
    }
    if ((v = jget(o, "ct")) != NULL) {
        if (v->type != J_NUM || !(v->num > 0.0))
            return trouble("%s: options.ct is not a positive number", mp);
        m->ct = v->num;
    }
    if ((v = jget(o, "collapse")) != NULL) {
        if (v->type != J_BOOL)
            return trouble("%s: options.collapse is not true or false", mp);
        m->collapse = v->b;
    }
    if ((v = jget(o, "skip_invalid")) != NULL) {
        if (v->type != J_BOOL)
            return trouble("%s: options.skip_invalid is not true or false",
                           mp);
        m->skip_invalid = v->b;
    }
    m->has_options = 1;
    return 0;
}

static void shape_text(char *buf, size_t room, int ndim, size_t rows,
                       size_t cols)
{
    if (ndim == 2)
        snprintf(buf, room, "(%zu, %zu)", rows, cols);
    else
        snprintf(buf, room, "(%zu,)", rows);
}

/* One file entry of a stage: checked against the documented schema, then
 * read and checked against what the manifest says. */
static int read_file_entry(const char *dir, const char *mp, stg *s,
                           const jval *f)
{
    const jval *va = jget(f, "array"), *vf = jget(f, "file"),
               *vd = jget(f, "dtype"), *vs = jget(f, "shape");
    atrbvh_dtype dt, mdt;
    size_t cols, dims[2] = {0, 1};
    int ndim;
    arr *e;
    npy_array a;
    char err[200], *path;
    size_t k;
    if (f->type != J_OBJ)
        return trouble("%s: stage %s: a file entry is not an object", mp,
                       s->name);
    if (!va || !vf || !vd || !vs)
        return trouble("%s: stage %s: missing key '%s' in a file entry", mp,
                       s->name,
                       !va ? "array" : !vf ? "file" : !vd ? "dtype" : "shape");
    if (va->type != J_STR || vf->type != J_STR || vd->type != J_STR ||
        vs->type != J_ARR)
        return trouble("%s: stage %s: a file entry has a key of the wrong "
                       "type", mp, s->name);
    if (npy_array_schema(va->str, &dt, &ndim, &cols) != 0)
        return trouble("%s: stage %s: unknown array '%s'", mp, s->name,
                       va->str);
    if (s->count == MAX_ARRAYS || stg_find(s, va->str))
        return trouble("%s: stage %s: array '%s' listed twice", mp, s->name,
                       va->str);
    if (!vf->str[0] || strchr(vf->str, '/') || strlen(vf->str) >= 128)
        return trouble("%s: stage %s: file '%s' is not a file name in the "
                       "directory", mp, s->name, vf->str);
    if (npy_dtype_of(vd->str, &mdt) != 0 || mdt != dt)
        return trouble("%s: %s: dtype '%s', but %s is %s", mp, vf->str,
                       vd->str, va->str, npy_descr(dt));
    if (vs->n != (size_t)ndim)
        return trouble("%s: %s: shape of %zu dimensions, but %s has %d", mp,
                       vf->str, vs->n, va->str, ndim);
    for (k = 0; k < vs->n; k++)
        if (jsize(&vs->items[k], 9007199254740992.0, &dims[k]) != 0)
            return trouble("%s: %s: bad shape", mp, vf->str);
    if (ndim == 2 && dims[1] != cols)
        return trouble("%s: %s: shape (%zu, %zu), but %s has %zu columns",
                       mp, vf->str, dims[0], dims[1], va->str, cols);
    path = cli_join(dir, vf->str);
    if (!path)
        return trouble("out of memory");
    if (npy_read(path, &a, err, sizeof err) != 0) {
        trouble("%s: %s", path, err);
        free(path);
        return -1;
    }
    if (a.dtype != dt || a.ndim != ndim || a.rows != dims[0] ||
        a.cols != dims[1]) {
        char have[64], want[64];
        shape_text(have, sizeof have, a.ndim, a.rows, a.cols);
        shape_text(want, sizeof want, ndim, dims[0], dims[1]);
        trouble("%s: holds %s %s, the manifest says %s %s", path,
                npy_descr(a.dtype), have, npy_descr(dt), want);
        npy_free(&a);
        free(path);
        return -1;
    }
    free(path);
    e = &s->a[s->count++];
    snprintf(e->name, sizeof e->name, "%s", va->str);
    snprintf(e->file, sizeof e->file, "%s", vf->str);
    e->dtype = dt;
    e->ndim = ndim;
    e->rows = a.rows;
    e->cols = a.cols;
    e->data = a.data;
    return 0;
}

/* DIR/manifest.json and every file it lists: 0, or -1 after one line. */
static int load_dump(const char *dir, dump *d, manifest *m)
{
    char *mp = cli_join(dir, "manifest.json"), *text;
    jparser j;
    jval root;
    const jval *v, *stages;
    size_t i, k, x;
    int rc = -1;
    memset(&root, 0, sizeof root);
    if (!mp)
        return trouble("out of memory");
    text = read_text(mp);
    if (!text) {
        free(mp);
        return -1;
    }
    memset(&j, 0, sizeof j);
    j.p = j.start = text;
    if (jvalue(&j, &root) != 0 || (jspace(&j), *j.p != '\0')) {
        if (!j.err[0])
            jfail(&j, "text after the JSON value");
        trouble("%s: not JSON: %s", mp, j.err);
        goto done;
    }
    if (root.type != J_OBJ) {
        trouble("%s: not a JSON object", mp);
        goto done;
    }
    v = jget(&root, "version");
    if (!v) {
        trouble("%s: missing key 'version'", mp);
        goto done;
    }
    if (jsize(v, 1e9, &x) != 0 || x != 1) {
        trouble("%s: unsupported version (this atrbvh reads version 1)", mp);
        goto done;
    }
    if ((v = jget(&root, "scene")) != NULL) {
        const jval *name = jget(v, "name");
        if (v->type != J_OBJ || (name && name->type != J_STR)) {
            trouble("%s: 'scene' is not an object with a string 'name'", mp);
            goto done;
        }
        if (name) {
            m->scene = strdup(name->str);
            if (!m->scene) {
                trouble("out of memory");
                goto done;
            }
        }
    }
    if ((v = jget(&root, "options")) != NULL && read_options(mp, v, m) != 0)
        goto done;
    stages = jget(&root, "stages");
    if (!stages) {
        trouble("%s: missing key 'stages'", mp);
        goto done;
    }
    if (stages->type != J_ARR) {
        trouble("%s: 'stages' is not an array", mp);
        goto done;
    }
    for (i = 0; i < stages->n; i++) {
        const jval *st = &stages->items[i], *name = jget(st, "name"),
                   *files = jget(st, "files");
        stg *s;
        unsigned r;
        if (!name || !files || name->type != J_STR || files->type != J_ARR) {
            trouble("%s: stage %zu: missing key '%s' (or not a %s)", mp, i,
                    !name || name->type != J_STR ? "name" : "files",
                    !name || name->type != J_STR ? "string" : "list");
            goto done;
        }
        if (npy_stage_rank(name->str, &r) < 0) {
            trouble("%s: unknown stage '%s'", mp, name->str);
            goto done;
        }
        if (dump_find(d, name->str)) {
            trouble("%s: stage '%s' listed twice", mp, name->str);
            goto done;
        }
        s = dump_add(d, name->str);
        if (!s) {
            trouble("out of memory");
            goto done;
        }
        for (k = 0; k < files->n; k++)
            if (read_file_entry(dir, mp, s, &files->items[k]) != 0)
                goto done;
    }
    rc = 0;
done:
    jfree(&root);
    free(text);
    free(mp);
    return rc;
}

/* ========================================================== comparing */
static uint32_t bits32(const void *p, size_t i)
{
    uint32_t u;
    memcpy(&u, (const char *)p + 4 * i, 4);
    return u;
}

static uint64_t bits64(const void *p, size_t i)
{
    uint64_t u;
    memcpy(&u, (const char *)p + 8 * i, 8);
    return u;
}

static int is_float(atrbvh_dtype t)
{
    return t == ATRBVH_DTYPE_F32 || t == ATRBVH_DTYPE_F64;
}

static int is_nan(atrbvh_dtype t, uint64_t u)
{
    if (t == ATRBVH_DTYPE_F32)
        return (u & 0x7f800000u) == 0x7f800000u && (u & 0x7fffffu);
    return (u & 0x7ff0000000000000ull) == 0x7ff0000000000000ull &&
           (u & 0xfffffffffffffull);
}

/* The bits of element i (floats: their bit pattern). */
static uint64_t elem(const arr *a, size_t i)
{
    return npy_dtype_size(a->dtype) == 4 ? bits32(a->data, i)
                                         : bits64(a->data, i);
}

/* Distance in units in the last place between two floats (not NaN):
 * the count of representable values from one to the other (+0 and -0
 * are 0 apart). */
static uint64_t ulps(atrbvh_dtype t, uint64_t a, uint64_t b)
{
    int64_t ka, kb;
    if (t == ATRBVH_DTYPE_F32) {
        ka = (int64_t)(a & 0x7fffffffu);
        kb = (int64_t)(b & 0x7fffffffu);
        if (a & 0x80000000u)
            ka = -ka;
        if (b & 0x80000000u)
            kb = -kb;
    } else {
        ka = (int64_t)(a & 0x7fffffffffffffffull);
        kb = (int64_t)(b & 0x7fffffffffffffffull);
        if (a >> 63)
            ka = -ka;
        if (b >> 63)
            kb = -kb;
    }
    return ka >= kb ? (uint64_t)ka - (uint64_t)kb
                    : (uint64_t)kb - (uint64_t)ka;
}

static int same(atrbvh_dtype t, uint64_t a, uint64_t b, unsigned tol)
{
    if (a == b)
        return 1;
    if (!is_float(t) || tol == 0 || is_nan(t, a) || is_nan(t, b))
        return 0;
    return ulps(t, a, b) <= tol;
}

static double as_double(atrbvh_dtype t, uint64_t u)
{
    if (t == ATRBVH_DTYPE_F32) {
        uint32_t v = (uint32_t)u;
        float f;
        memcpy(&f, &v, 4);
        return (double)f;
    } else {
        double d;
        memcpy(&d, &u, 8);
        return d;
    }
}

typedef struct finding {
    const stg *stage;    /* the user's stage                         */
    const arr *mine;     /* the first differing array                */
    const arr *ref;      /* its reference (NULL: missing)            */
    size_t index;        /* element index in the flattened array     */
    size_t items;        /* the stage's items compared               */
    size_t differing;    /* the stage's count of differing items     */
    int missing;         /* the reference has no such stage          */
} finding;

/* Compares one stage: the count of differing items (and the first). */
static void compare_stage(const stg *mine, stg *ref, unsigned tol,
                          finding *f)
{
    size_t k;
    memset(f, 0, sizeof *f);
    f->stage = mine;
    for (k = 0; k < mine->count; k++) {
        const arr *a = &mine->a[k];
        const arr *r = stg_find(ref, a->name);
        size_t na = a->rows * a->cols, nr, common, i;
        if (!r)
            continue; /* a reference dump without this array */
        nr = r->rows * r->cols;
        /* a different row count: the common rows, then the excess */
        common = na < nr ? na : nr;
        f->items += na > nr ? na : nr;
        for (i = 0; i < common; i++)
            if (!same(a->dtype, elem(a, i), elem(r, i), tol)) {
                if (!f->differing++) {
                    f->mine = a;
                    f->ref = r;
                    f->index = i;
                }
            }
        if (na != nr) {
            if (!f->differing) {
                f->mine = a;
                f->ref = r;
                f->index = common;
            }
            f->differing += (na > nr ? na : nr) - common;
        }
    }
}

static int stage_cmp(const void *x, const void *y)
{
    const stg *a = x, *b = y;
    if (a->rank != b->rank)
        return a->rank < b->rank ? -1 : 1;
    return a->round < b->round ? -1 : a->round > b->round;
}

/* A value for the text report. */
static void value_text(char *buf, size_t room, const arr *a, size_t i)
{
    uint64_t u = elem(a, i);
    switch (a->dtype) {
    case ATRBVH_DTYPE_U32:
    case ATRBVH_DTYPE_U64:
        snprintf(buf, room, "%llu", (unsigned long long)u);
        break;
    case ATRBVH_DTYPE_F32:
        snprintf(buf, room, "%.9g (0x%08llx)", as_double(a->dtype, u),
                 (unsigned long long)u);
        break;
    case ATRBVH_DTYPE_F64:
        snprintf(buf, room, "%.17g (0x%016llx)", as_double(a->dtype, u),
                 (unsigned long long)u);
        break;
    }
}

static void value_json(json_writer *w, const char *key, const arr *a,
                       size_t i)
{
    uint64_t u = elem(a, i);
    json_key(w, key);
    if (is_float(a->dtype))
        json_double(w, as_double(a->dtype, u));
    else
        json_uint(w, u);
}

/* The first difference's place: "order[17]" or "prim_boxes[17][3]". */
static void place_text(char *buf, size_t room, const arr *a, size_t i)
{
    if (a->ndim == 2)
        snprintf(buf, room, "%s[%zu][%zu]", a->name, i / a->cols,
                 i % a->cols);
    else
        snprintf(buf, room, "%s[%zu]", a->name, i);
}

/* ============================================================ command */
static const char *against;
static unsigned tolerance;
static int as_json;

static const cli_opt check_opts[] = {
    {.name = "--against", .kind = CLI_OPT_STRING, .arg = "SCENE|DIR",
     .dest = &against,
     .help = "the reference: a scene to build (default: the\n"
             "manifest's scene) or another dump directory"},
    {.name = "--tolerance-ulps", .kind = CLI_OPT_UINT, .arg = "N", .min = 0,
     .max = UINT_MAX, .dest = &tolerance,
     .help = "floats at most N ulps apart count as equal\n"
             "(boxes, costs; default 0: bit equality)"},
    {.name = "--json", .kind = CLI_OPT_FLAG, .dest = &as_json,
     .flag_value = 1, .help = "print one JSON object"},
    {.name = NULL}};

#define CHECK_GROUPS (CLI_BUILD_CORE | CLI_BUILD_BACKEND | CLI_BUILD_DEVICE)

static void check_help(FILE *f)
{
    cli_build_help(
        f,
        "Usage: atrbvh check DIR [--against SCENE|DIR] [OPTIONS]\n"
        "Compare the stage dumps in DIR (the files DIR/manifest.json lists; "
        "any subset\n"
        "of the stages) with the reference, stage by stage in pipeline "
        "order, and\n"
        "report the first differing stage: its first differing item with "
        "both values\n"
        "(floats also in ulps) and its count of differing items.  The "
        "reference is a\n"
        "build of the manifest's scene with the manifest's options (build "
        "options given\n"
        "here replace them), or the dumps of another directory.  See "
        "atrbvh-stages(7).\n",
        "Check", check_opts, CHECK_GROUPS,
        "0 same, 1 different, 2 trouble (a malformed manifest or .npy "
        "file,\nan unreadable file, bad options)");
}

static int is_dir(const char *p)
{
    struct stat sb;
    return stat(p, &sb) == 0 && S_ISDIR(sb.st_mode);
}

/* The reference build: 0, or -1 after the error line. */
static int build_reference(const char *spec, const atrbvh_build_options *opt,
                           const cli_build_args *cl, dump *ref, int *usage)
{
    scene sc;
    atrbvh_geometry g;
    atrbvh_build_options o = *opt;
    atrbvh_device *dev = NULL;
    atrbvh_bvh *bvh = NULL;
    atrbvh_error e;
    atrbvh_status st;
    char err[512];
    *usage = 0;
    if (scene_load(spec, &sc, err, sizeof err) != 0)
        return trouble("%s", err);
    if (sc.triangle_count == 0) {
        scene_free(&sc);
        return trouble("%s: the scene has no triangles", spec);
    }
    g = scene_geometry(&sc);
    memset(&e, 0, sizeof e);
    if (o.backend == ATRBVH_BACKEND_OPENCL) {
        const char *name = o.opencl_device;
        char dspec[512];
        snprintf(dspec, sizeof dspec, "opencl%s%s",
                 name && *name ? ":" : "", name && *name ? name : "");
        st = atrbvh_device_open(dspec, &dev, &e);
        if (st != ATRBVH_OK) {
            if (cli_bad_device(cl, st, e.text))
                cli_usage("check", "--device: %s", e.text);
            else
                trouble("%s", e.text[0] ? e.text : atrbvh_strerror(st));
            scene_free(&sc);
            return -1;
        }
        o.device = dev;
    }
    o.capture = on_capture;
    o.capture_user = ref;
    o.progress = NULL;
    st = atrbvh_build(&g, &o, &bvh, &e);
    atrbvh_bvh_free(bvh);
    atrbvh_device_close(dev);
    scene_free(&sc);
    if (st != ATRBVH_OK) {
        if (st == ATRBVH_ERR_INVALID_ARGUMENT)
            *usage = 1;
        return trouble("%s: the reference build failed: %s", spec,
                       ref->failed ? "out of memory"
                       : e.text[0] ? e.text
                                   : atrbvh_strerror(st));
    }
    return 0;
}

int cli_check(int argc, char **argv)
{
    static const atrbvh_method methods[] = {
        ATRBVH_METHOD_LBVH, ATRBVH_METHOD_TRBVH, ATRBVH_METHOD_ATRBVH};
    cli_build_args cl;
    cli_opt table[CLI_BUILD_MAX_OPTS + 1];
    int seen[CLI_BUILD_MAX_OPTS + 1];
    const cli_opt *tables[3];
    const char *pos[1], *dir, *ref_name;
    dump mine, ref;
    manifest m;
    atrbvh_build_options o;
    finding f;
    int n, k, rc, against_dir = 0, usage = 0;
    size_t i, first = (size_t)-1;
    finding *found = NULL;

    rc = cli_help_or_version(argc, argv, check_help);
    if (rc >= 0)
        return rc;
    against = NULL;
    tolerance = 0;
    as_json = 0;
    cli_build_args_init(&cl);
    cli_build_opts(&cl, CHECK_GROUPS, table);
    memset(seen, 0, sizeof seen);
    for (k = 0; table[k].name; k++)
        table[k].seen = &seen[k];
    tables[0] = check_opts;
    tables[1] = table;
    tables[2] = NULL;
    if (cli_parse("check", argc, argv, tables, NULL, pos, 1, &n, "DIR") != 0)
        return CLI_USAGE;
    if (n == 0)
        return cli_usage("check", "no DIR given");
    dir = pos[0];
    memset(&mine, 0, sizeof mine);
    memset(&ref, 0, sizeof ref);
    memset(&m, 0, sizeof m);
    rc = CHECK_TROUBLE;
    if (load_dump(dir, &mine, &m) != 0)
        goto done;

    if (against && is_dir(against)) {
        manifest other;
        memset(&other, 0, sizeof other);
        against_dir = 1;
        ref_name = against;
        k = load_dump(against, &ref, &other);
        free(other.scene);
        if (k != 0)
            goto done;
    } else {
        /* the manifest's options, then the command line's */
        int s;
        ref_name = against ? against : m.scene;
        if (!ref_name) {
            trouble("%s/manifest.json: missing key 'scene.name' (or give "
                    "--against)", dir);
            goto done;
        }
        atrbvh_build_options_init(&o);
        if (m.has_options) {
            o.method = m.method;
            o.treelet_size = m.treelet;
            o.rounds = m.rounds;
            o.gamma = m.gamma;
            if (m.ci > 0.0)
                o.ci = m.ci;
            if (m.ct > 0.0)
                o.ct = m.ct;
            o.collapse = m.collapse;
            o.max_leaf_size = m.max_leaf;
            o.skip_invalid = m.skip_invalid;
        }
        /* a method given here: its own defaults, not the manifest's
         * treelet size, rounds and gamma */
        for (s = 0; table[s].name; s++)
            if (seen[s] && (!strcmp(table[s].name, "--method") ||
                            !strcmp(table[s].name, "--quality"))) {
                o.method = methods[cl.method];
                o.treelet_size = cl.options.treelet_size;
                o.rounds = cl.options.rounds;
                o.gamma = 0;
            }
        for (s = 0; table[s].name; s++) {
            const char *nm = table[s].name;
            if (!seen[s])
                continue;
            if (!strcmp(nm, "--treelet")) {
                o.treelet_size = cl.options.treelet_size;
                o.gamma = 0;
            }
            if (!strcmp(nm, "--rounds"))
                o.rounds = cl.options.rounds;
            if (!strcmp(nm, "--no-collapse"))
                o.collapse = 0;
            if (!strcmp(nm, "--max-leaf"))
                o.max_leaf_size = cl.options.max_leaf_size;
            if (!strcmp(nm, "--ci"))
                o.ci = cl.options.ci;
            if (!strcmp(nm, "--ct"))
                o.ct = cl.options.ct;
            if (!strcmp(nm, "--skip-invalid"))
                o.skip_invalid = 1;
        }
        o.threads = cl.options.threads;
        o.backend = cl.backend == 1 ? ATRBVH_BACKEND_OPENCL
                                    : ATRBVH_BACKEND_CPU;
        o.opencl_device = cl.options.opencl_device;
        for (s = 0; table[s].name; s++)
            if (seen[s] && !strcmp(table[s].name, "--device") &&
                o.backend != ATRBVH_BACKEND_OPENCL) {
                rc = cli_usage("check", "--device needs --backend opencl");
                goto done;
            }
        if (!o.opencl_device) {
            const char *env = getenv("ATRBVH_OPENCL_DEVICE");
            if (env && *env)
                o.opencl_device = env;
        }
        if (build_reference(ref_name, &o, &cl, &ref, &usage) != 0)
            goto done;
    }

    /* every array of the user's stages must exist in the reference's */
    if (!against_dir)
        for (i = 0; i < mine.count; i++) {
            stg *r = dump_find(&ref, mine.s[i].name);
            size_t a;
            if (!r)
                continue;
            for (a = 0; a < mine.s[i].count; a++)
                if (!stg_find(r, mine.s[i].a[a].name)) {
                    trouble("%s/manifest.json: stage %s has no array '%s'",
                            dir, mine.s[i].name, mine.s[i].a[a].name);
                    goto done;
                }
        }

    if (mine.count)
        qsort(mine.s, mine.count, sizeof *mine.s, stage_cmp);
    found = calloc(mine.count ? mine.count : 1, sizeof *found);
    if (!found) {
        trouble("out of memory");
        goto done;
    }
    for (i = 0; i < mine.count; i++) {
        stg *r = dump_find(&ref, mine.s[i].name);
        if (!r) {
            memset(&found[i], 0, sizeof found[i]);
            found[i].stage = &mine.s[i];
            found[i].missing = 1;
            if (!against_dir) {
                first = i;
                break;
            }
            continue;
        }
        compare_stage(&mine.s[i], r, tolerance, &found[i]);
        if (found[i].differing) {
            first = i;
            break;
        }
    }
    rc = first == (size_t)-1 ? CHECK_SAME : CHECK_DIFFER;
    if (rc == CHECK_SAME) {
        /* "same" must mean something was compared */
        size_t compared = 0;
        for (i = 0; i < mine.count; i++)
            compared += found[i].items;
        if (compared == 0) {
            trouble("%s: nothing to compare: no array of its manifest is in "
                    "the reference%s", dir,
                    mine.count ? "" : " (the manifest lists no stage)");
            rc = CHECK_TROUBLE;
            goto done;
        }
    }

    if (as_json) {
        json_writer w;
        json_init(&w, stdout);
        json_begin_object(&w);
        json_kv_string(&w, "dir", dir);
        json_kv_string(&w, "reference", ref_name);
        json_kv_string(&w, "reference_kind", against_dir ? "dump" : "build");
        json_kv_uint(&w, "tolerance_ulps", tolerance);
        json_kv_string(&w, "result", rc == CHECK_SAME ? "same" : "different");
        if (rc == CHECK_DIFFER)
            json_kv_string(&w, "first_different_stage",
                           mine.s[first].name);
        else
            json_key(&w, "first_different_stage"), json_null(&w);
        json_key(&w, "stages");
        json_begin_array(&w);
        for (i = 0; i < mine.count; i++) {
            f = found[i];
            json_begin_object(&w);
            json_kv_string(&w, "stage", mine.s[i].name);
            if (i > first) {
                json_kv_string(&w, "result", "not compared");
            } else if (f.missing) {
                json_kv_string(&w, "result", against_dir
                                                 ? "not in the reference"
                                                 : "different");
                if (!against_dir)
                    json_kv_string(&w, "why",
                                   "the reference has no such stage");
            } else {
                json_kv_string(&w, "result",
                               f.differing ? "different" : "same");
                json_kv_uint(&w, "arrays", mine.s[i].count);
                json_kv_uint(&w, "items", f.items);
                json_kv_uint(&w, "differing_items", f.differing);
                if (f.differing) {
                    const arr *a = f.mine, *r = f.ref;
                    size_t na = a->rows * a->cols, nr = r->rows * r->cols;
                    json_key(&w, "first");
                    json_begin_object(&w);
                    json_kv_string(&w, "array", a->name);
                    json_kv_string(&w, "file", a->file);
                    json_kv_string(&w, "dtype", npy_descr(a->dtype));
                    json_kv_uint(&w, "index", f.index);
                    json_kv_uint(&w, "row", f.index / a->cols);
                    json_kv_uint(&w, "col", f.index % a->cols);
                    if (f.index < na)
                        value_json(&w, "value", a, f.index);
                    else
                        json_key(&w, "value"), json_null(&w);
                    if (f.index < nr)
                        value_json(&w, "reference", r, f.index);
                    else
                        json_key(&w, "reference"), json_null(&w);
                    if (is_float(a->dtype) && f.index < na &&
                        f.index < nr) {
                        uint64_t x = elem(a, f.index), y = elem(r, f.index);
                        json_key(&w, "ulps");
                        if (is_nan(a->dtype, x) || is_nan(a->dtype, y))
                            json_null(&w);
                        else
                            json_uint(&w, ulps(a->dtype, x, y));
                    }
                    if (na != nr) {
                        json_kv_uint(&w, "rows", a->rows);
                        json_kv_uint(&w, "reference_rows", r->rows);
                    }
                    json_end_object(&w);
                }
            }
            json_end_object(&w);
        }
        json_end_array(&w);
        json_end_object(&w);
        goto done;
    }

    printf("%s against %s%s", dir, ref_name,
           against_dir ? " (dumps)" : " (built)");
    if (tolerance)
        printf(", floats within %u ulps", tolerance);
    printf("\n");
    for (i = 0; i < mine.count; i++) {
        f = found[i];
        if (i > first) {
            printf("%zu later stage%s not compared\n", mine.count - i,
                   mine.count - i == 1 ? "" : "s");
            break;
        }
        if (f.missing) {
            printf("%-18s %s\n", mine.s[i].name,
                   against_dir ? "not in the reference dumps"
                               : "DIFFERENT: the reference has no such "
                                 "stage (check the rounds)");
            continue;
        }
        if (!f.differing) {
            printf("%-18s same (%zu array%s, %zu item%s)\n",
                   mine.s[i].name, mine.s[i].count,
                   mine.s[i].count == 1 ? "" : "s", f.items,
                   f.items == 1 ? "" : "s");
            continue;
        }
        {
            const arr *a = f.mine, *r = f.ref;
            size_t na = a->rows * a->cols, nr = r->rows * r->cols;
            char place[96], va[64], vr[64];
            place_text(place, sizeof place, a, f.index);
            if (f.index < na)
                value_text(va, sizeof va, a, f.index);
            else
                snprintf(va, sizeof va, "(absent: %zu rows)", a->rows);
            if (f.index < nr)
                value_text(vr, sizeof vr, r, f.index);
            else
                snprintf(vr, sizeof vr, "(absent: %zu rows)", r->rows);
            printf("%-18s DIFFERENT: %zu of %zu items\n", mine.s[i].name,
                   f.differing, f.items);
            printf("  first: %s in %s: %s, reference %s", place, a->file, va,
                   vr);
            if (is_float(a->dtype) && f.index < na && f.index < nr) {
                uint64_t x = elem(a, f.index), y = elem(r, f.index);
                if (is_nan(a->dtype, x) || is_nan(a->dtype, y))
                    printf(" (NaN)");
                else
                    printf(" (%llu ulps)",
                           (unsigned long long)ulps(a->dtype, x, y));
            }
            printf("\n");
            if (na != nr)
                printf("  rows: %zu, reference %zu\n", a->rows, r->rows);
        }
    }
    printf("%s\n", rc == CHECK_SAME ? "result: same"
                                    : "result: different");
done:
    (void)usage;
    free(found);
    free(m.scene);
    dump_free(&mine);
    dump_free(&ref);
    return rc;
}
