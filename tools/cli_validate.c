/*
 * cli_validate.c - `atrbvh validate SCENE [build options]`: build on the
 * CPU and on OpenCL, compare every stage's output (atrbvh_validate_backends),
 * print the first difference.  Exit 0 only when everything is identical.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include "cli.h"

#include <string.h>

static void validate_help(FILE *f)
{
    fputs("Usage: atrbvh validate SCENE [OPTIONS]\n"
          "Build SCENE on the CPU and on the OpenCL backend with the same "
          "options and\n"
          "compare every stage's output bit for bit: primitive boxes, Morton "
          "keys, sorted\n"
          "order, topology, boxes, counts and costs after refit and after "
          "optimise, the\n"
          "collapse decisions, and the final node and index arrays.  Prints "
          "the first\n"
          "differing stage and item.\n"
          "\n",
          f);
    cli_build_options_help(f);
    fputs("  -h, --help           this help\n"
          "\n"
          "(--backend and --output are ignored; --json prints "
          "{\"identical\": ..., \"difference\": ...}.)\n"
          "Exit status: 0 identical, 1 a difference or a failure, 2 usage "
          "error.\n",
          f);
}

int cli_validate(int argc, char **argv)
{
    cli_build_args a;
    scene sc;
    atrbvh_geometry g;
    atrbvh_error e;
    atrbvh_status st;
    char err[512];
    int rc, i = 1, identical = 0;
    double t0;

    if ((rc = cli_help_or_version(argc, argv, validate_help)) >= 0)
        return rc;
    cli_build_args_init(&a);
    while (i < argc) {
        const char *arg = argv[i];
        int r = cli_build_option("validate", argc, argv, &i, &a);
        if (r < 0)
            return CLI_USAGE;
        if (r > 0)
            continue;
        if (arg[0] == '-' && arg[1] != '\0')
            return cli_usage("validate", "unknown option '%s'", arg);
        if (a.scene)
            return cli_usage("validate", "more than one SCENE ('%s', '%s')",
                             a.scene, arg);
        a.scene = arg;
        i++;
    }
    if (!a.scene)
        return cli_usage("validate", "no SCENE given");
    if (scene_load(a.scene, &sc, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_FAIL;
    }
    if (sc.triangle_count == 0) {
        cli_error("%s: the scene has no triangles", a.scene);
        scene_free(&sc);
        return CLI_FAIL;
    }
    g = scene_geometry(&sc);
    memset(&e, 0, sizeof e);
    t0 = cli_now_ms();
    st = atrbvh_validate_backends(&g, &a.options, &identical, &e);
    scene_free(&sc);
    if (st != ATRBVH_OK) {
        cli_error("%s: %s", a.scene, e.text[0] ? e.text : atrbvh_strerror(st));
        return CLI_FAIL;
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
