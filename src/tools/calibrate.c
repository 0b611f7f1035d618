/* calibrate.c: 'make calibrate', the declared calibration of the model's unknowns (uasimpact-model(5),
 * CALIBRATION). The unknowns the paper leaves open are fitted to the training set alone: the
 * paper's three zero-wind grids (Tables 4, 5, 6), cell by cell over the full plane. Everything
 * else the paper prints is validation and is never read here.
 *
 *   calibrate [-s SPEC] [-o DIR] [-n MAXEVAL] [-r LOG] [-e [-m]] [-l FILE]...
 *             [NAME=VALUE | NAME/OTHER=SHARE ...]
 *     -s SPEC    the declaration (default src/models/calibrate.spec)
 *     -o DIR     log.csv (every evaluation) and result.txt go here (default build/calibration)
 *     -r LOG     resume the fit LOG records ('make calibrate RESUME=LOG'): the simplex is
 *                deterministic, so its first points must be LOG's rows, bit for bit; those are
 *                not evaluated again (their logged loss is taken), the rest are. A point that
 *                differs from its row stops the fit with an error naming the row
 *     -n N       at most N evaluations per simplex (default: the spec's maxeval)
 *     -e         evaluate once at the start (or at the model's own values with -m) and stop
 *     -m         with -e: the model's own values, not the spec's start (free parameters the
 *                model does not have are left out)
 *     -l FILE    'model load FILE' first (a part replaced: to measure a model change alone)
 *     NAME=VALUE model parameters set on top (SI), e.g. to measure one change alone
 *     NAME/OTHER=SHARE  the start (with -e: the point) of a share the spec declares
 *
 * `corner REL GAIN N` (optional) ends the fit once N evaluations in a row had every free parameter
 * within REL of its range from one of its bounds and the best loss fell by less than GAIN over
 * them: at such a corner the logistic coordinates run off to infinity, so the simplex's size
 * test cannot end the fit and a restart cannot leave it.
 *
 * Besides cases, free parameters and choices, a spec may hold `load FILE` (a part file loaded
 * over the built-in model before the fit, as -l; the spec's first) and `set NAME VALUE [UNIT]`
 * (a setting held at every evaluation, before the command line's NAME=VALUE). They are data:
 * a load only reads a part file, a set only sets a parameter (a NAME of letters, digits and _,
 * no ';' or quotes anywhere), nothing else runs.
 *
 * The loss (the spec's words; the man page states it), per training case X, over the full plane
 * (ura_grid_load mirrors the paper's half plane: a printed column dperp > 0 counts twice):
 *   loss integral   the integrated absolute error, the sum over cells of |P_ours - P_paper| times
 *                   the cell's area (our cells off the paper's grid against P = 0), divided by
 *                   the paper's Q of that grid (its full-plane sum of P times the cell area)
 *   loss footprint  (the default, the first declaration) the mean of |P_ours - P_paper| over the
 *                   union footprint (cells where the paper prints P > 0 or ours is at least
 *                   `threshold`), divided by the paper's mean P over its own footprint
 * summed over the cases; plus, where the spec asks for it ('share' on a case), the shortfall of
 * HIC's share of the fused P at Delta = (0,0) below `hic_share` (the paper's conclusion: Nij and
 * VC contribute much less than HIC). Free parameters are mapped to their bounds by a logistic,
 * so the simplex never leaves them; `free NAME LO HI START of=OTHER` fits a share of OTHER (the
 * model gets share * OTHER). The spec's discrete choices (injury curve decisions) change only
 * how the criteria of a cell become P, so every combination is scored on the same simulated
 * grids and the best is taken. The log starts with the spec's commit and the fit's UTC start
 * (and a line per resume); its values and total round-trip (%.17g), so a resumed fit is the
 * uninterrupted one.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multimin.h>

#include "../app/cmd/cmd.h"

#define MAXFREE   24
#define CORNERMAX 64 /* corner's N at most */
#define MAXCASE   4
#define MAXGROUP  4
#define MAXALT    4
#define MAXSET    8
#define LINELEN   512

typedef struct {
  char name[urNAMELEN];
  double lo, hi, start;
  char unit[16];
  char of[urNAMELEN]; /* a share of this free parameter ("": a value) */
  int other;          /* its index (-1: none) */
  int line;           /* in the spec, for errors */
} freeParam;

typedef struct { /* one alternative of a discrete group: injury settings */
  char label[24];
  int nset;
  char set[MAXSET][urNAMELEN];
  double val[MAXSET];
} alt;

typedef struct {
  char name[24];
  int nalt;
  alt a[MAXALT];
} group;

typedef struct {
  char name[8];
  double speed;
  char table[LINELEN];
  int share;     /* the HIC-share constraint applies at its centre */
  urGrid* paper; /* the paper's grid, full plane (ura_grid_load) */
  double pbar;   /* the paper's mean P over its footprint */
  double q;      /* the paper's Q: full-plane sum of P times the cell area, m^2 */
} trainCase;

typedef struct {
  int nfree, ncase, ngroup;
  freeParam f[MAXFREE];
  trainCase k[MAXCASE];
  group g[MAXGROUP];
  double hic_share, threshold, simplex, tol;
  int maxeval;                    /* evaluations per run of the simplex */
  int restarts;                   /* new simplices around the best point, while they gain */
  double gain;                    /* a restart that lowers the loss by less than this ends */
  double corner_rel, corner_gain; /* corner REL GAIN N: the end at a corner of the bounds */
  int corner_n;                   /* 0: no such end */
  int integral;                   /* loss integral (1) or footprint (0, the default) */
  int nload;                      /* load FILE: parts loaded over the built-in model, in order */
  char load[8][LINELEN];
  char set[LINELEN]; /* set NAME VALUE [UNIT]: held settings, '; '-joined */
} spec;

