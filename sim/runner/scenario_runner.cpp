#include "sim/runner/scenario_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "common/percentile.hpp"
#include "executive/modes/executive.hpp"
#include "planner/core/frame_assembler.hpp"
#include "sim/runner/path_conversion.hpp"

namespace ifar::runner {
namespace {

constexpr std::int64_t kGoalId = 1;
// A stop (not an e-stop) that lasts this long in simulated time ends the run: the executive halted and no
// new plan got it going again (a stale input in a lock-step run would be a bug, and ends the run too).
constexpr double kTerminalStopS = 3.0;
// Stand in for the planner's wall-clock budgets (per push search, per frame of interaction planning),
// which a deterministic run cannot use: the expansion limit still bounds each search.
constexpr double kUnlimitedSearchBudgetS = 1e9;
constexpr double kUnlimitedFrameBudgetMs = 1e12;
constexpr double kDegreesPerRadian = 57.29577951308232;

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::int64_t periodNanoseconds(double rate_hz)
{
  return std::llround(1e9 / rate_hz);
}

planner::PoseSample toPoseSample(std::int64_t utime, const geometry::Pose2& pose)
{
  planner::PoseSample sample;
  sample.utime = utime;
  sample.position = Eigen::Vector3d(pose.x, pose.y, 0.0);
  sample.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(pose.heading, Eigen::Vector3d::UnitZ()));
  return sample;
}

/// Keeps the newest revolution; the input flags of a superseded one carry over (as the planner daemon).
void keepLatest(std::optional<planner::FrameInput>& latest, planner::FrameInput frame)
{
  if (latest) {
    frame.flags |= latest->flags;
    if (!latest->problems.empty() && frame.problems.find(latest->problems) == std::string::npos) {
      frame.problems = latest->problems + (frame.problems.empty() ? "" : "; " + frame.problems);
    }
  }
  latest = std::move(frame);
}

FrameTimes frameTimes(const std::vector<double>& milliseconds)
{
  FrameTimes times;
  times.frames = milliseconds.size();
  if (!milliseconds.empty()) {
    times.median_ms = common::nearestRankPercentile(milliseconds, 50.0);
    times.p99_ms = common::nearestRankPercentile(milliseconds, 99.0);
    times.max_ms = *std::max_element(milliseconds.begin(), milliseconds.end());
  }
  return times;
}

/// Why the request cannot run, empty when it can.
std::string requestProblem(const RunRequest& request)
{
  if (!request.goal.allFinite()) {
    return "goal is not finite";
  }
  if (!(std::isfinite(request.planner_rate_hz) && request.planner_rate_hz > 0.0)) {
    return "planner_rate_hz must be a positive number";
  }
  if (!(std::isfinite(request.path_resend_hz) && request.path_resend_hz > 0.0)) {
    return "path_resend_hz must be a positive number";
  }
  if (!(std::isfinite(request.control_rate_hz) && request.control_rate_hz > 0.0)) {
    return "control_rate_hz must be a positive number";
  }
  if (!(std::isfinite(request.max_sim_time_s) && request.max_sim_time_s > 0.0)) {
    return "max_sim_time_s must be a positive number";
  }
  if (!(std::isfinite(request.simulator.physics.step_seconds) &&
        request.simulator.physics.step_seconds > 0.0)) {
    return "the physics step must be a positive number";
  }
  return {};
}

/// Everything one run owns; runScenario drives it step by step.
class Scenario {
 public:
  Scenario(const RunRequest& request, const std::function<void(const std::string&)>& progress,
           const FrameObserver& observe_frame);
  RunSummary run();

 private:
  void feedSensors(const sim::StepOutput& output);
  void planFrame(const sim::StepOutput& output);
  void applyAffordance(const executive::AffordanceEvent& event, std::int64_t utime);
  void applyBlockedPassage(const executive::BlockedPassage& passage, std::int64_t utime);
  void publishPath(const planner::FrameResult& result, std::int64_t utime);
  /// Obstacle points and the pushed object's observation from the executive's own lidar returns.
  void updateObstacleInputs(std::int64_t utime);
  /// One control cycle; true when the run ends (summary_.reason set).
  bool control(const sim::StepOutput& output);
  void report(const sim::StepOutput& output, const executive::Output& command) const;

