/* cli_build.c — `aeroeval build`: many missions, in parallel, incrementally.
 *
 * The parent loads the reference tables, the catalogue and the template
 * once, decides which missions are up to date, and hands the others to a
 * pool of forked workers (batch.h), each of which runs pipeline_build() for
 * one mission.  The pipeline replaces a mission's outputs as one set, with
 * a stamp that records the fingerprint of the inputs computed here and the
 * SHA-256 of every output (pipeline.h).
 */
#include "cli/cli_build.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli/batch.h"
#include "cli/cli.h"
#include "cli/cli_help.h"
#include "cli/cli_summary.h"
#include "fs/fsout.h"
#include "formats/index.h"
#include "cli/pipeline.h"
#include "cli/shard.h"
#include "util/sha256.h"
#include "util/strbuf.h"
#include "template/template.h"
#include "util/xalloc.h"

#define BUILD_USAGE "usage: aeroeval build [-o DIR] [-j N] [-q] [--force] " \
	"[--shard K/N] [--template FILE] [--db DIR] MISSION.json|DIR...\n"

/* A mission cannot hang (the solver is bounded); this only guards against a
 * bug.  AEROEVAL_BUILD_TIMEOUT_S overrides it (tests use a short one). */
#define BUILD_TIMEOUT_S 60.0
#define BUILD_TICK_S 0.1          /* progress line redraw interval */
#define BUILD_MAX_JOBS 1024       /* -j above this is a typo */

/* A growable list of mission paths. */
struct path_list {
	char **v;
	size_t n, cap;
};

/* Everything the run shares; workers see it copy-on-write. */
struct build {
	char out_dir[4096];        /* -o, without trailing slashes */
	int quiet;                 /* -q */
	int force;                 /* --force */
	struct shard shard;        /* --shard K/N; n == 0: every mission */
	size_t n_given;            /* missions given, before the shard's pick */
	int tty;                   /* stderr is a terminal: live progress line */
	struct path_list missions;
	char (*names)[256];        /* output folder of each mission, "" if unsafe */
	char (*fp)[SHA256_HEX_LEN]; /* fingerprint of each mission, "" if unknown */
	char base_fp[SHA256_HEX_LEN]; /* of every input but the mission file */
	struct cli_env *env;
	struct template *tpl;
	struct pipeline_opts popts;
	size_t n_ok, n_inf, n_rej, n_int, n_utd, n_utd_inf, n_stopped;
	size_t n_unw;              /* not written: a file-system problem */
	int line_shown;            /* the progress line is on screen */
};

static void
list_add(struct path_list *l, const char *s)
{
	if (l->n == l->cap) {
		l->cap = l->cap ? 2 * l->cap : 16;
		l->v = xrealloc(l->v, l->cap * sizeof *l->v);
	}
	l->v[l->n++] = xstrdup(s);
}

static void
list_free(struct path_list *l)
{
	for (size_t i = 0; i < l->n; i++)
		free(l->v[i]);
	free(l->v);
}

static int
cmp_str(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

static int
ends_with_json(const char *s)
{
	size_t n = strlen(s);
	return n > 5 && strcmp(s + n - 5, ".json") == 0;
}

/* True when the file name is one the design-space table writes into an
 * output folder (index.json), and dir is that output folder: a build given
 * its own output folder as input (build -o . .) read its index.json as a
 * mission. */
static int
is_own_table(const char *dir, const char *name, const char *out_dir)
{
	struct stat a, b;
	for (size_t i = 0; out_dir != NULL && index_file_names[i] != NULL; i++)
		if (strcmp(name, index_file_names[i]) == 0)
			return stat(dir, &a) == 0 && stat(out_dir, &b) == 0
			    && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
	return 0;
}

/* The *.json files of dir (no hidden ones, none of the table's files when
 * dir is out_dir; out_dir may be NULL), sorted for a stable order. */
static int
list_json(const char *dir, struct path_list *l, const char *out_dir)
{
	DIR *d = opendir(dir);
	if (d == NULL)
		return -1;
	size_t first = l->n, len = strlen(dir);
	const char *sep = len > 0 && dir[len - 1] == '/' ? "" : "/";
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		if (e->d_name[0] == '.' || !ends_with_json(e->d_name)
		    || is_own_table(dir, e->d_name, out_dir))
			continue;
		char p[4400];
		snprintf(p, sizeof p, "%s%s%s", dir, sep, e->d_name);
		list_add(l, p);
	}
	closedir(d);
	/* An empty directory adds nothing: l->v may still be NULL, which qsort
	 * must not be given (UBSan). */
	if (l->n - first > 1)
		qsort(l->v + first, l->n - first, sizeof *l->v, cmp_str);
	return 0;
}

