/* model.c: the model set (parts of model-language text), its parameters, the compiled model and
 * the settled stance, rebuilt lazily when something changes; the model command */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "case.h"
#include "builtin.h"


#define SETTLE_SECONDS 1.0         /* settling of the stance, s (it is still within 0.1 mm) */
#define BALANCE_ITERS  2           /* muscle-tone balancing of the upright posture */
#define MAXMODELFILE   (16L << 20) /* largest model file, bytes */
#define INFLATE_NOTE_NODES                                                                         \
  380 /* a bag inflated for a run gets a note from this many nodes
                                      (mesh 8: some seconds) */


/* built-in order: the person, the drone, its airbags, the simulation options */
static const char* const builtin_order[] = {"human", "ra3", "airbags", "sim", NULL};

static void parts_free(uraPart* p, int n) {
  for (int i = 0; i < n; i++) free(p[i].text);
}

/* the model parts change (or go): the live model, the kept ones and the grids computed with them
   are of the old parts. New parts keep the settled models as stance donors only: their keys name
   the old parts, so none becomes live again, but a new model whose person is byte for byte a
   kept one's takes its stance (a new drone or airbag file settles nothing; modelcache.c) */
static void parts_changed(uraCtx* c, int keep_stances) {
  if (keep_stances) {
    ura_mcache_park(c);
  } else {
    ura_model_stale(c);
    ura_mcache_flush(c);
  }
  ura_recall_flush(c);
  c->parts_gen++;
}

void ura_models_free(uraCtx* c) {
  ura_undo_free(c);
  parts_changed(c, 0);
  parts_free(c->part, c->npart);
  c->npart = 0;
  ura_trace_free(c);
  ur_memcache_free(c->memcache);
  c->memcache = NULL;
}

/* compile parts with the state's parameter overrides (messages name built-in parts by name, a
   loaded part by its file) */
static urModel* compile(uraCtx* c, const uraPart* part, int n, const uraState* st, char* err,
                        int errlen) {
  urModelSource src[uraMAXPARTS];
  urOverride ov[uraMAXOV];
  for (int i = 0; i < n; i++) {
    src[i].text = part[i].text;
    src[i].file = !strcmp(part[i].origin, "built-in") ? part[i].name : part[i].origin;
    src[i].line = part[i].line;
  }
  for (int i = 0; i < st->nov; i++) {
    ov[i].name = st->ov_name[i];
    ov[i].value = st->ov_val[i];
  }
  /* the session's inflated bags: a set that leaves a bag's spec as it was inflates nothing (no
     memory for the cache: each bag inflated afresh) */
  if (!c->memcache) c->memcache = ur_memcache_new();
  ur_memcache_set_threads(c->memcache, (int)st->threads); /* the inflations': the same bits */
  urModel* m =
      ur_model_parse_cache(src, n, ov, st->nov, ura_interrupt_flag(), c->memcache, err, errlen);
  if (m) m->opt.stop = ura_interrupt_flag(); /* Ctrl-C stops its runs at the next step */
  return m;
}

/* a compiled model of these parts must run impacts (ur_impact_check) and compile in every case
   preset with the user's overrides of st, so that 'case', 'reset' and a saved session's replay
   cannot meet a model that fails; 0, or -1 with what broke in err (m: the parts compiled with
   st's overrides) */
static int fits(uraCtx* c, const uraPart* part, int n, const uraState* st, const urModel* m,
                char* err, size_t errlen) {
  char e[300];
  if (ur_impact_check(m, e, sizeof e)) {
    snprintf(err, errlen, "%s", e);
    return -1;
  }
  /* every preset of the candidate model, the live case first: a failure there is not one of
     another case */
  const urPreset* order[m->npreset > 0 ? m->npreset : 1];
  int no = 0;
  for (int k = 0; k < m->npreset; k++) {
    if (!strcasecmp(m->preset[k].name, st->casename)) order[no++] = m->preset + k;
  }
  for (int k = 0; k < m->npreset; k++) {
    if (strcasecmp(m->preset[k].name, st->casename)) order[no++] = m->preset + k;
  }
  for (int k = 0; k < no; k++) {
    uraState ns;
    if (ura_preset_state(c, order[k], m, &ns)) return -1;
    for (int i = 0; i < st->nov; i++) {
      if (!st->ov_user[i]) continue;
      int at = -1;
      for (int j = 0; j < ns.nov; j++)
        if (!strcmp(ns.ov_name[j], st->ov_name[i])) at = j;
      if (at < 0 && ns.nov == uraMAXOV) continue;
      if (at < 0) at = ns.nov++;
      memcpy(ns.ov_name[at], st->ov_name[i], urNAMELEN);
      ns.ov_val[at] = st->ov_val[i];
      ns.ov_user[at] = 1;
    }
    urModel* mk = compile(c, part, n, &ns, e, sizeof e);
    int bad = !mk || ur_impact_check(mk, e, sizeof e);
    ur_model_free(mk);
    if (bad) {
      if (k)
        snprintf(err, errlen, "in case %s: %s", order[k]->name, e);
      else
        snprintf(err, errlen, "%s", e);
      return -1;
    }
  }
  return 0;
}

