/* membrane_inflate.c: the inflation of a bag, done once per compiled model (the paper's step 1,
 * MADYMO's initial metric method): from the declared shape (whose fabric rest lengths are the
 * shape's own or the flat pattern's), first at a constant shaping pressure (the declared gauge
 * pressure, at least 1 % of the ambient so that a bag filled to the ambient pressure still takes
 * its shape), then closed with the declared absolute pressure in the volume reached, relaxed by
 * kinetic damping (velocities zeroed at every peak of the kinetic energy; or, with the bag's
 * inflate=1, by FIRE) until the free nodes' forces are below 1e-3 of the pressure forces on them
 * (root mean squares; accepted below 1e-2). The result (positions in the carrier's body frame,
 * gas state) is where every impact starts (the paper's step 2). The relaxation runs on a team of
 * threads when asked (ur_mem_inflate_threads), to the same bits as one thread. */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "membrane_internal.h"

#define MAXSTEP 60000
#define TOL     1e-3
#define MINTRI  1000  /* triangles per thread at least (ur_mem_inflate_threads) */
#define SPIN    20000 /* a barrier's checks before it sleeps */
/* FIRE (a bag's inflate=1): the published parameters (Bitzek et al. 2006), the step from and at
   most the stable one (2 and 4 times it take more steps: the stops pile up) */
#define FNMIN   5
#define FINC    1.1
#define FDEC    0.5
#define FALPHA0 0.1
#define FALPHA  0.99
#define FDT0    1.0
#define FDTMAX  1.0
#define WINDOW  64  /* steps of a measure of the team or thread 0 alone (pace) */
#define PROBE   0.5 /* seconds between tries of the slower of the two */
#define VISC                                                                                       \
  0.98 /* velocity kept per step besides the kinetic damping: slack, wrinkled
                         patches would otherwise flap long after the bag has its shape */

/* a barrier of n threads (n changed for the next round by setting next: read by the last to
   arrive, before it lets the others go): spins a little (a step's work is tens of
   microseconds), then sleeps on the condition variable */
typedef struct {
  pthread_mutex_t mu;
  pthread_cond_t cv;
  atomic_int count, gen;
  int n, next;
} Barrier;

static void barrier_wait(Barrier* b) {
  if (b->n <= 1) {
    b->n = b->next;
    return;
  }
  int g = atomic_load_explicit(&b->gen, memory_order_acquire);
  if (atomic_fetch_add_explicit(&b->count, 1, memory_order_acq_rel) == b->n - 1) {
    atomic_store_explicit(&b->count, 0, memory_order_relaxed);
    b->n = b->next;
    pthread_mutex_lock(&b->mu);
    atomic_store_explicit(&b->gen, g + 1, memory_order_release);
    pthread_cond_broadcast(&b->cv);
    pthread_mutex_unlock(&b->mu);
    return;
  }
  for (int k = 0; k < SPIN; k++) {
    if (atomic_load_explicit(&b->gen, memory_order_acquire) != g) {
      return;
    }
  }
  pthread_mutex_lock(&b->mu);
  while (atomic_load_explicit(&b->gen, memory_order_acquire) == g) {
    pthread_cond_wait(&b->cv, &b->mu);
  }
  pthread_mutex_unlock(&b->mu);
}


/* the threads of a relaxation: each runs the same loop (relax_run) over its own chunks of
   triangles and range of nodes, and each sums the shared per-triangle and per-node terms itself,
   in the serial order, so all of them take the same decisions on the same bits, four barriers a
   step. The team's size (nact: the first nact threads) may change between steps, the others
   waiting parked, without changing a bit: thread 0 measures its steps' time and keeps the team
   only while it is faster than thread 0 alone (a shared machine: a barrier then waits for a
   thread the scheduler has not run), trying the other every PROBE seconds (pace) */
/* FIRE's state (Bitzek et al., PRL 97, 170201, 2006): step, mixing, downhill steps in a row */
typedef struct {
  double dt, dtmax, alpha;
  int npos;
} Fire;

