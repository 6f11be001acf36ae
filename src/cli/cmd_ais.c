/* fairway ais: what an AIS file holds, its tracks in a scenario's plane, and
 * the demand of a network from it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ais/ais.h"
#include "ais/ais_demand.h"
#include "ais/ais_track.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "core/idmap.h"
#include "core/mem.h"
#include "core/units.h"
#include "traffic/demand.h"

static void help(void)
{
    printf("usage: fairway ais summary FILE [--columns MAP]\n"
           "       fairway ais tracks FILE --origin LAT,LON [--out FILE] [options]\n"
           "       fairway ais demand FILE --network NAME --origin LAT,LON --out FILE [options]\n"
           "\n"
           "Reads AIS position reports from a CSV in the Danish Maritime Authority's layout\n"
           "(aisdk-YYYY-MM-DD.csv, header '# Timestamp,Type of mobile,MMSI,...'), or another\n"
           "layout through --columns.  Class A and B ships are kept; base stations, aids to\n"
           "navigation and other non-ships, broken lines and rows without a time, MMSI or\n"
           "position are skipped and counted.  The file is streamed, never loaded whole.\n"
           "\n"
           "  summary  rows read, kept and skipped by reason, ships by class and type,\n"
           "           the time span\n"
           "  tracks   the reports as a track file (t_s,id,east_m,north_m,course_deg,\n"
           "           speed_kn,type,length_m,breadth_m; ids the MMSIs) in the plane\n"
           "           about --origin, t = 0 the window's start: the layout traffic.tracks\n"
           "           replays (to stdout without --out)\n"
           "  demand   each ship's passes matched to the routes (streams) of a network\n"
           "           placed at --origin, written as that network's demand.yaml: ships\n"
           "           per hour per route, split by ship type onto the network's vTypes\n"
           "           (nearest length and service speed within the type)\n"
           "\n"
           "  --origin LAT,LON  the plane's centre (deg): the scenario's origin, or where\n"
           "                    the network's (0, 0) lies; not with a geo-referenced\n"
           "                    network (networks/README.md), whose own plane is used\n"
           "  --columns MAP     header names for another CSV: FIELD=NAME,... with FIELD\n"
           "                    one of time class mmsi lat lon sog cog heading type width\n"
           "                    length a b c d (\"class=\": no class column)\n"
           "  --start T         window start: \"YYYY-MM-DD HH:MM:SS\" (UTC) or seconds\n"
           "                    after the first report (default: the first report)\n"
           "  --end T           window end, the same way (default: the last report)\n"
           "  --max-gap S       reports farther apart are two passes (tracks: 300 s,\n"
           "                    demand: 1800 s)\n"
           "  --network NAME    the network whose routes the demand is for\n"
           "  --tolerance NM    a pass matches a route within this mean distance (1 nm)\n"
           "  --out FILE        the file written (under a temporary name, then renamed)\n"
           "\n"
           "Exit codes: 0 ok, 1 a read failed, 2 bad input (FILE:LINE: FIELD for a header\n"
           "the reader cannot use).\n");
}

typedef struct ais_opts {
    const char *file, *out, *columns, *start, *end, *network;
    double origin[2], max_gap, tolerance_nm;
    int n_origin;
    bool has_gap;
    fw_ais_columns cols;
} ais_opts;

/* "YYYY-MM-DD HH:MM:SS" or seconds after the first report. */
static fw_status window_opt(const char *opt, const char *text, double *t, bool *rel,
                            fw_error *err)
{
    if (!text)
        return FW_OK;
    if (fw_ais_parse_time(text, t)) {
        *rel = false;
        return FW_OK;
    }
    *rel = true;
    if (fw_parse_double(opt, text, t, err) || *t < 0)
        return fw_fail(err, FW_EINPUT, "%s '%s': expected \"YYYY-MM-DD HH:MM:SS\" (UTC) or "
                                       "seconds (>= 0) after the first report", opt, text);
    return FW_OK;
}

