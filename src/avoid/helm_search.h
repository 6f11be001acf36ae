/* helm_search.h - the paper's helm search (its Figure 21) over predicted tracks.
 *
 * For each permitted side, the least helm from min_helm to max_helm (step
 * 1 deg) whose Nomoto-predicted own track keeps every target (constant
 * velocity) outside the own domain over the horizon; if none does, the helm
 * whose nearest target stays farthest out.  Tracks depend only on the own
 * state, so a context computes each at most once per decision, lazily, and
 * only as far as a check looks along it (a candidate that lets a target in is
 * predicted up to that point only), and mirrors the port tracks from the
 * starboard ones when the start is symmetric.  Checks go chunk by chunk in
 * time, culled with bounding boxes in space and time and with each target's
 * reach window (how far the own ship can have gone; one test for a target out
 * of reach over the whole horizon), below a cap under 1 by a
 * chunk's own lower bound, then segment by segment with a cheap lower bound
 * before the exact ellipse test; all the tracks of one decision start from
 * one fw_track_origin.  The results are
 * those of the plain search to the bit (tests/test_decide.c compares them with
 * tests/helm_reference.c, the search before these shortcuts).
 */
#ifndef FW_HELM_SEARCH_H
#define FW_HELM_SEARCH_H

#include <stdbool.h>

#include "avoid/encounter.h"
#include "nomoto/track.h"
#include "ship/ship.h"

enum { FW_SIDE_PORT = -1, FW_SIDE_NONE = 0, FW_SIDE_STARBOARD = 1 };
/* "starboard", "port", "none": the one spelling, for logs and files. */
const char *fw_side_name(int side);
/* masks of permitted sides */
enum { FW_ALLOW_STARBOARD = 1, FW_ALLOW_PORT = 2, FW_ALLOW_EITHER = 3 };

typedef struct fw_helm_def {
    double min_helm_deg;   /* 10: the paper's minimum effective avoidance helm */
    double max_helm_deg;   /* 35: the ship's turning-test maximum */
    double step_deg;       /* 1 */
    int overtake_side;     /* overtaking: 0 = the side needing less helm (ties:
                              starboard), FW_SIDE_STARBOARD or FW_SIDE_PORT */
    fw_domain_def domain;
    fw_colregs_def colregs;
    fw_track_def track;
} fw_helm_def;

fw_helm_def fw_default_helm_def(void);

typedef struct fw_helm_ctx fw_helm_ctx;

/* The band a decision's tracks must keep to (policy.h: a channel about the
 * route): the strip along the line through (east, north) on `course`
 * (rad), room_starboard to its starboard and room_port to its port (m; 0 on
 * a side: no edge there).  A track leaves it where some sample is farther
 * out of the strip than the own ship starts by more than FW_BAND_SLACK_M
 * (or its end carried FW_BAND_AHEAD_S on is): a
 * ship already out is asked not to go farther, not to jump back.  With a
 * band, a candidate that leaves it keeps no target out (fw_helm_search) and
 * is no fallback either, and fw_helm_steer_clearance reports such a track
 * below 0.  off: no band (every output as before bands). */
typedef struct fw_helm_band {
    bool on;
    double east, north, course; /* m, m, rad */
    double room_starboard, room_port; /* m */
} fw_helm_band;

#define FW_BAND_SLACK_M 1.0
/* s: a track is also judged where its last sample's motion (from the sample
 * before) takes it this much later: a candidate that ends its horizon
 * heading for the edge (a hard turn slows the ship, and it reaches the edge
 * only just after) leaves the band as surely as one that crosses it inside
 * the horizon (a bend-channel run at density 2 turned 26 deg towards a ship
 * alongside, so, and collided) */
#define FW_BAND_AHEAD_S 120.0

/* m: how much farther out of band b than its first sample track tr goes
 * (0: it keeps within, or b is off). */
double fw_track_band_excess(const fw_helm_band *b, const fw_track *tr);

/* The ship must outlive the context. */
fw_status fw_helm_ctx_create(const fw_ship *ship, const fw_helm_def *def, fw_helm_ctx **out,
                             fw_error *err);
void fw_helm_ctx_destroy(fw_helm_ctx *ctx);

/* Starts a decision for this own state: forgets all tracks. */
void fw_helm_begin(fw_helm_ctx *ctx, const fw_own_state *own);
/* The band for the searches from now on (NULL or off: none); kept from
 * decision to decision until set again. */
void fw_helm_set_band(fw_helm_ctx *ctx, const fw_helm_band *band);

/* Number of candidate helms per side and the helm (rad, signed) of candidate i. */
int fw_helm_count(const fw_helm_ctx *ctx);
double fw_helm_value(const fw_helm_ctx *ctx, int side, int i);

