/* engine.c — one solve: requirements, defaults, dual run (see engine.h). */
#include "engine/engine.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics/aero.h"
#include "sizing/feasibility.h"
#include "engine/invariants.h"
#include "parts/parts.h"
#include "util/strbuf.h"
#include "physics/structure.h"
#include "util/numfmt.h"
#include "util/units.h"
#include "util/xalloc.h"

/* f_scale per aero body class (paper §IV-D). */
static const double body_f_scale[BODY_CLASS_MAX] = { 0.004, 0.012, 0.05 };

/* Rotor–arm interference constant c per arm configuration (paper §IV-F). */
static const double arm_interference_c[ARM_CONFIG_MAX] = { 0.6, 0.0, 1.5 };

/* Blade mass coefficient kg / m^2.2 per propeller material: one blade pair
 * of diameter D weighs k D^2.2, fitted to the catalogue's two-blade
 * propellers of 4 in and up (glass-filled nylon, "plastic": 0.33 over 166
 * of them, 10 in ≈ 16 g; carbon 0.25 over 16, 28 in ≈ 130 g; wood keeps
 * 0.45, none published).  Index by enum prop_class; PROP_AUTO is resolved
 * before use. */
static const double prop_k[PROP_CLASS_MAX] = { 0.0, 0.33, 0.25, 0.45 };
#define PROP_AUTO_CARBON_ABOVE_M 0.30 /* auto: carbon above 12 in */



static const char *
rotor_word(int n, bool coaxial)
{
	if (coaxial && n == 8)
		return "Octocopter in coaxial X8 layout";
	if (coaxial && n == 6)
		return "Hexacopter in coaxial Y6 layout";
	switch (n) {
	case 3: return "Tricopter";
	case 4: return "Quadcopter";
	case 6: return "Hexacopter";
	case 8: return "Octocopter";
	case 12: return "Dodecacopter";
	default: return "Multirotor";
	}
}

/* Requirements-first layer: every decision explained, explicit fields win. */
static void
apply_requirements(struct mission_spec *s, const struct model_data *md,
                   struct solve_result *r)
{
	const struct spec_requirements *q = &s->requirements;
	if (q->payload_preset != PRESET_NONE) {
		const struct model_preset *p = &md->preset[q->payload_preset];
		if (!s->given[SPECF_PAYLOAD_KG]) {
			s->payload_kg = p->payload_kg;
			res_rationale(r, "Payload set to %.2f kg by the \"%s\" preset.",
			    p->payload_kg, p->label);
		}
		if (!s->given[SPECF_ROLE_TYPE] && q->role == ROLE_NONE && p->role > 0) {
			s->payload_role.type = p->role;
			res_rationale(r, "Mission role \"%s\" implied by the \"%s\" preset.",
			    spec_enum_role[p->role], p->label);
		}
	}
	if (q->role != ROLE_NONE && !s->given[SPECF_ROLE_TYPE]) {
		s->payload_role.type = q->role;
		res_rationale(r, "Mission role \"%s\" taken from the requirements.",
		    spec_enum_role[q->role]);
	}
	if (!s->given[SPECF_AIRFRAME_CLASS]) {
		int cls = -1;
		const char *why = NULL;
		if (s->payload_role.type == ROLE_AGRICULTURE) {
			cls = AF_AGRICULTURAL;
			why = "agricultural spraying needs the heavy-lift class";
		} else if (s->payload_role.type == ROLE_RACING) {
			cls = AF_MICRO_AIO;
			why = "racing airframes are micro all-in-one builds";
		} else if (q->transport != TRANSPORT_NONE) {
			cls = md->transport[q->transport].airframe_class;
			why = md->transport[q->transport].label;
		}
		if (cls >= 0) {
			s->airframe_class = cls;
			res_rationale(r, "Airframe class %s: %s.", spec_enum_airframe[cls], why);
		}
	}
	if (q->transport != TRANSPORT_NONE && !s->given[SPECF_MAX_DIAMETER_M]) {
		const struct model_transport *t = &md->transport[q->transport];
		s->max_diameter_m = t->max_wheelbase_m;
		res_rationale(r, "Wheelbase ceiling %.0f mm so that the aircraft %s.",
		    t->max_wheelbase_m * 1000.0, t->label);
		/* Coaxial trigger: a quad on this wheelbase would need a disk
		 * loading above the limit at the seed mass. */
		if (!s->given[SPECF_COAXIAL_LAYOUT] && !s->given[SPECF_NUM_ROTORS]) {
			double m0 = sizing_seed_kg(s->payload_kg, RHO_SL_KG_M3);
			double d = aero_overlap_limit_m(s->max_diameter_m, 4, AERO_TIP_CLEARANCE);
			double dl = m0 * G0_M_S2 / (4.0 * 0.25 * M_PI * d * d);
			if (dl > md->coaxial_disk_loading_n_m2) {
				s->coaxial_layout = true;
				s->num_rotors = 8;
				res_rationale(r, "Sized as an Octocopter in coaxial X8 layout: "
				    "a quad inside the %.0f mm transport limit would load its "
				    "disks to %.0f N/m², above %.0f N/m²; stacking rotors in "
				    "pairs doubles the thrust on the same four arms.",
				    s->max_diameter_m * 1000.0, dl, md->coaxial_disk_loading_n_m2);
			}
		}
	}
	if (q->priority != PRIORITY_NONE) {
		const struct model_priority *p = &md->priority[q->priority];
		if (!s->given[SPECF_BATTERY_CHEMISTRY] && p->chemistry[0]) {
			snprintf(s->battery_chemistry, sizeof s->battery_chemistry, "%s",
			    p->chemistry);
			res_rationale(r, "Chemistry %s chosen for the \"%s\" priority.",
			    p->chemistry, spec_enum_priority[q->priority]);
		}
		if (p->v_auto && !s->given[SPECF_V_FORWARD_MS]) {
			s->v_forward_auto = true;
			res_rationale(r, "Forward speed set to the minimum-power speed "
			    "for the \"%s\" priority.", spec_enum_priority[q->priority]);
		}
	}
}

/* Role and class defaults for every derived field the mission left open;
 * written back into the spec so result.json shows the values used. */
