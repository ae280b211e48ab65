#include "executive/obstacles/local_obstacles.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "drivers/velodyne/packet_decoder.hpp"

namespace ifar::executive {
namespace {

// The VLP-16 sends about 754 packets per second in a single return mode and twice that in dual mode;
// the ring holds keep_s of the faster rate plus a few, so bursts overwrite the oldest packets only.
constexpr double kMaxPacketsPerSecond = 1600.0;
constexpr std::size_t kExtraSlots = 8;
constexpr double kMicrosecondsPerSecond = 1e6;
// Poses further apart than this give no velocity; packets are placed at most this far past the pose.
constexpr std::int64_t kMaxRateGapUs = 200'000;
constexpr double kMaxExtrapolationS = 0.1;

}  // namespace

LocalObstacles::LocalObstacles(const ObstacleSettings& settings, const common::VehicleSettings& vehicle)
    : settings_(settings),
      lidar_x_m_(vehicle.lidar_x_m),
      lidar_height_m_(vehicle.lidar_height_m),
      filter_(vehicle.lidar),
      slots_(static_cast<std::size_t>(std::ceil(std::max(settings.keep_s, 0.0) * kMaxPacketsPerSecond)) +
             kExtraSlots)
{
  decoded_.reserve(velodyne::kBlocksPerPacket * velodyne::kReturnsPerBlock);
}

void LocalObstacles::addPose(std::int64_t utime, const geometry::Pose2& pose)
{
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.heading)) {
    return;
  }
  pose_rate_ = geometry::Pose2{};
  if (pose_ && utime > pose_utime_ && utime - pose_utime_ <= kMaxRateGapUs) {
    const double elapsed_s = static_cast<double>(utime - pose_utime_) / kMicrosecondsPerSecond;
    pose_rate_ = geometry::Pose2{(pose.x - pose_->x) / elapsed_s, (pose.y - pose_->y) / elapsed_s,
                                 geometry::wrapAngle(pose.heading - pose_->heading) / elapsed_s};
  }
  pose_ = pose;
  pose_utime_ = utime;
}

bool LocalObstacles::addPacket(common::ByteView payload, std::int64_t receive_utime)
{
  decoded_.clear();
  const velodyne::DecodeResult result = velodyne::decodePacket(payload, decoded_);
  if (result.info.status != velodyne::PacketStatus::kOk) {
    ++malformed_packets_;
    return false;
  }
  if (!pose_) {
    ++packets_without_pose_;
    return false;
  }
  Slot& slot = slots_[next_slot_];
  next_slot_ = (next_slot_ + 1) % slots_.size();
  slot.receive_utime = receive_utime;
  slot.points.clear();
  // The pose moved on to the packet's time: at 50 Hz poses and 1.2 rad/s, 20 ms is 0.24 m at 10 m.
  const double ahead_s = std::clamp(static_cast<double>(receive_utime - pose_utime_) / kMicrosecondsPerSecond,
                                    0.0, kMaxExtrapolationS);
  const geometry::Pose2 pose{pose_->x + pose_rate_.x * ahead_s, pose_->y + pose_rate_.y * ahead_s,
                             pose_->heading + pose_rate_.heading * ahead_s};
  const double cos_heading = std::cos(pose.heading);
  const double sin_heading = std::sin(pose.heading);
  const auto min_range = static_cast<float>(filter_.min_range_m);
  const auto max_range = static_cast<float>(settings_.max_range_m);
  for (const velodyne::Point& point : decoded_) {
    if (point.distance < min_range || point.distance > max_range) {
      continue;
    }
    // The lidar's axes are the vehicle's (lidarMount): only its offset ahead and its height differ.
    const double height = point.z + lidar_height_m_;
    if (height < filter_.ground_clearance_m || height > filter_.max_height_m) {
      continue;
    }
    const double forward = point.x + lidar_x_m_;
    const double left = point.y;
    StoredPoint stored;
    stored.position = geometry::Point(pose.x + cos_heading * forward - sin_heading * left,
                                      pose.y + sin_heading * forward + cos_heading * left);
    stored.movable = point.reflectivity >= filter_.movable_reflectivity_threshold;
    slot.points.push_back(stored);
  }
  newest_packet_utime_ = std::max(newest_packet_utime_, receive_utime);
  return true;
}

bool LocalObstacles::isFresh(const Slot& slot, std::int64_t now_utime) const
{
  const auto keep_us = static_cast<std::int64_t>(settings_.keep_s * kMicrosecondsPerSecond);
  return slot.receive_utime != 0 && slot.receive_utime >= now_utime - keep_us;
}

template <typename Visitor>
void LocalObstacles::forEachFreshPoint(std::int64_t now_utime, Visitor&& visit) const
{
  std::size_t count = 0;
  for (const Slot& slot : slots_) {
    if (isFresh(slot, now_utime)) {
      count += slot.points.size();
    }
  }
  const bool thin = settings_.cell_m > 0.0;
  std::unordered_set<std::int64_t> occupied;
  if (thin) {
    occupied.reserve(count);
  }
  for (std::size_t age = 1; age <= slots_.size(); ++age) {
    const Slot& slot = slots_[(next_slot_ + slots_.size() - age) % slots_.size()];
    if (!isFresh(slot, now_utime)) {
      continue;
    }
    for (const StoredPoint& point : slot.points) {
      if (thin) {
        const auto column = static_cast<std::int64_t>(std::floor(point.position.x() / settings_.cell_m));
        const auto row = static_cast<std::int64_t>(std::floor(point.position.y() / settings_.cell_m));
        // Cells within +-2^31 of the origin are distinct: 100,000 km at 5 cm.
        const std::int64_t key = static_cast<std::int64_t>(static_cast<std::uint64_t>(column) << 32U) ^
                                 static_cast<std::int64_t>(static_cast<std::uint32_t>(row));
        if (!occupied.insert(key).second) {
          continue;
        }
      }
      visit(point);
    }
  }
}

std::vector<geometry::Point> LocalObstacles::points(std::int64_t now_utime) const
{
  std::vector<geometry::Point> result;
  forEachFreshPoint(now_utime, [&result](const StoredPoint& point) { result.push_back(point.position); });
  return result;
}

std::optional<geometry::Point> LocalObstacles::movableCentroid(const geometry::Point& near, double radius_m,
                                                               std::int64_t now_utime) const
{
  geometry::Point sum = geometry::Point::Zero();
  std::size_t count = 0;
  const double radius_squared = radius_m * radius_m;
  forEachFreshPoint(now_utime, [&](const StoredPoint& point) {
    if (point.movable && (point.position - near).squaredNorm() <= radius_squared) {
      sum += point.position;
      ++count;
    }
  });
  if (count == 0) {
    return std::nullopt;
  }
  return geometry::Point(sum / static_cast<double>(count));
}

std::int64_t LocalObstacles::malformedPackets() const
{
  return malformed_packets_;
}

std::int64_t LocalObstacles::packetsWithoutPose() const
{
  return packets_without_pose_;
}

std::int64_t LocalObstacles::newestPacketUtime() const
{
  return newest_packet_utime_;
}

}  // namespace ifar::executive
