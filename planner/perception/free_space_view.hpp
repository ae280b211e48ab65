#pragma once
// Where one scan's rays went through empty space, as seen from the sensor: for each azimuth bin, how far
// its rays stayed in the obstacle height band before they ended (a return) or left the band. A
// remembered obstacle cell that every ray across it passed well beyond is seen through: the estimator's
// jitter, drift or a jump once drew it where nothing stands. Rays without a return say nothing.

#include <cstddef>
#include <utility>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/span.hpp"
#include "planner/perception/world_point.hpp"

namespace ifar::perception {

struct FreeSpaceSettings {
  double ground_clearance_m = 0.15;  // the obstacle height band (above the ground under the vehicle)
  double vehicle_height_m = 1.2;
  double min_range_m = 0.4;  // closer returns are the vehicle itself: they show nothing
  /// A ray must pass a cell's far side by this much to see through it: the lidar's range noise and the
  /// pose's jitter along the ray.
  double margin_m = 0.1;
};

class FreeSpaceView {
 public:
  FreeSpaceView() = default;
  /// The rays of `points` (world frame, each with its sensor origin) binned around `origin`, the sensor
  /// at the end of the scan. Non-finite points and returns closer than min_range_m are skipped.
  FreeSpaceView(common::Span<const WorldPoint> points, const geometry::Point& origin,
                const FreeSpaceSettings& settings);

  /// Whether every bin across the square cell of side `cell_size_m` centred at `centre` holds a ray that
  /// went past the cell's far side by the margin, crossing it no higher than `top_m` above the ground
  /// (a ray over a low obstacle does not show it gone). A cell holding the origin is never seen through.
  bool seesThrough(const geometry::Point& centre, double cell_size_m, double top_m) const;

  /// Whether every bin across the square cell of side `cell_size_m` centred at `centre` holds a ray that
  /// got at least to the cell's near side: the scan looked at the cell (hit it or passed it), nothing
  /// nearer hid it. A cell holding the origin is never reached.
  bool reaches(const geometry::Point& centre, double cell_size_m) const;

  const geometry::Point& origin() const { return origin_; }
  std::size_t rays() const { return rays_; }
  bool empty() const { return rays_ == 0; }

 private:
  /// The farthest in-band reach of one bin's rays: of those that do not climb (no higher anywhere than
  /// the sensor), and of those that do, with how steeply the farthest of them climbs.
  struct Bin {
    float level_reach = 0.0F;
    float climbing_reach = 0.0F;
    float climb = 0.0F;  // metres up per metre out
  };

  /// The bins across the square cell at `centre`, as the first bin and how many; none (0) when the cell
  /// holds the origin. `range` is the cell centre's distance from the origin.
  std::pair<std::size_t, std::size_t> binsAcross(const geometry::Point& centre, double half_diagonal,
                                                 double& range) const;

  bool binSeesThrough(const Bin& bin, double range, double needed, double top_m) const;

  geometry::Point origin_ = geometry::Point::Zero();
  double margin_m_ = 0.1;
  double sensor_height_m_ = 0.0;  // the highest any ray started
  std::size_t rays_ = 0;
  std::vector<Bin> bins_;
};

}  // namespace ifar::perception
