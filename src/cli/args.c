#include "cli/args.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

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
    char *save = NULL;
    for (char *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (*n >= max)
            return fw_fail(err, FW_EINPUT, "%s: at most %d values in '%s'", opt, max, text);
        fw_status st = fw_parse_double(opt, tok, &out[*n], err);
        if (st)
            return st;
        (*n)++;
    }
    return FW_OK;
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
