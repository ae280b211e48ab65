// The planner with interaction planning on simulated VLP-16 packets of config/worlds/demo_room.yaml: the
// light box in the 1.4 m doorway at (8, 16) is pushed instead of driving round through the east doorway,
// its id is stable, AFFORDANCE re-plans or removes its edges, FAR mode never pushes.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "planner/core/frame_assembler.hpp"
#include "planner/core/planner.hpp"
#include "planner/perception/motion_compensation.hpp"
#include "sim/world/world_file.hpp"
#include "testing/simulated_feed.hpp"

namespace ifar::planner {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const geometry::Point kDoorwayBox(8.0, 16.0);
const geometry::Point kGoal(8.0, 26.0);

const sim::World& demoRoom()
{
  static const sim::World world = [] {
    const sim::WorldResult loaded =
        sim::loadWorldFile(std::string(IFAR_SOURCE_DIR) + "/config/worlds/demo_room.yaml");
    EXPECT_TRUE(loaded.ok()) << loaded.error();
    return loaded.ok() ? loaded.world() : sim::World{};
  }();
  return world;
}

/// Frames of the vehicle standing at the demo room's start (8, 4) facing the doorway.
const std::vector<FrameInput>& standingFrames()
{
  static const std::vector<FrameInput> frames = [] {
    FrameAssembler assembler{InputSettings{}};
    return test_support::feedAll(test_support::recordSimulation(demoRoom(), 0.45), assembler);
  }();
  return frames;
}

/// Frames of the vehicle standing at (8, 12) facing the doorway, as if it had driven up: from the start
/// the heavy box at (12, 10) hides part of the partition, and the search rightly tries that gap. Long
/// enough (graph.votes frames) for the merge to drop the corners of that gap.
const std::vector<FrameInput>& approachFrames()
{
  static const std::vector<FrameInput> frames = [] {
    sim::World world = demoRoom();
    world.start = geometry::Pose2{8.0, 12.0, M_PI / 2.0};
    FrameAssembler assembler{InputSettings{}};
    return test_support::feedAll(test_support::recordSimulation(world, 1.25), assembler);
  }();
  return frames;
}

FrameResult runFrames(Planner& planner, const std::vector<FrameInput>& frames)
{
  EXPECT_TRUE(planner.setGoal(Goal{3, kGoal}));
  FrameResult result;
  for (const FrameInput& frame : frames) {
    result = planner.processFrame(frame);
  }
  return result;
}

/// Standing at the start, then near the doorway.
FrameResult runStartThenApproach(Planner& planner)
{
  runFrames(planner, standingFrames());
  return runFrames(planner, approachFrames());
}

/// The stable id of the movable outline nearest `near` (0 when there is none within a metre).
std::int64_t objectNear(const FrameResult& result, const geometry::Point& near)
{
  for (std::size_t index = 0; index < result.polygons.size(); ++index) {
    if (result.polygon_ids[index] > 0 &&
        (geometry::centroid(result.polygons[index].vertices) - near).norm() < 1.0) {
      return result.polygon_ids[index];
    }
  }
  return 0;
}

/// x where the path first crosses the line y = `y`.
std::optional<double> crossingX(const PlannedPath& path, double y)
{
  for (std::size_t index = 1; index < path.waypoints.size(); ++index) {
    const geometry::Point& a = path.waypoints[index - 1].position;
    const geometry::Point& b = path.waypoints[index].position;
    if ((a.y() - y) * (b.y() - y) <= 0.0 && a.y() != b.y()) {
      return a.x() + (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y());
    }
  }
  return std::nullopt;
}

TEST(InteractionPlanner, DemoRoomPushesTheDoorwayBoxInsteadOfDrivingRound)
{
  ASSERT_GE(standingFrames().size(), 3U);
  Planner planner{PlannerSettings{}};
  const FrameResult result = runFrames(planner, standingFrames());
  const std::int64_t box = objectNear(result, kDoorwayBox);
  ASSERT_GT(box, 0);
  ASSERT_TRUE(result.path.valid) << result.status.message;
  ASSERT_EQ(result.path.pushes.size(), 1U);
  const PathPush& push = result.path.pushes.front();
  EXPECT_EQ(push.object_id, box);
  EXPECT_EQ(push.to_waypoint, push.from_waypoint + 1);
  EXPECT_EQ(push.plan.status, interaction::PlanStatus::Found);
  EXPECT_FALSE(push.plan.controls.empty());
  EXPECT_DOUBLE_EQ(push.affordance, interaction::ObjectPhysics{}.ground_friction);
  // Waypoint kinds: both ends are topological waypoints of the box, the push lands on the second.
  const graph::PathPoint& from = result.path.waypoints[push.from_waypoint];
  const graph::PathPoint& to = result.path.waypoints[push.to_waypoint];
  const auto kindOf = [&](graph::VertexId id) {
    const graph::Vertex* vertex = planner.graph().vertex(id);
    return vertex != nullptr ? static_cast<int>(vertex->kind) : -1;
  };
  EXPECT_EQ(kindOf(from.vertex), static_cast<int>(graph::VertexKind::TopologicalWaypoint));
  EXPECT_EQ(kindOf(to.vertex), static_cast<int>(graph::VertexKind::TopologicalWaypoint));
  EXPECT_EQ(from.interaction, graph::kNoInteraction);
  EXPECT_NE(to.interaction, graph::kNoInteraction);
  EXPECT_EQ(to.object_id, box);
  EXPECT_EQ(push.from_vertex, from.vertex);
  EXPECT_EQ(push.to_vertex, to.vertex);
  // South of the box before, north of it after, straight through the doorway.
  EXPECT_LT(from.position.y(), 16.0);
  EXPECT_GT(to.position.y(), 16.0);
  EXPECT_NEAR(from.position.x(), 8.0, 0.3);
  const std::optional<double> crossing = crossingX(result.path, 16.0);
  ASSERT_TRUE(crossing);
  EXPECT_NEAR(*crossing, 8.0, 0.3);

  EXPECT_GT(result.status.timings.interaction_ms, 0.0);

  // Cheaper than going round: near the doorway (the whole partition in view) the same frames in FAR mode
  // go through the east doorway, while the planner still pushes the box with the same id.
  const FrameResult near = runFrames(planner, approachFrames());
  ASSERT_EQ(near.path.pushes.size(), 1U);
  EXPECT_EQ(near.path.pushes.front().object_id, box);
  PlannerSettings far_settings;
  far_settings.interaction_enabled = false;
  Planner far_planner{far_settings};
  const FrameResult around = runStartThenApproach(far_planner);
  ASSERT_TRUE(around.path.valid);
  EXPECT_LT(near.path.cost, around.path.cost);
  const std::optional<double> around_crossing = crossingX(around.path, 16.0);
  ASSERT_TRUE(around_crossing);
  EXPECT_GT(*around_crossing, 24.0);
  EXPECT_LT(*around_crossing, 28.0);
}

TEST(InteractionPlanner, UnpushableBoxIsDroppedAtOnceAndForGood)
{
  Planner planner{PlannerSettings{}};
  const FrameResult pushed = runStartThenApproach(planner);
  const std::int64_t box = objectNear(pushed, kDoorwayBox);
  ASSERT_EQ(pushed.path.pushes.size(), 1U);
  EXPECT_EQ(pushed.path.pushes.front().object_id, box);
  const std::int64_t edges_before = pushed.status.interaction_edges;

  AffordanceUpdate update;
  update.object_id = box;
  update.pushable = false;
  const FrameResult result = planner.applyAffordance(update);
  EXPECT_EQ(result.sequence, pushed.sequence);  // no frame needed
  ASSERT_TRUE(result.path.valid) << result.status.message;
  EXPECT_TRUE(result.path.pushes.empty());
  EXPECT_LT(result.status.interaction_edges, edges_before);
  const std::optional<double> crossing = crossingX(result.path, 16.0);
  ASSERT_TRUE(crossing);
  EXPECT_GT(*crossing, 24.0);
  EXPECT_LT(*crossing, 28.0);
  EXPECT_EQ(result.status.bad_inputs, 0);

  // Later frames never bring the edges back.
  const FrameResult later = planner.processFrame(approachFrames().back());
  EXPECT_TRUE(later.path.pushes.empty());
  for (const graph::InteractionEdge& edge : planner.graph().interactionEdges()) {
    EXPECT_FALSE(edge.alive && edge.object_id == box);
  }
  // A later estimate that calls it pushable does not either.
  update.pushable = true;
  update.affordance = 0.3;
  EXPECT_TRUE(planner.applyAffordance(update).path.pushes.empty());
}

/// A 12 m room split at y = 6 by a partition with a 2 m doorway (x 5 to 7). A box fills the doorway from
/// its right post to `gap_m` short of the left one; movable (a tagged box) or a wall (control).
sim::World doorwayWithBox(double gap_m, bool movable)
{
  sim::World world;
  world.name = "doorway_with_box";
  world.bounds_min = geometry::Point(0.0, 0.0);
  world.bounds_max = geometry::Point(12.0, 12.0);
  const auto wall = [&world](const std::string& name, double x0, double y0, double x1, double y1) {
    sim::StaticObstacle obstacle;
    obstacle.name = name;
    obstacle.outline = {geometry::Point(x0, y0), geometry::Point(x1, y0), geometry::Point(x1, y1),
                        geometry::Point(x0, y1)};
    world.obstacles.push_back(obstacle);
  };
  wall("south", 0.0, 0.0, 12.0, 0.3);
  wall("north", 0.0, 11.7, 12.0, 12.0);
  wall("west", 0.0, 0.3, 0.3, 11.7);
  wall("east", 11.7, 0.3, 12.0, 11.7);
  wall("partition_west", 0.3, 5.85, 5.0, 6.15);
  wall("partition_east", 7.0, 5.85, 11.7, 6.15);
  const double box_left = 5.0 + gap_m;
  const double half_width = (7.0 - box_left) / 2.0;
  if (movable) {
    sim::MovableObject box;
    box.id = 1;
    box.name = "box";
    box.outline = {geometry::Point(-half_width, -0.25), geometry::Point(half_width, -0.25),
                   geometry::Point(half_width, 0.25), geometry::Point(-half_width, 0.25)};
    box.pose = geometry::Pose2{box_left + half_width, 6.0, 0.0};
    box.mass_kg = 30.0;
    world.objects.push_back(box);
  } else {
    wall("box", box_left, 5.75, 7.0, 6.25);
  }
  world.start = geometry::Pose2{5.5, 3.0, M_PI / 2.0};
  world.goals.push_back(sim::Goal{"goal", geometry::Point(5.5, 9.0)});
  return world;
}

/// Where the path for `world` seen from its start crosses the partition (none: no path through it).
std::optional<double> doorwayCrossing(const sim::World& world, bool interaction, FrameResult& result)
{
  PlannerSettings settings;
  settings.interaction_enabled = interaction;
  Planner planner{settings};
  EXPECT_TRUE(planner.setGoal(Goal{3, world.goals.front().position}));
  FrameAssembler assembler{InputSettings{}};
  for (const FrameInput& frame :
       test_support::feedAll(test_support::recordSimulation(world, 1.25), assembler)) {
    result = planner.processFrame(frame);
  }
  if (!result.path.valid) {
    return std::nullopt;
  }
  return crossingX(result.path, 6.0);
}

// The vehicle is 0.7 m wide and the planner inflates every obstacle by half of that: a gap 0.1 m wider than
// the vehicle between a movable box and a wall stays open in the graph (the two classes are dilated in
// images of their own, so neither swallows the gap to the other), and the path takes it instead of pushing
// the box. Two walls 0.1 m apart more than the vehicle would merge (one class, one dilation): the gap has
// to be some 0.9 m before it opens between them, which the control shows.
TEST(InteractionPlanner, AGapBetweenAMovableBoxAndAWallThatTheVehicleFitsStaysOpen)
{
  const double gap_m = common::VehicleSettings{}.width_m + 0.1;
  for (const bool interaction : {false, true}) {
    FrameResult result;
    const std::optional<double> crossing = doorwayCrossing(doorwayWithBox(gap_m, true), interaction, result);
    ASSERT_TRUE(crossing.has_value()) << "interaction " << interaction << ": " << result.status.message;
    EXPECT_GT(*crossing, 5.0) << "interaction " << interaction;
    EXPECT_LT(*crossing, 5.0 + gap_m) << "interaction " << interaction;
    EXPECT_TRUE(result.path.pushes.empty()) << "interaction " << interaction;
  }
  FrameResult walls;
  EXPECT_FALSE(doorwayCrossing(doorwayWithBox(gap_m, false), false, walls).has_value());
  const std::optional<double> wider = doorwayCrossing(doorwayWithBox(gap_m + 0.1, false), false, walls);
  ASSERT_TRUE(wider.has_value()) << walls.status.message;
  EXPECT_LT(*wider, 5.0 + gap_m + 0.1);
}

// A contact the vehicle did not reach is no force evidence: the light box stays pushable. The first report
// plans it again at once, the next suspends its pushes for contact_backoff_s, after which they come back;
// the back-offs per goal are bounded, and a new goal lifts them.
TEST(InteractionPlanner, AContactNotReachedKeepsTheBoxPushableAndRetriesAfterABackOff)
{
  PlannerSettings settings;
  settings.interaction.loop.contact_retries = 1;
  settings.interaction.loop.contact_backoff_s = 5.0;
  settings.interaction.loop.contact_backoffs = 1;
  Planner planner{settings};
  const FrameResult pushed = runStartThenApproach(planner);
  const std::int64_t box = objectNear(pushed, kDoorwayBox);
  ASSERT_EQ(pushed.path.pushes.size(), 1U);
  ASSERT_EQ(pushed.path.pushes.front().object_id, box);

  AffordanceUpdate update;
  update.object_id = box;
  update.pushable = true;
  update.contact_not_reached = true;
  const FrameResult retried = planner.applyAffordance(update);
  EXPECT_NE(retried.status.message.find("contact not reached, still pushable: planned again"),
            std::string::npos)
      << retried.status.message;
  ASSERT_EQ(retried.path.pushes.size(), 1U) << retried.status.message;
  EXPECT_EQ(retried.path.pushes.front().object_id, box);
  EXPECT_FALSE(planner.objectUnpushable(box));

  const FrameResult backed_off = planner.applyAffordance(update);
  EXPECT_TRUE(backed_off.path.pushes.empty());
  EXPECT_TRUE(planner.objectSuspended(box));
  EXPECT_FALSE(planner.objectUnpushable(box));
  EXPECT_EQ(backed_off.status.bad_inputs, 0);

  // Within the back-off the box gets no pushes; after it, it does again (it was never unpushable).
  FrameInput frame = approachFrames().back();
  frame.utime += 2'000'000;
  EXPECT_TRUE(planner.processFrame(frame).path.pushes.empty());
  frame.utime += 4'000'000;
  const FrameResult after = planner.processFrame(frame);
  ASSERT_EQ(after.path.pushes.size(), 1U) << after.status.message;
  EXPECT_EQ(after.path.pushes.front().object_id, box);

  // The one back-off of this goal is used: the next reports suspend the box until the goal changes.
  planner.applyAffordance(update);
  EXPECT_TRUE(planner.applyAffordance(update).path.pushes.empty());
  frame.utime += 60'000'000;
  EXPECT_TRUE(planner.processFrame(frame).path.pushes.empty());
  EXPECT_FALSE(planner.objectUnpushable(box));
  ASSERT_TRUE(planner.setGoal(Goal{4, kGoal}));
  frame.utime += 100'000;
  const FrameResult next_goal = planner.processFrame(frame);
  ASSERT_EQ(next_goal.path.pushes.size(), 1U) << next_goal.status.message;
  EXPECT_EQ(next_goal.path.pushes.front().object_id, box);
}

// The tracker loses the unpushable box (scans that do not show it) and finds it again under a new id:
// what AFFORDANCE said stays with it, so the vehicle is not sent to push it again.
TEST(InteractionPlanner, AnUnpushableBoxLostAndFoundAgainStaysUnpushable)
{
  Planner planner{PlannerSettings{}};
  const FrameResult pushed = runStartThenApproach(planner);
  const std::int64_t box = objectNear(pushed, kDoorwayBox);
  ASSERT_EQ(pushed.path.pushes.size(), 1U);
  AffordanceUpdate update;
  update.object_id = box;
  update.pushable = false;
  ASSERT_TRUE(planner.applyAffordance(update).path.pushes.empty());

  FrameInput blind = approachFrames().back();
  blind.points.clear();
  for (int frame = 0; frame < 10; ++frame) {
    blind.utime += 100'000;
    planner.processFrame(blind);
  }
  const FrameResult found = planner.processFrame(approachFrames().back());
  const std::int64_t again = objectNear(found, kDoorwayBox);
  EXPECT_NE(again, box) << "the tracker dropped the box while it was not seen";
  EXPECT_NE(found.status.message.find("keeps its affordance"), std::string::npos) << found.status.message;
  EXPECT_TRUE(found.path.pushes.empty());
  for (const graph::InteractionEdge& edge : planner.graph().interactionEdges()) {
    EXPECT_FALSE(edge.alive && edge.object_id == again);
  }
}

/// `frames` with no return from the doorway box's place or beyond it (within 1.2 m of the line of sight to
/// it): the rays that would show the box gone come back from nothing, as when it is hidden from the vehicle.
std::vector<FrameInput> nothingSeenAtTheDoorwayBox(std::vector<FrameInput> frames)
{
  for (FrameInput& frame : frames) {
    const Eigen::Isometry3d sensor =
        frame.motion.vehicle_at_end * perception::lidarMount(common::VehicleSettings{});
    const geometry::Point origin = sensor.translation().head<2>();
    const geometry::Vector to_box = kDoorwayBox - origin;
    const double half_angle = std::atan2(1.2, to_box.norm());
    frame.points.erase(std::remove_if(frame.points.begin(), frame.points.end(),
                                      [&](const perception::SensorPoint& point) {
                                        const geometry::Vector ray =
                                            (sensor * point.position_sensor.cast<double>()).head<2>() -
                                            origin;
                                        const double angle = std::abs(std::atan2(
                                            to_box.x() * ray.y() - to_box.y() * ray.x(), to_box.dot(ray)));
                                        return angle < half_angle && ray.norm() > to_box.norm() - 0.6;
                                      }),
                       frame.points.end());
  }
  return frames;
}

/// Frames at (8, 12) facing the doorway with the doorway box gone from the world and no return from its
/// place: it is out of sight.
const std::vector<FrameInput>& approachFramesWithoutTheBox()
{
  static const std::vector<FrameInput> frames = [] {
    sim::World world = demoRoom();
    world.start = geometry::Pose2{8.0, 12.0, M_PI / 2.0};
    world.objects.erase(std::remove_if(world.objects.begin(), world.objects.end(),
                                       [](const sim::MovableObject& object) {
                                         return (object.pose.position() - kDoorwayBox).norm() < 0.5;
                                       }),
                        world.objects.end());
    FrameAssembler assembler{InputSettings{}};
    return nothingSeenAtTheDoorwayBox(
        test_support::feedAll(test_support::recordSimulation(world, 1.25), assembler));
  }();
  return frames;
}

TEST(InteractionPlanner, AnUnpushableBoxOutOfSightStillClosesItsDoorway)
{
  // Found unpushable, then not seen (hidden behind a wall in the office world; here gone from the scan):
  // with the background memory it still closes the doorway, so the path keeps to the east doorway
  // (x 14) instead of flipping back through the box each time it is out of sight.
  for (const bool remember : {true, false}) {
    PlannerSettings settings;
    settings.perception.remember_background = remember;
    Planner planner{settings};
    const FrameResult pushed = runStartThenApproach(planner);
    ASSERT_EQ(pushed.path.pushes.size(), 1U) << "remember " << remember;
    AffordanceUpdate update;
    update.object_id = objectNear(pushed, kDoorwayBox);
    update.pushable = false;
    planner.applyAffordance(update);
    const FrameResult hidden = runFrames(planner, approachFramesWithoutTheBox());
    ASSERT_EQ(hidden.status.state, PlannerState::Planning) << hidden.status.message;
    const std::optional<double> crossing = crossingX(hidden.path, 16.0);
    ASSERT_TRUE(crossing.has_value());
    if (remember) {
      EXPECT_GT(*crossing, 12.0) << "the path goes through the unpushable box's doorway";
    } else {
      EXPECT_NEAR(*crossing, kDoorwayBox.x(), 0.5) << "control: without the memory the doorway looks open";
    }
  }
}

TEST(InteractionPlanner, FarModeRemembersABoxOutOfSightLikeAWall)
{
  // FAR mode knows no movable objects: the doorway box it saw stays an obstacle once out of sight.
  for (const bool remember : {true, false}) {
    PlannerSettings settings;
    settings.interaction_enabled = false;
    settings.perception.remember_background = remember;
    Planner planner{settings};
    const FrameResult seen = runStartThenApproach(planner);
    const std::optional<double> around = crossingX(seen.path, 16.0);
    ASSERT_TRUE(around.has_value());
    ASSERT_GT(*around, 12.0) << "FAR mode goes round the box it sees";
    const FrameResult hidden = runFrames(planner, approachFramesWithoutTheBox());
    const std::optional<double> crossing = crossingX(hidden.path, 16.0);
    ASSERT_TRUE(crossing.has_value()) << hidden.status.message;
    if (remember) {
      EXPECT_GT(*crossing, 12.0) << "the path goes through the box FAR mode saw";
    } else {
      EXPECT_NEAR(*crossing, kDoorwayBox.x(), 0.5) << "control: without the memory the doorway looks open";
    }
  }
}

// BLOCKED_PASSAGE: the vehicle could not get through the east doorway. The planner seals the doorway's
// narrowest point for good (also without the background memory), and the next frames route elsewhere.
TEST(InteractionPlanner, ABlockedPassageIsSealedAndRoutedAround)
{
  PlannerSettings settings;
  settings.interaction_enabled = false;  // FAR mode: the box closes the west doorway, the east one is the way
  settings.perception.remember_background = false;
  Planner planner{settings};
  const FrameResult before = runStartThenApproach(planner);
  const std::optional<double> east = crossingX(before.path, 16.0);
  ASSERT_TRUE(east.has_value()) << before.status.message;
  ASSERT_GT(*east, 24.0);
  ASSERT_LT(*east, 28.0);

  const FrameResult sealed =
      planner.applyBlockedPassage({geometry::Point(26.0, 13.0), geometry::Point(26.0, 19.0)});
  EXPECT_EQ(sealed.sequence, before.sequence);  // no frame needed
  EXPECT_NE(sealed.status.message.find("sealed at (26.00, 1"), std::string::npos) << sealed.status.message;
  EXPECT_EQ(sealed.status.bad_inputs, before.status.bad_inputs);
  // The 4 m doorway, 3.3 m between the inflated partition ends: a cell every 0.15 m across it.
  EXPECT_GE(planner.sealedCells(), 21U);

  // The doorway's old corners go once unseen for graph.votes frames (the approach frames are that long).
  const FrameResult after = runFrames(planner, approachFrames());
  ASSERT_TRUE(after.path.valid) << after.status.message;
  const std::optional<double> crossing = crossingX(after.path, 16.0);
  EXPECT_FALSE(crossing && *crossing > 24.0 && *crossing < 28.0)
      << "still through the sealed doorway at x = " << *crossing << ": " << after.status.message;
}

/// The area of the object's polygon in the frame (0 when it has none).
double objectArea(const FrameResult& result, std::int64_t object_id)
{
  for (std::size_t index = 0; index < result.polygons.size(); ++index) {
    if (result.polygon_ids[index] == object_id) {
      return std::abs(geometry::area(result.polygons[index].vertices));
    }
  }
  return 0.0;
}

// A blocked passage at a movable object (here the vehicle could not get past the doorway box) is kept
// with the object, not sealed for good: its outline takes in the seal's free cells from the next frame, and
// the seal goes once the object is pushed (AFFORDANCE with a measurement: it moved, the gap with it).
TEST(InteractionPlanner, ABlockedPassageAtAMovableObjectIsKeptWithItUntilItIsPushed)
{
  Planner planner{PlannerSettings{}};
  const FrameResult before = runStartThenApproach(planner);
  const std::int64_t box = objectNear(before, kDoorwayBox);
  ASSERT_GT(box, 0);
  const double area_before = objectArea(before, box);
  ASSERT_GT(area_before, 0.0);

  const FrameResult sealed =
      planner.applyBlockedPassage({geometry::Point(8.0, 12.5), geometry::Point(8.0, 19.0)});
  EXPECT_NE(sealed.status.message.find("kept with object " + std::to_string(box)), std::string::npos)
      << sealed.status.message;
  EXPECT_TRUE(planner.holdsObjectSeal(box));
  EXPECT_EQ(planner.sealedCells(), 0U);
  EXPECT_EQ(sealed.status.bad_inputs, before.status.bad_inputs);
  const FrameResult next = planner.processFrame(approachFrames().back());
  EXPECT_GT(objectArea(next, box), area_before + 0.1) << "the outline takes in the seal's cells";

  AffordanceUpdate measured;
  measured.object_id = box;
  measured.push_force_n = 40.0;
  planner.applyAffordance(measured);
  EXPECT_FALSE(planner.holdsObjectSeal(box));
  EXPECT_EQ(planner.sealedCells(), 0U);
  const FrameResult after = planner.processFrame(approachFrames().back());
  EXPECT_NEAR(objectArea(after, box), area_before, 1e-9);
}

TEST(InteractionPlanner, ASealKeptWithAnObjectFoundUnpushableBecomesAWall)
{
  Planner planner{PlannerSettings{}};
  const FrameResult before = runStartThenApproach(planner);
  const std::int64_t box = objectNear(before, kDoorwayBox);
  ASSERT_GT(box, 0);
  planner.applyBlockedPassage({geometry::Point(8.0, 12.5), geometry::Point(8.0, 19.0)});
  ASSERT_TRUE(planner.holdsObjectSeal(box));

  AffordanceUpdate unpushable;
  unpushable.object_id = box;
  unpushable.pushable = false;
  planner.applyAffordance(unpushable);
  EXPECT_FALSE(planner.holdsObjectSeal(box));
  EXPECT_GT(planner.sealedCells(), 0U);
}

/// A closed 12 m x 12 m room split at y = 6 by a wall with one 1.0 m door at x = 6; the vehicle stands at
/// (6, 3) facing it.
const std::vector<FrameInput>& oneDoorFrames()
{
  static const std::vector<FrameInput> frames = [] {
    const sim::WorldResult world = sim::parseWorld(R"(
name: one_door
units: m
start: {x: 6, y: 3, heading_deg: 90}
obstacles:
  - {name: south, polygon: [0, 0, 12, 0, 12, 0.2, 0, 0.2]}
  - {name: north, polygon: [0, 11.8, 12, 11.8, 12, 12, 0, 12]}
  - {name: west, polygon: [0, 0.2, 0.2, 0.2, 0.2, 11.8, 0, 11.8]}
  - {name: east, polygon: [11.8, 0.2, 12, 0.2, 12, 11.8, 11.8, 11.8]}
  - {name: left_of_door, polygon: [0.2, 5.9, 5.5, 5.9, 5.5, 6.1, 0.2, 6.1]}
  - {name: right_of_door, polygon: [6.5, 5.9, 11.8, 5.9, 11.8, 6.1, 6.5, 6.1]}
)",
                                                   "one_door");
    EXPECT_TRUE(world.ok()) << world.error();
    FrameAssembler assembler{InputSettings{}};
    return world.ok() ? test_support::feedAll(test_support::recordSimulation(world.world(), 1.25), assembler)
                      : std::vector<FrameInput>{};
  }();
  return frames;
}

