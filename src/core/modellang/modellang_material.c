/* modellang_material.c: the model-language parser (uasimpact-model(5), MATERIALS): the
 * statements material, section and layer, the material and section an ellipsoid or an arm's
 * restraint names, and the laws derived from them: an arm's hinge from beam theory, and the law
 * between a drone part and a person's layer from both sides' materials (Hertz's combination,
 * the layer bottoming on bone, a hollow part's shell in series). A law a pair names explicitly
 * is a declared override; where a derived law would exist, the model notes it. */
#include <stdarg.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include "uasimpact/material.h"
#include "uasimpact/modellang.h"
#include "modellang_internal.h"

/* append one line to the model's notes (dropped when they are full) */
void url_note(Parser* p, const char* fmt, ...) {
  char* n = p->m->note;
  size_t k = strlen(n);
  if (k + 2 >= sizeof p->m->note) {
    return;
  }
  if (k) {
    n[k++] = '\n';
    n[k] = 0;
  }
  va_list ap;
  va_start(ap, fmt);
  int w = vsnprintf(n + k, sizeof p->m->note - k, fmt, ap);
  va_end(ap);
  if (w < 0 || (size_t)w >= sizeof p->m->note - k) {
    n[k ? k - 1 : 0] = 0; /* a note that does not fit is left out whole */
  }
}


/* append one line to the model's derived values (dropped without memory) */
void url_derived(Parser* p, const char* fmt, ...) {
  char line[1024];
  va_list ap;
  va_start(ap, fmt);
  int w = vsnprintf(line, sizeof line, fmt, ap);
  va_end(ap);
  if (w < 0) {
    return;
  }
  size_t k = p->m->derived ? strlen(p->m->derived) : 0, n = strlen(line);
  char* d = realloc(p->m->derived, k + n + 2);
  if (!d) {
    return;
  }
  if (k) {
    d[k++] = '\n';
  }
  memcpy(d + k, line, n + 1);
  p->m->derived = d;
}


/* the name of the symbol of kind with index id ("?" none) */
static const char* symname(const Parser* p, int kind, int id) {
  for (int i = 0; i < p->nsym; i++) {
    if (p->sym[i].kind == kind && p->sym[i].id == id) {
      return p->sym[i].name;
    }
  }
  return "?";
}


/* material NAME E= nu= density= [yield=] [ultimate=] [fracture_strain=] */
int url_st_material(Parser* p, const Bound* b) {
  double nu = url_num(b, "nu", 0), sy = url_num(b, "yield", 0);
  if (url_nonneg(p, b, "E", 1) || url_nonneg(p, b, "density", 1) || url_nonneg(p, b, "yield", 0) ||
      url_nonneg(p, b, "ultimate", 0) || url_nonneg(p, b, "fracture_strain", 0)) {
    return -1;
  }
  if (!(nu >= 0 && nu < 0.5)) {
    return url_fail(p, url_get(b, "nu")->line, "material '%s': nu must be in [0, 0.5) (got %g)",
                    b->name, nu);
  }
  const Val* vu = url_get(b, "ultimate");
  if (vu->set && !(vu->v[0] >= sy)) {
    return url_fail(p, vu->line,
                    "material '%s': ultimate (%g Pa) must not be below yield (%g Pa); "
                    "expected the largest engineering stress of the stress-strain curve",
                    b->name, vu->v[0], sy);
  }
  const Val* vf = url_get(b, "fracture_strain");
  if (vf->set && !(vf->v[0] > 0 && vf->v[0] <= 1)) {
    return url_fail(p, vf->line, "material '%s': fracture_strain must be in (0, 1] (got %g)",
                    b->name, vf->v[0]);
  }
  int id = url_push(p, (void**)&p->mat, &p->nmat, &p->capmat, sizeof(urMaterial), b->line);
  if (id < 0 || url_declare(p, SYM_MATERIAL, b->name, b->line, id, 1)) {
    return -1;
  }
  urMaterial* m = p->mat + id;
  m->E = url_num(b, "E", 0);
  m->nu = nu;
  m->density = url_num(b, "density", 0);
  m->sy = sy;
  m->su = url_num(b, "ultimate", 0);
  m->ef = url_num(b, "fracture_strain", 0);
  return 0;
}


