#pragma once
// The obstacles a visibility graph is built against: closed loops with the blocked side on the LEFT
// (counter-clockwise around a blocked region, clockwise around a free pocket inside one), and a uniform
// grid over their edges so a visibility test only looks at edges near the segment.
//
// Visibility rule (exact for integer coordinates, e.g. GPPC maps): the open segment may touch and run
// along loop edges but may not enter a blocked side. At a loop vertex the blocked side is the wedge swept
// counter-clockwise from the next edge to the previous one; a segment through the vertex is blocked when
// either of its directions lies strictly inside the wedge. Where two blocked cells touch diagonally the
// loop visits the corner twice with reflex wedges, so squeezing through is refused.
//
// A segment that starts or ends at such a pinch point (two or more loop vertices at one position whose
// blocked wedges together cover every direction) stands in one of the free wedges there and is tested
// against that visit's wedge only (GPPC: a start or target on a double corner leaves or is reached
// through the cell whose top-left corner it is): the free wedge that holds the direction (1, 1), else
// the first one met turning from (1, 1) towards (1, 0). Outlines that merely touch keep every wedge.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/polygon.hpp"

namespace ifar::graph {

struct ObstacleLoop {
  geometry::Polygon vertices;  // blocked side on the left, at least 3 vertices
  std::int64_t object_id = 0;  // 0 for background, > 0 for a movable object (interaction planning)
};

struct Bounds {
  geometry::Point min = geometry::Point::Zero();
  geometry::Point max = geometry::Point::Zero();
  bool contains(const geometry::Point& point) const
  {
    return point.x() >= min.x() && point.y() >= min.y() && point.x() <= max.x() && point.y() <= max.y();
  }
};

/// An obstacle loop from a simple polygon whose inside is blocked (a perception outline), in either
/// orientation: made counter-clockwise so the blocked side is on the left.
ObstacleLoop loopFromPolygon(const geometry::Polygon& polygon, std::int64_t object_id = 0);

/// One loop vertex with its two loop neighbours: what tangency and wedge tests need.
struct LoopCorner {
  geometry::Point position;
  geometry::Point previous;  // loop vertex before
  geometry::Point next;      // loop vertex after
  std::uint32_t loop = 0;
};

/// True when direction `direction` from `corner.position` lies strictly inside the blocked wedge.
bool pointsIntoWedge(const LoopCorner& corner, const geometry::Vector& direction);
/// True when the blocked wedge is narrower than a half-plane: a corner shortest paths may bend around.
bool isConvexCorner(const LoopCorner& corner);
/// -1, 0 or +1: the sign of `value`, 0 within `tolerance` of zero.
inline int signBeyond(double value, double tolerance)
{
  return value > tolerance ? 1 : (value < -tolerance ? -1 : 0);
}

/// The sides of the line through the corner along `direction` that its two loop neighbours lie on:
/// +1 left, -1 right, 0 on the line (1e-9 of the operands' sizes, as the other orientation tests).
struct NeighbourSides {
  int previous = 0;
  int next = 0;
};

/// A corner's two loop edges as seen from it, with their sizes for the tolerance: what every tangency
/// test of the corner needs, worked out once where one corner is tested against many directions.
struct CornerArms {
  geometry::Vector to_previous = geometry::Vector::Zero();
  geometry::Vector to_next = geometry::Vector::Zero();
  double previous_size = 0.0;  // |x| + |y| of to_previous
  double next_size = 0.0;

