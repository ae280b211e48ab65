#pragma once
// Where a driven run's distance went beyond the achievable way to the goal (achievable_map.hpp), split
// into buckets that add up to it. The yardstick is g(x), the length of the achievable way from x to the
// goal. Each stretch of driving of length ds moves g by dg; ds + dg >= 0 is what the stretch wasted (a
// vehicle on the achievable way has dg = -ds). Summed over the run the waste is
//   excess = travelled - (g(start) - g(end)),
// which for an arrival is the distance beyond the achievable length (g(end) is at most the arrival radius).
// A stretch driven toward a dead end wastes twice its length at once (g grows as much as the vehicle
// drives), so the way back costs nothing more: each metre is booked when it is driven, to what the
// vehicle was doing then:
// - a stretch of a push (approach, pushing and the waits between) that ended with the object or its
//   passage found harder than planned: attempts; of a completed push: push overhead;
// - a stretch of following the path in force P splits in two. Execution: ds minus the progress along P
//   (DistanceToGo of P; loops, weaving, backing, going wide). The rest, the progress along P that was
//   no progress toward the goal, goes by how P's route ended (run_trace.hpp): given up after a push or a
//   passage proved harder: attempts; given up because it got worse (walls where unknown space was
//   counted free): exploring; given up for a cheaper route while it had not got worse: route switches;
//   kept to the end: route choice (the planner's route itself longer than the achievable one, e.g. round
//   an object it could have pushed);
// - driving before the first path: execution.
// docs/benchmarks.md ("Loss accounting") says the same for readers of the tables.

#include <functional>
#include <limits>
#include <string>

#include "common/geometry/point.hpp"
#include "system/run_trace.hpp"

namespace ifar::runner {

struct LossBuckets {
  double exploring_m = 0.0;
  double attempts_m = 0.0;
  double route_switches_m = 0.0;
  double route_choice_m = 0.0;
  double execution_m = 0.0;
  double push_overhead_m = 0.0;
  double total() const
  {
    return exploring_m + attempts_m + route_switches_m + route_choice_m + execution_m + push_overhead_m;
  }
};

/// Buckets of a run that was not accounted: every one NaN.
inline LossBuckets notAccounted()
{
  const double unknown = std::numeric_limits<double>::quiet_NaN();
  return LossBuckets{unknown, unknown, unknown, unknown, unknown, unknown};
}

/// The buckets' names as the benchmark's rows and tables write them, and a bucket by its index in that
/// order (exploring, attempts, route switches, route choice, execution, push overhead); `index` in
/// [0, kLossBucketCount).
constexpr int kLossBucketCount = 6;
inline constexpr double LossBuckets::*kLossBucketMembers[kLossBucketCount] = {
    &LossBuckets::exploring_m,    &LossBuckets::attempts_m,  &LossBuckets::route_switches_m,
    &LossBuckets::route_choice_m, &LossBuckets::execution_m, &LossBuckets::push_overhead_m};
inline constexpr const char* kLossBucketNames[kLossBucketCount] = {
    "exploring", "attempts", "route_switches", "route_choice", "execution", "push_overhead"};
inline const char* lossBucketName(int index)
{
  return kLossBucketNames[index];
}
inline double& lossBucket(LossBuckets& buckets, int index)
{
  return buckets.*kLossBucketMembers[index];
}
inline double lossBucket(const LossBuckets& buckets, int index)
{
  return buckets.*kLossBucketMembers[index];
}

struct LossAccount {
  bool valid = false;
  std::string problem;  // why not valid
  double travelled_m = 0.0;
  double achievable_m = std::numeric_limits<double>::quiet_NaN();  // g(start)
  double remaining_m = std::numeric_limits<double>::quiet_NaN();   // g(end)
  double excess_m = std::numeric_limits<double>::quiet_NaN();      // travelled - (g(start) - g(end))
  LossBuckets buckets;                                             // total() == excess_m up to rounding
};

/// g(x): the length of the achievable way from x to the goal; infinity where none leads to it.
using DistanceToGoal = std::function<double(const geometry::Point& from)>;

struct LossAccountingSettings {
  /// g is evaluated at least this often along the trajectory (and wherever the activity changes); the
  /// buckets add up to the excess whatever the spacing, a finer one only splits them more exactly.
  double evaluation_spacing_m = 0.05;
};

/// Not valid when the trace has no sample, or g is infinite at its first or last sample.
LossAccount accountLosses(const RunTrace& trace, const DistanceToGoal& distance_to_goal,
                          const LossAccountingSettings& settings = {});

}  // namespace ifar::runner
