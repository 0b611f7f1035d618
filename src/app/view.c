/* view.c: placeholder, replaced by the ncurses grid viewer */
#include "app.h"
int ura_cmd_view(uraCtx* c, int argc, char** argv) { return ura_fail(c, "view: not built yet"); }
