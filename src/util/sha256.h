/* sha256.h — SHA-256 (FIPS 180-4), computed by libcrypto (OpenSSL).
 *
 * Used to fingerprint inputs (mission, catalogue, template) in result.json
 * and the dossier, so a reader can tell which inputs produced an output,
 * and the inputs and outputs of a build in its stamp.  Any module but the
 * physics may include this.  No allocation; a struct sha256_ctx is a plain
 * value on the caller's stack.  sha256_update_fd() streams a file
 * descriptor through it, so no input is ever too large to fingerprint.
 *
 * libcrypto rather than a SHA-256 of our own: it takes 37 % fewer
 * instructions on the catalogue's 1.5 MiB (docs/libraries.md), and uses
 * the processor's SHA instructions where there are some.
 */
#ifndef AEROEVAL_SHA256_H
#define AEROEVAL_SHA256_H

#include <stddef.h>
#include <stdint.h>

#include <openssl/sha.h>

#define SHA256_DIGEST_LEN 32  /* bytes in a digest */
#define SHA256_HEX_LEN 65     /* bytes of hex text including the NUL */

struct sha256_ctx {
	SHA256_CTX s;         /* libcrypto's state: a plain struct */
};

/* Starts a new hash with the initial value of FIPS 180-4 §5.3.3. */
void sha256_init(struct sha256_ctx *c);

/* Adds n bytes of message; may be called any number of times with any
 * split.  data may be NULL when n == 0. */
void sha256_update(struct sha256_ctx *c, const void *data, size_t n);

/* Pads, finishes and writes the 32-byte digest.  c must be re-initialised
 * before it is used again. */
void sha256_final(struct sha256_ctx *c, unsigned char out[SHA256_DIGEST_LEN]);

/* Adds everything fd yields from its current offset to end-of-file, read
 * in small pieces so a file of any size is hashed whole without being held
 * in memory.  *n_read (may be NULL) receives the byte count.  Returns 0, or
 * -1 with errno set when a read fails (the context then holds part of the
 * file and must not be used).  The one function here that does I/O. */
int sha256_update_fd(struct sha256_ctx *c, int fd, uint64_t *n_read);

/* Writes the lowercase hex form of a digest (64 digits and a NUL). */
void sha256_to_hex(const unsigned char d[SHA256_DIGEST_LEN], char out[SHA256_HEX_LEN]);

/* One shot: the lowercase hex digest of data[0..n) into out (64 hex digits
 * and a NUL). */
void sha256_hex(const void *data, size_t n, char out[SHA256_HEX_LEN]);

#endif
