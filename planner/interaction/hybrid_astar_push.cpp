#include "planner/interaction/hybrid_astar_push.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "common/geometry/angle.hpp"
#include "planner/interaction/hybrid_astar.hpp"

namespace ifar::interaction {

using geometry::Pose2;

namespace {

struct PushState {
  Pose2 pose;  ///< of the object
  std::size_t edge = 0;
  PushControl control;      ///< how this state was reached from its parent (unused for roots)
  double approach_m = 0.0;  ///< roots: travel from the start waypoint to the contact
};

/// The push problem as a hybrid A* search space (hybrid_astar.hpp).
class PushSearchSpace {
 public:
  using State = PushState;

  PushSearchSpace(const PushObject& object, const PushCollisionChecker& checker,
                  const PushGoalTest& goal_test, const PushHeuristic& heuristic,
                  const PushPlanAssembler& assembler, const SearchSettings& search,
                  const PushProblem& problem)
      : object_(object),
        checker_(checker),
        goal_test_(goal_test),
        heuristic_(heuristic),
        assembler_(assembler),
        search_(search),
        problem_(problem),
        heading_bins_(std::max<std::size_t>(1, search.heading_bins))
  {
  }

  std::uint64_t key(const State& state) const;
  double heuristic(const State& state) const { return heuristic_.costToGo(state.pose, problem_.goal_region); }
  bool isGoal(const State& state) const { return goal_test_.reached(state.pose, problem_.goal_region); }
  /// One straight push to the goal when nothing is in the way.
  std::optional<HybridAStarStep<State>> analyticExpansion(const State& state) const;

  template <typename Add>
  void expand(const State& state, bool root, Add&& add) const
  {
    const EdgePushOptions& option = object_.edgeOptions()[state.edge];
    pushStraight(state, option, add);
    pushOnArcs(state, option, add);
    if (state.control.kind != ControlKind::ContactSwitch || root) {
      switchContacts(state, add);
    }
  }

 private:
  /// An object pose no push may reach: in an obstacle, or beyond the search radius, where the object
  /// would leave the surroundings the onward check sees (a box pushed on along a corridor would look as if
  /// it had left the corridor).
  bool ruledOut(const Pose2& from, const Pose2& to) const
  {
    return (to.position() - object_.model().pose.position()).norm() > search_.search_radius_m ||
           checker_.objectCollides(from, to, problem_.depth_side);
  }

  /// Whether the motion `along_motion(distance travelled)` may run for `distance`, checked every
  /// collision step.
  template <typename Motion>
  bool pushAllowed(Motion&& along_motion, double distance) const
  {
    const int steps = std::max(1, static_cast<int>(std::ceil(distance / search_.collision_step_m)));
    Pose2 previous = along_motion(0.0);
    for (int step = 1; step <= steps; ++step) {
      const Pose2 next = along_motion(distance * step / steps);
      if (ruledOut(previous, next)) {
        return false;
      }
      previous = next;
    }
    return true;
  }

  template <typename Add>
  void pushStraight(const State& state, const EdgePushOptions& option, Add& add) const
  {
    if (!option.straight) {
      return;
    }
    const double length = search_.primitive_length_m;
    const auto motion = [&](double distance) {
      return object_.pushedStraight(state.pose, state.edge, distance);
    };
    if (pushAllowed(motion, length)) {
      const Pose2 pose = motion(length);
      add(State{pose, state.edge,
                assembler_.control(ControlKind::Straight, state.edge, length,
                                   std::numeric_limits<double>::infinity(), option.straight_force_n, pose),
                0.0},
          option.straight_force_n * length / search_.reference_force_n);
    }
  }

  template <typename Add>
  void pushOnArcs(const State& state, const EdgePushOptions& option, Add& add) const
  {
    const double length = search_.primitive_length_m;
    const std::array<std::pair<double, double>, 2> arcs{
        std::make_pair(option.left_radius_m, option.left_force_n),
        std::make_pair(-option.right_radius_m, option.right_force_n)};
    const bool may_turn = !checker_.turnConfined(state.pose, problem_.depth_direction);
    for (const auto& [radius, force] : arcs) {
      if (!may_turn || !std::isfinite(radius)) {
        continue;
      }
      const auto motion = [&, radius = radius](double distance) {
        return object_.pushedOnArc(state.pose, state.edge, radius, distance);
      };
      if (pushAllowed(motion, length)) {
        const Pose2 pose = motion(length);
        const ControlKind kind = radius > 0.0 ? ControlKind::ArcLeft : ControlKind::ArcRight;
        add(State{pose, state.edge, assembler_.control(kind, state.edge, length, radius, force, pose), 0.0},
            force * length / search_.reference_force_n);
      }
    }
  }

