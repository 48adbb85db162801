/* ardupilot.c — vehicle_components.json and the starting parameter file
 * (see ardupilot.h).
 *
 * Parameter names, units and ranges are ArduPilot's (AP_BattMonitor_Params,
 * AP_MotorsMulticopter, HarmonicNotchFilter and ArduCopter Parameters.cpp
 * @Param blocks): BATT_* volts and mAh, MOT_BAT_VOLT_* volts, MOT_THST_HOVER
 * a thrust fraction in 0.2..0.8, INS_HNTCH_FREQ the base notch frequency
 * in Hz (10..495), INS_HNTCH_BW Hz (5..250, "typically half the base
 * frequency"), INS_HNTCH_REF the throttle-mode reference (0..1),
 * INS_HNTCH_MODE 1 = throttle, INS_HNTCH_HMNCS a bitmask of harmonics
 * (bit 0 the base frequency).
 */
#include "output/ardupilot.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

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
	double hz = d->hover_rpm / 60.0;
	d->notch_clamped = hz < NOTCH_MIN_HZ || hz > NOTCH_MAX_HZ;
	d->notch_hz = round_to(clamp(hz, NOTCH_MIN_HZ, NOTCH_MAX_HZ), 1);
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

static cJSON *
part(cJSON *comps, const char *key, const struct res_part *p)
{
	cJSON *c = cJSON_AddObjectToObject(comps, key);
	add_product(c, p->manufacturer, p->part_number, p->source_url);
	return c;
}

static void
notes(cJSON *comp, const struct strbuf *sb)
{
	cJSON_AddStringToObject(comp, "Notes", strbuf_str(sb));
}

static void
add_frame(cJSON *comps, const struct solve_result *r, const struct ardupilot_design *d)
{
	const struct res_run *rec = &r->closed;
	struct strbuf sb = STRBUF_INIT;
	cJSON *c = cJSON_AddObjectToObject(comps, "Frame");
	strbuf_printf(&sb, "Custom %d-rotor%s frame", d->n_rotors, d->coaxial ? " coaxial" : "");
	add_product(c, "", strbuf_str(&sb), "");
	cJSON *s = cJSON_AddObjectToObject(c, "Specifications");
	add_num(s, "TOW min Kg", d->tow_min_kg);
	add_num(s, "TOW max Kg", d->tow_max_kg);
	cJSON_AddStringToObject(s, "Frame class", d->frame_class_name);
	strbuf_reset(&sb);
	strbuf_printf(&sb, "aeroeval design of record: takeoff mass %.3f kg with %.3f kg "
	    "payload; TOW min is without payload, TOW max with the largest payload.  "
	    "Wheelbase %.3f m; CFRP arm tubes OD %.1f mm x wall %.2f mm, %.0f mm long.",
	    d->takeoff_mass_kg, rec->mass.payload_kg, r->mission.max_diameter_m,
	    rec->arm_outer_diameter_mm, rec->arm_wall_thickness_mm, 1000.0 * rec->arm_length_m);
	notes(c, &sb);
	strbuf_free(&sb);
}

static void
add_battery(cJSON *comps, const struct solve_result *r, const struct ardupilot_design *d)
{
	struct strbuf sb = STRBUF_INIT;
	cJSON *c = part(comps, "Battery", &r->battery);
	cJSON *s = cJSON_AddObjectToObject(c, "Specifications");
	cJSON_AddStringToObject(s, "Chemistry", d->chemistry);
	add_num(s, "Volt per cell max", d->cell_max_v);
	add_num(s, "Volt per cell arm", d->cell_arm_v);
	add_num(s, "Volt per cell low", d->cell_low_v);
	add_num(s, "Volt per cell crit", d->cell_crit_v);
	add_num(s, "Volt per cell min", d->cell_min_v);
	add_num(s, "Number of cells", d->cells);
	add_num(s, "Capacity mAh", d->capacity_mah);
	strbuf_printf(&sb, "%d pack%s, %d in series x %d in parallel: %dS %d mAh (%s).",
	    r->battery.qty, r->battery.qty == 1 ? "" : "s", r->battery_series_packs,
	    r->battery_parallel_packs, d->cells, d->capacity_mah, d->chemistry_aeroeval);
	if (d->cell_max_clamped)
		strbuf_printf(&sb, "  Its full charge is above what the configurator accepts "
		    "for %s: Volt per cell max is that limit.", d->chemistry);
	notes(c, &sb);
	strbuf_free(&sb);
}