/* proj: a geo-referenced network's plane (NULL: --origin's). */
static fw_status track_def(const ais_opts *o, double gap, const char *proj, const double off[2],
                           fw_ais_track_def *d, fw_error *err)
{
    *d = fw_default_ais_track_def();
    if (proj && o->n_origin)
        return fw_fail(err, FW_EINPUT, "--origin: network '%s' is geo-referenced (%s): its plane "
                                       "is used; leave --origin out", o->network, proj);
    if (proj) {
        d->proj = proj;
        d->off_e = off[0];
        d->off_n = off[1];
    } else if (o->n_origin != 2) {
        return fw_fail(err, FW_EINPUT, "--origin LAT,LON: the plane's centre is needed");
    }
    d->origin_lat = o->origin[0];
    d->origin_lon = o->origin[1];
    d->cols = &o->cols;
    d->max_gap = o->has_gap ? o->max_gap : gap;
    if (!(d->max_gap > 0 && d->max_gap <= 86400))
        return fw_fail(err, FW_EINPUT, "--max-gap %.15g: give 0 to 86400 s", d->max_gap);
    fw_status st;
    if ((st = window_opt("--start", o->start, &d->start, &d->start_rel, err)) ||
        (st = window_opt("--end", o->end, &d->end, &d->end_rel, err)))
        return st;
    return FW_OK;
}

/* summary: the reader's counts, ships by class and kind. */
static int summary(const ais_opts *o, fw_error *err)
{
    fw_ais_reader *rd;
    if (fw_ais_open(o->file, &o->cols, &rd, err))
        return fw_report(err);
    fw_idmap ids = {0};
    unsigned char *seen = NULL; /* per ship: class B bit 0x80, kind below */
    int cap = 0;
    fw_ais_report r;
    bool got = true;
    fw_status st = FW_OK;
    while (!st && got && !(st = fw_ais_next(rd, &r, &got, err)) && got) {
        char id[24];
        int k;
        snprintf(id, sizeof id, "%ld", r.mmsi);
        if (fw_idmap_intern(&ids, id, &k) != 0 ||
            (k >= cap && !fw_resize((void **)&seen, 1, (size_t)(cap = fw_grown_cap(cap, k + 1)))))
            st = fw_fail(err, FW_ERUN, "out of memory");
        else if (k < cap)
            seen[k] = (unsigned char)((r.class_b ? 0x80 : 0) |
                                      (r.kind != FW_AIS_UNKNOWN ? r.kind : seen[k] & 0x7f));
    }
    if (!st) {
        printf("file: %s\n", o->file);
        fw_ais_print_counts(stdout, fw_ais_counts_of(rd));
        int by_kind[FW_AIS_NKINDS] = {0}, nb = 0;
        for (int k = 0; k < ids.n; k++) {
            nb += (seen[k] & 0x80) != 0;
            by_kind[seen[k] & 0x7f]++;
        }
        printf("ships: %d (Class A %d, Class B %d)\n", ids.n, ids.n - nb, nb);
        for (int k = 0; k < FW_AIS_NKINDS; k++)
            if (by_kind[k])
                printf("ships, %s: %d\n", fw_ais_kind_name((fw_ais_kind)k), by_kind[k]);
    }
    free(seen);
    fw_idmap_free(&ids);
    fw_ais_close(rd);
    return st ? fw_report(err) : 0;
}

static int tracks(const ais_opts *o, fw_error *err)
{
    fw_ais_track_def d;
    fw_ais_tracks t;
    if (track_def(o, 300.0, NULL, NULL, &d, err) ||
        (o->out && fw_check_out_file("--out", o->out, true, err)))
        return fw_report(err);
    fw_status st = fw_ais_tracks_load(o->file, &d, &t, err);
    if (!st)
        st = o->out ? fw_ais_tracks_write_csv(&t, o->out, err)
                    : fw_ais_tracks_print_csv(&t, stdout, err);
    if (!st)
        fw_ais_tracks_print(stderr, &t);
    fw_ais_tracks_free(&t);
    return st ? fw_report(err) : 0;
}

