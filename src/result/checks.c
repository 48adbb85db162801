/* checks.c — the checks table and its evaluation (see checks.h). */
#include "result/checks.h"

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "util/numfmt.h"
#include "util/strbuf.h"

#define CHECK_RELTOL 1e-9 /* comparison tolerance, relative to the limit */

const struct check_def check_table[CK_COUNT] = {
	[CK_RESERVE] = { "RESERVE", "discharge",
	    "State of charge at landing (reserve)", "%", false, COND_LANDING,
	    "Landing below the reserve leaves no margin for a go-around, wind "
	    "or an aged pack.",
	    { "A larger pack or more packs in parallel",
	      "A shorter mission or a lighter payload",
	      "Allow a shorter flight: locks.auto_reduce_flight_time = true" } },
	[CK_THRUST] = { "THRUST", "parts",
	    "Thrust-to-weight with the largest payload", "", false, COND_FULL,
	    "Below the role's thrust-to-weight the aircraft lacks the control "
	    "authority and climb its role needs.",
	    { "A stronger motor or a larger propeller",
	      "A lighter payload (max_payload_kg) or a role with a lower requirement",
	      "More series cells (nominal_cell_count)" } },
	[CK_THROTTLE] = { "THROTTLE", "parts",
	    "Throttle the mission needs", "%", true, COND_MISSION,
	    "Above 100 % the motors need more voltage than the pack gives.",
	    { "A motor of higher KV or a larger propeller", "More series cells", NULL } },
	[CK_CLIMB_SPEED] = { "CLIMB_SPEED", "mission",
	    "Climb rate the mission asks for", "m/s", true, COND_FULL,
	    "The aircraft cannot climb faster than full thrust allows; it "
	    "flies its climb at the fastest rate it reaches.",
	    { "A climb rate (v_climb_ms) of {limit} or less",
	      "A higher thrust-to-weight (payload_role.thrust_margin_override)", NULL } },
	[CK_FORWARD_PITCH] = { "FORWARD_PITCH", "mission",
	    "Body pitch in forward flight", "°", true, COND_MISSION,
	    "Beyond the pitch limit the attitude controller has no margin left "
	    "for gusts.",
	    { "A lower forward speed (v_forward_ms)",
	      "A smaller frontal area (payload_role.added_drag_m2)", NULL } },
	[CK_FORWARD_SPEED] = { "FORWARD_SPEED", "mission",
	    "Forward speed the mission asks for", "m/s", true, COND_MISSION,
	    "Beyond it the rotors run out of thrust or the aircraft out of pitch.",
	    { "A forward speed (v_forward_ms) of {limit} or less",
	      "\"auto\" for the speed of least power",
	      "A smaller frontal area (payload_role.added_drag_m2)" } },
	[CK_DOWNWASH] = { "DOWNWASH", "feasibility",
	    "Downwash (crop damage and spray drift)", "m/s", true, COND_HOVER,
	    "Stronger downwash flattens the crop and blows the spray off target.",
	    { "A larger wheelbase (max_diameter_m): larger rotors lower the downwash",
	      "More rotors (num_rotors)",
	      "A higher limit (payload_role.ag_max_downwash_ms) if the crop allows" } },

	[CK_BATTERY_CONTINUOUS] = { "BATTERY_CURRENT", "parts",
	    "Battery current within its continuous rating", "A", true, COND_MISSION,
	    "Past its continuous rating a pack heats, sags and ages fast.",
	    { "A pack with a higher C rating or more capacity",
	      "More packs in parallel", NULL } },
	[CK_BATTERY_BURST] = { "BATTERY_BURST", "parts",
	    "Battery current within its burst rating", "A", true, COND_FULL,
	    "Past its burst rating a pack's voltage collapses and its cells are "
	    "damaged.",
	    { "A pack with a higher burst rating or more capacity",
	      "More packs in parallel", NULL } },
	[CK_BATTERY_POWER] = { "BATTERY_POWER", "discharge",
	    "Battery power within the cells' burst capability", "W", true, COND_FULL,
	    "The cells cannot deliver more power than their chemistry allows.",
	    { "A larger battery", "A higher-power chemistry such as LiPo or LiHV",
	      "A lower thrust-to-weight requirement" } },
	[CK_CONNECTOR_MISSION] = { "CONNECTOR_CURRENT", "parts",
	    "Battery connector current", "A", true, COND_MISSION,
	    "A connector run past its rating heats and its contacts degrade.",
	    { "A connector of a higher rating (AS150, QS8)",
	      "More packs in parallel, each with its own connector", NULL } },
	[CK_CONNECTOR_FULL] = { "CONNECTOR_CURRENT_FULL", "parts",
	    "Battery connector current", "A", true, COND_FULL,
	    "A connector run past its burst rating can weld or melt its housing.",
	    { "A connector of a higher rating (AS150, QS8)",
	      "More packs in parallel, each with its own connector", NULL } },
	[CK_POWER_MODULE_MISSION] = { "POWER_MODULE_CURRENT", "parts",
	    "Power module current", "A", true, COND_MISSION,
	    "A power module past its rating overheats and misreads the current.",
	    { "A power module rated above {value}", NULL, NULL } },
	[CK_POWER_MODULE_FULL] = { "POWER_MODULE_CURRENT_FULL", "parts",
	    "Power module current", "A", true, COND_FULL,
	    "A power module past its burst rating overheats on every punch-out.",
	    { "A power module rated above {value}",
	      "A lower thrust-to-weight", NULL } },
	[CK_HARNESS_FULL] = { "HARNESS_CURRENT_FULL", "parts",
	    "Power harness current", "A", true, COND_FULL,
	    "Wire past its rating heats its insulation and drops voltage.",
	    { "A heavier gauge of main power wire", NULL, NULL } },
	[CK_ESC_CURRENT] = { "ESC_CURRENT", "parts",
	    "ESC current", "A", true, COND_FULL,
	    "An ESC past its rating overheats and shuts down or fails.",
	    { "An ESC rated above {value} continuous",
	      "A smaller or lower-pitch propeller", NULL } },
	[CK_MOTOR_CURRENT_MISSION] = { "MOTOR_CURRENT_SUSTAINED", "parts",
	    "Motor current within its continuous rating", "A", true, COND_MISSION,
	    "A motor run past its continuous rating overheats its windings.",
	    { "A larger propeller or more rotors (lower disk loading)",
	      "A larger motor", NULL } },
	[CK_MOTOR_CURRENT_FULL] = { "MOTOR_CURRENT", "parts",
	    "Motor current within its peak rating", "A", true, COND_FULL,
	    "Past its peak rating the motor's windings and magnets are at risk.",
	    { "A smaller or lower-pitch propeller", "A larger motor", NULL } },
	[CK_MOTOR_POWER] = { "MOTOR_POWER", "parts",
	    "Motor input power", "W", true, COND_FULL,
	    "Past its rated power the motor overheats.",
	    { "A motor rated above {value}", "A smaller or lower-pitch propeller", NULL } },
	[CK_VOLTAGE_MISSION] = { "VOLTAGE_FLOOR", "discharge",
	    "Lowest pack voltage in flight", "V", false, COND_FLIGHT,
	    "Below the floor the autopilot's battery failsafe lands the aircraft.",
	    { "More capacity or a lower-resistance pack", "More series cells", NULL } },
	[CK_VOLTAGE_FULL] = { "VOLTAGE_FULL_THROTTLE", "parts",
	    "Pack voltage", "V", false, COND_FULL,
	    "A burst that pulls the pack below the floor trips the battery "
	    "failsafe and costs thrust when it is needed most.",
	    { "A lower-resistance pack (higher C rating)",
	      "More packs in parallel or more capacity", "More series cells" } },

	[CK_BATTERY_TEMP] = { "THERMAL_RUNAWAY", "discharge",
	    "Battery peak temperature", "°C", true, COND_FLIGHT,
	    "Above it lithium cells age fast and approach thermal runaway.",
	    { "More capacity or packs in parallel (lower C-rate, more mass to heat)",
	      "A lower-resistance pack", "A lower ambient temperature limit" } },
	[CK_WINDING_HOVER] = { "WINDING_TEMPERATURE_HOVER", "parts",
	    "Motor winding temperature", "°C", true, COND_HOVER,
	    "Above its class the winding's insulation fails.",
	    { "A larger motor (lower losses, more surface)",
	      "A larger propeller (lower disk loading)", NULL } },
	[CK_WINDING_FULL] = { "WINDING_TEMPERATURE", "parts",
	    "Motor winding temperature", "°C", true, COND_FULL,
	    "Above its class the winding's insulation fails.",
	    { "A larger motor (lower losses, more surface)",
	      "A smaller or lower-pitch propeller", NULL } },

	[CK_PROP_OVERLAP] = { "PROP_OVERLAP", "feasibility",
	    "Propeller diameter within the wheelbase", "in", true, COND_DESIGN,
	    "Larger propellers overlap their neighbours.",
	    { "A larger wheelbase (max_diameter_m)", "A smaller propeller", NULL } },
	[CK_TIP_MACH] = { "TIP_MACH", "propulsion",
	    "Propeller tip Mach number", "", true, COND_FULL,
	    "Near the speed of sound noise, losses and blade loads rise sharply.",
	    { "A larger, slower propeller", "A lower-KV motor", NULL } },
	[CK_PROP_RPM] = { "PROP_RPM", "parts",
	    "Propeller speed within the maker's limit", "rpm", true, COND_FULL,
	    "Past the maker's limit the blades may fail.",
	    { "A lower-KV motor", "A propeller rated for higher speed", NULL } },

	[CK_ARM_SAFETY] = { "ARM_STRENGTH", "structure",
	    "Arm factor of safety (fatigue strength over root stress)", "", false,
	    COND_DESIGN_LOAD,
	    "Below 1.5 the arm may crack under repeated loads.",
	    { "A larger arm tube", NULL, NULL } },
	[CK_ARM_TILT] = { "ARM_TILT", "structure",
	    "Motor tilt from arm bending", "°", true, COND_FULL,
	    "A motor that tilts under load cross-couples the axes and wastes thrust.",
	    { "A stiffer arm tube (larger diameter)", "A shorter arm", NULL } },
	[CK_ARM_TORSION] = { "ARM_TORSION", "structure",
	    "Arm shear stress from motor torque", "MPa", true, COND_FULL,
	    "Past it the tube's plies shear under the motor's reaction torque.",
	    { "A larger arm tube", "A tube with ±45° plies", NULL } },
	[CK_ARM_MODE_CONTROL] = { "ARM_MODE_CONTROL", "structure",
	    "Arm first bending mode above the rate-loop bandwidth", "Hz", false, COND_DESIGN,
	    "A mode within the rate loop's bandwidth couples with the "
	    "attitude loop and can oscillate.",
	    { "A stiffer arm (larger tube) above {limit}", "A shorter arm", NULL } },
	[CK_ARM_MODE_REV] = { "ARM_RESONANCE_REV", "structure",
	    "Arm first bending mode clear of the rotor speed", "Hz", true, COND_MISSION,
	    "A mode at the rotor's once-per-revolution frequency is driven by every "
	    "imbalance of the propeller.",
	    { "A stiffer arm (larger tube) above the band",
	      "Soft motor mounts, to move the mode below the band",
	      "A propeller balanced to ISO 21940 G2.5" } },
	[CK_ARM_MODE_BLADE_PASS] = { "ARM_RESONANCE", "structure",
	    "Arm first bending mode clear of the blade-pass band", "Hz", true,
	    COND_MISSION,
	    "A mode in the blade-pass band is driven by every blade passing the arm.",
	    { "A stiffer arm (larger tube) above the band",
	      "Soft motor mounts, to move the mode below the band",
	      "Another blade count (structural_overrides.num_blades)" } },
	[CK_FRAME_MTOW] = { "FRAME_MTOW", "parts",
	    "Takeoff mass within the frame kit's maximum", "kg", true, COND_DESIGN,
	    "The frame's maker does not warrant it above this mass.",
	    { "A larger frame kit", "Custom arms instead of the kit", NULL } },
	[CK_CG_OFFSET] = { "CG_OFFSET", "feasibility",
	    "Payload centre of gravity offset", "m", true, COND_DESIGN,
	    "Outside the rotor polygon the aircraft cannot be trimmed.",
	    { "Mount the payload nearer the centre", "A larger wheelbase", NULL } },
};

