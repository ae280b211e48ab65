#pragma once
// The planner node's core: everything between the bus and the Planner, without a bus. It takes the
// planner's input messages with their receive times, checks them and gathers packets and poses into
// revolutions (keeping the newest; a superseded one's input flags carry over), keeps goal changes and the
// executive's findings until they are handed over, and says at each tick what work the Planner should do.
// The daemon (planner/daemon) wraps it in the LCM run loop and runs jobs on a worker thread; the headless
// runner (system/) drives the same node on simulated time and runs jobs in line. One clock, `now_us`:
// microseconds, the clock of the receive times (wall clock in the daemon, simulated in the runner).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "common/input_silence.hpp"
#include "common/rate_limiter.hpp"
#include "ifar/affordance_t.hpp"
#include "ifar/blocked_passage_t.hpp"
#include "ifar/goal_t.hpp"
#include "ifar/object_polygons_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "planner/core/frame_assembler.hpp"
#include "planner/node/node_settings.hpp"
#include "planner/node/planner_job.hpp"

namespace ifar::planner {

/// The farthest a goal's coordinate may lie from the map origin, metres: far beyond any mission.
inline constexpr double kMaxGoalCoordinateM = 1e6;

/// The daemon's timers as its journal names them (node_journal_t KIND_TIMER codes).
inline constexpr std::int16_t kTickTimer = 0;
inline constexpr std::int16_t kPathResendTimer = 1;

/// What a tick asks for: work for the Planner, or (before anything was planned) a "waiting" status.
struct PlannerTick {
  std::optional<PlannerJob> job;
  std::optional<planner_status_t> waiting_status;
};

class PlannerNode {
 public:
  /// `logger` receives the node's warnings (refused input, goal changes); it must not be null.
  PlannerNode(const NodeSettings& settings, std::shared_ptr<spdlog::logger> logger, std::int64_t start_us);
  PlannerNode(const PlannerNode&) = delete;
  PlannerNode& operator=(const PlannerNode&) = delete;

  // Inputs, each with its receive time. None of them throws on bad content: it is counted and reported.
  void onVelodynePacket(const velodyne_packet_t& packet, std::int64_t now_us);
  void onPose(const pose_t& pose, std::int64_t now_us);
  /// Goals are resent: only a change counts. True when the goal changed (worth a job at once). A goal with
  /// a non-finite coordinate or one beyond kMaxGoalCoordinateM is refused (counted, logged).
  bool onGoal(const goal_t& goal, std::int64_t now_us);
  void onDetectedObjects(const object_polygons_t& objects, std::int64_t now_us);
  void onAffordance(const affordance_t& affordance, std::int64_t now_us);
  void onBlockedPassage(const blocked_passage_t& passage, std::int64_t now_us);

  /// At the planning rate: the latest revolution with any goal change and findings, or the waiting status
  /// while nothing has been planned. `planner_busy`: the Planner is still on the previous job, so a ready
  /// revolution waits for the next tick (counted as dropped).
  PlannerTick tick(std::int64_t now_us, bool planner_busy);
  /// Between ticks, after a goal change, an affordance or a blocked passage: the job that replans on the
  /// current graph at once, if there is anything to hand over and the Planner is free.
  std::optional<PlannerJob> takeUpdateJob(bool planner_busy);

  /// A finished job's outputs, before they are published: adds the node's own counters to the status.
  void finish(PlannerOutputs& outputs);
  /// The last published path again with a fresh utime (the executive takes an old path as a dead planner).
  std::optional<path_t> resendPath(std::int64_t now_us);

  /// For the heartbeat: inputs silent for too long, empty when none is.
  std::string healthProblem(std::int64_t now_us) const;

  std::int64_t published() const { return published_; }
  std::int64_t droppedFrames() const { return dropped_frames_; }
  std::int64_t skippedRevolutions() const { return skipped_revolutions_; }
  /// Inputs refused by the assembler plus malformed messages.
  std::int64_t refusedInputs() const { return assembler_.rejectedInputs() + bad_messages_; }

 private:
  std::optional<PlannerJob> takeJob(bool with_frame, bool planner_busy);
  void keepLatest(FrameInput frame);
  void warnRefused(const char* what, std::int64_t utime, InputVerdict verdict, std::int64_t now_us);

  NodeSettings settings_;
  std::shared_ptr<spdlog::logger> logger_;
  FrameAssembler assembler_;
  common::InputSilence silence_;
  std::size_t packets_input_;
  std::size_t pose_input_;
  std::optional<FrameInput> latest_frame_;
  std::optional<goal_t> last_goal_;
  std::optional<Goal> new_goal_;
  bool clear_goal_ = false;
  bool goal_changed_ = false;
  std::optional<std::int64_t> detector_utime_;
  std::vector<AffordanceUpdate> pending_affordances_;
  std::vector<BlockedPassage> pending_blocked_passages_;
  std::optional<path_t> last_path_;
  std::int64_t dropped_frames_ = 0;       // ready at a tick while the Planner was still busy
  std::int64_t skipped_revolutions_ = 0;  // superseded between ticks (rate below 10 Hz)
  std::int64_t bad_messages_ = 0;         // malformed detector polygons, data packets of the wrong size
  std::int64_t bad_affordances_ = 0;      // non-finite values (unknown ids are counted by the planner)
  std::int64_t published_ = 0;
  common::RateLimiter input_log_;
};

}  // namespace ifar::planner
