#include "planner/perception/background_memory.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <utility>
#include <vector>

#include "planner/perception/cell_key.hpp"

namespace ifar::perception {
namespace {

// Cells beyond this many from the origin are not remembered (2^31 cells of 0.15 m: 300,000 km).
constexpr double kLargestCellIndex = 2147483647.0;
// Heights are kept in centimetres in a byte: 2.55 m is above any obstacle band, and stands for "tall".
constexpr double kTallest = 255.0;

struct CellIndex {
  std::int64_t column = 0;
  std::int64_t row = 0;
};

/// The cell holding `point`; empty for a non-finite point or one beyond kLargestCellIndex cells.
std::optional<CellIndex> cellIndexOf(const geometry::Point& point, double cell_size)
{
  const double column = std::floor(point.x() / cell_size);
  const double row = std::floor(point.y() / cell_size);
  if (!std::isfinite(column) || !std::isfinite(row) || std::abs(column) > kLargestCellIndex ||
      std::abs(row) > kLargestCellIndex) {
    return std::nullopt;
  }
  return CellIndex{static_cast<std::int64_t>(column), static_cast<std::int64_t>(row)};
}

/// The cell index of world coordinate `value`, kept within kLargestCellIndex (infinities included).
std::int64_t clampedCellIndex(double value, double cell_size)
{
  const double index = std::floor(value / cell_size);
  if (std::isnan(index)) {
    return 0;
  }
  return static_cast<std::int64_t>(std::clamp(index, -kLargestCellIndex, kLargestCellIndex));
}

std::int64_t floorDivide(std::int64_t value, std::int64_t divisor)
{
  return value >= 0 ? value / divisor : -((-value + divisor - 1) / divisor);
}

/// Tiles [first, last], inclusive on either axis.
struct TileRange {
  CellIndex first;
  CellIndex last;
  bool contains(const CellIndex& tile) const
  {
    return tile.column >= first.column && tile.column <= last.column && tile.row >= first.row &&
           tile.row <= last.row;
  }
  double count() const
  {
    return (static_cast<double>(last.column - first.column) + 1.0) *
           (static_cast<double>(last.row - first.row) + 1.0);
  }
};

CellIndex unpackCellKey(std::uint64_t key)
{
  return {static_cast<std::int32_t>(static_cast<std::uint32_t>(key >> 32U)),
          static_cast<std::int32_t>(static_cast<std::uint32_t>(key & 0xFFFFFFFFU))};
}

constexpr std::int64_t kTileSide = BackgroundMemory::kTileSide;

/// The centre of cell `index` (row-major) of the tile `tile`.
geometry::Point centreOf(const CellIndex& tile, std::size_t index, double cell_size)
{
  const std::int64_t column = tile.column * kTileSide + static_cast<std::int64_t>(index % kTileSide);
  const std::int64_t row = tile.row * kTileSide + static_cast<std::int64_t>(index / kTileSide);
  return geometry::Point((static_cast<double>(column) + 0.5) * cell_size,
                         (static_cast<double>(row) + 0.5) * cell_size);
}

/// The tile holding cell `at` and the cell's row-major index inside it.
std::pair<CellIndex, std::size_t> tileSlotOf(const CellIndex& at)
{
  const CellIndex tile{floorDivide(at.column, kTileSide), floorDivide(at.row, kTileSide)};
  return {tile, static_cast<std::size_t>((at.row - tile.row * kTileSide) * kTileSide +
                                         (at.column - tile.column * kTileSide))};
}

/// The tiles that hold the square [minimum, maximum].
TileRange tileRangeOf(const geometry::Point& minimum, const geometry::Point& maximum, double cell_size)
{
  return {{floorDivide(clampedCellIndex(minimum.x(), cell_size), kTileSide),
           floorDivide(clampedCellIndex(minimum.y(), cell_size), kTileSide)},
          {floorDivide(clampedCellIndex(maximum.x(), cell_size), kTileSide),
           floorDivide(clampedCellIndex(maximum.y(), cell_size), kTileSide)}};
}

/// Calls visit(tile index, tile) for each tile of `tiles` in `range`: by lookup when the range holds fewer
/// tiles than the map, else by one pass over the map.
template <class TileMap, class Visit>
void forEachTileIn(TileMap& tiles, const TileRange& range, Visit visit)
{
  if (range.count() <= static_cast<double>(tiles.size())) {
    for (std::int64_t row = range.first.row; row <= range.last.row; ++row) {
      for (std::int64_t column = range.first.column; column <= range.last.column; ++column) {
        const auto found = tiles.find(packCellKey(column, row));
        if (found != tiles.end()) {
          visit(CellIndex{column, row}, found->second);
        }
      }
    }
    return;
  }
  for (auto& [key, tile] : tiles) {
    const CellIndex index = unpackCellKey(key);
    if (range.contains(index)) {
      visit(index, tile);
    }
  }
}

}  // namespace

BackgroundMemory::BackgroundMemory(double cell_size_m, int max_votes)
    : cell_size_(cell_size_m), max_votes_(std::clamp(max_votes, 1, 255))
{
}

void BackgroundMemory::remember(common::Span<const geometry::Point> points,
                                common::Span<const float> heights_m)
{
  mark(points, heights_m, 1);
}

void BackgroundMemory::mark(common::Span<const geometry::Point> points, common::Span<const float> heights_m,
                            int votes, bool decided)
{
  if (!(cell_size_ > 0.0) || !std::isfinite(cell_size_)) {
    return;  // unusable settings: perception refuses the frames anyway
  }
  ++scans_;
  const bool with_heights = heights_m.size() == points.size();
  // A scan's returns come in azimuth order: most fall in the tile of the one before.
  std::uint64_t last_key = 0;
  Tile* last_tile = nullptr;
  for (std::size_t index = 0; index < points.size(); ++index) {
    const std::optional<CellIndex> at = cellIndexOf(points[index], cell_size_);
    if (!at) {
      continue;
    }
    const auto [tile_index, slot] = tileSlotOf(*at);
    const std::uint64_t key = packCellKey(tile_index.column, tile_index.row);
    if (last_tile == nullptr || key != last_key) {
      last_tile = &tiles_[key];  // references into an unordered_map stay valid as it grows
      last_key = key;
    }
    Cell& cell = last_tile->cells[slot];
    if (cell.votes == 0) {
      ++last_tile->live;
      ++size_;
    }
    const double height_cm =
        with_heights && std::isfinite(heights_m[index]) ? 100.0 * heights_m[index] : kTallest;
    cell.top_cm = std::max(cell.top_cm, static_cast<std::uint8_t>(std::clamp(height_cm, 0.0, kTallest)));
    cell.decided = cell.decided || decided;
    if (cell.last_scan != scans_) {
      cell.last_scan = scans_;
      cell.votes = static_cast<std::uint8_t>(std::min(static_cast<int>(cell.votes) + votes, max_votes_));
    }
  }
}

void BackgroundMemory::clear(Tile& tile, std::size_t index)
{
  tile.cells[index] = Cell{};
  --tile.live;
  --size_;
}

ForgetStats BackgroundMemory::forgetSeenThrough(const FreeSpaceView& view, double range_m)
{
  ForgetStats stats;
  if (view.empty() || !(range_m > 0.0) || !(cell_size_ > 0.0)) {
    return stats;
  }
  const geometry::Point& origin = view.origin();
  const geometry::Point reach = geometry::Point::Constant(range_m);
  std::vector<std::uint64_t> emptied;
  const auto forget_in_tile = [&](const CellIndex& at, Tile& tile) {
    for (std::size_t index = 0; index < tile.cells.size(); ++index) {
      Cell& cell = tile.cells[index];
      if (cell.votes == 0) {
        continue;
      }
      const geometry::Point centre = centreOf(at, index, cell_size_);
      if ((centre - origin).squaredNorm() > range_m * range_m) {
        continue;
      }
      ++stats.checked;
      if (!view.seesThrough(centre, cell_size_, cell.top_cm / 100.0)) {
        continue;
      }
      ++stats.seen_through;
      if (--cell.votes == 0) {
        ++stats.forgotten;
        clear(tile, index);
      }
    }
    if (tile.live == 0) {
      emptied.push_back(packCellKey(at.column, at.row));
    }
  };
  forEachTileIn(tiles_, tileRangeOf(origin - reach, origin + reach, cell_size_), forget_in_tile);
  for (const std::uint64_t key : emptied) {
    tiles_.erase(key);
  }
  return stats;
}

std::size_t BackgroundMemory::forgetMarkedBefore(std::uint32_t first_mark)
{
  std::size_t forgotten = 0;
  for (auto tile = tiles_.begin(); tile != tiles_.end();) {
    for (std::size_t index = 0; index < tile->second.cells.size(); ++index) {
      const Cell& cell = tile->second.cells[index];
      if (cell.votes > 0 && !cell.decided && cell.last_scan < first_mark) {
        clear(tile->second, index);
        ++forgotten;
      }
    }
    tile = tile->second.live == 0 ? tiles_.erase(tile) : std::next(tile);
  }
  return forgotten;
}

int BackgroundMemory::votesAt(const geometry::Point& point) const
{
  const std::optional<CellIndex> at = cellIndexOf(point, cell_size_);
  if (!at) {
    return 0;
  }
  const auto [tile_index, slot] = tileSlotOf(*at);
  const auto found = tiles_.find(packCellKey(tile_index.column, tile_index.row));
  return found == tiles_.end() ? 0 : found->second.cells[slot].votes;
}

std::size_t BackgroundMemory::rememberOutline(const geometry::Polygon& outline)
{
  if (outline.empty() || !(cell_size_ > 0.0) || !std::isfinite(cell_size_) ||
      !std::all_of(outline.begin(), outline.end(),
                   [](const geometry::Point& vertex) { return vertex.allFinite(); })) {
    return 0;
  }
  const std::size_t before = size_;
  std::vector<geometry::Point> samples;
  for (std::size_t index = 0; index < outline.size(); ++index) {
    const geometry::Point& start = outline[index];
    const geometry::Point& end = outline[(index + 1) % outline.size()];
    // Samples under half a cell apart fall in the same or neighbouring cells: the marked cells leave no
    // gap along the edge (a cell the edge only clips at a corner may stay unmarked).
    const double steps = std::ceil((end - start).norm() / (0.45 * cell_size_));
    if (steps > kLargestCellIndex) {
      continue;
    }
    const auto count = static_cast<std::int64_t>(steps);
    for (std::int64_t step = 0; step <= count; ++step) {
      samples.push_back(count == 0 ? start : start + (end - start) * (static_cast<double>(step) / steps));
    }
  }
  remember(common::Span<const geometry::Point>(samples.data(), samples.size()));
  return size_ - before;
}

std::size_t BackgroundMemory::rememberInflatedOutline(const geometry::Polygon& inflated_outline,
                                                      double inflation_m)
{
  if (inflated_outline.size() < 3 || !(cell_size_ > 0.0) || !std::isfinite(cell_size_)) {
    return 0;
  }
  geometry::Point minimum = inflated_outline.front();
  geometry::Point maximum = inflated_outline.front();
  for (const geometry::Point& point : inflated_outline) {
    if (!point.allFinite()) {
      return 0;
    }
    minimum = minimum.cwiseMin(point);
    maximum = maximum.cwiseMax(point);
  }
  // Half a cell of slack: the outline was traced on cells, so its border is a cell's width uncertain.
  const double inside_m = std::max(0.0, inflation_m - 0.5 * cell_size_);
  std::vector<geometry::Point> cells;
  // Integer cell indices (a floating-point counter would drift over a long outline).
  const auto first_column = static_cast<std::int64_t>(std::floor(minimum.x() / cell_size_));
  const auto first_row = static_cast<std::int64_t>(std::floor(minimum.y() / cell_size_));
  for (std::int64_t row = first_row; (static_cast<double>(row) + 0.5) * cell_size_ < maximum.y(); ++row) {
    for (std::int64_t column = first_column; (static_cast<double>(column) + 0.5) * cell_size_ < maximum.x();
         ++column) {
      const geometry::Point centre((static_cast<double>(column) + 0.5) * cell_size_,
                                   (static_cast<double>(row) + 0.5) * cell_size_);
      if (geometry::containsPoint(inflated_outline, centre) &&
          geometry::distanceToBoundary(inflated_outline, centre) >= inside_m) {
        cells.push_back(centre);
      }
    }
  }
  // Decided (an object found unpushable): as sure as a wall seen for long.
  mark(common::Span<const geometry::Point>(cells.data(), cells.size()), {}, max_votes_, true);
  return cells.size();
}

std::vector<geometry::Point> BackgroundMemory::cellsWithin(const geometry::Point& minimum,
                                                           const geometry::Point& maximum) const
{
  std::vector<geometry::Point> centres;
  if (!(cell_size_ > 0.0) || !std::isfinite(cell_size_)) {
    return centres;
  }
  centres.reserve(size_);
  const double tile_size = cell_size_ * static_cast<double>(kTileSide);
  const auto take_from_tile = [&](const CellIndex& at, const Tile& tile) {
    const geometry::Point tile_minimum(static_cast<double>(at.column) * tile_size,
                                       static_cast<double>(at.row) * tile_size);
    const geometry::Point tile_maximum = tile_minimum + geometry::Point::Constant(tile_size);
    // A tile wholly inside the window needs no test per cell (most tiles, for the layer's square).
    const bool inside = tile_minimum.x() >= minimum.x() && tile_minimum.y() >= minimum.y() &&
                        tile_maximum.x() < maximum.x() && tile_maximum.y() < maximum.y();
    for (std::size_t index = 0; index < tile.cells.size(); ++index) {
      if (tile.cells[index].votes == 0) {
        continue;
      }
      const geometry::Point centre = centreOf(at, index, cell_size_);
      if (inside || (centre.x() >= minimum.x() && centre.y() >= minimum.y() && centre.x() < maximum.x() &&
                     centre.y() < maximum.y())) {
        centres.push_back(centre);
      }
    }
  };
  forEachTileIn(tiles_, tileRangeOf(minimum, maximum, cell_size_), take_from_tile);
  return centres;
}

}  // namespace ifar::perception
