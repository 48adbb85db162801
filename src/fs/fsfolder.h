/* fsfolder.h — one mission's output folder DIR/NAME/, replaced as a whole.
 *
 * The files of DIR/NAME change together or not at all.  A new set is
 * written into a temporary folder DIR/.NAME.tmp.PID.SEQ/, each file is
 * synced, and the folder is swapped with DIR/NAME in one step
 * (renameat2 RENAME_EXCHANGE); then the old set is removed.  So after any
 * fault (kill -9 at any instant, a full disk, an I/O error) DIR/NAME holds
 * the whole old set or the whole new one.  Where the file system cannot
 * exchange (NFS, some others), two renames do it: the old set aside to
 * DIR/.NAME.old.PID.SEQ/, the new set in.  SIGINT, SIGTERM, SIGHUP and
 * SIGQUIT wait until both are done; a kill -9 between them leaves DIR/NAME
 * missing, never mixed, and the next writer of NAME (fsfolder_open())
 * renames the set-aside old set back before anything else, so no clean-up
 * ever deletes the only copy of a set.
 *
 * Nothing under DIR is followed: every file is opened relative to DIR's
 * descriptor with O_NOFOLLOW, and created with O_CREAT|O_EXCL.  A symbolic
 * link, FIFO or any other non-regular file at DIR/NAME or inside it, and a
 * file there that is not one of the caller's, is an error naming it (the
 * folder is replaced as a whole, so nothing foreign may live in it).  The
 * caller's files are a NULL-ended list of names; an entry "*SUFFIX" stands
 * for every plain name ending in SUFFIX (a folder of missions: "*.json").  DIR
 * itself may be a link: it is the user's choice of place.
 *
 * Writers of one NAME exclude each other with flock(2) on DIR/.NAME.lock,
 * a file that exists only while someone holds it.
 *
 * File-system layer; the CLI's build pipeline uses it.  Every message (err) is
 * a whole diagnostic line without the newline, "PATH: error: why", PATH
 * being what the user knows (DIR/NAME or DIR/NAME/FILE), named once.
 */
#ifndef AEROEVAL_FSFOLDER_H
#define AEROEVAL_FSFOLDER_H

#include <stddef.h>

#include "fs/fsout.h"
#include "util/sha256.h"

/* fsfolder_open() flags. */
#define FSFOLDER_NOWAIT 1  /* do not wait for the lock; may read unlocked */

/* fsfolder_open() result when FSFOLDER_NOWAIT finds the lock taken. */
#define FSFOLDER_BUSY 1

/* Temporaries this old, whatever their owner, are stale (seconds): no
 * build writes one mission for an hour. */
#define FSFOLDER_STALE_S 3600.0

/* An open output folder.  Plain value; fsfolder_close() releases it. */
struct fsfolder {
	int dir_fd;                    /* DIR, -1 when closed */
	int lock_fd;                   /* DIR/.NAME.lock, flock'ed; -1 when not held */
	int cur_fd;                    /* DIR/NAME as found at open, -1 if absent */
	int tmp_fd;                    /* the temporary folder being written, -1 if none */
	char name[FSOUT_NAME_MAX + 1]; /* NAME */
	char tmp[FSOUT_NAME_MAX + 48]; /* the temporary folder's name in DIR, "" if none */
	char dir[4096];                /* DIR as given, for messages */
	const char *const *files;      /* the names DIR/NAME may hold, NULL-ended */
};

/* Opens DIR (which must exist), takes the lock of NAME, puts back an old
 * set a killed two-rename swap left aside (see above), and inspects
 * DIR/NAME: absent is fine; a real folder holding only regular files named
 * in files (or temporaries ".FILE.tmp.PID.SEQ" of an older aeroeval) is
 * fine; anything else is an error.  Without FSFOLDER_NOWAIT the lock is
 * waited for up to wait_s seconds, then it is an error.  With it, a lock
 * held elsewhere returns FSFOLDER_BUSY at once, and a DIR where no lock
 * file can be made (read-only) is opened unlocked, for reading only.
 * Returns 0, FSFOLDER_BUSY, or -1 with err set; in every case f is ready
 * for fsfolder_close(). */
int fsfolder_open(struct fsfolder *f, const char *dir, const char *name,
                  const char *const *files, int flags, double wait_s,
                  char *err, size_t errlen);

/* True when DIR/NAME existed at open. */
int fsfolder_exists(const struct fsfolder *f);

/* The SHA-256 (hex) of DIR/NAME/file, streamed.  -1 when the folder or
 * the file is absent, not regular, or unreadable. */
int fsfolder_hash(const struct fsfolder *f, const char *file,
                  char hex[SHA256_HEX_LEN]);

/* Reads DIR/NAME/file into buf (NUL-terminated, *n bytes) when it is a
 * regular file shorter than cap bytes; else -1. */
int fsfolder_read(const struct fsfolder *f, const char *file, char *buf,
                  size_t cap, size_t *n);

/* Removes the temporaries of NAME in DIR that a killed writer left behind:
 * folders ".NAME.tmp.PID.SEQ" (and, while DIR/NAME exists, set-aside old
 * sets ".NAME.old.PID.SEQ") whose process is gone or which are older
 * than max_age_s.  Only with the lock held (else does nothing); only
 * folders, and only the regular files, links and FIFOs in them, are
 * removed.  Returns how many were removed. */
int fsfolder_clean(struct fsfolder *f, double max_age_s);

/* Starts a new set: creates the temporary folder (lock required). */
int fsfolder_begin(struct fsfolder *f, char *err, size_t errlen);

/* Writes data[0..n) as file of the new set (mode 0644); with sync, makes
 * it durable (fsync) before returning. */
int fsfolder_put(struct fsfolder *f, const char *file, const void *data,
                 size_t n, int sync, char *err, size_t errlen);

/* Copies DIR/NAME/file of the current set into the new set unchanged and
 * synced, for a writer that replaces some files of a folder and keeps the
 * others; a file the current set lacks is no error (nothing is copied). */
int fsfolder_carry(struct fsfolder *f, const char *file, char *err, size_t errlen);

/* Swaps the new set in for DIR/NAME, removes the old set and syncs DIR.
 * On failure DIR/NAME is as it was. */
int fsfolder_commit(struct fsfolder *f, char *err, size_t errlen);

/* Removes an uncommitted new set, releases the lock (removing its file)
 * and closes everything.  Safe on a partly opened or closed f. */
void fsfolder_close(struct fsfolder *f);

#endif
