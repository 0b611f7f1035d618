/* dropped.c: the settings a case or a reset lets go. Before 'case B' replaces the state, the
 * settings the user changed from what the live case starts with (every parameter of the table,
 * the injury settings, the model parameters set with 'set') and that the new state does not keep
 * are listed in one note line, with their values, so that nothing changes silently; undo brings
 * them back. */
#include <stdio.h>
#include <string.h>

#include "case.h"


/* the text of setting p (a table parameter, or injury setting inj) in state s */
static void value_in(uraCtx* c, const uraState* s, const uraParam* p, int inj, char* buf,
                     size_t n) {
  uraState keep;
  memcpy(&keep, &c->st, sizeof keep);
  memcpy(&c->st, s, sizeof *s);
  if (p)
    ura_param_format(c, p, buf, n);
  else
    ura_injury_line(c, inj, buf, n, 1);
  memcpy(&c->st, &keep, sizeof keep);
}

/* one item "name value" at buf + *k, separated by ", " */
static void item(char* buf, size_t n, size_t* k, const char* name, const char* val) {
  if (*k < n) *k += (size_t)snprintf(buf + *k, n - *k, "%s%s %s", *k ? ", " : "", name, val);
}

/* an override's value in s by name, or NULL when s has none */
static const double* override_in(const uraState* s, const char* name) {
  for (int i = 0; i < s->nov; i++)
    if (!strcmp(s->ov_name[i], name)) return &s->ov_val[i];
  return NULL;
}

size_t ura_dropped(uraCtx* c, const uraState* now, const uraState* base, const uraState* next,
                   char* buf, size_t n) {
  size_t k = 0;
  buf[0] = 0;
  char a[1024], b[1024], z[1024], show[1100];
  for (const uraParam* p = ura_params; p->name; p++) {
    if (p->kind == uraP_CASE) continue;
    value_in(c, now, p, -1, a, sizeof a);
    value_in(c, base, p, -1, z, sizeof z);
    value_in(c, next, p, -1, b, sizeof b);
    if (strcmp(a, z) && strcmp(a, b)) {
      snprintf(show, sizeof show, "%s%s%s", a, *p->unit && strcmp(a, "auto") ? " " : "",
               strcmp(a, "auto") ? p->unit : "");
      item(buf, n, &k, p->name, show);
    }
  }
  const char* name;
  for (int i = 0; ur_injury_param_info(i, &name, NULL, NULL) == 0; i++) {
    value_in(c, now, NULL, i, a, sizeof a);
    value_in(c, base, NULL, i, z, sizeof z);
    value_in(c, next, NULL, i, b, sizeof b);
    if (strcmp(a, z) && strcmp(a, b)) item(buf, n, &k, name, a);
  }
  for (int i = 0; i < now->nov; i++) {
    if (!now->ov_user[i]) continue;
    const double* v = override_in(next, now->ov_name[i]);
    if (v && *v == now->ov_val[i]) continue;
    char val[96];
    ura_model_value_brief(c, now->ov_name[i], now->ov_val[i], val, sizeof val);
    item(buf, n, &k, now->ov_name[i], val);
  }
  if (k >= n && n > 4) strcpy(buf + n - 4, "...");
  return k;
}