static void
apply_defaults(struct mission_spec *s, const struct model_data *md)
{
	const struct model_role *ro = &md->role[s->payload_role.type];
	struct spec_role *pr = &s->payload_role;
	if (!s->given[SPECF_ROLE_AUX_POWER_W])
		pr->aux_power_w = ro->aux_power_w * md->cal.aux_scale;
	if (!s->given[SPECF_ROLE_ADDED_DRAG_M2])
		pr->added_drag_m2 = ro->added_drag_m2;
	if (!s->given[SPECF_ROLE_THRUST_MARGIN])
		pr->thrust_margin_override = ro->thrust_margin;
	if (!s->given[SPECF_ROLE_DRAG_MULT])
		pr->drag_area_multiplier = ro->forward_drag_multiplier;
	if (!s->given[SPECF_ROLE_RACING_LOAD_FACTOR])
		pr->racing_load_factor = md->role[ROLE_RACING].load_factor;
	if (!s->given[SPECF_ROLE_INTEGRATION_KG])
		pr->integration_overhead_kg = ro->integration_frac * s->payload_kg;
	if (!s->given[SPECF_ROLE_DROP_MASS_KG])
		pr->delivery_drop_mass_kg = s->payload_kg;
	if (!s->given[SPECF_BASELINE_V_FORWARD_MS])
		s->baseline_v_forward_ms = s->v_forward_auto ? 10.0 : s->v_forward_ms;
	if (!s->given[SPECF_BASELINE_T_FORWARD_S])
		s->baseline_t_forward_s = s->t_forward_s;
	if (!s->given[SPECF_AMBIENT_TEMP_C])
		s->ambient_temp_c = k_to_c(atmo_isa_temp_k(s->altitude_m));
	if (!s->given[SPECF_AERO_PROP_EFF])
		s->aerodynamic_overrides.propulsive_efficiency = md->cal.eta_drive;
	if (!s->given[SPECF_STRUCT_BODY_MULT])
		s->structural_overrides.body_mass_multiplier = md->cls[s->airframe_class].gamma;
}

void
engine_resolve(struct mission_spec *spec, const struct model_data *md,
               struct solve_result *r)
{
	apply_requirements(spec, md, r);
	apply_defaults(spec, md);
}

void
engine_params(const struct mission_spec *s, const struct model_data *md,
              bool baseline, struct sizing_params *p)
{
	const struct model_class *cls = &md->cls[s->airframe_class];
	int role = baseline ? ROLE_NONE : s->payload_role.type;
	const struct model_role *ro = &md->role[role];
	const struct spec_role *pr = &s->payload_role;
	const struct spec_aero *ao = &s->aerodynamic_overrides;
	const struct spec_structural *so = &s->structural_overrides;
	const struct spec_locks *lk = &s->locks;

	memset(p, 0, sizeof *p);
	p->wheelbase_m = s->max_diameter_m;
	p->n_rotors = s->num_rotors;
	p->coaxial = s->coaxial_layout;
	p->airframe_class = s->airframe_class;
	p->ambient_c = s->ambient_temp_c;
	atmo_at(s->altitude_m, c_to_k(s->ambient_temp_c), &p->air);

	p->duration_s[PHASE_CLIMB] = s->t_climb_s;
	p->duration_s[PHASE_HOVER] = s->t_hover_s;
	p->duration_s[PHASE_FORWARD] = baseline ? s->baseline_t_forward_s : s->t_forward_s;
	p->v_climb_ms = s->v_climb_ms;
	p->v_forward_ms = baseline ? s->baseline_v_forward_ms : s->v_forward_ms;
	p->v_auto = baseline ? false : s->v_forward_auto;
	p->allow_relax = lk->auto_reduce_flight_time;

	/* Baseline: null role, dead-weight hover math at θ = 0.60. */
	p->thrust_margin = baseline ? md->role[ROLE_NONE].thrust_margin : pr->thrust_margin_override;
	p->load_factor = role == ROLE_RACING ? pr->racing_load_factor : ro->load_factor;
	p->aux_w = baseline ? 0.0 : pr->aux_power_w;
	p->aux_scaled = !baseline && !s->given[SPECF_ROLE_AUX_POWER_W];
	p->aux_ref_kg = ro->aux_ref_kg;
	p->added_drag_m2 = baseline ? 0.0 : pr->added_drag_m2;
	p->fwd_drag_mult = baseline ? 1.0 : pr->drag_area_multiplier;
	p->cg_shift_m = baseline ? 0.0 : pr->cg_shift_m;
	p->role_aux_kg = baseline ? 0.0 : pr->integration_overhead_kg;
	p->c_motor = ro->c_motor;
	p->c_esc = cls->small_platform ? fmin(ro->c_esc, md->role[ROLE_RACING].c_esc) : ro->c_esc;
	p->h_conv_w_m2k = ro->h_conv_w_m2k;
	p->burst_factor = ro->burst_factor;
	p->small_platform = cls->small_platform || role == ROLE_RACING;
	p->duty = &ro->duty;
	p->shed = baseline || !pr->mass_shedding ? SHED_NONE : ro->shedding;
	p->drop_mass_kg = pr->delivery_drop_mass_kg;
	p->drop_ratio = pr->delivery_drop_time_ratio;
	p->spray_rate_kg_s = pr->spray_rate_kg_per_s;
	p->downwash_cap_ms = role == ROLE_AGRICULTURE ? pr->ag_max_downwash_ms : 0.0;
	p->payload_kg = s->payload_kg;
	p->extra_payload_kg = s->max_payload_kg > s->payload_kg
	    ? s->max_payload_kg - s->payload_kg : 0.0;

	p->chem = model_chem(md, s->battery_chemistry);
	if (p->chem == NULL)
		p->chem = &md->chem[0]; /* the parser has already refused unknown names */
	p->e_pack_override_wh_kg = s->battery_specific_energy_wh_kg;
	p->cells_fixed = lk->is_battery_locked ? lk->locked_cell_count
	    : lk->is_voltage_locked ? lk->locked_series_cells
	    : s->nominal_cell_count;
	p->cells_lo = cls->cells_min;
	p->cells_hi = cls->cells_max;
	p->pack_count = s->battery_pack_count;
	p->cycles = s->battery_cycle_count;
	p->capacity_locked = lk->is_battery_locked;
	p->capacity_locked_ah = mah_to_ah(lk->locked_capacity_mah);

	p->prop_locked = lk->is_prop_locked;
	p->prop_diameter_m = in_to_m(lk->locked_diameter_in);
	p->prop_pitch_m = in_to_m(lk->locked_pitch_in);
	p->kv_locked = lk->is_motor_locked;
	p->kv = lk->locked_kv;
	p->n_blades = so->num_blades;
	int pc = ao->propeller_class;
	if (pc == PROP_AUTO) {
		double d = p->prop_locked ? p->prop_diameter_m
		    : aero_overlap_limit_m(p->wheelbase_m,
		        p->coaxial ? p->n_rotors / 2 : p->n_rotors, AERO_TIP_CLEARANCE);
		pc = d > PROP_AUTO_CARBON_ABOVE_M ? PROP_CARBON : PROP_PLASTIC;
	}
	p->prop_kg_per_m22 = prop_k[pc];

	p->fom_override = ao->figure_of_merit;
	p->fom_isolated = ao->figure_of_merit_isolated;
	p->fom_isolated_mode = ao->figure_of_merit_mode == FOM_ISOLATED;
	p->kappa = md->cal.kappa;
	p->re_ref = md->cal.re_ref;
	p->interference_c = arm_interference_c[so->arm_config];
	p->eta_drive = ao->propulsive_efficiency;
	p->cd_h = ao->cd_horizontal;
	p->cd_v = ao->cd_vertical;
	p->wake_share = md->cal.wake_share;
	p->f_scale = ao->area_scaling_factor > 0.0 ? ao->area_scaling_factor
	    : body_f_scale[ao->aero_body_class] * md->cal.drag_scale;
	p->ct = ao->assumed_ct;

	p->c_body = so->geometry_constant;
	p->alpha_w = so->wall_thickness_ratio;
	p->gamma = so->body_mass_multiplier;
	p->lambda = md->cal.lambda[model_lambda_index(s->airframe_class, s->num_rotors)];
	p->fixed_frame_kg = s->fixed_airframe_mass_kg;
	p->equip_kg = md->cal.equip_kg[s->airframe_class];
	p->equip_exponent = md->cal.equip_exponent;
	p->avionics_share = cls->avionics_share;

	p->wire_coef = p->small_platform ? md->cal.wire_coef_small : md->cal.wire_coef;

	p->marketing = !baseline && s->evaluate_marketing_limits;
	p->max_iter = SIZING_MAX_ITER;
}

