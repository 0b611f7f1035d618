/* engine_membrane_cull.c: what decides which parts of a membrane airbag contact_geom
 * (engine_membrane.c) looks at for each target. Once a step the loads stage boxes the free nodes
 * and the free triangles' bounding spheres in blocks of urMEM_CBLK, and the blocks in groups
 * (urm_cull_boxes); for each target contact_geom skips the groups and blocks out of its reach and
 * tests the triangles of the others' spheres against the target's sphere and box, 4 at a time
 * (urm_cull_tris). Every bound is the scalar code's to the bit: the boxes take each coordinate's
 * extremes in the same order (a lane a coordinate), a group is the exact union of its blocks, and
 * each lane of the triangle test does the scalar operations in order (ISO C: no contraction into
 * FMA). The kernels are also compiled for AVX2, the clone picked at load time (as the fabric's
 * pass; urNO_CLONES: the default only). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "engine_membrane_cull.h"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(urNO_CLONES)
#define urmCULL_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define urmCULL_CLONES
#endif

typedef double cul4 __attribute__((vector_size(32)));
typedef long long cul4i __attribute__((vector_size(32)));

/* a where a < b, else b; a where a > b, else b (the scalar code's selects: a NaN a not taken);
   macros, not functions: no vector passed by value in the default clone */
#define urmMIN4(a, b)                                                                              \
  ((cul4)(((cul4i)(a) & (cul4i)((a) < (b))) | ((cul4i)(b) & ~(cul4i)((a) < (b)))))
#define urmMAX4(a, b)                                                                              \
  ((cul4)(((cul4i)(a) & (cul4i)((a) > (b))) | ((cul4i)(b) & ~(cul4i)((a) > (b)))))


/* the boxes of urMEM_CBLK free nodes (7 doubles a box, [6] unused), a lane a coordinate: each
   node's x, y, z read as one vector (its fourth lane, the next double of the state, ignored) */
static urmCULL_CLONES void node_boxes(const urMembrane* mb, const double* x, double* nbx) {
  for (int j0 = 0; j0 < mb->nfree; j0 += urMEM_CBLK) {
    int j1 = j0 + urMEM_CBLK < mb->nfree ? j0 + urMEM_CBLK : mb->nfree;
    cul4 lo = {INFINITY, INFINITY, INFINITY, INFINITY}, hi = -lo;
    for (int j = j0; j < j1; j++) {
      cul4 xi;
      memcpy(&xi, x + 3 * mb->free[j], sizeof(xi));
      lo = urmMIN4(xi, lo);
      hi = urmMAX4(xi, hi);
    }
    double* bx = nbx + 7 * (j0 / urMEM_CBLK);
    for (int k = 0; k < 3; k++) {
      bx[k] = lo[k];
      bx[3 + k] = hi[k];
    }
  }
}


/* the boxes of urMEM_CBLK free triangles' spheres and their largest radius, a lane a coordinate */
static urmCULL_CLONES void tri_boxes(const urMembrane* mb, const double* tb, double* tbx) {
  int nt = mb->nt;
  for (int j0 = 0; j0 < mb->ntfree; j0 += urMEM_CBLK) {
    int j1 = j0 + urMEM_CBLK < mb->ntfree ? j0 + urMEM_CBLK : mb->ntfree;
    cul4 lo = {INFINITY, INFINITY, INFINITY, INFINITY}, hi = -lo;
    double rm = 0;
    for (int j = j0; j < j1; j++) {
      int t = mb->tfree[j];
      double r = tb[3 * nt + t];
      cul4 ct = {tb[t], tb[nt + t], tb[2 * nt + t], 0};
      cul4 cl = ct - r, ch = ct + r;
      lo = urmMIN4(cl, lo);
      hi = urmMAX4(ch, hi);
      rm = r > rm ? r : rm;
    }
    double* bx = tbx + 7 * (j0 / urMEM_CBLK);
    for (int k = 0; k < 3; k++) {
      bx[k] = lo[k];
      bx[3 + k] = hi[k];
    }
    bx[6] = rm;
  }
}


/* the second level of contact_geom's culling: boxes of grp consecutive boxes of urMEM_CBLK free
   nodes (n) and of urMEM_CBLK free triangles' spheres (t, with their largest radius at [6]),
   grp chosen so that at most urmCULL_MAX of each. Each is the union of its boxes (min and max:
   exact), so box_gap2 to it is no larger than to any of them (each rounding is monotone) and
   its largest radius no smaller: a group out of a target's reach holds no box within it (the
   same bits as the boxes' tests alone). Built once a step for all of the bag's targets. */
#define SUPER_MIN 4 /* boxes per group at least */

static int super_union(double* sp, const double* bx, int nb, int grp, int rad) {
  int ns = 0;
  for (int b0 = 0; b0 < nb; b0 += grp, ns++) {
    int b1 = b0 + grp < nb ? b0 + grp : nb;
    double bb[7] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY, 0};
    for (int j = b0; j < b1; j++) {
      const double* b = bx + 7 * j;
      for (int k = 0; k < 3; k++) {
        bb[k] = b[k] < bb[k] ? b[k] : bb[k];
        bb[3 + k] = b[3 + k] > bb[3 + k] ? b[3 + k] : bb[3 + k];
      }
      bb[6] = rad && b[6] > bb[6] ? b[6] : bb[6]; /* the nodes' boxes have no radius */
    }
    memcpy(sp + 7 * ns, bb, sizeof(bb));
  }
  return ns;
}