  static CornerArms of(const LoopCorner& corner)
  {
    CornerArms arms;
    arms.to_previous = corner.previous - corner.position;
    arms.to_next = corner.next - corner.position;
    arms.previous_size = std::abs(arms.to_previous.x()) + std::abs(arms.to_previous.y());
    arms.next_size = std::abs(arms.to_next.x()) + std::abs(arms.to_next.y());
    return arms;
  }
};

inline NeighbourSides neighbourSides(const CornerArms& arms, const geometry::Vector& direction)
{
  const double previous_cross = direction.x() * arms.to_previous.y() - direction.y() * arms.to_previous.x();
  const double next_cross = direction.x() * arms.to_next.y() - direction.y() * arms.to_next.x();
  const double scale = 1e-9 * (std::abs(direction.x()) + std::abs(direction.y()));
  return {signBeyond(previous_cross, scale * arms.previous_size),
          signBeyond(next_cross, scale * arms.next_size)};
}

inline NeighbourSides neighbourSides(const LoopCorner& corner, const geometry::Vector& direction)
{
  return neighbourSides(CornerArms::of(corner), direction);
}

/// True when the line through the corner along `direction` keeps both loop neighbours on one side
/// (touching counts): the reduced visibility graph only keeps edges tangent at both ends. Inline: it
/// runs for every vertex pair of a build and every vertex of an attachment.
inline bool isTangent(const CornerArms& arms, const geometry::Vector& direction)
{
  const NeighbourSides sides = neighbourSides(arms, direction);
  return sides.previous * sides.next >= 0;
}
inline bool isTangent(const LoopCorner& corner, const geometry::Vector& direction)
{
  return isTangent(CornerArms::of(corner), direction);
}

/// The side of the line through the corner along `direction` that the blocked wedge lies on: +1 left,
/// -1 right; 0 when the wedge reaches both sides or lies along the line (same tolerance as isTangent).
inline int wedgeSide(const LoopCorner& corner, const geometry::Vector& direction)
{
  const NeighbourSides sides = neighbourSides(corner, direction);
  if (sides.previous * sides.next < 0) {
    return 0;
  }
  return sides.previous != 0 ? sides.previous : sides.next;
}

/// The turn from `incoming` to `outgoing`: +1 left (counter-clockwise), -1 right, 0 straight on or
/// straight back (within the orientation tolerance).
inline int turnSide(const geometry::Vector& incoming, const geometry::Vector& outgoing)
{
  const double value = incoming.x() * outgoing.y() - incoming.y() * outgoing.x();
  const double tolerance = 1e-9 * (std::abs(incoming.x()) + std::abs(incoming.y())) *
                           (std::abs(outgoing.x()) + std::abs(outgoing.y()));
  return signBeyond(value, tolerance);
}

/// False when a path that arrives at a convex corner along `incoming` and leaves along `outgoing`
/// can be shortened right at the corner, so that no shortest path bends there that way: it turns while
/// the corner's blocked wedge lies outside the turn (on the far side of one of the two lines from the
/// small sector between them, so a chord cutting the bend close to the corner is free and shorter), or
/// it goes straight back. True for every other bend (wrapping the corner, straight on, or undecided
/// within the orientation tolerance). Only the corner's own wedge is looked at: another obstacle vertex
/// at the same position may still fill the sector.
inline bool isTautBend(const LoopCorner& corner, const geometry::Vector& incoming,
                       const geometry::Vector& outgoing)
{
  const int turn = turnSide(incoming, outgoing);
  if (turn == 0) {
    return incoming.dot(outgoing) >= 0.0;
  }
  return wedgeSide(corner, incoming) != -turn && wedgeSide(corner, outgoing) != -turn;
}

struct SnapResult {
  geometry::Point point;
  bool snapped = false;   // the input was inside an obstacle and was moved to its boundary
  double distance = 0.0;  // how far it moved
};

/// Caller-owned memory of edges that recently blocked a visibility test. Consecutive tests from one
/// point in similar directions tend to be blocked by the same edges, so checking those first skips most
/// grid traversals. Purely an accelerator: results are identical with or without it.
struct BlockerCache {
  static constexpr std::size_t kSize = 16;
  std::array<std::uint32_t, kSize> edges{};
  std::size_t count = 0;
  std::size_t next_slot = 0;
};

/// Caller-owned memory for many visibility tests from one point (the robot or the goal being attached to
/// a graph): for each direction sector around `origin`, the edge that last blocked a test in it, and the
/// most recent blockers. Lines from one point in nearly the same direction are mostly blocked by the same
/// edge, whatever order they are tested in, so trying those first skips most grid walks. Purely an
/// accelerator: results are identical with or without it.
struct SectorBlockerCache {
  static constexpr std::size_t kSectors = 512;
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  explicit SectorBlockerCache(const geometry::Point& from) : origin(from) { edges.fill(kEmpty); }
  geometry::Point origin;
  std::array<std::uint32_t, kSectors> edges;
  BlockerCache recent;
};

class ObstacleSet {
 public:
  /// `bounds`, when given, is the extent of a prior map: everything outside counts as blocked (the
  /// loops must then include the map's rim). `bucket_size` <= 0 picks one from the edge lengths.
  /// Loops with fewer than 3 vertices or non-finite coordinates are skipped and counted.
  explicit ObstacleSet(std::vector<ObstacleLoop> loops, std::optional<Bounds> bounds = std::nullopt,
                       double bucket_size = 0.0);