static void
mass_diff(const struct res_mass *a, const struct res_mass *b, struct res_mass *d)
{
	d->payload_kg = a->payload_kg - b->payload_kg;
	d->battery_kg = a->battery_kg - b->battery_kg;
	d->frame_kg = a->frame_kg - b->frame_kg;
	d->arm_kg = a->arm_kg - b->arm_kg;
	d->motor_kg = a->motor_kg - b->motor_kg;
	d->prop_kg = a->prop_kg - b->prop_kg;
	d->esc_kg = a->esc_kg - b->esc_kg;
	d->wiring_kg = a->wiring_kg - b->wiring_kg;
	d->avionics_kg = a->avionics_kg - b->avionics_kg;
	d->role_aux_kg = a->role_aux_kg - b->role_aux_kg;
	d->other_kg = a->other_kg - b->other_kg;
	d->total_kg = a->total_kg - b->total_kg;
}

/* The propeller diameters a continuous design tries: the largest the
 * wheelbase admits, then each PROP_STEP smaller, N_PROP_FRACS in all (down
 * to 32 %).  The paper's overlap limit (eq. overlap) is a bound, not a
 * choice: a smaller rotor needs more power for the same thrust but turns
 * faster, and a motor weighs by its torque (sizing_motor_kg), so a light
 * aircraft on a wide frame is lighter on smaller rotors. */
#define PROP_STEP    0.85
#define N_PROP_FRACS 8

static double
prop_frac(int k)
{
	return pow(PROP_STEP, (double)k);
}

