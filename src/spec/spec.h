/* spec.h — the mission specification: every field of a mission file.
 *
 * One X-macro table, SPEC_FIELDS, is the single source of truth for the
 * mission contract (what a mission file may say).  It generates the
 * field-id enum used by spec->given[], the struct offsets the parser
 * writes through, the defaults, the allowed ranges, `aeroeval schema` and
 * the shipped JSON Schema.  Nothing else may restate a default or a range.
 *
 * Who may include it: everyone.  It includes no I/O library; the physics
 * layer reads struct mission_spec as plain values.
 *
 * Units: the JSON names carry their unit (payload_kg, t_hover_s, ...) and the
 * struct members keep those names, so nothing is converted here.  Non-SI
 * fields (locked_capacity_mah, locked_diameter_in, ambient_temp_c) are
 * converted to SI where the engine reads them, never in the table.
 */
#ifndef AEROEVAL_SPEC_H
#define AEROEVAL_SPEC_H

#include <stdbool.h>
#include <stddef.h>

/* ---- enumerations (string spellings are in spec.c, index = value) ------- */

enum airframe_class {
	AF_MICRO_AIO,         /* "MicroAIO": racers, micro all-in-one */
	AF_CONSUMER_FOLDING,  /* "ConsumerFolding" */
	AF_ENTERPRISE_RUGGED, /* "EnterpriseRugged" */
	AF_AGRICULTURAL,      /* "Agricultural" */
	AF_CLASS_MAX
};

enum role_type {
	ROLE_NONE,
	ROLE_IMAGING,
	ROLE_DELIVERY,
	ROLE_AGRICULTURE,
	ROLE_RACING,
	ROLE_INSPECTION,
	ROLE_MAPPING,
	ROLE_MAX
};

enum arm_config { ARM_OFFSET, ARM_FOLDING, ARM_UNDER_ROTOR, ARM_CONFIG_MAX };

enum fom_mode { FOM_INSTALLED, FOM_ISOLATED, FOM_MODE_MAX };

enum aero_body_class {
	BODY_COMMERCIAL_COMPACT,  /* f_scale 0.004 */
	BODY_COMMERCIAL_BULKY,    /* f_scale 0.012 */
	BODY_RESEARCH_EXPOSED,    /* f_scale 0.05 */
	BODY_CLASS_MAX
};

/* Propeller construction: sets blade mass per unit disk area. */
enum prop_class { PROP_AUTO, PROP_PLASTIC, PROP_CARBON, PROP_WOOD, PROP_CLASS_MAX };

enum transport { TRANSPORT_NONE, TRANSPORT_BACKPACK, TRANSPORT_CAR_TRUNK,
	TRANSPORT_INDUSTRIAL, TRANSPORT_MAX };

enum priority { PRIORITY_NONE, PRIORITY_ENDURANCE, PRIORITY_RANGE,
	PRIORITY_PAYLOAD, PRIORITY_MIN_MASS, PRIORITY_MAX };

enum payload_preset { PRESET_NONE, PRESET_DSLR_CAMERA, PRESET_SURVEY_LIDAR,
	PRESET_SPRAY_TANK_10L, PRESET_PARCEL_2KG, PRESET_THERMAL_CAMERA,
	PRESET_MAX };

/* NULL-terminated spellings, index = enum value (spec.c). */
extern const char *const spec_enum_airframe[];
extern const char *const spec_enum_role[];
extern const char *const spec_enum_arm[];
extern const char *const spec_enum_fom_mode[];
extern const char *const spec_enum_body[];
extern const char *const spec_enum_prop[];
extern const char *const spec_enum_transport[];
extern const char *const spec_enum_priority[];
extern const char *const spec_enum_preset[];

/* ---- field kinds --------------------------------------------------------- */

enum spec_type {
	SPEC_NUM,      /* double */
	SPEC_INT,      /* int, must be integral in JSON */
	SPEC_BOOL,     /* bool */
	SPEC_STR,      /* char[SPEC_STR_MAX] */
	SPEC_ENUM,     /* int, spelled by a string from the enum table */
	SPEC_SPEED,    /* double, or the string "auto" (sets v_forward_auto) */
	SPEC_DATE      /* char[SPEC_STR_MAX], "YYYY-MM-DD" */
};

/* Flags of a field. */
#define SPEC_F_MIN_EXCL  0x01u /* value must be > min, not >= min */
#define SPEC_F_DERIVED   0x02u /* when absent, the engine derives the value
                                  (role table, class, requirements); the
                                  table default is only the fallback */