/* add or replace the parts of a text in the candidate set np[0..*nn) (its texts owned) */
static int parts_add(uraCtx* c, uraPart* np, int* nn, const char* text, const char* file,
                     const char* origin) {
  urModelPart sp[uraMAXPARTS];
  char err[300];
  int n = ur_model_split(text, file, sp, uraMAXPARTS, err, sizeof err);
  if (n < 0) return ura_fail(c, "%s", err);
  if (n > uraMAXPARTS) return ura_fail(c, "%s: more than %d parts", file, uraMAXPARTS);
  if (n == 0) return ura_fail(c, "%s: no model text", file);
  char group[uraMAXPARTS * urNAMELEN];
  size_t gl = 0;
  group[0] = 0;
  for (int k = 0; k < n; k++) { /* at most uraMAXPARTS names of urNAMELEN - 1 and a blank */
    gl += (size_t)snprintf(group + gl, sizeof group - gl, "%s%.*s", k ? " " : "",
                           (int)urNAMELEN - 1, sp[k].name);
    if (gl >= sizeof group) gl = sizeof group - 1; /* cannot happen (the bound above); kept in */
  }
  for (int k = 0; k < n; k++) {
    int at = -1;
    for (int i = 0; i < *nn; i++) {
      if (!strcmp(np[i].name, sp[k].name)) at = i;
    }
    if (at < 0) {
      if (*nn == uraMAXPARTS) {
        return ura_fail(c, "%s: too many parts (at most %d)", file, uraMAXPARTS);
      }
      at = (*nn)++;
      np[at].text = NULL;
    }
    char* t = strndup(sp[k].text, sp[k].len);
    if (!t) return ura_fail(c, "%s: out of memory", file);
    snprintf(np[at].name, sizeof np[at].name, "%.*s", (int)sizeof np[at].name - 1, sp[k].name);
    free(np[at].text);
    np[at].text = t;
    snprintf(np[at].origin, sizeof np[at].origin, "%s", origin);
    memcpy(np[at].group, group, gl + 1);
    np[at].line = sp[k].line;
  }
  return 0;
}

/* the candidate set replaces the model set if it compiles with the current overrides and, when
   file is given (the parts loaded from file, which failures name), fits; a drop need not fit (a
   model may be rebuilt a part at a time: 'model drop ra3' before loading another drone); np is
   consumed either way; on error nothing changes */
static int parts_commit(uraCtx* c, uraPart* np, int nn, const char* file) {
  char err[300], why[400];
  urModel* m = compile(c, np, nn, &c->st, err, sizeof err);
  int bad = !m, in_file = 0;
  if (!m) {
    /* an error in the file names its line; one elsewhere is the file's doing all the same */
    size_t fl = file ? strlen(file) : 0;
    in_file = !file || (!strncmp(err, file, fl) && err[fl] == ':');
    snprintf(why, sizeof why, "%s", err);
  } else if (file) {
    bad = fits(c, np, nn, &c->st, m, why, sizeof why);
  }
  if (bad) {
    ur_model_free(m);
    int first = -1;
    for (int i = 0; file && i < nn && first < 0; i++)
      if (!strcmp(np[i].origin, file)) first = i;
    if (ura_interrupted()) {
      ura_fail(c, "model load: interrupted (Ctrl-C) while compiling '%s'; the model is unchanged",
               file ? file : "model");
    } else if (in_file || first < 0) {
      ura_fail(c, "%s", why);
    } else {
      ura_fail(c,
               "model load: %s:%d: part '%s' does not fit the model: %s; the model is "
               "unchanged",
               file, np[first].line, np[first].name, why);
    }
    parts_free(np, nn);
    return -1;
  }
  parts_changed(c, 1);
  parts_free(c->part, c->npart);
  memcpy(c->part, np, sizeof(uraPart) * nn);
  c->npart = nn;
  c->model = m;
  return 0;
}

/* add or replace the parts of a text; on error nothing changes */
static int parts_merge(uraCtx* c, const char* text, const char* file, const char* origin) {
  uraPart np[uraMAXPARTS];
  int nn = c->npart;
  memcpy(np, c->part, sizeof(uraPart) * nn);
  for (int i = 0; i < nn; i++) {
    np[i].text = strdup(c->part[i].text);
    if (!np[i].text) {
      parts_free(np, i);
      return ura_fail(c, "%s: out of memory", file);
    }
  }
  if (parts_add(c, np, &nn, text, file, origin)) {
    parts_free(np, nn);
    return -1;
  }
  return parts_commit(c, np, nn, file);
}

/* the built-in parts in order, compiled once */
int ura_models_init(uraCtx* c) {
  uraPart np[uraMAXPARTS];
  int nn = 0;
  for (int i = 0; builtin_order[i]; i++) {
    const char* t = ura_builtin_text(builtin_order[i]);
    if (t && parts_add(c, np, &nn, t, builtin_order[i], "built-in")) {
      parts_free(np, nn);
      return -1;
    }
  }
  return parts_commit(c, np, nn, NULL);
}

