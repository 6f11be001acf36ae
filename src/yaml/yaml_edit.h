/* yaml_edit.h - rewriting values in a YAML file people also edit by hand.
 *
 * Tools that write results back into data files (calibration, identification)
 * change single lines or blocks and keep every other line, comments included.
 * Files are replaced atomically (written to a temporary file, then renamed).
 */
#ifndef FW_YAML_EDIT_H
#define FW_YAML_EDIT_H

#include "core/error.h"

/* Sets section.key (a scalar directly under a top-level mapping) to value,
 * with an end-of-line comment (may be NULL to drop the comment). */
fw_status fw_yaml_set_scalar(const char *path, const char *section, const char *key,
                             const char *value, const char *comment, fw_error *err);

/* Replaces the comment lines between the line "# >>> TAG" and "# <<< TAG"
 * with text (each line should start with "# "); appends the block at the end
 * of the file's leading comment header if the markers are not there yet. */
fw_status fw_yaml_set_comment_block(const char *path, const char *tag, const char *text,
                                    fw_error *err);

/* Replaces a whole top-level block (the key line and everything indented
 * below it, plus the comment lines directly above it) with text; appends text
 * at the end when the key is absent.  text must end with a newline. */
fw_status fw_yaml_replace_block(const char *path, const char *key, const char *text,
                                fw_error *err);

#endif
