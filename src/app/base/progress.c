/* progress.c: the progress line of long work on a terminal (standard error): what runs, done of
 * total, the time since it started and an estimate of the time left; a sweep names the value it
 * is on (the label) */
#include <stdarg.h>
#include <stdio.h>
#include <time.h>

#include "base.h"


static char label[160];
static struct timespec t0;

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

/* a duration as 7 s, 2 min 05 s, 1 h 04 min */
static void duration(char* buf, size_t n, double s) {
  if (s < 60)
    snprintf(buf, n, "%.0f s", s);
  else if (s < 3600)
    snprintf(buf, n, "%d min %02d s", (int)(s / 60), (int)s % 60);
  else
    snprintf(buf, n, "%d h %02d min", (int)(s / 3600), (int)(s / 60) % 60);
}

void ura_progress_line(const char* what, long done, long total, const char* noun) {
  struct timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  double el = (double)(now.tv_sec - t0.tv_sec) + 1e-9 * (double)(now.tv_nsec - t0.tv_nsec);
  char e[32], left[48] = "";
  duration(e, sizeof e, el);
  if (done > 0 && done < total && el >= 1) {
    char r[32];
    duration(r, sizeof r, el * (double)(total - done) / (double)done);
    snprintf(left, sizeof left, ", about %s left", r);
  }
  fprintf(stderr, "\r%s%s %ld/%ld%s%s, %s%s\033[K", label, what, done, total, *noun ? " " : "",
          noun, e, left);
}