const urModel* ura_model(uraCtx* c) {
  if (c->model) return c->model;
  char err[300];
  c->model = compile(c, c->part, c->npart, &c->st, err, sizeof err);
  if (!c->model) ura_fail(c, "model: %s", err);
  return c->model;
}

/* what the stance was settled with, for its failures: " with thorax_k = 1e+06 N/m (set)", the
   model parameters set by the user or drawn by montecarlo, or " with the model's own
   parameters" */
static void params_set(uraCtx* c, char* buf, size_t n) {
  size_t k = 0;
  buf[0] = 0;
  for (int i = 0; i < c->st.nov && k < n; i++) {
    if (!c->st.ov_user[i]) continue;
    char v[80];
    ura_model_value_brief(c, c->st.ov_name[i], c->st.ov_val[i], v, sizeof v);
    k += (size_t)snprintf(buf + k, n - k, "%s%s = %s", k ? ", " : " with ", c->st.ov_name[i], v);
  }
  if (k && k < n) snprintf(buf + k, n - k, " (set)");
  if (!k) snprintf(buf, n, " with the model's own parameters");
}

/* a note, once, on a set-up whose impacts may start with the drone in the person: a person
   ellipsoid the drone can touch reaches above the head top, below which the drone never starts */
static void setup_note(uraCtx* c) {
  const urImpactSetup* s = &c->setup;
  char note[sizeof c->noted];
  if (!(s->overlap > 1e-6) || s->overlap_geom < 0 || c->mute) return;
  snprintf(note, sizeof note,
           "model: note: ellipsoid '%s' of the person reaches %.3g m above the top of the head "
           "(role head=); a drone started R_max above the head top may already overlap it",
           c->model->geom[s->overlap_geom].name, s->overlap);
  if (!strcmp(note, c->noted)) return;
  snprintf(c->noted, sizeof c->noted, "%s", note);
  fprintf(c->msg, "%s\n", note);
}

/* the live model's membrane bags inflated (ur_model_inflate), each once, when something first
   needs the inflated state: a note first for a bag that takes long and is not in the session's
   cache; Ctrl-C stops it (the model stays compiled, uninflated, for the next try) */
int ura_model_inflate(uraCtx* c) {
  if (!ura_model(c)) return -1;
  urModel* m = c->model;
  for (int i = 0; m->nraw && i < m->nbag; i++) {
    const urAirbag* b = m->bag + i;
    if (b->type != urBAG_MEMBRANE || b->inflated) continue;
    if (!c->mute && b->mem->nn >= INFLATE_NOTE_NODES && !ur_memcache_has(c->memcache, &b->mspec)) {
      fprintf(c->msg, "inflating %s (mesh %d, %d nodes) ...\n", b->name, b->mspec.mesh, b->mem->nn);
      fflush(c->msg);
    }
    char err[300];
    if (ur_model_inflate_bag(m, i, err, sizeof err)) {
      if (ura_interrupted())
        return ura_fail(c, "interrupted (Ctrl-C) while inflating %s; it inflates at the next run",
                        b->name);
      return ura_fail(c, "model: %s", err);
    }
  }
  return 0;
}

const urImpactSetup* ura_setup(uraCtx* c) {
  if (c->have_setup) return &c->setup;
  if (ura_dry(c, "simulation")) return NULL;
  if (ura_model_inflate(c)) return NULL;

  /* balance and settle, or take both from a kept model with the same person (modelcache.c) */
  const urImpactSetup* donors[uraMODELCACHE];
  int nd = ura_mcache_setups(c, donors, uraMODELCACHE);
  int rc = ur_impact_prepare(&c->setup, c->model, SETTLE_SECONDS, BALANCE_ITERS, donors, nd);
  char with[400];
  if (rc) params_set(c, with, sizeof with);
  if (rc == -1) {
    if (ura_interrupted())
      ura_fail(c, "interrupted (Ctrl-C) while settling the standing posture");
    else
      ura_fail(c, "model: the standing posture cannot be balanced (it falls)%s", with);
  } else if (rc) {
    if (ura_interrupted())
      ura_fail(c, "interrupted (Ctrl-C) while settling the stance");
    else
      ura_fail(c, "model: %s%s", c->setup.err, with);
  }
  if (rc) {
    /* the balancing shifts neutral positions in the model: compile afresh next time */
    ur_impact_free(&c->setup);
    ura_model_stale(c);
    return NULL;
  }
  c->have_setup = 1;
  setup_note(c);
  return &c->setup;
}

void ura_model_value_brief(uraCtx* c, const char* name, double v, char* buf, size_t n) {
  int k = ura_model_param_find(c, name);
  const char* u = k >= 0 ? c->model->param[k].unit : "";
  snprintf(buf, n, "%g%s%s", v, *u ? " " : "", u);
}

void ura_param_range_text(uraCtx* c, const urParam* p, char* buf, size_t n) {
  char lo[64], hi[64];
  if (isinf(p->lo) && isinf(p->hi)) {
    snprintf(buf, n, "any number");
    return;
  }
  ura_num_shortest(lo, sizeof lo, p->lo);
  ura_num_shortest(hi, sizeof hi, p->hi);
  snprintf(buf, n, "%s to %s %s%s%s", lo, hi, *p->unit ? p->unit : "(no unit)", *p->why ? ": " : "",
           p->why);
}

