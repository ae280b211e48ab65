#pragma once
// Wall-clock times of the planner's frames over a run, per stage: what `ifar run --json` and
// `ifar run-summary --json` report, so a long frame can be put down to its stage without a profiler.

#include <cstddef>
#include <limits>
#include <vector>

#include "planner/core/planner_status.hpp"

namespace ifar::runner {

/// Wall-clock milliseconds of one kind of planner work over a run's frames (this process's clock, so a
/// loaded machine shows in them). NaN while no frame was timed.
struct FrameTimes {
  std::size_t frames = 0;
  double median_ms = std::numeric_limits<double>::quiet_NaN();
  double p99_ms = std::numeric_limits<double>::quiet_NaN();  // nearest rank
  double max_ms = std::numeric_limits<double>::quiet_NaN();
};

/// Median, p99 (nearest rank) and maximum of per-frame times.
FrameTimes frameTimes(const std::vector<double>& milliseconds);

/// The stages of a frame other than interaction (which the summary reports on its own, beside the total).
struct StageFrameTimes {
  FrameTimes perception;   // points to classified polygons of the local layer
  FrameTimes local_graph;  // the local visibility graph
  FrameTimes merge;        // local into global graph
  FrameTimes search;       // the path query
};

/// Collects each frame's stage times as they come.
class PlannerFrameRecord {
 public:
  void add(const planner::StageTimings& timings);

  FrameTimes total() const { return frameTimes(total_ms_); }
  FrameTimes interaction() const { return frameTimes(interaction_ms_); }
  StageFrameTimes stages() const;

 private:
  std::vector<double> total_ms_;
  std::vector<double> perception_ms_;
  std::vector<double> local_graph_ms_;
  std::vector<double> merge_ms_;
  std::vector<double> interaction_ms_;
  std::vector<double> search_ms_;
};

}  // namespace ifar::runner
