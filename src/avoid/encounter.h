/* encounter.h - what each target means to the own ship right now.
 *
 * Per target: range, bearings, DCPA/TCPA (constant velocities: the
 * instantaneous CPA, as a radar's), the COLREGs situation (rules 13-17) by
 * named thresholds, whether it is out of sight in restricted visibility
 * (rule 19 then governs: policy.h, helm_search.h), and whether and when it enters the own domain with the own
 * ship keeping course and speed and the target moving as its predictor says
 * (constant velocity without one: closed form; with one: its path sampled
 * every 5 s); then a danger ranking.
 * Geometry (domain, CPA, body frame) is geom/geom.h's; the ship record is
 * fw_target (geom/target.h).  Frames: metres east/north, navigational
 * headings, SI.
 */
#ifndef FW_ENCOUNTER_H
#define FW_ENCOUNTER_H

#include <stdbool.h>

#include "geom/geom.h"
#include "nomoto/track.h"
#include "traffic/lane.h"



typedef enum fw_situation {
    FW_SIT_HEAD_ON,        /* rule 14: both alter to starboard */
    FW_SIT_OVERTAKING,     /* rule 13: own ship overtakes, keeps out of the way */
    FW_SIT_OVERTAKEN,      /* rule 13/17: target overtakes, own ship stands on */
    FW_SIT_GIVE_WAY,       /* rule 15/16: crossing, target on own starboard side */
    FW_SIT_STAND_ON,       /* rule 15/17: crossing, target on own port side */
} fw_situation;

const char *fw_situation_name(fw_situation s);

/* Thresholds of the classification, in degrees because people set them. */
typedef struct fw_colregs_def {
    /* head-on: each ship within this of the other's bow ... */
    double head_on_bearing_deg;      /* 6: half a point, "ahead or nearly ahead" */
    /* ... and courses within this of reciprocal */
    double head_on_course_tol_deg;   /* 15 */
    /* overtaking: "more than 22.5 deg abaft the beam" = relative bearing
     * strictly between this and 360 minus this */
    double overtake_sector_deg;      /* 112.5 */
    /* danger ranking (the paper, section 3.5): of two targets entering the
     * domain, the one that comes within this range first is the more
     * dangerous; m, 0 = off (then earliest domain entry first).  The policy
     * sets it to its action distance. */
    double rank_range_m;
    /* m, restricted visibility (the scenario's environment.visibility_nm):
     * ships farther apart are not in sight of one another (rule 3(k)) and
     * rule 19 governs them instead of rules 11-18; 0 = clear, every ship in
     * sight (the default) */
    double visibility;
} fw_colregs_def;

fw_colregs_def fw_default_colregs_def(void);

typedef struct fw_assessment {
    double range;        /* m */
    double bearing;      /* rad, true bearing of the target [0, 2 pi) */
    double rel_bearing;  /* rad, from the own bow, clockwise [0, 2 pi) */
    double dcpa, tcpa;   /* m, s (tcpa < 0: closest point already passed) */
    fw_situation situation;
    bool enters_domain;  /* within the horizon, both keeping course and speed */
    double t_enter;      /* s, 0 if inside now, INFINITY if never */
    double min_lambda;   /* smallest normalised domain radius (< 1 = inside) */
    double t_range;      /* s, when the range first falls to rank_range_m at constant
                            velocities (0 if within it now or the rule is off) */
    int rank;            /* 0 = most dangerous */
    bool rule19;         /* not in sight (range > visibility): rule 19, not 13-17 */
} fw_assessment;

fw_situation fw_classify(const fw_colregs_def *def, const fw_own_state *own,
                         const fw_target *t);

/* fw_classify for two ships whose lanes are known (lane.h; NULL: not on a
 * lane): ships meeting along one waterway (fw_lanes_meet) are head-on
 * (rules 9 and 14: round a bend they meet, they do not cross), whatever
 * their bearings; ships one ahead of the other along it (fw_lanes_along)
 * that fw_classify calls crossing are overtaking (the faster, own->U
 * against t->speed) or being overtaken. */
fw_situation fw_classify_lanes(const fw_colregs_def *def, const fw_own_state *own,
                               const fw_target *own_ship, const fw_lane_info *own_lane,
                               const fw_target *t, const fw_lane_info *t_lane);

/* fw_assess's situations again where lanes are known: as[i].situation =
 * fw_classify_lanes for each target with a lane (lanes[i] non-NULL), the
 * own ship's lane own_lane (its route: route.h fw_route_lane).  The own
 * ship meeting a channel's traffic round a bend is then head-on, as the
 * background ships judge it (rules 9 and 14), not crossing.  Ranks and
 * domain entries are unchanged (they do not depend on the situation). */
void fw_assess_lanes(const fw_colregs_def *def, const fw_own_state *own,
                     const fw_lane_info *own_lane, const fw_target *t,
                     const fw_lane_info *const *lanes, int n, fw_assessment *as);

/* Is a ship at this range out of sight (rule 19 governs)? */
static inline bool fw_not_in_sight(const fw_colregs_def *def, double range)
{
    return def->visibility > 0.0 && range > def->visibility;
}

/* m: the range of audibility of a ship's whistle (its fog signal, rule 35)
 * by its length, COLREGs Annex III 1(c): rule 19(e)'s "hears the fog signal". */
double fw_fog_signal_range(double length);

/* Fills out[0..n-1].  If order is not NULL (room for 2 n ints: the second
 * half is scratch) it gets the target indices most dangerous first and each
 * out[i].rank is set: targets entering the domain first; among those, the one
 * reaching rank_range_m first (the paper's rule: in its case 5 the crossing
 * ship comes within 1 nm at 107 s, before the head-on ship at 124 s, and is
 * "more dangerous"), then the earliest entry; then smallest DCPA, then
 * smallest range. */
void fw_assess(const fw_colregs_def *cdef, const fw_domain_def *dom, double horizon,
               const fw_own_state *own, const fw_target *t, int n, fw_assessment *out,
               int *order);

/* fw_assess without ranks, for a reader that needs of a target with a
 * predictor only whether and when it enters the domain (enters_domain and
 * t_enter, to the bit fw_assess's): its min_lambda is NAN, and the parts of
 * its path that cannot be within the domain are not looked at (the run's
 * records of the truth, whose predicted paths are the costly part).  Every
 * other field as fw_assess's. */
void fw_assess_entries(const fw_colregs_def *cdef, const fw_domain_def *dom, double horizon,
                       const fw_own_state *own, const fw_target *t, int n, fw_assessment *out);

#endif
