#pragma once
// What the lidar has shown of the static background, kept after it leaves the scan: one bit per layer
// cell, in world cells aligned with the local layer's raster. Walls seen once stay walls, so a goal seen
// through a doorway is not attached through a room's far wall that the corridor hides (the path would
// flip between the room and the corridor each time the vehicle stepped through the door). Movable
// objects are never remembered: they move, and the tracker follows them.

#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/polygon.hpp"
#include "common/span.hpp"

namespace ifar::perception {

class BackgroundMemory {
 public:
  /// Cells `cell_size_m` wide (the local layer's), cell (i, j) covering [i, i + 1) x [j, j + 1) cell sizes.
  /// A cell size that is not a positive number remembers nothing.
  explicit BackgroundMemory(double cell_size_m);

  /// Marks the cells of `points` (world frame); non-finite points are skipped.
  void remember(common::Span<const geometry::Point> points);

  /// Marks the cells of the obstacle whose outline inflated by `inflation_m` is `inflated_outline`: the
  /// cells inside it at least `inflation_m` from its border (an object found unpushable is background
  /// from then on, also while out of sight). Returns how many cells that was.
  std::size_t rememberInflatedOutline(const geometry::Polygon& inflated_outline, double inflation_m);

  /// Marks the cells along the boundary of `outline`, with no gap between them (a wall known before it is
  /// seen: its outline is enough, the layer inflates it like a scanned wall). Returns how many cells were
  /// new; an outline with a non-finite vertex marks nothing.
  std::size_t rememberOutline(const geometry::Polygon& outline);

  /// Centres of the remembered cells inside the square [minimum, maximum).
  std::vector<geometry::Point> cellsWithin(const geometry::Point& minimum,
                                           const geometry::Point& maximum) const;

  std::size_t size() const { return cells_.size(); }
  double cellSize() const { return cell_size_; }

 private:
  double cell_size_;
  std::unordered_set<std::uint64_t> cells_;  // column and row packed into one key
};

}  // namespace ifar::perception
