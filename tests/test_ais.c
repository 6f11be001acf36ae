/* test_ais.c - the AIS reader (ais/ais.h) and its tracks (ais/ais_track.h):
 * every kind of bad row counted by reason with the good rows' values, a line
 * too long, a column map for another CSV, fatal header errors naming
 * FILE:LINE, and the tracks' duplicates, order and filled-in motion. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "ais/ais.h"
#include "ais/ais_track.h"
#include "core/units.h"
#include "geom/geo.h"
#include "test.h"

static char bad_rows[1024];

/* All kept reports of path (at most max) and the reader's counts. */
static int read_all(const char *path, const fw_ais_columns *cols, fw_ais_report *r, int max,
                    fw_ais_counts *c, fw_error *err)
{
    fw_ais_reader *rd;
    if (fw_ais_open(path, cols, &rd, err))
        return -1;
    int n = 0;
    bool got = true;
    fw_ais_report tmp;
    while (got && fw_ais_next(rd, n < max ? &r[n] : &tmp, &got, err) == FW_OK)
        n += got;
    *c = *fw_ais_counts_of(rd);
    fw_ais_close(rd);
    return n;
}

static void test_bad_rows(void)
{
    fw_ais_report r[16];
    fw_ais_counts c;
    fw_error err = {0};
    int n = read_all(bad_rows, NULL, r, 16, &c, &err);
    CHECK_MSG(n == 6, "%d reports: %s", n, err.msg);
    if (n != 6)
        return;
    CHECK(c.rows == 18 && c.kept == 6);
    CHECK(c.skipped[FW_AIS_SKIP_NOT_SHIP] == 3); /* base station, AtoN, SAR aircraft */
    CHECK(c.skipped[FW_AIS_SKIP_BROKEN] == 2);   /* too few fields, an unterminated quote */
    CHECK(c.skipped[FW_AIS_SKIP_TIME] == 2);     /* 32/03, empty */
    CHECK(c.skipped[FW_AIS_SKIP_MMSI] == 2);     /* Unknown, 2190000x4 */
    CHECK(c.skipped[FW_AIS_SKIP_POSITION] == 3); /* 91/181, empty, Unknown */
    CHECK(c.class_a == 5 && c.class_b == 1 && c.no_sog == 1 && c.no_cog == 1);
    double t0;
    CHECK(fw_ais_parse_time("2026-03-01 12:00:00", &t0));
    CHECK_NEAR(t0, 1772366400.0, 0.0); /* date -u -d '2026-03-01 12:00:00' +%s */
    CHECK_NEAR(c.t_first, t0, 0.0);
    CHECK_NEAR(c.t_last, t0 + 30, 0.0);
    /* line 2: CRLF, a quoted name and destination with commas in them */
    CHECK(r[0].line == 2 && r[0].mmsi == 219000001 && !r[0].class_b);
    CHECK_NEAR(r[0].t, t0, 0.0);
    CHECK_NEAR(r[0].lat, 55.0, 0.0);
    CHECK_NEAR(r[0].lon, 11.0, 0.0);
    CHECK_NEAR(r[0].sog, fw_kn_to_ms(12.0), 1e-12);
    CHECK_NEAR(r[0].cog, fw_deg_to_rad(90.0), 1e-12);
    CHECK_NEAR(r[0].heading, fw_deg_to_rad(91.0), 1e-12);
    CHECK(r[0].kind == FW_AIS_CARGO && r[0].length == 120.0 && r[0].breadth == 20.0);
    CHECK(r[1].line == 3 && isnan(r[1].heading)); /* 511 */
    /* Class B without COG nor A-D: Length and Width */
    CHECK(r[2].line == 4 && r[2].class_b && isnan(r[2].cog) && r[2].kind == FW_AIS_PLEASURE);
    CHECK(r[2].length == 10.0 && r[2].breadth == 3.0);
    CHECK(r[3].line == 18 && r[4].line == 19); /* the duplicate and the out-of-order row */
    /* ISO time, SOG Unknown, "" inside quotes, A+B and C+D */
    CHECK(r[5].line == 20 && r[5].mmsi == 219000006 && isnan(r[5].sog));
    CHECK_NEAR(r[5].t, t0 + 30, 0.0);
    CHECK(r[5].kind == FW_AIS_TANKER && r[5].length == 180.0 && r[5].breadth == 40.0);
}

