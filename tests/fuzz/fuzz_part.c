/* fuzz_part.c: libFuzzer target for the part file reader (src/app/scale_part.c, the cells through
 * src/app/scale_cell.c): a part is data someone else may have written, so no input may crash it,
 * leak, or be accepted with anything merge could not trust. Each input is parsed twice: as it is
 * (the checksum refuses almost every mutation) and with its checksum line recomputed, as a forger
 * would, so that the line parser behind the checksum is reached. An accepted part must hold what
 * merge relies on: a shard below the shard count, a command line a shard runs (scripts and -c
 * COMMANDS, at least one), cells at increasing positions below the list length, each of which
 * reads back with p and every PoF in [0, 1] and a printable reason; a refusal is one line.
 *   make fuzz            (tests/fuzz/corpus_part, dictionary tests/fuzz/part.dict)
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/app/scale/scale.h"

/* what merge relies on in an accepted part; abort() when it does not hold */
static void check_accepted(const uraPartFile* p) {
  if (p->nshard < 1 || p->shard < 0 || p->shard >= p->nshard || p->argc < 1) abort();
  for (int i = 0; i < p->argc; i++) {
    if (!strcmp(p->argv[i], "-c")) {
      if (++i >= p->argc) abort();
    } else if (p->argv[i][0] == '-' && p->argv[i][1]) {
      abort();
    }
  }
  for (long g = 0; g < p->ngrid; g++) {
    const uraPartGrid* pg = &p->grid[g];
    if (pg->ncell < 0 || pg->ncell > pg->ntodo) abort();
    for (long k = 0; k < pg->ncell; k++) {
      if (pg->pos[k] < 0 || pg->pos[k] >= pg->ntodo || (k && pg->pos[k] <= pg->pos[k - 1])) abort();
      urCell c;
      memset(&c, 0, sizeof c);
      if (ura_cell_read(pg->cell[k], &c)) abort();
      if (!(c.p >= 0 && c.p <= 1)) abort();
      for (int i = 0; i < urNCRIT; i++) {
        if (!(c.pof[i] >= 0 && c.pof[i] <= 1)) abort();
      }
      for (int i = 0; i < urNVAL; i++) {
        if (isinf(c.val[i])) abort();
      }
      char shown[4 * sizeof c.reason + 1];
      ura_printable(c.reason, shown, sizeof shown);
      if (strcmp(shown, c.reason)) abort();
    }
  }
}

/* parse a copy of data (n bytes); when fix, its last line's checksum recomputed first */
static void parse(const uint8_t* data, size_t n, int fix) {
  char* text = malloc(n + 1);
  if (!text) return;
  memcpy(text, data, n);
  text[n] = 0;
  if (fix) { /* "sum " and 16 hex digits and a newline at the end: the digits made right */
    if (n < 22 || memcmp(text + n - 22, "\nsum ", 5) || text[n - 1] != '\n') {
      free(text);
      return;
    }
    char hex[17];
    snprintf(hex, sizeof hex, "%016llx", ura_fnv(uraFNV0, text, n - 21));
    memcpy(text + n - 17, hex, 16);
  }
  uraPartFile p;
  char err[uraERRLEN];
  err[0] = 0;
  if (ura_part_parse(text, n, "fuzz", &p, err, sizeof err) == 0) {
    check_accepted(&p);
  } else if (!err[0] || strlen(err) >= sizeof err - 1 || strchr(err, '\n')) {
    abort(); /* a refusal says why, on one line */
  }
  ura_part_free(&p);
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  parse(data, size, 0);
  parse(data, size, 1);
  return 0;
}
