#include "planner/graph/obstacle_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "common/geometry/angle.hpp"
#include "common/geometry/segment.hpp"

namespace ifar::graph {
namespace {

using geometry::Point;
using geometry::Vector;

// Relative tolerance of the orientation tests: far below one unit squared for integer maps up to 10^5
// cells, so GPPC coordinates are decided exactly.
constexpr double kRelativeTolerance = 1e-9;

double crossProduct(const Vector& u, const Vector& v)
{
  return u.x() * v.y() - u.y() * v.x();
}

/// -1, 0, +1: the side of `c` relative to the directed line a->b, 0 within tolerance.
int side(const Point& a, const Point& b, const Point& c)
{
  const Vector ab = b - a;
  const Vector ac = c - a;
  const double value = crossProduct(ab, ac);
  const double tolerance =
      kRelativeTolerance * (std::abs(ab.x()) + std::abs(ab.y())) * (std::abs(ac.x()) + std::abs(ac.y()));
  return value > tolerance ? 1 : (value < -tolerance ? -1 : 0);
}

/// Sign of u x v with a tolerance relative to the vectors' sizes.
int crossSign(const Vector& u, const Vector& v)
{
  const double value = crossProduct(u, v);
  const double tolerance =
      kRelativeTolerance * (std::abs(u.x()) + std::abs(u.y())) * (std::abs(v.x()) + std::abs(v.y()));
  return value > tolerance ? 1 : (value < -tolerance ? -1 : 0);
}

bool samePoint(const Point& a, const Point& b, double scale)
{
  return (a - b).cwiseAbs().maxCoeff() <= kRelativeTolerance * (1.0 + scale);
}

}  // namespace

ObstacleLoop loopFromPolygon(const geometry::Polygon& polygon, std::int64_t object_id)
{
  return ObstacleLoop{geometry::counterClockwise(polygon), object_id};
}

bool pointsIntoWedge(const LoopCorner& corner, const Vector& direction)
{
  // The blocked wedge runs counter-clockwise from the next edge to the previous one.
  const Vector to_next = corner.next - corner.position;
  const Vector to_previous = corner.previous - corner.position;
  const int turn = crossSign(to_next, to_previous);
  if (turn > 0) {
    return crossSign(to_next, direction) > 0 && crossSign(direction, to_previous) > 0;
  }
  if (turn < 0) {
    // Reflex wedge: everything except the closed convex sector from previous round to next.
    return !(crossSign(to_previous, direction) >= 0 && crossSign(direction, to_next) >= 0);
  }
  if (to_next.dot(to_previous) < 0.0) {
    return crossSign(to_next, direction) > 0;  // straight: the left half-plane
  }
  return false;  // a zero-width spike blocks nothing
}

bool isConvexCorner(const LoopCorner& corner)
{
  return crossSign(corner.next - corner.position, corner.previous - corner.position) > 0;
}

namespace {

/// For several loop vertices at one position: true when some direction lies strictly inside none of
/// their blocked wedges (two outlines that touch); false at a pinch point such as a double corner.
bool seesAnyDirection(const std::vector<LoopCorner>& visits)
{
  // The directions an end point at the vertex may take are those inside no visit's blocked wedge: the
  // intersection of the closed free wedges. When not empty it holds an edge of one of them.
  const auto freeForAll = [&](const Vector& direction) {
    return std::none_of(visits.begin(), visits.end(),
                        [&](const LoopCorner& visit) { return pointsIntoWedge(visit, direction); });
  };
  return std::any_of(visits.begin(), visits.end(), [&](const LoopCorner& visit) {
    return freeForAll(visit.previous - visit.position) || freeForAll(visit.next - visit.position);
  });
}

/// The visit whose free wedge an end point at a pinch point stands in: the one holding the direction
/// (1, 1), else the first met turning from (1, 1) towards (1, 0). Index into `visits` (not empty).
std::size_t homeVisit(const std::vector<LoopCorner>& visits)
{
  // A visit's free wedge runs counter-clockwise from its previous edge to its next one, so turning
  // clockwise from (1, 1) a wedge is entered through its next edge. A wedge holding (1, 1) wins.
  const Vector home_direction(1.0, 1.0);
  const double home_angle = std::atan2(home_direction.y(), home_direction.x());
  constexpr double kFullTurn = 2.0 * geometry::kPi;
  std::size_t home = 0;
  double home_turn = kFullTurn;
  for (std::size_t index = 0; index < visits.size(); ++index) {
    const LoopCorner& visit = visits[index];
    double turn = 0.0;
    if (pointsIntoWedge(visit, home_direction)) {
      const Vector to_next = visit.next - visit.position;
      turn = std::fmod(home_angle - std::atan2(to_next.y(), to_next.x()) + 2.0 * kFullTurn, kFullTurn);
    }
    if (turn < home_turn) {
      home_turn = turn;
      home = index;
    }
  }
  return home;
}

}  // namespace

ObstacleSet::ObstacleSet(std::vector<ObstacleLoop> loops, std::optional<Bounds> bounds, double bucket_size)
    : bounds_(std::move(bounds))
{
  for (auto& loop : loops) {
    const bool finite = std::all_of(loop.vertices.begin(), loop.vertices.end(),
                                    [](const Point& point) { return point.allFinite(); });
    if (loop.vertices.size() < 3 || !finite) {
      ++skipped_loops_;
      continue;
    }
    loops_.push_back(std::move(loop));
  }
  std::size_t corner_count = 0;
  for (const auto& loop : loops_) {
    corner_count += loop.vertices.size();
  }
  edges_.reserve(corner_count);
  for (const auto& loop : loops_) {
    const std::size_t count = loop.vertices.size();
    for (std::size_t index = 0; index < count; ++index) {
      edges_.push_back(Edge{loop.vertices[index], loop.vertices[(index + 1) % count],
                            loop.vertices[(index + count - 1) % count]});
    }
  }
  buildIndex(bucket_size);
  findPinchPoints();
}

void ObstacleSet::findPinchPoints()
{
  aside_at_end_point_.assign(edges_.size(), 0);
  if (columns_ == 0) {
    return;
  }
  // Every direction blocked at a point takes blocked wedges of 360 degrees or more, so one of its visits
  // is reflex: only those are looked at, with the other edges starting there from the point's bucket
  // (an edge lies in every bucket its box touches).
  std::vector<std::uint32_t> group;
  std::vector<LoopCorner> visits;
  for (std::uint32_t index = 0; index < edges_.size(); ++index) {
    const Edge& edge = edges_[index];
    if (crossSign(edge.end - edge.start, edge.previous - edge.start) >= 0) {
      continue;  // convex or straight
    }
    const int column = std::clamp(
        static_cast<int>(std::floor((edge.start.x() - grid_min_.x()) / bucket_size_)), 0, columns_ - 1);
    const int row = std::clamp(static_cast<int>(std::floor((edge.start.y() - grid_min_.y()) / bucket_size_)),
                               0, rows_ - 1);
    const std::size_t bucket =
        static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column);
    group.clear();
    for (std::uint32_t slot = bucket_offsets_[bucket]; slot < bucket_offsets_[bucket + 1]; ++slot) {
      if (edges_[bucket_edges_[slot]].start == edge.start) {
        group.push_back(bucket_edges_[slot]);
      }
    }
    // Each point once: from its first reflex visit in the bucket's order.
    const auto first_reflex = std::find_if(group.begin(), group.end(), [&](std::uint32_t other) {
      const Edge& visit = edges_[other];
      return crossSign(visit.end - visit.start, visit.previous - visit.start) < 0;
    });
    if (group.size() < 2 || *first_reflex != index) {
      continue;
    }
    visits.clear();
    for (const std::uint32_t other : group) {
      const Edge& visit = edges_[other];
      visits.push_back(LoopCorner{visit.start, visit.previous, visit.end, 0});
    }
    if (!seesAnyDirection(visits)) {
      const std::size_t home = homeVisit(visits);
      for (std::size_t slot = 0; slot < group.size(); ++slot) {
        aside_at_end_point_[group[slot]] = slot == home ? 0 : 1;
      }
    }
  }
}

