/* plot_term.c: the gnuplot terminals and outputs plot accepts: what each terminal draws on, the
 * checks of 'set terminal' and 'set output' (a known terminal, known options with strict numbers;
 * a file name gnuplot cannot take for a command), and the terminal an output's extension implies.
 * Nothing here runs gnuplot (plot.c does). */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "case.h"


/* the terminals plot accepts, by what they draw on */
static const char* const term_window[] = {"qt", "wxt", "x11", NULL};
static const char* const term_text[] = {"dumb",       "caca",  "sixelgd", "kittygd",
                                        "kittycairo", "block", NULL};
static const char* const term_file[] = {"png",      "pngcairo", "jpeg",       "gif",    "svg",
                                        "pdfcairo", "epscairo", "postscript", "canvas", NULL};

/* what completion offers after set terminal: gnuplot's default, then every accepted name */
const char* const ura_term_choices[] = {
    "default",    "png",        "pngcairo", "jpeg", "gif",  "svg",     "pdfcairo",
    "epscairo",   "postscript", "canvas",   "dumb", "caca", "sixelgd", "kittygd",
    "kittycairo", "block",      "qt",       "wxt",  "x11",  NULL};

static int in_list(const char* const* list, const char* w, size_t n) {
  for (int i = 0; list[i]; i++)
    if (strlen(list[i]) == n && !strncmp(list[i], w, n)) return 1;
  return 0;
}

int ura_term_kind(const char* t) {
  size_t n = strcspn(t, " ");
  if (!n || in_list(term_window, t, n)) return uraTERM_WINDOW;
  if (in_list(term_text, t, n)) return uraTERM_TEXT;
  return uraTERM_FILE;
}

/* terminal options: words alone, and words that take a number */
static const char* const opt_flag[] = {
    "enhanced",    "noenhanced",    "color",   "colour",    "mono",        "monochrome",
    "transparent", "notransparent", "crop",    "nocrop",    "rounded",     "butt",
    "square",      "solid",         "dashed",  "interlace", "nointerlace", "truecolor",
    "notruecolor", "standalone",    "persist", "nopersist", "raise",       "noraise",
    "ctrl",        "noctrl",        "ansi",    "ansi256",   "ansirgb",     "feed",
    "nofeed",      "utf8",          "ascii",   NULL};
static const char* const opt_num[] = {"fontscale", "linewidth",  "lw", "dashlength",
                                      "dl",        "pointscale", "ps", NULL};

/* a strict decimal number in (0, max], optionally followed by one of the units */
static int positive(const char* s, size_t n, double max, const char* const* units) {
  char buf[40];
  if (n == 0 || n >= sizeof buf) return 0;
  memcpy(buf, s, n);
  buf[n] = 0;
  for (int i = 0; units && units[i]; i++) {
    size_t k = strlen(units[i]);
    if (n > k && !strcmp(buf + n - k, units[i])) {
      buf[n - k] = 0;
      break;
    }
  }
  double v;
  return !ura_parse_number(buf, &v) && v > 0 && v <= max && !strpbrk(buf, " \t");
}

/* the next word of a terminal value: a quoted string ('...' or "...", its text without the
   quotes, *quoted set) or a run of non-blanks; NULL at the end or on an open quote */
static const char* word(const char** s, size_t* n, int* quoted) {
  const char* p = *s;
  while (*p == ' ' || *p == '\t') p++;
  *quoted = 0;
  if (!*p) return NULL;
  if (*p == '\'' || *p == '"') {
    const char* e = strchr(p + 1, *p);
    if (!e) {
      *n = 0;
      *s = p + strlen(p);
      *quoted = -1;
      return p;
    }
    *n = (size_t)(e - p - 1);
    *s = e + 1;
    *quoted = 1;
    return p + 1;
  }
  *n = strcspn(p, " \t");
  *s = p + *n;
  return p;
}

