/* validate.h — accuracy against real aircraft: cohort row -> mission, one
 * solve per row, and the statistics of predicted vs actual takeoff mass.
 *
 * For the `validate` and `calibrate` commands (cli_validate.c,
 * cli_calibrate.c, and the fit in study/calibrate.c).
 * Engine layer plus stats: no JSON, PDF or printing here.
 *
 * THE MISSION RULE (validate_mission_from_row), applied identically to every
 * row and using only the row's own facts — never takeoff_mass_kg,
 * empty_mass_kg, battery_mass_kg or anything derived from them:
 *   payload     payload_kg (integrated-camera aircraft say 0); unknown ->
 *               row skipped.  A takeoff figure is the aircraft plus what it
 *               carries: without that fact the row cannot be predicted (a
 *               rated maximum takeoff mass with 0 kg of payload would only
 *               measure the missing payload), no other fact bounds it, and
 *               empty_mass_kg is off limits (takeoff minus empty is the
 *               answer).
 *   load case   max_payload_kg, when the row gives one above payload_kg:
 *               motors, ESCs, propellers and structure are built for it
 *               (mission field max_payload_kg); the endurance is flown with
 *               payload_kg, the row's load state.
 *   rotors      rotor_count; unknown -> row skipped (a guess between 4, 6
 *               and 8 would change the prediction by tens of percent).
 *   coaxial     coaxial; unknown -> flat (noted): coaxial aircraft are the
 *               exception and cohort rows say so when they are.
 *   class       airframe_class; unknown -> row skipped.
 *   role        role -> payload_role.type; unknown -> "none" (noted).
 *   shedding    off (payload_role.mass_shedding = false) for the roles that
 *               shed (delivery, agriculture): a published endurance is
 *               flown at one takeoff mass, the load on board throughout.
 *   wheelbase   diagonal_wheelbase_mm; else the smallest wheelbase whose
 *               overlap limit (paper eq. overlap, 5 % tip clearance) admits
 *               the row's propeller, W = D / ((1 - 0.05) sin(pi / N_arms))
 *               with N_arms = rotors (coaxial: rotors / 2) (noted); else
 *               skipped.
 *   propeller   diameter locked at prop_diameter_in when it fits the
 *               wheelbase's overlap limit (pitch = prop_pitch_in, else
 *               0.45 D, which only labels the design: pitch enters no mass);
 *               a propeller larger than the limit is not locked and the
 *               engine uses the limit, the nearest diameter the model
 *               admits (noted); unknown -> not locked (the engine's own
 *               choice, the largest the wheelbase admits).
 *   chemistry   battery_chemistry when it names a loaded profile (case
 *               ignored); the bare family "Li-ion" -> "Li-ion NMC" (of the
 *               two Li-ion profiles the lower specific energy: no fact
 *               picks one, so the conservative one) (noted); else LiHV, the
 *               engine's default (noted).
 *   packs       battery_pack_count; unknown -> 1.
 *   cells       cell_count -> nominal_cell_count (the bus voltage is a fact
 *               of the aircraft); unknown -> chosen by the solver.
 *   capacity    NOT locked (VALIDATE_FROM_ENDURANCE, the default): sizing
 *               the energy is what is being tested (the paper sizes it
 *               too).  Under VALIDATE_PACK_LOCKED (validate --pack), a row
 *               that publishes its pack (cell_count and capacity; packs
 *               from battery_pack_count, else 1) has it locked, as a user
 *               reproducing the aircraft would, and the endurance becomes
 *               a check: a payload-free aircraft of given geometry sized
 *               from its endurance alone is ill-posed (dry mass and
 *               battery both grow with M, the loop's slope at the real
 *               mass is near or above 1), so the two rules measure
 *               different things and both are reported (docs/validation.md).
 *   endurance   the maker's to-empty time brought to the engine's reserve
 *               convention (the engine sizes capacity as 1.2 x the charge
 *               the mission draws), flown as the maker flew it: a hover
 *               time as one hover phase of hover_time_min / 1.2; else a
 *               maximum flight time as one level-flight phase of
 *               max_flight_time_min / 1.2 at cruise_speed_ms, else at the
 *               minimum-power speed ("auto") (noted); else skipped.
 * Everything else keeps the mission defaults (sea level, ISA, role and
 * class defaults).  The prediction is the custom run's takeoff mass.
 */
#ifndef AEROEVAL_VALIDATE_H
#define AEROEVAL_VALIDATE_H

#include <stdbool.h>
#include <stddef.h>

#include "input/cohort.h"
#include "spec/model.h"
#include "result/result.h"
#include "spec/spec.h"
#include "util/stats.h"

#define VALIDATE_PITCH_RATIO     0.45  /* pitch/diameter when only D is known */
#define VALIDATE_BOOT_RESAMPLES  2000  /* bootstrap resamples of the MAPE CI */
#define VALIDATE_BOOT_SEED       20261122u /* fixed: the CI is reproducible */

