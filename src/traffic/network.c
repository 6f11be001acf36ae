/* network.c - where a network's files are: its sources and demand (under
 * the data root or in a directory of the user's), the net.xml built from them
 * on first use (netbuild.h fw_network_build). */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files.h"
#include "ship/ship.h"
#include "traffic/demand.h"
#include "traffic/netbuild.h"

/* The networks under DATA/networks (directories holding a demand.yaml), for
 * a message: "a, b, c" in directory order, sorted. */
static void known_networks(char *out, size_t n)
{
    char dir[1100];
    out[0] = '\0';
    if (fw_path(dir, sizeof dir, NULL, "%s/networks", fw_data_root()))
        return;
    struct dirent **v = NULL;
    int k = scandir(dir, &v, NULL, alphasort);
    size_t len = 0;
    for (int i = 0; i < k; i++) {
        char demand[1400];
        if (v[i]->d_name[0] != '.' &&
            !fw_path(demand, sizeof demand, NULL, "%s/%s/demand.yaml", dir, v[i]->d_name) &&
            access(demand, R_OK) == 0 && len + strlen(v[i]->d_name) + 3 < n)
            len += (size_t)snprintf(out + len, n - len, "%s%s", len ? ", " : "", v[i]->d_name);
        free(v[i]);
    }
    free(v);
}

/* A source file DIR/NAME.ext: FW_EINPUT when required and missing or empty;
 * "" when optional and missing. */
/* The nodes' and edges' files hold at least one <node> or <edge> element (a
 * file of none is refused here, before netconvert's less plain message). */
static fw_status has_element(const fw_network_files *out, const char *path, const char *ext,
                             const char *what, fw_error *err)
{
    const char *tag = strcmp(ext, "nod.xml") == 0 ? "<node" : strcmp(ext, "edg.xml") == 0
                                                                 ? "<edge"
                                                                 : NULL;
    char *text = NULL;
    if (!tag)
        return FW_OK;
    fw_status st = fw_read_text(path, &text, NULL, err);
    if (st)
        return st;
    bool found = false;
    for (const char *p = strstr(text, tag); p && !found; p = strstr(p + 5, tag))
        found = p[5] == ' ' || p[5] == '\t' || p[5] == '\n' || p[5] == '\r' || p[5] == '/' ||
                p[5] == '>';
    free(text);
    return found ? FW_OK
                 : fw_fail(err, FW_EINPUT, "network '%s': %s has no %s> element (%s; "
                           "networks/README.md says what a network holds)", out->name, path,
                           tag, what);
}

static fw_status source_file(fw_network_files *out, const char *ext, bool required,
                             const char *what, char *path, size_t n, fw_error *err)
{
    fw_status st = fw_path(path, n, err, "%s/%s.%s", out->dir, out->name, ext);
    struct stat sb;
    if (st)
        return st;
    if (stat(path, &sb) == 0 && S_ISREG(sb.st_mode) && sb.st_size > 0 && access(path, R_OK) == 0)
        return has_element(out, path, ext, what, err);
    if (!required && stat(path, &sb) != 0) {
        path[0] = '\0';
        return FW_OK;
    }
    return fw_fail(err, FW_EINPUT, "network '%s': %s %s (%s; networks/README.md says what a "
                   "network holds)", out->name, path,
                   stat(path, &sb) != 0 ? "does not exist" : S_ISREG(sb.st_mode) && sb.st_size == 0
                                                               ? "is empty" : "cannot be read",
                   what);
}

/* NAME.proj's first line, a PROJ string ("+proj=..."), into out->proj. */
static fw_status read_proj(fw_network_files *out, fw_error *err)
{
    char path[1200], *text = NULL;
    fw_status st = source_file(out, "proj", false, "its projection", path, sizeof path, err);
    if (st || !path[0] || (st = fw_read_text(path, &text, NULL, err)))
        return st;
    size_t len = strcspn(text, "\r\n");
    if (strncmp(text, "+proj=", 6) != 0 || len >= sizeof out->proj)
        st = fw_fail_at(err, path, 1, "projection", "the first line must be a PROJ string "
                        "(+proj=...) of at most %zu characters", sizeof out->proj - 1);
    else
        snprintf(out->proj, sizeof out->proj, "%.*s", (int)len, text);
    free(text);
    return st;
}