/* A directory contributes its *.json files (one without any is noted in
 * empty; out_dir as for list_json()); a file is taken as given. */
static int
expand(const char *arg, struct path_list *l, struct path_list *empty, const char *out_dir)
{
	struct stat st;
	if (stat(arg, &st) != 0) {
		fprintf(stderr, "%s: error: %s\n", arg, strerror(errno));
		return -1;
	}
	size_t before = l->n;
	if (S_ISDIR(st.st_mode) && list_json(arg, l, out_dir) != 0) {
		fprintf(stderr, "%s: error: cannot read the directory: %s\n", arg,
		    strerror(errno));
		return -1;
	}
	if (S_ISDIR(st.st_mode) && l->n == before && empty != NULL)
		list_add(empty, arg);
	if (!S_ISDIR(st.st_mode))
		list_add(l, arg);
	return 0;
}

/* ---- fingerprints -------------------------------------------------------- */

/* One length-prefixed field, so that no two input sets hash alike by
 * shifting bytes from one field into the next. */
static void
hash_field(struct sha256_ctx *c, const void *p, size_t n)
{
	unsigned char len8[8];
	for (int k = 0; k < 8; k++)
		len8[k] = (unsigned char)((uint64_t)n >> (8 * k));
	sha256_update(c, len8, sizeof len8);
	sha256_update(c, p, n);
}

static void
hash_str(struct sha256_ctx *c, const char *s)
{
	hash_field(c, s, strlen(s));
}

/* The file's name and every one of its bytes (streamed, so no size is too
 * large); a missing or unreadable file hashes as "missing", and one that
 * changes while it is read as "changing" (never "up to date"). */
static void
hash_file(struct sha256_ctx *c, const char *path)
{
	char why[256];
	hash_str(c, path);
	int rc = cli_hash_file(c, path, why, sizeof why);
	if (rc != 0)
		hash_str(c, rc == -1 ? "missing" : "changing");
}

/* A large file that only an install replaces (the program, the fonts), by
 * its name, size and modification time: hashing their megabytes took
 * longer than compiling a mission.  Replacing one changes its mtime. */
static void
hash_file_identity(struct sha256_ctx *c, const char *path)
{
	struct stat st;
	char id[96];
	hash_str(c, path);
	if (stat(path, &st) != 0) {
		hash_str(c, "missing");
		return;
	}
	snprintf(id, sizeof id, "%lld %lld.%09ld", (long long)st.st_size,
	    (long long)st.st_mtim.tv_sec, (long)st.st_mtim.tv_nsec);
	hash_str(c, id);
}

static void
hex_final(struct sha256_ctx *c, char out[SHA256_HEX_LEN])
{
	unsigned char d[SHA256_DIGEST_LEN];
	sha256_final(c, d);
	for (int i = 0; i < SHA256_DIGEST_LEN; i++)
		snprintf(out + 2 * i, 3, "%02x", d[i]);
}

