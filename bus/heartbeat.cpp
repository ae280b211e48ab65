#include "bus/heartbeat.hpp"

#include <unistd.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "bus/duplicate_process_watch.hpp"
#include "common/input_silence.hpp"
#include "common/time.hpp"
#include "ifar/heartbeat_t.hpp"

namespace ifar::bus {

namespace {

void nameGrowth(std::string& message, std::int64_t before, std::int64_t after, const char* what)
{
  if (after <= before) {
    return;
  }
  if (!message.empty()) {
    message += ", ";
  }
  message += std::to_string(after - before) + " " + what;
}

}  // namespace

LoopCounters countersOf(const RunLoop& loop)
{
  return LoopCounters{loop.badMessages(), loop.handlerErrors(), loop.publishErrors()};
}

LoopHealth healthBetween(const LoopCounters& previous, const LoopCounters& current)
{
  LoopHealth health;
  nameGrowth(health.message, previous.bad_messages, current.bad_messages, "undecodable messages");
  nameGrowth(health.message, previous.handler_errors, current.handler_errors, "handler errors");
  nameGrowth(health.message, previous.publish_errors, current.publish_errors, "failed publishes");
  if (!health.message.empty()) {
    health.level = heartbeat_t::HEALTH_DEGRADED;
    health.message += " since the last beat";
  } else {
    health.level = heartbeat_t::HEALTH_OK;
  }
  return health;
}

LoopHealth withDaemonProblem(LoopHealth health, const std::string& problem)
{
  if (problem.empty()) {
    return health;
  }
  health.level = heartbeat_t::HEALTH_DEGRADED;
  health.message = health.message.empty() ? problem : problem + "; " + health.message;
  return health;
}

DaemonProblem loggedProblem(DaemonProblem problem, std::shared_ptr<spdlog::logger> logger, int repeat_beats)
{
  struct Reported {
    std::string text;  // without durations
    std::string last;  // as said
    int beats_since_said = 0;
  };
  auto reported = std::make_shared<Reported>();
  return [problem = std::move(problem), logger = std::move(logger), reported, repeat_beats]() {
    std::string text = problem ? problem() : std::string();
    const std::string stable = common::withoutDurations(text);
    ++reported->beats_since_said;
    if (stable != reported->text || (!text.empty() && reported->beats_since_said >= repeat_beats)) {
      if (text.empty()) {
        logger->info("no longer: {}", reported->last);
      } else {
        logger->warn("{}", text);
      }
      reported->text = stable;
      reported->last = text;
      reported->beats_since_said = 0;
    }
    return text;
  };
}

void publishHeartbeats(RunLoop& loop, const std::string& process, double period_s, DaemonProblem problem)
{
  heartbeat_t beat{};
  beat.process = process;
  beat.pid = static_cast<std::int32_t>(::getpid());
  beat.sequence = 0;
  // Shared by the subscription that fills it and the timer that reports it, both run by this loop.
  auto duplicates = std::make_shared<DuplicateProcessWatch>(process, beat.pid);
  loop.subscribe<heartbeat_t>(kHeartbeatChannel, [&loop, duplicates](const heartbeat_t& other, std::int64_t) {
    if (const std::optional<std::string> alarm = duplicates->onBeat(other.process, other.pid, loop.now())) {
      loop.logger().error("{}", *alarm);
    }
  });
  LoopCounters previous = countersOf(loop);
  loop.every(period_s, [&loop, beat, previous, duplicates, problem = std::move(problem)]() mutable {
    const LoopCounters current = countersOf(loop);
    std::string own_problem = problem ? problem() : std::string();
    const std::string duplicate = duplicates->problem(loop.now());
    if (!duplicate.empty()) {
      own_problem = own_problem.empty() ? duplicate : duplicate + "; " + own_problem;
    }
    const LoopHealth health = withDaemonProblem(healthBetween(previous, current), own_problem);
    previous = current;
    beat.utime = common::nowMicroseconds();
    beat.health = health.level;
    beat.message = health.message;
    loop.publish(kHeartbeatChannel, beat);
    ++beat.sequence;
  });
}

}  // namespace ifar::bus