/* Candidate track (computed on first use), and the keep-course track (rudder
 * ordered amidships from the present state). */
fw_status fw_helm_track(fw_helm_ctx *ctx, int side, int i, const fw_track **tr, fw_error *err);
fw_status fw_helm_keep_track(fw_helm_ctx *ctx, const fw_track **tr, fw_error *err);
/* Computes every candidate track now (benchmark baseline). */
fw_status fw_helm_precompute(fw_helm_ctx *ctx, fw_error *err);
int fw_helm_tracks_computed(const fw_helm_ctx *ctx);
/* The samples predicted this decision, in whole tracks (a candidate is
 * predicted only as far as its check looks; mirrored ones not counted). */
double fw_helm_tracks_predicted(const fw_helm_ctx *ctx);

/* Smallest normalised domain radius of any target along a track (>= 1: all
 * outside); *limiting gets that target (-1 if n = 0).  With stop_below > 0 it
 * returns as soon as a value below it is found (a fail/pass test). */
double fw_track_clearance(const fw_helm_def *def, const fw_track *tr, const fw_target *t, int n,
                          double stop_below, int *limiting);

/* Closest centre distance to one target along a track, and when. */
double fw_track_min_distance(const fw_track *tr, const fw_target *t, double *t_min);

/* The sides COLREGs permit against the threats (targets whose assessment says
 * they enter the domain): starboard only for head-on and give-way crossing
 * (and for a stand-on ship against a target on its port side: rule 17 forbids
 * a port turn then); overtaking per def->overtake_side; else either.  A
 * target out of sight (assessment rule19, restricted visibility): rule
 * 19(d) instead, whatever the situation: starboard only for one forward of
 * the beam (either for one the own ship overtakes), away from one abeam or
 * abaft the beam (port for one on the starboard side, starboard for one on
 * the port side).  Sides that exclude each other: starboard. */
int fw_permitted_sides(const fw_helm_def *def, const fw_assessment *as, int n);
/* Rule 19(d)'s sides (FW_ALLOW_*) against one ship not in sight: no
 * alteration of course to port for a ship forward of the beam, other than
 * one being overtaken (by the own ship); none towards a ship abeam or abaft
 * the beam. */
int fw_rule19_sides(const fw_assessment *a);

typedef struct fw_helm_result {
    bool threat;         /* keeping course lets some target into the domain */
    bool feasible;       /* some helm on a permitted side keeps all targets out */
    int allowed;         /* FW_ALLOW_* used */
    int side;            /* chosen side, FW_SIDE_NONE if no threat */
    double helm;         /* rad, signed order: the least clearing helm, or if none
                            clears, the one with the largest clearance */
    double clearance;    /* min normalised domain radius along the chosen track */
    double keep_clearance; /* the same along the keep-course track */
    int limiting;        /* target closest to the domain on the chosen track */
    double side_helm[2]; /* rad, least clearing helm [0] starboard [1] port; NAN if none/not searched */
    bool band_left;      /* with a band: a threat, and every candidate on the allowed sides
                            leaves the band (then side FW_SIDE_NONE, helm 0, clearance the
                            keep-course one) */
} fw_helm_result;

/* One decision: keep-course check, then the search on the allowed sides;
 * with a band (fw_helm_set_band) over the candidates that keep within it. */
fw_status fw_helm_search(fw_helm_ctx *ctx, const fw_target *t, int n, int allowed,
                         fw_helm_result *res, fw_error *err);

/* Does a track with `helm` started after waiting `delay` s keep all targets
 * out?  (For the action policy: would the minimum helm still do later?)
 * This and fw_helm_steer_clearance check against the targets as this
 * decision's fw_helm_search prepared them when given the same array and
 * count (the policy's calls): they must not have changed in between. */
fw_status fw_helm_clears_after(fw_helm_ctx *ctx, const fw_target *t, int n, double helm,
                               double delay, bool *clears, fw_error *err);

/* Clearance (smallest normalised domain radius, >= 1: all out; with a band,
 * a track leaving it by e m: -e / 1852, below 0) of the track
 * under a heading autopilot (nomoto/track.h): steadying on a heading, or the
 * return to the course.  For the policy, which then steers with the same
 * autopilot.  With `beyond` the track is continued past the horizon on its
 * last heading at constant velocity (the closest point of approach of every
 * target from there counts too): a return judged over the horizon alone would
 * meet, just beyond it, a ship converging slowly at the own speed, and the
 * verdict would change as the horizon slides. */
fw_status fw_helm_steer_clearance(fw_helm_ctx *ctx, const fw_target *t, int n,
                                  const fw_steer_def *ap, bool beyond, double *clearance,
                                  fw_error *err);

#endif