std::size_t ObstacleSet::memoryBytes() const
{
  std::size_t bytes = loops_.capacity() * sizeof(ObstacleLoop);
  for (const auto& loop : loops_) {
    bytes += loop.vertices.capacity() * sizeof(Point);
  }
  return bytes + edges_.capacity() * sizeof(Edge) + aside_at_end_point_.capacity() +
         (bucket_offsets_.capacity() + bucket_edges_.capacity()) * sizeof(std::uint32_t);
}

std::vector<LoopCorner> ObstacleSet::corners() const
{
  std::vector<LoopCorner> result;
  result.reserve(edges_.size());
  for (std::size_t loop_index = 0; loop_index < loops_.size(); ++loop_index) {
    const auto& vertices = loops_[loop_index].vertices;
    const std::size_t count = vertices.size();
    for (std::size_t index = 0; index < count; ++index) {
      result.push_back(LoopCorner{vertices[index], vertices[(index + count - 1) % count],
                                  vertices[(index + 1) % count], static_cast<std::uint32_t>(loop_index)});
    }
  }
  return result;
}

void ObstacleSet::buildIndex(double bucket_size)
{
  if (edges_.empty()) {
    columns_ = rows_ = 0;
    bucket_offsets_.assign(1, 0);
    return;
  }
  Point low = edges_.front().start;
  Point high = low;
  for (const auto& edge : edges_) {
    low = low.cwiseMin(edge.start).cwiseMin(edge.end);
    high = high.cwiseMax(edge.start).cwiseMax(edge.end);
  }
  const Vector extent = (high - low).cwiseMax(Vector(1e-9, 1e-9));
  if (!(std::isfinite(bucket_size) && bucket_size > 0.0)) {
    // About one bucket per edge, but never more than ~4 million buckets.
    bucket_size = std::sqrt(extent.x() * extent.y() / static_cast<double>(edges_.size()));
    bucket_size = std::max(bucket_size, std::max(extent.x(), extent.y()) / 2048.0);
  }
  bucket_size_ = bucket_size;
  grid_min_ = low;
  columns_ = static_cast<int>(std::floor(extent.x() / bucket_size_)) + 1;
  rows_ = static_cast<int>(std::floor(extent.y() / bucket_size_)) + 1;
  const double margin = 1e-6 * bucket_size_;
  const auto cellRange = [&](double low_value, double high_value, double origin, int limit) {
    const int first =
        std::clamp(static_cast<int>(std::floor((low_value - margin - origin) / bucket_size_)), 0, limit - 1);
    const int last =
        std::clamp(static_cast<int>(std::floor((high_value + margin - origin) / bucket_size_)), 0, limit - 1);
    return std::pair<int, int>(first, last);
  };
  // Two passes: count, then fill (compressed rows, no per-bucket vectors).
  const std::size_t bucket_count = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);
  std::vector<std::uint32_t> counts(bucket_count + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t edge_index = 0; edge_index < edges_.size(); ++edge_index) {
      const auto& edge = edges_[edge_index];
      const auto [first_column, last_column] = cellRange(
          std::min(edge.start.x(), edge.end.x()), std::max(edge.start.x(), edge.end.x()), low.x(), columns_);
      const auto [first_row, last_row] = cellRange(std::min(edge.start.y(), edge.end.y()),
                                                   std::max(edge.start.y(), edge.end.y()), low.y(), rows_);
      for (int row = first_row; row <= last_row; ++row) {
        for (int column = first_column; column <= last_column; ++column) {
          const std::size_t bucket = static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) +
                                     static_cast<std::size_t>(column);
          if (pass == 0) {
            ++counts[bucket + 1];
          } else {
            bucket_edges_[counts[bucket]++] = static_cast<std::uint32_t>(edge_index);
          }
        }
      }
    }
    if (pass == 0) {
      for (std::size_t bucket = 0; bucket < bucket_count; ++bucket) {
        counts[bucket + 1] += counts[bucket];
      }
      bucket_offsets_ = counts;
      bucket_edges_.resize(counts.back());
    }
  }
}

