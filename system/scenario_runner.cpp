#include "system/scenario_runner.hpp"

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

#include "executive/modes/mode.hpp"
#include "system/achievable_map.hpp"
#include "system/run_trace.hpp"
#include "system/saturated_push_watch.hpp"
#include "system/simulated_stack.hpp"

namespace ifar::runner {
namespace {

// A stop (not an e-stop) that lasts this long in simulated time ends the run: the executive halted and no
// new plan got it going again.
constexpr double kTerminalStopS = 3.0;
constexpr double kDegreesPerRadian = 57.29577951308232;
constexpr std::int64_t kReportPeriodUs = 1'000'000;

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Why the request cannot run, empty when it can.
std::string requestProblem(const RunRequest& request)
{
  if (!request.goal.allFinite()) {
    return "goal is not finite";
  }
  for (std::size_t index = 0; index < request.further_goals.size(); ++index) {
    if (!request.further_goals[index].allFinite()) {
      return fmt::format("goal {} is not finite", index + 2);
    }
  }
  if (!(std::isfinite(request.planner_node.rate_hz) && request.planner_node.rate_hz > 0.0)) {
    return "the planner's rate_hz must be a positive number";
  }
  if (!(std::isfinite(request.planner_node.path_resend_hz) && request.planner_node.path_resend_hz > 0.0)) {
    return "the planner's path_resend_hz must be a positive number";
  }
  if (!(std::isfinite(request.max_sim_time_s) && request.max_sim_time_s > 0.0)) {
    return "max_sim_time_s must be a positive number";
  }
  if (!(std::isfinite(request.sim.simulator.physics.step_seconds) &&
        request.sim.simulator.physics.step_seconds > 0.0)) {
    return "the physics step must be a positive number";
  }
  if (request.motor.cycle_us <= 0) {
    return "the motor cycle must be a positive number";
  }
  return {};
}

/// The watch for pushes at maximum force that the executive leaves undecided: the executive's own
/// notion of maximum force (fraction of the traction limit, capped by the sensor's range) and its window.
SaturatedPushWatch saturatedPushWatch(const RunRequest& request)
{
  const executive::TactileSettings& tactile = request.executive.tactile;
  const double max_force_n = std::min(request.vehicle.maxPushForce(), request.vehicle.force_sensor_range_n);
  return SaturatedPushWatch(tactile.max_force_fraction * max_force_n,
                            tactile.no_motion_time_s + kDecisionAllowanceS);
}

/// One run: the stack, and what the summary needs from it.
class Scenario {
 public:
  Scenario(const RunRequest& request, const std::function<void(const std::string&)>& progress,
           const FrameObserver& observe_frame);
  /// Starts recording to request.log_path; the reason when it cannot.
  std::string startLog();
  RunSummary run();

 private:
  void simulatorStepped(const sim::SimulatorStep& step);
  void plannerFinished(const planner::PlannerJob& job, const planner::PlannerJobResult& finished,
                       std::int64_t now_us);
  void executiveCycled(const executive::ExecutiveOutputs& outputs, std::int64_t now_us);
  void report(std::int64_t now_us) const;
  /// Ends the goal in hand (arrived or not) as a leg of the summary, with its loss account.
  void closeLeg(bool arrived, std::int64_t now_us);
  /// The loss account of a leg driven toward `goal` (invalid when not asked for).
  LossAccount accountLosses(const RunTrace& trace, const geometry::Point& goal);
  /// Sums the legs' accounts into summary_.losses.
  void addUpLosses();
  double simulatedSeconds(std::int64_t now_us) const;

