#pragma once
// What the lidar has shown of the static background, kept after it leaves the scan: one bit per layer
// cell, in world cells aligned with the local layer's raster. Walls seen once stay walls, so a goal seen
// through a doorway is not attached through a room's far wall that the corridor hides (the path would
// flip between the room and the corridor each time the vehicle stepped through the door). Movable
// objects are never remembered: they move, and the tracker follows them.
// A pose that jitters, drifts or jumps draws walls where nothing stands; each cell keeps votes (one more
// per scan that hits it, one fewer per scan whose rays pass through it), so what later scans see through
// goes, and a door smeared shut or a wall drawn across the vehicle from a bad pose does not stay.

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/polygon.hpp"
#include "common/span.hpp"
#include "planner/perception/free_space_view.hpp"

namespace ifar::perception {

/// What forgetSeenThrough did in one scan: its work is the cells it checked (those within range).
struct ForgetStats {
  std::size_t checked = 0;       // remembered cells within range of the sensor
  std::size_t seen_through = 0;  // ... that every ray across passed: one vote fewer
  std::size_t forgotten = 0;     // ... of which had none left
};

class BackgroundMemory {
 public:
  /// Cells are kept in square tiles of kTileSide x kTileSide cells, each tile a dense block: a range query
  /// (the layer's square, the carve circle) visits the tiles it overlaps in memory order instead of every
  /// cell of a hash map, so its cost follows the area it asks for, not the length of the drive.
  static constexpr std::int64_t kTileSide = 16;

  /// Cells `cell_size_m` wide (the local layer's), cell (i, j) covering [i, i + 1) x [j, j + 1) cell sizes.
  /// A cell size that is not a positive number remembers nothing. A cell holds up to `max_votes` votes.
  explicit BackgroundMemory(double cell_size_m, int max_votes = 1);

  /// Marks the cells of `points` (world frame) as one scan's: each gains one vote at most. Non-finite points
  /// are skipped. `heights_m` (height above the ground of each point, or empty: as tall as can be) keeps
  /// each cell's highest return, so rays above a low obstacle do not count as seeing through it.
  void remember(common::Span<const geometry::Point> points, common::Span<const float> heights_m = {});

  /// One vote fewer for each cell within `range_m` of the view's origin that the view sees through; a cell
  /// with none left is forgotten.
  ForgetStats forgetSeenThrough(const FreeSpaceView& view, double range_m);

  /// Marks the cells of the obstacle whose outline inflated by `inflation_m` is `inflated_outline`: the
  /// cells inside it at least `inflation_m` from its border (an object found unpushable is background
  /// from then on, also while out of sight). Returns how many cells that was.
  std::size_t rememberInflatedOutline(const geometry::Polygon& inflated_outline, double inflation_m);

  /// Marks the cells along the boundary of `outline`, with no gap between them (a wall known before it is
  /// seen: its outline is enough, the layer inflates it like a scanned wall). Returns how many cells were
  /// new; an outline with a non-finite vertex marks nothing.
  std::size_t rememberOutline(const geometry::Polygon& outline);

  /// Forgets every cell last marked before mark number `first_mark` (marks are counted by markCount()),
  /// except the cells of objects found unpushable. Returns how many went.
  std::size_t forgetMarkedBefore(std::uint32_t first_mark);

  /// How many times cells were marked so far (remember, rememberOutline and rememberInflatedOutline each
  /// count one).
  std::uint32_t markCount() const { return scans_; }

  /// Centres of the remembered cells inside the square [minimum, maximum).
  std::vector<geometry::Point> cellsWithin(const geometry::Point& minimum,
                                           const geometry::Point& maximum) const;

  std::size_t size() const { return size_; }
  double cellSize() const { return cell_size_; }
  /// The votes of the cell holding `point` (0: not remembered).
  int votesAt(const geometry::Point& point) const;

 private:
  struct Cell {
    std::uint8_t votes = 0;       // 0: not remembered (the other fields are then at their defaults)
    std::uint8_t top_cm = 0;      // the highest return seen in it, centimetres above the ground
    bool decided = false;         // an unpushable object's: kept by forgetMarkedBefore
    std::uint32_t last_scan = 0;  // the scan that last gave it a vote
  };
  struct Tile {
    std::array<Cell, kTileSide * kTileSide> cells{};
    std::int32_t live = 0;  // cells with votes
  };
  using Tiles = std::unordered_map<std::uint64_t, Tile>;

  void mark(common::Span<const geometry::Point> points, common::Span<const float> heights_m, int votes,
            bool decided = false);
  /// Forgets the cell at `index` of `tile` (its votes are gone).
  void clear(Tile& tile, std::size_t index);

  double cell_size_;
  int max_votes_;
  std::uint32_t scans_ = 0;
  Tiles tiles_;  // tile column and row packed into one key
  std::size_t size_ = 0;
};

}  // namespace ifar::perception
