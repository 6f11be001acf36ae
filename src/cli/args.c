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

fw_status fw_parse_double(const char *opt, const char *text, double *out, fw_error *err)
{
    if (!text)
        return fw_fail(err, FW_EINPUT, "option %s needs a value", opt);
    char *end = NULL;
    errno = 0;
    double v = strtod(text, &end);
    if (end == text || *end != '\0')
        return fw_fail(err, FW_EINPUT, "%s: '%s' is not a number", opt, text);
    if (!isfinite(v) || errno == ERANGE)
        return fw_fail(err, FW_EINPUT, "%s: '%s' is not a finite number", opt, text);
    *out = v;
    return FW_OK;
}

fw_status fw_parse_long(const char *opt, const char *text, long *out, fw_error *err)
{
    if (!text)
        return fw_fail(err, FW_EINPUT, "option %s needs a value", opt);
    char *end = NULL;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE)
        return fw_fail(err, FW_EINPUT, "%s: '%s' is not an integer", opt, text);
    *out = v;
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
        return fw_fail(err, FW_EINPUT, "%s: %g kn outside %g-%g kn", opt, kn, lo,
                       FW_SPEED_MAX_KN);
    return FW_OK;
}

void fw_warn_nomoto_speed(const fw_ship *ship, double kn, const char *file, const char *field)
{
    const fw_nomoto_kb *kb = &ship->nomoto;
    if (!kb->present || (kn >= kb->speed_min_kn - 1e-9 && kn <= kb->speed_max_kn + 1e-9))
        return;
    fprintf(stderr,
            "fairway: warning: %s%s%s: %g kn is outside %g-%g kn, the speeds %s's Nomoto "
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
