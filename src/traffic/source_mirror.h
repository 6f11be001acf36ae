/* source_mirror.h - recorded ships shown in SUMO: a replay source
 * (source_track.h, AIS tracks) whose ships are also SUMO vehicles, placed
 * every step where the replay puts them, so that sumo-gui shows a replayed
 * AIS run with the MMSIs as vehicle ids.
 *
 * fairway's targets still come from the replay (exact interpolation); SUMO
 * only shows them: each ship is added when it appears (its own vType of its
 * size, traffic.h fw_traffic_add_placed), moved to its hull centre and
 * course before every SUMO step (moveToXY off the lanes, as the own ship),
 * and taken out when it disappears (a gap in its reports, or its end).  SUMO
 * runs a network of one edge along the own ship's leg (built by netconvert
 * in dir) with the own ship on it; no SUMO ship of its own.
 */
#ifndef FW_TRAFFIC_SOURCE_MIRROR_H
#define FW_TRAFFIC_SOURCE_MIRROR_H

#include "traffic/source.h"
#include "traffic/traffic.h"

typedef struct fw_mirror_def {
    fw_traffic_mode mode;
    const char *dir;     /* SUMO's files and logs go here (it must exist) */
    double step;         /* s, the replay's */
    unsigned long seed;
    fw_target own;       /* id, position, course, size at t = 0 */
    double own_leg;      /* m, planned; SUMO's edge runs beyond it and the run's course */
    double duration;     /* s, the run */
    double radius;       /* m, sight: around() lists the ships within it */
} fw_mirror_def;

/* inner: the replay, seeing every ship (radius INFINITY); taken over (also
 * destroyed on failure). */
fw_status fw_mirror_source_create(fw_source *inner, const fw_mirror_def *def, fw_source **out,
                                  fw_error *err);

/* The SUMO side, for checks (fw_traffic_get): NULL for another source. */
fw_traffic *fw_mirror_source_traffic(fw_source *s);

#endif
