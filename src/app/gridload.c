/* gridload.c: placeholder, replaced by the grid CSV reader */
#include "app.h"
int ura_grid_load(uraCtx* c, const char* path) { return ura_fail(c, "grid load: not built yet"); }
