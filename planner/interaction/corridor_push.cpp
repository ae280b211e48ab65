#include "planner/interaction/corridor_push.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "planner/interaction/body_frame.hpp"
#include "planner/interaction/convex_polygon.hpp"
#include "planner/interaction/free_space_raster.hpp"
#include "planner/interaction/ring_stretches.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;
using geometry::Pose2;

namespace {

/// How far apart the way on is judged before refining: each judgement rasterises the object's
/// surroundings, and a push tens of metres long judged at every collision step would take tens of
/// milliseconds more.
constexpr double kCorridorJudgementStepM = 1.0;

}  // namespace

struct CorridorPush::Judgements {
  const SearchDeadline& deadline;
  std::size_t made = 0;
  std::optional<PlanStatus> stopped;  ///< ExpansionLimit or TimeBudget once the deadline ran out
};

CorridorPush::CorridorPush(const PushObject& object, const PushCollisionChecker& checker,
                           const PushGoalTest& goal_test, const SearchSettings& search,
                           const ConnectivitySettings& limits)
    : object_(object),
      checker_(checker),
      goal_test_(goal_test),
      search_(search),
      assembler_(object, search),
      junction_margin_m_(surroundingsReach(limits, search) - search.search_radius_m)
{
}

PushPlan CorridorPush::solve(const PushProblem& problem, const SearchDeadline& deadline) const
{
  PushPlan plan = assembler_.unplanned(PlanStatus::Exhausted);
  Judgements judgements{deadline, 0, std::nullopt};
  double best_cost = std::numeric_limits<double>::infinity();
  for (const PushContact& contact : problem.contacts) {
    const EdgePushOptions& option = object_.edgeOptions()[contact.edge];
    if (!option.straight) {
      continue;
    }
    const int last = freeSteps(contact.edge, problem.depth_side);
    const int first_open = firstOpenStep(contact.edge, last, problem, judgements);
    if (judgements.stopped) {
      plan = assembler_.unplanned(*judgements.stopped);
      break;
    }
    if (first_open == 0) {
      continue;
    }
    const double distance = first_open * search_.collision_step_m;
    const double cost = contact.approach_m + option.straight_force_n * distance / search_.reference_force_n;
    if (cost >= best_cost) {
      continue;
    }
    best_cost = cost;
    assembler_.complete(plan, contact.edge, contact.approach_m,
                        {assembler_.control(ControlKind::Straight, contact.edge, distance,
                                            std::numeric_limits<double>::infinity(), option.straight_force_n,
                                            poseAt(contact.edge, first_open))});
  }
  plan.expansions = judgements.made;
  plan.planning_time_s = deadline.elapsedSeconds();
  return plan;
}

Pose2 CorridorPush::poseAt(std::size_t edge, int step) const
{
  return object_.pushedStraight(object_.model().pose, edge, step * search_.collision_step_m);
}

int CorridorPush::freeSteps(std::size_t edge, std::size_t depth_side) const
{
  const int steps = static_cast<int>(std::floor(search_.search_radius_m / search_.collision_step_m));
  int last = 0;
  while (last < steps && !checker_.objectCollides(poseAt(edge, last), poseAt(edge, last + 1), depth_side)) {
    ++last;
  }
  return last;
}

int CorridorPush::firstOpenStep(std::size_t edge, int last, const PushProblem& problem,
                                Judgements& judgements) const
{
  const int stride =
      std::max(1, static_cast<int>(std::lround(kCorridorJudgementStepM / search_.collision_step_m)));
  for (int probe = stride; probe < last + stride; probe += stride) {
    const int step = std::min(probe, last);
    if (opens(edge, step, problem, judgements)) {
      int first_open = step;
      while (first_open > 1 && first_open > step - stride + 1 &&
             opens(edge, first_open - 1, problem, judgements)) {
        --first_open;
      }
      return first_open;
    }
    if (judgements.stopped) {
      break;
    }
  }
  return 0;
}

bool CorridorPush::opens(std::size_t edge, int step, const PushProblem& problem, Judgements& judgements) const
{
  const Pose2 pose = poseAt(edge, step);
  if (!goal_test_.passageClear(pose, problem.goal_region)) {
    return false;
  }
  if (judgements.deadline.outOfExpansions(judgements.made)) {
    judgements.stopped = PlanStatus::ExpansionLimit;
  } else if (judgements.deadline.outOfTime()) {
    judgements.stopped = PlanStatus::TimeBudget;
  }
  if (judgements.stopped) {
    return false;
  }
  ++judgements.made;
  return wayOnBeyond(pose, edge);
}

bool CorridorPush::wayOnBeyond(const Pose2& pose, std::size_t edge) const
{
  const Polygon footprint = transformed(object_.model().footprint, pose);
  Bounds window = boundsOf(footprint);
  window.minimum -= Point::Constant(junction_margin_m_);
  window.maximum += Point::Constant(junction_margin_m_);
  FreeSpaceRaster raster(window, PushGoalTest::kRasterResolutionM);
  checker_.rasterise(raster, window);
  raster.mark(raster.cellsNear(footprint, goal_test_.objectClearance()), FreeSpaceRaster::kMovable);
  int components = 0;
  const std::vector<int> labels =
      raster.labelComponents(FreeSpaceRaster::kObstacle | FreeSpaceRaster::kMovable, components);
  const auto behind = raster.nearestLabelled(pose.transform(object_.standingPoint(edge)), labels,
                                             goal_test_.waypointSearchCells());
  const std::vector<std::size_t> ring = raster.borderCells();
  if (!behind || ring.empty()) {
    return false;
  }
  const auto reached = [&](std::size_t cell) { return labels[cell] == labels[*behind]; };
  if (std::all_of(ring.begin(), ring.end(), reached)) {
    return true;  // the object stands in the open
  }
  int stretches = 0;
  ringStretches(ring, reached, stretches);
  return stretches >= 2;
}

}  // namespace ifar::interaction
