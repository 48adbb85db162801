/* batch.h — run many independent jobs in a pool of forked worker processes.
 *
 * Why processes and not threads: a job that crashes (a bug, a stack
 * overflow, an abort in a library) takes down only its own worker, and the
 * run goes on.  Everything the jobs share (the catalogue, reference tables,
 * template) is loaded by the caller before batch_run() and reaches each
 * worker copy-on-write through fork(), so it is loaded once per run.
 *
 * Each worker's diagnostics go into a pipe that the parent collects whole;
 * the parent hands them to done() when the worker has ended, so the text of
 * one job is printed in one piece and never interleaves with another's.
 *
 * SIGINT and SIGTERM (unless the caller's process ignores them, as a shell
 * does for background jobs) stop the run: no new job starts, the running
 * workers get SIGTERM (a second signal: SIGKILL), the parent waits for them
 * all, reports each through done() and returns the signal number.
 * A job that runs past the timeout is killed (SIGKILL) and reported.
 *
 * CLI layer (uses POSIX process calls).  No globals: the caller's state
 * travels in ops->ctx.
 */
#ifndef AEROEVAL_BATCH_H
#define AEROEVAL_BATCH_H

#include <stddef.h>
#include <stdio.h>

/* How a job ended. */
enum batch_end {
	BATCH_EXITED,     /* the worker returned; code is run()'s result */
	BATCH_SIGNALLED,  /* the worker died of signal `code` (a crash) */
	BATCH_TIMED_OUT,  /* killed after opts.timeout_s; code is the signal */
	BATCH_STOPPED,    /* killed because the run was interrupted; code is the signal */
	BATCH_FAILED      /* could not start (pipe/fork failed); code is errno */
};

struct batch_outcome {
	enum batch_end end;
	int code;            /* see enum batch_end */
	long pid;            /* worker process id (0 if none); its temp files carry it */
	double seconds;      /* wall time from start to end */
	const char *text;    /* everything the worker wrote to err, NUL-terminated */
	size_t n_text;       /* bytes of text */
};

/* What the progress display needs, given to tick(). */
struct batch_state {
	size_t n_jobs;       /* jobs in the run */
	size_t n_done;       /* jobs finished or skipped */
	size_t n_running;    /* workers alive */
	long oldest;         /* index of the longest-running job, -1 if none */
	double oldest_s;     /* how long it has been running */
	double elapsed_s;    /* since batch_run() started */
};

struct batch_ops {
	void *ctx;           /* passed to every callback */
	/* Parent, just before job i would start: nonzero means it needs no run
	 * (the callback reports it).  May be NULL. */
	int (*skip)(void *ctx, size_t i);
	/* Worker process: do job i, write diagnostics to err, return 0..255. */
	int (*run)(void *ctx, size_t i, FILE *err);
	/* Parent: job i has ended.  o->text is only valid during the call. */
	void (*done)(void *ctx, size_t i, const struct batch_outcome *o);
	/* Parent: progress, about every opts.tick_s and after each job.  May be NULL. */
	void (*tick)(void *ctx, const struct batch_state *s);
};

struct batch_opts {
	int n_workers;       /* jobs at once, >= 1 */
	double timeout_s;    /* per job, > 0 */
	double tick_s;       /* interval of tick() calls, > 0 */
};

/* Runs jobs 0..n_jobs-1 in index order of start.  Returns 0 when every job
 * was started (or skipped) and has ended, else the signal number (SIGINT or
 * SIGTERM) that stopped the run; the jobs that never started are not
 * reported.  *n_started (may be NULL) receives the number of jobs started
 * or skipped. */
int batch_run(size_t n_jobs, const struct batch_ops *ops,
              const struct batch_opts *opts, size_t *n_started);

/* Monotonic time in seconds, for elapsed-time reports only (never an
 * output: outputs are reproducible). */
double batch_now_s(void);

#endif
