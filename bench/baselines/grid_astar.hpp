#pragma once
// The grid baseline: 8-connected A* over the cells of a dense occupancy grid (the caller inflates the
// obstacles first, e.g. by the vehicle's half width; GPPC maps use zero inflation). Moves go between
// cell centres; a diagonal move needs both side cells free (no corner cutting). Octile heuristic,
// binary heap, flat arrays sized once per map so repeated queries allocate nothing.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bench/baselines/baseline_result.hpp"
#include "common/geometry/point.hpp"
#include "common/grid_map/grid_map.hpp"

namespace ifar::baselines {

struct GridSearchStats {
  std::size_t expansions = 0;
  std::size_t path_cells = 0;
};

class GridAStar {
 public:
  /// Copies the blocked/free state of `map` (Unknown cells count as `policy` says).
  explicit GridAStar(const grid_map::GridMap& map,
                     grid_map::UnknownPolicy policy = grid_map::UnknownPolicy::AsBlocked);

  /// Cell-to-cell search; length in world units (grid steps times the resolution).
  BaselineResult findPath(const grid_map::CellIndex& start, const grid_map::CellIndex& goal,
                          GridSearchStats* stats = nullptr);
  /// World-point search: each point goes to the free cell holding it (for a point on a cell corner, the
  /// nearest free one of the cells around it) and the straight pieces to and from those cell centres are
  /// added to the length.
  BaselineResult findPath(const geometry::Point& start, const geometry::Point& goal,
                          GridSearchStats* stats = nullptr);

  bool blocked(int x, int y) const
  {
    return x < 0 || y < 0 || x >= width_ || y >= height_ ||
           blocked_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                    static_cast<std::size_t>(x)] != 0;
  }

 private:
  struct QueueEntry {
    double priority;
    std::uint32_t cell;
  };
  /// The free cell a world point belongs to, or false.
  bool freeCellFor(const geometry::Point& point, grid_map::CellIndex& cell) const;

  int width_ = 0;
  int height_ = 0;
  double resolution_ = 1.0;
  geometry::Point origin_ = geometry::Point::Zero();
  std::vector<std::uint8_t> blocked_;
  std::vector<double> cost_so_far_;
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint32_t> seen_stamp_;
  std::vector<std::uint32_t> closed_stamp_;
  std::vector<QueueEntry> queue_;
  std::uint32_t generation_ = 0;
};

}  // namespace ifar::baselines
