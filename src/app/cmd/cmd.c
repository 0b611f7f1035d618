/* cmd.c: the command table (dispatch, help and completion all read it) and the state commands */
#include <stdio.h>
#include <string.h>

#include "cmd.h"


/* the one command table: name, handler, argument range, completion, usage, help */
const uraCmd ura_cmds[] = {
    {"help", ura_cmd_help, 0, 1, uraC_COMMAND, "help [COMMAND]",
     "list the commands, or explain one"},
    {"set", ura_cmd_set, 2, -1, uraC_PARAM, "set NAME VALUE [UNIT]",
     "change a parameter of the live case (see 'show' for names, units and ranges); model "
     "parameters take an optional unit, speeds m/s, km/h or kt; set terminal takes the rest of "
     "the line (set terminal png size 1000,700)"},
    {"show", ura_cmd_show, 0, 1, uraC_PARAM, "show [NAME|PREFIX]",
     "print the live case state with units, one parameter, or those whose names start with PREFIX (show bag); derived values say so"},
    {"case", ura_cmd_case, 1, 1, uraC_CASE, "case NAME",
     "load a preset of the model (the RA3's: A, B, C, A1, A2; 'model show' lists their preset lines); wind, "
     "face, step, recall and the output settings keep their values; a note names the settings "
     "of yours it drops (undo brings them back)"},
    {"reset", ura_cmd_reset, 0, 0, uraC_NONE, "reset",
     "restore every default (says which of your settings it drops; undo brings them back)"},
    {"undo", ura_cmd_undo, 0, 0, uraC_NONE, "undo",
     "restore the settings as they were before the last command that changed them (set, case, "
     "reset, design load, dist, source ...); up to 32 levels; grids, sweeps, designs and loaded "
     "model files stay"},
    {"descent", ura_cmd_descent, 0, 0, uraC_NONE, "descent",
     "impact speed and descent angle for each wind in 'winds' (paper Table 2); "
     "columns case,wind,speed,angle"},
    {"parametric", ura_cmd_parametric, 0, 0, uraC_NONE, "parametric",
     "Appendix D parametric areas and fatality probabilities for each wind in 'winds' "
     "(paper Table 3); columns case,wind,speed,angle,planform,mtow,gliding,pof_rcc,pof_bc,pof_awke"},
    {"grid", ura_cmd_grid, 0, 2, uraC_NONE, "grid [show|cells|load FILE]",
     "run the offset grid of the live case (summary row), print it as coloured text (show), "
     "every cell (cells), or load a grid CSV (the paper's tables) as the last grid"},
    {"sweep", ura_cmd_sweep, 1, 3, uraC_NONE,
     "sweep wind LIST [UNIT]|face LIST|NAME LIST [UNIT]|show|clear",
     "one grid per wind speed (m/s, or km/h or kt as UNIT) or face direction (deg) of LIST, columns "
     "case,wind,face,speed,angle,q; or per value of any numeric parameter NAME (a model "
     "parameter in UNIT), columns case,NAME,wind,face,speed,angle,q; the sweeps are kept for plot "
     "sweep and export sweep (show lists them, clear forgets them)"},
    {"compare", ura_cmd_compare, 0, 0, uraC_NONE, "compare",
     "the paper's Tables 11-13 for the live case: P{F|Delta=(0,0)} x gliding area against Q; "
     "columns case,wind,p_centre,gliding,q_parametric,q,factor"},
    {"design", ura_cmd_design, 1, 3, uraC_NONE, "design save|load|delete NAME|list|compare A B",
     "keep the live case's full state under NAME, make it live again, forget it, list the kept "
     "designs, or compare two (a grid each): columns design_a,case_a,q_a,design_b,case_b,q_b,"
     "ratio (q_b/q_a); the last grid becomes the difference P_b - P_a (view shows it)"},
    {"view", ura_cmd_view, 0, 0, uraC_NONE, "view",
     "browse the last grid in colour (ncurses): arrows move, Enter inspects a cell, p plots it, b its airbag, "
     "q returns"},
    {"plot", ura_cmd_plot, 1, -1, uraC_NONE,
     "plot pof|grid|bag|history [SIGNAL...|all]|sweep [wind|face|NAME]|montecarlo|tornado",
     "send curves to gnuplot: the PoF curves; the last grid as a heat map (a difference grid of "
     "design compare, P_b - P_a, on a diverging palette); the last impact's membrane airbags at first "
     "contact and peak pressure; time histories of the last impact (history all: every "
     "channel); Q of the kept sweeps (plot sweep: every kind kept, a panel each; plot sweep "
     "wind, face or NAME: that kind alone, one unit per axis); the last montecarlo's Q "
     "distribution (montecarlo) or its variance shares (tornado) (set terminal/output to write "
     "files)"},
    {"impact", ura_cmd_impact, 2, 5, uraC_NONE, "impact DPAR DPERP|aim head UP SIDE",
     "simulate one impact at the offset (along, across the course; m) of the live case, or (aim) "
     "with the drone's line of travel UP and SIDE (m) from the head's centre, at any angle 0-90 "
     "deg; columns "
     "dpar,dperp,contact,hic15,nij,nij_tf,nij_te,nij_cf,nij_ce,vc_thorax,vc_abdomen,p_hic,p_nij,"
     "p_vc,p (with 'set use_defl 1' also defl_thorax after vc_abdomen and p_defl after p_vc)"},
    {"history", ura_cmd_history, 0, -1, uraC_NONE, "history [all|CHANNEL...] [FROM:TO]",
     "the last impact at a glance: the peak of each derived signal and its time, each airbag's "
     "pressure, volume, force and strain, the injury criteria and P; all: every sensor channel's samples (time and every channel, as export "
     "history writes them); CHANNEL...: those signals' samples; FROM:TO: only the samples from "
     "FROM to TO ms after tau"},
    {"contacts", ura_cmd_contacts, 0, 0, uraC_NONE, "contacts",
     "list the drone's contacts with the person in the last impact, in order of first touch; "
     "columns drone,person,first,last,peak_force,peak_time (s from tau, N)"},
    {"model", ura_cmd_model, 1, 2, uraC_NONE,
     "model show|params [PREFIX]|parts|notes|save FILE|load FILE|drop PART",
     "print, list (params: with units and who set them, and the values derived from materials; "
     "PREFIX: the names starting with it; notes: the compiler's notes and derived values), "
     "write or load the model set (human, drone, airbags, options: uasimpact-model(5)), or drop a "
     "part (before loading another drone)"},
    {"pof", ura_cmd_pof, 1, 1, uraC_POF, "pof hic|nij|vc|vc_thorax|vc_abdomen|defl",
     "print a probability-of-fatality curve of the injury criteria as columns x,p "
     "(Appendix C; settings in uasimpact-injury(7))"},
    {"export", ura_cmd_export, 2, 2, uraC_NONE,
     "export grid|history|sweep|contacts|montecarlo FILE",
     "write the last grid's cells, the last impact's histories, the kept sweeps, the last "
     "impact's contacts or the last montecarlo's samples as CSV (atomically)"},
    {"risk", ura_cmd_risk, 0, 0, uraC_NONE, "risk",
     "Q of the live case mixed over parachute and airbag deployment (p_chute, p_bag, "
     "h_chute_min): one grid per branch; columns branch,weight,q, last row mixed"},
    {"dist", ura_cmd_dist, 0, -1, uraC_PARAM,
     "dist [NAME normal MEAN SD|uniform LO HI|weibull SCALE SHAPE|discrete VALUES PROBS|off|clear]",
     "declare the distribution montecarlo draws an input from (wind, wind_dir, face_dir, face, "
     "p_chute, ... any number parameter); without arguments list them"},
    {"montecarlo", ura_cmd_montecarlo, 1, 1, uraC_NONE, "montecarlo N|shares|samples",
     "draw N samples of the declared inputs and deployment outcomes (set seed), Q of each; "
     "columns n,mean,sd,lo95,hi95; shares: input,share (first-order); samples: every sample"},
    {"sora", ura_cmd_sora, 0, 1, uraC_NONE, "sora [mc]",
     "SORA 2.5 figures: critical area (Q, and Annex F) and iGRC of the unmitigated drone and the "
     "live case, and the reduction factor; mc: with the last montecarlo's intervals"},
    {"converge", ura_cmd_converge, 0, 0, uraC_NONE, "converge",
     "convergence evidence of the live grid: Q at the step and at half of it, the new cells' P "
     "against the coarse grid, and P at the centre and the worst cell with dt and dt/2; columns "
     "check,what,dpar,dperp,coarse,fine,change,rel_change"},
    {"report", ura_cmd_report, 1, 1, uraC_FILE, "report FILE.html",
     "write the session's study as one self-contained HTML file: question, answer (SORA 2.5 "
     "iGRC, M2 evidence, risk per flight hour), every grid, sweep, design comparison, risk, "
     "montecarlo, sora and converge result with its settings, notes and figures, warnings, "
     "assumptions, model validity and the model texts"},
    {"save", ura_cmd_save, 2, 2, uraC_NONE, "save session FILE",
     "write a script that recreates the live state exactly (replay: uasimpact FILE, or source)"},
    {"source", ura_cmd_source, 1, 1, uraC_FILE, "source FILE",
     "run the commands of a session script; errors name the file and line"},
    {"quit", ura_cmd_quit, 0, 0, uraC_NONE, "quit", "leave uasimpact (also: q, exit, Ctrl-D)"},
    {"exit", ura_cmd_quit, 0, 0, uraC_NONE, "exit", "leave uasimpact"},
    {NULL, NULL, 0, 0, uraC_NONE, NULL, NULL}};

