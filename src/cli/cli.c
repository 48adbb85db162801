/* cli.c — shared command set-up (see cli.h). */
#include "cli/cli.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "catalog/catalog.h"
#include "diag/diag.h"
#include "template/template.h"
#include "pdf/assets.h"
#include "fs/fsout.h"
#include "input/catalog_io.h"
#include "input/catalog_snap.h"
#include "input/cohort.h"
#include "input/json_in.h"
#include "input/model_io.h"
#include "input/template_io.h"
#include "util/sha256.h"
#include "util/file.h"
#include "util/xalloc.h"

void
cli_data_dir(char *out, size_t n)
{
	const char *env = getenv("AEROEVAL_DATA");
	if (env != NULL && *env != '\0')
		snprintf(out, n, "%s", env);
	else
		file_shipped_dir("data", "chemistries.json", out, n);
}

int
cli_hash_file(struct sha256_ctx *c, const char *path, char *err, size_t errlen)
{
	/* O_NONBLOCK: a FIFO must be refused, not waited on. */
	int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
	struct stat st;
	if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
		snprintf(err, errlen, "%s", fd < 0 ? strerror(errno) : "not a regular file");
		if (fd >= 0)
			close(fd);
		return -1;
	}
	unsigned char len8[8];
	for (int k = 0; k < 8; k++)
		len8[k] = (unsigned char)((unsigned long long)st.st_size >> (8 * k));
	sha256_update(c, len8, sizeof len8);
	uint64_t n = 0;
	int rc = sha256_update_fd(c, fd, &n);
	int saved = errno;
	close(fd);
	if (rc != 0) {
		snprintf(err, errlen, "read failed: %s", strerror(saved));
		return -2;
	}
	if (n != (uint64_t)st.st_size) {
		snprintf(err, errlen, "changed while it was being read");
		return -2;
	}
	return 0;
}

/* The shipped catalogue's snapshot and its length in bytes (snapshot.S),
 * in a program linked with it: the program and the test programs.  Weak,
 * so that a program linked without it (bench, the fuzzers) has none: both
 * are then NULL and the JSON is always read. */
extern const unsigned char aeroeval_snapshot[] __attribute__((weak));
extern const uint64_t aeroeval_snapshot_bytes __attribute__((weak));

int
cli_env_load(struct cli_env *env, const char *db_dir, int want_catalog,
             FILE *err)
{
	memset(env, 0, sizeof *env);
	/* "" once read "/motors.json": refused as -o "" is. */
	if (db_dir != NULL && db_dir[0] == '\0') {
		fprintf(err, "aeroeval: error: --db: the catalogue folder name is empty\n");
		return 2;
	}
	cli_data_dir(env->data_dir, sizeof env->data_dir);
	if (db_dir != NULL)
		snprintf(env->db_dir, sizeof env->db_dir, "%s", db_dir);
	else
		snprintf(env->db_dir, sizeof env->db_dir, "%s/catalog", env->data_dir);
	struct diag *dg = diag_alloc(err);
	int n_err = model_io_load(env->data_dir, &env->model, dg);
	diag_flush(dg);
	/* The catalogue from the program's own snapshot when the folder's
	 * files are byte for byte the ones it was made from
	 * (input/catalog_snap.h), else from its JSON. */
	if (n_err == 0 && want_catalog)
		env->cat = catalog_snap_read(aeroeval_snapshot, &aeroeval_snapshot_bytes != NULL
		                             ? (size_t)aeroeval_snapshot_bytes : 0, env->db_dir,
		                             env->model.chem_names, env->catalogue_sha256);
	if (n_err == 0 && want_catalog && env->cat == NULL) {
		env->cat = catalog_io_load(env->db_dir, env->model.chem_names, dg,
		                           env->catalogue_sha256);
		diag_flush(dg);
		n_err = env->cat == NULL;
	}
	diag_free(dg);
	return n_err != 0 ? 2 : 0;
}

void
cli_env_free(struct cli_env *env)
{
	catalog_free(env->cat);
	env->cat = NULL;
}

int
cli_out_dir(const char *cmd, const char *opt, const char *value, char *out, size_t n,
            FILE *err)
{
	struct stat st, root;
	size_t len = strlen(value);
	while (len > 1 && value[len - 1] == '/')
		len--;
	if (len == 0) {
		fprintf(err, "aeroeval %s: error: %s: the output folder name is empty\n", cmd, opt);
		return 2;
	}
	if (len >= n) {
		fprintf(err, "aeroeval %s: error: %s: the output folder name is too long\n", cmd, opt);
		return 2;
	}
	memcpy(out, value, len);
	out[len] = '\0';
	if (stat(out, &st) != 0)
		return 0;  /* made later; mkdir says what is wrong with it */
	if (!S_ISDIR(st.st_mode)) {
		fprintf(err, "%s: error: %s names a file, not a folder\n", out, opt);
		return 2;
	}
	if (stat("/", &root) == 0 && st.st_dev == root.st_dev && st.st_ino == root.st_ino) {
		fprintf(err, "%s: error: %s names the root folder; give the outputs "
		    "a folder of their own\n", out, opt);
		return 2;
	}
	return 0;
}

int
cli_close_stdout(int status)
{
	/* fflush reports a failure of the writes still buffered, ferror one
	 * of an earlier write, fclose one the kernel reports only at close
	 * (NFS).  EBADF at close alone means stdout was never open. */
	int failed = fflush(stdout) != 0;
	int e = failed ? errno : 0;  /* else unknown: an earlier write failed */
	failed |= ferror(stdout) != 0;
	if (fclose(stdout) != 0 && (failed || errno != EBADF)) {
		e = failed ? e : errno;
		failed = 1;
	}
	if (!failed)
		return status;
	fprintf(stderr, "aeroeval: error: cannot write to standard output: %s\n",
	    e != 0 ? strerror(e) : "write error");
	return status > 2 ? status : 2;
}

struct template *
cli_template_load(const char *path, FILE *err)
{
	if (path == NULL)
		return template_default();
	struct diag *dg = diag_alloc(err);
	struct template *t = template_io_load(path, assets_check, dg);
	diag_flush(dg);
	diag_free(dg);
	return t;
}

int
cli_cohort_load(const char *path, struct cli_env *env, struct cohort *c)
{
	int rc = cli_env_load(env, NULL, 0, stderr);
	if (rc != 0)
		return rc;
	cohort_load(path, c);
	for (size_t i = 0; i < c->n_errors; i++)
		fprintf(stderr, "%s\n", c->errors[i]);
	if (c->n_rows == 0) {
		fprintf(stderr, "%s: error: no usable row\n", path);
		return 2;
	}
	return 0;
}

int
cli_cohort_rejected(const char *path, const struct cohort *c)
{
	if (c->n_errors == 0)
		return 0;
	fprintf(stderr, "%s: error: %zu problem%s in the cohort (above); the figures cover "
	    "only the %zu rows read\n", path, c->n_errors, c->n_errors == 1 ? "" : "s",
	    c->n_rows);
	return 2;
}
