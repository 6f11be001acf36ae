#include "core/error.h"

#include <stdio.h>
#include <string.h>

fw_status fw_fail(fw_error *err, fw_status status, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
        err->status = status;
    }
    return status;
}

fw_status fw_fail_at(fw_error *err, const char *file, int line, const char *field,
                     const char *fmt, ...)
{
    if (err) {
        char detail[384];
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(detail, sizeof detail, fmt, ap);
        va_end(ap);
        if (field && field[0])
            snprintf(err->msg, sizeof err->msg, "%s:%d: %s: %s", file, line, field, detail);
        else
            snprintf(err->msg, sizeof err->msg, "%s:%d: %s", file, line, detail);
        err->status = FW_EINPUT;
    }
    return FW_EINPUT;
}

void fw_error_clear(fw_error *err)
{
    if (err) {
        err->status = FW_OK;
        err->msg[0] = '\0';
    }
}
