/* ardupilot.c — vehicle_components.json and the starting parameter files
 * (see ardupilot.h).
 *
 * Parameter names, units and ranges are ArduCopter 4.5's (the @Param blocks
 * of AP_BattMonitor_Params, AP_MotorsMulticopter, HarmonicNotchFilter,
 * AP_InertialSensor and ArduCopter Parameters.cpp): BATT_* volts and mAh,
 * MOT_BAT_VOLT_* volts, MOT_THST_HOVER a thrust fraction in 0.2..0.8,
 * INS_HNTCH_FREQ the base notch frequency in Hz (10..495), INS_HNTCH_BW Hz
 * (5..250, "typically half the base frequency"), INS_HNTCH_REF the
 * throttle-mode reference (0..1), INS_HNTCH_MODE 1 = throttle,
 * INS_HNTCH_HMNCS a bitmask of harmonics (bit 0 the base frequency),
 * BATT_MONITOR 4 analog voltage and current, 8 DroneCAN-BatteryInfo,
 * 21 INA2XX (I2C), MOT_PWM_TYPE 0 Normal (PWM), 6 DShot600, INS_GYRO_RATE
 * 0 = 1 kHz, 1 = 2 kHz (IMUs with fast sampling).
 */
#include "formats/ardupilot.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "formats/bom_csv.h"
#include "util/jsonw.h"
#include "util/numfmt.h"
#include "util/strbuf.h"

/* ArduPilot's documented ranges (see the file comment). */
#define THST_HOVER_MIN 0.2
#define THST_HOVER_MAX 0.8
#define NOTCH_MIN_HZ   10.0
#define NOTCH_MAX_HZ   495.0
#define NOTCH_BW_MIN_HZ 5.0
#define NOTCH_BW_MAX_HZ 250.0

/* The notch's gyro loop.  ArduPilot runs the harmonic notch at the gyro
 * backend rate (AP_InertialSensor initialises it with the gyro's raw
 * sample rate: 1 kHz, or 2 kHz with INS_GYRO_RATE 1 on an IMU that samples
 * fast) and applies a notch only below 0.48 of it
 * (HarmonicNotchFilter::update: the fundamental is constrained to that
 * limit and a notch is enabled only strictly below it). */
#define GYRO_RATE_HZ      1000
#define GYRO_RATE_FAST_HZ 2000
#define NOTCH_NYQUIST     0.48
#define NOTCH_MARGIN      0.47   /* where we put a notch held below the limit */

/* Our chemistry profiles (data/chemistries.json) by the configurator's
 * names, with the per-cell arm, low and critical levels it recommends for
 * that chemistry and the limits it accepts (ArduPilot Methodic
 * Configurator, battery_cell_voltages.py: Lipo 3.8/3.6/3.3 V within
 * 3.0-4.2 V, LipoHV 3.9/3.6/3.3 within 3.0-4.35, LiIon 3.6/3.1/2.8 within
 * 2.5-4.2, LiIonSS 3.6/3.0/2.7 within 2.4-4.2).  Full charge and the
 * lowest loaded voltage come from our profile: they are what the design was
 * sized and flown to.  Li-S has no configurator chemistry: no hand-off. */
static const struct chem_map {
	const char *ours;
	const char *theirs;
	double arm_v, low_v, crit_v;   /* per cell */
	double max_v, min_v;           /* the configurator's limits per cell */
} chem_map[] = {
	{ "LiPo",              "Lipo",    3.8, 3.6, 3.3, 4.2,  3.0 },
	{ "LiPo_standard",     "Lipo",    3.8, 3.6, 3.3, 4.2,  3.0 },
	{ "LiPo_agricultural", "Lipo",    3.8, 3.6, 3.3, 4.2,  3.0 },
	{ "LiHV",              "LipoHV",  3.9, 3.6, 3.3, 4.35, 3.0 },
	{ "LiPo_highvoltage",  "LipoHV",  3.9, 3.6, 3.3, 4.35, 3.0 },
	{ "LiPo_enterprise",   "LipoHV",  3.9, 3.6, 3.3, 4.35, 3.0 },
	{ "LiPo_premium",      "LipoHV",  3.9, 3.6, 3.3, 4.35, 3.0 },
	{ "LiPo_consumer",     "LipoHV",  3.9, 3.6, 3.3, 4.35, 3.0 },
	{ "Li-ion NCA",        "LiIon",   3.6, 3.1, 2.8, 4.2,  2.5 },
	{ "Li-ion NMC",        "LiIon",   3.6, 3.1, 2.8, 4.2,  2.5 },
	{ "Solid State",       "LiIonSS", 3.6, 3.0, 2.7, 4.2,  2.4 },
};

/* FRAME_CLASS by rotor count, plain and coaxial (stacked pairs). */
static const struct frame_map {
	int n_rotors;
	bool coaxial;
	enum ardupilot_frame_class cls;
	const char *name;
	int type;   /* FRAME_TYPE, -1 where ArduPilot ignores it */
} frame_map[] = {
	{ 3, false, AP_FRAME_TRI, "Tri", -1 },
	{ 4, false, AP_FRAME_QUAD, "Quad", AP_FRAME_TYPE_X },
	{ 6, false, AP_FRAME_HEXA, "Hexa", AP_FRAME_TYPE_X },
	{ 8, false, AP_FRAME_OCTA, "Octa", AP_FRAME_TYPE_X },
	{ 10, false, AP_FRAME_DECA, "Deca", AP_FRAME_TYPE_X },
	{ 6, true, AP_FRAME_Y6, "Y6", -1 },
	{ 8, true, AP_FRAME_OCTAQUAD, "OctaQuad", AP_FRAME_TYPE_X },
	{ 12, true, AP_FRAME_DODECAHEXA, "DodecaHexa", AP_FRAME_TYPE_X },
};

static double
clamp(double x, double lo, double hi)
{
	return x < lo ? lo : x > hi ? hi : x;
}

/* x rounded to `decimals` places, so both files print the same short
 * number ("4.2", not 4.2000000000000002). */
static double
round_to(double x, int decimals)
{
	double f = pow(10.0, decimals);
	return round(x * f) / f;
}