typedef struct {
  urMembrane* mb;
  double* st;
  double fixedp, pscale; /* the phase (relax's arguments) */
  int nthr, nact;        /* threads started; active this step (set by thread 0, under bar.mu
                            while a worker may be parked) */
  int alt;               /* > 0: the team and thread 0 alone alternate every alt steps (tests);
                            0: paced by time; < 0: the team throughout */
  int cut;               /* the team after the last step whose barrier a parked worker passed
                            (thread 0 writes it only then, or waking the parked) */
  int ready, done;       /* the team is set; the phase is over (under bar.mu) */
  int stopped;           /* the stop flag (urMembrane.stop) as thread 0 read it after a step */
  int parked;            /* workers parked (under bar.mu) */
  int it;                /* the step a parked worker resumes at, and its kinetic energy peak */
  double ke_prev;        /* (or FIRE's state) */
  Fire fire;
  double *vt, *rr, *kk, *pw, *vn; /* per triangle volume terms; per node f.f, kinetic energy
                                     (FIRE: v.v), FIRE's f.v, velocity */
  int steps;                      /* what the phase returns */
  double res;
  Barrier bar;
} Relax;

typedef struct {
  Relax* R;
  int tid;
} Worker;

/* thread 0's measure of the two ways: seconds per step of each (0: not yet), the current
   window's steps and start, when to try the slower way again */
typedef struct {
  double rate[2], t0, tprobe;
  int n, way; /* way 1: the team */
} Pace;

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* the way of the next step (1: the team), from the step just done; windows of WINDOW steps, a
   window of the team cut short once it is twice as slow as thread 0 alone */
static int pace(Pace* P) {
  double t = now(), el = t - P->t0;
  P->n++;
  int cut = P->way && P->rate[0] > 0 && el > 2 * P->rate[0] * WINDOW;
  if (P->n < WINDOW && !cut) {
    return P->way;
  }
  P->rate[P->way] = el / P->n;
  int best = P->rate[1] == 0 ? 1 : P->rate[0] == 0 ? 0 : P->rate[1] < P->rate[0];
  int way = best;
  if (t >= P->tprobe) {
    way = !P->way; /* the other way, measured afresh */
    P->tprobe = t + PROBE;
  }
  P->way = way;
  P->n = 0;
  P->t0 = t;
  return way;
}


/* thread tid's share of the nact: its blocks in b, its nodes in i (bounds) */
static void share(const Relax* R, int nact, int tid, int b[2], int i[2]) {
  int nc = (R->mb->ntb + urm_tri_chunk() - 1) / urm_tri_chunk();
  for (int k = 0; k < 2; k++) {
    long c = (long)nc * (tid + k) / nact * urm_tri_chunk();
    b[k] = c < R->mb->ntb ? (int)c : R->mb->ntb;
    i[k] = (int)((long)R->mb->nn * (tid + k) / nact);
  }
}


/* one relaxation phase (thread tid's share); fixedp > 0 holds the pressure there, else the gas is
   closed */
