/* scale_part.c: the part file of a shard (uasimpact --shard I/N --part OUT), versioned text:
 *   uasimpact-part 1       (uasrisk-part 1, the former name's, is read too, with a note)
 *   shard I N
 *   script HASH            the script files of the command line (ura_scale_script_hash)
 *   model HASH             the built-in models
 *   argc K                 then K lines 'arg WORD': the command line without --shard, --part
 *   grid G KEY NTODO NCELL then NCELL lines 'c POS CELL' (ura_cell_write), per grid run
 *   end STATUS NGRID       the shard's exit status and the grids it ran
 *   sum HASH               FNV-1a of every byte before this line
 * A part is data someone else may have written: reading checks every line strictly (a truncated
 * or damaged part is refused, not guessed at), reads the magic line before the rest, bounds every
 * count by the bytes left before allocating, and refuses a command line no shard runs and cell
 * values outside their domain (ura_cell_read). Its command line is never run: the merge compares
 * it with its own (scale_merge.c). */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "scale.h"
#include "../case/builtin.h"

#define MAXPART  (1L << 34) /* largest part read, bytes */
#define MAGICMAX 32         /* the most bytes read of a first line before it is known a part's */
#define MINARG   4          /* the shortest arg line: "arg\n" */
/* the shortest cell line: "c K ", status and contact, every value, PoF and p, extrap (2 bytes
   each or more), "|\n" */
#define MINCELL (4 + 4 + 2 * (urNVAL + urNCRIT + 1) + 2 + 2)

static void put_arg(FILE* f, const char* s) {
  fputs("arg ", f);
  for (; *s; s++) {
    unsigned char ch = (unsigned char)*s;
    if (ch == '\\')
      fputs("\\\\", f);
    else if (ch < 32 || ch == 127)
      fprintf(f, "\\x%02x", ch);
    else
      fputc(ch, f);
  }
  fputc('\n', f);
}

/* an escaped argument back in place; 0 or -1 */
static int get_arg(char* s) {
  char* w = s;
  for (char* r = s; *r; r++) {
    if (*r != '\\') {
      *w++ = *r;
    } else if (r[1] == '\\') {
      *w++ = '\\';
      r++;
    } else if (r[1] == 'x' && isxdigit((unsigned char)r[2]) && isxdigit((unsigned char)r[3])) {
      char hex[3] = {r[2], r[3], 0}, *end;
      long v = strtol(hex, &end, 16);
      if (*end || v <= 0) return -1;
      *w++ = (char)v;
      r += 3;
    } else {
      return -1;
    }
  }
  *w = 0;
  return 0;
}

void ura_part_header(FILE* f, int shard, int nshard, int argc, char** argv) {
  char sh[17], mh[17];
  ura_scale_script_hash(argc, argv, sh);
  ura_scale_model_hash(mh);
  fprintf(f, "%s %d\nshard %d %d\nscript %s\nmodel %s\nargc %d\n", uraPART_MAGIC, uraPART_VERSION,
          shard, nshard, sh, mh, argc);
  for (int i = 0; i < argc; i++) put_arg(f, argv[i]);
}

void ura_part_free(uraPartFile* p) {
  for (long g = 0; g < p->ngrid; g++) {
    free(p->grid[g].pos);
    free(p->grid[g].cell);
  }
  free(p->grid);
  free(p->argv);
  free(p->text);
  memset(p, 0, sizeof *p);
}

static int hex16(const char* s) {
  if (strlen(s) != 16) return -1;
  for (int i = 0; i < 16; i++) {
    if (!strchr("0123456789abcdef", s[i])) return -1;
  }
  return 0;
}

/* a whole decimal number in [lo, hi] */
static int num(const char* s, long lo, long hi, long* v) {
  char* end;
  if (!((*s >= '0' && *s <= '9') || (*s == '-' && s[1] >= '0' && s[1] <= '9'))) return -1;
  errno = 0;
  long x = strtol(s, &end, 10);
  if (errno || *end || x < lo || x > hi) return -1;
  *v = x;
  return 0;
}

