/* cli_solve.c — `aeroeval solve [--db DIR] [--summary] MISSION.json`. */
#include "cli/cli_solve.h"

#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/pipeline.h"
#include "formats/result_json.h"
#include "util/xalloc.h"

static void
print_run(FILE *out, const char *name, const struct res_run *o)
{
	if (!o->ran) {
		fprintf(out, "%s: not run (%s)\n", name, o->termination);
		return;
	}
	fprintf(out, "%s: MTOW %.3f kg  %s  iter %d  L %.3f  gamma %.2f\n", name,
	    o->mass.total_kg, o->converged ? "converged" : "NOT converged",
	    o->iterations, o->lipschitz, o->time_scale);
	fprintf(out, "  payload %.3f battery %.3f frame %.3f arms %.3f motors %.3f props %.3f esc %.3f wiring %.3f avionics %.3f role %.3f other %.3f\n",
	    o->mass.payload_kg, o->mass.battery_kg, o->mass.frame_kg, o->mass.arm_kg,
	    o->mass.motor_kg, o->mass.prop_kg, o->mass.esc_kg, o->mass.wiring_kg,
	    o->mass.avionics_kg, o->mass.role_aux_kg, o->mass.other_kg);
	fprintf(out, "  %dS %s %.0f mAh %.0f Wh  prop %.1fx%.1f in  KV %.0f  T/W %.2f  FoM %.3f  v %.1f m/s\n",
	    o->cell_count, o->chemistry, o->capacity_mah, o->energy_wh,
	    o->opt.prop_diameter_in, o->opt.prop_pitch_in, o->opt.motor_kv,
	    o->thrust_to_weight, o->fom_installed, o->optimal_speed_ms);
	fprintf(out, "  hover %.0f W, peak %.0f W %.0f A, Tmax %.1f C, Vmin %.2f V (floor %.2f), end SOC %.3f, endurance %.1f min, arm %.1f mm f %.0f/%.0f Hz, dw %.1f m/s\n",
	    o->phase[PHASE_HOVER].power_w, o->peak_power_w, o->peak_current_a,
	    o->max_battery_temp_c, o->min_terminal_voltage_v, o->voltage_floor_v,
	    o->end_soc, o->hover_endurance_s / 60.0, o->arm_outer_diameter_mm,
	    o->arm_natural_frequency_hz, o->blade_pass_frequency_hz, o->downwash_ms);
	fprintf(out, "  %s\n", o->termination);
	for (int i = 0; i < o->n_checks; i++)
		if (!o->checks[i].pass)
			fprintf(out, "  FAILED check: %s %.4g %s (limit %.4g)\n",
			    o->checks[i].name, o->checks[i].value, o->checks[i].unit,
			    o->checks[i].limit);
}

static void
print_summary(FILE *out, const struct solve_result *r)
{
	print_run(out, "baseline", &r->baseline);
	print_run(out, "custom", &r->custom);
	fprintf(out, "status: %s\n", r->feasible ? "feasible" : "infeasible");
	for (int i = 0; i < r->n_violations; i++)
		fprintf(out, "  violation [%s/%s] %s: %s\n", r->violations[i].run,
		    r->violations[i].stage, r->violations[i].code,
		    r->violations[i].message);
	for (int i = 0; i < r->n_rationale; i++)
		fprintf(out, "  - %s\n", r->rationale[i]);
}

int
cli_solve(int argc, char **argv)
{
	static const char usage[] =
	    "usage: aeroeval solve [--db DIR] [--summary] MISSION.json\n";
	const char *db = NULL, *path = NULL;
	int summary = 0;
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "--db") == 0 && i + 1 < argc) {
			db = argv[++i];
		} else if (strcmp(argv[i], "--summary") == 0) {
			summary = 1;
		} else if (argv[i][0] == '-' || path != NULL) {
			/* An unknown option or a second mission: one at a time. */
			fputs(usage, stderr);
			return 2;
		} else {
			path = argv[i];
		}
	}
	if (path == NULL) {
		fputs(usage, stderr);
		return 2;
	}
	struct cli_env *env = xcalloc(1, sizeof *env);
	int rc = cli_env_load(env, db, 1, stderr);
	if (rc != 0) {
		cli_env_free(env);
		free(env);
		return rc;
	}
	struct solve_result *r = xmalloc(sizeof *r);
	enum pipeline_status st = pipeline_solve(env, path, r, stderr, NULL, NULL);
	rc = (int)st;
	if (st == PIPE_FEASIBLE || st == PIPE_INFEASIBLE) {
		if (summary) {
			print_summary(stdout, r);
		} else {
			struct result_json_faults jf;
			char *json = result_json_render_checked(r, AEROEVAL_VERSION, &jf);
			if (jf.n_invalid > 0) {
				fprintf(stderr, "%s: internal error: non-finite value at %s\n",
				    path, jf.first_path);
				rc = 3;
			} else {
				fputs(json, stdout);
			}
			free(json);
		}
	}
	free(r);
	cli_env_free(env);
	free(env);
	return rc;
}