/* Everything a mission's outputs depend on besides the mission file: the
 * engine (its version and the program file's identity, so a rebuilt
 * compiler recompiles), the catalogue, the reference tables, the template
 * with its fonts, logo and ICC profile, and SOURCE_DATE_EPOCH (it can set
 * the dossier date).  The data, the template and the profile are hashed by
 * content (a checkout that only touches them stays up to date), the
 * program and the fonts by identity (hash_file_identity()). */
static void
base_fingerprint(struct build *b, const char *tpl_path)
{
	struct sha256_ctx c;
	sha256_init(&c);
	hash_str(&c, PIPELINE_STAMP_MAGIC);
	hash_str(&c, AEROEVAL_VERSION);
	char exe[4096];
	ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
	if (n > 0) {
		exe[n] = '\0';
		hash_file_identity(&c, exe);
	} else {
		hash_str(&c, "no program file");
	}
	hash_str(&c, b->env->catalogue_sha256);
	struct path_list data = { 0 };
	list_json(b->env->data_dir, &data, NULL);
	for (size_t i = 0; i < data.n; i++) {
		/* The name relative to data/, so a moved installation is the same. */
		const char *slash = strrchr(data.v[i], '/');
		hash_str(&c, slash ? slash + 1 : data.v[i]);
		hash_file(&c, data.v[i]);
	}
	list_free(&data);
	if (tpl_path != NULL)
		hash_file(&c, tpl_path);
	else
		hash_str(&c, "default");
	hash_file_identity(&c, b->tpl->font_regular);
	hash_file_identity(&c, b->tpl->font_bold);
	hash_file_identity(&c, b->tpl->font_mono);
	if (b->tpl->logo[0] != '\0')
		hash_file(&c, b->tpl->logo);
	if (b->tpl->icc_profile[0] != '\0')
		hash_file(&c, b->tpl->icc_profile);   /* the PDF/A output intent */
	const char *epoch = getenv("SOURCE_DATE_EPOCH");
	hash_str(&c, epoch ? epoch : "");
	hex_final(&c, b->base_fp);
}

/* The mission's fingerprint: the base, its output name (it is printed in
 * the dossier and the hand-off: a folder copied over another mission's
 * with the same bytes was called up to date) and its bytes (all of them,
 * streamed); not its file times, which no output depends on (the dossier
 * date is report.date, SOURCE_DATE_EPOCH or none: fsout_resolve_date), so a
 * copy or a checkout that changes only the mtime stays up to date.
 * Returns -1 when unreadable. */
static int
mission_fingerprint(const struct build *b, size_t i, char out[SHA256_HEX_LEN])
{
	const char *path = b->missions.v[i];
	char why[256];
	struct sha256_ctx c;
	sha256_init(&c);
	hash_str(&c, b->base_fp);
	hash_str(&c, b->names[i]);
	if (cli_hash_file(&c, path, why, sizeof why) != 0)
		return -1;
	hex_final(&c, out);
	return 0;
}

/* ---- output ---------------------------------------------------------------- */

/* Prints text in one write, first wiping the progress line if it is up. */
static void
emit(struct build *b, const struct strbuf *text)
{
	if (text->len == 0)
		return;
	if (b->line_shown) {
		fputs("\r\033[K", stderr);
		b->line_shown = 0;
	}
	fwrite(text->data, 1, text->len, stderr);
	fflush(stderr);
}

/* ---- the three callbacks of the worker pool -------------------------------- */

static int
build_skip(void *ctx, size_t i)
{
	struct build *b = ctx;
	b->fp[i][0] = '\0';
	if (b->names[i][0] == '\0' || mission_fingerprint(b, i, b->fp[i]) != 0) {
		b->fp[i][0] = '\0';
		return 0;  /* the worker reports why */
	}
	int st = b->force ? -1 : pipeline_current(&b->popts, b->names[i], b->fp[i]);
	if (st < 0)
		return 0;
	b->n_utd++;
	b->n_utd_inf += st == 1;
	if (!b->quiet && !b->tty) {
		struct strbuf line = STRBUF_INIT;
		strbuf_printf(&line, "%s: up to date%s\n", b->missions.v[i],
		    st == 1 ? " (infeasible)" : "");
		emit(b, &line);
		strbuf_free(&line);
	}
	return 1;
}

