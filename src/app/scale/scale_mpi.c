/* scale_mpi.c: the MPI distributor of ./uasimpact-mpi ('make mpi': this file compiled with
 * -DURA_MPI by mpicc; the plain build has none). Every rank replays the script; rank 0 prints,
 * the others are muted. In each grid rank 0 hands out chunks of the fixed cell list on demand
 * (about 1/(4 N) of the cells still free, so a slow chunk does not stall a rank): its own worker
 * threads take chunks directly, a server thread answers the other ranks' requests. When the list
 * is handed out, every rank sends rank 0 the cells it simulated, and rank 0 broadcasts the whole
 * grid, so that every rank goes on with the same state. Waiting polls with short sleeps instead
 * of spinning: ranks share cores with worker threads. Ctrl-C on rank 0 aborts every rank (status
 * 130); ranks out of step (another grid on another rank: the nodes see other files) abort every
 * rank with status 3; SIGTERM ends rank 0, and mpirun the others. Scripts only (no -i, no
 * standard input). */
#include "scale.h"

#ifndef URA_MPI
uraScale* ura_mpi_new(uraCtx* c, int* argc, char*** argv) {
  (void)c, (void)argc, (void)argv;
  return NULL;
}
#else
#include <fcntl.h>
#include <mpi.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

enum {
  TAG_REQ = 11,
  TAG_CHUNK,
  TAG_CELLS
};

typedef struct {
  int rank, size;
  pthread_mutex_t lock; /* the chunk state below; MPI calls of worker threads */
  long ntodo;
  long lo, hi;   /* this rank's chunk: positions lo..hi-1 */
  int exhausted; /* no chunk is left for this rank (this grid) */
  long pool;     /* rank 0: the first position not handed out */
  int told;      /* rank 0: ranks told that nothing is left */
  pthread_t server;
  int serving;
  long *mine, nmine, cap; /* positions this rank simulated (this grid) */
  int err_fd;             /* ranks but 0: their standard error, kept for a lone failure */
} mpiDist;

static void pause_us(long us) {
  struct timespec t = {0, us * 1000};
  nanosleep(&t, NULL);
}

/* wait for a request without spinning */
static void wait_req(MPI_Request* r) {
  int done = 0;
  for (;;) {
    MPI_Test(r, &done, MPI_STATUS_IGNORE);
    if (done) return;
    pause_us(50);
  }
}

/* exit statuses of a run stopped on every rank (uasimpact(1), EXIT STATUS): Ctrl-C as everywhere;
   ranks out of step (another grid on another rank) a status of its own; anything else 1 */
#define ST_INTERRUPTED 130
#define ST_OUT_OF_STEP 3
#define ST_FAILED      1

static void abort_all(const char* why, int status) {
  fprintf(stderr, "uasimpact-mpi: %s; every rank stopped\n", why);
  MPI_Abort(MPI_COMM_WORLD, status);
}

/* rank 0, lock held: the next chunk of the pool into [*lo, *hi) */
static void carve(mpiDist* d, long* lo, long* hi) {
  long left = d->ntodo - d->pool, n = left / (4L * d->size);
  if (n < 1) n = 1;
  if (n > left) n = left;
  *lo = d->pool;
  *hi = d->pool + n;
  d->pool += n;
}

static void* serve(void* arg) {
  uraScale* s = arg;
  mpiDist* d = s->impl;
  while (d->told < d->size - 1) {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, TAG_REQ, MPI_COMM_WORLD, &flag, &st);
    if (!flag) {
      if (ura_interrupted()) abort_all("interrupted (Ctrl-C) on rank 0", ST_INTERRUPTED);
      pause_us(50);
      continue;
    }
    long req[3], chunk[2]; /* grid number, list length, key: the same on every rank */
    MPI_Recv(req, 3, MPI_LONG, st.MPI_SOURCE, TAG_REQ, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (req[0] != s->grid || req[1] != d->ntodo || req[2] != (long)strtoull(s->key, NULL, 16)) {
      abort_all(
          "ranks out of step: another grid on another rank (do all nodes see the same "
          "script and model files?)",
          ST_OUT_OF_STEP);
    }
    pthread_mutex_lock(&d->lock);
    carve(d, &chunk[0], &chunk[1]);
    pthread_mutex_unlock(&d->lock);
    if (chunk[0] == chunk[1]) d->told++;
    MPI_Send(chunk, 2, MPI_LONG, st.MPI_SOURCE, TAG_CHUNK, MPI_COMM_WORLD);
  }
  return NULL;
}

