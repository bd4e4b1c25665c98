/* mem.c — checked allocation: out of memory ends the process with status 3 and says what and how
 * much. Under mpirun a non-zero exit of one rank ends the whole job. */
#include "base/mem.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#define MMAP_THRESHOLD_BYTES (128 * 1024)   /* glibc's initial threshold, kept fixed */

void mem_setup(void) {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, MMAP_THRESHOLD_BYTES);
#endif
}

_Noreturn void mem_fail(size_t bytes, const char *what) {
  if (bytes) fprintf(stderr, "mpsph: out of memory: %s (%zu bytes)\n", what, bytes);
  else fprintf(stderr, "mpsph: out of memory: %s (allocated inside a library)\n", what);
  fflush(NULL);
  _exit(3);   /* not exit(): HDF5's exit handler would close an open MPI-IO file collectively and
                 wait for the other ranks for ever; mpirun ends the job on this non-zero status */
}

size_t mem_bytes(size_t n, size_t size, const char *what) {
  if (size && n > SIZE_MAX / size) mem_fail(SIZE_MAX, what);
  return n * size;
}

void *mem_alloc(size_t bytes, const char *what) {
  void *p = malloc(bytes ? bytes : 1);
  if (!p) mem_fail(bytes, what);
  return p;
}

void *mem_calloc(size_t n, size_t size, const char *what) {
  size_t bytes = mem_bytes(n, size, what);
  void *p = calloc(bytes ? n : 1, bytes ? size : 1);
  if (!p) mem_fail(bytes, what);
  return p;
}

void *mem_realloc(void *ptr, size_t bytes, const char *what) {
  void *p = realloc(ptr, bytes ? bytes : 1);
  if (!p) mem_fail(bytes, what);
  return p;
}

char *mem_strndup(const char *text, size_t n, const char *what) {
  size_t len = strnlen(text, n);
  char *copy = mem_alloc(len + 1, what);
  memcpy(copy, text, len);
  copy[len] = '\0';
  return copy;
}
