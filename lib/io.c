/* placeholder: save, load, compare */
#include "internal.h"
typedef int atrbvh_placeholder_io_;
