#include "system/run_trace.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "common/geometry/segment.hpp"
#include "system/path_arc.hpp"

namespace ifar::runner {
namespace {

/// Distance from `point` to the polyline (to its point when it has one; infinity when empty).
double distanceToPolyline(const geometry::Point& point, const std::vector<geometry::Point>& polyline)
{
  if (polyline.size() == 1) {
    return (point - polyline.front()).norm();
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t index = 0; index + 1 < polyline.size(); ++index) {
    best = std::min(best, geometry::distanceToSegment(point, {polyline[index], polyline[index + 1]}));
  }
  return best;
}

/// Points along the polyline every `spacing` metres, its vertices included.
std::vector<geometry::Point> samplesAlong(const std::vector<geometry::Point>& polyline, double spacing)
{
  std::vector<geometry::Point> samples;
  for (std::size_t index = 0; index < polyline.size(); ++index) {
    samples.push_back(polyline[index]);
    if (index + 1 == polyline.size()) {
      break;
    }
    const geometry::Point step = polyline[index + 1] - polyline[index];
    const int pieces = static_cast<int>(std::floor(step.norm() / spacing));
    for (int piece = 1; piece < pieces; ++piece) {
      samples.push_back(polyline[index] + step * (piece * spacing / step.norm()));
    }
  }
  return samples;
}

/// True when every sample of each polyline is within `tolerance` of the other.
bool withinEachOther(const std::vector<geometry::Point>& first, const std::vector<geometry::Point>& second,
                     const RouteMatching& matching)
{
  for (const geometry::Point& point : samplesAlong(first, matching.sample_spacing_m)) {
    if (distanceToPolyline(point, second) > matching.tolerance_m) {
      return false;
    }
  }
  for (const geometry::Point& point : samplesAlong(second, matching.sample_spacing_m)) {
    if (distanceToPolyline(point, first) > matching.tolerance_m) {
      return false;
    }
  }
  return true;
}

/// True when every leg of what is left of a route (`remainder`: vehicle, foot, then the route's points)
/// is open, each tested `margin` in from its ends (at most a quarter of the leg). The vehicle's own step
/// onto the route is not tested: it is where the vehicle is, not the route.
bool legsOpen(const std::vector<geometry::Point>& remainder, const WayOpen& way_open, double margin)
{
  if (!way_open) {
    return true;
  }
  for (std::size_t index = 1; index + 1 < remainder.size(); ++index) {
    const geometry::Point& from = remainder[index];
    const geometry::Point& to = remainder[index + 1];
    const double length = (to - from).norm();
    if (length <= 0.0) {
      continue;
    }
    const geometry::Point inward = (to - from) * (std::min(margin, 0.25 * length) / length);
    if (!way_open(from + inward, to - inward)) {
      return false;
    }
  }
  return true;
}

}  // namespace

const char* routeEndName(RouteEnd end)
{
  switch (end) {
    case RouteEnd::Kept:
      return "kept";
    case RouteEnd::AttemptFailed:
      return "attempt failed";
    case RouteEnd::WorldChanged:
      return "world changed";
    case RouteEnd::Switched:
      return "switched";
  }
  return "unknown";
}

RunTraceRecorder::RunTraceRecorder(RouteMatching matching) : matching_(matching) {}

void RunTraceRecorder::plannedPath(std::vector<geometry::Point> polyline, const geometry::Point& vehicle,
                                   const WayOpen& way_open)
{
  if (polyline.empty()) {
    return;
  }

  if (trace_.paths.empty()) {
    trace_.routes.push_back(TraceRoute{});
    trace_.paths.push_back(TracePath{std::move(polyline), 0});
  } else {
    const TracePath& last = trace_.paths.back();
    if (polyline != last.polyline) {
      const PathArc old_path(last.polyline);
      const std::vector<geometry::Point> remainder = old_path.remainderFrom(vehicle);
      int route = last.route;
      // Both from where the vehicle is (a search starts from the nearest free point when the vehicle
      // stands in an inflated obstacle, so a path need not start at the vehicle).
      if (!withinEachOther(PathArc(polyline).remainderFrom(vehicle), remainder, matching_)) {
        RouteEnd& end = trace_.routes[static_cast<std::size_t>(route)].end;
        if (harder_since_path_) {
          end = RouteEnd::AttemptFailed;
        } else if (legsOpen(remainder, way_open, matching_.leg_end_margin_m)) {
          end = RouteEnd::Switched;
        } else {
          end = RouteEnd::WorldChanged;
        }
        trace_.routes.push_back(TraceRoute{});
        route = static_cast<int>(trace_.routes.size()) - 1;
      }
      trace_.paths.push_back(TracePath{std::move(polyline), route});
    }
  }
  harder_since_path_ = false;
}

void RunTraceRecorder::closePush(std::vector<TracePush>& pushes) const
{
  if (push_ < 0) {
    return;
  }
  TracePush& push = pushes[static_cast<std::size_t>(push_)];
  if (pushes_completed_ > pushes_at_start_) {
    push.outcome = PushOutcome::Completed;
  } else if (push_found_harder_) {
    push.outcome = PushOutcome::Failed;
  } else {
    push.outcome = PushOutcome::Abandoned;
  }
}

void RunTraceRecorder::executiveCycle(const ExecutiveCycle& cycle)
{
  pushes_completed_ = cycle.pushes_completed;
  if (cycle.found_harder) {
    harder_since_path_ = true;
    push_found_harder_ = push_found_harder_ || push_ >= 0;
  }
  const bool pushing = cycle.mode == executive::Mode::Approach || cycle.mode == executive::Mode::Push;
  // A wait for the replanned push, or a stop on the way, keeps the push in hand.
  const bool paused = cycle.mode == executive::Mode::ReplanWait || cycle.mode == executive::Mode::Stop;
  if (push_ >= 0 &&
      (pushing ? trace_.pushes[static_cast<std::size_t>(push_)].object_id != cycle.target_object_id
               : !paused)) {
    closePush(trace_.pushes);
    push_ = -1;
  }
  if (pushing && push_ < 0) {
    trace_.pushes.push_back(TracePush{cycle.target_object_id, PushOutcome::Abandoned});
    push_ = static_cast<int>(trace_.pushes.size()) - 1;
    pushes_at_start_ = cycle.pushes_completed;
    push_found_harder_ = cycle.found_harder;
  }
}

void RunTraceRecorder::position(const geometry::Point& position)
{
  trace_.samples.push_back(TraceSample{position, static_cast<int>(trace_.paths.size()) - 1, push_});
}

RunTrace RunTraceRecorder::finish() const
{
  RunTrace trace = trace_;
  closePush(trace.pushes);
  return trace;
}

}  // namespace ifar::runner
