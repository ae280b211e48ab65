#include "sim/lidar/lidar_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ifar::sim::lidar {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double signedArea(const geometry::Polygon& outline)
{
  double twice_area = 0.0;
  for (std::size_t index = 0; index < outline.size(); ++index) {
    const auto& current = outline[index];
    const auto& next = outline[(index + 1) % outline.size()];
    twice_area += current.x() * next.y() - next.x() * current.y();
  }
  return 0.5 * twice_area;
}

/// True when the segment touches the axis-aligned box (Liang-Barsky clipping).
bool segmentTouchesBox(double start_x, double start_y, double delta_x, double delta_y, double low_x,
                       double low_y, double high_x, double high_y)
{
  double enter = 0.0;
  double leave = 1.0;
  const double starts[2] = {start_x, start_y};
  const double deltas[2] = {delta_x, delta_y};
  const double lows[2] = {low_x, low_y};
  const double highs[2] = {high_x, high_y};
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(deltas[axis]) < 1e-15) {
      if (starts[axis] < lows[axis] || starts[axis] > highs[axis]) {
        return false;
      }
      continue;
    }
    double first = (lows[axis] - starts[axis]) / deltas[axis];
    double second = (highs[axis] - starts[axis]) / deltas[axis];
    if (first > second) {
      std::swap(first, second);
    }
    enter = std::max(enter, first);
    leave = std::min(leave, second);
    if (enter > leave) {
      return false;
    }
  }
  return true;
}

}  // namespace

/// Consumes crossings in order of distance and decides where the ray stops: on a wall face when the
/// ray's height at the crossing is within the prism's height, or on a prism's top when it enters above
/// the top while descending and reaches the top height before leaving the prism again.
class LidarScene::CrossingWalk {
 public:
  explicit CrossingWalk(const Ray& ray) : ray_(ray) {}

  bool feed(const Crossing& crossing)
  {
    if (pending_ && pending_distance_ <= crossing.distance) {
      return stopOnTop();
    }
    const Segment& segment = *crossing.segment;
    if (pending_ && segment.prism == pending_prism_ && !crossing.entering) {
      pending_ = false;  // left the prism while still above its top
    }
    const double height = ray_.height + ray_.slope * crossing.distance;
    if (height >= 0.0 && height <= segment.height) {
      hit_.surface = RayHit::Surface::Wall;
      hit_.horizontal_distance = crossing.distance;
      hit_.reflectivity = segment.reflectivity;
      hit_.wall_facing = std::abs(ray_.direction_x * segment.delta_y - ray_.direction_y * segment.delta_x) *
                         segment.inverse_length;
      return true;
    }
    if (crossing.entering && ray_.slope < 0.0 && height > segment.height) {
      pending_ = true;
      pending_prism_ = segment.prism;
      pending_distance_ = (ray_.height - segment.height) / -ray_.slope;
      pending_reflectivity_ = segment.reflectivity;
    }
    return false;
  }

  /// Called when every crossing up to `distance` has been fed.
  bool reached(double distance)
  {
    if (pending_ && pending_distance_ <= distance) {
      return stopOnTop();
    }
    return false;
  }

  const RayHit& hit() const { return hit_; }

 private:
  bool stopOnTop()
  {
    hit_.surface = RayHit::Surface::Top;
    hit_.horizontal_distance = pending_distance_;
    hit_.reflectivity = pending_reflectivity_;
    return true;
  }

  const Ray& ray_;
  RayHit hit_;
  bool pending_ = false;
  std::int32_t pending_prism_ = -1;
  double pending_distance_ = 0.0;
  double pending_reflectivity_ = 0.0;
};

void LidarScene::appendSegments(const Prism& prism, std::int32_t index, std::vector<Segment>& segments)
{
  const auto& outline = prism.outline;
  if (outline.size() < 3) {
    return;
  }
  // Store every edge so that its outward normal is (delta_y, -delta_x), i.e. counter-clockwise.
  const bool counter_clockwise = signedArea(outline) >= 0.0;
  for (std::size_t edge = 0; edge < outline.size(); ++edge) {
    geometry::Point start = outline[edge];
    geometry::Point end = outline[(edge + 1) % outline.size()];
    if (!counter_clockwise) {
      std::swap(start, end);
    }
    const geometry::Vector delta = end - start;
    if (delta.squaredNorm() < 1e-12) {
      continue;
    }
    segments.push_back({start.x(), start.y(), delta.x(), delta.y(), prism.height_m, prism.reflectivity,
                        1.0 / delta.norm(), index});
  }
}

