/* keywatch.h: the keys that stop a wait on a raw terminal (keywatch.c). */
#ifndef UASRISK_KEYWATCH_H
#define UASRISK_KEYWATCH_H

#include <pthread.h>
#include <stdatomic.h>

typedef struct {
  pthread_t thread;
  int fd;           /* the terminal read */
  int running;      /* the thread was started */
  _Atomic int stop; /* asks the thread to end */
  _Atomic int key;  /* the key that stopped the work: 3 (Ctrl-C), 'q', or 0 */
} uraKeyWatch;

/* watch fd (a terminal in raw mode) while the caller works: Ctrl-C or q sets the interrupt flag
   (interrupt.c) within 0.05 s; other keys are dropped. 0, or -1 when no thread could start (the
   work then runs unwatched) */
int ura_keywatch_start(uraKeyWatch* w, int fd);

/* end the watch; returns the key that stopped the work (3 for Ctrl-C, 'q') or 0 for none, and
   clears the interrupt flag a key set */
int ura_keywatch_stop(uraKeyWatch* w);

#endif
