/* model.h — the reference tables the engine reads: battery chemistries,
 * mission roles, airframe classes, calibration coefficients and the Mission
 * Workspace mapping.  Loaded at run time from data/ (model_io.c); the engine
 * sees only these plain structs.  Who may include it: everyone.
 */
#ifndef AEROEVAL_MODEL_H
#define AEROEVAL_MODEL_H

#include <stdbool.h>

#include "spec/spec.h"

/* One chemistry profile (data/chemistries.json). */
struct batt_chem {
	char name[32];              /* profile name, e.g. "LiPo" */
	double e_spec_wh_kg;        /* cell specific energy, Wh/kg */
	double p_spec_w_kg;         /* cell specific power, W/kg */
	double r_cell_mohm;         /* R_i,base per cell at C_ref, mOhm */
	double v_full;              /* full-charge cell voltage, V */
	double v_nom;               /* nominal cell voltage, V */
	double v_exp;               /* end of the exponential zone, V */
	double v_cutoff;            /* lowest cell voltage under load, V */
	double b;                   /* Tremblay exponential-zone constant B */
	double k;                   /* Tremblay polarisation constant K, V */
	bool pouch;                 /* pouch (LiPo family) vs cylindrical/exotic packaging */
	double pack_wh_kg_100;      /* pack specific energy of a 100 Wh 6S pack, Wh/kg */
	double pack_exponent;       /* its growth with pack energy (batt_pack_wh_kg) */
	double pack_series_exponent;/* its fall with series cells at that energy */
};

#define MODEL_MAX_CHEM 32

enum shed_kind { SHED_NONE, SHED_DROP, SHED_SPRAY };

/* How a role flies its mission (data/roles.json "duty"; docs/model.md,
 * "Duty cycles"): the paper's three phases, a race of repeating laps, spray
 * sorties with a turn at each swath end, or an out-and-back delivery with
 * the drop at the far end. */
enum duty_kind { DUTY_PHASES, DUTY_RACE, DUTY_SPRAY, DUTY_OUT_AND_BACK,
	DUTY_KIND_MAX };
extern const char *const duty_kind_name[DUTY_KIND_MAX]; /* "phases", ... */

#define MODEL_MAX_LAP 6          /* pieces of a race lap */
#define MODEL_DUTY_SOURCE 640    /* bytes of a profile's source text */

/* One piece of a race lap: its share of the lap's time and the battery
 * power it draws as a fraction of the design's full-throttle power. */
struct model_lap_piece {
	char name[32];              /* "full-throttle burst" */
	double share;               /* of the lap's time; the shares sum to 1 */
	double power_fraction;      /* of the full-throttle power, (0, 1] */
};

/* A role's duty profile. */
struct model_duty {
	enum duty_kind kind;
	/* race */
	double lap_s;               /* one lap, s */
	int n_lap;                  /* pieces of a lap */
	struct model_lap_piece lap[MODEL_MAX_LAP];
	/* spray sorties */
	double swath_length_m;      /* one spraying pass, m */
	double turn_accel_m_s2;     /* braking and acceleration at a swath end */
	double turn_yaw_s;          /* the yaw at a swath end, s */
	double transit_m;           /* take-off point to the field, each way, m */
	char source[MODEL_DUTY_SOURCE]; /* where the numbers come from */
};

/* One row of data/roles.json (paper Table roles). */
struct model_role {
	double thrust_margin;           /* 1 - hover throttle */
	double load_factor;             /* arm design load factor, g */
	double aux_power_w;             /* default auxiliary power, W */
	double aux_ref_kg;              /* ... of an aircraft of this mass */
	double added_drag_m2;           /* default payload drag area, m^2 */
	double forward_drag_multiplier; /* S_ref multiplier in forward flight */
	double integration_frac;        /* role hardware / payload mass */
	double c_motor;                 /* continuous motor-mass factor */
	double c_esc;                   /* continuous ESC-mass factor */
	double h_conv_w_m2k;            /* battery convection coefficient */
	double burst_factor;            /* 10 s burst / continuous battery power */
	enum shed_kind shedding;        /* payload shedding */
	struct model_duty duty;         /* how the role flies its mission */
};

/* One row of data/airframes.json. */
struct model_class {
	double gamma;           /* body overhead on spar mass */
	double avionics_share;  /* share of the equipment mass shown as avionics */
	int cells_min;          /* series-cell range searched */
	int cells_max;
	bool small_platform;    /* racing/small wiring and ESC factors */
};

/* How well a calibration predicts the cohort it was fitted on, by
 * leave-one-out (calibrate.c), and the split-conformal interval built from
 * those errors: ln(actual / predicted) lies in [log_lo, log_hi] for the
 * nominal share `level` of aircraft like the cohort's. */
