/* error.h - one error record shared by every module.
 *
 * Functions that can fail return an fw_status and, when given a non-NULL
 * fw_error, fill it with a one-line message.  The status maps directly to the
 * process exit code: 0 ok, 1 a run failed, 2 bad input.
 */
#ifndef FW_ERROR_H
#define FW_ERROR_H

#include <stdarg.h>

typedef enum fw_status {
    FW_OK = 0,
    FW_ERUN = 1,   /* the input was fine but the computation failed */
    FW_EINPUT = 2  /* the user's input (file, option, value) is wrong */
} fw_status;

typedef struct fw_error {
    fw_status status;
    char msg[512];
} fw_error;

/* Records status and a printf-style message; returns status so callers can
 * write `return fw_fail(err, FW_EINPUT, "...")`.  err may be NULL. */
fw_status fw_fail(fw_error *err, fw_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Same, for a location in a data file: "FILE:LINE: FIELD: message". */
fw_status fw_fail_at(fw_error *err, const char *file, int line, const char *field,
                     const char *fmt, ...) __attribute__((format(printf, 5, 6)));

void fw_error_clear(fw_error *err);

#endif
