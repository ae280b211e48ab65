#include "sim/runner/summary_json.hpp"

#include <cmath>

#include <fmt/format.h>

namespace ifar::runner {
namespace {

/// JSON has no NaN or infinity: such a number is written as null.
std::string jsonNumber(double value)
{
  return std::isfinite(value) ? fmt::format("{:.3f}", value) : "null";
}

}  // namespace

std::string jsonString(const std::string& text)
{
  std::string out = "\"";
  for (const char character : text) {
    switch (character) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(character) < 0x20) {
          out += fmt::format("\\u{:04x}", static_cast<unsigned>(static_cast<unsigned char>(character)));
        } else {
          out += character;
        }
    }
  }
  out += '"';
  return out;
}

std::string summaryJson(const RunSummary& summary)
{
  return fmt::format(
      "{{\"arrived\":{},\"reason\":{},\"distance_m\":{},\"time_s\":{},\"pushes\":{},\"replans\":{},"
      "\"affordance_updates\":{},\"goal_distance_m\":{},\"wall_time_s\":{}}}",
      summary.arrived ? "true" : "false", jsonString(summary.reason), jsonNumber(summary.distance_m),
      jsonNumber(summary.sim_time_s), summary.pushes, summary.replans, summary.affordance_updates,
      jsonNumber(summary.goal_distance_m), jsonNumber(summary.wall_time_s));
}

}  // namespace ifar::runner
