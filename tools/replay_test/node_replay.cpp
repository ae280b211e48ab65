#include "tools/replay_test/node_replay.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <utility>

#include <spdlog/sinks/null_sink.h>

#include "executive/node/executive_node.hpp"
#include "ifar/node_journal_t.hpp"
#include "planner/core/planner.hpp"
#include "planner/node/planner_job.hpp"
#include "planner/node/planner_messages.hpp"
#include "planner/node/planner_node.hpp"
#include "system/simulated_stack.hpp"

namespace ifar::replay_test {
namespace {

std::shared_ptr<spdlog::logger> silentLogger(const std::string& name)
{
  return std::make_shared<spdlog::logger>(name, std::make_shared<spdlog::sinks::null_sink_mt>());
}

/// A timer of the runner's kind: first due one period after the start, then every period; one that is
/// late fires once and skips the periods it missed.
class PeriodicTimer {
 public:
  PeriodicTimer(double period_s, std::int64_t start_utime)
      : period_us_(std::max<std::int64_t>(1, std::llround(period_s * 1e6))),
        next_due_us_(start_utime + period_us_)
  {
  }

  bool due(std::int64_t now_utime)
  {
    if (now_utime < next_due_us_) {
      return false;
    }
    next_due_us_ += period_us_ * (1 + (now_utime - next_due_us_) / period_us_);
    return true;
  }

 private:
  std::int64_t period_us_;
  std::int64_t next_due_us_;
};

class PlannerReplay final : public NodeReplay {
 public:
  PlannerReplay(const runner::RunRequest& request, std::int64_t start_utime, bool publish_graph,
                ReplayClock clock)
      : clock_(clock),
        channels_(request.planner_node.channels),
        node_(request.planner_node, silentLogger("planner_replay"), start_utime),
        planner_(runner::runnerPlannerSettings(request)),
        publish_graph_(publish_graph),
        tick_(1.0 / request.planner_node.rate_hz, start_utime),
        resend_(1.0 / request.planner_node.path_resend_hz, start_utime)
  {
  }

  std::set<std::string> inputChannels() const override { return channels_.inputs(); }

  std::set<std::string> outputChannels() const override
  {
    std::set<std::string> outputs{channels_.global_path, channels_.planner_status};
    if (publish_graph_) {
      outputs.insert(channels_.dv_graph);
    }
    return outputs;
  }

  void deliver(const std::string& channel, common::ByteView bytes, std::int64_t now) override
  {
    // In the order of the daemon's subscriptions; one channel may carry one input only.
    if (channel == channels_.velodyne_packet) {
      take<velodyne_packet_t>(bytes, [&](const auto& message) { node_.onVelodynePacket(message, now); });
    } else if (channel == channels_.pose) {
      take<pose_t>(bytes, [&](const auto& message) { node_.onPose(message, now); });
    } else if (channel == channels_.goal) {
      take<goal_t>(bytes, [&](const auto& message) {
        if (node_.onGoal(message, now)) {
          run(node_.takeUpdateJob(busy()), now);
        }
      });
    } else if (channel == channels_.detected_objects) {
      take<object_polygons_t>(bytes, [&](const auto& message) { node_.onDetectedObjects(message, now); });
    } else if (channel == channels_.affordance) {
      take<affordance_t>(bytes, [&](const auto& message) {
        node_.onAffordance(message, now);
        run(node_.takeUpdateJob(busy()), now);
      });
    } else if (channel == channels_.blocked_passage) {
      take<blocked_passage_t>(bytes, [&](const auto& message) {
        node_.onBlockedPassage(message, now);
        run(node_.takeUpdateJob(busy()), now);
      });
    }
  }

  void runTimers(std::int64_t now) override
  {
    if (tick_.due(now)) {
      runTick(now);
    }
    if (resend_.due(now)) {
      resendPath(now);
    }
  }

  void journalEvent(std::int8_t kind, std::int16_t code, std::int64_t utime) override
  {
    if (kind == node_journal_t::KIND_TIMER && code == planner::kTickTimer) {
      runTick(utime);
    } else if (kind == node_journal_t::KIND_TIMER && code == planner::kPathResendTimer) {
      resendPath(utime);
    } else if (kind == node_journal_t::KIND_JOB_FINISHED && !running_.empty()) {
      planner::PlannerOutputs outputs = std::move(running_.front());
      running_.pop_front();
      planner::stampPath(outputs.path, utime);
      publishFinished(outputs, utime);
    }
  }

 private:
  /// The daemon's worker is busy from a job's hand-over until the loop takes its outputs.
  bool busy() const { return !running_.empty(); }

  void runTick(std::int64_t now)
  {
    planner::PlannerTick tick = node_.tick(now, busy());
    if (tick.waiting_status) {
      publish(channels_.planner_status, *tick.waiting_status, now);
    }
    run(std::move(tick.job), now);
  }

  void resendPath(std::int64_t now)
  {
    if (const std::optional<path_t> path = node_.resendPath(now)) {
      publish(channels_.global_path, *path, now);
    }
  }

