/* index.h — the design-space table as index.csv and index.json.
 *
 * One row per compiled mission (result/table_row.h), in the order the caller
 * gives them (table_row_sort(): by name).  The same rows give the same bytes:
 * no date, no path, no machine name, so a sharded build and a single one
 * produce identical files.
 *
 * index.csv (RFC 4180, CRLF after every record, like bom.csv), header: the
 * name and verdict, the mission as asked, then the design of record:
 *   name,status,role,rotors,coaxial,wheelbase_m,airframe_class,
 *   battery_chemistry,altitude_m,ambient_temp_c,t_hover_s,t_forward_s,
 *   t_climb_s,payload_kg,max_payload_kg,takeoff_mass_kg,
 *   mtow_interval_level,mtow_lo_kg,mtow_hi_kg,flight_time_s,
 *   hover_endurance_s,cost_usd,unpriced_lines,cells,capacity_mah,motor,
 *   propeller,battery,tightest_check,tightest_margin
 * so a study plots any result against any input without joining the
 * mission files in.  The inputs are the fully defaulted mission's (what
 * the design was sized for: payload_role.type, num_rotors, coaxial_layout,
 * max_diameter_m, ..., max_payload_kg or payload_kg when it is 0).
 * Masses in kg with 3 decimals, the wheelbase in m with 3, altitude in m
 * with 0, ambient in degC with 2, times in s with 0, cost in USD with 2,
 * capacity in mAh with 0, the margin (a fraction of its limit, negative
 * when the check fails) with 3; coaxial is true or false; an unknown value
 * is an empty cell.  status is "feasible", "infeasible" or "not
 * buildable".  A text cell that starts like a spreadsheet formula (= + - @:
 * a mission file may be called "-x.json") gets a leading apostrophe, so a
 * spreadsheet shows it as text instead of evaluating it.
 *
 * index.json: {"aeroeval_version", "counts": {"feasible", "infeasible",
 * "not_buildable"}, "missions": [{"name", "status", "role", "rotors",
 * "coaxial", "wheelbase_m", "airframe_class", "battery_chemistry",
 * "altitude_m", "ambient_temp_c", "t_hover_s", "t_forward_s", "t_climb_s",
 * "payload_kg", "max_payload_kg", "takeoff_mass_kg",
 * "mtow_interval": {"level", "lo_kg", "hi_kg"} or null,
 * "flight_time_s", "hover_endurance_s", "cost_usd", "unpriced_lines",
 * "cell_count", "battery_capacity_mah", "motor", "propeller", "battery",
 * "tightest_check": {"name", "margin"} or null}]}; unknown values are
 * null, numbers exact (numfmt_shortest), text as read.
 *
 * Formats layer: renders text, writes no file.
 */
#ifndef AEROEVAL_INDEX_H
#define AEROEVAL_INDEX_H

#include "result/table_row.h"

/* The files the design-space table puts beside the mission folders of an
 * output folder (index.csv, index.json, overview.pdf), NULL-ended.  They
 * are the program's: no mission may be named after one (fsout_safe_name()),
 * and a build that reads missions from its own output folder skips them. */
extern const char *const index_file_names[];

/* index.csv of the rows.  Ownership: free(). */
char *index_csv(const struct table_rows *s);

/* index.json of the rows, naming the writer's version.  Ownership: free(). */
char *index_json(const struct table_rows *s, const char *aeroeval_version);

#endif
