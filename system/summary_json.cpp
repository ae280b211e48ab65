#include "system/summary_json.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/json_text.hpp"

namespace ifar::runner {
namespace {

/// JSON has no NaN or infinity: such a number is written as null.
std::string jsonNumber(double value)
{
  return std::isfinite(value) ? fmt::format("{:.3f}", value) : "null";
}

std::string timesJson(const FrameTimes& times)
{
  return fmt::format("{{\"frames\":{},\"median\":{},\"p99\":{},\"max\":{}}}", times.frames,
                     jsonNumber(times.median_ms), jsonNumber(times.p99_ms), jsonNumber(times.max_ms));
}

}  // namespace

std::string summaryJson(const RunSummary& summary)
{
  return fmt::format(
      "{{\"arrived\":{},\"reason\":{},\"distance_m\":{},\"time_s\":{},\"pushes\":{},\"replans\":{},"
      "\"affordance_updates\":{},\"blocked_passages\":{},\"goal_distance_m\":{},\"wall_time_s\":{},"
      "\"planner_frame_ms\":{},\"interaction_ms\":{},\"undecided_saturated_pushes\":{},"
      "\"longest_saturated_push_s\":{}}}",
      summary.arrived ? "true" : "false", common::jsonString(summary.reason), jsonNumber(summary.distance_m),
      jsonNumber(summary.sim_time_s), summary.pushes, summary.replans, summary.affordance_updates,
      summary.blocked_passages, jsonNumber(summary.goal_distance_m), jsonNumber(summary.wall_time_s),
      timesJson(summary.planner_frame), timesJson(summary.interaction), summary.undecided_saturated_pushes,
      jsonNumber(summary.longest_saturated_push_s));
}

}  // namespace ifar::runner
