/* encounter.h - what each target means to the own ship right now.
 *
 * Per target: range, bearings, DCPA/TCPA (constant velocities), the COLREGs
 * situation (rules 13-17) by named thresholds, and whether and when it enters
 * the own domain if both keep course and speed; then a danger ranking.
 * Frames: metres east/north, navigational headings, SI.
 */
#ifndef FW_ENCOUNTER_H
#define FW_ENCOUNTER_H

#include <stdbool.h>

#include "nomoto/track.h"

/* Room for a target id with its terminating NUL. */
enum { FW_TARGET_ID_MAX = 64 };

typedef struct fw_target {
    /* The caller's stable name for this ship (e.g. the SUMO vehicle id), the
     * same from step to step while the array order may change: the policy
     * remembers the target it is avoiding by it.  "" = no id (the policy then
     * falls back to the array index, which is right only if the order is
     * fixed).  Ids are compared whole: keep them unique and shorter than
     * FW_TARGET_ID_MAX. */
    char id[FW_TARGET_ID_MAX];
    double east, north; /* m */
    double course;      /* rad, navigational */
    double speed;       /* m/s */
    double length;      /* m, 0 = a point */
    double breadth;     /* m */
} fw_target;

/* The own domain: an ellipse centred on the own ship and aligned with its
 * heading.  Transverse semi-axis = size (the paper's 300 m "along the side");
 * fore-aft semi-axis = size * fore_aft_ratio.  Default ratio 1: the paper's
 * numbers (300 m passing distance, helms of 15-29 deg) are those of a 300 m
 * circle; Fujii and Tanaka's 8 L x 3.2 L ellipse (ratio 2.5) is for harbour
 * approaches and would be 750 m ahead at this size.  A target's hull counts
 * by growing each semi-axis by the target's half-extent along that own-ship
 * axis (L/2 |cos a| + B/2 |sin a| fore-aft, L/2 |sin a| + B/2 |cos a| abeam,
 * a = relative heading): the Minkowski sum of ellipse and rectangle, exact on
 * the axes and slightly generous between them. */
typedef struct fw_domain_def {
    double size;           /* m, transverse semi-axis */
    double fore_aft_ratio; /* fore-aft / transverse */
} fw_domain_def;

fw_domain_def fw_default_domain_def(void);

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
    int rank;            /* 0 = most dangerous */
} fw_assessment;

fw_situation fw_classify(const fw_colregs_def *def, const fw_own_state *own,
                         const fw_target *t);

/* Normalised domain radius of a target at body offset (x ahead, y starboard)
 * with relative heading given by its cosine/sine: >= 1 means outside. */
void fw_domain_axes(const fw_domain_def *dom, const fw_target *t, double cos_rel,
                    double sin_rel, double *a, double *b);

/* Normalised domain radius of target t now, for an own ship at (east, north)
 * heading psi: < 1 inside the (hull-grown) domain. */
double fw_domain_lambda(const fw_domain_def *dom, double east, double north, double psi,
                        const fw_target *t);

/* Fills out[0..n-1].  If order is not NULL (room for 2 n ints: the second
 * half is scratch) it gets the target indices most dangerous first and each
 * out[i].rank is set: targets entering the domain first, earliest entry first,
 * then smallest DCPA, then smallest range. */
/* Index of the target with this id in t[0..n-1], -1 if none or id is "". */
int fw_target_find(const fw_target *t, int n, const char *id);

void fw_assess(const fw_colregs_def *cdef, const fw_domain_def *dom, double horizon,
               const fw_own_state *own, const fw_target *t, int n, fw_assessment *out,
               int *order);

#endif
