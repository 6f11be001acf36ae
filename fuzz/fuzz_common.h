/* fuzz_common.h - what the loader fuzz targets share.
 *
 * The loaders read files by path, so each input is written to one file in a
 * private directory made once per process.  The directory mirrors the data
 * tree where a loader resolves names relative to its file: a study's
 * "scenario: ../traffic/X.yaml" finds the shipped scenarios through symlinks.
 * FAIRWAY_DATA is set to the source tree so ship names resolve.
 */
#ifndef FW_FUZZ_COMMON_H
#define FW_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>

/* Path of the file holding the input (under DIR/SUB/), rewritten whole. */
const char *fuzz_write_input(const char *sub, const uint8_t *data, size_t size);

#endif