struct model_interval {
	int n;                  /* leave-one-out residuals behind it */
	double log_lo, log_hi;  /* bounds on ln(actual / predicted) */
};

/* The two ways a design's battery comes about, each with its own
 * accuracy: sized from the mission's endurance, or a locked pack. */
enum model_basis { MODEL_FROM_ENDURANCE, MODEL_PACK_LOCKED, MODEL_BASIS_MAX };

struct model_accuracy {
	bool valid;                        /* calibration.json carries it */
	int n_rows;                        /* cohort rows sized */
	double loo_mape_pct;               /* leave-one-out MTOW MAPE */
	int n_battery;                     /* rows with a published battery mass */
	double loo_battery_mape_pct;       /* leave-one-out battery-mass MAPE */
	double level;                      /* nominal coverage, e.g. 0.90 */
	double coverage;                   /* share of the rows inside (LOO) */
	struct model_interval pooled;      /* every class together */
	struct model_interval cls[AF_CLASS_MAX]; /* n = 0: the pooled one serves */
	/* The design's own interval (engine_loop_interval()), each row's built
	 * from the other rows' spreads, against the row's real mass: */
	int design_rows;                   /* rows judged */
	double design_coverage;            /* share inside */
	double design_width;               /* median hi / lo */
};

/* How far a model's figure falls from the published one over a cohort:
 * the spread of ln(model / published) by leave-one-out, and the
 * split-conformal interval built from it (calibrate.c).  The forward
 * check (endurance at a real aircraft's mass and pack) and the dry mass at
 * a real aircraft's mass each have one. */
struct model_spread {
	bool valid;             /* calibration.json carries it */
	int n;                  /* residuals behind it */
	double mape_pct;        /* mean |model / published - 1| */
	double level;           /* nominal coverage of the interval */
	double log_lo, log_hi;  /* bounds on ln(published / model) */
	double coverage;        /* share inside, out of sample */
};

/* data/calibration.json: the calibrated coefficients. */
enum model_lambda { LAMBDA_MICRO, LAMBDA_CONSUMER, LAMBDA_ENTERPRISE_QUAD,
	LAMBDA_ENTERPRISE_MULTI, LAMBDA_AGRI, LAMBDA_MAX };

struct model_calibration {
	double lambda[LAMBDA_MAX];      /* per-class structural multiplier */
	double wire_coef;               /* C_wire, kg/(A m) */
	double wire_coef_small;         /* C_wire for racing/small platforms */
	/* Equipment (avionics, body shell, landing gear, gimbal and mounts):
	 * e_class (M_design / 1 kg)^exponent, kg (airframe.h). */
	double equip_kg[AF_CLASS_MAX];
	double equip_exponent;
	/* The power chain, fitted on the forward check's endurance residuals
	 * alone (calibrate.h): */
	double kappa;                   /* installed-FoM penalty (paper §IV-F) */
	double eta_drive;               /* motor + ESC efficiency in flight */
	double re_ref;                  /* Reynolds reference of FoM(Re) */
	double aux_scale;               /* on the roles' auxiliary power */
	double drag_scale;              /* on the body drag area S_ref */
	double wake_share;              /* forward flight: the share of the
	                                   hover induced power kept (mission.h) */
	struct model_accuracy accuracy[MODEL_BASIS_MAX]; /* of this calibration */
	struct model_spread forward;    /* endurance: the forward check */
	struct model_spread dry;        /* dry mass at the real mass */
};

/* The interval of a class: its own when the cohort had enough rows of it,
 * else the pooled one. */
const struct model_interval *model_interval_for(const struct model_accuracy *a,
                                                int airframe_class);

struct model_preset { double payload_kg; int role; char label[64]; };
struct model_transport { double max_wheelbase_m; int airframe_class; char label[64]; };
struct model_priority { char chemistry[32]; bool v_auto; };

struct model_data {
	struct batt_chem chem[MODEL_MAX_CHEM];
	int n_chem;
	const char *chem_names[MODEL_MAX_CHEM + 1]; /* NULL-terminated, for the parser */
	struct model_role role[ROLE_MAX];
	struct model_class cls[AF_CLASS_MAX];
	struct model_calibration cal;
	struct model_preset preset[PRESET_MAX];          /* [PRESET_NONE] unused */
	struct model_transport transport[TRANSPORT_MAX]; /* [TRANSPORT_NONE] unused */
	struct model_priority priority[PRIORITY_MAX];    /* [PRIORITY_NONE] unused */
	double coaxial_disk_loading_n_m2;                /* coaxial trigger */
};

/* Chemistry by name, or NULL. */
const struct batt_chem *model_chem(const struct model_data *m, const char *name);

/* Which λ applies to a class and rotor count. */
enum model_lambda model_lambda_index(int airframe_class, int n_rotors);

#endif
