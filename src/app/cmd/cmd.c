/* cmd.c: the command table (dispatch, help and completion all read it) and the state commands */
#include <stdio.h>
#include <string.h>

#include "cmd.h"


/* the one command table: name, handler, argument range, completion, usage, help */
const uraCmd ura_cmds[] = {
    {"help", ura_cmd_help, 0, 1, uraC_COMMAND, "help [COMMAND]",
     "list the commands, or explain one"},
    {"set", ura_cmd_set, 2, 3, uraC_PARAM, "set NAME VALUE [UNIT]",
     "change a parameter of the live case (see 'show' for names, units and ranges); model "
     "parameters take an optional unit"},
    {"show", ura_cmd_show, 0, 1, uraC_PARAM, "show [NAME]",
     "print the live case state with units, or one parameter; derived values say so"},
    {"case", ura_cmd_case, 1, 1, uraC_CASE, "case NAME",
     "load a preset of the model (the RA3's: A, B, C, A1, A2; 'model show' lists their preset lines); wind, "
     "face, step, recall and the output settings keep their values"},
    {"reset", ura_cmd_reset, 0, 0, uraC_NONE, "reset", "restore every default"},
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
     "sweep wind LIST|face LIST|NAME LIST [UNIT]|show|clear",
     "one grid per wind speed (m/s) or face direction (deg) of LIST, columns "
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
     "plot pof|grid|bag|history [SIGNAL...|all]|sweep [wind|face]|montecarlo|tornado",
     "send curves to gnuplot: the PoF curves, the last grid as a heat map, the last impact's "
     "membrane airbags at first contact and peak pressure, time histories of "
     "the last impact, Q of the kept sweeps, the last montecarlo's Q distribution or its "
     "variance shares (set terminal/output to write files)"},
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
     "model show|params [PREFIX]|parts|save FILE|load FILE|drop PART",
     "print, list (params: with units and who set them; PREFIX: the names starting with it), "
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
    {"quit", ura_cmd_quit, 0, 0, uraC_NONE, "quit", "leave uasimpact (also: exit, Ctrl-D)"},
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
    const uraCmd* k = ura_cmd_find(argv[1]);
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

/* set, then at the prompt the models the setting changes (design.c) */
int ura_cmd_set(uraCtx* c, int argc, char** argv) {
  int rc = ura_design_set(c, argv[1], argv[2], argc == 4 ? argv[3] : NULL);
  if (rc == 1) rc = set_one(c, argc, argv);
  const char* reach = rc ? NULL : ura_design_reach(c, argv[1]);
  if (reach && c->interactive) fprintf(c->msg, "set %s: changes %s\n", argv[1], reach);
  return rc;
}

