// One contract for every push strategy (push_strategy.hpp): each typed test below runs against each
// implementation, called through the PushStrategy interface on the problem PushPlanner poses.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "planner/interaction/body_frame.hpp"
#include "planner/interaction/connectivity.hpp"
#include "planner/interaction/corridor_push.hpp"
#include "planner/interaction/hybrid_astar_push.hpp"
#include "planner/interaction/push_search.hpp"
#include "testing/interaction_scenes.hpp"

namespace ifar::interaction {
namespace {

using geometry::Point;
using geometry::Pose2;
using test::rectangle;

struct HybridAStarPushTraits {
  using Strategy = HybridAStarPush;
  static SearchSettings settings(const SearchSettings& search) { return search; }
};

struct CorridorPushTraits {
  using Strategy = CorridorPush;
  static SearchSettings settings(SearchSettings search)
  {
    search.corridor_push_length_m = 60.0;
    return corridorSearch(search);
  }
};

/// A box (real 1.0 m x 1.0 m) in a dead-end niche 5 cm wider and deeper than it, open to the west: the
/// vehicle reaches its west face only, and any push runs it into the niche's walls.
LocalScene boxInANicheScene()
{
  LocalScene scene;
  scene.background = {rectangle(0.2, -1.85, 1.85, 1.85), rectangle(-2.0, 0.2, 1.85, 1.85),
                      rectangle(-2.0, -1.85, 1.85, -0.2)};
  scene.movable = {rectangle(-0.85, -0.85, 0.85, 0.85)};
  return scene;
}

template <typename Traits>
class PushStrategyContractTest : public ::testing::Test {
 protected:
  PushStrategyContractTest()
  {
    settings_.pusher = PusherSettings::fromVehicle(common::VehicleSettings{});
    settings_.search.time_budget_s = 1.0;  // generous: tests check outcomes, the benchmark checks speed
  }

  SearchSettings search() const { return Traits::settings(settings_.search); }

  /// The planner of the scene's first movable object, with this strategy.
  std::unique_ptr<PushPlanner> plannerFor(const LocalScene& scene, const SearchSettings& search) const
  {
    auto planner = std::make_unique<PushPlanner>(
        PushProblemObject{scene.movable[0], scene.background, ObjectPhysics{0.4, 20.0}}, settings_.pusher,
        search, settings_.connectivity);
    EXPECT_EQ(planner->status(), PlanStatus::Found) << toString(planner->status());
    EXPECT_NE(dynamic_cast<const typename Traits::Strategy*>(&planner->strategy()), nullptr);
    return planner;
  }

  static SearchDeadline deadlineOf(const SearchSettings& search)
  {
    return SearchDeadline(SearchDeadline::Clock::now(), search.time_budget_s, search.max_expansions);
  }

  /// Solves `start` -> `goal` through the strategy interface.
  static PushPlan solve(const PushPlanner& planner, const SearchSettings& search, const Point& start,
                        const Point& goal)
  {
    const PushProblemResult posed = planner.problem(start, goal);
    EXPECT_EQ(posed.status, PlanStatus::Found) << toString(posed.status);
    return planner.strategy().solve(posed.problem, deadlineOf(search));
  }

  /// Replays every control of `plan` at the search's collision step and holds each move to the checker:
  /// no push runs the object into an obstacle or out of the search radius, every contact switch has a
  /// free way round, and each control ends where it says.
  static void expectCollisionFree(const PushPlanner& planner, const SearchSettings& search,
                                  const PushProblem& problem, const PushPlan& plan)
  {
    const PushObject& object = planner.object();
    const PushCollisionChecker& checker = planner.collisionChecker();
    Pose2 pose = plan.start_object_pose;
    std::size_t edge = plan.contact_edge;
    for (const PushControl& control : plan.controls) {
      if (control.kind == ControlKind::ContactSwitch) {
        const auto& paths = object.switchPaths(edge, control.contact_edge);
        EXPECT_TRUE(checker.switchFree(pose, paths[0]) || checker.switchFree(pose, paths[1]));
        edge = control.contact_edge;
        continue;
      }
      const double radius =
          control.kind == ControlKind::Straight ? 0.0 : control.linear_mps / control.angular_radps;
      const auto motion = [&](double distance) {
        return control.kind == ControlKind::Straight ? object.pushedStraight(pose, edge, distance)
                                                     : object.pushedOnArc(pose, edge, radius, distance);
      };
      const int steps =
          std::max(1, static_cast<int>(std::ceil(control.distance_m / search.collision_step_m)));
      Pose2 previous = pose;
      for (int step = 1; step <= steps; ++step) {
        const Pose2 next = motion(control.distance_m * step / steps);
        EXPECT_FALSE(checker.objectCollides(previous, next, problem.depth_side))
            << toString(control.kind) << " step " << step << " of " << steps;
        EXPECT_LE((next.position() - plan.start_object_pose.position()).norm(),
                  search.search_radius_m + 1e-9);
        previous = next;
      }
      EXPECT_NEAR(previous.x, control.object_pose.x, 1e-9);
      EXPECT_NEAR(previous.y, control.object_pose.y, 1e-9);
      EXPECT_NEAR(geometry::wrapAngle(previous.heading - control.object_pose.heading), 0.0, 1e-9);
      EXPECT_EQ(control.contact_edge, edge);
      pose = control.object_pose;
    }
  }

