/* geom.h - the plane geometry of ships, written once.
 *
 *   body frame   a point's offset from a ship: x ahead, y to starboard
 *   velocity     east/north components of a speed on a course
 *   CPA/TCPA     closest point of approach of two ships at constant velocity
 *   domain       the own ship's domain, an ellipse aligned with its heading,
 *                grown by the other ship's hull, or the paper's transverse
 *                clearance about the target (fw_domain_def below)
 *   hulls        do two oriented rectangles overlap (the collision test), how
 *                far apart are they, and how close would they come on straight
 *                tracks (the geometric collision candidate)
 *
 * Used by the assessment and the helm search (src/avoid), the records
 * (src/run), the survey (src/survey), the scenario checks and the oracle.
 * The small ones are inline: they sit in the helm search's inner loops, and one
 * definition keeps every caller's arithmetic the same to the bit.
 * Frame: metres east/north, headings navigational (0 north, clockwise), SI.
 */
#ifndef FW_GEOM_H
#define FW_GEOM_H

#include <math.h>
#include <stdbool.h>

#include "geom/target.h"

/* A counting threshold on a distance is passed only when the distance lies
 * below it by more than FW_DIST_RESOLUTION.  Positions are not known to a
 * decimetre (SUMO writes its networks to 0.01 m, AIS to about 0.2 m), and a
 * test that rounding can decide counts ships by accident: Dover's two ferry
 * routes lie exactly 1000 m apart, and three in four of the default study's
 * traffic encounters were ferry pairs whose DCPA came out as 999.99999...
 * against the survey's 1000 m.  With the margin, ships on parallel routes a
 * threshold apart are not encounters, and a real pass 999.5 m off still is. */
#define FW_DIST_RESOLUTION 0.1
static inline bool fw_clearly_below(double d, double threshold)
{
    return d < threshold - FW_DIST_RESOLUTION;
}

/* Offset (de, dn) east/north seen from a ship whose heading has sine s and
 * cosine c: x ahead, y to starboard. */
static inline void fw_to_body(double de, double dn, double s, double c, double *x, double *y)
{
    *x = de * s + dn * c;
    *y = de * c - dn * s;
}

/* Velocity components (m/s east, north) of speed v on course (rad). */
static inline void fw_velocity(double v, double course, double *ve, double *vn)
{
    *ve = v * sin(course);
    *vn = v * cos(course);
}

/* Closest approach of a point at relative position (dx, dy) moving with
 * relative velocity (vx, vy): time (s, negative if already passed; 0 with no
 * relative motion) and distance. */
static inline void fw_cpa(double dx, double dy, double vx, double vy, double *tcpa, double *dcpa)
{
    double v2 = vx * vx + vy * vy;
    double t = v2 > 1e-12 ? -(dx * vx + dy * vy) / v2 : 0.0;
    *tcpa = t;
    *dcpa = hypot(dx + vx * t, dy + vy * t);
}

/* The same with the distance squared: for loops over many pairs that only
 * compare it with a threshold (hypot's care for overflow costs there). */
static inline void fw_cpa_sq(double dx, double dy, double vx, double vy, double *tcpa,
                             double *dcpa2)
{
    double v2 = vx * vx + vy * vy;
    double t = v2 > 1e-12 ? -(dx * vx + dy * vy) / v2 : 0.0;
    double px = dx + vx * t, py = dy + vy * t;
    *tcpa = t;
    *dcpa2 = px * px + py * py;
}

/* The own domain: an ellipse centred on the own ship and aligned with its
 * heading.  Transverse semi-axis = size (the paper's 300 m "along the side");
 * fore-aft semi-axis = size * fore_aft_ratio.  Default ratio 1: the paper's
 * numbers (300 m passing distance, helms of 15-29 deg) are those of a 300 m
 * circle; Fujii and Tanaka's 8 L x 3.2 L ellipse (ratio 2.5) is for harbour
 * approaches and would be 750 m ahead at this size.  A target's hull counts
 * by growing each semi-axis by the target's half-extent along that own-ship
 * axis (L/2 |cos a| + B/2 |sin a| fore-aft, L/2 |sin a| + B/2 |cos a| abeam,
 * a = relative heading): the Minkowski sum of ellipse and rectangle, exact on
 * the axes and slightly generous between them.
 * The own hull counts likewise when own_half_length / own_half_breadth are
 * set (a scenario's avoidance.domain_from: hull, the default): the semi-axes
 * grow by them too, and the size is then a clearance between the hulls, so
 * that a size below the own half length (167 m for the C-3) still keeps the
 * bows apart.  Both 0: a domain about the own ship's centre (the paper's, and
 * its five cases and the Imazu set say domain_from: centre).
 *
 * The reading (avoidance.domain_reading):
 *   ellipse     the above (the default): the ellipse turns with the own
 *               heading, and the target's extent is projected on the own
 *               axes, so a head-on target passing an own ship that has turned
 *               45 deg must stay 382 m from its centre (300 + (100 + 16)
 *               x 0.707 for a 200 x 32 m target), not 316.
 *   transverse  the paper's: the clearance is measured from the target ship
 *               ("300 metres along the side of the moving ships", "a
 *               distance of 300 metres from the port side of the target
 *               ship" at the passing, a "transverse safe domain"): an ellipse
 *               centred on the target and aligned with the target's heading,
 *               size beyond its side (transverse semi-axis size + B/2) and
 *               size * fore_aft_ratio beyond its bow and stern (L/2 added);
 *               the own ship's centre, or with domain_from: hull its outline
 *               projected on the target's axes, must stay outside.  Abeam of
 *               the target it asks exactly size from the target's side
 *               whatever the own heading; for a target on the own ship's beam
 *               on a parallel course the two readings are the same. */
