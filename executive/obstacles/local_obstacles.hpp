#pragma once
// The executive's own obstacle points: VLP-16 packets decoded one by one and placed in the world with
// the latest vehicle pose, so the follower reacts to a new obstacle within one packet period instead of
// waiting for the planner's 2.5 Hz frames. Points are kept per packet arrival time and dropped after
// keep_s; memory is a fixed ring of packet slots (no growth however fast packets come).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"
#include "common/parameters.hpp"
#include "common/span.hpp"
#include "common/vehicle.hpp"
#include "drivers/velodyne/point.hpp"

namespace ifar::executive {

/// From executive.yaml `obstacles:` section (loadObstacleSettings). Which returns are obstacles (heights,
/// least range, movable reflectivity) is the vehicle's lidar filter (vehicle.yaml `lidar:`).
struct ObstacleSettings {
  double max_range_m = 15.0;  // farther returns are ignored (sparse, irrelevant for the follower)
  double keep_s = 0.15;       // points older than this are dropped
  /// points() gives one point (the newest) per square cell of this size: the follower's clearance
  /// checks do not need the ~20,000 returns of 0.15 s, most of them on the same wall columns. 0: all.
  double cell_m = 0.05;
  std::string packet_channel = "VELODYNE_PACKET";  // LCM channel of velodyne_packet_t (daemon only)
};

/// Reads the `obstacles:` section (pass root.child("obstacles")): every key required, ranges checked,
/// unknown keys under it rejected.
ObstacleSettings loadObstacleSettings(const common::ConfigNode& node);

/// executive.yaml `obstacles:` keys, every one required.
const common::ParameterTable<ObstacleSettings>& obstacleParameters();

class LocalObstacles {
 public:
  LocalObstacles(const ObstacleSettings& settings, const common::VehicleSettings& vehicle);

  /// Vehicle pose (world frame, flat ground) at `utime`; used to place the following packets' returns,
  /// moved on to each packet's receive time (at most 0.1 s) with the velocity of the last two poses.
  /// Non-finite poses are ignored.
  void addPose(std::int64_t utime, const geometry::Pose2& pose);

  /// Decodes one VLP-16 data packet and places its obstacle returns in the world with the latest pose.
  /// False (counted in malformedPackets()) when the packet fails the format checks. Never throws.
  /// A valid packet received before any pose is counted in packetsWithoutPose() and also returns false.
  bool addPacket(common::ByteView payload, std::int64_t receive_utime);

  /// Obstacle points (world frame) received within keep_s before `now_utime`; background and movable.
  /// One per cell_m cell (the newest return in it), newest packets first.
  std::vector<geometry::Point> points(std::int64_t now_utime) const;

  /// Centroid of the movable (retro-reflective) returns within `radius_m` of `near`, if any were seen
  /// within keep_s: what the executive uses as ObjectObservation of the pushed object. One return per
  /// cell, like points(), so the part of the object seen twice within keep_s (1.5 revolutions) does not
  /// pull the centroid about with the lidar's phase.
  std::optional<geometry::Point> movableCentroid(const geometry::Point& near, double radius_m,
                                                 std::int64_t now_utime) const;

  std::int64_t malformedPackets() const;
  /// Valid packets dropped because no pose had been given yet.
  std::int64_t packetsWithoutPose() const;
  /// Receive time of the newest packet accepted, 0 before the first.
  std::int64_t newestPacketUtime() const;

 private:
  struct StoredPoint {
    geometry::Point position = geometry::Point::Zero();
    bool movable = false;
  };
  struct Slot {
    std::int64_t receive_utime = 0;
    std::vector<StoredPoint> points;
  };

  bool isFresh(const Slot& slot, std::int64_t now_utime) const;
  /// Calls visit(point) for the points of packets fresh at `now_utime`, newest packet first, one per
  /// cell_m cell (the first visited). Defined in the .cpp, the only user.
  template <typename Visitor>
  void forEachFreshPoint(std::int64_t now_utime, Visitor&& visit) const;

  ObstacleSettings settings_;
  double lidar_x_m_ = 0.0;
  double lidar_height_m_ = 0.0;
  common::LidarFilterSettings filter_;
  std::optional<geometry::Pose2> pose_;
  std::int64_t pose_utime_ = 0;
  geometry::Pose2 pose_rate_;  // per second: x, y and heading change between the last two poses
  std::vector<Slot> slots_;    // ring; next_slot_ is overwritten next
  std::size_t next_slot_ = 0;
  std::int64_t newest_packet_utime_ = 0;
  std::int64_t malformed_packets_ = 0;
  std::int64_t packets_without_pose_ = 0;
  std::vector<velodyne::Point> decoded_;  // scratch buffer reused by every packet
};

}  // namespace ifar::executive
