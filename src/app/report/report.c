/* report.c: report FILE.html, the study as one self-contained HTML file a reviewer reads top to
 * bottom: the question, the answer (SORA 2.5 iGRC, M2 evidence, risk per flight hour, tails,
 * convergence, from the last results of the session), the evidence (every kept result with its
 * command, notes, table, settings and figures), the warnings, the assumptions, the model's
 * validity (the paper's Table 17 beside this session's grids, the convergence checks, the physics
 * the test suite proves, the known limits) and appendices (inputs, the model texts in full with
 * their hashes, sources). Built as a libxml2 HTML tree and written by its serializer, so every
 * text is escaped by the library; figures are data: images (report_fig.c); no script, no link
 * outside the file; print styles for a clean PDF. */
#include <libxml/HTMLtree.h>
#include <libxml/xmlerror.h>
#include <libxml/xmlstring.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>
#include <time.h>

#include "report.h"
#include "uasimpact/sora25.h"

#define X(s) ((const xmlChar*)(s))

static const char* const css =
    "body{font-family:Helvetica,Arial,sans-serif;font-size:11pt;line-height:1.4;max-width:60em;"
    "margin:1.5em auto;padding:0 1em;color:#111}"
    "h1{font-size:18pt;border-bottom:2px solid #333}h2{font-size:14pt;margin-top:1.6em;"
    "border-bottom:1px solid #999}h3{font-size:12pt;margin-top:1.2em}"
    "table{border-collapse:collapse;margin:.5em 0;font-size:9pt}"
    "th,td{border:1px solid #bbb;padding:2px 5px;text-align:right}th{background:#eee}"
    "td.l,th.l{text-align:left}ul.notes{font-size:9pt;color:#333}li.warn{color:#a00}"
    "code,pre{font-family:Menlo,Consolas,monospace;font-size:8.5pt}"
    "pre{background:#f6f6f6;padding:.5em;white-space:pre-wrap;word-break:break-all}"
    "figure{margin:1em 0;page-break-inside:avoid}figure img{max-width:100%;height:auto}"
    "figcaption{font-size:9pt;color:#333}.answer{background:#f3f7ff;border:1px solid #9ab;"
    "padding:.5em 1em}.cells td{padding:0 2px;font-size:7pt;min-width:1.6em}"
    ".meta td{text-align:left}.warnbox{background:#fff3f3;border:1px solid #d99;padding:.3em 1em}"
    "@media print{body{max-width:none;margin:0;font-size:10pt}h2{page-break-after:avoid}"
    "h3{page-break-after:avoid}table,figure,pre{page-break-inside:avoid}"
    "section{page-break-before:auto}}";

/* ---- tree helpers: every text goes through libxml2 ---- */

/* text as XML can hold it: well-formed UTF-8 and the tab, line feed and carriage return kept,
   any other control byte or byte that is not UTF-8 (a model file in Latin-1) replaced by U+FFFD;
   NULL when text needs no change, else a new string the caller frees */
