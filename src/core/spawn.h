/* spawn.h - the one way fairway starts another program (sumo-gui, netconvert, Python).
 *
 * fork and exec with the child's standard output and error sent to a log
 * file (or /dev/null), optionally in another working directory.  A pipe that
 * exec closes tells the parent whether the program started at all, so "no
 * such program" is an error of fw_spawn itself, not an exit status later.
 * The child dies with fairway (PR_SET_PDEATHSIG): no program it started
 * outlives a SIGKILL of fairway.
 */
#ifndef FW_SPAWN_H
#define FW_SPAWN_H

#include <stdbool.h>
#include <sys/types.h>

#include "core/error.h"

typedef struct fw_spawn_def {
    const char *const *argv; /* program (looked up on PATH) and arguments, NULL-terminated */
    const char *log;         /* stdout and stderr go here; NULL: /dev/null */
    bool append;             /* append to the log instead of truncating it */
    const char *dir;         /* working directory of the child; NULL: ours */
} fw_spawn_def;

/* Starts the program; *pid is the child's. */
fw_status fw_spawn(const fw_spawn_def *def, pid_t *pid, fw_error *err);
/* Waits for the child (through EINTR): its exit status, or 128 + the signal
 * that ended it. */
int fw_spawn_wait(pid_t pid);
/* Starts the program and waits for it: *exit_status as fw_spawn_wait. */
fw_status fw_spawn_run(const fw_spawn_def *def, int *exit_status, fw_error *err);
/* SIGTERM, wait up to 3 s, then SIGKILL; always reaps.  Safe on pid <= 0. */
void fw_spawn_stop(pid_t pid);

/* fork with a pipe from the child to the parent, stdio flushed first, the
 * child set to die with the parent (PR_SET_PDEATHSIG): in the parent *pid
 * is the child's and *fd the pipe's read end; in the child *pid is 0 and *fd
 * the write end.  A worker's way to hand back a result (study/split_run.c,
 * sweep_split.c). */
fw_status fw_fork_piped(pid_t *pid, int *fd, fw_error *err);

/* All n bytes of buf read from, or written to, fd (a pipe to another process,
 * a file), through interrupted calls and short transfers: 0, or -1 at an end
 * of file or on an error (errno says which). */
int fw_fd_read(int fd, void *buf, size_t n);
int fw_fd_write(int fd, const void *buf, size_t n);

#endif
