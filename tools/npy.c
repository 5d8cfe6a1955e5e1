/*
 * npy.c - the NumPy .npy writer and strict reader (npy.h).
 */
#include "config.h"

#include "npy.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static const char *const descrs[4] = {"<u4", "<u8", "<f4", "<f8"};

const char *npy_descr(atrbvh_dtype dtype)
{
    return (unsigned)dtype < 4u ? descrs[dtype] : NULL;
}

int npy_dtype_of(const char *descr, atrbvh_dtype *dtype)
{
    int k;
    for (k = 0; k < 4; k++)
        if (strcmp(descr, descrs[k]) == 0) {
            *dtype = (atrbvh_dtype)k;
            return 0;
        }
    return -1;
}

size_t npy_dtype_size(atrbvh_dtype dtype)
{
    return dtype == ATRBVH_DTYPE_U32 || dtype == ATRBVH_DTYPE_F32 ? 4 : 8;
}

static int host_is_little(void)
{
    const uint16_t one = 1;
    unsigned char b;
    memcpy(&b, &one, 1);
    return b == 1;
}

/* Reverses each element's bytes (big-endian hosts only). */
static void swap_elements(unsigned char *p, size_t count, size_t size)
{
    size_t i, k;
    for (i = 0; i < count; i++, p += size)
        for (k = 0; k < size / 2; k++) {
            unsigned char t = p[k];
            p[k] = p[size - 1 - k];
            p[size - 1 - k] = t;
        }
}

int npy_write(FILE *f, atrbvh_dtype dtype, int ndim, size_t rows,
              size_t cols, const void *data)
{
    char dict[160];
    unsigned char pre[10];
    size_t len, total, count, size = npy_dtype_size(dtype);
    int m;
    if (!npy_descr(dtype) || (ndim != 1 && ndim != 2) ||
        (ndim == 1 && cols != 1)) {
        errno = EINVAL;
        return -1;
    }
    if (cols != 0 && rows > SIZE_MAX / cols) {
        errno = EOVERFLOW;
        return -1;
    }
    count = rows * cols;
    if (size != 0 && count > SIZE_MAX / size) {
        errno = EOVERFLOW;
        return -1;
    }
    if (ndim == 1)
        m = snprintf(dict, sizeof dict,
                     "{'descr': '%s', 'fortran_order': False, "
                     "'shape': (%zu,), }",
                     npy_descr(dtype), rows);
    else
        m = snprintf(dict, sizeof dict,
                     "{'descr': '%s', 'fortran_order': False, "
                     "'shape': (%zu, %zu), }",
                     npy_descr(dtype), rows, cols);
    if (m < 0 || (size_t)m >= sizeof dict - 70) {
        errno = EOVERFLOW;
        return -1;
    }
    len = (size_t)m;
    /* pad with spaces, end with '\n', so that 10 + header is 64k */
    total = (10 + len + 1 + 63) / 64 * 64;
    while (10 + len + 1 < total)
        dict[len++] = ' ';
    dict[len++] = '\n';
    memcpy(pre, "\x93NUMPY", 6);
    pre[6] = 1;
    pre[7] = 0;
    pre[8] = (unsigned char)(len & 0xff);
    pre[9] = (unsigned char)(len >> 8);
    if (fwrite(pre, 1, 10, f) != 10 || fwrite(dict, 1, len, f) != len)
        return -1;
    if (count == 0)
        return 0;
    if (host_is_little()) {
        if (fwrite(data, size, count, f) != count)
            return -1;
    } else {
        unsigned char buf[4096];
        const unsigned char *p = data;
        size_t per = sizeof buf / size;
        while (count > 0) {
            size_t k = count < per ? count : per;
            memcpy(buf, p, k * size);
            swap_elements(buf, k, size);
            if (fwrite(buf, size, k, f) != k)
                return -1;
            p += k * size;
            count -= k;
        }
    }
    return 0;
}

/* ---------------------------------------------------------------- read */
static void skip_space(const char **p)
{
    while (**p == ' ' || **p == '\t')
        (*p)++;
}

/* A Python string literal in single or double quotes (no escapes). */
static int parse_str(const char **p, char *out, size_t room)
{
    char q = **p;
    size_t n = 0;
    if (q != '\'' && q != '"')
        return -1;
    (*p)++;
    while (**p && **p != q) {
        if (**p == '\\' || n + 1 >= room)
            return -1;
        out[n++] = *(*p)++;
    }
    if (**p != q)
        return -1;
    (*p)++;
    out[n] = '\0';
    return 0;
}

static int parse_size(const char **p, size_t *out)
{
    size_t v = 0;
    if (**p < '0' || **p > '9')
        return -1;
    while (**p >= '0' && **p <= '9') {
        size_t d = (size_t)(**p - '0');
        if (v > (SIZE_MAX - d) / 10)
            return -1;
        v = v * 10 + d;
        (*p)++;
    }
    *out = v;
    return 0;
}

