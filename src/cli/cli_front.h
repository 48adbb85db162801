/* cli_front.h — the front-end commands: `aeroeval check` and `aeroeval schema`.
 *
 * Both take the argument vector after the program name: argv[0] is the
 * command name ("check", "schema"), argv[1..argc-1] its arguments.  They
 * return the process exit status (README.md, "Exit status").
 *
 * Who may include it: main.c.
 */
#ifndef AEROEVAL_CLI_FRONT_H
#define AEROEVAL_CLI_FRONT_H

/* aeroeval check MISSION.json...: validate every file (all of them, even
 * after one fails), diagnostics on stderr, nothing written.  0 when every
 * file is valid, 2 when any is not or on bad usage. */
int cli_check(int argc, char **argv);

/* aeroeval schema [--json]: every mission field on stdout, as text or as
 * the JSON Schema (data/mission.schema.json).  0, or 2 on bad usage. */
int cli_schema(int argc, char **argv);

#endif /* AEROEVAL_CLI_FRONT_H */