/* Plain sentences about what the solver decided and what binds. */
static void
explain(const struct sizing_params *p, const struct res_run *o,
        const struct mission_spec *s, struct solve_result *r)
{
	const char *rw = rotor_word(p->n_rotors, p->coaxial);
	char chem[64], v1[32], v2[32];
	res_chemistry_text(o->chemistry, chem, sizeof chem);
	res_rationale(r, "Sized as %s %s on a %.0f mm wheelbase (%s class).",
	    strchr("AEIOU", rw[0]) != NULL ? "an" : "a", rw, p->wheelbase_m * 1000.0,
	    spec_enum_airframe[p->airframe_class]);
	if (p->prop_locked)
		res_rationale(r, "Propeller %.1f × %.1f in is locked by the mission.",
		    o->opt.prop_diameter_in, o->opt.prop_pitch_in);
	else if (p->prop_frac < 1.0 && o->largest.tried && o->largest.passes)
		res_rationale(r, "Propeller %.1f × %.1f in, %.0f %% of the largest the "
		    "wheelbase admits (%.1f in): motor mass argues for it.  On the "
		    "largest the aircraft weighs %.2f kg, not %.2f: its slower, "
		    "higher-torque motors alone weigh %.2f kg, not %.2f.",
		    o->opt.prop_diameter_in, o->opt.prop_pitch_in,
		    100.0 * p->prop_frac, o->overlap_limit_in, o->largest.mass_kg,
		    o->mass.total_kg, o->largest.motor_kg, o->mass.motor_kg);
	else if (p->prop_frac < 1.0)
		res_rationale(r, "Propeller %.1f × %.1f in, %.0f %% of the largest the "
		    "wheelbase admits (%.1f in), the lightest that meets the mission: "
		    "on the largest, %.110s.",
		    o->opt.prop_diameter_in, o->opt.prop_pitch_in, 100.0 * p->prop_frac,
		    o->overlap_limit_in, o->largest.fails[0] ? o->largest.fails
		    : "it was not tried");
	else
		res_rationale(r, "Propeller %.1f × %.1f in: the largest the wheelbase "
		    "admits with 5 %% tip clearance, %s; pitch from the hover inflow "
		    "plus 4° incidence.", o->opt.prop_diameter_in, o->opt.prop_pitch_in,
		    o->feasible ? "the lightest passing design of the diameters tried"
		    : "as no diameter tried passes every check");
	res_rationale(r, "Hover throttle %.0f %% (thrust margin %.0f %%) gives a "
	    "design thrust-to-weight ratio of %.2f.", 100.0 * o->hover_throttle,
	    100.0 * (1.0 - o->hover_throttle), o->thrust_to_weight);
	if (s->locks.is_battery_locked)
		res_rationale(r, "Battery locked at %dS %.0f mAh; everything else "
		    "re-sized around it.", o->cell_count, o->capacity_mah);
	else if (p->cells_fixed > 0)
		res_rationale(r, "%dS bus fixed by the mission.", o->cell_count);
	else if (p->kv_locked)
		res_rationale(r, "%dS chosen so that the locked %.0f KV motor reaches "
		    "full-throttle rpm.", o->cell_count, p->kv);
	else {
		double budget = SIZING_CURRENT_BUDGET_A * sqrt(o->mass.total_kg);
		if (o->peak_current_a <= budget * 1.0001)
			res_rationale(r, "%dS %s: the lightest of the series counts "
			    "keeping the full-throttle current (%.0f A) within the "
			    "%.0f A harness budget of a %.1f kg aircraft (more cells: "
			    "a lighter harness, smaller and heavier cells).",
			    o->cell_count, chem, o->peak_current_a, budget,
			    o->mass.total_kg);
		else
			res_rationale(r, "%dS %s: the %s class allows at most %dS, so "
			    "the full-throttle current (%.0f A) stays above the %.0f A "
			    "harness budget; wiring and ESCs are sized for it.",
			    o->cell_count, chem,
			    spec_enum_airframe[p->airframe_class], p->cells_hi,
			    o->peak_current_a, budget);
	}
	if (!s->locks.is_battery_locked && o->battery_power_binds)
		res_rationale(r, "Battery capacity %.0f mAh (%.0f Wh) is set by "
		    "power, not energy: %s cells must deliver the %.0f W full-throttle "
		    "burst and every sustained phase, which needs more cells than the "
		    "mission's energy.", o->capacity_mah, o->energy_wh, chem,
		    o->peak_power_w);
	else if (!s->locks.is_battery_locked)
		res_rationale(r, "Battery capacity %.0f mAh (%.0f Wh): the charge the "
		    "mission draws in the discharge simulation and 20 %% more, so that "
		    "the aircraft lands with its %.1f %% reserve.", o->capacity_mah,
		    o->energy_wh, 100.0 * o->reserve_soc);
	res_rationale(r, "Target motor KV %.0f rpm/V: full-throttle rotor speed "
	    "%.0f rpm on a %.1f V bus.", o->opt.motor_kv, o->rpm_peak,
	    (double)o->cell_count * p->chem->v_full);
	res_rationale(r, "Arms Ø%.1f mm × %.2f mm CFRP, sized by %s: motor tilt "
	    "%.2f° at full thrust (at most %.0f°), factor of safety %.1f on the "
	    "fatigue strength%s.", o->arm_outer_diameter_mm,
	    o->arm_wall_thickness_mm, o->arm_sized_by != NULL ? o->arm_sized_by
	    : "strength", o->arm_tilt_full_deg, STRUCT_TILT_MAX_DEG,
	    o->arm_safety_factor, o->min_fraction_binds ? "; the frame's mass "
	    "is set by the minimum structural share for this wheelbase" : "");
	bool stiff = o->arm_natural_frequency_hz >= o->blade_pass_frequency_hz;
	res_rationale(r, "Arm first bending mode %.0f Hz: %s the in-flight "
	    "blade-pass band %.0f–%.0f Hz, %s the rotor's steady %.0f–%.0f Hz.",
	    o->arm_natural_frequency_hz, stiff ? "stiff, above" : "soft, below",
	    o->blade_pass_low_hz, o->blade_pass_frequency_hz,
	    o->arm_natural_frequency_hz < o->rev_band_low_hz ? "below"
	    : o->arm_natural_frequency_hz > o->rev_band_high_hz ? "above" : "within",
	    o->rev_band_low_hz, o->rev_band_high_hz);
	if (p->v_auto)
		res_rationale(r, "Forward speed %.1f m/s: the minimum-power speed of "
		    "the 1–30 m/s sweep.", o->optimal_speed_ms);
	if (o->time_scale < 1.0 && !r->ceiling.shown)
		res_rationale(r, "Shorter flight: the mission as asked does not size, "
		    "so every phase is flown at %.0f %% of its requested time (the "
		    "mission allows it: locks.auto_reduce_flight_time).",
		    100.0 * o->time_scale);
	/* The loop's gain dF/dM in an engineer's words: the mass growth
	 * factor 1 / (1 - dF/dM) (the solver appendix gives the rest). */
	if (o->converged && o->lipschitz < 1.0)
		res_rationale(r, "Mass growth: each kilogram added to the aircraft "
		    "calls for %.2f kg more battery, structure and motors, so a "
		    "kilogram of payload costs %.1f kg of takeoff mass.",
		    o->lipschitz, 1.0 / (1.0 - o->lipschitz));
	else if (o->converged)
		res_rationale(r, "Mass growth: each kilogram added to the aircraft "
		    "calls for %.2f kg more battery, structure and motors, more than "
		    "it adds itself: the design sits on the edge of runaway mass "
		    "growth, and any added payload or equipment tips it over.",
		    o->lipschitz);
	/* What binds: the tightest passing check not sized to its limit. */
	const struct res_check *t = res_tightest_check(o);
	if (t != NULL)
		res_rationale(r, "Tightest remaining constraint: %s at %s (%s%s%s "
		    "against a limit of %s%s%s, margin %.0f %%).", t->name, t->condition,
		    numfmt_sig(v1, sizeof v1, t->value, 3), t->unit[0] ? " " : "", t->unit,
		    numfmt_sig(v2, sizeof v2, t->limit, 3), t->unit[0] ? " " : "", t->unit,
		    100.0 * t->margin);
}

/* Is every number a run stores finite?  The formats and the PDF refuse NaN. */
static bool
run_finite(const struct res_run *o)
{
	const struct res_mass *m = &o->mass;
	double v[] = { m->total_kg, m->battery_kg, m->frame_kg, m->arm_kg,
		m->motor_kg, m->prop_kg, m->esc_kg, m->wiring_kg, o->lipschitz,
		o->capacity_mah, o->energy_wh, o->max_battery_temp_c,
		o->min_terminal_voltage_v, o->arm_natural_frequency_hz,
		o->hover_endurance_s, o->peak_power_w, o->downwash_ms };
	for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
		if (!isfinite(v[i]))
			return false;
	for (int i = 0; i < o->n_trace; i++)
		if (!isfinite(o->trace[i].v_term_v) || !isfinite(o->trace[i].temp_c))
			return false;
	return true;
}

