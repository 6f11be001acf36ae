/* test_geo.c - latitude/longitude and the local plane (geom/geo.h), and a
 * scenario placed in degrees against its twin in metres.
 *
 * Reference values: on the WGS84 ellipsoid (a = 6378137 m, e^2 =
 * 0.00669438) the meridian radius at 51 deg N is M = a (1 - e^2) / (1 - e^2
 * sin^2)^1.5 = 6374056 m and the radius of the parallel N cos = 4022037 m, so
 * 0.01 deg of latitude is 1112.49 m and 0.01 deg of longitude 701.98 m; the
 * meridian convergence 0.3 deg east of the central meridian is about
 * dlon sin(lat) = 0.2331 deg. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/files.h"
#include "core/units.h"
#include "geom/geo.h"
#include "scenario/scenario.h"
#include "traffic/demand.h"
#include "test.h"

static void test_plane_against_the_ellipsoid(void)
{
    fw_geo *g = NULL;
    fw_error err = {0};
    CHECK_MSG(fw_geo_create(51.0, 1.5, &g, &err) == FW_OK, "%s", err.msg);
    if (!g)
        return;
    double e, n, lat, lon, gamma;
    CHECK(fw_geo_to_plane(g, 51.0, 1.5, &e, &n, &err) == FW_OK);
    CHECK_NEAR(e, 0.0, 1e-6);
    CHECK_NEAR(n, 0.0, 1e-6);
    CHECK(fw_geo_to_plane(g, 51.01, 1.5, &e, &n, &err) == FW_OK);
    CHECK_NEAR(e, 0.0, 1e-6);
    CHECK_NEAR(n, 1112.49, 0.1);
    CHECK(fw_geo_to_plane(g, 51.0, 1.51, &e, &n, &err) == FW_OK);
    CHECK_NEAR(e, 701.98, 0.1);
    CHECK(fw_geo_convergence(g, 51.0, 1.8, &gamma, &err) == FW_OK);
    CHECK_NEAR(fw_rad_to_deg(gamma), 0.3 * sin(fw_deg_to_rad(51.0)), 0.002);
    /* at the pole, one-sided (a step past it was refused as "latitude 90.0001",
     * a number not in the file): gamma = dlon sin(90 deg) */
    CHECK_MSG(fw_geo_convergence(g, 90.0, 1.8, &gamma, &err) == FW_OK, "%s", err.msg);
    CHECK_NEAR(fw_rad_to_deg(gamma), 0.3, 0.002);
    CHECK(fw_geo_convergence(g, -90.0, 1.8, &gamma, &err) == FW_OK);
    CHECK_NEAR(fw_rad_to_deg(gamma), -0.3, 0.002);
    /* round trip 30 km out: a millionth of a metre */
    CHECK(fw_geo_to_latlon(g, 30000.0, -20000.0, &lat, &lon, &err) == FW_OK);
    CHECK(fw_geo_to_plane(g, lat, lon, &e, &n, &err) == FW_OK);
    CHECK_NEAR(e, 30000.0, 1e-6);
    CHECK_NEAR(n, -20000.0, 1e-6);
    fw_geo_destroy(g);
    /* no plane at the poles */
    CHECK(fw_geo_create(85.0, 0.0, &g, &err) == FW_EINPUT);
}

static fw_scenario *load(const char *path)
{
    fw_scenario *s = calloc(1, sizeof *s);
    fw_error err = {0};
    if (s && fw_scenario_load(path, s, &err)) {
        CHECK_MSG(0, "%s", err.msg);
        free(s);
        return NULL;
    }
    return s;
}

/* tests/data/geo_twin.yaml is the paper's case 3 with every position in
 * degrees about an origin in the Dover Strait: loaded, it is its metre twin
 * to 0.1 m and its courses are the same grid courses.  FAIRWAY_WRITE_TWIN=1
 * writes the file from the metre case instead (through fw_geo, the code
 * under test, which the ellipsoid test above holds to the reference). */
