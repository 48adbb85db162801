/* cli.c — shared command set-up (see cli.h). */
#include "cli/cli.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/catalog.h"
#include "output/fsout.h"
#include "input/model_io.h"
#include "util/sha256.h"
#include "util/xalloc.h"

static int
is_dir_with(const char *dir, const char *file)
{
	char path[4200];
	struct stat st;
	snprintf(path, sizeof path, "%s/%s", dir, file);
	return stat(path, &st) == 0;
}

void
cli_data_dir(char *out, size_t n)
{
	const char *env = getenv("AEROEVAL_DATA");
	if (env != NULL && *env != '\0') {
		snprintf(out, n, "%s", env);
		return;
	}
	char exe[PATH_MAX];
	ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
	if (len > 0) {
		exe[len] = '\0';
		char *slash = strrchr(exe, '/');
		if (slash != NULL) {
			*slash = '\0';
			/* build/aeroeval -> ../data; bin/aeroeval -> ../share/aeroeval/data */
			static const char *const rel[] = { "/../data",
				"/../share/aeroeval/data", "/data", NULL };
			for (int i = 0; rel[i] != NULL; i++) {
				char cand[PATH_MAX + 32];
				snprintf(cand, sizeof cand, "%s%s", exe, rel[i]);
				if (is_dir_with(cand, "chemistries.json")) {
					char real[PATH_MAX];
					snprintf(out, n, "%s", realpath(cand, real) ? real : cand);
					return;
				}
			}
		}
	}
	snprintf(out, n, "data");
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

/* SHA-256 over the catalogue files (name, NUL, length, bytes each), so a
 * dossier names exactly the catalogue it was built from.  Every byte is
 * hashed whatever the size; a file that cannot be opened counts as empty
 * (the catalogue loader has already said why).  -1, after a diagnostic on
 * err, when a file changes or fails while it is read. */
static int
catalogue_hash(const char *db_dir, char out[65], FILE *err)
{
	static const char *const files[] = { "motors.json", "propellers.json",
		"batteries.json", "escs.json", NULL };
	static const unsigned char empty8[8] = { 0 };
	struct sha256_ctx c;
	unsigned char digest[SHA256_DIGEST_LEN];
	sha256_init(&c);
	for (int i = 0; files[i] != NULL; i++) {
		char path[4400];
		snprintf(path, sizeof path, "%s/%s", db_dir, files[i]);
		sha256_update(&c, files[i], strlen(files[i]) + 1);
		char why[256];
		int rc = cli_hash_file(&c, path, why, sizeof why);
		if (rc == -1)
			sha256_update(&c, empty8, sizeof empty8);
		if (rc == -2) {
			fprintf(err, "%s: error: %s\n", path, why);
			return -1;
		}
	}
	sha256_final(&c, digest);
	sha256_to_hex(digest, out);
	return 0;
}

int
cli_env_load(struct cli_env *env, const char *db_dir, int want_catalog,
             FILE *err)
{
	memset(env, 0, sizeof *env);
	cli_data_dir(env->data_dir, sizeof env->data_dir);
	if (db_dir != NULL)
		snprintf(env->db_dir, sizeof env->db_dir, "%s", db_dir);
	else
		snprintf(env->db_dir, sizeof env->db_dir, "%s/catalog", env->data_dir);
	if (model_io_load(env->data_dir, &env->model, err) != 0)
		return 2;
	if (want_catalog) {
		int n_err = 0;
		env->cat = catalog_load(env->db_dir, env->model.chem_names, err, &n_err);
		if (env->cat == NULL)
			return 2;
		if (catalogue_hash(env->db_dir, env->catalogue_sha256, err) != 0)
			return 2;
	}
	return 0;
}

void
cli_env_free(struct cli_env *env)
{
	catalog_free(env->cat);
	env->cat = NULL;
}
