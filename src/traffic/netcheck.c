/* netcheck.c - a remote sumo's network against the one the run expects
 * (backend.h). */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "traffic/backend.h"

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The net.xml's convBoundary and its normal edges' ids, sorted, each followed
 * by "\n" (the form be->net gives). */
static fw_status read_net(const char *path, char *xml, double box[4], char **ids, fw_error *err)
{
    const char *b = strstr(xml, "convBoundary=\"");
    if (!b || sscanf(b + 14, "%lf,%lf,%lf,%lf", &box[0], &box[1], &box[2], &box[3]) != 4)
        return fw_fail(err, FW_ERUN, "%s: no convBoundary", path);
    size_t n = 0, cap = 64, len = 0;
    char **v = malloc(cap * sizeof *v);
    for (char *p = strstr(xml, "<edge "); v && p; p = strstr(p + 6, "<edge ")) {
        char *end = strchr(p, '>');
        char *id = strstr(p, " id=\"");
        char *fn = strstr(p, " function=\"");
        if (!end || !id || id > end || (fn && fn < end && strncmp(fn + 11, "normal\"", 7) != 0))
            continue;
        char *q = strchr(id + 5, '"');
        if (!q)
            continue;
        *q = '\0'; /* the text is ours: ids end where their quote was */
        if (n == cap && !(v = realloc(v, (cap *= 2) * sizeof *v)))
            break;
        v[n++] = id + 5;
        len += strlen(id + 5) + 1;
        p = q;
    }
    if (!v || !(*ids = malloc(len + 1))) {
        free(v);
        return fw_fail(err, FW_ERUN, "out of memory reading %s", path);
    }
    qsort(v, n, sizeof *v, cmp_str);
    char *o = *ids;
    for (size_t i = 0; i < n; i++)
        o += sprintf(o, "%s\n", v[i]);
    *o = '\0';
    free(v);
    return FW_OK;
}

/* The first id where the sorted lists a and b part: *in_a when a has it and b
 * does not. */
static void first_difference(const char *a, const char *b, char *out, size_t n, bool *in_a)
{
    while (*a || *b) {
        size_t ka = strcspn(a, "\n"), kb = strcspn(b, "\n");
        int c = !*a ? 1 : !*b ? -1 : strncmp(a, b, ka < kb ? ka : kb);
        if (c == 0 && ka != kb)
            c = ka < kb ? -1 : 1;
        if (c != 0) {
            *in_a = c < 0;
            snprintf(out, n, "%.*s", (int)(*in_a ? ka : kb), *in_a ? a : b);
            return;
        }
        a += ka + 1;
        b += kb + 1;
    }
    out[0] = '\0';
}

fw_status fw_traffic_net_check(const fw_sumo_backend *be, const char *net_file, const char *where,
                               fw_error *err)
{
    FILE *f = fopen(net_file, "rb");
    if (!f)
        return fw_fail(err, FW_ERUN, "cannot read %s", net_file);
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    rewind(f);
    char *xml = size >= 0 ? malloc((size_t)size + 1) : NULL;
    size_t got = xml ? fread(xml, 1, (size_t)size, f) : 0;
    fclose(f);
    if (!xml)
        return fw_fail(err, FW_ERUN, "out of memory reading %s", net_file);
    xml[got] = '\0';
    double want[4], have[4];
    char *want_ids = NULL, *have_ids = NULL;
    fw_status st = read_net(net_file, xml, want, &want_ids, err);
    if (!st)
        st = be->net(have, &have_ids, err);
    char miss[128] = "";
    bool box_ok = true;
    for (int k = 0; !st && k < 4; k++)
        box_ok = box_ok && fabs(want[k] - have[k]) < 0.1; /* net.xml prints 2 decimals */
    if (!st && !box_ok)
        st = fw_fail(err, FW_ERUN,
                     "the sumo at %s runs another network: its boundary is %.2f,%.2f,%.2f,%.2f, "
                     "%s's %.2f,%.2f,%.2f,%.2f (start sumo with the run's sumo/remote-command.txt)",
                     where, have[0], have[1], have[2], have[3],
                     strrchr(net_file, '/') ? strrchr(net_file, '/') + 1 : net_file, want[0], want[1],
                     want[2], want[3]);
    if (!st && strcmp(want_ids, have_ids) != 0) {
        bool ours = false;
        first_difference(want_ids, have_ids, miss, sizeof miss, &ours);
        st = fw_fail(err, FW_ERUN,
                     "the sumo at %s runs another network: edge '%s' %s (start sumo with the "
                     "run's sumo/remote-command.txt)",
                     where, miss, ours ? "of the run's network is not in it" : "is not in the run's network");
    }
    free(xml);
    free(want_ids);
    free(have_ids);
    return st;
}