#define SPEC_F_BEYOND    0x04u /* aeroeval extension, not in the paper's contract */
#define SPEC_F_ZERO_AUTO 0x08u /* 0 means "choose automatically" */

#define SPEC_STR_MAX 128       /* longest accepted string, NUL included */

/*
 * SPEC_FIELDS(X): X(ID, "json.path", TYPE, member, "unit", default, min, max,
 *                   flags, enum_table, "meaning")
 * - member is the struct mission_spec member path written by the parser.
 * - default/min/max are doubles; for ENUM the default is the enum value,
 *   for BOOL 0/1; ignored for STR/DATE.
 * - Group objects (report, locks, payload_role, ...) are implied by the path.
 */
#define SPEC_FIELDS(X) \
X(NAME, "name", SPEC_STR, name, "", 0, 0, 0, 0, NULL, \
  "Mission name; the output folder is named after the file, not this field") \
X(REPORT_TITLE, "report.title", SPEC_STR, report.title, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Dossier title") \
X(REPORT_CLIENT, "report.client", SPEC_STR, report.client, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Client the dossier is prepared for") \
X(REPORT_AUTHOR, "report.author", SPEC_STR, report.author, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Responsible engineer") \
X(REPORT_PROJECT_ID, "report.project_id", SPEC_STR, report.project_id, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Client or programme project identifier") \
X(REPORT_REVISION, "report.revision", SPEC_STR, report.revision, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Document revision, e.g. \"A\" or \"1.2\"") \
X(REPORT_DATE, "report.date", SPEC_DATE, report.date, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Issue date YYYY-MM-DD; else SOURCE_DATE_EPOCH, else none: the dossier is undated") \
X(REPORT_CHECKED_BY, "report.checked_by", SPEC_STR, report.checked_by, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Engineer who checked the dossier (document control; empty leaves the line to sign)") \
X(REPORT_APPROVED_BY, "report.approved_by", SPEC_STR, report.approved_by, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Person who approved the dossier for issue (document control; empty leaves the line to sign)") \
\
X(PAYLOAD_KG, "payload_kg", SPEC_NUM, payload_kg, "kg", 1.0, 0.0, 500.0, SPEC_F_DERIVED, NULL, \
  "Payload mass carried at takeoff (requirements.payload_preset may set it)") \
X(MAX_PAYLOAD_KG, "max_payload_kg", SPEC_NUM, max_payload_kg, "kg", 0.0, 0.0, 500.0, SPEC_F_ZERO_AUTO, NULL, \
  "Largest payload the aircraft must lift: structure, propulsion and the thrust floor are sized for the empty aircraft plus it, the energy for the mission as flown with payload_kg; 0 = payload_kg") \
X(MAX_DIAMETER_M, "max_diameter_m", SPEC_NUM, max_diameter_m, "m", 0.5, 0.03, 5.0, SPEC_F_MIN_EXCL | SPEC_F_DERIVED, NULL, \
  "Diagonal motor-to-motor wheelbase W; bounds propeller size by the overlap limit") \
X(NUM_ROTORS, "num_rotors", SPEC_INT, num_rotors, "", 4, 3, 16, SPEC_F_DERIVED, NULL, \
  "Number of rotors (a coaxial X8 has 8)") \
X(COAXIAL_LAYOUT, "coaxial_layout", SPEC_BOOL, coaxial_layout, "", 0, 0, 1, SPEC_F_DERIVED, NULL, \
  "Coaxial layout: rotors in stacked pairs on num_rotors/2 arms") \
X(AIRFRAME_CLASS, "airframe_class", SPEC_ENUM, airframe_class, "", AF_ENTERPRISE_RUGGED, 0, AF_CLASS_MAX - 1, SPEC_F_DERIVED, spec_enum_airframe, \
  "Structural class: sets installed-FoM penalty kappa, frame overhead gamma and calibration lambda") \
X(FIXED_AIRFRAME_MASS_KG, "fixed_airframe_mass_kg", SPEC_NUM, fixed_airframe_mass_kg, "kg", 0, 0, 200, SPEC_F_ZERO_AUTO, NULL, \
  "Frame mass fixed by the user (0 = sized by the structural model)") \
\
X(T_HOVER_S, "t_hover_s", SPEC_NUM, t_hover_s, "s", 600, 0, 36000, 0, NULL, \
  "Hover time") \
X(T_CLIMB_S, "t_climb_s", SPEC_NUM, t_climb_s, "s", 60, 0, 3600, 0, NULL, \
  "Climb time at v_climb_ms") \
X(T_FORWARD_S, "t_forward_s", SPEC_NUM, t_forward_s, "s", 0, 0, 36000, 0, NULL, \
  "Forward-flight time at v_forward_ms") \
X(V_CLIMB_MS, "v_climb_ms", SPEC_NUM, v_climb_ms, "m/s", 2.5, 0.1, 20, 0, NULL, \
  "Vertical climb speed") \
X(V_FORWARD_MS, "v_forward_ms", SPEC_SPEED, v_forward_ms, "m/s", 10, 1, 40, 0, NULL, \
  "Forward speed, or \"auto\" for the minimum-power speed (sweep 1-30 m/s, 0.5 m/s steps)") \