const char *
check_cond_text(enum check_cond cond)
{
	switch (cond) {
	case COND_DESIGN:      return "design";
	case COND_HOVER:       return "hover at takeoff mass";
	case COND_MISSION:     return "mission peak";
	case COND_FULL:        return "full-throttle burst, 10 s";
	case COND_DESIGN_LOAD: return "design load";
	case COND_LANDING:     return "landing";
	case COND_FLIGHT:      return "whole flight";
	case COND_COUNT:       break;
	}
	return "";
}

void
checks_init(struct check_values *v)
{
	/* The texts are most of its 13 KiB and a string needs only its NUL
	 * (one check_values is filled for every run and closing flown). */
	memset(v, 0, offsetof(struct check_values, basis));
	for (int i = 0; i < CK_COUNT; i++)
		v->basis[i][0] = v->note[i][0] = '\0';
}

void
checks_basis(struct check_values *v, enum check_id id, const char *fmt, ...)
{
	if (v->terse)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(v->basis[id], sizeof v->basis[id], fmt, ap);
	va_end(ap);
}

void
checks_set(struct check_values *v, enum check_id id, double value,
           double limit)
{
	v->on[id] = true;
	v->value[id] = isfinite(value) ? value : 0.0;
	v->limit[id] = isfinite(limit) ? limit : 0.0;
}

