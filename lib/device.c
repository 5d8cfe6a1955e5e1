/*
 * device.c - device handles (Embree's device object, opened once): the
 * spec names a backend and, for OpenCL, a device; the backend's open
 * selects it and makes what every build reuses.  A handle also keeps the
 * host scratch of its builds and the lock that serialises calls on it.
 */
#include "config.h"

#include "internal.h"

#include <string.h>

#define NO_INDEX ((uint64_t)-1)

atrbvh_status atrbvh_i_device_open_backend(const atrbvh_i_backend *backend,
                                           const char *spec,
                                           atrbvh_device **out,
                                           atrbvh_error *error)
{
    atrbvh_device *dev = atrbvh_i_malloc(sizeof *dev);
    atrbvh_status st;
    if (!dev)
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot allocate the device handle");
    memset(dev, 0, sizeof *dev);
    dev->backend = backend;
    if (pthread_mutex_init(&dev->lock, NULL) != 0) {
        atrbvh_i_free(dev);
        return atrbvh_i_fail(error, ATRBVH_ERR_NOMEM, NO_INDEX,
                             "cannot create the device's lock");
    }
    st = backend->open(dev, spec, error);
    if (st != ATRBVH_OK) {
        pthread_mutex_destroy(&dev->lock);
        atrbvh_i_free(dev);
        return st;
    }
    *out = dev;
    return ATRBVH_OK;
}

/* "opencl" or "opencl:REST" -> REST (NULL for the first device). */
static int opencl_spec(const char *spec, const char **rest)
{
    if (strncmp(spec, "opencl", 6) != 0)
        return 0;
    if (spec[6] == '\0') {
        *rest = NULL;
        return 1;
    }
    if (spec[6] != ':')
        return 0;
    *rest = spec + 7;
    return 1;
}

atrbvh_status atrbvh_device_open(const char *spec, atrbvh_device **out,
                                 atrbvh_error *error)
{
    const char *rest = NULL;
    atrbvh_i_clear_error(error);
    if (!out)
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "the output pointer is NULL");
    *out = NULL;
    if (!spec || strcmp(spec, "cpu") == 0)
        return atrbvh_i_device_open_backend(&atrbvh_i_cpu_backend, "", out,
                                            error);
    if (!opencl_spec(spec, &rest))
        return atrbvh_i_fail(error, ATRBVH_ERR_INVALID_ARGUMENT, NO_INDEX,
                             "device \"%s\" is not cpu, opencl, "
                             "opencl:PLATFORM:DEVICE or opencl:NAME",
                             spec);
#ifdef ATRBVH_HAVE_OPENCL
    return atrbvh_i_device_open_backend(&atrbvh_i_cl_backend, rest, out,
                                        error);
#else
    (void)rest;
    return atrbvh_i_fail(error, ATRBVH_ERR_UNSUPPORTED, NO_INDEX,
                         "this build of atrbvh has no OpenCL backend "
                         "(configure --enable-opencl)");
#endif
}

void atrbvh_device_close(atrbvh_device *dev)
{
    if (!dev)
        return;
    dev->backend->close(dev);
    atrbvh_i_scratch_free(&dev->scratch);
    if (!dev->temporary) {
        pthread_mutex_destroy(&dev->lock);
        atrbvh_i_free(dev);
    }
}

const char *atrbvh_device_name(const atrbvh_device *dev)
{
    return dev ? dev->name : NULL;
}

atrbvh_backend atrbvh_device_backend(const atrbvh_device *dev)
{
    return dev ? dev->backend->kind : ATRBVH_BACKEND_CPU;
}

void atrbvh_i_device_lock(atrbvh_device *dev)
{
    if (!dev->temporary)
        pthread_mutex_lock(&dev->lock);
}

void atrbvh_i_device_unlock(atrbvh_device *dev)
{
    if (!dev->temporary)
        pthread_mutex_unlock(&dev->lock);
}

void atrbvh_i_device_cpu_temp(atrbvh_device *dev)
{
    memset(dev, 0, sizeof *dev);
    dev->backend = &atrbvh_i_cpu_backend;
    strcpy(dev->name, "cpu");
    dev->temporary = 1;
    dev->scratch.transient = 1;
}
