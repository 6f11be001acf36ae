/* reactions.h - background ships that give way by COLREGs: the reactive traffic.
 *
 * SUMO moves its ships along their lanes and never yields: at a crossing
 * nobody gives way, and no ship ever keeps out of the own ship's way.  With
 * behaviour `colregs` (the default; `blind` is SUMO's own, the worst case)
 * every background ship the own ship sees is checked each step against every
 * ship near it, the own ship included:
 *
 *   risk        both keeping course, and each its own speed (for a
 *               background ship the fastest it has gone untold: what it
 *               means to do), the closest approach comes within cpa in less
 *               than horizon seconds (and it is ahead)
 *   role        from the ship's own side (avoid/encounter.h, rules 13-17):
 *               it gives way to a ship crossing from its starboard side
 *               (rule 15) and to the own ship when it overtakes it (rule 13;
 *               one background ship overtaking another in its lane is kept
 *               apart by SUMO's car following and lane changes)
 *   action      it slows down (rule 8(e): slacken speed to avoid collision;
 *               rule 16: early and substantial), to the fastest of the speeds
 *               from its own down to min_speed of it (in 5 % steps) at which
 *               every ship it gives way to passes at cpa or more; if none does,
 *               to the one that passes farthest (and the record says so): the
 *               closest pass compared first, then the next closest, so that a
 *               ship passing near at any speed does not hide one it must give
 *               way to (a ship holding a speed taken for another judges a new
 *               one anew).  A lane-bound ship has
 *               no other readily apparent action than its speed.
 *   resumption  once at its former speed it would pass every such ship at
 *               1.25 cpa or more, or they are past, it is given its speed back
 *               (the margin: given back at cpa exactly it would have to give
 *               way again a few steps later)
 *
 * Each ship looks round every `interval` seconds (10: an officer of the watch,
 * not a controller; the ships' looks are spread over the interval).
 * A stand-on ship keeps course and speed (rule 17(a)): nothing is ordered,
 * until the other has come so close (DCPA below last_cpa within last_time s)
 * that its action alone cannot avoid a collision: then it takes the speed,
 * down to min_speed of its own, that passes farthest (rule 17(b)), or, where
 * none of those passes at last_cpa, slower still, down to steerage way (1
 * m/s: rule 8(e), it takes the way off; lane-bound, it has no other action),
 * and its own speed back once that is no longer so.
 * In restricted visibility (colregs.visibility > 0) a ship farther off than
 * it is out of sight: rule 19 replaces the roles, and a ship at risk with one
 * forward of its beam gives way to it (slows) whichever side it is on; for
 * one abeam or abaft it does nothing (its only action, slowing, would not
 * take it away).  Rule 19(e): if it hears the fog signal of such a ship
 * forward of its beam (within the range of audibility of the other's
 * whistle by its length, COLREGs Annex III 1(c): 2 nm for 200 m or more,
 * 1.5 nm from 75 m, 1 nm from 20 m, 0.5 nm below; every ship is taken to
 * sound it, rule 35), or no speed keeps every ship at cpa (the
 * close-quarters situation it cannot avoid) with the nearest out of sight
 * forward of its beam, it reduces speed to min_speed of its own (the least
 * the model orders a lane-bound ship: taken as the speed at which she can
 * be kept on her course) and holds it until the danger is over (the
 * resumption below); the record says rule 19(e).
 * With a watch (watch.h) a ship notices a ship it must give way to only after
 * a delay, or not at all (a lapse); until then it treats it as not there.
 * Head-on meetings of two lane-bound ships are kept apart by their lanes;
 * the own ship's policy turns.  Two background ships on the lanes of one
 * waterway are judged by their lanes (traffic/lane.h, read through the
 * source and kept while a ship is in a junction): coming the other way down
 * each other's lanes they are head-on (encounter.h fw_classify_lanes), round
 * a bend too, and one ahead of the other of one stream they share the lanes
 * like ships on parallel courses.
 *
 * give_way: speed (the above: slowing down as if a lane-bound ship had no
 * other action) or course (the default): a give-way ship alters course to starboard (rules 8,
 * 15, 16), by the least of alter_min, alter_min + 5 deg, ... alter_max (20
 * and 60 deg: at least 20 deg is readily apparent to another ship, rule 8(b),
 * by eye and on radar) at which it passes every ship near it at cpa or more
 * on its new course at its own speed, if its lane has the sea room to
 * starboard for it (its sideways run until the closest approach, with its
 * half breadth and a tenth of the room to spare: source.h lane()); and a
 * ship meeting the own ship head-on alters to starboard likewise (rule 14;
 * nothing if it has no room).  Where no alteration clears or there is no
 * room, or the ship is changing lanes (its source says so, or it is more
 * than 10 m or 2 deg off its lane's line: SUMO's continuous lane change
 * outlives a take and a give back and would go on, stale, from where it
 * was), it slows down as above;
 * and an overtaking ship (rule 13) keeps out of the way by its speed (not
 * overtaking), since the ship it would overtake may itself be moving off
 * to starboard; overtaking a ship fairway steers it does nothing while
 * that ship leaves its way (on the course it is turning to it passes at
 * half cpa or more and is not closing its track sideways: it keeps its lane
 * and passes, and a speed it was held at for that ship is given back), and
 * it alters course to starboard, where it can, to pass one steered into its
 * way from its port side.  A ship that has slowed and whose speed no longer keeps
 * the passing distance tries an alteration first too, as one that has not
 * slowed does (rules 8(c) and 8(d)), and slows further only where it finds
 * none.  Every speed order says why it is not an alteration (fw_reaction
 * why; run.log "(not altering: ...)").  A ship that alters course is handed to
 * the world to steer (fw_reactions_takes; world/steer.h says how it turns,
 * when it comes back, and how) and given back to its lane after.
 * Every order is recorded (ship, time, kind, speeds or courses, the ship it
 * gives way to).
 *
 * Sensing (def.sensing; perfect by default, the truth as above): every ship
 * decides on what it knows of the others (reactions_sense.c), itself exact:
 *   AIS (modes ais, ais+radar)  every ship in the list (the background ships
 *            and fairway's vessels) sends its reports (sense/sensing.h
 *            fw_ais_tx: the standard's intervals, noise, losses, delay,
 *            dead reckoning, stale_s), drawn from its streams
 *            FW_PURPOSE_AIS_TX and _LOSS (not the own ship's sensor's: the
 *            own ship hears other draws of the same law); a report is one
 *            broadcast, heard by every background ship alike, a lost one
 *            lost to all.  Stepped every step for every ship in the list.
 *   eye      a ship without a current report within sight (the visibility;
 *            always in clear weather) is seen as it is
 *   radar (modes radar, ais+radar)  a ship out of sight without a report
 *            is known by the looking ship's own radar and tracker (a
 *            sense/sensing.h sensor per ship, its links keyed by the pair),
 *            fed at each look round (the scans since the last, the truth
 *            moved back along its velocity to each) with only those ships:
 *            within range, out of sight, without a report
 *   else     not known: not given way to, not avoided.
 * A record says how the acting ship knew the other and where it took it to
 * be beside where it was (fw_reaction known_*).  A ship taken to steer
 * (give_way course, world/steer.h) sees through the same reports
 * (fw_reactions_known: the reports as of the last reactions step, dead
 * reckoned to now; in sight without one, seen), but has no radar: a ship
 * out of its sight without a report is not in its view.  Not modelled:
 * per-receiver AIS losses, what a ship sees of a ship in sight (the truth).
 */
