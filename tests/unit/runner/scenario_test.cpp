// Whole runs of the headless runner on the shipped config: arrival on a free path, determinism, pushing
// the light box of the demo room, adapting to a box too heavy to push, a doorway livelock the progress
// monitor ends, a kerb that keeps the box out of reach, FAR mode going round, and what a frame observer
// (ifar-run --graph-png) sees.
// Each run takes tens of simulated seconds (label "system").

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim/generators/generators.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/world/world_file.hpp"
#include "system/graph_picture.hpp"
#include "system/run_config.hpp"
#include "system/scenario_runner.hpp"
#include "system/summary_json.hpp"

namespace ifar::runner {
namespace {

const std::string kSourceDir = IFAR_SOURCE_DIR;
// The demo room's goal is behind the light box in the west doorway (x 7.3..8.7 at y = 16): about 22 m
// straight through it; the east opening (x 24..28) makes any path round it longer than 40 m.
const geometry::Point kDemoGoal(8.0, 26.0);
constexpr double kThroughDoorwayLimitM = 30.0;

RunRequest requestFor(const sim::World& world, const geometry::Point& goal, double max_time_s)
{
  RunRequest request = loadRunSettings(kSourceDir + "/config");
  request.world = world;
  request.goal = goal;
  request.max_sim_time_s = max_time_s;
  return request;
}

sim::World worldFile(const std::string& path)
{
  const sim::WorldResult loaded = sim::loadWorldFile(path);
  if (!loaded.ok()) {
    ADD_FAILURE() << loaded.error();
    return {};
  }
  return loaded.world();
}

/// Runs `request`, printing its progress lines (and keeping them in `lines` when given) and its summary.
RunSummary runAndLog(const RunRequest& request, std::vector<std::string>* lines = nullptr)
{
  RunSummary summary = runScenario(request, [lines](const std::string& line) {
    std::fprintf(stderr, "%s\n", line.c_str());
    if (lines != nullptr) {
      lines->push_back(line);
    }
  });
  std::printf("%s\n", summaryJson(summary).c_str());
  return summary;
}

bool passesEastOpening(const RunSummary& summary)
{
  return std::any_of(summary.trajectory.begin(), summary.trajectory.end(), [](const geometry::Pose2& pose) {
    return pose.x > 23.0 && pose.y > 15.0 && pose.y < 17.0;
  });
}

TEST(RunnerScenario, RoomArrivesAlongNearlyStraightPath)
{
  const sim::World world = worldFile(kSourceDir + "/config/worlds/room.yaml");
  ASSERT_FALSE(world.goals.empty());
  const geometry::Point goal = world.goals.front().position;
  const RunSummary summary = runAndLog(requestFor(world, goal, 120.0));
  EXPECT_TRUE(summary.arrived) << summary.reason;
  EXPECT_EQ(summary.reason, "arrived");
  const double straight = (goal - world.start.position()).norm();
  EXPECT_LE(summary.distance_m, 1.3 * straight);
  EXPECT_LE(summary.goal_distance_m, 0.5);
  EXPECT_EQ(summary.pushes, 0);
  EXPECT_EQ(summary.affordance_updates, 0);
  EXPECT_FALSE(summary.trajectory.empty());
  // One planner frame per completed revolution at 2.5 Hz: the first needs a whole revolution (0.1 s) and
  // the run ends at arrival, so within one frame of 2.5 per simulated second.
  EXPECT_NEAR(static_cast<double>(summary.planner_frame.frames), 2.5 * summary.sim_time_s, 1.0);
  EXPECT_EQ(summary.interaction.frames, summary.planner_frame.frames);
  EXPECT_GT(summary.planner_frame.median_ms, 0.0);
  EXPECT_LE(summary.planner_frame.median_ms, summary.planner_frame.p99_ms);
  EXPECT_LE(summary.planner_frame.p99_ms, summary.planner_frame.max_ms);
  EXPECT_LE(summary.interaction.max_ms, summary.planner_frame.max_ms);
}

TEST(RunnerScenario, SameRequestSameSummary)
{
  // The demo room's first 32 s: following, interaction planning, approach and the push of the light box
  // (the push is over at about 30 s), so the planner's lifted wall-clock budgets are exercised too.
  const RunRequest request =
      requestFor(worldFile(kSourceDir + "/config/worlds/demo_room.yaml"), kDemoGoal, 32.0);
  const RunSummary first = runScenario(request, {});
  const RunSummary second = runScenario(request, {});
  EXPECT_EQ(first.arrived, second.arrived);
  EXPECT_EQ(first.reason, second.reason);
  EXPECT_EQ(first.distance_m, second.distance_m);
  EXPECT_EQ(first.sim_time_s, second.sim_time_s);
  EXPECT_EQ(first.pushes, second.pushes);
  EXPECT_EQ(first.replans, second.replans);
  EXPECT_EQ(first.affordance_updates, second.affordance_updates);
  EXPECT_EQ(first.goal_distance_m, second.goal_distance_m);
  ASSERT_EQ(first.trajectory.size(), second.trajectory.size());
  for (std::size_t index = 0; index < first.trajectory.size(); ++index) {
    ASSERT_EQ(first.trajectory[index].x, second.trajectory[index].x) << index;
    ASSERT_EQ(first.trajectory[index].y, second.trajectory[index].y) << index;
    ASSERT_EQ(first.trajectory[index].heading, second.trajectory[index].heading) << index;
  }
  EXPECT_EQ(first.pushes, 1);  // it did push
  ASSERT_EQ(first.final_objects.size(), second.final_objects.size());
  for (std::size_t index = 0; index < first.final_objects.size(); ++index) {
    EXPECT_EQ(first.final_objects[index].x, second.final_objects[index].x) << index;
    EXPECT_EQ(first.final_objects[index].y, second.final_objects[index].y) << index;
  }
}

TEST(RunnerScenario, DemoRoomPushesTheLightBoxAndArrives)
{
  const RunSummary summary =
      runAndLog(requestFor(worldFile(kSourceDir + "/config/worlds/demo_room.yaml"), kDemoGoal, 150.0));
  EXPECT_TRUE(summary.arrived) << summary.reason;
  EXPECT_GE(summary.pushes, 1);
  EXPECT_LT(summary.distance_m, kThroughDoorwayLimitM);
  EXPECT_FALSE(passesEastOpening(summary));
  // The loss accounting covers the whole drive and its buckets add up; pushing the box is all that is
  // booked to a push, and nothing failed.
  const LossAccount& losses = summary.losses;
  ASSERT_TRUE(losses.valid) << losses.problem;
  EXPECT_NEAR(losses.travelled_m, summary.distance_m, 1e-9);
  EXPECT_NEAR(losses.buckets.total(), losses.excess_m, 0.01);
  EXPECT_GT(losses.buckets.push_overhead_m, 0.0);
  EXPECT_EQ(losses.buckets.attempts_m, 0.0);
}

TEST(RunnerScenario, GoalsAreDrivenInOrderEachSentWhenTheOneBeforeIsReached)
{
  // Through the doorway (pushing the box), then along the upper half, then back down through the east
  // opening: three legs, each its own row and account.
  RunRequest request = requestFor(worldFile(kSourceDir + "/config/worlds/demo_room.yaml"), kDemoGoal, 300.0);
  request.further_goals = {geometry::Point(20.0, 26.0), geometry::Point(26.0, 6.0)};
  const RunSummary summary = runAndLog(request);
  EXPECT_TRUE(summary.arrived) << summary.reason;
  ASSERT_EQ(summary.legs.size(), 3u);
  double distance = 0.0;
  LossBuckets buckets;
  for (std::size_t index = 0; index < summary.legs.size(); ++index) {
    const GoalLeg& leg = summary.legs[index];
    EXPECT_TRUE(leg.arrived) << "goal " << index + 1;
    EXPECT_GT(leg.distance_m, 5.0) << "goal " << index + 1;
    ASSERT_TRUE(leg.losses.valid) << leg.losses.problem;
    EXPECT_NEAR(leg.losses.buckets.total(), leg.losses.excess_m, 0.01) << "goal " << index + 1;
    distance += leg.distance_m;
    for (int bucket = 0; bucket < kLossBucketCount; ++bucket) {
      lossBucket(buckets, bucket) += lossBucket(leg.losses.buckets, bucket);
    }
  }
  EXPECT_EQ(summary.legs[1].goal, geometry::Point(20.0, 26.0));
  EXPECT_NEAR(distance, summary.distance_m, 1e-9);
  EXPECT_NEAR(summary.losses.buckets.total(), buckets.total(), 1e-9);
  EXPECT_LT(summary.goal_distance_m, request.planner.arrival_radius_m + 1e-9);
  EXPECT_LT(summary.legs[0].distance_m, kThroughDoorwayLimitM);
}

TEST(RunnerScenario, HeavyBoxIsFoundUnpushableAndAvoided)
{
  // The demo room with the doorway box at 2000 kg: it looks the same to the planner, so it is planned
  // as pushable; the push stalls, the executive reports it unpushable and the vehicle goes east.
  std::vector<std::string> lines;
  const RunSummary summary = runAndLog(
      requestFor(worldFile(kSourceDir + "/config/worlds/demo_room_heavy.yaml"), kDemoGoal, 240.0), &lines);
  EXPECT_TRUE(summary.arrived) << summary.reason;
  EXPECT_GE(summary.affordance_updates, 1);
  // What the executive measured and what the planner made of it are in the progress lines.
  EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [](const std::string& line) {
    return line.rfind("affordance: object ", 0) == 0 &&
           line.find("unpushable; planner: object ") != std::string::npos &&
           line.find(" unpushable: edges removed") != std::string::npos;
  }));
  EXPECT_GE(summary.replans, 1);
  EXPECT_EQ(summary.pushes, 0);
  EXPECT_TRUE(passesEastOpening(summary));
  // The way to the heavy box and the push against it were for nothing: attempts, metres of them.
  ASSERT_TRUE(summary.losses.valid) << summary.losses.problem;
  EXPECT_GT(summary.losses.buckets.attempts_m, 1.0);
  EXPECT_NEAR(summary.losses.buckets.total(), summary.losses.excess_m, 0.01);
}