static void test_twin_scenario(void)
{
    char metric[1200], twin[1200];
    snprintf(metric, sizeof metric, "%s/scenarios/paper/3-crossing.yaml", fw_data_root());
    snprintf(twin, sizeof twin, "%s/tests/data/geo_twin.yaml", fw_data_root());
    fw_scenario *m = load(metric);
    if (!m)
        return;
    const double lat0 = 51.05, lon0 = 1.45;
    if (getenv("FAIRWAY_WRITE_TWIN")) {
        fw_geo *g = NULL;
        fw_error err = {0};
        CHECK(fw_geo_create(lat0, lon0, &g, &err) == FW_OK);
        FILE *in = fopen(metric, "r"), *out = fopen(twin, "w");
        CHECK(in && out && g);
        double la[2], lo[2], ga[2];
        fw_geo_to_latlon(g, m->east, m->north, &la[0], &lo[0], &err);
        fw_geo_to_latlon(g, m->targets[0].east, m->targets[0].north, &la[1], &lo[1], &err);
        fw_geo_convergence(g, la[0], lo[0], &ga[0], &err);
        fw_geo_convergence(g, la[1], lo[1], &ga[1], &err);
        fprintf(out, "# The paper's case 3 placed by latitude and longitude (tests/test_geo.c\n"
                     "# writes it from scenarios/paper/3-crossing.yaml; its twin in metres).\n"
                     "name: geo-twin\norigin: {lat_deg: %.2f, lon_deg: %.2f}\n", lat0, lon0);
        char line[1024];
        while (in && out && fgets(line, sizeof line, in)) {
            if (line[0] == '#' || strncmp(line, "name:", 5) == 0)
                continue;
            if (strncmp(line, "  east_m:", 9) == 0)
                fprintf(out, "  lat_deg: %.9f\n  lon_deg: %.9f\n", la[0], lo[0]);
            else if (strncmp(line, "  north_m:", 10) == 0)
                continue;
            else if (strncmp(line, "  course_deg:", 13) == 0)
                fprintf(out, "  course_deg: %.9f   # true; the grid course is 0\n",
                        fw_rad_to_deg(fw_wrap_2pi(m->course + ga[0])));
            else if (strstr(line, "{id: T1"))
                fprintf(out, "    - {id: T1, type: cargo, lat_deg: %.9f, lon_deg: %.9f, course_deg: "
                             "%.9f, speed_kn: 10, length_m: 200, breadth_m: 32}\n",
                        la[1], lo[1], fw_rad_to_deg(fw_wrap_2pi(m->targets[0].course + ga[1])));
            else
                fputs(line, out);
        }
        if (in)
            fclose(in);
        if (out)
            fclose(out);
        fw_geo_destroy(g);
    }
    fw_scenario *t = load(twin);
    if (t) {
        CHECK(t->has_origin && t->origin_lat == lat0 && t->origin_lon == lon0);
        CHECK_NEAR(t->east, m->east, 0.1);
        CHECK_NEAR(t->north, m->north, 0.1);
        CHECK_NEAR(fw_wrap_pi(t->course - m->course), 0.0, 1e-6);
        CHECK(t->n_targets == 1);
        CHECK_NEAR(t->targets[0].east, m->targets[0].east, 0.1);
        CHECK_NEAR(t->targets[0].north, m->targets[0].north, 0.1);
        CHECK_NEAR(fw_wrap_pi(t->targets[0].course - m->targets[0].course), 0.0, 1e-6);
        printf("  twin: own %.4f, %.4f m, T1 %.4f, %.4f m (metric 0, 0 and 2000, 2000)\n", t->east,
               t->north, t->targets[0].east, t->targets[0].north);
    }
    free(t);
    free(m);
}

/* A plane from a PROJ string and an offset (a geo-referenced SUMO network's
 * projParameter and netOffset) is the string's plane shifted: against the
 * transverse Mercator checked above. */
static void test_plane_from_a_network(void)
{
    fw_error err = {0};
    fw_geo *tm = NULL, *net = NULL;
    CHECK(fw_geo_create(51.05, 1.45, &tm, &err) == FW_OK);
    CHECK(fw_geo_create_proj(fw_geo_proj_string(tm), 100.0, -50.0, &net, &err) == FW_OK);
    if (!tm || !net) {
        fw_geo_destroy(tm);
        fw_geo_destroy(net);
        return;
    }
    double e0, n0, e1, n1, lat, lon, g0, g1;
    CHECK(fw_geo_to_plane(tm, 51.1, 1.6, &e0, &n0, &err) == FW_OK);
    CHECK(fw_geo_to_plane(net, 51.1, 1.6, &e1, &n1, &err) == FW_OK);
    CHECK_NEAR(e1 - e0, 100.0, 1e-6);
    CHECK_NEAR(n1 - n0, -50.0, 1e-6);
    CHECK(fw_geo_to_latlon(net, e1, n1, &lat, &lon, &err) == FW_OK);
    CHECK_NEAR(lat, 51.1, 1e-10);
    CHECK_NEAR(lon, 1.6, 1e-10);
    CHECK(fw_geo_convergence(tm, 51.1, 1.6, &g0, &err) == FW_OK);
    CHECK(fw_geo_convergence(net, 51.1, 1.6, &g1, &err) == FW_OK);
    CHECK_NEAR(g1, g0, 1e-12);
    /* the origin is where the plane's (0, 0) is: the tmerc's (-100, 50) */
    fw_geo_origin(net, &lat, &lon);
    CHECK(fw_geo_to_plane(tm, lat, lon, &e0, &n0, &err) == FW_OK);
    CHECK_NEAR(e0, -100.0, 1e-6);
    CHECK_NEAR(n0, 50.0, 1e-6);
    fw_geo_destroy(net);
    CHECK(fw_geo_create_proj("+proj=nonsense", 0, 0, &net, &err) == FW_EINPUT);
    CHECK(net == NULL);
    fw_geo_destroy(tm);
}