#ifndef FW_WORLD_REACTIONS_H
#define FW_WORLD_REACTIONS_H

#include "avoid/encounter.h"
#include "core/error.h"
#include "geom/target.h"
#include "sense/sensing.h"
#include "traffic/source.h"
#include "world/watch.h"

typedef enum fw_behaviour { FW_BEHAVIOUR_COLREGS, FW_BEHAVIOUR_BLIND } fw_behaviour;

/* How a give-way background ship acts (above). */
typedef enum fw_give_way { FW_GIVE_WAY_SPEED, FW_GIVE_WAY_COURSE } fw_give_way;
/* "speed", "course"; parse: FW_EINPUT for anything else. */
const char *fw_give_way_name(fw_give_way g);
fw_status fw_give_way_parse(const char *text, fw_give_way *out);

/* "colregs", "blind"; parse: FW_EINPUT for anything else. */
const char *fw_behaviour_name(fw_behaviour b);
fw_status fw_behaviour_parse(const char *text, fw_behaviour *out);

typedef struct fw_reactions_def {
    fw_behaviour behaviour;
    double cpa;           /* m, 926 (0.5 nm): the passing distance a give-way ship keeps */
    double horizon;       /* s, 900: acts once the closest approach is this close in time */
    double range;         /* m, 8000: ships farther apart are not looked at */
    double min_speed;     /* 0.3: the fraction of its speed it may slow to */
    double parallel;      /* rad, 30 deg: background ships on courses closer than this
                             share the lanes and are SUMO's to keep apart */
    double last_cpa;      /* m, 463 (0.25 nm) ... */
    double last_time;     /* s, 240: a stand-on ship this close this soon acts (rule 17(b)) */
    double interval;      /* s, 10: each ship looks round this often (0: every step) */
    fw_colregs_def colregs;
    fw_watch_def watch;   /* its watchkeeping (watch.h): flawless by default */
    fw_give_way give_way; /* course (default) or speed */
    double alter_min, alter_max; /* rad, 20 and 60 deg: the course alterations tried */
    /* the sea room is the lanes' (room_from_lanes: a channel, where the
     * edge of the lanes is the edge of the water; room_traffic_lanes: on a
     * separation scheme's traffic lanes only (source.h fw_lane_info), whose
     * ships proceed in their lane, rule 10(b)(i): an alteration that needs
     * more room than the lane has is not taken, the ship slows instead) or
     * unlimited (neither: open sea, and a ferry's route across a scheme);
     * room_from_lanes by default, scenarios set them from traffic.waterway */
    bool room_from_lanes;
    bool room_traffic_lanes;
    /* what they know of the others (Sensing, above): perfect by default */
    fw_sensing_def sensing;
} fw_reactions_def;