/* section NAME shape=tube D= t= | plate t= [b=] | solid D= | shell t= R= [h=] | box b= h= t= */
int url_st_section(Parser* p, const Bound* b) {
  static const char* const need[] = {"D,t", "t", "D", "t,R", "b,h,t"};
  static const char* const keys = "DtbRh";
  static const char* const uses[] = {"Dt", "tb", "D", "tRh", "bht"};
  static const char* const shape[] = {"tube", "plate", "solid", "shell", "box"};
  int sh = url_get(b, "shape")->e;
  for (const char* k = keys; *k; k++) {
    char key[2] = {*k, 0};
    const Val* v = url_get(b, key);
    if (v->set && !strchr(uses[sh], *k)) {
      return url_fail(p, v->line, "section '%s': a %s takes %s%s, not %s", b->name, shape[sh],
                      need[sh],
                      sh == 1   ? " (and b, its width)"
                      : sh == 3 ? " (and h, its depth to bottoming)"
                                : "",
                      key);
    }
    if (strchr(need[sh], *k) && !v->set) {
      return url_fail(p, b->line, "section '%s': a %s needs %s (m)", b->name, shape[sh], need[sh]);
    }
    if (v->set && url_nonneg(p, b, key, 1)) {
      return -1;
    }
  }
  urSection s;
  memset(&s, 0, sizeof s);
  s.type = (urSectionType)sh;
  s.D = url_num(b, "D", 0);
  s.t = url_num(b, "t", 0);
  s.b = url_num(b, "b", 0);
  s.R = url_num(b, "R", 0);
  s.h = url_num(b, "h", 0);
  if (sh == 4 && !(2 * s.t < s.b && 2 * s.t < s.h)) {
    return url_fail(p, url_get(b, "t")->line,
                    "section '%s': a box's wall t (%g m) must be thinner than half its width b "
                    "(%g m) and height h (%g m); a full bar is shape=plate with b",
                    b->name, s.t, s.b, s.h);
  }
  if (sh == 0 && !(2 * s.t < s.D)) {
    return url_fail(p, url_get(b, "t")->line,
                    "section '%s': a tube's wall t (%g m) must be thinner than half its "
                    "diameter D (%g m); a full bar is shape=solid",
                    b->name, s.t, s.D);
  }
  int id = url_push(p, (void**)&p->sec, &p->nsec, &p->capsec, sizeof(urSection), b->line);
  if (id < 0 || url_declare(p, SYM_SECTION, b->name, b->line, id, 1)) {
    return -1;
  }
  p->sec[id] = s;
  return 0;
}


/* the material record of ellipsoid g, grown to hold it (new entries: none) */
static urlGeomMat* geommat(Parser* p, int g, int line) {
  while (p->ngmat <= g) {
    int i = url_push(p, (void**)&p->gmat, &p->ngmat, &p->capgmat, sizeof(urlGeomMat), line);
    if (i < 0) {
      return NULL;
    }
    p->gmat[i].mat = p->gmat[i].sec = p->gmat[i].layer = -1;
  }
  return p->gmat + g;
}


/* the record of ellipsoid g if it has one, else NULL */
static const urlGeomMat* geommat_of(const Parser* p, int g) {
  return g >= 0 && g < p->ngmat ? p->gmat + g : NULL;
}


/* a layer's region: a material with its thickness and bone (ml), or one of the person's own
   laws (law= : no thickness, bone, radius or friction of its own; the law has them) */
static int layer_kind(Parser* p, const Bound* b, int* mat, int* law) {
  const Val* vm = url_get(b, "material");
  const Val* vl = url_get(b, "law");
  *mat = *law = -1;
  if (vm->set == vl->set) {
    return url_fail(p, b->line,
                    "layer '%s': give material= (with thickness= and bone_k=) or law= (one of "
                    "the person's laws), one of them",
                    b->name);
  }
  if (vl->set) {
    static const char* const own[] = {"thickness", "bone_k", "radius", "mu", "v_eps"};
    for (int i = 0; i < 5; i++) {
      const Val* v = url_get(b, own[i]);
      if (v->set) {
        return url_fail(p, v->line,
                        "layer '%s': a law layer takes no %s (its law '%s' gives the force); "
                        "expected on= and law= only",
                        b->name, own[i], vl->raw);
      }
    }
    *law = url_ref(p, SYM_LAW, vl->raw, vl->line, "layer");
    return *law < 0 ? -1 : 0;
  }
  static const char* const need[] = {"thickness", "bone_k"};
  for (int i = 0; i < 2; i++) {
    if (!url_get(b, need[i])->set) {
      return url_fail(p, b->line, "layer '%s': a material layer needs %s= (%s)", b->name, need[i],
                      i ? "N/m, the bone under it" : "m, where it bottoms");
    }
  }
  *mat = url_ref(p, SYM_MATERIAL, vm->raw, vm->line, "layer");
  if (*mat < 0 || url_nonneg(p, b, "thickness", 1) || url_nonneg(p, b, "bone_k", 1) ||
      url_nonneg(p, b, "radius", 0) || url_nonneg(p, b, "mu", 0) || url_nonneg(p, b, "v_eps", 0)) {
    return -1;
  }
  return 0;
}


