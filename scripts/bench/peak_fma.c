/* peak_fma.c — one core's double-precision multiply-add throughput [flop/s], for the benchmark
 * report's "fraction of peak". 32 independent accumulators a = a*b + c (two flops each), a loop
 * the compiler vectorises with the solver's flags and -ffp-contract=fast (the Makefile), so that
 * with ARCH=native it measures fused multiply-adds in the widest vectors (the portable build has
 * no FMA instruction: there it measures multiply + add).
 * Usage: peak_fma [SECONDS]   prints "peak_flops <flop/s>", the best of several repeats. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define LANES 32
#define INNER 4096

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Run `iters` sweeps of the accumulators; returns their sum so nothing is optimised away. */
static double sweep(long iters, double b, double c) {
  double acc[LANES];
  for (int k = 0; k < LANES; k++) acc[k] = 0.001 * k;
  for (long n = 0; n < iters; n++)
    for (int k = 0; k < LANES; k++) acc[k] = acc[k] * b + c;
  double s = 0;
  for (int k = 0; k < LANES; k++) s += acc[k];
  return s;
}

int main(int argc, char **argv) {
  double seconds = argc > 1 ? atof(argv[1]) : 1.0, best = 0, sink = 0;
  volatile double b = 0.999999, c = 1e-7;   /* volatile: not known at compile time */
  double end = now() + seconds;
  while (now() < end) {
    double t0 = now();
    sink += sweep(INNER * 64L, b, c);
    double rate = 2.0 * LANES * INNER * 64.0 / (now() - t0);
    if (rate > best) best = rate;
  }
  printf("peak_flops %.6g\n", best);
  fprintf(stderr, "(checksum %g)\n", sink);
  return 0;
}