static int set_one(uraCtx* c, int argc, char** argv) {
  /* set bag_model analytic|membrane: the model parameter bag_membrane (0|1) by name */
  if (!strcmp(argv[1], "bag_model")) {
    int mem = !strcmp(argv[2], "membrane");
    if (argc != 3 || (!mem && strcmp(argv[2], "analytic"))) {
      return ura_fail(c, "set bag_model: expected analytic or membrane (got '%s'%s)", argv[2],
                      argc == 4 ? " and a unit" : "");
    }
    if (ura_model_param_find(c, "bag_membrane") < 0) {
      return ura_fail(c,
                      "set bag_model: the model has no parameter bag_membrane (its airbags "
                      "declare no membrane)");
    }
    char* av[3] = {"set", "bag_membrane", mem ? "1" : "0"};
    return ura_model_param_set(c, av[1], av[2], NULL, 1);
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
  /* a unit is accepted when it is the parameter's own (set wind 3 m/s) */
  if (argc == 4 && !(p && *p->unit && !strcmp(argv[3], p->unit))) {
    return ura_fail(c, "set %s: takes no unit but its own (it is in %s)", argv[1],
                    p && *p->unit ? p->unit : "the unit 'show' prints");
  }
  return p ? ura_param_set(c, p, argv[2]) : ura_injury_set(c, i, argv[2]);
}

/* one line of show: name, value, unit, and where a derived value comes from; ext (NULL: one
   parameter alone) keeps the derived grid extents across the lines of a listing (ext[3]: 0 not
   sized yet, 1 sized, -1 not available) */
static int show_one(uraCtx* c, const uraParam* p, double ext[4]) {
  char val[1024], src[160];
  const char* note = "";
  if (p->setoff && !*(const int*)((const char*)&c->st + p->setoff)) {
    double one[4] = {0, 0, 0, 0}, *v = ext ? ext : one;
    if (!strcmp(p->name, "speed") || !strcmp(p->name, "angle")) {
      if (ura_impact_conditions(c, &v[0], &v[1])) {
        if (!ext) return -1;
        /* the whole listing still prints (e.g. the paper's Table 2 at an unprinted wind) */
        fprintf(c->out, "%-16s auto %s  (derived: not available: %s)\n", p->name, p->unit, c->err);
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
      /* grid extents: the lattice the next grid would use (sizing needs the settled stance) */
      if (v[3] == 0) v[3] = ura_grid_extents(c, &v[0], &v[1], &v[2]) ? -1 : 1;
      if (v[3] < 0) {
        if (!ext) return -1;
        /* the whole listing still prints (e.g. in dry mode): the value is left to the grid */
        c->err[0] = 0;
        fprintf(c->out, "%-16s auto %s  (derived at the next grid)\n", p->name, p->unit);
        return 0;
      }
      double x = !strcmp(p->name, "along_min") ? v[0] : !strcmp(p->name, "along_max") ? v[1] : v[2];
      note = "  (derived: every cell where contact is possible, padded by one cell)";
      snprintf(val, sizeof val, "%.6g", x);
    }
  } else {
    ura_param_format(c, p, val, sizeof val);
    if (p->setoff)
      note = "  (set)";
    else
      note = ura_design_mark(c, p->name, src, sizeof src);
  }
  fprintf(c->out, "%-16s %s%s%s%s\n", p->name, val, *p->unit ? " " : "", p->unit, note);
  return 0;
}

/* one injury setting */
static void show_injury(uraCtx* c, int i) {
  const char* name;
  char val[128];
  ur_injury_param_info(i, &name, NULL, NULL);
  ura_injury_line(c, i, val, sizeof val, 1);
  fprintf(c->out, "%-16s %s\n", name, val);
}

/* one model parameter: name, SI value, its unit */
static void show_model_param(uraCtx* c, const urParam* p) {
  fprintf(c->out, "%-16s %.10g%s%s\n", p->name, p->value, *p->unit ? " " : "", p->unit);
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
  if (found && !strncmp("bag", prefix, n < 3 ? n : 3)) ura_bag_derived(c, c->out);
  return found;
}

int ura_cmd_show(uraCtx* c, int argc, char** argv) {
  if (argc == 2) {
    const uraParam* p = ura_param_find(argv[1]);
    int i = p ? -1 : ura_injury_find(argv[1]);
    int k = p || i >= 0 ? -1 : ura_model_param_find(c, argv[1]);
    if (k >= 0) {
      show_model_param(c, &c->model->param[k]);
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
  fprintf(c->out, "# injury criteria (uasimpact-injury(7))\n");
  for (int i = 0; i < ur_injury_param_count(); i++) show_injury(c, i);
  fprintf(c->out,
          "# model parameters, SI units (uasimpact-model(5); 'model params' says who set "
          "them)\n");
  const urModel* m = ura_model(c);
  for (int i = 0; m && i < m->nparam; i++) show_model_param(c, &m->param[i]);
  ura_bag_derived(c, c->out);
  ura_dist_show(c);
  return 0;
}

int ura_cmd_case(uraCtx* c, int argc, char** argv) {
  return ura_case_load(c, argv[1]);
}

int ura_cmd_reset(uraCtx* c, int argc, char** argv) {
  ura_models_free(c);
  ura_state_defaults(&c->st);
  if (ura_models_init(c)) return -1;
  return ura_case_default(c);
}

int ura_cmd_quit(uraCtx* c, int argc, char** argv) {
  c->quit = 1;
  return 0;
}

void ura_suggest_commands(uraSuggest* s) {
  for (const uraCmd* k = ura_cmds; k->name; k++) ura_suggest_add(s, k->name);
}
