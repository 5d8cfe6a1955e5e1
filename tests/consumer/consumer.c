/*
 * consumer.c - a program outside the project that uses the installed
 * library the way a distribution's user would: <atrbvh.h> and pkg-config
 * only (tests/consumer.sh builds it against a DESTDIR staging tree, shared
 * and static).  Prints one line and exits 0 when everything agrees.
 */
#include <atrbvh.h>

#include <stdio.h>
#include <string.h>

static int fail(const char *what, const atrbvh_error *e)
{
    fprintf(stderr, "consumer: %s: %s\n", what, e ? e->text : "");
    return 1;
}

int main(void)
{
    /* A 4 x 4 grid of quads (32 triangles) in the plane z = 0. */
    float v[25 * 3];
    uint32_t idx[32 * 3];
    size_t nv = 0, nt = 0;
    for (int y = 0; y < 5; y++)
        for (int x = 0; x < 5; x++) {
            v[3 * nv] = (float)x;
            v[3 * nv + 1] = (float)y;
            v[3 * nv + 2] = 0.0f;
            nv++;
        }
    for (uint32_t y = 0; y < 4; y++)
        for (uint32_t x = 0; x < 4; x++) {
            uint32_t a = y * 5 + x, b = a + 1, c = a + 5, d = c + 1;
            uint32_t t[6] = {a, b, d, a, d, c};
            memcpy(idx + 3 * nt, t, sizeof t);
            nt += 2;
        }

    if (atrbvh_version() != ATRBVH_VERSION_HEX ||
        strcmp(atrbvh_version_string(), ATRBVH_VERSION_STRING) != 0) {
        fprintf(stderr, "consumer: header %s, library %s\n",
                ATRBVH_VERSION_STRING, atrbvh_version_string());
        return 1;
    }

    atrbvh_geometry g = atrbvh_geometry_triangles(v, nv, idx, nt);
    atrbvh_build_options o;
    atrbvh_build_options_init(&o);
    o.threads = 2;
    atrbvh_bvh *bvh = NULL;
    atrbvh_error err;
    if (atrbvh_build(&g, &o, &bvh, &err) != ATRBVH_OK)
        return fail("build", &err);

    atrbvh_stats st;
    atrbvh_bvh_stats(bvh, &st);
    if (st.primitives != nt)
        return fail("stats", NULL);

    /* Straight down onto the centre of the quad at (2.5, 1.5). */
    atrbvh_ray ray = {{2.25f, 1.75f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 100.0f};
    atrbvh_hit hit;
    if (!atrbvh_intersect(bvh, &g, &ray, &hit) || !(hit.t > 4.999f && hit.t < 5.001f) ||
        hit.primitive / 2 != 1 * 4 + 2)
        return fail("intersect", NULL);

    void *data = NULL;
    size_t size = 0;
    atrbvh_bvh *copy = NULL;
    if (atrbvh_save_memory(bvh, &data, &size, &err) != ATRBVH_OK)
        return fail("save_memory", &err);
    if (atrbvh_load_memory(data, size, &copy, &err) != ATRBVH_OK)
        return fail("load_memory", &err);
    if (atrbvh_compare(bvh, copy, &err) != 0)
        return fail("compare", &err);
    atrbvh_free(data);
    /* the same tree again, rebuilt into the loaded copy's memory */
    if (atrbvh_rebuild(&g, &o, &copy, &err) != ATRBVH_OK)
        return fail("rebuild", &err);
    if (atrbvh_compare(bvh, copy, &err) != 0)
        return fail("compare after rebuild", &err);
    atrbvh_bvh_free(copy);

    printf("consumer: libatrbvh %s, %zu triangles, %zu nodes, SAH %.3f, "
           "hit %u at t = %g\n",
           atrbvh_version_string(), st.primitives, st.nodes, st.sah,
           (unsigned)hit.primitive, (double)hit.t);
    atrbvh_bvh_free(bvh);
    return 0;
}
