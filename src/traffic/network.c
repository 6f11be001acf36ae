/* network.c - where a network's files are: the net.xml in the build tree
 * (netconvert output), the sources and demand under the data root. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "core/files.h"
#include "ship/ship.h"
#include "traffic/demand.h"

fw_status fw_network_find(const char *name, fw_network_files *out, fw_error *err)
{
    static const char *const known = "channel, crossing, strait, sea, dover";
    size_t n = strlen(name);
    bool ok = n > 0 && n < 64 && strspn(name, "abcdefghijklmnopqrstuvwxyz"
                                              "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") == n;
    if (!ok)
        return fw_fail(err, FW_EINPUT, "network '%s': not a network name (%s)", name, known);
    const char *root = fw_data_root();
    fw_status st;
    if ((st = fw_path(out->net, sizeof out->net, err, "%s/%s/%s.net.xml", FAIRWAY_NET_DIR, name,
                      name)) ||
        (st = fw_path(out->demand, sizeof out->demand, err, "%s/networks/%s/demand.yaml", root,
                      name)) ||
        (st = fw_path(out->types, sizeof out->types, err, "%s/networks/ships.add.xml", root)))
        return st;
    if (access(out->demand, R_OK) != 0)
        return fw_fail(err, FW_EINPUT, "unknown network '%s' (%s): no %s", name, known,
                       out->demand);
    if (access(out->net, R_OK) != 0)
        return fw_fail(err, FW_EINPUT, "network '%s' is not built: no %s (run the build)", name,
                       out->net);
    if (access(out->types, R_OK) != 0)
        return fw_fail(err, FW_EINPUT, "no ship types file %s", out->types);
    return FW_OK;
}
