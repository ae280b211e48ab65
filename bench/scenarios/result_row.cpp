#include "bench/scenarios/result_row.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

std::string quoted(const std::string& text)
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
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(character) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof(escaped), "\\u%04x", static_cast<unsigned>(character));
          out += escaped;
        } else {
          out += character;
        }
    }
  }
  return out + "\"";
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
  line += "\"table\": " + quoted(row.table);
  line += ", \"planner\": " + quoted(row.planner);
  line += ", \"kind\": " + quoted(row.kind);
  line += ", \"world\": " + quoted(row.world);
  line += ", \"task\": " + quoted(row.task);
  line += std::string(", \"success\": ") + (row.success ? "true" : "false");
  line += ", \"length\": " + number(row.length);
  line += ", \"optimal\": " + number(row.optimal);
  line += ", \"ms\": " + number(row.ms);
  line += ", \"status\": " + quoted(row.status);
  line += ", \"reason\": " + quoted(row.reason);
  line += ", \"graph_vertices\": " + number(row.graph_vertices);
  if (row.table == "system") {
    line += ", \"sim_time_s\": " + number(row.sim_time_s);
    line += ", \"pushes\": " + std::to_string(row.pushes);
  }
  return line + "}";
}

}  // namespace ifar::scenarios