  const std::vector<ObstacleLoop>& loops() const { return loops_; }
  const std::optional<Bounds>& bounds() const { return bounds_; }
  std::size_t edgeCount() const { return edges_.size(); }
  std::size_t skippedLoops() const { return skipped_loops_; }
  double bucketSize() const { return bucket_size_; }
  /// Heap bytes held (loops, edges, index), by capacity.
  std::size_t memoryBytes() const;

  /// Every loop vertex with its neighbours, in loop order.
  std::vector<LoopCorner> corners() const;

  /// True when the segment from `from` to `to` enters no blocked side (see the rule above); false for
  /// non-finite points. Thread safe.
  bool visible(const geometry::Point& from, const geometry::Point& to) const;
  /// The same test, first trying the edges in `cache` and remembering a new blocker in it.
  bool visible(const geometry::Point& from, const geometry::Point& to, BlockerCache& cache) const;
  /// The test from `cache.origin` to `to`, first trying the edge that last blocked a line in the same
  /// direction sector and remembering a new blocker there.
  bool visibleFrom(const geometry::Point& to, SectorBlockerCache& cache) const;

  /// True for points strictly inside a blocked region or outside the bounds; boundary points are free.
  bool isBlocked(const geometry::Point& point) const;
  /// Distance from `point` to the nearest loop edge (infinity when there are none).
  double distanceToBoundary(const geometry::Point& point) const;
  /// The point itself when free, else the nearest boundary point.
  SnapResult snapToFree(const geometry::Point& point) const;

 private:
  struct Edge {
    geometry::Point start;
    geometry::Point end;
    geometry::Point previous;  // loop vertex before `start`: the edge owns the wedge test at `start`
  };
  /// One visibility test's segment with the values every edge test needs, computed once per test.
  struct Segment {
    Segment(const geometry::Point& from_point, const geometry::Point& to_point);
    geometry::Point from;
    geometry::Point to;
    geometry::Vector direction;
    geometry::Point box_low;  // the segment's box grown by the margin: edges outside cannot matter
    geometry::Point box_high;
    double tolerance_scale;  // orientation tolerance per unit of the other operand's size
  };
  bool edgeBlocks(std::uint32_t edge_index, const Segment& segment) const;
  /// Index of an edge that blocks the segment, or kNoEdge.
  std::uint32_t findBlocker(const Segment& segment) const;
  static constexpr std::uint32_t kNoEdge = 0xFFFFFFFFu;
  void buildIndex(double bucket_size);
  void findPinchPoints();

  std::vector<ObstacleLoop> loops_;
  std::optional<Bounds> bounds_;
  std::vector<Edge> edges_;
  std::size_t skipped_loops_ = 0;
  // Per edge: 1 when its start is a pinch point and its wedge is not the one an end point there stands in
  // (see the rule above), so the end point's test skips it.
  std::vector<std::uint8_t> aside_at_end_point_;
  // Uniform grid over the edges' extent; bucket b holds edges bucket_edges_[bucket_offsets_[b] ..
  // bucket_offsets_[b + 1]).
  geometry::Point grid_min_ = geometry::Point::Zero();
  double bucket_size_ = 1.0;
  int columns_ = 0;
  int rows_ = 0;
  std::vector<std::uint32_t> bucket_offsets_;
  std::vector<std::uint32_t> bucket_edges_;
};

}  // namespace ifar::graph
