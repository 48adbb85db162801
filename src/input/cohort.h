/* cohort.h — reader for real-aircraft cohort files (data/cohorts/README.md).
 *
 * For the `validate` and `calibrate` commands.  A cohort file is CSV with a
 * header line; columns may come in any order, unknown columns are ignored,
 * and an empty cell means "unknown" — never zero.  Every number therefore
 * comes with a has_ flag; when the flag is false the value is 0 (never NaN),
 * and text fields are "" (never NULL).
 *
 * A malformed row (bad number, unknown class or role, negative mass, wrong
 * number of cells, broken quoting, text that is not valid UTF-8 or holds a
 * control character) is reported as
 *	FILE:LINE: error: COLUMN: message
 * and left out, while the other rows are kept.  Row-level problems use the
 * column name "row".  Nothing here prints: messages are collected in
 * struct cohort for the caller to print.
 */
#ifndef AEROEVAL_COHORT_H
#define AEROEVAL_COHORT_H

#include <stdbool.h>
#include <stddef.h>

#include "spec/spec.h"

enum cohort_confidence {
	COHORT_CONF_HIGH,    /* "high" */
	COHORT_CONF_MEDIUM,  /* "medium" */
	COHORT_CONF_LOW,     /* "low" */
	COHORT_CONF_MAX
};

/* One aircraft.  Units as in the README table (the column names carry
 * them).  A has_X flag is true when the cell was not empty. */
struct cohort_row {
	size_t line;                      /* line in the file where the row starts */
	char *name;                       /* platform name, never empty */
	char *cohort;                     /* cohort label, "" if unknown */
	double takeoff_mass_kg;           /* the "actual" to predict, always > 0 */
	double empty_mass_kg;             /* with battery, without payload, > 0 */
	bool has_empty_mass_kg;
	double payload_kg;                /* carried beyond empty mass, >= 0 */
	bool has_payload_kg;
	double max_payload_kg;            /* largest payload the maker allows, >= 0 */
	bool has_max_payload_kg;
	int rotor_count;                  /* rotors (coaxial X8 = 8), >= 1 */
	bool has_rotor_count;
	bool coaxial;                     /* coaxial layout */
	bool has_coaxial;
	double diagonal_wheelbase_mm;     /* motor-to-motor diagonal W, > 0 */
	bool has_diagonal_wheelbase_mm;
	double prop_diameter_in;          /* propeller diameter, > 0 */
	bool has_prop_diameter_in;
	double prop_pitch_in;             /* propeller pitch, > 0 */
	bool has_prop_pitch_in;
	char *battery_chemistry;          /* chemistry profile name, "" if unknown */
	int cell_count;                   /* series cells per pack, >= 1 */
	bool has_cell_count;
	double battery_capacity_mah;      /* capacity of one pack, > 0 */
	bool has_battery_capacity_mah;
	int battery_pack_count;           /* packs carried, >= 1 */
	bool has_battery_pack_count;
	double battery_mass_kg;           /* all packs together, > 0 */
	bool has_battery_mass_kg;
	double hover_time_min;            /* manufacturer hover time, > 0 */
	bool has_hover_time_min;
	double max_flight_time_min;       /* advertised maximum flight time, > 0 */
	bool has_max_flight_time_min;
	double cruise_speed_ms;           /* > 0 */
	bool has_cruise_speed_ms;
	double max_speed_ms;              /* > 0 */
	bool has_max_speed_ms;
	enum airframe_class airframe_class; /* structural class (spec.h) */
	bool has_airframe_class;
	enum role_type role;              /* mission role, never ROLE_NONE when set */
	bool has_role;
	char *source;                     /* where the facts come from, "" if none */
	enum cohort_confidence confidence; /* how sure the facts are */
	bool has_confidence;
	char *notes;                      /* free text, "" if none */
};

/* A parsed file: the good rows in file order and one message per problem. */
struct cohort {
	struct cohort_row *rows;  /* n_rows rows */
	size_t n_rows;
	char **errors;            /* n_errors lines "FILE:LINE: error: COLUMN: msg" */
	size_t n_errors;
};

/* Parses buf[0..n) (need not be NUL-terminated); file is the name used in
 * messages.  Fills *out, which the caller releases with cohort_free() in
 * every case.  Returns 0 when there was no error, -1 otherwise.  A header
 * without a `name` or `takeoff_mass_kg` column, a duplicated column, or an
 * empty file is an error that leaves no rows; a bad row is an error that
 * leaves the other rows in place. */
int cohort_parse(const char *file, const char *buf, size_t n, struct cohort *out);

/* Reads the file at path (at most 64 MiB) and parses it as above.  A file
 * that cannot be read gives one message "PATH: error: ..." and -1. */
int cohort_load(const char *path, struct cohort *out);

/* Releases everything in c and leaves it empty.  NULL is a no-op. */
void cohort_free(struct cohort *c);

/* The spelling of a confidence value ("high", ...), "" if out of range. */
const char *cohort_confidence_name(enum cohort_confidence c);

#endif
