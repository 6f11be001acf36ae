// range_read.h - the range query of the libsumo back end (traffic_sumo.cpp):
// every background ship whose front bumper is within the radius of the own
// ship's hull centre, exactly the ships and the order a context subscription
// would give, read with as few of SUMO's getters as that allows.
//
// A ship found outside the range is not asked again until it could be back
// in: its front moves at most `reach` metres a step (its type's top speed
// along a lane whose geometry may be longer than its length, plus a lane
// change's sideways speed) and the centre moves as fairway placed it, so
// while (distance at the last read - radius) exceeds what both could have
// covered since, the ship is still outside.  The bound holds when lane changes
// take time (lanechange.duration > 0) and SUMO has no sublane model; otherwise
// every ship is read every step.  The ships SUMO has are kept from its
// departed and arrived lists, not its id list.  FAIRWAY_RANGE_CHECK=1 reads
// every ship every step as well and fails the step on any difference
// (=understate: with every bound a hundred times too small, which it must).
#ifndef FW_RANGE_READ_H
#define FW_RANGE_READ_H

#include <string>
#include <vector>

extern "C" {
#include "traffic/backend.h"
}

namespace fw_range {

// After SUMO started: forget every ship, take the bounds from the network
// and the options.
void start();
// The range's radius (m) from now on.
void set_radius(double radius);
// The centre (SUMO coordinates), as placed before each step.
void place(double cx, double cy);
// After each SUMO step: the ships that departed and arrived.
void stepped();
// A ship fairway took out (Vehicle::remove).
void forget(const std::string &id);
// A ship fairway moves anywhere itself (moveToXY each step): read always.
void placed_anywhere(const std::string &id);
// The ships in range, but own, sorted by id (the subscription's order: a map
// by id).  Throws what SUMO throws.
const std::vector<fw_sumo_raw> &read(const std::string &own);
// At the simulation's end: with FAIRWAY_RANGE_CHECK, a line on stderr
// saying how many position reads were made and how many the bound spared.
void close();

} // namespace fw_range

#endif
