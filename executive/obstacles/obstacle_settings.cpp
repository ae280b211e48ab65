#include <string>

#include "executive/obstacles/local_obstacles.hpp"

namespace ifar::executive {

const common::ParameterTable<ObstacleSettings>& obstacleParameters()
{
  using S = ObstacleSettings;
  using Range = common::ParameterRange;
  static const auto table =
      common::ParameterTable<S>(common::Presence::required)
          .add("packet_channel", &S::packet_channel, "", Range::nonEmpty(),
               "ifar::velodyne_packet_t; position packets (port 8308) are skipped")
          .add("max_range_m", &S::max_range_m, "m", Range::positive(),
               "farther returns are ignored: the follower looks only a few metres round the vehicle, and the "
               "planner (which sees the whole lidar range) routes beyond that")
          // The ring of packet slots is sized for keep_s of packets; seconds of lidar would also smear a
          // moving obstacle.
          .add("keep_s", &S::keep_s, "s", Range::interval(0.0, false, 2.0, true),
               "a return is used this long after its packet arrived (one revolution is 0.1 s)")
          .add("cell_m", &S::cell_m, "m", Range::nonNegative(),
               "the follower gets one point (the newest) per cell this size; 0 gives every return");
  return table;
}

ObstacleSettings loadObstacleSettings(const common::ConfigNode& node)
{
  // The executive's loader accepts this whole section, so an unknown key here is caught here.
  return obstacleParameters().load(node);
}

}  // namespace ifar::executive
