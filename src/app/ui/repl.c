/* repl.c: the interactive loop on GNU readline, with completion generated from the tables */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <readline/history.h>
#include <readline/readline.h>

#include "ui.h"


/* the candidates for the word being completed, gathered by complete() and filtered by gen().
   The one justified exception to "the application's state lives in uraCtx": GNU readline calls
   its completion hooks (rl_attempted_completion_function, rl_completion_entry_function) without
   a user-data pointer, so the context they need and the candidates they share are file statics,
   set by ura_repl for the one interactive loop a process runs. */
#define MAXCAND 512
static char cand[MAXCAND][64];
static int ncand;
static uraCtx* repl_ctx; /* for the model's parameter names */

/* one candidate, once (wind is both a sweep keyword and a parameter) */
static void add(const char* name) {
  if (!name || strlen(name) >= sizeof cand[0]) return;
  for (int i = 0; i < ncand; i++)
    if (!strcmp(cand[i], name)) return;
  if (ncand < MAXCAND) strcpy(cand[ncand++], name);
}

/* generator over the candidates that start with text */
static char* gen(const char* text, int state) {
  static int i;
  size_t n = strlen(text);
  if (!state) i = 0;
  while (i < ncand) {
    const char* name = cand[i++];
    if (!strncmp(name, text, n)) return strdup(name);
  }
  return NULL;
}

/* the keywords a usage text accepts at its first place: lowercase words at bracket depth 0 that
   begin the text or follow '|' ("pof|grid|history [SIGNAL...|all]|sweep [wind|face]": pof,
   grid, history, sweep); a text that is one bracketed group is opened first. With after set,
   the text that follows that keyword (up to the next '|' at depth 0) is read instead. */
static void keywords(const char* u, const char* after) {
  char text[256];
  snprintf(text, sizeof text, "%s", u);
  for (int pass = after ? 0 : 1; pass < 2; pass++) {
    char* t = text;
    size_t n = strlen(t);
    if (n >= 2 && t[0] == '[' && t[n - 1] == ']' && !strchr(t + 1, '[')) {
      t[n - 1] = 0;
      t++;
    }
    int depth = 0;
    for (char* p = t; *p; p++) {
      if (*p == '[') depth++;
      if (*p == ']') depth--;
      int starts = depth == 0 && (p == t || p[-1] == '|') && *p >= 'a' && *p <= 'z';
      if (!starts) continue;
      size_t k = strspn(p, "abcdefghijklmnopqrstuvwxyz_0123456789");
      if (pass == 1) {
        char w[64];
        snprintf(w, sizeof w, "%.*s", (int)k, p);
        add(w);
      } else if (after && strlen(after) == k && !strncmp(p, after, k)) {
        /* the rest of this alternative becomes the text */
        char* q = p + k;
        while (*q == ' ') q++;
        int d = 0;
        char* e = q;
        for (; *e && !(d == 0 && *e == '|'); e++) {
          if (*e == '[') d++;
          if (*e == ']') d--;
        }
        memmove(text, q, (size_t)(e - q));
        text[e - q] = 0;
        break;
      }
      p += k - 1;
    }
    if (pass == 0 && !strcmp(text, u)) return; /* after is not a keyword here */
  }
}

/* parameter names: the case state's, the injury settings', the model's */
static void add_params(void) {
  const char* name;
  for (int i = 0; ura_params[i].name; i++) add(ura_params[i].name);
  for (int i = 0; ur_injury_param_info(i, &name, NULL, NULL) == 0; i++) add(name);
  const urModel* m = repl_ctx ? ura_model(repl_ctx) : NULL;
  for (int i = 0; m && i < m->nparam; i++) add(m->param[i].name);
  for (int i = 0; ura_named[i].name; i++)
    if (!ura_named[i].numeric) add(ura_named[i].name); /* the others are model parameters */
}

/* what sweep NAME takes: wind and face, then every number parameter of the case and the model
   (show and clear come from the usage's keywords) */
static void add_sweepable(void) {
  keywords(ura_cmd_find("sweep")->usage + strlen("sweep "), NULL);
  for (int i = 0; ura_params[i].name; i++)
    if (ura_params[i].kind == uraP_NUM) add(ura_params[i].name);
  const urModel* m = repl_ctx ? ura_model(repl_ctx) : NULL;
  for (int i = 0; m && i < m->nparam; i++) add(m->param[i].name);
}

