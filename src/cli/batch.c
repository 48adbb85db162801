/* batch.c — forked worker pool (see batch.h).
 *
 * The parent never blocks except in poll(): it watches one pipe per worker
 * and a signalfd that receives SIGINT/SIGTERM (blocked for normal delivery,
 * so no signal handler and no global flag is needed).  A worker's pipe
 * reaches end-of-file when the worker has exited, whatever the way; the
 * parent then reaps it with waitpid() and reports it.
 */
#include "cli/batch.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/signalfd.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "util/strbuf.h"
#include "util/xalloc.h"

struct worker {
	pid_t pid;           /* 0: the slot is free */
	int fd;              /* read end of the worker's diagnostics pipe */
	size_t job;          /* job index */
	double t0;           /* start time, monotonic seconds */
	int stop_sent;       /* SIGTERM sent because the run is stopping */
	int timeout_killed;  /* SIGKILL sent because the job ran too long */
	struct strbuf text;  /* what the worker wrote so far */
};

/* Everything batch_run() keeps between its steps. */
struct pool {
	const struct batch_ops *ops;
	const struct batch_opts *opts;
	size_t n_jobs;
	struct worker *w;    /* opts->n_workers slots */
	int n_running;
	size_t n_done;
	int sfd;             /* signalfd, -1 when both signals are ignored */
	sigset_t old_mask;   /* restored in every worker and at the end */
	int stopping;        /* signal that stopped the run, 0 while running */
	double t_start;
	struct pollfd *pfd;  /* poll set: the signal fd and one per worker */
	int *slot;           /* worker slot of each poll entry */
};

double
batch_now_s(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void
report(struct pool *p, size_t job, enum batch_end end, int code, long pid,
       double seconds, const struct strbuf *text)
{
	struct batch_outcome o = { end, code, pid, seconds,
		text ? strbuf_str(text) : "", text ? text->len : 0 };
	p->ops->done(p->ops->ctx, job, &o);
	p->n_done++;
}

/* Worker side: never returns. */
static void
worker_main(struct pool *p, size_t job, int fd)
{
	if (p->sfd >= 0)
		close(p->sfd);
	sigprocmask(SIG_SETMASK, &p->old_mask, NULL);
	FILE *err = fdopen(fd, "w");
	int rc = 3;
	if (err != NULL) {
		/* Fully buffered: the text leaves in few writes; the parent
		 * keeps it whole anyway. */
		setvbuf(err, NULL, _IOFBF, 1 << 16);
		rc = p->ops->run(p->ops->ctx, job, err);
		fclose(err);
	}
	/* _exit: the parent's stdio buffers and atexit handlers are not ours. */
	_exit(rc & 0xff);
}

/* Starts job in a free slot; reports it as failed when it cannot. */
static void
launch(struct pool *p, size_t job)
{
	struct worker *w = NULL;
	for (int k = 0; k < p->opts->n_workers; k++)
		if (p->w[k].pid == 0) {
			w = &p->w[k];
			break;
		}
	int fds[2];
	if (w == NULL || pipe(fds) != 0) {
		report(p, job, BATCH_FAILED, w ? errno : EAGAIN, 0, 0.0, NULL);
		return;
	}
	fflush(stdout);
	fflush(stderr);
	pid_t pid = fork();
	if (pid < 0) {
		int e = errno;
		close(fds[0]);
		close(fds[1]);
		report(p, job, BATCH_FAILED, e, 0, 0.0, NULL);
		return;
	}
	if (pid == 0) {
		close(fds[0]);
		worker_main(p, job, fds[1]);
	}
	close(fds[1]);
	w->pid = pid;
	w->fd = fds[0];
	w->job = job;
	w->t0 = batch_now_s();
	w->stop_sent = 0;
	w->timeout_killed = 0;
	strbuf_reset(&w->text);
	p->n_running++;
}

static void read_signals(struct pool *p);

/* The worker's pipe is at end-of-file: reap it and report. */
static void
reap(struct pool *p, struct worker *w)
{
	int st = 0;
	while (waitpid(w->pid, &st, 0) < 0 && errno == EINTR)
		;
	close(w->fd);
	enum batch_end end;
	int code;
	if (WIFEXITED(st)) {
		end = BATCH_EXITED;
		code = WEXITSTATUS(st);
	} else {
		code = WIFSIGNALED(st) ? WTERMSIG(st) : 0;
		/* A ^C on a terminal reaches the workers too (same process
		 * group), and the parent's copy may still be queued: read it
		 * first, so such a death counts as a stop, not a crash. */
		read_signals(p);
		if (w->timeout_killed)
			end = BATCH_TIMED_OUT;
		else if (w->stop_sent || p->stopping != 0)
			end = BATCH_STOPPED;
		else
			end = BATCH_SIGNALLED;
	}
	report(p, w->job, end, code, (long)w->pid, batch_now_s() - w->t0, &w->text);
	w->pid = 0;
	w->fd = -1;
	p->n_running--;
}

static void
signal_all(struct pool *p, int sig)
{
	for (int k = 0; k < p->opts->n_workers; k++)
		if (p->w[k].pid != 0) {
			kill(p->w[k].pid, sig);
			p->w[k].stop_sent = 1;
		}
}

/* Reads every queued signal; the first stops the run, a second one kills. */
static void
read_signals(struct pool *p)
{
	struct signalfd_siginfo si;
	while (p->sfd >= 0 && read(p->sfd, &si, sizeof si) == (ssize_t)sizeof si) {
		if (p->stopping == 0) {
			p->stopping = (int)si.ssi_signo;
			signal_all(p, SIGTERM);
		} else {
			signal_all(p, SIGKILL);
		}
	}
}

static void
tick(struct pool *p)
{
	if (p->ops->tick == NULL)
		return;
	double t = batch_now_s();
	struct batch_state s = { p->n_jobs, p->n_done, (size_t)p->n_running, -1,
		0.0, t - p->t_start };
	for (int k = 0; k < p->opts->n_workers; k++)
		if (p->w[k].pid != 0 && (s.oldest < 0 || t - p->w[k].t0 > s.oldest_s)) {
			s.oldest = (long)p->w[k].job;
			s.oldest_s = t - p->w[k].t0;
		}
	p->ops->tick(p->ops->ctx, &s);
}

/* One poll() round: read pipes, reap finished workers, enforce timeouts. */
static void
wait_step(struct pool *p, struct pollfd *pfd, int *slot)
{
	int n = 0;
	if (p->sfd >= 0) {
		pfd[n].fd = p->sfd;
		pfd[n].events = POLLIN;
		slot[n++] = -1;
	}
	double t = batch_now_s(), wait_s = p->opts->tick_s;
	for (int k = 0; k < p->opts->n_workers; k++) {
		struct worker *w = &p->w[k];
		if (w->pid == 0)
			continue;
		pfd[n].fd = w->fd;
		pfd[n].events = POLLIN;
		slot[n++] = k;
		double left = w->t0 + p->opts->timeout_s - t;
		if (!w->timeout_killed && left < wait_s)
			wait_s = left > 0.0 ? left : 0.0;
	}
	int ms = (int)(wait_s * 1000.0) + 1;
	if (poll(pfd, (nfds_t)n, ms) < 0 && errno != EINTR)
		return;
	for (int i = 0; i < n; i++) {
		if (slot[i] < 0) {
			if (pfd[i].revents & POLLIN)
				read_signals(p);
			continue;
		}
		if (!(pfd[i].revents & (POLLIN | POLLHUP | POLLERR)))
			continue;
		struct worker *w = &p->w[slot[i]];
		char buf[4096];
		ssize_t got = read(w->fd, buf, sizeof buf);
		if (got > 0)
			strbuf_append(&w->text, buf, (size_t)got);
		else if (got == 0 || (errno != EINTR && errno != EAGAIN))
			reap(p, w);
	}
	t = batch_now_s();
	for (int k = 0; k < p->opts->n_workers; k++) {
		struct worker *w = &p->w[k];
		if (w->pid != 0 && !w->timeout_killed && t - w->t0 > p->opts->timeout_s) {
			kill(w->pid, SIGKILL);
			w->timeout_killed = 1;
		}
	}
}

/* Watch SIGINT and SIGTERM through a signalfd, except a signal the process
 * inherited as ignored (a shell's background job must not die of ^C). */
static void
signals_open(struct pool *p)
{
	sigset_t set;
	sigemptyset(&set);
	static const int sigs[] = { SIGINT, SIGTERM };
	for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
		struct sigaction sa;
		if (sigaction(sigs[i], NULL, &sa) == 0 && sa.sa_handler != SIG_IGN)
			sigaddset(&set, sigs[i]);
	}
	sigprocmask(SIG_BLOCK, &set, &p->old_mask);
	p->sfd = signalfd(-1, &set, SFD_NONBLOCK | SFD_CLOEXEC);
	if (p->sfd < 0)  /* cannot watch: let the signals act as usual */
		sigprocmask(SIG_SETMASK, &p->old_mask, NULL);
}

