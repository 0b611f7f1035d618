/* injury.h: injury criteria (HIC, Nij, VC), SAE J211 CFC filtering and the conversion of each
 * criterion to a probability of fatality (PoF), after Jiang, Blom & Rattanagraikanakorn (2025),
 * Appendix C. Pure functions on caller-owned data: no globals, no I/O, reentrant.
 *
 * Conventions: SI units except head acceleration for HIC, which is in g (9.80665 m/s^2).
 * Neck: Fz > 0 tension, My > 0 flexion (SAE J211/J1733). Deflection D > 0 is compression.
 * Sources and defaults are documented in uasimpact-injury(7).
 */
#ifndef UASIMPACT_INJURY_H
#define UASIMPACT_INJURY_H

#include "uasimpact/injury_registry.h"

#ifdef __cplusplus
extern "C" {
#endif

#define urGRAVITY 9.80665 /* standard gravity, m/s^2 (1 g) */

/* ---- settings ---- */

typedef enum {
  urORDER_NONE = 0,  /* leave the raw AIS curves as they are */
  urORDER_RAISE = 1, /* Q4 = max(Q4,Q5), Q3 = max(Q3,Q4), Q2 = max(Q2,Q3) */
  urORDER_LOWER = 2  /* Q3 = min(Q3,Q2), Q4 = min(Q4,Q3), Q5 = min(Q5,Q4) */
} urNijOrder;

typedef enum {
  urVCFUSE_PRODUCT = 0, /* P_VC = 1 - (1 - P_thorax)(1 - P_abdomen) */
  urVCFUSE_MAX = 1      /* P_VC = max(P_thorax, P_abdomen) */
} urVcFuse;

typedef struct urInjuryParams {
  /* signal conditioning */
  int filter;      /* 1: CFC-filter channels before the criteria (default 0) */
  double cfc_head; /* head acceleration channel class, Hz (1000) */
  double cfc_neck; /* neck force/moment channel class, Hz (600) */
  double cfc_defl; /* thorax/abdomen deflection channel class, Hz (180) */
  /* HIC */
  double hic_window; /* window of the HIC used for PoF, s (0.015 = HIC15) */
  double hic_alpha;  /* AIS4+ Prasad-Mertz logistic alpha, - (4.90) */
  double hic_beta;   /* AIS4+ Prasad-Mertz logistic beta, 1/HIC (0.00351) */
  /* Nij */
  double nij_fzc_tension;     /* critical tension intercept, N (6806) */
  double nij_fzc_compression; /* critical compression intercept, N (6160) */
  double nij_myc_flexion;     /* critical flexion intercept, N m (310) */
  double nij_myc_extension;   /* critical extension intercept, N m (135) */
  double nij_condyle_d;       /* load-cell to condyle offset D: M_OC = My - D Fx, m (0) */
  double nij_alpha[4];        /* Eppinger AIS2+..AIS5+ logistic alpha, - */
  double nij_beta[4];         /* Eppinger AIS2+..AIS5+ logistic beta, 1/Nij */
  int nij_rescale;            /* 1: rescale each AIS curve to 0 at Nij = 0 (default 1) */
  int nij_order;              /* urNijOrder ordering fix (default urORDER_RAISE) */
  /* AIS -> PoF, Gennarelli & Wodzin (2006), upper ends */
  double pof_ais2; /* P{F | AIS = 2}, - (0.02) */
  double pof_ais3; /* P{F | AIS = 3}, - (0.10) */
  double pof_ais4; /* P{F | AIS = 4}, - (0.50) */
  double pof_ais6; /* P{F | AIS >= 5} bound by P{F | AIS = 6}, - (1.0) */
  /* VC */
  double vc_sf;           /* VC scale factor, - (1.0, human model) */
  double vc_d0_thorax;    /* thorax depth D0, m (0.229) */
  double vc_d0_abdomen;   /* abdomen depth D0, m (0.2185) */
  double vc25_thorax;     /* VC at 25 % risk of thorax AIS4+, m/s (1.0) */
  double vc25_abdomen;    /* VC at 25 % risk of abdomen AIS5+, m/s (1.2) */
  double vc_beta_thorax;  /* thorax logistic slope, s/m (6.08) */
  double vc_beta_abdomen; /* abdomen logistic slope, s/m (6.08) */
  double vc_pof_thorax;   /* P{F | thorax AIS4+ injury}, - (0.5 = pof_ais4) */
  double vc_pof_abdomen;  /* P{F | abdomen AIS5+ injury}, - (1.0 = pof_ais6) */
  int vc_rescale;         /* 1: rescale the VC curves to 0 at VC = 0 (default 1) */
  int vc_fuse;            /* urVcFuse thorax/abdomen combination (default product) */
  /* peak thorax deflection (urCRIT_DEFL, off by default: not in the paper) */
  int use_defl;      /* 1: P_DEFL enters the fusion (3.1) (default 0) */
  double defl_alpha; /* AIS3+ curve 1/(1+exp(alpha - beta D^e)), D in mm (10.5456) */
  double defl_beta;  /* its beta, mm^-e (1.568) */
  double defl_exp;   /* its exponent e, - (0.4612) */
  double defl_pof;   /* P{F | thorax AIS3+}, - (0.09 = pof_ais3) */
} urInjuryParams;

/* fill the documented defaults */
void ur_injury_defaults(urInjuryParams* p);

/* named settings for `set NAME VALUE`: 0 ok, -1 unknown name, -2 value out of range */
int ur_injury_param_set(urInjuryParams* p, const char* name, double value);
int ur_injury_param_get(const urInjuryParams* p, const char* name, double* value);

/* number of named settings; info on setting i (any pointer may be NULL). Returns -1 if i is out
   of range. unit is "" for dimensionless, help a one-line description with the source. */
int ur_injury_param_count(void);
int ur_injury_param_info(int i, const char** name, const char** unit, const char** help);
/* accepted range of setting i: [lo, hi] (lo excluded if open_lo), integers only if isint */
int ur_injury_param_range(int i, double* lo, double* hi, int* open_lo, int* isint);

/* ---- SAE J211 CFC filter ---- */

/* Phaseless CFC filter (J211-1 Appendix C second-order Butterworth, run forward then backward)
   of n uniformly spaced samples with step dt (s). y may equal x. Start-up uses steady state on
   the end values. Returns 0, or -1 on bad input (n < 1, dt <= 0, 2.0775 CFC dt >= 0.5). */
int ur_cfc_filter(const double* x, int n, double dt, double cfc, double* y);

/* amplitude gain of that forward-backward filter at frequency f (Hz); -1 on bad input */
double ur_cfc_gain(double cfc, double dt, double f);

/* ---- HIC ---- */

typedef struct {
  double hic; /* HIC value, g^2.5 s (0 if no positive window) */
  double t1;  /* window start, s */
  double t2;  /* window end, s */
  int i1, i2; /* sample indices of t1, t2 */
} urHic;

/* Exact discrete HIC over sample pairs with t2 - t1 <= window (s), from the cumulative
   trapezoid integral of a (g) on ascending, possibly non-uniform times t (s); starts are
   scanned in decreasing upper bound, so typically O(N log N + W^2), worst case O(N W).
   work: ur_hic_work_size(n) doubles, or NULL to allocate once. Returns 0, -1 bad input,
   -2 out of memory. */
int ur_hic(const double* t, const double* a, int n, double window, double* work, urHic* out);
int ur_hic_work_size(int n);

/* ---- Nij ---- */

typedef enum {
  urNIJ_NTF = 0, /* tension, flexion */
  urNIJ_NTE = 1, /* tension, extension */
  urNIJ_NCF = 2, /* compression, flexion */
  urNIJ_NCE = 3  /* compression, extension */
} urNijMode;

typedef struct {
  double mode[4]; /* per-mode maxima over time, indexed by urNijMode, - */
  int imode[4];   /* sample index of each mode maximum (-1: mode never seen) */
  double nij;     /* overall maximum, - */
  int which;      /* urNijMode of the overall maximum */
  int imax;       /* sample index of the overall maximum */
} urNij;

/* mode of one sample by the signs of Fz and M_OC (zero counts as tension / flexion) */
urNijMode ur_nij_mode(double fz, double moc);

/* Nij of one sample (mode by sign, intercepts from p) */
double ur_nij_sample(double fz, double moc, const urInjuryParams* p);

/* Nij over n samples of Fz (N, tension > 0) and My (N m, flexion > 0); fx (N) may be NULL,
   otherwise M_OC = My - nij_condyle_d Fx. Returns 0, -1 on bad input. */
int ur_nij(const double* fz, const double* my, const double* fx, int n, const urInjuryParams* p,
           urNij* out);

/* ---- VC ---- */

typedef enum {
  urTHORAX = 0,
  urABDOMEN = 1
} urRegion;

typedef struct {
  double vc; /* max over time of SF V(t) C(t), m/s */
  double t;  /* time of the maximum, s */
  double v;  /* deformation velocity at the maximum, m/s */
  double c;  /* compression D/D0 at the maximum, fraction */
  int imax;  /* sample index of the maximum */
} urVc;

/* VC from n deflections d (m, compression > 0) at times t (s). V by the five-point derivative
   on uniform samples, by the three-point non-uniform formula otherwise (and at the ends).
   vct (n doubles, may be NULL) receives VC(t). Returns 0, -1 on bad input (n < 3, d0 <= 0). */
int ur_vc(const double* t, const double* d, int n, double d0, double sf, double* vct, urVc* out);

/* ---- PoF curves ---- */

/* P{F_HIC}: AIS4+ Prasad-Mertz logistic, 0 for hic <= 0 */
double ur_pof_hic(double hic, const urInjuryParams* p);

/* P(AIS >= k | Nij) for k = 2..5 into q[0..3] after the rescale and ordering settings */
void ur_nij_ais(double nij, const urInjuryParams* p, double q[4]);

/* P{F_NI}: composite (C.3) of the AIS curves with the AIS -> PoF values */
double ur_pof_nij(double nij, const urInjuryParams* p);

/* P{F | VC} of one region by (C.5), with the region's logistic and AIS -> PoF factor */
double ur_pof_vc(double vc, urRegion region, const urInjuryParams* p);

/* P{F_VC} from the two regions' PoF (vc_fuse setting) */
double ur_pof_vc_fuse(double p_thorax, double p_abdomen, const urInjuryParams* p);

/* P{F | peak thorax deflection d (m)}: the AIS3+ curve rescaled to 0 at d = 0, times
   defl_pof; 0 for d <= 0 */
double ur_pof_defl(double d, const urInjuryParams* p);

/* overall PoF, eq. (3.1): 1 - (1 - P_HIC)(1 - P_NI)(1 - P_VC); with criteria beyond the paper's
   three, ur_pof_fuse_used (injury_registry.h) */
double ur_pof_fuse(double p_hic, double p_nij, double p_vc);

typedef enum {
  urPOF_HIC = 0,        /* x = HIC */
  urPOF_NIJ = 1,        /* x = Nij */
  urPOF_VC = 2,         /* x = VC (m/s) in both regions, fused by vc_fuse */
  urPOF_VC_THORAX = 3,  /* x = thorax VC, m/s */
  urPOF_VC_ABDOMEN = 4, /* x = abdomen VC, m/s */
  urPOF_DEFL = 5        /* x = peak thorax deflection, m */
} urPofKind;

/* n >= 2 points (x ascending from 0, prob) of a PoF curve over a range that reaches 99.5 % of
   the curve's upper limit. Returns n, or -1 on bad input. */
int ur_pof_curve(urPofKind kind, const urInjuryParams* p, int n, double* x, double* prob);

/* ---- all criteria at once ---- */

typedef struct urInjuryInput {
  int n;                     /* number of samples */
  const double* t;           /* times, s, ascending */
  const double* head_acc[3]; /* head CG acceleration x,y,z, m/s^2; only [0]: resultant */
  const double* neck_fz;     /* upper-neck axial force, N, tension > 0 (NULL: no Nij) */
  const double* neck_my;     /* upper-neck moment, N m, flexion > 0 */
  const double* neck_fx;     /* upper-neck shear force, N (NULL: none) */
  const double* thorax_d;    /* thorax deflection, m, compression > 0 (NULL: none) */
  const double* abdomen_d;   /* abdomen deflection, m, compression > 0 (NULL: none) */
  int skip_hic36;            /* 1: leave hic36 zero (no PoF uses it unless hic_window is
                                      0.036, when hic holds it anyway) */
} urInjuryInput;

typedef struct urInjuryResult {
  double val[urNVAL];  /* every criterion's values (urValueId), SI */
  double pof[urNCRIT]; /* every criterion's PoF (urCritId), used in the fusion or not */
  urHic hic15;         /* HIC15 */
  urHic hic36;         /* HIC36 */
  urHic hic;           /* HIC with hic_window, used for P_HIC */
  urNij nij;           /* Nij modes and maximum */
  urVc vc_thorax;      /* thorax VC */
  urVc vc_abdomen;     /* abdomen VC */
  double p_vc_thorax;  /* P{F | VC thorax} */
  double p_vc_abdomen; /* P{F | VC abdomen} */
  double p_total;      /* P{F | impact}, eq. (3.1) over the criteria in use */
} urInjuryResult;

/* doubles of workspace ur_injury_eval needs for n samples */
int ur_injury_work_size(int n);

/* Filter (if p->filter), compute every criterion of the registry whose channels are given, and
   the PoFs.
   Absent channels give zero criteria and zero PoF. work: ur_injury_work_size(n) doubles, or NULL
   to allocate once. Returns 0, -1 bad input, -2 out of memory, -3 filter on but samples not
   uniformly spaced or sampled too slowly for the CFC. */
int ur_injury_eval(const urInjuryInput* in, const urInjuryParams* p, double* work,
                   urInjuryResult* out);

#ifdef __cplusplus
}
#endif
#endif
