/* modellang.c: parser of the model language (uasimpact-model(5)): statements into builder calls,
 * parameters, units, overrides, enable flags, name resolution, checks with FILE:LINE messages,
 * and the split of a text into parts. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "uasimpact/modellang.h"
#include "modellang_internal.h"

static const KeySpec spec_curve[] = {{"x", K_LIST, urMAXCURVE, 2, 1, NULL},
                                     {"y", K_LIST, urMAXCURVE, 2, 0, NULL},
                                     {"abi", K_VEC, 5, 0, 0, NULL},
                                     NUM("xscale"),
                                     NUM("yscale"),
                                     ENABLE};
static const KeySpec spec_body[] = {
    NAMER("parent"),
    {"joint", K_ENUM, 1, 0, 1, "free|fixed|revolute|universal|spherical|prismatic"},
    VEC3R("pos"),
    QUAT,
    ROT,
    NUMR("mass"),
    VEC3("com"),
    {"inertia", K_VEC, 3, 6, 0, NULL},
    VEC3("axis"),
    VEC3("axis2"),
    NAME("jname"),
    FLAG("gravity"),
    ENABLE};
static const KeySpec spec_restraint[] = {{"dof", K_INT, 1, 0, 1, NULL},
                                         NUM("k"),
                                         NUM("sat"),
                                         NAME("load"),
                                         NAME("unload"),
                                         NUM("c"),
                                         NUM("lo"),
                                         NUM("hi"),
                                         NUM("kstop"),
                                         NUM("cstop"),
                                         NUM("x0"),
                                         NAME("material"),
                                         NAME("section"),
                                         NUM("length"),
                                         FLAG("fracture"),
                                         ENABLE};
static const KeySpec spec_ellipsoid[] = {
    NAMER("body"), VEC3R("pos"),     VEC3R("size"),   QUAT,  ROT,
    NUM("degree"), NAME("material"), NAME("section"), ENABLE};
static const KeySpec spec_material[] = {NUMR("E"),    NUMR("nu"),      NUMR("density"),
                                        NUM("yield"), NUM("ultimate"), NUM("fracture_strain"),
                                        ENABLE};
static const KeySpec spec_section[] = {{"shape", K_ENUM, 1, 0, 1, "tube|plate|solid|shell|box"},
                                       NUM("D"),
                                       NUM("t"),
                                       NUM("b"),
                                       NUM("R"),
                                       NUM("h"),
                                       ENABLE};
static const KeySpec spec_layer[] = {{"on", K_NAMES, MAXLIST, 1, 1, NULL},
                                     NAME("material"),
                                     NAME("law"),
                                     NUM("thickness"),
                                     NUM("bone_k"),
                                     NUM("radius"),
                                     NUM("mu"),
                                     NUM("v_eps"),
                                     ENABLE};
#define LAWTYPE                                                                                    \
  { "type", K_ENUM, 1, 0, 1, "hertz|table|foam" }
static const KeySpec spec_hertz[] = {LAWTYPE,         NUMR("E1"),      NUMR("nu1"), NUM("R1"),
                                     NUMR("E2"),      NUMR("nu2"),     NUM("R2"),   NUM("sy"),
                                     NUM("nu_yield"), FLAG("plastic"), FRICTION,    ENABLE};
static const KeySpec spec_table[] = {LAWTYPE, NAMER("load"), NAME("unload"), FRICTION, ENABLE};
static const KeySpec spec_foam[] = {
    LAWTYPE,     NAMER("stress"), NUMR("thickness"),        NUMR("unload_r"), NUMR("unload_p"),
    NUM("lock"), NAME("backing"), NAME("backing_material"), FRICTION,         ENABLE};
static const KeySpec spec_pair[] = {NAMER("a"), NAMER("b"), NAME("law"), ENABLE};
static const KeySpec spec_pairs[] = {
    {"a", K_NAMES, MAXLIST, 1, 1, NULL}, {"b", K_NAMES, MAXLIST, 1, 1, NULL}, NAME("law"), ENABLE};
static const KeySpec spec_airbag[] = {NAMER("geom"),
                                      NUMR("p0"),
                                      NUMR("patm"),
                                      NUMR("v0"),
                                      NUMR("gamma"),
                                      NUMR("kappa"),
                                      NUMR("thickness"),
                                      NUM("fabric_k"),
                                      NUM("fabric_c"),
                                      NUM("mu"),
                                      NUM("v_eps"),
                                      {"targets", K_NAMES, urMAXBAGTGT, 1, 1, NULL},
                                      ENABLE,
                                      /* the membrane bag (uasimpact-model(5), BAGS) */
                                      FLAG("membrane"),
                                      QUAT,
                                      ROT,
                                      {"plan", K_ENUM, 1, 0, 0, "ellipse|rect"},
                                      {"pattern", K_ENUM, 1, 0, 0, "shape|flat"},
                                      {"size", K_VEC, 2, 0, 0, NULL},
                                      NUM("depth"),
                                      NUM("top"),
                                      VEC3("mount"),
                                      NUM("mount_r"),
                                      {"mesh", K_INT, 1, 0, 0, NULL},
                                      {"inflate", K_INT, 1, 0, 0, NULL},
                                      {"wrinkle", K_INT, 1, 0, 0, NULL},
                                      {"live", K_INT, 1, 0, 0, NULL},
                                      NUM("e1t"),
                                      NUM("e2t"),
                                      NUM("nu12"),
                                      NUM("g0t"),
                                      NUM("gtt"),
                                      NUM("lock"),
                                      NUM("re"),
                                      NUM("rhot"),
                                      NUM("damp"),
                                      NUM("temp"),
                                      NUM("vent_area"),
                                      NUM("vent_cd"),
                                      NUM("leak"),
                                      NUM("kc_alpha"),
                                      NUM("kc_dt"),
                                      NUM("zeta_c"),
                                      NUM("dt_factor"),
                                      NUM("mscale"),
                                      {"support", K_NAMES, urMAXBAGTGT, 1, 0, NULL}};