static void
derive_pack(const struct res_run *rec, const struct chem_map *cm,
            const struct batt_chem *prof, struct ardupilot_design *d)
{
	d->chemistry = cm->theirs;
	d->chemistry_aeroeval = cm->ours;
	d->cells = rec->cell_count;
	d->capacity_mah = (int)lround(rec->capacity_mah);
	d->cell_max_clamped = prof->v_full > cm->max_v;
	d->cell_max_v = round_to(fmin(prof->v_full, cm->max_v), 3);
	d->cell_arm_v = fmin(cm->arm_v, d->cell_max_v);
	d->cell_low_v = fmin(cm->low_v, d->cell_arm_v);
	d->cell_crit_v = fmin(cm->crit_v, d->cell_low_v);
	d->cell_min_v = round_to(clamp(prof->v_cutoff, cm->min_v, d->cell_low_v), 3);
	d->reserve_soc = rec->reserve_soc;
	d->reserve_mah = rec->reserve_soc > 0.0 ? round(rec->reserve_soc * rec->capacity_mah) : 0.0;
}

static void
derive_frame(const struct solve_result *r, const struct res_run *rec,
             struct ardupilot_design *d)
{
	d->n_rotors = r->mission.num_rotors;
	d->coaxial = r->mission.coaxial_layout;
	d->frame_class = AP_FRAME_UNDEFINED;
	d->frame_class_name = "Undefined";
	d->frame_type = -1;
	for (size_t i = 0; i < sizeof frame_map / sizeof frame_map[0]; i++)
		if (frame_map[i].n_rotors == d->n_rotors && frame_map[i].coaxial == d->coaxial) {
			d->frame_class = frame_map[i].cls;
			d->frame_class_name = frame_map[i].name;
			d->frame_type = frame_map[i].type;
		}
	/* Takeoff weights: the empty aircraft with its pack, and with the
	 * largest payload it is built for (max_payload_kg, 0 = payload_kg). */
	double payload = rec->mass.payload_kg;
	double largest = fmax(payload, r->mission.max_payload_kg);
	d->takeoff_mass_kg = rec->mass.total_kg;
	d->tow_min_kg = round_to(rec->mass.total_kg - payload, 3);
	d->tow_max_kg = round_to(rec->mass.total_kg - payload + largest, 3);
}

static void
derive_drive(const struct solve_result *r, const struct res_run *rec,
             const struct catalog *cat, struct ardupilot_design *d)
{
	const struct catalog_motor *mo = cat ? catalog_find_motor(cat, r->motor.id) : NULL;
	const struct catalog_prop *pr = cat ? catalog_find_prop(cat, r->prop.id) : NULL;
	d->motor_kv = mo ? mo->kv_rpm_per_v : 0.0;
	d->esc_in_motor = mo != NULL && mo->integrated;
	d->prop_diameter_in = pr ? pr->diameter_in : rec->opt.prop_diameter_in;
	d->prop_pitch_in = pr ? pr->pitch_in : rec->opt.prop_pitch_in;
	d->blades = pr && pr->blades > 0 ? pr->blades : r->mission.structural_overrides.num_blades;
	if (d->blades < 2)
		d->blades = 2;
	const struct res_op *hover = &rec->perf.op[OP_HOVER], *full = &rec->perf.op[OP_FULL];
	bool drive = rec->perf.valid && hover->valid;
	d->hover_rpm = drive ? hover->rpm : rec->rpm_hover;
	d->hover_thrust_n = drive ? hover->thrust_n : 0.0;
	d->full_thrust_n = drive && full->valid ? full->thrust_n : 0.0;
	d->hover_throttle = drive ? hover->throttle : rec->hover_throttle;
	/* MOT_THST_HOVER is a thrust fraction (ArduPilot linearises thrust
	 * before the motor output), not the speed ratio the design calls its
	 * hover throttle; without a full-throttle point, the throttle stands in. */
	double t = d->full_thrust_n > 0.0 ? d->hover_thrust_n / d->full_thrust_n : d->hover_throttle;
	d->thrust_hover_clamped = t < THST_HOVER_MIN || t > THST_HOVER_MAX;
	d->thrust_hover = round_to(clamp(t, THST_HOVER_MIN, THST_HOVER_MAX), 3);
}

/* ---- the bill of materials, component by component --------------------------- */

const char *const ardupilot_role_name[AP_ROLE_MAX] = {
	"Flight Controller", "Battery Monitor", "GNSS Receiver", "RC Receiver",
	"Telemetry", "ESC", "Motors", "Propellers", "Battery", "Frame",
};

/* Does the part's catalogue text (part number and description) name w? */
static bool
names(const char *part_number, const char *description, const char *w)
{
	return strstr(part_number, w) != NULL || strstr(description, w) != NULL;
}

/* The avionics role of a catalogue kind, or -1. */
static int
avionics_role(const char *kind)
{
	static const struct { const char *kind; enum ardupilot_role role; } map[] = {
		{ "flight_controller", AP_ROLE_FC }, { "power_module", AP_ROLE_MONITOR },
		{ "pdb", AP_ROLE_MONITOR }, { "gnss", AP_ROLE_GNSS },
		{ "receiver", AP_ROLE_RX }, { "telemetry", AP_ROLE_TELEM },
	};
	for (size_t i = 0; i < sizeof map / sizeof map[0]; i++)
		if (strcmp(kind, map[i].kind) == 0)
			return (int)map[i].role;
	return -1;
}

/* The battery monitor's interface, from what its catalogue entry says:
 * CAN (DroneCAN, UAVCAN) before "digital" (a digital CAN module), then an
 * I2C or digital module (INA2xx-class monitors, ArduPilot's INA2XX driver),
 * then analog. */
static void
monitor_link(const char *pn, const char *desc, struct ardupilot_design *d)
{
	struct ardupilot_link *l = &d->link[AP_ROLE_MONITOR];
	if (names(pn, desc, "CAN")) {
		*l = (struct ardupilot_link){ "CAN1", "DroneCAN-BatteryInfo" };
		d->batt_monitor = 8;
	} else if (names(pn, desc, "I2C") || names(pn, desc, "digital")) {
		*l = (struct ardupilot_link){ "I2C1", "INA2XX" };
		d->batt_monitor = 21;
	} else if (names(pn, desc, "analog")) {
		*l = (struct ardupilot_link){ "Analog", "Analog Voltage and Current" };
		d->batt_monitor = 4;
	}
}

