#include "study_db.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "study/schema.h"

sqlite3 *sdb_create(const char *path, const char *schema_version)
{
    unlink(path);
    sqlite3 *db = NULL;
    if (sqlite3_open(path, &db) != SQLITE_OK) {
        fprintf(stderr, "%s: %s\n", path, sqlite3_errmsg(db));
        sqlite3_close(db);
        return NULL;
    }
    char schema[8192];
    if (fw_schema_sql(schema, sizeof schema) >= (int)sizeof schema ||
        sdb_exec(db, "%s", schema) ||
        sdb_exec(db, "INSERT INTO meta VALUES('schema_version', '%s'), ('study_name', 'synthetic'), "
                     "('near_miss_m', '200')",
                 schema_version)) {
        sqlite3_close(db);
        return NULL;
    }
    return db;
}

int sdb_exec(sqlite3 *db, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *sql = sqlite3_vmprintf(fmt, ap);
    va_end(ap);
    char *msg = NULL;
    int rc = sqlite3_exec(db, sql, NULL, NULL, &msg);
    if (rc != SQLITE_OK)
        fprintf(stderr, "sdb_exec: %s\n  in: %.200s\n", msg ? msg : "?", sql);
    sqlite3_free(msg);
    sqlite3_free(sql);
    return rc == SQLITE_OK ? 0 : -1;
}

static int run_row(sqlite3 *db, int id, double domain, double density, int rep, const char *status,
                   const char *reason, double sim_s, int n_enc, int n_actions, double min_dist,
                   int near, int coll, double max_helm, double path_plus, double time_lost,
                   int helm_orders, double traffic_ship_s)
{
    char min[40] = "NULL";
    if (!isnan(min_dist))
        snprintf(min, sizeof min, "%.17g", min_dist);
    return sdb_exec(db,
                    "INSERT INTO runs(run_id, domain_m, density, replication, seed, status, reason, "
                    "sim_s, wall_s, sumo_s, n_encounters, n_actions, min_dist_m, domain_entered, "
                    "near_miss, collision, colregs_ok, max_helm_deg, path_length_m, "
                    "path_lengthening_m, time_lost_s, rudder_work_deg_s, helm_orders, traffic_ship_s) "
                    "VALUES(%d, %.17g, %.17g, %d, %d, '%q', '%q', %.17g, 1, 1, %d, %d, %s, 0, %d, %d, 1, "
                    "%.17g, 0, %.17g, %.17g, 0, %d, %.17g)",
                    id, domain, density, rep, 1000 + rep, status, reason, sim_s, n_enc, n_actions,
                    min, near, coll,
                    max_helm, path_plus, time_lost, helm_orders, traffic_ship_s);
}

static int enc_row(sqlite3 *db, int run, int k, const char *sit, double cpa, int dom, int near,
                   int coll)
{
    return sdb_exec(db,
                    "INSERT INTO encounters(run_id, target, target_type, situation, min_dist_m, "
                    "domain_entered, near_miss, collision, colregs_ok) "
                    "VALUES(%d, 't%d', 'cargo', '%q', %.17g, %d, %d, %d, 1)",
                    run, k, sit, cpa, dom, near, coll);
}

static int traffic_row(sqlite3 *db, int run, int k, const char *type, double cpa)
{
    return sdb_exec(db,
                    "INSERT INTO traffic_encounters(run_id, ship_a, ship_b, type, own, t_first_s, "
                    "min_dist_m) VALUES(%d, 'a%d', 'b%d', '%q', 0, %d, %.17g)",
                    run, k, k, type, k, cpa);
}

/* The hand database, every number chosen so the report can be worked out on
 * paper (test_report.c does).  sim_s = 1800 s: half an hour per run. */
