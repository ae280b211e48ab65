#pragma once
// Liveness on the bus: every daemon publishes heartbeat_t on HEARTBEAT once a second, so lcm-spy, a log
// and a supervisor see which processes run and whether their loop is healthy. The health is the run
// loop's own: what went wrong on the bus since the previous beat.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>

#include "bus/run_loop.hpp"

namespace ifar::bus {

inline constexpr const char* kHeartbeatChannel = "HEARTBEAT";

/// What a run loop counted, at one beat.
struct LoopCounters {
  std::int64_t bad_messages = 0;
  std::int64_t handler_errors = 0;
  std::int64_t publish_errors = 0;
};

LoopCounters countersOf(const RunLoop& loop);

struct LoopHealth {
  std::int8_t level = 0;  // heartbeat_t::HEALTH_OK or HEALTH_DEGRADED
  std::string message;    // empty when OK, else what happened since the previous beat
};

/// OK when no counter grew from `previous` to `current`, else DEGRADED naming each that did and by how much.
LoopHealth healthBetween(const LoopCounters& previous, const LoopCounters& current);

/// `health` with the daemon's own problem (empty = none) put first: DEGRADED when there is one.
LoopHealth withDaemonProblem(LoopHealth health, const std::string& problem);

/// What a daemon reports about its own job at each beat ("stale inputs: pose"); empty when it is fine.
using DaemonProblem = std::function<std::string()>;

/// `problem` that also logs what it reports, for a daemon whose heartbeat says what it waits for: a warning
/// when a problem appears or changes (the clock in its durations aside, common::withoutDurations), again
/// every `repeat_beats` calls while it lasts, and an info line when it clears.
DaemonProblem loggedProblem(DaemonProblem problem, std::shared_ptr<spdlog::logger> logger,
                            int repeat_beats = 30);

/// Publishes a heartbeat_t for `process` on kHeartbeatChannel from `loop` every `period_s` seconds (the
/// first one period after the loop starts), with this process's id and a sequence from 0; `problem`
/// (may be empty) is asked at each beat. It also watches the heartbeats of `process`'s name: another process
/// of that name on the same URL is logged as an error and reported in every beat (DEGRADED) while present.
void publishHeartbeats(RunLoop& loop, const std::string& process, double period_s = 1.0,
                       DaemonProblem problem = {});

}  // namespace ifar::bus