/* what plot sweep NAME draws: its keywords (wind, face), then the parameters of the kept
   sweeps */
static void add_kept_sweeps(const char* args) {
  keywords(args, "sweep");
  for (int i = 0; repl_ctx && i < repl_ctx->npsweep; i++) add(repl_ctx->psweep[i].param);
}

static char** complete(const char* text, int start, int end) {
  /* the words before the one being completed, in the last command of the line */
  char words[4][64] = {"", "", "", ""};
  int nw = 0;
  const char* s = rl_line_buffer;
  for (const char* p = rl_line_buffer; p < rl_line_buffer + start; p++) {
    if (*p == ';') s = p + 1;
  }
  while (s < rl_line_buffer + start) {
    while (s < rl_line_buffer + start && *s == ' ') s++;
    size_t k = strcspn(s, " ");
    if (s + k > rl_line_buffer + start || s >= rl_line_buffer + start) break;
    if (nw < 4) snprintf(words[nw], sizeof words[0], "%.*s", (int)k, s);
    nw++;
    s += k;
  }

  /* first word: commands; then what the command's table entry says */
  ncand = 0;
  rl_attempted_completion_over = 1;
  const uraCmd* cmd = nw ? ura_cmd_resolve(words[0], NULL, 0) : NULL;
  const char* args = cmd ? cmd->usage + strlen(cmd->name) : "";
  while (*args == ' ') args++;
  if (nw == 0) {
    for (int i = 0; ura_cmds[i].name; i++) add(ura_cmds[i].name);
  } else if (!cmd) {
    return NULL;
  } else if (nw == 1 && !strcmp(cmd->name, "sweep")) {
    add_sweepable(); /* sweep NAME LIST: wind, face, show, clear and the numeric parameters */
  } else if (nw == 1) {
    switch (cmd->compl ) {
    case uraC_COMMAND:
      for (int i = 0; ura_cmds[i].name; i++) add(ura_cmds[i].name);
      break;
    case uraC_PARAM: add_params(); break;
    case uraC_CASE: { /* the model's presets */
      const urModel* m = repl_ctx ? ura_model(repl_ctx) : NULL;
      for (int i = 0; m && i < m->npreset; i++) add(m->preset[i].name);
      break;
    }
    case uraC_POF:
      for (int i = 0; ura_pof_names[i]; i++) add(ura_pof_names[i]);
      break;
    case uraC_FILE: break;
    case uraC_NONE: keywords(args, NULL); break;
    }
  } else if (nw == 2 && !strcmp(cmd->name, "set") && !strcmp(words[1], "output")) {
    rl_attempted_completion_over = 0; /* set output FILE: readline's file names */
    return NULL;
  } else if (nw == 2 && !strcmp(cmd->name, "plot") && !strcmp(words[1], "sweep")) {
    add_kept_sweeps(args); /* plot sweep NAME: wind, face, the kept parameter sweeps */
  } else if (nw == 2 && cmd->compl == uraC_PARAM && !strcmp(cmd->name, "set")) {
    const uraParam* p = ura_param_find(words[1]);
    for (int i = 0;
         p && (p->kind == uraP_ENUM || p->kind == uraP_STR) && p->choices && p->choices[i]; i++)
      add(p->choices[i]);
    if (p && p->setoff) add("auto");
    const uraNamed* nv = ura_named_find(words[1]); /* set bag_model analytic|membrane ... */
    for (int i = 0; nv && i < 2; i++) add(nv->word[i]);
  } else if (nw == 2 && cmd->compl == uraC_NONE) {
    keywords(args, words[1]);
  }
  /* history CHANNEL..., plot history CHANNEL...: the last impact's signals */
  int hist = !strcmp(cmd ? cmd->name : "", "history") ||
             (nw >= 2 && !strcmp(cmd ? cmd->name : "", "plot") && !strcmp(words[1], "history"));
  uraTrace tr;
  if (hist && nw >= 1 && repl_ctx && ura_last_trace(repl_ctx, &tr) == 0) {
    if (nw > 1 || strcmp(cmd->name, "plot")) {
      if (!ncand) add("all");
      for (int k = 0; k < tr.nsig; k++) add(tr.names[k]);
    }
  }

  /* no names: readline's file-name completion (not for the value of a parameter) */
  if (!ncand && cmd && cmd->compl == uraC_PARAM && nw >= 2) return NULL;
  if (!ncand) {
    rl_attempted_completion_over = 0;
    return NULL;
  }
  return rl_completion_matches(text, gen);
}