static void test_long_line(void)
{
    char path[] = "/tmp/fw_ais_long_XXXXXX";
    int fd = mkstemp(path);
    FILE *f = fdopen(fd, "w");
    fputs("Timestamp,MMSI,Latitude,Longitude\n", f);
    for (int i = 0; i < 70000; i++)
        fputc('9', f);
    fputs(",1,2,3\n2026-03-01 12:00:00,219000001,55,11\n", f);
    fclose(f);
    fw_ais_report r[2];
    fw_ais_counts c;
    fw_error err = {0};
    int n = read_all(path, NULL, r, 2, &c, &err);
    CHECK_MSG(n == 1 && c.skipped[FW_AIS_SKIP_BROKEN] == 1 && r[0].line == 3, "%d %s", n,
              err.msg);
    unlink(path);
}

/* A byte order mark before "# Timestamp" (as an editor saves the file) is
 * skipped; a directory named as the file is said to be one (its read failed
 * with EISDIR, which looked like an empty file). */
static void test_bom_and_directory(void)
{
    char path[] = "/tmp/fw_ais_bom_XXXXXX";
    int fd = mkstemp(path);
    FILE *f = fdopen(fd, "w");
    fputs("\xEF\xBB\xBF# Timestamp,Type of mobile,MMSI,Latitude,Longitude\n"
          "01/03/2026 12:00:00,Class A,219000001,55.0,11.0\n",
          f);
    fclose(f);
    fw_ais_report r[2];
    fw_ais_counts c;
    fw_error err = {0};
    int n = read_all(path, NULL, r, 2, &c, &err);
    CHECK_MSG(n == 1 && r[0].mmsi == 219000001 && r[0].line == 2, "%d: %s", n, err.msg);
    unlink(path);
    char dir[] = "/tmp/fw_ais_dir_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    CHECK(read_all(dir, NULL, r, 2, &c, &err) < 0 && err.status == FW_EINPUT);
    char want[64];
    snprintf(want, sizeof want, "%s: is a directory", dir);
    CHECK_CONTAINS(err.msg, want);
    rmdir(dir);
}

/* Another layout (US MarineCadastre-like): mapped columns, type codes, no
 * class column (the MMSI says what is a ship). */
