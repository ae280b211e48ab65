#include "system/frame_times.hpp"

#include <algorithm>

#include "common/percentile.hpp"

namespace ifar::runner {

FrameTimes frameTimes(const std::vector<double>& milliseconds)
{
  FrameTimes times;
  times.frames = milliseconds.size();
  if (!milliseconds.empty()) {
    times.median_ms = common::nearestRankPercentile(milliseconds, 50.0);
    times.p99_ms = common::nearestRankPercentile(milliseconds, 99.0);
    times.max_ms = *std::max_element(milliseconds.begin(), milliseconds.end());
  }
  return times;
}

void PlannerFrameRecord::add(const planner::StageTimings& timings)
{
  total_ms_.push_back(timings.total_ms);
  perception_ms_.push_back(timings.perception_ms);
  local_graph_ms_.push_back(timings.local_graph_ms);
  merge_ms_.push_back(timings.merge_ms);
  interaction_ms_.push_back(timings.interaction_ms);
  search_ms_.push_back(timings.search_ms);
}

StageFrameTimes PlannerFrameRecord::stages() const
{
  return StageFrameTimes{frameTimes(perception_ms_), frameTimes(local_graph_ms_), frameTimes(merge_ms_),
                         frameTimes(search_ms_)};
}

}  // namespace ifar::runner
