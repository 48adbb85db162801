/* table_row.h — the design-space table: one row per compiled mission.
 *
 * `aeroeval summary DIR` and `build` (which keeps DIR/index.csv and
 * DIR/index.json current) read every DIR/<name>/result.json into a row
 * (input/table_in.h) and render the rows (formats/index.h).  The table is
 * rebuilt from the per-mission files each time, never updated in place, so
 * a partial or sharded build gives a correct partial table.
 *
 * Units are SI (kg, s) except where the name says otherwise (capacity_mah,
 * cost_usd).  An unknown value has its has_ flag false (or "" for text):
 * its cell stays empty.
 * Who may include it: everyone (plain values, no I/O).
 */
#ifndef AEROEVAL_TABLE_ROW_H
#define AEROEVAL_TABLE_ROW_H

#include <stdbool.h>
#include <stddef.h>

#define TABLE_ROW_NAME_MAX 256 /* bytes of a mission name, NUL included */
#define TABLE_ROW_TEXT_MAX 200 /* bytes of a part or check name, NUL included */
#define TABLE_ROW_WORD_MAX 64  /* bytes of a role, class or chemistry name */

/* The verdict of a row, worst last. */
enum table_row_status {
	TABLE_ROW_FEASIBLE,       /* every check of the design of record passes */
	TABLE_ROW_INFEASIBLE,     /* built on real parts, some check fails */
	TABLE_ROW_NOT_BUILDABLE,  /* no real parts close: the continuous design */
	TABLE_ROW_STATUS_MAX
};

/* One compiled mission. */
struct table_row {
	char name[TABLE_ROW_NAME_MAX];   /* output folder name */
	enum table_row_status status;

	/* The mission as asked, from result.json's fully defaulted "mission";
	 * has_inputs is false when the file lacks any of them (then every
	 * input cell is empty). */
	bool has_inputs;
	char role[TABLE_ROW_WORD_MAX];   /* payload_role.type: "imaging", ... */
	int rotors;                      /* num_rotors */
	bool coaxial;                    /* coaxial_layout */
	double wheelbase_m;              /* max_diameter_m */
	char airframe_class[TABLE_ROW_WORD_MAX];
	char chemistry[TABLE_ROW_WORD_MAX]; /* battery_chemistry */
	double altitude_m;
	double ambient_temp_c;
	double t_hover_s, t_forward_s, t_climb_s; /* the mission times asked */
	double max_payload_kg;           /* the largest payload it is built for
	                                    (max_payload_kg, 0 there = payload_kg) */

	/* The design of record. */
	double takeoff_mass_kg;          /* MTOW of record */
	bool has_interval;               /* result.json carries mtow_interval */
	double interval_level;           /* its nominal coverage, e.g. 0.9 */
	double mtow_lo_kg, mtow_hi_kg;   /* its bounds */
	double payload_kg;               /* payload at takeoff (an input) */
	bool has_flight_time;
	double flight_time_s;            /* the mission's approved flight time */
	bool has_endurance;
	double hover_endurance_s;        /* hover at takeoff mass to the reserve */
	bool has_cost;
	double cost_usd;                 /* sum of the known BOM prices */
	int unpriced_lines;              /* BOM lines to buy without a price */
	int cells;                       /* series cells, 0 unknown */
	double capacity_mah;             /* pack capacity, 0 unknown */
	char motor[TABLE_ROW_TEXT_MAX];  /* "maker part", "" without parts */
	char propeller[TABLE_ROW_TEXT_MAX];
	char battery[TABLE_ROW_TEXT_MAX];
	char tightest[TABLE_ROW_TEXT_MAX]; /* binding check, "" when none */
	double tightest_margin;          /* its margin (negative: it fails) */
};

/* A growable list of rows.  Plain value: = { 0 }, table_row_free(). */
struct table_rows {
	struct table_row *rows;
	size_t n, cap;
};

/* Appends a copy of row. */
void table_row_add(struct table_rows *s, const struct table_row *row);

/* Orders the rows by name (bytewise), the table's one order. */
void table_row_sort(struct table_rows *s);

/* Releases the rows; s is empty and reusable after.  NULL is a no-op. */
void table_row_free(struct table_rows *s);

/* "feasible", "infeasible", "not buildable". */
const char *table_row_status_name(enum table_row_status st);

/* Rows of each status, for the one-line report. */
void table_row_count(const struct table_rows *s, size_t count[TABLE_ROW_STATUS_MAX]);

#endif
