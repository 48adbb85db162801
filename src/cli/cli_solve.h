/* cli_solve.h — `aeroeval solve`: result JSON of one mission on stdout. */
#ifndef AEROEVAL_CLI_SOLVE_H
#define AEROEVAL_CLI_SOLVE_H

/* argv[0] is "solve".  Exit 0 feasible, 1 infeasible, 2 bad input, 3 internal. */
int cli_solve(int argc, char **argv);

#endif
