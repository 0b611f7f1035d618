/* progress.c: the progress line of long work on a terminal (standard error): what runs, done of
 * total, the time since it started and an estimate of the time left; a sweep names the value it
 * is on (the label) and, being several grids, says how long is left of all of them: the
 * estimate of the whole run takes the grids done and the fraction of the one running, over the
 * time since the first one began (ura_progress_run). */
#include <stdarg.h>
#include <stdio.h>
#include <time.h>

#include "base.h"


static char label[160];
static struct timespec t0, r0; /* this piece of work; the run of several (a sweep) */
static int run_i, run_n;       /* the piece running, of how many (run_n 0: no run) */

void ura_progress_label(const char* fmt, ...) {
  if (!fmt) {
    label[0] = 0;
    return;
  }
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(label, sizeof label, fmt, ap);
  va_end(ap);
}

void ura_progress_start(void) {
  clock_gettime(CLOCK_MONOTONIC, &t0);
}

void ura_progress_run(int i, int n) {
  if (n > 0 && i == 0) clock_gettime(CLOCK_MONOTONIC, &r0);
  run_i = i;
  run_n = n;
}

/* a duration as 7 s, 2 min 05 s, 1 h 04 min (to the nearest second: 69.99 s is 1 min 10 s) */
static void duration(char* buf, size_t n, double s) {
  s = (double)(long)(s + 0.5);
  if (s < 60)
    snprintf(buf, n, "%.0f s", s);
  else if (s < 3600)
    snprintf(buf, n, "%d min %02d s", (int)(s / 60), (int)s % 60);
  else
    snprintf(buf, n, "%d h %02d min", (int)(s / 3600), (int)(s / 60) % 60);
}

void ura_progress_text(char* buf, size_t n, const char* what, long done, long total,
                       const char* noun, double el, int i, int runs, double el_run) {
  char e[32], left[48] = "", all[64] = "";
  duration(e, sizeof e, el);
  if (done > 0 && done < total && el >= 1) {
    char r[32];
    duration(r, sizeof r, el * (double)(total - done) / (double)done);
    snprintf(left, sizeof left, ", about %s left", r);
  }
  /* of a run of several: the pieces after this one as well */
  double frac = runs > 1 && total > 0 ? ((double)i + (double)done / (double)total) / runs : 0;
  if (frac > 0 && frac < 1 && i + 1 < runs && el_run >= 1) {
    char r[32];
    duration(r, sizeof r, el_run * (1 - frac) / frac);
    snprintf(all, sizeof all, " (all %d: about %s)", runs, r);
  }
  snprintf(buf, n, "%s%s %ld/%ld%s%s, %s%s%s", label, what, done, total, *noun ? " " : "", noun, e,
           left, all);
}

/* seconds from a to now */
static double since(const struct timespec* a) {
  struct timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return (double)(now.tv_sec - a->tv_sec) + 1e-9 * (double)(now.tv_nsec - a->tv_nsec);
}

void ura_progress_line(const char* what, long done, long total, const char* noun) {
  char buf[400];
  ura_progress_text(buf, sizeof buf, what, done, total, noun, since(&t0), run_i, run_n,
                    run_n ? since(&r0) : 0);
  fprintf(stderr, "\r%s\033[K", buf);
}