/* The microcontroller series a flight controller's text names. */
static const char *
mcu_of(const char *pn, const char *desc)
{
	static const char *const series[][2] = {
		{ "H7", "STM32H7xx" }, { "F7", "STM32F7xx" }, { "F4", "STM32F4xx" },
	};
	for (size_t i = 0; i < sizeof series / sizeof series[0]; i++)
		if (names(pn, desc, series[i][0]))
			return series[i][1];
	return "";
}

/* The components the bill of materials buys (d->line) and how each
 * connects (d->link). */
static void
derive_bom(const struct solve_result *r, const struct catalog *cat,
           struct ardupilot_design *d)
{
	for (int k = 0; k < AP_ROLE_MAX; k++)
		d->line[k] = -1;
	d->mcu = "";
	d->batt_monitor = -1;
	const struct catalog_esc *esc = NULL;
	int n = r->n_bom < 0 ? 0 : r->n_bom > RES_MAX_BOM ? RES_MAX_BOM : r->n_bom;
	for (int i = 0; i < n; i++) {
		const struct res_bom_line *b = &r->bom[i];
		int role = -1;
		if (strcmp(b->category, "motor") == 0)
			role = AP_ROLE_MOTOR;
		else if (strcmp(b->category, "propeller") == 0)
			role = AP_ROLE_PROP;
		else if (strcmp(b->category, "battery") == 0)
			role = AP_ROLE_BATTERY;
		else if (strcmp(b->category, "frame") == 0)
			role = AP_ROLE_FRAME;
		else if (strcmp(b->category, "esc") == 0) {
			role = AP_ROLE_ESC;
			esc = cat ? catalog_find_esc(cat, b->catalogue_id) : NULL;
		} else if (strcmp(b->category, "avionics") == 0 && cat != NULL) {
			const struct catalog_avionics *a = catalog_find_avionics(cat, b->catalogue_id);
			role = a != NULL ? avionics_role(a->kind) : -1;
			if (role == AP_ROLE_MONITOR && d->line[role] < 0)
				monitor_link(a->part_number, a->description, d);
			if (role == AP_ROLE_FC && d->line[role] < 0)
				d->mcu = mcu_of(a->part_number, a->description);
		}
		if (role >= 0 && d->line[role] < 0)
			d->line[role] = i;   /* the first: propellers CW before CCW */
	}
	/* An all-in-one board: the ESC board is the flight controller (and
	 * the receiver) the bill of materials does not buy apart. */
	if (esc != NULL && d->line[AP_ROLE_FC] < 0
	    && catalog_list_names(esc->carries, "flight_controller")) {
		d->line[AP_ROLE_FC] = d->line[AP_ROLE_ESC];
		d->fc_on_esc = true;
		d->mcu = mcu_of(esc->part_number, "");
	}
	if (esc != NULL && d->line[AP_ROLE_RX] < 0 && catalog_list_names(esc->carries, "receiver")) {
		d->line[AP_ROLE_RX] = d->line[AP_ROLE_ESC];
		d->rx_on_esc = true;
	}

	/* GNSS on the CAN bus or the GPS1 port (SERIAL3); CRSF receivers
	 * (Crossfire, Tracer, ExpressLRS) on TELEM2 (SERIAL2), others on RCin;
	 * the telemetry radio on TELEM1 (SERIAL1): a Pixhawk standard board. */
	int g = d->line[AP_ROLE_GNSS], x = d->line[AP_ROLE_RX];
	if (g >= 0)
		d->link[AP_ROLE_GNSS] = names(r->bom[g].part_number, r->bom[g].description, "CAN")
		    ? (struct ardupilot_link){ "CAN1", "DroneCAN" }
		    : (struct ardupilot_link){ "SERIAL3", "AUTO" };
	if (x >= 0 && !d->rx_on_esc) {
		const char *pn = r->bom[x].part_number, *desc = r->bom[x].description;
		d->link[AP_ROLE_RX] = names(pn, desc, "Crossfire") || names(pn, desc, "Tracer")
		    || names(pn, desc, "ELRS") || names(pn, desc, "ExpressLRS")
		    ? (struct ardupilot_link){ "SERIAL2", "CRSF" }
		    : (struct ardupilot_link){ "RCin/SBUS", "All" };
	}
	if (d->line[AP_ROLE_TELEM] >= 0)
		d->link[AP_ROLE_TELEM] = (struct ardupilot_link){ "SERIAL1", "MAVLink2" };

	/* The ESC protocol: DShot on the boards of the FPV kind (4-in-1 and
	 * all-in-one boards, whose BLHeli, Bluejay and AM32 firmwares take
	 * DShot600), standard PWM on single ESCs and integrated systems,
	 * which every multirotor ESC accepts (the catalogue lists no digital
	 * protocol for them). */
	bool dshot = esc != NULL && (esc->channels == 4 || esc->carries[0] != '\0');
	d->mot_pwm_type = dshot ? 6 : 0;
	d->link[AP_ROLE_ESC] = (struct ardupilot_link){ d->fc_on_esc ? "AIO" : "Main Out",
		dshot ? "DShot600" : "Normal" };
	if (d->line[AP_ROLE_ESC] < 0 && d->esc_in_motor)
		d->line[AP_ROLE_ESC] = d->line[AP_ROLE_MOTOR];
	int m = d->line[AP_ROLE_MONITOR];
	if (m >= 0)
		snprintf(d->monitor_part, sizeof d->monitor_part, "%s %s, bill of materials item "
		    "%d", r->bom[m].manufacturer, r->bom[m].part_number, r->bom[m].item);
}

