/* track.h - the own ship's predicted track for one helm order (Nomoto model).
 *
 * From the present state (position, heading, speed, yaw rate, rudder angle)
 * the rudder moves at the ship's rudder rate to the order and is held; the yaw
 * rate follows eq 8 solved exactly piece by piece (hold, ramp, hold), sampled
 * every dt.  The paper keeps U and moves the ship along its heading; the MMG
 * ship does neither: in a 20 deg turn at 10 kn it drifts 10 deg outwards and
 * loses a fifth of its speed within three minutes, and a track without them is
 * 111 m off by then (220 m at 35 deg; 90-582 m after five minutes at 10-12 kn
 * and 10-35 deg, tests/test_identify.c).  When the knowledge base has them
 * (ship.h: drift, speed_loss and their lags) the drift angle and the speed
 * follow the predicted yaw rate through first-order lags, and positions
 * integrate the course over ground (heading - drift) at that speed.
 */
#ifndef FW_TRACK_H
#define FW_TRACK_H

#include <stdbool.h>

#include "core/error.h"
#include "nomoto/nomoto.h"
#include "ship/ship.h"

/* What the predictor needs of the own ship, SI. */
typedef struct fw_own_state {
    double east, north;  /* m */
    double psi;          /* rad, heading (navigational) */
    double U;            /* m/s, speed through the water now (over ground in calm water) */
    double U0;           /* m/s, speed on a straight course (the propeller's); 0 = U */
    double beta;         /* rad, drift angle now: course through the water = psi - beta */
    double r;            /* rad/s, yaw rate */
    double rdot;         /* rad/s^2, yaw acceleration; 0 if unknown (steady turn) */
    double delta;        /* rad, actual rudder angle */
    /* m/s east, north: the current the ship knows (it sets towards); the
     * predicted track is the track through the water plus current x t, the
     * exact ground track in a uniform steady current (dynamics/stepper.h) */
    double cur_e, cur_n;
    /* rad: the rudder angle that holds the heading in the steady wind the
     * ship knows (world/vessel.h "Wind drift"; 0: still air): the Nomoto
     * model, which has no wind, turns by the rudder beyond it */
    double delta_wind;
} fw_own_state;

typedef struct fw_track_def {
    double dt;        /* s, sample interval; positions are exact to ~dt^2 r^2 / 12 */
    double horizon;   /* s, last sample time */
    double max_turn;  /* rad: once the heading has changed this much the prediction
                         steadies on the new course (the manoeuvre would be ended by
                         the return policy, not continued into a circle); 0 = never */
    double delay;     /* s, rudder kept at its present angle this long first */
} fw_track_def;

/* dt 5 s, horizon 600 s (a 2 nm encounter at 10 kn closes in 360 s), max_turn
 * 90 deg, no delay. */
fw_track_def fw_default_track_def(void);

typedef struct fw_track {
    int n;          /* samples at t = k dt, k = 0..n-1 */
    int cap;
    double dt;
    double helm;    /* rad, the order */
    double *east, *north, *psi, *r, *rdot, *delta, *sin_psi, *cos_psi;
} fw_track;

int fw_track_samples(const fw_track_def *def);
fw_status fw_track_alloc(fw_track *tr, int cap, fw_error *err);
void fw_track_free(fw_track *tr);

/* Predicts the track for helm order `helm` (rad, + = starboard, clamped to the
 * ship's maximum).  Nomoto indices at (U, |helm|), see nomoto.h; out must hold
 * fw_track_samples(def) samples. */
fw_status fw_track_predict(const fw_ship *ship, const fw_track_def *def, const fw_own_state *s,
                           double helm, fw_track *out, fw_error *err);

/* The same prediction made a few samples at a time (the helm search predicts
 * a candidate only as far as its clearance check looks): fw_track_start sets
 * out up (n, dt, helm; no samples yet), fw_track_extend computes samples up to
 * kmax (exclusive, at most n) that are not there yet.  The samples are those
 * of fw_track_predict to the bit, however the extensions are cut. */
