#pragma once
// Input side of the planner: raw VLP-16 packets and vehicle poses in, checked and gathered into one
// frame per sensor revolution (points in the sensor frame plus the vehicle's motion over the scan).
// Bad input is refused with a verdict and remembered as a flag on the next frame; it never throws.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/geometry/polygon.hpp"
#include "common/span.hpp"
#include "drivers/velodyne/revolution_assembler.hpp"
#include "planner/perception/sensor_point.hpp"

namespace ifar::planner {

/// Limits on input times, from the `daemon:` section of config/planner.yaml.
struct InputSettings {
  double max_future_s = 0.5;       // inputs stamped later than now + this are refused
  double stale_input_age_s = 0.5;  // a scan end farther than this from every pose cannot be placed
  double pose_history_s = 5.0;     // poses kept for interpolation
};

/// A vehicle base pose in the world frame (z up) at `utime`, as the state estimator sends it.
struct PoseSample {
  std::int64_t utime = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // body to world; must be unit length
};

enum class InputVerdict {
  Accepted,
  NonFinite,          // NaN or infinite time, position or orientation
  NotUnitQuaternion,  // orientation norm differs from 1 by more than 1e-3
  OutOfOrder,         // older than the last accepted input of the same kind
  FromFuture,         // stamped later than now + max_future_s
  Undecodable,        // the packet fails the VLP-16 format checks
};

const char* toString(InputVerdict verdict);

/// One revolution ready for Planner::processFrame.
struct FrameInput {
  std::int64_t utime = 0;  // scan start, microseconds
  std::vector<perception::SensorPoint> points;
  perception::ScanMotion motion;
  bool has_motion = false;  // false: no pose near the scan, the frame cannot be placed in the world
  std::int32_t flags = 0;   // PlannerFlag bits for input refused since the previous frame
  std::string problems;     // the reasons behind `flags`, for the status message
  std::optional<std::vector<geometry::Polygon>> detector_polygons;  // movable outlines, world frame
};

class FrameAssembler {
 public:
  explicit FrameAssembler(const InputSettings& settings);
  FrameAssembler(const FrameAssembler&) = delete;
  FrameAssembler& operator=(const FrameAssembler&) = delete;

  /// Checks and decodes one packet received at `packet_utime`; `now_utime` is the caller's clock.
  InputVerdict addPacket(common::ByteView payload, std::int64_t packet_utime, std::int64_t now_utime);
  InputVerdict addPose(const PoseSample& pose, std::int64_t now_utime);
  /// Detector outlines to attach to the following frames (world frame); nullopt = reflectivity decides.
  void setDetectorPolygons(std::optional<std::vector<geometry::Polygon>> polygons);

  /// Frames completed since the last call, oldest first.
  std::vector<FrameInput> takeFrames();
  /// Completes the revolution in progress (end of a log).
  void flush();

  std::int64_t rejectedInputs() const { return rejected_; }
  std::optional<PoseSample> latestPose() const;

 private:
  void onRevolution(const velodyne::Revolution& revolution);
  void reject(InputVerdict verdict, std::int32_t flag, const std::string& what);
  std::optional<Eigen::Isometry3d> poseAt(std::int64_t utime) const;

  InputSettings settings_;
  velodyne::RevolutionAssembler assembler_;
  std::vector<velodyne::Point> decoded_;  // scratch for one packet
  std::deque<PoseSample> poses_;          // increasing utime
  std::optional<std::int64_t> last_packet_utime_;
  std::optional<std::vector<geometry::Polygon>> detector_polygons_;
  std::vector<FrameInput> completed_;
  std::int32_t pending_flags_ = 0;
  std::string pending_problems_;
  std::int64_t rejected_ = 0;
};

}  // namespace ifar::planner
