/* json.h - the pieces of JSON output every --json writer shares.
 *
 * Text from files and options (ship names, reasons, paths) can hold quotes,
 * backslashes or control characters; written raw they would break the
 * object.  fw_json_string escapes them as RFC 8259 asks; ordinary text comes
 * out unchanged between its quotes.  Numbers that are not finite are null.
 */
#ifndef FW_JSON_H
#define FW_JSON_H

#include <stdio.h>

/* Writes s (UTF-8, NULL as null) as a quoted JSON string. */
void fw_json_string(FILE *f, const char *s);

/* Writes v with the printf format fmt ("%.1f"), or null when not finite. */
void fw_json_number(FILE *f, double v, const char *fmt);

#endif