X(BASELINE_V_FORWARD_MS, "baseline_v_forward_ms", SPEC_NUM, baseline_v_forward_ms, "m/s", 10, 1, 40, SPEC_F_DERIVED, NULL, \
  "Forward speed of the baseline run (default: v_forward_ms)") \
X(BASELINE_T_FORWARD_S, "baseline_t_forward_s", SPEC_NUM, baseline_t_forward_s, "s", 0, 0, 36000, SPEC_F_DERIVED, NULL, \
  "Forward time of the baseline run (default: t_forward_s)") \
X(ALTITUDE_M, "altitude_m", SPEC_NUM, altitude_m, "m", 0, 0, 20000, 0, NULL, \
  "Operating altitude above mean sea level (ISA pressure)") \
X(AMBIENT_TEMP_C, "ambient_temp_c", SPEC_NUM, ambient_temp_c, "degC", 15, -40, 55, SPEC_F_DERIVED, NULL, \
  "Ambient air temperature at the operating altitude (default: ISA temperature there, 15 degC at sea level)") \
\
X(BATTERY_CHEMISTRY, "battery_chemistry", SPEC_STR, battery_chemistry, "", 0, 0, 0, SPEC_F_DERIVED, NULL, \
  "Chemistry profile name from data/chemistries.json (default LiHV: the packs of current camera, enterprise and spraying aircraft)") \
X(NOMINAL_CELL_COUNT, "nominal_cell_count", SPEC_INT, nominal_cell_count, "cells", 0, 0, 24, SPEC_F_ZERO_AUTO, NULL, \
  "Series cell count (0 = chosen by the solver)") \
X(BATTERY_PACK_COUNT, "battery_pack_count", SPEC_INT, battery_pack_count, "packs", 1, 1, 8, 0, NULL, \
  "Packs carried in parallel") \
X(BATTERY_CYCLE_COUNT, "battery_cycle_count", SPEC_INT, battery_cycle_count, "cycles", 0, 0, 3000, 0, NULL, \
  "Charge cycles already on the pack (ageing raises resistance)") \
X(BATTERY_SPECIFIC_ENERGY_WH_KG, "battery_specific_energy_wh_kg", SPEC_NUM, battery_specific_energy_wh_kg, "Wh/kg", 0, 0, 700, SPEC_F_ZERO_AUTO, NULL, \
  "Pack specific energy override, whole pack (0 = the chemistry's pack law)") \
\
X(LOCK_BATTERY, "locks.is_battery_locked", SPEC_BOOL, locks.is_battery_locked, "", 0, 0, 1, 0, NULL, \
  "Battery capacity and cell count are fixed") \
X(LOCK_CAPACITY_MAH, "locks.locked_capacity_mah", SPEC_NUM, locks.locked_capacity_mah, "mAh", 5000, 50, 500000, 0, NULL, \
  "Locked total capacity at the pack terminals") \
X(LOCK_CELL_COUNT, "locks.locked_cell_count", SPEC_INT, locks.locked_cell_count, "cells", 4, 1, 24, 0, NULL, \
  "Locked series cell count of the locked battery") \
X(LOCK_VOLTAGE, "locks.is_voltage_locked", SPEC_BOOL, locks.is_voltage_locked, "", 0, 0, 1, 0, NULL, \
  "Bus voltage (series cells) is fixed") \
X(LOCK_SERIES_CELLS, "locks.locked_series_cells", SPEC_INT, locks.locked_series_cells, "cells", 6, 1, 24, 0, NULL, \
  "Locked series cell count of the bus") \
