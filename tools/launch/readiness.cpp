#include "tools/launch/readiness.hpp"

#include <cctype>
#include <cstdio>
#include <utility>

#include "common/input_silence.hpp"
#include "common/time.hpp"

namespace ifar::launch {
namespace {

constexpr std::int8_t kHealthOk = 0;  // heartbeat_t's values: OK, DEGRADED, ERROR
constexpr std::int8_t kHealthError = 2;

/// A daemon's log line without the time, logger name and level in front ("2026-12-01 21:13:54.396
/// [force-driver] [error] cannot open ..." -> "cannot open ..."), so the same failure reads the same.
std::string withoutLogPrefix(const std::string& line)
{
  std::size_t start = 0;
  const bool stamped = line.size() > 24 && std::isdigit(static_cast<unsigned char>(line[0])) != 0 &&
                       line[4] == '-' && line[10] == ' ' && line[13] == ':';
  if (stamped) {
    start = line.find(' ', 11);
    start = start == std::string::npos ? line.size() : start + 1;
    for (int tag = 0; tag < 2 && start < line.size() && line[start] == '['; ++tag) {
      const std::size_t close = line.find("] ", start);
      if (close == std::string::npos) {
        break;
      }
      start = close + 2;
    }
  }
  return line.substr(start);
}

std::string seconds(std::int64_t microseconds)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.0f s", common::microsecondsToSeconds(microseconds));
  return text;
}

}  // namespace

Readiness::Readiness(ReadinessSettings settings, std::int64_t start_us)
    : settings_(settings), start_us_(start_us)
{
}

void Readiness::onHeartbeat(const Heartbeat& beat, std::int64_t now_us)
{
  beats_[beat.pid] = Beat{beat, now_us};
}

std::string Readiness::stateOf(const ProcessState& process, std::int64_t now_us, bool& ready) const
{
  ready = false;
  const std::string why =
      process.last_exit +
      (process.exit_output.empty() ? std::string() : ": " + withoutLogPrefix(process.exit_output));
  if (process.pid < 0) {
    if (process.restart_pending) {
      return "restarting: " + why;
    }
    if (process.done) {
      return "ended: " + why;
    }
    return process.waiting_for.empty() ? "not started" : "waiting for " + process.waiting_for;
  }
  const std::int64_t timeout_us = common::secondsToMicroseconds(settings_.heartbeat_timeout_s);
  const auto found = beats_.find(static_cast<std::int32_t>(process.pid));
  if (found == beats_.end() || found->second.received_us < process.started_us) {
    if (now_us - process.started_us > timeout_us) {
      return "up, no heartbeat";
    }
    // Just restarted after a crash: still the crash's story until it beats (a crash loop reads the same).
    return process.restarts > 0 ? "restarting: " + why : "starting";
  }
  const Beat& beat = found->second;
  if (now_us - beat.received_us > timeout_us) {
    return "no heartbeat for " + seconds(now_us - beat.received_us);
  }
  if (beat.heartbeat.health == kHealthOk) {
    ready = true;
    return "ready";
  }
  return std::string(beat.heartbeat.health == kHealthError ? "error: " : "not ready: ") +
         beat.heartbeat.message;
}

bool Readiness::ready(const ProcessState& process, std::int64_t now_us) const
{
  bool ready = false;
  stateOf(process, now_us, ready);
  return ready;
}

std::vector<std::string> Readiness::summary(const std::vector<ProcessState>& processes,
                                            std::int64_t now_us) const
{
  std::size_t width = 0;
  for (const ProcessState& process : processes) {
    width = std::max(width, process.name.size());
  }
  std::vector<std::string> lines;
  std::size_t ready_count = 0;
  for (const ProcessState& process : processes) {
    bool ready = false;
    const std::string state = stateOf(process, now_us, ready);
    ready_count += ready ? 1 : 0;
    std::string line = "  " + process.name;
    line.resize(width + 4, ' ');
    line += state;
    lines.push_back(std::move(line));
  }
  lines.insert(lines.begin(), "readiness after " + seconds(now_us - start_us_) + ": " +
                                  std::to_string(ready_count) + " of " + std::to_string(processes.size()) +
                                  " ready");
  return lines;
}

std::optional<std::vector<std::string>> Readiness::report(const std::vector<ProcessState>& processes,
                                                          std::int64_t now_us)
{
  if (settings_.first_report_s <= 0.0 ||
      now_us - start_us_ < common::secondsToMicroseconds(settings_.first_report_s)) {
    return std::nullopt;
  }
  std::vector<std::string> lines = summary(processes, now_us);
  std::vector<std::string> compared;
  for (std::size_t index = 1; index < lines.size(); ++index) {  // the header's clock always runs
    compared.push_back(common::withoutDurations(lines[index]));
  }
  if (reported_ && compared == last_) {
    return std::nullopt;
  }
  reported_ = true;
  last_ = std::move(compared);
  return lines;
}

}  // namespace ifar::launch