int ura_model_param_find(uraCtx* c, const char* name) {
  const urModel* m = ura_model(c);
  return m ? ur_name_param(m, name) : -1;
}

int ura_model_state(uraCtx* c, const uraState* ns, const char* who) {
  /* the same overrides: the same model, and its settled stance stays valid; overrides seen
     earlier: the model kept for them, balanced and settled (modelcache.c) */
  uraModelKey now, want;
  ura_model_key(c, &c->st, &now);
  ura_model_key(c, ns, &want);
  if ((c->model && ura_model_key_same(&now, &want)) || ura_mcache_take(c, ns)) {
    c->st = *ns;
    return 0;
  }

  /* otherwise the model must compile with them, and run impacts, before anything changes */
  char err[300];
  urModel* m = compile(c, c->part, c->npart, ns, err, sizeof err);
  if (m && ur_impact_check(m, err, sizeof err)) {
    ur_model_free(m);
    m = NULL;
  }
  if (!m && ura_interrupted()) return ura_fail(c, "%s: interrupted (Ctrl-C)", who);
  if (!m) return ura_fail(c, "%s: refused, the model does not accept it: model: %s", who, err);
  ura_mcache_park(c);
  c->model = m;
  c->st = *ns;
  return 0;
}

int ura_model_param_set(uraCtx* c, const char* name, const char* value, const char* unit,
                        int user) {
  double v, f = 1;
  if (ura_parse_number(value, &v)) {
    return ura_fail(c,
                    "set %s: '%s' is not a number; accepted: a number, optionally with a "
                    "unit (uasimpact-model(5))",
                    name, value);
  }
  char si[urNAMELEN];
  /* km/h and kt for a parameter in m/s (the model language's units have no hour) */
  int speed = unit && strcmp(unit, "m/s") && !ura_speed_unit(unit, &f);
  if (speed) snprintf(si, sizeof si, "m/s");
  if (unit && !speed && ur_unit_parse(unit, &f, si, sizeof si)) {
    return ura_fail(c,
                    "set %s: unknown unit '%s'; accepted: the units of uasimpact-model(5) "
                    "(m mm cm kg g s ms N kN Pa kPa MPa GPa atm bar deg rad J L), or several "
                    "joined by * and / (N*m/rad); speeds also km/h and kt",
                    name, unit);
  }
  int k = ura_model_param_find(c, name);
  const char* want = k >= 0 && unit ? c->model->param[k].unit : "";
  if (unit && *want && strcmp(si, want)) {
    return ura_fail(c,
                    "set %s: the unit '%s' is in %s, not %s; accepted: a unit of %s (as in "
                    "its param line)",
                    name, unit, *si ? si : "no unit", want, want);
  }
  v *= f;
  if (k >= 0 && !ur_param_accepts(&c->model->param[k], v)) {
    char range[400];
    const char* u = unit ? unit : c->model->param[k].unit;
    ura_param_range_text(c, &c->model->param[k], range, sizeof range);
    return ura_fail(c, "set %s: %s%s%s is out of range; accepted: %s", name, value, *u ? " " : "",
                    u, range);
  }

  /* the new override list */
  uraState ns = c->st;
  int at = -1;
  for (int i = 0; i < ns.nov; i++) {
    if (!strcmp(ns.ov_name[i], name)) at = i;
  }
  if (at < 0) {
    if (ns.nov == uraMAXOV) return ura_fail(c, "set %s: too many model parameters set", name);
    at = ns.nov++;
    snprintf(ns.ov_name[at], urNAMELEN, "%s", name);
  }
  ns.ov_val[at] = v;
  ns.ov_user[at] = user;
  char who[urNAMELEN + 8];
  snprintf(who, sizeof who, "set %s", name);

  /* a value the model takes only while the element that reads it is disabled (an airbag's
     pressure in case B) is refused as well: it must hold in every case */
  char err[400];
  const urModel* live = ura_model(c);
  if (user && live && fits(c, c->part, c->npart, &ns, live, err, sizeof err)) {
    if (ura_interrupted()) return ura_fail(c, "%s: interrupted (Ctrl-C)", who);
    return ura_fail(c, "%s: refused, the model does not accept it: model: %s", who, err);
  }
  return ura_model_state(c, &ns, who);
}

int ura_model_param_from(const urModel* m, const urParam* p, char* buf, size_t n) {
  buf[0] = 0;
  if (p->from < 0 || p->from >= m->nparam) return -1;
  if (p->from_f == 1)
    snprintf(buf, n, "$%s", m->param[p->from].name);
  else
    snprintf(buf, n, "$%s x %g", m->param[p->from].name, p->from_f);
  return 0;
}

/* ---- the model command ---- */

/* the model set as text, each part ending in a newline; headers name each part's origin */
static void write_parts(const uraCtx* c, FILE* f, int headers) {
  for (int i = 0; i < c->npart; i++) {
    if (headers) fprintf(f, "# ---- part %s (%s) ----\n", c->part[i].name, c->part[i].origin);
    fputs(c->part[i].text, f);
    size_t n = strlen(c->part[i].text);
    if (n && c->part[i].text[n - 1] != '\n') fputc('\n', f);
  }
}