X(LOCK_PROP, "locks.is_prop_locked", SPEC_BOOL, locks.is_prop_locked, "", 0, 0, 1, 0, NULL, \
  "Propeller diameter and pitch are fixed") \
X(LOCK_DIAMETER_IN, "locks.locked_diameter_in", SPEC_NUM, locks.locked_diameter_in, "in", 10, 1, 80, 0, NULL, \
  "Locked propeller diameter") \
X(LOCK_PITCH_IN, "locks.locked_pitch_in", SPEC_NUM, locks.locked_pitch_in, "in", 4.5, 0.5, 40, 0, NULL, \
  "Locked propeller pitch") \
X(LOCK_MOTOR, "locks.is_motor_locked", SPEC_BOOL, locks.is_motor_locked, "", 0, 0, 1, 0, NULL, \
  "Motor KV is fixed") \
X(LOCK_KV, "locks.locked_kv", SPEC_NUM, locks.locked_kv, "rpm/V", 900, 10, 60000, 0, NULL, \
  "Locked motor KV") \
X(LOCK_AUTO_REDUCE, "locks.auto_reduce_flight_time", SPEC_BOOL, locks.auto_reduce_flight_time, "", 0, 0, 1, 0, NULL, \
  "Allow goal relaxation: scale mission times down (to 5 %) when the design cannot close") \
