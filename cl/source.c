/*
 * cl/source.c - the OpenCL program text: the kernel files embedded in the
 * library at build time (cl/embed), concatenated in order with their
 * `#include "` lines blanked and `#line` directives, so the compiler log
 * names the right file and line.  A file whose name ends in ".inc" is a
 * text its includer takes more than once (shared/treelet_arrays.inc):
 * its text goes where it is included, and nowhere else.
 *
 * Kernel development only: configured with --enable-kernel-source-override
 * (ATRBVH_KERNEL_SOURCE_OVERRIDE), a file of the same name in the first
 * folder of $ATRBVH_CL_SOURCE_DIR (colon-separated) that has it replaces
 * the embedded one.  A normal build reads no environment variable.
 */
#include "config.h"

#include "opencl.h"

#include <stdio.h>
#include <string.h>

#include "kernels_embedded.h"

#ifdef ATRBVH_KERNEL_SOURCE_OVERRIDE
#include <stdlib.h>

static char *read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long size;
    if (!f)
        return NULL;
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 ||
        fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return NULL;
    }
    buf = atrbvh_i_malloc((size_t)size + 1);
    if (!buf) {
        fclose(f);
        return NULL;
    }
    if (fread(buf, 1, (size_t)size, f) != (size_t)size) {
        atrbvh_i_free(buf);
        fclose(f);
        return NULL;
    }
    fclose(f);
    buf[size] = '\0';
    *len = (size_t)size;
    return buf;
}

static char *override_file(const char *name, size_t *len)
{
    const char *dirs = getenv("ATRBVH_CL_SOURCE_DIR");
    char path[1024];
    while (dirs && *dirs) {
        const char *colon = strchr(dirs, ':');
        size_t dl = colon ? (size_t)(colon - dirs) : strlen(dirs);
        if (dl > 0 && dl < 900) {
            char *text;
            snprintf(path, sizeof path, "%.*s/%s", (int)dl, dirs, name);
            text = read_file(path, len);
            if (text)
                return text;
        }
        dirs = colon ? colon + 1 : NULL;
    }
    return NULL;
}
#else
static char *override_file(const char *name, size_t *len)
{
    (void)name;
    (void)len;
    return NULL;
}
#endif

/* The embedded file an `#include "NAME"` line names when NAME ends in
 * ".inc" (a text included more than once, at its include sites), else -1.
 * Other include lines name files the program holds once, in order. */
static int included_file(const char *line, size_t len)
{
    const char *name = line + 10, *end, *b;
    size_t nl, bl;
    int k;
    end = memchr(name, '"', len - 10);
    if (!end)
        return -1;
    nl = (size_t)(end - name);
    if (nl < 4 || memcmp(end - 4, ".inc", 4) != 0)
        return -1;
    /* the base name: the files are embedded by theirs */
    b = end;
    while (b > name && b[-1] != '/')
        b--;
    bl = (size_t)(end - b);
    for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++)
        if (strlen(atrbvh_cl_files[k].name) == bl &&
            memcmp(atrbvh_cl_files[k].name, b, bl) == 0)
            return k;
    return -1;
}

static int is_inc(int k)
{
    size_t l = strlen(atrbvh_cl_files[k].name);
    return l >= 4 && strcmp(atrbvh_cl_files[k].name + l - 4, ".inc") == 0;
}

/* Writes file k's text at o (o NULL: only counts) after a #line 1, an
 * `#include "X.inc"` line replaced by X.inc's text (depth 0 only) and
 * followed by a #line back, every other `#include "` line blanked.
 * Returns the bytes (at most what the count gave). */
static size_t emit(char *o, int k, char *const *parts, const size_t *lens,
                   int depth)
{
    const char *t =
        parts[k] ? parts[k] : (const char *)atrbvh_cl_files[k].text;
    char head[96];
    size_t i = 0, out = 0, line_no = 1;
    int hl = sprintf(head, "#line 1 \"%.40s\"\n", atrbvh_cl_files[k].name);
    if (o)
        memcpy(o, head, (size_t)hl);
    out += (size_t)hl;
    while (i < lens[k]) {
        const char *line = t + i;
        size_t j = i;
        int inc;
        while (j < lens[k] && t[j] != '\n')
            j++;
        if (j < lens[k])
            j++; /* the newline */
        line_no++;
        if (j - i >= 10 && strncmp(line, "#include \"", 10) == 0) {
            inc = depth == 0 ? included_file(line, j - i) : -1;
            if (inc >= 0) {
                out += emit(o ? o + out : NULL, inc, parts, lens, 1);
                hl = sprintf(head, "\n#line %lu \"%.40s\"\n",
                             (unsigned long)line_no, atrbvh_cl_files[k].name);
                if (o)
                    memcpy(o + out, head, (size_t)hl);
                out += (size_t)hl;
            } else {
                if (o)
                    o[out] = '\n';
                out++;
            }
        } else {
            if (o)
                memcpy(o + out, line, j - i);
            out += j - i;
        }
        i = j;
    }
    if (o)
        o[out] = '\n';
    return out + 1;
}

char *atrbvh_i_cl_source(void)
{
    char *parts[ATRBVH_CL_FILE_COUNT];
    size_t lens[ATRBVH_CL_FILE_COUNT], total = 1;
    char *src;
    int k;
    for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++) {
        parts[k] = override_file(atrbvh_cl_files[k].name, &lens[k]);
        if (!parts[k])
            lens[k] = atrbvh_cl_files[k].length;
    }
    /* the files in order, an .inc only where it is included */
    for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++)
        if (!is_inc(k))
            total += emit(NULL, k, parts, lens, 0);
    src = atrbvh_i_malloc(total);
    if (src) {
        size_t o = 0;
        for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++)
            if (!is_inc(k))
                o += emit(src + o, k, parts, lens, 0);
        src[o] = '\0';
    }
    for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++)
        atrbvh_i_free(parts[k]);
    return src;
}
