/* steer.h - a background ship that alters course: its manoeuvring model and its helmsman.
 *
 * A background ship that must give way and has the sea room alters course to
 * starboard instead of slowing down (reactions.h decides when and by how
 * much); for as long as it steers itself it is taken from the traffic source
 * (world.h fw_world_take) and stepped by fairway as a Nomoto vessel
 * (vessel.h FW_DYN_NOMOTO) under the controller made here, then given back.
 *
 * Model (fw_steer_ship): first-order Nomoto, T r' + r = K delta, with
 *   K = K' U / L,  T = T' L / U,  K' = 0.548, T' = 0.497,
 * the non-dimensional indices of the C-3 (the ship whose manoeuvring the
 * project models, scenarios/ships/c3-mmg.yaml's 8-14 kn knowledge base,
 * identified from its MMG turning tests) at 12 kn and 15 deg of helm (its
 * MMG turning test there within 8.2 % RMS, test_steer): every background ship turns like a C-3 of its own
 * length at its own speed (a 150 m feeder at 16 kn holds 0.45 deg/s at 15
 * deg, a radius of about 7 ship lengths).  Fuller hulls (tankers, bulk
 * carriers) turn more readily at small helm and steady less readily than
 * that: not modelled.  The second-order terms are set to cancel (T2 = T3),
 * the speed is held (no speed loss in the turn), the rudder is limited to 35
 * deg and moves at 2.32 deg/s (SOLAS II-1/29.3.2: 35 deg on one side to 30
 * deg on the other in 28 s).
 *
 * Helmsman (fw_steer_controller_create), in three phases:
 *   alter    the course over ground of its lane at the ship plus the
 *            alteration (to starboard), and once it is `room` to starboard
 *            of its lane's line, that line's course at that offset (it never
 *            leaves its waterway), held until the ship it gives way to
 *            is past and clear: past, the range opening; clear, the
 *            course back to its lane passing it
 *            at the passing distance or more (or no closest approach
 *            ahead); a ship no longer in sight is past.  Past but its way
 *            back not yet clear, it steers the steepest course back, from
 *            the line of sight in 5 deg steps to its lane's course there
 *            (no farther off), that passes it at the passing distance and
 *            every other ship at half of it in the next 10 minutes
 *   return   back to its lane's centre line by line-of-sight guidance
 *            (look-ahead 4 ship lengths, at least 400 m), never crossing back
 *            at more than the alteration (at least 20, at most 45 deg); while that course would bring it
 *            within half the passing distance of a ship it sees in the next
 *            10 minutes (a ship of its lane, another coming back, one
 *            crossing ahead), it sails along its lane where it is if that
 *            clears them, else holds the course it makes good (rule 8(d):
 *            the alteration stands until they are past; rule 13: not across
 *            the bow of a ship it overtakes) if that does, else takes the
 *            one of the three that passes farthest; and while it is the
 *            stand-on ship of a crossing with risk (a ship that has it on
 *            her starboard side would pass within the passing distance of
 *            the course it makes good, in the next 15 minutes) it keeps that
 *            course where it clears the others (rule 17(a)(i)).  Each
 *            course back (and the one it holds) is judged both as a
 *            straight line from where it is and along the swing its helm
 *            gives it onto that course over the next 5 minutes, as at
 *            close quarters (below): the nearer pass counts
 *   done     on the line (hull centre and bow within 0.3 m of it, for the
 *            source's 1 m limit on giving back; the bow half a length ahead
 *            along its course over ground, as the source places it: in a
 *            cross-set the hull crabs) and its course along it: the world
 *            gives it back (world.h)
 * Headings are ordered by a proportional helm on the heading error (gain
 * from the model so the closed loop is critically damped with its time
 * constant L/U), at most 20 deg of helm (an officer's alteration, not a
 * crash turn); in a current the heading allows for the set (course over
 * ground is what is steered).
 * How the others expect it to move (its record's predictor, geom/turn.h):
 * while it turns, on turning at the rate its helm gives (K' U / L x helm,
 * or its present rate if faster) until it heads as its helmsman steers,
 * then straight on; steady, at constant velocity.
 * Speed: it sails at its own speed (the fastest the reactive traffic saw it
 * sail unhindered), and keeps its distance behind a ship ahead going its
 * way (within 45 deg of its course, in its path now or within 10 minutes)
 * as SUMO's ships do along a lane (networks/ships.add.xml: a gap of 200 m
 * plus 30 s at the leader's speed, closed or opened over a minute: it never
 * runs up on a lane-mate while off its lane or coming back); where it must
 * give way and no alteration clears it slows to 0.3 of its speed (rule
 * 8(e); the reactive traffic's floor), each for the next 10 s, looked at
 * again then.  At close quarters (a ship it would pass within a quarter of
 * the passing distance in the next 5 minutes, whatever the roles: rules
 * 2(b), 8(e), 17(b)) it takes, of the turns to starboard of its heading (10
 * to 90 deg, at most 60 deg off its lane) and its speeds (the one it sails,
 * its own, steerage way: taking the way off), the one that passes every ship
 * farthest over those 5 minutes, its speed changing at its rates below and
 * its heading swinging to the new course as its helm turns it (at most 20
 * deg of helm: K' / L x helm per metre run), if
 * that gains 50 m on going on as it is: it takes the way off where that
 * lets the other pass clear, and keeps or gets back its way where stopping
 * would leave it in a ship's path (a lane ship that can only slow runs onto
 * it).  Its speed orders change by at most
 * the background types' 0.05 m/s^2 up and 0.1 m/s^2 down, never below 1 m/s
 * (steerage way), and it is given back at the speed it has.
 * Wind acts on it no more than on SUMO's ships (neither has windage); a
 * current carries it (vessel.h: a Nomoto vessel's step).
 * While it steers itself it looks round every 10 s, as reactions.h's
 * officer does: a ship it must give way to (rules 14 and 15 from its own side)
 * that the course it steers would pass within 0.8 of the passing distance
 * in the next 15 minutes (one passing nearly as far is no new danger to a
 * ship that has acted) makes it alter further to starboard, by the least of
 * 20, 25, ... 60 deg that passes every ship it sees at the passing
 * distance, or else the least that passes that ship so and every other at
 * half of it (at most 60 deg off its lane; none: it slows, below),
 * and it gives way to that ship from then on.  Ships going its way (rule 13:
 * courses within 45 deg, and one of the two more than 22.5 deg abaft the
 * other's beam) never make it alter: one ahead it keeps its distance from
 * by speed (below), one astern is overtaking it and keeps clear (rule 13);
 * one converging from abeam on a course within 45 deg is crossing.
 * The other ships see it as a vessel and give way to it as the rules say
 * (reactions.h).
 */