// Seals are guesses from stalls (the follower may fail at a door the vehicle fits): when they leave no way
// at all, the planner forgets them and the route goes through the door again rather than stop.
TEST(InteractionPlanner, SealsThatLeaveNoPathAreForgotten)
{
  PlannerSettings settings;
  settings.perception.remember_background = false;
  Planner planner{settings};
  ASSERT_TRUE(planner.setGoal(Goal{4, geometry::Point(6.0, 9.0)}));
  FrameResult result;
  for (const FrameInput& frame : oneDoorFrames()) {
    result = planner.processFrame(frame);
  }
  ASSERT_TRUE(result.path.valid) << result.status.message;

  result = planner.applyBlockedPassage({geometry::Point(6.0, 4.5), geometry::Point(6.0, 7.5)});
  ASSERT_GT(planner.sealedCells(), 0U) << result.status.message;
  // From the next frame the layer holds the seal: no way is left, and the seals go.
  result = planner.processFrame(oneDoorFrames().front());
  EXPECT_FALSE(result.path.valid) << "the sealed door was the only way";
  EXPECT_NE(result.status.message.find("forgetting"), std::string::npos) << result.status.message;
  EXPECT_EQ(planner.sealedCells(), 0U);
  for (const FrameInput& frame : oneDoorFrames()) {
    result = planner.processFrame(frame);
  }
  ASSERT_TRUE(result.path.valid) << result.status.message;
  const std::optional<double> crossing = crossingX(result.path, 6.0);
  ASSERT_TRUE(crossing);
  EXPECT_NEAR(*crossing, 6.0, 0.5);
}