/* A number with its unit for a sentence: "142.8 A", "0.6201". */
static void
amount(char *b, size_t n, double x, const char *unit)
{
	char num[32];
	double a = fabs(x);
	int dec = a == 0.0 ? 0 : 3 - (int)floor(log10(a)); /* 4 figures */
	numfmt_fixed(num, sizeof num, x, dec < 0 ? 0 : dec > 3 ? 3 : dec);
	/* "60.00" reads "60", "1.250" reads "1.25". */
	if (strchr(num, '.') != NULL) {
		size_t k = strlen(num);
		while (k > 0 && num[k - 1] == '0')
			num[--k] = '\0';
		if (k > 0 && num[k - 1] == '.')
			num[--k] = '\0';
	}
	snprintf(b, n, "%s%s%s", num, unit[0] != '\0' ? " " : "", unit);
}

/* A fix with {value} and {limit} written out. */
static void
expand_fix(char *out, size_t n, const char *fix, const char *value,
           const char *limit)
{
	struct strbuf sb = STRBUF_INIT;
	for (const char *s = fix; *s != '\0';) {
		if (strncmp(s, "{value}", 7) == 0) {
			strbuf_append_str(&sb, value);
			s += 7;
		} else if (strncmp(s, "{limit}", 7) == 0) {
			strbuf_append_str(&sb, limit);
			s += 7;
		} else {
			strbuf_append_char(&sb, *s++);
		}
	}
	snprintf(out, n, "%s", strbuf_str(&sb));
	strbuf_free(&sb);
}

