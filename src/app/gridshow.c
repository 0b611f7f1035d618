/* gridshow.c: placeholder, replaced by the coloured text grid */
#include "app.h"
int ura_grid_show(uraCtx* c) { return ura_fail(c, "grid show: not built yet"); }
