#include "planner/core/seen_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "common/geometry/angle.hpp"

namespace ifar::planner {

namespace {

/// The grid grows by at least this much on a side, so a vehicle driving on does not copy it every frame.
constexpr double kGrowthMarginM = 32.0;
/// At most this many cells (16 MB; 4 km^2 at 0.5 m).
constexpr double kMaxCells = 16.0e6;

}  // namespace

SeenSpace::SeenSpace(double cell_size_m) : cell_size_m_(cell_size_m > 0.0 ? cell_size_m : 0.5) {}

void SeenSpace::cover(const geometry::Point& minimum, const geometry::Point& maximum)
{
  const geometry::Point current_max =
      origin_ + geometry::Point(columns_ * cell_size_m_, rows_ * cell_size_m_);
  if (columns_ > 0 && minimum.x() >= origin_.x() && minimum.y() >= origin_.y() &&
      maximum.x() <= current_max.x() && maximum.y() <= current_max.y()) {
    return;
  }
  const geometry::Point new_low = minimum - geometry::Point::Constant(kGrowthMarginM);
  const geometry::Point new_high = maximum + geometry::Point::Constant(kGrowthMarginM);
  geometry::Point low = new_low;
  geometry::Point high = new_high;
  if (columns_ > 0) {
    low = low.cwiseMin(origin_);
    high = high.cwiseMax(current_max);
  }
  const double kept_cells = ((high.x() - low.x()) / cell_size_m_) * ((high.y() - low.y()) / cell_size_m_);
  if (kept_cells > kMaxCells) {
    // A view this far from the last ones (a site of many kilometres, or a pose jump) starts a new grid:
    // what was seen before is forgotten rather than the memory exhausted.
    low = new_low;
    high = new_high;
    cells_.clear();
    columns_ = 0;
    rows_ = 0;
    seen_cells_ = 0;
  }
  low = (low / cell_size_m_).array().floor().matrix() * cell_size_m_;
  const int columns = static_cast<int>(std::ceil((high.x() - low.x()) / cell_size_m_));
  const int rows = static_cast<int>(std::ceil((high.y() - low.y()) / cell_size_m_));
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), 0);
  const int shift_x = static_cast<int>(std::lround((origin_.x() - low.x()) / cell_size_m_));
  const int shift_y = static_cast<int>(std::lround((origin_.y() - low.y()) / cell_size_m_));
  for (int row = 0; row < rows_; ++row) {
    std::copy_n(cells_.begin() + static_cast<std::ptrdiff_t>(row) * columns_, columns_,
                cells.begin() + static_cast<std::ptrdiff_t>(row + shift_y) * columns + shift_x);
  }
  cells_ = std::move(cells);
  origin_ = low;
  columns_ = columns;
  rows_ = rows;
}

std::optional<std::size_t> SeenSpace::indexOf(const geometry::Point& point) const
{
  const double column = std::floor((point.x() - origin_.x()) / cell_size_m_);
  const double row = std::floor((point.y() - origin_.y()) / cell_size_m_);
  if (!(column >= 0.0 && row >= 0.0 && column < columns_ && row < rows_)) {
    return std::nullopt;
  }
  return cellIndex(static_cast<int>(column), static_cast<int>(row));
}

std::size_t SeenSpace::cellIndex(int column, int row) const
{
  return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) +
         static_cast<std::size_t>(column);
}

void SeenSpace::mark(const geometry::Point& point)
{
  const std::optional<std::size_t> index = indexOf(point);
  if (index && cells_[*index] == 0) {
    cells_[*index] = 1;
    ++seen_cells_;
  }
}

bool SeenSpace::seen(const geometry::Point& point) const
{
  const std::optional<std::size_t> index = indexOf(point);
  return index && cells_[*index] != 0;
}

bool SeenSpace::seenCell(int column, int row) const
{
  if (column < 0 || row < 0 || column >= columns_ || row >= rows_) {
    return false;
  }
  return cells_[cellIndex(column, row)] != 0;
}

