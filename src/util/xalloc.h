/* xalloc.h — allocation that never returns NULL.
 *
 * Every allocation in aeroeval goes through these.  On exhaustion they print
 * one line and exit with status 3 (internal error; README.md, "Exit
 * status").  In a test build (-DAEROEVAL_TEST_HOOKS) the hook
 * AEROEVAL_FAIL_ALLOC=N makes the N-th allocation fail, so tests can prove
 * that an out-of-memory exit never leaves a truncated output behind.
 * Ownership: the caller frees what these return with free().
 */
#ifndef AEROEVAL_XALLOC_H
#define AEROEVAL_XALLOC_H

#include <stddef.h>

void *xmalloc(size_t n);
void *xcalloc(size_t n, size_t size);
void *xrealloc(void *p, size_t n);
char *xstrdup(const char *s);

/* Prints the out-of-memory line (n bytes wanted, 0 if unknown) and exits
 * with status 3: for a library that reports exhaustion as a status (cairo),
 * so every out-of-memory reads the same. */
void xalloc_die(size_t n) __attribute__((noreturn));

#endif