typedef struct {
  uraCtx* c;
  spec* s;
  FILE* log;
  int neval;
  double best;
  double bestx[MAXFREE];
  char bestcombo[128];
  double bestpart[MAXCASE], bestshare[MAXCASE];
  char extra[LINELEN]; /* NAME=VALUE settings given on the command line */
  int failed;
  int use[MAXFREE];   /* the free parameters set (-m: those the model has) */
  const char* resume; /* -r: the log replayed */
  char** rows;        /* its evaluation rows, in order */
  int* rowline;       /* their lines in that file */
  int nrows;
  int corner_run;              /* evaluations in a row at a corner of the bounds */
  double bests[CORNERMAX + 1]; /* the best loss after each of the last evaluations */
  int corner_done;             /* the corner rule ended the fit */
} fit;

/* ---- the spec ---- */

static int spec_fail(const char* path, int line, const char* msg, const char* word) {
  fprintf(stderr, "calibrate: %s:%d: %s%s%s\n", path, line, msg, word ? ": " : "",
          word ? word : "");
  return -1;
}

static int num(const char* w, double* v) {
  return !w || ura_parse_number(w, v);
}

/* NAME=VALUE,NAME=VALUE into an alternative */
static int parse_settings(const char* list, alt* a) {
  char buf[LINELEN];
  snprintf(buf, sizeof buf, "%s", list);
  for (char* item = strtok(buf, ","); item; item = strtok(NULL, ",")) {
    char* eq = strchr(item, '=');
    if (!eq || a->nset == MAXSET) return -1;
    *eq = 0;
    snprintf(a->set[a->nset], urNAMELEN, "%s", item);
    if (num(eq + 1, &a->val[a->nset])) return -1;
    a->nset++;
  }
  return a->nset ? 0 : -1;
}

