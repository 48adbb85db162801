/* catsnap.c — the build-time program that writes the shipped catalogue's
 * snapshot (input/catalog_snap.h), which `make` links into aeroeval.
 *
 *     catsnap DATA_DIR OUT
 *
 * Loads DATA_DIR/catalog exactly as aeroeval would (every check, the
 * chemistries of DATA_DIR) and writes the snapshot to OUT through a
 * temporary file and a rename.  Any catalogue error is printed as aeroeval
 * prints it and the exit status is 2: a catalogue that does not load does
 * not build. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag/diag.h"
#include "input/catalog_snap.h"
#include "input/model_io.h"

int
main(int argc, char **argv)
{
	if (argc != 3) {
		fprintf(stderr, "usage: catsnap DATA_DIR OUT\n");
		return 2;
	}
	const char *data_dir = argv[1], *out_path = argv[2];
	char db_dir[4200], tmp[4200], err[512];
	snprintf(db_dir, sizeof db_dir, "%s/catalog", data_dir);
	snprintf(tmp, sizeof tmp, "%s.tmp", out_path);

	struct model_data model;
	struct diag *dg = diag_alloc(stderr);
	int rc = model_io_load(data_dir, &model, dg) == 0 ? 0 : -1;
	diag_flush(dg);
	FILE *f = NULL;
	err[0] = '\0';
	if (rc == 0 && (f = fopen(tmp, "wb")) == NULL) {
		snprintf(err, sizeof err, "cannot open the temporary file: %s", strerror(errno));
		rc = -1;
	}
	if (rc == 0)
		rc = catalog_snap_write(db_dir, model.chem_names, dg, f, err, sizeof err);
	diag_flush(dg);
	diag_free(dg);
	if (f != NULL && fclose(f) != 0 && rc == 0) {
		snprintf(err, sizeof err, "writing the temporary file: %s", strerror(errno));
		rc = -1;
	}
	if (rc == 0 && rename(tmp, out_path) != 0) {
		snprintf(err, sizeof err, "cannot rename the temporary file: %s", strerror(errno));
		rc = -1;
	}
	if (rc != 0) {
		if (err[0] != '\0')
			fprintf(stderr, "catsnap: %s: %s\n", out_path, err);
		remove(tmp);
		return 2;
	}
	return 0;
}
