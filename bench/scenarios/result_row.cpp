#include "bench/scenarios/result_row.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "bench/scenarios/answer_text.hpp"
#include "common/json_text.hpp"

namespace ifar::scenarios {
namespace {

std::string number(double value)
{
  if (!std::isfinite(value)) {
    return "null";
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%.6g", value);
  return text;
}

}  // namespace

double successWeightedByPathLength(bool success, double optimal, double length)
{
  if (!success || !std::isfinite(optimal) || optimal <= 0.0 || !std::isfinite(length)) {
    return 0.0;
  }
  return optimal / std::max(length, optimal);
}

std::vector<std::string> sensingProfiles(const std::vector<ResultRow>& rows)
{
  std::vector<std::string> profiles;
  for (const ResultRow& row : rows) {
    if (row.table == "system" && std::find(profiles.begin(), profiles.end(), row.sensing) == profiles.end()) {
      profiles.push_back(row.sensing);
    }
  }
  std::stable_partition(profiles.begin(), profiles.end(),
                        [](const std::string& name) { return name == "ideal"; });
  return profiles;
}

std::string toJsonLine(const ResultRow& row)
{
  std::string line = "{";
  line += "\"table\": " + common::jsonString(row.table);
  line += ", \"planner\": " + common::jsonString(row.planner);
  line += ", \"kind\": " + common::jsonString(row.kind);
  line += ", \"world\": " + common::jsonString(row.world);
  line += ", \"task\": " + common::jsonString(row.task);
  line += std::string(", \"success\": ") + (row.success ? "true" : "false");
  line += ", \"length\": " + number(row.length);
  line += ", \"optimal\": " + number(row.optimal);
  line += ", \"achievable\": " + number(row.achievable);
  line += ", \"without_pushing\": " + number(row.without_pushing);
  line += ", \"ms\": " + number(row.ms);
  line += ", \"status\": " + common::jsonString(row.status);
  line += ", \"reason\": " + common::jsonString(row.reason);
  line += ", \"graph_vertices\": " + number(row.graph_vertices);
  if (row.table == "system") {
    line += ", \"sim_time_s\": " + number(row.sim_time_s);
    line += ", \"pushes\": " + std::to_string(row.pushes);
    line += ", \"frame_median_ms\": " + number(row.frame_median_ms);
    line += ", \"frame_p99_ms\": " + number(row.frame_p99_ms);
    line += ", \"frame_max_ms\": " + number(row.frame_max_ms);
    line += ", \"interaction_max_ms\": " + number(row.interaction_max_ms);
    line += ", \"sensing\": " + common::jsonString(row.sensing);
    line += ", \"sensing_seed\": " + std::to_string(row.sensing_seed);
    line += ", \"undecided_saturated_pushes\": " + std::to_string(row.undecided_saturated_pushes);
    line += ", \"escalations\": " + std::to_string(row.escalations);
    line += ", \"excess_m\": " + number(row.excess_m);
    for (int bucket = 0; bucket < runner::kLossBucketCount; ++bucket) {
      line += std::string(", \"loss_") + runner::lossBucketName(bucket) +
              "_m\": " + number(runner::lossBucket(row.losses, bucket));
    }
  }
  return line + "}";
}

namespace {

/// Every field of a row in answer order, to an AnswerWriter (Row = const ResultRow) or from an
/// AnswerReader (Row = ResultRow): one list, so writing and reading cannot drift apart.
template <typename Fields, typename Row>
void rowFields(Fields& fields, Row& row)
{
  fields.field(row.table);
  fields.field(row.planner);
  fields.field(row.kind);
  fields.field(row.world);
  fields.field(row.task);
  fields.field(row.success);
  fields.field(row.length);
  fields.field(row.optimal);
  fields.field(row.achievable);
  fields.field(row.without_pushing);
  fields.field(row.ms);
  fields.field(row.status);
  fields.field(row.reason);
  fields.field(row.graph_vertices);
  fields.field(row.sim_time_s);
  fields.field(row.pushes);
  fields.field(row.frame_median_ms);
  fields.field(row.frame_p99_ms);
  fields.field(row.frame_max_ms);
  fields.field(row.interaction_max_ms);
  fields.field(row.sensing);
  fields.field(row.sensing_seed);
  fields.field(row.undecided_saturated_pushes);
  fields.field(row.escalations);
  fields.field(row.excess_m);
  for (int bucket = 0; bucket < runner::kLossBucketCount; ++bucket) {
    fields.field(runner::lossBucket(row.losses, bucket));
  }
}

}  // namespace

std::string toAnswer(const ResultRow& row)
{
  AnswerWriter writer;
  rowFields(writer, row);
  return writer.answer();
}

std::optional<ResultRow> rowFromAnswer(std::string_view answer)
{
  AnswerReader reader(answer);
  ResultRow row;
  rowFields(reader, row);
  if (!reader.complete()) {
    return std::nullopt;
  }
  return row;
}

}  // namespace ifar::scenarios