/* The notch at the hover rotor speed, within what the gyro loop allows.
 * When the rotor or its blade-pass harmonic is beyond a 1 kHz loop, an H7
 * board samples its IMUs fast enough for a 2 kHz loop (INS_GYRO_RATE 1, the
 * wiki's setting for H7 boards); any other keeps 1 kHz: a notch on a faster
 * rotor is held at 470 Hz, the highest it acts at, where its bandwidth
 * still reaches the rotor, and a blade-pass harmonic beyond the limit is
 * left out of INS_HNTCH_HMNCS (ArduPilot would not enable it). */
static void
derive_notch(struct ardupilot_design *d)
{
	d->rotor_hz = d->hover_rpm / 60.0;
	d->gyro_rate_hz = GYRO_RATE_HZ;
	bool slow = d->rotor_hz > NOTCH_MARGIN * GYRO_RATE_HZ
	    || (d->blades <= 8 && d->blades * d->rotor_hz >= NOTCH_NYQUIST * GYRO_RATE_HZ);
	if (slow && strcmp(d->mcu, "STM32H7xx") == 0) {
		d->gyro_rate_hz = GYRO_RATE_FAST_HZ;
		d->gyro_rate_raised = true;
	}
	double top = fmin(NOTCH_MARGIN * d->gyro_rate_hz, NOTCH_MAX_HZ);
	d->notch_held = d->rotor_hz > top;
	d->notch_hz = round_to(clamp(d->rotor_hz, NOTCH_MIN_HZ, top), 1);
	d->notch_bw_hz = round_to(clamp(d->notch_hz / 2.0, NOTCH_BW_MIN_HZ, NOTCH_BW_MAX_HZ), 1);
	/* The base frequency, and the blade-pass frequency (harmonic `blades`)
	 * when ArduPilot would enable a notch there (HMNCS has 8 bits). */
	d->hmncs = 1;
	if (d->blades <= 8 && d->blades * d->notch_hz < NOTCH_NYQUIST * d->gyro_rate_hz)
		d->hmncs |= 1 << (d->blades - 1);
	else
		d->blade_harmonic_dropped = d->blades;
}

int
ardupilot_derive(const struct solve_result *r, const struct model_data *m,
                 const struct catalog *cat, struct ardupilot_design *d,
                 char *why, size_t whylen)
{
	bool buildable;
	const struct res_run *rec = res_record(r, &buildable);
	memset(d, 0, sizeof *d);
	if (!buildable) {
		snprintf(why, whylen, "the design of record is not buildable");
		return -1;
	}
	const struct chem_map *cm = NULL;
	for (size_t i = 0; i < sizeof chem_map / sizeof chem_map[0]; i++)
		if (strcmp(chem_map[i].ours, rec->chemistry) == 0)
			cm = &chem_map[i];
	const struct batt_chem *prof = model_chem(m, rec->chemistry);
	if (cm == NULL || prof == NULL) {
		snprintf(why, whylen, "the Methodic Configurator has no battery chemistry "
		    "for \"%s\"", rec->chemistry);
		return -1;
	}
	if (rec->cell_count < 1 || !(rec->capacity_mah > 0.0)) {
		snprintf(why, whylen, "the design of record has no pack");
		return -1;
	}
	derive_pack(rec, cm, prof, d);
	derive_frame(r, rec, d);
	derive_drive(r, rec, cat, d);
	derive_bom(r, cat, d);
	derive_notch(d);
	d->feasible = rec->feasible;
	return 0;
}

/* ---- vehicle_components.json ----------------------------------------------- */

/* x, printed exactly by jsonw (derive checks that it is finite). */
static void
add_num(cJSON *o, const char *key, double x)
{
	cJSON_AddNumberToObject(o, key, x);
}

/* Product {Manufacturer, Model, URL, Version}: the schema requires the
 * first two; "" is what the configurator's templates write when unknown. */
static void
add_product(cJSON *comp, const char *maker, const char *model, const char *url)
{
	cJSON *p = cJSON_AddObjectToObject(comp, "Product");
	cJSON_AddStringToObject(p, "Manufacturer", maker);
	cJSON_AddStringToObject(p, "Model", model);
	cJSON_AddStringToObject(p, "URL", url);
	cJSON_AddStringToObject(p, "Version", "");
}

static void
add_pair(cJSON *comp, const char *key, const char *a_key, const char *a,
         const char *b_key, const char *b)
{
	cJSON *o = cJSON_AddObjectToObject(comp, key);
	cJSON_AddStringToObject(o, a_key, a);
	cJSON_AddStringToObject(o, b_key, b);
}

/* A component from the BOM line of its role: the line's maker and
 * orderable part number, the maker's page; NULL when not bought. */
static cJSON *
bought(cJSON *comps, const struct solve_result *r, const struct ardupilot_design *d,
       enum ardupilot_role role)
{
	if (d->line[role] < 0)
		return NULL;
	const struct res_bom_line *b = &r->bom[d->line[role]];
	cJSON *c = cJSON_AddObjectToObject(comps, ardupilot_role_name[role]);
	add_product(c, b->manufacturer, bom_csv_part_number(r, b), b->source_url);
	return c;
}

/* A component the bill of materials does not buy: its product empty, as
 * the configurator's own template leaves it. */
static cJSON *
not_bought(cJSON *comps, enum ardupilot_role role)
{
	cJSON *c = cJSON_AddObjectToObject(comps, ardupilot_role_name[role]);
	add_product(c, "", "", "");
	return c;
}

/* Firmware {Type, Version} empty and the FC Connection of a role. */
static void
add_link(cJSON *c, const struct ardupilot_design *d, enum ardupilot_role role)
{
	const struct ardupilot_link *l = &d->link[role];
	add_pair(c, "Firmware", "Type", "", "Version", "");
	add_pair(c, "FC Connection", "Type", l->type ? l->type : "None",
	    "Protocol", l->protocol ? l->protocol : "None");
}

static void
notes(cJSON *comp, const struct strbuf *sb)
{
	cJSON_AddStringToObject(comp, "Notes", strbuf_str(sb));
}

/* "item N of the bill of materials: qty x description." */
static void
line_note(struct strbuf *sb, const struct solve_result *r, const struct ardupilot_design *d,
          enum ardupilot_role role)
{
	const struct res_bom_line *b = &r->bom[d->line[role]];
	strbuf_printf(sb, "Bill of materials item %d: %d x %s (%s).", b->item, b->qty,
	    bom_csv_part_number(r, b), b->description);
}