static int spec_read(const char* path, spec* s) {
  FILE* f = fopen(path, "r");
  if (!f) {
    fprintf(stderr, "calibrate: %s: %s\n", path, strerror(errno));
    return -1;
  }
  memset(s, 0, sizeof *s);
  s->threshold = 0.0005;
  s->simplex = 1;
  s->tol = 1e-3;
  s->maxeval = 400;
  s->gain = 0.005;
  char line[LINELEN];
  int ln = 0, rc = 0;
  while (rc == 0 && fgets(line, sizeof line, f)) {
    ln++;
    char* hash = strchr(line, '#');
    if (hash) *hash = 0;
    char* w[8] = {0};
    int n = 0;
    for (char* t = strtok(line, " \t\r\n"); t && n < 8; t = strtok(NULL, " \t\r\n")) w[n++] = t;
    if (n == 0) continue;
    if (!strcmp(w[0], "case") && n >= 4 && s->ncase < MAXCASE) {
      /* case NAME SPEED TABLE [share] */
      trainCase* k = s->k + s->ncase++;
      snprintf(k->name, sizeof k->name, "%s", w[1]);
      snprintf(k->table, sizeof k->table, "%s", w[3]);
      if (num(w[2], &k->speed)) rc = spec_fail(path, ln, "speed is not a number", w[2]);
      k->share = n > 4 && !strcmp(w[4], "share");
    } else if (!strcmp(w[0], "free") && n >= 5 && s->nfree < MAXFREE) {
      /* free NAME LO HI START [UNIT] [of=OTHER] */
      freeParam* p = s->f + s->nfree++;
      snprintf(p->name, sizeof p->name, "%s", w[1]);
      p->other = -1;
      p->line = ln;
      for (int i = 5; i < n; i++) {
        if (!strncmp(w[i], "of=", 3))
          snprintf(p->of, sizeof p->of, "%s", w[i] + 3);
        else
          snprintf(p->unit, sizeof p->unit, "%s", w[i]);
      }
      if (num(w[2], &p->lo) || num(w[3], &p->hi) || num(w[4], &p->start) ||
          !(p->lo < p->start && p->start < p->hi)) {
        rc = spec_fail(path, ln,
                       "expected free NAME LO HI START [UNIT] [of=OTHER], LO < START < HI", w[1]);
      }
    } else if (!strcmp(w[0], "load") && n == 2) {
      /* load FILE: a part file loaded over the built-in model (a path, no ';' or quotes) */
      if (s->nload == 8 || strpbrk(w[1], ";\"'"))
        rc =
            spec_fail(path, ln, "expected load FILE (at most 8; a path without ; or quotes)", w[1]);
      else
        snprintf(s->load[s->nload++], LINELEN, "%s", w[1]);
    } else if (!strcmp(w[0], "set") && n >= 3 && n <= 4) {
      /* set NAME VALUE [UNIT]: held for every evaluation; only a 'set', nothing else runs */
      int ok = strspn(w[1], "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") ==
               strlen(w[1]);
      for (int i = 2; i < n; i++) ok = ok && !strpbrk(w[i], ";\"'");
      size_t m = strlen(s->set);
      if (!ok || m + 4 + strlen(w[1]) + strlen(w[2]) + (n > 3 ? strlen(w[3]) : 0) + 8 > LINELEN)
        rc =
            spec_fail(path, ln, "expected set NAME VALUE [UNIT] (a parameter and its value)", w[1]);
      else
        snprintf(s->set + m, LINELEN - m, "%sset %s %s%s%s", m ? "; " : "", w[1], w[2],
                 n > 3 ? " " : "", n > 3 ? w[3] : "");
    } else if (!strcmp(w[0], "loss") && n == 2) {
      if (!strcmp(w[1], "integral") || !strcmp(w[1], "footprint"))
        s->integral = w[1][0] == 'i';
      else
        rc = spec_fail(path, ln, "expected loss integral|footprint", w[1]);
    } else if (!strcmp(w[0], "choice") && n == 4) {
      /* choice GROUP LABEL SETTING=VALUE,... */
      group* g = NULL;
      for (int i = 0; i < s->ngroup; i++) {
        if (!strcmp(s->g[i].name, w[1])) g = s->g + i;
      }
      if (!g && s->ngroup < MAXGROUP) {
        g = s->g + s->ngroup++;
        snprintf(g->name, sizeof g->name, "%s", w[1]);
      }
      if (!g || g->nalt == MAXALT) {
        rc = spec_fail(path, ln, "too many choices", w[1]);
      } else {
        alt* a = g->a + g->nalt++;
        snprintf(a->label, sizeof a->label, "%s", w[2]);
        if (parse_settings(w[3], a)) rc = spec_fail(path, ln, "expected NAME=VALUE,...", w[3]);
      }
    } else if (n == 2 &&
               (!strcmp(w[0], "hic_share") || !strcmp(w[0], "threshold") ||
                !strcmp(w[0], "simplex") || !strcmp(w[0], "tol") || !strcmp(w[0], "maxeval") ||
                !strcmp(w[0], "restarts") || !strcmp(w[0], "gain"))) {
      double v;
      if (num(w[1], &v)) {
        rc = spec_fail(path, ln, "not a number", w[1]);
      } else if (!strcmp(w[0], "hic_share")) {
        s->hic_share = v;
      } else if (!strcmp(w[0], "threshold")) {
        s->threshold = v;
      } else if (!strcmp(w[0], "simplex")) {
        s->simplex = v;
      } else if (!strcmp(w[0], "tol")) {
        s->tol = v;
      } else if (!strcmp(w[0], "restarts")) {
        s->restarts = (int)v;
      } else if (!strcmp(w[0], "gain")) {
        s->gain = v;
      } else {
        s->maxeval = (int)v;
      }
    } else if (n == 4 && !strcmp(w[0], "corner")) {
      double r, g, k;
      if (num(w[1], &r) || num(w[2], &g) || num(w[3], &k) || !(r >= 0 && r < 0.5) || !(g >= 0) ||
          k != (int)k || k < 1 || k > CORNERMAX) {
        rc = spec_fail(path, ln, "expected corner REL GAIN N (0 <= REL < 0.5, GAIN >= 0, N 1-64)",
                       w[1]);
      } else {
        s->corner_rel = r;
        s->corner_gain = g;
        s->corner_n = (int)k;
      }
    } else {
      rc = spec_fail(path, ln, "unknown or malformed statement", w[0]);
    }
  }
  fclose(f);
  /* shares: of a plain free parameter declared in the spec */
  for (int j = 0; rc == 0 && j < s->nfree; j++) {
    freeParam* p = s->f + j;
    if (!p->of[0]) continue;
    for (int i = 0; i < s->nfree; i++) {
      if (i != j && !strcmp(s->f[i].name, p->of)) p->other = i;
    }
    if (p->other < 0) {
      rc = spec_fail(path, p->line, "share of an undeclared parameter (of=OTHER: a free NAME)",
                     p->of);
    } else if (s->f[p->other].of[0]) {
      rc = spec_fail(path, p->line, "share of a share (of=OTHER: a free parameter of its own)",
                     p->of);
    }
  }
  if (rc == 0 && (s->ncase == 0 || s->nfree == 0)) {
    fprintf(stderr, "calibrate: %s: no training case or no free parameter\n", path);
    rc = -1;
  }
  return rc;
}

/* ---- the paper's grids ---- */

/* load each training table through 'grid load' (strict; the full plane, mirrored) */
static int load_tables(uraCtx* c, spec* s) {
  for (int i = 0; i < s->ncase; i++) {
    trainCase* k = s->k + i;
    if (ura_grid_load(c, k->table)) {
      fprintf(stderr, "calibrate: %s\n", c->err);
      return -1;
    }
    k->paper = c->last.g;
    c->last.g = NULL;
    double sum = 0;
    int n = 0;
    for (long j = 0; j < (long)k->paper->nrow * k->paper->ncol; j++) {
      if (k->paper->cell[j].p > 0) {
        sum += k->paper->cell[j].p;
        n++;
      }
    }
    k->pbar = n ? sum / n : 1;
    ur_grid_summarise(k->paper);
    k->q = k->paper->q > 0 ? k->paper->q : 1;
  }
  return 0;
}

/* ---- one evaluation ---- */

static double to_param(const freeParam* p, double z) {
  return p->lo + (p->hi - p->lo) / (1 + exp(-z));
}

static double to_z(const freeParam* p, double x) {
  return log((x - p->lo) / (p->hi - x));
}