/* out->name and out->dir from a name or a directory's path. */
static fw_status locate(const char *name, fw_network_files *out, fw_error *err)
{
    if (strchr(name, '/')) {
        size_t n = strlen(name);
        while (n > 1 && name[n - 1] == '/')
            n--;
        const char *base = name + n;
        while (base > name && base[-1] != '/')
            base--;
        size_t bn = (size_t)(name + n - base);
        if (bn == 0 || bn >= sizeof out->name || n >= sizeof out->dir)
            return fw_fail(err, FW_EINPUT, "network '%s': not a network directory (its last "
                           "part names the network, at most %zu characters)", name,
                           sizeof out->name - 1);
        snprintf(out->name, sizeof out->name, "%.*s", (int)bn, base);
        snprintf(out->dir, sizeof out->dir, "%.*s", (int)n, name);
        return FW_OK;
    }
    size_t n = strlen(name);
    bool ok = n > 0 && n < sizeof out->name &&
              strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") == n;
    char known[512];
    known_networks(known, sizeof known);
    if (!ok)
        return fw_fail(err, FW_EINPUT, "network '%s': not a network name (%s) nor a directory's "
                       "path", name, known);
    snprintf(out->name, sizeof out->name, "%s", name);
    fw_status st = fw_path(out->dir, sizeof out->dir, err, "%s/networks/%s", fw_data_root(), name);
    struct stat sb;
    if (!st && (stat(out->dir, &sb) != 0 || !S_ISDIR(sb.st_mode)))
        st = fw_fail(err, FW_EINPUT, "unknown network '%s' (%s): no directory %s", name, known,
                     out->dir);
    return st;
}

fw_status fw_network_find(const char *name, fw_network_files *out, fw_error *err)
{
    memset(out, 0, sizeof *out);
    fw_status st = locate(name, out, err);
    struct stat sb;
    if (!st && (stat(out->dir, &sb) != 0 || !S_ISDIR(sb.st_mode)))
        st = fw_fail(err, FW_EINPUT, "network '%s': %s is not a directory", out->name, out->dir);
    if (st || (st = source_file(out, "nod.xml", true, "its nodes", out->nodes, sizeof out->nodes,
                                err)) ||
        (st = source_file(out, "edg.xml", true, "its edges", out->edges, sizeof out->edges, err)) ||
        (st = source_file(out, "typ.xml", false, "its edge types", out->typ, sizeof out->typ,
                          err)) ||
        (st = read_proj(out, err)) ||
        (st = fw_path(out->demand, sizeof out->demand, err, "%s/demand.yaml", out->dir)))
        return st;
    if (access(out->demand, R_OK) != 0)
        return fw_fail(err, FW_EINPUT, "network '%s': no %s (its traffic streams; "
                       "networks/README.md)", out->name, out->demand);
    /* the network's own ship types, else the shared ones */
    if ((st = fw_path(out->types, sizeof out->types, err, "%s/ships.add.xml", out->dir)))
        return st;
    if (access(out->types, R_OK) != 0 &&
        (st = fw_path(out->types, sizeof out->types, err, "%s/networks/ships.add.xml",
                      fw_data_root())))
        return st;
    if (access(out->types, R_OK) != 0)
        return fw_fail(err, FW_EINPUT, "no ship types file %s", out->types);
    return fw_network_build(out, err);
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

fw_status fw_network_check_demand(const fw_network_files *nf, const fw_demand *dm, fw_error *err)
{
    const char *name = nf->name, *path = nf->edges;
    fw_status st;
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