static void
add_fc(cJSON *comps, const struct solve_result *r, const struct ardupilot_design *d)
{
	struct strbuf sb = STRBUF_INIT;
	cJSON *c = bought(comps, r, d, AP_ROLE_FC);
	if (c == NULL) {
		c = not_bought(comps, AP_ROLE_FC);
		strbuf_append_str(&sb, "The bill of materials buys no flight controller: "
		    "choose one.");
	} else {
		line_note(&sb, r, d, AP_ROLE_FC);
		if (d->fc_on_esc)
			strbuf_append_str(&sb, "  An all-in-one board: the flight controller "
			    "and the ESCs are one part.");
	}
	add_pair(c, "Firmware", "Type", "ArduCopter", "Version", "");
	cJSON_AddStringToObject(cJSON_AddObjectToObject(c, "Specifications"), "MCU Series",
	    d->mcu);
	notes(c, &sb);
	strbuf_free(&sb);
}

static void
add_frame(cJSON *comps, const struct solve_result *r, const struct ardupilot_design *d)
{
	const struct res_run *rec = &r->closed;
	struct strbuf sb = STRBUF_INIT;
	cJSON *c = bought(comps, r, d, AP_ROLE_FRAME);
	if (c == NULL) {
		c = cJSON_AddObjectToObject(comps, "Frame");
		strbuf_printf(&sb, "Custom %d-rotor%s frame", d->n_rotors, d->coaxial ? " coaxial" : "");
		add_product(c, "", strbuf_str(&sb), "");
		strbuf_reset(&sb);
	}
	cJSON *s = cJSON_AddObjectToObject(c, "Specifications");
	add_num(s, "TOW min Kg", d->tow_min_kg);
	add_num(s, "TOW max Kg", d->tow_max_kg);
	cJSON_AddStringToObject(s, "Frame class", d->frame_class_name);
	if (d->line[AP_ROLE_FRAME] >= 0) {
		line_note(&sb, r, d, AP_ROLE_FRAME);
		strbuf_append_str(&sb, "  ");
	}
	strbuf_printf(&sb, "aeroeval design of record: takeoff mass %.3f kg with %.3f kg "
	    "payload; TOW min is without payload, TOW max with the largest payload.  "
	    "Wheelbase %.3f m", d->takeoff_mass_kg, rec->mass.payload_kg,
	    r->mission.max_diameter_m);
	if (d->line[AP_ROLE_FRAME] < 0)
		strbuf_printf(&sb, "; CFRP arm tubes OD %.1f mm x wall %.2f mm, %.0f mm long",
		    rec->arm_outer_diameter_mm, rec->arm_wall_thickness_mm, 1000.0 * rec->arm_length_m);
	strbuf_append_str(&sb, ".");
	notes(c, &sb);
	strbuf_free(&sb);
}

/* Why BATT_MONITOR is not written, with what to do. */
static const char *
monitor_missing(const struct ardupilot_design *d)
{
	if (d->line[AP_ROLE_MONITOR] >= 0)
		return "the battery monitor's catalogue entry does not say how it "
		    "connects; set it for that monitor";
	if (d->fc_on_esc)
		return "the bill of materials buys no battery monitor apart from the "
		    "all-in-one board, whose catalogue entry does not say whether it senses "
		    "the current; set BATT_MONITOR 4 (analog voltage and current) if it does";
	return "the bill of materials buys no battery monitor; set it for the monitor "
	    "fitted";
}

static void
add_monitor(cJSON *comps, const struct solve_result *r, const struct ardupilot_design *d)
{
	struct strbuf sb = STRBUF_INIT;
	cJSON *c = bought(comps, r, d, AP_ROLE_MONITOR);
	if (c == NULL) {
		c = not_bought(comps, AP_ROLE_MONITOR);
		add_pair(c, "Firmware", "Type", "", "Version", "");
		add_pair(c, "FC Connection", "Type", "None", "Protocol", "Disabled");
		strbuf_printf(&sb, "BATT_MONITOR is not set: %s.  The BATT_ values of "
		    "ardupilot.param apply once it is.", monitor_missing(d));
	} else {
		add_link(c, d, AP_ROLE_MONITOR);
		line_note(&sb, r, d, AP_ROLE_MONITOR);
		if (d->batt_monitor < 0)
			strbuf_append_str(&sb, "  Its catalogue entry does not say how it connects: "
			    "set its FC Connection and BATT_MONITOR.");
	}
	notes(c, &sb);
	strbuf_free(&sb);
}

static void
add_battery(cJSON *comps, const struct solve_result *r, const struct ardupilot_design *d)
{
	struct strbuf sb = STRBUF_INIT;
	cJSON *c = bought(comps, r, d, AP_ROLE_BATTERY);
	if (c == NULL) {  /* never: a buildable design has its pack */
		c = cJSON_AddObjectToObject(comps, "Battery");
		add_product(c, r->battery.manufacturer, r->battery.part_number, r->battery.source_url);
	}
	cJSON *s = cJSON_AddObjectToObject(c, "Specifications");
	cJSON_AddStringToObject(s, "Chemistry", d->chemistry);
	add_num(s, "Volt per cell max", d->cell_max_v);
	add_num(s, "Volt per cell arm", d->cell_arm_v);
	add_num(s, "Volt per cell low", d->cell_low_v);
	add_num(s, "Volt per cell crit", d->cell_crit_v);
	add_num(s, "Volt per cell min", d->cell_min_v);
	add_num(s, "Number of cells", d->cells);
	add_num(s, "Capacity mAh", d->capacity_mah);
	if (d->line[AP_ROLE_BATTERY] >= 0) {
		line_note(&sb, r, d, AP_ROLE_BATTERY);
		strbuf_append_str(&sb, "  ");
	}
	strbuf_printf(&sb, "%d pack%s, %d in series x %d in parallel: %dS %d mAh (%s).",
	    r->battery.qty, r->battery.qty == 1 ? "" : "s", r->battery_series_packs,
	    r->battery_parallel_packs, d->cells, d->capacity_mah, d->chemistry_aeroeval);
	if (d->cell_max_clamped)
		strbuf_printf(&sb, "  Its full charge is above what the configurator accepts "
		    "for %s: Volt per cell max is that limit.", d->chemistry);
	notes(c, &sb);
	strbuf_free(&sb);
}