/* Test hook (test builds only): AEROEVAL_TEST_WORKER=abort:NAME or
 * hang:NAME makes the worker of mission NAME crash or hang, so tests can
 * prove the run survives it. */
static void
test_hook(const char *name)
{
#ifndef AEROEVAL_TEST_HOOKS
	(void)name;
#else
	const char *h = getenv("AEROEVAL_TEST_WORKER");
	if (h == NULL)
		return;
	if (strncmp(h, "abort:", 6) == 0 && strcmp(h + 6, name) == 0)
		abort();
	if (strncmp(h, "hang:", 5) == 0 && strcmp(h + 5, name) == 0)
		for (;;)
			pause();
#endif
}

/* Worker process: compile mission i; the pipeline writes its stamp. */
static int
build_run(void *ctx, size_t i, FILE *err)
{
	struct build *b = ctx;
	if (b->names[i][0] != '\0')
		test_hook(b->names[i]);
	return pipeline_build(b->env, &b->popts, b->missions.v[i], b->fp[i], err);
}

static void
build_done(void *ctx, size_t i, const struct batch_outcome *o)
{
	struct build *b = ctx;
	const char *path = b->missions.v[i];
	struct strbuf out = STRBUF_INIT;
	int bad = 1;  /* an error: printed even with -q */
	/* A worker that died may have left a temporary folder: its pid is
	 * gone now, so the folder's stale temporaries can go at once. */
	if (o->end != BATCH_EXITED && o->end != BATCH_FAILED && b->names[i][0] != '\0')
		pipeline_clean(&b->popts, b->names[i]);
	strbuf_append(&out, o->text, o->n_text);
	if (o->n_text > 0 && o->text[o->n_text - 1] != '\n')
		strbuf_append_char(&out, '\n');
	switch (o->end) {
	case BATCH_EXITED:
		if (o->code == PIPE_FEASIBLE || o->code == PIPE_INFEASIBLE) {
			bad = 0;
			if (o->code == PIPE_FEASIBLE)
				b->n_ok++;
			else
				b->n_inf++;
			strbuf_printf(&out, "%s: compiled (%s%.2f s)\n", path,
			    o->code == PIPE_INFEASIBLE ? "infeasible, " : "", o->seconds);
		} else if (o->code == PIPE_REJECTED) {
			b->n_rej++;
			strbuf_printf(&out, "%s: rejected\n", path);
		} else if (o->code == PIPE_UNWRITTEN) {
			b->n_unw++;
			strbuf_printf(&out, "%s: not written\n", path);
		} else {
			b->n_int++;
			strbuf_printf(&out, "%s: internal error\n", path);
		}
		break;
	case BATCH_SIGNALLED:
		b->n_int++;
		strbuf_printf(&out, "%s: internal error: the worker died of signal %d (%s)\n",
		    path, o->code, strsignal(o->code));
		break;
	case BATCH_TIMED_OUT:
		b->n_int++;
		strbuf_printf(&out, "%s: internal error: no result after %.1f s; the worker was stopped\n",
		    path, o->seconds);
		break;
	case BATCH_STOPPED:
		b->n_stopped++;
		bad = 0;
		strbuf_printf(&out, "%s: interrupted\n", path);
		break;
	case BATCH_FAILED:
		b->n_int++;
		strbuf_printf(&out, "%s: internal error: cannot start a worker: %s\n",
		    path, strerror(o->code));
		break;
	}
	/* On a terminal the progress line stands for the missions that went
	 * well; -q keeps only the errors. */
	if (bad || (!b->quiet && (!b->tty || o->n_text > 0 || o->end == BATCH_STOPPED
	    || o->code == PIPE_INFEASIBLE)))
		emit(b, &out);
	strbuf_free(&out);
}

