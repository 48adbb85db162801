/* pipeline.h — compile one mission: read, validate, solve, render, write.
 *
 * Everything a mission's outputs depend on is in its arguments (the shared
 * read-only environment and the mission path), so `build` can compile
 * missions in parallel.  Nothing is written unless the mission is valid,
 * and the outputs of a mission are replaced as one set (fsfolder.h): an
 * interrupted or failed compile never leaves a truncated file, a mix of
 * old and new files, or destroys a good set.  A stamp in the set records
 * the fingerprint of the inputs and the SHA-256 of every output, so a set
 * is "up to date" only while its files are the ones the stamp vouches for.
 */
#ifndef AEROEVAL_PIPELINE_H
#define AEROEVAL_PIPELINE_H

#include <stddef.h>
#include <stdio.h>

#include "cli/cli.h"
#include "result/result.h"

struct strbuf;
struct template;

/* Outcome of one mission, as exit statuses (README.md, "Exit status"). */
enum pipeline_status {
	PIPE_FEASIBLE = 0,    /* compiled, every design feasible */
	PIPE_INFEASIBLE = 1,  /* compiled, outputs say why it is infeasible */
	PIPE_REJECTED = 2,    /* bad input: nothing written */
	PIPE_INTERNAL = 3,    /* internal error: nothing written */
	PIPE_UNWRITTEN = 4    /* a file-system problem (read-only, full disk, a
	                       * link or FIFO in the way): nothing changed;
	                       * exit status 2 like bad input */
};

/* The stamp file in DIR/<name>/ and its first line. */
#define PIPELINE_STAMP ".aeroeval-stamp"
#define PIPELINE_STAMP_MAGIC "aeroeval-stamp 3\n"

/* The files `sensitivity` adds to DIR/<name>/ (pipeline_add()); a build
 * recognises them as the program's, and drops them when it replaces the
 * set (a new set is the outputs of the mission as it now is). */
#define PIPELINE_SENS_JSON "sensitivity.json"
#define PIPELINE_SENS_PDF "sensitivity.pdf"

struct pipeline_opts {
	const char *out_dir;          /* DIR of DIR/<name>/; must exist */
	const struct template *tpl;   /* dossier template (NULL: no dossier) */
	double lock_wait_s;           /* how long to wait for another writer */
	struct strbuf *dossier_text;  /* NULL, or receives the text of the dossier
	                                 written (report_input.transcript): for
	                                 the tests that read what it says */
};

/* Solve the mission at path into *r (callers own r, large: allocate it).
 * Diagnostics are buffered and flushed in one write to err.  Returns the
 * status; on PIPE_REJECTED *r is untouched.  When bytes is not NULL it
 * receives the mission file (caller frees). */
enum pipeline_status pipeline_solve(const struct cli_env *env, const char *path,
                                    struct solve_result *r, FILE *err,
                                    unsigned char **bytes, size_t *n_bytes);

/* Compile path into out_dir/<name>/{result.json,bom.csv,bom_totals.csv,
 * dossier.pdf}, for a buildable design also vehicle_components.json,
 * ardupilot.param and qgroundcontrol.params (formats/ardupilot.h), and,
 * when fp is not NULL or "", a stamp vouching for them with fingerprint fp
 * (the caller's digest of every input).  The name is checked before the
 * solve; a file-system problem is one line naming the path, PIPE_UNWRITTEN. */
enum pipeline_status pipeline_build(const struct cli_env *env,
                                    const struct pipeline_opts *o,
                                    const char *path, const char *fp, FILE *err);

/* 0 (feasible) or 1 (infeasible) when out_dir/name holds a whole set whose
 * stamp has fingerprint fp and whose files all have the SHA-256 the stamp
 * records; -1 otherwise, also when another build holds the folder (it is
 * never waited for) or anything is odd (pipeline_build() will say what).
 * Removes the folder's stale temporaries on the way. */
int pipeline_current(const struct pipeline_opts *o, const char *name, const char *fp);

/* Removes the stale temporaries of out_dir/name (fsfolder_clean()) unless
 * another build holds the folder; for a worker that was killed. */
void pipeline_clean(const struct pipeline_opts *o, const char *name);

/* The output folder name of a mission path; -1 when unsafe, -2 when longer
 * than FSOUT_NAME_MAX, -3 when the name is one of the table's files
 * (fsout_safe_name()). */
int pipeline_name(const char *path, char *out, size_t n);

/* pipeline_name(), and on refusal one line on err saying why, "PATH:
 * error: ...", before anything is solved or written. */
int pipeline_name_checked(const char *path, char *out, size_t n, FILE *err);

/* One file added to a mission's folder by pipeline_add(). */
struct pipeline_extra {
	const char *file;    /* PIPELINE_SENS_JSON or PIPELINE_SENS_PDF */
	const void *data;
	size_t n;
};

/* Adds (or replaces) the n_x files x in out_dir/name, keeping every other
 * file of the folder as it is, by the same rules as pipeline_build(): the
 * lock, the refusals (a link, a non-folder, a foreign file), one new set
 * swapped in whole.  A build's outputs and their stamp stay valid (the
 * mission stays up to date).  PIPE_FEASIBLE, or PIPE_UNWRITTEN after one
 * line on err. */
enum pipeline_status pipeline_add(const struct pipeline_opts *o, const char *name,
                                  const struct pipeline_extra *x, size_t n_x,
                                  FILE *err);

#endif
