/* airframe.c — the structure, body, harness and avionics masses (see
 * airframe.h). */
#include "sizing/airframe.h"

#include <math.h>

#include "result/result.h"

#define S_SCALE_LO_KG     0.3   /* S_scale = 0.25 below this M_ref */
#define S_SCALE_HI_KG     1.8   /* S_scale = 1 above this M_ref */
#define S_SCALE_MIN       0.25

double
airframe_equipment_kg(const struct sizing_params *p, double design_mass_kg)
{
	double m = design_mass_kg > 0.0 ? design_mass_kg : 0.0;
	return p->equip_kg * pow(m, p->equip_exponent);
}

double
airframe_s_scale(double m_ref_kg)
{
	/* Paper §VI-E: light configurations get lighter ESCs and harnesses. */
	if (m_ref_kg <= S_SCALE_LO_KG)
		return S_SCALE_MIN;
	if (m_ref_kg >= S_SCALE_HI_KG)
		return 1.0;
	return S_SCALE_MIN + (1.0 - S_SCALE_MIN)
	    * (m_ref_kg - S_SCALE_LO_KG) / (S_SCALE_HI_KG - S_SCALE_LO_KG);
}

void
airframe_structure(const struct sizing_params *p,
                   const struct airframe_loads *in, struct airframe_masses *out)
{
	int arms = p->coaxial ? p->n_rotors / 2 : p->n_rotors;
	double arm_len = 0.5 * p->wheelbase_m;

	/* Arms: strength at max(load factor × CG thrust, full thrust),
	 * stiffness for the motor's tilt at full thrust and a first mode
	 * above the rate loop's bandwidth; the resonance with the rotor is checked
	 * afterwards (the checks table).  The CG polygon is that of the arms
	 * (a coaxial pair shares one). */
	double t_cg;
	out->cg_ok = structure_cg_thrust_n(in->mass_kg, arms, arm_len,
	    p->cg_shift_m, &t_cg);
	if (p->coaxial)
		t_cg *= 0.5; /* each rotor of the pair carries half the arm's share */
	double per_arm = p->coaxial ? 2.0 : 1.0;
	double force = fmax(p->load_factor * t_cg, in->peak_thrust_n) * per_arm;
	struct structure_arm_loads al = { force, in->peak_thrust_n * per_arm,
		in->peak_torque_nm * per_arm, in->tip_mass_kg * per_arm, arm_len,
		p->alpha_w, structure_rate_bandwidth_hz(in->prop_diameter_m) };
	structure_size_arm(&al, &out->arm);
	/* The paper's proxy for the size of the whole structure (joints,
	 * centre plates, body, gear: C_body and γ) is the strength-sized
	 * tube; the wall and diameter stiffness adds are tube alone and add
	 * on top, not multiplied through the body. */
	struct structure_arm strength;
	struct structure_arm_loads sl = al;
	sl.full_force_n = 0.0;
	sl.mode_floor_hz = 0.0;
	structure_size_arm(&sl, &strength);
	double tubes = (double)arms * strength.mass_kg;
	double stiffness_kg = (double)arms * (out->arm.mass_kg - strength.mass_kg);

	/* The minimum structural fraction floors the structure the strength
	 * sizes.  (The paper floors the spar and then adds γ on top, which
	 * puts an agricultural frame at >= 40 % of takeoff mass and makes
	 * every spraying mission diverge; see docs/model.md.) */
	double sized = p->c_body * tubes * (1.0 + p->gamma);
	double floor_kg = in->mass_kg * structure_min_fraction(p->wheelbase_m);
	out->min_fraction_binds = floor_kg > sized;
	double base = p->lambda * fmax(sized, floor_kg);
	double extra = p->lambda * stiffness_kg;
	if (p->fixed_frame_kg > 0.0) {
		base = p->fixed_frame_kg;
		extra = 0.0;
	}
	double frame_total = base + extra;
	out->frame_total_kg = frame_total;
	/* Split the structure: tubes, centre plates/joints, body and gear. */
	double unit = base / ((1.0 + p->gamma) * p->c_body);
	out->arm_kg = unit + extra;
	out->frame_kg = unit * (p->c_body - 1.0);
	out->other_kg = unit * p->c_body * p->gamma;

	out->wiring_kg = 0.0; /* airframe_harness() */
	double equip = airframe_equipment_kg(p, in->mass_kg);
	out->avionics_kg = p->avionics_share * equip;
	out->shell_kg = equip - out->avionics_kg;
	out->other_kg += out->shell_kg;
	out->role_aux_kg = p->role_aux_kg;
}

void
airframe_harness(const struct sizing_params *p, double peak_current_a,
                 struct airframe_masses *out)
{
	/* The harness scales with the current it carries (paper §VI-E). */
	double scale = airframe_s_scale(out->frame_total_kg + p->payload_kg);
	out->wiring_kg = p->wire_coef * peak_current_a * p->wheelbase_m * scale;
}

void
airframe_masses(const struct sizing_params *p, const struct airframe_loads *in,
                struct airframe_masses *out)
{
	airframe_structure(p, in, out);
	airframe_harness(p, in->peak_current_a, out);
}

void
airframe_record_arm(const struct structure_arm *arm, double prop_diameter_m,
                    struct res_run *run)
{
	run->arm_length_m = arm->length_m;
	run->arm_outer_diameter_mm = arm->d_out_m * 1000.0;
	run->arm_wall_thickness_mm = arm->wall_m * 1000.0;
	run->arm_stress_mpa = arm->stress_pa / 1e6;
	run->arm_stress_allow_mpa = structure_sigma_allow_pa() / 1e6;
	run->arm_natural_frequency_hz = arm->f_nat_hz;
	run->arm_wall_floor_binds = arm->wall_floor_binds;
	run->arm_sized_by = structure_sized_by_text[arm->sized_by];
	run->arm_safety_factor = arm->safety_factor;
	run->arm_tilt_full_deg = arm->tilt_full_deg;
	run->arm_deflection_full_mm = arm->deflection_full_m * 1000.0;
	run->arm_torsion_mpa = arm->torsion_pa / 1e6;
	run->arm_torsion_allow_mpa = structure_tau_allow_pa() / 1e6;
	run->rate_bandwidth_hz = structure_rate_bandwidth_hz(prop_diameter_m);
}