/* The header dictionary: 0, or -1 with err. */
static int parse_dict(const char *h, npy_array *a, char *err, size_t errlen)
{
    const char *p = h;
    char key[32], val[32];
    int have_descr = 0, have_order = 0, have_shape = 0;
    skip_space(&p);
    if (*p++ != '{') {
        snprintf(err, errlen, "header is not a dictionary");
        return -1;
    }
    for (;;) {
        skip_space(&p);
        if (*p == '}')
            break;
        if (parse_str(&p, key, sizeof key) != 0) {
            snprintf(err, errlen, "header: bad key");
            return -1;
        }
        skip_space(&p);
        if (*p++ != ':') {
            snprintf(err, errlen, "header: ':' expected after '%s'", key);
            return -1;
        }
        skip_space(&p);
        if (strcmp(key, "descr") == 0) {
            if (parse_str(&p, val, sizeof val) != 0 ||
                npy_dtype_of(val, &a->dtype) != 0) {
                snprintf(err, errlen,
                         "unsupported dtype (want '<u4', '<u8', '<f4' or "
                         "'<f8')");
                return -1;
            }
            have_descr = 1;
        } else if (strcmp(key, "fortran_order") == 0) {
            if (strncmp(p, "False", 5) == 0) {
                p += 5;
            } else if (strncmp(p, "True", 4) == 0) {
                snprintf(err, errlen, "Fortran order is not supported");
                return -1;
            } else {
                snprintf(err, errlen, "header: bad fortran_order");
                return -1;
            }
            have_order = 1;
        } else if (strcmp(key, "shape") == 0) {
            size_t dims[3] = {0, 0, 0};
            int nd = 0;
            if (*p++ != '(') {
                snprintf(err, errlen, "header: bad shape");
                return -1;
            }
            for (;;) {
                skip_space(&p);
                if (*p == ')')
                    break;
                if (nd == 3 || parse_size(&p, &dims[nd]) != 0) {
                    snprintf(err, errlen, "header: bad shape");
                    return -1;
                }
                nd++;
                skip_space(&p);
                if (*p == ',')
                    p++;
                else if (*p != ')') {
                    snprintf(err, errlen, "header: bad shape");
                    return -1;
                }
            }
            p++;
            if (nd < 1 || nd > 2) {
                snprintf(err, errlen,
                         "shape has %d dimensions (want 1 or 2)", nd);
                return -1;
            }
            a->ndim = nd;
            a->rows = dims[0];
            a->cols = nd == 2 ? dims[1] : 1;
            have_shape = 1;
        } else {
            snprintf(err, errlen, "header: unknown key '%s'", key);
            return -1;
        }
        skip_space(&p);
        if (*p == ',')
            p++;
        else if (*p != '}') {
            snprintf(err, errlen, "header: ',' or '}' expected");
            return -1;
        }
    }
    p++;
    while (*p == ' ' || *p == '\n')
        p++;
    if (*p) {
        snprintf(err, errlen, "header: text after the dictionary");
        return -1;
    }
    if (!have_descr || !have_order || !have_shape) {
        snprintf(err, errlen, "header lacks '%s'",
                 !have_descr ? "descr"
                             : !have_order ? "fortran_order" : "shape");
        return -1;
    }
    return 0;
}