/* layer NAME on=E1,E2,.. material= thickness= bone_k= [radius=] [mu=] [v_eps=] | law= */
int url_st_layer(Parser* p, const Bound* b) {
  int mat, law;
  if (layer_kind(p, b, &mat, &law)) {
    return -1;
  }
  int id = url_push(p, (void**)&p->layer, &p->nlayer, &p->caplayer, sizeof(urlLayer), b->line);
  if (id < 0 || url_declare(p, SYM_LAYER, b->name, b->line, id, 1)) {
    return -1;
  }
  urlLayer* l = p->layer + id;
  l->mat = mat;
  l->law = law;
  l->h = url_num(b, "thickness", 0);
  l->bone_k = url_num(b, "bone_k", 0);
  l->radius = url_num(b, "radius", 0);
  l->mu = url_num(b, "mu", 0);
  l->v_eps = url_num(b, "v_eps", 0);

  /* the ellipsoids it covers: one layer each */
  const Val* vo = url_get(b, "on");
  for (int i = 0; i < vo->n; i++) {
    char na[urNAMELEN];
    url_item(vo->raw, i, na, sizeof(na));
    int g = url_ref(p, SYM_ELLIPSOID, na, vo->line, "layer");
    if (g < 0) {
      return -1;
    }
    urlGeomMat* gm = geommat(p, g, b->line);
    if (!gm) {
      return -1;
    }
    if (gm->layer >= 0 || gm->mat >= 0) {
      return url_fail(p, vo->line,
                      "layer '%s': ellipsoid '%s' already has a %s; expected one layer or "
                      "material per ellipsoid",
                      b->name, na, gm->layer >= 0 ? "layer" : "material");
    }
    gm->layer = id;
  }
  return 0;
}


/* the material= and section= keys of ellipsoid statement b, for ellipsoid g */
int url_geom_material(Parser* p, const Bound* b, int g) {
  const Val* vm = url_get(b, "material");
  const Val* vs = url_get(b, "section");
  if (!vm->set && !vs->set) {
    return 0;
  }
  if (!vm->set) {
    return url_fail(p, vs->line, "ellipsoid '%s': a section needs material= (what it is made of)",
                    b->name);
  }
  int mat = url_ref(p, SYM_MATERIAL, vm->raw, vm->line, "ellipsoid");
  int sec = -1;
  if (mat < 0 || (vs->set && (sec = url_ref(p, SYM_SECTION, vs->raw, vs->line, "ellipsoid")) < 0)) {
    return -1;
  }
  urlGeomMat* gm = geommat(p, g, b->line);
  if (!gm) {
    return -1;
  }
  gm->mat = mat;
  gm->sec = sec;
  return 0;
}


/* restraint keys material= section= length= [fracture=1]: the hinge from beam theory into r.
   Returns 1 when derived, 0 when the restraint gives its law itself, -1 on error. */
