/* discharge.h — the time-step discharge simulation (paper Module 4).
 *
 * Flies the mission segment by segment, as the role's duty plan lays it
 * out (duty.h: the paper's climb, forward and hover, or laps, passes and
 * turns, an out-leg and a return), with the Tremblay–Dessaint pack
 * (C-rate-scaled OCV, temperature- and age-dependent resistance, current
 * from the quadratic power balance), the transient pack temperature, and
 * the payload the plan sheds.  It stops early on
 * voltage collapse, power overflow, the terminal-voltage floor, an empty
 * pack or thermal runaway (60 °C), and says which.  The sampled trace is
 * what the dossier plots.
 */
#ifndef AEROEVAL_DISCHARGE_H
#define AEROEVAL_DISCHARGE_H

#include <stdbool.h>

#include "physics/batt.h"
#include "physics/duty.h"
#include "physics/mission.h"
#include "result/result.h"
#include "physics/role.h"

enum discharge_end {
	DIS_COMPLETED,      /* flew the whole mission */
	DIS_DEPLETED,       /* state of charge reached the clamp */
	DIS_VOLTAGE_FLOOR,  /* loaded voltage fell below cells × cutoff */
	DIS_COLLAPSE,       /* no real current: voltage collapse */
	DIS_OVERFLOW,       /* power not finite / above the guard */
	DIS_THERMAL,        /* pack above 60 °C: thermal runaway */
	DIS_END_MAX
};
extern const char *const discharge_end_text[DIS_END_MAX];

struct discharge_pack {
	const struct batt_chem *chem;
	int cells;               /* series cells */
	double capacity_ah;      /* total at the terminals */
	double mass_kg;          /* pack mass (thermal capacity and area) */
	int cycles;              /* ageing */
	int n_rotors;            /* ESCs sharing R_ds,on */
	double h_conv_w_m2k;     /* convection coefficient */
	double r_cells_ohm;      /* a real pack's cells in series at 25 °C,
	                            new (batt_rated_cell_ohm() × cells); 0:
	                            the chemistry profile's R_sys (eq. rsys) */
};

/* The mission to fly: a duty plan (duty.h), or, when plan is NULL, the
 * paper's three phases with the legacy shedding below. */
struct discharge_mission {
	const struct mission_model *model;
	double dry_mass_kg;              /* aircraft without payload */
	const struct duty_plan *plan;    /* the segments to fly, or NULL */
	double full_throttle_w;          /* battery power at full throttle (the
	                                    race's pieces are fractions of it) */
	double full_throttle_shaft_w;    /* its shaft power, all rotors */
	double full_throttle_v;          /* the terminal voltage it is given at:
	                                    on a sagging pack full throttle gives
	                                    less, P_full (V / V_full)³ */
	struct role_shedding shed;       /* plan NULL: payload over time */
	double duration_s[PHASE_MAX];    /* plan NULL: phase durations */
	double speed_ms[PHASE_MAX];      /* plan NULL: climb speed, forward
	                                    speed, 0 */
	double ambient_c;                /* air temperature */
};

struct discharge_out {
	enum discharge_end end;
	double t_end_s;           /* time flown */
	double ah_used;           /* charge drawn */
	double wh_used;           /* energy drawn at the terminals */
	double peak_temp_c;
	double min_v_term_v;
	double end_soc;
	double peak_current_a;
	double phase_energy_wh[PHASE_MAX];
	double phase_mean_current_a[PHASE_MAX];
	double phase_mean_power_w[PHASE_MAX];  /* energy / time flown */
	double phase_mean_shaft_w[PHASE_MAX];  /* shaft energy / time flown */
	double peak_power_w;                   /* the highest step power */
	/* Per group of the plan (duty_plan.group): what its segments drew. */
	double group_energy_wh[DUTY_MAX_GROUP];
	double group_ah[DUTY_MAX_GROUP];
	double group_time_s[DUTY_MAX_GROUP];
	double end_payload_kg;                 /* payload when the flight ended */
};

/* Simulate the mission with about `steps` time steps in all (at least 4 per
 * flown phase).  When trace != NULL, up to max_trace samples are stored and
 * *n_trace set.  Returns out->end == DIS_COMPLETED on success. */
void discharge_run(const struct discharge_pack *pack,
                   const struct discharge_mission *mis, int steps,
                   struct res_sample *trace, int max_trace, int *n_trace,
                   struct discharge_out *out);

/* The battery energy of a plan at a constant dry mass, each segment's
 * power at its mean payload, no battery flown: a seed for sizing, Wh. */
double discharge_plan_energy_wh(const struct discharge_mission *mis);

/* What a run flew, for the dossier: the plan's groups with what the
 * discharge out drew in each, and the profile's figures. */
void discharge_duty_record(const struct duty_plan *plan,
                           const struct discharge_out *out,
                           double full_throttle_w, const char *source,
                           struct res_duty *rec);

/* Hover endurance at constant mass_kg from full charge down to reserve_soc
 * (or the voltage floor, or a thermal stop), s.  aux_w replaces the model's
 * auxiliary load (marketing mode passes 0). */
double discharge_hover_endurance_s(const struct discharge_pack *pack,
                                   const struct mission_model *model,
                                   double mass_kg, double ambient_c,
                                   double reserve_soc);

/* The same with `steps` integration steps over the estimated endurance
 * (the plain form uses 240); the crossing is interpolated within a step. */
double discharge_hover_endurance_steps_s(const struct discharge_pack *pack,
                                         const struct mission_model *model,
                                         double mass_kg, double ambient_c,
                                         double reserve_soc, int steps);

/* Endurance at a constant battery power power_w from full charge down to
 * reserve_soc (or the voltage floor, or a thermal stop), in `steps` steps
 * over the estimate, s: the full-throttle flight time of a design. */
double discharge_power_endurance_s(const struct discharge_pack *pack,
                                   double power_w, double ambient_c,
                                   double reserve_soc, int steps);

#endif
