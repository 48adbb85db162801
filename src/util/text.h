/* text.h — small text helpers every reader shares: UTF-8 validation,
 * line:col of a byte offset, and the edit distance behind every
 * "did you mean" suggestion.
 * Who may include it: everyone.
 */
#ifndef AEROEVAL_TEXT_H
#define AEROEVAL_TEXT_H

#include <stddef.h>

/* Strings longer than this are "far" for text_distance(). */
#define TEXT_DISTANCE_MAX 64

/* Length in bytes of the valid UTF-8 sequence at s (at most left bytes),
 * or 0 when the bytes there are not valid UTF-8 (overlong forms,
 * surrogates and code points above U+10FFFF are invalid). */
size_t text_utf8_seq(const char *s, size_t left);

/* The code point of the valid UTF-8 sequence of seq bytes at s (seq from
 * text_utf8_seq(), > 0). */
unsigned long text_utf8_cp(const char *s, size_t seq);

/* True for a code point no text field may hold: the C0 controls
 * (U+0000-U+001F: ESC, CR, LF, ...), DEL, the C1 controls (U+0080-U+009F)
 * and the bidirectional controls (U+061C, U+200E, U+200F, U+202A-U+202E,
 * U+2066-U+2069), which make a name read differently from what it holds
 * (U+202E turns "exe.pdf" into "fdp.exe"). */
int text_is_control(unsigned long cp);

/* The value of the hexadecimal digit c (either case), or -1. */
int text_hex_digit(unsigned char c);

/* Length of a UTF-8 byte-order mark at the start of b[0..len), or 0. */
size_t text_bom(const char *b, size_t len);

/* Line and column (1-based; columns count characters, not bytes) of byte
 * offset off in buf[0..len) (off is clamped to len; a leading byte-order
 * mark takes no column). */
void text_line_col(const char *buf, size_t len, size_t off, int *line,
                   int *col);

/* Edit distance between a and b ignoring case, where insertions,
 * deletions, substitutions and swaps of two neighbours cost 1 (optimal
 * string alignment); strings longer than TEXT_DISTANCE_MAX count as far
 * ((size_t)-1 / 2). */
size_t text_distance(const char *a, const char *b);

/* The word of the NULL-terminated list closest to word by text_distance(),
 * when it is close enough to be a likely typo (about one edit per three
 * characters of word, at least one and at most three), else NULL.  The
 * rule behind every "did you mean" of the readers. */
const char *text_nearest(const char *word, const char *const *list);

/* "a, b, c" from the NULL-terminated list into buf (size n, always
 * NUL-terminated; cut short when it does not fit), for "allowed: ..." texts. */
void text_join(const char *const *list, char *buf, size_t n);

/* A copy of s in which every byte that is not part of valid UTF-8 is
 * replaced by U+FFFD, for text that must be UTF-8 (JSON) but comes from
 * outside (a file name).  Ownership: free(). */
char *text_utf8_copy(const char *s);

/* The edit budget text_nearest() allows for a word of len bytes. */
size_t text_typo_limit(size_t len);

/* True when s starts like a spreadsheet formula (=, +, - or @), which a
 * spreadsheet opening a CSV file would evaluate (CSV formula injection).
 * The readers refuse such text in the catalogue (json_in.h), and the
 * writers of CSV tables neutralise such cells of text they did not check. */
int text_is_formula(const char *s);

/* An error message into err[0..errlen) when the caller asked for one
 * (err NULL or errlen 0: nothing is written). */
void text_errf(char *err, size_t errlen, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