/* GNSS, RC receiver and telemetry radio: bought, with their link. */
static void
add_radio(cJSON *comps, const struct solve_result *r, const struct ardupilot_design *d,
          enum ardupilot_role role)
{
	cJSON *c = bought(comps, r, d, role);
	if (c == NULL)
		return;
	struct strbuf sb = STRBUF_INIT;
	if (role == AP_ROLE_RX && d->rx_on_esc) {
		add_pair(c, "Firmware", "Type", "", "Version", "");
		line_note(&sb, r, d, role);
		strbuf_append_str(&sb, "  The receiver is on the all-in-one board.");
	} else {
		add_link(c, d, role);
		line_note(&sb, r, d, role);
		if (d->link[role].type[0] == 'S')
			strbuf_printf(&sb, "  Port as wired on a Pixhawk standard board; change it "
			    "to the port it is wired to.");
	}
	notes(c, &sb);
	strbuf_free(&sb);
}

static void
add_drive(cJSON *comps, const struct solve_result *r, const struct ardupilot_design *d)
{
	struct strbuf sb = STRBUF_INIT;
	cJSON *c = bought(comps, r, d, AP_ROLE_ESC);
	if (c != NULL) {
		add_pair(c, "Firmware", "Type", "", "Version", "");
		add_pair(c, "FC Connection", "Type", d->link[AP_ROLE_ESC].type, "Protocol",
		    d->link[AP_ROLE_ESC].protocol);
		line_note(&sb, r, d, AP_ROLE_ESC);
		if (d->esc_in_motor && r->esc.qty == 0)
			strbuf_append_str(&sb, "  The ESC is inside the integrated motor system.");
		strbuf_printf(&sb, "  Protocol %s: MOT_PWM_TYPE %d in ardupilot.param.",
		    d->mot_pwm_type == 6 ? "DShot600, which the firmwares of 4-in-1 and "
		    "all-in-one boards take" : "Normal (PWM), which every multirotor ESC accepts",
		    d->mot_pwm_type);
		notes(c, &sb);
	}

	c = bought(comps, r, d, AP_ROLE_MOTOR);
	if (c != NULL) {
		strbuf_reset(&sb);
		line_note(&sb, r, d, AP_ROLE_MOTOR);
		strbuf_printf(&sb, "  %.0f KV (rpm/V), %.0f g each; hover %.0f rpm at takeoff "
		    "mass.  Pole count: not in the catalogue.", d->motor_kv,
		    1000.0 * r->motor.unit_mass_kg, d->hover_rpm);
		notes(c, &sb);
	}

	c = bought(comps, r, d, AP_ROLE_PROP);
	if (c != NULL) {
		cJSON *s = cJSON_AddObjectToObject(c, "Specifications");
		add_num(s, "Diameter_inches", d->prop_diameter_in);
		strbuf_reset(&sb);
		strbuf_printf(&sb, "%d propellers, diameter %.1f in, pitch %.1f in, %d blades "
		    "(%s), half of them CCW.", r->prop.qty, d->prop_diameter_in, d->prop_pitch_in,
		    d->blades, r->prop.description);
		notes(c, &sb);
	}
	strbuf_free(&sb);
}

char *
ardupilot_components(const struct solve_result *r, const struct ardupilot_design *d,
                     const char *name, const char *aeroeval_version)
{
	cJSON *root = cJSON_CreateObject();
	add_num(root, "Format version", 1);
	cJSON *comps = cJSON_AddObjectToObject(root, "Components");
	add_fc(comps, r, d);
	add_frame(comps, r, d);
	add_monitor(comps, r, d);
	add_battery(comps, r, d);
	add_drive(comps, r, d);
	add_radio(comps, r, d, AP_ROLE_GNSS);
	add_radio(comps, r, d, AP_ROLE_RX);
	add_radio(comps, r, d, AP_ROLE_TELEM);
	cJSON_AddStringToObject(root, "Program version", aeroeval_version);
	struct strbuf sb = STRBUF_INIT;
	strbuf_printf(&sb, "aeroeval %s", name);
	cJSON_AddStringToObject(root, "Configuration template", strbuf_str(&sb));
	strbuf_free(&sb);
	char *text = jsonw_print(root, NULL);
	cJSON_Delete(root);
	return text;
}

/* ---- the parameter files ---------------------------------------------------- */

#define MAX_PARAMS 32

/* MAVLink parameter types (MAV_PARAM_TYPE) of the values written, for
 * QGroundControl's fifth column: ArduPilot's AP_Int8, AP_Int32, AP_Float. */
enum mav_type { MAV_INT8 = 2, MAV_INT32 = 6, MAV_REAL32 = 9 };

struct param {
	char name[17];        /* ArduPilot names have at most 16 characters */
	double value;
	enum mav_type type;
	bool reboot;          /* takes effect (or shows its group) after a reboot */
	char comment[400];    /* how it was derived, its own line */
	const char *section;  /* a heading before it, or NULL */
};

struct params {
	struct param p[MAX_PARAMS];
	int n;
	const char *section;  /* the heading the next parameter opens */
};

/* A heading for the parameters that follow. */
static void
section(struct params *ps, const char *title)
{
	ps->section = title;
}

__attribute__((format(printf, 6, 7)))
static void
set(struct params *ps, const char *name, double value, enum mav_type type, bool reboot,
    const char *fmt, ...)
{
	if (ps->n >= MAX_PARAMS)
		return;
	struct param *p = &ps->p[ps->n++];
	snprintf(p->name, sizeof p->name, "%s", name);
	p->value = value;
	p->type = type;
	p->reboot = reboot;
	p->section = ps->section;
	ps->section = NULL;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(p->comment, sizeof p->comment, fmt, ap);
	va_end(ap);
	/* One line of ASCII, whatever a catalogue text holds. */
	for (char *c = p->comment; *c != '\0'; c++)
		if (*c == '\r' || *c == '\n' || *c == '\t' || (unsigned char)*c >= 0x80)
			*c = ' ';
}