/// The demo room with its doorway box taken out, and `obstacles` and `objects` put in.
sim::World demoRoomWith(const std::vector<sim::StaticObstacle>& obstacles,
                        const std::vector<sim::MovableObject>& objects)
{
  sim::World world = worldFile(kSourceDir + "/config/worlds/demo_room.yaml");
  world.objects.erase(std::remove_if(world.objects.begin(), world.objects.end(),
                                     [](const sim::MovableObject& object) { return object.id == 1; }),
                      world.objects.end());
  world.obstacles.insert(world.obstacles.end(), obstacles.begin(), obstacles.end());
  world.objects.insert(world.objects.end(), objects.begin(), objects.end());
  return world;
}

sim::StaticObstacle block(const std::string& name, double x0, double y0, double x1, double y1,
                          double height_m)
{
  sim::StaticObstacle obstacle;
  obstacle.name = name;
  obstacle.outline = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  obstacle.height_m = height_m;
  return obstacle;
}

bool anyLineHas(const std::vector<std::string>& lines, const std::string& text)
{
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& line) { return line.find(text) != std::string::npos; });
}

TEST(RunnerScenario, AStoolBesideAPillarInADoorwayLivelocksUntilTheProgressMonitorEscalates)
{
  // The 1.4 m doorway holds a 0.3 m pillar at its west post and a 0.35 m stool at its east post: 0.75 m
  // between them, which the planner's outlines leave open but the 0.7 m vehicle does not get through
  // with its guard's clearance. With stall and on-sight gap reports off, nothing but the progress
  // monitor tells the planner: without it the vehicle tries the gap until the time limit.
  sim::MovableObject stool;
  stool.id = 1;
  stool.name = "stool";
  stool.outline = {{-0.175, -0.175}, {0.175, -0.175}, {0.175, 0.175}, {-0.175, 0.175}};
  stool.pose = geometry::Pose2{8.525, 16.0, 0.0};
  stool.height_m = 0.8;
  stool.mass_kg = 8.0;
  stool.ground_friction = 0.4;
  RunRequest request =
      requestFor(demoRoomWith({block("pillar", 7.3, 15.7, 7.6, 16.3, 2.0)}, {stool}), kDemoGoal, 240.0);
  request.executive.blocked_passage_stalls = 0;
  request.executive.blocked_passage_on_sight = executive::GapReportScope::Off;
  std::vector<std::string> lines;
  const RunSummary summary = runAndLog(request, &lines);
  EXPECT_TRUE(summary.arrived) << summary.reason;
  EXPECT_GE(summary.escalations, 1);
  EXPECT_TRUE(anyLineHas(lines, "no progress toward the goal for 60 s"));

  request.executive.progress.timeout_s = 0.0;
  request.max_sim_time_s = 200.0;
  const RunSummary unmonitored = runScenario(request, {});
  EXPECT_FALSE(unmonitored.arrived);
  EXPECT_EQ(unmonitored.escalations, 0);
}

