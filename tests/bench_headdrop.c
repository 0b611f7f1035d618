/* bench_headdrop.c: the head drop of 49 CFR 572.32 (a Hybrid III head dropped 376 mm onto a rigid
 * plate; its peak resultant acceleration must lie in 225-275 g) run on the person's scalp layer
 * as the built-in human model declares it (human.urm: material scalp, layer scalp), against the
 * paper's half-space Hertz scalp and with the layer's thickness and skull stiffness varied.
 * A benchmark of the layer, not a test: it says how far the layer is from the dummy's corridor
 * (tests/MEASUREMENTS.md). Head: the Hybrid III's 4.54 kg (human-model sheet 7.1) on a sphere
 * of the paper's radius 0.0875 m; plate: steel (E 200 GPa, nu 0.3), flat. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "uasimpact/engine.h"
#include "uasimpact/modellang.h"
#include "../src/app/case/builtin.h"


#define G      9.80665
#define H_DROP 0.376 /* m: 14.8 in */
#define M_HEAD 4.54  /* kg: Hybrid III head */

/* the logical line of the built-in human model that starts with prefix (continuations joined),
   or "" */
static void statement(const char* prefix, char* out, size_t n) {
  const char* t = ura_builtin_text("human");
  out[0] = 0;
  for (const char* l = t; l && *l; l = strchr(l, '\n') ? strchr(l, '\n') + 1 : NULL) {
    if (strncmp(l, prefix, strlen(prefix))) continue;
    size_t k = 0;
    while (*l && k + 1 < n) {
      const char* e = strchr(l, '\n');
      size_t len = e ? (size_t)(e - l) : strlen(l);
      int cont = len > 0 && l[len - 1] == '\\';
      size_t c = cont ? len - 1 : len;
      if (k + c + 2 >= n) break;
      memcpy(out + k, l, c);
      k += c;
      out[k++] = ' ';
      if (!cont || !e) break;
      l = e + 1;
    }
    out[k] = 0;
    return;
  }
}

/* replace the value of key= in statement s (n bytes) by v */
static void setkey(char* s, size_t n, const char* key, double v) {
  char* k = strstr(s, key);
  if (!k) return;
  char* e = k + strlen(key);
  while (*e && *e != ' ') e++;
  char rest[1024];
  snprintf(rest, sizeof rest, "%s", e);
  snprintf(k, n - (size_t)(k - s), "%s%g%s", key, v, rest);
}


/* the drop on a layer of thickness h (m; 0: the human model's) over a skull of bone_k (N/m;
   0: the model's), or on the paper's half-space law (paper = 1); peak acceleration in g,
   pulse duration in ms, the deepest penetration in mm */
static int drop(int paper, double h, double kb, double* peak, double* ms, double* depth) {
  char mat[1024], lay[1024], text[6000];
  statement("material scalp ", mat, sizeof mat);
  statement("layer scalp ", lay, sizeof lay);
  if (!mat[0] || !lay[0]) {
    fprintf(stderr, "bench_headdrop: the built-in human model declares no scalp layer\n");
    return -1;
  }
  if (h > 0) setkey(lay, sizeof lay, "thickness=", h);
  if (kb > 0) setkey(lay, sizeof lay, "bone_k=", kb);
  const char* law = paper ? "law paper type=hertz E1=2.23e7 nu1=0.29 R1=0.0875 E2=2e11 nu2=0.3 "
                            "R2=0 mu=0.3 v_eps=0.01\n"
                          : "";
  snprintf(text, sizeof text,
           "%s\nmaterial steel E=2e11 nu=0.3 density=7850 yield=2.5e8\n"
           "section slab shape=plate t=0.05\n"
           "body head parent=world joint=free pos=0,0,1 mass=%g inertia=0.0212,0.0229,0.0152\n"
           "ellipsoid head_cranium body=head pos=0,0,0 size=0.0875,0.0875,0.0875\n"
           "ellipsoid head_face body=head pos=0,0,0.3 size=0.01,0.01,0.01\n"
           "%s\n"
           "body plate parent=world joint=fixed pos=0,0,0 mass=100 inertia=1,1,1\n"
           "ellipsoid slab body=plate pos=0,0,-0.05 size=0.5,0.5,0.05 degree=20 "
           "material=steel section=slab\n%s"
           "pair drop a=head_cranium b=slab%s\n",
           mat, M_HEAD, lay, law, paper ? " law=paper" : "");
  char err[300];
  urModelSource src = {text, "headdrop", 1};
  urModel* m = ur_model_parse(&src, 1, NULL, 0, err, sizeof err);
  if (!m) {
    fprintf(stderr, "bench_headdrop: %s\n", err);
    return -1;
  }
  m->opt.dt = 1e-6;
  m->opt.gravity[2] = -G;
  urData* d = ur_data_new(m);
  double v0 = sqrt(2 * G * H_DROP), vel[3] = {0, 0, -v0}, zero[3] = {0, 0, 0};
  ur_set_free(m, d, 0, (double[3]){0, 0, 0.0875 + 1e-6}, NULL, vel, zero);
  ur_forward(m, d);
  double p0[3], l0[3], p1[3], l1[3], t0 = -1, t1 = -1;
  *peak = *depth = 0;
  ur_momentum(m, d, p0, l0);
  for (int i = 0; i < 50000; i++) {
    ur_step(m, d);
    ur_forward(m, d);
    ur_momentum(m, d, p1, l1);
    double a = (p1[2] - p0[2]) / (M_HEAD * m->opt.dt) + G; /* the accelerometer: contact only */
    if (a > 1e-3 * G && t0 < 0) t0 = d->time;
    if (a > 1e-3 * G) t1 = d->time;
    *peak = fmax(*peak, a / G);
    *depth = fmax(*depth, 1e3 * d->pair[0].ls.dmax);
    memcpy(p0, p1, sizeof p0);
    if (t0 >= 0 && p1[2] > 0 && a < 1e-3 * G) break;
  }
  *ms = 1e3 * (t1 - t0);
  ur_data_free(d);
  ur_model_free(m);
  return 0;
}

int main(void) {
  double pk, ms, dep;
  printf(
      "bench_headdrop: 49 CFR 572.32 head drop, %g mm onto a rigid plate, %.3f m/s, head "
      "%g kg R 0.0875 m; corridor 225-275 g\n",
      1e3 * H_DROP, sqrt(2 * G * H_DROP), M_HEAD);
  if (drop(1, 0, 0, &pk, &ms, &dep)) return 1;
  printf(
      "  paper's half-space Hertz scalp:           peak %6.1f g  pulse %5.2f ms  depth %5.2f "
      "mm\n",
      pk, ms, dep);
  if (drop(0, 0, 0, &pk, &ms, &dep)) return 1;
  printf(
      "  human.urm scalp layer (as declared):      peak %6.1f g  pulse %5.2f ms  depth %5.2f "
      "mm\n",
      pk, ms, dep);
  static const double H[3] = {0.005, 0.006, 0.007}, K[2] = {812e3, 4023e3};
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 2; j++) {
      if (drop(0, H[i], K[j], &pk, &ms, &dep)) return 1;
      printf(
          "  layer %.0f mm over %4.0f N/mm skull:         peak %6.1f g  pulse %5.2f ms  depth "
          "%5.2f mm\n",
          1e3 * H[i], 1e-3 * K[j], pk, ms, dep);
    }
  }
  return 0;
}
