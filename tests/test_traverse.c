/* placeholder test program */
int main(void) { return 77; }