/* the fused P of a simulated cell under injury settings ip, each criterion's in part */
static double cell_p(const urCell* e, const urInjuryParams* ip, double part[urNCRIT]) {
  for (int k = 0; k < urNCRIT; k++) part[k] = 0;
  if (!e || e->status != urCELL_DONE || !e->contact) return 0;
  for (int k = 0; k < urNCRIT; k++) part[k] = ur_criterion(k)->pof(e->val, ip);
  return ur_pof_fuse_used(part, ip);
}

/* the integral of |dP| over the full plane / the paper's Q: the paper's cells (ours at the
   nearest of our cells), then our cells off the paper's grid (the paper's P is 0 there) */
static double case_integral(const trainCase* k, urGrid* ours, const urInjuryParams* ip) {
  urGrid* pg = k->paper;
  double sum = 0, part[urNCRIT];
  for (long j = 0; j < (long)pg->nrow * pg->ncol; j++) {
    const urCell* pc = pg->cell + j;
    sum += fabs(cell_p(ur_grid_find(ours, pc->dpar, pc->dperp), ip, part) - pc->p) * pg->step *
           pg->step;
  }
  for (long j = 0; j < (long)ours->nrow * ours->ncol; j++) {
    const urCell* e = ours->cell + j;
    if (!ur_grid_find(pg, e->dpar, e->dperp)) sum += cell_p(e, ip, part) * ours->step * ours->step;
  }
  return sum / k->q;
}

/* the case's loss (integral, or mean |dP| over the union footprint / the paper's mean P), and
   HIC's share at the centre */
static double case_loss(const spec* s, const trainCase* k, urGrid* ours, const urInjuryParams* ip,
                        double* share) {
  const urGrid* pg = k->paper;
  double sum = 0, w = 0, part[urNCRIT];
  for (long j = 0; !s->integral && j < (long)pg->nrow * pg->ncol; j++) {
    const urCell* pc = pg->cell + j;
    double po = cell_p(ur_grid_find(ours, pc->dpar, pc->dperp), ip, part);
    if (pc->p > 0 || po >= s->threshold) {
      sum += fabs(po - pc->p);
      w += 1;
    }
  }
  double p0 = cell_p(ur_grid_find(ours, 0, 0), ip, part);
  double tot = 0;
  for (int c = 0; c < urNCRIT; c++) tot += ur_criterion_used(c, ip) ? part[c] : 0;
  *share = p0 > 0 && tot > 0 ? part[0] / tot : 1;
  if (s->integral) return case_integral(k, ours, ip);
  return w > 0 ? sum / w / k->pbar : 0;
}
/* (the plain mean |dP| of a case is its loss times the paper's mean P) */

/* what the model gets of free parameter j: its value, or its share of another */
static double model_value(const spec* s, const double* x, int j) {
  return s->f[j].other >= 0 ? x[j] * x[s->f[j].other] : x[j];
}

/* the grids of every training case at the parameters x */
static int run_grids(fit* F, const double* x, urGrid** g) {
  spec* s = F->s;
  uraCtx* c = F->c;
  for (int i = 0; i < s->ncase; i++) {
    char line[4096];
    int n = snprintf(line, sizeof line,
                     "case %s; set wind 0; set face 0; set step 0.05; "
                     "set speed %.17g; set angle 90",
                     s->k[i].name, s->k[i].speed);
    for (int j = 0; j < s->nfree; j++) {
      if (F->use[j]) {
        n += snprintf(line + n, sizeof line - n, "; set %s %.17g", s->f[j].name,
                      model_value(s, x, j));
      }
    }
    if (F->extra[0]) snprintf(line + n, sizeof line - n, "; %s", F->extra);
    if (ura_run_line(c, line) || ura_grid_run(c, 1) || !c->last.g || !c->last.g->complete) {
      fprintf(stderr, "calibrate: case %s: %s\n", s->k[i].name,
              c->err[0] ? c->err : "the grid has failed cells");
      return -1;
    }
    g[i] = c->last.g;
    c->last.g = NULL;
  }
  return 0;
}

/* the best loss over the discrete combinations; combo, per-case parts and shares of the best */
static double score(fit* F, urGrid** g, char* combo, size_t len, double* parts, double* shares) {
  spec* s = F->s;
  int ncomb = 1, idx[MAXGROUP];
  for (int i = 0; i < s->ngroup; i++) ncomb *= s->g[i].nalt;
  double best = INFINITY;
  for (int m = 0; m < ncomb; m++) {
    urInjuryParams ip = F->c->st.injury;
    int r = m;
    for (int i = 0; i < s->ngroup; i++) {
      idx[i] = r % s->g[i].nalt;
      r /= s->g[i].nalt;
      const alt* a = s->g[i].a + idx[i];
      for (int j = 0; j < a->nset; j++) ur_injury_param_set(&ip, a->set[j], a->val[j]);
    }
    double loss = 0, pt[MAXCASE], sh[MAXCASE];
    for (int i = 0; i < s->ncase; i++) {
      pt[i] = case_loss(s, s->k + i, g[i], &ip, sh + i);
      loss += pt[i];
      if (s->k[i].share && sh[i] < s->hic_share) loss += s->hic_share - sh[i];
    }
    if (loss < best) {
      best = loss;
      size_t n = 0;
      combo[0] = 0;
      for (int i = 0; i < s->ngroup && n < len; i++) {
        n += snprintf(combo + n, len - n, "%s%s", i ? "+" : "", s->g[i].a[idx[i]].label);
      }
      memcpy(parts, pt, sizeof pt);
      memcpy(shares, sh, sizeof sh);
    }
  }
  return best;
}