ObstacleSet::Segment::Segment(const Point& from_point, const Point& to_point)
    : from(from_point), to(to_point), direction(to_point - from_point)
{
  // Boxes apart by more than this margin (far above the orientation tolerance) decide nothing.
  const double margin =
      1e-7 * (1.0 + std::abs(from.x()) + std::abs(from.y()) + std::abs(to.x()) + std::abs(to.y()));
  box_low = Point(std::min(from.x(), to.x()) - margin, std::min(from.y(), to.y()) - margin);
  box_high = Point(std::max(from.x(), to.x()) + margin, std::max(from.y(), to.y()) + margin);
  tolerance_scale = kRelativeTolerance * (std::abs(direction.x()) + std::abs(direction.y()));
}

bool ObstacleSet::edgeBlocks(std::uint32_t edge_index, const Segment& segment) const
{
  const Edge& edge = edges_[edge_index];
  const Point& p = edge.start;
  const Point& q = edge.end;
  if (std::max(p.x(), q.x()) < segment.box_low.x() || std::min(p.x(), q.x()) > segment.box_high.x() ||
      std::max(p.y(), q.y()) < segment.box_low.y() || std::min(p.y(), q.y()) > segment.box_high.y()) {
    return false;
  }
  const Point& from = segment.from;
  const Point& to = segment.to;
  const Vector& direction = segment.direction;
  // side(from, to, p) and side(from, to, q) with the per-test part of the tolerance precomputed (same
  // operations in the same order, so the same decisions).
  const auto sideOf = [&](const Point& point) {
    const Vector offset = point - from;
    const double value = direction.x() * offset.y() - direction.y() * offset.x();
    const double tolerance = segment.tolerance_scale * (std::abs(offset.x()) + std::abs(offset.y()));
    return value > tolerance ? 1 : (value < -tolerance ? -1 : 0);
  };
  const int side_p = sideOf(p);
  const int side_q = sideOf(q);
  if (side_p * side_q > 0) {
    return false;
  }
  if (side_p * side_q < 0) {
    const int side_from = side(p, q, from);
    const int side_to = side(p, q, to);
    if (side_from * side_to < 0) {
      return true;  // proper crossing of a boundary edge enters the blocked side
    }
    if (side_from == 0 && side_to != 0) {
      return crossSign(q - p, direction) > 0;  // starts on the edge and heads to its blocked (left) side
    }
    if (side_to == 0 && side_from != 0) {
      return crossSign(q - p, -direction) > 0;
    }
    return false;
  }
  // The edge touches the segment's line at p, at q, or lies on it. Each edge answers for its start
  // vertex only; q is the next edge's start.
  if (side_p != 0) {
    return false;
  }
  const double length_squared = direction.squaredNorm();
  const double parameter = (p - from).dot(direction) / length_squared;
  const double scale = std::abs(direction.x()) + std::abs(direction.y());
  const LoopCorner corner{p, edge.previous, q, 0};
  if (samePoint(p, from, scale + from.cwiseAbs().maxCoeff())) {
    return aside_at_end_point_[edge_index] == 0 && pointsIntoWedge(corner, direction);
  }
  if (samePoint(p, to, scale + to.cwiseAbs().maxCoeff())) {
    return aside_at_end_point_[edge_index] == 0 && pointsIntoWedge(corner, -direction);
  }
  if (parameter <= 0.0 || parameter >= 1.0) {
    return false;
  }
  return pointsIntoWedge(corner, direction) || pointsIntoWedge(corner, -direction);
}