bool LidarScene::intersect(const Ray& ray, const Segment& segment, double& distance, bool& entering)
{
  const double denominator = ray.direction_x * segment.delta_y - ray.direction_y * segment.delta_x;
  if (std::abs(denominator) < 1e-12) {
    return false;  // parallel: grazing a face returns nothing, as a real beam would not either
  }
  const double offset_x = segment.start_x - ray.origin_x;
  const double offset_y = segment.start_y - ray.origin_y;
  const double along_ray = (offset_x * segment.delta_y - offset_y * segment.delta_x) / denominator;
  const double along_segment = (offset_x * ray.direction_y - offset_y * ray.direction_x) / denominator;
  if (along_ray <= 0.0 || along_segment < 0.0 || along_segment > 1.0) {
    return false;
  }
  distance = along_ray;
  entering = denominator < 0.0;  // direction . outward normal < 0
  return true;
}

LidarScene::LidarScene(const std::vector<Prism>& static_prisms, const LidarSceneSettings& settings)
    : settings_(settings)
{
  for (std::size_t index = 0; index < static_prisms.size(); ++index) {
    appendSegments(static_prisms[index], static_cast<std::int32_t>(index), segments_);
    tallest_height_ = std::max(tallest_height_, static_prisms[index].height_m);
  }
  if (segments_.empty()) {
    return;
  }
  const double cell = settings_.cell_size_m > 0.0 ? settings_.cell_size_m : 2.0;
  settings_.cell_size_m = cell;
  double low_x = kInfinity, low_y = kInfinity, high_x = -kInfinity, high_y = -kInfinity;
  for (const auto& segment : segments_) {
    low_x = std::min({low_x, segment.start_x, segment.start_x + segment.delta_x});
    low_y = std::min({low_y, segment.start_y, segment.start_y + segment.delta_y});
    high_x = std::max({high_x, segment.start_x, segment.start_x + segment.delta_x});
    high_y = std::max({high_y, segment.start_y, segment.start_y + segment.delta_y});
  }
  grid_min_x_ = low_x - 0.5 * cell;
  grid_min_y_ = low_y - 0.5 * cell;
  columns_ = static_cast<int>(std::ceil((high_x - grid_min_x_) / cell + 0.5));
  rows_ = static_cast<int>(std::ceil((high_y - grid_min_y_) / cell + 0.5));
  const std::size_t cell_count = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);

  // Two passes over the cells each segment's bounding box covers: count, then fill (CSR layout).
  std::vector<std::uint32_t> counts(cell_count + 1, 0);
  auto forEachCell = [&](const Segment& segment, auto&& visit) {
    const double end_x = segment.start_x + segment.delta_x;
    const double end_y = segment.start_y + segment.delta_y;
    const int first_column = static_cast<int>((std::min(segment.start_x, end_x) - grid_min_x_) / cell);
    const int last_column = static_cast<int>((std::max(segment.start_x, end_x) - grid_min_x_) / cell);
    const int first_row = static_cast<int>((std::min(segment.start_y, end_y) - grid_min_y_) / cell);
    const int last_row = static_cast<int>((std::max(segment.start_y, end_y) - grid_min_y_) / cell);
    for (int row = first_row; row <= last_row; ++row) {
      for (int column = first_column; column <= last_column; ++column) {
        const double cell_x = grid_min_x_ + column * cell;
        const double cell_y = grid_min_y_ + row * cell;
        if (segmentTouchesBox(segment.start_x, segment.start_y, segment.delta_x, segment.delta_y, cell_x,
                              cell_y, cell_x + cell, cell_y + cell)) {
          visit(static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) +
                static_cast<std::size_t>(column));
        }
      }
    }
  };
  for (const auto& segment : segments_) {
    forEachCell(segment, [&](std::size_t cell_index) { ++counts[cell_index + 1]; });
  }
  for (std::size_t index = 1; index <= cell_count; ++index) {
    counts[index] += counts[index - 1];
  }
  cell_start_ = counts;
  cell_items_.resize(cell_start_.back());
  for (std::size_t index = 0; index < segments_.size(); ++index) {
    forEachCell(segments_[index], [&](std::size_t cell_index) {
      cell_items_[counts[cell_index]++] = static_cast<std::uint32_t>(index);
    });
  }
}

LidarScene LidarScene::fromWorld(const World& world, const LidarSceneSettings& settings)
{
  std::vector<Prism> prisms;
  prisms.reserve(world.obstacles.size());
  for (const auto& obstacle : world.obstacles) {
    prisms.push_back({obstacle.outline, obstacle.height_m, obstacle.reflectivity});
  }
  return LidarScene(prisms, settings);
}

