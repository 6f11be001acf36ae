/* libFuzzer target: AIS CSV files (ais/ais.h) read row by row, and the same
 * file as tracks (ais/ais_track.h) replayed for a few steps.  The first byte
 * picks the variant: bit 0 a column map without a class column (another
 * CSV's layout), bit 1 a window relative to the first report, bit 2 a short
 * max_gap.  Every row must be counted once: kept or skipped for a reason. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "ais/ais_track.h"
#include "fuzz_common.h"

static void read_rows(const char *path, const fw_ais_columns *cols)
{
    fw_ais_reader *rd;
    fw_error err = {0};
    if (fw_ais_open(path, cols, &rd, &err) != FW_OK)
        return;
    fw_ais_report r;
    bool got = true;
    while (got && fw_ais_next(rd, &r, &got, &err) == FW_OK)
        if (got && (!(fabs(r.lat) <= 90) || !(fabs(r.lon) <= 180) || !(r.sog >= 0 || isnan(r.sog))))
            __builtin_trap(); /* a kept report is within range */
    const fw_ais_counts *c = fw_ais_counts_of(rd);
    long sum = c->kept;
    for (int k = 0; k < FW_AIS_NSKIP; k++)
        sum += c->skipped[k];
    if (sum != c->rows || c->class_a + c->class_b != c->kept)
        __builtin_trap();
    fw_ais_close(rd);
}

static void replay(const char *path, const fw_ais_columns *cols, uint8_t mode)
{
    fw_ais_track_def d = fw_default_ais_track_def();
    d.origin_lat = 56.5;
    d.origin_lon = 11.5;
    d.cols = cols;
    if (mode & 2) {
        d.start = 5;
        d.end = 120;
        d.start_rel = d.end_rel = true;
    }
    if (mode & 4)
        d.max_gap = 2;
    fw_ais_tracks t;
    fw_error err = {0};
    if (fw_ais_tracks_load(path, &d, &t, &err) == FW_OK) {
        fw_replay_def rd = fw_default_replay_def();
        rd.max_gap = d.max_gap;
        fw_source *s = NULL;
        if (fw_ais_replay_source_create(&t, &rd, &s, &err) == FW_OK) {
            fw_target own = {.id = "own"};
            const fw_target *v;
            int n;
            fw_source_place(s, &own, &err);
            for (int k = 0; k < 5; k++) {
                fw_source_around(s, &v, &n, &err);
                for (int i = 0; i < n; i++)
                    if (!isfinite(v[i].east) || !isfinite(v[i].north) || !(v[i].speed >= 0))
                        __builtin_trap();
                fw_source_advance(s, &err);
            }
            fw_source_destroy(s);
        }
    }
    fw_ais_tracks_free(&t);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    uint8_t mode = data[0];
    const char *path = fuzz_write_input("ais-in", data + 1, size - 1);
    fw_ais_columns map, *cols = NULL;
    if (mode & 1) {
        fw_error err = {0};
        if (fw_ais_columns_parse("time=BaseDateTime,lat=LAT,lon=LON,type=VesselType,class=",
                                 "fuzz", &map, &err) != FW_OK)
            __builtin_trap();
        cols = &map;
    }
    read_rows(path, cols);
    replay(path, cols, mode);
    return 0;
}
