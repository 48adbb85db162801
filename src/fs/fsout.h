/* fsout.h — file output that never loses the previous good file, plus the
 * small filesystem helpers the compiler needs around it.
 *
 * For the CLI and fsfolder.c; the formats and the PDF return bytes and
 * never include this, nor do the physics modules.  Every function returns
 * 0 on success and -1 on failure; on failure err (if errlen > 0) holds one
 * line without a trailing newline, of the form "PATH: what failed:
 * strerror", ready to be prefixed with "error: " by the caller.  Nothing
 * here prints.
 *
 * Test hooks, compiled into test builds only (-DAEROEVAL_TEST_HOOKS; the
 * program `make` installs has none): with AEROEVAL_FAIL_WRITE=N in the
 * environment, the N-th file
 * write of the process (counting from 1: fsout_write_atomic() and
 * fsfolder_put() calls) writes part of its temporary file and then fails as
 * if the disk were full (ENOSPC), or with the error NAME of N:NAME (ENOSPC,
 * EIO, EDQUOT, EROFS, EFBIG), so tests can prove that the previous output
 * survives and no temporary file is left behind.  AEROEVAL_TEST_WRITE_DELAY_MS=T
 * makes fsfolder sleep T ms before each file, before the swap and between
 * the two renames of the fallback swap, so a test can signal or kill a
 * build at each of those moments; AEROEVAL_TEST_NO_EXCHANGE (any value)
 * makes fsfolder swap by two renames, as where renameat2 is missing.
 */
#ifndef AEROEVAL_FSOUT_H
#define AEROEVAL_FSOUT_H

#include <stddef.h>

/* Writes data[0..n) to path so that, whatever happens, path holds either its
 * previous content or the complete new content, never a truncated mix.
 * Only a regular file is replaced: an existing link (never followed),
 * folder, device or FIFO at path is an error before anything is written.
 * A temporary file ".NAME.tmp.PID.SEQ" is created in the same directory
 * (O_EXCL, mode 0644), written, fsync'ed, renamed over path, and then the
 * directory is fsync'ed so the rename itself is durable.  On any failure the
 * temporary file is removed and path is untouched.  The directory must
 * exist (see fsout_mkdirs).  Safe to call from several threads at once. */
int fsout_write_atomic(const char *path, const void *data, size_t n,
                       char *err, size_t errlen);

/* Creates dir and any missing parents (mkdir -p, mode 0755).  An existing
 * directory is success; an existing non-directory is an error. */
int fsout_mkdirs(const char *dir, char *err, size_t errlen);


/* Where fsout_resolve_date found the date (never a file time: touching a
 * mission changes no output byte). */
enum fsout_date_source {
	FSOUT_DATE_REPORT,      /* the mission's report.date */
	FSOUT_DATE_EPOCH_ENV,   /* the SOURCE_DATE_EPOCH environment variable */
	FSOUT_DATE_NONE         /* neither: the dossier is undated */
};

/* The dossier date as "YYYY-MM-DD" (UTC) in out: report_date if it is not
 * "" (it must be a real calendar date written YYYY-MM-DD), else
 * SOURCE_DATE_EPOCH if set and not empty (decimal seconds since
 * 1970-01-01T00:00:00Z, digits only, at most year 9999), else none (out =
 * "": the dossier says "undated" and carries no PDF date).  Nothing here
 * reads a file time or the clock: the same inputs give the same dossier
 * whatever the file times.  A set but invalid report_date or
 * SOURCE_DATE_EPOCH is an error, not a reason to fall through, so a typo
 * cannot silently change the date.  Returns the enum fsout_date_source used
 * (>= 0), or -1 with err set. */
int fsout_resolve_date(const char *report_date, char out[11], char *err, size_t errlen);

/* Longest output folder name: with ".NAME.tmp.PID.SEQ" (fsfolder.h) it
 * still fits the 255 bytes a file name may have. */
#define FSOUT_NAME_MAX 200

/* The output folder name for a mission file: its base name (after the last
 * '/') without a final ".json".  Rejected (-1, out = "") when that is empty,
 * starts with '.' (hidden names are the program's: temporaries, locks,
 * stamps; "." and ".." with them), or contains a byte outside
 * [A-Za-z0-9._-], so the name is always one harmless path component and a
 * write under DIR/<name>/ cannot leave DIR; -2 (out = "") when it is longer
 * than FSOUT_NAME_MAX bytes or does not fit in n; -3 (out = "") when it is
 * one of the files of the design-space table beside the mission folders
 * (index_file_names: "index.csv.json" would name the folder index.csv).
 * "../../etc.json" gives "etc"; the directories of the mission path never
 * reach the output path. */
int fsout_safe_name(const char *mission_path, char *out, size_t n);

/* Test support only: restarts the AEROEVAL_FAIL_WRITE count at zero so a
 * test program can inject a failure into a chosen later write. */
void fsout_fault_reset(void);

#endif
