/* sha256.c — SHA-256 through libcrypto's SHA256_Init/Update/Final (see
 * sha256.h).
 *
 * OpenSSL 3 marks these calls deprecated in favour of EVP_Digest*, whose
 * context is allocated (every caller would then have to release a context
 * it abandons) and whose first use loads a provider: 6 M instructions more
 * per process.  The calls remain part of OpenSSL 3's API; asking for the
 * 1.1.1 API level here keeps them without the deprecation warning.
 */
#define OPENSSL_API_COMPAT 0x10101000L

#include "util/sha256.h"

#include <errno.h>
#include <string.h>
#include <unistd.h>

void
sha256_init(struct sha256_ctx *c)
{
	SHA256_Init(&c->s);
}

void
sha256_update(struct sha256_ctx *c, const void *data, size_t n)
{
	if (n > 0)
		SHA256_Update(&c->s, data, n);
}

void
sha256_final(struct sha256_ctx *c, unsigned char out[SHA256_DIGEST_LEN])
{
	SHA256_Final(out, &c->s);
}

int
sha256_update_fd(struct sha256_ctx *c, int fd, uint64_t *n_read)
{
	/* 64 KiB: large enough that read(2) calls cost nothing next to the
	 * compression, small enough for any stack. */
	unsigned char buf[1 << 16];
	uint64_t total = 0;
	for (;;) {
		ssize_t k = read(fd, buf, sizeof buf);
		if (k < 0 && errno == EINTR)
			continue;
		if (k < 0)
			return -1;
		if (k == 0)
			break;
		sha256_update(c, buf, (size_t)k);
		total += (uint64_t)k;
	}
	if (n_read != NULL)
		*n_read = total;
	return 0;
}

void
sha256_to_hex(const unsigned char d[SHA256_DIGEST_LEN], char out[SHA256_HEX_LEN])
{
	static const char hex[] = "0123456789abcdef";
	for (int i = 0; i < SHA256_DIGEST_LEN; i++) {
		out[2 * i] = hex[d[i] >> 4];
		out[2 * i + 1] = hex[d[i] & 15];
	}
	out[64] = '\0';
}

void
sha256_hex(const void *data, size_t n, char out[SHA256_HEX_LEN])
{
	struct sha256_ctx c;
	unsigned char d[SHA256_DIGEST_LEN];
	sha256_init(&c);
	sha256_update(&c, data, n);
	sha256_final(&c, d);
	sha256_to_hex(d, out);
}