static void relax_run(Relax* R, int tid) {
  urMembrane* mb = R->mb;
  int nn = mb->nn, nt = mb->nt, it = 0, nact = R->nact, bs[2], is[2];
  double *st = R->st, *x = st, *v = st + 3 * nn, *f = st + 6 * nn, *sc = st + 18 * nn;
  double dt = mb->dt_stable, ke_prev = 0, r = INFINITY, fixedp = R->fixedp;
  const urMemSpec* s = &mb->spec;
  Pace P = {{0, 0}, now(), now() + PROBE, 0, nact > 1};
  int fire = mb->spec.inflate == urMEM_FIRE;
  Fire F = R->fire;

  // the pressure forces' reference (root mean square over the free nodes' areas)
  double q2 = 0;
  for (int i = 0; i < nn; i++) {
    if (mb->invm[i] > 0) {
      double ref = R->pscale * mb->mass[i] / s->rhot;
      q2 += ref * ref;
    }
  }
  share(R, nact, tid, bs, is);
  while (it < MAXSTEP && !R->stopped) { /* stopped on request: ur_mem_inflate says so */
    // the fabric of this thread's triangles; the volume (ur_mem_volume's sum, ur_mem_forces's)
    urm_tri_pass_part(mb, st, bs[0], bs[1], R->vt);
    barrier_wait(&R->bar);
    double V = 0, mgas = sc[urMEMS_MGAS];
    for (int t = 0; t < nt; t++) {
      V += R->vt[t];
    }
    V /= 6;
    if (fixedp > 0) {
      mgas = mb->mref * (V / mb->vref) * pow(fixedp / mb->pref, 1 / s->gamma);
    }
    double p = ur_mem_pressure(mb, V, mgas);
    urm_tri_forces_part(mb, st, (p - s->patm) / 6, bs[0], bs[1]);
    barrier_wait(&R->bar);
    urm_node_forces(mb, st, is[0], is[1], f);

    // this thread's nodes: residual terms; symplectic Euler's velocities (taken below unless
    // converged) and their kinetic energy, or FIRE's power f . v and v . v
    for (int i = is[0]; i < is[1]; i++) {
      double im = mb->invm[i], *fi = f + 3 * i, *vi = R->vn + 3 * i;
      R->rr[i] = im > 0 ? urm_dot(fi, fi) : 0;
      if (fire) {
        R->kk[i] = im > 0 ? urm_dot(v + 3 * i, v + 3 * i) : 0;
        R->pw[i] = im > 0 ? urm_dot(fi, v + 3 * i) : 0;
        continue;
      }
      for (int k = 0; k < 3; k++) {
        vi[k] = VISC * v[3 * i + k] + dt * im * fi[k];
      }
      R->kk[i] = im > 0 ? mb->mass[i] * urm_dot(vi, vi) : 0;
    }
    barrier_wait(&R->bar);

    // residual: the free nodes' forces against the pressure forces on their areas (root mean
    // squares: wrinkled, slack patches flap long after the bag has its shape and volume)
    double r2 = 0, ke = 0, pw = 0;
    for (int i = 0; i < nn; i++) {
      r2 += R->rr[i];
      ke += R->kk[i];
    }
    r = sqrt(r2 / q2);
    if (r < TOL && it > 10) {
      break;
    }

    if (fire) {
      // FIRE: downhill (power f . v > 0) the velocity turned towards the force, the step grown
      // after FNMIN such steps; uphill, stopped, the step halved
      for (int i = 0; i < nn; i++) {
        pw += R->pw[i];
      }
      double c1 = 0, c2 = 0;
      if (pw > 0) {
        c1 = 1 - F.alpha;
        c2 = F.alpha * sqrt(ke / r2);
        if (++F.npos > FNMIN) {
          F.dt = fmin(F.dt * FINC, F.dtmax);
          F.alpha *= FALPHA;
        }
      } else {
        F.dt *= FDEC;
        F.alpha = FALPHA0;
        F.npos = 0;
      }
      for (int i = is[0]; i < is[1]; i++) {
        double im = mb->invm[i];
        for (int k = 0; k < 3; k++) {
          double* vk = v + 3 * i + k;
          *vk = im > 0 ? c1 * *vk + c2 * f[3 * i + k] + F.dt * im * f[3 * i + k] : 0;
          x[3 * i + k] += F.dt * *vk;
        }
      }
    } else {
      // kinetic damping at the peaks of the kinetic energy
      int peak = ke < ke_prev;
      ke_prev = peak ? 0 : ke;
      for (int i = 3 * is[0]; i < 3 * is[1]; i++) {
        v[i] = peak ? 0 : R->vn[i];
        x[i] += dt * v[i];
      }
    }
    it++;

    // the next step's team: thread 0 decides (alone, or before the others pass the barrier)
    int next = nact, woke = 0;
    if (tid == 0) {
      R->stopped = mb->stop && *mb->stop; /* read by the others after the barrier */
    }
    if (tid == 0 && R->nthr > 1) {
      int way = R->alt > 0 ? it / R->alt % 2 == 0 : R->alt < 0 ? 1 : pace(&P);
      next = way ? R->nthr : 1;
      if (next > nact) {
        // the parked wake at this step, once every one of them is parked (else they might read
        // cut after this: the next step alone)
        pthread_mutex_lock(&R->bar.mu);
        if (R->parked < R->nthr - nact) {
          pthread_mutex_unlock(&R->bar.mu);
          next = nact;
          goto alone;
        }
        R->it = it;
        R->ke_prev = ke_prev;
        R->fire = F;
        R->bar.next = R->bar.n = next; /* no one is in the barrier: thread 0 was alone */
        R->nact = R->cut = next;
        pthread_cond_broadcast(&R->bar.cv);
        pthread_mutex_unlock(&R->bar.mu);
        woke = 1; /* so this step's barrier is not theirs */
      } else if (next < nact) {
        R->nact = R->cut = next; /* read by the others after the barrier */
        R->bar.next = next;
      }
    }
  alone:
    if (!woke) {
      barrier_wait(&R->bar);
    }
    if (tid > 0) {
      next = R->cut;
      if (next <= tid) {
        // parked until the team has this thread again, or the phase is over
        pthread_mutex_lock(&R->bar.mu);
        R->parked++;
        while (R->nact <= tid && !R->done) {
          pthread_cond_wait(&R->bar.cv, &R->bar.mu);
        }
        R->parked--;
        int over = R->done;
        next = R->nact;
        it = R->it;
        ke_prev = R->ke_prev;
        F = R->fire;
        pthread_mutex_unlock(&R->bar.mu);
        if (over) {
          return;
        }
      }
    }
    if (next != nact) {
      nact = next;
      share(R, nact, tid, bs, is);
    }
  }
  if (tid == 0) {
    R->steps = it;
    R->res = r;
    pthread_mutex_lock(&R->bar.mu);
    R->done = 1;
    pthread_cond_broadcast(&R->bar.cv);
    pthread_mutex_unlock(&R->bar.mu);
  }
}


