/* source_sumo.h - the SUMO traffic source: everything fairway writes for SUMO, and the coupling.
 *
 * What a run needs from SUMO is described here in fairway's terms (a network
 * by name with its demand, explicit target ships at constant course and
 * speed, the own ship's start and leg) and turned into SUMO's files here:
 *
 *   network only       the built networks/NAME/NAME.net.xml as it is, and a
 *                      route file from the network's demand (demand.h); the
 *                      own ship is placed anywhere by moveToXY
 *   explicit targets   one straight one-lane edge along each target's track
 *                      and one along the own ship's leg, as plain XML, built
 *                      with the network's own sources (if any) by netconvert
 *                      into dir; a route per target (departPos is SUMO's
 *                      front bumper: the hull centre lands on the start)
 *
 * Target lanes allow only vClass custom1, so moveToXY can never map the own
 * ship (vClass ship) onto a target's lane where the target would brake for it:
 * targets keep course and speed exactly.  Explicit targets are listed with the
 * scenario's type label, not the generated vType.
 *
 * After create, SUMO has made its first step (it inserts ships during a
 * step): the ships are where they are at fairway's t = 0.  Then every network
 * ship (not an explicit target) that SUMO's fill put within clear_range of
 * the own ship, or on a course that would bring it within clear_cpa of it in
 * the next clear_tcpa seconds (both at constant velocity), is taken out: a
 * study must not begin with a ship already on top of the own ship.  So is
 * the later (in SUMO's order) of two network ships anywhere on the network
 * (every ship read once, not only those about the own ship) on crossing
 * courses (30 to 140 deg apart) that would come within clear_cpa that soon,
 * or meeting on reciprocal courses with hulls that would touch: put there at
 * the start they would have no time to give way.  At three times Dover's
 * density (5 seeds) this took the fill pairs that collided in the first 10
 * minutes from 2 to 0 (12 to 0 with blind traffic), 4.9% of the fill's ships
 * taken out in all (2.1% when only the own ship's surroundings were looked at).
 *
 * It has no within() (source.h): a vessel other than the own ship sees the
 * SUMO ships of nearby() (the range query about the own ship) within its
 * sight, so none beyond the query's circle; reading every ship's position
 * for it would cost a getter per ship and step.
 *
 * A ship taken (source.h take: its state as the range query converted it)
 * stays in SUMO, placed every step where fairway's vessel is by moveToXY
 * with the own ship's keepRoute 2 and 1 mm threshold: sumo-gui shows it,
 * area() lists it as placed, and fairway's reactive traffic gives way to it
 * (world/reactions.h).  SUMO's own view of it depends on where it is
 * (measured with SUMO 1.15 on networks/channel): within 1 mm of a lane's
 * line (a ship taken on its lane and held straight) SUMO keeps it on that
 * lane and its followers keep their distance by car following (one slowed
 * from 9.5 to 7.4 m/s behind it in 5 minutes); off the lines it is off the
 * lanes, as the own ship is, and SUMO's ships do not see it (SUMO's reads
 * of one taken in the middle of a lane change stayed where the first move
 * put it: nothing here reads them).  Mapped onto a lane of another
 * edge (steered across its line, within the 1 mm), SUMO gives it that edge
 * as its route; its route as taken is what it is given back to.  Given
 * back, it is moved onto the nearest lane of its route ahead where it will
 * be after the next step (moveToXY keepRoute 1; where SUMO replaced its
 * route, keepRoute 0 onto that lane and the route as taken set again from
 * there after the step) with its speed as its last (setPreviousSpeed), and
 * SUMO drives it on; refused if that lane is not on its route as taken
 * ahead, if its line is more than
 * FW_SOURCE_REJOIN_MAX away, or while a ship in that lane or changing lanes
 * into it is beside it or ahead within its gap, or behind too close to slow
 * for it at its own decel (traffic.h fw_traffic_give_back): it is steered
 * on along its line meanwhile.
 * Taken again before SUMO has stepped it (in the step it was given back),
 * it is handed over as it was given back, and its rejoin is not made.
 */
#ifndef FW_SOURCE_SUMO_H
#define FW_SOURCE_SUMO_H

#include "traffic/source.h"
#include "traffic/traffic.h"

typedef struct fw_sumo_source_def {
    fw_traffic_mode mode;
    const char *dir;            /* SUMO's files and logs go here (it must exist) */
    const char *network;        /* networks/NAME; NULL or "" = none */
    double density;             /* demand scale */
    int fill;                   /* network ships along the routes at t = 0, at density 1 */
    unsigned long seed;         /* SUMO's and the demand's */
    double duration;            /* s, the run; flows run to duration + step */
    double step;                /* s */
    bool fcd;                   /* SUMO's FCD of every ship into dir/fcd.xml ... */
    double fcd_period;          /* s, ... every this (0: every step) */
    /* the network's plane when it is geo-referenced (scenario.h plane: a PROJ
     * string and netOffset; NULL: none): the tracks' nodes are then written in
     * degrees for netconvert to project as the build projected the network */
    const char *proj;
    double proj_off_e, proj_off_n;
    const fw_target *targets;   /* explicit ships at t = 0 (constant velocity) */
    int n_targets;
    fw_target own;              /* id, position, course, speed, length, breadth at t = 0 */
    double own_leg;             /* m, planned straight leg along the course */
    double radius;              /* m, sight (own hull centre to SUMO's front bumper) */
    double area_radius;         /* m, 0 = no area query */
    double near_radius;         /* m, the reactive traffic's (0: the sight's) */
    double clear_range;         /* m, 2 nm */
    double clear_cpa;           /* m, 0.25 nm (a collision course) ... */
    double clear_tcpa;          /* s, ... within 600 s */
} fw_sumo_source_def;

fw_sumo_source_def fw_default_sumo_source_def(void);

fw_status fw_sumo_source_create(const fw_sumo_source_def *def, fw_source **out, fw_error *err);

/* How many fill ships were taken out at the start (0 for another source). */
int fw_sumo_source_cleared(const fw_source *s);
/* How many fill ships found no room on their lanes at the start and were
 * not placed (0 for another source). */
int fw_sumo_source_unplaced(const fw_source *s);

/* Wall-clock seconds spent in SUMO's steps so far (benchmarks and the study
 * database only, never in a run's files). */
double fw_sumo_source_step_wall(const fw_source *s);

#endif
