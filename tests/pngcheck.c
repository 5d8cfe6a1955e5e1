/*
 * pngcheck.c - reads a PNG with libpng and prints "WIDTH HEIGHT"; exit 1
 * when libpng cannot read all of it.  For tests/bench.sh.
 */
#include "config.h"

#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    png_image img;
    png_bytep buf;
    if (argc != 2) {
        fprintf(stderr, "usage: pngcheck FILE.png\n");
        return 2;
    }
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, argv[1])) {
        fprintf(stderr, "pngcheck: %s: %s\n", argv[1], img.message);
        return 1;
    }
    img.format = PNG_FORMAT_RGB;
    buf = malloc(PNG_IMAGE_SIZE(img));
    if (!buf || !png_image_finish_read(&img, NULL, buf, 0, NULL)) {
        fprintf(stderr, "pngcheck: %s: %s\n", argv[1],
                buf ? img.message : "out of memory");
        free(buf);
        png_image_free(&img);
        return 1;
    }
    printf("%u %u\n", (unsigned)img.width, (unsigned)img.height);
    free(buf);
    return 0;
}
