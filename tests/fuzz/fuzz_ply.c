/* fuzz_ply.c - libFuzzer harness for the PLY reader (tools/ply.c): any
 * bytes either load into a scene whose every index is in range, or fail
 * with one line naming the file and a line or byte offset. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_scene(data, size, scene_parse_ply, "fuzz.ply");
    return 0;
}
