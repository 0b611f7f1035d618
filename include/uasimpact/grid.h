/* grid.h: offset grids of impacts and the Q integral (paper eq. 4.5).
 *
 * A grid covers offsets Delta = (dpar along the drone course, dperp across it) on a square
 * lattice of pitch `step`, centred on Delta = 0. Row i has dpar = par_max - i*step (rows run from
 * the front to the back, as the paper's tables), column j has dperp = perp_min + j*step. Each cell
 * is decided geometrically (no contact possible: not simulated) or by one impact simulation.
 * Q = sum over the full plane of p * step^2.
 *
 * The runner is generic: the impact itself is a callback, so the grid knows nothing of models.
 * Workers are POSIX threads over cells; results do not depend on the number of threads.
 */
#ifndef UASIMPACT_GRID_H
#define UASIMPACT_GRID_H

#include "uasimpact/injury_registry.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
  urCELL_PENDING = 0, /* not computed (yet, or the run was interrupted) */
  urCELL_NOCONTACT,   /* decided geometrically: the drone cannot touch the person */
  urCELL_DONE,        /* simulated */
  urCELL_FAILED       /* the simulation failed (reason in `reason`) */
} urCellStatus;

typedef struct {
  double dpar, dperp;  /* offset, m */
  int status;          /* urCellStatus */
  int contact;         /* the drone touched the person */
  int mirrored;        /* copied from the mirror cell (-dperp) */
  double val[urNVAL];  /* the criteria's values (urValueId; NAN: not known) */
  double pof[urNCRIT]; /* injury-specific PoF (urCritId; NAN: not known) */
  double p;            /* fused PoF (eq. 3.1) */
  int extrap;          /* laws or curves used beyond their data (urImpactResult) */
  char reason[64];     /* why a cell failed */
} urCell;

typedef struct {
  int nrow, ncol;  /* rows along, columns across (full plane) */
  double step;     /* lattice pitch, m */
  double par_max;  /* dpar of row 0, m */
  double perp_min; /* dperp of column 0, m */
  urCell* cell;    /* nrow*ncol, row-major */
  /* summary */
  double q; /* sum of p*step^2 over finished cells, m^2 */
  int ndone, ncontact, nfailed, npending, nsimulated;
  int nextrap;    /* finished cells whose impact used a law beyond its data */
  int complete;   /* every cell finished and none failed */
  double seconds; /* wall time of the run */
} urGrid;

/* decide a cell: return 1 if contact is geometrically possible (then it is simulated) */
typedef int (*urMayContactFn)(void* ctx, double dpar, double dperp);
/* simulate a cell: fill the result fields of c (dpar, dperp are set); 0 ok, -1 failed */
typedef int (*urImpactFn)(void* ctx, int worker, urCell* c);
/* the cells of one worker as a stream, for a callback that simulates several at once: take gives
   the next cell to simulate (dpar, dperp set) or NULL when none is left or a stop was asked;
   put records a finished cell (rc 0 ok, -1 failed with c->reason) */
typedef urCell* (*urCellTakeFn)(void* feed);
typedef void (*urCellPutFn)(void* feed, urCell* c, int rc);
typedef void (*urImpactStreamFn)(void* ctx, int worker, urCellTakeFn take, urCellPutFn put,
                                 void* feed);
/* progress: cells finished so far out of the total to simulate */
typedef void (*urProgressFn)(void* ctx, int done, int total);

/* optional: who simulates which cell, for work split over processes. The cells to simulate form
   a fixed list (row-major order of the cells neither mirrored nor decided geometrically), the
   same in every process. begin is told its length; next hands out the next position of the list
   this process simulates (-1: none left), from any worker thread; end, after the workers, fills
   the cells simulated elsewhere (status and results; dpar, dperp are kept) before the mirror rule
   and the summary. begin or end failing makes ur_grid_run return -2. */
typedef struct {
  void* ctx;
  int (*begin)(void* ctx, long ntodo);
  long (*next)(void* ctx);
  int (*end)(void* ctx, urGrid* g, const long* todo, long ntodo);
} urGridDist;

typedef struct {
  double step;             /* pitch, m */
  double par_min, par_max; /* along extent, m (rounded outwards to the lattice) */
  double perp_max;         /* across extent |dperp| <= perp_max, m */
  int mirror;              /* the set-up is symmetric in dperp: simulate dperp >= 0 only */
  int threads;             /* worker threads (>= 1) */
  urMayContactFn may_contact;
  urImpactFn impact;
  urProgressFn progress; /* optional; called from worker threads, serialised */
  void* ctx;
  const _Atomic int* stop;        /* optional; workers stop starting cells when *stop != 0 */
  urImpactStreamFn impact_stream; /* optional; when set, each worker hands it its cells instead
                                      of calling impact per cell */
  const urGridDist* dist;         /* optional; NULL: this process simulates every cell */
} urGridSpec;

/* allocate the lattice of a spec (cells pending); NULL on bad extents or no memory */
urGrid* ur_grid_new(const urGridSpec* spec);
void ur_grid_free(urGrid* g);

/* cells the spec would hold, for refusing huge grids before allocating */
long ur_grid_cell_count(const urGridSpec* spec);

/* run the spec on a grid from ur_grid_new; keeps finished cells when stopped. 0; -1 out of
   memory; -2 the distributor (spec->dist) failed */
int ur_grid_run(urGrid* g, const urGridSpec* spec);

/* recompute q and the counts from the cells */
void ur_grid_summarise(urGrid* g);

/* the cell at (row, col), and the cell nearest an offset (NULL outside) */
urCell* ur_grid_at(urGrid* g, int row, int col);
urCell* ur_grid_find(urGrid* g, double dpar, double dperp);

#ifdef __cplusplus
}
#endif
#endif
