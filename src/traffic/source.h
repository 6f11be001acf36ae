/* source.h - where the world's background ships come from: one interface, two sources.
 *
 * A traffic source moves the ships that fairway does not step itself and says
 * where they are, as fw_target records (geom/target.h: hull centre,
 * navigational course, SI), converted from the source's own terms inside the
 * source.  The world (world/world.h) drives it, every step of fixed length:
 *
 *   place(own)   where the own ship is now (SUMO keeps a vehicle for it, so
 *                that sumo-gui shows it and the area query lists it)
 *   advance()    one step of the source's ships
 *   around()     the ships within sight of the own ship, sorted by id
 *   area()       every ship within the area radius of the own ship, the own
 *                ship included (flagged own), sorted by id: the survey's input
 *   nearby()     the ships that give way to each other (world/reactions.h):
 *                watched beyond sight, so that none comes into sight in the
 *                middle of a crossing nobody handled (optional: a source
 *                without it gives around())
 *   set_speed()  a ship told to hold a speed (or to go on as before)
 *   within()     the ships within r of a point, sorted by id: what a vessel
 *                other than the own ship sees (optional: a source without it
 *                gives nearby() filtered by distance, so such a vessel sees
 *                only what the source watches around the own ship)
 *   take()       a ship handed to fairway (world.h fw_world_take): its exact
 *                state out; from then on the source no longer drives it nor
 *                lists it in around(), nearby() or within() (it is a vessel,
 *                seen through the world), but area() lists it where steer()
 *                last put it (optional: a source without it refuses)
 *   steer()      where a taken ship is now, every step before advance()
 *   give_back()  a taken ship driven by the source again: it rejoins its
 *                route ahead of where it is, at its speed; FW_EINPUT (and
 *                still taken) if it is more than FW_SOURCE_REJOIN_MAX off
 *                its route: a vessel must be steered back to its route first
 *                (the SUMO source also while a ship in its lane, or changing
 *                lanes into it, is beside it or ahead within its gap)
 *   lane()       a ship's lane before it is taken (fw_lane_info): the centre
 *                line it follows along its route ahead and the sea room on
 *                either side of it (optional: a source without it has no
 *                lanes, and its ships are never taken to steer)
 *
 * Sources:
 *   SUMO        (source_sumo.h) libsumo in-process or libtraci to a sumo or
 *               sumo-gui; the only code that writes SUMO's files
 *   kinematic   (below) scripted legs of constant course and speed, no SUMO
 *               process: tests, the oracle, benchmarks, quick runs
 *
 * Lists returned point into the source and stay valid until its next
 * advance or query.  Sorting by id makes every result independent of the
 * order in which a source keeps its ships.
 */
#ifndef FW_TRAFFIC_SOURCE_H
#define FW_TRAFFIC_SOURCE_H

#include "core/error.h"
#include "geom/target.h"
#include "traffic/lane.h"

typedef struct fw_source fw_source;


typedef struct fw_source_ops {
    const char *name;
    fw_status (*place)(fw_source *s, const fw_target *own, fw_error *err);
    fw_status (*advance)(fw_source *s, fw_error *err);
    fw_status (*around)(fw_source *s, const fw_target **ships, int *n, fw_error *err);
    fw_status (*area)(fw_source *s, const fw_target **ships, int *n, fw_error *err);
    fw_status (*nearby)(fw_source *s, const fw_target **ships, int *n, fw_error *err);
    /* Holds ship id at speed (m/s) from the next step on; speed < 0 gives it
     * back its own (the scripted or SUMO's).  The world's reactive traffic
     * (world/reactions.h) gives way through it. */
    fw_status (*set_speed)(fw_source *s, const char *id, double speed, fw_error *err);
    /* Optional, see above. */
    fw_status (*within)(fw_source *s, double east, double north, double r,
                        const fw_target **ships, int *n, fw_error *err);
    fw_status (*take)(fw_source *s, const char *id, fw_target *state, fw_error *err);
    fw_status (*steer)(fw_source *s, const fw_target *ship, fw_error *err);
    fw_status (*give_back)(fw_source *s, const fw_target *ship, fw_error *err);
    fw_status (*lane)(fw_source *s, const char *id, fw_lane_info *out, fw_error *err);
    double (*time)(const fw_source *s);        /* s, after the last advance */
    double (*step_length)(const fw_source *s); /* s */
    void (*destroy)(fw_source *s);
} fw_source_ops;

/* Every source begins with this header. */
struct fw_source {
    const fw_source_ops *ops;
};

