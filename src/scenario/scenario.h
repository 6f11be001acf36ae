/* scenario.h - one encounter or traffic scenario, loaded from YAML and checked.
 *
 * A scenario names the own ship (ship file, start, course, speed, leg), the
 * traffic (a network from networks/ with a demand density, and/or explicit
 * target ships), the avoidance settings, optionally a traffic survey (the
 * encounters among all ships around the own ship), the run (duration, step,
 * seed) and the outputs.  Everything is validated at load time, so a run never starts
 * (and never creates an output directory) from a bad file: errors are
 * "FILE:LINE: FIELD: problem" with status FW_EINPUT.
 *
 * File units are the ones people use (m, kn, deg, nm, s); the struct is SI.
 * Frame: metres east/north of the scenario origin, navigational headings.
 * With `origin: {lat_deg, lon_deg}` ships may be placed by latitude and
 * longitude instead (scenario/position.h, geom/geo.h): the plane is then a
 * transverse Mercator centred on the origin and courses are grid courses.
 */
#ifndef FW_SCENARIO_H
#define FW_SCENARIO_H

#include <stdbool.h>

#include "audit/audit.h"
#include "avoid/policy.h"
#include "core/error.h"
#include "env/env.h"
#include "sense/sensing.h"
#include "geom/geom.h"
#include "ship/ship.h"
#include "survey/survey.h"
#include "world/reactions.h"

#define FW_SCN_MAX_TARGETS 64
/* Waypoints of a target that follows them (a DNV traffic situation: scn_dnv.h) */
#define FW_SCN_MAX_WAYPOINTS 256

/* A target's way: it is at wp[0] at t = 0 and goes from each waypoint to the
 * next at the leg's speed (wp[i].speed, m/s, the leg from i-1 to i; wp[0]'s
 * unused), and on along its last leg after the last. */
typedef struct fw_scn_waypoint {
    double east, north; /* m */
    double speed;       /* m/s, on the leg arriving here */
} fw_scn_waypoint;

typedef struct fw_scn_route {
    int n; /* 0: the target moves at constant velocity (targets[i]) */
    /* s: it is at wp[0] at `appear` (0: from the start) and, when `vanish`
     * is finite, gone after its last waypoint (reached then) */
    double appear, vanish;
    /* its situation gives the turns it was seen making (scn_dnv.h
     * fw_scn_dnv_turns: read from the file when the run is made) */
    bool turns;
    fw_scn_waypoint wp[FW_SCN_MAX_WAYPOINTS];
} fw_scn_route;

/* traffic.ais: AIS reports replayed as the traffic (ais/ais_track.h). */
typedef struct fw_scn_ais {
    char file[1024];     /* "" = none */
    char columns[512];   /* the column map (ais.h fw_ais_columns_parse), "" = DMA */
    /* the window: UTC seconds, or seconds after the file's first report
     * when *_rel; NAN = from the first / to the last report */
    double start, end;
    bool start_rel, end_rel;
    double max_gap;      /* s, reports farther apart are two passes */
} fw_scn_ais;


