/* named.c: the model parameters that 'set' also takes by name, one table for the command and
 * its completion: set bag_model analytic|membrane is bag_membrane 0|1, set endrun window|final
 * is endrun 0|1, and show NAME prints the word the parameter's value stands for. A name the
 * model does not declare is one clear error line. */
#include <string.h>

#include "cmd.h"

const uraNamed ura_named[] = {
    {"bag_model", "bag_membrane", {"analytic", "membrane"}, 0, "its airbags declare no membrane"},
    {"endrun", "endrun", {"window", "final"}, 1, "sim.urm declares it"},
    {NULL, NULL, {NULL, NULL}, 0, NULL},
};

const uraNamed* ura_named_find(const char* name) {
  for (const uraNamed* n = ura_named; n->name; n++) {
    if (!strcmp(n->name, name)) return n;
  }
  return NULL;
}

int ura_named_set(uraCtx* c, const uraNamed* n, int argc, char** argv) {
  int v = argc != 3 ? -1 : !strcmp(argv[2], n->word[1]) ? 1 : !strcmp(argv[2], n->word[0]) ? 0 : -1;
  if (v < 0) {
    return ura_fail(c, "set %s: expected %s or %s (got '%s'%s)", n->name, n->word[0], n->word[1],
                    argv[2], argc == 4 ? " and a unit" : "");
  }
  if (ura_model_param_find(c, n->param) < 0) {
    return ura_fail(c, "set %s: the model has no parameter %s (%s)", n->name, n->param, n->why);
  }
  return ura_model_param_set(c, n->param, v ? "1" : "0", NULL, 1);
}

int ura_named_word(uraCtx* c, const uraNamed* n, const char** word, double* v) {
  int k = ura_model_param_find(c, n->param);
  if (k < 0) {
    return ura_fail(c, "show %s: the model has no parameter %s (%s)", n->name, n->param, n->why);
  }
  *v = c->model->param[k].value;
  *word = *v == 1 ? n->word[1] : *v == 0 ? n->word[0] : NULL;
  return 0;
}