TEST(RunnerScenario, ForceFeltShortOfTheBoxIsAContactNotReachedAndTheBoxStaysPushable)
{
  // A 0.1 m kerb across the doorway's approach, 1.1 m south of the light box: below the lidar's obstacle
  // band, so no one plans round it, and the bumper presses on it with the box out of reach. That force
  // is not the box's: the contact is not reached, the box stays pushable, and the vehicle goes east.
  RunRequest request = requestFor(worldFile(kSourceDir + "/config/worlds/demo_room.yaml"), kDemoGoal, 240.0);
  request.world.obstacles.push_back(block("kerb", 6.8, 14.4, 9.2, 14.6, 0.1));
  std::vector<std::string> lines;
  const RunSummary summary = runAndLog(request, &lines);
  EXPECT_TRUE(summary.arrived) << summary.reason;
  EXPECT_TRUE(anyLineHas(lines, "object 1 contact not reached, still pushable"));
  EXPECT_FALSE(anyLineHas(lines, "unpushable"));
  EXPECT_EQ(summary.pushes, 0);
  EXPECT_TRUE(passesEastOpening(summary));
}

TEST(RunnerScenario, FarModeGoesRoundWithoutPushing)
{
  RunRequest request = requestFor(worldFile(kSourceDir + "/config/worlds/demo_room.yaml"), kDemoGoal, 240.0);
  request.planner.interaction_enabled = false;
  const RunSummary summary = runAndLog(request);
  EXPECT_TRUE(summary.arrived) << summary.reason;
  EXPECT_EQ(summary.pushes, 0);
  EXPECT_EQ(summary.affordance_updates, 0);
  EXPECT_GT(summary.distance_m, kThroughDoorwayLimitM);  // longer than through the pushed doorway
  EXPECT_TRUE(passesEastOpening(summary));
}