/* after a load, the live case's parameters as the loaded text's preset of that case sets them:
   the values the old preset set go, the user's stay (a model saved with its case changed gives
   that case; a case the new text has no preset of keeps what it had) */
static int case_again(uraCtx* c) {
  const urModel* m = ura_model(c);
  const urPreset* pr = NULL;
  for (int i = 0; m && i < m->npreset; i++) {
    if (!strcasecmp(m->preset[i].name, c->st.casename)) pr = m->preset + i;
  }
  if (!pr) return 0;
  uraState ns = c->st;
  ns.nov = 0;
  for (int i = 0; i < c->st.nov; i++) {
    if (!c->st.ov_user[i]) continue;
    memcpy(ns.ov_name[ns.nov], c->st.ov_name[i], urNAMELEN);
    ns.ov_val[ns.nov] = c->st.ov_val[i];
    ns.ov_user[ns.nov++] = 1;
  }
  for (int k = 0; k < pr->n && ns.nov < uraMAXOV; k++) {
    int user = 0;
    for (int i = 0; i < ns.nov; i++) user |= !strcmp(ns.ov_name[i], pr->key[k]);
    if (pr->param[k] < 0 || user) continue;
    snprintf(ns.ov_name[ns.nov], urNAMELEN, "%s", pr->key[k]);
    ns.ov_val[ns.nov] = pr->value[k];
    ns.ov_user[ns.nov++] = 0;
  }
  return ura_model_state(c, &ns, "model load");
}

static int model_load(uraCtx* c, const char* path) {
  if (ura_dry(c, "model load")) return -1;
  if (ura_word_inert(path)) {
    return ura_fail(c,
                    "model load: cannot use '%s': the name holds a control character, or a "
                    "single quote with a double quote, $, backquote, backslash or !; accepted: "
                    "a file name that save session can write back as one quoted word that "
                    "neither uasimpact nor a shell expands",
                    path);
  }
  /* in a script or session file the file's own folder first (it replays from anywhere), then
     the current folder, then the installed example models (model load quad.urm); only read */
  char found[4096];
  FILE* f = NULL;
  struct stat sb;
  if (c->srcdir && path[0] != '/' && strcmp(c->srcdir, ".")) {
    int w = snprintf(found, sizeof found, "%s/%s", c->srcdir, path);
    if (w > 0 && (size_t)w < sizeof found && !ura_word_inert(found) && !stat(found, &sb) &&
        S_ISREG(sb.st_mode))
      f = fopen(found, "r"); /* a name save session can write back, as the one typed */
  }
  if (!f) f = ura_data_open(path, found, sizeof found);
  if (!f && ura_interrupted()) {
    return ura_fail(c, "model load: interrupted (Ctrl-C) while opening '%s'", path);
  }
  if (!f) return ura_fail(c, "model load: cannot open '%s': %s", path, strerror(errno));
  path = found;
  ura_input_seen(c, f, path); /* a shard's part may not replace it */

  /* the whole text, bounded (a device never ends), read errors named */
  char* text = NULL;
  size_t len = 0;
  FILE* mem = open_memstream(&text, &len);
  if (!mem) {
    fclose(f);
    return ura_fail(c, "model load: out of memory");
  }
  char buf[4096];
  size_t k;
  long total = 0;
  int nul = 0;
  while (!nul && total <= MAXMODELFILE && !ura_interrupted() &&
         (k = fread(buf, 1, sizeof buf, f)) > 0) {
    fwrite(buf, 1, k, mem);
    total += (long)k;
    nul = memchr(buf, 0, k) != NULL;
  }
  int e = errno, rerr = ferror(f);
  fclose(f);
  fclose(mem);
  if (ura_interrupted()) {
    free(text);
    return ura_fail(c,
                    "model load: interrupted (Ctrl-C) while reading '%s'; the model is "
                    "unchanged",
                    path);
  }
  const char* why = nul                    ? "it contains NUL bytes"
                    : rerr                 ? strerror(e)
                    : total > MAXMODELFILE ? "larger than 16 MiB"
                                           : NULL;
  if (why) {
    free(text);
    return ura_fail(c,
                    "model load: cannot use '%s': %s; accepted: a model text file "
                    "(uasimpact-model(5))",
                    path, why);
  }
  int rc = parts_merge(c, text, path, path);
  free(text);
  return rc ? rc : case_again(c);
}

/* model drop PART: the part leaves the model set (e.g. the RA3 and its airbags before another
   drone is loaded); the overrides of parameters that no part defines any more go with it */
