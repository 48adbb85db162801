/* diag.h — compiler-style diagnostics, accumulated in a context.
 *
 * Every user-input problem is reported through diag_report() into a struct
 * diag, which counts errors and buffers the text, so that a whole file can be
 * checked in one pass (STYLE rule 10) and the lines of one mission leave in a
 * single write even when missions are compiled in parallel processes.
 * Line format (README.md, "Commands"):
 *
 *     file:line:col: error: field.path: summary detail
 *
 * `:line:col` is left out when the position is unknown, `field.path: ` when
 * the problem is not about one field.  The summary comes from the message
 * table DIAG_KINDS; the caller's detail (printf-style) is appended verbatim,
 * so it starts with its own separator (": ", " (", "; ").
 *
 * Who may include it: the input and command layers.  No globals: one struct
 * diag per mission (or per command), owned by its caller.
 */
#ifndef AEROEVAL_DIAG_H
#define AEROEVAL_DIAG_H

#include <stdarg.h>
#include <stdio.h>

enum diag_severity {
	DIAG_NOTE,    /* extra context for the error before it */
	DIAG_ERROR    /* the input is rejected */
};

/*
 * DIAG_KINDS(X): X(ID, severity, exit status, "summary")
 * The exit status is what the kind makes the program return (README.md:
 * 2 bad input, 3 internal error); notes do not change it (0).
 */
#define DIAG_KINDS(X) \
X(IO,           DIAG_ERROR, 2, "cannot read file") \
X(SYNTAX,       DIAG_ERROR, 2, "malformed JSON") \
X(TRAILING,     DIAG_ERROR, 2, "unexpected text after the JSON value") \
X(TOP_LEVEL,    DIAG_ERROR, 2, "the top level must be an object") \
X(UNKNOWN,      DIAG_ERROR, 2, "unknown field") \
X(DUPLICATE,    DIAG_ERROR, 2, "duplicate field") \
X(FIRST_HERE,   DIAG_NOTE,  0, "first given here") \
X(TYPE,         DIAG_ERROR, 2, "wrong type") \
X(NOT_INTEGER,  DIAG_ERROR, 2, "must be an integer") \
X(RANGE,        DIAG_ERROR, 2, "out of range") \
X(OVERFLOW,     DIAG_ERROR, 2, "number out of range of a double") \
X(BAD_ENUM,     DIAG_ERROR, 2, "unknown value") \
X(BAD_CHEMISTRY, DIAG_ERROR, 2, "unknown battery chemistry") \
X(TOO_LONG,     DIAG_ERROR, 2, "string too long") \
X(BAD_UTF8,     DIAG_ERROR, 2, "string is not valid UTF-8") \
X(NUL_IN_STRING, DIAG_ERROR, 2, "string contains a NUL character") \
X(BAD_DATE,     DIAG_ERROR, 2, "invalid date") \
X(MISSING,      DIAG_ERROR, 2, "missing field") \
X(MISSING_ENTRY, DIAG_ERROR, 2, "missing entry") \
X(CONTROL_CHAR, DIAG_ERROR, 2, "string contains a control character") \
X(FORMULA,      DIAG_ERROR, 2, "text starts like a spreadsheet formula") \
X(INCONSISTENT, DIAG_ERROR, 2, "inconsistent values") \
X(BAD_ID,       DIAG_ERROR, 2, "invalid id") \
X(DUPLICATE_ID, DIAG_ERROR, 2, "duplicate id") \
X(TOO_MANY,     DIAG_ERROR, 2, "too many entries") \
X(BAD_FONT,     DIAG_ERROR, 2, "not a usable TrueType font") \
X(BAD_IMAGE,    DIAG_ERROR, 2, "not a usable PNG image") \
X(NO_INPUT,     DIAG_ERROR, 2, "nothing to read") \
X(MORE,         DIAG_NOTE,  0, "more errors not shown") \
X(INTERNAL,     DIAG_ERROR, 3, "internal error")

enum diag_kind {
#define DIAG_X_ENUM(id, sev, status, text) DIAG_##id,
	DIAG_KINDS(DIAG_X_ENUM)
#undef DIAG_X_ENUM
	DIAG_MAX
};

/* Where a diagnostic points.  line == 0: no position (whole file). */
struct diag_loc {
	const char *file;  /* file name as the user gave it */
	int line;          /* 1-based line, 0 = unknown */
	int col;           /* 1-based column in characters */
};

struct diag;

/* A diagnostics context writing to out (stderr in the program) on
 * diag_flush(); out may be NULL to keep the text only (tests).
 * Ownership: free with diag_free(). */
struct diag *diag_alloc(FILE *out);
void diag_free(struct diag *dg);   /* NULL is a no-op */

/* Record one diagnostic.  path may be NULL or "" (no field), fmt may be NULL
 * (summary only).  Unprintable bytes and invalid UTF-8 in path are escaped. */
void diag_report(struct diag *dg, enum diag_kind kind,
                 const struct diag_loc *loc, const char *path,
                 const char *fmt, ...)
	__attribute__((format(printf, 5, 6)));

/* The same with a va_list (consumed), for wrappers such as json_in. */
void diag_vreport(struct diag *dg, enum diag_kind kind,
                  const struct diag_loc *loc, const char *path,
                  const char *fmt, va_list ap)
	__attribute__((format(printf, 5, 0)));

/* Count one diagnostic of this kind without recording its text: for a
 * reader that shows only the first errors of a file (json_in.h).  The error
 * count and the exit status change as if it had been reported. */
void diag_count(struct diag *dg, enum diag_kind kind);

/* Write the buffered lines to out in one write, then forget them. */
void diag_flush(struct diag *dg);

/* The buffered, not yet flushed text ("" when none).  Valid until the next
 * diag_report/diag_flush/diag_free. */
const char *diag_text(const struct diag *dg);

/* Errors reported so far (notes not counted; flushing does not reset). */
int diag_n_errors(const struct diag *dg);

/* Raise the exit status to at least status (e.g. 1 for an infeasible
 * design); it never goes down. */
void diag_raise_status(struct diag *dg, int status);

/* Exit status for the program: the worst status seen, 0 when clean. */
int diag_exit_status(const struct diag *dg);

/* Write s[0..len) as a double-quoted, printable string into out (size n,
 * always NUL-terminated): control bytes, '"', '\\' and invalid UTF-8 are
 * escaped (\xNN), and text beyond max_chars characters becomes "...".
 * For quoting user input inside a message. */
void diag_quote(const char *s, size_t len, size_t max_chars, char *out,
                size_t n);

/* "error" / "note". */
const char *diag_severity_name(enum diag_severity sev);

/* Severity of a kind, from the table. */
enum diag_severity diag_kind_severity(enum diag_kind kind);

#endif /* AEROEVAL_DIAG_H */