void LidarScene::setMovables(std::vector<Prism> movables)
{
  movable_segments_.clear();
  movables_.clear();
  movable_tallest_ = 0.0;
  for (std::size_t index = 0; index < movables.size(); ++index) {
    const auto& prism = movables[index];
    const std::size_t first = movable_segments_.size();
    appendSegments(prism, static_cast<std::int32_t>(index), movable_segments_);
    if (movable_segments_.size() == first) {
      continue;
    }
    geometry::Point low = prism.outline.front();
    geometry::Point high = prism.outline.front();
    for (const auto& point : prism.outline) {
      low = low.cwiseMin(point);
      high = high.cwiseMax(point);
    }
    const geometry::Point centre = 0.5 * (low + high);
    movables_.push_back(
        {centre.x(), centre.y(), 0.5 * (high - low).norm() + 1e-6, first, movable_segments_.size()});
    movable_tallest_ = std::max(movable_tallest_, prism.height_m);
  }
}

RayHit LidarScene::castStatic(const Ray& ray, double limit) const
{
  if (segments_.empty() || limit <= 0.0) {
    return {};
  }
  const double cell = settings_.cell_size_m;
  // Clip [0, limit] to the grid's box.
  double enter = 0.0;
  double leave = limit;
  const double grid_max_x = grid_min_x_ + columns_ * cell;
  const double grid_max_y = grid_min_y_ + rows_ * cell;
  const double origins[2] = {ray.origin_x, ray.origin_y};
  const double directions[2] = {ray.direction_x, ray.direction_y};
  const double lows[2] = {grid_min_x_, grid_min_y_};
  const double highs[2] = {grid_max_x, grid_max_y};
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(directions[axis]) < 1e-15) {
      if (origins[axis] < lows[axis] || origins[axis] >= highs[axis]) {
        return {};
      }
      continue;
    }
    double first = (lows[axis] - origins[axis]) / directions[axis];
    double second = (highs[axis] - origins[axis]) / directions[axis];
    if (first > second) {
      std::swap(first, second);
    }
    enter = std::max(enter, first);
    leave = std::min(leave, second);
  }
  if (enter > leave) {
    return {};
  }
  // Amanatides-Woo walk from the entry point.
  const double entry_x = ray.origin_x + ray.direction_x * enter;
  const double entry_y = ray.origin_y + ray.direction_y * enter;
  int column = std::clamp(static_cast<int>((entry_x - grid_min_x_) / cell), 0, columns_ - 1);
  int row = std::clamp(static_cast<int>((entry_y - grid_min_y_) / cell), 0, rows_ - 1);
  const int step_column = ray.direction_x > 0.0 ? 1 : -1;
  const int step_row = ray.direction_y > 0.0 ? 1 : -1;
  const double delta_column =
      std::abs(ray.direction_x) > 1e-15 ? cell / std::abs(ray.direction_x) : kInfinity;
  const double delta_row = std::abs(ray.direction_y) > 1e-15 ? cell / std::abs(ray.direction_y) : kInfinity;
  double next_column =
      std::abs(ray.direction_x) > 1e-15
          ? (grid_min_x_ + (column + (step_column > 0 ? 1 : 0)) * cell - ray.origin_x) / ray.direction_x
          : kInfinity;
  double next_row =
      std::abs(ray.direction_y) > 1e-15
          ? (grid_min_y_ + (row + (step_row > 0 ? 1 : 0)) * cell - ray.origin_y) / ray.direction_y
          : kInfinity;

  CrossingWalk walk(ray);
  std::array<Crossing, 48> crossings;
  std::vector<Crossing> overflow;
  double cell_enter = 0.0;  // crossings before the grid entry cannot exist: the grid holds every segment
  while (true) {
    const double cell_leave = std::min({next_column, next_row, leave});
    const bool last_cell = cell_leave >= leave;
    const std::size_t cell_index =
        static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column);
    std::size_t found = 0;
    overflow.clear();
    for (std::uint32_t item = cell_start_[cell_index]; item < cell_start_[cell_index + 1]; ++item) {
      const Segment& segment = segments_[cell_items_[item]];
      double distance = 0.0;
      bool entering = false;
      if (!intersect(ray, segment, distance, entering)) {
        continue;
      }
      // Each crossing belongs to exactly one cell: [enter, leave), the last cell closed.
      if (distance < cell_enter || distance > cell_leave || (distance == cell_leave && !last_cell)) {
        continue;
      }
      if (found < crossings.size()) {
        crossings[found++] = {distance, &segment, entering};
      } else {
        overflow.push_back({distance, &segment, entering});
      }
    }
    if (found > 0) {
      auto by_distance = [](const Crossing& first, const Crossing& second) {
        return first.distance < second.distance;
      };
      if (!overflow.empty()) {
        overflow.insert(overflow.end(), crossings.begin(),
                        crossings.begin() + static_cast<std::ptrdiff_t>(found));
        std::sort(overflow.begin(), overflow.end(), by_distance);
        for (const auto& crossing : overflow) {
          if (walk.feed(crossing)) {
            return walk.hit();
          }
        }
      } else {
        std::sort(crossings.begin(), crossings.begin() + static_cast<std::ptrdiff_t>(found), by_distance);
        for (std::size_t index = 0; index < found; ++index) {
          if (walk.feed(crossings[index])) {
            return walk.hit();
          }
        }
      }
    }
    if (walk.reached(cell_leave)) {
      return walk.hit();
    }
    if (last_cell) {
      return {};
    }
    cell_enter = cell_leave;
    if (next_column < next_row) {
      column += step_column;
      next_column += delta_column;
      if (column < 0 || column >= columns_) {
        return {};
      }
    } else {
      row += step_row;
      next_row += delta_row;
      if (row < 0 || row >= rows_) {
        return {};
      }
    }
  }
}

