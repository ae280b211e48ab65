#include "planner/daemon/planner_daemon.hpp"

#include <utility>

namespace ifar::planner {
namespace {

// Finished outputs are picked up this often: the worker has no way into the loop's thread.
constexpr double kPublishPollS = 0.02;

}  // namespace

PlannerDaemon::PlannerDaemon(bus::RunLoop& loop, const NodeSettings& settings, Planner planner,
                             std::shared_ptr<spdlog::logger> logger, WorkerThreading threading)
    : loop_(loop),
      settings_(settings),
      start_utime_(loop.now()),
      node_(settings, std::move(logger), start_utime_),
      worker_(
          std::move(planner), [&loop] { return loop.now(); }, threading),
      // Finished jobs are taken before each input, so the node decides on the same worker state in a replay.
      journal_(loop, settings.channels.journal, "planner", start_utime_, settings.channels.inputs(),
               [this] { publishFinished(); })
{
  const PlannerChannels& channels = settings_.channels;
  loop_.subscribe<velodyne_packet_t>(channels.velodyne_packet,
                                     [this](const velodyne_packet_t& message, std::int64_t receive_utime) {
                                       node_.onVelodynePacket(message, receive_utime);
                                     });
  loop_.subscribe<pose_t>(channels.pose, [this](const pose_t& message, std::int64_t receive_utime) {
    node_.onPose(message, receive_utime);
  });
  loop_.subscribe<goal_t>(channels.goal, [this](const goal_t& message, std::int64_t receive_utime) {
    if (node_.onGoal(message, receive_utime)) {
      submit(node_.takeUpdateJob(worker_.busy()));
    }
  });
  loop_.subscribe<object_polygons_t>(channels.detected_objects,
                                     [this](const object_polygons_t& message, std::int64_t receive_utime) {
                                       node_.onDetectedObjects(message, receive_utime);
                                     });
  loop_.subscribe<affordance_t>(
      channels.affordance, [this](const affordance_t& message, std::int64_t receive_utime) {
        node_.onAffordance(message, receive_utime);
        submit(node_.takeUpdateJob(worker_.busy()));  // replans at once when the worker is free
      });
  loop_.subscribe<blocked_passage_t>(channels.blocked_passage,
                                     [this](const blocked_passage_t& message, std::int64_t receive_utime) {
                                       node_.onBlockedPassage(message, receive_utime);
                                       submit(node_.takeUpdateJob(worker_.busy()));
                                     });

  loop_.every(1.0 / settings_.rate_hz, [this] {
    publishFinished();
    const std::int64_t now = loop_.now();
    journal_.recorder().timer(kTickTimer, now);
    PlannerTick tick = node_.tick(now, worker_.busy());
    if (tick.waiting_status) {
      loop_.publish(settings_.channels.planner_status, *tick.waiting_status);
    }
    submit(std::move(tick.job));
  });
  loop_.every(kPublishPollS, [this] { publishFinished(); });
  // The same path again between updates, freshly stamped: the executive treats an old path as a dead
  // planner, while graph updates come at only 2.5 Hz.
  loop_.every(1.0 / settings_.path_resend_hz, [this] {
    const std::int64_t now = loop_.now();
    journal_.recorder().timer(kPathResendTimer, now);
    if (const std::optional<path_t> path = node_.resendPath(now)) {
      loop_.publish(settings_.channels.global_path, *path);
    }
  });
}

void PlannerDaemon::submit(std::optional<PlannerJob> job)
{
  if (!job) {
    return;
  }
  worker_.submit(std::move(*job));
  publishFinished();  // at once when the job ran in line
}

void PlannerDaemon::publishFinished()
{
  for (PlannerOutputs& outputs : worker_.takeFinished()) {
    journal_.recorder().jobFinished(outputs.path.utime);
    node_.finish(outputs);
    const PlannerChannels& channels = settings_.channels;
    if (outputs.graph) {
      loop_.publish(channels.dv_graph, *outputs.graph);
    }
    loop_.publish(channels.global_path, outputs.path);
    loop_.publish(channels.planner_status, outputs.status);
  }
}

}  // namespace ifar::planner
