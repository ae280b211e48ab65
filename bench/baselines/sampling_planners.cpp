#include "bench/baselines/sampling_planners.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>
#include <ompl/util/RandomNumbers.h>

#include "bench/baselines/cpu_clock.hpp"

namespace ifar::baselines {

namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using Clock = std::chrono::steady_clock;

geometry::Point toPoint(const ob::State* state)
{
  const auto* values = state->as<ob::RealVectorStateSpace::StateType>();
  return geometry::Point(values->values[0], values->values[1]);
}

// Tests the straight segment exactly instead of sampling states along it.
class ExactMotionValidator : public ob::MotionValidator {
 public:
  ExactMotionValidator(const ob::SpaceInformationPtr& information, const graph::ObstacleSet& obstacles)
      : ob::MotionValidator(information), obstacles_(obstacles)
  {
  }

  bool checkMotion(const ob::State* from, const ob::State* to) const override
  {
    const bool valid = si_->isValid(to) && obstacles_.visible(toPoint(from), toPoint(to));
    (valid ? valid_ : invalid_)++;
    return valid;
  }

  // Planners that want the last valid state get the start (fraction 0): a conservative answer that
  // neither RRT* nor BIT* relies on for correctness.
  bool checkMotion(const ob::State* from, const ob::State* to,
                   std::pair<ob::State*, double>& last_valid) const override
  {
    const bool valid = checkMotion(from, to);
    if (!valid) {
      if (last_valid.first != nullptr) {
        si_->copyState(last_valid.first, from);
      }
      last_valid.second = 0.0;
    }
    return valid;
  }

 private:
  const graph::ObstacleSet& obstacles_;
};

BaselineResult failure(BaselineStatus status, std::string reason)
{
  BaselineResult result;
  result.status = status;
  result.length = std::numeric_limits<double>::quiet_NaN();
  result.reason = std::move(reason);
  return result;
}

}  // namespace

const char* toString(SamplingAlgorithm algorithm)
{
  return algorithm == SamplingAlgorithm::RrtStar ? "rrt_star" : "bit_star";
}

void seedSamplingPlanners(std::uint64_t seed)
{
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed));
}

