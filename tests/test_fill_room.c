/* test_fill_room - the start-up fill is there from t = 0 or not at all
 * (source_sumo.c drop_unplaced).
 *
 * The fill's ships depart at t = 0 at a random free place of the edge drawn
 * for them.  A fill larger than the lanes hold left SUMO with ships waiting
 * for room, which it inserted later wherever room appeared: after a ship
 * fairway had taken off its lane, onto that ship's hull (networks/dover, a
 * fill of 405: 35 waiting, one inserted at t = 2 s 15 m behind a taken ferry,
 * the hulls overlapping), unchecked by the start's clearing.  Here, on the
 * channel network with a fill it cannot hold: the ships with no room are
 * counted and never appear; every fill ship is accounted for (there at the
 * start, taken out by the clearing, or not placed); a fill the lanes hold
 * places every ship. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/units.h"
#include "test.h"
#include "test_tmp.h"
#include "traffic/source.h"
#include "traffic/source_sumo.h"

static char workdir[256];

/* The number of distinct fill ids among n ships (seen: the ids met so far,
 * FW_TARGET_ID_MAX each, *n_seen of them); *late counts those first met
 * after the start (step > 0). */
static void count_fill(const fw_target *v, int n, char (*seen)[FW_TARGET_ID_MAX], int *n_seen,
                       int cap, int step, int *late)
{
    for (int i = 0; i < n; i++) {
        if (!strstr(v[i].id, "_fill"))
            continue;
        int j = 0;
        while (j < *n_seen && strcmp(seen[j], v[i].id) != 0)
            j++;
        if (j < *n_seen || *n_seen >= cap)
            continue;
        snprintf(seen[(*n_seen)++], FW_TARGET_ID_MAX, "%s", v[i].id);
        if (step > 0) {
            ++*late;
            printf("  %s first seen at step %d\n", v[i].id, step);
        }
    }
}

/* A channel run with fill ships, 200 steps: *at_start fill ships there
 * after the first step, *late first seen later, *cleared and *unplaced as
 * the source counts them. */
static void run_fill(int fill, int *at_start, int *late, int *cleared, int *unplaced)
{
    fw_error err = {0};
    char dir[300];
    snprintf(dir, sizeof dir, "%s/fill%d", workdir, fill);
    CHECK(fw_mkdirs(dir, "the run directory", &err) == FW_OK);
    fw_sumo_source_def d = fw_default_sumo_source_def();
    d.dir = dir;
    d.network = "channel";
    d.fill = fill;
    d.density = 1.0; /* the fill scales with it; arrivals are FLOW.N, not counted */
    d.duration = 200.0;
    d.seed = 5;
    d.own = (fw_target){.id = "fw_own", .east = 0.0, .north = 3000.0, .course = 0.0,
                        .speed = 0.0, .length = 180.0, .breadth = 30.0};
    d.radius = 1e6;
    d.area_radius = 1e6; /* the whole network */
    d.clear_range = 0.0;
    fw_source *s = NULL;
    *at_start = *late = *cleared = *unplaced = 0;
    CHECK_MSG(fw_sumo_source_create(&d, &s, &err) == FW_OK, "%s", err.msg);
    if (!s)
        return;
    *cleared = fw_sumo_source_cleared(s);
    *unplaced = fw_sumo_source_unplaced(s);
    static char seen[2000][FW_TARGET_ID_MAX];
    int n_seen = 0;
    for (int k = 0; k < 200; k++) {
        const fw_target *v;
        int n;
        if (k > 0)
            CHECK_MSG(s->ops->place(s, &d.own, &err) == FW_OK &&
                          s->ops->advance(s, &err) == FW_OK, "step %d: %s", k, err.msg);
        CHECK_MSG(s->ops->area(s, &v, &n, &err) == FW_OK, "%s", err.msg);
        count_fill(v, n, seen, &n_seen, 2000, k, late);
        if (k == 0)
            *at_start = n_seen;
    }
    s->ops->destroy(s);
}

static void test_overflowing_fill(void)
{
    int at_start, late, cleared, unplaced;
    run_fill(600, &at_start, &late, &cleared, &unplaced);
    printf("fill 600 on the channel: %d there at the start, %d taken out, %d not placed, %d "
           "first seen later\n", at_start, cleared, unplaced, late);
    CHECK_MSG(unplaced > 0, "the channel held a fill of 600: %d there", at_start);
    CHECK_MSG(late == 0, "%d fill ships appeared after the start", late);
    CHECK(at_start + cleared + unplaced == 600);
}

static void test_fill_that_fits(void)
{
    int at_start, late, cleared, unplaced;
    run_fill(20, &at_start, &late, &cleared, &unplaced);
    printf("fill 20 on the channel: %d there at the start, %d taken out, %d not placed\n",
           at_start, cleared, unplaced);
    CHECK(unplaced == 0 && late == 0);
    CHECK(at_start + cleared == 20);
}

int main(void)
{
    if (test_tmpdir("fill_room", workdir, sizeof workdir))
        return 1;
    TEST_RUN(test_overflowing_fill);
    TEST_RUN(test_fill_that_fits);
    return TEST_EXIT();
}
