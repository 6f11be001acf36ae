/* world_view.h - the tests' look at a world's own ship (world.h): what it
 * sees, and the traffic monitors (survey/monitor.h) fed with it. */
#ifndef FW_TEST_WORLD_VIEW_H
#define FW_TEST_WORLD_VIEW_H

#include "survey/monitor.h"
#include "test.h"
#include "world/world.h"

/* Vessel v's view entry for id (NULL: not seen). */
static inline const fw_target *in_view(const fw_vessel *v, const char *id)
{
    const fw_target *tg;
    const fw_assessment *as;
    int n;
    fw_vessel_view(v, &tg, &as, &n);
    int j = fw_target_find(tg, n, id);
    return j < 0 ? NULL : &tg[j];
}

/* The monitors' step: the own ship and what it sees. */
static inline void monitor_step(fw_monitor *m, fw_world *w, fw_error *err)
{
    const fw_vessel *o = fw_world_vessel(w, fw_world_own(w));
    const fw_target *tg;
    const fw_assessment *as;
    int n;
    fw_vessel_view(o, &tg, &as, &n);
    CHECK_MSG(fw_monitor_step(m, fw_world_time(w), fw_vessel_record(o), tg, n, err) == FW_OK,
              "%s", err->msg);
}

#endif
