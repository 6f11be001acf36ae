/* netbuild.h - SUMO networks built at run time from plain XML.
 *
 * The build turns networks/NAME/ into net.xml once; a scenario with explicit
 * target ships needs a network of its own (a straight waterway edge along each
 * target's track), so the run writes plain XML and calls netconvert here, with
 * the same options as the build (normalisation off: SUMO's x/y are the node
 * coordinates).  The timestamp netconvert writes into the file's header is
 * removed, so the same inputs give byte-identical networks.
 */
#ifndef FW_NETBUILD_H
#define FW_NETBUILD_H

#include "core/error.h"

/* netconvert run in directory dir (relative names are relative to it, and
 * are what the net.xml's header records, so a run directory's network does not
 * depend on where the directory is): node and edge files (comma-separated
 * lists allowed), an optional type file (NULL) -> out; proj (NULL: none) a
 * PROJ string for nodes given in degrees (--proj, as the build gives a
 * geo-referenced network's).  netconvert's messages go to log (NULL:
 * discarded).  FW_ERUN with the log's name when it fails. */
fw_status fw_netconvert(const char *dir, const char *nodes, const char *edges, const char *types,
                        const char *proj, const char *out, const char *log, fw_error *err);

#endif
