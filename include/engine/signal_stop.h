/* signal_stop.h — a clean stop on SIGTERM, SIGINT or SIGUSR1: the handler only records the
 * signal; the time loop asks once per step, all ranks together. */
#ifndef MPSPH_SIGNAL_STOP_H
#define MPSPH_SIGNAL_STOP_H

#include <mpi.h>

/** Install the handlers of SIGTERM, SIGINT and SIGUSR1 (after MPI_Init). They record the
 *  signal number and nothing else. */
void signal_stop_install(void);

/** Collective: the largest signal number any rank of comm has received (0 if none), so that
 *  every rank stops at the same step. */
int signal_stop_agreed(MPI_Comm comm);

/** The name of a stop signal ("SIGTERM"). */
const char *signal_stop_name(int signo);

#endif