const uraCmd* ura_cmd_find(const char* name) {
  for (const uraCmd* k = ura_cmds; k->name; k++) {
    if (!strcmp(k->name, name)) return k;
  }
  return NULL;
}

int ura_cmd_help(uraCtx* c, int argc, char** argv) {
  /* one command in detail */
  if (argc == 2) {
    char cands[400];
    const uraCmd* k = ura_cmd_resolve(argv[1], cands, sizeof cands);
    if (!k && *cands) {
      return ura_fail(c, "help: ambiguous command '%s': %s? type more of the name", argv[1], cands);
    }
    if (!k) {
      uraSuggest sg;
      char dym[120];
      ura_suggest_init(&sg, argv[1]);
      ura_suggest_commands(&sg);
      return ura_fail(c, "help: no command '%s'%s; type 'help' for the list", argv[1],
                      ura_suggest_text(&sg, dym, sizeof dym));
    }
    fprintf(c->out, "usage: %s\n", k->usage);
    ura_wrap(c->out, "  ", "  ", k->help, ura_text_width(c));
    return 0;
  }

  /* the whole table */
  fprintf(c->out, "commands (help COMMAND for one; set/show NAME for parameters):\n");
  int width = ura_text_width(c);
  for (const uraCmd* k = ura_cmds; k->name; k++) {
    char lead[300];
    if (strlen(k->usage) > 26) ura_wrap(c->out, "  ", "    ", k->usage, width);
    snprintf(lead, sizeof lead, "  %-26s ", strlen(k->usage) > 26 ? "" : k->usage);
    ura_wrap(c->out, lead, "                             ", k->help, width);
  }
  return 0;
}

