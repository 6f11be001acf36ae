#include "cli/args.h"

#include <errno.h>
#include <libgen.h>
#include <netdb.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files.h"

bool fw_args_opt(fw_args *a, const char *name, const char **value, fw_error *err)
{
    if (a->i >= a->argc)
        return false;
    const char *arg = a->argv[a->i];
    size_t n = strlen(name);
    if (strncmp(arg, name, n) != 0)
        return false;
    if (arg[n] == '=') {
        *value = arg + n + 1;
        a->i++;
        return true;
    }
    if (arg[n] != '\0')
        return false;
    if (a->i + 1 >= a->argc) {
        fw_fail(err, FW_EINPUT, "option %s needs a value", name);
        *value = NULL;
        a->i++;
        return true;
    }
    *value = a->argv[a->i + 1];
    a->i += 2;
    return true;
}

bool fw_args_flag(fw_args *a, const char *name)
{
    if (a->i < a->argc && strcmp(a->argv[a->i], name) == 0) {
        a->i++;
        return true;
    }
    return false;
}

/* Strict number reading shared by both parsers: the whole text, finite;
 * out (a double or a long) is written only when the text is good. */
static fw_status parse_number(const char *opt, const char *text, bool integer, void *out,
                              fw_error *err)
{
    if (!text)
        return fw_fail(err, FW_EINPUT, "option %s needs a value", opt);
    char *end = NULL;
    errno = 0;
    long l = integer ? strtol(text, &end, 10) : 0;
    double d = integer ? 0.0 : strtod(text, &end);
    if (end == text || *end != '\0' || (integer && errno == ERANGE))
        return fw_fail(err, FW_EINPUT, "%s: '%s' is not %s", opt, text,
                       integer ? "an integer" : "a number");
    if (!isfinite(d) || errno == ERANGE)
        return fw_fail(err, FW_EINPUT, "%s: '%s' is not a finite number", opt, text);
    if (integer)
        *(long *)out = l;
    else
        *(double *)out = d;
    return FW_OK;
}

fw_status fw_parse_double(const char *opt, const char *text, double *out, fw_error *err)
{
    return parse_number(opt, text, false, out, err);
}

fw_status fw_parse_long(const char *opt, const char *text, long *out, fw_error *err)
{
    return parse_number(opt, text, true, out, err);
}

fw_status fw_args_one_file(void *ctx, const char *arg, fw_error *err)
{
    const char **slot = ctx;
    if (*slot)
        return fw_fail(err, FW_EINPUT, "one file at a time ('%s' and '%s')", *slot, arg);
    *slot = arg;
    return FW_OK;
}

fw_status fw_parse_list(const char *opt, const char *text, double *out, int max, int *n,
                        fw_error *err)
{
    *n = 0;
    if (!text)
        return fw_fail(err, FW_EINPUT, "option %s needs a value", opt);
    char buf[512];
    if (strlen(text) >= sizeof buf)
        return fw_fail(err, FW_EINPUT, "%s: value too long", opt);
    strcpy(buf, text);
    /* split by hand: strtok would pass over an empty item ("10,,12") */
    char *tok = buf;
    for (;;) {
        char *comma = strchr(tok, ',');
        if (comma)
            *comma = '\0';
        if (!tok[0])
            return fw_fail(err, FW_EINPUT, "%s: empty item in '%s'", opt, text);
        if (*n >= max)
            return fw_fail(err, FW_EINPUT, "%s: at most %d values in '%s'", opt, max, text);
        fw_status st = fw_parse_double(opt, tok, &out[*n], err);
        if (st)
            return st;
        (*n)++;
        if (!comma)
            return FW_OK;
        tok = comma + 1;
    }
}

bool fw_args_help(const fw_args *a, void (*help)(void))
{
    if (a->i >= a->argc || !fw_is_help(a->argv[a->i]))
        return false;
    help();
    return true;
}

static fw_status store_option(const fw_opt *o, const char *v, fw_error *err)
{
    switch (o->kind) {
    case FW_OPT_TEXT:
        *(const char **)o->out = v;
        return FW_OK;
    case FW_OPT_DOUBLE:
        return fw_parse_double(o->name, v, o->out, err);
    case FW_OPT_LONG:
        return fw_parse_long(o->name, v, o->out, err);
    case FW_OPT_LIST:
        return fw_parse_list(o->name, v, o->out, o->max, o->n, err);
    case FW_OPT_FLAG:
        *(bool *)o->out = true;
        return FW_OK;
    case FW_OPT_CALL:
        return o->call(o->out, o->name, v, err);
    }
    return fw_fail(err, FW_ERUN, "%s: unknown option kind", o->name);
}

