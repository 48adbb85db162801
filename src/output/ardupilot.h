/* ardupilot.h — the hand-off to the autopilot: vehicle_components.json for
 * the ArduPilot Methodic Configurator and a starting parameter file.
 *
 * Written for a buildable design of record only (res_record(): real parts
 * that close), from the parts of its bill of materials and the numbers of
 * its real-parts drive, so the builder types nothing in again.
 *
 * vehicle_components.json follows the configurator's published schema,
 * ardupilot_methodic_configurator/vehicle_components_schema.json in
 * github.com/ArduPilot/MethodicConfigurator, and the layout of the
 * vehicle_components.json files of its templates (vehicle_templates/
 * ArduCopter/.../vehicle_components.json, format version 1): the top-level
 * keys "Format version", "Components", "Program version" and
 * "Configuration template"; the components Flight Controller, Frame,
 * Battery Monitor, Battery, ESC, Motors and Propellers, each with its
 * Product {Manufacturer, Model, URL, Version} and Notes.  What the design
 * cannot know (flight controller, firmware version, battery monitor, ESC
 * protocol, motor poles) is left as the configurator's own empty template
 * leaves it, or out where the schema allows; the motor's KV and the
 * propeller's pitch, which the schema has no field for, are in the Notes.
 *
 * The parameter file ("NAME,VALUE  # comment" lines, as Mission Planner
 * and the configurator write them, names sorted) sets what the design
 * determines, each value with a comment saying how it was derived:
 * BATT_CAPACITY, BATT_LOW_MAH, BATT_ARM_VOLT, BATT_LOW_VOLT, BATT_CRT_VOLT,
 * MOT_BAT_VOLT_MAX, MOT_BAT_VOLT_MIN, MOT_THST_HOVER, FRAME_CLASS,
 * FRAME_TYPE and the throttle-based harmonic notch INS_HNTCH_*.
 *
 * Output layer: renders text, writes no file.
 */
#ifndef AEROEVAL_ARDUPILOT_H
#define AEROEVAL_ARDUPILOT_H

#include <stdbool.h>
#include <stddef.h>

#include "core/catalog.h"
#include "core/model.h"
#include "core/result.h"

/* ArduPilot's FRAME_CLASS values used here (ArduCopter Parameters.cpp). */
enum ardupilot_frame_class {
	AP_FRAME_UNDEFINED = 0,
	AP_FRAME_QUAD = 1,
	AP_FRAME_HEXA = 2,
	AP_FRAME_OCTA = 3,
	AP_FRAME_OCTAQUAD = 4,
	AP_FRAME_Y6 = 5,
	AP_FRAME_TRI = 7,
	AP_FRAME_DODECAHEXA = 12,
	AP_FRAME_DECA = 14
};

#define AP_FRAME_TYPE_X 1  /* FRAME_TYPE 1: X */

/* What the design determines, worked out once for both files. */
struct ardupilot_design {
	const char *chemistry;        /* the configurator's name, e.g. "Lipo" */
	const char *chemistry_aeroeval; /* ours, e.g. "LiPo" */
	int cells;                    /* series cells of the pack of record */
	int capacity_mah;             /* its capacity */
	double cell_max_v;            /* full charge: the profile's, within the
	                                 configurator's limit for the chemistry */
	double cell_arm_v;            /* per-cell arm, low and critical levels */
	double cell_low_v;
	double cell_crit_v;
	double cell_min_v;            /* the profile's loaded cut-off */
	bool cell_max_clamped;        /* the profile's full charge was above it */
	double reserve_mah;           /* capacity left at the design's reserve, 0 unknown */
	double reserve_soc;           /* that reserve as a state of charge */
	double tow_min_kg;            /* without payload */
	double tow_max_kg;            /* with the largest payload */
	double takeoff_mass_kg;       /* of record */
	int n_rotors;
	bool coaxial;
	enum ardupilot_frame_class frame_class;
	const char *frame_class_name; /* "Quad", ..., "Undefined" */
	int frame_type;               /* AP_FRAME_TYPE_X, or -1: not used */
	double motor_kv;              /* rpm/V, 0 unknown */
	double prop_diameter_in;
	double prop_pitch_in;
	int blades;                   /* per propeller */
	double hover_rpm;             /* rotor speed in hover at takeoff mass */
	double hover_thrust_n;        /* one rotor, hover */
	double full_thrust_n;         /* one rotor, full throttle; 0 unknown */
	double hover_throttle;        /* the design's hover throttle (speed ratio) */
	double thrust_hover;          /* MOT_THST_HOVER as written */
	bool thrust_hover_clamped;    /* the ratio fell outside 0.2..0.8 */
	double notch_hz;              /* INS_HNTCH_FREQ as written */
	bool notch_clamped;           /* outside 10..495 Hz */
	bool feasible;                /* the design of record passes its checks */
};

/* Works out d for r's design of record.  Returns 0, or -1 when the design
 * gets no hand-off, with the reason in why: not buildable, or a chemistry
 * the configurator has no name for (Li-S).  m gives the chemistry profile,
 * cat the parts' KV, pitch and blade count. */
int ardupilot_derive(const struct solve_result *r, const struct model_data *m,
                     const struct catalog *cat, struct ardupilot_design *d,
                     char *why, size_t whylen);

/* vehicle_components.json of r with d (ardupilot_derive()), naming the
 * mission name and aeroeval_version.  Ownership: free(). */
char *ardupilot_components(const struct solve_result *r,
                           const struct ardupilot_design *d, const char *name,
                           const char *aeroeval_version);

/* The starting parameter file.  Ownership: free(). */
char *ardupilot_params(const struct ardupilot_design *d, const char *name,
                       const char *aeroeval_version);

#endif