bool ObstacleSet::visible(const Point& from, const Point& to) const
{
  return from.allFinite() && to.allFinite() && findBlocker(Segment(from, to)) == kNoEdge;
}

bool ObstacleSet::visible(const Point& from, const Point& to, BlockerCache& cache) const
{
  if (!from.allFinite() || !to.allFinite()) {
    return false;  // nothing sensible to say about a line through infinity
  }
  const Segment segment(from, to);
  for (std::size_t slot = 0; slot < cache.count; ++slot) {
    if (edgeBlocks(cache.edges[slot], segment)) {
      return false;
    }
  }
  const std::uint32_t blocker = findBlocker(segment);
  if (blocker == kNoEdge) {
    return true;
  }
  cache.edges[cache.next_slot] = blocker;
  cache.next_slot = (cache.next_slot + 1) % BlockerCache::kSize;
  cache.count = std::min(cache.count + 1, BlockerCache::kSize);
  return false;
}

bool ObstacleSet::visibleFrom(const Point& to, SectorBlockerCache& cache) const
{
  const Point& from = cache.origin;
  if (!from.allFinite() || !to.allFinite()) {
    return false;
  }
  const Segment segment(from, to);
  // Sector from a pseudo-angle in [0, 4) that grows monotonically with the direction's angle (no trig).
  const double dx = segment.direction.x();
  const double dy = segment.direction.y();
  const double size = std::abs(dx) + std::abs(dy);
  if (size == 0.0) {
    return findBlocker(segment) == kNoEdge;
  }
  const double ratio = dy / size;
  const double pseudo_angle = dx >= 0.0 ? (dy >= 0.0 ? ratio : 4.0 + ratio) : 2.0 - ratio;
  const std::size_t sector = std::min(
      SectorBlockerCache::kSectors - 1,
      static_cast<std::size_t>(pseudo_angle * (static_cast<double>(SectorBlockerCache::kSectors) / 4.0)));
  std::uint32_t& remembered = cache.edges[sector];
  if (remembered != SectorBlockerCache::kEmpty && edgeBlocks(remembered, segment)) {
    return false;
  }
  BlockerCache& recent = cache.recent;
  for (std::size_t slot = 0; slot < recent.count; ++slot) {
    if (edgeBlocks(recent.edges[slot], segment)) {
      remembered = recent.edges[slot];
      return false;
    }
  }
  const std::uint32_t blocker = findBlocker(segment);
  if (blocker == kNoEdge) {
    return true;
  }
  remembered = blocker;
  recent.edges[recent.next_slot] = blocker;
  recent.next_slot = (recent.next_slot + 1) % BlockerCache::kSize;
  recent.count = std::min(recent.count + 1, BlockerCache::kSize);
  return false;
}

