// ifar-planner: the LCM adapter around the Planner library. Packets and poses are checked and gathered
// into revolutions on the LCM thread; at the configured rate the latest revolution (and any goal change)
// goes to a worker thread, so a slow frame never blocks the loop. A frame that finds the worker busy is
// kept for the next tick and counted as dropped; revolutions between ticks are skipped by design (their
// input flags carry over).

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/bus/heartbeat.hpp"
#include "common/bus/run_loop.hpp"
#include "common/daemon_main.hpp"
#include "common/input_silence.hpp"
#include "common/rate_limiter.hpp"
#include "common/time.hpp"
#include "common/vehicle.hpp"
#include "ifar/affordance_t.hpp"
#include "ifar/blocked_passage_t.hpp"
#include "ifar/goal_t.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "planner/core/planner.hpp"
#include "planner/daemon/daemon_settings.hpp"
#include "planner/daemon/planner_messages.hpp"
#include "planner/daemon/planner_worker.hpp"

namespace ifar::planner {
namespace {

constexpr int kVelodyneDataPort = 2368;
// Planner::applyAffordance names a refused estimate (unknown id, non-finite values) this way.
constexpr const char* kAffordanceRejected = "affordance for object";
constexpr const char* kBlockedPassage = "blocked passage";
// An input silent this long makes the heartbeat DEGRADED: ten revolutions of packets, fifty poses.
constexpr double kSilentInputS = 1.0;

/// Everything the LCM thread owns between callbacks.
struct LoopState {
  explicit LoopState(const InputSettings& input) : assembler(input) {}
  FrameAssembler assembler;
  std::optional<FrameInput> latest_frame;
  std::optional<Goal> new_goal;
  bool clear_goal = false;
  bool goal_changed = false;
  std::optional<std::int64_t> detector_utime;
  std::int64_t dropped_frames = 0;       // ready at a tick while the worker was still busy
  std::int64_t skipped_revolutions = 0;  // superseded between ticks (rate below 10 Hz)
  std::int64_t bad_messages = 0;         // malformed detector polygons, non-data packets of the wrong size
  std::int64_t published = 0;
  std::int64_t affordances = 0;
  std::int64_t bad_affordances = 0;  // non-finite values (unknown ids are counted by the planner)
  std::vector<AffordanceUpdate> pending_affordances;  // wait for the worker, applied before the next search
  std::vector<BlockedPassage> pending_blocked_passages;  // likewise
  std::optional<path_t> last_path;                       // resent between updates with a fresh utime
  common::RateLimiter input_log{5'000'000};
};

/// Keeps the newest frame; the input flags of a superseded one carry over so no problem goes unreported.
void keepLatest(LoopState& state, FrameInput frame)
{
  if (state.latest_frame) {
    ++state.skipped_revolutions;
    frame.flags |= state.latest_frame->flags;
    if (!state.latest_frame->problems.empty() &&
        frame.problems.find(state.latest_frame->problems) == std::string::npos) {
      frame.problems = state.latest_frame->problems + (frame.problems.empty() ? "" : "; " + frame.problems);
    }
  }
  state.latest_frame = std::move(frame);
}

int runPlanner(common::DaemonContext& context)
{
  const common::ConfigNode& config = context.config;
  const PlannerConfig loaded = loadPlannerConfig(config);
  PlannerSettings settings = loaded.planner;
  const DaemonSettings& daemon = loaded.daemon;
  settings.vehicle = common::loadVehicleSettings(common::ConfigNode::loadFile(daemon.vehicle_config));
  const auto& logger = context.logger;

  Planner planner(settings);
  if (!daemon.prior_graph.empty()) {
    const std::string error = planner.loadPriorGraph(daemon.prior_graph);
    if (error.empty()) {
      logger->info("prior graph {}: {} vertices", daemon.prior_graph, planner.graph().vertexCount());
    } else {
      // A prior map asked for and missing is a bad config: starting empty would plan without it unnoticed.
      config.child("daemon").fail("prior_graph", "cannot load the prior graph: " + error);
    }
  }

  bus::RunLoop loop(context.lcm_url, logger);
  common::InputSilence silence(common::monotonicMicroseconds(), kSilentInputS);
  const std::size_t packets_input = silence.watch(daemon.channels.velodyne_packet);
  const std::size_t pose_input = silence.watch(daemon.channels.pose);
  bus::publishHeartbeats(loop, logger->name(), 1.0,
                         [&silence] { return silence.problem(common::monotonicMicroseconds()); });
  LoopState state(daemon.input);
  PlannerWorker<PlannerMessages> worker(
      std::move(planner),
      [](const Planner& owner, const FrameResult& result, const std::string& goal_problem) {
        PlannerMessages messages = toMessages(owner, result, common::nowMicroseconds());
        if (!goal_problem.empty()) {
          messages.status.state = planner_status_t::STATE_BAD_INPUT;
          messages.status.message =
              goal_problem + (messages.status.message.empty() ? "" : "; " + messages.status.message);
        }
        return messages;
      });
  const PlannerChannels& channels = daemon.channels;

  // Hands the goal change (and, at a tick, the latest frame) to the worker; when it is busy they wait for
  // the next tick. A goal change alone replans at once without taking the frame, so graph updates keep
  // to the configured rate.
  const auto dispatch = [&](bool with_frame) {
    if (!(with_frame && state.latest_frame) && !state.goal_changed && state.pending_affordances.empty() &&
        state.pending_blocked_passages.empty()) {
      return;
    }
    PlannerJob job;
    if (with_frame) {
      job.frame = state.latest_frame;
    }
    job.new_goal = state.new_goal;
    job.clear_goal = state.clear_goal;
    job.affordances = state.pending_affordances;
    job.blocked_passages = state.pending_blocked_passages;
    if (!worker.trySubmit(std::move(job))) {
      if (with_frame && state.latest_frame) {
        ++state.dropped_frames;
      }
      return;
    }
    if (with_frame) {
      state.latest_frame.reset();
    }
    state.pending_affordances.clear();
    state.pending_blocked_passages.clear();
    state.new_goal.reset();
    state.clear_goal = false;
    state.goal_changed = false;
  };
  loop.subscribe<velodyne_packet_t>(channels.velodyne_packet, [&](const velodyne_packet_t& packet,
                                                                  std::int64_t) {
    silence.arrived(packets_input, common::monotonicMicroseconds());
    if (packet.port != kVelodyneDataPort) {
      return;  // position packets (port 8308) carry no points
    }
    if (packet.size != static_cast<std::int32_t>(packet.data.size())) {
      ++state.bad_messages;
      return;
    }
    const InputVerdict verdict = state.assembler.addPacket(
        common::ByteView(packet.data.data(), packet.data.size()), packet.utime, common::nowMicroseconds());
    if (verdict != InputVerdict::Accepted && state.input_log.allow(common::monotonicMicroseconds())) {
      logger->warn("{}: packet at {} refused: {}", channels.velodyne_packet, packet.utime, toString(verdict));
    }
    for (FrameInput& frame : state.assembler.takeFrames()) {
      keepLatest(state, std::move(frame));
    }
  });
  loop.subscribe<pose_t>(channels.pose, [&](const pose_t& pose, std::int64_t) {
    silence.arrived(pose_input, common::monotonicMicroseconds());
    const InputVerdict verdict = state.assembler.addPose(toPoseSample(pose), common::nowMicroseconds());
    if (verdict != InputVerdict::Accepted && state.input_log.allow(common::monotonicMicroseconds())) {
      logger->warn("{}: pose at {} refused: {}", channels.pose, pose.utime, toString(verdict));
    }
  });
  std::optional<goal_t> last_goal;  // goals are resent: only a change replans
  loop.subscribe<goal_t>(channels.goal, [&](const goal_t& goal, std::int64_t) {
    const bool same = last_goal && last_goal->goal_id == goal.goal_id && last_goal->cancel == goal.cancel &&
                      (goal.cancel || (last_goal->x == goal.x && last_goal->y == goal.y));
    last_goal = goal;
    if (same) {
      return;
    }
    state.goal_changed = true;
    if (goal.cancel) {
      state.clear_goal = true;
      state.new_goal.reset();
      logger->info("goal {} cancelled", goal.goal_id);
    } else {
      state.clear_goal = false;
      state.new_goal = Goal{goal.goal_id, geometry::Point(goal.x, goal.y)};
      logger->info("goal {} at ({:.2f}, {:.2f})", goal.goal_id, goal.x, goal.y);
    }
    dispatch(false);
  });
  loop.subscribe<object_polygons_t>(channels.detected_objects,
                                    [&](const object_polygons_t& objects, std::int64_t) {
                                      std::int64_t skipped = 0;
                                      state.assembler.setDetectorPolygons(toPolygons(objects, skipped));
                                      state.detector_utime = objects.utime;
                                      state.bad_messages += skipped;
                                    });
  loop.subscribe<affordance_t>(channels.affordance, [&](const affordance_t& affordance, std::int64_t) {
    ++state.affordances;
    const AffordanceUpdate update = toAffordanceUpdate(affordance);
    if (!std::isfinite(update.push_force_n) || !std::isfinite(update.affordance)) {
      // Still handed on: the planner counts it and says so in PLANNER_STATUS.
      ++state.bad_affordances;
      logger->warn("{}: object {}: push_force_n {} / affordance {} not finite, ignored ({} so far)",
                   channels.affordance, affordance.object_id, affordance.push_force_n, affordance.affordance,
                   state.bad_affordances);
    } else {
      logger->info("affordance for object {}: pushable {}, force {:.1f} N, mu {:.3f}", affordance.object_id,
                   affordance.pushable, affordance.push_force_n, affordance.affordance);
    }
    state.pending_affordances.push_back(update);
    dispatch(false);  // replans at once when the worker is free, else with the next job
  });

  loop.subscribe<blocked_passage_t>(
      channels.blocked_passage, [&](const blocked_passage_t& passage, std::int64_t) {
        // Non-finite points are handed on too: the planner counts them and says so in PLANNER_STATUS.
        logger->warn("blocked passage, goal {}: ({:.2f}, {:.2f}) -> ({:.2f}, {:.2f}): {}", passage.goal_id,
                     passage.from_x, passage.from_y, passage.to_x, passage.to_y, passage.reason);
        state.pending_blocked_passages.push_back(toBlockedPassage(passage));
        dispatch(false);
      });

  loop.every(1.0 / daemon.rate_hz, [&] {
    const std::int64_t now = common::nowMicroseconds();
    if (state.detector_utime &&
        now - *state.detector_utime > common::secondsToMicroseconds(daemon.detector_max_age_s)) {
      state.assembler.setDetectorPolygons(std::nullopt);
      state.detector_utime.reset();
    }
    if (!state.latest_frame && !state.goal_changed && state.published == 0) {
      planner_status_t waiting{};
      waiting.utime = now;
      waiting.state = planner_status_t::STATE_IDLE;
      waiting.bad_inputs = state.assembler.rejectedInputs() + state.bad_messages;
      waiting.message = "waiting for packets and poses";
      loop.publish(channels.planner_status, waiting);
      return;
    }
    dispatch(true);
  });
  loop.every(0.02, [&] {
    for (PlannerMessages& messages : worker.takeFinished()) {
      messages.status.bad_inputs += state.assembler.rejectedInputs() + state.bad_messages;
      if (state.dropped_frames > 0) {
        messages.status.message += (messages.status.message.empty() ? "" : "; ") +
                                   std::to_string(state.dropped_frames) +
                                   " frames dropped while the worker was busy";
      }
      if (messages.status.message.find(kAffordanceRejected) != std::string::npos) {
        logger->warn("{}: {}", channels.affordance, messages.status.message);
      }
      if (messages.status.message.find(kBlockedPassage) != std::string::npos) {
        logger->info("{}: {}", channels.blocked_passage, messages.status.message);
      }
      loop.publish(channels.dv_graph, messages.graph);
      loop.publish(channels.global_path, messages.path);
      state.last_path = messages.path;
      loop.publish(channels.planner_status, messages.status);
      ++state.published;
      logger->debug("frame {}: {} vertices, {} edges, path {} ({:.2f} m), {:.1f} ms", messages.status.frames,
                    messages.status.num_vertices, messages.status.num_edges,
                    messages.path.valid ? "valid" : "none", messages.path.length_m, messages.status.total_ms);
    }
  });

  // The same path again between updates, freshly stamped: the executive treats a path older than about
  // 0.2 s as a dead planner, while graph updates come at only 2.5 Hz.
  loop.every(1.0 / daemon.path_resend_hz, [&] {
    if (state.last_path) {
      state.last_path->utime = common::nowMicroseconds();
      loop.publish(channels.global_path, *state.last_path);
    }
  });

  logger->info("planning at {} Hz on {}; publishing {}, {}, {}", daemon.rate_hz, channels.velodyne_packet,
               channels.dv_graph, channels.global_path, channels.planner_status);
  const int code = loop.run();
  logger->info("stopped: {} updates published, {} frames dropped, {} revolutions skipped, {} inputs refused",
               state.published, state.dropped_frames, state.skipped_revolutions,
               state.assembler.rejectedInputs() + state.bad_messages);
  return code;
}

}  // namespace
}  // namespace ifar::planner

int main(int argc, char** argv)
{
  return ifar::common::runDaemon(argc, argv,
                                 {"planner",
                                  "DV-graph planner: VELODYNE_PACKET, POSE, GOAL in; DV_GRAPH, "
                                  "GLOBAL_PATH, PLANNER_STATUS out",
                                  "config/planner.yaml"},
                                 ifar::planner::runPlanner);
}
