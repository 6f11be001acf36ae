// range_read.cpp - the libsumo back end's range query (range_read.h).
#include "traffic/range_read.h"
#include "traffic/sumo_text.h"

#include <libsumo/libsumo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <unordered_set>

namespace S = libsumo;

namespace fw_range {
namespace {

const double kInf = std::numeric_limits<double>::infinity();
// metres a check keeps in hand: rounding in the distances, and the few
// millimetres where one lane's shape ends and the next one's begins
const double kSlack = 1.0;

// What is kept of a ship SUMO has: asked once (type, length, width, reach),
// and where it was when last found outside the range.
struct Ship {
    std::string id;
    std::string type;
    double length, width;
    double reach;    // m its front moves at most in a step; inf: unknown
    double outside;  // m beyond the radius at the last read; < 0: read it
    long read_step;  // the step of that read
    double read_path; // the centre's path length then
    int key;          // fw_sumo_raw.key: numbered as added, from 1
};

std::vector<Ship> g_ships; // sorted by id
std::vector<fw_sumo_raw> g_found;
std::unordered_set<std::string> g_anywhere;
double g_radius = 0.0, g_cx = 0.0, g_cy = 0.0, g_path = 0.0;
bool g_placed = false;
long g_step = 0;
double g_dt = 1.0;
// m a step any ship's front can move beyond its own top speed's share
// (geometry factor, lateral); reach unknown (inf) if lane changes jump
double g_geometry = 1.0, g_lateral = kInf;
bool g_check = false;
double g_understate = 1.0;
long g_skipped = 0, g_made = 0;
int g_keys = 0; // keys given so far

bool by_id(const Ship &s, const std::string &id) { return s.id < id; }

// SUMO's test for a context (libsumo Helper): distance2D(centre, front) <=
// range, the square root of the summed squares; the distance in *d.
bool in_range(const libsumo::TraCIPosition &p, double *d)
{
    const double dx = p.x - g_cx, dy = p.y - g_cy;
    *d = std::sqrt(dx * dx + dy * dy);
    return !(*d > g_radius);
}

std::vector<Ship>::iterator find(const std::string &id)
{
    auto it = std::lower_bound(g_ships.begin(), g_ships.end(), id, by_id);
    return it != g_ships.end() && it->id == id ? it : g_ships.end();
}

// The network's bounds on how far a front moves in a step: SUMO advances a
// ship along its lane by speed * dt, drawn on a shape up to g_geometry times
// longer than the lane's length; a lane change of duration D moves it across
// by at most the widest lane in D.  No bound when lane changes are instant or
// the sublane model moves ships sideways at will.
void network_bounds()
{
    g_geometry = 1.0;
    g_lateral = kInf;
    double widest = 0.0;
    for (const std::string &lane : S::Lane::getIDList()) {
        const double len = S::Lane::getLength(lane);
        const std::vector<libsumo::TraCIPosition> &pts = S::Lane::getShape(lane).value;
        double drawn = 0.0;
        for (size_t k = 1; k < pts.size(); k++)
            drawn += std::hypot(pts[k].x - pts[k - 1].x, pts[k].y - pts[k - 1].y);
        if (len > 0.0)
            g_geometry = std::max(g_geometry, drawn / len);
        widest = std::max(widest, S::Lane::getWidth(lane));
    }
    const double duration = std::atof(S::Simulation::getOption("lanechange.duration").c_str());
    const double sublane = std::atof(S::Simulation::getOption("lateral-resolution").c_str());
    if (duration > 0.0 && !(sublane > 0.0))
        g_lateral = widest / duration * g_dt;
}

void add(const std::string &id)
{
    auto it = std::lower_bound(g_ships.begin(), g_ships.end(), id, by_id);
    if (it != g_ships.end() && it->id == id)
        return;
    Ship s{id, S::Vehicle::getTypeID(id), S::Vehicle::getLength(id), S::Vehicle::getWidth(id),
           kInf, -1.0, 0, 0.0, ++g_keys};
    if (!g_anywhere.count(id))
        s.reach = (S::Vehicle::getMaxSpeed(id) * g_dt * g_geometry + g_lateral) * g_understate;
    g_ships.insert(it, std::move(s));
}

// Still outside for sure: its last distance beyond the radius exceeds what it
// and the centre can have moved since.
bool surely_outside(const Ship &s)
{
    if (!(s.outside >= 0.0) || !std::isfinite(s.reach))
        return false;
    const double moved = s.reach * (double)(g_step - s.read_step) + (g_path - s.read_path);
    return s.outside - moved > kSlack;
}

void fill(fw_sumo_raw *r, const Ship &s, double x, double y)
{
    fw_copy_text(r->id, sizeof r->id, s.id);
    fw_copy_text(r->type, sizeof r->type, s.type);
    r->x = x;
    r->y = y;
    r->angle_deg = S::Vehicle::getAngle(s.id);
    r->speed = S::Vehicle::getSpeed(s.id);
    r->length = s.length;
    r->width = s.width;
    r->key = s.key;
}

// FAIRWAY_RANGE_CHECK: SUMO's own range test over every ship it has, against
// what the schedule found.
void check(const std::string &own)
{
    std::vector<std::string> ids;
    for (const std::string &id : S::Vehicle::getIDList()) {
        double d;
        if (id != own && in_range(S::Vehicle::getPosition(id), &d))
            ids.push_back(id);
    }
    std::sort(ids.begin(), ids.end());
    const std::string at = "range read (FAIRWAY_RANGE_CHECK): at step " + std::to_string(g_step);
    for (size_t k = 0; k < ids.size() || k < g_found.size(); k++) {
        if (k >= g_found.size())
            throw libsumo::TraCIException(at + ": ship " + ids[k] + " in range was not read");
        if (k >= ids.size())
            throw libsumo::TraCIException(at + ": ship " + g_found[k].id + " read, not in range");
        if (ids[k] != g_found[k].id)
            throw libsumo::TraCIException(at + ": the read has " + g_found[k].id + " where SUMO has " +
                                          ids[k]);
        const libsumo::TraCIPosition p = S::Vehicle::getPosition(ids[k]);
        if (p.x != g_found[k].x || p.y != g_found[k].y)
            throw libsumo::TraCIException(at + ": ship " + ids[k] + " is not where the read has it");
    }
}

} // namespace

void start()
{
    g_ships.clear();
    g_anywhere.clear();
    g_placed = false;
    g_path = 0.0;
    g_step = 0;
    g_skipped = g_made = 0;
    g_keys = 0;
    g_dt = S::Simulation::getDeltaT();
    const char *c = std::getenv("FAIRWAY_RANGE_CHECK");
    g_check = c && (std::strcmp(c, "1") == 0 || std::strcmp(c, "understate") == 0);
    network_bounds();
    // a bound a hundred times too small, for the test that the check catches it
    g_understate = c && std::strcmp(c, "understate") == 0 ? 0.01 : 1.0;
    // ships SUMO has already (none, unless it was stepped before)
    for (const std::string &id : S::Vehicle::getIDList())
        add(id);
}

void set_radius(double radius)
{
    g_radius = radius;
    for (Ship &s : g_ships)
        s.outside = -1.0;
}

void place(double cx, double cy)
{
    if (g_placed)
        g_path += std::hypot(cx - g_cx, cy - g_cy);
    g_cx = cx;
    g_cy = cy;
    g_placed = true;
}

void stepped()
{
    g_step++;
    const std::vector<std::string> arrived = S::Simulation::getArrivedIDList();
    for (const std::string &id : arrived)
        forget(id);
    // a ship that departed and arrived within the step is gone already
    for (const std::string &id : S::Simulation::getDepartedIDList())
        if (std::find(arrived.begin(), arrived.end(), id) == arrived.end())
            add(id);
}

void forget(const std::string &id)
{
    auto it = find(id);
    if (it != g_ships.end())
        g_ships.erase(it);
}

void placed_anywhere(const std::string &id)
{
    g_anywhere.insert(id);
    auto it = find(id);
    if (it != g_ships.end())
        it->reach = kInf;
}

const std::vector<fw_sumo_raw> &read(const std::string &own)
{
    g_found.clear();
    for (Ship &s : g_ships) {
        if (s.id == own)
            continue;
        if (surely_outside(s)) {
            g_skipped++;
            continue;
        }
        g_made++;
        const libsumo::TraCIPosition p = S::Vehicle::getPosition(s.id);
        double d;
        if (!in_range(p, &d)) {
            s.outside = d - g_radius;
            s.read_step = g_step;
            s.read_path = g_path;
            continue;
        }
        s.outside = -1.0;
        g_found.emplace_back();
        fill(&g_found.back(), s, p.x, p.y);
    }
    if (g_check)
        check(own);
    return g_found;
}

void close()
{
    if (g_check)
        std::fprintf(stderr, "fairway: range read: %ld position reads, %ld spared, every step checked\n",
                     g_made, g_skipped);
    g_check = false;
}

} // namespace fw_range