/* ---- the log: every evaluation a row, written now or replayed (-r) ---- */

#define ROWLEN (LINELEN * 4)
#define MAXFLD (1 + MAXFREE + 3 * MAXCASE + 2)

static int row_fields(const spec* s) {
  return 1 + s->nfree + s->ncase * (s->integral ? 3 : 2) + 2;
}

/* split a row at its commas, in place (empty fields kept); the number of fields */
static int split_row(char* row, char** fld) {
  int n = 0;
  row[strcspn(row, "\n")] = 0;
  for (char* c = row; n < MAXFLD;) {
    fld[n++] = c;
    c = strchr(c, ',');
    if (!c) break;
    *c++ = 0;
  }
  return n;
}

/* v in the fewest digits that read back as v to the bit (15 to 17) */
static int exact(char* out, size_t len, double v) {
  int n = 0;
  for (int d = 15; d <= 17; d++) {
    n = snprintf(out, len, ",%.*g", d, v);
    if (strtod(out + 1, NULL) == v || !isfinite(v)) break;
  }
  return n;
}

/* the corner rule (spec 'corner REL GAIN N'): the fit ends once N evaluations in a row had every
   free parameter within REL of its range from a bound and the best loss fell by less than GAIN
   over them. There the logistic coordinates run off to infinity, so the simplex's size test
   cannot end it and a restart cannot leave the corner. */
static void corner(fit* F, const double* x) {
  const spec* s = F->s;
  F->bests[F->neval % (CORNERMAX + 1)] = F->best;
  if (s->corner_n <= 0) return;
  int at = 1;
  for (int j = 0; j < s->nfree; j++) {
    double lo = s->f[j].lo, hi = s->f[j].hi, tol = s->corner_rel * (hi - lo);
    at = at && (x[j] - lo <= tol || hi - x[j] <= tol);
  }
  F->corner_run = at ? F->corner_run + 1 : 0;
  if (F->corner_run >= s->corner_n && F->neval > s->corner_n) {
    double before = F->bests[(F->neval - s->corner_n) % (CORNERMAX + 1)];
    if (before - F->best < s->corner_gain) F->corner_done = 1;
  }
}

/* a logged row (written now or replayed) into the count and the best; its loss */
static double account(fit* F, const char* row) {
  spec* s = F->s;
  char buf[ROWLEN], *fld[MAXFLD];
  snprintf(buf, sizeof buf, "%s", row);
  int n = split_row(buf, fld), per = s->integral ? 3 : 2;
  double x[MAXFREE], parts[MAXCASE], shares[MAXCASE];
  for (int j = 0; j < s->nfree; j++) x[j] = strtod(fld[1 + j], NULL);
  for (int i = 0; i < s->ncase; i++) {
    parts[i] = strtod(fld[1 + s->nfree + per * i], NULL);
    shares[i] = strtod(fld[s->nfree + per * (i + 1)], NULL);
  }
  double loss = strtod(fld[n - 1], NULL);
  F->neval++;
  if (!isfinite(loss)) F->failed++;
  if (loss < F->best) {
    F->best = loss;
    memcpy(F->bestx, x, sizeof(double) * s->nfree);
    snprintf(F->bestcombo, sizeof F->bestcombo, "%s", fld[n - 2]);
    memcpy(F->bestpart, parts, sizeof parts);
    memcpy(F->bestshare, shares, sizeof shares);
  }
  corner(F, x);
  return loss;
}

/* the next logged row of a resumed fit, if its point is x to the bit (else stop: not the same
   fit); its loss */
static double replay(fit* F, const double* x) {
  spec* s = F->s;
  const char* row = F->rows[F->neval];
  char buf[ROWLEN], *fld[MAXFLD];
  snprintf(buf, sizeof buf, "%s", row);
  int n = split_row(buf, fld);
  int bad = n != row_fields(s) || atoi(fld[0]) != F->neval + 1 ? 0 : -1;
  for (int j = 0; bad < 0 && j < s->nfree; j++) {
    double v = strtod(fld[1 + j], NULL);
    if (memcmp(&v, x + j, sizeof v)) bad = 1 + j;
  }
  if (bad >= 0) {
    char what[LINELEN];
    if (bad)
      snprintf(what, sizeof what, "its %s is %s, the resumed fit's %.17g", s->f[bad - 1].name,
               fld[bad], x[bad - 1]);
    else
      snprintf(what, sizeof what, "not evaluation %d of this spec (number or columns)",
               F->neval + 1);
    fprintf(stderr,
            "calibrate: %s:%d: row %d differs: %s; resume only with the spec, code and "
            "arguments that wrote it\n",
            F->resume, F->rowline[F->neval], F->neval + 1, what);
    exit(1);
  }
  fputs(row, F->log);
  fflush(F->log);
  double loss = account(F, row);
  fprintf(stderr, "calibrate: %4d  loss %.5f (best %.5f) replayed\n", F->neval, loss, F->best);
  return loss;
}

