// The planner frame pipeline on simulated VLP-16 packets, and every kind of bad input issue 5 names.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "planner/core/frame_assembler.hpp"
#include "planner/core/planner.hpp"
#include "planner/graph/graph_file.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/world/world_geometry.hpp"
#include "testing/simulated_feed.hpp"

namespace ifar::planner {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Box of 0.6 m centred at (3.5, 6) in a 12 m room; the vehicle stands at (2, 6) facing it.
const std::vector<test_support::FeedRecord>& pushRoomRecords()
{
  static const std::vector<test_support::FeedRecord> records =
      test_support::recordSimulation(sim::builtinPushRoom(200.0), 0.35);
  return records;
}

std::vector<FrameInput> pushRoomFrames()
{
  FrameAssembler assembler{InputSettings{}};
  return test_support::feedAll(pushRoomRecords(), assembler);
}

/// A frame with valid motion: the vehicle still at (2, 6) facing +x.
FrameInput stillFrame()
{
  FrameInput frame;
  frame.utime = 1'000'000;
  frame.has_motion = true;
  frame.motion.vehicle_at_start.translation() = Eigen::Vector3d(2.0, 6.0, 0.0);
  frame.motion.vehicle_at_end = frame.motion.vehicle_at_start;
  frame.motion.duration_s = 0.1;
  return frame;
}

TEST(PlannerCore, SimulatedRoomGivesPolygonsGraphAndPathAroundTheBox)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_GE(frames.size(), 2U);
  Planner planner{PlannerSettings{}};
  ASSERT_TRUE(planner.setGoal(Goal{7, geometry::Point(6.0, 6.0)}));
  const FrameResult result = planner.processFrame(frames[1]);

  EXPECT_EQ(result.status.state, PlannerState::Planning) << result.status.message;
  EXPECT_EQ(result.status.flags, 0) << result.status.message;
  EXPECT_GE(result.status.polygons, 2);  // the room's walls and the box
  bool has_movable = false;
  for (const auto& polygon : result.polygons) {
    has_movable = has_movable || polygon.obstacle_class == perception::ObstacleClass::Movable;
  }
  EXPECT_TRUE(has_movable);
  EXPECT_GE(result.status.vertices, 4);
  EXPECT_GT(result.status.edges, 0);
  EXPECT_EQ(result.sequence, 1);

  ASSERT_TRUE(result.path.valid);
  EXPECT_EQ(result.path.goal_id, 7);
  ASSERT_GE(result.path.waypoints.size(), 3U);  // must bend around the inflated box
  EXPECT_NEAR(result.path.waypoints.front().position.x(), 2.0, 0.05);
  EXPECT_NEAR(result.path.waypoints.front().position.y(), 6.0, 0.05);
  EXPECT_NEAR(result.path.waypoints.back().position.x(), 6.0, 1e-9);
  EXPECT_NEAR(result.path.waypoints.back().position.y(), 6.0, 1e-9);
  EXPECT_GT(result.path.length_m, 4.0 + 1e-3);  // longer than the blocked straight line
  EXPECT_LT(result.path.length_m, 5.5);
  // The box spans y 5.7..6.3; its inflated outline (rounded, simplified corners) keeps a waypoint at
  // least 0.45 m from the centre line.
  bool beside_box = false;
  for (const auto& waypoint : result.path.waypoints) {
    beside_box = beside_box || std::abs(waypoint.position.y() - 6.0) >= 0.45;
  }
  EXPECT_TRUE(beside_box);

  EXPECT_GT(result.status.timings.total_ms, 0.0);
}