fw_reactions_def fw_default_reactions_def(void);

/* slow: a speed order; resume: its own speed back; alter: a course
 * alteration (the ship taken to steer); rejoin: given back to its lane */
typedef enum fw_reaction_kind {
    FW_REACT_SLOW,
    FW_REACT_RESUME,
    FW_REACT_ALTER,
    FW_REACT_REJOIN
} fw_reaction_kind;

/* How the acting ship knew the other (Sensing, above). */
typedef enum fw_known {
    FW_KNOWN_TRUTH,  /* perfect sensing */
    FW_KNOWN_NOT,    /* not known (never in a record) */
    FW_KNOWN_AIS,    /* by its AIS reports */
    FW_KNOWN_EYE,    /* in sight, without a report: seen */
    FW_KNOWN_RADAR   /* out of sight, without a report: the ship's radar track */
} fw_known;

/* Why a give-way ship slowed down (FW_REACT_SLOW) instead of altering course
 * (give_way course; FW_WHY_NONE with give_way speed and for a ship that
 * speeds up): fw_speed_why_name gives the words run.log prints. */
typedef enum fw_speed_why {
    FW_WHY_NONE,
    FW_WHY_OVERTAKING,  /* rule 13: it keeps out of the way by its speed */
    FW_WHY_NO_LANE,     /* in a junction: no lane to come back to */
    FW_WHY_LANE_CHANGE, /* in the middle of a lane change */
    FW_WHY_NO_ROOM,     /* an alteration clears, but its lane's edge is too near */
    FW_WHY_NO_CLEAR,    /* no alteration of alter_min..alter_max passes every ship at cpa */
    FW_WHY_RULE17,      /* a stand-on ship acting under rule 17(b) */
    FW_WHY_RULE19       /* rule 19(e) in restricted visibility */
} fw_speed_why;

