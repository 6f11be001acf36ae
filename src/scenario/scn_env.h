/* scn_env.h - a scenario's environment: the current and the wind
 * (environment:, env/env.h).  Internal to the scenario loader.
 *
 *   environment:
 *     current: {speed_kn: 2, towards_deg: 90}      # uniform: the way it sets
 *     # or a rectilinear tidal stream, flooding towards flood_towards_deg at up
 *     # to rate_kn at springs and neap_rate_kn at neaps (absent: rate_kn, no
 *     # spring-neap cycle), greatest at max_flood_s after the start, springs
 *     # at springs_s, period_h 12.42 (M2), springs to springs 14.77 days:
 *     current: {tidal: {rate_kn: 2.25, neap_rate_kn: 1.25, flood_towards_deg: 85,
 *                       max_flood_s: 0, springs_s: 0}}
 *     # or the network's charted stream (networks/NAME/tide.yaml, with its
 *     # source), any key above given here overriding it:
 *     current: {tidal: {network: true, max_flood_s: 3600}}
 *     wind: {speed_kn: 20, from_deg: 270,          # the way it blows from
 *            gust_intensity: 0.1, gust_time_s: 30} # optional gusts (env.h)
 *     visibility_nm: 1                             # restricted visibility
 *
 * Knots and degrees here, converted once (core/units.h); the current sets
 * TOWARDS its direction and the wind blows FROM its own, as charts and
 * weather reports (and DNV's maritime-schema) give them.  Bounds: a current
 * of 0 to 10 kn (a neap rate at most the spring rate), a period of 1 to 48
 * h, times within 1e7 s, a wind of 0 to 100 kn, a gust intensity of 0 to 0.3
 * with a time scale of 1 to 3600 s.  Any of these keys is a study axis
 * (study_axes.h: `environment.wind.speed_kn: [0, 20, 40]`).  A wind that is
 * not calm is refused here, located, when the own ship's ship file has no
 * windage: section or its dynamics are Nomoto's (env.h fw_env_check_vessel).
 * The own ship must be loaded first (load_own).
 * visibility_nm: ships farther apart are not in sight of one another and
 * follow rule 19 (avoid/policy.h, world/reactions.h); more than 0, at most
 * 100 (0 or less: FILE:LINE: FIELD); without it the weather is clear.  It is
 * the environment's, as in DNV's maritime-schema (environment.visibility,
 * NM), since it governs conduct and not what the sensors see (radar and AIS
 * work in fog: sense/arpa.h); the avoidance and the traffic must be loaded
 * first (it is set into their colregs definitions).
 */
#ifndef FW_SCENARIO_SCN_ENV_H
#define FW_SCENARIO_SCN_ENV_H

#include "scenario/scenario.h"
#include "yaml/yaml_tree.h"

/* A visibility of m metres (> 0) into s and the rules' colregs definitions
 * (the own ship's and the background ships'): what visibility_nm sets; for
 * other readers of an environment (scn_dnv.c). */
void fw_scn_set_visibility(fw_scenario *s, double m);

/* sensing: of root into s->sensing (sense/sensing.h; perfect without it):
 *   sensing: {mode: ais, position_sd_m: 10, sog_sd_kn: 0.1, cog_sd_deg: 1,
 *             heading_sd_deg: 0.5, dropout: 0.1, latency_s: 1, stale_s: 360}
 *   sensing: {mode: radar, range_sd_m: 15, bearing_sd_deg: 0.5, scan_s: 2.5,
 *             alpha: 0.1, antenna_height_m: 15}
 * what the own ship knows of the others (the values shown are the defaults
 * but dropout's and latency's, 0): mode perfect, ais, radar or ais+radar
 * (sense/sensing.h; the radar's keys are arpa.h's, its beta the
 * Benedict-Bordner alpha^2 / (2 - alpha)); a probability outside [0, 1], a
 * value out of its bounds or an unknown mode: FILE:LINE: FIELD. */
fw_status fw_scn_load_sensing(const yt_doc *doc, const yt_node *root, fw_scenario *s,
                              fw_error *err);

/* traffic.watch (tr: the traffic map) into s->reactions.watch (world/watch.h;
 * flawless without it):
 *   traffic: {watch: {detect_s: 120, delay_s: 60, lapse: 0.05,
 *                     late: 0.1, late_range_nm: 1}}
 * the mean time a background ship takes to detect a ship it must give way to
 * (exponential, per encounter), the time it then takes to decide, the
 * probability it never acts, and the probability it acts only within
 * late_range_nm; no defaults with a source yet: the user's values.  A
 * probability outside [0, 1], a negative time, a late action without its
 * range: FILE:LINE: FIELD.  own_ship: perfect (default: the own ship sees
 * every ship in its view at once, an autonomous system) or human (the same
 * watch, its clock started when a ship first enters its view) into
 * s->own_watch. */
fw_status fw_scn_load_watch(const yt_doc *doc, const yt_node *tr, fw_scenario *s, fw_error *err);

/* traffic.mix (after the watch: the own ship's watch is not mixed): the
 * shares of background ships that are compliant, late (act only within
 * late_range_nm) or passive (never act), world/watch.h; compliant may be
 * left out (the rest), given it makes the shares sum to 1.  An unknown
 * behaviour, a share outside [0, 1], shares that do not sum to 1, late
 * without its range: FILE:LINE: FIELD. */
fw_status fw_scn_load_mix(const yt_doc *doc, const yt_node *tr, fw_scenario *s, fw_error *err);

/* environment: of root into s->env (calm water and still air without it). */
fw_status fw_scn_load_env(const yt_doc *doc, const yt_node *root, fw_scenario *s, fw_error *err);

#endif
