/* builtin.h: the built-in model texts, the .urm files of src/models compiled in verbatim
 * (scripts/embed.sh writes the table into the build's models/builtin.c with this same struct):
 * the table and a lookup by part name, for the workbench's model set, the distributors' model
 * hash and the tests that build a model from the built-in parts. */
#ifndef URA_BUILTIN_H
#define URA_BUILTIN_H

#include <string.h>

typedef struct {
  const char* name; /* the part's name: its file's name without .urm */
  const char* text; /* the file's text */
} urBuiltinModel;

/* every built-in part in the order of the Makefile's MODELS, then {NULL, NULL} */
extern const urBuiltinModel ur_builtin_models[];

/* the text of the built-in part name, or NULL */
static inline const char* ura_builtin_text(const char* name) {
  for (const urBuiltinModel* b = ur_builtin_models; b->name; b++) {
    if (!strcmp(b->name, name)) {
      return b->text;
    }
  }
  return NULL;
}

#endif
