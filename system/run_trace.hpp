#pragma once
// What a driven run did, as the loss accounting (loss_accounting.hpp) needs it: where the vehicle was at
// every simulator step, which planned path was in force and which push it was busy with, the routes the
// planner chose one after another and why each was given up, and how each push ended. RunTraceRecorder
// builds it from what the runner sees (the planner's paths, the executive's cycles, the true pose); it
// knows nothing of the world, so a trace can also be written by hand (tests).

#include <cstdint>
#include <functional>
#include <vector>

#include "common/geometry/point.hpp"
#include "executive/modes/mode.hpp"

namespace ifar::runner {

/// Why a route stopped being the one the planner chose.
enum class RouteEnd : std::uint8_t {
  Kept,           ///< still in force when the run ended
  AttemptFailed,  ///< given up after the executive found a push or a passage harder than planned
  WorldChanged,   ///< given up where what was left of it ran into obstacles seen since
  Switched,       ///< given up while what was left of it was still open
};

const char* routeEndName(RouteEnd end);

/// How a push (approach to contact, pushing, and the waits between) ended.
enum class PushOutcome : std::uint8_t {
  Completed,  ///< the executive counted the push plan done
  Failed,     ///< the executive found the object (or its passage) harder than planned
  Abandoned,  ///< neither: the plan changed before contact or before the end (counts as following)
};

struct TraceRoute {
  RouteEnd end = RouteEnd::Kept;
};

/// One planned path as published (robot first, goal last); a route is a run of such paths that stay
/// within RouteMatching::tolerance_m of each other.
struct TracePath {
  std::vector<geometry::Point> polyline;
  int route = 0;  // index in RunTrace::routes
};

struct TracePush {
  std::int64_t object_id = -1;
  PushOutcome outcome = PushOutcome::Abandoned;
};

struct TraceSample {
  geometry::Point position = geometry::Point::Zero();  // ground truth
  int path = -1;  // index in RunTrace::paths of the path in force; -1 before the first
  int push = -1;  // index in RunTrace::pushes while approaching or pushing; -1 otherwise
};

struct RunTrace {
  std::vector<TraceRoute> routes;
  std::vector<TracePath> paths;
  std::vector<TracePush> pushes;
  std::vector<TraceSample> samples;  // one per simulator step, in order
};

struct RouteMatching {
  /// A new path continues the route when every point of each is within this of the other (the new path
  /// against what is left of the old one from the vehicle on): about a vehicle length, so a corner seen
  /// a little elsewhere or a way round a box does not start a new route, a way round a wall does.
  double tolerance_m = 1.0;
  double sample_spacing_m = 0.25;  // points of each path compared, along it
  /// What is left of a route is open when each of its legs is, tested this far in from both ends (at
  /// most a quarter of the leg): a leg's ends are obstacle corners, on the obstacles' edges.
  double leg_end_margin_m = 0.25;
};

/// Whether the straight way between two points is open in the planner's map of the moment.
using WayOpen = std::function<bool(const geometry::Point& from, const geometry::Point& to)>;

/// What the executive did in one control cycle, for the trace.
struct ExecutiveCycle {
  executive::Mode mode = executive::Mode::Idle;
  std::int64_t target_object_id = -1;
  int pushes_completed = 0;  // the executive's count for the goal
  /// The executive reported an object harder to push than planned (unpushable, jammed, costlier) or a
  /// passage given up, on this cycle.
  bool found_harder = false;
};

class RunTraceRecorder {
 public:
  explicit RunTraceRecorder(RouteMatching matching = {});

  /// The planner published a path (`polyline` robot first) while the vehicle was at `vehicle`;
  /// `way_open` tells whether a stretch is open in the planner's map now (empty: every stretch is).
  void plannedPath(std::vector<geometry::Point> polyline, const geometry::Point& vehicle,
                   const WayOpen& way_open);
  void executiveCycle(const ExecutiveCycle& cycle);
  /// The vehicle's true position after a simulator step.
  void position(const geometry::Point& position);

  /// The trace so far, with a push in hand closed as it stands.
  RunTrace finish() const;

 private:
  void closePush(std::vector<TracePush>& pushes) const;

  RouteMatching matching_;
  RunTrace trace_;
  bool harder_since_path_ = false;
  // The push in hand: its index in trace_.pushes, the completed count when it began, whether the
  // executive found something harder during it.
  int push_ = -1;
  int pushes_at_start_ = 0;
  bool push_found_harder_ = false;
  int pushes_completed_ = 0;
};

}  // namespace ifar::runner
