/* placeholder: treelet restructuring (issue 3) */
#include "internal.h"

atrbvh_status __atrbvh_optimise(__atrbvh_tree *t, const __atrbvh_config *cfg,
                                atrbvh_error *error)
{
    (void)t;
    if (cfg->method == ATRBVH_METHOD_LBVH)
        return ATRBVH_OK;
    return __atrbvh_fail(error, ATRBVH_ERR_UNSUPPORTED, (uint64_t)-1,
                         "treelet restructuring is not implemented yet");
}
