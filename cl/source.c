/*
 * cl/source.c - the OpenCL program text: the kernel files embedded in the
 * library at build time (cl/embed), concatenated in order with their
 * `#include "` lines blanked and `#line` directives, so the compiler log
 * names the right file and line.
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

char *atrbvh_i_cl_source(void)
{
    char *parts[ATRBVH_CL_FILE_COUNT];
    size_t lens[ATRBVH_CL_FILE_COUNT], total = 1;
    char *src, *o;
    int k;
    for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++) {
        parts[k] = override_file(atrbvh_cl_files[k].name, &lens[k]);
        if (!parts[k])
            lens[k] = atrbvh_cl_files[k].length;
        total += lens[k] + 64;
    }
    src = atrbvh_i_malloc(total);
    if (src) {
        o = src;
        for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++) {
            const char *t = parts[k] ? parts[k]
                                     : (const char *)atrbvh_cl_files[k].text;
            size_t i = 0;
            o += sprintf(o, "#line 1 \"%.40s\"\n", atrbvh_cl_files[k].name);
            while (i < lens[k]) {
                const char *line = t + i;
                size_t j = i;
                while (j < lens[k] && t[j] != '\n')
                    j++;
                if (j < lens[k])
                    j++; /* the newline */
                if (strncmp(line, "#include \"", 10) == 0) {
                    *o++ = '\n';
                } else {
                    memcpy(o, line, j - i);
                    o += j - i;
                }
                i = j;
            }
            *o++ = '\n';
        }
        *o = '\0';
    }
    for (k = 0; k < ATRBVH_CL_FILE_COUNT; k++)
        atrbvh_i_free(parts[k]);
    return src;
}