  const RunRequest& request_;
  const std::function<void(const std::string&)>& progress_;
  const FrameObserver& observe_frame_;
  sim::Simulator simulator_;
  planner::FrameAssembler assembler_;
  planner::Planner planner_;
  executive::Executive executive_;
  executive::LocalObstacles obstacles_;
  executive::Inputs inputs_;
  std::optional<planner::FrameInput> latest_frame_;
  std::optional<executive::AffordanceEvent> pending_affordance_;
  std::optional<executive::BlockedPassage> pending_blocked_passage_;
  executive::Output last_output_;
  double force_sum_ = 0.0;
  int force_samples_ = 0;
  std::int64_t stopped_since_ns_ = -1;
  std::vector<double> frame_ms_;        // per planner frame, for summary_.planner_frame
  std::vector<double> interaction_ms_;  // ... and summary_.interaction
  RunSummary summary_;
};

planner::PlannerSettings runnerPlannerSettings(const RunRequest& request)
{
  planner::PlannerSettings settings = request.planner;
  settings.vehicle = request.vehicle;
  settings.interaction.search.time_budget_s = kUnlimitedSearchBudgetS;
  settings.interaction.loop.frame_budget_ms = kUnlimitedFrameBudgetMs;
  return settings;
}

Scenario::Scenario(const RunRequest& request, const std::function<void(const std::string&)>& progress,
                   const FrameObserver& observe_frame)
    : request_(request),
      progress_(progress),
      observe_frame_(observe_frame),
      simulator_(request.world, request.vehicle, request.simulator),
      assembler_(planner::InputSettings{}),
      planner_(runnerPlannerSettings(request)),
      executive_(request.executive, request.vehicle),
      obstacles_(request.obstacles, request.vehicle)
{
  if (request.known_map) {
    std::vector<geometry::Polygon> outlines;
    outlines.reserve(request.world.obstacles.size());
    for (const sim::StaticObstacle& obstacle : request.world.obstacles) {
      outlines.push_back(obstacle.outline);
    }
    planner_.rememberKnownObstacles(common::Span<const geometry::Polygon>(outlines.data(), outlines.size()));
  }
  planner_.setGoal(planner::Goal{kGoalId, request.goal});
  // The drives and their heartbeat are simulated as healthy for the whole run.
  inputs_.motor = executive::Stamped<executive::MotorReading>{{true, false, {}}, 0};
}

void Scenario::feedSensors(const sim::StepOutput& output)
{
  const geometry::Pose2& estimate = output.pose_estimate.pose;
  assembler_.addPose(toPoseSample(output.utime, estimate), output.utime);
  obstacles_.addPose(output.utime, estimate);
  for (const auto& packet : output.packets) {
    const common::ByteView payload(packet.data(), packet.size());
    assembler_.addPacket(payload, output.utime, output.utime);
    obstacles_.addPacket(payload, output.utime);
  }
  for (planner::FrameInput& frame : assembler_.takeFrames()) {
    keepLatest(latest_frame_, std::move(frame));
  }
  inputs_.pose = executive::Stamped<geometry::Pose2>{estimate, output.utime};
  force_sum_ += output.bumper_force_n;
  ++force_samples_;
}

void Scenario::publishPath(const planner::FrameResult& result, std::int64_t utime)
{
  inputs_.path = executive::Stamped<executive::Path>{
      toExecutivePath(result.path, planner_.graph(), utime, result.sequence), utime};
}

void Scenario::updateObstacleInputs(std::int64_t utime)
{
  // As the executive daemon does: stamped with the newest packet, so a silent lidar makes them stale.
  const std::int64_t newest = obstacles_.newestPacketUtime();
  if (newest == 0) {
    return;
  }
  inputs_.obstacles = executive::Stamped<std::vector<geometry::Point>>{obstacles_.points(utime), newest};
  const std::optional<executive::ObjectObservation> expected = executive_.pushedObjectEstimate();
  if (!expected) {
    return;
  }
  // The object's retro-reflective returns, searched from its last sighting, else where the plan expects it.
  geometry::Point near = expected->position;
  if (inputs_.pushed_object && inputs_.pushed_object->value.object_id == expected->object_id &&
      static_cast<double>(utime - inputs_.pushed_object->utime) <=
          request_.executive.stale.obstacles_s * 1e6) {
    near = inputs_.pushed_object->value.position;
  }
  if (const std::optional<geometry::Point> centroid =
          obstacles_.movableCentroid(near, request_.executive.pushed_object.radius_m, utime)) {
    inputs_.pushed_object =
        executive::Stamped<executive::ObjectObservation>{{expected->object_id, *centroid}, newest};
  }
}

void Scenario::planFrame(const sim::StepOutput& output)
{
  if (!latest_frame_) {
    return;
  }
  const planner::FrameResult result = planner_.processFrame(*latest_frame_);
  latest_frame_.reset();
  frame_ms_.push_back(result.status.timings.total_ms);
  interaction_ms_.push_back(result.status.timings.interaction_ms);
  publishPath(result, output.utime);
  if (observe_frame_) {
    observe_frame_(FrameView{static_cast<double>(output.time_ns) * 1e-9, planner_, result,
                             summary_.trajectory, output.objects});
  }
}

void Scenario::applyAffordance(const executive::AffordanceEvent& event, std::int64_t utime)
{
  planner::AffordanceUpdate update;
  update.object_id = event.object_id;
  update.pushable = event.pushable;
  update.push_force_n = event.push_force_n;
  update.affordance = event.affordance;
  ++summary_.affordance_updates;
  const planner::FrameResult result = planner_.applyAffordance(update);
  if (progress_) {
    progress_(fmt::format("affordance: {}; planner: {}", event.text, result.status.message));
  }
  publishPath(result, utime);
}

void Scenario::applyBlockedPassage(const executive::BlockedPassage& passage, std::int64_t utime)
{
  ++summary_.blocked_passages;
  const planner::FrameResult result = planner_.applyBlockedPassage({passage.from, passage.to});
  if (progress_) {
    progress_(fmt::format("blocked passage: {}; planner: {}", passage.text, result.status.message));
  }
  publishPath(result, utime);
}

void Scenario::report(const sim::StepOutput& output, const executive::Output& command) const
{
  if (!progress_) {
    return;
  }
  const geometry::Pose2& pose = output.vehicle.pose;
  progress_(fmt::format(
      "t={:.1f}s pos=({:.2f}, {:.2f}) heading={:.0f}deg mode={} target=({:.2f}, {:.2f}) goal={:.2f}m "
      "pushes={} replans={} affordance_updates={}: {}",
      static_cast<double>(output.time_ns) * 1e-9, pose.x, pose.y, pose.heading * kDegreesPerRadian,
      executive::modeName(command.status.mode), command.status.target.x(), command.status.target.y(),
      (pose.position() - request_.goal).norm(), command.status.pushes, command.status.replans,
      summary_.affordance_updates, command.status.reason));
}

bool Scenario::control(const sim::StepOutput& output)
{
  const std::int64_t now = output.utime;
  inputs_.force = executive::Stamped<executive::ForceReading>{
      {force_samples_ > 0 ? force_sum_ / force_samples_ : output.bumper_force_n, false}, now};
  force_sum_ = 0.0;
  force_samples_ = 0;
  inputs_.motor->utime = now;
  updateObstacleInputs(now);

  const executive::Output result = executive_.step(now, inputs_);
  simulator_.setVelocityCommand(result.command.linear, result.command.angular);
  if (result.affordance) {
    pending_affordance_ = result.affordance;  // applied on the next physics step: the replan comes after it
  }
  if (result.blocked_passage) {
    pending_blocked_passage_ = result.blocked_passage;
  }
  last_output_ = result;
  summary_.trajectory.push_back(output.vehicle.pose);
  summary_.pushes = result.status.pushes;
  summary_.replans = result.status.replans;

  const double goal_distance = (output.vehicle.pose.position() - request_.goal).norm();
  if (result.status.mode == executive::Mode::Arrived || goal_distance <= request_.planner.arrival_radius_m) {
    summary_.arrived = true;
    summary_.reason = "arrived";
    return true;
  }
  if (result.status.mode == executive::Mode::Stop) {
    if (stopped_since_ns_ < 0) {
      stopped_since_ns_ = output.time_ns;
    } else if (static_cast<double>(output.time_ns - stopped_since_ns_) * 1e-9 >= kTerminalStopS) {
      summary_.reason = "stopped: " + result.status.reason;
      return true;
    }
  } else {
    stopped_since_ns_ = -1;
  }
  return false;
}

RunSummary Scenario::run()
{
  const std::int64_t physics_ns = std::llround(request_.simulator.physics.step_seconds * 1e9);
  const std::int64_t control_ns = periodNanoseconds(request_.control_rate_hz);
  const std::int64_t planner_ns = periodNanoseconds(request_.planner_rate_hz);
  const std::int64_t end_ns = std::llround(request_.max_sim_time_s * 1e9);
  std::int64_t next_control_ns = control_ns;
  std::int64_t next_planner_ns = planner_ns;
  const std::int64_t resend_ns = periodNanoseconds(request_.path_resend_hz);
  std::int64_t next_resend_ns = resend_ns;
  std::int64_t next_report_ns = 1'000'000'000;
  geometry::Pose2 previous = request_.world.start;
  sim::StepOutput output;
  bool ended = false;
  while (!ended) {
    output = simulator_.step(static_cast<double>(physics_ns) * 1e-9);
    summary_.distance_m += (output.vehicle.pose.position() - previous.position()).norm();
    previous = output.vehicle.pose;
    feedSensors(output);
    if (pending_affordance_) {
      applyAffordance(*pending_affordance_, output.utime);
      pending_affordance_.reset();
    }
    if (pending_blocked_passage_) {
      applyBlockedPassage(*pending_blocked_passage_, output.utime);
      pending_blocked_passage_.reset();
    }
    if (output.time_ns >= next_planner_ns) {
      planFrame(output);
      next_planner_ns += planner_ns;
    }
    if (output.time_ns >= next_resend_ns) {
      if (inputs_.path) {
        inputs_.path->utime = output.utime;  // the same plan, received again
      }
      next_resend_ns += resend_ns;
    }
    if (output.time_ns >= next_control_ns) {
      ended = control(output);
      next_control_ns += control_ns;
    }
    if (output.time_ns >= next_report_ns) {
      report(output, last_output_);
      next_report_ns += 1'000'000'000;
    }
    if (!ended && output.time_ns >= end_ns) {
      summary_.reason = fmt::format("timeout after {:g} s of simulated time ({})", request_.max_sim_time_s,
                                    last_output_.status.reason);
      ended = true;
    }
  }
  summary_.sim_time_s = static_cast<double>(output.time_ns) * 1e-9;
  summary_.goal_distance_m = (output.vehicle.pose.position() - request_.goal).norm();
  summary_.planner_frame = frameTimes(frame_ms_);
  summary_.interaction = frameTimes(interaction_ms_);
  for (const auto& object : output.objects) {
    summary_.final_objects.push_back(object.pose);
  }
  return summary_;
}

}  // namespace

RunSummary runScenario(const RunRequest& request, const std::function<void(const std::string&)>& progress,
                       const FrameObserver& observe_frame)
{
  const auto started = std::chrono::steady_clock::now();
  RunSummary summary;
  std::string problem = requestProblem(request);
  std::unique_ptr<Scenario> scenario;
  if (problem.empty()) {
    try {
      scenario = std::make_unique<Scenario>(request, progress, observe_frame);
    } catch (const std::invalid_argument& error) {
      // The simulator or the executive refused the world or the vehicle.
      problem = error.what();
    }
  }
  if (scenario) {
    try {
      summary = scenario->run();
    } catch (const std::exception& error) {
      // A library failure ends the run as not arrived, with the reason, instead of the process.
      summary = RunSummary{};
      summary.reason = std::string("failed: ") + error.what();
      summary.goal_distance_m = (request.world.start.position() - request.goal).norm();
    }
  }
  if (!problem.empty()) {
    summary = RunSummary{};
    summary.reason = "bad request: " + problem;
    summary.goal_distance_m = (request.world.start.position() - request.goal).norm();
  }
  summary.wall_time_s = secondsSince(started);
  return summary;
}

}  // namespace ifar::runner
