/* band.h - the band about the route that the avoidance keeps to (policy.h):
 * how far the heading has turned from the active leg's course, counted
 * through every turn, and which sides still have room.  Internal to
 * src/avoid (policy.c). */
#ifndef FW_BAND_H
#define FW_BAND_H

#include "avoid/policy.h"

/* Is there a band (a route, and band_xte > 0)? */
bool fw_band_active(const fw_policy *p);

/* Counts the turn since the last step into p->dev (from the leg's course at
 * the first step). */
void fw_band_track(fw_policy *p, const fw_own_state *own);

/* The leg changed from course c_old to the active leg's: dev from the new. */
void fw_band_leg(fw_policy *p, double c_old);

/* The helm search's band (helm_search.h) for the active leg: the water
 * its waterway has about it (route.h room_starboard, room_port); off
 * without (open water: band_xte and band_turn alone, below) or without a
 * band. */
fw_helm_band fw_band_of(const fw_policy *p);

/* FW_ALLOW_* sides a new alteration still has room for: less than
 * band_turn - min_alteration turned that way and less than band_xte across
 * to that side.  FW_ALLOW_EITHER without a band. */
int fw_band_sides(const fw_policy *p, const fw_own_state *own);

/* In a channel (fw_band_of on, set in in->ctx), the FW_ALLOW_* sides an
 * alteration may take against the ships the own ship overtakes that would
 * enter its domain (in->as; rule 13: it keeps clear of them): away from each
 * across the active leg, never towards it and across its bow (a ship to port
 * of the own ship leaves starboard, one to starboard port; ships on both
 * sides leave none).  FW_ALLOW_EITHER without a channel: in open water the
 * side is the search's (helm_search.h overtake_side). */
int fw_band_overtaking_sides(const fw_policy *p, const fw_policy_input *in);

/* At (or past) the band's edge on side (FW_SIDE_*): turned band_turn that
 * way, or band_xte across to it. */
bool fw_band_edge(const fw_policy *p, const fw_own_state *own, int side);

/* m/s: the planned speed (the active leg's; 0 without a route). */
double fw_band_planned(const fw_policy *p);

/* m/s: the speed ordered when the domain cannot be kept and slowing keeps the
 * targets farther out (fw_band_least_bad): slow_factor of the planned speed,
 * not below kb's lowest fitted speed. */
double fw_band_slow(const fw_policy *p, const fw_nomoto_kb *kb);

/* m/s: rule 19(e)'s speed, "the minimum at which she can be kept on her
 * course": kb's lowest fitted speed (the lowest at which the policy's
 * predictions, and so its keeping of the course, hold; not the hull's
 * steerage way), not above the planned speed. */
double fw_rule19e_speed(const fw_nomoto_kb *kb, double planned);

/* STEADY at the band's edge: the heading held stays within band_turn of the
 * leg's course; once band_xte across, it becomes the leg's course if that
 * keeps every target out, else it is held and p->unkept set. */
fw_status fw_band_hold(fw_policy *p, const fw_policy_input *in, fw_error *err);

/* The domain cannot be kept: p->psi_hold becomes the least bad heading within
 * the band (the leg's course +-15, 30 .. band_turn deg, none further out past
 * band_xte; in a channel, fw_band_of on, the leg's course alone, parallel to
 * its edges: any other heading meets an edge within minutes, and one judged
 * clear at the slowed speed left it at the present one, so the ship steered it
 * and steadied back by turns): the one whose steering keeps the targets
 * farthest out, over the horizon and beyond (the return's check), the nearest
 * the course among equals (within 0.02 of the normalised domain radius);
 * p->slow: whether at the slowed speed (fw_band_slow) or the planned one,
 * whichever keeps them farther out on it, slowed among equals (each predicted
 * with the speed relaxing to it: nomoto/track.h fw_steer_def.U0); the heading
 * and speed in force (p->lb_k, p->slow while p->lb_held) are kept unless
 * another keeps the targets farther out by 0.1 of the domain (band.c
 * LEAST_BAD_KEEP: chosen afresh every step, the choice swung with the
 * rudder's and propeller's response to the last order).  Slowing
 * gives a ship ahead or crossing time and room (rule 8(e)); for one coming up
 * from astern or across the quarter it only lets it in sooner. */
fw_status fw_band_least_bad(fw_policy *p, const fw_policy_input *in, fw_error *err);

#endif
