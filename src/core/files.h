/* files.h - the few file-system operations several commands share, and where
 * fairway's data are. */
#ifndef FW_FILES_H
#define FW_FILES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "core/error.h"

/* Removes path and everything under it (no symlinks followed); quiet when it
 * does not exist. */
void fw_remove_tree(const char *path);

/* Creates dir and its missing parents; an existing directory is fine.
 * what names the option or field in the error ("--out"). */
fw_status fw_mkdirs(const char *dir, const char *what, fw_error *err);

/* Creates the directory path (its parent must exist) or accepts an existing
 * one, but only a real directory: a symlink there, even to a directory, is
 * refused (FW_EINPUT "WHAT PATH: a symlink, not a directory fairway made;
 * not writing through it"), so nothing is written into or deleted from
 * whatever a link planted in an output points to. */
fw_status fw_mkdir_own(const char *path, const char *what, fw_error *err);

/* dir, about to be replaced whole by a run: only if it is not there, or is
 * a run directory fairway made (a real directory holding its run.log or
 * own.csv, which a run opens first), or empty.  Anything else there is the
 * user's: FW_EINPUT "OPT: DIR exists and is not a run directory (a symlink):
 * not replacing it" or "OPT: DIR is not a run directory of fairway (no
 * run.log in it): not replacing it". */
fw_status fw_check_run_dir(const char *opt, const char *dir, fw_error *err);

/* The directory a file is to be written in: there, a directory, and ours to
 * write in.  FW_EINPUT "OPT PATH: no directory DIR" or "OPT PATH: CANNOT DIR:
 * reason" (cannot: "cannot write in", "cannot create it in"). */
fw_status fw_check_parent_dir(const char *opt, const char *path, const char *cannot,
                              fw_error *err);

/* Copies path into dst (size n): FW_EINPUT "PATH: path longer than N
 * characters" when it does not fit, never a truncated path. */
fw_status fw_path_copy(char *dst, size_t n, const char *path, fw_error *err);

/* Every file fairway writes goes through these three (and fw_file_write),
 * so that a symlink or file planted beside an output can never be written
 * through: the temporary name is unpredictable and created exclusively
 * (mkstemp: O_CREAT|O_EXCL, never following a symlink), and the rename that
 * finishes it replaces whatever is at path, a planted symlink included,
 * without touching what that symlink points to.
 *
 * A stream is not replaced: "-" (standard output) and a path that is a
 * character device, FIFO or socket, or under /dev/ or /proc/ (/dev/stdout,
 * /dev/null), is written as it is, never created, truncated or renamed over
 * (as root, renaming over /dev/stdout would replace the link with a file). */
bool fw_file_is_stream(const char *path);

/* Starts the file path: a temporary file (tmp, size n, its name) beside path,
 * DIR/.NAME.fairway-tmp.PID.XXXXXX with the mode path has (a new file: 0666
 * less the umask); for a stream, .fairway-out.fairway-tmp.PID.XXXXXX in
 * $TMPDIR (else /tmp).  Such files there whose writer is gone (a SIGKILL
 * left them) are removed first, said on stderr (core/leftover.h).  Either way tmp names the whole
 * content written so far, for a check that reads it back before the commit.
 * NULL and FW_EINPUT "PATH: cannot write: reason" when it cannot be made
 * (tmp then "", so that fw_file_abort(NULL, tmp) is always safe). */
FILE *fw_file_begin(const char *path, char *tmp, size_t n, fw_error *err);

/* Finishes it: flushes, syncs and closes f, then renames tmp to path (and
 * syncs the directory), so a reader never finds a partial file where a
 * complete one is expected; for a stream, copies the content to it then and
 * only then.  On any failure tmp is removed and path left as it was. */
fw_status fw_file_commit(FILE *f, const char *tmp, const char *path, fw_error *err);

/* Gives up a file begun: closes f (may be NULL), removes tmp. */
void fw_file_abort(FILE *f, const char *tmp);

/* A file written in place as a run goes (run.log, own.csv: read while the
 * run is under way, and by a snapshot, run/branch.h), in a directory fairway
 * has just made: created exclusively (O_CREAT|O_EXCL|O_NOFOLLOW), so a file
 * or link already there is an error, never written through.  NULL and FW_ERUN
 * "cannot create PATH: reason". */
FILE *fw_file_create(const char *path, fw_error *err);

/* The whole of path in a malloc'd buffer (*data, NUL-terminated, the caller
 * frees) of *n bytes; FW_ERUN "cannot read PATH: reason". */
fw_status fw_file_read(const char *path, char **data, size_t *n, fw_error *err);
/* n bytes of data as path, written under a temporary name beside it and
 * renamed (fw_file_commit): path is whole or as it was. */
fw_status fw_file_write(const char *path, const void *data, size_t n, fw_error *err);

/* Formats a path into buf (size bytes); FW_ERUN naming the start of the path
 * if it does not fit: a path is never silently cut. */
fw_status fw_path(char *buf, size_t size, fw_error *err, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* The data root (scenarios/, networks/ sources, analysis/):
 *   $FAIRWAY_DATA if set and not empty;
 *   else, for an installed fairway (PREFIX/bin/fairway), PREFIX/share/fairway,
 *     found from the executable's own path at run time, so an install can be
 *     moved and never needs the tree it was built from;
 *   else, for a program of the build tree (under FAIRWAY_BUILD_DIR), the
 *     source tree it was built from (FAIRWAY_DATA_DIR);
 *   else PREFIX/share/fairway all the same: a copied executable says which
 *     files it misses instead of quietly reading a source tree. */
const char *fw_data_root(void);
/* The whole of a (small) file as text: *text malloc'd, NUL-terminated, its
 * length in *len (may be NULL).  FW_EINPUT "PATH: cannot read: reason". */
fw_status fw_read_text(const char *path, char **text, size_t *len, fw_error *err);

/* Where the loadable modules are (the SUMO back ends, traffic/backend.h):
 * PREFIX/lib/fairway of an install, the build tree's lib/fairway for a
 * build-tree program.  Not moved by $FAIRWAY_DATA, like the networks. */
const char *fw_module_dir(void);
/* Splits a CSV line (no quoting) in place at its commas, its line end cut:
 * up to max fields into f; returns how many. */
int fw_csv_split(char *line, char **f, int max);

#endif