typedef struct fw_track_kin {  /* position, speed and drift (track.c) */
    const fw_nomoto_kb *kb;
    double L;
    bool slip;                /* the knowledge base has drift or speed loss */
    double east, north;
    double U, U0, beta;       /* speed now, on a straight course, drift angle */
    double sb, cb;            /* sin, cos of beta, kept by rotation: beta moves slowly */
    double cse, csn;          /* unit vector of the course over ground */
    double Eb, Eu;            /* lag factors over one step */
    bool drift;               /* a current: positions + (cur_e, cur_n) t */
    double cur_e, cur_n;      /* m/s */
} fw_track_kin;

typedef struct fw_track_piece { /* the rudder piece under way and its recurrences */
    fw_nomoto_piece pc;
    double t_end, tau, E1, E2, phidt, e2, ph, A, B, TT, TS;
} fw_track_piece;

typedef struct fw_track_gen { /* the predictor's state between extensions */
    fw_nomoto_indices ix;
    fw_track_kin kn;
    fw_track_piece q;
    double piece_start[3], piece_rho[3], piece_delta0[3];
    double dt, max_turn, psi0;
    int n, k, p;              /* samples in all, computed; rudder piece */
    bool in_piece, steadied;
    bool have_E;              /* q's one-step factors made (the same in every piece) */
    double r0, v0, turned0;   /* at the start of piece p */
    double dw;                /* the own state's delta_wind */
    double sn, cs, prev_turn; /* heading at sample k - 1 */
} fw_track_gen;

fw_status fw_track_start(const fw_ship *ship, const fw_track_def *def, const fw_own_state *s,
                         double helm, fw_track *out, fw_track_gen *g, fw_error *err);

/* What starting a track from an own state computes whatever the helm (the
 * speed and drift state, the heading's unit vector: sines, cosines and
 * exponentials), kept for a knowledge base so that the candidates of one
 * decision start from it: fw_track_start_from with origin[2] (one per
 * knowledge base, ship.h; valid = false before the first) fills it the first
 * time and copies it after.  The tracks are fw_track_start's to the bit; the
 * origin holds for the own state it was made from only. */
typedef struct fw_track_origin {
    bool valid;
    double dt;
    fw_track_kin kn;
    double sn, cs;
} fw_track_origin;

fw_status fw_track_start_from(const fw_ship *ship, const fw_track_def *def,
                              const fw_own_state *s, double helm, fw_track *out,
                              fw_track_gen *g, fw_track_origin origin[2], fw_error *err);
void fw_track_extend(fw_track_gen *g, fw_track *out, int kmax);

/* A heading autopilot: helm = -kp (psi - psi_ref) - kd r, within +-max_helm
 * (plus the own state's delta_wind in a wind, as the policy's). */
typedef struct fw_steer_def {
    double psi_ref;   /* rad */
    double kp;        /* rad of helm per rad of heading error */
    double kd;        /* s */
    double max_helm;  /* rad */
    double U0;        /* m/s, the straight-course speed predicted (a speed ordered
                         now: the speed relaxes to it with the knowledge base's
                         speed lag); 0: the state's own U0 */
} fw_steer_def;

/* Predicts the track under that autopilot, the order re-evaluated every 5 s
 * at most (the step loop does it every second: within 3 m over 10 minutes)
 * and the rudder following at its rate; the
 * Nomoto indices at U and the order's angle (to the nearest degree).
 * def->max_turn and def->delay are not used.
 * For the policy's steadying and return, so that what it checks is what it
 * then does. */
fw_status fw_track_predict_steer(const fw_ship *ship, const fw_track_def *def,
                                 const fw_own_state *s, const fw_steer_def *ap, fw_track *out,
                                 fw_error *err);

/* The mirror image of src about the line of the initial heading: the track
 * for -helm when the start is symmetric (r = rdot = delta = 0, no current:
 * asserted). */
void fw_track_mirror(const fw_track *src, const fw_own_state *s, fw_track *dst);
/* The same for samples k0..k1-1 of src only. */
void fw_track_mirror_range(const fw_track *src, const fw_own_state *s, fw_track *dst, int k0,
                           int k1);

#endif