static int p_begin(uraScale* s, long ntodo) {
  mpiDist* d = s->impl;
  d->ntodo = ntodo;
  d->lo = d->hi = d->pool = 0;
  d->exhausted = 0;
  d->told = 0;
  d->nmine = 0;
  d->serving = 0;
  if (d->rank == 0 && d->size > 1) {
    if (pthread_create(&d->server, NULL, serve, s)) {
      abort_all("cannot start the thread that hands out cells", ST_FAILED);
    }
    d->serving = 1;
  }
  return 0;
}

static long p_next(uraScale* s) {
  mpiDist* d = s->impl;
  long pos = -1;
  pthread_mutex_lock(&d->lock);
  if (d->lo == d->hi && !d->exhausted) {
    if (d->rank == 0) {
      carve(d, &d->lo, &d->hi);
    } else {
      long chunk[2], req[3] = {s->grid, d->ntodo, (long)strtoull(s->key, NULL, 16)};
      MPI_Request r;
      MPI_Send(req, 3, MPI_LONG, 0, TAG_REQ, MPI_COMM_WORLD);
      MPI_Irecv(chunk, 2, MPI_LONG, 0, TAG_CHUNK, MPI_COMM_WORLD, &r);
      wait_req(&r);
      d->lo = chunk[0];
      d->hi = chunk[1];
    }
    if (d->lo == d->hi) d->exhausted = 1;
  }
  if (d->lo < d->hi) {
    pos = d->lo++;
    if (d->nmine == d->cap) {
      long cap = d->cap ? 2 * d->cap : 1024;
      long* t = realloc(d->mine, (size_t)cap * sizeof *t);
      if (!t) abort_all("out of memory", ST_FAILED);
      d->mine = t;
      d->cap = cap;
    }
    d->mine[d->nmine++] = pos;
  }
  pthread_mutex_unlock(&d->lock);
  return pos;
}

/* cells as text: 'POS CELL' lines */
static char* pack(urGrid* g, const long* todo, const long* pos, long n, int* len) {
  char* text = NULL;
  size_t size = 0;
  char line[512];
  FILE* f = open_memstream(&text, &size);
  if (!f) abort_all("out of memory", ST_FAILED);
  for (long k = 0; k < n; k++) {
    int w = ura_cell_write(&g->cell[todo[pos ? pos[k] : k]], line, sizeof line);
    if (w == -2) {
      abort_all(
          "a cell holds a value outside its domain (p or a PoF not in [0, 1], or an "
          "infinite criterion): a message cannot carry it",
          ST_FAILED);
    } else if (w < 0) {
      abort_all("a cell's result does not fit a message line", ST_FAILED);
    }
    fprintf(f, "%ld %s\n", pos ? pos[k] : k, line);
  }
  fclose(f);
  if (size > 2000000000) abort_all("a grid too large for one message", ST_FAILED);
  *len = (int)size;
  return text;
}

static int unpack(uraScale* s, urGrid* g, const long* todo, long ntodo, char* text) {
  for (char* line = text; *line;) {
    char* nl = strchr(line, '\n');
    char* end;
    if (!nl) break;
    *nl = 0;
    long k = strtol(line, &end, 10);
    if (end == line || *end != ' ' || k < 0 || k >= ntodo ||
        ura_cell_read(end + 1, &g->cell[todo[k]])) {
      return ura_fail(s->c, "grid: a damaged message from another rank");
    }
    line = nl + 1;
  }
  return 0;
}

