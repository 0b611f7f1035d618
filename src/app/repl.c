/* repl.c: the interactive loop on GNU readline, with completion generated from the tables */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <readline/history.h>
#include <readline/readline.h>

#include "app.h"

/* what the word being completed is: a command, or the argument of a command */
static uraCompl compl_kind;

/* generator over the names of the current kind */
static char* gen(const char* text, int state) {
  static int i;
  size_t n = strlen(text);
  if (!state) i = 0;
  for (;;) {
    const char* name = NULL;
    switch (compl_kind) {
    case uraC_COMMAND: name = ura_cmds[i].name; break;
    case uraC_PARAM: name = ura_params[i].name; break;
    case uraC_CASE: name = ura_case_names[i]; break;
    case uraC_POF: name = ura_pof_names[i]; break;
    default: return NULL;
    }
    if (!name) return NULL;
    i++;
    if (!strncmp(name, text, n)) return strdup(name);
  }
}

static char** complete(const char* text, int start, int end) {
  /* first word: commands; later words: what the command's table entry says */
  char first[64] = "";
  int k = 0;
  const char* s = rl_line_buffer;
  while (*s == ' ') s++;
  while (*s && *s != ' ' && k < 63) first[k++] = *s++;
  first[k] = 0;
  int is_first = (s - rl_line_buffer) >= start;

  rl_attempted_completion_over = 1;
  if (is_first) {
    compl_kind = uraC_COMMAND;
  } else {
    const uraCmd* cmd = ura_cmd_find(first);
    compl_kind = cmd ? cmd->compl : uraC_NONE;
    if (compl_kind == uraC_FILE || compl_kind == uraC_NONE) {
      rl_attempted_completion_over = 0;   /* readline's file-name completion */
      return NULL;
    }
  }
  return rl_completion_matches(text, gen);
}

static char* history_path(void) {
  const char* home = getenv("HOME");
  if (!home) return NULL;
  size_t n = strlen(home) + 32;
  char* p = malloc(n);
  snprintf(p, n, "%s/.uasrisk_history", home);
  return p;
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

int ura_repl(uraCtx* c) {
  char* hist = history_path();
  rl_readline_name = "uasrisk";
  rl_attempted_completion_function = complete;

  /* SIGINT is ours (interrupt.c); while readline reads, its own handler restores the terminal,
     passes the signal on to ours, and calls on_signal */
  ura_interrupt_install(1);
  rl_signal_event_hook = on_signal;
  if (hist) read_history(hist);
  c->interactive = 1;

  /* read, run, report; errors never end the session */
  while (!c->quit) {
    char prompt[64];
    snprintf(prompt, sizeof prompt, "uasrisk[%s]> ", c->st.casename);
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
