/* mem.h — the one way mpsph allocates: a failed allocation ends the process with status 3 and a
 * message naming what was being allocated and how many bytes. */
#ifndef MPSPH_MEM_H
#define MPSPH_MEM_H

#include <stddef.h>

/** Keep large blocks (128 kB and more) out of the heap: glibc then maps each one by itself and
 *  returns it to the system when freed (it would otherwise raise the threshold after the first
 *  such free and keep the later blocks, freed or not, resident in the heap: about 15 % more
 *  resident memory measured on a 2-rank two-phase run). Call first in main. */
void mem_setup(void);

/** malloc(bytes) for `what` (e.g. "halo send buffer"); never returns NULL. */
void *mem_alloc(size_t bytes, const char *what);

/** calloc(n, size) for `what`, zero-filled; refuses n * size overflowing size_t; never NULL. */
void *mem_calloc(size_t n, size_t size, const char *what);

/** realloc(ptr, bytes) for `what`; never returns NULL (ptr is then no longer valid). */
void *mem_realloc(void *ptr, size_t bytes, const char *what);

/** A copy of the first at most n bytes of text, NUL-terminated, for `what`; never returns NULL. */
char *mem_strndup(const char *text, size_t n, const char *what);

/** End the process as a failed allocation of `bytes` for `what` (0: a library's own allocation
 *  of unknown size failed). */
_Noreturn void mem_fail(size_t bytes, const char *what);

/** n * size for `what`, ending the process as an allocation failure when it overflows size_t. */
size_t mem_bytes(size_t n, size_t size, const char *what);

#endif
