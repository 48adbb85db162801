/* cli_calibrate.h — `aeroeval calibrate`: the model's coefficients fitted
 * on a cohort of real aircraft.
 *
 *   aeroeval calibrate [--write FILE] COHORT.csv
 *
 * Prints the fit (each coefficient's prior, before and after, the in-sample
 * and leave-one-out errors, the prediction intervals) and, with --write,
 * writes the calibration JSON to FILE.  Progress goes to stderr.
 * Exit: 0 done, 2 bad usage or bad input (a malformed cohort row is reported
 * and the rest used, then 2), 3 internal error.
 */
#ifndef AEROEVAL_CLI_CALIBRATE_H
#define AEROEVAL_CLI_CALIBRATE_H

/* argv[0] is "calibrate". */
int cli_calibrate(int argc, char **argv);

#endif