static void
frame_params(struct params *ps, const struct ardupilot_design *d)
{
	if (d->frame_class == AP_FRAME_UNDEFINED)
		return;
	section(ps, "Frame");
	set(ps, "FRAME_CLASS", d->frame_class, MAV_INT8, true, "%s: %d rotors%s", d->frame_class_name,
	    d->n_rotors, d->coaxial ? " in coaxial pairs" : "");
	if (d->frame_type >= 0)
		set(ps, "FRAME_TYPE", d->frame_type, MAV_INT8, true, "X: the motor order of the "
		    "frame as built decides; check it against ArduPilot's motor diagrams");
}

static void
motor_params(struct params *ps, const struct ardupilot_design *d)
{
	int n = d->cells;
	section(ps, "Motors and ESCs");
	set(ps, "MOT_PWM_TYPE", d->mot_pwm_type, MAV_INT8, true, "%s: the ESC protocol of "
	    "vehicle_components.json", d->mot_pwm_type == 6 ? "DShot600, which 4-in-1 and "
	    "all-in-one FPV boards take" : "Normal (PWM), which every multirotor ESC accepts");
	set(ps, "MOT_BAT_VOLT_MAX", round_to(n * d->cell_max_v, 2), MAV_REAL32, false,
	    "%d cells x %.2f V full charge (%s profile%s)", n, d->cell_max_v, d->chemistry_aeroeval,
	    d->cell_max_clamped ? ", held to the configurator's limit" : "");
	set(ps, "MOT_BAT_VOLT_MIN", round_to(n * d->cell_min_v, 2), MAV_REAL32, false,
	    "%d cells x %.2f V: the lowest loaded cell voltage the design was flown to", n,
	    d->cell_min_v);
	if (d->full_thrust_n > 0.0)
		set(ps, "MOT_THST_HOVER", d->thrust_hover, MAV_REAL32, false, "hover thrust / "
		    "full-throttle thrust per rotor: %.2f N / %.2f N%s (hover throttle %.2f by "
		    "speed); learnt in flight with MOT_HOVER_LEARN", d->hover_thrust_n,
		    d->full_thrust_n, d->thrust_hover_clamped ? ", held to 0.2..0.8" : "",
		    d->hover_throttle);
	else
		set(ps, "MOT_THST_HOVER", d->thrust_hover, MAV_REAL32, false, "the design's hover "
		    "throttle%s", d->thrust_hover_clamped ? ", held to 0.2..0.8" : "");
}

static void
battery_params(struct params *ps, const struct ardupilot_design *d)
{
	int n = d->cells;
	section(ps, "Battery monitor");
	if (d->batt_monitor >= 0)
		set(ps, "BATT_MONITOR", d->batt_monitor, MAV_INT8, true, "%s, the power module "
		    "the bill of materials buys (%s); the BATT_ parameters below exist once it "
		    "is set", d->link[AP_ROLE_MONITOR].protocol, d->monitor_part);
	set(ps, "BATT_CAPACITY", d->capacity_mah, MAV_INT32, false, "pack of record: %dS %d mAh",
	    n, d->capacity_mah);
	if (d->reserve_mah > 0.0)
		set(ps, "BATT_LOW_MAH", d->reserve_mah, MAV_REAL32, false, "the design's landing "
		    "reserve: %.1f %% of %d mAh left", 100.0 * d->reserve_soc, d->capacity_mah);
	set(ps, "BATT_ARM_VOLT", round_to(n * d->cell_arm_v, 2), MAV_REAL32, false, "%d cells x "
	    "%.2f V: arm only on a charged pack (%s arm level)", n, d->cell_arm_v, d->chemistry);
	set(ps, "BATT_LOW_VOLT", round_to(n * d->cell_low_v, 2), MAV_REAL32, false, "%d cells x "
	    "%.2f V (%s low level)", n, d->cell_low_v, d->chemistry);
	set(ps, "BATT_CRT_VOLT", round_to(n * d->cell_crit_v, 2), MAV_REAL32, false, "%d cells x "
	    "%.2f V (%s critical level)", n, d->cell_crit_v, d->chemistry);
}

static void
notch_params(struct params *ps, const struct ardupilot_design *d)
{
	section(ps, "Harmonic notch on the motor noise");
	if (d->gyro_rate_raised)
		set(ps, "INS_GYRO_RATE", 1, MAV_INT8, true, "2 kHz gyro loop: the rotor (%.0f Hz) "
		    "or its %d-blade pass (%.0f Hz) is above the %.0f Hz a 1 kHz loop notches "
		    "(ArduPilot notches below 0.48 x the gyro rate), and the %s flight controller "
		    "samples its IMUs fast enough", d->rotor_hz, d->blades, d->blades * d->rotor_hz,
		    NOTCH_NYQUIST * GYRO_RATE_HZ, d->mcu);
	set(ps, "INS_HNTCH_ENABLE", 1, MAV_INT8, true, "harmonic notch on; the INS_HNTCH_ "
	    "parameters below exist once it is set");
	set(ps, "INS_HNTCH_MODE", 1, MAV_INT8, false, "throttle-based: the notch follows the "
	    "thrust");
	if (d->notch_held && d->rotor_hz > NOTCH_MARGIN * d->gyro_rate_hz)
		set(ps, "INS_HNTCH_FREQ", d->notch_hz, MAV_REAL32, false, "hover rotor speed "
		    "%.0f rpm / 60 = %.0f Hz is above what the %d Hz gyro loop notches (0.48 x "
		    "its rate%s): held at %.0f Hz, the highest the notch acts at; an ESC-"
		    "telemetry notch (INS_HNTCH_MODE 3) tracks this rotor better", d->hover_rpm,
		    d->rotor_hz, d->gyro_rate_hz, d->mcu[0] != '\0' && !d->gyro_rate_raised
		    ? "; the flight controller's CPU keeps it at 1 kHz" : "", d->notch_hz);
	else if (d->notch_held)
		set(ps, "INS_HNTCH_FREQ", d->notch_hz, MAV_REAL32, false, "hover rotor speed "
		    "%.0f rpm / 60 = %.0f Hz, held to the parameter's %.0f Hz maximum",
		    d->hover_rpm, d->rotor_hz, d->notch_hz);
	else
		set(ps, "INS_HNTCH_FREQ", d->notch_hz, MAV_REAL32, false, "hover rotor speed "
		    "%.0f rpm / 60%s", d->hover_rpm, d->rotor_hz < NOTCH_MIN_HZ ? ", held to the "
		    "10 Hz minimum" : "");
	set(ps, "INS_HNTCH_BW", d->notch_bw_hz, MAV_REAL32, false, "half the base frequency, as "
	    "ArduPilot's notch setup advises");
	set(ps, "INS_HNTCH_REF", d->thrust_hover, MAV_REAL32, true, "= MOT_THST_HOVER: the thrust "
	    "at which the notch sits at INS_HNTCH_FREQ");
	if (d->blade_harmonic_dropped == 0)
		set(ps, "INS_HNTCH_HMNCS", d->hmncs, MAV_INT8, true, "base frequency and harmonic %d, "
		    "the blade-pass frequency of the %d-blade propellers (%.1f Hz in hover)",
		    d->blades, d->blades, d->blades * d->notch_hz);
	else
		set(ps, "INS_HNTCH_HMNCS", d->hmncs, MAV_INT8, true, "base frequency only: harmonic "
		    "%d, the blade-pass frequency of the %d-blade propellers (%.0f Hz), is above "
		    "the %.0f Hz the %d Hz gyro loop notches", d->blades, d->blades,
		    d->blades * d->notch_hz, NOTCH_NYQUIST * d->gyro_rate_hz, d->gyro_rate_hz);
}