int sdb_hand(const char *path)
{
    sqlite3 *db = sdb_create(path, FW_SCHEMA_VERSION);
    if (!db)
        return -1;
    int rc = 0;
    /* per run: situations (H head-on, O overtaking, B being overtaken, G give-way,
     * S stand-on) with domain-entered / near-miss / collision flags */
    static const struct {
        const char *sits, *dom, *near, *coll;
    } enc[6] = {
        {"HHOG", "1100", "1000", "0000"},    /* 100 m, rep 0 */
        {"HBBSSS", "010000", "000000", "000000"}, /* 100 m, rep 1 */
        {"GGGGG", "11100", "11000", "10000"}, /* 100 m, rep 2 */
        {"HHOG", "0000", "0000", "0000"},    /* 500 m, rep 0 */
        {"HBBSSS", "000000", "000000", "000000"},
        {"GGGGG", "10000", "00000", "00000"},
    };
    static const int actions[6] = {3, 4, 5, 6, 7, 9};
    static const double plus[6] = {100, 150, 200, 300, 350, 500};
    static const double lost[6] = {30, 45, 60, 90, 100, 150};
    static const double helm[6] = {10, 15, 20, 20, 25, 35};
    rc |= sdb_exec(db, "BEGIN");
    int cpa_k = 0;
    for (int r = 0; r < 6 && !rc; r++) {
        double domain = r < 3 ? 100 : 500;
        int n = 0, coll = 0, near = 0;
        for (const char *c = enc[r].sits; *c; c++, n++) {
            const char *sit = *c == 'H' ? "head-on" : *c == 'O' ? "overtaking"
                            : *c == 'B' ? "being overtaken" : *c == 'G' ? "crossing give-way"
                                                                        : "crossing stand-on";
            /* CPAs 100, 200, ..., 1500 m over the 15 encounters of 100 m; at
             * 500 m each one 50 m wider */
            double cpa = 100.0 * (1 + cpa_k++ % 15) + (r < 3 ? 0.0 : 50.0);
            int d = enc[r].dom[n] == '1', nm = enc[r].near[n] == '1', cl = enc[r].coll[n] == '1';
            near |= nm;
            coll |= cl;
            rc |= enc_row(db, r, n, sit, cpa, d, nm, cl);
        }
        /* run 4 has no min_dist recorded: the report counts it as missing */
        rc |= run_row(db, r, domain, 1.0, r % 3, "ok", "", 1800.0, n, actions[r],
                      r == 4 ? NAN : 100.0 * (r + 1), near, coll, helm[r], plus[r], lost[r],
                      2 * actions[r], 36000.0);
    }
    /* traffic: 10 ship-hours per run; 5, 4, 6 encounters in the three
     * replications (the same traffic at both domain sizes) */
    static const char *traffic[3] = {"hhhcc", "hoco", "oooccc"};
    for (int r = 0; r < 6 && !rc; r++)
        for (int k = 0; traffic[r % 3][k]; k++) {
            char t = traffic[r % 3][k];
            rc |= traffic_row(db, r, k, t == 'h' ? "head-on" : t == 'o' ? "overtaking" : "crossing",
                              250.0 * (k + 1));
        }
    /* a failed run and the rows it left: none of it may count */
    rc |= run_row(db, 6, 500, 1.0, 3, "failed", "SUMO error: vehicle teleported", 900.0, 1, 50,
                  5.0, 1, 1, 35, 9999, 9999, 1, 1.0);
    rc |= enc_row(db, 6, 0, "head-on", 5.0, 1, 1, 1);
    rc |= traffic_row(db, 6, 0, "head-on", 5.0);
    rc |= sdb_exec(db, "COMMIT");
    sqlite3_close(db);
    return rc ? -1 : 0;
}