static double evaluate(fit* F, const double* x) {
  spec* s = F->s;
  if (F->neval < F->nrows) return replay(F, x);
  urGrid* g[MAXCASE] = {0};
  char combo[128] = "";
  double parts[MAXCASE] = {0}, shares[MAXCASE] = {0};
  double loss = INFINITY;
  if (run_grids(F, x, g) == 0) loss = score(F, g, combo, sizeof combo, parts, shares);
  for (int i = 0; i < s->ncase; i++) ur_grid_free(g[i]);

  /* log every evaluation: the values and the total read back to the bit, so a resume can
     replay them */
  char row[ROWLEN];
  int n = snprintf(row, sizeof row, "%d", F->neval + 1);
  for (int j = 0; j < s->nfree; j++) n += exact(row + n, sizeof row - n, x[j]);
  for (int i = 0; i < s->ncase; i++) {
    n += snprintf(row + n, sizeof row - n, ",%.6f", parts[i]);
    if (s->integral) n += snprintf(row + n, sizeof row - n, ",%.6f", parts[i] * s->k[i].q);
    n += snprintf(row + n, sizeof row - n, ",%.4f", shares[i]);
  }
  n += snprintf(row + n, sizeof row - n, ",%s", combo);
  n += exact(row + n, sizeof row - n, loss);
  snprintf(row + n, sizeof row - n, "\n");
  fputs(row, F->log);
  fflush(F->log);
  loss = account(F, row);
  fprintf(stderr, "calibrate: %4d  loss %.5f (best %.5f)\n", F->neval, loss, F->best);
  return loss;
}

static double nm_f(const gsl_vector* z, void* ctx) {
  fit* F = ctx;
  double x[MAXFREE];
  /* ended by the corner rule: the iteration's remaining points are not run (the best loss, a
     finite value the simplex takes quietly; the loop stops after this iteration) */
  if (F->corner_done) return F->best;
  for (int j = 0; j < F->s->nfree; j++) x[j] = to_param(F->s->f + j, gsl_vector_get(z, j));
  return evaluate(F, x);
}

/* ---- output ---- */

static void write_result(fit* F, const char* dir, double seconds) {
  spec* s = F->s;
  char path[LINELEN + 32];
  snprintf(path, sizeof path, "%s/result.txt", dir);
  FILE* f = fopen(path, "w");
  if (!f) {
    fprintf(stderr, "calibrate: %s: %s\n", path, strerror(errno));
    return;
  }
  FILE* outs[2] = {f, stdout};
  for (int o = 0; o < 2; o++) {
    FILE* out = outs[o];
    fprintf(out, "# calibrate: %d evaluations (%d failed) in %.0f s; best loss %.5f\n", F->neval,
            F->failed, seconds, F->best);
    if (F->corner_done)
      fprintf(out,
              "# ended by the corner rule: %d evaluations in a row at a corner of the bounds, "
              "the best loss falling by less than %g over the last %d\n",
              F->corner_run, s->corner_gain, s->corner_n);
    for (int i = 0; i < s->ncase; i++) {
      const trainCase* k = s->k + i;
      if (s->integral) {
        fprintf(out,
                "# case %s: integral |dP| / Q = %.4f (integral |dP| %.4f m^2, the paper's Q "
                "%.4f m^2)",
                k->name, F->bestpart[i], F->bestpart[i] * k->q, k->q);
      } else {
        fprintf(out,
                "# case %s: mean |dP| / mean P = %.4f (mean |dP| %.4f, the paper's mean P "
                "%.4f)",
                k->name, F->bestpart[i], F->bestpart[i] * k->pbar, k->pbar);
      }
      fprintf(out, ", HIC share at (0,0) %.3f%s\n", F->bestshare[i],
              k->share ? " (constrained)" : "");
    }
    fprintf(out, "# injury choices: %s\n", F->bestcombo[0] ? F->bestcombo : "none");
    for (int j = 0; j < s->nfree; j++) {
      const freeParam* p = s->f + j;
      if (p->other >= 0) fprintf(out, "# share %s/%s %.6g\n", p->name, p->of, F->bestx[j]);
      fprintf(out, "set %s %.6g\n", p->name, model_value(s, F->bestx, j));
    }
  }
  fclose(f);
}

/* ---- the log's header ---- */

/* the spec's commit: HEAD's hash if the file is as HEAD has it, else "modified" */
static void spec_commit(const char* path, char* out, size_t len) {
  char dir[LINELEN], got[2][64] = {"", ""};
  snprintf(dir, sizeof dir, "%s", path);
  char* slash = strrchr(dir, '/');
  if (slash) *slash = 0;
  setenv("CALIBRATE_DIR", slash ? (dir[0] ? dir : "/") : ".", 1);
  setenv("CALIBRATE_FILE", slash ? slash + 1 : path, 1);
  FILE* p = popen(
      "cd \"$CALIBRATE_DIR\" 2>/dev/null && git rev-parse -q --verify HEAD "
      "2>/dev/null && { git ls-files --error-unmatch -- \"$CALIBRATE_FILE\" "
      ">/dev/null 2>&1 && git diff --quiet HEAD -- \"$CALIBRATE_FILE\" >/dev/null "
      "2>&1 && echo same || echo modified; }",
      "r");
  for (int i = 0; p && i < 2 && fgets(got[i], sizeof got[i], p); i++) {
    got[i][strcspn(got[i], "\n")] = 0;
  }
  if (p) pclose(p);
  if (!strcmp(got[1], "same"))
    snprintf(out, len, "commit %s", got[0]);
  else if (got[0][0])
    snprintf(out, len, "modified (not as in HEAD %s)", got[0]);
  else
    snprintf(out, len, "modified (not in a git work tree)");
}

