#include "tools/launch/launch_config.hpp"

#include <set>
#include <utility>

namespace ifar::launch {

namespace {

std::string expanded(const common::ConfigNode& node, const std::string& key, const std::string& text,
                     const VariableLookup& lookup)
{
  Expansion expansion = expandVariables(text, lookup);
  if (!expansion.error.empty()) {
    node.fail(key, expansion.error);
  }
  return std::move(expansion.text);
}

}  // namespace

LaunchSpec loadLaunchSpec(const common::ConfigNode& root, const VariableLookup& lookup)
{
  LaunchSpec spec;
  spec.stop_timeout_s = root.optional<double>("stop_timeout_s", spec.stop_timeout_s);
  if (!(spec.stop_timeout_s > 0.0)) {
    root.fail("stop_timeout_s", "must be greater than zero");
  }
  spec.readiness_after_s = root.optional<double>("readiness_after_s", spec.readiness_after_s);
  if (!(spec.readiness_after_s >= 0.0 && spec.readiness_after_s <= 3600.0)) {
    root.fail("readiness_after_s", "must be between 0 (no summary) and 3600 seconds");
  }
  spec.start_wait_s = root.optional<double>("start_wait_s", spec.start_wait_s);
  if (!(spec.start_wait_s >= 0.0 && spec.start_wait_s <= 3600.0)) {
    root.fail("start_wait_s", "must be between 0 and 3600 seconds");
  }
  std::set<std::string> names;
  const auto processes = root.sequence("processes");
  if (processes.empty()) {
    root.fail("processes", "the launch file starts nothing: list at least one process");
  }
  for (const auto& node : processes) {
    ProcessSpec process;
    process.name = node.required<std::string>("name");
    if (process.name.empty() || !names.insert(process.name).second) {
      node.fail("name", "'" + process.name + "' is empty or used twice");
    }
    process.command = node.required<std::vector<std::string>>("command");
    for (std::string& argument : process.command) {
      argument = expanded(node, "command", argument, lookup);
    }
    if (process.command.empty() || process.command.front().empty()) {
      node.fail("command", "must name a program");
    }
    process.respawn = node.optional<bool>("respawn", process.respawn);
    process.respawn_delay_s = node.optional<double>("respawn_delay_s", process.respawn_delay_s);
    process.max_restarts = node.optional<int>("max_restarts", process.max_restarts);
    process.required = node.optional<bool>("required", process.required);
    if (node.has("environment")) {
      const auto environment = node.child("environment");
      for (const auto& key : environment.keys()) {
        process.environment[key] = expanded(environment, key, environment.required<std::string>(key), lookup);
      }
    }
    if (node.has("after")) {
      process.after = node.required<std::vector<std::string>>("after");
      for (const std::string& earlier : process.after) {
        // Only earlier ones: the file's order is the start order, and no two can wait on each other.
        if (earlier == process.name || names.count(earlier) == 0) {
          node.fail("after", "'" + earlier + "' is not a process listed before " + process.name);
        }
      }
    }
    spec.processes.push_back(std::move(process));
  }
  root.rejectUnknownKeys();
  return spec;
}

}  // namespace ifar::launch
