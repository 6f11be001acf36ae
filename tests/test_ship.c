/* Ship files: values as written, derived quantities, and located errors. */
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "core/units.h"
#include "ship/ship.h"
#include "test.h"

static void test_load_c3(void)
{
    fw_error err = {0};
    fw_ship s;
    CHECK_MSG(fw_ship_load("c3", &s, &err) == FW_OK, "%s", err.msg);
    CHECK_NEAR(s.L, 318.2, 0);
    CHECK_NEAR(s.Loa, 333.2, 0);
    CHECK_NEAR(fw_rad_to_deg(s.rudder_rate), 3.0, 1e-12);
    CHECK_NEAR(fw_rad_to_deg(s.rudder_max), 35.0, 1e-12);
    /* volume derived from Cb L B d when the file leaves it out */
    CHECK_REL(s.volume, 0.56 * 318.2 * 42.8 * 6.915, 1e-12);
    CHECK(s.nomoto.present);
    /* equation 10 at 26.7 kn, 35 deg: the reference's worked value */
    CHECK_NEAR(fw_nomoto_index_eval(&s.nomoto.K, 26.7, 35.0), 0.01912, 5e-6);
    CHECK_NEAR(fw_nomoto_index_eval(&s.nomoto.T1, 26.7, 35.0), 18.59, 5e-3);
    CHECK_NEAR(fw_nomoto_index_eval(&s.nomoto.T2, 26.7, 35.0), 63.62, 5e-3);
    CHECK_NEAR(fw_nomoto_index_eval(&s.nomoto.T3, 26.7, 35.0), 100.71, 5e-3);
}

static void test_load_kvlcc2(void)
{
    fw_error err = {0};
    fw_ship m, f;
    CHECK_MSG(fw_ship_load("kvlcc2-l7", &m, &err) == FW_OK, "%s", err.msg);
    CHECK_MSG(fw_ship_load("kvlcc2", &f, &err) == FW_OK, "%s", err.msg);
    CHECK_NEAR(fw_ship_f_alpha(&m), 2.747, 5e-4);
    /* the full-scale file is geometrically similar to the model */
    double lam = f.L / m.L;
    CHECK_REL(f.B, m.B * lam, 1e-4);
    CHECK_REL(f.d, m.d * lam, 1e-4);
    CHECK_REL(f.volume, m.volume * lam * lam * lam, 1e-5);
    CHECK_REL(f.A_R, m.A_R * lam * lam, 1e-5);
    CHECK_REL(f.rudder_rate, m.rudder_rate / sqrt(lam), 1e-4);
    CHECK(!m.nomoto.present);
}

/* Writes c3.yaml with one line replaced (or a line appended) to a temp file. */
static void write_variant(const char *path, const char *find, const char *replace)
{
    char src[600];
    snprintf(src, sizeof src, "%s/scenarios/ships/c3.yaml", fw_data_root());
    FILE *in = fopen(src, "r");
    FILE *out = fopen(path, "w");
    char line[1024];
    while (fgets(line, sizeof line, in)) {
        if (find && strncmp(line, find, strlen(find)) == 0)
            fputs(replace, out);
        else
            fputs(line, out);
    }
    if (!find)
        fputs(replace, out);
    fclose(in);
    fclose(out);
}

/* Line of the first line of c3.yaml starting with find (1-based). */
static int line_of(const char *find)
{
    char src[600], line[1024];
    snprintf(src, sizeof src, "%s/scenarios/ships/c3.yaml", fw_data_root());
    FILE *in = fopen(src, "r");
    int n = 0, found = 0;
    while (!found && fgets(line, sizeof line, in)) {
        n++;
        if (strncmp(line, find, strlen(find)) == 0)
            found = n;
    }
    fclose(in);
    return found;
}

static void expect_error(const char *find, const char *replace, const char *message)
{
    char path[] = "/tmp/fw_ship_XXXXXX.yaml";
    int fd = mkstemps(path, 5);
    close(fd);
    write_variant(path, find, replace);
    fw_error err = {0};
    fw_ship s;
    CHECK(fw_ship_load(path, &s, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, message);
    CHECK_CONTAINS(err.msg, path);
    unlink(path);
}

static void test_errors(void)
{
    char msg[128];
    snprintf(msg, sizeof msg, ":%d: hull.N_r: 'nan' is not a finite number", line_of("  N_r:"));
    expect_error("  N_r:", "  N_r: nan\n", msg);
    expect_error("  N_r:", "  N_r: .nan\n", "hull.N_r: '.nan' is not a number");
    expect_error("  N_r:", "  N_r: abc\n", "hull.N_r: 'abc' is not a number");
    expect_error("  N_r:", "", "hull.N_r: required field is missing");
    snprintf(msg, sizeof msg, ":%d: particulars.B: 4280 is out of range", line_of("  B: 42.8"));
    expect_error("  B: 42.8", "  B: 4280\n", msg);
    expect_error("  A_R:", "  A_R: 80\n  A_X: 3\n", "rudder.A_X: unknown field");
    expect_error(NULL, "extra: 1\n", "extra: unknown field");
    expect_error("  D_P:", "  D_P: nan\n", "propeller.D_P");
    expect_error("  T2: {", "  T2: {\"1\": 1, q: 2}\n", "nomoto.T2.q: unknown field");
    expect_error("name: c3", "name: [a]\n", "name: expected a text value");
    fw_error err = {0};
    fw_ship s;
    CHECK(fw_ship_load("nosuch", &s, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "unknown ship 'nosuch'");
}

int main(void)
{
    TEST_RUN(test_load_c3);
    TEST_RUN(test_load_kvlcc2);
    TEST_RUN(test_errors);
    return TEST_EXIT();
}
