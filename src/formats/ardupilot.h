/* ardupilot.h — the hand-off to the autopilot: vehicle_components.json for
 * the ArduPilot Methodic Configurator and the starting parameters, in the
 * format Mission Planner, MAVProxy and the configurator load and in the one
 * QGroundControl loads.
 *
 * Written for a buildable design of record only (res_record(): real parts
 * that close), from the lines of its bill of materials and the numbers of
 * its real-parts drive, so the builder types nothing in again.
 *
 * vehicle_components.json follows the configurator's published schema,
 * ardupilot_methodic_configurator/vehicle_components_schema.json in
 * github.com/ArduPilot/MethodicConfigurator, and the layout of its
 * templates' vehicle_components.json (vehicle_templates/ArduCopter/...,
 * format version 1): "Format version", "Components", "Program version",
 * "Configuration template".  Every component the configurator knows that
 * the bill of materials buys is filled from its BOM line, part for part:
 * Flight Controller (an all-in-one board when the ESC board carries it),
 * Battery Monitor (the power module), GNSS Receiver, RC Receiver,
 * Telemetry, ESC (with its protocol), Motors, Propellers, Battery, Frame;
 * each Product's Manufacturer and Model are the BOM line's maker and
 * orderable part number (bom_csv_part_number()).  The FC Connection of each
 * is the port and protocol the configurator offers for it (its
 * data_model_vehicle_components_validation.py: "Analog", "CAN1", "I2C1",
 * "SERIALn", "Main Out"/"AIO"; "Analog Voltage and Current",
 * "DroneCAN-BatteryInfo", "INA2XX", "AUTO", "DroneCAN", "CRSF", "MAVLink2",
 * "Normal", "DShot600"), read from the part's catalogue description (its
 * bus, its radio family) and, for serial ports, as wired on a Pixhawk
 * standard board (TELEM1 SERIAL1, TELEM2 SERIAL2, GPS1 SERIAL3).  What the
 * design cannot know (firmware versions, motor poles) is left as the
 * configurator's empty template leaves it.
 *
 * ardupilot.param: "NAME,VALUE" lines with every comment on its own line
 * starting with '#', ASCII, LF line ends.  That is the one layout all of
 * these loaders accept in full:
 *   - Mission Planner (ParamFile.loadParamFile): skips lines starting with
 *     '#', splits the others on space, comma and tab and takes only lines
 *     of exactly two tokens (a trailing "# comment" makes a line vanish);
 *   - MAVProxy / pymavlink (mavparm.load): strips, skips empty and '#'
 *     lines, turns commas into spaces and rejects lines of other than two
 *     words ("Invalid line");
 *   - the Methodic Configurator (ParDict.load_param_file_into_dict): UTF-8
 *     (a byte order mark would spoil the first line), '#' lines skipped,
 *     NAME matching ^[A-Z][A-Z_0-9]*$ of at most 16 characters, no name
 *     twice, VALUE a float.
 * QGroundControl's parameter files are tab-separated "vehicle component
 * NAME VALUE type" lines (ParameterManager / ParameterEditorController
 * read only lines of five tab-separated fields), so qgroundcontrol.params
 * carries the same values in that format.
 *
 * Both files open with a header naming the firmware the names and ranges
 * are ArduCopter 4.5's, the parameters that need a reboot, and the two-pass
 * load that enable parameters require (the BATT_ and INS_HNTCH_ values
 * exist on the autopilot only once BATT_MONITOR and INS_HNTCH_ENABLE are
 * set and it has rebooted); each enable parameter comes before the
 * parameters it enables, and each value follows a comment saying how it
 * was derived.
 *
 * Formats layer: renders text, writes no file.
 */
#ifndef AEROEVAL_ARDUPILOT_H
#define AEROEVAL_ARDUPILOT_H

#include <stdbool.h>
#include <stddef.h>

#include "catalog/catalog.h"
#include "spec/model.h"
#include "result/result.h"

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