static const KeySpec spec_sensor[] = {
    {"type", K_ENUM, 1, 0, 1,
     "accel|jointload|jointpos|jointvel|contact|airbag|bodypos|bodyvel|hinge"},
    NAMER("obj"),
    {"dof", K_INT, 1, 0, 0, NULL},
    VEC3("pos"),
    QUAT,
    ROT,
    ENABLE};

//---------------------------------- driver --------------------------------------------------------

/* one statement */
static int statement(Parser* p, const urlStmt* st) {
  static const struct {
    const char* kw;
    int kind;
  } elem[] = {{"curve", SYM_CURVE},         {"body", SYM_BODY},       {"restraint", -1},
              {"ellipsoid", SYM_ELLIPSOID}, {"law", SYM_LAW},         {"pair", SYM_PAIR},
              {"airbag", SYM_AIRBAG},       {"sensor", SYM_SENSOR},   {"pairs", -1},
              {"material", SYM_MATERIAL},   {"section", SYM_SECTION}, {"layer", SYM_LAYER}};
  const char* kw = url_word(&p->lx, st->word);
  Bound b;
  b.kw = kw;
  b.what = kw;
  b.name = NULL;
  b.line = st->line;

  /* statements without NAME key=value */
  if (!strcmp(kw, "param")) {
    return url_st_param(p, st);
  }
  if (!strcmp(kw, "part")) {
    return url_st_part(p, st);
  }
  if (!strcmp(kw, "preset")) {
    return url_st_preset(p, st);
  }
  if (!strcmp(kw, "role")) {
    if (st->nword > 1 && !strchr(url_word(&p->lx, st->word + 1), '=')) {
      return url_fail(p, st->line, "role takes key=value pairs only (no name)");
    }
    return url_st_role(p, st, &b);
  }
  if (!strcmp(kw, "option")) {
    if (st->nword > 1 && !strchr(url_word(&p->lx, st->word + 1), '=')) {
      return url_fail(p, st->line, "option takes key=value pairs only (no name)");
    }
    return url_st_option(p, st, &b);
  }

  /* element statements: KEYWORD NAME key=value... */
  int e = 0, ne = (int)(sizeof(elem) / sizeof(elem[0]));
  while (e < ne && strcmp(elem[e].kw, kw)) {
    e++;
  }
  if (e == ne) {
    return url_fail(p, st->line, "unknown keyword '%s'; expected one of %s",
                    url_quote(kw, strlen(kw)).s, url_keywords);
  }
  if (st->nword < 2 || strchr(url_word(&p->lx, st->word + 1), '=')) {
    return url_fail(p, st->line, "%s needs a %s before its keys; expected '%s %s key=value ...'",
                    kw, e == 2 ? "BODY" : "NAME", kw, e == 2 ? "BODY" : "NAME");
  }
  b.name = url_word(&p->lx, st->word + 1);
  if (url_checkname(p, b.name, strlen(b.name), st->line, kw)) {
    return -1;
  }

  /* key table (laws by type) */
  const KeySpec* spec;
  int nspec;
  switch (e) {
  case 0:
    spec = spec_curve;
    nspec = NKEY(spec_curve);
    break;
  case 1:
    spec = spec_body;
    nspec = NKEY(spec_body);
    break;
  case 2:
    spec = spec_restraint;
    nspec = NKEY(spec_restraint);
    break;
  case 3:
    spec = spec_ellipsoid;
    nspec = NKEY(spec_ellipsoid);
    break;
  case 5:
    spec = spec_pair;
    nspec = NKEY(spec_pair);
    break;
  case 6:
    spec = spec_airbag;
    nspec = NKEY(spec_airbag);
    break;
  case 7:
    spec = spec_sensor;
    nspec = NKEY(spec_sensor);
    break;
  case 8:
    spec = spec_pairs;
    nspec = NKEY(spec_pairs);
    break;
  case 9:
    spec = spec_material;
    nspec = NKEY(spec_material);
    break;
  case 10:
    spec = spec_section;
    nspec = NKEY(spec_section);
    break;
  case 11:
    spec = spec_layer;
    nspec = NKEY(spec_layer);
    break;
  default: {
    const char* t = NULL;
    for (int w = 2; w < st->nword; w++) {
      const char* s = url_word(&p->lx, st->word + w);
      if (!strncmp(s, "type=", 5)) {
        t = s + 5;
      }
    }
    if (!t || !*t) {
      return url_fail(p, st->line, "law '%s': missing %s 'type'; expected type=hertz|table|foam",
                      b.name, t ? "value for key" : "key");
    }
    if (!strcmp(t, "hertz")) {
      spec = spec_hertz;
      nspec = NKEY(spec_hertz);
      b.what = "law type=hertz";
    } else if (!strcmp(t, "table")) {
      spec = spec_table;
      nspec = NKEY(spec_table);
      b.what = "law type=table";
    } else if (!strcmp(t, "foam")) {
      spec = spec_foam;
      nspec = NKEY(spec_foam);
      b.what = "law type=foam";
    } else {
      return url_fail(p, st->line,
                      "key 'type': unknown value '%s'; expected one of hertz/table/foam",
                      url_quote(t, strlen(t)).s);
    }
  }
  }

  /* bind; a disabled element leaves only its name behind (for messages) */
  int rc = url_bind(p, st, 2, spec, nspec, &b);
  if (rc < 0) {
    return -1;
  }
  if (rc) {
    if (e == 8) {
      return url_pairs_disabled(p, &b, st->line);
    }
    if (elem[e].kind < 0) {
      return 0;
    }
    if (elem[e].kind == SYM_BODY) {
      const Val* vj = url_get(&b, "jname");
      int named = vj->set && url_isident(vj->raw, strlen(vj->raw)) && strlen(vj->raw) < urNAMELEN;
      if (url_declare(p, SYM_JOINT, named ? vj->raw : b.name, st->line, -1, 0)) {
        return -1;
      }
    }
    return url_declare(p, elem[e].kind, b.name, st->line, -1, 0);
  }
  switch (e) {
  case 0: return url_st_curve(p, &b);
  case 1: return url_st_body(p, &b);
  case 2: return url_st_restraint(p, &b);
  case 3: return url_st_ellipsoid(p, &b);
  case 4: return url_st_law(p, &b);
  case 5: return url_st_pair(p, &b);
  case 6: return url_st_airbag(p, &b);
  case 7: return url_st_sensor(p, &b);
  case 9: return url_st_material(p, &b);
  case 10: return url_st_section(p, &b);
  case 11: return url_st_layer(p, &b);
  default: return url_st_pairs(p, &b);
  }
}


