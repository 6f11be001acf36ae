/* leftover.h - directories a fairway process makes for itself, recognised
 * and removed when that process was killed before it could remove them.
 *
 * A SIGKILL leaves what a process was writing: a run's `.NAME.tmp.PID` in
 * its output, a sweep's fairway-sweep-XXXXXX work directory in $TMPDIR.  A
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

#endif
