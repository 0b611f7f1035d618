/* test_parts.h: a workbench context's live model parsed anew by the core (its parts with the
 * live overrides, through an inflated-bag cache or none), for the tests that hold the
 * workbench's model beside the core's (test_membrane_cache.c, test_engine_membrane.c). Include
 * after cmocka.h. */
#ifndef UASIMPACT_TEST_PARTS_H
#define UASIMPACT_TEST_PARTS_H

#include "../src/app/ui/ui.h"

static urModel* parse_parts(const uraCtx* c, urMemCache* mc) {
  urModelSource src[uraMAXPARTS];
  urOverride ov[uraMAXOV];
  for (int i = 0; i < c->npart; i++) {
    src[i].text = c->part[i].text;
    src[i].file = c->part[i].name;
    src[i].line = c->part[i].line;
  }
  for (int i = 0; i < c->st.nov; i++) {
    ov[i].name = c->st.ov_name[i];
    ov[i].value = c->st.ov_val[i];
  }
  char err[300];
  urModel* m = ur_model_parse_cache(src, c->npart, ov, c->st.nov, NULL, mc, err, sizeof err);
  if (!m) print_message("parse: %s\n", err);
  assert_non_null(m);
  return m;
}

#endif
