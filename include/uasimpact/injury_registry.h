/* injury_registry.h: the injury criteria as data. One row per criterion (its name, value columns
 * with units, input channels, compute function, PoF curve, the setting that switches it into the
 * fusion and whether it is on by default); results (urInjuryResult) and grid cells (urCell) carry
 * their values in arrays indexed by the ids below, and everything that prints, stores, loads or
 * fuses criteria iterates over the rows. Adding a criterion: an id in each enum, one row in
 * src/core/injury_registry.c, one compute function (src/README, "Adding an injury criterion").
 *
 * Only this file's enums are needed to size the arrays: grid.h includes it without injury.h.
 */
#ifndef UASIMPACT_INJURY_REGISTRY_H
#define UASIMPACT_INJURY_REGISTRY_H

#ifdef __cplusplus
extern "C" {
#endif

/* every value a criterion computes, in column order (the CSV names are in the rows) */
typedef enum {
  urVAL_HIC15 = 0, /* HIC15, - */
  urVAL_HIC_T1,    /* HIC15 window start, s */
  urVAL_HIC_T2,    /* HIC15 window end, s */
  urVAL_NIJ,       /* max of the four Nij modes, - */
  urVAL_NIJ_MODE,  /* urNijMode of that maximum (0 NTF, 1 NTE, 2 NCF, 3 NCE) */
  urVAL_NIJ_TF,    /* per-mode maxima, - */
  urVAL_NIJ_TE,
  urVAL_NIJ_CF,
  urVAL_NIJ_CE,
  urVAL_VC_THORAX,   /* VC of the thorax, m/s */
  urVAL_VC_ABDOMEN,  /* VC of the abdomen, m/s */
  urVAL_DEFL_THORAX, /* peak thorax deflection, m */
  urNVAL
} urValueId;

/* every criterion, in fusion order */
typedef enum {
  urCRIT_HIC = 0, /* head: HIC -> P_HIC */
  urCRIT_NIJ,     /* neck: Nij -> P_NI */
  urCRIT_VC,      /* thorax and abdomen: VC -> P_VC */
  urCRIT_DEFL,    /* thorax: peak deflection -> P_DEFL (off by default) */
  urNCRIT
} urCritId;

/* where a value appears (urValueDef.where) */
#define urIN_ROW    1  /* `impact` rows (CSV columns of the impact command) */
#define urIN_CELL   2  /* grid cells: `grid cells`, `export grid` */
#define urIN_LOAD   4  /* read back by `grid load` */
#define urIN_PANEL  8  /* the viewer's inspect panel */
#define urIN_CURSOR 16 /* the viewer's cursor line */

struct urInjuryParams;
struct urInjuryResult;
struct urInjuryInput;

typedef struct {
  const char* name;         /* CSV column name (a public interface: never renamed) */
  const char* unit;         /* SI unit of the stored value, "" for none */
  int crit;                 /* the criterion that computes it (urCritId) */
  int where;                /* urIN_* bits */
  const char* label;        /* display label before the number ("" for the main value) */
  const char* fmt;          /* display format of the number (after scale) */
  double scale;             /* display = stored * scale */
  const char* dunit;        /* display unit, "" for none */
  const char* const* names; /* labels of an integer-coded value (NULL: a number) */
  int nnames;
} urValueDef;

typedef struct {
  const char* name;     /* curve name of `pof NAME` (also the suffix of pof_col) */
  const char* pof_col;  /* CSV column of its PoF ("p_hic") */
  const char* label;    /* short display label ("HIC15") */
  const char* channels; /* input channels it reads (urInjuryInput fields), words */
  int val0, nval;       /* its values: ids [val0, val0 + nval) */
  const char* use;      /* the setting that switches it into the fusion, NULL: always */
  unsigned use_off;     /* where that int setting is: offsetof(urInjuryParams, ...) */
  int use_default;      /* whether it is in the fusion by default */
  /* compute its values and PoF from conditioned channels into out->val, out->pof and its
     detail fields; absent channels leave zeros. work: ur_injury_work_size(n) doubles less the
     channel buffers (see injury_eval.c). 0, or -1 on bad input. */
  int (*compute)(const struct urInjuryInput* in, const struct urInjuryParams* p, double* work,
                 struct urInjuryResult* out);
  /* its PoF from stored values (a grid cell's val[]), without the histories: the same number
     compute gives when the values came from compute (HIC: exact for hic_window 0.015) */
  double (*pof)(const double* val, const struct urInjuryParams* p);
} urCriterion;

/* row k of the registry (urCritId), NULL out of range */
const urCriterion* ur_criterion(int k);

/* value v's definition (urValueId), NULL out of range */
const urValueDef* ur_value_def(int v);

/* the criterion whose curve name is name, -1 if none */
int ur_criterion_find(const char* name);

/* 1 if criterion k enters the fusion under p (its use setting, or always) */
int ur_criterion_used(int k, const struct urInjuryParams* p);

/* 1 if value v appears in `where` (urIN_* bits) under p: its flag is set and its criterion used */
int ur_value_shown(int v, int where, const struct urInjuryParams* p);

/* the display text of a stored value: a label of an integer-coded value, the number with the
   value's format and scale, or "-" if not finite; buf of n bytes */
void ur_value_format(int v, double x, char* buf, unsigned n);

/* overall PoF, eq. (3.1) over the criteria in use: 1 - prod (1 - pof[k]) */
double ur_pof_fuse_used(const double pof[urNCRIT], const struct urInjuryParams* p);

#ifdef __cplusplus
}
#endif
#endif
