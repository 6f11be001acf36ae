/* network.c - where a network's files are: the net.xml in the build tree
 * or the install (netconvert output, core/files.h fw_net_dir), the sources
 * and demand under the data root. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/files.h"
#include "ship/ship.h"
#include "traffic/demand.h"

fw_status fw_network_find(const char *name, fw_network_files *out, fw_error *err)
{
    static const char *const known = "channel, crossing, strait, sea, dover, geo-channel, bend";
    size_t n = strlen(name);
    bool ok = n > 0 && n < 64 && strspn(name, "abcdefghijklmnopqrstuvwxyz"
                                              "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") == n;
    if (!ok)
        return fw_fail(err, FW_EINPUT, "network '%s': not a network name (%s)", name, known);
    const char *root = fw_data_root();
    fw_status st;
    if ((st = fw_path(out->net, sizeof out->net, err, "%s/%s/%s.net.xml", fw_net_dir(), name,
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

/* Is id the id of an <edge> in the plain-XML edges text? */
static bool has_edge(const char *xml, const char *id)
{
    size_t n = strlen(id);
    for (const char *p = strstr(xml, "<edge"); p; p = strstr(p + 5, "<edge")) {
        const char *end = strchr(p, '>');
        const char *a = strstr(p, " id=\"");
        if (a && (!end || a < end) && strncmp(a + 5, id, n) == 0 && a[5 + n] == '"')
            return true;
    }
    return false;
}

fw_status fw_network_check_demand(const char *name, const fw_demand *dm, fw_error *err)
{
    char path[1200];
    fw_status st = fw_path(path, sizeof path, err, "%s/networks/%s/%s.edg.xml", fw_data_root(),
                           name, name);
    if (st)
        return st;
    char *xml = NULL;
    size_t len = 0;
    fw_error rerr = {0};
    if ((st = fw_read_text(path, &xml, &len, &rerr)))
        return fw_fail(err, st, "network '%s': %s", name, rerr.msg);
    if (len == 0) {
        free(xml);
        return fw_fail(err, FW_EINPUT, "network '%s': %s is empty", name, path);
    }
    for (int i = 0; !st && i < dm->n; i++)
        for (int k = 0; !st && k < dm->streams[i].n_edges; k++)
            if (!has_edge(xml, dm->streams[i].edges[k])) {
                char field[64];
                snprintf(field, sizeof field, "streams[%d].edges", i);
                st = fw_fail_at(err, dm->file, dm->streams[i].edge_line[k], field,
                                "edge '%s' is not in %s", dm->streams[i].edges[k], path);
            }
    free(xml);
    return st;
}

/* The value of attribute name="..." inside the tag text tag (up to its '>'),
 * into out; false when it is not there. */
static bool tag_attr(const char *tag, const char *name, char *out, size_t n)
{
    const char *end = strchr(tag, '>');
    char key[64];
    snprintf(key, sizeof key, " %s=\"", name);
    const char *a = strstr(tag, key);
    if (!a || (end && a > end))
        return false;
    a += strlen(key);
    const char *q = strchr(a, '"');
    if (!q || (size_t)(q - a) >= n)
        return false;
    memcpy(out, a, (size_t)(q - a));
    out[q - a] = '\0';
    return true;
}

fw_status fw_network_plane(const fw_network_files *nf, char *proj, size_t n, double *off_e,
                           double *off_n, fw_error *err)
{
    proj[0] = '\0';
    *off_e = *off_n = 0.0;
    FILE *f = fopen(nf->net, "rb");
    if (!f)
        return fw_fail(err, FW_EINPUT, "cannot read %s", nf->net);
    /* <location> is among the first lines netconvert writes */
    char head[16384];
    size_t got = fread(head, 1, sizeof head - 1, f);
    fclose(f);
    head[got] = '\0';
    const char *loc = strstr(head, "<location ");
    char off[128];
    if (!loc || !tag_attr(loc, "netOffset", off, sizeof off) ||
        sscanf(off, "%lf,%lf", off_e, off_n) != 2)
        return fw_fail(err, FW_EINPUT, "%s: no <location netOffset> in its first 16 kB", nf->net);
    if (!tag_attr(loc, "projParameter", proj, n))
        return fw_fail(err, FW_EINPUT, "%s: <location>'s projParameter missing or longer than "
                                       "%zu characters", nf->net, n - 1);
    if (strcmp(proj, "!") == 0) /* netconvert's "no projection" */
        proj[0] = '\0';
    return FW_OK;
}