TEST(InteractionPlanner, ABlockedPassageThatCannotBeSealedIsCountedAndChangesNothing)
{
  Planner planner{PlannerSettings{}};
  const FrameResult early =
      planner.applyBlockedPassage({geometry::Point(1.0, 1.0), geometry::Point(2.0, 2.0)});
  EXPECT_NE(early.status.message.find("rejected: no frame placed yet"), std::string::npos)
      << early.status.message;
  const FrameResult before = runFrames(planner, standingFrames());
  const FrameResult bad =
      planner.applyBlockedPassage({geometry::Point(kNaN, 1.0), geometry::Point(2.0, 2.0)});
  EXPECT_NE(bad.status.message.find("must be finite"), std::string::npos) << bad.status.message;
  // Shorter than the distance the seal keeps from the vehicle.
  const FrameResult close =
      planner.applyBlockedPassage({geometry::Point(8.0, 4.0), geometry::Point(8.0, 4.2)});
  EXPECT_NE(close.status.message.find("no free point to seal"), std::string::npos) << close.status.message;
  EXPECT_EQ(planner.sealedCells(), 0U);
  EXPECT_EQ(planner.badInputs(), before.status.bad_inputs + 2);
}

TEST(InteractionPlanner, AffordanceChangesTheFrictionAndReplansAtOnce)
{
  Planner planner{PlannerSettings{}};
  const FrameResult pushed = runFrames(planner, standingFrames());
  const std::int64_t box = objectNear(pushed, kDoorwayBox);
  ASSERT_EQ(pushed.path.pushes.size(), 1U);
  const double cost_before = pushed.path.pushes.front().plan.cost;

  AffordanceUpdate update;
  update.object_id = box;
  update.affordance = 0.8;
  update.push_force_n = 500.0;  // mu wins over the force when both are given
  const FrameResult heavier = planner.applyAffordance(update);
  EXPECT_DOUBLE_EQ(planner.objectPhysics(box).ground_friction, 0.8);
  EXPECT_DOUBLE_EQ(planner.objectPhysics(box).mass_kg, interaction::ObjectPhysics{}.mass_kg);
  ASSERT_EQ(heavier.path.pushes.size(), 1U);
  EXPECT_DOUBLE_EQ(heavier.path.pushes.front().affordance, 0.8);
  EXPECT_GT(heavier.path.pushes.front().plan.cost, cost_before);
  EXPECT_NEAR(heavier.path.pushes.front().plan.expected_force_n,
              2.0 * pushed.path.pushes.front().plan.expected_force_n, 1e-6);

  // Only a force: mu = force / (mass g).
  update.affordance = 0.0;
  update.push_force_n = 39.24;
  const FrameResult lighter = planner.applyAffordance(update);
  EXPECT_NEAR(planner.objectPhysics(box).ground_friction, 39.24 / (20.0 * 9.81), 1e-12);
  ASSERT_EQ(lighter.path.pushes.size(), 1U);
  EXPECT_LT(lighter.path.pushes.front().plan.cost, cost_before);
  EXPECT_EQ(lighter.status.bad_inputs, 0);
}