int url_hinge(Parser* p, const Bound* b, urRestraint* r) {
  const Val* vm = url_get(b, "material");
  const Val* vs = url_get(b, "section");
  const Val* vl = url_get(b, "length");
  const Val* vf = url_get(b, "fracture");
  if (!vm->set && !vs->set && !vl->set) {
    if (vf->set) {
      return url_fail(p, vf->line,
                      "restraint '%s': fracture needs material=, section= and length=", b->name);
    }
    return 0;
  }
  if (!vm->set || !vs->set || !vl->set) {
    return url_fail(p, b->line,
                    "restraint '%s': a hinge from beam theory needs material=, section= "
                    "and length= (m) together",
                    b->name);
  }
  static const char* const explicit[] = {"k", "sat", "load", "unload"};
  for (int i = 0; i < 4; i++) {
    const Val* v = url_get(b, explicit[i]);
    if (v->set) {
      return url_fail(p, v->line,
                      "restraint '%s': %s is an explicit law and material= derives one; "
                      "expected either material=, section=, length= or k/sat/load",
                      b->name, explicit[i]);
    }
  }
  int mat = url_ref(p, SYM_MATERIAL, vm->raw, vm->line, "restraint");
  int sec = mat < 0 ? -1 : url_ref(p, SYM_SECTION, vs->raw, vs->line, "restraint");
  if (sec < 0 || url_nonneg(p, b, "length", 1)) {
    return -1;
  }
  if (!(p->mat[mat].sy > 0)) {
    return url_fail(p, vm->line,
                    "restraint '%s': material '%s' gives no yield stress; a hinge from beam "
                    "theory needs yield= (its plastic moment)",
                    b->name, vm->raw);
  }
  urHinge h;
  if (ur_hinge_from_beam(p->mat + mat, p->sec + sec, vl->v[0], &h)) {
    return url_fail(p, vs->line,
                    "restraint '%s': section '%s' has no bending law (a shell, or a plate "
                    "without its width b); expected a tube, a box, a solid bar or a plate with b",
                    b->name, vs->raw);
  }
  int fracture = vf->set && vf->v[0] != 0;
  if (fracture && !(h.mu > 0)) {
    return url_fail(p, vf->line,
                    "restraint '%s': fracture=1 needs the material's ultimate stress or "
                    "fracture_strain",
                    b->name);
  }
  r->k = h.k;
  r->mp = h.mp;
  r->kh = h.kh;
  r->mfrac = fracture ? (h.mu > h.mp ? h.mu : h.mp) : 0;

  /* what was derived, with its formula and inputs (model params) */
  const urMaterial* mm = p->mat + mat;
  urSectionProps sp;
  ur_section_props(p->sec + sec, &sp);
  char who[urNAMELEN + 48];
  snprintf(who, sizeof who, "restraint '%s' dof %d (%s, %s, L %g m)", b->name,
           (int)url_get(b, "dof")->v[0], vm->raw, vs->raw, vl->v[0]);
  url_derived(p, "%s: hinge k = 3 E I / L = %.6g N m/rad (E %.6g Pa, I %.6g m^4)", who, h.k, mm->E,
              sp.I);
  url_derived(p, "%s: hinge M_p = sigma_y Z_p = %.6g N m (sigma_y %.6g Pa, Z_p %.6g m^3)", who,
              h.mp, mm->sy, sp.Zp);
  url_derived(p, "%s: hinge k_h = k E_t / E = %.6g N m/rad (E_t %.6g Pa: %s)", who, h.kh,
              h.kh * mm->E / h.k,
              mm->su > mm->sy && mm->ef > mm->sy / mm->E ? "(sigma_u - sigma_y) / (e_f - sigma_y/E)"
                                                         : "E/100, EN 1993-1-5 C.6");
  if (r->mfrac > 0) {
    url_derived(p, "%s: hinge fracture M_u = %.6g N m (%s)", who, r->mfrac,
                mm->su > 0 ? "sigma_u Z_p" : "E e_f Z_e");
  }
  return 1;
}


/* the Hertz radius (m) of a drone part's section: a tube's or a bar's D/2, a shell's R, 0 for a
   plate (flat); -1: none (take the ellipsoids' curvature) */
static double section_radius(const Parser* p, const urlGeomMat* gm) {
  if (!gm || gm->sec < 0) {
    return -1;
  }
  const urSection* s = p->sec + gm->sec;
  switch (s->type) {
  case urSEC_TUBE:
  case urSEC_SOLID: return s->D / 2;
  case urSEC_SHELL: return s->R;
  case urSEC_BOX: return -1; /* its edges: the ellipsoids' curvature */
  default: return 0;
  }
}


/* a foam law's backing derived from the layer of the person's part ga (backing=derived, the
   backing's material bm): Hertz of the layer's material on bm, flat, at the layer's radius or
   the part's curvature at each contact; or a law layer's loading curve */