// Issue 5: polygons from a simulated scan of a known world match the world's inflated obstacles within two
// cells. Every vertex the planner extracts from the simulator's VLP-16 packets lies within two cells of the
// inflation radius around some wall or object of the world (outer outlines and free-space holes alike),
// and the box is found where it stands.
TEST(PlannerCore, PolygonsFromSimulatedPacketsMatchTheInflatedWorldWithinTwoCells)
{
  const sim::World world = sim::builtinPushRoom(200.0);
  std::vector<geometry::Polygon> world_outlines;
  for (const auto& obstacle : world.obstacles) {
    world_outlines.push_back(obstacle.outline);
  }
  for (const auto& object : world.objects) {
    geometry::Polygon placed;
    for (const auto& corner : object.outline) {
      placed.push_back(object.pose.transform(corner));
    }
    world_outlines.push_back(placed);
  }
  const PlannerSettings settings{};
  const double inflation = settings.perception.inflation_radius_m;
  const double two_cells = 2.0 * settings.perception.cell_size_m;

  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_GE(frames.size(), 2U);
  Planner planner{settings};
  const FrameResult result = planner.processFrame(frames[1]);
  ASSERT_FALSE(result.polygons.empty());
  std::size_t vertices = 0;
  for (const auto& polygon : result.polygons) {
    for (const auto& vertex : polygon.vertices) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& outline : world_outlines) {
        const double distance =
            geometry::containsPoint(outline, vertex) ? 0.0 : geometry::distanceToBoundary(outline, vertex);
        nearest = std::min(nearest, distance);
      }
      EXPECT_NEAR(nearest, inflation, two_cells)
          << "vertex (" << vertex.x() << ", " << vertex.y() << ") is " << nearest
          << " m from the nearest world obstacle, expected the inflation radius " << inflation;
      ++vertices;
    }
  }
  EXPECT_GT(vertices, 8U);

  bool box_found = false;
  for (const auto& polygon : result.polygons) {
    if (polygon.obstacle_class == perception::ObstacleClass::Movable) {
      const geometry::Point middle = geometry::centroid(polygon.vertices);
      box_found = box_found || (middle - world.objects.front().pose.position()).norm() < two_cells;
    }
  }
  EXPECT_TRUE(box_found) << "no movable polygon centred within two cells of the box";
}

TEST(PlannerCore, NoGoalIsIdle)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_FALSE(frames.empty());
  Planner planner{PlannerSettings{}};
  const FrameResult result = planner.processFrame(frames[0]);
  EXPECT_EQ(result.status.state, PlannerState::Idle);
  EXPECT_FALSE(result.path.valid);
  EXPECT_GT(result.status.vertices, 0);
}

TEST(PlannerCore, GoalInsideObstacleIsSnappedAndFlagged)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_FALSE(frames.empty());
  Planner planner{PlannerSettings{}};
  ASSERT_TRUE(planner.setGoal(Goal{1, geometry::Point(3.5, 6.0)}));  // the box's centre
  const FrameResult result = planner.processFrame(frames[0]);
  EXPECT_NE(result.status.flags & kFlagGoalSnapped, 0) << result.status.message;
  EXPECT_NE(result.status.message.find("snapped"), std::string::npos);
  ASSERT_TRUE(result.path.valid);
  // Only the box's front face is seen, so the snap leaves through the near side of its inflated outline.
  EXPECT_GT((result.path.waypoints.back().position - geometry::Point(3.5, 6.0)).norm(), 0.01);
}

TEST(PlannerCore, GoalOffTheMapIsFlaggedAndAttempted)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_FALSE(frames.empty());
  Planner planner{PlannerSettings{}};
  ASSERT_TRUE(planner.setGoal(Goal{2, geometry::Point(500.0, 6.0)}));
  const FrameResult result = planner.processFrame(frames[0]);
  EXPECT_NE(result.status.flags & kFlagGoalOffMap, 0) << result.status.message;
  EXPECT_NE(result.status.message.find("outside the observed map"), std::string::npos);
}

TEST(PlannerCore, GoalWithinArrivalRadiusIsArrivedAndClearingIsIdle)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_FALSE(frames.empty());
  Planner planner{PlannerSettings{}};
  ASSERT_TRUE(planner.setGoal(Goal{4, geometry::Point(2.3, 6.1)}));  // 0.32 m from the vehicle
  EXPECT_EQ(planner.processFrame(frames[0]).status.state, PlannerState::Arrived);
  planner.clearGoal();
  const FrameResult idle = planner.replan();
  EXPECT_EQ(idle.status.state, PlannerState::Idle);
  EXPECT_FALSE(idle.path.valid);
}

TEST(PlannerCore, NonFiniteGoalIsRefused)
{
  Planner planner{PlannerSettings{}};
  EXPECT_FALSE(planner.setGoal(Goal{3, geometry::Point(kNaN, 1.0)}));
  EXPECT_FALSE(planner.goal().has_value());
  EXPECT_EQ(planner.badInputs(), 1);
}