static void
build_tick(void *ctx, const struct batch_state *s)
{
	struct build *b = ctx;
	if (!b->tty || b->quiet || s->oldest < 0)
		return;
	const char *path = b->missions.v[s->oldest];
	const char *base = strrchr(path, '/');
	fprintf(stderr, "\r[%zu/%zu] compiling %.48s  %.1f s\033[K", s->n_done + 1,
	    s->n_jobs, base ? base + 1 : path, s->oldest_s);
	fflush(stderr);
	b->line_shown = 1;
}

/* ---- the command ------------------------------------------------------------- */

static int
parse_jobs(const char *s, int *out)
{
	char *end;
	errno = 0;
	long v = strtol(s, &end, 10);
	if (errno != 0 || end == s || *end != '\0' || v < 1 || v > BUILD_MAX_JOBS)
		return -1;
	*out = (int)v;
	return 0;
}

static double
timeout_s(void)
{
	const char *s = getenv("AEROEVAL_BUILD_TIMEOUT_S");
	char *end;
	double v = s ? strtod(s, &end) : 0.0;
	return s && end != s && *end == '\0' && v > 0.0 && v < 1e6 ? v : BUILD_TIMEOUT_S;
}

/* Name clashes are an error before anything is written. */
static int
check_names(struct build *b)
{
	int rc = 0;
	for (size_t i = 0; i < b->missions.n; i++) {
		if (pipeline_name(b->missions.v[i], b->names[i], sizeof b->names[i]) != 0) {
			b->names[i][0] = '\0';  /* the worker reports it as rejected */
			continue;
		}
		for (size_t j = 0; j < i; j++)
			if (strcmp(b->names[i], b->names[j]) == 0) {
				fprintf(stderr, "%s: error: output name \"%s\" clashes with %s\n",
				    b->missions.v[i], b->names[i], b->missions.v[j]);
				rc = 2;
				break;
			}
	}
	return rc;
}

static void
summary(const struct build *b, int sig, size_t n_started, double seconds)
{
	struct strbuf s = STRBUF_INIT;
	strbuf_append_str(&s, "build: ");
	if (sig != 0)
		strbuf_printf(&s, "interrupted (%s): ", sig == SIGINT ? "SIGINT" : "SIGTERM");
	strbuf_printf(&s, "%zu compiled (%zu infeasible), %zu up to date (%zu infeasible), "
	    "%zu rejected, ", b->n_ok + b->n_inf, b->n_inf, b->n_utd, b->n_utd_inf, b->n_rej);
	if (b->n_unw > 0)  /* shown only when it happened: it is rare */
		strbuf_printf(&s, "%zu not written (file system), ", b->n_unw);
	strbuf_printf(&s, "%zu internal errors", b->n_int);
	if (sig != 0)
		strbuf_printf(&s, ", %zu stopped, %zu not started", b->n_stopped,
		    b->missions.n - n_started);
	strbuf_printf(&s, "; %zu missions", b->missions.n);
	if (b->shard.n > 0)
		strbuf_printf(&s, " (shard %u/%u of %zu)", b->shard.k, b->shard.n, b->n_given);
	strbuf_printf(&s, " in %.1f s\n", seconds);
	fwrite(s.data, 1, s.len, stderr);
	strbuf_free(&s);
}

/* Keeps the missions of this machine's share (shard.h); the others are
 * other machines'.  A name that cannot name a folder is shared out by its
 * file's base name, so exactly one machine rejects it. */