fw_arg_read fw_args_next(fw_args *a, const char *cmd, const fw_opt *opts, void (*help)(void),
                         fw_error *err)
{
    if (fw_args_help(a, help))
        return FW_ARG_HELP;
    const char *arg = a->argv[a->i];
    for (const fw_opt *o = opts; o->name; o++) {
        const char *v = NULL;
        bool hit = o->kind == FW_OPT_FLAG ? fw_args_flag(a, o->name)
                                          : fw_args_opt(a, o->name, &v, err);
        if (!hit)
            continue;
        if (err->status || store_option(o, v, err))
            return FW_ARG_ERROR;
        if (o->given)
            *o->given = true;
        return FW_ARG_OPTION;
    }
    if (arg[0] != '-' || !arg[1])
        return FW_ARG_POSITIONAL;
    fw_fail(err, FW_EINPUT, "%s: unknown option '%s' (see fairway %s --help)", cmd, arg, cmd);
    return FW_ARG_ERROR;
}

int fw_args_parse(int argc, char **argv, const char *cmd, const fw_opt *opts,
                  void (*help)(void), fw_args_positional positional, void *ctx, fw_error *err)
{
    fw_args a = {argc, argv, 0};
    while (a.i < a.argc) {
        switch (fw_args_next(&a, cmd, opts, help, err)) {
        case FW_ARG_OPTION:
            break;
        case FW_ARG_HELP:
            return 0;
        case FW_ARG_POSITIONAL:
            if (!positional)
                fw_fail(err, FW_EINPUT, "%s: unexpected argument '%s' (see fairway %s --help)",
                        cmd, argv[a.i], cmd);
            else
                positional(ctx, argv[a.i++], err);
            if (err->status)
                return fw_report(err);
            break;
        case FW_ARG_ERROR:
            return fw_report(err);
        }
    }
    return -1;
}

bool fw_is_help(const char *arg)
{
    return strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0;
}

int fw_report(const fw_error *err)
{
    fprintf(stderr, "fairway: %s\n", err->msg);
    return err->status ? (int)err->status : 1;
}

fw_status fw_check_out_file(const char *opt, const char *path, bool replace, fw_error *err)
{
    struct stat sb;
    if (!path[0])
        return fw_fail(err, FW_EINPUT, "%s: empty path", opt);
    if (fw_file_is_stream(path))
        return FW_OK; /* written as it is, not replaced (core/files.h) */
    if (stat(path, &sb) == 0) {
        if (S_ISDIR(sb.st_mode))
            return fw_fail(err, FW_EINPUT, "%s %s: is a directory, expected a file name", opt,
                           path);
        if (!replace)
            return fw_fail(err, FW_EINPUT, "%s %s: file exists (give --force to replace it)",
                           opt, path);
    }
    return fw_check_parent_dir(opt, path, "cannot write in", err);
}

fw_status fw_check_speed(const char *opt, double kn, double lo, fw_error *err)
{
    if (!(kn >= lo && kn <= FW_SPEED_MAX_KN))
        return fw_fail(err, FW_EINPUT, "%s: %.15g kn outside %.15g-%.15g kn", opt, kn, lo,
                       FW_SPEED_MAX_KN);
    return FW_OK;
}

void fw_warn_nomoto_speed(const fw_ship *ship, double kn, const char *file, const char *field)
{
    const fw_nomoto_kb *kb = &ship->nomoto;
    if (!kb->present || (kn >= kb->speed_min_kn - 1e-9 && kn <= kb->speed_max_kn + 1e-9))
        return;
    fprintf(stderr,
            "fairway: warning: %s%s%s: %.15g kn is outside %.15g-%.15g kn, the speeds %s's Nomoto "
            "knowledge base was fitted over (%s): its predictions are extrapolated\n",
            file ? file : "", file ? ": " : "", field, kn, kb->speed_min_kn, kb->speed_max_kn,
            ship->name, ship->file);
}

fw_status fw_check_sumo_mode(const char *opt, const fw_traffic_mode *mode, fw_error *err)
{
    if (mode->kind != FW_TRAFFIC_REMOTE)
        return FW_OK;
    /* resolved now: libtraci would only say "Invalid network address" later */
    struct addrinfo hints = {.ai_socktype = SOCK_STREAM}, *res = NULL;
    int rc = getaddrinfo(mode->host, NULL, &hints, &res);
    if (res)
        freeaddrinfo(res);
    if (rc != 0)
        return fw_fail(err, FW_EINPUT, "%s remote:%s:%d: cannot resolve host '%s': %s", opt,
                       mode->host, mode->port, mode->host, gai_strerror(rc));
    return FW_OK;
}
