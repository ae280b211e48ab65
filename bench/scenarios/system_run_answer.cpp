#include <cstdint>

#include "bench/scenarios/answer_text.hpp"
#include "bench/scenarios/system_runs.hpp"

namespace ifar::scenarios {

std::string toAnswer(const SystemRun& run)
{
  AnswerWriter writer;
  writer.flag(run.ran);
  writer.flag(run.arrived);
  writer.text(run.failure_status);
  writer.text(run.reason);
  for (const double value : {run.distance_m, run.sim_time_s, run.wall_time_s}) {
    writer.number(value);
  }
  writer.integer(run.pushes);
  for (const double value :
       {run.frame_median_ms, run.frame_p99_ms, run.frame_max_ms, run.interaction_max_ms}) {
    writer.number(value);
  }
  writer.integer(static_cast<std::int64_t>(run.trajectory.size()));
  for (const geometry::Pose2& pose : run.trajectory) {
    writer.number(pose.x);
    writer.number(pose.y);
    writer.number(pose.heading);
  }
  return writer.answer();
}

std::optional<SystemRun> systemRunFromAnswer(std::string_view answer)
{
  AnswerReader reader(answer);
  SystemRun run;
  reader.flag(run.ran);
  reader.flag(run.arrived);
  reader.text(run.failure_status);
  reader.text(run.reason);
  for (double* value : {&run.distance_m, &run.sim_time_s, &run.wall_time_s}) {
    reader.number(*value);
  }
  std::int64_t pushes = 0;
  reader.integer(pushes);
  run.pushes = static_cast<int>(pushes);
  for (double* value :
       {&run.frame_median_ms, &run.frame_p99_ms, &run.frame_max_ms, &run.interaction_max_ms}) {
    reader.number(*value);
  }
  std::int64_t poses = 0;
  // Each pose takes at least 6 bytes, so a count the answer cannot hold is refused before reserving.
  if (!reader.integer(poses) || poses < 0 || static_cast<std::size_t>(poses) > answer.size() / 6) {
    return std::nullopt;
  }
  run.trajectory.reserve(static_cast<std::size_t>(poses));
  for (std::int64_t index = 0; index < poses; ++index) {
    geometry::Pose2 pose;
    reader.number(pose.x);
    reader.number(pose.y);
    reader.number(pose.heading);
    run.trajectory.push_back(pose);
  }
  if (!reader.complete()) {
    return std::nullopt;
  }
  return run;
}

}  // namespace ifar::scenarios