static int foam_backing(Parser* p, const char* what, int ga, int bm, int line, urLaw* out) {
  const urlGeomMat* a = geommat_of(p, ga);
  const char* na = p->m->geom[ga].name;
  if (!a || a->layer < 0) {
    return url_fail(p, line,
                    "%s: the foam's backing=derived needs a layer on '%s' (the person's part, "
                    "a=); expected 'layer ... on=%s' in the person's model, or a declared "
                    "backing=LAW",
                    what, na, na);
  }
  const urlLayer* l = p->layer + a->layer;
  char who[2 * urNAMELEN + 64];
  snprintf(who, sizeof who, "%s, foam on layer %s:", what, symname(p, SYM_LAYER, a->layer));
  int told = p->m->derived && strstr(p->m->derived, who); /* once per statement and layer */
  if (l->law >= 0) {
    const urLaw* ll = p->law + l->law;
    if (ll->type != urLAW_TABLE) {
      return url_fail(p, line,
                      "%s: the foam's backing=derived takes a law layer's loading curve, and "
                      "'%s' (layer %s) is not a table law",
                      what, symname(p, SYM_LAW, l->law), symname(p, SYM_LAYER, a->layer));
    }
    out->backing = ll->load;
    if (!told) {
      url_derived(p, "%s backing beyond the lock strain = the loading curve of law %s", who,
                  symname(p, SYM_LAW, l->law));
    }
    return 0;
  }
  const urMaterial *ml = p->mat + l->mat, *mb = p->mat + bm;
  urLaw h;
  memset(&h, 0, sizeof h);
  ur_law_hertz(&h, ml->E, ml->nu, l->radius, mb->E, mb->nu, 0, 0, 0, 0);
  out->backing_estar = h.estar;
  if (l->radius > 0) {
    out->backing_r = h.radius;
    out->backing_k = ur_law_backing_k(out, h.radius);
  } else {
    out->backing_r = urHERTZ_CURVATURE;
    out->backing_k = 0;
  }
  if (told) {
    return 0;
  }
  if (l->radius > 0) {
    url_derived(p,
                "%s backing K = 4/3 E* sqrt(R) = %.6g N/m^1.5 (E* %.6g Pa of E1 %.6g Pa, nu1 %g "
                "on %s E2 %.6g Pa, nu2 %g; R %g m, flat backing)",
                who, out->backing_k, h.estar, ml->E, ml->nu, symname(p, SYM_MATERIAL, bm), mb->E,
                mb->nu, h.radius);
  } else {
    url_derived(p,
                "%s backing K = 4/3 E* sqrt(R), E* %.6g Pa (E1 %.6g Pa, nu1 %g on %s E2 %.6g Pa, "
                "nu2 %g), R the curvature of the person's part at each contact (flat backing)",
                who, h.estar, ml->E, ml->nu, symname(p, SYM_MATERIAL, bm), mb->E, mb->nu);
  }
  return 0;
}


/* the law of a pair of ellipsoids ga, gb (gb -1: the ground): law (>= 0) as declared, or, with
   law < 0, derived from a layer on one side (a law layer: its law; a material layer: Hertz with
   a material on the other side). A declared law on a layer other than a law layer's own (a
   drone file's own scalp law) is an override, and noted once per statement; a declared foam
   law whose backing is derived is the drone's, not an override, and takes its backing from
   the person's part a. */