  /// Drives round to every other pushable edge, the shorter way first, the other if that one is blocked.
  template <typename Add>
  void switchContacts(const State& state, Add& add) const
  {
    const std::vector<EdgePushOptions>& options = object_.edgeOptions();
    for (std::size_t edge = 0; edge < options.size(); ++edge) {
      if (edge == state.edge || !options[edge].pushable()) {
        continue;
      }
      const std::array<SwitchPath, 2>& paths = object_.switchPaths(state.edge, edge);
      const std::size_t shorter = paths[0].length <= paths[1].length ? 0 : 1;
      for (const std::size_t direction : {shorter, 1 - shorter}) {
        if (checker_.switchFree(state.pose, paths[direction])) {
          add(State{state.pose, edge,
                    assembler_.control(ControlKind::ContactSwitch, edge, paths[direction].length, 0.0, 0.0,
                                       state.pose),
                    0.0},
              paths[direction].length);
          break;
        }
      }
    }
  }

  const PushObject& object_;
  const PushCollisionChecker& checker_;
  const PushGoalTest& goal_test_;
  const PushHeuristic& heuristic_;
  const PushPlanAssembler& assembler_;
  const SearchSettings& search_;
  const PushProblem& problem_;
  std::size_t heading_bins_;
};

std::uint64_t PushSearchSpace::key(const State& state) const
{
  const auto cell = [&](double value) {
    return static_cast<std::uint64_t>(
        static_cast<std::int64_t>(std::floor(value / search_.position_resolution_m)) & 0xFFFFF);
  };
  const double turn = (geometry::wrapAngle(state.pose.heading) + geometry::kPi) / (2.0 * geometry::kPi);
  const auto heading_cell = static_cast<std::uint64_t>(
      std::min(heading_bins_ - 1, static_cast<std::size_t>(turn * static_cast<double>(heading_bins_))));
  return (cell(state.pose.x) << 44) | (cell(state.pose.y) << 24) | (heading_cell << 8) |
         static_cast<std::uint64_t>(state.edge & 0xFF);
}

std::optional<HybridAStarStep<PushState>> PushSearchSpace::analyticExpansion(const State& state) const
{
  const EdgePushOptions& option = object_.edgeOptions()[state.edge];
  if (!option.straight) {
    return std::nullopt;
  }
  const int steps = static_cast<int>(std::ceil(search_.analytic_max_distance_m / search_.collision_step_m));
  Pose2 previous = state.pose;
  for (int step = 1; step <= steps; ++step) {
    const double distance = step * search_.collision_step_m;
    const Pose2 pose = object_.pushedStraight(state.pose, state.edge, distance);
    if (ruledOut(previous, pose)) {
      return std::nullopt;
    }
    previous = pose;
    if (goal_test_.reached(pose, problem_.goal_region)) {
      return HybridAStarStep<State>{
          State{pose, state.edge,
                assembler_.control(ControlKind::Straight, state.edge, distance,
                                   std::numeric_limits<double>::infinity(), option.straight_force_n, pose),
                0.0},
          option.straight_force_n * distance / search_.reference_force_n};
    }
  }
  return std::nullopt;
}

PlanStatus planStatus(HybridAStarStatus status)
{
  switch (status) {
    case HybridAStarStatus::Found:
      return PlanStatus::Found;
    case HybridAStarStatus::ExpansionLimit:
      return PlanStatus::ExpansionLimit;
    case HybridAStarStatus::TimeBudget:
      return PlanStatus::TimeBudget;
    case HybridAStarStatus::Exhausted:
      break;
  }
  return PlanStatus::Exhausted;
}

}  // namespace

HybridAStarPush::HybridAStarPush(const PushObject& object, const PushCollisionChecker& checker,
                                 const PushGoalTest& goal_test, const SearchSettings& search)
    : object_(object),
      checker_(checker),
      goal_test_(goal_test),
      heuristic_(object.model().footprint, object.smallestForce(), search.reference_force_n),
      search_(search),
      assembler_(object, search)
{
}

PushPlan HybridAStarPush::solve(const PushProblem& problem, const SearchDeadline& deadline) const
{
  const PushSearchSpace space(object_, checker_, goal_test_, heuristic_, assembler_, search_, problem);
  std::vector<HybridAStarStep<PushState>> roots;
  for (const PushContact& contact : problem.contacts) {
    PushState root;
    root.pose = object_.model().pose;
    root.edge = contact.edge;
    root.approach_m = contact.approach_m;
    roots.push_back(HybridAStarStep<PushState>{root, root.approach_m});
  }
  HybridAStar<PushSearchSpace> search(space, deadline, search_.analytic_interval);
  const HybridAStarResult<PushState> found = search.run(roots);
  PushPlan plan = assembler_.unplanned(planStatus(found.status));
  plan.expansions = found.expansions;
  plan.planning_time_s = deadline.elapsedSeconds();
  if (found.status != HybridAStarStatus::Found) {
    return plan;
  }
  std::vector<PushControl> controls;
  for (std::size_t link = 1; link < found.path.size(); ++link) {
    controls.push_back(found.path[link].control);
  }
  assembler_.complete(plan, found.path.front().edge, found.path.front().approach_m, std::move(controls));
  return plan;
}

}  // namespace ifar::interaction