/* Replace non-finite numbers by 0 so nothing unphysical is ever printed;
 * the caller has already turned the run into a violation. */
static void
scrub(struct res_run *o)
{
	double *d = (double *)(void *)&o->mass;
	for (size_t i = 0; i < sizeof o->mass / sizeof(double); i++)
		if (!isfinite(d[i]))
			d[i] = 0.0;
	for (int i = 0; i < o->n_history; i++)
		if (!isfinite(o->history_kg[i]))
			o->history_kg[i] = SIZING_RUNAWAY_KG;
}

/* The feasibility gate of one run; false, with o marked as not run, when
 * it stops the run. */
static bool
run_gate(const struct sizing_params *p, const char *name, struct res_run *o,
         struct solve_result *r)
{
	if (feasibility_gate(p, name, r))
		return true;
	memset(o, 0, sizeof *o);
	o->ran = false;
	snprintf(o->termination, sizeof o->termination,
	    "rejected by the feasibility gate");
	return false;
}

/* What follows one run's mass loop: the non-finite guard, the checks and
 * violations, the custom run's rationale. */
static void
run_finish(const struct sizing_params *p, const char *name, bool baseline,
           enum sizing_status st, const struct mission_spec *s,
           struct res_run *o, struct solve_result *r, int *rc)
{
	if (!run_finite(o)) {
		scrub(o);
		if (st != SIZING_RUNAWAY)
			*rc = 3;
	}
	feasibility_checks(p, st, name, o, r);
	/* A custom run that fails is explained by its ceiling instead
	 * (engine_solve()): its own figures describe no aircraft. */
	if (!baseline && o->ran && o->feasible)
		explain(p, o, s, r);
}


/* Does run t, a sizing_run() of p, stand as a continuous design: finite,
 * converged and passing every check (judged on a scratch result)? */
static bool
design_passes(const struct sizing_params *p, enum sizing_status st,
              const char *name, struct res_run *t, struct solve_result *scratch)
{
	if (!run_finite(t))
		return false;
	scratch->n_violations = 0;
	feasibility_checks(p, st, name, t, scratch);
	return t->converged && t->feasible;
}

/* What the largest rotor gave, for the rationale: kept in t->largest, so
 * it travels with whichever run the search keeps (*best is a copy). */
static void
note_largest(struct res_run *t, bool ok, const struct solve_result *scratch)
{
	struct res_largest_rotor *l = &t->largest;
	memset(l, 0, sizeof *l);
	l->tried = true;
	l->passes = ok;
	l->mass_kg = t->mass.total_kg;
	l->motor_kg = t->mass.motor_kg;
	l->battery_kg = t->mass.battery_kg;
	if (ok)
		return;
	/* The first check it fails, said short enough for a rationale line. */
	for (int i = 0; i < t->n_checks; i++) {
		const struct res_check *c = &t->checks[i];
		if (c->pass || c->advisory)
			continue;
		char v1[32], v2[32];
		snprintf(l->fails, sizeof l->fails, "%s at %s is %s%s%s, the limit "
		    "%s%s%s", c->name, c->condition, numfmt_sig(v1, sizeof v1, c->value, 3),
		    c->unit[0] ? " " : "", c->unit, numfmt_sig(v2, sizeof v2, c->limit, 3),
		    c->unit[0] ? " " : "", c->unit);
		return;
	}
	snprintf(l->fails, sizeof l->fails, "%s", scratch->n_violations > 0
	    ? scratch->violations[0].message : t->termination);
}

/* The lightest passing design over every diameter prop_frac() gives: the
 * continuous design is the lightest aircraft that meets every requirement
 * over its design variables, so every share is tried (the minimum over a
 * fixed set of designs cannot rise when a requirement falls).  Fills *best
 * (the largest share's run when none passes), *best_frac and *passes;
 * returns that run's status.  With `any`, only *passes is asked: the
 * shares stop at the first that passes (*best is then that one). */
static enum sizing_status
lightest_share(struct sizing_params *p, const char *name, struct res_run *best,
               double *best_frac, bool *passes, struct solve_result *scratch,
               bool any)
{
	struct res_run *t = &scratch->custom;
	enum sizing_status best_st = SIZING_RUNAWAY;
	struct res_largest_rotor largest;
	memset(&largest, 0, sizeof largest);
	*passes = false;
	for (int k = 0; k < N_PROP_FRACS; k++) {
		p->prop_frac = prop_frac(k);
		*t = *best;
		enum sizing_status st = sizing_run(p, t);
		bool ok = design_passes(p, st, name, t, scratch);
		if (k == 0)
			note_largest(t, ok, scratch);
		if (k > 0)
			t->largest = largest;
		else
			largest = t->largest;
		if (k == 0 || (ok && (!*passes
		    || t->mass.total_kg < best->mass.total_kg))) {
			*best = *t;
			*best_frac = p->prop_frac;
			best_st = st;
			*passes = ok;
		}
		if (any && *passes)
			break;
	}
	return best_st;
}

/* A continuous design's propeller: with a locked one the mass loop once;
 * else the lightest passing design over the diameters prop_frac() gives,
 * or the largest (the paper's choice) when none passes.  A locked battery
 * takes the diameter the mission's energy argues for: the one the same
 * design with its battery sized to the mission chooses (with the pack
 * fixed, a smaller rotor only spends the pack's spare energy on lighter
 * motors, which no designer would do).  Fills *o (its checks not yet
 * made) and p->prop_frac; returns the loop's status. */
static enum sizing_status
prop_search(struct sizing_params *p, const char *name, struct res_run *o,
            const struct solve_result *r)
{
	p->prop_frac = 1.0;
	if (p->prop_locked)
		return sizing_run(p, o);
	struct solve_result *scratch = xcalloc(1, sizeof *scratch);
	struct res_run *best = xmalloc(sizeof *best);
	scratch->mission = r->mission;
	double frac = 1.0;
	bool passes;
	enum sizing_status st;
	*best = *o;
	if (p->capacity_locked) {
		struct sizing_params sized = *p;
		sized.capacity_locked = false;
		lightest_share(&sized, name, best, &frac, &passes, scratch, false);
		if (!passes)
			frac = 1.0;
		p->prop_frac = frac;
		*best = *o;
		st = sizing_run(p, best);
	} else {
		st = lightest_share(p, name, best, &frac, &passes, scratch, false);
	}
	*o = *best;
	p->prop_frac = frac;
	free(best);
	free(scratch);
	return st;
}