static void
pick_shard(struct build *b)
{
	b->n_given = b->missions.n;
	if (b->shard.n == 0)
		return;
	size_t k = 0;
	for (size_t i = 0; i < b->missions.n; i++) {
		char *p = b->missions.v[i], name[256];
		if (pipeline_name(p, name, sizeof name) != 0) {
			const char *slash = strrchr(p, '/');
			str_copy(name, sizeof name, slash ? slash + 1 : p);
		}
		if (shard_has(&b->shard, name))
			b->missions.v[k++] = p;
		else
			free(p);
	}
	b->missions.n = k;
}

/* After a run that changed a mission folder, finished or interrupted, or
 * when the table no longer matches the folders (cli_summary_stale(): a
 * table missing, damaged or older than a row, a killed writer's
 * leftovers), the design-space table of the output folder is rebuilt
 * (cli_summary.h).  SIGINT and SIGTERM wait until it is written whole; one
 * that came meanwhile makes the status 128 + its number.  Returns the
 * run's exit status, raised to the refresh's (2 or 3) when that failed. */
static int
refresh_index(const struct build *b, int rc)
{
	if (b->n_ok + b->n_inf == 0 && !cli_summary_stale(b->out_dir))
		return rc;
	sigset_t stop, old;
	sigemptyset(&stop);
	sigaddset(&stop, SIGINT);
	sigaddset(&stop, SIGTERM);
	sigprocmask(SIG_BLOCK, &stop, &old);
	int irc = cli_summary_refresh(b->out_dir, b->tpl, stderr);
	/* Take a signal that came during the refresh instead of dying of it
	 * when the mask is restored; an ignored one is dropped there anyway. */
	struct timespec now = { 0, 0 };
	int sig = sigtimedwait(&stop, NULL, &now);
	sigprocmask(SIG_SETMASK, &old, NULL);
	if (irc > rc && rc < 128)
		rc = irc;
	return sig > 0 && rc < 128 ? 128 + sig : rc;
}