/* a worker: waits until the team is known (relax), then runs its share */
static void* relax_worker(void* arg) {
  Worker* w = arg;
  Relax* R = w->R;
  pthread_mutex_lock(&R->bar.mu);
  while (!R->ready) {
    pthread_cond_wait(&R->bar.cv, &R->bar.mu);
  }
  pthread_mutex_unlock(&R->bar.mu);
  if (w->tid < R->nthr) {
    relax_run(R, w->tid);
  }
  return NULL;
}


/* one relaxation phase over nthr threads (the calling one and nthr - 1 started here; as many as
   start; alt as Relax's). work: nt + 6 nn doubles. Returns the steps taken, the final residual
   in *res */
static int relax(urMembrane* mb, double* st, double fixedp, double pscale, int nthr, int alt,
                 double* work, double* res) {
  Relax R = {mb, st, fixedp, pscale};
  R.alt = alt;
  R.vt = work;
  R.rr = R.vt + mb->nt;
  R.kk = R.rr + mb->nn;
  R.pw = R.kk + mb->nn;
  R.vn = R.pw + mb->nn;
  R.fire = (Fire){FDT0 * mb->dt_stable, FDTMAX * mb->dt_stable, FALPHA0, 0};
  atomic_init(&R.bar.count, 0);
  atomic_init(&R.bar.gen, 0);
  if (pthread_mutex_init(&R.bar.mu, NULL)) {
    nthr = 1;
  } else if (pthread_cond_init(&R.bar.cv, NULL)) {
    pthread_mutex_destroy(&R.bar.mu);
    nthr = 1;
  }
  pthread_t th[urMEM_MAXTHR];
  Worker w[urMEM_MAXTHR];
  int n = 1;
  for (; n < nthr; n++) {
    w[n].R = &R;
    w[n].tid = n;
    if (pthread_create(&th[n], NULL, relax_worker, &w[n])) {
      break;
    }
  }
  if (nthr > 1) {
    pthread_mutex_lock(&R.bar.mu);
  }
  R.nthr = R.nact = R.cut = R.bar.n = R.bar.next = n; /* the team as it started */
  R.stopped = mb->stop && *mb->stop;
  R.ready = 1;
  if (nthr > 1) {
    pthread_cond_broadcast(&R.bar.cv);
    pthread_mutex_unlock(&R.bar.mu);
  }
  relax_run(&R, 0);
  for (int k = 1; k < n; k++) {
    pthread_join(th[k], NULL);
  }
  if (nthr > 1) {
    pthread_cond_destroy(&R.bar.cv);
    pthread_mutex_destroy(&R.bar.mu);
  }
  *res = R.res;
  return R.steps;
}