BaselineResult planSampling(SamplingAlgorithm algorithm, const graph::ObstacleSet& obstacles,
                            const geometry::Point& start, const geometry::Point& goal, double optimal_length,
                            const SamplingSettings& settings)
{
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  if (!obstacles.bounds()) {
    return failure(BaselineStatus::Error, "obstacle set has no bounds: sampling needs a bounded map");
  }
  if (!std::isfinite(start.x()) || !std::isfinite(start.y()) || obstacles.isBlocked(start)) {
    return failure(BaselineStatus::InvalidStart, "start is blocked, off the map or not finite");
  }
  if (!std::isfinite(goal.x()) || !std::isfinite(goal.y()) || obstacles.isBlocked(goal)) {
    return failure(BaselineStatus::InvalidGoal, "goal is blocked, off the map or not finite");
  }
  const auto began = Clock::now();
  const double began_cpu = threadCpuMilliseconds();
  const graph::Bounds& bounds = *obstacles.bounds();
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds space_bounds(2);
  space_bounds.setLow(0, bounds.min.x());
  space_bounds.setLow(1, bounds.min.y());
  space_bounds.setHigh(0, bounds.max.x());
  space_bounds.setHigh(1, bounds.max.y());
  space->setBounds(space_bounds);

  auto information = std::make_shared<ob::SpaceInformation>(space);
  information->setStateValidityChecker(
      [&obstacles](const ob::State* state) { return !obstacles.isBlocked(toPoint(state)); });
  information->setMotionValidator(std::make_shared<ExactMotionValidator>(information, obstacles));
  information->setup();

  ob::ScopedState<ob::RealVectorStateSpace> start_state(space);
  start_state[0] = start.x();
  start_state[1] = start.y();
  ob::ScopedState<ob::RealVectorStateSpace> goal_state(space);
  goal_state[0] = goal.x();
  goal_state[1] = goal.y();
  auto problem = std::make_shared<ob::ProblemDefinition>(information);
  problem->setStartAndGoalStates(start_state, goal_state, 1e-6);

  const bool have_optimum = std::isfinite(optimal_length) && optimal_length > 0.0;
  const double target =
      have_optimum ? settings.optimum_factor * optimal_length : std::numeric_limits<double>::infinity();
  auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(information);
  objective->setCostThreshold(ob::Cost(target));
  problem->setOptimizationObjective(objective);

  // Record when the target cost is first met, so the reported time does not include the planner's
  // wind-down after the termination condition fires.
  std::atomic<bool> target_met{false};
  double target_milliseconds = 0.0;
  problem->setIntermediateSolutionCallback(
      [&](const ob::Planner*, const std::vector<const ob::State*>&, const ob::Cost cost) {
        if (!target_met.load() && cost.value() <= target) {
          target_milliseconds = threadCpuMilliseconds() - began_cpu;
          target_met.store(true);
        }
      });

  ob::PlannerPtr planner;
  if (algorithm == SamplingAlgorithm::RrtStar) {
    auto rrt = std::make_shared<og::RRTstar>(information);
    if (settings.range_m > 0.0) {
      rrt->setRange(settings.range_m);
    }
    rrt->setGoalBias(settings.goal_bias);
    planner = rrt;
  } else {
    planner = std::make_shared<og::BITstar>(information);
  }
  planner->setProblemDefinition(problem);

  // The cap counts this thread's CPU time (RRT* and BIT* plan in the calling thread), so a loaded
  // machine does not turn slow queries into timeouts; a wall-clock cap of 20x bounds a stalled run.
  const double cap_milliseconds = settings.time_cap_s * 1e3;
  const auto wall_deadline = began + std::chrono::duration_cast<Clock::duration>(
                                         std::chrono::duration<double>(20.0 * settings.time_cap_s));
  const ob::PlannerTerminationCondition stop([&] {
    return target_met.load() || threadCpuMilliseconds() - began_cpu >= cap_milliseconds ||
           Clock::now() >= wall_deadline;
  });
  // OMPL reports setup problems by throwing; here they become a recorded Error with OMPL's message.
  ob::PlannerStatus status;
  try {
    planner->setup();
    status = planner->solve(stop);
  } catch (const ompl::Exception& error) {
    return failure(BaselineStatus::Error, std::string("OMPL: ") + error.what());
  }
  const double total_milliseconds = threadCpuMilliseconds() - began_cpu;
  const double wall_milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - began).count();

  BaselineResult result;
  result.length = std::numeric_limits<double>::quiet_NaN();
  result.wall_milliseconds = wall_milliseconds;
  if (status == ob::PlannerStatus::EXACT_SOLUTION && problem->hasExactSolution()) {
    const auto* path = problem->getSolutionPath()->as<og::PathGeometric>();
    result.length = path->length();
    for (std::size_t index = 0; index < path->getStateCount(); ++index) {
      result.path.push_back(toPoint(path->getState(index)));
    }
  }
  const bool within = std::isfinite(result.length) && result.length <= target * (1.0 + 1e-9);
  if (within) {
    result.status = BaselineStatus::Solved;
    result.milliseconds = target_met.load() ? target_milliseconds : total_milliseconds;
    return result;
  }
  result.status = BaselineStatus::Timeout;
  result.milliseconds = total_milliseconds;
  if (std::isfinite(result.length)) {
    result.reason = "time cap " + std::to_string(settings.time_cap_s) + " s CPU: best length " +
                    std::to_string(result.length) + " above target " + std::to_string(target);
  } else {
    result.reason = "time cap " + std::to_string(settings.time_cap_s) + " s CPU: no path found (" +
                    status.asString() + ")";
  }
  return result;
}

}  // namespace ifar::baselines
