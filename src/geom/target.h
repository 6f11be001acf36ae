/* target.h - one ship as the others see it: the one record of "another ship".
 *
 * From the traffic source's read (SUMO, the kinematic script, later AIS)
 * through the world, the assessment and the helm search to the encounter book
 * and the traffic survey, a ship is an fw_target.  SUMO's own terms (front
 * bumper, angle in degrees) are converted into it once, inside src/traffic.
 *
 * Frame: metres east/north of the scenario origin, the position the hull
 * centre (midship), headings navigational (0 north, clockwise), SI.
 *
 * Motion over ground and the hull apart: `course` and `speed` are the course
 * and speed over ground, the velocity CPA, TCPA and constant-velocity
 * prediction use; `heading` is where the hull points (hull outlines, the
 * domain's orientation, SUMO's placement angle, the sideways check) and
 * `stw` the speed through the water.  They differ by the drift angle in a
 * turn (an MMG ship slides outwards, even in calm water) and by the current.
 * Sources that know no drift and no current (SUMO's ships, the kinematic
 * script, recorded tracks) give heading = course and stw = speed.
 *
 * How the ship is expected to move is its predictor (`pred`): NULL means at
 * constant velocity, the assumption of the paper's search; a source that knows
 * a ship's route can attach one that follows it (fw_predictor below) without
 * any change to the assessment's or the helm search's callers.
 */
#ifndef FW_GEOM_TARGET_H
#define FW_GEOM_TARGET_H

#include <stdbool.h>

/* Room for an id or a type with its terminating NUL. */
enum { FW_TARGET_ID_MAX = 64 };

typedef struct fw_predictor fw_predictor;

typedef struct fw_target {
    /* A stable name (the SUMO vehicle id, the scenario's target id, later an
     * MMSI), the same from step to step while the array order may change: the
     * policy remembers the target it is avoiding by it, the records key their
     * book by it.  "" = no id (the policy then falls back to the array index,
     * which is right only if the order is fixed).  Ids are compared whole. */
    char id[FW_TARGET_ID_MAX];
    char type[FW_TARGET_ID_MAX]; /* a label ("cargo", a SUMO vType): records only */
    double east, north;          /* m, hull centre */
    double course;               /* rad, navigational, course over ground */
    double speed;                /* m/s, >= 0, speed over ground */
    double heading;              /* rad, navigational, the hull's heading */
    double stw;                  /* m/s, speed through the water */
    double length;               /* m, 0 = a point */
    double breadth;              /* m */
    bool own;                    /* the own ship (listed only in area queries) */
    const fw_predictor *pred;    /* NULL: constant velocity */
    /* A number the traffic source gives the id, 1, 2, ..., the same for the
     * whole run and one id's only, so that the modules that key their data
     * by ship (core/idmap.h) find it without hashing the id; 0 = none (the
     * id is looked up).  Whoever renames a record resets it. */
    int key;
} fw_target;

/* Where a ship will be: positions and the hull's headings at t = k dt,
 * k = 0..n-1, from its present record.  Implementations keep their own data
 * behind `self`. */
struct fw_predictor {
    void (*path)(const fw_predictor *self, const fw_target *now, double dt, int n,
                 double *east, double *north, double *heading);
    /* Is its path now the constant-velocity one (NULL: never)?  Then the
     * record carrying it is given no predictor (world/vessel.h), and every
     * reader takes constant velocity's closed forms instead of a path. */
    bool (*steady)(const fw_predictor *self);
};

/* Fills the path of t (its predictor, or constant velocity: positions along
 * the ground velocity, the heading held). */
void fw_target_path(const fw_target *t, double dt, int n, double *east, double *north,
                    double *heading);

/* t with heading = course and stw = speed: a ship that knows no drift and
 * no current (every traffic source's). */
static inline fw_target fw_target_undrifted(fw_target t)
{
    t.heading = t.course;
    t.stw = t.speed;
    return t;
}

/* t with its id set to id (cut at FW_TARGET_ID_MAX - 1 characters: for
 * tests and benchmarks, whose ids are short). */
fw_target fw_target_named(const char *id, fw_target t);

/* Index of the target with this id in t[0..n-1], -1 if none or id is "". */
int fw_target_find(const fw_target *t, int n, const char *id);

#endif
