/* test_book.c - the encounter book's COLREGs reading (run/book.h) in
 * restricted visibility: a ship out of sight when met and when acted for is
 * judged by rule 19, not 13-17:
 *   a ship closing from abaft the starboard beam: an alteration to port
 *     (away) is right, to starboard (towards it) wrong; in clear weather, a
 *     ship overtaking, either side is right
 *   a crossing ship on the port bow entering the domain with no action: in
 *     clear weather the own ship stood on (right); out of sight there is no
 *     standing on (wrong)
 *   the audit reads such an encounter as rule 19's, the own ship a give-way
 *     ship, the side as above */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "avoid/helm_search.h"
#include "core/files.h"
#include "core/units.h"
#include "run/book.h"
#include "scenario/scenario.h"
#include "test.h"

/* One ship at relative bearing rb (deg) 3 km off on a collision course (it
 * meets the own ship, 6 m/s north, 600 s on), then 100 m off in the domain;
 * the own ship acts to side (FW_SIDE_NONE: not at all) at t = 1.  Returns
 * the entry's colregs_ok; its audit into *audit when not NULL. */
static bool judged_audit(double rb_deg, int side, double visibility, fw_audit_result *audit)
{
    fw_scenario s;
    fw_error err = {0};
    char path[1100];
    snprintf(path, sizeof path, "%s/scenarios/imazu/imazu-02.yaml", fw_data_root());
    CHECK_MSG(fw_scenario_load(path, &s, &err) == FW_OK, "%s", err.msg);
    s.visibility = s.helm.colregs.visibility = visibility;
    fw_book *b = NULL;
    CHECK(fw_book_create(&s, &b, &err) == FW_OK);
    fw_own_state own = {.U = 6.0};
    fw_mmg_state x = {.u = 6.0};
    double rb = fw_deg_to_rad(rb_deg), T = 600.0;
    for (int k = 0; k < 3; k++) {
        double R = k < 2 ? 3000.0 : 100.0;
        fw_target t = {.id = "T", .east = R * sin(rb), .north = R * cos(rb), .length = 100,
                       .breadth = 16, .type = "cargo"};
        double ve = -3000.0 * sin(rb) / T, vn = (own.U * T - 3000.0 * cos(rb)) / T;
        t.course = t.heading = fw_wrap_2pi(atan2(ve, vn));
        t.speed = hypot(ve, vn);
        fw_assessment as;
        int order[2];
        fw_assess(&s.helm.colregs, &s.helm.domain, s.helm.track.horizon, &own, &t, 1, &as, order);
        CHECK(fw_book_target(b, k, &t, &x, &as, &err) == FW_OK);
        if (k == 1 && side != FW_SIDE_NONE)
            fw_book_action(b, k, side, 0.2 * side, "T", &t, &as, 1);
    }
    fw_run_summary sum;
    memset(&sum, 0, sizeof sum);
    fw_book_judge(b, &sum);
    int n;
    const fw_encounter *e = fw_book_entries(b, &n);
    bool ok = e[0].colregs_ok;
    CHECK(n == 1 && ok == sum.colregs_ok);
    if (audit)
        *audit = e[0].audit;
    fw_book_destroy(b);
    return ok;
}

static bool judged(double rb_deg, int side, double visibility)
{
    return judged_audit(rb_deg, side, visibility, NULL);
}

static void test_rule19_judged(void)
{
    double fog = fw_nm_to_m(0.5);
    CHECK(judged(135.0, FW_SIDE_PORT, fog));
    CHECK(!judged(135.0, FW_SIDE_STARBOARD, fog));
    CHECK(judged(135.0, FW_SIDE_STARBOARD, 0.0)); /* being overtaken: either side */
    CHECK(judged(45.0, FW_SIDE_STARBOARD, fog));
    CHECK(!judged(45.0, FW_SIDE_PORT, fog));
    CHECK(judged(315.0, FW_SIDE_NONE, 0.0)); /* stand-on (rule 17) */
    CHECK(!judged(315.0, FW_SIDE_NONE, fog));
    /* the audit (audit.h fw_audit_evaluate_rule19): rule 19, a give-way role,
     * the side read as above */
    fw_audit_result a;
    judged_audit(135.0, FW_SIDE_STARBOARD, fog, &a);
    CHECK(a.rule == 19 && a.role == FW_ROLE_GIVE_WAY && a.compliant == 0);
    CHECK_CONTAINS(a.note, "rule 19(d)");
    judged_audit(135.0, FW_SIDE_STARBOARD, 0.0, &a);
    CHECK(a.rule == 13 && a.role == FW_ROLE_STAND_ON);
    judged_audit(135.0, FW_SIDE_PORT, fog, &a);
    CHECK(a.rule == 19 && strstr(a.note, "rule 19(d)") == NULL);
}

int main(void)
{
    TEST_RUN(test_rule19_judged);
    return TEST_EXIT();
}
