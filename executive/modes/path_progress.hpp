#pragma once
// The path in hand and how far along it the vehicle is: which waypoint it heads for, which it has passed,
// where the pushes on it start, and the stretch ahead.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "common/geometry/point.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/modes/inputs.hpp"

namespace ifar::executive {

/// The waypoint following heads for, and whether it is the goal.
struct WayOn {
  geometry::Point position = geometry::Point::Zero();
  bool is_goal = false;
};

class PathProgress {
 public:
  explicit PathProgress(const ExecutiveSettings& settings);

  /// Takes `path` and heads for its first waypoint after the start.
  void adopt(const Path& path);
  /// Takes `path` and keeps heading for the same waypoint index (a replan while a push goes on: the
  /// index is set again when the push is over).
  void replace(const Path& path) { path_ = path; }
  /// Heads for the first waypoint after the start again.
  void rewind();

  bool hasPath() const { return has_path_; }
  const Path& path() const { return path_; }
  std::size_t index() const { return index_; }
  void setIndex(std::size_t index) { index_ = index; }
  /// Heads for the next waypoint.
  void next() { ++index_; }
  /// The waypoint following heads for; none before a path or when it has no waypoints.
  std::optional<WayOn> wayOn() const;

  /// The push plan that starts at waypoint `index` (its own, or the next waypoint's when that is a push
  /// waypoint); null when none does.
  const PushPlan* planForWaypoint(std::size_t index) const;
  /// The index of the push waypoint of `object_id`; -1 when the path has none.
  int pushWaypointIndex(std::int64_t object_id) const;

  /// Moves past the intermediate waypoints the vehicle at `position` has passed: within the waypoint
  /// tolerance, or within the pass radius and beyond the waypoint (on the next leg's side of the line
  /// through it square to that leg; on either side when `stalled_here`). Never past a topological
  /// waypoint with a push plan.
  void advancePassed(const geometry::Point& position, bool stalled_here);
  /// Moves on while the current waypoint (never the last) satisfies `passed`.
  void advanceWhile(const std::function<bool(const geometry::Point&)>& passed);

  /// `position`, then the waypoints ahead up to where a push takes over (pushing goes through its own
  /// gap).
  std::vector<geometry::Point> ahead(const geometry::Point& position) const;
  /// The point `distance_m` along the path from `position` through the current waypoint and those after
  /// it; the last waypoint when the path is shorter.
  geometry::Point pointAlong(const geometry::Point& position, double distance_m) const;
  /// The length of the path still to drive from `position`: to the current waypoint, then along the rest.
  double remainingLength(const geometry::Point& position) const;

 private:
  double waypoint_tolerance_m_;
  double waypoint_pass_radius_m_;
  bool has_path_ = false;
  Path path_;
  std::size_t index_ = 0;
};

}  // namespace ifar::executive
