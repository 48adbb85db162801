/* pipeline.h — compile one mission: read, validate, solve, render, write.
 *
 * Everything a mission's outputs depend on is in its arguments (the shared
 * read-only environment and the mission path), so `build` can compile
 * missions in parallel.  Nothing is written unless the mission is valid,
 * and every file is written atomically (temp + rename): an interrupted or
 * failed compile never leaves a truncated file or destroys a good one.
 */
#ifndef AEROEVAL_PIPELINE_H
#define AEROEVAL_PIPELINE_H

#include <stddef.h>
#include <stdio.h>

#include "cli/cli.h"
#include "core/result.h"

struct template;

/* Outcome of one mission, as PRODUCT.md §2 exit statuses. */
enum pipeline_status {
	PIPE_FEASIBLE = 0,    /* compiled, every design feasible */
	PIPE_INFEASIBLE = 1,  /* compiled, outputs say why it is infeasible */
	PIPE_REJECTED = 2,    /* bad input: nothing written */
	PIPE_INTERNAL = 3     /* internal error: nothing (more) written */
};

struct pipeline_opts {
	const char *out_dir;          /* DIR of DIR/<name>/ */
	const struct template *tpl;   /* dossier template (NULL: no dossier) */
};

/* Solve the mission at path into *r (callers own r, large: allocate it).
 * Diagnostics are buffered and flushed in one write to err.  Returns the
 * status; on PIPE_REJECTED *r is untouched.  When bytes is not NULL it
 * receives the mission file (caller frees). */
enum pipeline_status pipeline_solve(const struct cli_env *env, const char *path,
                                    struct solve_result *r, FILE *err,
                                    unsigned char **bytes, size_t *n_bytes);

/* Compile path into out_dir/<name>/{result.json,bom.csv,dossier.pdf}. */
enum pipeline_status pipeline_build(const struct cli_env *env,
                                    const struct pipeline_opts *o,
                                    const char *path, FILE *err);

/* The output folder name of a mission path, or -1 when unsafe. */
int pipeline_name(const char *path, char *out, size_t n);

#endif
