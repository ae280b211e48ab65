#include "system/loss_accounting.hpp"

#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "system/path_arc.hpp"

namespace ifar::runner {
namespace {

/// What a sample's vehicle was busy with, as far as the buckets care.
struct Activity {
  int route = -1;  // of the path in force, -1 before the first
  int push = -1;   // a push that completed or failed; -1 when not pushing (or the push was abandoned)
  bool operator!=(const Activity& other) const { return route != other.route || push != other.push; }
};

// How far the projection onto the path in force may move in one step, as a multiple of the distance
// driven: enough to catch up round a bend the vehicle cuts, never a jump to a part of the path that passes
// nearby later, and none at all while the vehicle stands.
constexpr double kProjectionReach = 1.5;

class Accountant {
 public:
  explicit Accountant(const RunTrace& trace) : trace_(trace) {}

  Activity activityOf(const TraceSample& sample) const
  {
    Activity activity;
    if (sample.path >= 0) {
      activity.route = trace_.paths[static_cast<std::size_t>(sample.path)].route;
    }
    if (sample.push >= 0 &&
        trace_.pushes[static_cast<std::size_t>(sample.push)].outcome != PushOutcome::Abandoned) {
      activity.push = sample.push;
    }
    return activity;
  }

  /// The driving of the step to `step` from `from` beyond its progress along the path in force (0 while
  /// pushing or before a path): the progress is how far the vehicle's projection onto the path moved.
  double executionOf(const TraceSample& step, const geometry::Point& from, double travelled)
  {
    if (activityOf(step).push >= 0 || step.path < 0) {
      path_index_ = -1;  // after a push the vehicle is projected afresh
      return 0.0;
    }
    if (step.path != path_index_) {
      path_index_ = step.path;
      path_.emplace(trace_.paths[static_cast<std::size_t>(step.path)].polyline);
      arc_ = path_->nearest(from).arc;
    }
    const double reach = kProjectionReach * travelled;
    const double arc = path_->nearest(step.position, arc_ - reach, arc_ + reach).arc;
    const double progress = arc - arc_;
    arc_ = arc;
    return travelled - progress;
  }

  /// Books a stretch of one activity: its waste (travelled + dg) and the execution part of it.
  void book(const Activity& activity, double waste, double execution, LossBuckets& buckets) const
  {
    if (activity.push >= 0) {
      const PushOutcome outcome = trace_.pushes[static_cast<std::size_t>(activity.push)].outcome;
      (outcome == PushOutcome::Completed ? buckets.push_overhead_m : buckets.attempts_m) += waste;
      return;
    }
    if (activity.route < 0) {
      buckets.execution_m += waste;
      return;
    }
    buckets.execution_m += execution;
    const double route_part = waste - execution;
    switch (trace_.routes[static_cast<std::size_t>(activity.route)].end) {
      case RouteEnd::Kept:
        buckets.route_choice_m += route_part;
        break;
      case RouteEnd::AttemptFailed:
        buckets.attempts_m += route_part;
        break;
      case RouteEnd::WorldChanged:
        buckets.exploring_m += route_part;
        break;
      case RouteEnd::Switched:
        buckets.route_switches_m += route_part;
        break;
    }
  }

 private:
  const RunTrace& trace_;
  int path_index_ = -1;  // the path the projection is on
  std::optional<PathArc> path_;
  double arc_ = 0.0;  // the vehicle's projection onto it
};

}  // namespace

LossAccount accountLosses(const RunTrace& trace, const DistanceToGoal& distance_to_goal,
                          const LossAccountingSettings& settings)
{
  LossAccount account;
  const std::vector<TraceSample>& samples = trace.samples;
  if (samples.empty()) {
    account.problem = "the run has no trajectory";
    return account;
  }
  Accountant accountant(trace);
  double stretch_start_g = distance_to_goal(samples.front().position);
  if (!std::isfinite(stretch_start_g)) {
    account.problem = "no achievable way leads from the start to the goal";
    return account;
  }
  account.achievable_m = stretch_start_g;
  // Step `index` runs from sample index - 1 to sample index and is booked to what sample `index` says the
  // vehicle was doing: the recorder writes a position under the command that drove the vehicle there.
  std::optional<Activity> stretch_activity;
  double stretch_travelled = 0.0;
  double stretch_execution = 0.0;
  for (std::size_t index = 1; index < samples.size(); ++index) {
    const TraceSample& step = samples[index];
    const geometry::Point& from = samples[index - 1].position;
    const double travelled = (step.position - from).norm();
    account.travelled_m += travelled;
    stretch_travelled += travelled;
    stretch_execution += accountant.executionOf(step, from, travelled);
    if (!stretch_activity) {
      stretch_activity = accountant.activityOf(step);
    }
    const bool last = index + 1 == samples.size();
    const bool activity_changes = !last && accountant.activityOf(samples[index + 1]) != *stretch_activity;
    if (!last && !activity_changes && stretch_travelled < settings.evaluation_spacing_m) {
      continue;
    }
    const double g = distance_to_goal(step.position);
    if (!std::isfinite(g)) {
      if (last) {
        account.problem = "no achievable way leads from where the vehicle ended to the goal";
        return account;
      }
      continue;  // a point off the achievable map: the stretch goes on to the next point on it
    }
    accountant.book(*stretch_activity, stretch_travelled + g - stretch_start_g, stretch_execution,
                    account.buckets);
    stretch_activity.reset();
    stretch_start_g = g;
    stretch_travelled = 0.0;
    stretch_execution = 0.0;
  }
  account.remaining_m = stretch_start_g;  // g at the last sample: the loop ends on a booked stretch
  account.excess_m = account.travelled_m - (account.achievable_m - account.remaining_m);
  account.valid = true;
  return account;
}

}  // namespace ifar::runner