static char* xml_clean(const char* text) {
  int ok = 1;
  for (const unsigned char* p = (const unsigned char*)text; *p && ok; p++) {
    ok = *p >= 0x20 || *p == '\t' || *p == '\n' || *p == '\r';
  }
  if (ok && xmlCheckUTF8(X(text))) {
    return NULL;
  }
  size_t n = strlen(text);
  char* out = malloc(3 * n + 1);
  if (!out) {
    return NULL;
  }
  size_t k = 0;
  const unsigned char* p = (const unsigned char*)text;
  while (*p) {
    int len = (int)strlen((const char*)p);
    int c = *p < 0x80 ? *p : xmlGetUTF8Char(p, &len);
    if (*p < 0x80) {
      len = 1;
    }
    if (c < 0 || (c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f) {
      memcpy(out + k, "\xef\xbf\xbd", 3); // U+FFFD
      k += 3;
      p += c < 0 ? 1 : len;
      continue;
    }
    memcpy(out + k, p, (size_t)len);
    k += (size_t)len;
    p += len;
  }
  out[k] = 0;
  return out;
}

static xmlNodePtr el(xmlNodePtr parent, const char* tag, const char* text) {
  char* c = text ? xml_clean(text) : NULL;
  xmlNodePtr n = xmlNewTextChild(parent, NULL, X(tag), text ? X(c ? c : text) : NULL);
  free(c);
  return n;
}

static xmlNodePtr elf(xmlNodePtr parent, const char* tag, const char* fmt, ...)
    __attribute__((format(printf, 3, 4)));
static xmlNodePtr elf(xmlNodePtr parent, const char* tag, const char* fmt, ...) {
  char buf[4000];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  return el(parent, tag, buf);
}

static void attr(xmlNodePtr n, const char* name, const char* value) {
  char* c = xml_clean(value);
  xmlNewProp(n, X(name), X(c ? c : value));
  free(c);
}

static void attrf(xmlNodePtr n, const char* name, const char* fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void attrf(xmlNodePtr n, const char* name, const char* fmt, ...) {
  char buf[200];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  attr(n, name, buf);
}

/* a section with its id and heading */
static xmlNodePtr section(xmlNodePtr body, const char* id, const char* title) {
  xmlNodePtr s = el(body, "section", NULL);
  attr(s, "id", id);
  el(s, "h2", title);
  return s;
}

/* a link inside the file */
static void anchor(xmlNodePtr parent, const char* href, const char* text) {
  xmlNodePtr a = el(parent, "a", text);
  attr(a, "href", href);
}

/* ---- reading the kept tables ---- */

static int colix(const uraRepTable* t, const char* name) {
  for (int j = 0; j < t->ncol; j++) {
    if (!strcmp(t->names[j], name)) return j;
  }
  return -1;
}

static const char* cell(const uraRepTable* t, int row, const char* name) {
  int j = colix(t, name);
  return j >= 0 && row >= 0 && row < t->nrow ? t->cells[row * t->ncol + j] : NULL;
}

/* the row whose column a is va (and b is vb when b) */
static int findrow(const uraRepTable* t, const char* a, const char* va, const char* b,
                   const char* vb) {
  int ja = colix(t, a), jb = b ? colix(t, b) : -1;
  if (ja < 0 || (b && jb < 0)) return -1;
  for (int r = 0; r < t->nrow; r++) {
    if (strcmp(t->cells[r * t->ncol + ja], va)) continue;
    if (b && strcmp(t->cells[r * t->ncol + jb], vb)) continue;
    return r;
  }
  return -1;
}

/* the last kept table of a command whose first column is first (and holding column has) */
static int last_table(const uraReport* r, const char* name, const char* first, const char* has) {
  for (int i = r->nt - 1; i >= 0; i--) {
    const uraRepTable* t = &r->t[i];
    if (strcmp(t->name, name) || t->failed || !t->ncol || strcmp(t->names[0], first)) continue;
    if (has && colix(t, has) < 0) continue;
    return i;
  }
  return -1;
}

/* a kept table after index i from the same command line, whose first column is first */
static int sibling(const uraReport* r, int i, const char* first) {
  for (int k = i + 1; k < r->nt && !strcmp(r->t[k].cmd, r->t[i].cmd); k++) {
    if (!strcmp(r->t[k].names[0], first)) return k;
  }
  return -1;
}

/* ---- pieces ---- */

static void data_table(xmlNodePtr parent, const uraRepTable* t, int maxrow) {
  xmlNodePtr tb = el(parent, "table", NULL);
  xmlNodePtr tr = el(tb, "tr", NULL);
  for (int j = 0; j < t->ncol; j++) el(tr, "th", t->names[j]);
  int n = t->nrow < maxrow ? t->nrow : maxrow;
  for (int r = 0; r < n; r++) {
    tr = el(tb, "tr", NULL);
    for (int j = 0; j < t->ncol; j++) {
      xmlNodePtr td = el(tr, "td", t->cells[r * t->ncol + j]);
      if (j == 0) attr(td, "class", "l");
    }
  }
  if (t->nrow > n) {
    elf(parent, "p", "(%d more rows not shown; the command prints them all)", t->nrow - n);
  }
}

/* the paper's coloured table of P per cell (percent, the viewer's bands) */
static void cell_table(xmlNodePtr parent, const uraRepGrid* rg) {
  const urGrid* g = &rg->g;
  xmlNodePtr tb = el(parent, "table", NULL);
  attr(tb, "class", "cells");
  xmlNodePtr tr = el(tb, "tr", NULL);
  el(tr, "th", "dpar \\ dperp");
  for (int j = 0; j < g->ncol; j++) elf(tr, "th", "%.3g", g->perp_min + j * g->step);
  for (int i = 0; i < g->nrow; i++) {
    tr = el(tb, "tr", NULL);
    elf(tr, "th", "%.3g", g->par_max - i * g->step);
    for (int j = 0; j < g->ncol; j++) {
      const urCell* c = &g->cell[(size_t)i * g->ncol + j];
      int fin = rg->diff || c->status == urCELL_DONE || c->status == urCELL_NOCONTACT;
      double p = 100 * c->p;
      xmlNodePtr td = fin ? elf(tr, "td", "%.0f", p) : el(tr, "td", "?");
      const char* bg;
      if (rg->diff)
        bg = p > 0.5 ? "#f4a582" : p < -0.5 ? "#92c5de" : "#f7f7f7";
      else
        bg = !fin                  ? "#cccccc"
             : p >= uraBAND_SEVERE ? "#d7191c"
             : p >= uraBAND_HIGH   ? "#ff9000"
             : p >= uraBAND_MED    ? "#ffe000"
             : p > 0               ? "#fff3b0"
                                   : "#ffffff";
      attrf(td, "style", "background:%s", bg);
    }
  }
}

static void figure(uraCtx* c, xmlNodePtr parent, const char* uri, const char* caption,
                   const char* id) {
  xmlNodePtr f = el(parent, "figure", NULL);
  attr(f, "id", id);
  if (uri) {
    xmlNodePtr img = el(f, "img", NULL);
    attr(img, "src", uri);
    attr(img, "alt", caption);
  } else {
    elf(f, "p", "figure not drawn: %s", c->err);
  }
  el(f, "figcaption", caption);
}

/* ---- the sections ---- */

static void meta(uraCtx* c, xmlNodePtr body) {
  struct utsname u;
  char when[64], machine[400] = "unknown";
  time_t now = time(NULL);
  strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S %Z", localtime(&now));
  if (uname(&u) == 0) {
    snprintf(machine, sizeof machine, "%s (%s %s, %s)", u.nodename, u.sysname, u.release,
             u.machine);
  }
  xmlNodePtr t = el(body, "table", NULL);
  attr(t, "class", "meta");
  const char* rows[][2] = {
      {"program", ura_version()}, {"date", when}, {"machine", machine}, {NULL, NULL}};
  for (int i = 0; rows[i][0]; i++) {
    xmlNodePtr tr = el(t, "tr", NULL);
    el(tr, "th", rows[i][0]);
    xmlNodePtr td = el(tr, "td", rows[i][1]);
    attr(td, "class", "l");
  }
  xmlNodePtr tr = el(t, "tr", NULL);
  el(tr, "th", "threads");
  elf(tr, "td", "%.0f (results do not depend on it)", c->st.threads);
  tr = el(t, "tr", NULL);
  el(tr, "th", "model");
  char buf[1200];
  size_t k = 0;
  buf[0] = 0;
  for (int i = 0; i < c->npart && k < sizeof buf; i++) {
    unsigned long long h = ura_fnv(uraFNV0, c->part[i].text, strlen(c->part[i].text));
    k += (size_t)snprintf(buf + k, sizeof buf - k, "%s%s %016llx", i ? ", " : "", c->part[i].name,
                          h);
  }
  xmlNodePtr td = elf(tr, "td", "parts (FNV-1a 64 of each text, in full in Appendix B): %s", buf);
  attr(td, "class", "l");
}

static void question(uraCtx* c, xmlNodePtr body) {
  xmlNodePtr s = section(body, "question", "1. Question");
  const uraRiskSet* r = &c->st.risk;
  char bands[400];
  size_t k = 0;
  bands[0] = 0;
  for (int i = 0; i < r->npop && k < sizeof bands; i++) {
    k += (size_t)snprintf(bands + k, sizeof bands - k, "%s%g", i ? ", " : "", r->pop_density[i]);
  }
  /* what it carries, as risk and sora count it: a parachute when area_chute > 0, an airbag as a
     device when bag_bottom or bag_front switches it (uasimpact(1), RISK FIGURES) */
  urDeploy dep;
  int bag[urMAXBAGS];
  char carries[300];
  if (ura_risk_devices(c, &c->st, &dep, bag)) dep.chute = 0, dep.nbag = 0;
  if (!dep.chute)
    snprintf(carries, sizeof carries, "no parachute (area_chute 0) and no deployable airbag");
  else if (!dep.nbag)
    snprintf(carries, sizeof carries, "a parachute deploying with probability %g, no airbag",
             r->p_chute);
  else
    snprintf(carries, sizeof carries,
             "a parachute deploying with probability %g and %d airbag%s deploying with "
             "probability %g each",
             r->p_chute, dep.nbag, dep.nbag == 1 ? "" : "s", r->p_bag);
  uraSora25 s25;
  ura_sora25_inputs(c, 0, &s25);
  elf(s, "p",
      "Does the drone of case %s (%g kg; width %g m, length %g m%s), carrying %s, keep the "
      "expected number of ground fatalities per flight hour at or below the target level of "
      "safety %g per flight hour over the population densities %s ppl/km^2, and which SORA 2.5 "
      "intrinsic ground-risk class and M2 credit (effects of ground impact reduced) does the "
      "simulation support?",
      c->st.casename, c->st.descent.mass, c->st.para.width, c->st.para.length,
      s25.dim_ra3 ? ": the workbench's defaults, the RA3's, not this drone's (warning)" : "",
      carries, r->tlos, bands);
  el(s, "p",
     "The answer below is read from the last results of the session; every number it quotes is "
     "in the evidence with its command, settings and notes.");
}

/* the text of the first note of t beginning with head, from the first from in it (the whole
   note when from is NULL); NULL when there is none */
static const char* note_from(const uraRepTable* t, const char* head, const char* from) {
  for (int k = 0; k < t->nnote; k++) {
    if (strncmp(t->notes[k], head, strlen(head))) continue;
    return from ? strstr(t->notes[k], from) : t->notes[k];
  }
  return NULL;
}

static void answer(uraCtx* c, xmlNodePtr body, const uraReport* r) {
  xmlNodePtr s = section(body, "answer", "2. Answer");
  xmlNodePtr box = el(s, "div", NULL);
  attr(box, "class", "answer");
  xmlNodePtr ul = el(box, "ul", NULL);
  int so = last_table(r, "sora", "case", "igrc_sora25");
  if (so < 0) {
    el(ul, "li",
       "No SORA answer: the session ran no sora. Run sora (or montecarlo N and sora mc) before "
       "report.");
  } else {
    const uraRepTable* t = &r->t[so];
    const char* g = cell(t, 0, "igrc_sora25");
    const char* basis = note_from(t, "igrc_sora25: ", "column ");
    const char* dimwarn = note_from(t, "warning: the characteristic dimension", NULL);
    elf(ul, "li",
        "Intrinsic ground-risk class for the submission (SORA 2.5 Table 2, by characteristic "
        "dimension and maximum speed at the highest density): %s%s; basis: %s%s. Command: %s.",
        g ? g : "?", g && !strcmp(g, "grey") ? " (not part of SORA: certified category)" : "",
        basis ? basis : "not stated", dimwarn ? " (warning: not the drone's dimension, 3.2)" : "",
        t->cmd);
    int rq = t->nrow >= 3 ? 2 : 0;
    const char* at = note_from(t, "SORA 2.5 at ", "SORA 2.5 at ");
    char atb[200];
    snprintf(atb, sizeof atb, "%s", at ? at + strlen("SORA 2.5 at ") : "?");
    atb[strcspn(atb, ":")] = 0; /* "D ppl/km^2, TLOS T /h, compensation C" */
    if (rq)
      elf(ul, "li",
          "Quantitative iGRC from Q (Annex F's formula at %s, clamped into Table 2; supports, "
          "does not replace, the table's class): %s for case %s, %s unmitigated (Q %s and %s "
          "m^2).",
          atb, cell(t, rq, "igrc_quant") ? cell(t, rq, "igrc_quant") : "?", cell(t, rq, "case"),
          cell(t, 0, "igrc_quant") ? cell(t, 0, "igrc_quant") : "?", cell(t, rq, "ca"),
          cell(t, 0, "ca"));
    else
      elf(ul, "li",
          "Quantitative iGRC from Q (Annex F's formula at %s, clamped into Table 2; supports, "
          "does not replace, the table's class): %s for the drone as it is (Q %s m^2; no "
          "mitigated design to compare).",
          atb, cell(t, 0, "igrc_quant") ? cell(t, 0, "igrc_quant") : "?", cell(t, 0, "ca"));
    int m2 = sibling(r, so, "quantity");
    if (m2 >= 0) {
      const uraRepTable* m = &r->t[m2];
      int row = findrow(m, "quantity", "q", NULL, NULL);
      const char* lv = cell(m, row, "m2_integrity");
      int none = !lv || !strcmp(lv, "none");
      char claim[600];
      if (none)
        snprintf(claim, sizeof claim,
                 "below the about one order of magnitude (factor 10, 90 %%) that integrity "
                 "criterion #1 asks for at medium: no M2 credit");
      else
        snprintf(claim, sizeof claim,
                 "the reduction that integrity criterion #1 asks for at level %s (lower bound: "
                 "%s); the rest of criterion #1 (activation elements, a failure of the "
                 "mitigation not degrading safety%s), criteria #2 and #3 and the assurance are "
                 "not shown by a simulation",
                 lv, cell(m, row, "m2_lo95") ? cell(m, row, "m2_lo95") : "?",
                 strcmp(lv, "high") ? "" : ", automated activation");
      const char *lo = cell(m, row, "lo95"), *hi = cell(m, row, "hi95");
      char iv[160];
      if (lo && hi && strcmp(lo, hi))
        snprintf(iv, sizeof iv, "95 %% interval %s to %s", lo, hi);
      else
        snprintf(iv, sizeof iv, "deterministic, no interval: 'sora mc' gives one");
      elf(ul, "li",
          "M2 evidence: Q is reduced by a factor %s (%s; %s orders of magnitude, a reduction of "
          "%s %%): %s; GRC credit %s, final GRC %s%s (M1 not applied). A simulation cannot show "
          "deployment reliability, automatic activation or post-impact hazards: see the "
          "assumptions.",
          cell(m, row, "factor"), iv, cell(m, row, "orders"), cell(m, row, "reduction_pct"), claim,
          cell(m, row, "grc_credit"), cell(m, row, "final_grc"),
          atoi(cell(m, row, "final_grc") ? cell(m, row, "final_grc") : "0") > urSORA25_FINAL_MAX
              ? " (above 7: outside the SORA, the certified category)"
              : "");
    } else {
      el(ul, "li",
         "M2: no reduction factor: the drone carries no parachute or deployable airbag to "
         "compare it with (an airbag fitted in every branch is part of the drone; 'set "
         "m2_baseline design:NAME' compares with a design kept by 'design save').");
    }
    int e = sibling(r, so, "case");
    if (e >= 0 && colix(&r->t[e], "fatalities_per_fh") >= 0) {
      const uraRepTable* q = &r->t[e];
      char buf[2500], limits[400];
      size_t k = 0, kl = 0;
      limits[0] = 0;
      for (int i = 0; i < q->nrow && k < sizeof buf; i++) {
        const char *lo = cell(q, i, "lo95"), *hi = cell(q, i, "hi95");
        char iv[120] = "";
        if (lo && hi && strcmp(lo, hi)) snprintf(iv, sizeof iv, ", 95 %% interval %s..%s", lo, hi);
        k += (size_t)snprintf(
            buf + k, sizeof buf - k,
            "%scase %s at %s ppl/km^2: %s per flight hour (Q %s m^2%s; meets: %s)", i ? "; " : "",
            cell(q, i, "case"), cell(q, i, "density"), cell(q, i, "fatalities_per_fh"),
            cell(q, i, "q"), iv, cell(q, i, "meets"));
        if ((i == 0 || strcmp(cell(q, i, "case"), cell(q, i - 1, "case"))) && kl < sizeof limits)
          kl += (size_t)snprintf(limits + kl, sizeof limits - kl, "%scase %s %s ppl/km^2",
                                 kl ? ", " : "", cell(q, i, "case"), cell(q, i, "density_limit"));
      }
      const char* f = note_from(q, "risk per flight hour, eq. (1.1)", "E{n_F} = ");
      char formula[400];
      snprintf(formula, sizeof formula, "%s", f ? f : "?");
      char* cut = strstr(formula, ", per density band");
      if (cut) *cut = 0;
      const char* qb = note_from(q, "Q: ", NULL);
      elf(ul, "li",
          "Risk per flight hour, eq. (1.1) of the paper, %s (lambda_system and P_shelter are "
          "inputs, not results; %s), against the target %s per flight hour: %s. The target is "
          "met up to %s.",
          formula, qb ? qb : "Q: ?", cell(q, 0, "tlos"), buf, limits);
    }
  }
  int mc = last_table(r, "montecarlo", "n", "mean");
  if (mc >= 0) {
    const uraRepTable* t = &r->t[mc];
    char buf[600];
    size_t k = 0;
    buf[0] = 0;
    for (int j = 5; j < t->ncol && k < sizeof buf; j++) {
      k += (size_t)snprintf(buf + k, sizeof buf - k, "%s%s %s", j > 5 ? ", " : "", t->names[j],
                            t->cells[j]);
    }
    elf(ul, "li",
        "Uncertainty (%s): mean Q %s m^2 over %s samples, 95 %% interval of the mean %s to %s "
        "m^2; the "
        "spread of Q itself: %s m^2.",
        t->cmd, cell(t, 0, "mean"), cell(t, 0, "n"), cell(t, 0, "lo95"), cell(t, 0, "hi95"),
        buf[0] ? buf : "no quantiles");
  }
  int cv = last_table(r, "converge", "check", NULL);
  if (cv >= 0) {
    const uraRepTable* t = &r->t[cv];
    int q = findrow(t, "check", "step", "what", "q");
    int d = findrow(t, "check", "dt", "what", "p_centre");
    int mq = findrow(t, "check", "mesh", "what", "q");
    char mesh[160] = "";
    if (mq >= 0) {
      snprintf(mesh, sizeof mesh, "; doubling the membrane bag's mesh changes Q by %s",
               cell(t, mq, "rel_change") ? cell(t, mq, "rel_change") : "?");
    }
    elf(ul, "li",
        "Convergence (changes as fractions of the finer result): halving the grid step changes "
        "Q by %s; halving the time step changes P at the centre by %s%s. These discretisation "
        "changes are not in the intervals above, which are the sampling's alone.",
        q >= 0 ? cell(t, q, "rel_change") : "?", d >= 0 ? cell(t, d, "rel_change") : "?", mesh);
  } else {
    el(ul, "li", "Convergence: not run in this session (converge).");
  }
  if (r->nwarn) {
    xmlNodePtr li = elf(ul, "li", "%d warning%s: ", r->nwarn, r->nwarn == 1 ? "" : "s");
    anchor(li, "#warnings", "listed in 3.2");
  }
}

static void evidence(uraCtx* c, xmlNodePtr body, const uraReport* r) {
  xmlNodePtr s = section(body, "evidence", "3. Evidence");
  el(s, "h3", "3.1 Results, in the order computed");
  if (!r->nt) el(s, "p", "The session computed no result.");
  int nfig = 0;
  char id[64], cap[600];
  for (int i = 0; i < r->nt; i++) {
    const uraRepTable* t = &r->t[i];
    xmlNodePtr d = el(s, "div", NULL);
    snprintf(id, sizeof id, "result-%d", i + 1);
    attr(d, "id", id);
    xmlNodePtr h = elf(d, "h4", "R%d: ", i + 1);
    el(h, "code", t->cmd);
    if (t->failed) el(d, "p", "The command failed after printing this table (see warnings).");
    xmlNodePtr p = el(d, "p", "Inputs: ");
    snprintf(id, sizeof id, "#settings-%d", t->settings + 1);
    snprintf(cap, sizeof cap, "settings S%d (Appendix A)", t->settings + 1);
    anchor(p, id, cap);
    if (t->nnote) {
      xmlNodePtr ul = el(d, "ul", NULL);
      attr(ul, "class", "notes");
      for (int k = 0; k < t->nnote; k++) {
        xmlNodePtr li = el(ul, "li", t->notes[k]);
        if (ura_report_alarm(t->notes[k])) attr(li, "class", "warn");
      }
    }
    data_table(d, t, 200);
    if (t->grid >= 0) {
      const uraRepGrid* g = &r->g[t->grid];
      char* uri = ura_report_svg_grid(c, g);
      snprintf(id, sizeof id, "figure-%d", ++nfig);
      snprintf(cap, sizeof cap, "Figure %d: %s of R%d as a heat map (%s).", nfig,
               g->diff ? "the difference grid" : "the grid", i + 1, g->title);
      figure(c, d, uri, cap, id);
      free(uri);
      if ((long)g->g.nrow * g->g.ncol <= 1600) {
        elf(d, "p",
            "%s of R%d cell by cell, P in %% (the paper's coloured tables; rows along the course, "
            "columns across; bands %g, %g, %g %%):",
            g->diff ? "The difference" : "The grid", i + 1, uraBAND_MED, uraBAND_HIGH,
            uraBAND_SEVERE);
        cell_table(d, g);
      } else {
        elf(d, "p",
            "The grid has %d cells: only its heat map is shown ('export grid' writes them).",
            g->g.nrow * g->g.ncol);
      }
    }
  }
  if (r->dropped) {
    elf(s, "p", "%d grids were not kept for figures (at most %d, %ld cells in all).", r->dropped,
        uraREPMAXGRIDS, uraREPMAXCELLS);
  }
  if (c->nsweep || c->npsweep) {
    char* uri = ura_report_svg_plot(c, "sweep");
    snprintf(id, sizeof id, "figure-%d", ++nfig);
    snprintf(cap, sizeof cap, "Figure %d: the kept sweeps, Q against the swept value.", nfig);
    figure(c, s, uri, cap, id);
    free(uri);
  }
  if (c->mc) {
    char* uri = ura_report_svg_plot(c, "montecarlo");
    snprintf(id, sizeof id, "figure-%d", ++nfig);
    snprintf(cap, sizeof cap, "Figure %d: the last montecarlo's distribution of Q.", nfig);
    figure(c, s, uri, cap, id);
    free(uri);
    uri = ura_report_svg_plot(c, "tornado");
    snprintf(id, sizeof id, "figure-%d", ++nfig);
    snprintf(cap, sizeof cap, "Figure %d: the last montecarlo's first-order variance shares.",
             nfig);
    figure(c, s, uri, cap, id);
    free(uri);
  }
  xmlNodePtr w = el(s, "h3", "3.2 Warnings");
  attr(w, "id", "warnings");
  if (!r->nwarn) {
    el(s, "p", "The session gave no warning in the kept results.");
  } else {
    xmlNodePtr box = el(s, "div", NULL);
    attr(box, "class", "warnbox");
    xmlNodePtr ul = el(box, "ul", NULL);
    for (int i = 0; i < r->nwarn; i++) el(ul, "li", r->warn[i]);
  }
}

static void assumptions(uraCtx* c, xmlNodePtr body) {
  xmlNodePtr s = section(body, "assumptions", "4. Assumptions");
  const uraRiskSet* r = &c->st.risk;
  xmlNodePtr ul = el(s, "ul", NULL);
  elf(ul, "li",
      "Ground-crash rate lambda_system = %g per flight hour and P_shelter = %g are inputs of eq. "
      "(1.1), not results; the target is %g fatalities per flight hour (SORA 2.5 TLOS).",
      r->lambda, r->p_shelter, r->tlos);
  int ra3_c = !strcmp(ura_risk_none_name(c), "C"); /* the model's case C is the unmitigated one */
  urDeploy dep;
  int bag[urMAXBAGS];
  if (ura_risk_devices(c, &c->st, &dep, bag)) dep.chute = 0;
  if (dep.chute)
    elf(ul, "li",
        "Deployment: the parachute deploys with probability %g above %g m, each airbag with %g; "
        "without the parachute no airbag is credited (the drone falls %s).",
        r->p_chute, r->h_chute_min, r->p_bag, ra3_c ? "as case C" : "without them: branch none");
  else
    el(ul, "li",
       "Deployment: none; the drone carries no parachute (area_chute 0), so p_chute and p_bag "
       "do not apply (an airbag fitted in every branch is part of the drone).");
  elf(ul, "li",
      "SORA 2.5 Table 2 column: characteristic dimension %s, maximum speed %s; density bands have "
      "strict upper edges (5, 50, 500, 5 000 go one band up; 50 000 is taken as '> 50 000'); "
      "a UA of at most 250 g and 25 m/s has iGRC 1 outside assemblies of people (p. 24).",
      r->ua_dim_set ? "as set (ua_dimension)" : "the larger of width and length",
      r->ua_speed_set ? "as set (ua_max_speed)"
                      : "the unmitigated impact speed standing in for the designer's maximum "
                        "commanded airspeed");
  const char* m2_name = "";
  int m2 = ura_m2_baseline(r, &m2_name);
  char m2_text[120];
  snprintf(m2_text, sizeof m2_text,
           "design %s (its grids under the live deployment mixture, wind, face, altitude and step)",
           m2_name);
  elf(ul, "li",
      "M2 baseline: %s. Only integrity criterion #1's reduction is assessed; M1 is not applied; "
      "the final GRC is floored at the column's controlled-ground-area value.",
      m2 == uraM2_TABLE_B8 ? "Annex B Table B.8's critical area of the column (warned: double "
                             "counting with Step #2)"
      : m2 == uraM2_DESIGN ? m2_text
      : !dep.chute         ? "none (nothing deployable to compare with)"
      : ra3_c              ? "the same drone without parachute and airbag (case C)"
                           : "the same drone without parachute and airbag (branch none)");
  el(ul, "li",
     "What the simulation cannot show: that the devices deploy (activation tests, reliability "
     "evidence), automatic activation (required for high), that a failure of the mitigation does "
     "not degrade safety, immediate post-impact hazards (fire, debris), procedures and training "
     "(M2 criteria #2 and #3), and the assurance level (medium accepts simulation whose validity "
     "is justified: section 5; high needs an EASA design verification report).");
  el(ul, "li",
     "Every setting each result ran under, derived or set, is listed in Appendix A; the model "
     "texts are in Appendix B.");
}

/* a grid's row, or a sweep over wind or face: not a sweep of another parameter, whose rows each
   ran with a value of their own */
static int paper_columns(const uraRepTable* t) {
  static const char* const cols[] = {"case",    "wind",     "speed",         "angle",
                                     "face",    "step",     "cells",         "q",
                                     "seconds", "complete", "contact_cells", NULL};
  for (int j = 0; j < t->ncol; j++) {
    int k = 0;
    while (cols[k] && strcmp(cols[k], t->names[j])) k++;
    if (!cols[k]) return 0;
  }
  return 1;
}

static void validity(uraCtx* c, xmlNodePtr body, const uraReport* r) {
  xmlNodePtr s = section(body, "validity", "5. Model validity");
  el(s, "h3", "5.1 The paper's Table 17 beside this session's grids");
  el(s, "p",
     "Q in m^2 at face 0; the printed values of Jiang, Blom and Rattanagraikanakorn (2025); "
     "'this session' is the last grid or sweep of that case and wind the session computed at the "
     "paper's conditions (any step, descent and tau; nothing else set that changes a grid: no "
     "model part or parameter, attitude, speed, angle, extents or injury setting of its own) "
     "(none: not computed here; 'make reproduce' computes all). The ratio is taken against the "
     "basis the calibration declares (uasimpact-model(5), CALIBRATION, Scoring): the full-plane "
     "sum of the paper's own grid where it prints one, else the printed value. A at 0 m/s: the "
     "caption's 0.031 is the half plane, the full-plane sum of the paper's Table 4 grid is "
     "0.058; B at 0 m/s: the caption's 0.256 matches neither sum of Table 5's grid (full plane "
     "0.286); A1 and A2 at 0 m/s print no grid: against the printed value / twice it.");
  xmlNodePtr tb = el(s, "table", NULL);
  xmlNodePtr tr = el(tb, "tr", NULL);
  const char* hd[] = {"case", "wind (m/s)", "paper", "this session", "basis", "ratio", "step (m)"};
  for (int j = 0; j < 7; j++) el(tr, "th", hd[j]);
  const char* cn;
  double wind, q, basis;
  for (int k = 0; ura_report_table17(k, &cn, &wind, &q, &basis) == 0; k++) {
    const char *ours = NULL, *step = "";
    char sbuf[32]; /* a sweep's rows: the step it ran with */
    for (int i = 0; i < r->nt; i++) {
      const uraRepTable* t = &r->t[i];
      if (strcmp(t->name, "grid") && strcmp(t->name, "sweep")) continue;
      if (!t->paper || !paper_columns(t)) continue;
      for (int row = 0; row < t->nrow; row++) {
        const char *tc = cell(t, row, "case"), *tw = cell(t, row, "wind"),
                   *tf = cell(t, row, "face"), *tq = cell(t, row, "q");
        if (!tc || !tw || !tf || !tq || strcmp(tc, cn) || atof(tw) != wind || atof(tf) != 0)
          continue;
        ours = tq;
        step = cell(t, row, "step");
        if (!step) {
          snprintf(sbuf, sizeof sbuf, "%g", t->step);
          step = sbuf;
        }
      }
    }
    tr = el(tb, "tr", NULL);
    el(tr, "td", cn);
    elf(tr, "td", "%g", wind);
    elf(tr, "td", "%.3f", q);
    el(tr, "td", ours ? ours : "none");
    if (basis > 0)
      elf(tr, "td", "%.4f (grid, full plane)", basis);
    else if (basis < 0)
      elf(tr, "td", "%.3f / %.3f (printed / twice)", q, 2 * q);
    else
      elf(tr, "td", "%.3f (printed)", q);
    if (ours && basis < 0)
      elf(tr, "td", "%.2f / %.2f", atof(ours) / q, atof(ours) / (2 * q));
    else if (ours)
      elf(tr, "td", "%.2f", atof(ours) / (basis > 0 ? basis : q));
    else
      el(tr, "td", "");
    el(tr, "td", step);
  }
  el(s, "h3", "5.2 Numerical convergence");
  int cv = 0;
  for (int i = 0; i < r->nt; i++) {
    if (strcmp(r->t[i].name, "converge")) continue;
    elf(s, "p", "R%d (%s):", i + 1, r->t[i].cmd);
    data_table(s, &r->t[i], 50);
    cv++;
  }
  if (!cv) el(s, "p", "The session ran no converge: grid and time-step convergence not shown.");
  el(s, "h3", "5.3 Physics the test suite proves");
  el(s, "p",
     "Each check is a test of the source tree that can fail (make check runs them all); golden "
     "values come from closed forms, the paper or cited data.");
  tb = el(s, "table", NULL);
  tr = el(tb, "tr", NULL);
  attr(el(tr, "th", "test"), "class", "l");
  attr(el(tr, "th", "proves"), "class", "l");
  const char *file, *proves;
  for (int k = 0; (file = ura_report_check(k, &proves)); k++) {
    tr = el(tb, "tr", NULL);
    xmlNodePtr td = el(tr, "td", NULL);
    attr(td, "class", "l");
    el(td, "code", file);
    td = el(tr, "td", proves);
    attr(td, "class", "l");
  }
  el(s, "h3", "5.4 Known limits");
  xmlNodePtr ul = el(s, "ul", NULL);
  const char* lim;
  for (int k = 0; (lim = ura_report_limit(k)); k++) el(ul, "li", lim);
}

static void appendix(uraCtx* c, xmlNodePtr body, const uraReport* r, const char* dir) {
  xmlNodePtr s = section(body, "appendix", "Appendices");
  el(s, "h3", "A. Inputs: every setting, derived or set ('show')");
  char id[32];
  for (int i = 0; i < r->nset; i++) {
    xmlNodePtr h = elf(s, "h4", "S%d", i + 1);
    snprintf(id, sizeof id, "settings-%d", i + 1);
    attr(h, "id", id);
    el(s, "pre", r->settings[i]);
  }
  if (!r->nset) el(s, "p", "No result was kept, so no settings either.");
  el(s, "h3", "B. Model texts");
  for (int i = 0; i < c->npart; i++) {
    unsigned long long h = ura_fnv(uraFNV0, c->part[i].text, strlen(c->part[i].text));
    char name[PATH_MAX]; /* a loaded file as named from the report's folder */
    const char* from = ura_model_origin_at(dir, c->part[i].origin, name, sizeof name);
    elf(s, "h4", "%s (%s, FNV-1a 64 %016llx)", c->part[i].name, from, h);
    el(s, "pre", c->part[i].text);
  }
  el(s, "h3", "C. Sources");
  xmlNodePtr ol = el(s, "ol", NULL);
  const char* src;
  for (int k = 0; (src = ura_report_source(k)); k++) el(ol, "li", src);
}

/* libxml2's generic error handler while the report is serialised: silent (the texts are
   cleaned to UTF-8 before they enter the tree; a failure shows as no memory) */
static void quiet(void* ctx, const char* msg, ...) {
  (void)ctx;
  (void)msg;
}

int ura_cmd_report(uraCtx* c, int argc, char** argv) {
  if (ura_dry(c, "report")) return -1;
  if (ura_name_fits(c, "report", argv[1], "HTML", "html htm xhtml")) return -1;
  uraReport empty;
  memset(&empty, 0, sizeof empty);
  uraReport* r = c->rep ? c->rep : &empty;
  r->busy = 1;

  htmlDocPtr doc = htmlNewDocNoDtD(NULL, NULL);
  xmlCreateIntSubset(doc, X("html"), NULL, NULL);
  xmlNodePtr html = xmlNewNode(NULL, X("html"));
  xmlDocSetRootElement(doc, html);
  attr(html, "lang", "en");
  xmlNodePtr head = el(html, "head", NULL);
  xmlNodePtr mc = el(head, "meta", NULL);
  attr(mc, "charset", "utf-8");
  elf(head, "title", "Ground-risk study report: case %s", c->st.casename);
  el(head, "style", css);
  xmlNodePtr body = el(html, "body", NULL);
  elf(body, "h1", "Ground-risk study report: case %s", c->st.casename);
  meta(c, body);
  question(c, body);
  answer(c, body, r);
  evidence(c, body, r);
  assumptions(c, body);
  validity(c, body, r);
  char dir[4096];
  ura_dir_of(argv[1], dir, sizeof dir);
  appendix(c, body, r, dir);
  r->busy = 0;

  xmlChar* mem = NULL;
  int size = 0;
  xmlSetGenericErrorFunc(NULL, quiet); // a serializer message would land on the prompt
  htmlDocDumpMemoryFormat(doc, &mem, &size, 1);
  xmlSetGenericErrorFunc(NULL, NULL);
  xmlFreeDoc(doc);
  if (!mem) return ura_fail(c, "report: out of memory");
  uraAtomic a;
  int rc = ura_atomic_open(c, &a, argv[1], "report");
  if (rc == 0) {
    fwrite(mem, 1, (size_t)size, a.f);
    rc = ura_atomic_close(c, &a, 1, "report");
  }
  xmlFree(mem);
  if (rc == 0 && c->msg && !c->mute) {
    fprintf(c->msg, "report: %s written (%d result%s, %d grid%s drawn, %d warning%s)\n", argv[1],
            r->nt, r->nt == 1 ? "" : "s", r->ng, r->ng == 1 ? "" : "s", r->nwarn,
            r->nwarn == 1 ? "" : "s");
  }
  return rc;
}