static int model_drop(uraCtx* c, const char* name) {
  int at = -1;
  for (int i = 0; i < c->npart; i++) {
    if (!strcmp(c->part[i].name, name)) at = i;
  }
  if (at < 0) return ura_fail(c, "model drop: no part '%s'; 'model parts' lists them", name);
  uraPart np[uraMAXPARTS] = {0}; /* zeroed: -O2 with sanitizers cannot see nn bound it */
  int nn = 0;
  for (int i = 0; i < c->npart; i++) {
    if (i == at) continue;
    np[nn] = c->part[i];
    np[nn].text = strdup(c->part[i].text);
    if (!np[nn++].text) {
      parts_free(np, nn);
      return ura_fail(c, "model drop: out of memory");
    }
  }

  /* the parameters the rest defines (compiled without overrides), then its overrides */
  uraState ns = c->st;
  ns.nov = 0;
  char err[300];
  urModel* m = compile(c, np, nn, &ns, err, sizeof err);
  if (!m) {
    parts_free(np, nn);
    return ura_fail(c, "model drop %s: refused, the other parts do not compile alone: %s", name,
                    err);
  }
  for (int i = 0; i < c->st.nov; i++) {
    if (ur_name_param(m, c->st.ov_name[i]) < 0) continue;
    snprintf(ns.ov_name[ns.nov], urNAMELEN, "%s", c->st.ov_name[i]);
    ns.ov_val[ns.nov] = c->st.ov_val[i];
    ns.ov_user[ns.nov++] = c->st.ov_user[i];
  }
  ur_model_free(m);
  uraState keep = c->st;
  c->st = ns;
  if (parts_commit(c, np, nn, NULL)) {
    c->st = keep;
    return -1;
  }
  return 0;
}

/* the name a file written in folder at gives a model file: relative to that folder when the
   file is in it or below, else absolute, so the session replays from any current folder (a
   name it cannot resolve, or one the reader would not take back, stays as loaded) */
const char* ura_model_origin_at(const char* at, const char* origin, char* buf, size_t n) {
  char dir[PATH_MAX], file[PATH_MAX];
  if (!at || !realpath(at, dir) || !realpath(origin, file)) return origin;
  size_t k = strlen(dir);
  const char* name = file;
  if (!strncmp(file, dir, k) && file[k] == '/') name = file + k + 1;
  if (!strcmp(dir, "/")) name = file + 1;
  if (ura_word_inert(name) || strlen(name) >= n) return origin;
  return memcpy(buf, name, strlen(name) + 1);
}

/* is there a part of that name in the model set */
static int has_part(const uraCtx* c, const char* name, size_t n) {
  for (int i = 0; i < c->npart; i++) {
    if (strlen(c->part[i].name) == n && !strncmp(c->part[i].name, name, n)) return 1;
  }
  return 0;
}

/* after the load of a file: its parts that are no longer in the model set (dropped since, and
   not brought back by another load), dropped in turn, the last first (later parts may use
   earlier ones), so that the replay holds what the session held (a file of two drones' parts
   loaded whole would not compile beside a second drone) */
static void write_drops(const uraCtx* c, const char* group, FILE* f) {
  const char* w[uraMAXPARTS];
  size_t len[uraMAXPARTS];
  int nw = 0;
  for (const char* p = group; *p && nw < uraMAXPARTS;) {
    size_t n = strcspn(p, " ");
    w[nw] = p;
    len[nw++] = n;
    p += n;
    p += strspn(p, " ");
  }
  for (int k = nw - 1; k >= 0; k--) {
    if (has_part(c, w[k], len[k])) continue;
    if (len[k])
      fprintf(f, "model drop %.*s", (int)len[k], w[k]);
    else
      fprintf(f, "model drop ''"); /* the file's unnamed part (text before its first part line) */
    fprintf(f, "   # a part of that file, dropped later\n");
  }
}

/* the model parts of a session: the built-in parts it lacks dropped, the loaded ones loaded (and
   the parts of a loaded file that were dropped since, dropped again) */
void ura_model_write_parts(uraCtx* c, FILE* f) {
  int nb = 0;
  while (builtin_order[nb]) nb++;
  for (int b = nb - 1; b >= 0; b--) { /* later parts may use earlier ones: last first */
    int have = 0;
    for (int i = 0; i < c->npart; i++) {
      have |= !strcmp(c->part[i].name, builtin_order[b]) && !strcmp(c->part[i].origin, "built-in");
    }
    if (!have) fprintf(f, "model drop %s\n", builtin_order[b]);
  }
  /* one load per run of parts from the same file (a model save'd set is one file of four
     parts: loading it once loads them all) */
  for (int i = 0; i < c->npart; i++) {
    if (!strcmp(c->part[i].origin, "built-in")) continue;
    int n = 1;
    while (i + n < c->npart && !strcmp(c->part[i + n].origin, c->part[i].origin)) n++;
    char name[PATH_MAX];
    fprintf(f, "model load ");
    ura_put_word(f, ura_model_origin_at(c->savedir, c->part[i].origin, name, sizeof name));
    fprintf(f, "   # part%s %s", n > 1 ? "s" : "", c->part[i].name);
    for (int k = 1; k < n; k++) fprintf(f, ", %s", c->part[i + k].name);
    fputc('\n', f);
    write_drops(c, c->part[i].group, f);
    i += n - 1;
  }
}

/* parameters of the model (those whose names start with prefix): name, SI value, unit, and who
   set it */