TEST(RunnerScenario, BadRequestsEndAtOnce)
{
  RunRequest request = requestFor(sim::builtinRoom(), geometry::Point(std::nan(""), 1.0), 10.0);
  RunSummary summary = runScenario(request, {});
  EXPECT_FALSE(summary.arrived);
  EXPECT_EQ(summary.reason, "bad request: goal is not finite");
  EXPECT_EQ(summary.sim_time_s, 0.0);

  request.goal = geometry::Point(5.0, 5.0);
  request.planner_node.rate_hz = 0.0;
  summary = runScenario(request, {});
  EXPECT_EQ(summary.reason, "bad request: the planner's rate_hz must be a positive number");

  // A world the simulator refuses: an object whose outline is a line.
  request = requestFor(sim::builtinPushRoom(15.0), geometry::Point(8.0, 6.0), 10.0);
  request.world.objects.front().outline = {geometry::Point(0.0, 0.0), geometry::Point(0.5, 0.0)};
  summary = runScenario(request, {});
  EXPECT_FALSE(summary.arrived);
  EXPECT_EQ(summary.reason.rfind("bad request: ", 0), 0U) << summary.reason;
}

TEST(RunnerScenario, GoalOutsideTheWorldEndsWithTheExecutivesStop)
{
  // The planner finds no path to a goal far outside the closed room; the executive halts and says why.
  const RunSummary summary =
      runScenario(requestFor(sim::builtinRoom(), geometry::Point(50.0, 50.0), 60.0), {});
  EXPECT_FALSE(summary.arrived);
  EXPECT_EQ(summary.reason.rfind("stopped: ", 0), 0U) << summary.reason;
  EXPECT_NE(summary.reason.find("no path"), std::string::npos) << summary.reason;
  // ... and the planner why: the closed room has no corner to go round, the vehicle is enclosed.
  EXPECT_NE(
      summary.reason.find("; planner: search: no_path: no graph vertex is visible from the start: it is "
                          "enclosed"),
      std::string::npos)
      << summary.reason;
  EXPECT_LT(summary.sim_time_s, 10.0);  // three seconds after the stop, not the time limit
  EXPECT_LT(summary.distance_m, 0.1);
}