static void utc_now(char* out, size_t len) {
  time_t t = time(NULL);
  struct tm tm;
  gmtime_r(&t, &tm);
  strftime(out, len, "%Y-%m-%dT%H:%M:%SZ", &tm);
}

/* the column line: eval, the values (a share as NAME/OTHER), per case its loss (with
   `integral` its integral, m^2) and HIC share, the choices, the total */
static void columns(const spec* s, char* out, size_t len) {
  size_t n = snprintf(out, len, "eval");
  for (int j = 0; j < s->nfree && n < len; j++) {
    n += snprintf(out + n, len - n, ",%s%s%s", s->f[j].name, s->f[j].of[0] ? "/" : "", s->f[j].of);
  }
  for (int i = 0; i < s->ncase && n < len; i++) {
    n += snprintf(out + n, len - n, ",loss_%s", s->k[i].name);
    if (s->integral) n += snprintf(out + n, len - n, ",integral_%s", s->k[i].name);
    n += snprintf(out + n, len - n, ",hic_share_%s", s->k[i].name);
  }
  if (n < len) snprintf(out + n, len - n, ",choices,loss\n");
}

/* -r: the header lines of the log to resume (kept) and its rows (replayed); a row cut short
   (no newline: the fit was stopped while writing it) is dropped */
static int resume_read(fit* F, const char* cols, char** head) {
  FILE* f = fopen(F->resume, "r");
  if (!f) {
    fprintf(stderr, "calibrate: %s: %s\n", F->resume, strerror(errno));
    return -1;
  }
  char* line = NULL;
  size_t cap = 0, n = 0;
  int ln = 0, seen = 0, rc = 0;
  while (rc == 0 && getline(&line, &cap, f) > 0) {
    ln++;
    if (!seen && line[0] == '#') {
      char* more = realloc(*head, n + strlen(line) + 1);
      if (!more) {
        fprintf(stderr, "calibrate: %s: out of memory\n", F->resume);
        rc = -1;
      } else {
        *head = more;
        n += sprintf(more + n, "%s", line);
      }
    } else if (!seen) {
      seen = 1;
      if (strcmp(line, cols)) {
        fprintf(stderr, "calibrate: %s:%d: not this spec's columns (expected %.*s)\n", F->resume,
                ln, (int)strcspn(cols, "\n"), cols);
        rc = -1;
      }
    } else if (line[0] != '#' && line[strlen(line) - 1] == '\n') {
      char** rows = realloc(F->rows, (F->nrows + 1) * sizeof *rows);
      int* at = realloc(F->rowline, (F->nrows + 1) * sizeof *at);
      if (rows) F->rows = rows;
      if (at) F->rowline = at;
      if (!rows || !at || !(F->rows[F->nrows] = strdup(line))) {
        fprintf(stderr, "calibrate: %s: out of memory\n", F->resume);
        rc = -1;
      } else {
        F->rowline[F->nrows++] = ln;
      }
    }
  }
  free(line);
  fclose(f);
  if (rc == 0 && !seen) {
    fprintf(stderr, "calibrate: %s: no column line 'eval,...': not a log of calibrate\n",
            F->resume);
    rc = -1;
  }
  return rc;
}

/* the command line's NAME/OTHER=SHARE: the start of that share */
static int set_share(const char* specpath, spec* s, const char* arg, const char* eq) {
  double v;
  for (int j = 0; j < s->nfree; j++) {
    const freeParam* p = s->f + j;
    size_t ln = strlen(p->name);
    if (p->other >= 0 && !strncmp(arg, p->name, ln) && arg[ln] == '/' &&
        !strncmp(arg + ln + 1, p->of, eq - arg - ln - 1) && arg + ln + 1 + strlen(p->of) == eq) {
      if (num(eq + 1, &v)) break;
      if (!(p->lo < v && v < p->hi)) {
        fprintf(stderr, "calibrate: '%s': outside the share's bounds %g .. %g (%s:%d)\n", arg,
                p->lo, p->hi, specpath, p->line);
        return -1;
      }
      s->f[j].start = v;
      return 0;
    }
  }
  fprintf(stderr,
          "calibrate: '%s': %s declares no such share (NAME/OTHER=SHARE, a number, for a "
          "'free NAME LO HI START of=OTHER')\n",
          arg, specpath);
  return -1;
}