TEST(PlannerCore, NonFinitePointsAreDroppedAndFlagged)
{
  std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_FALSE(frames.empty());
  FrameInput frame = frames[0];
  perception::SensorPoint bad;
  bad.position_sensor = Eigen::Vector3f(std::numeric_limits<float>::quiet_NaN(), 1.0F, 0.0F);
  frame.points.push_back(bad);
  bad.position_sensor = Eigen::Vector3f(std::numeric_limits<float>::infinity(), 1.0F, 0.0F);
  frame.points.push_back(bad);
  Planner planner{PlannerSettings{}};
  const FrameResult result = planner.processFrame(frame);
  EXPECT_NE(result.status.flags & kFlagBadPoints, 0);
  EXPECT_NE(result.status.message.find("2 non-finite points"), std::string::npos) << result.status.message;
  EXPECT_GT(result.status.polygons, 0);  // the good points still make the frame
}

TEST(PlannerCore, NonFiniteMotionRejectsTheFrame)
{
  FrameInput frame = stillFrame();
  frame.motion.vehicle_at_end.translation().x() = kNaN;
  Planner planner{PlannerSettings{}};
  const FrameResult result = planner.processFrame(frame);
  EXPECT_EQ(result.status.state, PlannerState::BadInput);
  EXPECT_EQ(result.status.frames, 0);
  EXPECT_EQ(planner.badInputs(), 1);
  EXPECT_NE(result.status.message.find("not finite"), std::string::npos) << result.status.message;
}

TEST(PlannerCore, FrameWithoutPoseIsRejected)
{
  FrameInput frame = stillFrame();
  frame.has_motion = false;
  Planner planner{PlannerSettings{}};
  const FrameResult result = planner.processFrame(frame);
  EXPECT_EQ(result.status.state, PlannerState::BadInput);
  EXPECT_NE(result.status.message.find("no pose"), std::string::npos);
}

TEST(PlannerCore, EmptyScanIsFlaggedAndKeepsTheGraph)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_FALSE(frames.empty());
  PlannerSettings settings;
  settings.perception.remember_background = false;
  Planner planner{settings};
  planner.processFrame(frames[0]);
  const std::size_t vertices = planner.graph().vertexCount();
  ASSERT_GT(vertices, 0U);
  for (int frame_index = 0; frame_index < settings.graph.votes + 2; ++frame_index) {
    const FrameResult result = planner.processFrame(stillFrame());
    EXPECT_NE(result.status.flags & kFlagEmptyScan, 0);
    EXPECT_EQ(result.status.polygons, 0);
  }
  EXPECT_EQ(planner.graph().vertexCount(), vertices);  // a sensor gap casts no removal votes
}

/// An empty scan's frame with the goal (16, 6) outside the room: with the room's walls in the layer (seen
/// before, or known) the path goes round them; without, straight through.
void expectGoalBehindTheWalls(const FrameResult& blind, bool walls_in_the_layer)
{
  EXPECT_NE(blind.status.flags & kFlagEmptyScan, 0);
  const bool straight_through_the_wall = blind.path.valid && blind.path.waypoints.size() == 2;
  if (walls_in_the_layer) {
    EXPECT_GE(blind.status.polygons, 1) << "the walls are there";
    EXPECT_FALSE(straight_through_the_wall) << blind.status.message;
  } else {
    EXPECT_EQ(blind.status.polygons, 0);
    EXPECT_TRUE(straight_through_the_wall) << blind.status.message;
  }
}

// The room's walls, once seen, stay in the layer: a goal outside the closed room is not attached
// through a wall the current scan does not show (here: an empty scan), as it is without the memory.
TEST(PlannerCore, RememberedWallsKeepTheGoalFromBeingAttachedThroughThem)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_FALSE(frames.empty());
  for (const bool remember : {false, true}) {
    PlannerSettings settings;
    settings.perception.remember_background = remember;
    Planner planner{settings};
    ASSERT_TRUE(planner.setGoal(Goal{3, geometry::Point(16.0, 6.0)}));
    const FrameResult seen = planner.processFrame(frames[0]);
    EXPECT_GE(seen.status.polygons, 2);
    expectGoalBehindTheWalls(planner.processFrame(stillFrame()), remember);
  }
}