// A field vehicle's sensing (drift, jitter, jumps and latency of the pose; range noise, dropouts and
// missed or false tags of the lidar; wheel slip; force noise): from the start room of the generated office
// through its door, along the corridor and through the door of the room across, about 10 m.
TEST(RunnerScenario, AShortOfficeRouteArrivesUnderFieldSensing)
{
  const sim::WorldResult office = sim::generateWorld(*sim::parseWorldKind("office"), 1);
  ASSERT_TRUE(office.ok()) << office.error();
  RunRequest request = loadRunSettings(kSourceDir + "/config", "field");
  request.world = office.world();
  request.goal = geometry::Point(3.0, 15.0);
  request.max_sim_time_s = 200.0;
  const RunSummary summary = runScenario(request, {});
  EXPECT_TRUE(summary.arrived) << summary.reason;
  EXPECT_EQ(summary.undecided_saturated_pushes, 0);
}

TEST(RunnerScenario, ProgressOncePerSimulatedSecondAndTimeout)
{
  const sim::World world = sim::builtinRoom();
  std::vector<std::string> lines;
  const RunSummary summary = runScenario(requestFor(world, geometry::Point(10.0, 6.0), 3.0),
                                         [&lines](const std::string& line) { lines.push_back(line); });
  EXPECT_FALSE(summary.arrived);
  EXPECT_EQ(summary.reason.rfind("timeout after 3 s of simulated time", 0), 0U) << summary.reason;
  EXPECT_DOUBLE_EQ(summary.sim_time_s, 3.0);
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_EQ(lines[0].rfind("t=1.0s pos=(", 0), 0U) << lines[0];
  EXPECT_EQ(lines[2].rfind("t=3.0s pos=(", 0), 0U) << lines[2];
  EXPECT_NE(lines[2].find("mode=follow target=("), std::string::npos) << lines[2];
  // One pose per control cycle (50 Hz): at 0.02 s, 0.04 s, ... 3.0 s.
  EXPECT_EQ(summary.trajectory.size(), 150U);
  EXPECT_GT(summary.distance_m, 0.5);
  EXPECT_NEAR(summary.goal_distance_m,
              (geometry::Point(10.0, 6.0) - summary.trajectory.back().position()).norm(), 0.05);
}

sim::StaticObstacle wallBetween(const std::string& name, double low_x, double low_y, double high_x,
                                double high_y)
{
  sim::StaticObstacle wall;
  wall.name = name;
  wall.outline = {{low_x, low_y}, {high_x, low_y}, {high_x, high_y}, {low_x, high_y}};
  return wall;
}