X(LOCK_MOTOR_PART, "locks.motor_part", SPEC_STR, locks.motor_part, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Catalogue id of a motor to use") \
X(LOCK_PROP_PART, "locks.prop_part", SPEC_STR, locks.prop_part, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Catalogue id of a propeller to use") \
X(LOCK_BATTERY_PART, "locks.battery_part", SPEC_STR, locks.battery_part, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Catalogue id of a battery pack to use") \
X(LOCK_ESC_PART, "locks.esc_part", SPEC_STR, locks.esc_part, "", 0, 0, 0, SPEC_F_BEYOND, NULL, \
  "Catalogue id of an ESC to use") \
\
X(ROLE_TYPE, "payload_role.type", SPEC_ENUM, payload_role.type, "", ROLE_NONE, 0, ROLE_MAX - 1, SPEC_F_DERIVED, spec_enum_role, \
  "Mission role: sets thrust margin, load factor, aux power and drag (data/roles.json)") \
X(ROLE_AUX_POWER_W, "payload_role.aux_power_w", SPEC_NUM, payload_role.aux_power_w, "W", 0, 0, 5000, SPEC_F_DERIVED, NULL, \
  "Auxiliary electrical power (gimbal, pump, sensors); default: the role's value for a 5 kg aircraft, scaled by (M / 5 kg)^(2/3) with the design's mass (each run reports the power it flew)") \
X(ROLE_ADDED_DRAG_M2, "payload_role.added_drag_m2", SPEC_NUM, payload_role.added_drag_m2, "m2", 0, 0, 5, SPEC_F_DERIVED, NULL, \
  "Drag area added to S_ref by the payload; default from the role") \
X(ROLE_CG_SHIFT_M, "payload_role.cg_shift_m", SPEC_NUM, payload_role.cg_shift_m, "m", 0, 0, 5, 0, NULL, \
  "Payload centre-of-gravity offset from the geometric centre") \
X(ROLE_DROP_MASS_KG, "payload_role.delivery_drop_mass_kg", SPEC_NUM, payload_role.delivery_drop_mass_kg, "kg", 0, 0, 500, SPEC_F_DERIVED, NULL, \
  "Delivery: mass released at the drop (default: the whole payload)") \
X(ROLE_DROP_TIME_RATIO, "payload_role.delivery_drop_time_ratio", SPEC_NUM, payload_role.delivery_drop_time_ratio, "", 0.5, 0, 1, 0, NULL, \
  "Delivery: the out-leg's share of the forward time; the parcel is carried out, hovered over the drop point for t_hover_s and released, and the rest of the forward time is the return leg (0.5: out and back)") \
X(ROLE_SPRAY_RATE, "payload_role.spray_rate_kg_per_s", SPEC_NUM, payload_role.spray_rate_kg_per_s, "kg/s", 0, 0, 20, SPEC_F_ZERO_AUTO | SPEC_F_DERIVED, NULL, \
  "Agriculture: liquid spray rate while spraying (0 = the tank empties at the end of the last spraying pass)") \
X(ROLE_RACING_LOAD_FACTOR, "payload_role.racing_load_factor", SPEC_NUM, payload_role.racing_load_factor, "g", 10, 1, 20, SPEC_F_DERIVED, NULL, \
  "Racing: arm design load factor") \
X(ROLE_AG_MAX_DOWNWASH, "payload_role.ag_max_downwash_ms", SPEC_NUM, payload_role.ag_max_downwash_ms, "m/s", 17, 1, 40, 0, NULL, \
  "Agriculture: limit on the far-wake downwash 2 v_i (crop lodging and drift); 17 m/s is that of the heaviest production sprayers (70-80 kg on six 1.2 m rotors), which fly over crops daily; set lower for sensitive crops") \
X(ROLE_THRUST_MARGIN, "payload_role.thrust_margin_override", SPEC_NUM, payload_role.thrust_margin_override, "", 0.4, 0.05, 0.8, SPEC_F_DERIVED, NULL, \
  "Thrust margin; hover throttle = 1 - margin, T/W = 1/throttle^2 (default from the role)") \
X(ROLE_DRAG_MULT, "payload_role.drag_area_multiplier", SPEC_NUM, payload_role.drag_area_multiplier, "", 1, 0.1, 10, SPEC_F_DERIVED, NULL, \
  "Forward-flight drag-area multiplier (mapping LiDAR 1.5 by default)") \
X(ROLE_MASS_SHEDDING, "payload_role.mass_shedding", SPEC_BOOL, payload_role.mass_shedding, "", 1, 0, 1, SPEC_F_BEYOND, NULL, \
  "Model payload leaving the aircraft (delivery drop, spray); false sizes for the full payload throughout (static sizing)") \
X(ROLE_INTEGRATION_KG, "payload_role.integration_overhead_kg", SPEC_NUM, payload_role.integration_overhead_kg, "kg", 0, 0, 100, SPEC_F_DERIVED, NULL, \
  "Mounts, pumps, release mechanisms added by the role (default from the role)") \
\
X(STRUCT_GEOMETRY, "structural_overrides.geometry_constant", SPEC_NUM, structural_overrides.geometry_constant, "", 1.5, 1.0, 5.0, 0, NULL, \
  "C_body: spar mass = C_body x effective arm mass") \
X(STRUCT_WALL_RATIO, "structural_overrides.wall_thickness_ratio", SPEC_NUM, structural_overrides.wall_thickness_ratio, "", 0.90, 0.5, 0.98, 0, NULL, \
  "alpha_w: arm tube inner/outer diameter ratio") \
X(STRUCT_BODY_MULT, "structural_overrides.body_mass_multiplier", SPEC_NUM, structural_overrides.body_mass_multiplier, "", 0.5, 0, 5, SPEC_F_DERIVED, NULL, \
  "gamma: body plate, landing gear and mounts as a fraction of spar mass (default per class)") \
X(STRUCT_NUM_BLADES, "structural_overrides.num_blades", SPEC_INT, structural_overrides.num_blades, "", 2, 2, 6, 0, NULL, \
  "Blades per propeller (blade-pass frequency)") \
X(STRUCT_ARM_CONFIG, "structural_overrides.arm_config", SPEC_ENUM, structural_overrides.arm_config, "", ARM_OFFSET, 0, ARM_CONFIG_MAX - 1, 0, spec_enum_arm, \
  "Arm position relative to the rotor: rotor-arm interference c = 0.6 offset, 1.5 under_rotor, 0 folding") \
\
X(AERO_FOM, "aerodynamic_overrides.figure_of_merit", SPEC_NUM, aerodynamic_overrides.figure_of_merit, "", 0, 0, 0.95, SPEC_F_ZERO_AUTO, NULL, \
  "Installed figure of merit used as is (0 = model: isolated/kappa and the calibrated Reynolds fit)") \
X(AERO_FOM_ISOLATED, "aerodynamic_overrides.figure_of_merit_isolated", SPEC_NUM, aerodynamic_overrides.figure_of_merit_isolated, "", 0.75, 0.3, 0.95, 0, NULL, \
  "Isolated (test-stand) figure of merit of the propeller") \
X(AERO_FOM_MODE, "aerodynamic_overrides.figure_of_merit_mode", SPEC_ENUM, aerodynamic_overrides.figure_of_merit_mode, "", FOM_INSTALLED, 0, FOM_MODE_MAX - 1, 0, spec_enum_fom_mode, \
  "installed: divide the isolated FoM by the calibrated installation penalty kappa; isolated: use it undivided") \
X(AERO_PROP_EFF, "aerodynamic_overrides.propulsive_efficiency", SPEC_NUM, aerodynamic_overrides.propulsive_efficiency, "", 0, 0, 1.0, SPEC_F_ZERO_AUTO, NULL, \
  "Motor and ESC drive efficiency: electrical power = shaft power / efficiency (0 = the calibrated value)") \
X(AERO_CD_H, "aerodynamic_overrides.cd_horizontal", SPEC_NUM, aerodynamic_overrides.cd_horizontal, "", 1.0, 0.05, 3.0, 0, NULL, \
  "Body drag coefficient in forward flight, on S_ref") \
X(AERO_CD_V, "aerodynamic_overrides.cd_vertical", SPEC_NUM, aerodynamic_overrides.cd_vertical, "", 1.2, 0.05, 3.0, 0, NULL, \
  "Body drag coefficient in vertical climb, on S_ref") \
X(AERO_AREA_SCALING, "aerodynamic_overrides.area_scaling_factor", SPEC_NUM, aerodynamic_overrides.area_scaling_factor, "m2/kg^(2/3)", 0, 0, 0.5, SPEC_F_ZERO_AUTO, NULL, \
  "f_scale in S_ref = f_scale M^(2/3) + dA (0 = from aero_body_class)") \
X(AERO_BODY_CLASS, "aerodynamic_overrides.aero_body_class", SPEC_ENUM, aerodynamic_overrides.aero_body_class, "", BODY_COMMERCIAL_BULKY, 0, BODY_CLASS_MAX - 1, 0, spec_enum_body, \
  "Body shape class: f_scale 0.004 compact, 0.012 bulky, 0.05 research_exposed") \
X(AERO_CT, "aerodynamic_overrides.assumed_ct", SPEC_NUM, aerodynamic_overrides.assumed_ct, "", 0.12, 0.03, 0.3, 0, NULL, \
  "Thrust coefficient C_t in T = C_t rho n^2 D^4 (sets rpm and KV)") \
X(AERO_PROP_CLASS, "aerodynamic_overrides.propeller_class", SPEC_ENUM, aerodynamic_overrides.propeller_class, "", PROP_AUTO, 0, PROP_CLASS_MAX - 1, 0, spec_enum_prop, \
  "Propeller material (blade mass); auto = plastic below 12 in, carbon above") \
\
X(MARKETING, "evaluate_marketing_limits", SPEC_BOOL, evaluate_marketing_limits, "", 0, 0, 1, 0, NULL, \
  "Also report the manufacturer-style best-case endurance (no reserve, ideal conditions)") \
\
X(REQ_PRESET, "requirements.payload_preset", SPEC_ENUM, requirements.payload_preset, "", PRESET_NONE, 0, PRESET_MAX - 1, 0, spec_enum_preset, \
  "Mission Workspace payload preset (sets payload_kg and role)") \
X(REQ_TRANSPORT, "requirements.transport", SPEC_ENUM, requirements.transport, "", TRANSPORT_NONE, 0, TRANSPORT_MAX - 1, 0, spec_enum_transport, \
  "Transport footprint: sets the wheelbase ceiling and may force a coaxial layout") \
X(REQ_ROLE, "requirements.role", SPEC_ENUM, requirements.role, "", ROLE_NONE, 0, ROLE_MAX - 1, 0, spec_enum_role, \
  "Mission Workspace role card") \
X(REQ_PRIORITY, "requirements.priority", SPEC_ENUM, requirements.priority, "", PRIORITY_NONE, 0, PRIORITY_MAX - 1, 0, spec_enum_priority, \
  "Optimisation priority: endurance, range, payload or min_mass")

/* Field ids SPECF_<ID>, in table order, then SPEC_N_FIELDS (index of given[]). */
enum spec_field {
#define SPEC_X_ENUM(id, ...) SPECF_##id,
	SPEC_FIELDS(SPEC_X_ENUM)
#undef SPEC_X_ENUM
	SPEC_N_FIELDS
};

/* ---- the struct ---------------------------------------------------------- */

struct spec_report {
	char title[SPEC_STR_MAX];      /* dossier title */
	char client[SPEC_STR_MAX];     /* client name */
	char author[SPEC_STR_MAX];     /* responsible engineer */
	char project_id[SPEC_STR_MAX]; /* project identifier */
	char revision[SPEC_STR_MAX];   /* document revision */
	char date[SPEC_STR_MAX];       /* YYYY-MM-DD or "" */
	char checked_by[SPEC_STR_MAX]; /* checker, "" not yet */
	char approved_by[SPEC_STR_MAX]; /* approver, "" not yet */
};

struct spec_locks {
	bool is_battery_locked;        /* capacity + cells fixed */
	double locked_capacity_mah;    /* total capacity at the terminals, mAh */
	int locked_cell_count;         /* series cells of the locked battery */
	bool is_voltage_locked;        /* series cells fixed */
	int locked_series_cells;       /* series cells of the bus */
	bool is_prop_locked;           /* diameter + pitch fixed */
	double locked_diameter_in;     /* propeller diameter, inch */
	double locked_pitch_in;        /* propeller pitch, inch */
	bool is_motor_locked;          /* KV fixed */
	double locked_kv;              /* motor KV, rpm/V */
	bool auto_reduce_flight_time;  /* goal relaxation allowed */
	char motor_part[SPEC_STR_MAX];   /* catalogue id or "" */
	char prop_part[SPEC_STR_MAX];    /* catalogue id or "" */
	char battery_part[SPEC_STR_MAX]; /* catalogue id or "" */
	char esc_part[SPEC_STR_MAX];     /* catalogue id or "" */
};

struct spec_role {
	int type;                        /* enum role_type */
	double aux_power_w;              /* auxiliary electrical load, W */
	double added_drag_m2;            /* payload drag area, m^2 */
	double cg_shift_m;               /* payload CG offset, m */
	double delivery_drop_mass_kg;    /* released at the drop, kg */
	double delivery_drop_time_ratio; /* t_drop / t_total */
	double spray_rate_kg_per_s;      /* 0 = payload / mission time */
	double racing_load_factor;       /* arm design load factor, g */
	double ag_max_downwash_ms;       /* downwash cap, m/s */
	double thrust_margin_override;   /* 1 - hover throttle */
	double drag_area_multiplier;     /* forward-flight S_ref multiplier */
	double integration_overhead_kg;  /* role hardware mass, kg */
	bool mass_shedding;              /* drop/spray modelled (false = static) */
};

struct spec_structural {
	double geometry_constant;     /* C_body */
	double wall_thickness_ratio;  /* alpha_w = d_in / d_out */
	double body_mass_multiplier;  /* gamma */
	int num_blades;               /* N_b */
	int arm_config;               /* enum arm_config */
};

struct spec_aero {
	double figure_of_merit;          /* installed FoM used as is, 0 = model */
	double figure_of_merit_isolated; /* lab FoM */
	int figure_of_merit_mode;        /* enum fom_mode */
	double propulsive_efficiency;    /* motor + ESC efficiency */
	double cd_horizontal;            /* body Cd, forward flight */
	double cd_vertical;              /* body Cd, climb */
	double area_scaling_factor;      /* f_scale, 0 = from body class */
	int aero_body_class;             /* enum aero_body_class */
	double assumed_ct;               /* C_t */
	int propeller_class;             /* enum prop_class */
};

struct spec_requirements {
	int payload_preset;  /* enum payload_preset */
	int transport;       /* enum transport */
	int role;            /* enum role_type */
	int priority;        /* enum priority */
};

struct mission_spec {
	char name[SPEC_STR_MAX];          /* mission name */
	struct spec_report report;        /* dossier identity */
	double payload_kg;                /* payload at takeoff, kg */
	double max_payload_kg;            /* largest payload it is built for, kg; 0 = payload_kg */
	double max_diameter_m;            /* wheelbase W, m */
	int num_rotors;                   /* N_r */
	bool coaxial_layout;              /* stacked rotor pairs */
	int airframe_class;               /* enum airframe_class */
	double fixed_airframe_mass_kg;    /* 0 = sized */
	double t_hover_s;                 /* hover time, s */
	double t_climb_s;                 /* climb time, s */
	double t_forward_s;               /* forward time, s */
	double v_climb_ms;                /* climb speed, m/s */
	double v_forward_ms;              /* forward speed, m/s (when not auto) */
	bool v_forward_auto;              /* v_forward_ms was "auto" */
	double baseline_v_forward_ms;     /* baseline forward speed, m/s */
	double baseline_t_forward_s;      /* baseline forward time, s */
	double altitude_m;                /* ISA altitude, m */
	double ambient_temp_c;            /* ambient temperature, degC */
	char battery_chemistry[SPEC_STR_MAX]; /* chemistry profile name */
	int nominal_cell_count;           /* 0 = auto */
	int battery_pack_count;           /* packs in parallel */
	int battery_cycle_count;          /* cycles of ageing */
	double battery_specific_energy_wh_kg; /* 0 = chemistry value */
	struct spec_locks locks;
	struct spec_role payload_role;
	struct spec_structural structural_overrides;
	struct spec_aero aerodynamic_overrides;
	bool evaluate_marketing_limits;   /* marketing-mode endurance */
	struct spec_requirements requirements;
	bool given[SPEC_N_FIELDS];        /* true where the file set the field */
};

/* One row of the field table. */
struct spec_field_info {
	enum spec_field id;
	const char *path;          /* "payload_role.aux_power_w" */
	enum spec_type type;
	size_t offset;             /* offsetof(struct mission_spec, member) */
	const char *unit;          /* "" when dimensionless */
	double def, min, max;
	unsigned flags;            /* SPEC_F_* */
	const char *const *enums;  /* spellings for SPEC_ENUM */
	const char *help;          /* one-line meaning */
};

/* The table, in SPEC_FIELDS order; spec_fields[i].id == i. */
extern const struct spec_field_info spec_fields[SPEC_N_FIELDS];

/* ---- the essentials ------------------------------------------------------
 *
 * What a mission must give to be sized (README, "A first design"): its
 * payload, its wheelbase and at least one mission time.  An essential is
 * met when the file gives one of its fields (a time above 0: a mission of
 * no time is none), or sets the requirements field that derives it to
 * other than "none" (engine.c apply_requirements: a payload preset sets
 * payload_kg, a transport footprint max_diameter_m; nothing derives a
 * time).  `check`, `solve` and `build` refuse a mission that misses one. */
#define SPEC_ESSENTIAL_FIELDS 3   /* the most fields an essential offers */

struct spec_essential {
	const char *what;              /* "payload_kg", "a mission time" */
	enum spec_field any_of[SPEC_ESSENTIAL_FIELDS]; /* SPEC_N_FIELDS pads */
	bool positive;                 /* a given value must be above 0 */
	enum spec_field derived_by;    /* a requirements field, or SPEC_N_FIELDS */
};

#define SPEC_N_ESSENTIALS 3
extern const struct spec_essential spec_essentials[SPEC_N_ESSENTIALS];

/* Does s (its given[] flags and values) meet essential e? */
bool spec_essential_met(const struct mission_spec *s, const struct spec_essential *e);

/* Fill *s with every default ("LiPo" chemistry, no given[] set). */
void spec_defaults(struct mission_spec *s);

/* Field info by JSON path, or NULL. */
const struct spec_field_info *spec_field_by_path(const char *path);

/* Pointer to the member a field describes inside *s. */
void *spec_member(struct mission_spec *s, const struct spec_field_info *f);
const void *spec_member_const(const struct mission_spec *s,
                              const struct spec_field_info *f);

/* Index of name in a NULL-terminated enum table, or -1. */
int spec_enum_index(const char *const *table, const char *name);

/* Group of path: the text before the first '.', or "" at the top level.
 * Writes it to buf (size n); returns the key after the dot (or path). */
const char *spec_split(const char *path, char *buf, size_t n);

/* True when name is a group object of the mission file ("locks",
 * "payload_role", ...): some field path starts with name + ".". */
bool spec_is_group(const char *name);

/* The valid path closest to path, for "unknown field" messages: a field
 * path or a group name.  Case is ignored, transpositions count as one edit,
 * and the key is also compared with the fields of other groups, so
 * "payload_kgs" -> "payload_kg", "Payload_KG" -> "payload_kg", top-level
 * "aux_power_w" -> "payload_role.aux_power_w", "lock" -> "locks".
 * Writes it to out (size n) and returns true; false (out = "") when nothing
 * is close enough or the closest is path itself. */
bool spec_suggest(const char *path, char *out, size_t n);

/* The allowed range of numeric field f as text: "0 to 500 kg", or
 * "above 0.05 up to 5 m" when the minimum is exclusive (SPEC_F_MIN_EXCL). */
void spec_range_text(const struct spec_field_info *f, char *buf, size_t n);

/* The value of field f in *s as text with its unit, for the dossier
 * appendix: "1.5 kg", "4 cells", "true", "EnterpriseRugged", "auto",
 * "2026-03-01", and "(none)" for an empty string.  buf of size n is always
 * NUL-terminated. */
void spec_format_value(const struct mission_spec *s,
                             const struct spec_field_info *f, char *buf,
                             size_t n);

#endif /* AEROEVAL_SPEC_H */
