/* fsout_int.h — what fsout.c shares with fsfolder.c, and no one else.
 *
 * Who may include it: src/fs/fsout.c, src/fs/fsfolder.c and
 * tests/test_fsout.c.
 */
#ifndef AEROEVAL_FSOUT_INT_H
#define AEROEVAL_FSOUT_INT_H

#include <stddef.h>

#ifdef AEROEVAL_TEST_HOOKS
/* Counts one file write for the AEROEVAL_FAIL_WRITE hook (fsout.h) and
 * returns the errno this write must fail with, or 0 when it must not. */
int fsout_fault_take(void);

/* Sleeps AEROEVAL_TEST_WRITE_DELAY_MS milliseconds (fsout.h); no-op unset. */
void fsout_test_delay(void);
#else
/* Outside test builds the hooks are not there: no write fails on purpose,
 * none waits (and the compiler drops the branches that would). */
static inline int fsout_fault_take(void) { return 0; }
static inline void fsout_test_delay(void) { }
#endif

/* write(2) until all n bytes are out; EINTR and short writes are retried.
 * Returns 0, or -1 with errno set. */
int fsout_write_all(int fd, const void *data, size_t n);

#endif
