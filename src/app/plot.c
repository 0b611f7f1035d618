/* plot.c: placeholder, replaced by the gnuplot pipe */
#include "app.h"
int ura_cmd_plot(uraCtx* c, int argc, char** argv) { return ura_fail(c, "plot: not built yet"); }