// Walls known before the run are in the layer from the first frame, seen or not, whatever
// remember_background says: the goal outside the closed room is not attached through them.
TEST(PlannerCore, KnownWallsKeepTheGoalFromBeingAttachedThroughThemBeforeTheyAreSeen)
{
  std::vector<geometry::Polygon> walls;
  for (const sim::StaticObstacle& obstacle : sim::builtinPushRoom(200.0).obstacles) {
    walls.push_back(obstacle.outline);
  }
  ASSERT_GE(walls.size(), 4U);
  for (const bool known : {false, true}) {
    PlannerSettings settings;
    settings.perception.remember_background = false;
    Planner planner{settings};
    if (known) {
      EXPECT_GT(
          planner.rememberKnownObstacles(common::Span<const geometry::Polygon>(walls.data(), walls.size())),
          100U);
    }
    ASSERT_TRUE(planner.setGoal(Goal{3, geometry::Point(16.0, 6.0)}));
    expectGoalBehindTheWalls(planner.processFrame(stillFrame()), known);
  }
}

// A goal among known walls is on the map: not flagged as attempted through unknown space, though it lies
// beyond the 200 m layer round the vehicle at (2, 6).
TEST(PlannerCore, AGoalAmongKnownWallsIsOnTheMap)
{
  const std::vector<geometry::Polygon> walls{{{0.0, 0.0}, {160.0, 0.0}, {160.0, 0.2}, {0.0, 0.2}},
                                             {{0.0, 11.8}, {160.0, 11.8}, {160.0, 12.0}, {0.0, 12.0}}};
  for (const bool known : {false, true}) {
    Planner planner{PlannerSettings{}};
    if (known) {
      planner.rememberKnownObstacles(common::Span<const geometry::Polygon>(walls.data(), walls.size()));
    }
    ASSERT_TRUE(planner.setGoal(Goal{3, geometry::Point(150.0, 6.0)}));
    const FrameResult first = planner.processFrame(stillFrame());
    EXPECT_EQ((first.status.flags & kFlagGoalOffMap) != 0, !known) << first.status.message;
    EXPECT_TRUE(first.path.valid) << first.status.message;
  }
}

TEST(PlannerCore, CorruptGraphFileIsReportedAndIgnored)
{
  const std::string path = std::string(IFAR_BINARY_DIR) + "/planner_core_corrupt_graph.txt";
  {
    std::ofstream file(path);
    file << "ifar-dv-graph 1\nslots 2\nvertices 1\nv 0 0 nan 1 0 0 0 0 0 0\n";
  }
  Planner planner{PlannerSettings{}};
  const std::string error = planner.loadPriorGraph(path);
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_EQ(planner.graph().vertexCount(), 0U);
  EXPECT_EQ(planner.badInputs(), 1);
}

TEST(PlannerCore, SavedGraphLoadsAsPriorMap)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_FALSE(frames.empty());
  Planner first{PlannerSettings{}};
  first.processFrame(frames[0]);
  const std::string path = std::string(IFAR_BINARY_DIR) + "/planner_core_prior_graph.txt";
  ASSERT_EQ(graph::saveGraph(first.graph(), path), "");
  Planner second{PlannerSettings{}};
  EXPECT_EQ(second.loadPriorGraph(path), "");
  EXPECT_EQ(graph::serializeGraph(second.graph()), graph::serializeGraph(first.graph()));
}

// A prior map's edge that an obstacle now crosses (the merge keeps it: neither end is observed) is
// dropped when the search takes it, with the other blocked edges of its ends, and the path goes round
// the box.
TEST(PlannerCore, AGraphEdgeThroughAnObstacleSeenSinceIsDroppedWhenTheSearchTakesIt)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_GE(frames.size(), 2U);
  graph::DvGraph prior;
  graph::Vertex vertex;
  vertex.kind = graph::VertexKind::TopologicalWaypoint;
  vertex.position = geometry::Point(2.2, 6.0);  // beside the vehicle, 0.7 m from the box's corners
  const graph::VertexId west = prior.addVertex(vertex);
  vertex.position = geometry::Point(5.8, 6.0);  // beside the goal
  const graph::VertexId east = prior.addVertex(vertex);
  vertex.position = geometry::Point(5.8, 4.5);  // also behind the box, a way longer than round it
  const graph::VertexId east_lower = prior.addVertex(vertex);
  ASSERT_EQ(prior.addVisibilityEdge(west, east), graph::EdgeStatus::Added);        // through the box
  ASSERT_EQ(prior.addVisibilityEdge(west, east_lower), graph::EdgeStatus::Added);  // through the box too
  const std::string path = std::string(IFAR_BINARY_DIR) + "/planner_core_stale_edge_graph.txt";
  ASSERT_EQ(graph::saveGraph(prior, path), "");

  Planner planner{PlannerSettings{}};
  ASSERT_EQ(planner.loadPriorGraph(path), "");
  ASSERT_TRUE(planner.setGoal(Goal{7, geometry::Point(6.0, 6.0)}));
  const FrameResult result = planner.processFrame(frames[1]);
  ASSERT_TRUE(result.path.valid) << result.status.message;
  EXPECT_GT(result.path.length_m, 4.0 + 1e-3) << "the 4.0 m way through the box";
  EXPECT_LT(result.path.length_m, 5.5);
  EXPECT_FALSE(planner.graph().hasVisibilityEdge(west, east));
  // The other blocked edge of the same vertex goes with it, before a search takes it.
  EXPECT_FALSE(planner.graph().hasVisibilityEdge(west, east_lower));
  EXPECT_NE(result.status.message.find("dropped 2 graph edges"), std::string::npos) << result.status.message;
}