/* ---- the ceiling of a mission beyond reach ------------------------------ */

#define CEILING_BISECT 10   /* bisection steps: 1/1024 of the range */
#define CEILING_TIGHT  0.02 /* a check within 2 % of its limit binds */

/* May a bisection step ask reachable() for its answer only?  (Test
 * builds: not with AEROEVAL_TEST_EXHAUSTIVE, which sizes every share.) */
static bool
answer_only(void)
{
#ifdef AEROEVAL_TEST_HOOKS
	return getenv("AEROEVAL_TEST_EXHAUSTIVE") == NULL;
#else
	return true;
#endif
}

/* Does a continuous design that passes every check exist for the custom
 * parameters p with every phase at share gamma of its request and the
 * payload (and the largest payload) at share payload_scale?  The design
 * into *out (scratch holds its checks): the lightest that passes, or, with
 * `any` (the answer only, for a bisection step), the first found. */
static bool
reachable(const struct sizing_params *p0, double gamma, double payload_scale,
          struct res_run *out, struct solve_result *scratch, bool any)
{
	struct sizing_params p = *p0;
	p.time_scale = gamma;
	p.allow_relax = false;
	p.payload_kg *= payload_scale;
	p.extra_payload_kg *= payload_scale;
	p.drop_mass_kg *= payload_scale;
	p.role_aux_kg *= payload_scale;
	memset(out, 0, sizeof *out);
	if (p.prop_locked || p.capacity_locked) {
		enum sizing_status st = prop_search(&p, "custom", out, scratch);
		out->prop_frac = p.prop_frac;
		return design_passes(&p, st, "custom", out, scratch);
	}
	double frac = 1.0;
	bool passes;
	struct solve_result *inner = xcalloc(1, sizeof *inner);
	inner->mission = scratch->mission;
	lightest_share(&p, "custom", out, &frac, &passes, inner, any);
	out->prop_frac = frac;
	p.prop_frac = frac;
	if (passes) {
		/* The checks of the run kept, into scratch. */
		scratch->n_violations = 0;
		feasibility_checks(&p, SIZING_CONVERGED, "custom", out, scratch);
	}
	free(inner);
	return passes;
}

/* The mission as asked does not size: find what does (PRODUCT "A mission
 * beyond what its geometry can reach gets its ceiling").  The longest
 * flight at the asked payload, as the largest share of every phase that
 * sizes, and the largest payload that flies the whole mission, each by
 * bisection (a shorter flight or a lighter payload is an easier mission,
 * and the sized designs are monotone in both: test_monotone.c).  The
 * longest flight's design replaces the run that failed in r->custom, so
 * that no page shows a diverged iterate; its violations stay. */
static void
ceiling(const struct sizing_params *p, struct solve_result *r)
{
	struct res_ceiling *c = &r->ceiling;
	memset(c, 0, sizeof *c);
	c->valid = true;
	c->min_time_scale = SIZING_GAMMA_MIN;
	for (int i = 0; i < r->n_violations; i++)
		if (strcmp(r->violations[i].run, "custom") == 0) {
			const char *msg = r->violations[i].message;
			snprintf(c->binds_code, sizeof c->binds_code, "%s", r->violations[i].code);
			snprintf(c->binds, sizeof c->binds, "%s", msg);
			/* It follows a colon: "The takeoff mass ..." -> "the ...",
			 * an acronym ("RPM ...") kept. */
			if (c->binds[0] >= 'A' && c->binds[0] <= 'Z' && c->binds[1] >= 'a'
			    && c->binds[1] <= 'z')
				c->binds[0] = (char)(c->binds[0] - 'A' + 'a');
			break;
		}
	struct solve_result *scratch = xcalloc(1, sizeof *scratch);
	struct res_run *t = xmalloc(sizeof *t), *best = xmalloc(sizeof *best);
	scratch->mission = r->mission;

	/* The longest flight at the asked payload. */
	double lo = SIZING_GAMMA_MIN, hi = 1.0;
	if (reachable(p, lo, 1.0, best, scratch, false)) {
		c->endurance_found = true;
		/* The steps ask only whether some design passes; the lightest
		 * is sized once, at the share found (the same design: reachable()
		 * is a function of its arguments). */
		bool any = answer_only();
		for (int k = 0; k < CEILING_BISECT; k++) {
			double mid = 0.5 * (lo + hi);
			if (reachable(p, mid, 1.0, t, scratch, any)) {
				lo = mid;
				if (!any)
					*best = *t;
			} else {
				hi = mid;
			}
		}
		if (any && lo > SIZING_GAMMA_MIN)
			reachable(p, lo, 1.0, best, scratch, false);
		c->time_scale = lo;
		/* What binds there: a check the longest flight meets with
		 * (almost) no margin, else what stopped the mission as asked. */
		const struct res_check *tight = res_tightest_check(best);
		if (tight != NULL && tight->margin < CEILING_TIGHT) {
			snprintf(c->binds_code, sizeof c->binds_code, "CHECK");
			char v1[32], v2[32];
			snprintf(c->binds, sizeof c->binds, "%s reaches its limit (%s%s%s "
			    "against %s) on the longest flight that sizes; beyond it the "
			    "mission fails.", tight->name, numfmt_sig(v1, sizeof v1, tight->value, 3),
			    tight->unit[0] ? " " : "", tight->unit,
			    numfmt_sig(v2, sizeof v2, tight->limit, 3));
		}
		c->flight_time_s = best->flight_time_s;
		c->hover_endurance_s = best->hover_endurance_s;
		c->mass_kg = best->mass.total_kg;
		/* The ceiling design stands in the custom run's place, with its
		 * own checks (all passed); the asked mission's violations stay. */
		r->custom = *best;
		c->shown = true;
	}

	/* The largest payload that flies the whole mission. */
	if (r->mission.payload_kg > 0.0 && reachable(p, 1.0, 0.0, t, scratch, false)) {
		c->payload_found = true;
		double plo = 0.0, phi = 1.0, m = t->mass.total_kg;
		bool any = answer_only();
		for (int k = 0; k < CEILING_BISECT; k++) {
			double mid = 0.5 * (plo + phi);
			if (reachable(p, 1.0, mid, t, scratch, any)) {
				plo = mid;
				if (!any)
					m = t->mass.total_kg;
			} else {
				phi = mid;
			}
		}
		if (any && plo > 0.0 && reachable(p, 1.0, plo, t, scratch, false))
			m = t->mass.total_kg;
		c->max_payload_kg = plo * r->mission.payload_kg;
		c->mass_at_payload_kg = m;
	}
	free(best);
	free(t);
	free(scratch);
}