static void
add_drive(cJSON *comps, const struct solve_result *r, const struct ardupilot_design *d)
{
	struct strbuf sb = STRBUF_INIT;
	cJSON *c = part(comps, "ESC", &r->esc);
	add_pair(c, "Firmware", "Type", "", "Version", "");
	add_pair(c, "FC->ESC Connection", "Type", "Main Out", "Protocol", "Normal");
	add_pair(c, "ESC->FC Telemetry", "Type", "None", "Protocol", "None");
	strbuf_printf(&sb, "%d x %s.  Connection and protocol are the configurator's "
	    "defaults, not chosen by aeroeval.", r->esc.qty, r->esc.description);
	notes(c, &sb);

	c = part(comps, "Motors", &r->motor);
	strbuf_reset(&sb);
	strbuf_printf(&sb, "%d motors, %.0f KV (rpm/V), %.0f g each; hover %.0f rpm at "
	    "takeoff mass.  Pole count: not in the catalogue.", r->motor.qty, d->motor_kv,
	    1000.0 * r->motor.unit_mass_kg, d->hover_rpm);
	notes(c, &sb);

	c = part(comps, "Propellers", &r->prop);
	cJSON *s = cJSON_AddObjectToObject(c, "Specifications");
	add_num(s, "Diameter_inches", d->prop_diameter_in);
	strbuf_reset(&sb);
	strbuf_printf(&sb, "%d propellers, diameter %.1f in, pitch %.1f in, %d blades "
	    "(%s).", r->prop.qty, d->prop_diameter_in, d->prop_pitch_in, d->blades,
	    r->prop.description);
	notes(c, &sb);
	strbuf_free(&sb);
}

char *
ardupilot_components(const struct solve_result *r, const struct ardupilot_design *d,
                     const char *name, const char *aeroeval_version)
{
	cJSON *root = cJSON_CreateObject();
	add_num(root, "Format version", 1);
	cJSON *comps = cJSON_AddObjectToObject(root, "Components");

	cJSON *c = cJSON_AddObjectToObject(comps, "Flight Controller");
	add_product(c, "", "", "");
	add_pair(c, "Firmware", "Type", "ArduCopter", "Version", "");
	cJSON_AddStringToObject(cJSON_AddObjectToObject(c, "Specifications"), "MCU Series", "");
	cJSON_AddStringToObject(c, "Notes", "Not chosen by aeroeval: the bill of materials "
	    "carries the avionics as one mass allowance.");

	add_frame(comps, r, d);

	c = cJSON_AddObjectToObject(comps, "Battery Monitor");
	add_product(c, "", "", "");
	add_pair(c, "Firmware", "Type", "", "Version", "");
	add_pair(c, "FC Connection", "Type", "None", "Protocol", "Disabled");
	cJSON_AddStringToObject(c, "Notes", "Not chosen by aeroeval.  Choose one: the "
	    "BATT_ voltages and capacities of ardupilot.param need it.");

	add_battery(comps, r, d);
	add_drive(comps, r, d);

	cJSON_AddStringToObject(root, "Program version", aeroeval_version);
	struct strbuf sb = STRBUF_INIT;
	strbuf_printf(&sb, "aeroeval %s", name);
	cJSON_AddStringToObject(root, "Configuration template", strbuf_str(&sb));
	strbuf_free(&sb);
	char *text = jsonw_print(root, NULL);
	cJSON_Delete(root);
	return text;
}

/* ---- the parameter file ------------------------------------------------------ */

#define MAX_PARAMS 24

struct param {
	char name[17];        /* ArduPilot names have at most 16 characters */
	double value;
	char comment[320];
};

struct params {
	struct param p[MAX_PARAMS];
	int n;
};

__attribute__((format(printf, 4, 5)))
static void
set(struct params *ps, const char *name, double value, const char *fmt, ...)
{
	if (ps->n >= MAX_PARAMS)
		return;
	struct param *p = &ps->p[ps->n++];
	snprintf(p->name, sizeof p->name, "%s", name);
	p->value = value;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(p->comment, sizeof p->comment, fmt, ap);
	va_end(ap);
	/* The reader splits a line at its first '#': none may be in a comment. */
	for (char *c = p->comment; *c != '\0'; c++)
		if (*c == '#' || *c == '\r' || *c == '\n')
			*c = ' ';
}

static int
cmp_param(const void *a, const void *b)
{
	return strcmp(((const struct param *)a)->name, ((const struct param *)b)->name);
}

static void
battery_params(struct params *ps, const struct ardupilot_design *d)
{
	int n = d->cells;
	set(ps, "BATT_CAPACITY", d->capacity_mah, "pack of record: %dS %d mAh", n,
	    d->capacity_mah);
	if (d->reserve_mah > 0.0)
		set(ps, "BATT_LOW_MAH", d->reserve_mah, "the design's landing reserve: %.1f %% "
		    "of %d mAh left", 100.0 * d->reserve_soc, d->capacity_mah);
	set(ps, "BATT_ARM_VOLT", round_to(n * d->cell_arm_v, 2), "%d cells x %.2f V: arm "
	    "only on a charged pack (%s arm level)", n, d->cell_arm_v, d->chemistry);
	set(ps, "BATT_LOW_VOLT", round_to(n * d->cell_low_v, 2), "%d cells x %.2f V (%s "
	    "low level)", n, d->cell_low_v, d->chemistry);
	set(ps, "BATT_CRT_VOLT", round_to(n * d->cell_crit_v, 2), "%d cells x %.2f V (%s "
	    "critical level)", n, d->cell_crit_v, d->chemistry);
	set(ps, "MOT_BAT_VOLT_MAX", round_to(n * d->cell_max_v, 2), "%d cells x %.2f V "
	    "full charge (%s profile%s)", n, d->cell_max_v, d->chemistry_aeroeval,
	    d->cell_max_clamped ? ", held to the configurator's limit" : "");
	set(ps, "MOT_BAT_VOLT_MIN", round_to(n * d->cell_min_v, 2), "%d cells x %.2f V: "
	    "the lowest loaded cell voltage the design was flown to", n, d->cell_min_v);
}