/* 1 if some source has a 'param NAME' line (before or after the statement being read) */
int url_param_declared(Parser* p, const char* name) {
  for (int s = 0; s < p->lx.nstmt; s++) {
    const urlStmt* st = p->lx.stmt + s;
    if (st->nword >= 2 && !strcmp(url_word(&p->lx, st->word), "param") &&
        !strcmp(url_word(&p->lx, st->word + 1), name)) {
      return 1;
    }
  }
  return 0;
}


/* a preset's key that names a parameter of a later part (sim.urm's tmax in airbags.urm's
   presets) is bound to it once every statement is read */
static void bind_preset_params(Parser* p) {
  for (int i = 0; i < p->m->npreset; i++) {
    urPreset* pr = p->m->preset + i;
    for (int k = 0; k < pr->n; k++) {
      if (pr->param[k] < 0) pr->param[k] = ur_name_param(p->m, pr->key[k]);
    }
  }
}


/* every override must name a parameter that some source defines, with a finite value */
static int check_overrides(Parser* p) {
  for (int i = 0; i < p->nov; i++) {
    const char* name = p->ov[i].name;
    if (!name) {
      snprintf(p->msg, sizeof(p->msg), "override %d: no parameter name", i + 1);
      return -1;
    }
    if (!isfinite(p->ov[i].value)) {
      snprintf(p->msg, sizeof(p->msg), "override '%s': the value is not a finite number",
               url_quote(name, strlen(name)).s);
      return -1;
    }
    if (!url_param_declared(p, name)) {
      snprintf(p->msg, sizeof(p->msg),
               "override '%s': no model text defines a parameter of "
               "that name; expected a name from 'param NAME VALUE' lines",
               url_quote(name, strlen(name)).s);
      return -1;
    }
  }
  return 0;
}


