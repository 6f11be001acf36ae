/* args.h - small helpers for subcommand option parsing.
 *
 * Options are GNU style (--name VALUE or --name=VALUE).  Number parsing is
 * strict: the whole text must be a finite number, and the error names the
 * option.  Interface units (knots, degrees) are converted by the caller via
 * core/units.h, never here.
 */
#ifndef FW_ARGS_H
#define FW_ARGS_H

#include <stdbool.h>
#include <stdio.h>

#include "core/error.h"
#include "ship/ship.h"
#include "traffic/traffic.h"

typedef struct fw_args {
    int argc;
    char **argv;
    int i; /* next argument to read */
} fw_args;

/* If argv[i] is option `name` (with or without "=VALUE"), consumes it, stores
 * the value in *value (NULL for flags) and returns true. */
bool fw_args_opt(fw_args *a, const char *name, const char **value, fw_error *err);
/* The argument at hand is --help or -h: the command's help is printed (the
 * caller then exits 0). */
bool fw_args_help(const fw_args *a, void (*help)(void));
bool fw_args_flag(fw_args *a, const char *name);

fw_status fw_parse_double(const char *opt, const char *text, double *out, fw_error *err);
fw_status fw_parse_long(const char *opt, const char *text, long *out, fw_error *err);
/* Splits "a,b,c" into up to max finite numbers; *n gets the count. */
fw_status fw_parse_list(const char *opt, const char *text, double *out, int max, int *n,
                        fw_error *err);

bool fw_is_help(const char *arg);

/* Checks, before any computation, that path can be written as a new file:
 * not a directory, an existing directory to hold it that we may write in,
 * and not an existing file unless replace. */
fw_status fw_check_out_file(const char *opt, const char *path, bool replace, fw_error *err);

/* The fastest speed any command accepts, as scenarios do (kn). */
#define FW_SPEED_MAX_KN 40.0
/* Refuses kn outside [lo, FW_SPEED_MAX_KN]. */
fw_status fw_check_speed(const char *opt, double kn, double lo, fw_error *err);
/* Warns on stderr when kn is outside the speeds the ship's Nomoto knowledge
 * base was fitted over: "FILE: FIELD: ..." (file may be NULL: "--own"). */
void fw_warn_nomoto_speed(const fw_ship *ship, double kn, const char *file, const char *field);

/* A remote SUMO's host must resolve (checked before anything runs). */
fw_status fw_check_sumo_mode(const char *opt, const fw_traffic_mode *mode, fw_error *err);


/* Prints "fairway: msg" to stderr and returns the status as an exit code. */
int fw_report(const fw_error *err);

#endif