/* The ceiling's sentences, then the shown design's own (explain()). */
static void
explain_ceiling(const struct sizing_params *p0, struct solve_result *r)
{
	const struct res_ceiling *c = &r->ceiling;
	const struct mission_spec *s = &r->mission;
	res_rationale(r, "Beyond reach as asked: %s", c->binds[0] ? c->binds
	    : "the continuous design fails a check.");
	if (c->endurance_found)
		res_rationale(r, "The longest flight that sizes at the asked payload "
		    "is %.0f %% of the mission (%.1f of %.1f min), on a %.2f kg "
		    "aircraft; the design shown is that aircraft.",
		    100.0 * c->time_scale, c->flight_time_s / 60.0,
		    c->flight_time_s / c->time_scale / 60.0, c->mass_kg);
	else
		res_rationale(r, "No shorter flight sizes either: not even %.0f %% of "
		    "the mission at the asked payload.", 100.0 * SIZING_GAMMA_MIN);
	if (c->payload_found)
		res_rationale(r, "The largest payload that flies the whole mission is "
		    "%.2f kg of the %.2f kg asked, on a %.2f kg aircraft.",
		    c->max_payload_kg, s->payload_kg, c->mass_at_payload_kg);
	else if (s->payload_kg > 0.0)
		res_rationale(r, "Without any payload the mission does not size "
		    "either: the geometry and class bind, not the payload.");
	if (c->shown) {
		struct sizing_params p = *p0;
		p.prop_frac = r->custom.prop_frac;
		explain(&p, &r->custom, s, r);
	}
}

/* Does the mission shed payload on the way (a drop or a spray)? */
static bool
sheds(const struct mission_spec *m)
{
	return m->payload_role.mass_shedding && (m->payload_role.type == ROLE_DELIVERY
	    || m->payload_role.type == ROLE_AGRICULTURE);
}

/* The role overhead and its rationale line. */
static void
role_overhead(struct solve_result *r)
{
	/* Only between two designs of the same mission: not against a
	 * diverged run, nor against the ceiling's shorter flight. */
	if (!r->baseline.ran || !r->custom.ran || !r->baseline.converged
	    || !r->custom.converged || r->ceiling.valid)
		return;
	mass_diff(&r->custom.mass, &r->baseline.mass, &r->role_overhead);
	if (r->mission.payload_role.type == ROLE_NONE)
		return;
	if (r->role_overhead.total_kg >= 0.0)
		res_rationale(r, "The %s role adds %.2f kg over the baseline, the "
		    "same mission without the role's equipment (%.2f kg → %.2f kg).",
		    spec_enum_role[r->mission.payload_role.type],
		    r->role_overhead.total_kg, r->baseline.mass.total_kg,
		    r->custom.mass.total_kg);
	else
		res_rationale(r, "With the %s role the aircraft is %.2f kg lighter "
		    "than the baseline (%.2f kg → %.2f kg): %s.",
		    spec_enum_role[r->mission.payload_role.type],
		    -r->role_overhead.total_kg, r->baseline.mass.total_kg,
		    r->custom.mass.total_kg, sheds(&r->mission)
		    ? "the baseline carries its payload as dead weight for the whole "
		      "flight, the role's aircraft sheds it on the way"
		    : "the baseline is sized to a fixed 60 % hover throttle, the "
		      "role to its own thrust margin");
}

void
engine_loop_interval(double dry_share, double battery_share, double lipschitz,
                     const struct model_spread *dry, const struct model_spread *fwd,
                     double *log_lo, double *log_hi)
{
	double l = lipschitz < 0.0 ? 0.0 : lipschitz > ENGINE_MAX_L ? ENGINE_MAX_L
	    : lipschitz;
	double gain = 1.0 / (1.0 - l);
	/* A real endurance longer than the model's (fwd > 0) means less power
	 * and so a lighter battery: the forward spread enters reversed. */
	*log_lo = gain * (dry_share * dry->log_lo - battery_share * fwd->log_hi);
	*log_hi = gain * (dry_share * dry->log_hi - battery_share * fwd->log_lo);
}

/* The model's calibrated accuracy for a mission like this one (its battery
 * sized or locked), and the intervals of the design of record, each its
 * own: the takeoff mass of an aircraft its bill of materials builds is the
 * published mass of its parts plus the lines the model estimates (frame,
 * arms, harness, allowances), whose uncertainty is the dry-mass model's;
 * a continuous design's carries the open-loop errors through its own loop
 * gain (engine_loop_interval()).  Hover power and endurance carry the
 * forward check's spread. */
