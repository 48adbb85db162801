/* file.h — reading a whole input file, safely.
 *
 * Every reader of aeroeval (missions, the catalogue, reference data,
 * templates, cohorts, fonts and logos) takes its bytes through
 * file_read(): a regular file only (a FIFO, device or directory is refused
 * at once, never waited on), and never more than a cap.
 * Who may include it: every layer but physics.
 */
#ifndef AEROEVAL_FILE_H
#define AEROEVAL_FILE_H

#include <dirent.h>
#include <stddef.h>

/* Reads the whole regular file at path.  On success *out is a heap buffer
 * of *n bytes plus one extra NUL byte (so text parsers may treat it as a C
 * string); the caller frees it with free().  A file larger than max_n bytes
 * is refused (a mission or catalogue of gigabytes is a mistake, not input).
 * On failure *out is NULL and *n is 0. */
int file_read(const char *path, size_t max_n, unsigned char **out,
                    size_t *n, char *err, size_t errlen);

/* The same for the entry name of the open directory dir_fd, never
 * following a symbolic link there (an output folder's files: nothing under
 * an output folder is followed, fsfolder.h); path names it in messages. */
int file_read_at(int dir_fd, const char *name, const char *path, size_t max_n,
                 unsigned char **out, size_t *n, char *err, size_t errlen);

/* A directory stream over the folder open at dir_fd, from its first entry,
 * on a duplicate of the descriptor: closedir() closes the duplicate, never
 * dir_fd, which stays usable for the *at() calls on the entries.  NULL with
 * errno set when it cannot be made. */
DIR *file_dir_stream(int dir_fd);

/* Finds the directory `name` (data, templates) that ships with the program:
 * next to the build tree (<program dir>/../name), installed
 * (<program dir>/../share/aeroeval/name), beside the program
 * (<program dir>/name), then ./name; the first that holds the file `probe`
 * wins.  Writes its real path into out (n bytes) and returns 0; returns -1
 * when none holds probe, with out holding "name". */
int file_shipped_dir(const char *name, const char *probe, char *out, size_t n);

#endif