/* A failed check's violation: what, where, against what, why. */
static void
violate(const struct check_values *v, enum check_id id,
        const struct res_check *c, const char *run, struct solve_result *r)
{
	if (r->n_violations >= RES_MAX_VIOLATIONS)
		return;
	const struct check_def *d = &check_table[id];
	struct res_violation *x = &r->violations[r->n_violations++];
	x->run = run;
	x->stage = d->stage;
	x->code = d->code;
	x->message[0] = '\0';
	x->n_fixes = 0;
	if (r->terse)
		return;
	char val[48], lim[48];
	amount(val, sizeof val, c->value, d->unit);
	amount(lim, sizeof lim, c->limit, d->unit);
	snprintf(x->message, sizeof x->message, "%s at %s: %s, against %s %s%s%s%s. %s%s%s",
	    d->name, check_cond_text(d->cond), val, c->upper ? "at most" : "at least",
	    lim, v->basis[id][0] ? " (" : "", v->basis[id], v->basis[id][0] ? ")" : "",
	    d->why, v->note[id][0] ? " " : "", v->note[id]);
	for (int k = 0; k < RES_MAX_FIXES && d->fix[k] != NULL; k++)
		expand_fix(x->fixes[x->n_fixes++], RES_TEXT, d->fix[k], val, lim);
}

void
checks_apply(const struct check_values *v, const char *run, struct res_run *o,
             struct solve_result *r)
{
	o->n_checks = 0;
	bool all = true;
	for (int id = 0; id < CK_COUNT; id++) {
		if (!v->on[id] || o->n_checks >= RES_MAX_CHECKS)
			continue;
		const struct check_def *d = &check_table[id];
		struct res_check *c = &o->checks[o->n_checks++];
		memset(c, 0, sizeof *c);
		c->code = d->code;
		c->name = d->name;
		c->unit = d->unit;
		c->condition = check_cond_text(d->cond);
		str_copy(c->basis, sizeof c->basis, v->basis[id]);
		c->value = v->value[id];
		c->limit = v->limit[id];
		c->upper = v->side[id] != 0 ? v->side[id] > 0 : d->upper;
		c->sized = v->sized[id];
		c->advisory = v->advisory[id];
		double scale = fabs(c->limit) > 1e-12 ? fabs(c->limit) : 1.0;
		c->margin = c->upper ? (c->limit - c->value) / scale
		    : (c->value - c->limit) / scale;
		/* A quantity sized to its limit must pass: compare with a
		 * relative tolerance far below any physical meaning. */
		double tol = CHECK_RELTOL * scale;
		c->pass = v->pass_within_tol[id] || (c->upper ? c->value <= c->limit + tol
		    : c->value >= c->limit - tol);
		if (!c->pass && !c->advisory) {
			all = false;
			violate(v, (enum check_id)id, c, run, r);
		}
	}
	o->feasible = all;
}

const struct res_check *
checks_find(const struct res_run *o, const char *code)
{
	for (int i = 0; i < o->n_checks && i < RES_MAX_CHECKS; i++)
		if (o->checks[i].code != NULL && strcmp(o->checks[i].code, code) == 0)
			return &o->checks[i];
	return NULL;
}
