/*
 * png_write.c - 8-bit RGB PNG files through libpng (HAVE_PNG), for
 * `atrbvh render`.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"
#include "outfile.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#ifdef HAVE_PNG
#include <png.h>

int cli_png_available(void)
{
    return 1;
}

/* What the libpng callbacks share (libpng's error pointer). */
typedef struct png_sink {
    const char *path;
    FILE *f;
    int write_errno; /* errno of a failed write, else 0 */
} png_sink;

/* libpng's errors end in a longjmp; the one error line names the file. */
static void png_err(png_structp p, png_const_charp msg)
{
    png_sink *s = (png_sink *)png_get_error_ptr(p);
    if (s->write_errno)
        cli_error("%s: write failed: %s", s->path, strerror(s->write_errno));
    else
        cli_error("%s: libpng: %s", s->path, msg);
    png_longjmp(p, 1);
}

static void png_warn(png_structp p, png_const_charp msg)
{
    (void)p;
    (void)msg;
}

/* Our own write callback, so that a failed write's errno is kept. */
static void png_sink_write(png_structp p, png_bytep data, size_t n)
{
    png_sink *s = (png_sink *)png_get_io_ptr(p);
    errno = 0;
    if (fwrite(data, 1, n, s->f) != n) {
        s->write_errno = errno ? errno : EIO;
        png_error(p, "write failed");
    }
}

static void png_sink_flush(png_structp p)
{
    (void)p; /* cli_out_commit flushes */
}

/* The PNG goes through outfile.h: written beside the target and renamed
 * over it only when complete, so a failure leaves no truncated PNG (and
 * the previous file, if any, untouched). */
int cli_png_write(const char *path, unsigned width, unsigned height,
                  const unsigned char *rgb)
{
    cli_out out;
    png_sink sink;
    png_structp png = NULL;
    png_infop info = NULL;
    unsigned y;
    sink.path = path;
    sink.write_errno = 0;
    sink.f = cli_out_open(path, &out);
    if (!sink.f)
        return -1;
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, png_err,
                                  png_warn);
    if (png)
        info = png_create_info_struct(png);
    if (!png || !info) {
        png_destroy_write_struct(&png, NULL);
        cli_out_abort(&out);
        cli_error("%s: libpng could not start", path);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        /* png_err printed the error line */
        png_destroy_write_struct(&png, &info);
        cli_out_abort(&out);
        return -1;
    }
    png_set_write_fn(png, &sink, png_sink_write, png_sink_flush);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < height; y++)
        png_write_row(png, (png_const_bytep)(rgb + (size_t)y * width * 3));
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return cli_out_commit(&out) == 0 ? 0 : -1;
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