  InteractionSettings settings_;
};

using Strategies = ::testing::Types<HybridAStarPushTraits, CorridorPushTraits>;

class StrategyNames {
 public:
  template <typename Traits>
  static std::string GetName(int /*index*/)
  {
    return std::is_same_v<Traits, CorridorPushTraits> ? "CorridorPush" : "HybridAStarPush";
  }
};

TYPED_TEST_SUITE(PushStrategyContractTest, Strategies, StrategyNames);

TYPED_TEST(PushStrategyContractTest, ClearsADoorwayOfTheBoxBlockingIt)
{
  const SearchSettings search = this->search();
  const auto planner = this->plannerFor(test::doorwayScene(), search);
  for (const auto& [start, goal] : {std::make_pair(Point(-1.1, 0.0), Point(1.1, 0.0)),
                                    std::make_pair(Point(1.1, 0.0), Point(-1.1, 0.0))}) {
    const PushProblemResult posed = planner->problem(start, goal);
    ASSERT_EQ(posed.status, PlanStatus::Found);
    const PushPlan plan = planner->strategy().solve(posed.problem, this->deadlineOf(search));
    ASSERT_EQ(plan.status, PlanStatus::Found) << toString(plan.status);
    ASSERT_FALSE(plan.controls.empty());
    EXPECT_EQ(plan.footprint, planner->model().footprint);
    const Pose2 end = plan.controls.back().object_pose;
    EXPECT_TRUE(planner->goalTest().reached(end, posed.problem.goal_region));
    EXPECT_GE(segmentPolygonDistance(geometry::Segment{start, goal}, transformed(plan.footprint, end)),
              planner->goalTest().objectClearance());
    EXPECT_GT(plan.push_distance_m, 0.0);
    EXPECT_NEAR(plan.cost, plan.push_work_nm / search.reference_force_n + plan.travel_distance_m, 1e-9);
    EXPECT_LE(plan.expansions, search.max_expansions);
    this->expectCollisionFree(*planner, search, posed.problem, plan);
  }
}

TYPED_TEST(PushStrategyContractTest, NeverReturnsACollidingPlan)
{
  const SearchSettings search = this->search();
  std::size_t found = 0;
  for (const LocalScene& scene :
       {test::doorwayWithWallBehindScene(), test::doorwayWithThinWallBehindScene(),
        test::doorwayWithNearWallScene(), test::tJunctionScene(), test::fireDoorScene(),
        test::faceOnlyDoorwayWithWallBehindScene(), test::barInATunnelScene(true)}) {
    const ConnectivityResult connectivity = analyzeConnectivity(scene, 0, this->settings_.connectivity);
    const auto planner = this->plannerFor(scene, search);
    for (const OrderedPair& pair : connectivity.pairs) {
      const PushProblemResult posed = planner->problem(connectivity.waypoints[pair.from].position,
                                                       connectivity.waypoints[pair.to].position);
      ASSERT_EQ(posed.status, PlanStatus::Found) << toString(posed.status);
      const PushPlan plan = planner->strategy().solve(posed.problem, this->deadlineOf(search));
      if (plan.status == PlanStatus::Found) {
        ++found;
        this->expectCollisionFree(*planner, search, posed.problem, plan);
      } else {
        EXPECT_EQ(plan.status, PlanStatus::Exhausted) << toString(plan.status);
        EXPECT_TRUE(plan.controls.empty());
      }
    }
  }
  EXPECT_GE(found, 2U);
}

TYPED_TEST(PushStrategyContractTest, StopsAtTheExpansionLimit)
{
  SearchSettings search = this->search();
  search.analytic_max_distance_m = 0.0;  // no shortcut: the search has to expand
  const auto planner = this->plannerFor(test::doorwayScene(), search);
  for (const std::size_t limit : {0U, 1U, 3U}) {
    search.max_expansions = limit;
    const PushPlan plan = this->solve(*planner, search, Point(-1.1, 0.0), Point(1.1, 0.0));
    EXPECT_LE(plan.expansions, limit);
    if (plan.status != PlanStatus::Found) {
      EXPECT_EQ(plan.status, PlanStatus::ExpansionLimit) << toString(plan.status);
      EXPECT_EQ(plan.expansions, limit);
      EXPECT_TRUE(plan.controls.empty());
    }
  }
  search.max_expansions = 0;
  EXPECT_EQ(this->solve(*planner, search, Point(-1.1, 0.0), Point(1.1, 0.0)).status,
            PlanStatus::ExpansionLimit);
}

TYPED_TEST(PushStrategyContractTest, StopsWhenTheTimeBudgetIsSpent)
{
  const SearchSettings search = this->search();
  const auto planner = this->plannerFor(test::doorwayScene(), search);
  const PushProblemResult posed = planner->problem(Point(-1.1, 0.0), Point(1.1, 0.0));
  ASSERT_EQ(posed.status, PlanStatus::Found);
  // Started a second ago with no time to spend: no clock reading can fall within the budget.
  const SearchDeadline spent(SearchDeadline::Clock::now() - std::chrono::seconds(1), 0.0,
                             search.max_expansions);
  const PushPlan plan = planner->strategy().solve(posed.problem, spent);
  EXPECT_EQ(plan.status, PlanStatus::TimeBudget) << toString(plan.status);
  EXPECT_TRUE(plan.controls.empty());
  EXPECT_GE(plan.planning_time_s, 1.0);
}

TYPED_TEST(PushStrategyContractTest, ReportsNoPlanForABoxNoPushCanMove)
{
  const SearchSettings search = this->search();
  const auto planner = this->plannerFor(boxInANicheScene(), search);
  const PushProblemResult posed = planner->problem(Point(-2.5, 0.0), Point(2.5, 0.0));
  ASSERT_EQ(posed.status, PlanStatus::Found) << toString(posed.status);
  ASSERT_EQ(posed.problem.contacts.size(), 1U) << "only the west face is in reach";
  const PushPlan plan = planner->strategy().solve(posed.problem, this->deadlineOf(search));
  EXPECT_EQ(plan.status, PlanStatus::Exhausted) << toString(plan.status);
  EXPECT_TRUE(plan.controls.empty());
  EXPECT_EQ(plan.footprint, planner->model().footprint);
}

TYPED_TEST(PushStrategyContractTest, SolvingAgainGivesTheSamePlan)
{
  const SearchSettings search = this->search();
  const auto planner = this->plannerFor(test::doorwayWithNearWallScene(), search);
  const PushPlan first = this->solve(*planner, search, Point(-1.1, 0.0), Point(1.1, 0.0));
  const PushPlan second = this->solve(*planner, search, Point(-1.1, 0.0), Point(1.1, 0.0));
  EXPECT_EQ(first.status, second.status);
  EXPECT_EQ(first.expansions, second.expansions);
  EXPECT_EQ(first.cost, second.cost);
  ASSERT_EQ(first.controls.size(), second.controls.size());
  for (std::size_t index = 0; index < first.controls.size(); ++index) {
    EXPECT_EQ(first.controls[index].kind, second.controls[index].kind);
    EXPECT_EQ(first.controls[index].object_pose.x, second.controls[index].object_pose.x);
    EXPECT_EQ(first.controls[index].object_pose.y, second.controls[index].object_pose.y);
    EXPECT_EQ(first.controls[index].object_pose.heading, second.controls[index].object_pose.heading);
  }
}

}  // namespace
}  // namespace ifar::interaction
