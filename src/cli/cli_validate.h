/* cli_validate.h — `aeroeval validate`: the model against a cohort of real
 * aircraft.
 *
 *   aeroeval validate [--report FILE.pdf] [--json] [--missions DIR] COHORT.csv
 *
 * validate prints a per-row table and the statistics (or, with --json, the
 * same numbers as JSON) on stdout; --report writes the validation PDF;
 * --missions writes each row's mission as DIR/<row-name>.json so that other
 * engines can compile the same missions.  (`calibrate` is cli_calibrate.h.)
 * Exit: 0 done, 2 bad usage or bad input (a malformed cohort row is reported
 * and the rest used, then 2; 2 as well when no row is usable), 3 internal
 * error.
 */
#ifndef AEROEVAL_CLI_VALIDATE_H
#define AEROEVAL_CLI_VALIDATE_H

/* argv[0] is "validate". */
int cli_validate(int argc, char **argv);

#endif