static int set_one(uraCtx* c, int argc, char** argv);

/* set terminal NAME OPTION...: the words joined again as gnuplot reads the rest of its line;
   a word that was quoted (it holds a blank or a comma after font or background) is quoted again,
   so that ura_terminal_check sees what was typed */
static int set_terminal_words(uraCtx* c, int argc, char** argv) {
  char line[512];
  size_t k = 0;
  for (int i = 2; i < argc && k < sizeof line; i++) {
    int q = strpbrk(argv[i], " \t") ||
            (i > 2 && (!strcmp(argv[i - 1], "font") || !strcmp(argv[i - 1], "background")));
    const char* quote = !q ? "" : strchr(argv[i], '\'') ? "\"" : "'";
    k += (size_t)snprintf(line + k, sizeof line - k, "%s%s%s%s", i > 2 ? " " : "", quote, argv[i],
                          quote);
  }
  if (k >= sizeof line) {
    return ura_fail(c, "set terminal: the line is too long; accepted: a terminal and its options");
  }
  char* av[3] = {argv[0], argv[1], line};
  return ura_cmd_set(c, 3, av);
}

/* set, then at the prompt the models the setting changes (design.c) */
int ura_cmd_set(uraCtx* c, int argc, char** argv) {
  if (argc > 3 && !strcmp(argv[1], "terminal")) return set_terminal_words(c, argc, argv);
  if (argc > 4) {
    return ura_fail(c,
                    "set %s: wrong number of arguments (%d); usage: set NAME VALUE [UNIT] (only "
                    "set terminal takes more words: its options)",
                    argv[1], argc - 1);
  }
  int rc = ura_design_set(c, argv[1], argv[2], argc == 4 ? argv[3] : NULL);
  if (rc == 1) rc = set_one(c, argc, argv);
  const char* reach = rc ? NULL : ura_design_reach(c, argv[1]);
  if (reach && c->interactive) fprintf(c->msg, "set %s: changes %s\n", argv[1], reach);
  return rc;
}

