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

#include "core/files.h"
#include "core/units.h"
#include "geom/geo.h"
#include "scenario/scenario.h"
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

int main(void)
{
    TEST_RUN(test_plane_against_the_ellipsoid);
    TEST_RUN(test_twin_scenario);
    return TEST_EXIT();
}
