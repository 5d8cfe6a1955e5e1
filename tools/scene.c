/* placeholder: to be written (see the issue) */
typedef int atrbvh_placeholder_scene_;