const char *fw_speed_why_name(fw_speed_why w);

typedef struct fw_reaction {
    double t;                        /* s */
    char ship[FW_TARGET_ID_MAX];     /* the ship that acts */
    char other[FW_TARGET_ID_MAX];    /* the ship it gives way to (the nearest in time) */
    fw_reaction_kind kind;
    fw_situation situation;          /* from the acting ship's side */
    double speed_from, speed_to;     /* m/s ordered: from, to (resume: to its own) */
    double dcpa_before, dcpa_after;  /* m, the closest approach at the old and new speed
                                        (alter: course) */
    bool enough;                     /* the new speed keeps cpa against every ship */
    double course_from, course_to;   /* rad, alter: its course and the one ordered */
    /* how it knew `other`, where it took it to be and where it was (m) */
    fw_known known_how;
    double known_e, known_n, true_e, true_n;
    bool rule19e;                    /* slowed to min_speed by rule 19(e) (above) */
    fw_speed_why why;                /* slow: why not a course alteration */
} fw_reaction;

/* A ship to take from the source and steer (give_way course): itself as it
 * is now, its lane, the alteration (rad, to starboard), the ship it gives
 * way to and the passing distance. */
typedef struct fw_take_order {
    fw_target ship;
    fw_lane_info lane;
    double alteration;
    char other[FW_TARGET_ID_MAX];
    double cpa;
    double speed;      /* m/s, the speed it sails when nothing is in its way */
} fw_take_order;

typedef struct fw_reactions fw_reactions;

fw_status fw_reactions_create(const fw_reactions_def *def, fw_reactions **out, fw_error *err);
void fw_reactions_destroy(fw_reactions *r);

/* One step at time t: the background ships seen and the nv vessels fairway
 * steps (world.h: the own ship and any other, a ship taken from the source
 * among them), which are given way to as the own ship is and never told
 * anything; orders go to src.  Does nothing with behaviour blind. */
fw_status fw_reactions_step(fw_reactions *r, double t, const fw_target *vessels, int nv,
                            const fw_target *ships, int n, fw_source *src, fw_error *err);

/* The world's streams, for a watch that draws (watch.h). */
void fw_reactions_set_rng(fw_reactions *r, fw_rng_getter rng, void *ctx);
/* Encounters its watch met and of them those it lapsed (0, 0: flawless). */
void fw_reactions_watch_counts(const fw_reactions *r, long *pairs, long *lapsed);
/* A split's branch at t: the watch's undetected ships drawn afresh (watch.h fw_watch_redraw). */
int fw_reactions_redraw(fw_reactions *r, double t);
void fw_reactions_mix_counts(const fw_reactions *r, long counts[FW_BEH_N]);

/* What ship self (a ship fairway steers for the traffic) knows at t of
 * ship o (Sensing, above) into *out: false when it does not know it (out of
 * sight without a current AIS report).  Perfect sensing: o itself. */
bool fw_reactions_known(const fw_reactions *r, const fw_target *self, const fw_target *o,
                        double t, fw_target *out);

/* Does it do anything (behaviour colregs)? */
bool fw_reactions_active(const fw_reactions *r);

/* Every order so far, in time order; valid until the next step. */
const fw_reaction *fw_reactions_list(const fw_reactions *r, int *n);

/* The ships the last step decided to take and steer (give_way course), in
 * the order decided; valid until the next step.  The world takes them. */
const fw_take_order *fw_reactions_takes(const fw_reactions *r, int *n);

/* A record of the world's (a ship given back: FW_REACT_REJOIN) added. */
fw_status fw_reactions_note(fw_reactions *r, const fw_reaction *x, fw_error *err);

#endif
