/* cli_build.h — `aeroeval build [-o DIR] [-j N] [-q] [--force]
 * [--template FILE] [--db DIR] MISSION.json|DIR...`: compile missions into
 * DIR/<name>/ in parallel worker processes (batch.h), skipping those whose
 * stamp (DIR/<name>/.aeroeval-stamp) says they are up to date.  Every
 * mission is reported in one piece, the run ends with a summary line.
 * See the man page (src/aeroeval.1) for the user's view.
 */
#ifndef AEROEVAL_CLI_BUILD_H
#define AEROEVAL_CLI_BUILD_H

/* argv[0] is "build".  Exit status: the worst mission outcome (0 feasible,
 * 1 infeasible, 2 bad usage or input, 3 internal error), or
 * 128 + the signal (130 SIGINT, 143 SIGTERM) when the run was interrupted. */
int cli_build(int argc, char **argv);

#endif