int url_pair_law(Parser* p, const char* what, int ga, int gb, int law, int line, urLaw* out) {
  const urlGeomMat *a = geommat_of(p, ga), *b = geommat_of(p, gb);
  const urlGeomMat* lay = a && a->layer >= 0 ? a : b && b->layer >= 0 ? b : NULL;
  const urlGeomMat* part = lay == a ? b : a;
  const urlLayer* ly = lay ? p->layer + lay->layer : NULL;
  int derivable = ly && (ly->law >= 0 || (part && part->mat >= 0));
  if (law >= 0) {
    *out = p->law[law];
    int bm = p->lawback[law];
    if (bm >= 0) {
      return foam_backing(p, what, ga, bm, line, out);
    }
    if (ly && ly->law != law && !strstr(p->m->note, what)) { /* once per statement */
      int gl = lay == a ? ga : gb, go = lay == a ? gb : ga;
      int mat = derivable && ly->law < 0;
      url_note(p,
               "%s: its declared law '%s' overrides the layer of '%s'%s%s%s (uasimpact-model(5), "
               "MATERIALS)",
               what, symname(p, SYM_LAW, law), p->m->geom[gl].name,
               mat ? " and the material of '" : "", mat ? p->m->geom[go].name : "", mat ? "'" : "");
    }
    return 0;
  }
  if (!derivable) {
    return url_fail(p, line,
                    "%s: no law= and nothing to derive one from; expected law=NAME, or a "
                    "layer on one ellipsoid ('layer ... on=') and material= on the other",
                    what);
  }
  if (ly->law >= 0) {
    /* a law layer: the person's own law, whatever the drone part */
    *out = p->law[ly->law];
    return 0;
  }

  /* Hertz from both materials; the radius from the layer's and the section's, else curvature */
  const urlLayer* l = ly;
  const urMaterial *ml = p->mat + l->mat, *mp = p->mat + part->mat;
  double rp = section_radius(p, part);
  memset(out, 0, sizeof *out);
  ur_law_hertz(out, ml->E, ml->nu, l->radius, mp->E, mp->nu, rp > 0 ? rp : 0, ml->sy, ml->nu, 0);
  if (!(l->radius > 0) || rp < 0) {
    out->radius = urHERTZ_CURVATURE;
  }
  out->layer_h = l->h;
  out->bone_k = l->bone_k;
  out->mu = l->mu;
  out->v_eps = l->v_eps;
  if (part->sec >= 0) {
    out->shell_k = ur_shell_stiffness(mp, p->sec + part->sec);
    out->crush_f = out->shell_k > 0 ? ur_shell_crush_force(mp, p->sec + part->sec) : 0;
    out->crush_h = out->crush_f > 0 ? ur_shell_crush_depth(p->sec + part->sec) : 0;
  }

  /* what was derived, with its formula and inputs (model params) */
  char who[4 * urNAMELEN + 64];
  snprintf(who, sizeof who, "%s, %s on %s (layer %s, material %s)", what,
           p->m->geom[lay == a ? gb : ga].name, p->m->geom[lay == a ? ga : gb].name,
           symname(p, SYM_LAYER, lay->layer), symname(p, SYM_MATERIAL, part->mat));
  url_derived(p,
              "%s: Hertz E* = 1/((1-nu1^2)/E1 + (1-nu2^2)/E2) = %.6g Pa (E1 %.6g Pa, nu1 %g; E2 "
              "%.6g Pa, nu2 %g)",
              who, out->estar, ml->E, ml->nu, mp->E, mp->nu);
  if (out->radius == urHERTZ_CURVATURE) {
    url_derived(p, "%s: Hertz R from the ellipsoids' curvature at each contact", who);
  } else {
    url_derived(p, "%s: Hertz R = 1/(1/R1 + 1/R2) = %.6g m (R1 %g m, R2 %g m; 0: flat)", who,
                out->radius, l->radius, rp > 0 ? rp : 0);
  }
  url_derived(p, "%s: layer bottoms at h = %g m, then bone_k = %.6g N/m", who, l->h, l->bone_k);
  if (out->shell_k > 0) {
    const urSection* sc = p->sec + part->sec;
    url_derived(p,
                "%s: shell k_s = 4 E t^2 / (R sqrt(3 (1-nu^2))) = %.6g N/m (section %s: E "
                "%.6g Pa, t %g m, R %g m, nu %g)",
                who, out->shell_k, symname(p, SYM_SECTION, part->sec), mp->E, sc->t, sc->R, mp->nu);
    if (out->crush_f > 0) {
      url_derived(p,
                  "%s: shell crush F_c = 2 pi M0 = pi sigma_y t^2 / 2 = %.6g N (sigma_y %.6g Pa, t "
                  "%g m), bottoming after %g m of crush (%s)",
                  who, out->crush_f, mp->sy, sc->t, out->crush_h, sc->h > 0 ? "h" : "R");
    } else {
      url_derived(p, "%s: shell crush none (material %s gives no yield): elastic shell", who,
                  symname(p, SYM_MATERIAL, part->mat));
    }
  }
  return 0;
}


/* a membrane bag's targets that carry a layer: the layer's foundation stiffness E_oed / h
   (N/m^3) as the penalty of the fabric on them (engine_membrane.c caps it where the explicit
   step cannot carry it); the others keep the bag's kc_alpha */
void url_bag_layers(Parser* p, urAirbag* bag) {
  for (int t = 0; t < bag->ntarget; t++) {
    const urlGeomMat* gm = geommat_of(p, bag->target[t]);
    bag->tk[t] = 0;
    if (!gm || gm->layer < 0 || p->layer[gm->layer].mat < 0) {
      continue; /* no layer, or a law layer: the bag's own penalty */
    }
    const urlLayer* l = p->layer + gm->layer;
    const urMaterial* ml = p->mat + l->mat;
    bag->tk[t] = ur_layer_foundation(ml, l->h);
    if (bag->tk[t] > 0) {
      url_derived(p,
                  "airbag '%s' on %s (layer %s): fabric penalty k = E_oed / h = %.6g N/m^3 "
                  "(E_oed = E (1-nu) / ((1+nu) (1-2 nu)), E %.6g Pa, nu %g, h %g m)",
                  bag->name, p->m->geom[bag->target[t]].name, symname(p, SYM_LAYER, gm->layer),
                  bag->tk[t], ml->E, ml->nu, l->h);
    }
  }
}
