/* structure.h — CFRP arm sizing, cantilever resonance, frame mass.
 *
 * Paper §V-A..C: hollow circular CFRP cantilever arms of length W/2 sized
 * for root bending (eq. dout) at σ_all = 720·0.40/1.5 = 192 MPa (eq.
 * sigallow), a minimum wall thickness, the CG-offset thrust, the size-
 * dependent minimum structural fraction, C_body and the class overhead γ,
 * and the Rayleigh–Ritz natural frequency (eq. fnat).
 *
 * Beyond the paper, the arm is also sized for stiffness (the motor tilts
 * at most STRUCT_TILT_MAX_DEG at full thrust, θ = F L² / 2EI) and for a
 * first mode above the flight controller's gyro filter; its torsion under
 * the motor's reaction torque is checked against the shear allowable.
 *
 * Resonance (paper §V-C) is a check, not a sizing criterion: the paper asks
 * f_nat >= 1.5 f_bpf at peak rpm (a stiff, subcritical arm).  Strength-sized
 * CFRP arms of real multirotors are almost always soft instead: their first
 * mode lies below the whole in-flight blade-pass band and is only crossed
 * during spin-up.  aeroeval therefore accepts either side with the paper's
 * 1.5 margin — f_nat >= 1.5 f_bpf(peak) or f_nat <= f_bpf(lowest flight
 * rpm) / 1.5 — and fails an arm whose mode sits inside the band.
 */
#ifndef AEROEVAL_STRUCTURE_H
#define AEROEVAL_STRUCTURE_H

#include <stdbool.h>

#define STRUCT_SIGMA_ULT_PA   720e6  /* CFRP ultimate bending strength, Pa */
#define STRUCT_FATIGUE        0.40   /* fatigue knock-down, - */
#define STRUCT_FOS            1.5    /* factor of safety, - */
#define STRUCT_RHO_CF_KG_M3   1600.0 /* CFRP density, kg/m^3 */
#define STRUCT_E_CF_PA        70e9   /* CFRP modulus, Pa */
#define STRUCT_MIN_WALL_M     0.0005 /* thinnest roll-wrapped CFRP tube wall, m */
#define STRUCT_RESONANCE_MARGIN 1.5  /* f_nat >= 1.5 f_bpf */
/* Stiffness and the loads the paper leaves out (docs/model.md, "Arms"). */
#define STRUCT_TILT_MAX_DEG   1.0    /* motor tilt from arm bending at full
                                        thrust: practice keeps it <= 1° */
#define STRUCT_TAU_ULT_PA     68e6   /* in-plane shear strength of carbon/
                                        epoxy (T300/5208, Tsai & Hahn) */
#define STRUCT_STIFF_ALPHA_W  0.95   /* wall D/40 where stiffness sizes the
                                        tube (local buckling far above
                                        σ_all at that wall) */
#define STRUCT_REV_MARGIN     1.15   /* a mode within ±15 % of a steady
                                        excitation resonates */

/* σ_all = σ_ult f_fat / FoS, Pa (192 MPa). */
double structure_sigma_allow_pa(void);

/* Thrust of the most loaded motor with the payload CG offset x_cg:
 * (M g / N_r)(1 + x_cg / d_y), d_y = L_arm cos(π/N_r).  Returns false when
 * x_cg >= d_y (the design is rejected). */
bool structure_cg_thrust_n(double mass_kg, int n_rotors, double arm_length_m,
                           double cg_shift_m, double *thrust_n);

/* Size-dependent minimum structural mass fraction
 * max(0.06, min(0.20, 0.05 + 0.05 W)). */
double structure_min_fraction(double wheelbase_m);

/* What set an arm tube's diameter. */
enum structure_sized_by { ARM_BY_STRENGTH, ARM_BY_TILT, ARM_BY_MODE };
extern const char *const structure_sized_by_text[3]; /* "strength", ... */

/* The loads and limits an arm is sized for. */
struct structure_arm_loads {
	double design_force_n;   /* strength: the design load at the tip */
	double full_force_n;     /* full thrust at the tip (stiffness) */
	double full_torque_nm;   /* the motors' reaction torque at full throttle */
	double tip_mass_kg;      /* motor(s) and propeller(s) at the tip */
	double length_m;
	double alpha_w;          /* inner / outer diameter */
	double mode_floor_hz;    /* the first mode at least this, 0: none */
};

struct structure_arm {
	double length_m;         /* L_arm = W / 2 */
	double root_moment_nm;   /* M_b = F_arm L_arm */
	double d_out_m;          /* outer diameter */
	double d_in_m;           /* inner diameter */
	double wall_m;           /* wall thickness */
	double area_m2;          /* wall cross-section */
	double i_x_m4;           /* second moment of area */
	double stress_pa;        /* root bending stress at the design load */
	double mass_kg;          /* one arm tube */
	double f_nat_hz;         /* first bending frequency with the tip mass */
	bool wall_floor_binds;   /* the minimum wall set the wall */
	enum structure_sized_by sized_by;
	double safety_factor;    /* fatigue strength / stress at the design load */
	double tilt_full_deg;    /* tip slope at full thrust */
	double deflection_full_m;/* tip deflection at full thrust */
	double torsion_pa;       /* shear stress from the full-throttle torque */
};

/* Arm tube sized for strength (eq. dout, with the wall floor), for the
 * tilt limit at full thrust and for the mode floor: the smallest diameter
 * that meets all three. */
void structure_size_arm(const struct structure_arm_loads *in,
                        struct structure_arm *out);

/* τ_all = τ_ult f_fat / FoS, Pa (18.1 MPa). */
double structure_tau_allow_pa(void);

/* The gyro low-pass filter a flight controller is set up with for this
 * propeller (ArduPilot Mission Planner's initial-parameters fit,
 * 289.22 D_in^-0.838 Hz). */
double structure_gyro_filter_hz(double prop_diameter_m);

/* The rate loop's bandwidth for this propeller: the filter Mission
 * Planner's initial parameters put on the rate controller's target and
 * derivative, half the gyro filter.  An arm mode above it is not one the
 * attitude loop drives. */
double structure_rate_bandwidth_hz(double prop_diameter_m);

/* A mode's clearance from an excitation band [lo, hi] widened by margin:
 * the near edge it must stay beyond, and whether it does.  *above says
 * which side the mode is on (above: it must be >= the edge). */
bool structure_band_clear(double f_nat_hz, double lo_hz, double hi_hz,
                          double margin, double *edge_hz, bool *above);

/* Resonance check: the arm mode must clear the blade-pass band
 * [f_bpf_low_hz, f_bpf_peak_hz] by the 1.5 margin on either side.  Returns
 * the margin (>= 0 passes): f_nat/(1.5 f_peak) - 1 when stiff, else
 * (f_low/1.5)/f_nat - 1; -1 when the arm or the band is unknown (0). */
double structure_resonance_margin(double f_nat_hz, double f_bpf_low_hz,
                                  double f_bpf_peak_hz);

/* Natural frequency of a cantilever tube, eq. (fnat), Hz. */
double structure_natural_freq_hz(double i_x_m4, double length_m,
                                 double tip_mass_kg, double mu_kg_m);

#endif