/* Stand-ins the rule used for a row (bit flags, validate_note_text). */
enum validate_note {
	VALIDATE_NOTE_WHEELBASE_PROP = 1u << 0, /* wheelbase from the prop overlap */
	VALIDATE_NOTE_PROP_OVER      = 1u << 1, /* prop above the overlap limit, not locked */
	VALIDATE_NOTE_CHEM_FAMILY    = 1u << 2, /* "Li-ion" -> "Li-ion NMC" */
	VALIDATE_NOTE_CHEM_DEFAULT   = 1u << 3, /* chemistry unknown -> LiHV */
	VALIDATE_NOTE_COAX_DEFAULT   = 1u << 4, /* coaxial unknown -> flat */
	VALIDATE_NOTE_ROLE_DEFAULT   = 1u << 5, /* role unknown -> none */
	VALIDATE_NOTE_MAX_FLIGHT     = 1u << 6, /* endurance from the max flight time */
	VALIDATE_NOTE_PACK_LOCKED    = 1u << 7, /* the published pack locked */
	VALIDATE_NOTE_COUNT          = 8
};

/* Why a row was skipped. */
enum validate_skip {
	VALIDATE_SKIP_NONE,        /* not skipped */
	VALIDATE_SKIP_PAYLOAD,     /* payload of the takeoff figure unknown */
	VALIDATE_SKIP_ROTORS,      /* rotor count unknown */
	VALIDATE_SKIP_CLASS,       /* airframe class unknown */
	VALIDATE_SKIP_WHEELBASE,   /* neither wheelbase nor propeller known */
	VALIDATE_SKIP_ENDURANCE,   /* neither hover time nor max flight time */
	VALIDATE_SKIP_RANGE,       /* a fact outside the mission contract's range */
	VALIDATE_SKIP_MAX
};

/* Outcome of one row. */
enum validate_status {
	VALIDATE_ROW_SKIPPED,      /* the rule had no mission for it */
	VALIDATE_ROW_OK,           /* converged: counts in the statistics */
	VALIDATE_ROW_NOT_CONVERGED,/* ran, mass loop did not converge: listed apart */
	VALIDATE_ROW_NOT_RUN,      /* rejected by the feasibility gate or an internal error */
	VALIDATE_ROW_STATUS_MAX
};

/* The one-line text of a single note flag ("role unknown: none"), or "". */
const char *validate_note_text(unsigned note);

/* The text of a skip reason ("rotor count unknown"), "" for NONE. */
const char *validate_skip_text(enum validate_skip s);

/* The status word ("ok", "skipped", "not converged", "not run"). */
const char *validate_status_text(enum validate_status s);

/* Which fact of a row put a mission field outside the contract's range
 * (VALIDATE_SKIP_RANGE). */
struct validate_fact {
	const char *column;        /* the cohort column ("rotor_count"), NULL if none */
	double value;              /* its value in the row */
	enum spec_field field;     /* the mission field it sets */
	double field_value;        /* the value the field would take */
};

/* "hover_time_min 900 gives t_hover_s 45000, outside the mission
 * contract's range (0 to 36000 s)" into buf. */
void validate_fact_text(const struct validate_fact *f, char *buf, size_t n);

/* Which battery the rule gives a row (see "capacity" above). */
enum validate_rule {
	VALIDATE_FROM_ENDURANCE,   /* capacity sized from the endurance */
	VALIDATE_PACK_LOCKED,      /* the published pack locked where given */
	VALIDATE_RULE_MAX
};

/* Builds the mission for a row by the rule above into *out (every field it
 * sets is marked given[]).  md supplies the chemistry names.  *notes gets
 * the OR of the enum validate_note flags used.  Returns VALIDATE_SKIP_NONE,
 * or the reason the row has no mission (then *out holds the defaults). */
enum validate_skip validate_mission_from_row(const struct cohort_row *row,
                                             const struct model_data *md,
                                             struct mission_spec *out,
                                             unsigned *notes);

/* The same, naming in *fact (may be NULL) the fact behind a
 * VALIDATE_SKIP_RANGE. */
enum validate_skip validate_mission_explained(const struct cohort_row *row,
                                              const struct model_data *md,
                                              enum validate_rule rule,
                                              struct mission_spec *out,
                                              unsigned *notes,
                                              struct validate_fact *fact);

/* THE FORWARD CHECK (validate_forward()): the aircraft a row describes,
 * its published pack locked (the VALIDATE_PACK_LOCKED mission), flown at
 * its published takeoff mass as makers quote a flight time: to an empty
 * pack, without the mission's reserve, in hover for the hover time and in
 * level flight at the published cruise speed (else the minimum-power
 * speed) for the maximum flight time (engine_endurance_at_mass()).  An
 * unlocked propeller is the largest the wheelbase admits.  Racing rows
 * are left out: their flight times are flown at race throttle, neither in
 * hover nor at a stated speed. */
