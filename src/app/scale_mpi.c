/* scale_mpi.c: the MPI distributor (built with -DURA_MPI by 'make mpi' into ./uasrisk-mpi); in
 * the plain build there is none. */
#include "scale.h"

#ifndef URA_MPI
uraScale* ura_mpi_new(uraCtx* c, int* argc, char*** argv) {
  (void)c, (void)argc, (void)argv;
  return NULL;
}
#endif
