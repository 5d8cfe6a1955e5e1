/* fuzz_bvh.c - libFuzzer harness for atrbvh_load_memory (lib/load.c).
 * Arbitrary bytes either load into a BVH that passes the structural
 * checks, saves back to the same bytes and answers ray queries without
 * reading out of bounds, or fail with ATRBVH_ERR_FORMAT (or NOMEM) and a
 * message; nothing allocated is larger than the data (plus the fixed BVH
 * object).  Mutating the checksum is hopeless, so the first byte of the
 * input says whether to fix the CRC up before loading. */
#include "fuzz_common.h"
#include "testutil.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    unsigned char *d;
    atrbvh_bvh *b = NULL;
    atrbvh_error e;
    atrbvh_status st;
    size_t n;
    if (size < 1)
        return 0;
    n = size - 1;
    d = malloc(n ? n : 1);
    memcpy(d, data + 1, n);
    if ((data[0] & 1) && n >= 4)
        tu_fix_crc(d, n);
    tu_count_reset(-1);
    atrbvh_set_allocator(tu_count_malloc, tu_count_free);
    st = atrbvh_load_memory(d, n, &b, &e);
    atrbvh_set_allocator(NULL, NULL);
    FUZZ_CHECK(tu_alloc.largest <= (n > 512 ? n : 512),
               "allocated %zu for %zu bytes", tu_alloc.largest, n);
    if (st != ATRBVH_OK) {
        FUZZ_CHECK(b == NULL, "failed but returned a BVH");
        FUZZ_CHECK(st == ATRBVH_ERR_FORMAT || st == ATRBVH_ERR_NOMEM,
                   "status %d: %s", (int)st, e.text);
        FUZZ_CHECK(e.text[0] != '\0', "no message");
    } else {
        void *again = NULL;
        size_t again_n = 0, nn, np, i;
        const atrbvh_node *nodes = atrbvh_bvh_nodes(b, &nn);
        const uint32_t *idx = atrbvh_bvh_primitive_indices(b, &np);
        atrbvh_stats stats;
        atrbvh_bvh_stats(b, &stats);
        FUZZ_CHECK(atrbvh_save_memory(b, &again, &again_n, &e) == ATRBVH_OK,
                   "%s", e.text);
        /* the same bytes, but for the informative SAH (recomputed on
         * load) and so the checksum */
        FUZZ_CHECK(again_n == n && memcmp(again, d, 72) == 0 &&
                       memcmp((char *)again + 80, d + 80, n - 84) == 0,
                   "saved bytes differ");
        atrbvh_free(again);
        FUZZ_CHECK(nn == stats.nodes && np == stats.primitives, "stats");
        {
            /* Query over a geometry of boxes large enough for every index
             * (indices are below the input count, which is at most the
             * index count plus the skipped ones). */
            size_t nb = stats.primitives + stats.invalid_skipped;
            if (nb <= 100000) {
                float *boxes = calloc(nb * 6, sizeof *boxes);
                atrbvh_geometry g = atrbvh_geometry_boxes(boxes, nb);
                for (i = 0; i < nb * 6; i++)
                    boxes[i] = (float)(i % 6 < 3 ? -1.0 : 1.0);
                for (i = 0; i < 8; i++) {
                    atrbvh_ray r;
                    atrbvh_hit h;
                    r.origin[0] = (float)i - 4;
                    r.origin[1] = 0.5f;
                    r.origin[2] = -10;
                    r.dir[0] = 0.1f;
                    r.dir[1] = (float)i * 0.01f;
                    r.dir[2] = 1;
                    r.tmin = 0;
                    r.tmax = INFINITY;
                    (void)atrbvh_intersect(b, &g, &r, &h);
                    (void)atrbvh_occluded(b, &g, &r);
                }
                free(boxes);
            }
        }
        (void)nodes;
        (void)idx;
        atrbvh_bvh_free(b);
    }
    free(d);
    return 0;
}