std::uint32_t ObstacleSet::findBlocker(const Segment& segment) const
{
  if (columns_ == 0) {
    return kNoEdge;
  }
  const Point& from = segment.from;
  const Vector& direction = segment.direction;
  if (direction.x() == 0.0 && direction.y() == 0.0) {
    return kNoEdge;
  }
  // Clip to the indexed extent (Liang-Barsky): no edge lies outside it.
  const double margin = 1e-6 * bucket_size_;
  const Point box_low = grid_min_ - Vector(margin, margin);
  const Point box_high = grid_min_ + bucket_size_ * Vector(columns_, rows_) + Vector(margin, margin);
  double enter = 0.0;
  double leave = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    const double delta = direction[axis];
    if (delta == 0.0) {
      if (from[axis] < box_low[axis] || from[axis] > box_high[axis]) {
        return kNoEdge;
      }
      continue;
    }
    double t_low = (box_low[axis] - from[axis]) / delta;
    double t_high = (box_high[axis] - from[axis]) / delta;
    if (t_low > t_high) {
      std::swap(t_low, t_high);
    }
    enter = std::max(enter, t_low);
    leave = std::min(leave, t_high);
  }
  if (enter > leave) {
    return kNoEdge;
  }
  const Point entry = from + enter * direction;
  int column =
      std::clamp(static_cast<int>(std::floor((entry.x() - grid_min_.x()) / bucket_size_)), 0, columns_ - 1);
  int row =
      std::clamp(static_cast<int>(std::floor((entry.y() - grid_min_.y()) / bucket_size_)), 0, rows_ - 1);
  const Point exit_point = from + leave * direction;
  const int last_column = std::clamp(
      static_cast<int>(std::floor((exit_point.x() - grid_min_.x()) / bucket_size_)), 0, columns_ - 1);
  const int last_row =
      std::clamp(static_cast<int>(std::floor((exit_point.y() - grid_min_.y()) / bucket_size_)), 0, rows_ - 1);
  const int step_column = direction.x() > 0.0 ? 1 : (direction.x() < 0.0 ? -1 : 0);
  const int step_row = direction.y() > 0.0 ? 1 : (direction.y() < 0.0 ? -1 : 0);
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const auto boundaryParameter = [&](int cell, int step, int axis) {
    if (step == 0) {
      return kInfinity;
    }
    const double boundary = grid_min_[axis] + (cell + (step > 0 ? 1 : 0)) * bucket_size_;
    return (boundary - from[axis]) / direction[axis];
  };
  double next_column_t = boundaryParameter(column, step_column, 0);
  double next_row_t = boundaryParameter(row, step_row, 1);
  const double column_delta = step_column != 0 ? bucket_size_ / std::abs(direction.x()) : kInfinity;
  const double row_delta = step_row != 0 ? bucket_size_ / std::abs(direction.y()) : kInfinity;
  const int max_steps = columns_ + rows_ + 2;
  for (int steps = 0; steps < max_steps; ++steps) {
    const std::size_t bucket =
        static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column);
    for (std::uint32_t slot = bucket_offsets_[bucket]; slot < bucket_offsets_[bucket + 1]; ++slot) {
      if (edgeBlocks(bucket_edges_[slot], segment)) {
        return bucket_edges_[slot];
      }
    }
    if (column == last_column && row == last_row) {
      break;
    }
    if (next_column_t < next_row_t) {
      if (next_column_t > leave) {
        break;
      }
      column += step_column;
      next_column_t += column_delta;
    } else {
      if (next_row_t > leave) {
        break;
      }
      row += step_row;
      next_row_t += row_delta;
    }
    if (column < 0 || row < 0 || column >= columns_ || row >= rows_) {
      break;
    }
  }
  return kNoEdge;
}