  const RunRequest& request_;
  const std::function<void(const std::string&)>& progress_;
  const FrameObserver& observe_frame_;
  std::int64_t epoch_us_;
  SimulatedStack stack_;
  geometry::Pose2 vehicle_;  // ground truth after the last step
  std::vector<sim::physics::BodyState> objects_;
  executive::Status last_status_;
  std::vector<std::string>
      findings_;  // the executive's AFFORDANCE and BLOCKED_PASSAGE texts not yet answered
  std::int64_t stopped_since_us_ = -1;
  std::string planner_no_path_;  // the planner's status message while it has no path
  bool ended_ = false;
  SaturatedPushWatch saturated_pushes_;
  PlannerFrameRecord frames_;  // each planner frame's stage times, for summary_'s
  RunTraceRecorder trace_;     // of the leg in hand
  // The goal in hand: its index (0: request.goal, then request.further_goals), where it is, and where
  // its leg began.
  std::size_t goal_index_ = 0;
  geometry::Point goal_;
  double leg_start_distance_m_ = 0.0;
  std::int64_t leg_start_us_ = 0;
  std::optional<PlanningGraph> achievable_;  // built for the first leg's account
  RunSummary summary_;
};

Scenario::Scenario(const RunRequest& request, const std::function<void(const std::string&)>& progress,
                   const FrameObserver& observe_frame)
    : request_(request),
      progress_(progress),
      observe_frame_(observe_frame),
      epoch_us_(request.sim.simulator.epoch_utime),
      stack_(request,
             StackObservers{[this](const sim::SimulatorStep& step) { simulatorStepped(step); },
                            [this](const planner::PlannerJob& job, const planner::PlannerJobResult& finished,
                                   std::int64_t now_us) { plannerFinished(job, finished, now_us); },
                            [this](const executive::ExecutiveOutputs& outputs, std::int64_t now_us) {
                              executiveCycled(outputs, now_us);
                            }}),
      vehicle_(request.world.start),
      saturated_pushes_(saturatedPushWatch(request)),
      goal_(request.goal),
      leg_start_us_(epoch_us_)
{
}

std::string Scenario::startLog()
{
  return request_.log_path.empty() ? std::string() : stack_.recordTo(request_.log_path);
}

double Scenario::simulatedSeconds(std::int64_t now_us) const
{
  return static_cast<double>(now_us - epoch_us_) * 1e-6;
}

void Scenario::simulatorStepped(const sim::SimulatorStep& step)
{
  summary_.distance_m += (step.output.vehicle.pose.position() - vehicle_.position()).norm();
  vehicle_ = step.output.vehicle.pose;
  trace_.position(vehicle_.position());
  objects_ = step.output.objects;
  saturated_pushes_.force(step.output.utime, step.output.bumper_force_n);
}

void Scenario::plannerFinished(const planner::PlannerJob& job, const planner::PlannerJobResult& finished,
                               std::int64_t now_us)
{
  const planner::FrameResult& result = finished.result;
  if (result.path.valid) {
    std::vector<geometry::Point> polyline;
    polyline.reserve(result.path.waypoints.size());
    for (const graph::PathPoint& waypoint : result.path.waypoints) {
      polyline.push_back(waypoint.position);
    }
    const std::optional<graph::ObstacleSet>& obstacles = stack_.planner().observedObstacles();
    WayOpen way_open;
    if (obstacles) {
      way_open = [&obstacles](const geometry::Point& from, const geometry::Point& to) {
        return obstacles->visible(from, to);
      };
    }
    trace_.plannedPath(std::move(polyline), vehicle_.position(), way_open);
  }
  if (!job.affordances.empty() || !job.blocked_passages.empty()) {
    // What the executive found and what the planner made of it, on one line.
    for (const std::string& finding : findings_) {
      if (progress_) {
        progress_(finding + "; planner: " + result.status.message);
      }
    }
    findings_.clear();
  }
  // Why the planner has no path, while it has none: the run's reason says so if it ends that way.
  if (result.status.state == planner::PlannerState::NoPath) {
    planner_no_path_ = result.status.message;
  } else if (result.path.valid) {
    planner_no_path_.clear();
  }
  if (!job.frame) {
    return;
  }
  frames_.add(result.status.timings);
  if (observe_frame_) {
    observe_frame_(
        FrameView{simulatedSeconds(now_us), stack_.planner(), result, summary_.trajectory, objects_});
  }
}

void Scenario::executiveCycled(const executive::ExecutiveOutputs& outputs, std::int64_t now_us)
{
  const executive::Output& result = outputs.output;
  last_status_ = result.status;
  summary_.trajectory.push_back(vehicle_);
  summary_.pushes = result.status.pushes;
  summary_.replans = result.status.replans;
  if (result.affordance) {
    ++summary_.affordance_updates;
    saturated_pushes_.decided(now_us);
    findings_.push_back("affordance: " + result.affordance->text);
  }
  if (result.escalation) {
    ++summary_.escalations;
    findings_.push_back(*result.escalation);
  }
  if (result.blocked_passage) {
    ++summary_.blocked_passages;
    findings_.push_back("blocked passage: " + result.blocked_passage->text);
  }
  const bool found_harder =
      result.blocked_passage.has_value() ||
      (result.affordance && result.affordance->reason != executive::AffordanceReason::CostLower);
  trace_.executiveCycle(
      ExecutiveCycle{result.status.mode, result.status.target_object_id, result.status.pushes, found_harder});
  const double goal_distance = (vehicle_.position() - goal_).norm();
  const std::int64_t goal_id = SimulatedStack::kFirstGoalId + static_cast<std::int64_t>(goal_index_);
  const bool at_goal = (result.status.mode == executive::Mode::Arrived && result.status.goal_id == goal_id) ||
                       goal_distance <= request_.planner.arrival_radius_m;
  if (at_goal) {
    closeLeg(true, now_us);
    if (goal_index_ < request_.further_goals.size()) {
      // On to the next goal, as an operator would send it.
      goal_ = request_.further_goals[goal_index_];
      ++goal_index_;
      stack_.sendGoal(goal_, goal_id + 1);
      stopped_since_us_ = -1;
      if (progress_) {
        progress_(fmt::format("goal {} of {} reached; on to ({:.2f}, {:.2f})", goal_index_,
                              request_.further_goals.size() + 1, goal_.x(), goal_.y()));
      }
      return;
    }
    summary_.arrived = true;
    summary_.reason = "arrived";
    ended_ = true;
    return;
  }
  if (result.status.mode != executive::Mode::Stop) {
    stopped_since_us_ = -1;
  } else if (stopped_since_us_ < 0) {
    stopped_since_us_ = now_us;
  } else if (static_cast<double>(now_us - stopped_since_us_) * 1e-6 >= kTerminalStopS) {
    summary_.reason = "stopped: " + result.status.reason;
    ended_ = true;
  }
}

void Scenario::report(std::int64_t now_us) const
{
  if (!progress_) {
    return;
  }
  progress_(fmt::format(
      "t={:.1f}s pos=({:.2f}, {:.2f}) heading={:.0f}deg mode={} target=({:.2f}, {:.2f}) goal={:.2f}m "
      "pushes={} replans={} affordance_updates={}: {}",
      simulatedSeconds(now_us), vehicle_.x, vehicle_.y, vehicle_.heading * kDegreesPerRadian,
      executive::modeName(last_status_.mode), last_status_.target.x(), last_status_.target.y(),
      (vehicle_.position() - goal_).norm(), last_status_.pushes, last_status_.replans,
      summary_.affordance_updates, last_status_.reason));
}

void Scenario::closeLeg(bool arrived, std::int64_t now_us)
{
  const RunTrace trace = trace_.finish();
  trace_ = RunTraceRecorder();
  trace_.position(vehicle_.position());  // the next leg starts where this one ended
  summary_.routes += static_cast<int>(trace.routes.size());
  summary_.routes_switched +=
      static_cast<int>(std::count_if(trace.routes.begin(), trace.routes.end(), [](const TraceRoute& route) {
        return route.end == RouteEnd::Switched;
      }));
  GoalLeg leg;
  leg.goal = goal_;
  leg.arrived = arrived;
  leg.distance_m = summary_.distance_m - leg_start_distance_m_;
  leg.sim_time_s = static_cast<double>(now_us - leg_start_us_) * 1e-6;
  leg.losses = accountLosses(trace, goal_);
  summary_.legs.push_back(std::move(leg));
  leg_start_distance_m_ = summary_.distance_m;
  leg_start_us_ = now_us;
}

LossAccount Scenario::accountLosses(const RunTrace& trace, const geometry::Point& goal)
{
  if (!request_.account_losses) {
    return {};
  }
  if (!achievable_) {
    AchievableMapSettings settings;
    settings.inflation_m = 0.5 * request_.vehicle.width_m;
    achievable_ = buildAchievableMap(request_.world, request_.vehicle, settings);
  }
  graph::SearchScratch scratch;
  return runner::accountLosses(trace, [&](const geometry::Point& from) {
    return achievableDistance(*achievable_, from, goal, scratch);
  });
}

void Scenario::addUpLosses()
{
  if (summary_.legs.size() == 1) {
    summary_.losses = summary_.legs.front().losses;
    return;
  }
  LossAccount total;
  total.valid = !summary_.legs.empty();
  total.achievable_m = 0.0;
  total.remaining_m = 0.0;
  total.excess_m = 0.0;
  for (const GoalLeg& leg : summary_.legs) {
    if (!leg.losses.valid) {
      total = LossAccount{};
      total.problem = leg.losses.problem.empty() ? "a leg was not accounted" : leg.losses.problem;
      break;
    }
    total.travelled_m += leg.losses.travelled_m;
    total.achievable_m += leg.losses.achievable_m;
    total.remaining_m += leg.losses.remaining_m;
    total.excess_m += leg.losses.excess_m;
    for (int bucket = 0; bucket < kLossBucketCount; ++bucket) {
      lossBucket(total.buckets, bucket) += lossBucket(leg.losses.buckets, bucket);
    }
  }
  summary_.losses = total;
}

RunSummary Scenario::run()
{
  const std::int64_t end_us = epoch_us_ + std::llround(request_.max_sim_time_s * 1e6);
  std::int64_t next_report_us = epoch_us_ + kReportPeriodUs;
  std::int64_t now_us = epoch_us_;
  while (!ended_) {
    stack_.step();
    now_us = stack_.nowUtime();
    if (now_us >= next_report_us) {
      report(now_us);
      next_report_us += kReportPeriodUs;
    }
    if (!ended_ && now_us >= end_us) {
      summary_.reason = fmt::format("timeout after {:g} s of simulated time ({})", request_.max_sim_time_s,
                                    last_status_.reason);
      ended_ = true;
    }
  }
  stack_.flush();
  if (!summary_.arrived && !planner_no_path_.empty()) {
    summary_.reason += "; planner: " + planner_no_path_;
  }
  if (!stack_.recordingError().empty() && progress_) {
    progress_("log: " + stack_.recordingError());
  }
  summary_.sim_time_s = simulatedSeconds(now_us);
  summary_.goal_distance_m = (vehicle_.position() - goal_).norm();
  summary_.planner_frame = frames_.total();
  summary_.interaction = frames_.interaction();
  summary_.stages = frames_.stages();
  summary_.undecided_saturated_pushes = saturated_pushes_.undecided();
  summary_.longest_saturated_push_s = saturated_pushes_.longestUndecidedSeconds();
  for (const auto& object : objects_) {
    summary_.final_objects.push_back(object.pose);
  }
  if (!summary_.arrived) {
    closeLeg(false, now_us);
  }
  addUpLosses();
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
      problem = scenario->startLog();
    } catch (const std::invalid_argument& error) {
      // The simulator or the executive refused the world or the vehicle.
      problem = error.what();
    }
  }
  if (scenario && problem.empty()) {
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
