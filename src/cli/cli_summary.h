/* cli_summary.h — `aeroeval summary DIR`, and the index `build` keeps.
 *
 * Both rebuild the design-space table (core/summary.h) from every
 * DIR/<name>/result.json and write DIR/index.csv and DIR/index.json
 * (output/index.h), each atomically and only when its bytes change.  The
 * command also draws DIR/overview.pdf (output/index_pdf.h), which `build`
 * then keeps current too.  Builds of
 * several machines into one shared DIR take turns through a lock,
 * DIR/.aeroeval-index.lock, so the last one to finish writes a table that
 * holds everything finished before it.
 *
 * CLI layer.
 */
#ifndef AEROEVAL_CLI_SUMMARY_H
#define AEROEVAL_CLI_SUMMARY_H

#include <stdio.h>

/* The command; argv[0] is "summary".  Returns the exit status. */
int cli_summary(int argc, char **argv);

struct template;

/* For `build`: rewrites DIR/index.csv and DIR/index.json from the folders
 * of DIR, and DIR/overview.pdf with template tpl when `summary` drew one
 * there (tpl may be NULL: then it is left).  A result.json it cannot read
 * is left out of the table and reported to err.  Returns 0, or 2 (3) after
 * reporting to err when the table could not be written (rendered) or a
 * result.json was unreadable. */
int cli_summary_refresh(const char *dir, const struct template *tpl, FILE *err);

/* True when DIR has no index.csv yet, or holds what a killed writer of
 * the table left (a temporary, the lock file): an up-to-date build then
 * refreshes the table, which removes them. */
int cli_summary_stale(const char *dir);

#endif