static int model_params(uraCtx* c, const char* prefix) {
  static const char* const cols[] = {"name", "value", "unit", "set_by"};
  const urModel* m = ura_model(c);
  if (!m) return -1;
  int found = 0;
  /* in format json one table (name, value, unit, set_by), else aligned lines */
  uraTable* t = c->st.format == uraFMT_JSON ? ura_table_new(4, cols) : NULL;
  for (int i = 0; i < m->nparam; i++) {
    if (strncmp(m->param[i].name, prefix, strlen(prefix))) continue;
    found++;
    char from[2 * urNAMELEN], follows[2 * urNAMELEN + 8];
    const char* who = "model";
    if (!ura_model_param_from(m, &m->param[i], from, sizeof from)) {
      snprintf(follows, sizeof follows, "model: %s", from); /* it follows another */
      who = follows;
    }
    for (int k = 0; k < c->st.nov; k++) {
      if (!strcmp(c->st.ov_name[k], m->param[i].name)) who = c->st.ov_user[k] ? "set" : "case";
    }
    const char* u = m->param[i].unit;
    if (t) {
      ura_table_cell(t, "%s", m->param[i].name);
      ura_table_cell(t, "%.10g", m->param[i].value);
      ura_table_cell(t, "%s", u);
      ura_table_cell(t, "%s", who);
    } else {
      char val[64]; /* as show prints it; csv as before */
      if (c->st.format == uraFMT_CSV)
        snprintf(val, sizeof val, "%.10g", m->param[i].value);
      else
        ura_num_show(val, sizeof val, m->param[i].value);
      fprintf(c->out, "%-16s %s%s%s  (%s)\n", m->param[i].name, val, *u ? " " : "", u, who);
    }
  }
  if (t && !found) ura_table_free(t);
  if (!found) {
    return ura_fail(c,
                    "model params: no model parameter starts with '%s'; accepted: a prefix of "
                    "the names 'model params' lists",
                    prefix);
  }
  if (!strncmp("bag", prefix, strlen(prefix) < 3 ? strlen(prefix) : 3)) {
    if (ura_model_inflate(c)) { /* 'model params bag' asks for the inflated state */
      if (t) ura_table_free(t);
      return -1;
    }
    ura_bag_derived(c, c->out, t);
  }
  if (!*prefix) ura_model_derived(c, c->out, t);
  if (t) ura_table_print(c, t);
  return 0;
}

void ura_model_derived(uraCtx* c, FILE* f, uraTable* t) {
  const urModel* m = ura_model(c);
  for (const char* s = m ? m->derived : NULL; s && *s;) {
    size_t n = strcspn(s, "\n");
    if (t)
      ura_table_note(t, "derived, %.*s", (int)n, s);
    else
      fprintf(f, "# derived, %.*s\n", (int)n, s);
    s += n + (s[n] == '\n');
  }
}

/* model notes: what the model language noted when it compiled the model set (overrides of
   derived laws, ...) and every value it derived, with its formula and inputs; columns kind
   (note or derived) and text */
static int model_notes(uraCtx* c) {
  static const char* const cols[] = {"kind", "text"};
  const urModel* m = ura_model(c);
  if (!m) return -1;
  uraTable* t = c->st.format == uraFMT_JSON ? ura_table_new(2, cols) : NULL;
  const char* kind[2] = {"note", "derived"};
  const char* text[2] = {m->note, m->derived};
  int any = 0;
  for (int k = 0; k < 2; k++) {
    for (const char* s = text[k]; s && *s;) {
      size_t n = strcspn(s, "\n");
      any++;
      if (t) {
        ura_table_cell(t, "%s", kind[k]);
        ura_table_cell(t, "%.*s", (int)n, s);
      } else {
        fprintf(c->out, "%-8s %.*s\n", kind[k], (int)n, s);
      }
      s += n + (s[n] == '\n');
    }
  }
  if (t) {
    if (!any) ura_table_note(t, "the model set has no notes and derives nothing");
    ura_table_print(c, t);
  } else if (!any) {
    fprintf(c->out, "# the model set has no notes and derives nothing\n");
  }
  return 0;
}

/* the fabric's penalty on each target: its layer's E_oed / h (capped where the step cannot carry
   it) or the bag's kc_alpha */
static void bag_penalties(const urModel* m, const urAirbag* b, FILE* f, uraTable* t) {
  const urMemSpec* s = &b->mem->spec;
  double dk = fmax(m->opt.dt, s->kc_dt), unit = s->rhot / (dk * dk);
  char line[2048];
  int n = snprintf(line, sizeof line, "derived, membrane %s: penalty on", b->name);
  for (int i = 0; i < b->ntarget && n < (int)sizeof line; i++) {
    double kc = ur_bag_penalty(m, b, i);
    const char* g = m->geom[b->target[i]].name;
    if (b->tk[i] > 0 && kc * unit < b->tk[i])
      n +=
          snprintf(line + n, sizeof line - n,
                   " %s %.3g N/m^3 (kc_alpha %.3g; its layer's E_oed/h %.3g, %s),", g, kc * unit,
                   kc, b->tk[i],
                   s->kc_alpha > 1 ? "capped at the bag's kc_alpha" : "more than the step carries");
    else if (b->tk[i] > 0)
      n += snprintf(line + n, sizeof line - n, " %s %.3g N/m^3 (its layer's E_oed/h),", g,
                    kc * unit);
    else
      n += snprintf(line + n, sizeof line - n, " %s %.3g N/m^3 (kc_alpha %.3g),", g, kc * unit, kc);
  }
  if (n < (int)sizeof line)
    snprintf(line + n, sizeof line - n, " supports %.3g N/m^3 (kc_alpha %.3g)", s->kc_alpha * unit,
             s->kc_alpha);
  if (t)
    ura_table_note(t, "%s", line);
  else
    fprintf(f, "# %s\n", line);
}