static void test_columns(void)
{
    char path[] = "/tmp/fw_ais_cols_XXXXXX";
    int fd = mkstemp(path);
    FILE *f = fdopen(fd, "w");
    fputs("MMSI,BaseDateTime,LAT,LON,SOG,COG,Heading,VesselType,Length,Width\n"
          "367000001,2026-03-01T12:00:00,40.5,-73.9,10.5,180.0,511,70,200,32\n"
          "3669999,2026-03-01T12:00:00,40.5,-73.9,0,0,0,0,0,0\n"
          "367000002,2026-03-01T12:00:01,40.6,-73.8,3.0,360.0,511,52,30,10\n",
          f);
    fclose(f);
    fw_ais_columns cols;
    fw_error err = {0};
    CHECK(fw_ais_columns_parse("time=BaseDateTime,lat=LAT,lon=LON,type=VesselType,class=",
                               "--columns", &cols, &err) == FW_OK);
    fw_ais_report r[4];
    fw_ais_counts c;
    int n = read_all(path, &cols, r, 4, &c, &err);
    CHECK_MSG(n == 2, "%d: %s", n, err.msg);
    CHECK(c.skipped[FW_AIS_SKIP_NOT_SHIP] == 1); /* 7 digits: a base station */
    if (n == 2) {
        CHECK(r[0].kind == FW_AIS_CARGO && r[0].type_code == 70 && r[0].length == 200.0);
        CHECK(r[1].kind == FW_AIS_SERVICE && isnan(r[1].cog)); /* 360: not available */
    }
    /* DMA names against this header: no Timestamp column, fatal at line 1 */
    CHECK(read_all(path, NULL, r, 4, &c, &err) < 0 && err.status == FW_EINPUT);
    CHECK_CONTAINS(err.msg, ":1: header: no column 'Timestamp'");
    CHECK(fw_ais_columns_parse("time=X,speed=SOG", "--columns", &cols, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "--columns: 'speed=SOG': expected FIELD=HEADER NAME");
    unlink(path);
    CHECK(read_all("/nonexistent/aisdk.csv", NULL, r, 4, &c, &err) < 0 &&
          err.status == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "/nonexistent/aisdk.csv: cannot open");
}

static void test_times(void)
{
    double t;
    CHECK(fw_ais_parse_time("29/02/2024 23:59:59", &t));
    char buf[32];
    fw_ais_format_time(t, buf, sizeof buf);
    CHECK(strcmp(buf, "2024-02-29 23:59:59") == 0);
    CHECK(!fw_ais_parse_time("29/02/2023 00:00:00", &t)); /* not a leap year */
    CHECK(!fw_ais_parse_time("01/03/2026 24:00:00", &t));
    CHECK(!fw_ais_parse_time("01/03-2026 12:00:00", &t));
    CHECK(!fw_ais_parse_time("01/03/2026 12:00:00 x", &t));
}

static void test_tracks(void)
{
    fw_ais_track_def d = fw_default_ais_track_def();
    d.origin_lat = 55.0;
    d.origin_lon = 11.0;
    fw_ais_tracks t;
    fw_error err = {0};
    fw_status st = fw_ais_tracks_load(bad_rows, &d, &t, &err);
    CHECK_MSG(st == FW_OK, "%s", err.msg);
    CHECK(t.n == 3 && t.duplicates == 1 && t.out_of_order == 1 && t.points == 5);
    if (t.n == 3) {
        const fw_rec_track *a = &t.v[0];
        CHECK(strcmp(a->info.id, "219000001") == 0 && strcmp(a->info.type, "cargo") == 0);
        CHECK(a->n == 3 && a->p[0].t == 0.0 && a->p[1].t == 5.0 && a->p[2].t == 10.0);
        CHECK_NEAR(a->p[0].east, 0.0, 1e-6);
        /* 0.001 deg of longitude at 55 N: 63.9 m (WGS84 radius of the parallel) */
        CHECK_NEAR(a->p[2].east, 63.97, 0.05);
        /* COG 90 true is 90 grid at the central meridian */
        CHECK_NEAR(a->p[0].course, fw_deg_to_rad(90.0), 1e-4);
        /* the Class B ship had no COG and one point: no motion to take it from */
        CHECK(t.v[1].n == 1 && t.v[1].p[0].course == 0.0);
        /* the tanker had no SOG and one point: speed 0 */
        CHECK(t.v[2].n == 1 && t.v[2].p[0].speed == 0.0 && t.v[2].info.length == 180.0);
    }
    fw_ais_tracks_free(&t);
    /* a window that is empty */
    d.start = 100;
    d.end = 50;
    d.start_rel = d.end_rel = true;
    CHECK(fw_ais_tracks_load(bad_rows, &d, &t, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "time window is empty");
    fw_ais_tracks_free(&t);
    /* a window from 12:00:06: ship 1's points before it by up to max_gap are kept */
    d.start = 6;
    d.end = NAN;
    d.max_gap = 3;
    CHECK(fw_ais_tracks_load(bad_rows, &d, &t, &err) == FW_OK);
    CHECK(t.outside_window == 1 && t.points == 4 && t.t0 == 1772366406.0);
    fw_ais_tracks_free(&t);
}

/* A report the plane cannot hold (90 deg of longitude from the origin: PROJ
 * fails) is skipped and counted with FILE:LINE (it stopped the whole read,
 * naming neither); two reports of one MMSI at one instant 5.5 km apart are
 * two ships, counted apart from a mere repeat (both were "duplicates"). */
static void test_unprojected_and_clash(void)
{
    char path[] = "/tmp/fw_ais_clash_XXXXXX";
    int fd = mkstemp(path);
    FILE *f = fdopen(fd, "w");
    fputs("Timestamp,MMSI,Latitude,Longitude\n"
          "2026-03-01 12:00:00,219000001,55.00,11.00\n"
          "2026-03-01 12:00:00,219000001,55.00,11.00\n" /* a repeat */
          "2026-03-01 12:00:10,219000001,55.00,11.01\n"
          "2026-03-01 12:00:05,219000002,0.0,101.0\n" /* line 5: 90 deg east */
          "2026-03-01 12:00:00,219000003,55.02,11.00\n"
          "2026-03-01 12:00:00,219000003,55.07,11.00\n" /* another ship, 5.5 km north */
          "2026-03-01 12:00:06,219000002,0.0,-79.0\n",
          f);
    fclose(f);
    fw_ais_track_def d = fw_default_ais_track_def();
    d.origin_lat = 55.0;
    d.origin_lon = 11.0;
    fw_ais_tracks t;
    fw_error err = {0};
    fw_status st = fw_ais_tracks_load(path, &d, &t, &err);
    CHECK_MSG(st == FW_OK, "%s", err.msg);
    CHECK_MSG(t.unprojected == 2 && t.points == 3 && t.n == 2, "%ld %ld %d", t.unprojected,
              t.points, t.n);
    char want[64];
    snprintf(want, sizeof want, "%s:5", path);
    CHECK_MSG(strcmp(t.unprojected_at, want) == 0, "'%s'", t.unprojected_at);
    CHECK(t.duplicates == 2 && t.clashes == 1 && t.clash_ships == 1 &&
          t.clash_first == 219000003);
    char out[2048] = "";
    FILE *m = fmemopen(out, sizeof out - 1, "w");
    fw_ais_tracks_print(m, &t);
    fclose(m);
    CHECK_CONTAINS(out, "cannot be projected into the plane: 2 (the first at /tmp/fw_ais_clash_");
    CHECK_CONTAINS(out, "two ships on one MMSI (reports at one instant more than 50 m apart, one "
                        "dropped): 1 on 1 MMSIs, the first 219000003");
    fw_ais_tracks_free(&t);
    unlink(path);
}

/* The reports of one ship in the plane, sorted by time (the test's own
 * projection and order: what the replay must reproduce). */
typedef struct ref_pt {
    double t, e, n, sog;
} ref_pt;

static int cmp_ref(const void *a, const void *b)
{
    double x = ((const ref_pt *)a)->t, y = ((const ref_pt *)b)->t;
    return (x > y) - (x < y);
}

static int ref_track(const char *path, long mmsi, double t0, ref_pt *p, int max)
{
    fw_ais_reader *rd;
    fw_geo *g;
    fw_error err = {0};
    if (fw_ais_open(path, NULL, &rd, &err) || fw_geo_create(56.5, 11.5, &g, &err))
        return 0;
    fw_ais_report r;
    bool got = true;
    int n = 0;
    while (fw_ais_next(rd, &r, &got, &err) == FW_OK && got)
        if (r.mmsi == mmsi && n < max && (n == 0 || r.t != p[n - 1].t)) {
            p[n] = (ref_pt){r.t - t0, 0, 0, r.sog};
            fw_geo_to_plane(g, r.lat, r.lon, &p[n].e, &p[n].n, &err);
            n++;
        }
    fw_geo_destroy(g);
    fw_ais_close(rd);
    qsort(p, (size_t)n, sizeof *p, cmp_ref);
    return n;
}

/* The example file replayed at 1 s steps: every ship where the linear
 * interpolation in time of its projected reports puts it (10 m), moving at
 * its reported SOG (5 %), and the tanker and the ferry on the generator's
 * straight lines in the plane (10 m). */
static void test_replay(void)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/scenarios/ais/aisdk-2026-03-01.csv", getenv("FAIRWAY_DATA"));
    fw_ais_track_def d = fw_default_ais_track_def();
    d.origin_lat = 56.5;
    d.origin_lon = 11.5;
    fw_ais_tracks t;
    fw_error err = {0};
    fw_source *src = NULL;
    fw_replay_def rd = fw_default_replay_def();
    rd.max_gap = d.max_gap;
    CHECK_MSG(fw_ais_tracks_load(path, &d, &t, &err) == FW_OK, "%s", err.msg);
    double t0 = t.t0;
    CHECK(t.n == 6 && t.duplicates == 1 && t.out_of_order == 1);
    CHECK(fw_ais_replay_source_create(&t, &rd, &src, &err) == FW_OK);
    fw_ais_tracks_free(&t);
    if (!src)
        return;
    static ref_pt ref[6][400];
    static const long mmsi[6] = {219000101, 219000102, 219000103, 219000104, 219000105,
                                 219000106};
    int nref[6];
    for (int k = 0; k < 6; k++)
        nref[k] = ref_track(path, mmsi[k], t0, ref[k], 400);
    fw_target own = {.id = "own"}, prev[6];
    bool had[6] = {false};
    double worst_pos = 0, worst_speed = 0, worst_line = 0;
    long steps = 0;
    fw_source_place(src, &own, &err);
    for (int step = 0; step <= 2700; step++) {
        const fw_target *v;
        int n;
        CHECK(fw_source_around(src, &v, &n, &err) == FW_OK);
        bool now[6] = {false};
        for (int i = 0; i < n; i++) {
            int k = (int)(atol(v[i].id) - 219000101);
            if (k < 0 || k > 5)
                continue;
            now[k] = true;
            /* the reports around t, and where their interpolation puts the ship */
            const ref_pt *r = ref[k];
            int j = 0;
            while (j + 1 < nref[k] - 1 && r[j + 1].t <= step)
                j++;
            double w = r[j + 1].t > r[j].t ? (step - r[j].t) / (r[j + 1].t - r[j].t) : 0;
            w = w < 0 ? 0 : w > 1 ? 1 : w;
            double e = r[j].e + w * (r[j + 1].e - r[j].e), no = r[j].n + w * (r[j + 1].n - r[j].n);
            double off = hypot(v[i].east - e, v[i].north - no);
            worst_pos = fmax(worst_pos, off);
            if (k == 1) /* the tanker: 13600 m east at 10:00, west at 10 kn, 300 m north */
                worst_line = fmax(worst_line, hypot(v[i].east - (13600 - fw_kn_to_ms(10) * step),
                                                    v[i].north - 300));
            if (k == 2) /* the ferry: from x = 0 at 10:20, east at 18 kn, 500 m south */
                worst_line = fmax(worst_line,
                                  hypot(v[i].east - fw_kn_to_ms(18) * (step - 1200),
                                        v[i].north + 500));
            double sog = isnan(r[j].sog) ? r[j + 1].sog : r[j].sog;
            if (had[k] && sog > 0) {
                double sp = hypot(v[i].east - prev[k].east, v[i].north - prev[k].north) / 1.0;
                worst_speed = fmax(worst_speed, fabs(sp - sog) / sog);
                steps++;
            }
            prev[k] = v[i];
        }
        memcpy(had, now, sizeof had);
        fw_source_advance(src, &err);
    }
    printf("replay: %ld speed samples, worst speed error %.3f %%, worst position %.3f m, "
           "worst off the generator's line %.3f m\n",
           steps, 100 * worst_speed, worst_pos, worst_line);
    CHECK(steps > 10000);
    CHECK_MSG(worst_speed <= 0.05, "%.4f", worst_speed);
    CHECK_MSG(worst_pos <= 10.0, "%.3f m", worst_pos);
    CHECK_MSG(worst_line <= 10.0, "%.3f m", worst_line);
    fw_source_destroy(src);
}

int main(void)
{
    const char *root = getenv("FAIRWAY_DATA");
    snprintf(bad_rows, sizeof bad_rows, "%s/tests/data/ais/bad-rows.csv", root ? root : ".");
    TEST_RUN(test_bad_rows);
    TEST_RUN(test_long_line);
    TEST_RUN(test_bom_and_directory);
    TEST_RUN(test_columns);
    TEST_RUN(test_times);
    TEST_RUN(test_tracks);
    TEST_RUN(test_unprojected_and_clash);
    TEST_RUN(test_replay);
    return TEST_EXIT();
}
