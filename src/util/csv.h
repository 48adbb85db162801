/* csv.h — an RFC 4180 CSV reader over a buffer in memory, and the field
 * and record writer of the tables aeroeval writes (bom.csv,
 * bom_totals.csv, index.csv).
 *
 * For input modules (cohort.c); it knows nothing about what the columns
 * mean.  Accepted: fields quoted with '"' holding commas, doubled quotes
 * ("") and line breaks; records ended by LF or CRLF; a UTF-8 byte order mark
 * at the start (skipped); a last record with or without a line end.  Lines
 * that are completely empty are skipped (they are not records).  Fields are
 * not trimmed: spaces are data, as RFC 4180 says.  A lone CR that is not
 * followed by LF is ordinary data.
 *
 * A malformed record (an unterminated quote, a quote inside an unquoted
 * field, text after a closing quote, a NUL byte) is reported with the line
 * on which it starts, and reading resumes on the next line, so one bad row
 * never hides the rows after it.
 *
 * Usage:
 *	struct csv_reader r;
 *	struct csv_record rec;
 *	csv_init(&r, buf, n);
 *	while ((st = csv_next(&r, &rec, err, sizeof err)) != CSV_EOF)
 *		if (st == CSV_RECORD) use rec.fields[0..rec.n_fields);
 *		else report "file:rec.line: error: err";
 *	csv_free(&r);
 */
#ifndef AEROEVAL_CSV_H
#define AEROEVAL_CSV_H

#include <stdbool.h>
#include <stddef.h>

#include "util/strbuf.h"

/* Reader state.  The fields are private: use csv_next. */
struct csv_reader {
	const char *p;          /* next unread byte */
	const char *end;        /* one past the last byte of the buffer */
	size_t line;            /* 1-based physical line of p */
	struct strbuf text;     /* the current record's fields, each NUL-ended */
	size_t *offs;           /* start of field i in text.data */
	const char **fields;    /* field pointers handed out in csv_record */
	size_t cap_fields;      /* entries allocated in offs and fields */
};

/* One record.  Borrowed from the reader: valid until the next csv_next or
 * csv_free.  Fields are NUL-terminated, with quotes removed and "" undone. */
struct csv_record {
	const char *const *fields; /* n_fields strings */
	size_t n_fields;           /* >= 1 for a record */
	size_t line;               /* 1-based line on which the record starts */
};

enum csv_status {
	CSV_MALFORMED = -1, /* bad record skipped; err and rec->line say why/where */
	CSV_EOF = 0,        /* no more records; rec is untouched */
	CSV_RECORD = 1      /* rec holds the next record */
};

/* Starts reading buf[0..n).  buf is borrowed and must outlive the reader;
 * it need not be NUL-terminated.  Allocates nothing yet. */
void csv_init(struct csv_reader *r, const char *buf, size_t n);

/* Reads the next record into rec.  On CSV_MALFORMED, err (size errlen)
 * holds a message without position ("unterminated quoted field") and
 * rec->line the line on which the bad record starts; rec->n_fields is 0. */
enum csv_status csv_next(struct csv_reader *r, struct csv_record *rec,
                         char *err, size_t errlen);

/* Releases what the reader allocated.  NULL is a no-op. */
void csv_free(struct csv_reader *r);

/* ---- writing ------------------------------------------------------------- */

/* Appends s as one RFC 4180 field: as it is, or in double quotes (an inner
 * quote doubled) when it holds a comma, a double quote, CR or LF.  The
 * caller writes the separators (",") and record ends ("\r\n"). */
void csv_write_field(struct strbuf *sb, const char *s);

/* A record being written into sb, for the tables aeroeval writes (bom.csv,
 * bom_totals.csv, index.csv): fields with their separators, CRLF after the
 * record as RFC 4180 says (after the last one too).
 *	struct csv_out o = { &sb, 0 };
 *	csv_out_field(&o, "a"); csv_out_num(&o, true, 1.25, 2); csv_out_end(&o); */
struct csv_out {
	struct strbuf *sb;  /* the text */
	int n;              /* fields written in the current record */
};

/* One field (csv_write_field), after a ',' unless it opens the record. */
void csv_out_field(struct csv_out *o, const char *s);

/* x with `decimals` digits after the point, never "-0.0" (numfmt_fixed);
 * an empty field when !known.  Returns false, leaving the field empty,
 * when x is known but not finite: the caller counts that as an error. */
bool csv_out_num(struct csv_out *o, bool known, double x, int decimals);

/* Ends the record with CRLF. */
void csv_out_end(struct csv_out *o);

#endif
