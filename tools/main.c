/* placeholder: the command-line tool */
#include <stdio.h>
int main(void)
{
    fputs("atrbvh: not built yet\n", stderr);
    return 1;
}
