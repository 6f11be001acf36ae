// traffic_sumo.cpp - the thin C++ shim over SUMO's client API.
//
// Compiled twice: plain against libsumo (in-process) and with FW_LIBTRACI
// against libtraci (socket); the two share the source because both libraries
// expose the same classes under namespaces libsumo / libtraci.  Each build is
// a loadable module (fairway-libsumo.so, fairway-libtraci.so) built with
// hidden visibility, exporting one function, fw_sumo_backend_table, that
// returns its table (backend.h).  Every entry point catches everything: a
// SUMO exception becomes an fw_status and a message.
#ifdef FW_LIBTRACI
#include <libsumo/libtraci.h>
namespace S = libtraci;
#define FW_BACKEND_TABLE fw_backend_libtraci
#define FW_BACKEND_NAME "libtraci"
#else
#include <libsumo/libsumo.h>
#include "traffic/range_read.h"
namespace S = libsumo;
#define FW_BACKEND_TABLE fw_backend_libsumo
#define FW_BACKEND_NAME "libsumo"
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <unordered_map>
#include <vector>

#include "traffic/sumo_text.h"

extern "C" {
#include "traffic/backend.h"
#include "traffic/traffic.h"
}

namespace {

// Ids of what fairway adds to SUMO next to the own vehicle.
const char *const kOwnType = FW_TRAFFIC_OWN_TYPE;
const char *const kOwnRoute = "fw_own_route";
const char *const kRangePoi = "fw_own_range";

std::string g_own;      // own vehicle id
bool g_subscribed = false; // the range query is set up (the own ship added)
// The range query: ships whose front bumper is within g_radius of (g_cx,
// g_cy), the own ship's hull centre as last placed.
double g_radius = 0.0, g_cx = 0.0, g_cy = 0.0;
bool g_centred = false; // the range's POI (and fw_range) put at (g_cx, g_cy)

// Only a started simulation or an open connection may be closed: libtraci's
// close after a failed init follows a dangling connection.
bool g_open = false;

// Moves wait for the step.  SUMO keeps every ship moved by moveToXY in a
// table of its own (libsumo::Helper, keyed by id, holding the vehicle itself)
// until the next step moves them, and neither closing the simulation nor
// removing the ship clears it: a simulation closed after a move (a run's last
// step, or a failed one) left the vehicle there, and the next simulation in
// the process (fairway worst sails several) followed it at its first step
// when a ship of that id was in it (a fill ship: SIGSEGV in
// MSVehicle::Influencer::postProcessRemoteControl, tests/test_sumo_reopen.c);
// a ship moved and then removed is looked for at the step.  So fairway hands SUMO its moves only in be_step, right before
// SUMO's step, in the order they were made (the last for a ship wins, as in
// SUMO), forgets those of a ship it removes, and drops them at close: no
// sequence of calls leaves SUMO a move past its step.  Nothing reads a moved
// ship before the step (SUMO moves it only there), so every run is as before.
struct Move {
    std::string id, edge;
    int lane, keep_route;
    double x, y, angle, match;
    double prev_speed; // keepRoute 0 or 1 (a ship given back): its speed, set after the move
    // keepRoute 0 (a ship given back whose route SUMO replaced while it was
    // steered): its route ahead as taken, from the edge it is put on, set
    // after the step (SUMO takes a route only from the edge a ship is on)
    std::vector<std::string> route;
};
std::vector<Move> g_moves;
// The routes given back after the next step (Move::route), and each steered
// ship's route as taken with its index on it: placed off the lanes, a ship
// within a lane's line's match threshold of another edge is mapped onto it
// and SUMO gives it that edge as its route (dover-imperfect seed 1,
// replication 54: a northbound ferry steered across the eastbound lane
// came back on it with route [NE] and sailed east to the end of the run).
std::vector<Move> g_reroutes;
struct Taken {
    std::vector<std::string> route;
    int at;
};
std::unordered_map<std::string, Taken> g_taken;

#ifdef FW_LIBTRACI
// A variable subscription result as double / string, whatever the back end
// stored it as.
double as_double(const libsumo::TraCIResults &r, int var)
{
    auto it = r.find(var);
    if (it == r.end())
        throw libsumo::TraCIException("subscription result misses variable " + std::to_string(var));
    auto *d = dynamic_cast<const libsumo::TraCIDouble *>(it->second.get());
    if (!d)
        throw libsumo::TraCIException("subscription variable " + std::to_string(var) + " is not a number");
    return d->value;
}
#endif

fw_status fail(fw_error *err, fw_status st, const char *what, const char *detail)
{
    return fw_fail(err, st, "SUMO (%s): %s: %s", FW_BACKEND_NAME, what, detail);
}

// Runs body and turns every exception into an fw_status.  TraCIException is a
// refusal of a request; anything else (lost connection, process error) a run
// failure.  Both are FW_ERUN for the caller: the input was checked before.
template <typename F> fw_status guarded(const char *what, fw_error *err, F body)
{
    try {
        body();
        return FW_OK;
    } catch (const libsumo::TraCIException &e) {
        return fail(err, FW_ERUN, what, e.what()[0] ? e.what() : "TraCI error");
    } catch (const libsumo::FatalTraCIError &e) {
        return fail(err, FW_ERUN, what, e.what()[0] ? e.what() : "connection lost");
    } catch (const std::exception &e) {
        return fail(err, FW_ERUN, what, e.what()[0] ? e.what() : "error");
    } catch (...) {
        return fail(err, FW_ERUN, what, "unknown exception");
    }
}

fw_status reserve(fw_sumo_list *out, int n, fw_error *err)
{
    if (n <= out->cap)
        return FW_OK;
    int cap = out->cap ? out->cap : 64;
    while (cap < n)
        cap *= 2;
    void *p = std::realloc(out->v, sizeof(fw_sumo_raw) * (size_t)cap);
    if (!p)
        return fw_fail(err, FW_ERUN, "out of memory for %d ships", n);
    out->v = static_cast<fw_sumo_raw *>(p);
    out->cap = cap;
    return FW_OK;
}

void read_vehicle(const std::string &id, fw_sumo_raw *r)
{
    const libsumo::TraCIPosition p = S::Vehicle::getPosition(id);
    fw_copy_text(r->id, sizeof r->id, id);
    fw_copy_text(r->type, sizeof r->type, S::Vehicle::getTypeID(id));
    r->x = p.x;
    r->y = p.y;
    r->angle_deg = S::Vehicle::getAngle(id);
    r->speed = S::Vehicle::getSpeed(id);
    r->length = S::Vehicle::getLength(id);
    r->width = S::Vehicle::getWidth(id);
    r->key = 0;
}

// The first normal edge whose first lane lets ships through.
std::string ship_edge()
{
    for (const std::string &e : S::Edge::getIDList()) {
        if (e.empty() || e[0] == ':')
            continue;
        std::vector<std::string> allowed = S::Lane::getAllowed(e + "_0");
        if (allowed.empty())
            return e;
        for (const std::string &c : allowed)
            if (c == "ship")
                return e;
    }
    throw libsumo::TraCIException("the network has no edge that allows vClass ship");
}

fw_status be_start(const char *const *argv, fw_error *err)
{
#ifdef FW_LIBTRACI
    (void)argv;
    return fw_fail(err, FW_ERUN, "libtraci back end cannot start an in-process simulation");
#else
    std::vector<std::string> cmd;
    for (int i = 0; argv[i]; i++)
        cmd.emplace_back(argv[i]);
    g_subscribed = false;
    g_centred = false;
    g_moves.clear();
    g_reroutes.clear();
    g_taken.clear();
    return guarded("cannot load the simulation", err, [&] {
        S::Simulation::start(cmd);
        g_open = true;
        fw_range::start();
    });
#endif
}

fw_status be_connect(const char *host, int port, int retries, fw_error *err)
{
#ifdef FW_LIBTRACI
    g_subscribed = false;
    g_centred = false;
    g_moves.clear();
    g_reroutes.clear();
    g_taken.clear();
    return guarded("cannot connect", err, [&] {
        S::Simulation::init(port, retries, host);
        g_open = true;
    });
#else
    (void)host;
    (void)port;
    (void)retries;
    return fw_fail(err, FW_ERUN, "libsumo back end cannot connect to a remote sumo");
#endif
}

double be_step_length(void)
{
    try {
        return S::Simulation::getDeltaT();
    } catch (...) {
        return -1.0;
    }
}

fw_status be_add_own(const char *id, double length, double width, const char *edge,
                     double radius, fw_error *err)
{
    return guarded("cannot add the own ship", err, [&] {
        g_own = id;
        S::VehicleType::copy("DEFAULT_VEHTYPE", kOwnType);
        S::VehicleType::setVehicleClass(kOwnType, "ship");
        S::VehicleType::setShapeClass(kOwnType, "ship");
        S::VehicleType::setLength(kOwnType, length);
        S::VehicleType::setWidth(kOwnType, width);
        S::VehicleType::setMinGap(kOwnType, 0.0);
        // no speed factor drawn from SUMO's random numbers (DEFAULT_VEHTYPE's
        // deviation is 0.1): the own ship's speed is fairway's, and SUMO's
        // random stream stays the one sumo alone has on the same inputs, so
        // that the run's sumo/run.sumocfg replays its traffic (sumofiles.c)
        S::VehicleType::setSpeedDeviation(kOwnType, 0.0);
        // signal orange: stands out against the background types' blues, browns, greys
        S::VehicleType::setColor(kOwnType, libsumo::TraCIColor(255, 80, 0, 255));
        S::Route::add(kOwnRoute, {edge && edge[0] ? std::string(edge) : ship_edge()});
        S::Vehicle::add(g_own, kOwnRoute, kOwnType, "now");
        // The range query's centre is a POI at the own ship's hull centre, not
        // the vehicle: a vehicle context is evaluated from its lane, and the own
        // ship is often off the lanes.  Transparent, so sumo-gui shows the ship;
        // kept in libsumo too, so that both back ends simulate the same objects.
        S::POI::add(kRangePoi, 0.0, 0.0, libsumo::TraCIColor(0, 0, 0, 0), "fw_range");
        g_centred = false;
        g_radius = radius;
#ifdef FW_LIBTRACI
        // over a socket, one subscription (answered with every step) beats a
        // round trip per ship and variable
        S::POI::subscribeContext(kRangePoi, libsumo::CMD_GET_VEHICLE_VARIABLE, radius,
                                 {libsumo::VAR_POSITION, libsumo::VAR_ANGLE, libsumo::VAR_SPEED,
                                  libsumo::VAR_LENGTH, libsumo::VAR_WIDTH, libsumo::VAR_TYPE});
#else
        fw_range::set_radius(radius);
#endif
        g_subscribed = true;
    });
}

// SUMO 1.15 (Debian's) leaves the local lanePos of Vehicle::moveToXY
// uninitialised when keepRoute 2 maps the vehicle onto no lane, the case of
// our own ship, then asserts !ISNAN(lanePos) (Debian builds SUMO with its
// asserts on): whether the process aborts depends on what the stack held
// there.  A sweep's run processes are forks of one parent whose stack
// differs from run to run, so some runs aborted and some did not (measured:
// 1 to 7 of the small study's 10 runs).  The value is never used off the
// lanes; zeroing the stack the call is about to use makes it 0.0 and the
// run deterministic.  4 KiB: in Debian's libsumocpp.so 1.15, lanePos lies
// 464 bytes below the stack pointer at the call (objdump: -0x1c0(%rbp) in
// moveToXY, whose frame is 0x228 bytes below six saved registers), where
// this pad lies, called from the same frame just before; the calls
// moveToXY makes before its assert are deeper and never write there.
// Checked: all 32 KiB below the call filled with NaN bytes aborts the 1 nm
// fog run of bench/imperfect_cost.py; the first 4 KiB zeroed and the next
// 28 KiB NaN, it runs to the end, every output byte-identical.  Every
// steered ship's placement clears it: 32 KiB took about 2 % of that run's
// CPU (perf samples).
[[gnu::noinline]] void clear_stack_below()
{
    unsigned char pad[4096];
    std::memset(pad, 0, sizeof pad);
    __asm__ __volatile__("" : : "r"(pad) : "memory"); // the memset is kept
}

void apply_move(const Move &m)
{
    if (m.keep_route == 2)
        clear_stack_below();
    S::Vehicle::moveToXY(m.id, m.edge, m.lane, m.x, m.y, m.angle, m.keep_route, m.match);
    if (m.keep_route != 2)
        S::Vehicle::setPreviousSpeed(m.id, m.prev_speed);
    if (m.keep_route == 0)
        g_reroutes.push_back(m);
    else if (m.keep_route == 1)
        g_taken.erase(m.id); // given back: SUMO's from now on
}

// After the step: each ship moved by keepRoute 0 is on the edge it was put
// on, with that edge alone as its route; its route ahead as taken is set
// from there.
void apply_reroutes()
{
    for (const Move &m : g_reroutes) {
        const std::string on = S::Vehicle::getRoadID(m.id);
        if (on != m.route.front())
            throw libsumo::TraCIException("ship '" + m.id + "' given back onto edge '" +
                                          m.route.front() + "' is on '" + on + "'");
        S::Vehicle::setRoute(m.id, m.route);
        g_taken.erase(m.id);
    }
    g_reroutes.clear();
}

fw_status be_place(const char *id, double fx, double fy, double angle_deg, double cx, double cy,
                   fw_error *err)
{
    return guarded("cannot place the own ship", err, [&] {
        // keepRoute 2: exactly here, off the lanes if need be; never refused.
        // A match threshold of 1 mm keeps it off the lanes always: mapped onto
        // a lane, SUMO ships behind it took it for their leader and braked to
        // a stop (emergency braking, measured), which ships cannot do.  Off the
        // lanes they keep lane and speed, as the benchmark targets do.
        g_moves.push_back(Move{id, "", -1, 2, fx, fy, angle_deg, 1e-3, 0.0, {}});
        // every ship fairway steers is placed after the own ship, about the
        // same centre: the POI is moved (a look-up by name; over a socket a
        // round trip) only when the centre moves
        if (g_centred && cx == g_cx && cy == g_cy)
            return;
        S::POI::setPosition(kRangePoi, cx, cy);
        g_cx = cx;
        g_cy = cy;
        g_centred = true;
#ifndef FW_LIBTRACI
        fw_range::place(cx, cy);
#endif
    });
}

fw_status be_add_placed(const char *id, double length, double width, fw_error *err)
{
    return guarded("cannot add a replayed ship", err, [&] {
        // a ship back after a gap in its reports keeps the type it had
        const std::string type = std::string("fw_placed_") + id;
        const std::vector<std::string> types = S::VehicleType::getIDList();
        if (std::find(types.begin(), types.end(), type) == types.end())
            S::VehicleType::copy(kOwnType, type);
        S::VehicleType::setLength(type, length);
        S::VehicleType::setWidth(type, width);
        S::VehicleType::setColor(type, libsumo::TraCIColor(40, 110, 220, 255));
        S::Vehicle::add(id, kOwnRoute, type, "now");
#ifndef FW_LIBTRACI
        fw_range::placed_anywhere(id);
#endif
    });
}

fw_status be_take(const char *id, fw_error *err)
{
    return guarded("cannot take a ship", err, [&] {
        // whatever speed the reactive traffic held it at: fairway's now
        S::Vehicle::setSpeed(id, -1.0);
        // its route as taken; one given back in this step and taken again
        // keeps the one it had (its rejoin, below, is not made)
        if (g_taken.find(id) == g_taken.end())
            g_taken.emplace(id, Taken{S::Vehicle::getRoute(id),
                                      std::max(0, S::Vehicle::getRouteIndex(id))});
        // given back in this step and taken again: its rejoin is not made,
        // SUMO gets the one move fairway steers it to
        g_moves.erase(std::remove_if(g_moves.begin(), g_moves.end(),
                                     [&](const Move &m) { return m.id == id; }),
                      g_moves.end());
#ifndef FW_LIBTRACI
        // moved anywhere from now on: read every step (it stays so)
        fw_range::placed_anywhere(id);
#endif
    });
}

// the lane index k of edge e, clamped to the lanes it has
std::string lane_of(const std::string &e, int k)
{
    const int nl = S::Edge::getLaneNumber(e);
    return e + "_" + std::to_string(std::max(0, std::min(k, nl - 1)));
}

// Whether a ship at speed vf (its decel b and headway tau) gap m behind
// the back of one at speed vl (decel bl) is already faster than SUMO's safe
// speed behind it (Krauss: the speed from which, after its headway, it stops
// behind the leader braking at the leader's own rate), and so must brake
// harder than its own decel: SUMO brakes it at its emergency rate.
bool must_brake_for(double gap, double vf, double b, double tau, double vl, double bl)
{
    return gap < 0.0 || vf * tau + vf * vf / (2.0 * b) > gap + vl * vl / (2.0 * bl);
}

// The ship of edge e's lanes in lane `lane` (or moving across into it from
// another: its lateral offset towards it) that a ship of length len, gap
// min_gap, speed v and decel b with its front at pos would have ahead within
// its gap or beside it, or behind too close to slow for it (must_brake_for),
// "" for none (id itself aside).  SUMO's lane changes take minutes
// (lanechange.duration), and one begun beside a ship fairway had taken (its
// lane-change model does not see such a ship) counts that ship, given back
// there, as the follower that must let it in: it brakes at its emergency
// rate to a stop and waits until the other is a gap ahead (strait-domain
// seed 2, replication 4: west.5 given back beside west.1, a 366 m ship
// crossing into its lane 28 m ahead, stopped for 150 s).  A faster ship
// behind brakes so too (dover-imperfect seed 2, replication 3 in fog:
// sw_fill3, in a lane change out of sw_fill12's lane at 18.9 kn, was braked
// to 0.6 kn in 12 s when sw_fill12 came back 10 kn slower 400 m ahead, and
// slid sideways at 2.2 m/s as its lane change went on at a standstill).
std::string lane_blocker(const std::string &e, int lane, const char *id, double pos, double len,
                         double min_gap, double v, double b)
{
    const int nl = S::Edge::getLaneNumber(e);
    for (int k = 0; k < nl; k++)
        for (const std::string &o : S::Lane::getLastStepVehicleIDs(lane_of(e, k))) {
            const double lat = S::Vehicle::getLateralLanePosition(o);
            // lanes count from the right, lateral offsets to the left
            if (o == id || (k != lane && !(k > lane ? lat < -1e-3 : lat > 1e-3)))
                continue;
            const double p = S::Vehicle::getLanePosition(o);
            if (p > pos - len ? p - S::Vehicle::getLength(o) - pos < min_gap
                              : must_brake_for(pos - len - p - S::Vehicle::getMinGap(o),
                                               S::Vehicle::getSpeed(o), S::Vehicle::getDecel(o),
                                               S::Vehicle::getTau(o), v, b))
                return o;
        }
    return "";
}

fw_status be_rejoin(const char *id, double fx, double fy, double angle_deg, double speed,
                    double max_off, double *off, fw_error *err)
{
    fw_status st = FW_OK;
    *off = INFINITY;
    fw_status gst = guarded("cannot give a ship back", err, [&] {
        // its route as taken; SUMO's now, unless SUMO replaced it meanwhile
        std::vector<std::string> route = S::Vehicle::getRoute(id);
        int at = std::max(0, S::Vehicle::getRouteIndex(id));
        const auto taken = g_taken.find(id);
        const bool replaced = taken != g_taken.end() && taken->second.route != route;
        if (replaced)
            route = taken->second.route, at = taken->second.at;
        // the nearest lane a ship may use, and the point of its line there
        const libsumo::TraCIRoadPosition rp = S::Simulation::convertRoad(fx, fy, false, "ship");
        const auto on = at > (int)route.size()
                            ? route.end()
                            : std::find(route.begin() + at, route.end(), rp.edgeID);
        if (on == route.end()) {
            st = fw_fail(err, FW_EINPUT, "ship '%s' is nearest to edge '%s', not on its route "
                         "ahead: steer it back first", id, rp.edgeID.c_str());
            return;
        }
        const libsumo::TraCIPosition c = S::Simulation::convert2D(rp.edgeID, rp.pos, rp.laneIndex);
        *off = std::hypot(fx - c.x, fy - c.y);
        if (!(*off <= max_off)) {
            st = fw_fail(err, FW_EINPUT, "ship '%s' is %.1f m off the nearest lane of its route "
                         "(at most %.1f m): steer it back first", id, *off, max_off);
            return;
        }
        const std::string b = lane_blocker(rp.edgeID, rp.laneIndex, id, rp.pos,
                                           S::Vehicle::getLength(id), S::Vehicle::getMinGap(id),
                                           speed, S::Vehicle::getDecel(id));
        if (!b.empty()) {
            st = fw_fail(err, FW_EINPUT, "ship '%s' would come back within its gap of '%s' (ahead, "
                         "beside, or behind and too fast to slow for it) in its lane or crossing "
                         "into it: not yet", id, b.c_str());
            return;
        }
        // keepRoute 1: onto that lane of its route, where it is along it;
        // keepRoute 0 onto that lane where SUMO replaced its route, and the
        // route as taken set from there after the step
        g_moves.push_back(Move{id, rp.edgeID, rp.laneIndex, replaced ? 0 : 1, fx, fy, angle_deg,
                               max_off + 1.0, speed,
                               replaced ? std::vector<std::string>(on, route.end())
                                        : std::vector<std::string>()});
    });
    return gst ? gst : st;
}

fw_status be_lane(const char *id, double *xy, int max, int *n, double *right, double *left,
                  bool *traffic_lane, bool *changing, fw_error *err)
{
    fw_status st = FW_OK;
    *n = 0;
    fw_status gst = guarded("cannot read a ship's lane", err, [&] {
        const std::string edge = S::Vehicle::getRoadID(id);
        if (edge.empty() || edge[0] == ':') {
            st = fw_fail(err, FW_EINPUT, "ship '%s' is in a junction, not on a lane", id);
            return;
        }
        const int li = S::Vehicle::getLaneIndex(id);
        const int nl = S::Edge::getLaneNumber(edge);
        // SUMO counts lanes from the right (index 0) and lateral offsets to the left
        double r = 0.0, l = 0.0, w = S::Lane::getWidth(lane_of(edge, li));
        for (int k = 0; k < nl; k++)
            if (k != li)
                (k < li ? r : l) += S::Lane::getWidth(lane_of(edge, k));
        const double lat = S::Vehicle::getLateralLanePosition(id);
        *right = r + 0.5 * w + lat, *left = l + 0.5 * w - lat;
        *changing = lat != 0.0; // SUMO's continuous lane change (no sublanes)
        *traffic_lane = S::Edge::getParameter(edge, "fairway.traffic_lane") == "true";
        const std::vector<std::string> route = S::Vehicle::getRoute(id);
        double length = 0.0;
        for (size_t i = (size_t)std::max(0, S::Vehicle::getRouteIndex(id));
             i < route.size() && *n < max && length < 3e4; i++) {
            const libsumo::TraCIPositionVector sh = S::Lane::getShape(lane_of(route[i], li));
            for (const libsumo::TraCIPosition &p : sh.value) {
                if (*n >= max)
                    break;
                if (*n > 0)
                    length += std::hypot(p.x - xy[2 * *n - 2], p.y - xy[2 * *n - 1]);
                xy[2 * *n] = p.x, xy[2 * *n + 1] = p.y;
                ++*n;
            }
        }
    });
    return gst ? gst : st;
}

fw_status be_set_speed(const char *id, double speed, fw_error *err)
{
    return guarded("cannot set a ship's speed", err, [&] {
        // setSpeed holds the speed (within the type's decel and accel) until
        // it is given -1, which hands the ship back to its car-following model
        S::Vehicle::setSpeed(id, speed);
    });
}

fw_status be_remove(const char *id, fw_error *err)
{
    return guarded("cannot remove a ship", err, [&] {
        S::Vehicle::remove(id);
        g_taken.erase(id);
        g_moves.erase(std::remove_if(g_moves.begin(), g_moves.end(),
                                     [&](const Move &m) { return m.id == id; }),
                      g_moves.end());
#ifndef FW_LIBTRACI
        fw_range::forget(id);
#endif
    });
}

fw_status be_step(double *time, fw_error *err)
{
    fw_status st = FW_OK;
    for (const Move &m : g_moves) {
        // a refused move still lets SUMO step, which empties its table
        const std::string what = "cannot place ship '" + m.id + "'";
        if ((st = guarded(what.c_str(), err, [&] { apply_move(m); })))
            break;
    }
    g_moves.clear();
    fw_error step_err = {};
    fw_status sst = guarded("step failed", st ? &step_err : err, [&] {
        S::Simulation::step();
        *time = S::Simulation::getTime();
#ifndef FW_LIBTRACI
        fw_range::stepped();
#endif
    });
    if (!st && !sst)
        sst = guarded("cannot give a ship its route back", err, apply_reroutes);
    g_reroutes.clear();
    return st ? st : sst;
}

#ifdef FW_LIBTRACI
// The subscription's results: SUMO's own range test, made at the step.
void read_context(fw_sumo_list *out, fw_status *st, fw_error *err)
{
    const libsumo::SubscriptionResults res = S::POI::getContextSubscriptionResults(kRangePoi);
    if ((*st = reserve(out, (int)res.size(), err)) != FW_OK)
        return;
    for (const auto &kv : res) {
        if (kv.first == g_own)
            continue;
        fw_sumo_raw *r = &out->v[out->n++];
        const libsumo::TraCIResults &v = kv.second;
        fw_copy_text(r->id, sizeof r->id, kv.first);
        auto pit = v.find(libsumo::VAR_POSITION);
        auto *pos = pit == v.end() ? nullptr
                    : dynamic_cast<const libsumo::TraCIPosition *>(pit->second.get());
        if (!pos)
            throw libsumo::TraCIException("subscription result without a position");
        r->x = pos->x;
        r->y = pos->y;
        r->angle_deg = as_double(v, libsumo::VAR_ANGLE);
        r->speed = as_double(v, libsumo::VAR_SPEED);
        r->length = as_double(v, libsumo::VAR_LENGTH);
        r->width = as_double(v, libsumo::VAR_WIDTH);
        r->key = 0;
        auto tit = v.find(libsumo::VAR_TYPE);
        r->type[0] = '\0';
        if (tit != v.end())
            fw_copy_text(r->type, sizeof r->type, tit->second->getString());
    }
}
#else
// In-process, getters cost less than SUMO evaluating a context subscription
// each step (measured, bench/results/traffic_read.txt), and range_read.h
// spares the ships that cannot be in range the getters too.
void read_context(fw_sumo_list *out, fw_status *st, fw_error *err)
{
    const std::vector<fw_sumo_raw> &found = fw_range::read(g_own);
    if ((*st = reserve(out, (int)found.size(), err)) != FW_OK)
        return;
    std::copy(found.begin(), found.end(), out->v);
    out->n = (int)found.size();
}
#endif

fw_status be_context(fw_sumo_list *out, fw_error *err)
{
    out->n = 0;
    if (!g_subscribed)
        return fw_fail(err, FW_ERUN, "SUMO (%s): no range query (own ship not added)",
                       FW_BACKEND_NAME);
    fw_status st = FW_OK;
    fw_status gst = guarded("range query failed", err, [&] { read_context(out, &st, err); });
    return gst ? gst : st;
}

fw_status be_all(fw_sumo_list *out, fw_error *err)
{
    out->n = 0;
    fw_status st = FW_OK;
    fw_status gst = guarded("reading all ships failed", err, [&] {
        const std::vector<std::string> ids = S::Vehicle::getIDList();
        if ((st = reserve(out, (int)ids.size(), err)) != FW_OK)
            return;
        for (const std::string &id : ids)
            read_vehicle(id, &out->v[out->n++]);
    });
    return gst ? gst : st;
}

fw_status be_get(const char *id, fw_sumo_raw *out, fw_error *err)
{
    return guarded("reading a ship failed", err, [&] { read_vehicle(id, out); });
}

// The view of a sumo-gui: libsumo has no GUI, so these are libtraci's only.
const char *const kView = "View #0";

fw_status be_gui_follow(const char *id, double x, double y, double view_m, bool zoom,
                        fw_error *err)
{
    return guarded("cannot set the view", err, [&] {
        if (zoom) {
            // the settings file's scheme is loaded but not always the one shown
            S::GUI::setSchema(kView, "fairway");
            // the zoom (a box about the ship); tracking keeps it centred
            S::GUI::setBoundary(kView, x - 0.5 * view_m, y - 0.5 * view_m, x + 0.5 * view_m,
                                y + 0.5 * view_m);
        }
        // a ship sumo-gui has not drawn yet cannot be tracked: asked again
        // until it is (one call a step, in gui mode only)
        if (S::GUI::getTrackedVehicle(kView) != id)
            S::GUI::trackVehicle(kView, id);
    });
}

fw_status be_gui_screenshot(const char *file, int width, int height, fw_error *err)
{
    return guarded("cannot take a screenshot", err,
                   [&] { S::GUI::screenshot(kView, file, width, height); });
}

fw_status be_net(double box[4], char **ids, fw_error *err)
{
    *ids = nullptr;
    return guarded("cannot read the network", err, [&] {
        const libsumo::TraCIPositionVector b = S::Simulation::getNetBoundary();
        if (b.value.size() != 2)
            throw libsumo::TraCIException("network boundary without two corners");
        box[0] = b.value[0].x, box[1] = b.value[0].y, box[2] = b.value[1].x, box[3] = b.value[1].y;
        std::vector<std::string> edges = S::Edge::getIDList();
        std::sort(edges.begin(), edges.end());
        std::string all;
        for (const std::string &e : edges)
            if (!e.empty() && e[0] != ':')
                all += e + "\n";
        *ids = strdup(all.c_str());
        if (!*ids)
            throw std::bad_alloc();
    });
}

fw_status be_pending(char **ids, fw_error *err)
{
    *ids = nullptr;
    return guarded("cannot list the ships waiting to depart", err, [&] {
        std::string all;
        for (const std::string &v : S::Simulation::getPendingVehicles())
            all += v + "\n";
        *ids = strdup(all.c_str());
        if (!*ids)
            throw std::bad_alloc();
    });
}

void be_close(void)
{
    g_moves.clear(); // never given to SUMO (Moves wait for the step)
    g_reroutes.clear();
    g_taken.clear();
    g_subscribed = false;
    if (!g_open)
        return;
    g_open = false;
#ifndef FW_LIBTRACI
    fw_range::close();
#endif
    try {
        S::Simulation::close();
    } catch (...) {
        // already gone (lost connection, failed start): nothing left to close
    }
}

} // namespace

// hidden like everything else here: the entry below hands it out
extern "C" const fw_sumo_backend FW_BACKEND_TABLE = {
    FW_BACKEND_NAME, be_start, be_connect, be_step_length, be_add_own, be_place,
    be_set_speed, be_remove, be_step, be_context, be_all, be_get, be_gui_follow,
    be_gui_screenshot, be_net, be_close, be_add_placed, be_take, be_rejoin, be_lane,
    be_pending,
};

extern "C" __attribute__((visibility("default"))) const fw_sumo_backend *fw_sumo_backend_table(void)
{
    return &FW_BACKEND_TABLE;
}
