// TagHold (planner/core/tag_hold.hpp): a movable object's returns seen from beyond the lidar's face range
// keep its class when the vehicle is close, and the planner keeps the push through a door that a low,
// tagged box plugs while the vehicle comes up to it with some of the box's tags missed.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "planner/core/planner.hpp"
#include "planner/core/tag_hold.hpp"
#include "planner/perception/classification.hpp"
#include "planner/perception/motion_compensation.hpp"
#include "planner/perception/synthetic/synthetic_scan.hpp"
#include "sim/sensing/sensing_settings.hpp"
#include "sim/world/world_file.hpp"
#include "testing/simulated_feed.hpp"

namespace ifar::planner {
namespace {

using perception::synthetic::boxFootprint;
using perception::synthetic::PrismObstacle;

TrackedObject objectAt(std::int64_t id, const geometry::Polygon& outline)
{
  TrackedObject object;
  object.id = id;
  object.outline = outline;
  object.centroid = geometry::centroid(outline);
  return object;
}

TEST(TagHold, TheFaceRangeIsWhereTheLowestLaserMeetsTheObstacleBandsBottom)
{
  common::VehicleSettings vehicle;
  vehicle.lidar_height_m = 0.8;
  vehicle.lidar.ground_clearance_m = 0.15;
  const TagHoldSettings settings = TagHoldSettings::fromVehicle(vehicle, 0.1);
  // The VLP-16's lowest laser looks 15 degrees down.
  EXPECT_NEAR(settings.face_range_m, 0.65 / std::tan(15.0 * M_PI / 180.0), 1e-9);
  EXPECT_DOUBLE_EQ(settings.margin_m, 0.1);
  vehicle.lidar.ground_clearance_m = 0.9;  // the lidar below the band: every laser meets a face's foot
  EXPECT_DOUBLE_EQ(TagHoldSettings::fromVehicle(vehicle, 0.1).face_range_m, 0.0);
}

TEST(TagHold, ReturnsSeenFromBeyondTheFaceRangeAreHeldWhenTheSensorComesClose)
{
  TagHoldSettings settings;
  settings.face_range_m = 2.4;
  settings.margin_m = 0.1;
  TagHold hold(settings);
  const geometry::Polygon outline = boxFootprint(5.0, 0.0, 1.2, 1.6);  // inflated outline of a face
  std::vector<geometry::Point> face;
  for (double y = -0.45; y <= 0.45; y += 0.01) {
    face.emplace_back(4.75, y);
  }
  const std::vector<float> heights(face.size(), 0.7F);
  // A door post's face beside the box's end, inside the object's inflated outline.
  const std::vector<geometry::Point> post{geometry::Point(4.9, 0.5), geometry::Point(4.9, 0.55),
                                          geometry::Point(7.0, 0.0)};
  const std::vector<TrackedObject> seen{objectAt(3, outline)};

  const auto observeFrom = [&](const std::vector<geometry::Point>& points, const geometry::Point& sensor) {
    hold.observe(seen, common::Span<const geometry::Point>(points.data(), points.size()),
                 common::Span<const float>(heights.data(), points.size()),
                 common::Span<const geometry::Point>(post.data(), post.size()), sensor);
  };
  // First seen 1.75 m away, within the face range: the best view so far is held.
  observeFrom(face, geometry::Point(3.0, 0.0));
  ASSERT_TRUE(hold.holds(3));
  EXPECT_TRUE(hold.heldNear(geometry::Point(3.0, 0.0)).movable.empty()) << "not nearer than the view held";
  EXPECT_FALSE(hold.heldNear(geometry::Point(3.5, 0.0)).movable.empty());

  // From 3.5 m, beyond the face range: replaces it (one return per cell half a margin wide), and it is
  // given out only within the face range.
  observeFrom(face, geometry::Point(1.25, 0.0));
  const std::size_t held = hold.heldOf(3).size();
  EXPECT_GE(held, 18U);
  EXPECT_LT(held, face.size());
  EXPECT_TRUE(hold.heldNear(geometry::Point(1.25, 0.0)).movable.empty());
  EXPECT_TRUE(hold.heldNear(geometry::Point(2.3, 0.0)).movable.empty());
  EXPECT_EQ(hold.heldNear(geometry::Point(4.3, 0.0)).movable.size(), held);
  EXPECT_EQ(hold.heldNear(geometry::Point(3.0, 0.0)).movable.size(), held);
  EXPECT_EQ(hold.heldNear(geometry::Point(4.3, 0.0)).background.size(), 2U) << "the post, not the far wall";

  // Nearer views (a part of the face up close, all of it from 1.75 m) do not replace what was held.
  const std::vector<geometry::Point> part(face.begin(), face.begin() + 10);
  observeFrom(part, geometry::Point(4.3, 0.0));
  EXPECT_EQ(hold.heldOf(3).size(), held);
  observeFrom(std::vector<geometry::Point>(face.begin(), face.begin() + 50), geometry::Point(3.0, 0.0));
  EXPECT_EQ(hold.heldOf(3).size(), held);

  hold.forget(3);
  EXPECT_FALSE(hold.holds(3));
  observeFrom(face, geometry::Point(1.25, 0.0));
  ASSERT_TRUE(hold.holds(3));

  // Pushed 0.3 m on, seen from 0.5 m: its tagged returns lie away from where it was held, and the hold goes.
  std::vector<geometry::Point> pushed;
  for (const geometry::Point& point : face) {
    pushed.push_back(point + geometry::Point(0.3, 0.0));
  }
  observeFrom(pushed, geometry::Point(4.55, 0.0));
  EXPECT_FALSE(hold.holds(3));
}

perception::WorldPoint returnAt(double x, double y, float reflectivity)
{
  perception::WorldPoint point;
  point.position_world = Eigen::Vector3d(x, y, 0.7);
  point.sensor_world = Eigen::Vector3d(4.3, 0.0, 0.8);
  point.height_above_ground_m = 0.7;
  point.reflectivity = reflectivity;
  point.range_m = (point.position_world - point.sensor_world).norm();
  return point;
}

TEST(TagHold, HeldReturnsReadAMissedTagBesideTheFaceAsMovableAndThePostAsWall)
{
  // Held from farther: the face at x 4.75 (y -0.45 .. 0.45) and a door post's face 0.15 m behind it,
  // 0.05 m beyond the box's end.
  std::vector<geometry::Point> face;
  for (double y = -0.45; y <= 0.451; y += 0.05) {
    face.emplace_back(4.75, y);
  }
  const std::vector<geometry::Point> post{geometry::Point(4.9, 0.5), geometry::Point(4.9, 0.55)};
  perception::HeldReturns held;
  held.movable = common::Span<const geometry::Point>(face.data(), face.size());
  held.background = common::Span<const geometry::Point>(post.data(), post.size());
  held.margin_m = 0.1;
  // This scan, up close: a missed tag on the face, the post's corner 0.1 m from the face's end and 0.06 m
  // from the post, a wall far off, and a tagged return.
  const std::vector<perception::WorldPoint> points{returnAt(4.77, 0.2, 60.0F), returnAt(4.84, 0.49, 20.0F),
                                                   returnAt(6.0, 0.0, 20.0F), returnAt(4.75, 0.0, 200.0F)};
  perception::TagReading reading;
  reading.neighbourhood_m = 0.0;
  std::size_t taken = 0;
  const perception::ClassifiedPoints classified = perception::classifyByReflectivity(
      common::Span<const perception::WorldPoint>(points.data(), points.size()), reading, held, taken);
  EXPECT_EQ(taken, 1U);
  ASSERT_EQ(classified.movable.size(), 2U);
  EXPECT_EQ(classified.movable[0], geometry::Point(4.75, 0.0));
  EXPECT_EQ(classified.movable[1], geometry::Point(4.77, 0.2)) << "the missed tag, last";
  ASSERT_EQ(classified.background.size(), 2U);
  EXPECT_EQ(classified.background[0], geometry::Point(4.84, 0.49)) << "the post stays wall";
  EXPECT_EQ(classified.movable_heights_m.size(), 2U);
  EXPECT_EQ(classified.background_heights_m.size(), 2U);

  // Nothing held: as by the tags alone.
  std::size_t none = 7;
  const perception::ClassifiedPoints alone = perception::classifyByReflectivity(
      common::Span<const perception::WorldPoint>(points.data(), points.size()), reading,
      perception::HeldReturns{}, none);
  EXPECT_EQ(none, 0U);
  EXPECT_EQ(alone.movable.size(), 1U);
}

// A room and the corridor beyond its wall (walls 0.2 m thick and 2 m high), joined only by a 1.0 m door
// at x 2.3 .. 3.3 that a light tagged box plugs: 0.9 m wide, 0.5 m deep and 0.8 m tall, standing in the
// wall's middle, its face 0.15 m in front of the wall and 0.05 m from each door post. The vehicle starts
// 2.5 m from the door, facing it.
const sim::World& roomWithABoxedDoor()
{
  static const sim::World world = [] {
    const std::string text = R"(name: "boxed_door"
units: m
start: {x: 2.8, y: 11.15, heading_deg: 90}
goals:
  - {name: "corridor", x: 5.5, y: 15.0}
obstacles:
  - {name: "south", height: 2, reflectivity: 0.2, polygon: [0, 7, 7, 7, 7, 7.2, 0, 7.2]}
  - {name: "west", height: 2, reflectivity: 0.2, polygon: [0, 7.2, 0.2, 7.2, 0.2, 16.25, 0, 16.25]}
  - {name: "east", height: 2, reflectivity: 0.2, polygon: [6.8, 7.2, 7, 7.2, 7, 16.25, 6.8, 16.25]}
  - {name: "north", height: 2, reflectivity: 0.2, polygon: [0, 16.25, 7, 16.25, 7, 16.45, 0, 16.45]}
  - {name: "wall_west", height: 2, reflectivity: 0.2, polygon: [0.2, 13.55, 2.3, 13.55, 2.3, 13.75, 0.2, 13.75]}
  - {name: "wall_east", height: 2, reflectivity: 0.2, polygon: [3.3, 13.55, 6.8, 13.55, 6.8, 13.75, 3.3, 13.75]}
objects:
  - id: 1
    name: "door_box"
    pose: {x: 2.8, y: 13.65, heading_deg: 0}
    mass_kg: 20
    ground_friction: 0.4
    reflectivity: 0.9
    height: 0.8
    polygon: [-0.45, -0.25, 0.45, -0.25, 0.45, 0.25, -0.45, 0.25]
)";
    const sim::WorldResult parsed = sim::parseWorld(text, "tag_hold_test");
    EXPECT_TRUE(parsed.ok()) << parsed.error();
    return parsed.ok() ? parsed.world() : sim::World{};
  }();
  return world;
}

/// Frames of the vehicle standing at `start` under the field profile's lidar (missed and false tags,
/// range noise, dropouts; the pose exact), `seconds` long, from scan time `utime_offset` on.
std::vector<FrameInput> standingFieldFrames(const geometry::Pose2& start, double seconds,
                                            std::int64_t utime_offset)
{
  sim::World world = roomWithABoxedDoor();
  world.start = start;
  sim::SimulatorSettings settings;
  settings.sensing.lidar = sim::sensingProfile(sim::SensingProfile::kField).lidar;
  settings.seed = 3;
  FrameAssembler assembler{InputSettings{}};
  std::vector<FrameInput> frames =
      test_support::feedAll(test_support::recordSimulation(world, settings, seconds), assembler);
  for (FrameInput& frame : frames) {
    frame.utime += utime_offset;
  }
  return frames;
}

// The vehicle sees the door box from its start 2.5 m away, then stands at the push's stand-off point, the
// bumper 0.05 m from the box's face (the lidar 0.3 m from it). From there the lowest lasers pass over all but
// a strip under the box's top, and the walls beside and behind the door outvote that strip's missed tags:
// without the hold the face reads as wall across the door, the box's push edges go and nothing leads into the
// corridor. With it the box keeps its id, its class and its push through the door.
TEST(TagHold, ABoxPluggingADoorKeepsItsPushAtTheStandOffPointWithMissedTags)
{
  Planner planner{PlannerSettings{}};
  ASSERT_TRUE(planner.setGoal(Goal{1, roomWithABoxedDoor().goals.front().position}));
  const geometry::Pose2 start = roomWithABoxedDoor().start;
  FrameResult result;
  for (const FrameInput& frame : standingFieldFrames(start, 2.0, 0)) {
    result = planner.processFrame(frame);
  }
  ASSERT_TRUE(result.path.valid) << result.status.message;
  ASSERT_EQ(result.path.pushes.size(), 1U) << "from the start the push through the door is the way";
  const std::int64_t box = result.path.pushes.front().object_id;

  const double face_y = 13.4;
  const geometry::Pose2 stand_off{2.8, face_y - 0.5 * common::VehicleSettings{}.length_m - 0.05, M_PI / 2.0};
  int frames = 0;
  for (const FrameInput& frame : standingFieldFrames(stand_off, 4.0, 10'000'000)) {
    result = planner.processFrame(frame);
    ++frames;
    ASSERT_TRUE(result.path.valid) << "frame " << frames
                                   << " at the stand-off point: " << result.status.message;
    ASSERT_EQ(result.path.pushes.size(), 1U) << "frame " << frames << " at the stand-off point";
    EXPECT_EQ(result.path.pushes.front().object_id, box);
  }
  EXPECT_GE(frames, 30);
}

// A box taller than the lidar held in a 1.0 m door at y 3.5 .. 4.5 of a wall at x 7.9 .. 8.1, then pushed
// out of it: the scan from 1.05 m sees through the open door, and what its rays pass beyond is not held
// any more (the ends of the face, where the posts stop the rays across their cells, may stay). A ray over
// a box lower than the lidar does not show it gone (FreeSpaceView::seesThrough).
TEST(TagHold, WhereRaysPassThroughAHeldObjectNothingIsHeld)
{
  TagHoldSettings settings;
  settings.face_range_m = 2.4;
  settings.margin_m = 0.1;
  TagHold hold(settings);
  std::vector<geometry::Point> face;
  for (double y = 3.55; y <= 4.45; y += 0.01) {
    face.emplace_back(7.75, y);
  }
  const std::vector<float> heights(face.size(), 1.0F);
  hold.observe({objectAt(2, boxFootprint(8.0, 4.0, 1.2, 1.6))},
               common::Span<const geometry::Point>(face.data(), face.size()),
               common::Span<const float>(heights.data(), heights.size()),
               common::Span<const geometry::Point>(), geometry::Point(4.2, 4.0));
  ASSERT_TRUE(hold.holds(2));

  const auto wall = [](double centre_x, double centre_y, double size_x, double size_y) {
    PrismObstacle obstacle;
    obstacle.footprint = boxFootprint(centre_x, centre_y, size_x, size_y);
    obstacle.height_m = 2.0;
    return obstacle;
  };
  const std::vector<PrismObstacle> world{wall(8.0, 1.75, 0.2, 3.5), wall(8.0, 6.25, 0.2, 3.5),
                                         wall(16.1, 4.0, 0.2, 8.4)};
  Eigen::Isometry3d sensor = perception::lidarMount(common::VehicleSettings{});
  sensor.translation() += Eigen::Vector3d(6.5, 4.0, 0.0);
  perception::synthetic::RevolutionSettings revolution;
  revolution.ceiling_height_m = 3.0;
  const std::vector<perception::SensorPoint> points =
      perception::synthetic::simulateRevolution(world, sensor, revolution);
  perception::ScanMotion motion;
  motion.vehicle_at_start.translation() = Eigen::Vector3d(6.5, 4.0, 0.0);
  motion.vehicle_at_end = motion.vehicle_at_start;
  const std::vector<perception::WorldPoint> world_points =
      perception::compensateMotion(common::Span<const perception::SensorPoint>(points.data(), points.size()),
                                   perception::lidarMount(common::VehicleSettings{}), motion);
  const perception::FreeSpaceView view(
      common::Span<const perception::WorldPoint>(world_points.data(), world_points.size()),
      geometry::Point(sensor.translation().x(), sensor.translation().y()), perception::FreeSpaceSettings{});
  const std::size_t held = hold.heldOf(2).size();
  EXPECT_GT(hold.releaseSeenThrough(view, 0.15), held / 2);
  for (const geometry::Point& point : hold.heldOf(2)) {
    EXPECT_GT(std::abs(point.y() - 4.0), 0.3) << "held at y " << point.y();
  }
}

}  // namespace
}  // namespace ifar::planner
