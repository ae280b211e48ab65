#include "planner/interaction/push_search.hpp"

#include "planner/interaction/corridor_push.hpp"
#include "planner/interaction/hybrid_astar_push.hpp"
#include "planner/interaction/push_plan_assembler.hpp"

namespace ifar::interaction {

PushPlanner::PushPlanner(const PushProblemObject& problem, const PusherSettings& pusher,
                         const SearchSettings& search, const ConnectivitySettings& limits)
    : search_(search), object_(problem, pusher, search, limits)
{
  if (object_.status() != PlanStatus::Found) {
    return;
  }
  checker_.emplace(problem, object_, pusher, search, limits);
  // The corridor push judges the way on round each pushed pose itself.
  goal_test_.emplace(problem, object_, *checker_, pusher, search, limits, !search.corridor);
  if (search.corridor) {
    strategy_ = std::make_unique<CorridorPush>(object_, *checker_, *goal_test_, search, limits);
  } else {
    strategy_ = std::make_unique<HybridAStarPush>(object_, *checker_, *goal_test_, search);
  }
}

PushPlanner::~PushPlanner() = default;

PushProblemResult PushPlanner::problem(const geometry::Point& start, const geometry::Point& goal) const
{
  if (object_.status() != PlanStatus::Found) {
    return PushProblemResult{object_.status(), {}};
  }
  return makePushProblem(object_, *checker_, *goal_test_, start, goal);
}

PushPlan PushPlanner::plan(const geometry::Point& start, const geometry::Point& goal) const
{
  const auto started = SearchDeadline::Clock::now();
  const PushProblemResult posed = problem(start, goal);
  if (posed.status != PlanStatus::Found) {
    return PushPlanAssembler(object_, search_).unplanned(posed.status);
  }
  const SearchDeadline deadline =
      search_.corridor ? SearchDeadline::unlimited(started)
                       : SearchDeadline(started, search_.time_budget_s, search_.max_expansions);
  return strategy_->solve(posed.problem, deadline);
}

}  // namespace ifar::interaction