int
batch_run(size_t n_jobs, const struct batch_ops *ops,
          const struct batch_opts *opts, size_t *n_started)
{
	struct pool p = { 0 };
	p.ops = ops;
	p.opts = opts;
	p.n_jobs = n_jobs;
	p.w = xcalloc((size_t)opts->n_workers, sizeof *p.w);
	p.t_start = batch_now_s();
	signals_open(&p);
	/* Held in the pool so a forked worker still reaches them (its leak
	 * check under valgrind must not see the parent's buffers as lost). */
	p.pfd = xcalloc((size_t)opts->n_workers + 1, sizeof *p.pfd);
	p.slot = xcalloc((size_t)opts->n_workers + 1, sizeof *p.slot);
	struct pollfd *pfd = p.pfd;
	int *slot = p.slot;
	size_t next = 0;
	double last_tick = 0.0;
	for (;;) {
		while (!p.stopping && p.n_running < opts->n_workers && next < n_jobs) {
			size_t job = next++;
			if (ops->skip != NULL && ops->skip(ops->ctx, job)) {
				p.n_done++;
				continue;
			}
			launch(&p, job);
			read_signals(&p);
		}
		if (p.n_running == 0)
			break;
		size_t done_before = p.n_done;
		wait_step(&p, pfd, slot);
		double t = batch_now_s();
		if (p.n_done != done_before || t - last_tick >= opts->tick_s) {
			tick(&p);
			last_tick = t;
		}
	}
	read_signals(&p);  /* a signal that came with the last job still counts */
	if (p.sfd >= 0) {
		close(p.sfd);
		sigprocmask(SIG_SETMASK, &p.old_mask, NULL);
	}
	for (int k = 0; k < opts->n_workers; k++)
		strbuf_free(&p.w[k].text);
	free(pfd);
	free(slot);
	free(p.w);
	if (n_started != NULL)
		*n_started = next;
	return p.stopping;
}