/* the history file in HOME (NAME: .uasimpact_history, or the former name's .uasrisk_history) */
static char* history_path(const char* name) {
  const char* home = getenv("HOME");
  if (!home) return NULL;
  size_t n = strlen(home) + strlen(name) + 2;
  char* p = malloc(n);
  snprintf(p, n, "%s/%s", home, name);
  return p;
}

/* read the history: ~/.uasimpact_history, or once, while it does not exist yet, the history the
   tool kept under its former name (~/.uasrisk_history, left as it is); the new file is written
   at the end of the session */
static void history_load(const char* hist) {
  if (access(hist, F_OK) == 0) {
    read_history(hist);
    return;
  }
  char* old = history_path(".uasrisk_history");
  if (old) read_history(old);
  free(old);
}

/* Ctrl-C while typing: the line is dropped and the prompt comes again (never an exit) */
static int on_signal(void) {
  if (!ura_interrupted()) return 0;
  ura_interrupt_clear();
  rl_replace_line("", 0);
  rl_crlf();
  rl_on_new_line();
  rl_redisplay();
  return 0;
}

/* the prompt: the case, then the live model where it is not the case's: the parts loaded from
   files by name, "modified" when built-in parts were dropped or model parameters set
   (uasimpact[A|bag2]>, uasimpact[A|modified]>) */
static void prompt_text(uraCtx* c, char* buf, size_t n) {
  size_t k = (size_t)snprintf(buf, n, "uasimpact[%s", c->st.casename);
  for (int i = 0; i < c->npart && k < n; i++) {
    if (strcmp(c->part[i].origin, "built-in")) {
      k += (size_t)snprintf(buf + k, n - k, "%s%s", strchr(buf, '|') ? "," : "|", c->part[i].name);
    }
  }
  int modified = 0;
  for (int i = 0; i < c->st.nov; i++) modified |= c->st.ov_user[i];
  char* drops = NULL;
  size_t nd = 0;
  FILE* f = open_memstream(&drops, &nd);
  if (f) {
    ura_model_write_parts(c, f);
    fclose(f);
    modified |= drops && strstr(drops, "model drop") != NULL;
    free(drops);
  }
  if (modified && k < n) k += (size_t)snprintf(buf + k, n - k, "|modified");
  if (k < n) snprintf(buf + k, n - k, "]> ");
}

int ura_repl(uraCtx* c) {
  char* hist = history_path(".uasimpact_history");
  rl_readline_name = "uasimpact";
  repl_ctx = c;
  rl_attempted_completion_function = complete;

  /* SIGINT is ours (interrupt.c); while readline reads, its own handler restores the terminal,
     passes the signal on to ours, and calls on_signal */
  ura_interrupt_install(1);
  rl_signal_event_hook = on_signal;
  if (hist) history_load(hist);
  c->interactive = 1;

  /* one line on how to go on, as gnuplot and python greet a person (the version: what a report
     of a problem needs first); not when the lines come from a pipe (-i < FILE) */
  if (isatty(STDIN_FILENO))
    fprintf(c->msg, "%s; type help for the commands, q to quit\n", ura_version());

  /* read, run, report; errors never end the session */
  while (!c->quit) {
    char prompt[200];
    prompt_text(c, prompt, sizeof prompt);
    ura_interrupt_clear();
    char* line = readline(prompt);
    if (!line) {
      fputc('\n', c->out);
      break;
    }
    if (*line) add_history(line);
    /* (after Ctrl-C the terminal has echoed ^C: the message on a line of its own) */
    if (ura_run_line(c, line)) {
      fprintf(c->msg, "%serror: %s\n", ura_interrupted() ? "\n" : "", c->err);
    }
    free(line);
  }

  if (hist) {
    write_history(hist);
    history_truncate_file(hist, 1000);
    free(hist);
  }
  return 0;
}