#ifndef FW_WORLD_STEER_H
#define FW_WORLD_STEER_H

#include "avoid/encounter.h"
#include "geom/turn.h"
#include "ship/ship.h"
#include "traffic/source.h"
#include "world/vessel.h"

/* The non-dimensional Nomoto indices every steered background ship has. */
#define FW_STEER_K_ND 0.548
#define FW_STEER_T_ND 0.497

/* The model of a background ship of this Loa (m, > 0), breadth (m) and
 * type name (copied, cut to fit) into *out. */
void fw_steer_ship(double length, double breadth, const char *type, fw_ship *out);

typedef struct fw_alter_def {
    fw_lane_info lane;                 /* where it comes back to (source.h) */
    double alteration;                 /* rad, > 0: to starboard of its lane's course */
    char other[FW_TARGET_ID_MAX];      /* the ship it gives way to */
    double cpa;                        /* m, the passing distance it keeps */
    double room;                       /* m, the farthest to starboard of its line it goes */
    double length;                     /* m, its Loa */
    double breadth;                    /* m */
    double speed;                      /* m/s, its speed when nothing is in its way
                                          (0: its speed at the first decision) */
    double helm_max;                   /* rad, 20 deg */
    fw_turn_pred *pred;                /* kept up to date (NULL: none); must outlive
                                          every copy of the ship's record */
} fw_alter_def;

/* lane and other empty, alteration 30 deg, cpa 926 m, room unlimited, length 100 m,
 * breadth 16 m, speed 0, helm 20 deg. */
fw_alter_def fw_default_alter_def(void);

typedef enum fw_steer_phase { FW_STEER_ALTER, FW_STEER_RETURN, FW_STEER_DONE } fw_steer_phase;

fw_status fw_steer_controller_create(const fw_alter_def *def, fw_controller **out,
                                     fw_error *err);
/* Is c one (and then its phase)? */
bool fw_steer_controller_is(const fw_controller *c);
fw_steer_phase fw_steer_controller_phase(const fw_controller *c);
/* A further alteration it made since the last call (its course over ground
 * from, to, rad; the ship, FW_TARGET_ID_MAX room, and the situation): true
 * once for each. */
bool fw_steer_controller_news(fw_controller *c, double *from, double *to, char *other,
                              fw_situation *sit);


#endif