static unsigned long long rng;
static double uniform(void)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return ((rng >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}
static int poisson(double mean)
{
    double l = exp(-mean), p = 1.0;
    int k = 0;
    while ((p *= uniform()) > l)
        k++;
    return k;
}

int sdb_random(const char *path, unsigned long long seed)
{
    static const double domains[] = {100, 300, 600, 1000}, densities[] = {1, 2};
    static const char *const sits[] = {"head-on", "overtaking", "being overtaken",
                                       "crossing give-way", "crossing stand-on"};
    static const char *const types[] = {"head-on", "overtaking", "crossing"};
    sqlite3 *db = sdb_create(path, FW_SCHEMA_VERSION);
    if (!db)
        return -1;
    int rc = sdb_exec(db, "BEGIN"), id = 0;
    for (int di = 0; di < 2 && !rc; di++)
        for (int rep = 0; rep < 6 && !rc; rep++) {
            /* common random numbers: the replication's traffic is drawn once
             * and sailed with every domain size */
            unsigned long long traffic_seed = seed * 1000003ull + (unsigned long long)(di * 100 + rep);
            for (int dj = 0; dj < 4 && !rc; dj++, id++) {
                double dom = domains[dj], dens = densities[di];
                if (di == 1 && rep == 5 && dj == 2) {
                    rc |= run_row(db, id, dom, dens, rep, "failed", "integration failed: NaN", 60,
                                  0, 0, NAN, 0, 0, 0, 0, 0, 0, 0);
                    continue;
                }
                rng = traffic_seed;
                int n = poisson(6.0 * dens), actions = 0, near = 0, coll = 0;
                double min = NAN;
                for (int k = 0; k < n; k++) {
                    const char *sit = sits[(int)(uniform() * 5)];
                    /* a larger domain keeps targets further off */
                    double cpa = (50.0 + 1500.0 * uniform() * uniform()) * (1.0 + dom / 1000.0);
                    int d = cpa < dom, nm = cpa < 200.0, cl = cpa < 60.0;
                    actions += uniform() < 0.3 + dom / 1500.0;
                    near |= nm;
                    coll |= cl;
                    min = isnan(min) || cpa < min ? cpa : min;
                    rc |= enc_row(db, id, k, sit, cpa, d, nm, cl);
                }
                double ship_s = 3600.0 * 30.0 * dens;
                int nt = poisson(40.0 * dens);
                for (int k = 0; k < nt; k++)
                    rc |= traffic_row(db, id, k, types[(int)(uniform() * 3)], 2000.0 * uniform());
                rc |= run_row(db, id, dom, dens, rep, "ok", "", 3600.0, n, actions, min, near, coll,
                              5.0 + 20.0 * uniform() + dom / 100.0, actions * (40.0 + dom / 5.0),
                              actions * (10.0 + dom / 20.0), 2 * actions, ship_s);
            }
        }
    rc |= run_row(db, id, 100, 1, 6, "failed", "SUMO error: connection closed", 10, 0, 0, NAN, 0,
                  0, 0, 0, 0, 0, 0);
    rc |= sdb_exec(db, "COMMIT");
    sqlite3_close(db);
    return rc ? -1 : 0;
}

int sdb_only_failed(const char *path)
{
    sqlite3 *db = sdb_create(path, FW_SCHEMA_VERSION);
    if (!db)
        return -1;
    int rc = run_row(db, 0, 100, 1, 0, "failed", "SUMO error: no network", 0, 0, 0, NAN, 0, 0, 0,
                     0, 0, 0, 0);
    rc |= run_row(db, 1, 500, 1, 0, "failed", "SUMO error: no network", 0, 0, 0, NAN, 0, 0, 0, 0,
                  0, 0, 0);
    sqlite3_close(db);
    return rc ? -1 : 0;
}

int sdb_zeros(const char *path)
{
    sqlite3 *db = sdb_create(path, FW_SCHEMA_VERSION);
    if (!db)
        return -1;
    int rc = sdb_exec(db, "BEGIN");
    for (int r = 0; r < 40 && !rc; r++) {
        double domain = r < 20 ? 100 : 300;
        rc |= run_row(db, r, domain, 1.0, r % 20, "ok", "", 3600.0, 1, 1, 900.0, 0, 0, 10, 0, 0,
                      2, 3600.0);
        rc |= enc_row(db, r, 0, "crossing give-way", 900.0, 0, 0, 0);
    }
    rc |= sdb_exec(db, "COMMIT");
    sqlite3_close(db);
    return rc ? -1 : 0;
}