static int set_one(uraCtx* c, int argc, char** argv) {
  /* a parameter by name (named.c): set bag_model analytic|membrane, set endrun window|final */
  const uraNamed* nv = ura_named_find(argv[1]);
  if (nv && !(nv->numeric && argc == 3 && strspn(argv[2], "0123456789.") > 0)) {
    return ura_named_set(c, nv, argc, argv);
  }
  const uraParam* p = ura_param_find(argv[1]);
  int i = p ? -1 : ura_injury_find(argv[1]);
  if (!p && i < 0) {
    if (ura_model_param_find(c, argv[1]) >= 0) {
      return ura_model_param_set(c, argv[1], argv[2], argc == 4 ? argv[3] : NULL, 1);
    }
    uraSuggest sg;
    char dym[120];
    ura_suggest_init(&sg, argv[1]);
    ura_suggest_params(c, &sg);
    return ura_fail(c, "set: unknown parameter '%s'%s; 'show' lists the parameters", argv[1],
                    ura_suggest_text(&sg, dym, sizeof dym));
  }
  /* a speed in km/h or kt (set wind 10 kt, set winds 0,10,20 km/h): converted to m/s here */
  double f;
  if (argc == 4 && p && !strcmp(p->unit, "m/s") && strcmp(argv[3], "m/s") &&
      !ura_speed_unit(argv[3], &f)) {
    char si[1024], who[80];
    snprintf(who, sizeof who, "set %s", p->name);
    if (ura_speed_convert(c, who, p, argv[2], argv[3], si, sizeof si)) return -1;
    return ura_param_set(c, p, si);
  }
  /* a unit is accepted when it is the parameter's own (set wind 3 m/s) */
  if (argc == 4 && !(p && *p->unit && !strcmp(argv[3], p->unit))) {
    if (p && !strcmp(p->unit, "m/s")) {
      return ura_fail(c, "set %s: unknown unit '%s'; accepted: %s", argv[1], argv[3],
                      uraSPEED_UNITS);
    }
    return ura_fail(c, "set %s: takes no unit but its own (it is in %s)", argv[1],
                    p && *p->unit ? p->unit : "the unit 'show' prints");
  }
  return p ? ura_param_set(c, p, argv[2]) : ura_injury_set(c, i, argv[2]);
}

/* show in JSON: one row per setting (name, value, unit, source) gathered here and
   printed as one table; NULL: show prints its aligned lines */
static uraTable* show_tab;

/* one setting as show prints it: an aligned line, or a row of show_tab; note is the source in
   the line's form ("  (set)", "  (derived: ...)") */
static void show_line(uraCtx* c, const char* name, const char* val, const char* unit,
                      const char* note) {
  if (!show_tab) {
    fprintf(c->out, "%-16s %s%s%s%s\n", name, val, *unit ? " " : "", unit, note);
    return;
  }
  char src[1024];
  snprintf(src, sizeof src, "%s", note + strspn(note, " ("));
  size_t n = strlen(src);
  if (n && src[n - 1] == ')') src[n - 1] = 0;
  ura_table_cell(show_tab, "%s", name);
  ura_table_cell(show_tab, "%s", val);
  ura_table_cell(show_tab, "%s", unit);
  ura_table_cell(show_tab, "%s", src);
}

