/* cli_sens.h — `aeroeval sensitivity`: the paper's 14-parameter study.
 *
 *   aeroeval sensitivity [-o DIR] [--template FILE] [--tsv] MISSION.json
 *       the table on stdout (tab-separated with --tsv), DIR/sensitivity.json
 *       and DIR/sensitivity.pdf (DIR defaults to out/<mission-name>, next to
 *       the dossier); the solve count and time go to stderr
 *   aeroeval sensitivity --compare-shedding [STATIC.json] DYNAMIC.json
 *       the paper's §VII-D shedding savings of DYNAMIC over STATIC (or over
 *       DYNAMIC with payload_role.mass_shedding off), as key=value lines
 *   aeroeval sensitivity --case-row RESULT.json
 *       one case-study row (MTOW, prop, KV, battery, convergence) from a
 *       result.json written by `aeroeval solve`, as key=value pairs
 *
 * The two helper modes exist for tests/paper.sh (make paper), so that the
 * script needs no JSON tool.  Exit status: 0 done and the nominal design
 * feasible, 1 nominal infeasible (outputs still written), 2 bad usage or
 * input, 3 internal error.
 *
 * Who may include it: main.c.
 */
#ifndef AEROEVAL_CLI_SENS_H
#define AEROEVAL_CLI_SENS_H

/* argv[0] is "sensitivity". */
int cli_sensitivity(int argc, char **argv);

#endif
