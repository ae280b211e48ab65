#pragma once
// The VLP-16's timing and geometry: 16 lasers at their real vertical angles fire one after another every
// 2.304 us, a firing sequence every 55.296 us while the head spins at 10 Hz (about 0.2 degree per firing),
// 24 firings to a packet (about 754 packets per second). Each laser's ray is cast at its own firing time
// and azimuth from the sensor's pose, interpolated over the step.
//
// Mounting: the sensor sits at (lidar_x_m, 0, lidar_height_m) in the vehicle frame with its azimuth 0
// (sensor +Y) pointing forward along the vehicle's +x, and sensor +X to the vehicle's right; azimuth
// grows clockwise seen from above, as the sensor reports it.

#include <array>
#include <cstdint>
#include <vector>

#include "common/geometry/pose2.hpp"
#include "sim/lidar/lidar_scene.hpp"
#include "sim/lidar/vlp16_packet_encoder.hpp"
#include "sim/sensing/lidar_model.hpp"

namespace ifar::sim::lidar {

/// Vertical angles in degrees by laser index (data channel order).
constexpr std::array<double, kVlp16Lasers> kVlp16VerticalAnglesDeg = {-15, 1, -13, 3,  -11, 5,  -9, 7,
                                                                      -7,  9, -5,  11, -3,  13, -1, 15};
constexpr std::int64_t kVlp16LaserIntervalNs = 2304;
constexpr std::int64_t kVlp16FiringIntervalNs = 55296;

struct Vlp16Settings {
  double rotation_hz = 10.0;
  double max_range_m = 100.0;      // slant range beyond which the sensor reports no return
  double min_range_m = 0.4;        // closer returns are dropped, as the real sensor does
  double mount_x_m = 0.2;          // vehicle frame
  double mount_height_m = 0.8;     // above ground
  double start_azimuth_deg = 0.0;  // head azimuth at time 0
  LidarModelSettings model;        // noise, dropouts, reach and reflectivity errors (all 0 = exact)
  std::uint64_t seed = 1;          // the simulator's seed (the model draws from a stream of its own)
};

/// One laser return as fired (for tests and tools): what the encoder wrote and where it hit.
struct Vlp16Return {
  std::int64_t time_ns = 0;
  int laser = 0;
  double azimuth_deg = 0.0;       // clockwise from the sensor's +Y (vehicle forward)
  double slant_distance_m = 0.0;  // 0 = no return
  std::uint8_t reflectivity = 0;
  RayHit::Surface surface = RayHit::Surface::None;
};

class Vlp16Scanner {
 public:
  explicit Vlp16Scanner(const Vlp16Settings& settings);

  /// Fires every laser whose firing time lies in (previous end, end_time_ns], with the vehicle pose
  /// interpolated linearly from `pose_before` (at the previous end) to `pose_after` (at end_time_ns), and
  /// returns the packets completed. `epoch_utime` is the Unix time in microseconds of time 0 (for the
  /// timestamps past the hour). When `returns` is not null every fired laser is appended to it.
  std::vector<Vlp16Packet> advance(std::int64_t end_time_ns, const geometry::Pose2& pose_before,
                                   const geometry::Pose2& pose_after, const LidarScene& scene,
                                   std::int64_t epoch_utime, std::vector<Vlp16Return>* returns = nullptr);

  /// Head azimuth in degrees [0, 360) at `time_ns`.
  double azimuthAt(std::int64_t time_ns) const;
  const Vlp16Settings& settings() const { return settings_; }

 private:
  Vlp16Settings settings_;
  LidarReturnModel model_;
  std::array<double, kVlp16Lasers> slopes_{};
  std::array<double, kVlp16Lasers> cosines_{};
  std::int64_t next_firing_ = 0;  // index of the next firing sequence
  std::int64_t previous_end_ns_ = 0;
  std::array<Vlp16Block, kVlp16BlocksPerPacket> blocks_{};
  std::int64_t packet_start_ns_ = 0;
};

}  // namespace ifar::sim::lidar