int npy_read(const char *path, npy_array *out, char *err, size_t errlen)
{
    unsigned char pre[12];
    char *header = NULL;
    size_t hlen, count, bytes, got;
    FILE *f;
    int c;
    memset(out, 0, sizeof *out);
    f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s", strerror(errno));
        return -1;
    }
    if (fread(pre, 1, 10, f) != 10 || memcmp(pre, "\x93NUMPY", 6) != 0) {
        snprintf(err, errlen, "not a .npy file (bad magic)");
        goto fail;
    }
    if (pre[6] == 1 && pre[7] == 0) {
        hlen = (size_t)pre[8] | (size_t)pre[9] << 8;
    } else if (pre[6] == 2 && pre[7] == 0) {
        if (fread(pre + 10, 1, 2, f) != 2) {
            snprintf(err, errlen, "truncated header");
            goto fail;
        }
        hlen = (size_t)pre[8] | (size_t)pre[9] << 8 |
               (size_t)pre[10] << 16 | (size_t)pre[11] << 24;
        if (hlen > 65536) {
            snprintf(err, errlen, "header too long");
            goto fail;
        }
    } else {
        snprintf(err, errlen, "unsupported .npy version %u.%u", pre[6],
                 pre[7]);
        goto fail;
    }
    header = malloc(hlen + 1);
    if (!header) {
        snprintf(err, errlen, "out of memory");
        goto fail;
    }
    if (fread(header, 1, hlen, f) != hlen) {
        snprintf(err, errlen, "truncated header");
        goto fail;
    }
    header[hlen] = '\0';
    if (strlen(header) != hlen) {
        snprintf(err, errlen, "header holds a NUL byte");
        goto fail;
    }
    if (parse_dict(header, out, err, errlen) != 0)
        goto fail;
    if (out->cols != 0 && out->rows > SIZE_MAX / out->cols) {
        snprintf(err, errlen, "shape too large");
        goto fail;
    }
    count = out->rows * out->cols;
    if (count > SIZE_MAX / 8) {
        snprintf(err, errlen, "shape too large");
        goto fail;
    }
    bytes = count * npy_dtype_size(out->dtype);
    /* the data as it comes, its buffer at most twice what has come: a
     * shape that claims more than the file holds is a truncated file,
     * never an allocation of the claimed size */
    got = 0;
    {
        size_t cap = bytes < 65536u ? bytes : 65536u;
        out->data = malloc(cap ? cap : 1);
        while (out->data) {
            got += fread((char *)out->data + got, 1, cap - got, f);
            if (got < cap || cap == bytes)
                break; /* the end of the file, or all of it */
            {
                const size_t more = cap <= bytes - cap ? 2u * cap : bytes;
                void *grown = realloc(out->data, more);
                if (!grown) {
                    free(out->data);
                    out->data = NULL;
                    break;
                }
                out->data = grown;
                cap = more;
            }
        }
    }
    if (!out->data) {
        snprintf(err, errlen, "out of memory (%zu bytes)", bytes);
        goto fail;
    }
    if (got != bytes) {
        snprintf(err, errlen, "truncated data: %zu of %zu bytes", got, bytes);
        goto fail;
    }
    c = fgetc(f);
    if (c != EOF) {
        snprintf(err, errlen, "more bytes after the %zu the shape says",
                 bytes);
        goto fail;
    }
    if (ferror(f)) {
        snprintf(err, errlen, "read error");
        goto fail;
    }
    if (!host_is_little())
        swap_elements(out->data, count, npy_dtype_size(out->dtype));
    free(header);
    fclose(f);
    return 0;
fail:
    free(header);
    fclose(f);
    npy_free(out);
    return -1;
}

void npy_free(npy_array *a)
{
    free(a->data);
    a->data = NULL;
}

/* ------------------------------------------------ the stage dump format */
int npy_stage_rank(const char *stage, unsigned *round)
{
    static const char *const names[] = {"bounds",   "morton", "sort",
                                        "hierarchy", "refit", NULL,
                                        "optimise", "collapse", "layout"};
    static const char prefix[] = "optimise_round";
    int k;
    *round = 0;
    for (k = 0; k < 9; k++)
        if (names[k] && strcmp(stage, names[k]) == 0)
            return k;
    if (strncmp(stage, prefix, sizeof prefix - 1) == 0) {
        const char *p = stage + sizeof prefix - 1;
        unsigned long r = 0;
        if (*p < '1' || *p > '9')
            return -1;
        for (; *p >= '0' && *p <= '9'; p++) {
            r = r * 10 + (unsigned long)(*p - '0');
            if (r > 1000000ul)
                return -1;
        }
        if (*p)
            return -1;
        *round = (unsigned)r;
        return 5;
    }
    return -1;
}

int npy_array_schema(const char *array, atrbvh_dtype *dtype, int *ndim,
                     size_t *cols)
{
    static const struct {
        const char *name;
        atrbvh_dtype dtype;
        int ndim;
        size_t cols;
    } known[] = {
        {"prim_boxes", ATRBVH_DTYPE_F32, 2, 6},
        {"scene_box", ATRBVH_DTYPE_F32, 2, 6},
        {"centroid_box", ATRBVH_DTYPE_F32, 2, 6},
        {"morton_frame", ATRBVH_DTYPE_F64, 2, 3},
        {"keys", ATRBVH_DTYPE_U64, 1, 1},
        {"sorted_keys", ATRBVH_DTYPE_U64, 1, 1},
        {"order", ATRBVH_DTYPE_U32, 1, 1},
        {"left", ATRBVH_DTYPE_U32, 1, 1},
        {"right", ATRBVH_DTYPE_U32, 1, 1},
        {"parent", ATRBVH_DTYPE_U32, 1, 1},
        {"count", ATRBVH_DTYPE_U32, 1, 1},
        {"leaf_prim", ATRBVH_DTYPE_U32, 1, 1},
        {"box", ATRBVH_DTYPE_F32, 2, 6},
        {"cost", ATRBVH_DTYPE_F64, 1, 1},
        {"collapse_size", ATRBVH_DTYPE_U32, 1, 1},
        {"node_boxes", ATRBVH_DTYPE_F32, 2, 6},
        {"node_index_count", ATRBVH_DTYPE_U32, 2, 2},
        {"prim_indices", ATRBVH_DTYPE_U32, 1, 1},
    };
    size_t k;
    for (k = 0; k < sizeof known / sizeof known[0]; k++)
        if (strcmp(array, known[k].name) == 0) {
            *dtype = known[k].dtype;
            *ndim = known[k].ndim;
            *cols = known[k].cols;
            return 0;
        }
    return -1;
}