/* the next line, split at spaces into at most max words (the last takes the rest) */
static int words(char** at, char* end, char** w, int max) {
  char* s = *at;
  if (s >= end) return -1;
  char* nl = memchr(s, '\n', (size_t)(end - s));
  if (!nl) return -1;
  *nl = 0;
  *at = nl + 1;
  int n = 0;
  while (n < max) {
    w[n++] = s;
    if (n == max) break;
    char* sp = strchr(s, ' ');
    if (!sp) break;
    *sp = 0;
    s = sp + 1;
  }
  return n;
}

/* the magic line "uasimpact-part VERSION" (or the former name's) at the start of text (n bytes): 0, or -1 with why */
static int magic(const char* text, size_t n, const char* path, char* err, size_t nerr) {
  size_t ml = strlen(uraPART_MAGIC);
  const char* nl = memchr(text, '\n', n);
  size_t ol = strlen(uraPART_MAGIC_OLD);
  if (nl && n > ol && !memcmp(text, uraPART_MAGIC_OLD " ", ol + 1)) {
    /* the tool's former name: its parts are the same format under another magic word */
    ml = ol;
    fprintf(stderr, "note: '%s' was written under the former name uasrisk; read as a part file\n",
            path);
  } else if (n < ml + 1 || memcmp(text, uraPART_MAGIC " ", ml + 1) || !nl) {
    snprintf(err, nerr,
             "'%s' is not a part file; accepted: files written by 'uasimpact --shard I/N --part "
             "FILE'",
             path);
    return -1;
  }
  long ver;
  char vbuf[16];
  snprintf(vbuf, sizeof vbuf, "%.*s", (int)(nl - text - (long)ml - 1), text + ml + 1);
  if (num(vbuf, 0, 1000000, &ver) || ver != uraPART_VERSION) {
    snprintf(err, nerr,
             "'%s' is a part file of format version %s; accepted: version %d (write the parts "
             "again with this uasimpact)",
             path, vbuf, uraPART_VERSION);
    return -1;
  }
  return 0;
}

/* the whole file, NUL-terminated. The magic line is read first, so that a directory, a device
   that never ends (/dev/zero) or any other file is refused at once; the rest is bounded by the
   file's size (a regular file) and by MAXPART */
static char* slurp(const char* path, size_t* n, char* err, size_t nerr) {
  FILE* f = fopen(path, "rb");
  struct stat st;
  if (!f || fstat(fileno(f), &st)) {
    snprintf(err, nerr, "cannot read '%s': %s", path, strerror(errno));
    if (f) fclose(f);
    return NULL;
  }
  if (S_ISDIR(st.st_mode)) {
    snprintf(err, nerr,
             "'%s' is a directory; accepted: files written by 'uasimpact --shard I/N --part FILE'",
             path);
    fclose(f);
    return NULL;
  }
  char head[MAGICMAX + 1];
  size_t len = 0;
  int ch = 0;
  while (len < MAGICMAX && ch != '\n' && (ch = getc(f)) != EOF) head[len++] = (char)ch;
  if (ferror(f)) {
    snprintf(err, nerr, "cannot read '%s': %s", path, strerror(errno ? errno : EIO));
    fclose(f);
    return NULL;
  }
  if (magic(head, len, path, err, nerr)) {
    fclose(f);
    return NULL;
  }
  if (S_ISREG(st.st_mode) && st.st_size > MAXPART) {
    snprintf(err, nerr, "'%s' is too large to read (%lld bytes; at most %lld)", path,
             (long long)st.st_size, (long long)MAXPART);
    fclose(f);
    return NULL;
  }
  size_t cap = S_ISREG(st.st_mode) ? (size_t)st.st_size + 65536 : 1 << 20;
  char* buf = malloc(cap);
  if (!buf) {
    snprintf(err, nerr, "'%s' is too large to read (out of memory)", path);
    fclose(f);
    return NULL;
  }
  memcpy(buf, head, len);
  for (;;) {
    if (len + 65536 + 1 > cap) {
      cap = 2 * cap;
      char* t = cap > (size_t)MAXPART + 65536 ? NULL : realloc(buf, cap);
      if (!t) {
        snprintf(err, nerr, "'%s' is too large to read (at most %lld bytes)", path,
                 (long long)MAXPART);
        free(buf);
        fclose(f);
        return NULL;
      }
      buf = t;
    }
    size_t r = fread(buf + len, 1, 65536, f);
    len += r;
    if (r < 65536) break;
  }
  int bad = ferror(f);
  int e = errno;
  fclose(f);
  if (bad) {
    snprintf(err, nerr, "cannot read '%s': %s", path, strerror(e ? e : EIO));
    free(buf);
    return NULL;
  }
  buf[len] = 0;
  *n = len;
  return buf;
}