static int p_end(uraScale* s, urGrid* g, const long* todo, long ntodo) {
  mpiDist* d = s->impl;
  int len = 0, rc = 0;
  char* text;
  if (d->rank == 0) {
    if (d->serving) pthread_join(d->server, NULL);
    d->serving = 0;
    if (ura_interrupted()) abort_all("interrupted (Ctrl-C) on rank 0", ST_INTERRUPTED);
    for (int r = 1; r < d->size; r++) { /* the cells of each rank */
      int flag = 0;
      MPI_Status st;
      for (;;) {
        MPI_Iprobe(r, TAG_CELLS, MPI_COMM_WORLD, &flag, &st);
        if (flag) break;
        if (ura_interrupted()) abort_all("interrupted (Ctrl-C) on rank 0", ST_INTERRUPTED);
        pause_us(50);
      }
      MPI_Get_count(&st, MPI_CHAR, &len);
      text = malloc((size_t)len + 1);
      if (!text) abort_all("out of memory", ST_FAILED);
      MPI_Recv(text, len, MPI_CHAR, r, TAG_CELLS, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      text[len] = 0;
      if (!rc) rc = unpack(s, g, todo, ntodo, text);
      free(text);
    }
    text = pack(g, todo, NULL, ntodo, &len);
  } else {
    MPI_Request r;
    text = pack(g, todo, d->mine, d->nmine, &len);
    MPI_Isend(text, len, MPI_CHAR, 0, TAG_CELLS, MPI_COMM_WORLD, &r);
    wait_req(&r);
    free(text);
    text = NULL;
  }

  /* the whole grid to every rank */
  MPI_Request r;
  MPI_Ibcast(&len, 1, MPI_INT, 0, MPI_COMM_WORLD, &r);
  wait_req(&r);
  if (d->rank != 0) {
    text = malloc((size_t)len + 1);
    if (!text) abort_all("out of memory", ST_FAILED);
  }
  MPI_Ibcast(text, len, MPI_CHAR, 0, MPI_COMM_WORLD, &r);
  wait_req(&r);
  text[len] = 0;
  if (d->rank != 0 && !rc) rc = unpack(s, g, todo, ntodo, text);
  free(text);
  return rc;
}

/* the end of the run. Ranks replay the same script, so a failing command fails on every rank and
   they all arrive here; a rank that fails alone (a file only its node lacks, a full disk on rank
   0) would leave the others waiting in the next grid: a failed rank waits at most FINISH_WAIT s
   for the others, then aborts them all with its status and message */
#define FINISH_WAIT    5.0
static int p_finish(uraScale* s, int rc) {
  mpiDist* d = s->impl;
  if (rc == 130 && d->size > 1) abort_all("interrupted (Ctrl-C)", ST_INTERRUPTED);
  MPI_Request r;
  int done = 0;
  double t0 = MPI_Wtime();
  MPI_Ibarrier(MPI_COMM_WORLD, &r);
  while (!done) {
    MPI_Test(&r, &done, MPI_STATUS_IGNORE);
    if (done) break;
    if (rc && MPI_Wtime() - t0 > FINISH_WAIT) {
      if (d->err_fd >= 0) {
        dprintf(d->err_fd, "uasimpact-mpi: rank %d failed alone: %s\n", d->rank, s->c->err);
      }
      fprintf(stderr, "uasimpact-mpi: rank %d failed alone; every rank stopped\n", d->rank);
      MPI_Abort(MPI_COMM_WORLD, rc);
    }
    pause_us(1000);
  }
  MPI_Finalize();
  free(d->mine);
  pthread_mutex_destroy(&d->lock);
  free(d);
  free(s);
  return rc;
}

static const uraScaleOps ops = {"mpi", p_begin, p_next, p_end, p_finish};

uraScale* ura_mpi_new(uraCtx* c, int* argc, char*** argv) {
  int have = 0;
  if (MPI_Init_thread(argc, argv, MPI_THREAD_MULTIPLE, &have) != MPI_SUCCESS) {
    fprintf(stderr, "uasimpact-mpi: MPI_Init failed\n");
    exit(2);
  }
  if (have < MPI_THREAD_SERIALIZED) {
    fprintf(stderr,
            "uasimpact-mpi: this MPI cannot be called from threads (MPI_THREAD_SERIALIZED "
            "is needed)\n");
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  uraScale* s = calloc(1, sizeof *s);
  mpiDist* d = calloc(1, sizeof *d);
  if (!s || !d) {
    fprintf(stderr, "uasimpact-mpi: out of memory\n");
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &d->rank);
  MPI_Comm_size(MPI_COMM_WORLD, &d->size);
  pthread_mutex_init(&d->lock, NULL);

  /* scripts only: an interactive session would read its commands on rank 0 alone */
  int work = 0;
  for (int i = 1; i < *argc; i++) {
    if (!strcmp((*argv)[i], "-i")) work = -1000;
    work += strcmp((*argv)[i], "-c") ? ((*argv)[i][0] != '-') : 1;
    if (!strcmp((*argv)[i], "-c")) i++;
  }
  if (work <= 0) {
    if (d->rank == 0) {
      fprintf(stderr,
              "uasimpact-mpi: runs scripts, not sessions; accepted: mpirun -n N "
              "uasimpact-mpi [-c COMMANDS] [FILE]... (no -i)\n");
    }
    MPI_Finalize();
    exit(2);
  }
  d->err_fd = -1;
  if (d->rank != 0) { /* rank 0 speaks for all */
    ura_scale_mute(c);
    d->err_fd = dup(STDERR_FILENO);
    int fd = open("/dev/null", O_WRONLY);
    if (fd >= 0) dup2(fd, STDERR_FILENO), close(fd);
  }
  s->ops = &ops;
  s->c = c;
  s->grid = -1;
  s->impl = d;
  return s;
}
#endif