// A wall the lidar cannot see from the start (in the shadow of a nearer one, both taller than the
// lidar's beams reach there) is in the planner's first frame only when the walls are known beforehand.
TEST(RunnerScenario, KnownMapPutsAWallOutOfSightIntoTheFirstFrame)
{
  sim::World world = sim::builtinRoom();  // 12 m, the vehicle at (2, 6) facing +x
  world.obstacles.push_back(wallBetween("near", 4.0, 4.5, 4.2, 7.5));
  world.obstacles.push_back(wallBetween("hidden", 7.0, 5.6, 7.2, 6.4));
  const geometry::Point hidden_centre(7.1, 6.0);
  for (const bool known : {false, true}) {
    RunRequest request = requestFor(world, geometry::Point(10.0, 6.0), 0.5);
    request.known_map = known;
    int frames = 0;
    bool hidden_in_first_frame = false;
    runScenario(request, {}, [&](const FrameView& frame) {
      if (frames++ == 0) {
        hidden_in_first_frame = std::any_of(frame.result.polygons.begin(), frame.result.polygons.end(),
                                            [&](const perception::LayerPolygon& polygon) {
                                              return geometry::containsPoint(polygon.vertices, hidden_centre);
                                            });
      }
    });
    ASSERT_GE(frames, 1);
    EXPECT_EQ(hidden_in_first_frame, known) << (known ? "known map" : "explored");
  }
}

TEST(RunnerScenario, FrameObserverSeesEachPlannerFrameAndThePictureKeepsTheOneAsked)
{
  const sim::World world = sim::builtinRoom();
  const RunRequest request = requestFor(world, geometry::Point(10.0, 6.0), 3.0);
  std::vector<double> times;
  std::vector<std::size_t> trajectory_sizes;
  GraphPicture at_one_second(world, 1.0);
  GraphPicture last(world, std::nullopt);
  GraphPicture too_late(world, 10.0);
  const RunSummary summary = runScenario(request, {}, [&](const FrameView& frame) {
    times.push_back(frame.sim_time_s);
    trajectory_sizes.push_back(frame.trajectory.size());
    EXPECT_EQ(frame.objects.size(), world.objects.size());
    EXPECT_TRUE(frame.result.path.valid);
    EXPECT_GT(frame.planner.graph().vertexCount(), 0U);
    at_one_second.observe(frame);
    last.observe(frame);
    too_late.observe(frame);
  });
  // The planner runs at 2.5 Hz on the latest whole revolution: every 0.4 s, in order.
  ASSERT_EQ(times.size(), summary.planner_frame.frames);
  ASSERT_GE(times.size(), 6U);
  for (std::size_t index = 1; index < times.size(); ++index) {
    EXPECT_NEAR(times[index] - times[index - 1], 0.4, 1e-6);
    EXPECT_GT(trajectory_sizes[index], trajectory_sizes[index - 1]);  // 20 control cycles more
  }
  EXPECT_LE(trajectory_sizes.back(), summary.trajectory.size());

  ASSERT_TRUE(at_one_second.kept());
  EXPECT_GE(at_one_second.keptTimeS(), 1.0);
  EXPECT_LT(at_one_second.keptTimeS(), 1.4);
  ASSERT_TRUE(last.kept());
  EXPECT_DOUBLE_EQ(last.keptTimeS(), times.back());
  EXPECT_FALSE(too_late.kept());
  const std::string png = std::string(IFAR_BINARY_DIR) + "/runner_graph_picture_test.png";
  std::remove(png.c_str());
  EXPECT_EQ(at_one_second.writePng(png), "");
  EXPECT_GT(std::filesystem::file_size(png), 1000U);
  std::remove(png.c_str());
  EXPECT_EQ(too_late.writePng(png), png + ": no planner frame at or after 10.0 s of simulated time");
}

}  // namespace
}  // namespace ifar::runner