static int demand(const ais_opts *o, fw_error *err)
{
    fw_ais_track_def d;
    if (!o->network || !o->out)
        return fw_report((fw_fail(err, FW_EINPUT, "ais demand: give --network NAME and --out "
                                                  "FILE (see fairway ais --help)"), err));
    /* on a geo-referenced network the reports go into the network's own plane */
    fw_network_files nf;
    char proj[512] = "";
    double off[2] = {0.0, 0.0};
    if (fw_network_find(o->network, &nf, err) ||
        fw_network_plane(&nf, proj, sizeof proj, &off[0], &off[1], err))
        return fw_report(err);
    if (track_def(o, 1800.0, proj[0] ? proj : NULL, off, &d, err) ||
        fw_check_out_file("--out", o->out, true, err))
        return fw_report(err);
    fw_ais_demand_def dd = fw_default_ais_demand_def();
    dd.network = o->network;
    dd.tolerance = fw_nm_to_m(o->tolerance_nm);
    if (!(dd.tolerance > 0))
        return fw_report((fw_fail(err, FW_EINPUT, "--tolerance %.15g: must be > 0 nm",
                                  o->tolerance_nm), err));
    fw_ais_tracks t;
    fw_ais_demand_result res;
    fw_status st = fw_ais_tracks_load(o->file, &d, &t, err);
    if (!st)
        st = fw_ais_demand_write(&t, &dd, o->out, &res, err);
    if (!st) {
        printf("passes: %d, matched %d, unmatched %d, in %.3f h\n", res.n_passes, res.n_matched,
               res.n_passes - res.n_matched, res.hours);
        for (int i = 0; i < res.n_routes; i++)
            printf("route %s: %d passes, %.3f per hour\n", res.route[i], res.passes[i],
                   res.passes[i] / res.hours);
        printf("wrote %s\n", o->out);
    }
    fw_ais_tracks_free(&t);
    return st ? fw_report(err) : 0;
}

int fw_cmd_ais(int argc, char **argv)
{
    fw_error err = {0};
    if (argc < 1 || fw_is_help(argv[0])) {
        help();
        return argc < 1 ? 2 : 0;
    }
    const char *sub = argv[0];
    ais_opts o = {.tolerance_nm = 1.0};
    const fw_opt opts[] = {
        FW_OPT_LISTOF("--origin", o.origin, 2, &o.n_origin),
        FW_OPT("--columns", FW_OPT_TEXT, &o.columns),
        FW_OPT("--out", FW_OPT_TEXT, &o.out),
        FW_OPT("--start", FW_OPT_TEXT, &o.start),
        FW_OPT("--end", FW_OPT_TEXT, &o.end),
        FW_OPT_SEEN("--max-gap", FW_OPT_DOUBLE, &o.max_gap, &o.has_gap),
        FW_OPT("--network", FW_OPT_TEXT, &o.network),
        FW_OPT("--tolerance", FW_OPT_DOUBLE, &o.tolerance_nm),
        FW_OPT_END,
    };
    int rc = fw_args_parse(argc - 1, argv + 1, "ais", opts, help, fw_args_one_file, &o.file,
                           &err);
    if (rc >= 0)
        return rc;
    if (!o.file)
        return fw_report((fw_fail(&err, FW_EINPUT, "ais %s: no AIS file given (see fairway ais "
                                                   "--help)", sub), &err));
    o.cols = fw_ais_dma_columns();
    if (o.columns && fw_ais_columns_parse(o.columns, "--columns", &o.cols, &err))
        return fw_report(&err);
    if (strcmp(sub, "summary") == 0)
        return summary(&o, &err);
    if (strcmp(sub, "tracks") == 0)
        return tracks(&o, &err);
    if (strcmp(sub, "demand") == 0)
        return demand(&o, &err);
    return fw_report((fw_fail(&err, FW_EINPUT, "ais: '%s': expected summary, tracks or demand",
                              sub), &err));
}