  /// Runs `job` at once; its outputs go out now (the runner's way) or where the journal says (kept).
  void run(std::optional<planner::PlannerJob> job, std::int64_t now)
  {
    if (!job) {
      return;
    }
    const planner::PlannerJobResult finished = planner::runPlannerJob(planner_, *job);
    planner::PlannerOutputs outputs = planner::toOutputs(planner_, finished, now, publish_graph_);
    if (clock_ == ReplayClock::kJournal) {
      running_.push_back(std::move(outputs));
    } else {
      publishFinished(outputs, now);
    }
  }

  void publishFinished(planner::PlannerOutputs& outputs, std::int64_t now)
  {
    node_.finish(outputs);
    if (outputs.graph) {
      publish(channels_.dv_graph, *outputs.graph, now);
    }
    publish(channels_.global_path, outputs.path, now);
    publish(channels_.planner_status, outputs.status, now);
  }

  ReplayClock clock_;
  planner::PlannerChannels channels_;
  planner::PlannerNode node_;
  planner::Planner planner_;
  bool publish_graph_;
  PeriodicTimer tick_;
  PeriodicTimer resend_;
  std::deque<planner::PlannerOutputs> running_;  // handed to the daemon's worker, not yet taken back
};

class ExecutiveReplay final : public NodeReplay {
 public:
  ExecutiveReplay(const runner::RunRequest& request, std::int64_t start_utime)
      : packet_channel_(request.obstacles.packet_channel),
        node_(request.executive, request.obstacles, request.vehicle, silentLogger("executive_replay")),
        cycle_(executive::kControlPeriodS, start_utime)
  {
  }

  std::set<std::string> inputChannels() const override { return executive::inputChannels(packet_channel_); }

  std::set<std::string> outputChannels() const override
  {
    return {executive::kCommandChannel, executive::kStatusChannel, executive::kAffordanceChannel,
            executive::kBlockedPassageChannel};
  }

  void deliver(const std::string& channel, common::ByteView bytes, std::int64_t now) override
  {
    if (channel == executive::kPoseChannel) {
      take<pose_t>(bytes, [&](const auto& message) { node_.onPose(message, now); });
    } else if (channel == packet_channel_) {
      take<velodyne_packet_t>(bytes, [&](const auto& message) { node_.onVelodynePacket(message, now); });
    } else if (channel == executive::kPathChannel) {
      take<path_t>(bytes, [&](const auto& message) { node_.onPath(message, now); });
    } else if (channel == executive::kForceChannel) {
      take<force_t>(bytes, [&](const auto& message) { node_.onForce(message, now); });
    } else if (channel == executive::kMotorStatusChannel) {
      take<motor_status_t>(bytes, [&](const auto& message) { node_.onMotorStatus(message, now); });
    } else if (channel == executive::kOdometryChannel) {
      take<odometry_t>(bytes, [&](const auto& message) { node_.onOdometry(message, now); });
    } else if (channel == executive::kEStopChannel) {
      take<e_stop_t>(bytes, [&](const auto& message) { node_.onEStop(message, now); });
    }
  }

  void runTimers(std::int64_t now) override
  {
    if (cycle_.due(now)) {
      publishOutputs(node_.cycle(now), now);
    }
  }

  void journalEvent(std::int8_t kind, std::int16_t code, std::int64_t utime) override
  {
    if (kind == node_journal_t::KIND_TIMER && code == executive::kControlCycleTimer) {
      publishOutputs(node_.cycle(utime), utime);
    } else if (kind == node_journal_t::KIND_STOP) {
      publishOutputs(node_.stop(utime), utime);
    }
  }

 private:
  void publishOutputs(const executive::ExecutiveOutputs& outputs, std::int64_t now)
  {
    publish(executive::kCommandChannel, outputs.command, now);
    if (outputs.status) {
      publish(executive::kStatusChannel, *outputs.status, now);
    }
    if (outputs.affordance) {
      publish(executive::kAffordanceChannel, *outputs.affordance, now);
    }
    if (outputs.blocked_passage) {
      publish(executive::kBlockedPassageChannel, *outputs.blocked_passage, now);
    }
  }

  std::string packet_channel_;
  executive::ExecutiveNode node_;
  PeriodicTimer cycle_;
};

}  // namespace

std::vector<Published> NodeReplay::takePublished()
{
  std::vector<Published> published;
  published.swap(published_);
  return published;
}

std::unique_ptr<NodeReplay> plannerReplay(const runner::RunRequest& request, std::int64_t start_utime,
                                          bool publish_graph, ReplayClock clock)
{
  return std::make_unique<PlannerReplay>(request, start_utime, publish_graph, clock);
}

std::unique_ptr<NodeReplay> executiveReplay(const runner::RunRequest& request, std::int64_t start_utime)
{
  return std::make_unique<ExecutiveReplay>(request, start_utime);
}

}  // namespace ifar::replay_test