typedef enum fw_domain_reading { FW_DOMAIN_ELLIPSE, FW_DOMAIN_TRANSVERSE } fw_domain_reading;

/* "ellipse", "transverse"; parse: -1 for anything else. */
const char *fw_domain_reading_name(fw_domain_reading r);
int fw_domain_reading_parse(const char *text);

typedef struct fw_domain_def {
    double size;             /* m, transverse semi-axis (beyond the hulls, see above) */
    double fore_aft_ratio;   /* fore-aft / transverse */
    double own_half_length;  /* m, 0: centred on the own ship */
    double own_half_breadth; /* m */
    fw_domain_reading reading;
} fw_domain_def;

fw_domain_def fw_default_domain_def(void);

/* Semi-axes (fore-aft a, transverse b) of the domain grown by a hull of half
 * length hl and half breadth hb whose heading relative to the own ship has
 * cosine cos_rel and sine sin_rel; with the transverse reading the axes are
 * the target's (the own hull is the one projected). */
static inline void fw_domain_grown(const fw_domain_def *dom, double hl, double hb,
                                   double cos_rel, double sin_rel, double *a, double *b)
{
    double c = fabs(cos_rel), s = fabs(sin_rel);
    if (dom->reading == FW_DOMAIN_TRANSVERSE) {
        *a = dom->size * dom->fore_aft_ratio + hl + dom->own_half_length * c +
             dom->own_half_breadth * s;
        *b = dom->size + hb + dom->own_half_length * s + dom->own_half_breadth * c;
        return;
    }
    *a = dom->size * dom->fore_aft_ratio + dom->own_half_length + hl * c + hb * s;
    *b = dom->size + dom->own_half_breadth + hl * s + hb * c;
}

/* The domain's frame for an own ship heading (so, co) (sine, cosine) and a
 * target heading (ts, tc): the own heading (ellipse) or the target's
 * (transverse).  Offsets and relative velocities go into it by fw_to_body;
 * the normalised radius is then (x/a)^2 + (y/b)^2 with fw_domain_grown's axes
 * (cos_rel, sin_rel of the target heading less the own). */
static inline void fw_domain_frame(const fw_domain_def *dom, double so, double co, double ts,
                                   double tc, double *fs, double *fc)
{
    bool t = dom->reading == FW_DOMAIN_TRANSVERSE;
    *fs = t ? ts : so;
    *fc = t ? tc : co;
}

/* The same for target t. */
void fw_domain_axes(const fw_domain_def *dom, const fw_target *t, double cos_rel,
                    double sin_rel, double *a, double *b);

/* Normalised domain radius of target t now, for an own ship at (east, north)
 * heading psi: < 1 inside the (hull-grown) domain. */
double fw_domain_lambda(const fw_domain_def *dom, double east, double north, double psi,
                        const fw_target *t);

/* Centre distance beyond which target t is outside the domain whatever the
 * headings: the largest semi-axis plus the hull's half diagonal. */
double fw_domain_reach(const fw_domain_def *dom, const fw_target *t);

/* Oriented rectangles (centre, heading, length, breadth) overlap?  Separating
 * axis test on the four hull axes: the collision criterion of fairway. */
bool fw_hulls_overlap(double e1, double n1, double psi1, double l1, double b1, double e2,
                      double n2, double psi2, double l2, double b2);

/* Shortest distance between the two hull rectangles (0 when they overlap):
 * the hull-to-hull measure of closest approaches and near misses. */
double fw_hull_distance(double e1, double n1, double psi1, double l1, double b1, double e2,
                        double n2, double psi2, double l2, double b2);

/* A hull on a straight track: where it is, its heading (the rectangle's
 * orientation, kept), its velocity over ground and its size. */
typedef struct fw_hull_track {
    double east, north;  /* m, hull centre at t = 0 */
    double heading;      /* rad */
    double ve, vn;       /* m/s east, north */
    double length, breadth;
} fw_hull_track;

/* The track of target t: its course is heading and direction of motion. */
fw_hull_track fw_hull_track_of(const fw_target *t);

/* Smallest hull-to-hull distance of a and b moving on their straight tracks
 * over 0 <= t <= horizon (INFINITY: all the future), and when (t_min may be
 * NULL).  0 means the hulls would come into contact: the two ships are a
 * geometric collision candidate in the sense of Pedersen (1995) and IWRAP,
 * "ships that would collide if no aversive manoeuvre were made", taken per
 * encounter from its first detection.  Exact up to rounding: the headings
 * stay fixed, so the distance is the distance of a point moving on a line
 * from a convex set (the Minkowski difference of the rectangles), a convex
 * function of t, minimised by golden-section search on a bracket around the
 * centres' closest approach that holds every minimiser. */
double fw_hull_cpa(const fw_hull_track *a, const fw_hull_track *b, double horizon, double *t_min);

#endif