void SeenSpace::markView(const perception::LocalLayer& layer, const geometry::Point& viewpoint,
                         double range_m, double inflation_m)
{
  if (!(range_m > 0.0) || !viewpoint.allFinite()) {
    return;
  }
  cover(viewpoint - geometry::Point::Constant(range_m), viewpoint + geometry::Point::Constant(range_m));
  const perception::LayerGrid& grid = layer.grid;
  const auto occupied = [&](const geometry::Point& point) {
    const std::optional<std::size_t> index = grid.indexOf(point);
    if (!index) {
      return false;
    }
    return (*index < layer.background_occupancy.size() && layer.background_occupancy[*index] != 0) ||
           (*index < layer.movable_occupancy.size() && layer.movable_occupancy[*index] != 0);
  };
  // Steps of half the finer of the two cells along each ray; rays close enough that neighbours at the
  // range are a cell apart.
  const double step = 0.5 * std::min(cell_size_m_, grid.cell_size_m);
  const int rays = std::max(8, static_cast<int>(std::ceil(2.0 * geometry::kPi * range_m / cell_size_m_)));
  const int steps = static_cast<int>(std::ceil(range_m / step));
  // A vehicle inside an obstacle's inflation (squeezing past a wall) still sees out: a ray passes the
  // occupied cells it starts in, for no more than the inflation, so it does not pass the wall itself.
  const bool starts_occupied = occupied(viewpoint);
  for (int ray = 0; ray < rays; ++ray) {
    const double angle = 2.0 * geometry::kPi * ray / rays;
    const geometry::Point direction(std::cos(angle), std::sin(angle));
    bool leaving = starts_occupied;
    for (int index = 0; index <= steps; ++index) {
      const double along = index * step;
      const geometry::Point point = viewpoint + direction * along;
      mark(point);
      const bool blocked = occupied(point);
      leaving = leaving && blocked && along <= inflation_m;
      if (blocked && !leaving) {
        break;
      }
    }
  }
}

double SeenSpace::unseenLength(const geometry::Point& from, const geometry::Point& to) const
{
  const double length = (to - from).norm();
  if (!(length > 0.0)) {
    return 0.0;
  }
  // Cell by cell along the segment (Amanatides and Woo): t runs from 0 at `from` to 1 at `to`, and each
  // step ends where the segment leaves the current cell.
  const geometry::Point start = (from - origin_) / cell_size_m_;
  const geometry::Point delta = (to - from) / cell_size_m_;
  int column = static_cast<int>(std::floor(start.x()));
  int row = static_cast<int>(std::floor(start.y()));
  const int step_column = delta.x() > 0.0 ? 1 : -1;
  const int step_row = delta.y() > 0.0 ? 1 : -1;
  const double infinity = std::numeric_limits<double>::infinity();
  const double t_delta_x = delta.x() != 0.0 ? 1.0 / std::abs(delta.x()) : infinity;
  const double t_delta_y = delta.y() != 0.0 ? 1.0 / std::abs(delta.y()) : infinity;
  double t_next_x = delta.x() != 0.0
                        ? (delta.x() > 0.0 ? column + 1 - start.x() : start.x() - column) * t_delta_x
                        : infinity;
  double t_next_y =
      delta.y() != 0.0 ? (delta.y() > 0.0 ? row + 1 - start.y() : start.y() - row) * t_delta_y : infinity;
  double t = 0.0;
  double unseen = 0.0;
  const double crossings = std::abs(delta.x()) + std::abs(delta.y()) + 2.0;
  for (int cell = 0; t < 1.0 && cell <= crossings; ++cell) {
    const double t_end = std::min({t_next_x, t_next_y, 1.0});
    if (!seenCell(column, row)) {
      unseen += t_end - t;
    }
    t = t_end;
    if (t_next_x < t_next_y) {
      t_next_x += t_delta_x;
      column += step_column;
    } else {
      t_next_y += t_delta_y;
      row += step_row;
    }
  }
  return length * std::min(unseen, 1.0);
}

}  // namespace ifar::planner
