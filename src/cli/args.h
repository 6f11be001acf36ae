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

/* A command's options as a table, read by fw_args_next: every command parses
 * the same way and names a bad option the same way. */
typedef enum fw_opt_kind {
    FW_OPT_TEXT,   /* out: const char ** */
    FW_OPT_DOUBLE, /* out: double * (strict, as fw_parse_double) */
    FW_OPT_LONG,   /* out: long * */
    FW_OPT_LIST,   /* out: double[max], count into *n (as fw_parse_list) */
    FW_OPT_FLAG,   /* out: bool *, set true; takes no value */
    FW_OPT_CALL,   /* call(out, name, value, err) checks and stores the value */
} fw_opt_kind;

typedef struct fw_opt {
    const char *name; /* "--name"; NULL ends the table */
    fw_opt_kind kind;
    void *out;
    bool *given; /* optional: set true when the option is given */
    int max, *n; /* FW_OPT_LIST only */
    fw_status (*call)(void *ctx, const char *name, const char *value, fw_error *err);
} fw_opt;

/* Table rows: FW_OPT("--speed", FW_OPT_DOUBLE, &speed), ..., FW_OPT_END. */
#define FW_OPT(n_, k_, o_) {.name = (n_), .kind = (k_), .out = (o_)}
#define FW_OPT_SEEN(n_, k_, o_, g_) {.name = (n_), .kind = (k_), .out = (o_), .given = (g_)}
#define FW_OPT_FN(n_, f_, ctx_) {.name = (n_), .kind = FW_OPT_CALL, .out = (ctx_), .call = (f_)}
#define FW_OPT_LISTOF(n_, o_, max_, cnt_) \
    {.name = (n_), .kind = FW_OPT_LIST, .out = (o_), .max = (max_), .n = (cnt_)}
#define FW_OPT_END {.name = NULL}

typedef enum fw_arg_read {
    FW_ARG_OPTION,     /* an option of the table was read and stored */
    FW_ARG_HELP,       /* --help or -h: the help was printed, exit 0 */
    FW_ARG_POSITIONAL, /* argv[a->i] is no option; left for the caller */
    FW_ARG_ERROR,      /* *err says which option and why */
} fw_arg_read;

/* Reads the argument at a->i against opts.  An unknown option is an error
 * "CMD: unknown option '--x' (see fairway CMD --help)". */
fw_arg_read fw_args_next(fw_args *a, const char *cmd, const fw_opt *opts, void (*help)(void),
                         fw_error *err);
/* A positional argument (a file): stores it or says why not. */
typedef fw_status (*fw_args_positional)(void *ctx, const char *arg, fw_error *err);
/* The positional reader of a command that takes one file: ctx is its
 * const char * slot; a second file is an error. */
fw_status fw_args_one_file(void *ctx, const char *arg, fw_error *err);
/* The whole command line against opts; positional arguments go to
 * positional(ctx, ...), or are refused when it is NULL.  Returns -1 to go
 * on, 0 after --help, else the exit code (the error printed). */
int fw_args_parse(int argc, char **argv, const char *cmd, const fw_opt *opts,
                  void (*help)(void), fw_args_positional positional, void *ctx, fw_error *err);

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