/* release everything but the model */
static void release(Parser* p) {
  url_free(&p->lx);
  free(p->sym);
  free(p->chain);
  free(p->curve);
  free(p->law);
  free(p->lawback);
  free(p->pval);
  free(p->mat);
  free(p->sec);
  free(p->layer);
  free(p->gmat);
}


urModel* ur_model_parse(const urModelSource* src, int nsrc, const urOverride* ov, int nov,
                        char* err, int errlen) {
  return ur_model_parse_stop(src, nsrc, ov, nov, NULL, err, errlen);
}


urModel* ur_model_parse_stop(const urModelSource* src, int nsrc, const urOverride* ov, int nov,
                             const _Atomic int* stop, char* err, int errlen) {
  return ur_model_parse_cache(src, nsrc, ov, nov, stop, NULL, err, errlen);
}


urModel* ur_model_parse_cache(const urModelSource* src, int nsrc, const urOverride* ov, int nov,
                              const _Atomic int* stop, urMemCache* c, char* err, int errlen) {
  Parser p;
  memset(&p, 0, sizeof(p));
  p.stop = stop;
  p.src = src;
  p.nsrc = nsrc;
  p.ov = ov;
  p.nov = ov ? nov : 0;
  int rc = 0;

  /* arguments */
  if (nsrc < 0 || (nsrc > 0 && !src) || nov < 0 || (nov > 0 && !ov)) {
    snprintf(p.msg, sizeof(p.msg), "ur_model_parse: bad arguments");
    rc = -1;
  }

  /* lex every source, then check the overrides against the param lines */
  for (int i = 0; !rc && i < nsrc; i++) {
    rc = url_lex(&p.lx, src[i].text, i, url_srcname(&p, i), src[i].line, p.msg, sizeof(p.msg));
  }
  if (!rc) {
    rc = check_overrides(&p);
  }

  /* statements in order */
  if (!rc && !(p.m = ur_model_new())) {
    snprintf(p.msg, sizeof(p.msg), "out of memory");
    rc = -1;
  }
  for (int i = 0; !rc && i < p.lx.nstmt; i++) {
    p.cur = i;
    p.cursrc = p.lx.stmt[i].src;
    if (p.stop && *p.stop) {
      snprintf(p.msg, sizeof(p.msg), "%s:%d: stopped on request (interrupted)",
               url_srcname(&p, p.cursrc), p.lx.stmt[i].line);
      rc = -1;
      break;
    }
    rc = statement(&p, p.lx.stmt + i);
  }

  /* the drone's design parameters, then compile (elements were checked on their lines; this
     should not fail) */
  if (!rc) {
    bind_preset_params(&p);
    rc = url_apply_design(&p);
  }
  if (!rc) {
    p.m->opt.memcache = c; /* kept: ur_model_inflate takes the bags through it */
    int bad = ur_model_compile(p.m);
    if (bad) {
      snprintf(p.msg, sizeof(p.msg), "%s: the model does not compile: %s",
               url_srcname(&p, nsrc - 1), p.m->err);
      rc = -1;
    }
  }
  release(&p);
  if (rc) {
    ur_model_free(p.m);
    p.m = NULL;
    if (err && errlen > 0) {
      snprintf(err, (size_t)errlen, "%s", p.msg);
    }
  } else if (err && errlen > 0) {
    err[0] = 0;
  }
  return p.m;
}

//---------------------------------- parts ---------------------------------------------------------

