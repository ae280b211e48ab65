#include "sim/lidar/vlp16_scanner.hpp"

#include <algorithm>
#include <cmath>

#include "common/geometry/angle.hpp"

namespace ifar::sim::lidar {
namespace {

constexpr double kDegree = geometry::radiansFromDegrees(1.0);
constexpr std::int64_t kMicrosecondsPerHour = 3'600'000'000LL;

}  // namespace

Vlp16Scanner::Vlp16Scanner(const Vlp16Settings& settings)
    : settings_(settings), model_(settings.model, settings.seed)
{
  for (std::size_t laser = 0; laser < kVlp16Lasers; ++laser) {
    slopes_[laser] = std::tan(kVlp16VerticalAnglesDeg[laser] * kDegree);
    cosines_[laser] = std::cos(kVlp16VerticalAnglesDeg[laser] * kDegree);
  }
}

double Vlp16Scanner::azimuthAt(std::int64_t time_ns) const
{
  // Integer nanoseconds keep the firing times exact; the phase is reduced before scaling to degrees.
  const double revolutions = settings_.rotation_hz * static_cast<double>(time_ns) * 1e-9;
  double azimuth = settings_.start_azimuth_deg + 360.0 * (revolutions - std::floor(revolutions));
  azimuth = std::fmod(azimuth, 360.0);
  return azimuth < 0.0 ? azimuth + 360.0 : azimuth;
}

std::vector<Vlp16Packet> Vlp16Scanner::advance(std::int64_t end_time_ns, const geometry::Pose2& pose_before,
                                               const geometry::Pose2& pose_after, const LidarScene& scene,
                                               std::int64_t epoch_utime, std::vector<Vlp16Return>* returns)
{
  std::vector<Vlp16Packet> packets;
  const std::int64_t start_ns = previous_end_ns_;
  const double span_ns = static_cast<double>(end_time_ns - start_ns);
  const double heading_change = std::remainder(pose_after.heading - pose_before.heading, 2.0 * geometry::kPi);
  while (next_firing_ * kVlp16FiringIntervalNs <= end_time_ns) {
    const std::int64_t firing_ns = next_firing_ * kVlp16FiringIntervalNs;
    const std::size_t in_packet = static_cast<std::size_t>(next_firing_ % kVlp16FiringsPerPacket);
    if (in_packet == 0) {
      packet_start_ns_ = firing_ns;
    }
    Vlp16Block& block = blocks_[in_packet / 2];
    Vlp16Firing& firing = in_packet % 2 == 0 ? block.first : block.second;
    if (in_packet % 2 == 0) {
      block.azimuth_centidegrees =
          static_cast<std::uint16_t>(std::lround(azimuthAt(firing_ns) * 100.0) % 36000);
    }
    for (std::size_t laser = 0; laser < kVlp16Lasers; ++laser) {
      const std::int64_t laser_ns = firing_ns + static_cast<std::int64_t>(laser) * kVlp16LaserIntervalNs;
      const double fraction = span_ns > 0.0 ? static_cast<double>(laser_ns - start_ns) / span_ns : 1.0;
      const double heading = pose_before.heading + fraction * heading_change;
      const double base_x = pose_before.x + fraction * (pose_after.x - pose_before.x);
      const double base_y = pose_before.y + fraction * (pose_after.y - pose_before.y);
      const double azimuth_deg = azimuthAt(laser_ns);
      const double direction = heading - azimuth_deg * kDegree;
      Ray ray;
      ray.origin_x = base_x + settings_.mount_x_m * std::cos(heading);
      ray.origin_y = base_y + settings_.mount_x_m * std::sin(heading);
      ray.height = settings_.mount_height_m;
      ray.direction_x = std::cos(direction);
      ray.direction_y = std::sin(direction);
      ray.slope = slopes_[laser];
      ray.max_horizontal = settings_.max_range_m * cosines_[laser];
      const RayHit hit = scene.cast(ray);
      double slant = hit.horizontal_distance / cosines_[laser];
      bool returned = hit.surface != RayHit::Surface::None;
      std::uint8_t reflectivity =
          returned ? static_cast<std::uint8_t>(std::lround(std::clamp(hit.reflectivity, 0.0, 1.0) * 255.0))
                   : 0;
      if (returned && model_.active()) {
        // A face's normal is horizontal (incidence from the beam's elevation and its facing), a top's and
        // the ground's vertical.
        const double cos_incidence = hit.surface == RayHit::Surface::Wall
                                         ? cosines_[laser] * hit.wall_facing
                                         : std::abs(std::sin(kVlp16VerticalAnglesDeg[laser] * kDegree));
        const LidarReturn modelled =
            model_.apply(slant, hit.reflectivity, cos_incidence, hit.surface == RayHit::Surface::Ground);
        returned = modelled.returned;
        slant = modelled.slant_m;
        reflectivity = modelled.reflectivity;
      }
      returned = returned && slant >= settings_.min_range_m && slant <= settings_.max_range_m;
      const long units = returned ? std::lround(slant / kVlp16DistanceUnitM) : 0;
      firing.distance_units[laser] = static_cast<std::uint16_t>(std::min<long>(units, 0xFFFF));
      firing.reflectivity[laser] = returned ? reflectivity : 0;
      if (returns != nullptr) {
        returns->push_back({laser_ns, static_cast<int>(laser), azimuth_deg, returned ? slant : 0.0,
                            firing.reflectivity[laser], returned ? hit.surface : RayHit::Surface::None});
      }
    }
    if (in_packet == kVlp16FiringsPerPacket - 1) {
      const std::int64_t utime = epoch_utime + packet_start_ns_ / 1000;
      const auto past_hour = static_cast<std::uint32_t>(
          ((utime % kMicrosecondsPerHour) + kMicrosecondsPerHour) % kMicrosecondsPerHour);
      packets.push_back(encodeVlp16Packet(blocks_, past_hour));
    }
    ++next_firing_;
  }
  previous_end_ns_ = end_time_ns;
  return packets;
}

}  // namespace ifar::sim::lidar
