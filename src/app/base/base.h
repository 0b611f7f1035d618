/* base.h: the base layer of the application (src/app/base): text and files, knowing nothing of a
 * case. Strict parsing of numbers, tables, wrapping, the pager, the progress line, Ctrl-C and the
 * temporary file it removes, defensive line reading and printable messages, files written
 * atomically, "did you mean", the version, and the colour roles (the P{F|Delta} bands and the
 * parts of a screen, after htop's ColorElements/CRT_colors, shared by 'grid show' and 'view').
 * Everything here takes plain streams, buffers and values, never the session's context: a
 * failure is a return value with its message in a buffer the caller owns. The layers above
 * (case, cmd, ui, scale, main) include this header; it includes no header of theirs.
 */
#ifndef UASIMPACT_BASE_H
#define UASIMPACT_BASE_H

#include <jansson.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdio.h>

#include "uasimpact/grid.h"

#define uraERRLEN 1024 /* a failure message, bytes */

/* ---- strict parsing ---- */

/* a finite decimal number (no hex, nan, inf, empty, or trailing text) */
int ura_parse_number(const char* s, double* v);
/* a comma-separated list of numbers; returns count or -1 */
int ura_parse_list(const char* s, double* v, int max);
/* the same, and on failure why (n bytes) says what is wrong, naming the value by its place
   rather than echoing the list: "value 3 of 70, 'x', is not a number", "value 2 of 3 is
   empty", "70 values, more than 64", "the list is empty" */
int ura_parse_list_why(const char* s, double* v, int max, char* why, size_t n);
/* the number of values a comma-separated list holds (its commas plus one) */
int ura_list_count(const char* s);
/* the installed data folder (PREFIX/share/uasimpact beside the program's PREFIX/bin) into buf;
   0, or -1 when there is none (datadir.c) */
int ura_data_dir(char* buf, size_t n);
/* open path for reading; a relative name that is not in the current folder is looked for in the
   data folder, its sessions/ and their subfolders; the name opened into found (n bytes); NULL
   with errno of the first attempt when none (datadir.c) */
FILE* ura_data_open(const char* path, char* found, size_t n);
/* the folder of path into buf (n bytes): "." for a bare name, "/" at the root (datadir.c) */
void ura_dir_of(const char* path, char* buf, size_t n);
/* the format a file name's extension names ("HTML" for x.html, "text" for x.txt, "PNG", ...;
   case ignored), or NULL for none or one unknown here; whether the name fits a writer of the
   extensions exts (blank-separated, "html htm"): 1 when its extension is one of them or names no
   format here (fileext.c) */
const char* ura_ext_format(const char* path);
int ura_ext_fits(const char* path, const char* exts);
/* the first extension of a format ura_ext_format names ("png" for "PNG"), or NULL */
const char* ura_format_ext(const char* format);
/* a speed unit: m/s, km/h or kt (exactly so); 0 with the factor to m/s, or -1 (speedunit.c) */
int ura_speed_unit(const char* unit, double* to_si);
/* v in a unit ura_speed_unit accepts, in m/s (v * 1852 / 3600 for kt: 36 km/h is 10 m/s exactly) */
double ura_speed_to_si(const char* unit, double v);
#define uraSPEED_UNITS "m/s, km/h or kt"

/* ---- hashing (fnv.c) ---- */

/* 64-bit FNV-1a, chained from h (start with uraFNV0): the checksums and hashes of part files,
   the model texts' hashes in a report */
#define uraFNV0 0xcbf29ce484222325ULL
unsigned long long ura_fnv(unsigned long long h, const void* p, size_t n);

/* ---- tabular output ---- */

