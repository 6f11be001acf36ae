/* leftover.h - directories and files a fairway process makes for itself,
 * recognised and removed when that process was killed before it could remove
 * them.
 *
 * A SIGKILL leaves what a process was writing: a run's `.NAME.tmp.PID` in
 * its output, a sweep's fairway-sweep-XXXXXX work directory and a network
 * build's fairway-net-NAME.XXXXXX in $TMPDIR, a network cache entry's
 * .tmp.XXXXXX beside the others, an output file's temporary beside it.  A
 * directory made with fw_leftover_mark holds a file naming its owner (the
 * process id and its start time, so a reused id is not taken for the owner);
 * fw_leftover_clean removes, in a parent directory, the marked directories
 * with a given prefix whose owner is gone, and says so on stderr.  Only
 * marked directories of this user are touched: fairway deletes nothing it
 * cannot show it made.
 */
#ifndef FW_LEFTOVER_H
#define FW_LEFTOVER_H

#include "core/error.h"

/* Marks dir (existing, made by this process) as this process's. */
fw_status fw_leftover_mark(const char *dir, fw_error *err);

/* Takes the mark off dir again (a directory about to become an output that
 * holds only its own files: a report's). */
void fw_leftover_unmark(const char *dir);

/* Removes the directories parent/PREFIX* marked by a process that is gone;
 * `what` names them in the message ("an interrupted run").  The number
 * removed. */
int fw_leftover_clean(const char *parent, const char *prefix, const char *what);

/* The temporary files fairway writes outputs through (files.h,
 * fw_file_begin), DIR/.NAME.fairway-tmp.PID.XXXXXX, that a killed process
 * left in dir: each removed (and said on stderr) when it is a regular file of
 * this user, its writer PID is gone (no such process, or one that started
 * after the file was last written: the id was reused) and no process holds it
 * open (a fork of the writer that goes on with it).  Anything else, a symlink
 * or a name of any other form included, is left alone.  The number removed.
 * (Process ids are this PID namespace's: a fairway in another container
 * writing into the same directory is not seen.) */
int fw_leftover_clean_files(const char *dir);

#endif
