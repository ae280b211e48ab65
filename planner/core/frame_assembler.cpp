#include "planner/core/frame_assembler.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/time.hpp"
#include "drivers/velodyne/packet_decoder.hpp"
#include "planner/core/planner_status.hpp"
#include "planner/perception/motion_compensation.hpp"

namespace ifar::planner {

const char* toString(InputVerdict verdict)
{
  switch (verdict) {
    case InputVerdict::Accepted:
      return "accepted";
    case InputVerdict::NonFinite:
      return "not finite";
    case InputVerdict::NotUnitQuaternion:
      return "orientation is not a unit quaternion";
    case InputVerdict::OutOfOrder:
      return "out of order";
    case InputVerdict::FromFuture:
      return "from the future";
    case InputVerdict::Undecodable:
      return "not a valid VLP-16 packet";
  }
  return "unknown";
}

FrameAssembler::FrameAssembler(const InputSettings& settings)
    : settings_(settings),
      assembler_([this](const velodyne::Revolution& revolution) { onRevolution(revolution); })
{
}

void FrameAssembler::reject(InputVerdict verdict, std::int32_t flag, const std::string& what)
{
  ++rejected_;
  pending_flags_ |= flag;
  // One reason per kind is enough for a status message; counts are in rejectedInputs().
  const std::string reason = what + " " + toString(verdict);
  if (pending_problems_.find(reason) == std::string::npos) {
    pending_problems_ += pending_problems_.empty() ? reason : "; " + reason;
  }
}

InputVerdict FrameAssembler::addPacket(common::ByteView payload, std::int64_t packet_utime,
                                       std::int64_t now_utime)
{
  if (packet_utime > now_utime + common::secondsToMicroseconds(settings_.max_future_s)) {
    reject(InputVerdict::FromFuture, kFlagStaleInput, "packet");
    return InputVerdict::FromFuture;
  }
  if (last_packet_utime_ && packet_utime < *last_packet_utime_) {
    reject(InputVerdict::OutOfOrder, kFlagStaleInput, "packet");
    return InputVerdict::OutOfOrder;
  }
  decoded_.clear();
  const velodyne::DecodeResult result = velodyne::decodePacket(payload, decoded_);
  if (result.info.status != velodyne::PacketStatus::kOk) {
    reject(InputVerdict::Undecodable, kFlagStaleInput, "packet");
    return InputVerdict::Undecodable;
  }
  last_packet_utime_ = packet_utime;
  assembler_.add(common::Span<const velodyne::Point>(decoded_.data(), decoded_.size()), packet_utime);
  return InputVerdict::Accepted;
}

InputVerdict FrameAssembler::addPose(const PoseSample& pose, std::int64_t now_utime)
{
  if (!pose.position.allFinite() || !pose.orientation.coeffs().allFinite()) {
    reject(InputVerdict::NonFinite, kFlagBadPose, "pose");
    return InputVerdict::NonFinite;
  }
  if (std::abs(pose.orientation.norm() - 1.0) > 1e-3) {
    reject(InputVerdict::NotUnitQuaternion, kFlagBadPose, "pose");
    return InputVerdict::NotUnitQuaternion;
  }
  if (pose.utime > now_utime + common::secondsToMicroseconds(settings_.max_future_s)) {
    reject(InputVerdict::FromFuture, kFlagBadPose, "pose");
    return InputVerdict::FromFuture;
  }
  if (!poses_.empty() && pose.utime <= poses_.back().utime) {
    reject(InputVerdict::OutOfOrder, kFlagBadPose, "pose");
    return InputVerdict::OutOfOrder;
  }
  PoseSample accepted = pose;
  accepted.orientation.normalize();
  poses_.push_back(accepted);
  const std::int64_t oldest_kept = pose.utime - common::secondsToMicroseconds(settings_.pose_history_s);
  while (poses_.size() > 2 && poses_.front().utime < oldest_kept) {
    poses_.pop_front();
  }
  return InputVerdict::Accepted;
}

void FrameAssembler::setDetectorPolygons(std::optional<std::vector<geometry::Polygon>> polygons)
{
  detector_polygons_ = std::move(polygons);
}

std::vector<FrameInput> FrameAssembler::takeFrames()
{
  std::vector<FrameInput> frames;
  frames.swap(completed_);
  return frames;
}

void FrameAssembler::flush()
{
  assembler_.flush();
}

std::optional<PoseSample> FrameAssembler::latestPose() const
{
  if (poses_.empty()) {
    return std::nullopt;
  }
  return poses_.back();
}

namespace {

Eigen::Isometry3d toIsometry(const PoseSample& pose)
{
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = pose.orientation.toRotationMatrix();
  transform.translation() = pose.position;
  return transform;
}

}  // namespace

std::optional<Eigen::Isometry3d> FrameAssembler::poseAt(std::int64_t utime) const
{
  if (poses_.empty()) {
    return std::nullopt;
  }
  const std::int64_t tolerance = common::secondsToMicroseconds(settings_.stale_input_age_s);
  if (utime <= poses_.front().utime) {
    return poses_.front().utime - utime <= tolerance ? std::optional(toIsometry(poses_.front()))
                                                     : std::nullopt;
  }
  if (utime >= poses_.back().utime) {
    return utime - poses_.back().utime <= tolerance ? std::optional(toIsometry(poses_.back())) : std::nullopt;
  }
  const auto after =
      std::upper_bound(poses_.begin(), poses_.end(), utime,
                       [](std::int64_t time, const PoseSample& pose) { return time < pose.utime; });
  const auto before = std::prev(after);
  perception::ScanMotion between;
  between.vehicle_at_start = toIsometry(*before);
  between.vehicle_at_end = toIsometry(*after);
  between.duration_s = common::microsecondsToSeconds(after->utime - before->utime);
  return perception::interpolateVehiclePose(between, common::microsecondsToSeconds(utime - before->utime));
}

void FrameAssembler::onRevolution(const velodyne::Revolution& revolution)
{
  FrameInput frame;
  frame.utime = revolution.start_time_us;
  frame.points.reserve(revolution.points.size());
  float last_offset_us = 0.0F;
  for (const velodyne::Point& point : revolution.points) {
    perception::SensorPoint sensor_point;
    sensor_point.position_sensor = Eigen::Vector3f(point.x, point.y, point.z);
    sensor_point.reflectivity = static_cast<float>(point.reflectivity);
    sensor_point.time_offset_s = static_cast<double>(point.time_offset_us) * 1e-6;
    frame.points.push_back(sensor_point);
    if (std::isfinite(point.time_offset_us)) {
      last_offset_us = std::max(last_offset_us, point.time_offset_us);
    }
  }
  const std::int64_t end_utime = revolution.start_time_us + static_cast<std::int64_t>(last_offset_us);
  const auto start_pose = poseAt(revolution.start_time_us);
  const auto end_pose = poseAt(end_utime);
  if (start_pose && end_pose) {
    frame.has_motion = true;
    frame.motion.vehicle_at_start = *start_pose;
    frame.motion.vehicle_at_end = *end_pose;
    frame.motion.duration_s = common::microsecondsToSeconds(end_utime - revolution.start_time_us);
  } else {
    pending_flags_ |= kFlagStaleInput;
    const std::string reason = "no pose within stale_input_age_s of the scan";
    pending_problems_ += pending_problems_.empty() ? reason : "; " + reason;
  }
  frame.flags = pending_flags_;
  frame.problems = pending_problems_;
  frame.detector_polygons = detector_polygons_;
  pending_flags_ = 0;
  pending_problems_.clear();
  completed_.push_back(std::move(frame));
}

}  // namespace ifar::planner
