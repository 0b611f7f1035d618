/* keywatch.c: the keys that stop a wait on a raw terminal. The viewer puts the terminal in raw
 * mode, so Ctrl-C is a byte to read, not SIGINT; while the viewer waits on work (the impact
 * Enter runs, gnuplot drawing p's plot) nobody reads the terminal. A thread reads it meanwhile
 * and turns Ctrl-C and q into the interrupt flag that the work polls (interrupt.c: the engine's
 * opt.stop, the wait for gnuplot), within the 0.05 s of its poll. Other keys typed during the
 * wait are read and dropped (a terminal's escape sequences cannot be handed back to ncurses).
 * The thread touches only the descriptor and two atomics, never ncurses.
 */
#include <errno.h>
#include <poll.h>
#include <string.h>
#include <unistd.h>

#include "base.h"

/* the thread: poll the terminal every 0.05 s until asked to stop */
static void* watch(void* arg) {
  uraKeyWatch* w = arg;
  while (!atomic_load(&w->stop)) {
    struct pollfd pf = {w->fd, POLLIN, 0};
    int r = poll(&pf, 1, 50);
    if (r < 0 && errno != EINTR) break;
    if (r <= 0) continue;
    if (!(pf.revents & POLLIN)) break; /* hung up or closed: nothing more to read */
    unsigned char buf[64];
    ssize_t n = read(w->fd, buf, sizeof buf);
    if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) break;
    for (ssize_t i = 0; i < n; i++) {
      if ((buf[i] == 3 || buf[i] == 'q') && !atomic_load(&w->key)) {
        atomic_store(&w->key, buf[i]);
        atomic_store_explicit(ura_interrupt_flag(), 1, memory_order_relaxed);
      }
    }
  }
  return NULL;
}

int ura_keywatch_start(uraKeyWatch* w, int fd) {
  memset(w, 0, sizeof *w);
  w->fd = fd;
  atomic_init(&w->stop, 0);
  atomic_init(&w->key, 0);
  w->running = pthread_create(&w->thread, NULL, watch, w) == 0;
  return w->running ? 0 : -1;
}

int ura_keywatch_stop(uraKeyWatch* w) {
  if (!w->running) return 0;
  atomic_store(&w->stop, 1);
  pthread_join(w->thread, NULL);
  w->running = 0;
  int key = atomic_load(&w->key);
  if (key) ura_interrupt_clear();
  return key;
}
