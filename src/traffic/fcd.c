/* fcd.c - a run's floating car data in SUMO's layout (fcd.h). */
#include "traffic/fcd.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"

struct fw_fcd {
    FILE *f;
    char path[1100], tmp[1110];
    bool failed;
};

fw_status fw_fcd_open(const char *path, fw_fcd **out, fw_error *err)
{
    *out = NULL;
    fw_fcd *d = calloc(1, sizeof *d);
    if (!d)
        return fw_fail(err, FW_ERUN, "out of memory");
    if (fw_path(d->path, sizeof d->path, err, "%s", path) ||
        !(d->f = fw_file_begin(path, d->tmp, sizeof d->tmp, err))) {
        free(d);
        return err->status;
    }
    fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
          "<!-- written by fairway in SUMO's FCD layout: every ship, x/y its front bumper -->\n"
          "<fcd-export>\n", d->f);
    *out = d;
    return FW_OK;
}

void fw_xml_putc(int c, FILE *f)
{
    switch (c) {
    case '&': fputs("&amp;", f); break;
    case '<': fputs("&lt;", f); break;
    case '"': fputs("&quot;", f); break;
    default: fputc(c, f);
    }
}

/* Ids and types are SUMO's: letters, digits and a few marks, but a user's
 * network may name them with anything XML must escape. */
static void put_text(FILE *f, const char *s)
{
    for (; *s; s++)
        fw_xml_putc(*s, f);
}

fw_status fw_fcd_step(fw_fcd *d, double time, const fw_sumo_raw *v, int n, fw_error *err)
{
    FILE *f = d->f;
    fprintf(f, "    <timestep time=\"%.2f\">\n", time);
    for (int i = 0; i < n; i++) {
        fputs("        <vehicle id=\"", f);
        put_text(f, v[i].id);
        fprintf(f, "\" x=\"%.2f\" y=\"%.2f\" angle=\"%.2f\" type=\"", v[i].x, v[i].y,
                v[i].angle_deg);
        put_text(f, v[i].type);
        fprintf(f, "\" speed=\"%.2f\"/>\n", v[i].speed);
    }
    fputs("    </timestep>\n", f);
    if (ferror(f)) {
        d->failed = true;
        return fw_fail(err, FW_ERUN, "cannot write %s: %s", d->path, strerror(errno ? errno : EIO));
    }
    return FW_OK;
}

fw_status fw_fcd_close(fw_fcd *d, bool keep, fw_error *err)
{
    if (!d)
        return FW_OK;
    fw_status st = FW_OK;
    if (keep && !d->failed) {
        fputs("</fcd-export>\n", d->f);
        st = fw_file_commit(d->f, d->tmp, d->path, err);
    } else {
        fw_file_abort(d->f, d->tmp);
    }
    free(d);
    return st;
}