TEST(PlannerCore, ReplanAnswersANewGoalWithoutANewFrame)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_FALSE(frames.empty());
  Planner planner{PlannerSettings{}};
  planner.processFrame(frames[0]);
  ASSERT_TRUE(planner.setGoal(Goal{9, geometry::Point(2.0, 9.0)}));
  const FrameResult result = planner.replan();
  EXPECT_EQ(result.status.state, PlannerState::Planning) << result.status.message;
  ASSERT_TRUE(result.path.valid);
  EXPECT_NEAR(result.path.length_m, 3.0, 0.05);  // nothing between the vehicle and this goal
}

TEST(PlannerFrameAssembler, SimulatedPacketsMakeOneFramePerRevolutionWithMotion)
{
  const std::vector<FrameInput> frames = pushRoomFrames();
  ASSERT_GE(frames.size(), 2U);
  for (const FrameInput& frame : frames) {
    EXPECT_TRUE(frame.has_motion);
    EXPECT_EQ(frame.flags, 0) << frame.problems;
    EXPECT_NEAR(frame.motion.vehicle_at_end.translation().x(), 2.0, 1e-6);
  }
  // 10 Hz: a full revolution holds about 0.1 s of firings.
  EXPECT_NEAR(frames[1].motion.duration_s, 0.1, 0.015);
  EXPECT_EQ(frames[1].utime - frames[0].utime, 100'000);
}

/// A 4 m tunnel along y (x -2 .. 2), 300 m long, in rock. The vehicle starts 20 m south of y 0, facing
/// north; the goal is 40 m east of y 0, in rock nobody has seen inside: the way there leads round the north
/// or the south end of the tunnel's east wall, as far as it is known.
sim::World tunnelInRock()
{
  sim::World world;
  world.name = "tunnel in rock";
  const auto rock = [&world](double x0, double y0, double x1, double y1) {
    sim::StaticObstacle obstacle;
    obstacle.name = "rock_" + std::to_string(world.obstacles.size());
    obstacle.outline = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    obstacle.height_m = 4.0;
    world.obstacles.push_back(obstacle);
  };
  rock(-12.0, -152.0, -2.0, 152.0);
  rock(2.0, -152.0, 12.0, 152.0);
  rock(-2.0, 150.0, 2.0, 152.0);
  rock(-2.0, -152.0, 2.0, -150.0);
  world.start = geometry::Pose2{0.0, -20.0, 0.5 * M_PI};
  world.goals.push_back(sim::Goal{"east", geometry::Point(40.0, 0.0)});
  sim::updateBounds(world);
  return world;
}

/// Drives north along the tunnel at 1 m/s for 30 s and returns, per frame once the vehicle is 3 m past the
/// goal's y, whether the path's first step points south (back the way it came).
std::vector<bool> southboundFrames(double layer_size_m)
{
  static const std::vector<test_support::FeedRecord> records =
      test_support::recordSimulation(tunnelInRock(), 30.0, 1.0);
  FrameAssembler assembler{InputSettings{}};
  const std::vector<FrameInput> frames = test_support::feedAll(records, assembler);
  PlannerSettings settings;
  settings.perception.layer_size_m = layer_size_m;
  Planner planner{settings};
  EXPECT_TRUE(planner.setGoal(Goal{1, geometry::Point(40.0, 0.0)}));
  std::vector<bool> southbound;
  for (std::size_t index = 0; index < frames.size(); ++index) {
    const FrameResult result = planner.processFrame(frames[index]);
    if (frames[index].motion.vehicle_at_end.translation().y() < 3.0) {
      continue;
    }
    EXPECT_TRUE(result.path.valid) << result.status.message;
    if (result.path.valid && result.path.waypoints.size() >= 2) {
      const geometry::Point step = result.path.waypoints[1].position - result.path.waypoints[0].position;
      southbound.push_back(step.y() < 0.0);
    }
  }
  return southbound;
}

TEST(PlannerCore, DrivingOnAlongATunnelTheRouteDoesNotTurnBackWhereTheLayerCutsTheWall)
{
  // The layer holds all the lidar reaches, so the wall's end behind the vehicle is its remembered end,
  // which stays put, and the route round the end ahead only gets better as the vehicle goes on.
  const std::vector<bool> southbound = southboundFrames(PlannerSettings{}.perception.layer_size_m);
  ASSERT_GE(southbound.size(), 50U);
  EXPECT_EQ(std::count(southbound.begin(), southbound.end(), true), 0);
  // Control: a 60 m layer cuts the east wall 30 m behind the vehicle, and that corner follows it north:
  // once north of the goal, going back round it is the shorter way.
  const std::vector<bool> sixty = southboundFrames(60.0);
  EXPECT_GT(std::count(sixty.begin(), sixty.end(), true), 0);
}

/// A wall along x = 5 (y -12 .. 8) between the vehicle and the goal (10, -2), which lies as far from
/// either end. The vehicle drives 8 m north from (0, -8) to about (0, -0.6): the way round the north end
/// is 2.5 m shorter, but the vehicle never came within 6 m of its far part; it passed by the start of
/// the way south.
std::vector<FrameInput> wallBetweenFrames()
{
  sim::World world;
  world.name = "wall between";
  sim::StaticObstacle wall;
  wall.name = "wall";
  wall.outline = {{5.0, -12.0}, {5.2, -12.0}, {5.2, 8.0}, {5.0, 8.0}};
  wall.height_m = 2.0;
  world.obstacles.push_back(wall);
  world.start = geometry::Pose2{0.0, -8.0, 0.5 * M_PI};
  world.goals.push_back(sim::Goal{"east", geometry::Point(10.0, -2.0)});
  sim::updateBounds(world);
  FrameAssembler assembler{InputSettings{}};
  return test_support::feedAll(test_support::recordSimulation(world, 8.0, 1.0), assembler);
}

TEST(PlannerCore, WithAnUnseenCostAWayThroughSeenSpaceBeatsAShorterGuess)
{
  const std::vector<FrameInput> frames = wallBetweenFrames();
  ASSERT_GE(frames.size(), 40U);
  for (const double unseen_cost : {0.0, 2.0}) {
    PlannerSettings settings;
    settings.graph.unseen_cost = unseen_cost;
    settings.graph.seen_range_m = 6.0;
    Planner planner{settings};
    ASSERT_TRUE(planner.setGoal(Goal{1, geometry::Point(10.0, -2.0)}));
    FrameResult last;
    for (const FrameInput& frame : frames) {
      last = planner.processFrame(frame);
    }
    ASSERT_TRUE(last.path.valid) << last.status.message;
    ASSERT_GE(last.path.waypoints.size(), 3U);
    const geometry::Point first_step = last.path.waypoints[1].position - last.path.waypoints[0].position;
    if (unseen_cost > 0.0) {
      EXPECT_LT(first_step.y(), 0.0) << "round the south end, by what was seen";
      EXPECT_GT(last.path.cost, last.path.length_m + 20.0) << "twice the unseen way behind the wall";
    } else {
      EXPECT_GT(first_step.y(), 0.0) << "round the shorter north end";
      EXPECT_NEAR(last.path.cost, last.path.length_m, 1e-9);
    }
  }
}

TEST(PlannerFrameAssembler, BadPosesAreRefusedWithAReason)
{
  FrameAssembler assembler{InputSettings{}};
  PoseSample pose = test_support::planarPose(1'000'000, 1.0, 2.0, 0.0);
  EXPECT_EQ(assembler.addPose(pose, 1'000'000), InputVerdict::Accepted);
  PoseSample nan_pose = test_support::planarPose(1'010'000, kNaN, 2.0, 0.0);
  EXPECT_EQ(assembler.addPose(nan_pose, 1'010'000), InputVerdict::NonFinite);
  PoseSample infinite_pose = test_support::planarPose(1'010'000, 1.0, 2.0, 0.0);
  infinite_pose.orientation.w() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(assembler.addPose(infinite_pose, 1'010'000), InputVerdict::NonFinite);
  PoseSample scaled = test_support::planarPose(1'010'000, 1.0, 2.0, 0.0);
  scaled.orientation.coeffs() *= 2.0;
  EXPECT_EQ(assembler.addPose(scaled, 1'010'000), InputVerdict::NotUnitQuaternion);
  EXPECT_EQ(assembler.addPose(test_support::planarPose(900'000, 1.0, 2.0, 0.0), 1'010'000),
            InputVerdict::OutOfOrder);
  EXPECT_EQ(assembler.addPose(test_support::planarPose(9'000'000, 1.0, 2.0, 0.0), 1'010'000),
            InputVerdict::FromFuture);
  EXPECT_EQ(assembler.rejectedInputs(), 5);
  ASSERT_TRUE(assembler.latestPose().has_value());
  EXPECT_EQ(assembler.latestPose()->utime, 1'000'000);
}

TEST(PlannerFrameAssembler, BadPacketsAreRefusedAndFlagTheNextFrame)
{
  const std::vector<test_support::FeedRecord>& records = pushRoomRecords();
  FrameAssembler assembler{InputSettings{}};
  std::vector<FrameInput> frames;
  bool injected = false;
  for (const test_support::FeedRecord& record : records) {
    if (record.kind == test_support::FeedRecord::Kind::Pose) {
      assembler.addPose(record.pose, record.utime);
      continue;
    }
    ASSERT_EQ(assembler.addPacket(common::ByteView(record.payload.data(), record.payload.size()),
                                  record.utime, record.utime),
              InputVerdict::Accepted);
    if (!injected && record.utime > records.front().utime + 50'000) {
      injected = true;
      const common::ByteView payload(record.payload.data(), record.payload.size());
      EXPECT_EQ(assembler.addPacket(payload, record.utime - 20'000, record.utime), InputVerdict::OutOfOrder);
      EXPECT_EQ(assembler.addPacket(payload, record.utime + 5'000'000, record.utime),
                InputVerdict::FromFuture);
      EXPECT_EQ(assembler.addPacket(common::ByteView(record.payload.data(), 100), record.utime, record.utime),
                InputVerdict::Undecodable);
    }
    for (FrameInput& frame : assembler.takeFrames()) {
      frames.push_back(std::move(frame));
    }
  }
  ASSERT_TRUE(injected);
  ASSERT_FALSE(frames.empty());
  EXPECT_NE(frames[0].flags & kFlagStaleInput, 0);
  EXPECT_NE(frames[0].problems.find("packet out of order"), std::string::npos) << frames[0].problems;
  EXPECT_NE(frames[0].problems.find("packet from the future"), std::string::npos);
  EXPECT_EQ(assembler.rejectedInputs(), 3);
  // Processing the flagged frame still works and reports the flag.
  Planner planner{PlannerSettings{}};
  const FrameResult result = planner.processFrame(frames[0]);
  EXPECT_NE(result.status.flags & kFlagStaleInput, 0);
  EXPECT_GT(result.status.polygons, 0);
}

TEST(PlannerFrameAssembler, PacketsWithoutPosesGiveAFrameThatCannotBePlaced)
{
  FrameAssembler assembler{InputSettings{}};
  for (const test_support::FeedRecord& record : pushRoomRecords()) {
    if (record.kind == test_support::FeedRecord::Kind::Packet) {
      assembler.addPacket(common::ByteView(record.payload.data(), record.payload.size()), record.utime,
                          record.utime);
    }
  }
  const std::vector<FrameInput> frames = assembler.takeFrames();
  ASSERT_FALSE(frames.empty());
  EXPECT_FALSE(frames[0].has_motion);
  EXPECT_NE(frames[0].flags & kFlagStaleInput, 0);
  Planner planner{PlannerSettings{}};
  EXPECT_EQ(planner.processFrame(frames[0]).status.state, PlannerState::BadInput);
}

}  // namespace
}  // namespace ifar::planner
