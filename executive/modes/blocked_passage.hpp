#pragma once
// A passage the vehicle cannot get through, as the executive reports it to the planner (BLOCKED_PASSAGE).

#include <cstdint>
#include <string>

#include "common/geometry/point.hpp"

namespace ifar::executive {

/// A passage the vehicle could not get through: following toward `to` stalled `stalls` times within
/// ExecutiveSettings::stall_site_radius_m of `from`, or a gap too narrow for the vehicle was seen ahead.
/// The daemon publishes it as BLOCKED_PASSAGE; the planner seals the narrowest point between the two and
/// routes around it.
struct BlockedPassage {
  std::int64_t goal_id = -1;
  geometry::Point from = geometry::Point::Zero();  ///< the vehicle, world frame
  geometry::Point to = geometry::Point::Zero();    ///< the path point it could not reach
  int stalls = 0;                                  ///< 0: an impassable gap seen ahead, no stall
  std::string text;                                ///< for people
};

}  // namespace ifar::executive
