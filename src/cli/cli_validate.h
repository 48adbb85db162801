/* cli_validate.h — `aeroeval validate` and `aeroeval calibrate`.
 *
 *   aeroeval validate [--report FILE.pdf] [--json] [--missions DIR] COHORT.csv
 *   aeroeval calibrate [--write FILE] COHORT.csv
 *
 * validate prints a per-row table and the statistics (or, with --json, the
 * same numbers as JSON) on stdout; --report writes the validation PDF;
 * --missions writes each row's mission as DIR/<row-name>.json so that other
 * engines can compile the same missions.  calibrate prints the fit and,
 * with --write, writes the calibration JSON to FILE.
 * Exit: 0 done, 2 bad usage or bad input (a malformed cohort row is reported
 * and the rest used: still 0 unless no row is usable), 3 internal error.
 */
#ifndef AEROEVAL_CLI_VALIDATE_H
#define AEROEVAL_CLI_VALIDATE_H

/* argv[0] is "validate". */
int cli_validate(int argc, char **argv);

/* argv[0] is "calibrate". */
int cli_calibrate(int argc, char **argv);

#endif
