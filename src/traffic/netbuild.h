/* netbuild.h - SUMO networks built at run time from plain XML.
 *
 * A network's sources become its net.xml on first use (fw_network_build); a
 * scenario with explicit target ships needs a network of its own (a straight
 * waterway edge along each target's track), so the run writes plain XML and
 * calls netconvert here, with the same options (normalisation off: SUMO's x/y
 * are the node coordinates).  The timestamp netconvert writes into the file's header is
 * removed, so the same inputs give byte-identical networks.
 */
#ifndef FW_NETBUILD_H
#define FW_NETBUILD_H

#include "core/error.h"
#include "traffic/demand.h"

/* netconvert run in directory dir (relative names are relative to it, and
 * are what the net.xml's header records, so a run directory's network does not
 * depend on where the directory is): node and edge files (comma-separated
 * lists allowed), an optional type file (NULL) -> out; proj (NULL: none) a
 * PROJ string for nodes given in degrees (--proj, as the build gives a
 * geo-referenced network's).  netconvert's messages go to log (NULL:
 * discarded).  FW_ERUN with the log's name when it fails. */
fw_status fw_netconvert(const char *dir, const char *nodes, const char *edges, const char *types,
                        const char *proj, const char *out, const char *log, fw_error *err);

/* The net.xml of a network's sources (demand.h fw_network_find), built on
 * first use into the network cache (netcache.h) and again whenever a
 * source's bytes change; nf->net is set to the cache entry's file, which is
 * what SUMO reads: the sources a study records the digests of are the very
 * bytes the file was built from.  netconvert runs in the sources' directory
 * on their own names, and the header's output file is cut to NAME.net.xml, so
 * the same sources give the same bytes wherever they are.  A build goes into
 * a directory of its own and is stored whole (renamed into place), so
 * parallel runs (a sweep's workers) building the same network at once never
 * read a partial file.  Without a usable cache the file stays in the build's
 * temporary directory until the process exits.  FW_EINPUT when netconvert
 * refuses the sources: FILE:LINE when it names them, else its message quoted.
 */
fw_status fw_network_build(fw_network_files *nf, fw_error *err);

#endif
