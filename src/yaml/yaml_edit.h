/* yaml_edit.h - rewriting values in a YAML file people also edit by hand.
 *
 * Tools that write results back into data files (calibration, identification)
 * change single lines or blocks and keep every other line, comments included.
 *
 * An edit works on the file's text in memory.  Lines are split exactly where
 * libyaml breaks them (LF, CRLF, a bare CR, NEL, LS, PS), so the line numbers
 * of the YAML tree always point at the right line, and inserted text takes the
 * file's own line ending.  Every edit is checked by parsing the result: the
 * edited value must read back as written and every other field must be
 * unchanged, otherwise the edit is refused with a clear error and nothing is
 * changed.  Saving writes a temporary file beside the target, fsyncs it,
 * optionally checks it (check callback) and renames it over the target, so
 * the target is either the old file or the complete new one, never a part.
 */
#ifndef FW_YAML_EDIT_H
#define FW_YAML_EDIT_H

#include <stddef.h>

#include "core/error.h"

typedef struct fw_yaml_edit fw_yaml_edit;

/* Reads path (which must parse as YAML) for editing. */
fw_status fw_yaml_edit_open(const char *path, fw_yaml_edit **out, fw_error *err);
/* Same, from text in memory; name is used in messages and by save(NULL). */
fw_status fw_yaml_edit_open_text(const char *text, size_t len, const char *name,
                                 fw_yaml_edit **out, fw_error *err);
void fw_yaml_edit_free(fw_yaml_edit *ed);

/* The current text (NUL-terminated) and its length. */
const char *fw_yaml_edit_text(const fw_yaml_edit *ed, size_t *len);

/* Sets section.key (a scalar on the key's own line directly under a top-level
 * mapping) to value, with an end-of-line comment (NULL: no comment). */
fw_status fw_yaml_edit_scalar(fw_yaml_edit *ed, const char *section, const char *key,
                              const char *value, const char *comment, fw_error *err);

/* Replaces the comment lines between the line "# >>> TAG" and "# <<< TAG"
 * with text (each line should start with "# "); inserts the block at the end
 * of the file's leading comment header if the markers are not there yet. */
fw_status fw_yaml_edit_comment_block(fw_yaml_edit *ed, const char *tag, const char *text,
                                     fw_error *err);

/* Replaces a whole top-level block (the key line and everything indented
 * below it, plus the comment lines directly above it) with text; appends text
 * at the end when the key is absent.  text must end with a newline. */
fw_status fw_yaml_edit_block(fw_yaml_edit *ed, const char *key, const char *text,
                             fw_error *err);

/* Checks a complete temporary file before it replaces the target. */
typedef fw_status (*fw_yaml_check)(const char *tmp_path, void *ctx, fw_error *err);

/* Writes the text to path (NULL: the file it was opened from) atomically:
 * temporary file in the same directory, fsync, check (may be NULL), rename.
 * On any failure the target is untouched and no temporary file is left. */
fw_status fw_yaml_edit_save(const fw_yaml_edit *ed, const char *path, fw_yaml_check check,
                            void *ctx, fw_error *err);

/* One edit: open, edit, save over the same file (the tests' convenience;
 * the commands use a session for several edits and one save). */
fw_status fw_yaml_set_scalar(const char *path, const char *section, const char *key,
                             const char *value, const char *comment, fw_error *err);

#endif
