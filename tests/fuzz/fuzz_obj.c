/* fuzz_obj.c - libFuzzer harness for the OBJ reader (tools/obj.c); see
 * fuzz_ply.c. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_scene(data, size, scene_parse_obj, "fuzz.obj");
    return 0;
}
