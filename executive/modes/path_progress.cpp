#include "executive/modes/path_progress.hpp"

#include <algorithm>

namespace ifar::executive {

PathProgress::PathProgress(const ExecutiveSettings& settings)
    : waypoint_tolerance_m_(settings.waypoint_tolerance_m),
      waypoint_pass_radius_m_(settings.waypoint_pass_radius_m)
{
}

void PathProgress::adopt(const Path& path)
{
  path_ = path;
  has_path_ = true;
  index_ = std::min<std::size_t>(1, path_.waypoints.empty() ? 0 : path_.waypoints.size() - 1);
}

void PathProgress::rewind()
{
  index_ = std::min<std::size_t>(1, path_.waypoints.size() - 1);
}

std::optional<WayOn> PathProgress::wayOn() const
{
  if (!has_path_ || path_.waypoints.empty()) {
    return std::nullopt;
  }
  const std::size_t last = path_.waypoints.size() - 1;
  const std::size_t index = std::min(index_, last);
  return WayOn{path_.waypoints[index].position, index == last};
}

const PushPlan* PathProgress::planForWaypoint(std::size_t index) const
{
  const auto plan_at = [this](int plan_index) -> const PushPlan* {
    if (plan_index < 0 || static_cast<std::size_t>(plan_index) >= path_.push_plans.size()) {
      return nullptr;
    }
    return &path_.push_plans[static_cast<std::size_t>(plan_index)];
  };
  if (const PushPlan* plan = plan_at(path_.waypoints[index].push_plan_index)) {
    return plan;
  }
  if (index + 1 < path_.waypoints.size() && path_.waypoints[index + 1].kind == WaypointKind::Push) {
    return plan_at(path_.waypoints[index + 1].push_plan_index);
  }
  return nullptr;
}

int PathProgress::pushWaypointIndex(std::int64_t object_id) const
{
  for (std::size_t index = 0; index < path_.waypoints.size(); ++index) {
    const Waypoint& waypoint = path_.waypoints[index];
    if (waypoint.kind == WaypointKind::Push && waypoint.object_id == object_id) {
      return static_cast<int>(index);
    }
  }
  return -1;
}

void PathProgress::advancePassed(const geometry::Point& position, bool stalled_here)
{
  const std::vector<Waypoint>& waypoints = path_.waypoints;
  if (waypoints.empty()) {
    return;
  }
  const std::size_t last = waypoints.size() - 1;
  index_ = std::min(index_, last);
  // Where following has stalled again after its escape (`stalled_here`), a waypoint within the pass radius
  // counts as passed on either side: it is the corner of an obstacle inflated by a disc of the half width
  // (and a layer cell off), where the vehicle's rectangle may not fit facing the next leg, while the
  // follower's cost-to-go to the next waypoint leads round the corner with clearance.
  const auto passed = [&](std::size_t index) {
    const double distance = (waypoints[index].position - position).norm();
    if (distance <= waypoint_tolerance_m_) {
      return true;
    }
    const geometry::Point leg = waypoints[index + 1].position - waypoints[index].position;
    return distance <= waypoint_pass_radius_m_ &&
           (stalled_here || leg.dot(position - waypoints[index].position) > 0.0);
  };
  while (index_ < last && passed(index_) &&
         !(waypoints[index_].kind == WaypointKind::Topological && planForWaypoint(index_))) {
    ++index_;
  }
}

void PathProgress::advanceWhile(const std::function<bool(const geometry::Point&)>& passed)
{
  while (index_ + 1 < path_.waypoints.size() && passed(path_.waypoints[index_].position)) {
    ++index_;
  }
}

std::vector<geometry::Point> PathProgress::ahead(const geometry::Point& position) const
{
  std::vector<geometry::Point> points{position};
  for (std::size_t index = index_; index < path_.waypoints.size(); ++index) {
    const Waypoint& waypoint = path_.waypoints[index];
    if (waypoint.kind == WaypointKind::Push ||
        (waypoint.kind == WaypointKind::Topological && planForWaypoint(index))) {
      break;
    }
    points.push_back(waypoint.position);
  }
  return points;
}

geometry::Point PathProgress::pointAlong(const geometry::Point& position, double distance_m) const
{
  geometry::Point from = position;
  for (std::size_t index = index_; index < path_.waypoints.size(); ++index) {
    const geometry::Point to = path_.waypoints[index].position;
    const double leg = (to - from).norm();
    if (leg >= distance_m && leg > 0.0) {
      return from + (to - from) * (distance_m / leg);
    }
    distance_m -= leg;
    from = to;
  }
  return from;
}

double PathProgress::remainingLength(const geometry::Point& position) const
{
  double length = 0.0;
  geometry::Point from = position;
  for (std::size_t index = index_; index < path_.waypoints.size(); ++index) {
    length += (path_.waypoints[index].position - from).norm();
    from = path_.waypoints[index].position;
  }
  return length;
}

}  // namespace ifar::executive
