/* fuzz_model.c: libFuzzer target for the model language (uasimpact-model(5)). Each input is a
 * model text: split into parts (ur_model_split) and parsed, built and compiled
 * (ur_model_parse, as the application compiles its model set). A model that compiles is then
 * stepped a few times from its reference configuration (ur_data_new, ur_step), which runs the
 * forward dynamics, contacts, airbags and sensors on whatever the text built; the settling and
 * impacts the application runs next take seconds and are left out. Texts holding NUL bytes are
 * skipped: the application refuses them before parsing (model load).
 *   make fuzz            (tests/fuzz/corpus_model, dictionary tests/fuzz/model.dict)
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "uasimpact/engine.h"
#include "uasimpact/modellang.h"

#define STEPS 8

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (memchr(data, 0, size)) return 0;
  char* text = malloc(size + 1);
  if (!text) return 0;
  memcpy(text, data, size);
  text[size] = 0;

  /* parts, then the whole text as one model */
  char err[300];
  urModelPart part[32];
  int n = ur_model_split(text, "fuzz", part, 32, err, sizeof err);
  for (int i = 0; i < n && i < 32; i++) {
    if (part[i].text < text || part[i].text + part[i].len > text + size) abort();
  }
  urModelSource src = {text, "fuzz", 1};
  urModel* m = ur_model_parse(&src, 1, NULL, 0, err, sizeof err);
  if (!m && !memchr(err, 0, sizeof err)) abort(); /* the message is a string */

  /* a few steps of what was built */
  if (m) {
    urData* d = ur_data_new(m);
    for (int i = 0; d && i < STEPS && ur_step(m, d) >= 0; i++) {
    }
    ur_data_free(d);
    ur_model_free(m);
  }
  free(text);
  return 0;
}