/* numbers as they read back (csv and json: scripts read them) or as a person reads them (the
   table format: 6 significant digits for a converted 10 kt, not 17) */
static int show_exact(const uraCtx* c) {
  return show_tab || c->st.format == uraFMT_CSV;
}

/* one line of show: name, value, unit, and where a derived value comes from; ext (NULL: one
   parameter alone) keeps the derived grid extents across the lines of a listing (ext[3]: 0 not
   sized yet, 1 sized, -1 not available) */
static int show_one(uraCtx* c, const uraParam* p, double ext[4]) {
  char val[1024], src[160], mnote[300];
  const char* note = "";
  if (p->setoff && !*(const int*)((const char*)&c->st + p->setoff)) {
    double one[4] = {0, 0, 0, 0}, *v = ext ? ext : one;
    if (!strcmp(p->name, "ua_dimension")) {
      /* SORA's inputs when not set: what sora takes (cmd_sora25.c) */
      snprintf(val, sizeof val, "%.6g",
               c->st.para.width > c->st.para.length ? c->st.para.width : c->st.para.length);
      show_line(c, p->name, val, "m", "  (derived: the larger of the drone's width and length)");
      return 0;
    }
    if (!strcmp(p->name, "ua_max_speed")) {
      show_line(c, p->name, "auto", "m/s",
                "  (derived at sora: the unmitigated drone's impact speed)");
      return 0;
    }
    if (!strcmp(p->name, "speed") || !strcmp(p->name, "angle")) {
      if (ura_impact_conditions(c, &v[0], &v[1])) {
        if (!ext) return -1;
        /* the whole listing still prints (e.g. the paper's Table 2 at an unprinted wind) */
        char why[uraERRLEN + 40];
        snprintf(why, sizeof why, "  (derived: not available: %s)", c->err);
        show_line(c, p->name, "auto", p->unit, why);
        c->err[0] = 0;
        return 0;
      }
      if (c->st.descent_src == uraDESC_PAPER) {
        snprintf(src, sizeof src,
                 "  (derived: the paper's Table 2, case %s's column, at the live "
                 "wind; set descent paper)",
                 ura_paper_descent_column(c->st.casename));
        note = src;
      } else {
        note = "  (derived: descent model at the live wind)";
      }
      snprintf(val, sizeof val, "%.6g", v[!strcmp(p->name, "angle")]);
    } else {
      /* grid extents: the lattice the next grid would use (sizing needs the settled stance
         and the inflated bags: a listing leaves a membrane bag not yet inflated as it is, which
         'show along_min' alone inflates) */
      const urModel* m = ext && !c->have_setup ? ura_model(c) : NULL;
      if (v[3] == 0 && m && m->nraw) v[3] = -2;
      if (v[3] == 0) v[3] = ura_grid_extents(c, &v[0], &v[1], &v[2]) ? -1 : 1;
      if (v[3] < 0) {
        if (!ext) return -1;
        /* the whole listing still prints (e.g. in dry mode): the value is left to the grid */
        c->err[0] = 0;
        show_line(c, p->name, "auto", p->unit,
                  v[3] < -1 ? "  (derived at the next grid, after the airbag's inflation)"
                            : "  (derived at the next grid)");
        return 0;
      }
      double x = !strcmp(p->name, "along_min") ? v[0] : !strcmp(p->name, "along_max") ? v[1] : v[2];
      note = "  (derived: every cell where contact is possible, padded by one cell)";
      snprintf(val, sizeof val, "%.6g", x);
    }
  } else {
    if (show_exact(c))
      ura_param_format(c, p, val, sizeof val);
    else
      ura_param_display(c, p, val, sizeof val);
    if (p->setoff)
      note = "  (set)";
    else
      note = ura_design_mark(c, p->name, src, sizeof src);
    if (!strcmp(p->name, "mirror") && !*note) {
      /* whether the next grid takes its half dperp < 0 as the mirror image, and why not */
      char why[200];
      if (ura_grid_mirror(c, why, sizeof why))
        snprintf(mnote, sizeof mnote,
                 "  (derived: the next grid simulates dperp >= 0 and mirrors it)");
      else
        snprintf(mnote, sizeof mnote, "  (derived: the next grid simulates every cell: %s)", why);
      note = mnote;
    }
  }
  show_line(c, p->name, val, p->unit, note);
  return 0;
}

