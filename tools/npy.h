/*
 * npy.h - NumPy .npy files (format version 1.0) for `atrbvh stages` and
 * `atrbvh check`: little-endian u32, u64, f32 and f64 arrays of one or two
 * dimensions, C order.  The header is the magic "\x93NUMPY", the version
 * bytes 1 0, a little-endian 16-bit header length and the dictionary
 * {'descr': '<u4', 'fortran_order': False, 'shape': (n,), } padded with
 * spaces and a final newline so that the data starts at a multiple of 64
 * bytes (docs/stages.md).
 */
#ifndef ATRBVH_TOOLS_NPY_H
#define ATRBVH_TOOLS_NPY_H

#include <stddef.h>
#include <stdio.h>

#include "atrbvh.h"

/* "<u4", "<u8", "<f4", "<f8"; NULL for anything else. */
const char *npy_descr(atrbvh_dtype dtype);
/* The dtype of a descr string: 0 and *dtype, or -1 when unknown. */
int npy_dtype_of(const char *descr, atrbvh_dtype *dtype);
size_t npy_dtype_size(atrbvh_dtype dtype);

/* Writes an array of rows x cols elements: shape (rows,) when ndim is 1
 * (cols must then be 1), (rows, cols) when 2.  0, or -1 with errno set
 * (EOVERFLOW for a size that does not fit). */
int npy_write(FILE *f, atrbvh_dtype dtype, int ndim, size_t rows,
              size_t cols, const void *data);

typedef struct npy_array {
    atrbvh_dtype dtype;
    int ndim;          /* 1 or 2                                  */
    size_t rows, cols; /* cols 1 when ndim is 1                   */
    void *data;        /* host byte order; malloc'ed              */
} npy_array;

/* Reads a whole .npy file strictly: version 1.0 or 2.0, one of the four
 * dtypes, C order, one or two dimensions, exactly the data the shape
 * says (neither truncated nor followed by more bytes).  0, or -1 with a
 * one-line reason in err ("truncated data: 40 of 48 bytes", ...). */
int npy_read(const char *path, npy_array *out, char *err, size_t errlen);
void npy_free(npy_array *a);

#endif

/* ------------------------------------------------ the stage dump format */
/* The pipeline position of a stage name: bounds 0, morton 1, sort 2,
 * hierarchy 3, refit 4, optimise_roundK 5 (*round = K), optimise 6,
 * collapse 7, layout 8; -1 for an unknown name. */
int npy_stage_rank(const char *stage, unsigned *round);
/* The documented dtype and shape of an array of the dumps (ndim 1, or 2
 * with `cols` columns): 0, or -1 for an unknown array name. */
int npy_array_schema(const char *array, atrbvh_dtype *dtype, int *ndim,
                     size_t *cols);
