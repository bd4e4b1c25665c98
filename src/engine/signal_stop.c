/* signal_stop.c — records SIGTERM, SIGINT and SIGUSR1 in a flag that the time loop polls.
 * SIGUSR1 is there for Open MPI's mpirun: it forwards SIGUSR1 to the ranks, whereas on SIGTERM
 * or SIGINT it kills them one second after passing the signal on. */
#include "engine/signal_stop.h"

#include <signal.h>
#include <string.h>

static volatile sig_atomic_t received = 0;

static void record(int signo) { received = signo; }

void signal_stop_install(void) {
  static const int signals[] = {SIGTERM, SIGINT, SIGUSR1};
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = record;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;   /* system calls in progress (file writes) carry on */
  for (size_t k = 0; k < sizeof signals / sizeof signals[0]; k++) sigaction(signals[k], &sa, NULL);
}

int signal_stop_agreed(MPI_Comm comm) {
  int mine = received, any;
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm);
  return any;
}

const char *signal_stop_name(int signo) {
  return signo == SIGTERM ? "SIGTERM" : signo == SIGINT ? "SIGINT" : signo == SIGUSR1 ? "SIGUSR1" : "a signal";
}
