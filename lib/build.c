/* placeholder: core stage, being written */
typedef int atrbvh_placeholder_build;
