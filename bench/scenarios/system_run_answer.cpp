#include <cstdint>

#include "bench/scenarios/answer_text.hpp"
#include "bench/scenarios/system_runs.hpp"

namespace ifar::scenarios {

namespace {

/// Every field of a run but its trajectory, in answer order, to an AnswerWriter (Run = const
/// SystemRun) or from an AnswerReader (Run = SystemRun). The trajectory follows with its count, which
/// the reader checks against the answer's size before reserving.
template <typename Fields, typename Run>
void runFields(Fields& fields, Run& run)
{
  fields.field(run.ran);
  fields.field(run.arrived);
  fields.field(run.failure_status);
  fields.field(run.reason);
  fields.field(run.distance_m);
  fields.field(run.sim_time_s);
  fields.field(run.wall_time_s);
  fields.field(run.pushes);
  fields.field(run.frame_median_ms);
  fields.field(run.frame_p99_ms);
  fields.field(run.frame_max_ms);
  fields.field(run.interaction_max_ms);
  fields.field(run.undecided_saturated_pushes);
  fields.field(run.escalations);
  fields.field(run.excess_m);
  for (int bucket = 0; bucket < runner::kLossBucketCount; ++bucket) {
    fields.field(runner::lossBucket(run.losses, bucket));
  }
}

}  // namespace

std::string toAnswer(const SystemRun& run)
{
  AnswerWriter writer;
  runFields(writer, run);
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
  runFields(reader, run);
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