/* one injury setting */
static void show_injury(uraCtx* c, int i) {
  const char *name, *unit;
  char val[128];
  ur_injury_param_info(i, &name, &unit, NULL);
  ura_injury_line(c, i, val, sizeof val, !show_tab);
  if (!show_exact(c)) { /* as a person reads it, with its unit */
    double v;
    ur_injury_param_get(&c->st.injury, name, &v);
    ura_num_show(val, sizeof val, v);
    if (unit && *unit) snprintf(val + strlen(val), sizeof val - strlen(val), " %s", unit);
  }
  if (show_tab)
    show_line(c, name, val, unit ? unit : "", "  (injury criteria)");
  else
    fprintf(c->out, "%-16s %s\n", name, val);
}

/* one model parameter: name, SI value, its unit; one that follows another (param NAME $OTHER)
   says so while it is not set */
static void show_model_param(uraCtx* c, const urParam* p) {
  char val[64], from[2 * urNAMELEN], note[4 * urNAMELEN + 80];
  if (show_exact(c))
    snprintf(val, sizeof val, "%.10g", p->value);
  else
    ura_num_show(val, sizeof val, p->value);
  const urModel* m = ura_model(c);
  if (m && !ura_model_param_from(m, p, from, sizeof from)) {
    const urParam* o = &m->param[p->from];
    if (p->from_f == 1)
      snprintf(note, sizeof note, "  (derived: %s's value, the model's %s; set it to give its own)",
               o->name, from);
    else
      snprintf(note, sizeof note,
               "  (derived: %g x %s's value, the model's %s; set it to give its own)", p->from_f,
               o->name, from);
    show_line(c, p->name, val, p->unit, note);
    return;
  }
  show_line(c, p->name, val, p->unit, show_tab ? "  (model parameter, SI)" : "");
}

/* show PREFIX: every parameter whose name starts with it, in the order of the full listing */
static int show_prefix(uraCtx* c, const char* prefix) {
  size_t n = strlen(prefix);
  int found = 0;
  const char* name;
  for (const uraParam* p = ura_params; p->name; p++) {
    if (!strncmp(p->name, prefix, n) && p->kind != uraP_CASE) {
      if (show_one(c, p, NULL)) return -1;
      found++;
    }
  }
  for (int i = 0; ur_injury_param_info(i, &name, NULL, NULL) == 0; i++) {
    if (!strncmp(name, prefix, n)) show_injury(c, i), found++;
  }
  const urModel* m = ura_model(c);
  for (int i = 0; m && i < m->nparam; i++) {
    if (!strncmp(m->param[i].name, prefix, n)) show_model_param(c, &m->param[i]), found++;
  }
  if (found && !strncmp("bag", prefix, n < 3 ? n : 3)) {
    if (ura_model_inflate(c)) return -1; /* 'show bag' asks for the inflated state */
    ura_bag_derived(c, c->out, show_tab);
  }
  return found;
}

static int show_lines(uraCtx* c, int argc, char** argv);

/* show [NAME|PREFIX]: aligned lines (also in format csv: scripts read them so), or in format
   json one table (name, value, unit, source) */
int ura_cmd_show(uraCtx* c, int argc, char** argv) {
  if (c->st.format != uraFMT_JSON) return show_lines(c, argc, argv);
  static const char* const cols[] = {"name", "value", "unit", "source"};
  show_tab = ura_table_new(4, cols);
  int rc = show_lines(c, argc, argv);
  uraTable* t = show_tab;
  show_tab = NULL;
  if (rc == 0) {
    ura_table_print(c, t);
  } else {
    ura_table_free(t);
  }
  return rc;
}