static void
accuracy(struct solve_result *r, const struct model_data *md)
{
	const struct mission_spec *s = &r->mission;
	bool locked = s->locks.is_battery_locked;
	const struct model_accuracy *a = &md->cal.accuracy[locked ? MODEL_PACK_LOCKED
	    : MODEL_FROM_ENDURANCE];
	const struct model_spread *dry = &md->cal.dry, *fwd = &md->cal.forward;
	struct res_accuracy *o = &r->accuracy;
	struct res_design_intervals *di = &r->intervals;
	memset(o, 0, sizeof *o);
	memset(di, 0, sizeof *di);
	memset(&r->mtow_interval, 0, sizeof r->mtow_interval);
	if (a->valid) {
		const struct model_interval *iv = model_interval_for(a, s->airframe_class);
		o->valid = true;
		o->pack_locked = locked;
		o->n_rows = a->n_rows;
		o->mape = a->loo_mape_pct / 100.0;
		o->battery_mape = a->loo_battery_mape_pct / 100.0;
		o->level = a->level;
		o->ratio_lo = exp(iv->log_lo);
		o->ratio_hi = exp(iv->log_hi);
		o->interval_rows = iv->n;
		o->coverage = a->coverage;
		o->design_coverage = a->design_coverage;
	}
	bool buildable;
	const struct res_run *rec = res_record(r, &buildable);
	/* No interval around a loop's last iterate, nor around the ceiling's
	 * shorter flight: neither is the aircraft asked for. */
	if (rec == NULL || !rec->ran || !rec->converged || !(rec->mass.total_kg > 0.0)
	    || !dry->valid || !fwd->valid || r->ceiling.valid)
		return;
	double m = rec->mass.total_kg;
	r->mtow_interval.valid = true;
	r->mtow_interval.level = dry->level;
	if (buildable) {
		double est = 0.0;
		for (int i = 0; i < r->n_bom && i < RES_MAX_BOM; i++)
			if (r->bom[i].catalogue_id[0] == '\0'
			    && strcmp(r->bom[i].category, "payload") != 0)
				est += r->bom[i].total_mass_kg;
		di->from_parts = true;
		di->estimated_kg = est;
		r->mtow_interval.lo_kg = m - est + est * exp(dry->log_lo);
		r->mtow_interval.hi_kg = m - est + est * exp(dry->log_hi);
	} else {
		double lo, hi;
		engine_loop_interval((m - rec->mass.payload_kg - rec->mass.battery_kg) / m,
		    rec->mass.battery_kg / m, rec->lipschitz, dry, fwd, &lo, &hi);
		di->loop_gain = 1.0 / (1.0 - fmin(fmax(rec->lipschitz, 0.0), ENGINE_MAX_L));
		r->mtow_interval.lo_kg = m * exp(lo);
		r->mtow_interval.hi_kg = m * exp(hi);
	}
	if (rec->hover_power_w > 0.0 && rec->hover_endurance_s > 0.0) {
		di->power_valid = true;
		di->hover_power_w = rec->hover_power_w;
		di->endurance_s = rec->hover_endurance_s;
		/* The spread is on ln(published / model) endurance: the power
		 * moves the other way. */
		di->endurance_lo_s = rec->hover_endurance_s * exp(fwd->log_lo);
		di->endurance_hi_s = rec->hover_endurance_s * exp(fwd->log_hi);
		di->hover_power_lo_w = rec->hover_power_w * exp(-fwd->log_hi);
		di->hover_power_hi_w = rec->hover_power_w * exp(-fwd->log_lo);
	}
}

int
engine_solve(const struct mission_spec *spec, const struct model_data *md,
             const struct catalog *cat, struct solve_result *r)
{
	int rc = 0;
	r->mission = *spec;
	engine_resolve(&r->mission, md, r);

	/* Each continuous design chooses its propeller (prop_search). */
	struct sizing_params p;
	engine_params(&r->mission, md, true, &p);
	if (run_gate(&p, "baseline", &r->baseline, r)) {
		enum sizing_status st = prop_search(&p, "baseline", &r->baseline, r);
		run_finish(&p, "baseline", true, st, &r->mission, &r->baseline, r, &rc);
		r->baseline.prop_frac = p.prop_frac;
	}
	engine_params(&r->mission, md, false, &p);
	if (run_gate(&p, "custom", &r->custom, r)) {
		enum sizing_status st = prop_search(&p, "custom", &r->custom, r);
		run_finish(&p, "custom", false, st, &r->mission, &r->custom, r, &rc);
		r->custom.prop_frac = p.prop_frac;
		if (rc == 0 && !r->custom.feasible && !r->skip_ceiling) {
			ceiling(&p, r);
			explain_ceiling(&p, r);
		}
	}
	role_overhead(r);

	/* Real parts on top of a custom run that meets the mission as asked
	 * (parts.h); a mission beyond reach has none to match. */
	if (cat != NULL && r->custom.ran && r->custom.converged && !r->ceiling.valid
	    && parts_select(&r->mission, &p, md, cat, r) != 0)
		rc = 3;
	r->feasible = r->n_violations == 0 && r->custom.ran && r->custom.feasible;
	accuracy(r, md);
	/* Nothing leaves the engine that breaks the physics (invariants.h). */
	if (rc == 0)
		rc = invariants_check(r, r->internal_error, sizeof r->internal_error);
	else if (r->internal_error[0] == '\0')
		snprintf(r->internal_error, sizeof r->internal_error,
		    "a non-finite value reached the result");
	return rc;
}

bool
engine_at_mass(const struct mission_spec *spec, const struct model_data *md,
               double mass_kg, double share, struct sizing_open *out)
{
	struct mission_spec s = *spec;
	engine_resolve(&s, md, NULL);
	struct sizing_params p;
	engine_params(&s, md, false, &p);
	if (p.prop_locked || share > 0.0) {
		p.prop_frac = p.prop_locked ? 1.0 : share;
		bool ok = sizing_at_mass(&p, mass_kg, out);
		out->prop_frac = p.prop_frac;
		return ok;
	}
	/* The diameter the designer would choose at this mass: of those the
	 * closed loop tries, the one that closes lightest. */
	bool any = false;
	for (int k = 0; k < N_PROP_FRACS; k++) {
		struct sizing_open t;
		p.prop_frac = prop_frac(k);
		if (sizing_at_mass(&p, mass_kg, &t)
		    && (!any || t.mass.total_kg < out->mass.total_kg)) {
			*out = t;
			out->prop_frac = p.prop_frac;
			any = true;
		}
	}
	if (!any) {
		p.prop_frac = 1.0;
		sizing_at_mass(&p, mass_kg, out);
		out->prop_frac = 1.0;
	}
	return any;
}

bool
engine_endurance_at_mass(const struct mission_spec *spec,
                         const struct model_data *md, double mass_kg,
                         double share, double v_forward_ms,
                         struct sizing_endurance *out)
{
	struct mission_spec s = *spec;
	engine_resolve(&s, md, NULL);
	struct sizing_params p;
	engine_params(&s, md, false, &p);
	p.prop_frac = p.prop_locked || !(share > 0.0) ? 1.0 : share;
	return p.capacity_locked && sizing_endurance_at_mass(&p, mass_kg,
	    v_forward_ms, out);
}

void
engine_explore(struct solve_result *r, const struct model_data *md)
{
	struct res_run *o = &r->custom;
	o->n_endurance = 0;
	o->endurance_inflection_scale = 0.0;
	/* A run that ran away has no fixed point to explore around. */
	if (!o->ran || !(o->fixed.mass_kg > 0.0))
		return;
	struct sizing_params p;
	engine_params(&r->mission, md, false, &p);
	p.prop_frac = o->prop_frac;
	sizing_explore(&p, o);
}