int ura_part_read(const char* path, uraPartFile* p, char* err, size_t nerr) {
  size_t n;
  memset(p, 0, sizeof *p);
  char* text = slurp(path, &n, err, nerr);
  if (!text) return -1;
  return ura_part_parse(text, n, path, p, err, nerr);
}

int ura_part_parse(char* text, size_t n, const char* path, uraPartFile* p, char* err, size_t nerr) {
  memset(p, 0, sizeof *p);
  p->text = text;
  if (magic(text, n, path, err, nerr)) return -1;
  if (memchr(text, 0, n)) {
    snprintf(err, nerr, "'%s' is damaged (a NUL byte: a part is text); run its shard again", path);
    return -1;
  }

  /* the checksum of everything before the last line */
  char* last = n >= 2 ? text + n - 2 : text;
  while (last > text && *last != '\n') last--;
  if (n == 0 || text[n - 1] != '\n' || last == text || strncmp(last + 1, "sum ", 4)) {
    snprintf(err, nerr,
             "'%s' is truncated (no checksum line at its end); its shard did not "
             "finish: run it again",
             path);
    return -1;
  }
  char want[17];
  snprintf(want, sizeof want, "%016llx", ura_fnv(uraFNV0, text, (size_t)(last + 1 - text)));
  if (strlen(last + 5) != 17 || strncmp(last + 5, want, 16)) {
    snprintf(err, nerr,
             "'%s' is damaged (its checksum does not match its contents); run its "
             "shard again",
             path);
    return -1;
  }

  /* the lines, strictly */
  char *at = text, *end = last + 1, *w[8];
  long v, a, b;
  int nw;
#define BAD(what)                                                                                  \
  do {                                                                                             \
    snprintf(err, nerr, "'%s' is damaged (%s)", path, what);                                       \
    return -1;                                                                                     \
  } while (0)
  words(&at, end, w, 2);
  nw = words(&at, end, w, 3);
  if (nw != 3 || strcmp(w[0], "shard") || num(w[2], 1, 1000000, &b) || num(w[1], 0, b - 1, &a)) {
    BAD("bad shard line");
  }
  p->shard = (int)a;
  p->nshard = (int)b;
  nw = words(&at, end, w, 2);
  if (nw != 2 || strcmp(w[0], "script") || hex16(w[1])) BAD("bad script line");
  memcpy(p->script, w[1], 17);
  nw = words(&at, end, w, 2);
  if (nw != 2 || strcmp(w[0], "model") || hex16(w[1])) BAD("bad model line");
  memcpy(p->model, w[1], 17);
  nw = words(&at, end, w, 2);
  /* counts are bounded by the bytes left before anything is allocated: an arg line has at
     least MINARG bytes, a cell line MINCELL */
  if (nw != 2 || strcmp(w[0], "argc") || num(w[1], 0, (end - at) / MINARG, &v)) {
    BAD("bad argc line");
  }
  p->argc = (int)v;
  p->argv = calloc((size_t)p->argc + 1, sizeof *p->argv);
  if (!p->argv) BAD("out of memory");
  for (int i = 0; i < p->argc; i++) {
    nw = words(&at, end, w, 2);
    if (nw == 1 && !strcmp(w[0], "arg")) w[1] = w[0] + 3, nw = 2; /* an empty word */
    if (nw != 2 || strcmp(w[0], "arg") || get_arg(w[1])) BAD("bad arg line");
    p->argv[i] = w[1];
  }
  /* a command line a shard runs: scripts and -c COMMANDS, at least one, no other option */
  int ok = p->argc > 0;
  for (int i = 0; ok && i < p->argc; i++) {
    if (!strcmp(p->argv[i], "-c"))
      ok = ++i < p->argc;
    else
      ok = p->argv[i][0] != '-' || !p->argv[i][1];
  }
  if (!ok) {
    snprintf(err, nerr,
             "'%s' records a command line that no shard runs (an option other than -c, or no "
             "script); accepted: parts written by 'uasimpact --shard I/N --part FILE'",
             path);
    return -1;
  }
  long cap = 0;
  for (;;) {
    nw = words(&at, end, w, 5);
    if (nw < 1) BAD("no end line");
    if (!strcmp(w[0], "end")) break;
    if (nw != 5 || strcmp(w[0], "grid") || num(w[1], p->ngrid, p->ngrid, &v) || hex16(w[2]) ||
        num(w[3], 0, 1L << 40, &a) || num(w[4], 0, a, &b) || b > (end - at) / MINCELL) {
      BAD("bad grid line");
    }
    if (p->ngrid == cap) {
      cap = cap ? 2 * cap : 64;
      uraPartGrid* t = realloc(p->grid, (size_t)cap * sizeof *t);
      if (!t) BAD("out of memory");
      p->grid = t;
    }
    uraPartGrid* g = &p->grid[p->ngrid++];
    memset(g, 0, sizeof *g);
    memcpy(g->key, w[2], 17);
    g->ntodo = a;
    g->ncell = b;
    g->pos = malloc((size_t)(b ? b : 1) * sizeof *g->pos);
    g->cell = malloc((size_t)(b ? b : 1) * sizeof *g->cell);
    if (!g->pos || !g->cell) BAD("out of memory");
    for (long k = 0; k < b; k++) {
      nw = words(&at, end, w, 3);
      urCell cell = {0};
      if (nw != 3 || strcmp(w[0], "c") || num(w[1], k ? g->pos[k - 1] + 1 : 0, a - 1, &v) ||
          ura_cell_read(w[2], &cell)) {
        BAD("bad cell line");
      }
      g->pos[k] = v;
      g->cell[k] = w[2];
    }
  }
  if (nw != 3 || num(w[1], 0, 255, &a) || num(w[2], p->ngrid, p->ngrid, &v) || at != end) {
    BAD("bad end line");
  }
  p->status = (int)a;
  return 0;
#undef BAD
}

