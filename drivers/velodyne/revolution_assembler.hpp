#pragma once
// Gathers decoded points into full revolutions, cutting where the azimuth wraps past 360 degrees.

#include <cstdint>
#include <functional>
#include <vector>

#include "common/span.hpp"
#include "drivers/velodyne/point.hpp"

namespace ifar::velodyne {

/// One sweep of the sensor. Points keep packet order; their time_offset_us is re-based to start_time_us.
struct Revolution {
  std::int64_t start_time_us = 0;  // time of the first packet that contributed (caller's clock)
  std::size_t packet_count = 0;
  std::vector<Point> points;
};

class RevolutionAssembler {
 public:
  using Handler = std::function<void(const Revolution&)>;

  /// `handler` is called for each completed revolution, from within add() or flush().
  explicit RevolutionAssembler(Handler handler);

  /// Adds the points of one packet taken at `packet_time_us` (any microsecond clock, e.g. host receive
  /// time or the unwrapped device time). A point whose azimuth is more than 180 degrees below the previous
  /// point's starts a new revolution, so small backward steps (dual return pairs, jitter) never cut.
  void add(common::Span<const Point> packet_points, std::int64_t packet_time_us);

  /// Emits the partial revolution held so far (if it has points) and starts empty.
  void flush();

  /// Points gathered for the revolution in progress.
  std::size_t pendingPoints() const { return current_.points.size(); }

 private:
  Handler handler_;
  Revolution current_;
  float previous_azimuth_degrees_ = 0.0F;
  bool has_previous_ = false;
};

}  // namespace ifar::velodyne