struct validate_forward {
	bool valid;                /* the row has a pack, a time and is no racer,
	                              and the model flew it */
	double hover_model_s, hover_pub_s;   /* 0 when not published */
	double max_model_s, max_pub_s;       /* 0 when not published */
	double speed_ms;           /* the level flight's speed */
};

/* The forward check of a row; pack_spec is its VALIDATE_PACK_LOCKED
 * mission (battery locked, else the check is not valid). */
void validate_forward(const struct cohort_row *row, const struct mission_spec *pack_spec,
                      const struct model_data *md, struct validate_forward *out);

/* One row's result. */
struct validate_row {
	size_t index;              /* row in the cohort */
	enum validate_status status;
	enum validate_skip skip;   /* when status is SKIPPED */
	struct validate_fact fact; /* when skip is VALIDATE_SKIP_RANGE */
	unsigned notes;            /* enum validate_note flags */
	struct mission_spec spec;  /* the mission the rule built (unresolved) */
	double actual_kg;          /* takeoff_mass_kg */
	double predicted_kg;       /* custom-run MTOW; 0 unless OK or NOT_CONVERGED */
	double err_pct;            /* 100 (pred - actual) / actual; 0 unless OK */
	double k;                  /* actual / predicted; 0 unless OK */
	bool feasible;             /* every check of the custom run passed */
	bool has_battery;          /* status OK and the row gives battery_mass_kg */
	double battery_actual_kg;
	double battery_pred_kg;
	double battery_err_pct;
	bool inside;               /* actual inside the shipped interval (OK rows) */
	double slope_at_real;      /* dF/dM of the model at the real takeoff mass
	                            * (open loop, capacity re-sized at each side);
	                            * >= 1: the real aircraft is no stable fixed
	                            * point of the model, 0 when not evaluated */
	int cells;                 /* series cells of the design (0 unless run) */
	double lipschitz;          /* its loop's dF/dM at the fixed point */
	struct validate_forward forward; /* the forward check (any rule) */
	double dry_pred_kg;        /* its mass less payload and battery */
	double capacity_mah;       /* capacity of the design (0 unless run) */
	double thrust_to_weight;   /* T/W the design flies (0 unless run) */
};

/* The whole validation. */
struct validate_report {
	size_t n_rows;             /* = cohort rows */
	struct validate_row *rows; /* n_rows, cohort order */
	size_t n_ok;               /* rows in the statistics */
	struct stats_summary mtow; /* over the OK rows */
	double ci_lo_pct;          /* bootstrap 95 % CI of the MAPE */
	double ci_hi_pct;
	struct stats_group *by_class; /* MAPE per airframe class name */
	size_t n_classes;
	struct stats_summary battery; /* over the OK rows with battery_mass_kg */
	enum validate_rule rule;   /* the rule the missions were built by */
	/* Open loop: the model at each aircraft's real takeoff mass, over the
	 * rows with a published battery mass (dry = takeoff - payload - battery). */
	size_t n_open;
	double open_dry_mape_pct;
	double open_battery_mape_pct;
	/* The forward check over the rows it applies to: the MAPE of the
	 * model's endurance against every published figure (hover and
	 * maximum flight times). */
	size_t n_forward_rows;
	size_t n_forward_figures;
	double forward_mape_pct;
	/* The shipped calibration's prediction interval for this rule: the OK
	 * rows whose actual mass lies inside it. */
	bool has_interval;
	double interval_level;
	size_t n_inside;
};

/* Solves one mission and fills the prediction fields of *vr (status,
 * predicted_kg, feasible, cells, capacity) from the custom run.  work is a
 * caller-owned scratch result (large: keep one per thread). */
void validate_solve_row(const struct mission_spec *spec, const struct model_data *md,
                        struct solve_result *work, struct validate_row *vr);

/* Runs the rule and a solve on every row of c and the statistics over the
 * converged rows.  Returns 0, or -1 if a statistic refused its input (cannot
 * happen for finite positive masses).  Release with validate_report_free. */
int validate_cohort(const struct cohort *c, const struct model_data *md,
                    enum validate_rule rule, struct validate_report *out);

void validate_report_free(struct validate_report *v);

/* The statistics part of validate_cohort: from v->rows (status, actual_kg,
 * predicted_kg, has_battery and the battery masses) fills n_ok, mtow,
 * the CI, by_class (keys from c's rows) and battery, replacing what was
 * there.  Returns 0, or -1 if a statistic refused its input. */
int validate_summarize(const struct cohort *c, struct validate_report *v);

/* The group key of a row for the per-class statistics ("MicroAIO", ...). */
const char *validate_class_key(const struct cohort_row *row);

#endif
