/*
 * cli_validate.c - `atrbvh validate SCENE [build options]`: build on the
 * CPU and on OpenCL, compare every stage's output (atrbvh_validate_backends),
 * print the first difference.  Exit 0 identical, 1 different, 2 trouble
 * (as cmp and diff).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"

#include <string.h>

/* No --backend (both are used) and no --output (nothing is saved). */
#define VALIDATE_BUILD_OPTS (CLI_BUILD_CORE | CLI_BUILD_DEVICE | CLI_BUILD_JSON)

static void validate_help(FILE *f)
{
    cli_build_help(f,
                   "Usage: atrbvh validate SCENE [OPTIONS]\n"
                   "Build SCENE on the CPU and on the OpenCL backend with "
                   "the same options and\n"
                   "compare every stage's output bit for bit: primitive "
                   "boxes, Morton keys, sorted\n"
                   "order, topology, boxes, counts and costs after refit "
                   "and after optimise, the\n"
                   "collapse decisions, and the final node and index "
                   "arrays.  Prints the first\n"
                   "differing stage and item.  --json prints {\"identical\": "
                   "..., \"difference\": ...},\n"
                   "or {\"error\": ...} when the check could not be made.\n",
                   NULL, NULL, VALIDATE_BUILD_OPTS,
                   "0 identical, 1 different, 2 trouble (usage error, "
                   "unreadable scene,\nno OpenCL device, a failed build)");
}

/* A failure: the error line, and with --json a JSON object saying so. */
static int trouble(const cli_build_args *a, const char *text)
{
    cli_error("%s", text);
    if (a->json) {
        json_writer w;
        json_init(&w, stdout);
        json_begin_object(&w);
        json_kv_string(&w, "scene", a->scene);
        json_key(&w, "identical");
        json_null(&w);
        json_kv_string(&w, "error", text);
        json_end_object(&w);
    }
    return CLI_USAGE;
}

int cli_validate(int argc, char **argv)
{
    cli_build_args a;
    scene sc;
    atrbvh_geometry g;
    atrbvh_error e;
    atrbvh_status st;
    char err[512], text[1024];
    int rc, identical = 0;
    double t0;

    if ((rc = cli_help_or_version(argc, argv, validate_help)) >= 0)
        return rc;
    cli_build_args_init(&a);
    if (cli_build_parse("validate", argc, argv, NULL, VALIDATE_BUILD_OPTS,
                        &a) != 0)
        return CLI_USAGE;
    if (scene_load(a.scene, &sc, err, sizeof err) != 0)
        return trouble(&a, err);
    if (sc.triangle_count == 0) {
        scene_free(&sc);
        snprintf(text, sizeof text, "%s: the scene has no triangles", a.scene);
        return trouble(&a, text);
    }
    g = scene_geometry(&sc);
    memset(&e, 0, sizeof e);
    t0 = cli_now_ms();
    st = atrbvh_validate_backends(&g, &a.options, &identical, &e);
    scene_free(&sc);
    if (st != ATRBVH_OK && cli_bad_device(&a, st, e.text))
        return cli_usage("validate", "--device: %s", e.text);
    if (st != ATRBVH_OK) {
        snprintf(text, sizeof text, "%s: %s", a.scene,
                 e.text[0] ? e.text : atrbvh_strerror(st));
        return trouble(&a, text);
    }
    if (a.json) {
        json_writer w;
        json_init(&w, stdout);
        json_begin_object(&w);
        json_kv_string(&w, "scene", a.scene);
        json_kv_bool(&w, "identical", identical);
        if (!identical)
            json_kv_string(&w, "difference", e.text);
        json_kv_double(&w, "ms", cli_now_ms() - t0);
        json_end_object(&w);
    } else if (identical) {
        printf("%s: cpu and opencl identical at every stage\n", a.scene);
    } else {
        printf("%s: %s\n", a.scene, e.text);
    }
    return identical ? CLI_OK : CLI_FAIL;
}