int
cli_build(int argc, char **argv)
{
	double t0 = batch_now_s();
	struct build b = { 0 };
	struct path_list empty_dirs = { 0 };   /* directories without a mission */
	struct path_list operands = { 0 };     /* files and directories, expanded
	                                        * once -o is known */
	const char *db = NULL, *tpl_path = NULL;
	long n_cpu = sysconf(_SC_NPROCESSORS_ONLN);
	int n_workers = n_cpu >= 1 && n_cpu <= BUILD_MAX_JOBS ? (int)n_cpu : 1;
	int rc = 0, opts_done = 0;
	const char *out_opt = "out";
	for (int i = 1; i < argc; i++) {
		const char *a = argv[i];
		int has_val = i + 1 < argc;
		if (opts_done || a[0] != '-' || a[1] == '\0') {
			list_add(&operands, a);
		} else if (strcmp(a, "--") == 0) {
			opts_done = 1;
		} else if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
			cli_help_command("build", stdout);
			list_free(&operands);
			return 0;
		} else if (strcmp(a, "-q") == 0) {
			b.quiet = 1;
		} else if (strcmp(a, "--force") == 0) {
			b.force = 1;
		} else if (strcmp(a, "-o") == 0 && has_val) {
			out_opt = argv[++i];
		} else if (strcmp(a, "--db") == 0 && has_val) {
			db = argv[++i];
		} else if (strcmp(a, "--template") == 0 && has_val) {
			tpl_path = argv[++i];
		} else if ((strcmp(a, "--shard") == 0 && has_val) || strncmp(a, "--shard=", 8) == 0) {
			const char *v = a[7] == '=' ? a + 8 : argv[++i];
			char msg[160];
			if (shard_parse(v, &b.shard, msg, sizeof msg) != 0) {
				fprintf(stderr, "aeroeval build: error: %s\n", msg);
				rc = 2;
			}
		} else if (strncmp(a, "-j", 2) == 0 && (a[2] != '\0' || has_val)) {
			const char *v = a[2] != '\0' ? a + 2 : argv[++i];
			if (parse_jobs(v, &n_workers) != 0) {
				fprintf(stderr, "aeroeval build: -j wants a whole number "
				    "from 1 to %d (got \"%s\")\n", BUILD_MAX_JOBS, v);
				rc = 2;
			}
		} else {
			fprintf(stderr, "aeroeval build: unknown option or missing value: %s\n%s",
			    a, BUILD_USAGE);
			list_free(&operands);
			return 2;
		}
	}
	for (size_t i = 0; i < operands.n; i++)
		if (expand(operands.v[i], &b.missions, &empty_dirs, out_opt) != 0)
			rc = 2;
	list_free(&operands);
	if (b.missions.n == 0 && rc == 0 && empty_dirs.n > 0) {
		for (size_t i = 0; i < empty_dirs.n; i++)
			fprintf(stderr, "%s: error: no mission file (*.json) in this directory\n",
			    empty_dirs.v[i]);
		rc = 2;
	} else if (b.missions.n == 0 && rc == 0) {
		fprintf(stderr, "aeroeval build: no mission given\n%s", BUILD_USAGE);
		rc = 2;
	}
	list_free(&empty_dirs);
	pick_shard(&b);
	b.names = xcalloc(b.missions.n + 1, sizeof *b.names);
	b.fp = xcalloc(b.missions.n + 1, sizeof *b.fp);
	b.env = xcalloc(1, sizeof *b.env);
	if (rc == 0)
		rc = cli_out_dir("build", "-o", out_opt, b.out_dir, sizeof b.out_dir, stderr);
	if (rc == 0 && b.missions.n == 0) {
		/* Nothing of this machine's: not an error, the others compile. */
		if (!b.quiet)
			fprintf(stderr, "build: shard %u/%u holds none of the %zu missions\n",
			    b.shard.k, b.shard.n, b.n_given);
		goto out;
	}
	if (rc == 0)
		rc = check_names(&b);
	if (rc == 0 && cli_env_load(b.env, db, 1, stderr) != 0)
		rc = 2;
	if (rc == 0) {
		b.tpl = cli_template_load(tpl_path, stderr);
		if (b.tpl == NULL)
			rc = 2;
	}
	char msg[4400];
	if (rc == 0 && fsout_mkdirs(b.out_dir, msg, sizeof msg) != 0) {
		fprintf(stderr, "aeroeval build: error: %s\n", msg);
		rc = 2;
	}
	if (rc == 0) {
		/* A file-size limit (ulimit -f) must fail a write with EFBIG and a
		 * clear message, not kill the worker; workers inherit this. */
		signal(SIGXFSZ, SIG_IGN);
		base_fingerprint(&b, tpl_path);
		b.popts.out_dir = b.out_dir;
		b.popts.tpl = b.tpl;
		b.popts.lock_wait_s = 0.5 * timeout_s();
		b.tty = isatty(STDERR_FILENO);
		if ((size_t)n_workers > b.missions.n)
			n_workers = (int)b.missions.n;
		struct batch_ops ops = { &b, build_skip, build_run, build_done, build_tick };
		struct batch_opts bo = { n_workers, timeout_s(), BUILD_TICK_S };
		size_t n_started = 0;
		int sig = batch_run(b.missions.n, &ops, &bo, &n_started);
		if (b.line_shown)
			fputs("\r\033[K", stderr);
		if (!b.quiet || sig != 0)
			summary(&b, sig, n_started, batch_now_s() - t0);
		if (sig != 0)
			rc = 128 + sig;
		else
			rc = b.n_int ? 3 : b.n_rej + b.n_unw ? 2 : b.n_inf + b.n_utd_inf ? 1 : 0;
		/* Interrupted too: the missions compiled before the signal are
		 * new rows. */
		rc = refresh_index(&b, rc);
	}
out:
	template_free(b.tpl);
	cli_env_free(b.env);
	free(b.env);
	free(b.names);
	free(b.fp);
	list_free(&b.missions);
	return rc;
}
