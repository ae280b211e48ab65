#include "planner/interaction/push_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "planner/interaction/convex_polygon.hpp"
#include "planner/interaction/interaction_planner.hpp"
#include "testing/interaction_scenes.hpp"

namespace ifar::interaction {
namespace {

using geometry::Point;
using geometry::Pose2;
using test::rectangle;

InteractionSettings defaultSettings()
{
  InteractionSettings settings;
  settings.pusher = PusherSettings::fromVehicle(common::VehicleSettings{});
  settings.search.time_budget_s = 1.0;  // generous: tests check outcomes, the benchmark checks speed
  return settings;
}

/// Follows the controls from the contact pose as a unicycle and checks each control ends where it says.
void expectControlsConsistent(const PushPlan& plan)
{
  Pose2 vehicle = plan.contact_pose;
  for (const PushControl& control : plan.controls) {
    if (control.kind == ControlKind::ContactSwitch) {
      vehicle = control.vehicle_pose;
      continue;
    }
    const double turn = control.angular_radps * control.duration_s;
    if (std::abs(control.angular_radps) < 1e-12) {
      vehicle.x += std::cos(vehicle.heading) * control.linear_mps * control.duration_s;
      vehicle.y += std::sin(vehicle.heading) * control.linear_mps * control.duration_s;
    } else {
      const double radius = control.linear_mps / control.angular_radps;
      vehicle.x += radius * (std::sin(vehicle.heading + turn) - std::sin(vehicle.heading));
      vehicle.y -= radius * (std::cos(vehicle.heading + turn) - std::cos(vehicle.heading));
      vehicle.heading = geometry::wrapAngle(vehicle.heading + turn);
    }
    EXPECT_NEAR(vehicle.x, control.vehicle_pose.x, 1e-6);
    EXPECT_NEAR(vehicle.y, control.vehicle_pose.y, 1e-6);
    EXPECT_NEAR(geometry::wrapAngle(vehicle.heading - control.vehicle_pose.heading), 0.0, 1e-6);
  }
}

double passageClearance(const PushPlan& plan, const Point& from, const Point& to)
{
  const Pose2 final_pose = plan.controls.empty() ? plan.start_object_pose : plan.controls.back().object_pose;
  geometry::Polygon world;
  for (const Point& vertex : plan.footprint) {
    world.push_back(final_pose.transform(vertex));
  }
  return segmentPolygonDistance(geometry::Segment{from, to}, world);
}

TEST(PushSearchTest, DoorwayGivesTwoDirectedPlans)
{
  const LocalScene scene = test::doorwayScene();
  const ObjectInteractions result =
      planObjectInteractions(scene, 0, ObjectPhysics{0.4, 20.0}, defaultSettings());
  ASSERT_EQ(result.connectivity.waypoints.size(), 2U);
  ASSERT_EQ(result.plans.size(), 2U);
  for (const PairPlan& pair : result.plans) {
    const PushPlan& plan = pair.plan;
    ASSERT_EQ(plan.status, PlanStatus::Found) << toString(plan.status);
    ASSERT_FALSE(plan.controls.empty());
    const Point from = result.connectivity.waypoints[pair.pair.from].position;
    const Point to = result.connectivity.waypoints[pair.pair.to].position;
    EXPECT_GE(passageClearance(plan, from, to), 0.32);
    // The vehicle starts on the waypoint's side and pushes away from it through the door.
    EXPECT_GT(plan.contact_pose.x * from.x(), 0.0);
    EXPECT_GT(std::cos(plan.contact_pose.heading) * (to.x() - from.x()), 0.0);
    // Straight pushes of a 20 kg box on mu 0.4: 78.48 N; J = work / 100 N + travel.
    EXPECT_NEAR(plan.expected_force_n, 0.4 * 20.0 * 9.81, 1e-9);
    EXPECT_NEAR(plan.cost, plan.push_work_nm / 100.0 + plan.travel_distance_m, 1e-9);
    EXPECT_GT(plan.push_distance_m, 1.0);
    EXPECT_LT(plan.push_distance_m, 3.0);
    expectControlsConsistent(plan);
  }
}

TEST(PushSearchTest, TJunctionGivesSixDirectedPlans)
{
  const ObjectInteractions result =
      planObjectInteractions(test::tJunctionScene(), 0, ObjectPhysics{0.4, 20.0}, defaultSettings());
  ASSERT_EQ(result.connectivity.waypoints.size(), 3U);
  ASSERT_EQ(result.plans.size(), 6U);
  for (const PairPlan& pair : result.plans) {
    ASSERT_EQ(pair.plan.status, PlanStatus::Found)
        << pair.pair.from << " -> " << pair.pair.to << ": " << toString(pair.plan.status);
    EXPECT_GE(passageClearance(pair.plan, result.connectivity.waypoints[pair.pair.from].position,
                               result.connectivity.waypoints[pair.pair.to].position),
              0.32);
    expectControlsConsistent(pair.plan);
  }
}

/// Every footprint sample at every control's end pose stays out of the obstacles' real extent.
void expectNoWallHit(const PushPlan& plan, const std::vector<geometry::Polygon>& obstacles, double inflation)
{
  for (const PushControl& control : plan.controls) {
    for (std::size_t index = 0; index < plan.footprint.size(); ++index) {
      const Point first = plan.footprint[index];
      const Point second = plan.footprint[(index + 1) % plan.footprint.size()];
      for (int step = 0; step < 20; ++step) {
        const Point world = control.object_pose.transform(first + (second - first) * (0.05 * step));
        for (const geometry::Polygon& obstacle : obstacles) {
          if (geometry::containsPoint(obstacle, world)) {
            EXPECT_LE(geometry::distanceToBoundary(obstacle, world), inflation + 0.031);
          }
        }
      }
    }
  }
}

TEST(PushSearchTest, WallBehindTheDoorForcesATurnedPush)
{
  const LocalScene scene = test::doorwayWithWallBehindScene();
  const InteractionSettings settings = defaultSettings();
  const ObjectInteractions result = planObjectInteractions(scene, 0, ObjectPhysics{0.4, 20.0}, settings);
  ASSERT_EQ(result.plans.size(), 2U);
  for (const PairPlan& pair : result.plans) {
    ASSERT_EQ(pair.plan.status, PlanStatus::Found) << toString(pair.plan.status);
    expectNoWallHit(pair.plan, scene.background, settings.pusher.inflation_m);
    expectControlsConsistent(pair.plan);
    const Point from = result.connectivity.waypoints[pair.pair.from].position;
    const Point to = result.connectivity.waypoints[pair.pair.to].position;
    EXPECT_GE(passageClearance(pair.plan, from, to), 0.32);
    if (from.x() < 0.0) {  // pushing towards the wall: a straight push cannot clear the door
      const bool turned =
          std::any_of(pair.plan.controls.begin(), pair.plan.controls.end(),
                      [](const PushControl& control) { return control.kind != ControlKind::Straight; });
      EXPECT_TRUE(turned);
    }
  }
}

/// The plan of the pair that pushes from the west of the doorway (x < 0) eastward.
PushPlan eastwardPlan(const ObjectInteractions& interactions)
{
  for (const PairPlan& pair : interactions.plans) {
    if (interactions.connectivity.waypoints[pair.pair.from].position.x() < 0.0) {
      return pair.plan;
    }
  }
  ADD_FAILURE() << "no eastward pair";
  return PushPlan{};
}

TEST(PushSearchTest, AWallSeenAsOneCellIsNotPushedThrough)
{
  // Inflated, a wall one cell thick has no point deeper than the allowed depth (inflation + tolerance):
  // the depth test alone let the straight push run the box through it (driven Willow t0: the east
  // corridor's box turned through the corridor's wall). No point of the box may cross the wall's face.
  const LocalScene scene = test::doorwayWithThinWallBehindScene();
  const InteractionSettings settings = defaultSettings();
  const ObjectInteractions result = planObjectInteractions(scene, 0, ObjectPhysics{0.4, 20.0}, settings);
  const double face_x = 1.875;       // the middle of the wall's cell
  const double face_reach_y = 0.65;  // the cell's ends, inflation taken off the rectangle
  const PushPlan plan = eastwardPlan(result);
  ASSERT_EQ(plan.status, PlanStatus::Found) << toString(plan.status);
  expectControlsConsistent(plan);
  double farthest = -std::numeric_limits<double>::infinity();
  for (const PushControl& control : plan.controls) {
    for (const Point& vertex : plan.footprint) {
      const Point world = control.object_pose.transform(vertex);
      if (std::abs(world.y()) <= face_reach_y) {
        farthest = std::max(farthest, world.x());
      }
    }
  }
  EXPECT_LT(farthest, face_x);
}

/// The lowest and highest y of `footprint` placed at `pose`.
std::pair<double, double> spanInY(const geometry::Polygon& footprint, const Pose2& pose)
{
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  for (const Point& vertex : footprint) {
    low = std::min(low, pose.transform(vertex).y());
    high = std::max(high, pose.transform(vertex).y());
  }
  return {low, high};
}

/// Whether the box, where `plan` leaves it, keeps a lane `lane` wide beside it in the corridor (real
/// 0 < y < 2.5); with `door_counts`, a box still in the fire door's wall (|x| < 0.8) passes too: the lane is
/// then the door.
::testing::AssertionResult leavesACorridorLane(const PushPlan& plan, double lane, bool door_counts)
{
  const Pose2 end = plan.controls.back().object_pose;
  const auto [low, high] = spanInY(plan.footprint, end);
  if ((door_counts && std::abs(end.x) < 0.8) || low >= lane - 0.03 || 2.5 - high >= lane - 0.03) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "box ends at (" << end.x << ", " << end.y << ", " << end.heading
                                       << ") spanning y " << low << " .. " << high;
}

TEST(PushSearchTest, ABoxIsNotPushedAlongACorridorItWouldCloseFurtherOn)
{
  // The segment between the waypoints clears after a straight push of a metre or two, but the box then
  // stands across the corridor beyond the waypoint: a plan must leave a lane at least the vehicle's width
  // plus the passage margin beside the box (real corridor 0 < y < 2.5), or there is no plan. A side door
  // beyond the fire door keeps the east side open when the box closes the corridor, and must not count.
  const InteractionSettings settings = defaultSettings();
  const double lane = 2.0 * settings.pusher.inflation_m + settings.search.passage_margin_m;
  for (const LocalScene& scene : {test::fireDoorScene(), test::fireDoorWithSideDoorScene()}) {
    const ObjectInteractions result = planObjectInteractions(scene, 0, ObjectPhysics{0.4, 20.0}, settings);
    ASSERT_EQ(result.connectivity.waypoints.size(), 2U);
    ASSERT_EQ(result.plans.size(), 2U);
    int found = 0;
    for (const PairPlan& pair : result.plans) {
      if (pair.plan.status != PlanStatus::Found) {
        continue;
      }
      ++found;
      EXPECT_TRUE(leavesACorridorLane(pair.plan, lane, true));
    }
    EXPECT_EQ(found, 2) << "the box can be turned out of the door and pushed against a corridor wall";
  }
  const LocalScene scene = test::fireDoorScene();
  // With the corridor's walls not seen (only the door's wall, long), a straight push through is enough.
  LocalScene unknown_beyond;
  unknown_beyond.background = {test::rectangle(-0.45, -8.0, 0.45, 1.0),
                               test::rectangle(-0.45, 1.5, 0.45, 8.0)};
  unknown_beyond.movable = scene.movable;
  const ObjectInteractions open =
      planObjectInteractions(unknown_beyond, 0, ObjectPhysics{0.4, 20.0}, settings);
  ASSERT_EQ(open.plans.size(), 2U);
  for (const PairPlan& pair : open.plans) {
    ASSERT_EQ(pair.plan.status, PlanStatus::Found) << toString(pair.plan.status);
    EXPECT_TRUE(
        std::all_of(pair.plan.controls.begin(), pair.plan.controls.end(),
                    [](const PushControl& control) { return control.kind == ControlKind::Straight; }));
  }
}

TEST(PushSearchTest, AWayRoundTheFireDoorDoesNotLetTheBoxCloseTheCorridorBeyondIt)
{
  // Through the room the two sides of the fire door are one space in the surroundings. The check once
  // stopped there ("nothing separated"), and a straight push east that closes the corridor beyond the
  // room's door passed (in the office, stretches of wall not yet seen joined the rooms either side).
  const InteractionSettings settings = defaultSettings();
  const double lane = 2.0 * settings.pusher.inflation_m + settings.search.passage_margin_m;
  const ObjectInteractions result =
      planObjectInteractions(test::fireDoorBesideARoomScene(), 0, ObjectPhysics{0.4, 20.0}, settings);
  ASSERT_EQ(result.connectivity.waypoints.size(), 2U);
  ASSERT_EQ(result.plans.size(), 2U);
  for (const PairPlan& pair : result.plans) {
    const bool eastward = result.connectivity.waypoints[pair.pair.from].position.x() < 0.0;
    if (!eastward) {
      // West, the box may close the corridor: the room's doors lead round it to the corridor beyond.
      EXPECT_EQ(pair.plan.status, PlanStatus::Found) << toString(pair.plan.status);
      continue;
    }
    ASSERT_EQ(pair.plan.status, PlanStatus::Found) << toString(pair.plan.status);
    EXPECT_TRUE(leavesACorridorLane(pair.plan, lane, false));
  }
}

TEST(PushSearchTest, AWayRoundThroughARoomDoesNotLetTheBoxCloseTheCorridor)
{
  // With the box closing the corridor 2 m on, the corridor beyond is still reachable through the room
  // south of it, 8 m round: that is no way on. Either way the box must leave the corridor a lane.
  const InteractionSettings settings = defaultSettings();
  const double lane = 2.0 * settings.pusher.inflation_m + settings.search.passage_margin_m;
  const ObjectInteractions result =
      planObjectInteractions(test::fireDoorWithALoopRoundItScene(), 0, ObjectPhysics{0.4, 20.0}, settings);
  ASSERT_EQ(result.connectivity.waypoints.size(), 2U);
  ASSERT_EQ(result.plans.size(), 2U);
  for (const PairPlan& pair : result.plans) {
    ASSERT_EQ(pair.plan.status, PlanStatus::Found) << toString(pair.plan.status);
    EXPECT_TRUE(leavesACorridorLane(pair.plan, lane, true));
  }
}

/// A 3.6 m x 1.2 m box across a 4 m corridor running south from an east-west corridor (y 1.4 .. 5.4, as in
/// the generated tunnel), inflated like the planner's scene; each wall is cut off `margin` beyond the box.
LocalScene boxAcrossACorridorScene(double margin)
{
  const double inflation = 0.35;
  const geometry::Polygon box =
      rectangle(-1.8 - inflation, -0.6 - inflation, 1.8 + inflation, 0.6 + inflation);
  const double low_x = -1.8 - inflation - margin;
  const double high_x = 1.8 + inflation + margin;
  const double low_y = -0.6 - inflation - margin;
  const double high_y = 0.6 + inflation + margin;
  LocalScene scene;
  scene.background = {rectangle(low_x, low_y, -2.0 + inflation, 1.4 + inflation),
                      rectangle(2.0 - inflation, low_y, high_x, 1.4 + inflation),
                      rectangle(low_x, 5.4 - inflation, high_x, high_y)};
  scene.movable = {box};
  return scene;
}

/// The plans that push the box from the junction (north) down the corridor (south).
std::vector<PushPlan> plansDownTheCorridor(const ObjectInteractions& interactions)
{
  std::vector<PushPlan> down;
  for (const PairPlan& pair : interactions.plans) {
    const Point from = interactions.connectivity.waypoints[pair.pair.from].position;
    const Point to = interactions.connectivity.waypoints[pair.pair.to].position;
    if (from.y() > to.y()) {
      down.push_back(pair.plan);
    }
  }
  return down;
}

TEST(PushSearchTest, TheStraightPushToTheGoalKeepsTheObjectWithinTheSearchRadius)
{
  // Walls far beyond the search: only the search radius keeps the box near enough for the onward check to
  // see that it still closes the corridor. The straight push tried towards the goal once went 7 m down.
  const InteractionSettings settings = defaultSettings();
  const ObjectInteractions result =
      planObjectInteractions(boxAcrossACorridorScene(40.0), 0, ObjectPhysics{0.5, 32.0}, settings);
  ASSERT_EQ(result.connectivity.waypoints.size(), 2U);
  for (const PairPlan& pair : result.plans) {
    for (const PushControl& control : pair.plan.controls) {
      EXPECT_LE(control.object_pose.position().norm(), settings.search.search_radius_m + 1e-9)
          << toString(pair.plan.status);
    }
  }
  const std::vector<PushPlan> down = plansDownTheCorridor(result);
  ASSERT_EQ(down.size(), 1U);
  EXPECT_NE(down.front().status, PlanStatus::Found) << "a push of 4 m or less leaves the corridor closed";
}

TEST(PushSearchTest, WallsCutOffAtTheSceneMarginStillCloseTheCorridor)
{
  // The planner hands the interaction planner its walls only out to sceneMargin round the objects. Cut
  // off nearer than the onward check looks, free space ran round the check's edge, both sides of the
  // box looked connected, and a 2 m push down the corridor counted as opening it (in the tunnel, 22
  // pushes 40 m down a corridor, each planned as the last).
  const InteractionSettings settings = defaultSettings();
  ASSERT_GT(sceneMargin(settings), surroundingsReach(settings.connectivity, settings.search));
  const ObjectInteractions result = planObjectInteractions(boxAcrossACorridorScene(sceneMargin(settings)), 0,
                                                           ObjectPhysics{0.5, 32.0}, settings);
  ASSERT_EQ(result.connectivity.waypoints.size(), 2U);
  const std::vector<PushPlan> down = plansDownTheCorridor(result);
  ASSERT_EQ(down.size(), 1U);
  EXPECT_NE(down.front().status, PlanStatus::Found) << "pushed on down the corridor";
  // Into the junction the box can go: it leaves a lane beside it there.
  for (const PairPlan& pair : result.plans) {
    if (result.connectivity.waypoints[pair.pair.from].position.y() < 0.0) {
      EXPECT_EQ(pair.plan.status, PlanStatus::Found) << toString(pair.plan.status);
    }
  }
}

TEST(PushSearchTest, ABoxPluggingALongPassageIsPushedOutOfItsFarEndByTheExtendedSearch)
{
  // No push within the 4 m search radius gets the box out of the 6 m passage, and inside it the box closes
  // the way on: the search proves that (exhausted). The extended search pushes it through into the room.
  // Pushed the other way, into the wide corridor, the near search's plan stands.
  InteractionSettings settings = defaultSettings();
  const auto northward = [](const ObjectInteractions& interactions, const PairPlan& pair) {
    return interactions.connectivity.waypoints[pair.pair.from].position.y() <
           interactions.connectivity.waypoints[pair.pair.to].position.y();
  };
  const ObjectInteractions near =
      planObjectInteractions(test::pluggedPassageScene(), 0, ObjectPhysics{0.4, 20.0}, settings);
  ASSERT_EQ(near.connectivity.waypoints.size(), 2U);
  ASSERT_EQ(near.plans.size(), 2U);
  settings.search.extended_search_radius_m = 8.0;
  ASSERT_GT(sceneMargin(settings), obstacleReach(settings.connectivity, settings.search, settings.pusher))
      << "the scene must reach as far as the extended search looks";
  const ObjectInteractions extended =
      planObjectInteractions(test::pluggedPassageScene(), 0, ObjectPhysics{0.4, 20.0}, settings);
  ASSERT_EQ(extended.plans.size(), 2U);
  for (std::size_t index = 0; index < 2; ++index) {
    const PushPlan& before = near.plans[index].plan;
    const PushPlan& after = extended.plans[index].plan;
    if (!northward(near, near.plans[index])) {
      ASSERT_EQ(before.status, PlanStatus::Found) << toString(before.status);
      EXPECT_LE(before.push_distance_m, settings.search.search_radius_m);
      EXPECT_EQ(after.push_distance_m, before.push_distance_m) << "a pair the near search solves stays";
      EXPECT_EQ(after.expansions, before.expansions);
      continue;
    }
    EXPECT_EQ(before.status, PlanStatus::Exhausted) << toString(before.status);
    ASSERT_EQ(after.status, PlanStatus::Found) << toString(after.status);
    expectControlsConsistent(after);
    const Pose2 end = after.controls.back().object_pose;
    EXPECT_GT(spanInY(after.footprint, end).first, 6.0 - 0.35) << "the box ends at y " << end.y;
    EXPECT_GT(after.push_distance_m, 6.0);
    for (const PushControl& control : after.controls) {
      EXPECT_LE((control.object_pose.position() - after.start_object_pose.position()).norm(), 8.0 + 1e-9);
    }
  }
}

bool turns(const PushControl& control)
{
  return control.kind == ControlKind::ArcLeft || control.kind == ControlKind::ArcRight;
}

TEST(PushSearchTest, AFaceOnlyBoxIsNotTurnedInsideAPassage)
{
  // Only the box's west face is seen, so its depth is a guess. In a 3 m long, 1.2 m wide passage a turn
  // would sweep that depth into the passage walls (driven Willow t3 jammed so); the thin face alone would
  // turn (it did, from where it stands). It goes straight until its face's ends, a metre beyond them, are
  // clear of the walls (0.3 m), then turns aside: straight on it would close the corridor.
  InteractionSettings settings = defaultSettings();
  const ObjectInteractions result =
      planObjectInteractions(test::faceOnlyInALongDoorScene(), 0, ObjectPhysics{0.4, 20.0}, settings);
  ASSERT_EQ(result.plans.size(), 2U);
  bool eastward_checked = false;
  for (const PairPlan& pair : result.plans) {
    if (result.connectivity.waypoints[pair.pair.from].position.x() > 0.0) {
      continue;  // pushed west out of the passage's mouth: its depth is outside
    }
    eastward_checked = true;
    const PushPlan& plan = pair.plan;
    ASSERT_EQ(plan.status, PlanStatus::Found) << toString(plan.status);
    expectControlsConsistent(plan);
    Pose2 before = plan.start_object_pose;
    bool turned = false;
    for (const PushControl& control : plan.controls) {
      if (turns(control)) {
        // Walls end at x 3.25 (inflated); the probe a metre on leaves them 0.3 m from their end.
        EXPECT_GE(before.x, 3.25 - 0.05 - 1.0 - 1e-9) << "turned in the passage at x " << before.x;
      }
      turned = turned || turns(control);
      before = control.object_pose;
    }
    EXPECT_TRUE(turned) << "pushed straight along the corridor the box closes it";
  }
  EXPECT_TRUE(eastward_checked);
}

TEST(PushSearchTest, AFaceOnlyBoxInADoorIsTurnedAtOnce)
{
  // The same face in the fire door, whose wall is 0.2 m thick: a metre beyond the face is open corridor,
  // so the guessed depth sweeps no wall and the box is turned from where it stands, as one whose depth
  // was seen (pushed straight out first, the office's door boxes cost the driven office two arrivals).
  const InteractionSettings settings = defaultSettings();
  const ObjectInteractions result =
      planObjectInteractions(test::faceOnlyFireDoorScene(), 0, ObjectPhysics{0.4, 20.0}, settings);
  ASSERT_EQ(result.plans.size(), 2U);
  for (const PairPlan& pair : result.plans) {
    const PushPlan& plan = pair.plan;
    ASSERT_EQ(plan.status, PlanStatus::Found) << toString(plan.status);
    expectControlsConsistent(plan);
    ASSERT_FALSE(plan.controls.empty());
    EXPECT_TRUE(turns(plan.controls.front()));
  }
}

/// How deep the real box reaches into `walls` at any control's end: the box is `depth` deep along
/// `inward` (body frame, unit) from the face of the plan's footprint that `inward` points away from, as
/// wide as the footprint; points every 1 % of each side.
double deepestIntoWalls(const PushPlan& plan, const Point& inward, double depth,
                        const std::vector<geometry::Polygon>& walls)
{
  const Point lateral(-inward.y(), inward.x());
  double near = std::numeric_limits<double>::infinity();
  double low = near;
  double high = -near;
  for (const Point& vertex : plan.footprint) {
    near = std::min(near, vertex.dot(inward));
    low = std::min(low, vertex.dot(lateral));
    high = std::max(high, vertex.dot(lateral));
  }
  const geometry::Polygon real = {inward * near + lateral * low, inward * (near + depth) + lateral * low,
                                  inward * (near + depth) + lateral * high, inward * near + lateral * high};
  double deepest = 0.0;
  for (const PushControl& control : plan.controls) {
    for (std::size_t side = 0; side < real.size(); ++side) {
      const Point& from = real[side];
      const Point& to = real[(side + 1) % real.size()];
      for (int step = 0; step <= 100; ++step) {
        const Point world = control.object_pose.transform(from + (to - from) * (step / 100.0));
        for (const geometry::Polygon& wall : walls) {
          if (geometry::locatePoint(wall, world) == geometry::Containment::Inside) {
            deepest = std::max(deepest, geometry::distanceToBoundary(wall, world));
          }
        }
      }
    }
  }
  return deepest;
}

TEST(PushSearchTest, AFaceOnlyBoxIsNotPushedIntoAWallByItsUnseenDepth)
{
  // Driven Willow t0 turned the east corridor's box, seen by its north face, into a side room's 0.8 m
  // gap: the face alone fitted, the real box, 0.5 m deep, caught the gap's far corner and jammed (the
  // wall there, seen as a thin shell, let the corner through as well: docs/interaction.md, Limits).
  // Here the face alone is pushed straight east until it nearly meets the wall behind the door, and the
  // real box would be 0.12 m into that wall. Taken to be unseen_depth_m (0.5 m) deep, it is turned aside
  // short of the wall instead.
  InteractionSettings settings = defaultSettings();
  const LocalScene scene = test::faceOnlyDoorwayWithWallBehindScene();
  const PushPlan plan = eastwardPlan(planObjectInteractions(scene, 0, ObjectPhysics{0.4, 20.0}, settings));
  ASSERT_EQ(plan.status, PlanStatus::Found) << toString(plan.status);
  expectControlsConsistent(plan);
  EXPECT_TRUE(std::any_of(plan.controls.begin(), plan.controls.end(), turns));
  EXPECT_LT(deepestIntoWalls(plan, Point(1.0, 0.0), 0.5, test::faceOnlyDoorwayWithWallBehindRealWalls()),
            0.01);

  settings.search.unseen_depth_m = 0.0;  // as thin as the face seen
  const PushPlan thin = eastwardPlan(planObjectInteractions(scene, 0, ObjectPhysics{0.4, 20.0}, settings));
  ASSERT_EQ(thin.status, PlanStatus::Found) << toString(thin.status);
  EXPECT_GT(deepestIntoWalls(thin, Point(1.0, 0.0), 0.5, test::faceOnlyDoorwayWithWallBehindRealWalls()),
            0.1);
}

TEST(PushSearchTest, ABarFillingATunnelIsPushedAlongItIntoTheNextJunctionByTheCorridorPush)
{
  // The bar can only go along its tunnel: no push within 4 or 8 m leaves the way on open (exhausted). The
  // corridor push drives it straight on until the vehicle behind it can turn off at the next junction,
  // leaving the bar in the branch straight ahead; where the tunnel ends instead, nothing opens the way.
  InteractionSettings settings = defaultSettings();
  settings.search.extended_search_radius_m = 8.0;
  const auto southward = [](const ObjectInteractions& interactions, const PairPlan& pair) {
    return interactions.connectivity.waypoints[pair.pair.from].position.y() >
           interactions.connectivity.waypoints[pair.pair.to].position.y();
  };
  const auto southwardPlan = [&](const ObjectInteractions& interactions) {
    for (const PairPlan& pair : interactions.plans) {
      if (southward(interactions, pair)) {
        return pair.plan;
      }
    }
    ADD_FAILURE() << "no southward pair";
    return PushPlan{};
  };
  const ObjectPhysics light{0.4, 20.0};
  const ObjectInteractions without =
      planObjectInteractions(test::barInATunnelScene(true), 0, light, settings);
  EXPECT_EQ(southwardPlan(without).status, PlanStatus::Exhausted) << toString(southwardPlan(without).status);

  settings.search.corridor_push_length_m = 60.0;
  ASSERT_GE(sceneMargin(settings), 60.0) << "the scene must reach as far as the corridor push looks";
  const PushPlan through =
      southwardPlan(planObjectInteractions(test::barInATunnelScene(true), 0, light, settings));
  ASSERT_EQ(through.status, PlanStatus::Found) << toString(through.status);
  ASSERT_EQ(through.controls.size(), 1U);
  EXPECT_EQ(through.controls.front().kind, ControlKind::Straight);
  expectControlsConsistent(through);
  const Pose2 end = through.controls.back().object_pose;
  const double top = spanInY(through.footprint, end).second;
  // Into the crossing tunnel (y from -40 to -36), far enough that the vehicle (0.7 m wide) fits between the
  // bar and the crossing's north corners, and no further: the first pose that opens a way on is taken.
  EXPECT_LT(top, -36.0 - 0.7) << "the bar ends at y " << end.y;
  EXPECT_GT(top, -36.0 - 0.7 - 1.0) << "the bar ends at y " << end.y;
  EXPECT_NEAR(end.x, through.start_object_pose.x, 1e-9);
  EXPECT_NEAR(through.push_distance_m, through.start_object_pose.y - end.y, 1e-9);
  EXPECT_NEAR(through.cost,
              through.travel_distance_m + through.push_work_nm / settings.search.reference_force_n, 1e-9);

  const PushPlan dead_end =
      southwardPlan(planObjectInteractions(test::barInATunnelScene(false), 0, light, settings));
  EXPECT_EQ(dead_end.status, PlanStatus::Exhausted) << toString(dead_end.status);
}

TEST(PushSearchTest, NearWallNeedsAContactSwitch)
{
  const LocalScene scene = test::doorwayWithNearWallScene();
  const InteractionSettings settings = defaultSettings();
  const ObjectInteractions result = planObjectInteractions(scene, 0, ObjectPhysics{0.4, 20.0}, settings);
  ASSERT_EQ(result.plans.size(), 2U);
  for (const PairPlan& pair : result.plans) {
    ASSERT_EQ(pair.plan.status, PlanStatus::Found) << toString(pair.plan.status);
    expectNoWallHit(pair.plan, scene.background, settings.pusher.inflation_m);
    expectControlsConsistent(pair.plan);
    EXPECT_GE(passageClearance(pair.plan, result.connectivity.waypoints[pair.pair.from].position,
                               result.connectivity.waypoints[pair.pair.to].position),
              0.32);
    if (result.connectivity.waypoints[pair.pair.from].position.x() < 0.0) {
      const auto switched =
          std::find_if(pair.plan.controls.begin(), pair.plan.controls.end(),
                       [](const PushControl& control) { return control.kind == ControlKind::ContactSwitch; });
      ASSERT_NE(switched, pair.plan.controls.end());
      EXPECT_GT(switched->distance_m, 0.5);
      EXPECT_NEAR(pair.plan.cost, pair.plan.push_work_nm / 100.0 + pair.plan.travel_distance_m, 1e-9);
      for (const geometry::Polygon& wall : scene.background) {
        EXPECT_FALSE(geometry::containsPoint(wall, switched->vehicle_pose.position()));
      }
    }
  }
}

PushProblemObject doorwayProblem(const ObjectPhysics& physics)
{
  const LocalScene scene = test::doorwayScene();
  return PushProblemObject{scene.movable[0], scene.background, physics};
}

TEST(PushSearchTest, BadPhysicsGivesReasons)
{
  const InteractionSettings settings = defaultSettings();
  const auto status = [&](const ObjectPhysics& physics, const PusherSettings& pusher) {
    return PushPlanner(doorwayProblem(physics), pusher, settings.search, settings.connectivity)
        .plan(Point(-1.1, 0.0), Point(1.1, 0.0))
        .status;
  };
  EXPECT_EQ(status(ObjectPhysics{0.0, 20.0}, settings.pusher), PlanStatus::InvalidPhysics);
  EXPECT_EQ(status(ObjectPhysics{0.4, -1.0}, settings.pusher), PlanStatus::InvalidPhysics);
  EXPECT_EQ(status(ObjectPhysics{0.4, std::nan("")}, settings.pusher), PlanStatus::InvalidPhysics);
  EXPECT_EQ(status(ObjectPhysics{0.9, 500.0}, settings.pusher), PlanStatus::TooHeavy);
  PusherSettings slippery = settings.pusher;
  slippery.bumper_friction = 0.0;
  EXPECT_EQ(status(ObjectPhysics{0.4, 20.0}, slippery), PlanStatus::NoStableContact);
}

TEST(PushSearchTest, DegenerateObjectsGiveReasons)
{
  const InteractionSettings settings = defaultSettings();
  const auto status = [&](const geometry::Polygon& object) {
    PushProblemObject problem = doorwayProblem(ObjectPhysics{0.4, 20.0});
    problem.object = object;
    return PushPlanner(problem, settings.pusher, settings.search, settings.connectivity)
        .plan(Point(-1.1, 0.0), Point(1.1, 0.0))
        .status;
  };
  EXPECT_EQ(status({Point(0, 0), Point(1, 0)}), PlanStatus::DegeneratePolygon);
  EXPECT_EQ(status({Point(0, 0), Point(1, 0), Point(2, 1e-7)}), PlanStatus::DegeneratePolygon);
  EXPECT_EQ(status({Point(0, 0), Point(1, 1), Point(1, 0), Point(0, 1)}), PlanStatus::DegeneratePolygon);
  EXPECT_EQ(status({}), PlanStatus::DegeneratePolygon);
  EXPECT_EQ(status(rectangle(-50.0, -1.0, 50.0, 1.0)), PlanStatus::ObjectTooLarge);
}

TEST(PushSearchTest, EnclosedObjectHasUnreachableContacts)
{
  // Walls 0.2 m (real) round every face: no standing point is free.
  PushProblemObject problem;
  problem.object = rectangle(-0.6, -0.6, 0.6, 0.6);
  problem.obstacles = {rectangle(-2.0, 0.4, 2.0, 2.0), rectangle(-2.0, -2.0, 2.0, -0.4),
                       rectangle(-2.0, -2.0, -0.4, 2.0), rectangle(0.4, -2.0, 2.0, 2.0)};
  const InteractionSettings settings = defaultSettings();
  const PushPlanner planner(problem, settings.pusher, settings.search, settings.connectivity);
  EXPECT_EQ(planner.status(), PlanStatus::Found);
  EXPECT_EQ(planner.plan(Point(3.0, 0.0), Point(-3.0, 0.0)).status, PlanStatus::UnreachableContact);
}

TEST(PushSearchTest, WaypointsInsideObstaclesAreRejected)
{
  const InteractionSettings settings = defaultSettings();
  const PushPlanner planner(doorwayProblem(ObjectPhysics{0.4, 20.0}), settings.pusher, settings.search,
                            settings.connectivity);
  EXPECT_EQ(planner.plan(Point(0.0, 2.0), Point(1.1, 0.0)).status, PlanStatus::InvalidWaypoints);
  EXPECT_EQ(planner.plan(Point(1.1, 0.0), Point(1.1, 0.0)).status, PlanStatus::InvalidWaypoints);
  EXPECT_EQ(planner.plan(Point(std::nan(""), 0.0), Point(1.1, 0.0)).status, PlanStatus::InvalidWaypoints);
}

TEST(PushSearchTest, BudgetsStopTheSearch)
{
  InteractionSettings settings = defaultSettings();
  settings.search.analytic_max_distance_m = 0.0;  // no shortcut: the search has to expand
  settings.search.max_expansions = 2;
  const PushProblemObject problem = doorwayProblem(ObjectPhysics{0.4, 20.0});
  const PushPlan limited = PushPlanner(problem, settings.pusher, settings.search, settings.connectivity)
                               .plan(Point(-1.1, 0.0), Point(1.1, 0.0));
  EXPECT_EQ(limited.status, PlanStatus::ExpansionLimit);
  EXPECT_EQ(limited.expansions, 2U);
  settings.search.max_expansions = 100000;
  settings.search.time_budget_s = 0.0;
  EXPECT_EQ(PushPlanner(problem, settings.pusher, settings.search, settings.connectivity)
                .plan(Point(-1.1, 0.0), Point(1.1, 0.0))
                .status,
            PlanStatus::TimeBudget);
}

TEST(PushSearchTest, SearchWithoutAnalyticExpansionStillFindsThePlan)
{
  InteractionSettings settings = defaultSettings();
  settings.search.analytic_max_distance_m = 0.0;
  const PushPlan plan = PushPlanner(doorwayProblem(ObjectPhysics{0.4, 20.0}), settings.pusher,
                                    settings.search, settings.connectivity)
                            .plan(Point(-1.1, 0.0), Point(1.1, 0.0));
  ASSERT_EQ(plan.status, PlanStatus::Found) << toString(plan.status);
  EXPECT_GE(passageClearance(plan, Point(-1.1, 0.0), Point(1.1, 0.0)), 0.32);
  expectControlsConsistent(plan);
}

}  // namespace
}  // namespace ifar::interaction
