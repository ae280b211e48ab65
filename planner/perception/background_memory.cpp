#include "planner/perception/background_memory.hpp"

#include <algorithm>
#include <cmath>

#include "planner/perception/cell_key.hpp"

namespace ifar::perception {
namespace {

// Cells beyond this many from the origin are not remembered (2^31 cells of 0.15 m: 300,000 km).
constexpr double kLargestCellIndex = 2147483647.0;
// Heights are kept in centimetres in a byte: 2.55 m is above any obstacle band, and stands for "tall".
constexpr double kTallest = 255.0;

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
  for (std::size_t index = 0; index < points.size(); ++index) {
    const geometry::Point& point = points[index];
    const double column = std::floor(point.x() / cell_size_);
    const double row = std::floor(point.y() / cell_size_);
    if (!std::isfinite(column) || !std::isfinite(row) || std::abs(column) > kLargestCellIndex ||
        std::abs(row) > kLargestCellIndex) {
      continue;
    }
    Cell& cell = cells_[packCellKey(static_cast<std::int64_t>(column), static_cast<std::int64_t>(row))];
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

ForgetStats BackgroundMemory::forgetSeenThrough(const FreeSpaceView& view, double range_m)
{
  ForgetStats stats;
  if (view.empty() || !(range_m > 0.0) || !(cell_size_ > 0.0)) {
    return stats;
  }
  const geometry::Point& origin = view.origin();
  for (auto cell = cells_.begin(); cell != cells_.end();) {
    const geometry::Point centre = centreOf(cell->first);
    if ((centre - origin).squaredNorm() > range_m * range_m) {
      ++cell;
      continue;
    }
    ++stats.checked;
    if (!view.seesThrough(centre, cell_size_, cell->second.top_cm / 100.0)) {
      ++cell;
      continue;
    }
    ++stats.seen_through;
    if (--cell->second.votes == 0) {
      ++stats.forgotten;
      cell = cells_.erase(cell);
    } else {
      ++cell;
    }
  }
  return stats;
}

std::size_t BackgroundMemory::forgetMarkedBefore(std::uint32_t first_mark)
{
  std::size_t forgotten = 0;
  for (auto cell = cells_.begin(); cell != cells_.end();) {
    if (!cell->second.decided && cell->second.last_scan < first_mark) {
      cell = cells_.erase(cell);
      ++forgotten;
    } else {
      ++cell;
    }
  }
  return forgotten;
}

int BackgroundMemory::votesAt(const geometry::Point& point) const
{
  const double column = std::floor(point.x() / cell_size_);
  const double row = std::floor(point.y() / cell_size_);
  if (!std::isfinite(column) || !std::isfinite(row) || std::abs(column) > kLargestCellIndex ||
      std::abs(row) > kLargestCellIndex) {
    return 0;
  }
  const auto found =
      cells_.find(packCellKey(static_cast<std::int64_t>(column), static_cast<std::int64_t>(row)));
  return found == cells_.end() ? 0 : found->second.votes;
}

geometry::Point BackgroundMemory::centreOf(std::uint64_t cell) const
{
  const auto column = static_cast<std::int32_t>(static_cast<std::uint32_t>(cell >> 32U));
  const auto row = static_cast<std::int32_t>(static_cast<std::uint32_t>(cell & 0xFFFFFFFFU));
  return geometry::Point((column + 0.5) * cell_size_, (row + 0.5) * cell_size_);
}

std::size_t BackgroundMemory::rememberOutline(const geometry::Polygon& outline)
{
  if (outline.empty() || !(cell_size_ > 0.0) || !std::isfinite(cell_size_) ||
      !std::all_of(outline.begin(), outline.end(),
                   [](const geometry::Point& vertex) { return vertex.allFinite(); })) {
    return 0;
  }
  const std::size_t before = cells_.size();
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
  return cells_.size() - before;
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
  for (const auto& cell : cells_) {
    const geometry::Point centre = centreOf(cell.first);
    if (centre.x() >= minimum.x() && centre.y() >= minimum.y() && centre.x() < maximum.x() &&
        centre.y() < maximum.y()) {
      centres.push_back(centre);
    }
  }
  return centres;
}

}  // namespace ifar::perception
