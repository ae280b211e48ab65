// The planner under a pose that jitters, drifts and jumps (a state estimator's): ray-cast VLP-16 scans
// of two rooms joined by a door, placed with a wrong pose, then with the right one again.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "planner/core/planner.hpp"
#include "planner/perception/motion_compensation.hpp"
#include "planner/perception/synthetic/synthetic_scan.hpp"

namespace ifar::planner {
namespace {

using perception::synthetic::boxFootprint;
using perception::synthetic::PrismObstacle;

/// Rooms [0, 8] x [0, 8] (A) and [8, 16] x [0, 8] (B), walls 0.2 m thick and 2.5 m high, joined only by a
/// 1.4 m door at y 3.3 .. 4.7 in the wall between them.
std::vector<PrismObstacle> twoRoomsWithADoor()
{
  const auto wall = [](double centre_x, double centre_y, double size_x, double size_y) {
    PrismObstacle obstacle;
    obstacle.footprint = boxFootprint(centre_x, centre_y, size_x, size_y);
    obstacle.height_m = 2.5;
    return obstacle;
  };
  return {wall(8.0, -0.1, 16.4, 0.2), wall(8.0, 8.1, 16.4, 0.2), wall(-0.1, 4.0, 0.2, 8.4),
          wall(16.1, 4.0, 0.2, 8.4),  wall(8.0, 1.65, 0.2, 3.3), wall(8.0, 6.35, 0.2, 3.3)};
}

/// A planar vehicle pose.
Eigen::Isometry3d vehiclePose(double x, double y, double heading)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, 0.0);
  pose.linear() = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

/// One revolution taken by the vehicle standing at `truth`, placed by the estimator as moving from
/// `estimate_start` to `estimate_end` over the scan; with `dark_ahead`, nothing returns from beyond 4 m
/// within 14 degrees of straight ahead (the door's jambs do, the dark room beyond the door and its floor
/// do not).
FrameInput scanPlacedAt(const Eigen::Isometry3d& truth, const Eigen::Isometry3d& estimate_start,
                        const Eigen::Isometry3d& estimate_end, std::int64_t utime, bool dark_ahead = false)
{
  static const std::vector<PrismObstacle> world = twoRoomsWithADoor();
  perception::synthetic::RevolutionSettings revolution;
  revolution.ceiling_height_m = 3.0;
  const Eigen::Isometry3d sensor = truth * perception::lidarMount(common::VehicleSettings{});
  FrameInput frame;
  frame.utime = utime;
  frame.points = perception::synthetic::simulateRevolution(world, sensor, revolution);
  frame.points.erase(std::remove_if(frame.points.begin(), frame.points.end(),
                                    [&](const perception::SensorPoint& point) {
                                      const Eigen::Vector3f& ray = point.position_sensor;
                                      return dark_ahead && ray.x() > 0.0F &&
                                             std::abs(ray.y()) < std::tan(0.25F) * ray.x() &&
                                             ray.norm() > 4.0F;
                                    }),
                     frame.points.end());
  frame.has_motion = true;
  frame.motion.vehicle_at_start = estimate_start;
  frame.motion.vehicle_at_end = estimate_end;
  frame.motion.duration_s = revolution.duration_s;
  return frame;
}

FrameInput scanPlacedAt(const Eigen::Isometry3d& truth, const Eigen::Isometry3d& estimate, std::int64_t utime)
{
  return scanPlacedAt(truth, estimate, estimate, utime);
}

const Eigen::Isometry3d kInRoomA = vehiclePose(4.0, 4.0, 0.0);
const Goal kGoalInRoomB{1, geometry::Point(12.0, 4.0)};
constexpr std::int64_t kFramePeriodUs = 400'000;

/// Frames of true poses after the disturbance until the planner has a path again (`limit` when it has none
/// by then).
int framesUntilAPath(Planner& planner, int limit, std::int64_t& utime)
{
  for (int frame = 1; frame <= limit; ++frame) {
    utime += kFramePeriodUs;
    if (planner.processFrame(scanPlacedAt(kInRoomA, kInRoomA, utime)).path.valid) {
      return frame;
    }
  }
  return limit;
}

/// Carving alone: no forgetting of the memory for want of a path.
PlannerSettings withCarving(bool carving)
{
  PlannerSettings settings;
  settings.perception.no_path_forget_limit = 0;
  if (!carving) {
    settings.perception.carve_range_m = 0.0;
  }
  return settings;
}

/// Whether the middle of the doorway is inside an obstacle of the frame's layer: inside more outer
/// outlines than free-space holes.
bool doorwayBlocked(const FrameResult& frame)
{
  const geometry::Point doorway(8.0, 4.0);
  int depth = 0;
  for (const perception::LayerPolygon& polygon : frame.polygons) {
    if (geometry::containsPoint(polygon.vertices, doorway)) {
      depth += polygon.boundary == perception::BoundaryKind::Outer ? 1 : -1;
    }
  }
  return depth > 0;
}

/// Scans from the right pose until the doorway is free in the layer (`limit` when it is not by then).
int framesUntilTheDoorwayIsFree(Planner& planner, int limit, std::int64_t& utime)
{
  for (int frame = 1; frame <= limit; ++frame) {
    utime += kFramePeriodUs;
    if (!doorwayBlocked(planner.processFrame(scanPlacedAt(kInRoomA, kInRoomA, utime)))) {
      return frame;
    }
  }
  return limit;
}

// Drift smears the door's jambs into the doorway (scans placed 0.4 m too far up, then 0.4 m too far
// down, while nothing returned through the door: no ray showed it open), so the remembered walls close
// it. Later scans from the right pose pass through the doorway: the smeared cells go and the doorway is
// free again; without the rays' say, it stays shut for good.
TEST(PlannerEstimatorRobustness, ADoorSmearedClosedByDriftReopensWhenLaterRaysPassThroughIt)
{
  for (const bool carving : {true, false}) {
    Planner planner{withCarving(carving)};
    ASSERT_TRUE(planner.setGoal(kGoalInRoomB));
    std::int64_t utime = 0;
    const FrameResult first = planner.processFrame(scanPlacedAt(kInRoomA, kInRoomA, utime));
    ASSERT_FALSE(doorwayBlocked(first));
    ASSERT_TRUE(first.path.valid);
    FrameResult smeared;
    for (const double drift : {0.4, 0.4, 0.4, -0.4, -0.4, -0.4}) {
      utime += kFramePeriodUs;
      const Eigen::Isometry3d estimate = vehiclePose(4.0, 4.0 + drift, 0.0);
      smeared = planner.processFrame(scanPlacedAt(kInRoomA, estimate, estimate, utime, true));
    }
    EXPECT_TRUE(doorwayBlocked(smeared)) << "the smeared jambs close the door";

    constexpr int kLimit = 12;
    const int frames = framesUntilTheDoorwayIsFree(planner, kLimit, utime);
    if (carving) {
      EXPECT_LE(frames, 6) << "the door reopens within a few scans through it";
      EXPECT_TRUE(planner.processFrame(scanPlacedAt(kInRoomA, kInRoomA, utime + kFramePeriodUs)).path.valid);
    } else {
      EXPECT_EQ(frames, kLimit) << "without carving the door stays shut";
    }
  }
}

// A burst of spoofed poses: one scan placed from the true pose to one 30 m away (its walls smeared along
// the way, across both rooms), two from there, one back. From the next scans placed right the planner
// has its path through the door again within a few frames; without the rays' say, never.
TEST(PlannerEstimatorRobustness, ASpoofedPoseBurstLeavesThePlannerWithAPathAgainWithinAFewFrames)
{
  const Eigen::Isometry3d far_away = vehiclePose(30.0, 18.0, 2.0);
  for (const bool carving : {true, false}) {
    Planner planner{withCarving(carving)};
    ASSERT_TRUE(planner.setGoal(kGoalInRoomB));
    std::int64_t utime = 0;
    for (int frame = 0; frame < 3; ++frame, utime += kFramePeriodUs) {
      ASSERT_TRUE(planner.processFrame(scanPlacedAt(kInRoomA, kInRoomA, utime)).path.valid);
    }
    planner.processFrame(scanPlacedAt(kInRoomA, kInRoomA, far_away, utime));
    for (int frame = 0; frame < 2; ++frame) {
      utime += kFramePeriodUs;
      planner.processFrame(scanPlacedAt(kInRoomA, far_away, utime));
    }
    utime += kFramePeriodUs;
    const FrameResult back = planner.processFrame(scanPlacedAt(kInRoomA, far_away, kInRoomA, utime));
    if (!carving) {
      EXPECT_FALSE(back.path.valid) << "the smeared walls enclose the vehicle: " << back.status.message;
    }
    constexpr int kLimit = 15;
    const int frames = framesUntilAPath(planner, kLimit, utime);
    if (carving) {
      EXPECT_LE(frames, 5) << "a path again within a few frames of sane poses";
    } else {
      EXPECT_EQ(frames, kLimit) << "without carving the phantom walls stay";
    }
  }
}

// The same burst with carving off: the phantom walls leave no path, and the memory out of the latest
// scan's sight is forgotten (what the scan sees stays); the path is back within two frames. Without
// that, the planner stays at "no path".
TEST(PlannerEstimatorRobustness, WithNoPathLeftTheWallsRememberedOutOfSightAreForgotten)
{
  const Eigen::Isometry3d far_away = vehiclePose(30.0, 18.0, 2.0);
  for (const int limit : {3, 0}) {
    PlannerSettings settings = withCarving(false);
    settings.perception.no_path_forget_limit = limit;
    Planner planner{settings};
    ASSERT_TRUE(planner.setGoal(kGoalInRoomB));
    std::int64_t utime = 0;
    bool forgotten = false;
    const auto frame = [&](const Eigen::Isometry3d& start, const Eigen::Isometry3d& end) {
      FrameResult result = planner.processFrame(scanPlacedAt(kInRoomA, start, end, utime));
      utime += kFramePeriodUs;
      forgotten = forgotten || result.status.message.find("remembered wall cells") != std::string::npos;
      return result;
    };
    ASSERT_TRUE(frame(kInRoomA, kInRoomA).path.valid);
    frame(kInRoomA, far_away);
    frame(far_away, far_away);
    const FrameResult back = frame(far_away, kInRoomA);
    EXPECT_EQ(forgotten, limit > 0);
    constexpr int kLimit = 6;
    const int frames = framesUntilAPath(planner, kLimit, utime);
    if (limit > 0) {
      EXPECT_LE(frames, 2) << "the walls out of sight are gone, the latest scan's stay";
    } else {
      EXPECT_FALSE(back.path.valid) << back.status.message;
      EXPECT_EQ(frames, kLimit);
    }
  }
}

/// A reproducible offset of standard deviation `amplitude`, near Gaussian: the sum of three uniform ones
/// (std::mt19937's output is the same everywhere; the standard distributions are not).
double jitter(std::mt19937& random, double amplitude)
{
  double sum = 0.0;
  for (int term = 0; term < 3; ++term) {
    sum += 2.0 * static_cast<double>(random()) / 4294967295.0 - 1.0;
  }
  return amplitude * sum;
}

/// The planner's work over `frames` scans from room A placed with a pose off by `position_m` and
/// `heading_rad` (standard deviations, seeded): the last frame's, with the most cells any frame checked.
FrameWork workUnderJitter(int frames, double position_m, double heading_rad)
{
  Planner planner{PlannerSettings{}};
  planner.setGoal(kGoalInRoomB);
  std::mt19937 random(7);
  FrameWork work;
  FrameWork most;
  for (int frame = 0; frame < frames; ++frame) {
    const Eigen::Isometry3d estimate = vehiclePose(
        4.0 + jitter(random, position_m), 4.0 + jitter(random, position_m), jitter(random, heading_rad));
    work = planner.processFrame(scanPlacedAt(kInRoomA, estimate, frame * kFramePeriodUs)).status.work;
    most.checked_cells = std::max(most.checked_cells, work.checked_cells);
  }
  work.checked_cells = most.checked_cells;
  return work;
}

// Jitter of a state estimator's size (2 cm, 0.003 rad) does not pile up: after 80 jittered scans the
// remembered walls, the cells checked against the rays, the raster and the outlines' vertices stay within
// twice what still scans give, and the memory grows by little from 40 scans to 80.
TEST(PlannerEstimatorRobustness, FrameWorkUnderPoseJitterStaysBounded)
{
  const FrameWork still = workUnderJitter(80, 0.0, 0.0);
  const FrameWork jittered_40 = workUnderJitter(40, 0.02, 0.003);
  const FrameWork jittered = workUnderJitter(80, 0.02, 0.003);
  ASSERT_GT(still.remembered_cells, 100);
  EXPECT_LE(jittered.remembered_cells, 2 * still.remembered_cells) << "still " << still.remembered_cells;
  EXPECT_LE(jittered.remembered_cells, jittered_40.remembered_cells * 5 / 4);
  EXPECT_LE(jittered.checked_cells, 2 * still.remembered_cells);
  EXPECT_LE(jittered.layer_cells, 2 * still.layer_cells);
  EXPECT_LE(jittered.polygon_vertices, 2 * still.polygon_vertices) << "still " << still.polygon_vertices;
}

}  // namespace
}  // namespace ifar::planner
