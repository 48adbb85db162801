/* cli_help.h — the text of `aeroeval --help`, `aeroeval help CMD`,
 * `aeroeval CMD --help` and `aeroeval --version`.
 *
 * One table holds every command's synopsis, one-line summary and options,
 * so the overview and the per-command pages cannot disagree.  The man page
 * (src/aeroeval.1) says the same at length.  CLI layer; prints only.
 */
#ifndef AEROEVAL_CLI_HELP_H
#define AEROEVAL_CLI_HELP_H

#include <stdio.h>

/* Every command in one line each, and where to read more. */
void cli_help_overview(FILE *out);

/* The synopsis, summary and options of one command.  Returns 0, or -1
 * (printing nothing) when cmd is not an aeroeval command.  With out NULL it
 * only tells whether cmd is one. */
int cli_help_command(const char *cmd, FILE *out);

/* "aeroeval VERSION" and one line on what it is. */
void cli_help_version(FILE *out);

#endif