/* SUMO's x, y of a junction in the built net.xml. */
static bool junction_xy(const char *net, const char *id, double *x, double *y)
{
    FILE *f = fopen(net, "rb");
    char buf[1 << 16], key[64];
    size_t got = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
    if (f)
        fclose(f);
    buf[got] = '\0';
    snprintf(key, sizeof key, "<junction id=\"%s\"", id);
    const char *j = strstr(buf, key), *px = j ? strstr(j, " x=\"") : NULL,
               *py = j ? strstr(j, " y=\"") : NULL;
    return px && py && sscanf(px + 4, "%lf", x) == 1 && sscanf(py + 4, "%lf", y) == 1;
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* A scenario on the geo-referenced network geo-channel (nodes in degrees,
 * projected by netconvert) is in the network's plane: the own ship placed on
 * the W node's latitude and longitude lands on SUMO's junction W (to the
 * net.xml's 0.01 m); an origin of its own is refused, explicit targets are in
 * the plane. */
static void test_geo_network(void)
{
    static const char body[] =
        "own_ship: {ship: c3-mmg, lat_deg: 57.0, lon_deg: 11.335065, course_deg: 90, "
        "speed_kn: 12, leg_nm: 5}\n"
        "run: {duration_s: 60}\n";
    char dir[] = "/tmp/fw_geonet_XXXXXX", path[128], text[1024], net[1200];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/s.yaml", dir);
    snprintf(text, sizeof text, "name: geo-net\ntraffic: {network: geo-channel}\n%s", body);
    write_file(path, text);
    fw_scenario *s = load(path);
    double x = NAN, y = NAN;
    fw_network_files nf;
    CHECK(fw_network_find("geo-channel", &nf, NULL) == FW_OK);
    snprintf(net, sizeof net, "%s", nf.net);
    CHECK(junction_xy(net, "W", &x, &y));
    if (s) {
        CHECK(s->has_origin);
        CHECK(strstr(s->plane, "+proj=tmerc +lat_0=57 +lon_0=11.5") == s->plane);
        CHECK_NEAR(s->east, x, 0.006);
        CHECK_NEAR(s->north, y, 0.006);
        CHECK_NEAR(s->origin_lat, 57.0, 1e-9);
        CHECK_NEAR(s->origin_lon, 11.5, 1e-9);
        printf("  geo-channel: own ship at %.3f, %.3f m, SUMO's junction W at %.2f, %.2f\n",
               s->east, s->north, x, y);
    }
    free(s);
    fw_scenario *r = calloc(1, sizeof *r);
    fw_error err = {0};
    snprintf(text, sizeof text, "name: geo-net\norigin: {lat_deg: 57, lon_deg: 11.5}\n"
                                "traffic: {network: geo-channel}\n%s", body);
    write_file(path, text);
    CHECK(r && fw_scenario_load(path, r, &err) == FW_EINPUT);
    CHECK(strstr(err.msg, "s.yaml:2: origin: network 'geo-channel' is geo-referenced") != NULL);
    snprintf(text, sizeof text, "name: geo-net\ntraffic:\n  network: geo-channel\n  targets:\n"
                                "    - {id: T1, east_m: 0, north_m: 3000, course_deg: 180, "
                                "speed_kn: 10, length_m: 150, breadth_m: 25}\n%s", body);
    write_file(path, text);
    memset(&err, 0, sizeof err);
    /* explicit targets are in the network's plane too (their runs:
     * tests/scripts/geo_targets.sh) */
    CHECK_MSG(r && fw_scenario_load(path, r, &err) == FW_OK, "%s", err.msg);
    if (r && r->n_targets == 1) {
        CHECK_NEAR(r->targets[0].east, 0.0, 1e-9);
        CHECK_NEAR(r->targets[0].north, 3000.0, 1e-9);
    }
    free(r);
    remove(path);
    rmdir(dir);
}

int main(void)
{
    TEST_RUN(test_plane_against_the_ellipsoid);
    TEST_RUN(test_twin_scenario);
    TEST_RUN(test_plane_from_a_network);
    TEST_RUN(test_geo_network);
    return TEST_EXIT();
}
