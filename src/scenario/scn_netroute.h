/* scn_netroute.h - the own ship's route on a SUMO network: given as the
 * network's edges (or a stream of its demand.yaml), and a waypoint route
 * checked against the network's water.  Internal to the scenario loader.
 *
 *   own_ship:
 *     ship: c3-mmg
 *     network_route:
 *       edges: [WB, BE]          # in order, each beginning where the last ends
 *       # stream: east           #   or a stream of the network's demand.yaml
 *       speeds_kn: [10, 12]      # the speed on each edge (or one speed for all)
 *   traffic: {network: bend}
 *
 * The route's line is each edge's starboard lane's centre line (SUMO's lane
 * 0, the rightmost in the edge's direction, in the built net.xml:
 * traffic/netshape.h): a master keeps to the starboard side of a narrow
 * channel (COLREGs rule 9(a)), and that lane is the one the channel's slower
 * ships keep to, the others theirs to overtake in; on the edges' centre line
 * (between two lanes) the ships in either lane passed half a lane off.  The
 * lines are joined where an edge's last segment meets the next one's first,
 * then reduced (from each waypoint the farthest point whose chord keeps
 * every point between) to within FW_NETROUTE_TOL_M of that line with no leg
 * under 0.1 nm; when that needs more than a route's 9 waypoints
 * (avoid/route.h), within twice that, and so on up to a quarter of the
 * narrowest starboard lane's width (the ship then stays in that lane's
 * middle half); beyond, refused.  Each leg's speed is
 * that of the edge it begins on.  The route replaces east_m/north_m,
 * course_deg, speed_kn, leg_nm and destination, and own_ship.route (giving
 * both is an error).  The network is the scenario's traffic.network.
 *
 * own_ship.route on a network: a waypoint more than FW_ROUTE_OFF_NETWORK_M
 * outside the box of the network's lanes (with their widths) is refused at
 * its line.  SUMO networks say nothing of land, so water is the box.
 */
#ifndef FW_SCN_NETROUTE_H
#define FW_SCN_NETROUTE_H

#include "scenario/scenario.h"
#include "traffic/demand.h"
#include "yaml/yaml_tree.h"

#define FW_NETROUTE_TOL_M 10.0
#define FW_ROUTE_OFF_NETWORK_M 1852.0

/* own_ship.network_route into s->route and the start (as fw_scn_load_route);
 * own the own_ship map, s->ship loaded. */
fw_status fw_scn_load_net_route(const yt_doc *doc, const yt_node *root, const yt_node *own,
                                fw_scenario *s, fw_error *err);

/* own_ship.route's waypoints against the network nf (built). */
fw_status fw_scn_route_on_network(const yt_doc *doc, const yt_node *root, const fw_scenario *s,
                                  const fw_network_files *nf, fw_error *err);

#endif
