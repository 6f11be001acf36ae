/* netcache.h - netconvert's output kept by what it was made from.
 *
 * A network's own net.xml (netbuild.h fw_network_build, read in place) and a
 * network built for a run with its targets' tracks (copied into the run)
 * depend only on netconvert's command
 * line, the netconvert program and the bytes of its input files.  The cache
 * keeps each build's files (the net.xml, netconvert's log) in
 * ROOT/net/HASH/, ROOT being $XDG_CACHE_HOME/fairway or ~/.cache/fairway,
 * beside the key they were made from, written out in full: the command line,
 * SUMO_HOME, netconvert's size and modification time, every input file's name
 * and bytes.  A lookup compares the whole key byte for byte, so a hash
 * collision or a changed input can only miss, never hand out another
 * network; what a hit copies into the run is byte for byte what netconvert
 * wrote for the same inputs.
 *
 * An entry also holds each file's size and FNV-1a digest (sums), checked at
 * every use: a damaged entry (a truncated file, a disk error, an edit by
 * hand) is removed and built again, never handed to SUMO.
 *
 * An entry is a directory written under a temporary name and renamed into
 * place whole, so parallel runs (a sweep's workers) never see a partial entry;
 * of two runs storing the same entry at once, the second throws its copy away.
 * The cache never makes a run fail: any failure of its own (no home directory,
 * a full disk, a damaged entry) just means netconvert runs.
 * FAIRWAY_NETCACHE=off turns it off.  It keeps at most FAIRWAY_NETCACHE_MAX
 * entries (512), the least recently used going first.
 */
#ifndef FW_NETCACHE_H
#define FW_NETCACHE_H

#include <stdbool.h>
#include <stddef.h>

typedef struct fw_netcache_key {
    char *text;               /* the key written out (malloc'd) */
    size_t n;
    char dir[1200];           /* the entry's directory */
    int n_files;              /* what the entry holds: these names */
    const char *const *names;
} fw_netcache_key;

/* The key of netconvert run as argv (NULL-terminated) in dir, its input files
 * the comma-separated lists in inputs (NULL-terminated; relative names are
 * relative to dir), the entry holding the n_files files names (kept by
 * pointer).  False, *k empty, when the cache is off or unusable or an input
 * cannot be read (netconvert will say why).  needed: the entry is the only
 * place its files will have (a network's own net.xml, read in place): with
 * the cache off or without a place, the entry goes to TMPDIR/fairway-UID/net,
 * a directory of the user's alone. */
bool fw_netcache_key_make(const char *dir, const char *const *argv, const char *const *inputs,
                          int n_files, const char *const *names, bool needed,
                          fw_netcache_key *k);

/* A hit: the entry's files copied to dest[i] (one per name), each written
 * whole under a temporary name first.  False when the entry is missing, its
 * key differs, a file is not as stored (the entry then removed) or a copy
 * fails. */
bool fw_netcache_get(const fw_netcache_key *k, const char *const *dest);

/* A hit read in place: the path of the entry's first file (names[0]) into
 * path, the entry marked recently used.  False when the entry is missing, its
 * key differs or a file is not as stored (the entry then removed). */
bool fw_netcache_lookup(const fw_netcache_key *k, char *path, size_t n);

/* Stores the files src[i] (one per name) under k: quietly nothing if the
 * entry appeared meanwhile or the cache cannot be written. */
void fw_netcache_put(const fw_netcache_key *k, const char *const *src);

void fw_netcache_key_free(fw_netcache_key *k);

#endif
