/* cli_help.c — help and version text (see cli_help.h). */
#include "cli/cli_help.h"

#include <ctype.h>
#include <string.h>

/* One command: how it is called, what it does, and its options. */
struct help_cmd {
	const char *name;
	const char *synopsis;  /* after "aeroeval " */
	const char *summary;   /* one line */
	const char *details;   /* options and notes, each line ending in \n */
};

static const struct help_cmd help_cmds[] = {
	{ "build",
	  "build [-o DIR] [-j N] [-q] [--force] [--shard K/N] [--template FILE] [--db DIR] "
	  "MISSION.json|DIR...",
	  "compile missions into DIR/<name>/{dossier.pdf,result.json,bom.csv}",
	  "A directory stands for its *.json files, in name order.  Missions\n"
	  "compile in parallel worker processes; one failing mission does not\n"
	  "stop the others, and each is reported in one piece.\n"
	  "\n"
	  "  -o DIR           output folder (default: out)\n"
	  "  -j N             compile N missions at once (default: online cores)\n"
	  "  -q               print errors only\n"
	  "  --force          recompile missions that are up to date\n"
	  "  --shard K/N      compile share K of N only (N machines, one shared DIR)\n"
	  "  --template FILE  dossier template (default: the built-in A4 one)\n"
	  "  --db DIR         parts catalogue folder (default: data/catalog)\n"
	  "\n"
	  "A mission whose file, catalogue, reference data, template and compiler\n"
	  "are unchanged since its last good compile is skipped (\"up to date\").\n"
	  "^C stops the run: finished outputs stay, no partial file is left.\n"
	  "A mission's outputs are replaced as one set: old or new, never a mix.\n"
	  "A buildable design also gets vehicle_components.json (ArduPilot\n"
	  "Methodic Configurator), ardupilot.param (Mission Planner, MAVProxy,\n"
	  "the configurator) and qgroundcontrol.params.  DIR/index.csv and\n"
	  "DIR/index.json, the table of every mission in DIR, are kept current.\n"
	  "Exit status: 0 all feasible, 1 some design infeasible, 2 bad usage,\n"
	  "input or a file-system problem, 3 internal error, 130/143 interrupted.\n" },
	{ "solve",
	  "solve [--db DIR] [--summary] MISSION.json",
	  "solve one mission and print result.json on stdout (no files written)",
	  "  --db DIR    parts catalogue folder (default: data/catalog)\n"
	  "  --summary   a short human-readable summary instead of the JSON\n" },
	{ "check",
	  "check MISSION.json...",
	  "validate missions only: diagnostics, no output files",
	  "Every problem of a file is reported in one pass, as\n"
	  "FILE:LINE:COL: error: FIELD: MESSAGE.\n" },
	{ "schema",
	  "schema [--json]",
	  "list every mission field: type, unit, default, range, meaning",
	  "  --json   print a JSON Schema instead of the table\n" },
	{ "validate",
	  "validate [--pack] [--report FILE.pdf] [--json] [--missions DIR] COHORT.csv",
	  "measure the accuracy against a cohort of real aircraft",
	  "  --pack              lock each row's published pack (cells, capacity)\n"
	  "                      instead of sizing the battery from its endurance\n"
	  "  --report FILE.pdf   also write a validation dossier\n"
	  "  --json              print the report as JSON\n"
	  "  --missions DIR      write each row's mission file into DIR, a folder of\n"
	  "                      its own replaced as a whole\n"
	  "\n"
	  "Exit status 2 also when a row of the cohort was rejected.\n" },
	{ "calibrate",
	  "calibrate [--write FILE] COHORT.csv",
	  "fit the calibration coefficients to a cohort of real aircraft",
	  "Fits open loop from the priors, then measures the fit by leave-one-out\n"
	  "with batteries sized from the endurance and with published packs\n"
	  "locked, and derives the 90 % prediction interval (docs/validation.md).\n"
	  "  --write FILE   write the fit and its accuracy as data/calibration.json\n" },
	{ "sensitivity",
	  "sensitivity [-o DIR] [--template FILE] [--tsv] MISSION.json",
	  "the 14-parameter sensitivity table of one mission",
	  "Prints the table and writes sensitivity.json and sensitivity.pdf into\n"
	  "DIR/<name>/ beside the mission's build outputs, by build's rules (the\n"
	  "folder replaced as a whole, its other files kept).\n"
	  "  -o DIR           output folder (default: out)\n"
	  "  --template FILE  template of sensitivity.pdf (default: the built-in one)\n"
	  "  --tsv            print the table as tab-separated fields\n" },
	{ "summary",
	  "summary [-q] [--stdout] [--no-pdf] [--template FILE] DIR",
	  "tabulate every compiled mission of DIR: index.csv, index.json, overview.pdf",
	  "One row per DIR/<name>/result.json, by name: verdict, takeoff mass\n"
	  "(and its prediction interval when given), payload, flight times, cost,\n"
	  "pack, parts and the tightest check.  Rebuilt from the files each time,\n"
	  "so a partial or sharded build gives a correct partial table; `build`\n"
	  "keeps index.csv and index.json current by itself.\n"
	  "\n"
	  "  -q               print errors only\n"
	  "  --stdout         print index.csv on stdout and write nothing\n"
	  "  --no-pdf         write the tables only, no overview.pdf\n"
	  "  --template FILE  template of overview.pdf (default: the built-in A4 one)\n"
	  "\n"
	  "Exit status: 0 written, 2 bad usage, no compiled mission, a result.json\n"
	  "that cannot be read (the table is written without it) or a file-system\n"
	  "problem, 3 internal error.\n" },
};

#define HELP_N_CMDS (sizeof help_cmds / sizeof help_cmds[0])

void
cli_help_overview(FILE *out)
{
	fputs("usage: aeroeval COMMAND [OPTIONS] [FILES]\n"
	      "       aeroeval --help | --version | help COMMAND\n"
	      "\n"
	      "aeroeval sizes multirotor UAVs: a mission file in, a design dossier,\n"
	      "result.json and bill of materials out.\n"
	      "\n"
	      "commands:\n", out);
	for (size_t i = 0; i < HELP_N_CMDS; i++)
		fprintf(out, "  %-12s %s\n", help_cmds[i].name, help_cmds[i].summary);
	fputs("\n"
	      "Run 'aeroeval help COMMAND' (or 'aeroeval COMMAND --help') for a\n"
	      "command's options, and 'man aeroeval' for the full manual.\n", out);
}

int
cli_help_command(const char *cmd, FILE *out)
{
	for (size_t i = 0; i < HELP_N_CMDS; i++) {
		const struct help_cmd *c = &help_cmds[i];
		if (strcmp(cmd, c->name) != 0)
			continue;
		if (out == NULL)
			return 0;
		/* The summary is a sentence here: capital first letter, full stop. */
		fprintf(out, "usage: aeroeval %s\n\n%c%s.\n", c->synopsis,
		        toupper((unsigned char)c->summary[0]), c->summary + 1);
		if (c->details[0] != '\0')
			fprintf(out, "\n%s", c->details);
		return 0;
	}
	return -1;
}

void
cli_help_version(FILE *out)
{
	fprintf(out, "aeroeval %s\n"
	        "multirotor UAV sizing compiler (C11; cJSON, libharu, cairo)\n",
	        AEROEVAL_VERSION);
}
