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

std::string stagesJson(const StageFrameTimes& stages)
{
  return fmt::format("{{\"perception\":{},\"local_graph\":{},\"merge\":{},\"search\":{}}}",
                     timesJson(stages.perception), timesJson(stages.local_graph), timesJson(stages.merge),
                     timesJson(stages.search));
}

std::string lossesJson(const LossAccount& losses)
{
  if (!losses.valid) {
    return fmt::format("{{\"valid\":false,\"problem\":{}}}", common::jsonString(losses.problem));
  }
  const LossBuckets& buckets = losses.buckets;
  return fmt::format(
      "{{\"valid\":true,\"achievable_m\":{},\"remaining_m\":{},\"excess_m\":{},\"exploring_m\":{},"
      "\"attempts_m\":{},\"route_switches_m\":{},\"route_choice_m\":{},\"execution_m\":{},"
      "\"push_overhead_m\":{}}}",
      jsonNumber(losses.achievable_m), jsonNumber(losses.remaining_m), jsonNumber(losses.excess_m),
      jsonNumber(buckets.exploring_m), jsonNumber(buckets.attempts_m), jsonNumber(buckets.route_switches_m),
      jsonNumber(buckets.route_choice_m), jsonNumber(buckets.execution_m),
      jsonNumber(buckets.push_overhead_m));
}

std::string legsJson(const std::vector<GoalLeg>& legs)
{
  std::string text = "[";
  for (const GoalLeg& leg : legs) {
    text += fmt::format("{}{{\"goal\":[{},{}],\"arrived\":{},\"distance_m\":{},\"time_s\":{},\"losses\":{}}}",
                        text.size() > 1 ? "," : "", jsonNumber(leg.goal.x()), jsonNumber(leg.goal.y()),
                        leg.arrived ? "true" : "false", jsonNumber(leg.distance_m),
                        jsonNumber(leg.sim_time_s), lossesJson(leg.losses));
  }
  return text + "]";
}

}  // namespace

std::string summaryJson(const RunSummary& summary)
{
  return fmt::format(
      "{{\"arrived\":{},\"reason\":{},\"distance_m\":{},\"time_s\":{},\"pushes\":{},\"replans\":{},"
      "\"affordance_updates\":{},\"blocked_passages\":{},\"escalations\":{},\"goal_distance_m\":{},"
      "\"wall_time_s\":{},"
      "\"planner_frame_ms\":{},\"interaction_ms\":{},\"stage_ms\":{},\"undecided_saturated_pushes\":{},"
      "\"longest_saturated_push_s\":{},\"routes\":{},\"routes_switched\":{},\"losses\":{},\"legs\":{}}}",
      summary.arrived ? "true" : "false", common::jsonString(summary.reason), jsonNumber(summary.distance_m),
      jsonNumber(summary.sim_time_s), summary.pushes, summary.replans, summary.affordance_updates,
      summary.blocked_passages, summary.escalations, jsonNumber(summary.goal_distance_m),
      jsonNumber(summary.wall_time_s), timesJson(summary.planner_frame), timesJson(summary.interaction),
      stagesJson(summary.stages), summary.undecided_saturated_pushes,
      jsonNumber(summary.longest_saturated_push_s), summary.routes, summary.routes_switched,
      lossesJson(summary.losses), legsJson(summary.legs));
}

}  // namespace ifar::runner