int ur_mem_inflate(urMembrane* mb, char* err, size_t n) {
  return urm_mem_inflate_team(mb, 1, 0, err, n);
}


int ur_mem_inflate_threads(urMembrane* mb, int threads, char* err, size_t n) {
  // a thread for every MINTRI triangles at most: below, the barriers cost what it saves
  int most = mb->nt / MINTRI;
  return urm_mem_inflate_team(mb, threads < most ? threads : most, 0, err, n);
}


int urm_mem_inflate_team(urMembrane* mb, int nthr, int alt, char* err, size_t n) {
  const urMemSpec* s = &mb->spec;
  int nn = mb->nn, nc = (mb->ntb + urm_tri_chunk() - 1) / urm_tri_chunk();
  nthr = nthr < nc ? nthr : nc;
  nthr = nthr < urMEM_MAXTHR ? nthr : urMEM_MAXTHR;
  nthr = nthr > 1 ? nthr : 1;
  double* st = calloc(ur_mem_state_size(mb), sizeof(double));
  double* work = malloc(((size_t)mb->nt + 6 * (size_t)nn) * sizeof(double));
  if (!st || !work) {
    free(st);
    free(work);
    snprintf(err, n, "out of memory");
    return -1;
  }
  static const double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, z3[3] = {0, 0, 0};
  memcpy(mb->x0, mb->xshape, 3 * (size_t)nn * sizeof(double));
  mb->vref = ur_mem_volume(mb, mb->x0);
  mb->pref = s->p0;
  mb->mref = s->p0 * mb->vref / (urMEM_RS * s->temp);
  mb->strain0 = 0;
  ur_mem_state_init(mb, st, R, z3, z3, z3);

  // phase 1: the shaping pressure held
  double pg = fmax(s->p0 - s->patm, 0.01 * s->patm), res1, res2;
  int n1 = relax(mb, st, s->patm + pg, pg, nthr, alt, work, &res1);

  // phase 2: closed at the declared pressure in the volume reached
  double* sc = st + 18 * nn;
  mb->vref = ur_mem_volume(mb, st);
  mb->pref = s->p0;
  mb->mref = s->p0 * mb->vref / (urMEM_RS * s->temp);
  sc[urMEMS_MGAS] = mb->mref;
  memset(st + 3 * nn, 0, 3 * (size_t)nn * sizeof(double));
  int n2 = relax(mb, st, 0, pg, nthr, alt, work, &res2);
  mb->inflate_steps = n1 + n2;
  mb->inflate_res = res2;

  // the inflated state
  urMemInfo info;
  ur_mem_forces(mb, st, st + 6 * nn, &info);
  memcpy(mb->x0, st, 3 * (size_t)nn * sizeof(double));
  mb->vref = info.volume;
  mb->pref = info.pressure;
  mb->strain0 = info.strain;
  double c[3] = {0, 0, 0};
  for (int i = 0; i < nn; i++) {
    for (int k = 0; k < 3; k++) {
      c[k] += mb->x0[3 * i + k] / nn;
    }
  }
  double r = 0;
  for (int i = 0; i < nn; i++) {
    double d[3];
    urm_sub(d, mb->x0 + 3 * i, c);
    r = fmax(r, sqrt(urm_dot(d, d)));
  }
  memcpy(mb->cbound, c, sizeof(c));
  mb->rbound = r;
  free(st);
  free(work);
  if (mb->stop && *mb->stop) {
    snprintf(err, n, "stopped on request (interrupted) while inflating");
    return -1;
  }
  if (!(res2 < 10 * TOL) || !(info.volume > 0) || !isfinite(info.pressure)) {
    snprintf(err, n,
             "the bag did not settle when inflated (residual %.3g after %d steps); a finer "
             "mesh or a rounder shape may help",
             res2, n1 + n2);
    return -1;
  }
  return 0;
}
