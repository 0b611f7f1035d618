/* scale.h: the cells of a script's grids split over processes (uasimpact(1), SCALING OUT).
 *
 * Every process replays the whole script; only the simulated cells of each grid are shared out.
 * Grids are numbered in the order they run (0, 1, ...); the cells a grid simulates form a fixed
 * list (urGridDist), so a cell's result does not depend on the process that computes it. One
 * distributor drives the grids of a run:
 *   serial  none (c->scale NULL): this process simulates every cell
 *   shard   --shard I/N --part OUT: position k of grid G when (k + G) mod N == I; the cells go
 *           to the part file OUT, the other cells are placeholders (output muted)
 *   merge   uasimpact merge [-c COMMANDS] [--script FILE]... PART...: runs the script given (checked
 *           against the command line the parts record; never the parts') with every cell from
 *           the parts
 *   mpi     ./uasimpact-mpi under mpirun: rank 0 hands out chunks on demand, gathers, broadcasts
 */
#ifndef URA_SCALE_H
#define URA_SCALE_H

#include <sys/stat.h>

#include "../cmd/cmd.h"

#define uraPART_VERSION   1
#define uraPART_MAGIC     "uasimpact-part"
#define uraPART_MAGIC_OLD "uasrisk-part" /* the former name's parts, still read (with a note) */

typedef struct uraScale uraScale;

typedef struct {
  const char* name;
  int (*begin)(uraScale* s, long ntodo); /* grid s->grid with key s->key is about to run */
  long (*next)(uraScale* s);             /* any worker thread: next position, -1 none */
  int (*end)(uraScale* s, urGrid* g, const long* todo, long ntodo);
  int (*finish)(uraScale* s, int rc); /* end of the run: the exit status */
  void (*input)(uraScale* s, const char* path, const struct stat* st); /* a file read; or NULL */
} uraScaleOps;

struct uraScale {
  const uraScaleOps* ops;
  uraCtx* c;
  long grid;    /* number of the running grid (-1 before the first) */
  char key[17]; /* its key: settings, model and extents, hashed */
  void* impl;
};

/* ---- scale.c: the command line, the hook of ura_grid_run, the end of a run ---- */

/* --shard I/N --part OUT, or 'merge ... PART...' (argv replaced by the merge's script and -c
   commands), or the MPI build's start: 0, or the exit status of a refusal (its message printed) */
int ura_scale_args(uraCtx* c, int* argc, char*** argv);
/* the end of the run with status rc: the part written, MPI finished; the exit status */
int ura_scale_end(uraCtx* c, int rc);
/* a grid about to run under c->scale: its number and key, and spec->dist pointing at d */
void ura_scale_grid(uraCtx* c, urGridSpec* spec, urGridDist* d);
/* a file the run reads (a script, a sourced file, a model, a grid), open as f: a shard keeps its
   device and inode, so that its part never replaces an input of the run */
void ura_scale_input(uraCtx* c, FILE* f, const char* path);
/* results, notes and files of this process go nowhere (a shard, an MPI rank other than 0) */
int ura_scale_mute(uraCtx* c);

/* the hash of the script files named on a command line (the -c texts are in the line) and of
   the built-in models: 16 hex digits each */
void ura_scale_script_hash(int argc, char** argv, char out[17]);
void ura_scale_model_hash(char out[17]);

/* ---- scale_cell.c: one cell's results as one line of text, exactly ---- */

/* the results of c (not dpar, dperp, mirrored) as text without a newline (a reason's bytes that
   are not printable as spaces or '?'); the length, -1 if n is too small, -2 if a value is outside
   its domain (p or a PoF not a probability, an infinite criterion, no Nij mode) */
int ura_cell_write(const urCell* c, char* buf, size_t n);
/* the results of a line of ura_cell_write into c (dpar, dperp kept); 0, or -1 if malformed, a
   value is outside its domain or the reason is not printable text (c unchanged) */
int ura_cell_read(const char* s, urCell* c);

/* ---- the distributors ---- */

/* scale_shard.c: shard i of n, its part written to path at the end */
uraScale* ura_shard_new(uraCtx* c, int i, int n, const char* path, int argc, char** argv);
/* scale_merge.c: 'merge [-c COMMANDS] [--script FILE]... PART...' (argv[1] is "merge"): the
   parts checked and loaded, their recorded command line compared with the one given; argv becomes
   the one given (FILE for --script FILE), never the parts'. 0, or 2 with the refusal printed */
int ura_merge_new(uraCtx* c, int* argc, char*** argv);
/* scale_mpi.c: the MPI distributor (NULL without MPI_Init, i.e. in the plain build) */
uraScale* ura_mpi_new(uraCtx* c, int* argc, char*** argv);

/* scale_part.c: the part format shared by shard and merge */
typedef struct {
  int shard, nshard;
  char script[17], model[17];
  int argc;
  char** argv; /* the command line without --shard and --part: data, compared, never run */
  int status;  /* the exit status of the shard's run */
  long ngrid;
  struct uraPartGrid* grid; /* ngrid */
  char* text;               /* the whole file, owned (lines point into it) */
} uraPartFile;
typedef struct uraPartGrid {
  char key[17];
  long ntodo, ncell;
  long* pos;   /* positions, increasing */
  char** cell; /* their cell lines (ura_cell_read) */
} uraPartGrid;
/* write the header of a part */
void ura_part_header(FILE* f, int shard, int nshard, int argc, char** argv);
/* read and check a part; 0, or -1 with why in err (free p either way) */
int ura_part_read(const char* path, uraPartFile* p, char* err, size_t nerr);
/* the same on a part's text (n bytes, NUL-terminated, malloc'd: p owns it from here), named path
   in messages */
int ura_part_parse(char* text, size_t n, const char* path, uraPartFile* p, char* err, size_t nerr);
void ura_part_free(uraPartFile* p);

#endif
