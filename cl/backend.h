/*
 * cl/backend.h - what the OpenCL backend's files share.  Internal.
 */
#ifndef ATRBVH_CL_BACKEND_H
#define ATRBVH_CL_BACKEND_H

#include "internal.h"

#ifndef CL_TARGET_OPENCL_VERSION
#define CL_TARGET_OPENCL_VERSION 120
#endif
#include <CL/cl.h>

/* "CL_INVALID_VALUE", ... */
const char *atrbvh_i_cl_error_name(cl_int err);
/* Fills `error`: "OpenCL: CALL failed [for WHAT]: NAME (code)";
 * ATRBVH_ERR_NOMEM for the out-of-memory codes, else ATRBVH_ERR_BACKEND. */
atrbvh_status atrbvh_i_cl_fail(atrbvh_error *error, cl_int err,
                               const char *call, const char *what);
/* The device for `spec` (NULL: $ATRBVH_OPENCL_DEVICE, else the first). */
atrbvh_status atrbvh_i_cl_select(const char *spec, cl_device_id *out,
                                 char *name, size_t name_size,
                                 atrbvh_error *error);

#endif