double ObstacleSet::distanceToBoundary(const Point& point) const
{
  double best = std::numeric_limits<double>::infinity();
  for (const auto& edge : edges_) {
    best = std::min(best, geometry::distanceToSegment(point, geometry::Segment{edge.start, edge.end}));
  }
  return best;
}

bool ObstacleSet::isBlocked(const Point& point) const
{
  if (!point.allFinite()) {
    return true;
  }
  if (bounds_ && !bounds_->contains(point)) {
    return true;
  }
  const int outside = bounds_ ? 1 : 0;  // the outside of a bounded map is one more blocked layer
  if (columns_ == 0) {
    return outside > 0;
  }
  const double row_position = std::floor((point.y() - grid_min_.y()) / bucket_size_);
  if (row_position < 0.0 || row_position >= rows_) {
    return outside > 0;
  }
  const int row = static_cast<int>(row_position);
  const double tolerance = kRelativeTolerance * (1.0 + point.cwiseAbs().maxCoeff());
  const auto distanceTo = [&](const Edge& edge) {
    return geometry::distanceToSegment(point, geometry::Segment{edge.start, edge.end});
  };
  // Winding number along a ray to +x through the bucket row. An edge lies in every bucket its box
  // touches, so it is counted only in the bucket holding its crossing point.
  int winding = outside;
  const double column_position = std::floor((point.x() - grid_min_.x()) / bucket_size_);
  if (column_position >= columns_) {
    return outside > 0;  // right of every edge: the ray crosses nothing
  }
  const int first_column = column_position < 0.0 ? 0 : static_cast<int>(column_position);
  for (int column = first_column; column < columns_; ++column) {
    const double column_low = grid_min_.x() + column * bucket_size_;
    const double column_high =
        column + 1 == columns_ ? std::numeric_limits<double>::infinity() : column_low + bucket_size_;
    const std::size_t bucket =
        static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column);
    for (std::uint32_t slot = bucket_offsets_[bucket]; slot < bucket_offsets_[bucket + 1]; ++slot) {
      const Edge& edge = edges_[bucket_edges_[slot]];
      if (column == first_column && distanceTo(edge) <= tolerance) {
        return false;  // on the boundary: free
      }
      const bool upward = edge.start.y() <= point.y() && edge.end.y() > point.y();
      const bool downward = edge.start.y() > point.y() && edge.end.y() <= point.y();
      if (!upward && !downward) {
        continue;
      }
      const double crossing_x = edge.start.x() + (point.y() - edge.start.y()) *
                                                     (edge.end.x() - edge.start.x()) /
                                                     (edge.end.y() - edge.start.y());
      const bool counted_here =
          (column == first_column || crossing_x >= column_low) && crossing_x < column_high;
      if (!counted_here || crossing_x < point.x()) {
        continue;
      }
      winding += upward ? 1 : -1;
    }
  }
  return winding > 0;
}

SnapResult ObstacleSet::snapToFree(const Point& point) const
{
  SnapResult result{point, false, 0.0};
  if (!isBlocked(point)) {
    return result;
  }
  double best = std::numeric_limits<double>::infinity();
  for (const auto& edge : edges_) {
    const Point candidate = geometry::closestPointOnSegment(point, geometry::Segment{edge.start, edge.end});
    if (bounds_ && !bounds_->contains(candidate)) {
      continue;
    }
    const double distance = (candidate - point).norm();
    if (distance < best) {
      best = distance;
      result.point = candidate;
    }
  }
  result.snapped = std::isfinite(best);
  result.distance = result.snapped ? best : 0.0;
  return result;
}

}  // namespace ifar::graph
