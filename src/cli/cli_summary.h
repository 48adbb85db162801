/* cli_summary.h — `aeroeval summary DIR`, and the index `build` keeps.
 *
 * Both rebuild the design-space table (result/table_row.h) from every
 * DIR/<name>/result.json and write DIR/index.csv and DIR/index.json
 * (formats/index.h), each atomically and only when its bytes change, then
 * the stamp DIR/.aeroeval-index-stamp that vouches for both and for the
 * rows they were made from (cli_summary_stale()).  The
 * command also draws DIR/overview.pdf (pdf/index_pdf.h), which `build`
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

/* True when DIR's table is not what `summary` would write: index.csv or
 * index.json missing, damaged or older than a row (the stamp
 * DIR/.aeroeval-index-stamp, written last by every refresh, vouches for
 * neither them nor the rows there are), or what a killed writer of the
 * table left (a temporary, the lock file).  A build then refreshes the
 * table, which mends all of it.  Reads the mission stamps, not every
 * result.json: quick beside an up-to-date check. */
int cli_summary_stale(const char *dir);

#endif