/* ---- what the distributors share: the checksum, the hashes a part is checked by, muting ---- */


void ura_scale_script_hash(int argc, char** argv, char out[17]) {
  unsigned long long h = uraFNV0;
  for (int i = 0; i < argc; i++) {
    if (!strcmp(argv[i], "-c")) {
      i++;
      continue;
    }
    if (argv[i][0] == '-' && argv[i][1]) continue;
    FILE* f = fopen(argv[i], "rb");
    char buf[65536];
    size_t r;
    h = ura_fnv(h, argv[i], strlen(argv[i]) + 1);
    if (!f) continue; /* the run itself will say it cannot read it */
    while ((r = fread(buf, 1, sizeof buf, f)) > 0) h = ura_fnv(h, buf, r);
    fclose(f);
  }
  snprintf(out, 17, "%016llx", h);
}

void ura_scale_model_hash(char out[17]) {
  unsigned long long h = uraFNV0;
  for (const urBuiltinModel* b = ur_builtin_models; b->name; b++) {
    h = ura_fnv(h, b->name, strlen(b->name) + 1);
    h = ura_fnv(h, b->text, strlen(b->text) + 1);
  }
  snprintf(out, 17, "%016llx", h);
}

int ura_scale_mute(uraCtx* c) {
  FILE* f = fopen("/dev/null", "w");
  if (!f) return -1;
  c->out = f;
  c->msg = f;
  c->mute = 1;
  return 0;
}