/* The components of vehicle_components.json the bill of materials can
 * fill, each from one BOM line. */
enum ardupilot_role {
	AP_ROLE_FC,        /* Flight Controller */
	AP_ROLE_MONITOR,   /* Battery Monitor */
	AP_ROLE_GNSS,      /* GNSS Receiver */
	AP_ROLE_RX,        /* RC Receiver */
	AP_ROLE_TELEM,     /* Telemetry */
	AP_ROLE_ESC,       /* ESC */
	AP_ROLE_MOTOR,     /* Motors */
	AP_ROLE_PROP,      /* Propellers */
	AP_ROLE_BATTERY,   /* Battery */
	AP_ROLE_FRAME,     /* Frame (a catalogue kit; else custom) */
	AP_ROLE_MAX
};

/* The configurator's component name of a role ("Flight Controller"). */
extern const char *const ardupilot_role_name[AP_ROLE_MAX];

/* How a component connects to the flight controller (the configurator's
 * "FC Connection" Type and Protocol). */
struct ardupilot_link {
	const char *type;      /* "SERIAL3", "CAN1", "Analog", "Main Out", ... */
	const char *protocol;  /* "AUTO", "DroneCAN", "CRSF", "DShot600", ... */
};

/* What the design determines, worked out once for every file. */
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
	bool feasible;                /* the design of record passes its checks */

	/* The bill of materials, by component. */
	int line[AP_ROLE_MAX];        /* index into r->bom, -1: not bought */
	bool fc_on_esc;               /* the ESC board carries the flight controller */
	bool rx_on_esc;               /* ... and the receiver */
	bool esc_in_motor;            /* integrated motor + ESC systems */
	const char *mcu;              /* "STM32H7xx", ..., "" unknown */
	struct ardupilot_link link[AP_ROLE_MAX]; /* NULL members: none */
	int batt_monitor;             /* BATT_MONITOR, -1: no monitor known */
	char monitor_part[200];       /* its maker, part number and BOM item */
	int mot_pwm_type;             /* MOT_PWM_TYPE: 0 Normal (PWM), 6 DShot600 */

	/* The harmonic notch and the gyro loop it runs in. */
	double rotor_hz;              /* hover rotor speed / 60 */
	int gyro_rate_hz;             /* 1000, or 2000 when INS_GYRO_RATE is raised */
	bool gyro_rate_raised;        /* write INS_GYRO_RATE 1 (an H7 board) */
	double notch_hz;              /* INS_HNTCH_FREQ as written */
	bool notch_held;              /* the rotor is faster than the loop allows */
	double notch_bw_hz;           /* INS_HNTCH_BW */
	int hmncs;                    /* INS_HNTCH_HMNCS */
	int blade_harmonic_dropped;   /* the blade-pass harmonic lies above the
	                                 loop's limit and is left out (0: kept) */
};

/* Works out d for r's design of record.  Returns 0, or -1 when the design
 * gets no hand-off, with the reason in why: not buildable, or a chemistry
 * the configurator has no name for (Li-S).  m gives the chemistry profile,
 * cat the parts' KV, pitch, blade count and the avionics' kinds. */
int ardupilot_derive(const struct solve_result *r, const struct model_data *m,
                     const struct catalog *cat, struct ardupilot_design *d,
                     char *why, size_t whylen);

/* vehicle_components.json of r with d (ardupilot_derive()), naming the
 * mission name and aeroeval_version.  Ownership: free(). */
char *ardupilot_components(const struct solve_result *r,
                           const struct ardupilot_design *d, const char *name,
                           const char *aeroeval_version);

/* ardupilot.param.  Ownership: free(). */
char *ardupilot_params(const struct ardupilot_design *d, const char *name,
                       const char *aeroeval_version);

/* qgroundcontrol.params: the same parameters, in the same order, for
 * QGroundControl.  Ownership: free(). */
char *ardupilot_params_qgc(const struct ardupilot_design *d, const char *name,
                           const char *aeroeval_version);

#endif