static void super_build(urmCullGroups* sb, const urMembrane* mb, const double* nbx,
                        const double* tbx) {
  int nbn = (mb->nfree + urMEM_CBLK - 1) / urMEM_CBLK;
  int nbt = (mb->ntfree + urMEM_CBLK - 1) / urMEM_CBLK, nb = nbn > nbt ? nbn : nbt;
  sb->grp = (nb + urmCULL_MAX - 1) / urmCULL_MAX;
  sb->grp = sb->grp < SUPER_MIN ? SUPER_MIN : sb->grp;
  sb->nn = super_union(sb->n, nbx, nbn, sb->grp, 0);
  sb->nt = super_union(sb->t, tbx, nbt, sb->grp, 1);
}


/* the triangles tfree[j0..j1) whose bounding sphere (tb: centres, radii) reaches g's sphere
   (centre gc, radius rg) and g's box (half-widths gh), appended to tl in their order (ntl of
   them there: the new count returned). 4 lanes at a time (GCC vector extensions; an AVX2 clone),
   each lane the operations of the scalar test in the same order (ISO C: no
   contraction into FMA; fmax(u, 0) as a select: both 0 for a NaN u), so the same triangles;
   lanes past j1 at an infinite centre fail. Four triangles of consecutive numbers (the usual
   case) are read as one vector each. */
urmCULL_CLONES int urm_cull_tris(const urMembrane* mb, const double* tb, const double gc[3],
                                 double rg, const double gh[3], int j0, int j1, double* tl,
                                 int ntl) {
  const int nt = mb->nt, *tf = mb->tfree;
  const cul4i sign = {INT64_MIN, INT64_MIN, INT64_MIN, INT64_MIN};
  for (int j = j0; j < j1; j += 4) {
    int nl = j1 - j < 4 ? j1 - j : 4;
    cul4 c[4]; /* centre x, y, z and radius */
    if (nl == 4 && tf[j + 3] - tf[j] == 3) {
      for (int k = 0; k < 4; k++) {
        memcpy(c + k, tb + k * (size_t)nt + tf[j], sizeof(cul4));
      }
    } else {
      for (int l = 0; l < 4; l++) {
        for (int k = 0; k < 4; k++) {
          c[k][l] = l < nl ? tb[k * (size_t)nt + tf[j + l]] : k < 3 ? INFINITY : 0;
        }
      }
    }
    cul4 dx = c[0] - gc[0], dy = c[1] - gc[1], dz = c[2] - gc[2], r = c[3];
    cul4 rr = (rg + r) * (1 + 1e-9);
    cul4i in = (cul4i)(dx * dx + dy * dy + dz * dz < rr * rr);
    cul4 ux = (cul4)((cul4i)dx & ~sign) - gh[0], uy = (cul4)((cul4i)dy & ~sign) - gh[1];
    cul4 uz = (cul4)((cul4i)dz & ~sign) - gh[2], rt = r * (1 + 1e-6) + 1e-9;
    ux = (cul4)((cul4i)ux & (cul4i)(ux > 0)), uy = (cul4)((cul4i)uy & (cul4i)(uy > 0));
    uz = (cul4)((cul4i)uz & (cul4i)(uz > 0));
    in &= (cul4i)(ux * ux + uy * uy + uz * uz < rt * rt);
    for (int l = 0; l < nl; l++) {
      if (in[l]) {
        tl[ntl++] = tf[j + l];
      }
    }
  }
  return ntl;
}


void urm_cull_boxes(const urMembrane* mb, const double* x, double* tb, double* nbx, double* tbx,
                    double lo[3], double hi[3], urmCullGroups* sb) {
  // the free nodes' box (the free nodes are those of invm != 0), from their blocks' boxes
  node_boxes(mb, x, nbx);
  for (int k = 0; k < 3; k++) {
    lo[k] = INFINITY;
    hi[k] = -INFINITY;
  }
  for (int j0 = 0; j0 < mb->nfree; j0 += urMEM_CBLK) {
    const double* bx = nbx + 7 * (j0 / urMEM_CBLK);
    for (int k = 0; k < 3; k++) {
      lo[k] = bx[k] < lo[k] ? bx[k] : lo[k];
      hi[k] = bx[3 + k] > hi[k] ? bx[3 + k] : hi[k];
    }
  }
  // each triangle's bounding sphere (its centroid, the farthest node from it: every point of the
  // triangle within), SoA for contact_geom's test: ur_mem_forces left the centres and squared
  // radii at the end of the scratch (membrane.h), the radii here
  int nt = mb->nt;
  for (int t = 0; t < nt; t++) {
    tb[3 * nt + t] = sqrt(tb[3 * nt + t]); /* apart: a vector loop, no wait on each root */
  }
  tri_boxes(mb, tb, tbx);
  super_build(sb, mb, nbx, tbx);
}
