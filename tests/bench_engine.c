/* bench_engine.c: cost of the engine on a drone-on-human scene (25 bodies, 29 pairs, airbag):
 * time per step, per simulated millisecond, and CPU time of one complete impact. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "uasimpact/engine.h"
#include "core/engine/test_engine_scene.h"

static double cpu(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}


int main(int argc, char** argv) {
  urModel* m = scene_build(1);
  if (!m) {
    fprintf(stderr, "bench_engine: scene does not compile\n");
    return 1;
  }

  // optional: time step and integrator (bench_engine [dt [rk4]])
  if (argc > 1) {
    m->opt.dt = atof(argv[1]);
  }
  if (argc > 2) {
    m->opt.integrator = urINT_RK4;
  }
  urData* d = ur_data_new(m);
  int dr = ur_name_body(m, "drone");
  int hs = ur_name_sensor(m, "head_acc"), ns = ur_name_sensor(m, "upper_neck");
  printf("bench_engine: %d bodies, %d dof, %d ellipsoids, %d pairs, %d airbag, dt %.0e s\n",
         m->nbody, m->nv, m->ngeom, m->npair, m->nbag, m->opt.dt);

  // settle the standing human (drone parked far above), timing the steps
  urData* rest = ur_data_new(m);
  double park[3] = {0, 0, 100}, zero[3] = {0, 0, 0};
  ur_set_free(m, rest, dr, park, NULL, zero, zero);
  int n = (int)(0.3 / m->opt.dt);
  double t0 = cpu();
  for (int i = 0; i < n; i++) {
    ur_step(m, rest);
  }
  double ts = (cpu() - t0) / n;
  printf("  stepping (no drone contact): %.2f us/step, %.3f ms CPU per simulated ms\n", 1e6 * ts,
         1e3 * ts * 1e-3 / m->opt.dt);
  printf("  kinetic energy left after settling: %.3g J (then zeroed)\n", rest->energy);
  memset(rest->qvel, 0, (size_t)m->nv * sizeof(double));
  rest->time = 0;
  ur_forward(m, rest);
  printf("  settled stance after %.2f s: %s, neck load %.1f N\n", n * m->opt.dt,
         ur_status_str(rest->status), rest->sensordata[m->sensor[ns].adr + 2]);

  // complete impacts at several offsets and speeds
  double offs[4] = {0.0, 0.05, 0.1, 0.2}, spd[3] = {7.5, 12.5, 40};
  double tot = 0, worst = 0, steps = 0;
  int runs = 0;
  for (int s = 0; s < 3; s++) {
    for (int o = 0; o < 4; o++) {
      double pos[3] = {offs[o], 0, 2.3}, vel[3] = {0, 0, -spd[s]};
      ur_data_copy(m, d, rest);
      t0 = cpu();
      int st = ur_run_impact(m, d, dr, pos, NULL, vel);
      double t = cpu() - t0;
      tot += t;
      worst = fmax(worst, t);
      steps += d->nstep;
      runs++;
      const double* pk = d->peakmax + m->sensor[hs].adr;
      const double* pn = d->peakmin + m->sensor[hs].adr;
      printf(
          "  impact v %4.1f off %.2f: %-20s %5ld steps (%4.1f ms), %6.2f ms CPU, "
          "head a [%6.0f, %6.0f] m/s^2, neck Fz [%6.0f, %6.0f] N\n",
          spd[s], offs[o], ur_status_str(st), d->nstep, 1e3 * (d->time - d->t_jump), 1e3 * t, pn[2],
          pk[2], d->peakmin[m->sensor[ns].adr + 2], d->peakmax[m->sensor[ns].adr + 2]);
    }
  }
  printf("  impacts: mean %.2f ms CPU, worst %.2f ms CPU, %.2f us/step in contact\n",
         1e3 * tot / runs, 1e3 * worst, 1e6 * tot / steps);
  ur_data_free(d);
  ur_data_free(rest);
  ur_model_free(m);
  return 0;
}