typedef struct fw_scenario {
    char file[512];
    char name[64];       /* letters, digits, '-', '_': names the output directory */
    char description[256];
    bool has_origin;     /* origin: the plane's centre in WGS84 */
    double origin_lat, origin_lon; /* deg */
    /* On a geo-referenced network the network's plane instead (its PROJ
     * string and netOffset: traffic/demand.h fw_network_plane); "" otherwise */
    char plane[512];
    double plane_off_e, plane_off_n;
    /* own ship */
    fw_ship ship;
    double east, north;  /* m */
    double course;       /* rad */
    double speed;        /* m/s */
    double leg;          /* m, planned straight leg along the course (the route's length) */
    /* own_ship.route (scenario/scn_route.h): waypoints with a speed per leg,
     * followed by the policy (avoid/route.h); n 0: none, the one leg above */
    fw_route route;
    /* own_ship.dynamics: false (mmg, the default) the MMG model integrated by
     * ARKODE; true (nomoto) the ship's own Nomoto model, the paper's
     * fast-time simulation: the plant is the prediction (world/vessel.h) */
    bool nomoto_plant;
    /* traffic */
    char network[1024];  /* a network's name or its directory's path; "" = none */
    double density;      /* demand scale of the network's streams */
    int fill;            /* network ships placed along the routes at t = 0 */
    fw_reactions_def reactions; /* behaviour: colregs (default) or blind */
    char tracks[1024];   /* recorded tracks (traffic/source_track.h) replayed, "" = none */
    fw_scn_ais ais;      /* AIS reports replayed (needs the origin) */
    int n_targets;
    fw_target targets[FW_SCN_MAX_TARGETS]; /* at t = 0; type: the label kept in the records */
    /* targets that follow waypoints (all of them when set; scn_dnv.h): the
     * recorded-track source replays their ways, no SUMO */
    bool waypoint_targets;
    fw_scn_route target_routes[FW_SCN_MAX_TARGETS];
    /* avoidance */
    fw_helm_def helm;
    /* traffic.waterway: open-sea (default), tss or channel; sets the audit's
     * risk distance (audit.h fw_audit_def_for) */
    fw_waterway waterway;
    fw_audit_def audit;  /* the COLREGs audit's thresholds (by waterway; a study sets them) */
    fw_policy_def policy;
    double radius;       /* m, range within which targets are seen */
    /* traffic-level survey (src/survey): every pair of ships in the area */
    bool survey;         /* the file has a survey: section */
    double survey_radius;/* m, area around the own ship's hull centre */
    fw_survey_def survey_def;
    /* environment: the current and the wind (scn_env.h; calm by default) */
    fw_env env;
    /* environment.visibility_nm: m, restricted visibility, 0 = clear (scn_env.h);
     * also in helm.colregs and reactions.colregs, where the rules read it */
    double visibility;
    /* sensing: what the own ship knows of the others (sense/sensing.h), and
     * (sensing_background, sensing.background: true by default) the
     * reacting background ships too (world/reactions.h) */
    fw_sensing_def sensing;
    bool sensing_background;
    /* traffic.watch.own_ship: the own ship's watch (world/watch.h): flawless
     * (perfect, an autonomous system) by default; human: the background
     * ships' watch (scn_env.h) */
    fw_watch_def own_watch;
    /* run */
    double duration;     /* s */
    double step;         /* s */
    unsigned long seed;
    /* outputs */
    bool targets_csv;
    double record_every; /* s, time-history sampling (a multiple of step) */
    bool fcd;            /* SUMO's own FCD output of every ship (sumo/fcd.xml) */
    /* how the scenario was made, a line for run.log ("" = a YAML scenario):
     * a DNV situation's own-ship model and what of the situation it uses */
    char note[768];
    /* a DNV situation's run answers in the situation output (run/dnv_out.h),
     * its times from utc_start (s since 1970, UTC: the situation's startTime) */
    bool situation_output;
    double utc_start;
} fw_scenario;

/* The scenario's plane (geom/geo.h), *g NULL when it has no origin: the
 * network's own projection on a geo-referenced network, else a transverse
 * Mercator about the origin.  The caller destroys it. */
typedef struct fw_geo fw_geo;
fw_status fw_scenario_plane(const fw_scenario *s, fw_geo **g, fw_error *err);

/* Why scenario s has no randomness after t = 0 (text for an error), or NULL
 * when something in its world draws from fairway's streams after the start
 * (sensing noise, watchkeeping, gusts ...: what the scenario turns on).
 * Splitting (study/split_run.h) needs such randomness: without it every
 * branch repeats its parent. */
const char *fw_scenario_randomness(const fw_scenario *s);

/* The defaults every scenario starts from (s zeroed first; file set). */
fw_status fw_scenario_defaults(const char *path, fw_scenario *s, fw_error *err);

/* Loads and checks path.  s is large (a ship inside): callers heap-allocate. */
fw_status fw_scenario_load(const char *path, fw_scenario *s, fw_error *err);

/* One setting laid over a scenario file: `key` a dotted path into it
 * ("sensing.visibility_nm", "traffic.behaviour"), `value` a YAML scalar. */
typedef struct fw_setting {
    const char *key;
    const char *value;
} fw_setting;

/* fw_scenario_load with settings[0..n-1] laid over the file first (yaml_tree.h
 * yt_set), each then read and checked as if the file had it: a study's axes
 * make one scenario per setting this way, so any key of a scenario can be
 * swept and every value is checked by the one reader of that key. */
fw_status fw_scenario_load_with(const char *path, const fw_setting *settings, int n,
                                fw_scenario *s, fw_error *err);

#endif
