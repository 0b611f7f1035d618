/* fuzz_script.c: libFuzzer target for the command language. Each input is a session script
 * run by the real reader and dispatcher (ura_run_stream: lines, NUL bytes, comments, ';',
 * quotes, every command handler and the strict parsers) on a fresh context in dry mode
 * (uraCtx.dry, ura_dry): commands parse and check their arguments, then refuse to simulate,
 * run grids or sweeps, plot, open the viewer or open and write files, which would be slow or
 * side-effecting. Output goes to /dev/null.
 *
 * A fresh context is what ura_init gives. Compiling the built-in model set costs milliseconds,
 * so the parts and compiled model are kept from one input to the next when the input left the
 * parts as ura_init loads them (recompiled only if the parameter overrides changed, through
 * ura_model_state as 'case' and 'set' do); everything else is reset.
 *   make fuzz            (tests/fuzz/corpus_script, dictionary tests/fuzz/script.dict)
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/app/ui/ui.h"

static uraCtx c;
static uraState st0;             /* the state of a fresh context */
static char* text0[uraMAXPARTS]; /* the parts of a fresh context */
static int npart0, ready;
static FILE* null;

/* the model parts are still those ura_init loads (and nothing was simulated) */
static int same_parts(void) {
  if (c.have_setup || c.have_work || c.npart != npart0) return 0;
  for (int i = 0; i < npart0; i++) {
    if (strcmp(c.part[i].text, text0[i]) || strcmp(c.part[i].origin, "built-in")) return 0;
  }
  return 1;
}

static void fresh(void) {
  if (!ready || !same_parts()) {
    if (ready) ura_models_free(&c);
    ura_last_free(&c);
    ura_init(&c);
    if (!c.model) abort(); /* the built-in models must compile */
    st0 = c.st;
    for (int i = 0; i < npart0; i++) free(text0[i]);
    npart0 = c.npart;
    for (int i = 0; i < npart0; i++) text0[i] = strdup(c.part[i].text);
    ready = 1;
  } else {
    /* the model of the fresh state (compiled again only if the overrides changed), then
       everything else as ura_init leaves it */
    if (ura_model_state(&c, &st0, "fuzz")) abort();
    uraPart part[uraMAXPARTS];
    memcpy(part, c.part, sizeof part);
    int npart = c.npart;
    urModel* m = c.model;
    urMemCache* mc = c.memcache; /* the session's inflated bags stay too */
    ura_last_free(&c);
    memset(&c, 0, sizeof c);
    c.memcache = mc;
    c.st = st0;
    c.inspect = ura_inspect_cell;
    memcpy(c.part, part, sizeof part);
    c.npart = npart;
    c.model = m;
  }
  c.out = c.msg = null;
  c.dry = 1;
}

int LLVMFuzzerInitialize(int* argc, char*** argv) {
  null = fopen("/dev/null", "w");
  return null ? 0 : 1;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  fresh();
  FILE* f = fmemopen((void*)data, size, "r");
  if (!f) return 0;
  ura_run_stream(&c, f, "fuzz");
  fclose(f);
  /* a failure leaves one message line */
  if (strlen(c.err) >= sizeof c.err) abort();
  return 0;
}