static void
motor_params(struct params *ps, const struct ardupilot_design *d)
{
	if (d->full_thrust_n > 0.0)
		set(ps, "MOT_THST_HOVER", d->thrust_hover, "hover thrust / full-throttle thrust "
		    "per rotor: %.2f N / %.2f N%s (hover throttle %.2f by speed); learnt in "
		    "flight with MOT_HOVER_LEARN", d->hover_thrust_n, d->full_thrust_n,
		    d->thrust_hover_clamped ? ", held to 0.2..0.8" : "", d->hover_throttle);
	else
		set(ps, "MOT_THST_HOVER", d->thrust_hover, "the design's hover throttle%s",
		    d->thrust_hover_clamped ? ", held to 0.2..0.8" : "");
	if (d->frame_class != AP_FRAME_UNDEFINED)
		set(ps, "FRAME_CLASS", d->frame_class, "%s: %d rotors%s", d->frame_class_name,
		    d->n_rotors, d->coaxial ? " in coaxial pairs" : "");
	if (d->frame_class != AP_FRAME_UNDEFINED && d->frame_type >= 0)
		set(ps, "FRAME_TYPE", d->frame_type, "X: the motor order of the frame as built "
		    "decides; check it against ArduPilot's motor diagrams");
}

static void
notch_params(struct params *ps, const struct ardupilot_design *d)
{
	double bp_hz = d->blades * d->hover_rpm / 60.0;
	double bw = round_to(clamp(d->notch_hz / 2.0, NOTCH_BW_MIN_HZ, NOTCH_BW_MAX_HZ), 1);
	/* The base frequency is the rotor's turning rate; the blade-pass
	 * frequency is its harmonic number `blades`, notched too. */
	int hmncs = 1 | (d->blades <= 16 ? 1 << (d->blades - 1) : 0);
	set(ps, "INS_HNTCH_ENABLE", 1, "harmonic notch on the motor noise");
	set(ps, "INS_HNTCH_MODE", 1, "throttle-based: the notch follows the thrust");
	set(ps, "INS_HNTCH_FREQ", d->notch_hz, "hover rotor speed %.0f rpm / 60%s",
	    d->hover_rpm, d->notch_clamped ? ", held to 10..495 Hz" : "");
	set(ps, "INS_HNTCH_BW", bw, "half the base frequency, as ArduPilot's notch setup "
	    "advises");
	set(ps, "INS_HNTCH_REF", d->thrust_hover, "= MOT_THST_HOVER: the thrust at which "
	    "the notch sits at INS_HNTCH_FREQ");
	set(ps, "INS_HNTCH_HMNCS", hmncs, "base frequency and harmonic %d, the blade-pass "
	    "frequency of the %d-blade propellers (%.1f Hz in hover)", d->blades, d->blades,
	    bp_hz);
}

char *
ardupilot_params(const struct ardupilot_design *d, const char *name,
                 const char *aeroeval_version)
{
	struct params ps = { .n = 0 };
	battery_params(&ps, d);
	motor_params(&ps, d);
	notch_params(&ps, d);
	qsort(ps.p, (size_t)ps.n, sizeof ps.p[0], cmp_param);

	struct strbuf sb = STRBUF_INIT;
	strbuf_printf(&sb, "# ArduCopter starting parameters for %s, derived by aeroeval %s\n"
	    "# from its design of record: %s, takeoff mass %.3f kg.\n", name, aeroeval_version,
	    d->feasible ? "real parts, every check passes" : "real parts, SOME CHECKS FAIL "
	    "(see the dossier)", d->takeoff_mass_kg);
	if (d->frame_class == AP_FRAME_UNDEFINED)
		strbuf_printf(&sb, "# FRAME_CLASS is not set: ArduPilot has no frame class for "
		    "%d rotors%s.\n", d->n_rotors, d->coaxial ? " in coaxial pairs" : "");
	strbuf_append_str(&sb, "# Everything else (failsafe actions, radio, ports, gains) is "
	    "the configurator's to set.\n");
	for (int i = 0; i < ps.n; i++) {
		char v[NUMFMT_SHORTEST_LEN];
		if (numfmt_shortest(v, ps.p[i].value) == 0)
			continue;  /* derive keeps every value finite */
		strbuf_printf(&sb, "%s,%s  # %s\n", ps.p[i].name, v, ps.p[i].comment);
	}
	return strbuf_take(&sb, NULL);
}