int ur_model_words(const char* text, urModelWord** words, int* nword, char* err, int errlen) {
  urlLex lx;
  char msg[MSGLEN];
  memset(&lx, 0, sizeof(lx));
  *words = NULL;
  *nword = 0;
  if (url_lex(&lx, text, 0, NULL, 1, msg, sizeof(msg))) {
    url_free(&lx);
    snprintf(err, (size_t)errlen, "%s", msg);
    return -1;
  }
  if (lx.nword > 0 && !(*words = malloc(sizeof(urModelWord) * (size_t)lx.nword))) {
    url_free(&lx);
    snprintf(err, (size_t)errlen, "model: out of memory");
    return -1;
  }
  for (int s = 0; s < lx.nstmt; s++) {
    for (int k = 0; k < lx.stmt[s].nword; k++) {
      const urlWord* w = lx.word + lx.stmt[s].word + k;
      (*words)[(*nword)++] = (urModelWord){w->at, w->len, s};
    }
  }
  url_free(&lx);
  return 0;
}

int ur_model_split(const char* text, const char* file, urModelPart* parts, int maxpart, char* err,
                   int errlen) {
  urlLex lx;
  char msg[MSGLEN];
  memset(&lx, 0, sizeof(lx));
  if (!file || !file[0]) {
    file = "model";
  }
  if (err && errlen > 0) {
    err[0] = 0;
  }
  int rc = url_lex(&lx, text, 0, file, 1, msg, sizeof(msg));

  /* check the part lines: one valid name each, no duplicates, at most limit[SYM_PART] (each
     compared with the part lines before it) */
  int* seen = NULL;
  int nseen = 0;
  for (int s = 0; !rc && s < lx.nstmt; s++) {
    const urlStmt* st = lx.stmt + s;
    if (strcmp(url_word(&lx, st->word), "part")) {
      continue;
    }
    const char* name = st->nword == 2 ? url_word(&lx, st->word + 1) : "";
    if (st->nword != 2 || !url_isident(name, strlen(name)) || strlen(name) >= urNAMELEN) {
      snprintf(msg, sizeof(msg), "%s:%d: part takes exactly one NAME; expected 'part NAME' (%s)",
               file, st->line, url_expect_name);
      rc = -1;
    } else if (nseen == url_limit[SYM_PART]) {
      snprintf(msg, sizeof(msg),
               "%s:%d: more than %d parts; accepted: at most %d "
               "(uasimpact-model(5), LIMITS)",
               file, st->line, url_limit[SYM_PART], url_limit[SYM_PART]);
      rc = -1;
    } else if (!seen && !(seen = malloc(sizeof(int) * (size_t)url_limit[SYM_PART]))) {
      snprintf(msg, sizeof(msg), "%s: out of memory", file);
      rc = -1;
    }
    for (int k = 0; !rc && k < nseen; k++) {
      const urlStmt* sk = lx.stmt + seen[k];
      if (!strcmp(url_word(&lx, sk->word + 1), name)) {
        snprintf(msg, sizeof(msg),
                 "%s:%d: duplicate part name '%s' (first at line %d); names "
                 "must be unique",
                 file, st->line, name, sk->line);
        rc = -1;
      }
    }
    if (!rc) {
      seen[nseen++] = s;
    }
  }
  free(seen);
  if (rc) {
    url_free(&lx);
    if (err && errlen > 0) {
      snprintf(err, (size_t)errlen, "%s", msg);
    }
    return -1;
  }

  /* part "" from the start when the first part line is not there */
  size_t len = strlen(text);
  int np = 0;
  for (int s = -1; s < lx.nstmt; s++) {
    const urlStmt* st = s >= 0 ? lx.stmt + s : NULL;
    if (st && strcmp(url_word(&lx, st->word), "part")) {
      continue;
    }
    size_t start = st ? st->linestart : 0;
    if (!st && (len == 0 || np > 0)) {
      continue;
    }

    /* a part line closes the previous part; at offset 0 it replaces the empty part "" */
    if (np > 0 && np <= maxpart) {
      parts[np - 1].len = start - (size_t)(parts[np - 1].text - text);
    }
    if (np == 1 && start == 0) {
      np = 0;
    }
    if (np < maxpart) {
      snprintf(parts[np].name, sizeof(parts[np].name), "%s", st ? url_word(&lx, st->word + 1) : "");
      parts[np].text = text + start;
      parts[np].len = len - start;
      parts[np].line = st ? st->line : 1;
    }
    np++;
  }
  url_free(&lx);
  return np;
}
