/* xalloc.c — allocation that never returns NULL (see xalloc.h). */
#include "util/xalloc.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef AEROEVAL_TEST_HOOKS
/* Countdown for the AEROEVAL_FAIL_ALLOC test hook; read once.  This is the
 * one process-wide variable of the test build: it only ever counts down and
 * is only set by tests, so -j N workers (separate processes) are unaffected. */
static long fail_countdown = -2; /* -2 unread, -1 disabled */
#endif

void
xalloc_die(size_t n)
{
	fprintf(stderr, "aeroeval: error: out of memory (%zu bytes)\n", n);
	exit(3);
}

/* The AEROEVAL_FAIL_ALLOC hook, compiled into test builds only. */
static void
maybe_inject_failure(size_t n)
{
#ifdef AEROEVAL_TEST_HOOKS
	if (fail_countdown == -2) {
		const char *e = getenv("AEROEVAL_FAIL_ALLOC");
		fail_countdown = (e != NULL && *e != '\0') ? strtol(e, NULL, 10) : -1;
	}
	if (fail_countdown > 0 && --fail_countdown == 0)
		xalloc_die(n);
#else
	(void)n;
#endif
}

void *
xmalloc(size_t n)
{
	maybe_inject_failure(n);
	void *p = malloc(n ? n : 1);
	if (p == NULL)
		xalloc_die(n);
	return p;
}

void *
xcalloc(size_t n, size_t size)
{
	maybe_inject_failure(n * size);
	void *p = calloc(n ? n : 1, size ? size : 1);
	if (p == NULL)
		xalloc_die(n * size);
	return p;
}

void *
xrealloc(void *p, size_t n)
{
	maybe_inject_failure(n);
	void *q = realloc(p, n ? n : 1);
	if (q == NULL)
		xalloc_die(n);
	return q;
}

char *
xstrdup(const char *s)
{
	size_t n = strlen(s) + 1;
	char *d = xmalloc(n);
	memcpy(d, s, n);
	return d;
}

