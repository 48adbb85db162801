/* numfmt.h — exact, reproducible number text for result.json, bom.csv and
 * the dossier.
 *
 * Any module may include this.  Both functions use snprintf in the C locale
 * (aeroeval never calls setlocale), so the decimal point is always '.'.
 * Neither ever writes "nan", "inf" or "-0...": non-finite input is refused,
 * so NaN/Inf cannot reach an output file through them.
 */
#ifndef AEROEVAL_NUMFMT_H
#define AEROEVAL_NUMFMT_H

#include <stddef.h>

/* Size that numfmt_shortest needs: "-1.2345678901234567e-308" is 24 bytes. */
#define NUMFMT_SHORTEST_LEN 32

/* Writes into buf the shortest of %.15g, %.16g and %.17g whose strtod()
 * gives back exactly x, so a JSON reader recovers the same double and two
 * runs print the same bytes.  %.17g always round-trips, so one is found.
 * Negative zero prints as "0" (the sign of a zero means nothing in our
 * outputs).  Exponent forms such as "1e-05" and "1.5e+20" are valid JSON.
 * Returns the length written (> 0), or 0 when x is NaN or infinite: then
 * buf holds "" and the caller must report the value as an internal error. */
int numfmt_shortest(char buf[NUMFMT_SHORTEST_LEN], double x);

/* Writes x with exactly `decimals` digits after the point (%.*f, decimals
 * clamped to 0..17) into buf of size n, for tables meant for people.  A
 * value that rounds to zero prints without a sign ("0.00", never "-0.00").
 * Returns the length written (> 0), or 0 when x is not finite or the text
 * does not fit in n bytes: then buf holds "" (if n > 0). */
int numfmt_fixed(char *buf, size_t n, double x, int decimals);

/* Writes x with `sig` significant digits (1..6) in plain notation, never
 * an exponent ("1974", "13.2", "0.0588"; a large value keeps all its
 * integer digits), for sentences meant for people.  "—" (U+2014) when x
 * is not finite.  Returns buf. */
const char *numfmt_sig(char *buf, size_t n, double x, int sig);

#endif
