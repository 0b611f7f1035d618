/* material.h: a drone built from its materials and a person's soft tissue: materials (elastic
 * constants, yield, ultimate stress, fracture strain), cross-sections (tube, plate, solid bar,
 * shell wall) and the closed forms the model language derives laws from: a beam's hinge law
 * (elastic slope, plastic moment, hardening, fracture moment), the Hertz combination of two
 * materials, a soft layer over bone, and the local indentation stiffness of a thin shell.
 * Pure functions on caller-owned data: no globals, no I/O. SI units.
 *
 * Sources (uasimpact-model(5), MATERIALS): the materials-membrane reference sheet, E.1 (section
 * properties), E.2 (k = 3EI/L: the paper's tip-load conversion M = F L, theta = d/L on a clamped
 * cantilever; M_p = sigma_y Z_p), E.3 (Reissner's shallow spherical shell under a point load),
 * E.5 (two-sided Hertz), F.2 (layer over bone, bottoming); EN 1993-1-5 Annex C.6 for the
 * default hardening slope E/100.
 */
#ifndef UASIMPACT_MATERIAL_H
#define UASIMPACT_MATERIAL_H

#ifdef __cplusplus
extern "C" {
#endif

/* one material */
typedef struct {
  double E;       /* Young's modulus, Pa */
  double nu;      /* Poisson ratio, [0, 0.5) */
  double density; /* kg/m^3 */
  double sy;      /* yield stress, Pa (a brittle material: its strength) */
  double su;      /* ultimate stress, Pa; 0: not given */
  double ef;      /* fracture strain; 0: not given */
} urMaterial;

/* kinds of cross-section */
typedef enum {
  urSEC_TUBE = 0, /* round tube, outer diameter D, wall t */
  urSEC_PLATE,    /* rectangular plate of thickness t, width b (bending about its width) */
  urSEC_SOLID,    /* solid round bar of diameter D */
  urSEC_SHELL,    /* thin shell wall of thickness t and radius of curvature R (hollow parts) */
  urSEC_BOX       /* rectangular tube b wide, h high (bent about its width), wall t */
} urSectionType;

/* one cross-section */
typedef struct {
  urSectionType type;
  double D; /* outer diameter, m (tube, solid) */
  double t; /* wall or plate thickness, m (tube, plate, shell) */
  double b; /* plate width, m */
  double R; /* shell radius of curvature, m */
  double h; /* box height, m; a shell's depth to bottoming (0: R) */
} urSection;

/* properties of a section in bending */
typedef struct {
  double A;  /* area, m^2 */
  double I;  /* second moment of area, m^4 */
  double Ze; /* elastic section modulus 2I/D (I/(t/2) for a plate), m^3 */
  double Zp; /* plastic section modulus, m^3 */
} urSectionProps;

/* Bending properties of a section (tube: I = pi (D^4 - d^4)/64, Zp = (D^3 - d^3)/6,
   d = D - 2t; solid: d = 0; plate: I = b t^3/12, Zp = b t^2/4; box: I = (b h^3 - bi hi^3)/12,
   Zp = (b h^2 - bi hi^2)/4, bi = b - 2t, hi = h - 2t). Returns 0, or -1 for a shell or a
   section whose sizes are not positive (a tube's or box's wall must leave a hollow). */
int ur_section_props(const urSection* s, urSectionProps* out);

/* a hinge's moment-angle law derived from beam theory */
typedef struct {
  double k;  /* elastic slope 3EI/L, N m/rad */
  double mp; /* plastic moment sigma_y Zp, N m */
  double kh; /* hardening slope beyond mp, N m/rad: k Et/E */
  double mu; /* fracture moment, N m: su Zp, else E ef Ze (brittle); 0: neither given */
} urHinge;

/* The hinge law of an arm of length L (m) of material mat and section sec: the elastic slope
   of a clamped cantilever loaded at its tip read as the paper reads its test (M = F L,
   theta = d/L: k = 3EI/L), the plastic moment, a hardening slope from the bilinear fit of the
   stress-strain curve through yield and ultimate, Et = (su - sy)/(ef - sy/E) when su and ef
   are given, else Et = E/100, and the fracture moment. Returns 0, or -1 with invalid inputs. */
int ur_hinge_from_beam(const urMaterial* mat, const urSection* sec, double L, urHinge* out);

/* Effective modulus of two materials in contact, Pa: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2. */
double ur_hertz_estar(const urMaterial* a, const urMaterial* b);

/* Compressive stress of a foam at strain e in [0, 1) by the Avalle-Belingardi-Ibba law (Avalle,
   Belingardi & Ibba 2007; contact sheet 3.2): p = {A, E, m, B, n},
   sigma = A (1 - exp(-(E/A) e (1 - e)^m)) + B (e / (1 - e))^n (Pa with A, E, B in Pa). */
double ur_foam_abi(const double p[5], double e);

/* Local indentation stiffness of a thin shell under a point load, N/m (Reissner):
   k = 4 E t^2 / (R sqrt(3 (1 - nu^2))); 0 for a section that is not a shell. */
double ur_shell_stiffness(const urMaterial* mat, const urSection* sec);

/* Crush load of a thin shell wall under a concentrated load, N: the rigid-plastic collapse load
   of a plate under a point load, P = 2 pi M0 with M0 = sy t^2 / 4 (Tresca; Hopkins & Prager
   1953; Jones, Structural Impact, 2nd ed. 2012, ch. 2), i.e. pi sy t^2 / 2, independent of the
   wall's span; a lower bound for a curved wall, whose membrane action adds to it. 0 for a
   section that is not a shell or a material without a yield stress. */
double ur_shell_crush_force(const urMaterial* mat, const urSection* sec);

/* The crushed depth at which a shell bottoms on its contents, m: its section's h, else R. */
double ur_shell_crush_depth(const urSection* sec);

/* Pressure per depth of a soft layer of thickness h (m) bonded to bone, pressed over an area
   wider than h (a membrane's fabric on the scalp), N/m^3: k = E_oed / h with the confined
   (oedometric) modulus E_oed = E (1 - nu) / ((1 + nu) (1 - 2 nu)) (a Winkler foundation of the
   layer; materials-membrane sheet F.2). 0 for h <= 0 or nu outside [0, 0.5). */
double ur_layer_foundation(const urMaterial* mat, double h);

#ifdef __cplusplus
}
#endif
#endif