int main(int argc, char** argv) {
  const char* specpath = "src/models/calibrate.spec";
  const char* dir = "build/calibration";
  int maxeval = -1, once = 0, shipped = 0, nload = 0, opt;
  const char* load[8];
  static spec s;
  static uraCtx c;
  fit F = {&c, &s, NULL, 0, INFINITY, {0}, "", {0}, {0}, "", 0, {0}, NULL, NULL, NULL, 0};
  while ((opt = getopt(argc, argv, "s:o:n:r:eml:")) != -1) {
    switch (opt) {
    case 's': specpath = optarg; break;
    case 'o': dir = optarg; break;
    case 'n': maxeval = atoi(optarg); break;
    case 'r': F.resume = optarg; break;
    case 'e': once = 1; break;
    case 'm': shipped = 1; break;
    case 'l':
      if (nload < 8) load[nload++] = optarg;
      break;
    default:
      fprintf(stderr,
              "usage: calibrate [-s SPEC] [-o DIR] [-n MAXEVAL] [-r LOG] [-e [-m]] [-l FILE]... "
              "[NAME=VALUE | NAME/OTHER=SHARE ...]\n");
      return 2;
    }
  }
  if (spec_read(specpath, &s)) return 1;
  snprintf(F.extra, sizeof F.extra, "%s", s.set); /* the spec's held settings, then the line's */
  for (int i = optind; i < argc; i++) {
    char* eq = strchr(argv[i], '=');
    if (!eq) {
      fprintf(stderr, "calibrate: '%s': expected NAME=VALUE\n", argv[i]);
      return 2;
    }
    if (memchr(argv[i], '/', eq - argv[i])) {
      if (set_share(specpath, &s, argv[i], eq)) return 2;
      continue;
    }
    size_t n = strlen(F.extra);
    snprintf(F.extra + n, sizeof F.extra - n, "%sset %.*s %s", n ? "; " : "", (int)(eq - argv[i]),
             argv[i], eq + 1);
  }
  if (maxeval > 0) s.maxeval = maxeval;
  char cols[ROWLEN], *head = NULL, commit[128], now[32];
  columns(&s, cols, sizeof cols);
  if (F.resume && resume_read(&F, cols, &head)) return 1;
  spec_commit(specpath, commit, sizeof commit);
  utc_now(now, sizeof now);
  ura_init(&c); /* GSL failures as return codes (ur_init) */
  c.out = fopen("/dev/null", "w");
  if (!c.out || ura_models_init(&c) || load_tables(&c, &s)) return 1;
  for (int i = 0; i < s.nload + nload; i++) { /* the spec's loads, then -l's */
    char cmd[LINELEN + 16];
    snprintf(cmd, sizeof cmd, "model load %s", i < s.nload ? s.load[i] : load[i - s.nload]);
    if (ura_run_line(&c, cmd)) {
      fprintf(stderr, "calibrate: %s\n", c.err);
      return 1;
    }
  }
  mkdir(dir, 0777);
  char path[LINELEN + 32];
  snprintf(path, sizeof path, "%s/log.csv", dir);
  F.log = fopen(path, "w");
  if (!F.log) {
    fprintf(stderr, "calibrate: %s: %s\n", path, strerror(errno));
    return 1;
  }
  /* the header: the spec's commit and the start, every resume a line of its own */
  if (F.resume) {
    fprintf(F.log, "%s# resumed %s from %s after %d rows; spec %s: %s\n", head ? head : "", now,
            F.resume, F.nrows, specpath, commit);
    free(head);
  } else {
    fprintf(F.log, "# spec %s: %s\n# started %s\n", specpath, commit, now);
  }
  fputs(cols, F.log);

  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  double x[MAXFREE];
  const urModel* model = ura_model(&c);
  if (!model) {
    fprintf(stderr, "calibrate: %s\n", c.err);
    return 1;
  }
  for (int j = 0; j < s.nfree; j++) {
    F.use[j] = !shipped || ur_name_param(model, s.f[j].name) >= 0;
    x[j] = shipped ? ur_model_param(model, s.f[j].name, s.f[j].start) : s.f[j].start;
    if (!F.use[j]) fprintf(stderr, "calibrate: the model has no %s; left out\n", s.f[j].name);
  }
  for (int j = 0; j < s.nfree; j++) { /* -m: a share is the model's ratio */
    int o = s.f[j].other;
    if (o < 0 || !shipped) continue;
    F.use[j] = F.use[j] && F.use[o] && x[o] != 0;
    x[j] = F.use[j] ? x[j] / x[o] : s.f[j].start;
  }
  if (once) {
    evaluate(&F, x);
  } else {
    /* Nelder-Mead in the logistic coordinates, from the spec's start; then a fresh simplex
       around the best point (the simplex collapses early in many dimensions), again while a
       restart lowers the loss by at least `gain` */
    gsl_multimin_function fn = {nm_f, (size_t)s.nfree, &F};
    gsl_vector* z = gsl_vector_alloc(s.nfree);
    gsl_vector* step = gsl_vector_alloc(s.nfree);
    gsl_multimin_fminimizer* nm =
        gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, s.nfree);
    double before = INFINITY;
    for (int run = 0;
         run <= s.restarts && !F.corner_done && (run == 0 || before - F.best >= s.gain); run++) {
      before = F.best;
      for (int j = 0; j < s.nfree; j++) {
        gsl_vector_set(z, j, to_z(s.f + j, run ? F.bestx[j] : x[j]));
        gsl_vector_set(step, j, s.simplex);
      }
      fprintf(F.log, "# simplex %d from evaluation %d\n", run + 1, F.neval + 1);
      gsl_multimin_fminimizer_set(nm, &fn, z, step);
      for (int n0 = F.neval; F.neval - n0 < s.maxeval;) {
        if (gsl_multimin_fminimizer_iterate(nm) || F.corner_done) break;
        if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(nm), s.tol) == GSL_SUCCESS) break;
      }
    }
    gsl_multimin_fminimizer_free(nm);
    gsl_vector_free(z);
    gsl_vector_free(step);
  }
  clock_gettime(CLOCK_MONOTONIC, &t1);
  fclose(F.log);
  write_result(&F, dir, (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec));
  for (int i = 0; i < F.nrows; i++) free(F.rows[i]); /* the replayed log's rows */
  free(F.rows);
  free(F.rowline);
  return isfinite(F.best) ? 0 : 1;
}