static inline fw_status fw_source_place(fw_source *s, const fw_target *own, fw_error *err)
{
    return s->ops->place(s, own, err);
}
static inline fw_status fw_source_advance(fw_source *s, fw_error *err)
{
    return s->ops->advance(s, err);
}
static inline fw_status fw_source_around(fw_source *s, const fw_target **v, int *n,
                                         fw_error *err)
{
    return s->ops->around(s, v, n, err);
}
static inline fw_status fw_source_area(fw_source *s, const fw_target **v, int *n, fw_error *err)
{
    return s->ops->area(s, v, n, err);
}
static inline fw_status fw_source_nearby(fw_source *s, const fw_target **v, int *n,
                                         fw_error *err)
{
    return s->ops->nearby ? s->ops->nearby(s, v, n, err) : s->ops->around(s, v, n, err);
}
static inline fw_status fw_source_set_speed(fw_source *s, const char *id, double speed,
                                            fw_error *err)
{
    return s->ops->set_speed(s, id, speed, err);
}
/* m, how far off its route a ship may be given back: a step's sideways move
 * at well under the traffic monitors' 2 m/s (survey/monitor.h) */
#define FW_SOURCE_REJOIN_MAX 1.0

static inline fw_status fw_source_take(fw_source *s, const char *id, fw_target *state,
                                       fw_error *err)
{
    if (!s->ops->take)
        return fw_fail(err, FW_EINPUT, "the %s source cannot hand its ships over (take '%s')",
                       s->ops->name, id);
    return s->ops->take(s, id, state, err);
}
/* Only for ships taken (so never NULL then). */
static inline fw_status fw_source_steer(fw_source *s, const fw_target *ship, fw_error *err)
{
    return s->ops->steer(s, ship, err);
}
static inline fw_status fw_source_give_back(fw_source *s, const fw_target *ship, fw_error *err)
{
    return s->ops->give_back(s, ship, err);
}
/* FW_EINPUT for a source without lanes, or a ship it cannot say (not on a
 * lane now: in a junction, say). */
static inline fw_status fw_source_lane(fw_source *s, const char *id, fw_lane_info *out,
                                       fw_error *err)
{
    if (!s->ops->lane)
        return fw_fail(err, FW_EINPUT, "the %s source has no lanes ('%s')", s->ops->name, id);
    return s->ops->lane(s, id, out, err);
}
/* Ships' lanes as their source last said them, for judging encounters
 * (lane.h fw_lanes_meet): a ship's lane is read again once the one kept is
 * FW_LANE_REFRESH_S old, and a ship whose lane cannot be said now (in a
 * junction) keeps the last one said for FW_LANE_KEEP_S (its line runs on
 * along its route).  Keyed by fw_target.key; zero-initialised is empty. */
#define FW_LANE_REFRESH_S 10.0
#define FW_LANE_KEEP_S 120.0
typedef struct fw_lane_entry fw_lane_entry;
typedef struct fw_lane_cache {
    fw_lane_entry **v; /* by key - 1; NULL: none yet */
    int cap;
} fw_lane_cache;
/* Ship s's lane at time t into *out (NULL: none known: a source without
 * lanes, a ship without a key, or none said for FW_LANE_KEEP_S), valid
 * until the cache is freed (its contents until s's next read); FW_ERUN
 * when the source fails or memory runs out. */
fw_status fw_lane_cache_get(fw_lane_cache *c, fw_source *src, const fw_target *s, double t,
                            const fw_lane_info **out, fw_error *err);
void fw_lane_cache_free(fw_lane_cache *c);

static inline double fw_source_time(const fw_source *s) { return s->ops->time(s); }
static inline double fw_source_step_length(const fw_source *s) { return s->ops->step_length(s); }
/* Safe on NULL. */
void fw_source_destroy(fw_source *s);

/* ---- the kinematic source ---- */

enum { FW_KIN_MAX_LEGS = 8 };

/* One scripted ship: from t = 0 on its first leg; at each later leg's
 * t_start it takes that leg's course and speed at once (a script, not a ship
 * manoeuvre: for tests of what the own ship does when a target alters).
 * Taken (take), it is where steer puts it; given back, its script goes on
 * from the foot of the perpendicular from where it is onto its leg of that
 * time (the leg moved along itself), at the leg's course and speed. */
typedef struct fw_kin_ship {
    fw_target start;  /* id, type, position, course, speed, size at t = 0 */
    int n_legs;       /* further legs, 0 = constant velocity throughout */
    struct { double t_start, course, speed; } legs[FW_KIN_MAX_LEGS];
} fw_kin_ship;

typedef struct fw_kinematic_def {
    const fw_kin_ship *ships; /* copied */
    int n;
    double step;              /* s, > 0 */
    double radius;            /* m, sight: hull centre to hull centre; INFINITY = all */
    double area_radius;       /* m, 0 = no area query */
    const char *own_id;       /* the own ship's id in area lists */
    /* lane(): a ship's lane is its leg now (its line 10 km back to 50 km
     * ahead) with this sea room on each side (m; INFINITY: open water) */
    double room;
} fw_kinematic_def;

/* No ships, step 1 s, sight unlimited, no area, own id "own", open water. */
fw_kinematic_def fw_default_kinematic_def(void);

/* FW_EINPUT on a bad def (duplicate or empty id, non-finite value, legs out
 * of time order). */
fw_status fw_kinematic_source_create(const fw_kinematic_def *def, fw_source **out,
                                     fw_error *err);

#endif
