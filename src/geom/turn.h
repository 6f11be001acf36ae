/* turn.h - a ship expected to finish the turn it is making: a predictor
 * (target.h fw_predictor) for the others' look at it.
 *
 * While it turns (turning), it is expected to turn at `rate` until it heads
 * `heading`, then to run straight on; its drift (course over ground less
 * heading) and its speed over ground held throughout.  Steady (not turning),
 * it is at constant velocity, and a record carrying it is given no
 * predictor (world/vessel.h), so every reader takes constant velocity's
 * closed forms.  An officer who sees a ship swing (and AIS's rate of turn)
 * reads its alteration; a constant-velocity look at a ship half way through
 * its turn would see it heading for the very collision it is turning away
 * from.
 *
 * Who sets it: a background ship fairway steers (world/steer.h: the rate its
 * helm gives, or its own if faster, and the heading its helmsman steers),
 * and a replayed track whose rows carry the turn it was making when it was
 * recorded (traffic/source_track.h: turn_rate_degps, turn_to_deg), so that a
 * replay's own ship expects what the original's did.
 */
#ifndef FW_GEOM_TURN_H
#define FW_GEOM_TURN_H

#include <stdbool.h>

#include "geom/target.h"

typedef struct fw_turn_pred {
    fw_predictor base;
    double rate;    /* rad/s, > 0: how fast it is expected to turn */
    double heading; /* rad: the heading it turns to */
    bool turning;
} fw_turn_pred;

/* A predictor that expects constant velocity (not turning). */
void fw_turn_pred_init(fw_turn_pred *p);

/* p as a turn predictor: NULL for NULL or a predictor of another kind. */
const fw_turn_pred *fw_turn_pred_of(const fw_predictor *p);

#endif
