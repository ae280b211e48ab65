#include "planner/node/planner_node.hpp"

#include <cmath>
#include <utility>

#include "common/span.hpp"
#include "planner/node/planner_messages.hpp"

namespace ifar::planner {
namespace {

// Planner::applyAffordance names a refused estimate (unknown id, non-finite values) this way.
constexpr const char* kAffordanceRejected = "affordance for object";
constexpr const char* kBlockedPassage = "blocked passage";
// An input silent this long makes the heartbeat DEGRADED: ten revolutions of packets, fifty poses.
constexpr double kSilentInputS = 1.0;
constexpr std::int64_t kInputLogIntervalUs = 5'000'000;

bool sameGoal(const goal_t& previous, const goal_t& goal)
{
  return previous.goal_id == goal.goal_id && previous.cancel == goal.cancel &&
         (goal.cancel || (previous.x == goal.x && previous.y == goal.y));
}

}  // namespace

PlannerNode::PlannerNode(const NodeSettings& settings, std::shared_ptr<spdlog::logger> logger,
                         std::int64_t start_us)
    : settings_(settings),
      logger_(std::move(logger)),
      assembler_(settings.input),
      silence_(start_us, kSilentInputS),
      packets_input_(silence_.watch(settings.channels.velodyne_packet)),
      pose_input_(silence_.watch(settings.channels.pose)),
      input_log_(kInputLogIntervalUs)
{
}

void PlannerNode::warnRefused(const char* what, std::int64_t utime, InputVerdict verdict, std::int64_t now_us)
{
  if (verdict != InputVerdict::Accepted && input_log_.allow(now_us)) {
    logger_->warn("{} at {} refused: {}", what, utime, toString(verdict));
  }
}

void PlannerNode::keepLatest(FrameInput frame)
{
  if (latest_frame_) {
    ++skipped_revolutions_;
    frame.flags |= latest_frame_->flags;
    if (!latest_frame_->problems.empty() &&
        frame.problems.find(latest_frame_->problems) == std::string::npos) {
      frame.problems = latest_frame_->problems + (frame.problems.empty() ? "" : "; " + frame.problems);
    }
  }
  latest_frame_ = std::move(frame);
}

void PlannerNode::onVelodynePacket(const velodyne_packet_t& packet, std::int64_t now_us)
{
  silence_.arrived(packets_input_, now_us);
  if (packet.port != settings_.data_port) {
    return;  // position packets (port 8308) carry no points
  }
  if (packet.size != static_cast<std::int32_t>(packet.data.size())) {
    ++bad_messages_;
    return;
  }
  const InputVerdict verdict =
      assembler_.addPacket(common::ByteView(packet.data.data(), packet.data.size()), packet.utime, now_us);
  warnRefused("packet", packet.utime, verdict, now_us);
  for (FrameInput& frame : assembler_.takeFrames()) {
    keepLatest(std::move(frame));
  }
}

void PlannerNode::onPose(const pose_t& pose, std::int64_t now_us)
{
  silence_.arrived(pose_input_, now_us);
  warnRefused("pose", pose.utime, assembler_.addPose(toPoseSample(pose), now_us), now_us);
}

bool PlannerNode::onGoal(const goal_t& goal, std::int64_t /*now_us*/)
{
  // A goal is a place the vehicle can drive to: a non-finite or absurdly far one (a corrupted or hostile
  // message) would poison every distance the search adds up. Refused and counted like any bad input; the
  // current goal stays.
  if (!goal.cancel && !(std::isfinite(goal.x) && std::isfinite(goal.y) &&
                        std::abs(goal.x) <= kMaxGoalCoordinateM && std::abs(goal.y) <= kMaxGoalCoordinateM)) {
    ++bad_messages_;
    logger_->warn("goal {} at ({}, {}) refused: each coordinate must be finite and within {} m", goal.goal_id,
                  goal.x, goal.y, kMaxGoalCoordinateM);
    return false;
  }
  const bool same = last_goal_ && sameGoal(*last_goal_, goal);
  last_goal_ = goal;
  if (same) {
    return false;
  }
  goal_changed_ = true;
  if (goal.cancel) {
    clear_goal_ = true;
    new_goal_.reset();
    logger_->info("goal {} cancelled", goal.goal_id);
  } else {
    clear_goal_ = false;
    new_goal_ = Goal{goal.goal_id, geometry::Point(goal.x, goal.y)};
    logger_->info("goal {} at ({:.2f}, {:.2f})", goal.goal_id, goal.x, goal.y);
  }
  return true;
}

void PlannerNode::onDetectedObjects(const object_polygons_t& objects, std::int64_t now_us)
{
  std::int64_t skipped = 0;
  assembler_.setDetectorPolygons(toPolygons(objects, skipped));
  // Aged by receive time: the detector's own clock need not be the planner's.
  detector_utime_ = now_us;
  bad_messages_ += skipped;
}

void PlannerNode::onAffordance(const affordance_t& affordance, std::int64_t /*now_us*/)
{
  const AffordanceUpdate update = toAffordanceUpdate(affordance);
  if (!std::isfinite(update.push_force_n) || !std::isfinite(update.affordance)) {
    // Still handed on: the planner counts it and says so in PLANNER_STATUS.
    ++bad_affordances_;
    logger_->warn("{}: object {}: push_force_n {} / affordance {} not finite, ignored ({} so far)",
                  settings_.channels.affordance, affordance.object_id, affordance.push_force_n,
                  affordance.affordance, bad_affordances_);
  } else {
    logger_->info("affordance for object {}: pushable {}, force {:.1f} N, mu {:.3f}", affordance.object_id,
                  affordance.pushable, affordance.push_force_n, affordance.affordance);
  }
  pending_affordances_.push_back(update);
}

void PlannerNode::onBlockedPassage(const blocked_passage_t& passage, std::int64_t /*now_us*/)
{
  // Non-finite points are handed on too: the planner counts them and says so in PLANNER_STATUS.
  logger_->warn("blocked passage, goal {}: ({:.2f}, {:.2f}) -> ({:.2f}, {:.2f}): {}", passage.goal_id,
                passage.from_x, passage.from_y, passage.to_x, passage.to_y, passage.reason);
  pending_blocked_passages_.push_back(toBlockedPassage(passage));
}

std::optional<PlannerJob> PlannerNode::takeJob(bool with_frame, bool planner_busy)
{
  const bool frame_ready = with_frame && latest_frame_.has_value();
  if (!frame_ready && !goal_changed_ && pending_affordances_.empty() && pending_blocked_passages_.empty()) {
    return std::nullopt;
  }
  if (planner_busy) {
    if (frame_ready) {
      ++dropped_frames_;
    }
    return std::nullopt;
  }
  PlannerJob job;
  if (frame_ready) {
    job.frame = std::move(latest_frame_);
    latest_frame_.reset();
  }
  job.new_goal = new_goal_;
  job.clear_goal = clear_goal_;
  job.affordances = std::move(pending_affordances_);
  job.blocked_passages = std::move(pending_blocked_passages_);
  pending_affordances_.clear();
  pending_blocked_passages_.clear();
  new_goal_.reset();
  clear_goal_ = false;
  goal_changed_ = false;
  return job;
}

PlannerTick PlannerNode::tick(std::int64_t now_us, bool planner_busy)
{
  PlannerTick tick;
  if (detector_utime_ && now_us - *detector_utime_ >
                             static_cast<std::int64_t>(std::llround(settings_.detector_max_age_s * 1e6))) {
    assembler_.setDetectorPolygons(std::nullopt);
    detector_utime_.reset();
  }
  if (!latest_frame_ && !goal_changed_ && published_ == 0) {
    planner_status_t waiting{};
    waiting.utime = now_us;
    waiting.state = planner_status_t::STATE_IDLE;
    waiting.bad_inputs = refusedInputs();
    waiting.message = "waiting for packets and poses";
    tick.waiting_status = std::move(waiting);
    return tick;
  }
  tick.job = takeJob(true, planner_busy);
  return tick;
}

std::optional<PlannerJob> PlannerNode::takeUpdateJob(bool planner_busy)
{
  return takeJob(false, planner_busy);
}

void PlannerNode::finish(PlannerOutputs& outputs)
{
  planner_status_t& status = outputs.status;
  status.bad_inputs += refusedInputs();
  if (dropped_frames_ > 0) {
    status.message += (status.message.empty() ? "" : "; ") + std::to_string(dropped_frames_) +
                      " frames dropped while the worker was busy";
  }
  if (status.message.find(kAffordanceRejected) != std::string::npos) {
    logger_->warn("{}: {}", settings_.channels.affordance, status.message);
  }
  if (status.message.find(kBlockedPassage) != std::string::npos) {
    logger_->info("{}: {}", settings_.channels.blocked_passage, status.message);
  }
  last_path_ = outputs.path;
  ++published_;
  logger_->debug("frame {}: {} vertices, {} edges, path {} ({:.2f} m), {:.1f} ms", status.frames,
                 status.num_vertices, status.num_edges, outputs.path.valid ? "valid" : "none",
                 outputs.path.length_m, status.total_ms);
}

std::optional<path_t> PlannerNode::resendPath(std::int64_t now_us)
{
  if (!last_path_) {
    return std::nullopt;
  }
  last_path_->utime = now_us;
  return last_path_;
}

std::string PlannerNode::healthProblem(std::int64_t now_us) const
{
  return silence_.problem(now_us);
}

}  // namespace ifar::planner