/* Every parameter, enable parameters before those they enable. */
static void
all_params(struct params *ps, const struct ardupilot_design *d)
{
	ps->n = 0;
	ps->section = NULL;
	frame_params(ps, d);
	motor_params(ps, d);
	battery_params(ps, d);
	notch_params(ps, d);
}

/* The header both files share, each line after `lead` ("# "). */
static void
header(struct strbuf *sb, const struct params *ps, const struct ardupilot_design *d,
       const char *name, const char *aeroeval_version, const char *format)
{
	strbuf_printf(sb, "# ArduCopter parameters for %s, derived by aeroeval %s from its\n"
	    "# design of record: real parts, %s, takeoff mass %.3f kg.\n", name, aeroeval_version,
	    d->feasible ? "every check passes" : "SOME CHECKS FAIL (see the dossier)",
	    d->takeoff_mass_kg);
	strbuf_printf(sb, "# Firmware: ArduCopter 4.5 or later (the parameter names, units "
	    "and ranges of its\n# documentation).\n# %s\n", format);
	strbuf_append_str(sb, "# Reboot required after writing:");
	for (int i = 0, k = 0; i < ps->n; i++)
		if (ps->p[i].reboot)
			strbuf_printf(sb, "%s %s", k++ == 0 ? "" : ",", ps->p[i].name);
	strbuf_append_str(sb, ".\n# Enable parameters come first: BATT_MONITOR and "
	    "INS_HNTCH_ENABLE make the BATT_ and\n# INS_HNTCH_ parameters exist only after "
	    "that reboot, so load this file, write,\n# reboot, and load it again; the "
	    "second pass sets the rest.\n");
	if (d->frame_class == AP_FRAME_UNDEFINED)
		strbuf_printf(sb, "# FRAME_CLASS is not set: ArduPilot has no frame class for "
		    "%d rotors%s.\n", d->n_rotors, d->coaxial ? " in coaxial pairs" : "");
	if (d->batt_monitor < 0)
		strbuf_printf(sb, "# BATT_MONITOR is not set: %s.\n", monitor_missing(d));
	strbuf_append_str(sb, "# Everything else (failsafe actions, radio, ports, gains) is "
	    "the configurator's to set.\n");
}

/* The value as ArduPilot's loaders read it (shortest exact text). */
static const char *
value_text(char buf[NUMFMT_SHORTEST_LEN], double x)
{
	if (numfmt_shortest(buf, x) == 0)
		snprintf(buf, NUMFMT_SHORTEST_LEN, "0");  /* derive keeps every value finite */
	return buf;
}

char *
ardupilot_params(const struct ardupilot_design *d, const char *name,
                 const char *aeroeval_version)
{
	struct params ps;
	all_params(&ps, d);
	struct strbuf sb = STRBUF_INIT;
	header(&sb, &ps, d, name, aeroeval_version, "Format: NAME,VALUE lines, every comment "
	    "on its own line (Mission Planner,\n# MAVProxy and the Methodic Configurator load "
	    "it); qgroundcontrol.params holds\n# the same values for QGroundControl.");
	for (int i = 0; i < ps.n; i++) {
		char v[NUMFMT_SHORTEST_LEN];
		if (ps.p[i].section != NULL)
			strbuf_printf(&sb, "#\n# %s\n", ps.p[i].section);
		strbuf_printf(&sb, "# %s: %s%s\n%s,%s\n", ps.p[i].name, ps.p[i].comment,
		    ps.p[i].reboot ? " (reboot)" : "", ps.p[i].name, value_text(v, ps.p[i].value));
	}
	return strbuf_take(&sb, NULL);
}

char *
ardupilot_params_qgc(const struct ardupilot_design *d, const char *name,
                     const char *aeroeval_version)
{
	struct params ps;
	all_params(&ps, d);
	struct strbuf sb = STRBUF_INIT;
	header(&sb, &ps, d, name, aeroeval_version, "Format: QGroundControl's parameter file, "
	    "tab-separated; how each value\n# was derived is in ardupilot.param.");
	strbuf_append_str(&sb, "#\n# Vehicle-Id\tComponent-Id\tName\tValue\tType\n");
	for (int i = 0; i < ps.n; i++) {
		char v[NUMFMT_SHORTEST_LEN];
		strbuf_printf(&sb, "1\t1\t%s\t%s\t%d\n", ps.p[i].name, value_text(v, ps.p[i].value),
		    (int)ps.p[i].type);
	}
	return strbuf_take(&sb, NULL);
}
