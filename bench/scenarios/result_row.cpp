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
  }
  return line + "}";
}

std::string toAnswer(const ResultRow& row)
{
  AnswerWriter writer;
  for (const std::string* text : {&row.table, &row.planner, &row.kind, &row.world, &row.task}) {
    writer.text(*text);
  }
  writer.flag(row.success);
  for (const double value : {row.length, row.optimal, row.achievable, row.ms}) {
    writer.number(value);
  }
  writer.text(row.status);
  writer.text(row.reason);
  for (const double value : {row.graph_vertices, row.sim_time_s}) {
    writer.number(value);
  }
  writer.integer(row.pushes);
  for (const double value :
       {row.frame_median_ms, row.frame_p99_ms, row.frame_max_ms, row.interaction_max_ms}) {
    writer.number(value);
  }
  return writer.answer();
}

std::optional<ResultRow> rowFromAnswer(std::string_view answer)
{
  AnswerReader reader(answer);
  ResultRow row;
  for (std::string* text : {&row.table, &row.planner, &row.kind, &row.world, &row.task}) {
    reader.text(*text);
  }
  reader.flag(row.success);
  for (double* value : {&row.length, &row.optimal, &row.achievable, &row.ms}) {
    reader.number(*value);
  }
  reader.text(row.status);
  reader.text(row.reason);
  for (double* value : {&row.graph_vertices, &row.sim_time_s}) {
    reader.number(*value);
  }
  std::int64_t pushes = 0;
  reader.integer(pushes);
  row.pushes = static_cast<int>(pushes);
  for (double* value :
       {&row.frame_median_ms, &row.frame_p99_ms, &row.frame_max_ms, &row.interaction_max_ms}) {
    reader.number(*value);
  }
  if (!reader.complete()) {
    return std::nullopt;
  }
  return row;
}

}  // namespace ifar::scenarios