TEST(InteractionPlanner, BadAffordanceIsCountedAndChangesNothing)
{
  Planner planner{PlannerSettings{}};
  const FrameResult pushed = runFrames(planner, standingFrames());
  const std::int64_t box = objectNear(pushed, kDoorwayBox);
  ASSERT_EQ(pushed.path.pushes.size(), 1U);

  AffordanceUpdate unknown;
  unknown.object_id = 9999;
  unknown.pushable = false;
  const FrameResult unknown_result = planner.applyAffordance(unknown);
  EXPECT_EQ(unknown_result.status.bad_inputs, pushed.status.bad_inputs + 1);
  EXPECT_NE(unknown_result.status.message.find("9999"), std::string::npos) << unknown_result.status.message;
  EXPECT_NE(unknown_result.status.message.find("no such object"), std::string::npos);
  EXPECT_EQ(unknown_result.path.pushes.size(), 1U);

  for (const auto& [force, mu] : {std::pair<double, double>{kNaN, 0.5}, std::pair<double, double>{50.0, kNaN},
                                  std::pair<double, double>{std::numeric_limits<double>::infinity(), 0.0}}) {
    AffordanceUpdate bad;
    bad.object_id = box;
    bad.pushable = false;  // must not be acted on either
    bad.push_force_n = force;
    bad.affordance = mu;
    const FrameResult result = planner.applyAffordance(bad);
    EXPECT_NE(result.status.message.find("finite"), std::string::npos) << result.status.message;
    EXPECT_EQ(result.path.pushes.size(), 1U);
    EXPECT_DOUBLE_EQ(planner.objectPhysics(box).ground_friction,
                     interaction::ObjectPhysics{}.ground_friction);
  }
  EXPECT_EQ(planner.badInputs(), pushed.status.bad_inputs + 4);
}

