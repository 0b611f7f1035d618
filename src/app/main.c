/* main.c: placeholder entry point, replaced by the REPL */
#include <stdio.h>
int main(void) { puts("uasrisk"); return 0; }