/* show's lines (or rows of show_tab) */
static int show_lines(uraCtx* c, int argc, char** argv) {
  if (argc == 2) {
    const uraParam* p = ura_param_find(argv[1]);
    int i = p ? -1 : ura_injury_find(argv[1]);
    int k = p || i >= 0 ? -1 : ura_model_param_find(c, argv[1]);
    if (k >= 0) {
      show_model_param(c, &c->model->param[k]);
      return 0;
    }
    /* a name set also takes (set bag_model membrane): the word, and the parameter it sets */
    const uraNamed* nv = p || i >= 0 ? NULL : ura_named_find(argv[1]);
    if (nv) {
      const char* word;
      double v;
      if (ura_named_word(c, nv, &word, &v)) return -1;
      char note[200];
      snprintf(note, sizeof note, "  (%s %g; set %s %s|%s)", nv->param, v, nv->name, nv->word[0],
               nv->word[1]);
      show_line(c, nv->name, word ? word : "?", "", note);
      return 0;
    }
    if (!p && i < 0) {
      int found = show_prefix(c, argv[1]);
      if (found) return found < 0 ? -1 : 0;
      uraSuggest sg;
      char dym[120];
      ura_suggest_init(&sg, argv[1]);
      ura_suggest_params(c, &sg);
      return ura_fail(c,
                      "show: unknown parameter '%s'%s; 'show' lists the parameters, 'show "
                      "PREFIX' those whose names start with PREFIX",
                      argv[1], ura_suggest_text(&sg, dym, sizeof dym));
    }
    if (p) return show_one(c, p, NULL);
    show_injury(c, i);
    return 0;
  }
  double ext[4] = {0, 0, 0, 0};
  for (const uraParam* p = ura_params; p->name; p++) {
    if (show_one(c, p, ext)) return -1;
  }
  if (!show_tab) fprintf(c->out, "# injury criteria (uasimpact-injury(7))\n");
  for (int i = 0; i < ur_injury_param_count(); i++) show_injury(c, i);
  if (!show_tab) {
    fprintf(c->out,
            "# model parameters, SI units (uasimpact-model(5); 'model params' says who set "
            "them)\n");
  }
  const urModel* m = ura_model(c);
  for (int i = 0; m && i < m->nparam; i++) show_model_param(c, &m->param[i]);
  ura_bag_derived(c, c->out, show_tab);
  ura_model_derived(c, c->out, show_tab);
  if (!show_tab) {
    ura_dist_show(c);
  } else {
    const uraRiskSet* r = &c->st.risk;
    char buf[1200];
    for (int i = 0; i < r->ndist; i++) {
      ura_dist_format(&r->dist[i], buf, sizeof buf);
      show_line(c, r->dist[i].name, buf, "", "  (input distribution of montecarlo: dist)");
    }
  }
  return 0;
}

int ura_cmd_case(uraCtx* c, int argc, char** argv) {
  return ura_case_load(c, argv[1]);
}

int ura_cmd_reset(uraCtx* c, int argc, char** argv) {
  /* what the user set: against the defaults under the live case's preset */
  uraState base, before = c->st;
  int known = ura_case_baseline(c, 0, &base) == 0;
  uraUndo* undo = c->undo; /* the undo levels outlive the reset (undo goes back before it) */
  c->undo = NULL;
  ura_models_free(c);
  c->undo = undo;
  ura_state_defaults(&c->st);
  if (ura_models_init(c)) return -1;
  if (ura_case_default(c)) return -1;
  char list[1500] = "";
  if (known) ura_dropped(c, &before, &base, &c->st, list, sizeof list);
  ura_dropped_note(c, "reset", list);
  return 0;
}

int ura_cmd_undo(uraCtx* c, int argc, char** argv) {
  char what[64];
  if (ura_undo_pop(c, what, sizeof what)) return -1;
  int left = ura_undo_levels(c);
  fprintf(c->msg, "undo: the settings as before '%s' (%d more level%s to undo, at most %d kept)\n",
          what, left, left == 1 ? "" : "s", uraUNDO_LEVELS);
  return 0;
}

int ura_cmd_quit(uraCtx* c, int argc, char** argv) {
  c->quit = 1;
  return 0;
}

void ura_suggest_commands(uraSuggest* s) {
  for (const uraCmd* k = ura_cmds; k->name; k++) ura_suggest_add(s, k->name);
}
