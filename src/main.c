/* main.c — argv, subcommand dispatch, exit status.  Drives; computes nothing. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_build.h"
#include "cli_front.h"
#include "cli_solve.h"
#include "doc.h"

int
main(int argc, char **argv)
{
	atexit(doc_global_cleanup); /* fontconfig/cairo caches: valgrind-clean exit */
	if (argc >= 2 && strcmp(argv[1], "--version") == 0) {
		printf("aeroeval %s\n", AEROEVAL_VERSION);
		return 0;
	}
	if (argc >= 2 && strcmp(argv[1], "check") == 0)
		return cli_check(argc - 1, argv + 1);
	if (argc >= 2 && strcmp(argv[1], "schema") == 0)
		return cli_schema(argc - 1, argv + 1);
	if (argc >= 2 && strcmp(argv[1], "build") == 0)
		return cli_build(argc - 1, argv + 1);
	if (argc >= 2 && strcmp(argv[1], "solve") == 0)
		return cli_solve(argc - 1, argv + 1);
	fprintf(stderr, "usage: aeroeval build|solve|check|schema|validate|calibrate|sensitivity ...\n");
	return 2;
}