int ura_terminal_check(uraCtx* c, const char* value, char* norm, size_t n) {
  static const char* const accepted =
      "accepted: NAME [OPTION...]: NAME one of png, pngcairo, jpeg, gif, svg, pdfcairo, epscairo, "
      "postscript, canvas, dumb, caca, sixelgd, kittygd, kittycairo, block, qt, wxt, x11; options "
      "size W,H (numbers, in or cm after each for vector terminals), font 'NAME,SIZE' (letters, "
      "digits, blanks, ,.-_+), background '#RRGGBB' or 'NAME', fontscale, linewidth, dashlength, "
      "pointscale N, and words such as enhanced, mono, transparent, crop, ansi (uasimpact(1))";
  static const char* const size_units[] = {"in", "cm", NULL};
  const char* s = value;
  size_t len, k = 0;
  int quoted;
  char buf[512];
  const char* w = word(&s, &len, &quoted);
  if (!w || quoted ||
      !(in_list(term_window, w, len) || in_list(term_text, w, len) || in_list(term_file, w, len))) {
    char name[80];
    snprintf(name, sizeof name, "%.*s", w ? (int)(len < 60 ? len : 60) : 0, w ? w : "");
    return ura_fail(c, "set terminal: unknown terminal '%s'; %s", name, accepted);
  }
  k += (size_t)snprintf(buf + k, sizeof buf - k, "%.*s", (int)len, w);

  /* the options, each checked and written again by us */
  while ((w = word(&s, &len, &quoted))) {
    const char* why = NULL;
    if (quoted) {
      why = quoted < 0 ? "an unterminated quote" : "a quoted text where an option belongs";
    } else if (in_list(opt_flag, w, len)) {
      k += (size_t)snprintf(buf + k, sizeof buf - k, " %.*s", (int)len, w);
    } else if (in_list(opt_num, w, len) || (len == 4 && !strncmp(w, "size", 4))) {
      int size = len == 4 && !strncmp(w, "size", 4);
      char key[16];
      snprintf(key, sizeof key, "%.*s", (int)len, w);
      const char* a = word(&s, &len, &quoted);
      const char* comma = a && !quoted ? memchr(a, ',', len) : NULL;
      int ok = a && !quoted &&
               (size ? comma && positive(a, (size_t)(comma - a), 20000, size_units) &&
                           positive(comma + 1, len - (size_t)(comma - a) - 1, 20000, size_units)
                     : positive(a, len, 100, NULL));
      if (!ok) {
        why = size ? "size needs W,H: two positive numbers up to 20000 without blanks"
                   : "this option needs a positive number up to 100";
        w = key;
        len = strlen(key);
      } else {
        k += (size_t)snprintf(buf + k, sizeof buf - k, " %s %.*s", key, (int)len, a);
      }
    } else if (len == 4 && !strncmp(w, "font", 4)) {
      const char* a = word(&s, &len, &quoted);
      if (!a || quoted != 1 || len > 40 ||
          strspn(a,
                 "abcdefghijklmnopqrstuvwxyz"
                 "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 ,.-_+") < len) {
        why = "font needs a quoted 'NAME,SIZE' of at most 40 letters, digits, blanks and ,.-_+";
        w = "font";
        len = 4;
      } else {
        k += (size_t)snprintf(buf + k, sizeof buf - k, " font '%.*s'", (int)len, a);
      }
    } else if (len == 10 && !strncmp(w, "background", 10)) {
      const char* a = word(&s, &len, &quoted);
      if (a && !quoted && len == 3 && !strncmp(a, "rgb", 3)) a = word(&s, &len, &quoted);
      int hex = a && len >= 7 && len <= 9 && a[0] == '#' &&
                strspn(a + 1, "0123456789abcdefABCDEF") >= len - 1 && (len == 7 || len == 9);
      int named = a && len >= 1 && len <= 30 && strspn(a, "abcdefghijklmnopqrstuvwxyz-") >= len;
      if (!a || quoted != 1 || !(hex || named)) {
        why = "background needs a quoted colour, '#RRGGBB' or a name such as 'white'";
        w = "background";
        len = 10;
      } else {
        k += (size_t)snprintf(buf + k, sizeof buf - k, " background rgb '%.*s'", (int)len, a);
      }
    } else {
      why = "not an option plot accepts";
    }
    if (why) {
      char opt[80];
      snprintf(opt, sizeof opt, "%.*s", (int)(len < 60 ? len : 60), w);
      return ura_fail(c, "set terminal: option '%s': %s; %s", opt, why, accepted);
    }
    if (k >= sizeof buf) break;
  }
  if (k >= n) {
    return ura_fail(c,
                    "set terminal: the terminal and its options take %zu characters; accepted: "
                    "at most %zu",
                    k, n - 1);
  }
  memcpy(norm, buf, k + 1);
  return 0;
}

int ura_output_check(uraCtx* c, const char* value, char* norm, size_t n) {
  const char* p = value;
  while (*p == ' ' || *p == '\t') p++;
  const char* why = *p == '|' ? "it starts with '|', which gnuplot takes for a pipe to a command"
                    : ura_word_ok(value) ? "it holds a control character or both quote characters"
                    : strlen(value) >= n ? "it is too long"
                                         : NULL;
  if (why) {
    return ura_fail(c,
                    "set output: '%s' is refused: %s; accepted: a file name of at most %zu "
                    "bytes without control characters, not starting with '|' (write ./|NAME for "
                    "such a file)",
                    value, why, n - 1);
  }
  strcpy(norm, value);
  return 0;
}

/* a terminal for an output file without one, from its extension */
const char* ura_term_for_ext(const char* path) {
  static const char* const map[][2] = {{".png", "pngcairo"}, {".svg", "svg"},  {".pdf", "pdfcairo"},
                                       {".eps", "epscairo"}, {".txt", "dumb"}, {".jpg", "jpeg"},
                                       {".jpeg", "jpeg"},    {".gif", "gif"},  {NULL, NULL}};
  const char* dot = strrchr(path, '.');
  if (!dot) return NULL;
  for (int i = 0; map[i][0]; i++)
    if (!strcasecmp(dot, map[i][0])) return map[i][1];
  return NULL;
}
