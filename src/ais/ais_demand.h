/* ais_demand.h - a network's demand (networks/NAME/demand.yaml) from AIS.
 *
 * Each ship's track (ais_track.h, split into passes where its reports are
 * farther apart than the tracks' max_gap) is matched to the route of one of
 * the network's streams: the route whose line (ais_routes.h) the pass keeps
 * closest to on average, if that mean distance is within the tolerance and
 * the pass moves along the route in its direction (its progress along the
 * route at least `along` times the distance between its ends).  Passes
 * shorter than min_pass, or matching no route, are counted as unmatched.
 *
 * Rates: the passes of a route divided by the window's length (hours), so
 * a day of AIS gives ships per day / 24.  Each route's passes are split by
 * ship onto the network's vTypes: the AIS type (ais.h kinds: cargo -> bulk_,
 * cargo_, container_; tanker -> tanker_; passenger, high-speed -> ferry_;
 * fishing, pleasure, service -> small_craft) picks the candidates, the
 * nearest in length and in service speed (the pass's median SOG) among them
 * wins; a ship of unknown type keeps the route's own types.  So the type mix
 * and the speed mix become streams ROUTE_VTYPE with their own rates; routes
 * without passes keep a stream at rate 0.
 *
 * The file is written under a temporary name, loaded back with
 * fw_demand_load and checked against the network's edges, then renamed.
 */
#ifndef FW_AIS_DEMAND_H
#define FW_AIS_DEMAND_H

#include "ais/ais_track.h"
#include "traffic/demand.h"

typedef struct fw_ais_demand_def {
    const char *network; /* networks/NAME */
    double tolerance;    /* m, 1 nm */
    double along;        /* 0.7 */
    double min_pass;     /* m, 1000 */
} fw_ais_demand_def;

fw_ais_demand_def fw_default_ais_demand_def(void);

typedef struct fw_ais_demand_result {
    int n_passes, n_matched;
    double hours;                               /* the window */
    int n_routes;                               /* the network's streams */
    char route[FW_DEMAND_MAX_STREAMS][64];      /* their ids */
    int passes[FW_DEMAND_MAX_STREAMS];          /* matched to each */
    int n_streams;                              /* written */
} fw_ais_demand_result;

fw_status fw_ais_demand_write(const fw_ais_tracks *t, const fw_ais_demand_def *def,
                              const char *path, fw_ais_demand_result *res, fw_error *err);

#endif