typedef struct uraTable uraTable;
uraTable* ura_table_new(int ncol, const char* const* names);
void ura_table_cell(uraTable* t, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
void ura_table_note(uraTable* t, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
/* how a table is written: aligned for people, plain CSV, or one JSON object on one line */
enum {
  uraTAB_TEXT,
  uraTAB_CSV,
  uraTAB_JSON
};
/* write t to f as how says and free it. Text: notes first as '# ' lines wrapped at width, the
   columns folded into blocks that fit width (0: neither wrapped nor folded). CSV: the header
   line and the rows only, the notes to nf as '# ' lines (nf NULL: not written). JSON:
   {"columns":[...],"rows":[{column:value,...}],"notes":[...]} (numbers as numbers, empty cells
   null) and a newline. A cell "-" (no value) is an empty field in CSV and null in JSON, so that
   a numeric column stays numeric */
void ura_table_write(FILE* f, FILE* nf, uraTable* t, int how, int width);
/* the table as a new JSON object (the form ura_table_write writes), for a caller that keeps it */
json_t* ura_table_json(const uraTable* t);
/* the unit of column col, kept for the sidecar of an export (unit NULL: none); what was given */
void ura_table_unit(uraTable* t, int col, const char* unit);
const char* ura_table_unit_of(const uraTable* t, int col);
/* free t unwritten */
void ura_table_free(uraTable* t);
/* how many rows t holds */
int ura_table_rows(const uraTable* t);
/* what a table holds, for a reader that keeps it (the report): its column names, cells (row by
   row) and notes, owned by the table */
void ura_table_parts(const uraTable* t, int* ncol, char* const** names, int* ncell,
                     char* const** cells, int* nnote, char* const** notes);

/* a word a script reads back as s: ura_put_word writes it in single quotes, or in double ones
   when s holds a single quote (word.c). ura_word_ok: -1 when the script reader cannot take it
   back (a control byte, or both quote characters); ura_word_inert: -1 also when it cannot be
   quoted so that a shell would not expand it either (a single quote with a double quote, $,
   backquote, backslash or !): the test of what save session writes */
int ura_word_ok(const char* s);
int ura_word_inert(const char* s);
void ura_put_word(FILE* f, const char* s);

/* files written atomically (atomic.c): open a temporary file beside path (symbolic links
   followed); close renames it over the file if ok and everything was written, else removes it (a
   failure message unless !ok). A FIFO, a character device or an open descriptor (/dev/stdout)
   is written in place; directories, block devices and sockets are refused. */
typedef struct {
  FILE* f;
  int fd;
  int inplace;     /* written in place (no temporary file, no rename) */
  int err;         /* errno of the first failed write */
  char path[1024]; /* as given (messages) */
  char real[4096]; /* the file replaced */
  char tmp[4200];  /* the temporary file beside it */
} uraAtomic;
/* open, as above; close, as above. who names the command in messages ("save session"); a
   failure is -1 with its message in err (nerr bytes). regular: for a file another process writes
   by the name a->tmp (gnuplot): only a regular file or a new one; anything else (/dev/stdout,
   /dev/fd/N, a FIFO, a device) is refused */
int ura_atomic_begin(uraAtomic* a, const char* path, const char* who, int regular, char* err,
                     size_t nerr);
int ura_atomic_end(uraAtomic* a, int ok, const char* who, char* err, size_t nerr);

/* Ctrl-C (interrupt.c): the handler for the whole run (interactive: repeated Ctrl-C never end
   the program), the flag that long work polls (also the models' opt.stop), cleared at the
   prompt */
void ura_interrupt_install(int interactive);
_Atomic int* ura_interrupt_flag(void);
int ura_interrupted(void);
void ura_interrupt_clear(void);
/* the temporary file of a write under way, removed if a signal that ends the program by default
   (SIGTERM, SIGHUP, SIGUSR1, SIGALRM, SIGPIPE, ...) or a fatal Ctrl-C ends it (at most one at a
   time); disarm when it is renamed or removed */
void ura_temp_arm(const char* path);
void ura_temp_disarm(void);
/* a child process (gnuplot) that writes the armed temporary file: killed and reaped before the
   file is removed, so that it cannot make it again; disarm once it is reaped */
void ura_child_arm(int pid);
void ura_child_disarm(void);

/* the keys that stop a wait on a raw terminal (keywatch.c) */
typedef struct {
  pthread_t thread;
  int fd;           /* the terminal read */
  int running;      /* the thread was started */
  _Atomic int stop; /* asks the thread to end */
  _Atomic int key;  /* the key that stopped the work: 3 (Ctrl-C), 'q', or 0 */
} uraKeyWatch;

/* watch fd (a terminal in raw mode) while the caller works: Ctrl-C or q sets the interrupt flag
   (interrupt.c) within 0.05 s; other keys are dropped. 0, or -1 when no thread could start (the
   work then runs unwatched) */
int ura_keywatch_start(uraKeyWatch* w, int fd);

/* end the watch; returns the key that stopped the work (3 for Ctrl-C, 'q') or 0 for none, and
   clears the interrupt flag a key set */
int ura_keywatch_stop(uraKeyWatch* w);

/* text files (textin.c): the next line of f without its line end into *buf (realloc'ed, *cap
   its size), at most max bytes; its length, or one of these */
enum {
  uraLINE_EOF = -1,
  uraLINE_ERROR = -2 /* errno */,
  uraLINE_LONG = -3,
  uraLINE_NUL = -4
};
long ura_read_line(FILE* f, char** buf, size_t* cap, size_t max);
#define uraMAXLINE (1L << 20) /* longest line of a script or grid file, bytes */
/* s as printable text into buf (n bytes, cut to fit): control bytes, DEL, C1 controls and bytes
   that are not UTF-8 as \xNN, printable ASCII and UTF-8 kept; its length. Every message goes
   through it (ura_fail), so that no input echoed in an error can drive the terminal. */
size_t ura_printable(const char* s, char* buf, size_t n);
/* a buffered stream writing to fd (standard output when it is not a terminal) that keeps the
   errno of its first failed write: ura_out_errno, 0 if none since ura_out_clear */
FILE* ura_out_stream(int fd);
int ura_out_errno(void);
void ura_out_clear(void);

/* the terminal (pager.c): f is a terminal (or the pager's buffer of one); its size; gather a
   command's output (the stream out it would go to; NULL when it is not to be paged: a
   command that takes the screen, runs others, starts a program or leaves, or a gathering under
   way) and release it: paged when taller than the screen, else written to out, which is
   returned (NULL: nothing was gathered); a pager that is missing, fails or dies is said on msg
   and the text written to out: nothing computed is lost */
int ura_tty(FILE* f);
void ura_term_size(int* rows, int* cols);
FILE* ura_pager_gather(FILE* out, const char* cmd);
FILE* ura_pager_release(FILE* msg);

/* the progress line on standard error (progress.c): a label before it (a sweep's value; NULL:
   none), the start of the work, one line "LABEL WHAT DONE/TOTAL NOUN, ELAPSED, about T left" */
void ura_progress_label(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
void ura_progress_start(void);
void ura_progress_line(const char* what, long done, long total, const char* noun);
/* a run of n pieces of work (a sweep's grids), piece i (0 first: the run's clock starts) now
   running; n 0 ends the run. The line then says how long is left of all of them */
void ura_progress_run(int i, int n);
/* the line's text (what ura_progress_line prints after the label and before clearing the rest):
   el seconds since this piece began; piece i of runs (0: not a run) begun el_run seconds ago */
void ura_progress_text(char* buf, size_t n, const char* what, long done, long total,
                       const char* noun, double el, int i, int runs, double el_run);
/* "uasimpact VERSION (commit HASH[-dirty])" (version.c) */
const char* ura_version(void);
/* "did you mean" (suggest.c): the edit distance of two names; the nearest name offered for a
   word, near enough for a typing slip; its text (" (did you mean 'NAME'?)" or ""); the names of
   a usage text's keywords (the command table's: cmd.h; the parameter tables': case.h) */
typedef struct {
  const char* word;
  char best[64];
  int d;
} uraSuggest;
int ura_edit_distance(const char* a, const char* b);
void ura_suggest_init(uraSuggest* s, const char* word);
void ura_suggest_add(uraSuggest* s, const char* name);
const char* ura_suggest_text(const uraSuggest* s, char* buf, size_t n);
void ura_suggest_keywords(uraSuggest* s, const char* usage);

/* text after lead, wrapped between words at width (0: one line), later lines after cont */
void ura_wrap(FILE* f, const char* lead, const char* cont, const char* text, int width);
/* s split at its double spaces into at most max lines of width (the last takes the rest); the
   number of lines */
int ura_split_fields(const char* s, int width, char (*out)[256], int max);

/* ---- colours (colors.c) ---- */

/* band thresholds, percent: low < MED <= medium < HIGH <= high < SEVERE <= severe */
#define uraBAND_MED    5.0
#define uraBAND_HIGH   30.0
#define uraBAND_SEVERE 90.0

typedef enum {
  uraROLE_NONE = 0, /* no contact, or P = 0: white / blank */
  uraROLE_LOW,      /* 0 < P < 5 % */
  uraROLE_MEDIUM,   /* 5 <= P < 30 % (yellow) */
  uraROLE_HIGH,     /* 30 <= P < 90 % (orange) */
  uraROLE_SEVERE,   /* P >= 90 % (red) */
  uraROLE_FAILED,   /* the cell's simulation failed */
  uraROLE_PENDING,  /* the cell is not computed */
  uraROLE_AXIS,     /* axis labels */
  uraROLE_TITLE,    /* title and status lines */
  /* a difference grid P_b - P_a (design compare), a diverging scale: */
  uraROLE_SAFER2,   /* P_b - P_a <= -30 % (deep blue) */
  uraROLE_SAFER,    /* -30 % < P_b - P_a < 0 (light blue) */
  uraROLE_RISKIER,  /* 0 < P_b - P_a < 30 % (light red) */
  uraROLE_RISKIER2, /* P_b - P_a >= 30 % (deep red) */
  uraROLE_N
} uraRole;

typedef enum {
  uraSCHEME_PLAIN = 0, /* no escapes at all (not a terminal, or NO_COLOR for text) */
  uraSCHEME_MONO,      /* attributes and glyphs only (ncurses without colour) */
  uraSCHEME_BASIC,     /* the 8 ANSI colours */
  uraSCHEME_XTERM,     /* 256 colours: white, pale yellow, yellow, orange, red */
  uraSCHEME_N
} uraScheme;

enum {
  uraATTR_BOLD = 1,
  uraATTR_REVERSE = 2,
  uraATTR_DIM = 4,
  uraATTR_UNDERLINE = 8
};

typedef struct {
  short fg, bg; /* colour numbers (0-7 ANSI, 8-255 xterm), -1 default */
  int attr;     /* uraATTR_* bits */
  char glyph;   /* marker of the band where colour is absent */
} uraStyle;

/* role of a probability 0..1 (band), and of a grid cell (band, failed or pending) */
uraRole ura_band_role(double p);
uraRole ura_cell_role(const urCell* cell);

/* role of a cell of a difference grid (diverging: 0 is none), and of a cell of a grid that is
   one (diff) or not */
uraRole ura_diff_role(const urCell* cell);
uraRole ura_grid_role(int diff, const urCell* cell);

/* style of a role in a scheme */
const uraStyle* ura_style(uraScheme s, uraRole r);

/* short name of a role ("none", "low", ...) and its legend text ("0 / no contact", "0-5 %") */
const char* ura_role_name(uraRole r);
const char* ura_role_label(uraRole r);

/* scheme for text on a stream: PLAIN unless it is a terminal and NO_COLOR is unset; XTERM when
   TERM or COLORTERM promise 256 colours, PLAIN when terminfo gives TERM fewer than 8 colours
   (vt100), BASIC otherwise */
uraScheme ura_scheme_for_stream(FILE* f);

/* true when the NO_COLOR convention (https://no-color.org) asks for no colour */
int ura_no_color(void);

/* SGR escape sequence of a style into buf ("" for PLAIN); returns its length */
size_t ura_style_sgr(uraScheme s, const uraStyle* st, char* buf, size_t n);

#endif
