/*
 * png_write.c - 8-bit RGB PNG files through libpng (HAVE_PNG), for
 * `atrbvh render`.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#ifdef HAVE_PNG
#include <png.h>

int cli_png_available(void)
{
    return 1;
}

static void png_err(png_structp p, png_const_charp msg)
{
    cli_error("libpng: %s", msg);
    png_longjmp(p, 1);
}

static void png_warn(png_structp p, png_const_charp msg)
{
    (void)p;
    (void)msg;
}

int cli_png_write(const char *path, unsigned width, unsigned height,
                  const unsigned char *rgb)
{
    FILE *f = fopen(path, "wb");
    png_structp png = NULL;
    png_infop info = NULL;
    unsigned y;
    if (!f) {
        cli_error("%s: %s", path, strerror(errno));
        return -1;
    }
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, png_err,
                                  png_warn);
    if (png)
        info = png_create_info_struct(png);
    if (!png || !info) {
        png_destroy_write_struct(&png, NULL);
        fclose(f);
        cli_error("%s: libpng could not start", path);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < height; y++)
        png_write_row(png, (png_const_bytep)(rgb + (size_t)y * width * 3));
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    if (fclose(f) != 0) {
        cli_error("%s: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

#else

int cli_png_available(void)
{
    return 0;
}

int cli_png_write(const char *path, unsigned width, unsigned height,
                  const unsigned char *rgb)
{
    (void)width, (void)height, (void)rgb;
    cli_error("%s: not built with libpng", path);
    return -1;
}

#endif