void ura_bag_derived(uraCtx* c, FILE* f, uraTable* t) {
  const urModel* m = ura_model(c);
  for (int i = 0; m && i < m->nbag; i++) {
    const urAirbag* b = m->bag + i;
    char line[600];
    if (b->type != urBAG_MEMBRANE || !b->mem) {
      snprintf(line, sizeof line,
               "derived, airbag %s: analytic uniform-pressure bag (bag_model analytic: fast, "
               "less faithful; 'set bag_model membrane' for the finite-element bag)",
               b->name);
    } else {
      const urMembrane* mb = b->mem;
      double mass = 0;
      for (int k = 0; k < mb->nn; k++) mass += mb->mass[k];
      int k = snprintf(line, sizeof line,
                       "derived, membrane %s: %d nodes, %d triangles, %d mount nodes, fabric "
                       "%.3g kg",
                       b->name, mb->nn, mb->nt, mb->nfix, mass);
      if (mb->madd > 0)
        k += snprintf(line + k, sizeof line - k,
                      " (%.3g kg of it added by mass scaling, mscale %g, to %d triangles)",
                      mb->madd, mb->spec.mscale, mb->nscaled);
      k += snprintf(line + k, sizeof line - k,
                    "; stable step %.3g us: %d sub-step%s per %.3g us step; ", 1e6 * mb->dt_stable,
                    b->nsub, b->nsub > 1 ? "s" : "", 1e6 * m->opt.dt);
      if (b->inflated)
        k += snprintf(line + k, sizeof line - k,
                      "inflated %.4g L at %.6g Pa (gauge %.4g Pa), largest yarn strain %.3g %%",
                      1e3 * mb->vref, mb->pref, mb->pref - mb->spec.patm, 100 * mb->strain0);
      else
        k += snprintf(line + k, sizeof line - k,
                      "not inflated yet (when a run first needs it; 'show bag' inflates it)");
      if (mb->spec.wrinkle == urMEM_REDUCE && k > 0 && (size_t)k < sizeof line)
        snprintf(line + k, sizeof line - k,
                 "; wrinkling by LAW19's reduction (wrinkle=1: faster, no potential)");
    }
    if (t)
      ura_table_note(t, "%s", line);
    else
      fprintf(f, "# %s\n", line);
    if (b->type == urBAG_MEMBRANE && b->mem) bag_penalties(m, b, f, t);
  }
}

int ura_cmd_model(uraCtx* c, int argc, char** argv) {
  if (argc == 2 && !strcmp(argv[1], "show")) {
    write_parts(c, c->out, 1);
    return 0;
  }
  if (argc <= 3 && !strcmp(argv[1], "params")) return model_params(c, argc == 3 ? argv[2] : "");
  if (argc == 2 && !strcmp(argv[1], "notes")) return model_notes(c);
  if (argc == 3 && !strcmp(argv[1], "save")) return ura_model_save(c, argv[2]);
  if (argc == 3 && !strcmp(argv[1], "load")) return model_load(c, argv[2]);
  if (argc == 3 && !strcmp(argv[1], "drop")) return model_drop(c, argv[2]);
  if (argc == 2 && !strcmp(argv[1], "parts")) {
    static const char* const cols[] = {"part", "origin"};
    uraTable* t = c->st.format == uraFMT_JSON ? ura_table_new(2, cols) : NULL;
    for (int i = 0; i < c->npart; i++) {
      if (t) {
        ura_table_cell(t, "%s", c->part[i].name);
        ura_table_cell(t, "%s", c->part[i].origin);
      } else {
        fprintf(c->out, "%-12s %s\n", c->part[i].name, c->part[i].origin);
      }
    }
    if (t) ura_table_print(c, t);
    return 0;
  }
  return ura_fail(c,
                  "model: usage: model show|params [PREFIX]|parts|notes|save FILE|load FILE|"
                  "drop PART");
}

void ura_trace_free(uraCtx* c) {
  for (int k = uraTRACE_NDERIVED; k < c->trace.nsig; k++) free(c->trace.names[k]);
  free(c->trace.t);
  free(c->trace.v);
  free(c->trace.names);
  free(c->trace.units);
  memset(&c->trace, 0, sizeof c->trace);
}

int ura_trace_find(const uraTrace* tr, const char* name) {
  for (int k = 0; tr && tr->names && k < tr->nsig; k++) {
    if (tr->names[k] && !strcmp(tr->names[k], name)) return k;
  }
  return -1;
}