TEST(InteractionPlanner, FarModeNeverPushes)
{
  PlannerSettings settings;
  settings.interaction_enabled = false;
  Planner planner{settings};
  const FrameResult result = runFrames(planner, standingFrames());
  ASSERT_TRUE(result.path.valid);
  EXPECT_TRUE(result.path.pushes.empty());
  EXPECT_EQ(result.status.interaction_edges, 0);
  EXPECT_EQ(result.status.timings.interaction_ms >= 0.0, true);
  for (const graph::Vertex& vertex : planner.graph().vertexSlots()) {
    EXPECT_FALSE(vertex.alive && vertex.kind == graph::VertexKind::TopologicalWaypoint);
  }
  // Ids are tracked all the same (the daemon's polygon ids).
  EXPECT_GT(objectNear(result, kDoorwayBox), 0);
}

TEST(InteractionPlanner, ObjectKeepsItsIdWhileTheVehicleDrivesTwoMetres)
{
  FrameAssembler assembler{InputSettings{}};
  const std::vector<FrameInput> frames =
      test_support::feedAll(test_support::recordSimulation(demoRoom(), 3.0, 1.0), assembler);
  ASSERT_GE(frames.size(), 10U);
  Planner planner{PlannerSettings{}};
  ASSERT_TRUE(planner.setGoal(Goal{3, kGoal}));
  std::int64_t doorway_id = 0;
  std::int64_t heavy_id = 0;
  int frames_seen = 0;
  geometry::Point first_position = geometry::Point::Zero();
  geometry::Point last_position = geometry::Point::Zero();
  for (std::size_t index = 0; index < frames.size(); ++index) {
    const FrameResult result = planner.processFrame(frames[index]);
    const geometry::Point position = frames[index].motion.vehicle_at_end.translation().head<2>();
    if (index == 0) {
      first_position = position;
    }
    last_position = position;
    const std::int64_t doorway = objectNear(result, kDoorwayBox);
    const std::int64_t heavy = objectNear(result, geometry::Point(12.0, 10.0));
    ASSERT_GT(doorway, 0) << "frame " << index;
    ASSERT_GT(heavy, 0) << "frame " << index;
    if (index == 0) {
      doorway_id = doorway;
      heavy_id = heavy;
    }
    EXPECT_EQ(doorway, doorway_id) << "frame " << index;
    EXPECT_EQ(heavy, heavy_id) << "frame " << index;
    EXPECT_NE(doorway, heavy);
    ++frames_seen;
    for (const PathPush& push : result.path.pushes) {
      EXPECT_EQ(push.object_id, doorway_id);
    }
  }
  EXPECT_GE(frames_seen, 10);
  EXPECT_GE((last_position - first_position).norm(), 2.0);
  // Moving closer does not make a new plan every frame: the cache keeps the plans of an unmoved object
  // and replans only when much more of its surroundings came into view.
  EXPECT_LT(planner.interactionPlans(doorway_id), frames.size() / 2);
}

TEST(InteractionPlanner, FrameBudgetSharesObjectsRoundRobin)
{
  PlannerSettings settings;
  settings.interaction.loop.frame_budget_ms = 1e-9;  // one object per frame
  Planner planner{settings};
  ASSERT_TRUE(planner.setGoal(Goal{3, kGoal}));
  const FrameResult first = planner.processFrame(standingFrames()[0]);
  std::vector<std::int64_t> ids;
  for (const std::int64_t id : first.polygon_ids) {
    if (id > 0) {
      ids.push_back(id);
    }
  }
  ASSERT_GE(ids.size(), 2U);
  std::size_t planned = 0;
  for (const std::int64_t id : ids) {
    planned += planner.interactionPlans(id) > 0 ? 1U : 0U;
  }
  EXPECT_EQ(planned, 1U);
  for (std::size_t frame = 1; frame < ids.size(); ++frame) {
    planner.processFrame(standingFrames()[frame % standingFrames().size()]);
  }
  for (const std::int64_t id : ids) {
    EXPECT_EQ(planner.interactionPlans(id), 1U) << "object " << id;
  }
}

}  // namespace
}  // namespace ifar::planner