RayHit LidarScene::castMovables(const Ray& ray, double limit) const
{
  // Most rays meet no movable at all; a fixed buffer covers the rest without allocating.
  std::array<Crossing, 32> buffer;
  std::vector<Crossing> overflow;
  std::size_t found = 0;
  for (const auto& movable : movables_) {
    const double offset_x = movable.centre_x - ray.origin_x;
    const double offset_y = movable.centre_y - ray.origin_y;
    const double along = offset_x * ray.direction_x + offset_y * ray.direction_y;
    if (along + movable.radius < 0.0 || along - movable.radius > limit) {
      continue;
    }
    const double across = offset_x * ray.direction_y - offset_y * ray.direction_x;
    if (std::abs(across) > movable.radius) {
      continue;
    }
    for (std::size_t index = movable.first_segment; index < movable.end_segment; ++index) {
      double distance = 0.0;
      bool entering = false;
      if (intersect(ray, movable_segments_[index], distance, entering) && distance <= limit) {
        if (found < buffer.size()) {
          buffer[found++] = {distance, &movable_segments_[index], entering};
        } else {
          overflow.push_back({distance, &movable_segments_[index], entering});
        }
      }
    }
  }
  if (found == 0) {
    return {};
  }
  overflow.insert(overflow.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(found));
  std::sort(overflow.begin(), overflow.end(),
            [](const Crossing& first, const Crossing& second) { return first.distance < second.distance; });
  CrossingWalk walk(ray);
  for (const auto& crossing : overflow) {
    if (walk.feed(crossing)) {
      return walk.hit();
    }
  }
  if (walk.reached(limit)) {
    return walk.hit();
  }
  return {};
}

RayHit LidarScene::cast(const Ray& ray) const
{
  double limit = ray.max_horizontal;
  double ground_distance = kInfinity;
  if (ray.slope < 0.0) {
    ground_distance = ray.height / -ray.slope;
    limit = std::min(limit, ground_distance);
  }
  // An upward ray above the tallest prism can hit nothing further on.
  auto ceilingLimit = [&](double tallest) {
    return ray.slope > 0.0 ? std::min(limit, std::max(0.0, (tallest - ray.height) / ray.slope)) : limit;
  };
  RayHit best = castStatic(ray, ceilingLimit(tallest_height_));
  const double movable_limit = best.surface == RayHit::Surface::None
                                   ? ceilingLimit(movable_tallest_)
                                   : std::min(best.horizontal_distance, ceilingLimit(movable_tallest_));
  if (!movables_.empty()) {
    const RayHit movable = castMovables(ray, movable_limit);
    if (movable.surface != RayHit::Surface::None &&
        (best.surface == RayHit::Surface::None || movable.horizontal_distance < best.horizontal_distance)) {
      best = movable;
    }
  }
  if (best.surface == RayHit::Surface::None && ground_distance <= ray.max_horizontal) {
    best.surface = RayHit::Surface::Ground;
    best.horizontal_distance = ground_distance;
    best.reflectivity = settings_.ground_reflectivity;
  }
  return best;
}

}  // namespace ifar::sim::lidar
