#include "drivers/velodyne/revolution_assembler.hpp"

#include <utility>

namespace ifar::velodyne {
namespace {
constexpr float kWrapDropDegrees = 180.0F;
}  // namespace

RevolutionAssembler::RevolutionAssembler(Handler handler) : handler_(std::move(handler)) {}

void RevolutionAssembler::add(common::Span<const Point> packet_points, std::int64_t packet_time_us)
{
  bool counted_packet = false;
  for (const Point& point : packet_points) {
    if (has_previous_ && previous_azimuth_degrees_ - point.azimuth_degrees > kWrapDropDegrees) {
      flush();
      counted_packet = false;
    }
    previous_azimuth_degrees_ = point.azimuth_degrees;
    has_previous_ = true;
    if (current_.points.empty()) {
      current_.start_time_us = packet_time_us;
      current_.packet_count = 0;
    }
    if (!counted_packet) {
      ++current_.packet_count;
      counted_packet = true;
    }
    Point rebased = point;
    rebased.time_offset_us += static_cast<float>(packet_time_us - current_.start_time_us);
    current_.points.push_back(rebased);
  }
}

void RevolutionAssembler::flush()
{
  if (!current_.points.empty()) {
    handler_(current_);
  }
  current_.points.clear();
  current_.packet_count = 0;
}

}  // namespace ifar::velodyne
