#include "planner/perception/perception_pipeline.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "common/geometry/angle.hpp"
#include "planner/perception/motion_compensation.hpp"
#include "planner/perception/synthetic/synthetic_scan.hpp"
#include "tests/unit/perception/inflated_box_matching.hpp"

namespace ifar::perception {
namespace {

using synthetic::boxFootprint;
using synthetic::PrismObstacle;
using testing::mismatchToInflatedBox;
using testing::polygonsOf;

using ifar::geometry::kPi;

Eigen::Isometry3d planarPose(double x, double y, double yaw)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(x, y, 0.0);
  return pose;
}

SensorMount mount()
{
  SensorMount sensor_mount = SensorMount::Identity();
  sensor_mount.translation() = Eigen::Vector3d(0.2, 0.0, 0.8);
  return sensor_mount;
}

/// Two dull boxes and one tagged box around a vehicle at (1, 2) facing 30 degrees.
struct BoxScene {
  std::vector<PrismObstacle> obstacles = {{boxFootprint(5.0, 3.0, 2.0, 1.0), 1.0, 20.0F},
                                          {boxFootprint(-2.0, 6.0, 1.0, 1.0), 0.8, 30.0F},
                                          {boxFootprint(2.0, -2.0, 0.8, 0.6), 0.7, 200.0F}};
  Eigen::Isometry3d vehicle = planarPose(1.0, 2.0, kPi / 6.0);
  std::vector<double> heights = {0.3, 0.5, 0.7};

  std::vector<SensorPoint> scan() const
  {
    return synthetic::sampleObstacleFaces(obstacles, heights, 0.05, vehicle * mount());
  }
  PerceptionInput input(const std::vector<SensorPoint>& points) const
  {
    PerceptionInput perception_input;
    perception_input.points = points;
    perception_input.mount = mount();
    perception_input.motion.vehicle_at_start = vehicle;
    perception_input.motion.vehicle_at_end = vehicle;
    return perception_input;
  }
};

void expectMatches(const std::vector<LayerPolygon>& polygons, const std::vector<geometry::Polygon>& boxes,
                   const PerceptionSettings& settings)
{
  ASSERT_EQ(polygons.size(), boxes.size());
  for (const geometry::Polygon& box : boxes) {
    double best = std::numeric_limits<double>::infinity();
    for (const LayerPolygon& polygon : polygons) {
      best = std::min(best, mismatchToInflatedBox(polygon.vertices, box, settings.inflation_radius_m));
    }
    EXPECT_LE(best, 2.0 * settings.cell_size_m) << "box centred near " << geometry::centroid(box).transpose();
  }
}

TEST(PerceptionPipeline, KnownBoxesGiveInflatedPolygonsSplitByReflectivity)
{
  const PerceptionSettings settings;
  const BoxScene scene;
  const std::vector<SensorPoint> points = scene.scan();
  const PerceptionResult result = runPerception(scene.input(points), settings);
  EXPECT_EQ(result.status, PerceptionStatus::Ok) << result.message;
  EXPECT_EQ(result.stats.input_points, points.size());
  EXPECT_EQ(result.stats.non_finite_points, 0U);
  EXPECT_EQ(result.stats.outside_height_band_points, 0U);
  EXPECT_EQ(result.stats.movable_points, result.stats.input_points - result.stats.background_points);
  expectMatches(polygonsOf(result.layer, ObstacleClass::Background, BoundaryKind::Outer),
                {scene.obstacles[0].footprint, scene.obstacles[1].footprint}, settings);
  expectMatches(polygonsOf(result.layer, ObstacleClass::Movable, BoundaryKind::Outer),
                {scene.obstacles[2].footprint}, settings);
  // Faces sampled all round can leave small enclosed free space inside a box: a hole, inside that box.
  for (const LayerPolygon& hole : polygonsOf(result.layer, ObstacleClass::Background, BoundaryKind::Hole)) {
    const geometry::Point centre = geometry::centroid(hole.vertices);
    EXPECT_TRUE(geometry::containsPoint(scene.obstacles[0].footprint, centre) ||
                geometry::containsPoint(scene.obstacles[1].footprint, centre))
        << centre.transpose();
  }
  // The layer is centred on the vehicle.
  const double half = 0.5 * result.layer.extent.sideLength();
  EXPECT_NEAR(result.layer.extent.origin.x() + half, 1.0, 0.15);
  EXPECT_NEAR(result.layer.extent.origin.y() + half, 2.0, 0.15);
}

TEST(PerceptionPipeline, DetectorPolygonsDecideMovable)
{
  const PerceptionSettings settings;
  const BoxScene scene;
  const std::vector<SensorPoint> points = scene.scan();
  PerceptionInput input = scene.input(points);
  // The detector reports the first dull box as movable (slightly grown outline) and not the tagged one.
  input.detector_polygons = std::vector<geometry::Polygon>{boxFootprint(5.0, 3.0, 2.1, 1.1)};
  const PerceptionResult result = runPerception(input, settings);
  EXPECT_EQ(result.status, PerceptionStatus::Ok) << result.message;
  expectMatches(polygonsOf(result.layer, ObstacleClass::Movable, BoundaryKind::Outer),
                {scene.obstacles[0].footprint}, settings);
  expectMatches(polygonsOf(result.layer, ObstacleClass::Background, BoundaryKind::Outer),
                {scene.obstacles[1].footprint, scene.obstacles[2].footprint}, settings);
}

TEST(PerceptionPipeline, MovingVehicleScanIsCompensated)
{
  const PerceptionSettings settings;
  const BoxScene scene;
  // The vehicle drives 1.5 m forward and turns 20 degrees during the 0.1 s scan; each point is taken
  // from the pose at its own time.
  ScanMotion motion;
  motion.vehicle_at_start = planarPose(0.0, 0.0, 0.0);
  motion.vehicle_at_end = planarPose(1.5, 0.0, 20.0 * kPi / 180.0);
  motion.duration_s = 0.1;
  std::vector<SensorPoint> points;
  const std::vector<SensorPoint> world_aligned =
      synthetic::sampleObstacleFaces(scene.obstacles, scene.heights, 0.05, Eigen::Isometry3d::Identity());
  for (std::size_t index = 0; index < world_aligned.size(); ++index) {
    const double time =
        motion.duration_s * static_cast<double>(index) / static_cast<double>(world_aligned.size());
    const Eigen::Isometry3d sensor_to_world = interpolateVehiclePose(motion, time) * mount();
    SensorPoint point = world_aligned[index];
    point.position_sensor = (sensor_to_world.inverse() * point.position_sensor.cast<double>()).cast<float>();
    point.time_offset_s = time;
    points.push_back(point);
  }
  PerceptionInput input = scene.input(points);
  input.motion = motion;
  const PerceptionResult compensated = runPerception(input, settings);
  EXPECT_EQ(compensated.status, PerceptionStatus::Ok) << compensated.message;
  expectMatches(polygonsOf(compensated.layer, ObstacleClass::Background, BoundaryKind::Outer),
                {scene.obstacles[0].footprint, scene.obstacles[1].footprint}, settings);
  expectMatches(polygonsOf(compensated.layer, ObstacleClass::Movable, BoundaryKind::Outer),
                {scene.obstacles[2].footprint}, settings);

  // Without compensation (end pose for every point) the same points smear and miss the boxes.
  input.motion.vehicle_at_start = motion.vehicle_at_end;
  const PerceptionResult smeared = runPerception(input, settings);
  const auto movable = polygonsOf(smeared.layer, ObstacleClass::Movable, BoundaryKind::Outer);
  ASSERT_FALSE(movable.empty());
  EXPECT_GT(
      mismatchToInflatedBox(movable[0].vertices, scene.obstacles[2].footprint, settings.inflation_radius_m),
      2.0 * settings.cell_size_m);
}

TEST(PerceptionPipeline, NanPointsAreCountedAndDropped)
{
  const PerceptionSettings settings;
  const BoxScene scene;
  std::vector<SensorPoint> points = scene.scan();
  const std::size_t valid = points.size();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float infinity = std::numeric_limits<float>::infinity();
  for (int index = 0; index < 25; ++index) {
    // Cycle through the ways a coordinate can be malformed.
    SensorPoint bad;
    bad.position_sensor = Eigen::Vector3f(2.0F, 1.0F, 0.0F);
    bad.position_sensor[index % 3] = index % 2 == 0 ? nan : (index % 4 == 1 ? infinity : -infinity);
    points.push_back(bad);
  }
  SensorPoint bad_time;
  bad_time.position_sensor = Eigen::Vector3f(3.0F, 0.0F, 0.0F);
  bad_time.time_offset_s = std::numeric_limits<double>::quiet_NaN();
  points.push_back(bad_time);
  const PerceptionResult result = runPerception(scene.input(points), settings);
  EXPECT_EQ(result.status, PerceptionStatus::Ok);
  EXPECT_EQ(result.stats.non_finite_points, 26U);
  EXPECT_EQ(result.stats.background_points + result.stats.movable_points, valid);
  EXPECT_NE(result.message.find("non-finite"), std::string::npos) << result.message;
  EXPECT_EQ(polygonsOf(result.layer, ObstacleClass::Background, BoundaryKind::Outer).size(), 2U);
  EXPECT_EQ(polygonsOf(result.layer, ObstacleClass::Movable, BoundaryKind::Outer).size(), 1U);
}

TEST(PerceptionPipeline, EmptyScanGivesNoPolygonsAndSaysSo)
{
  const BoxScene scene;
  const std::vector<SensorPoint> points;
  const PerceptionSettings settings;
  const PerceptionResult result = runPerception(scene.input(points), settings);
  EXPECT_EQ(result.status, PerceptionStatus::EmptyScan);
  EXPECT_TRUE(result.layer.polygons.empty());
  EXPECT_NE(result.message.find("empty scan"), std::string::npos);
  EXPECT_STREQ(toString(result.status), "empty scan");
  EXPECT_EQ(result.layer.grid.cells, settings.layerCells());  // the layer is still there: all of it free
}

TEST(PerceptionPipeline, GroundOnlyScanHasNoObstaclePoints)
{
  const BoxScene scene;
  std::vector<SensorPoint> points;
  for (int index = 0; index < 100; ++index) {
    SensorPoint ground;
    ground.position_sensor = Eigen::Vector3f(2.0F + 0.1F * static_cast<float>(index), 0.0F, -0.78F);
    points.push_back(ground);
  }
  const PerceptionResult result = runPerception(scene.input(points), PerceptionSettings{});
  EXPECT_EQ(result.status, PerceptionStatus::NoObstaclePoints);
  EXPECT_EQ(result.stats.outside_height_band_points, 100U);
  EXPECT_TRUE(result.layer.polygons.empty());
}

TEST(PerceptionPipeline, InvalidMotionRejectsTheFrame)
{
  const BoxScene scene;
  const std::vector<SensorPoint> points = scene.scan();
  PerceptionInput input = scene.input(points);
  input.motion.vehicle_at_end.translation().y() = std::numeric_limits<double>::infinity();
  const PerceptionResult result = runPerception(input, PerceptionSettings{});
  EXPECT_EQ(result.status, PerceptionStatus::InvalidMotion);
  EXPECT_TRUE(result.layer.polygons.empty());
  EXPECT_FALSE(result.message.empty());
}

TEST(PerceptionPipeline, InvalidSettingsRejectTheFrame)
{
  const BoxScene scene;
  const std::vector<SensorPoint> points = scene.scan();
  PerceptionSettings settings;
  settings.cell_size_m = -0.15;
  const PerceptionResult result = runPerception(scene.input(points), settings);
  EXPECT_EQ(result.status, PerceptionStatus::InvalidSettings);
  EXPECT_NE(result.message.find("cell_size_m"), std::string::npos) << result.message;
  EXPECT_TRUE(result.layer.polygons.empty());
}

TEST(PerceptionPipeline, SimulatedRoomRevolution)
{
  const PerceptionSettings settings;
  synthetic::RevolutionSettings revolution;
  revolution.ceiling_height_m = 3.0;
  const std::vector<PrismObstacle> room = synthetic::roomWithBoxes();
  const Eigen::Isometry3d sensor_to_world = planarPose(0.0, 0.0, 0.0) * mount();
  const std::vector<SensorPoint> points = synthetic::simulateRevolution(room, sensor_to_world, revolution);
  EXPECT_EQ(points.size(), 1800U * 16U);  // walls, ground and ceiling return every beam
  PerceptionInput input;
  input.points = points;
  input.mount = mount();
  const PerceptionResult result = runPerception(input, settings);
  EXPECT_EQ(result.status, PerceptionStatus::Ok) << result.message;
  // The three tagged boxes are seen and are the only movable polygons.
  EXPECT_EQ(polygonsOf(result.layer, ObstacleClass::Movable, BoundaryKind::Outer).size(), 3U);
}

/// One revolution from the centre of the 32 m room of synthetic::roomWithBoxes with its walls only.
std::vector<SensorPoint> emptyRoomScan()
{
  std::vector<PrismObstacle> walls = synthetic::roomWithBoxes();
  walls.resize(4);
  synthetic::RevolutionSettings revolution;
  revolution.ceiling_height_m = 3.0;
  return synthetic::simulateRevolution(walls, planarPose(0.0, 0.0, 0.0) * mount(), revolution);
}

TEST(PerceptionPipeline, ClosedRoomEnclosesTheVehicleInAHole)
{
  // Walls only: nothing casts a shadow, so the inflated walls close into a ring around the vehicle.
  const std::vector<SensorPoint> points = emptyRoomScan();
  PerceptionInput input;
  input.points = points;
  input.mount = mount();
  const PerceptionSettings settings;
  const PerceptionResult result = runPerception(input, settings);
  const auto holes = polygonsOf(result.layer, ObstacleClass::Background, BoundaryKind::Hole);
  ASSERT_EQ(holes.size(), 1U);
  EXPECT_TRUE(geometry::containsPoint(holes[0].vertices, geometry::Point(0.0, 0.0)));
  // The inner wall faces are at +-16 m; the free space ends one inflation radius before them.
  EXPECT_LE(mismatchToInflatedBox(holes[0].vertices,
                                  boxFootprint(0.0, 0.0, 32.0 - 2.0 * 0.35, 32.0 - 2.0 * 0.35), 0.0),
            2.0 * settings.cell_size_m);
  EXPECT_EQ(polygonsOf(result.layer, ObstacleClass::Background, BoundaryKind::Outer).size(), 1U);
}

// Remembered walls within scan_trust_range_m that this scan's rays reached are left out (the scan says
// what stands there); beyond that range, behind what the rays hit, and what is kept otherwise (sealed
// passages, a prior map) are drawn.
TEST(PerceptionPipeline, RememberedWallsWhereTheScanLookedCloseByAreLeftOut)
{
  const std::vector<SensorPoint> points = emptyRoomScan();
  const std::vector<geometry::Point> remembered = {geometry::Point(3.05, 0.05), geometry::Point(12.05, 0.05),
                                                   geometry::Point(17.05, 0.05)};
  const std::vector<geometry::Point> kept = {geometry::Point(0.05, 3.05)};
  PerceptionInput input;
  input.points = points;
  input.mount = mount();
  input.remembered_background = common::Span<const geometry::Point>(remembered.data(), remembered.size());
  input.kept_background = common::Span<const geometry::Point>(kept.data(), kept.size());
  const auto occupied = [](const PerceptionResult& result, const geometry::Point& point) {
    const auto index = result.layer.grid.indexOf(point);
    return index && result.layer.background_occupancy[*index] != 0;
  };
  for (const double range : {8.0, 0.0}) {
    PerceptionSettings settings;
    settings.scan_trust_range_m = range;
    const PerceptionResult result = runPerception(input, settings);
    ASSERT_EQ(result.status, PerceptionStatus::Ok) << result.message;
    EXPECT_EQ(occupied(result, remembered[0]), range == 0.0) << "in view, " << range;
    EXPECT_TRUE(occupied(result, remembered[1])) << "beyond the range";
    EXPECT_TRUE(occupied(result, remembered[2])) << "behind the wall";
    EXPECT_TRUE(occupied(result, kept[0])) << "kept";
  }
}

// The cells along a corridor wall's inflated face from y_from to y_to that the layer leaves free.
int freeCellsAlongWall(const LocalLayer& layer, double face_x, double y_from, double y_to)
{
  int free_cells = 0;
  for (double y = y_from; y <= y_to; y += 0.05) {
    const auto index = layer.grid.indexOf(geometry::Point(face_x, y));
    if (!index || layer.background_occupancy[*index] == 0) {
      ++free_cells;
    }
  }
  return free_cells;
}

TEST(PerceptionPipeline, AFarCorridorWallIsWholeWithGrazingGapsFilled)
{
  // A 4 m corridor running 80 m north of the vehicle, walls 4 m high: 25-35 m on, its walls are seen at
  // 3.3-4.6 degrees by the one laser whose returns lie in the height band there (-1 degree).
  const std::vector<PrismObstacle> walls = {{boxFootprint(-2.1, 35.0, 0.2, 90.0), 4.0, 20.0F},
                                            {boxFootprint(2.1, 35.0, 0.2, 90.0), 4.0, 20.0F}};
  const Eigen::Isometry3d vehicle = planarPose(0.0, 0.0, kPi / 2.0);
  const std::vector<SensorPoint> points =
      synthetic::simulateRevolution(walls, vehicle * mount(), synthetic::RevolutionSettings{});
  PerceptionInput input;
  input.points = points;
  input.mount = mount();
  input.motion.vehicle_at_start = vehicle;
  input.motion.vehicle_at_end = vehicle;
  PerceptionSettings settings;
  settings.gap_fill_azimuth_step_deg = 0.2;  // the VLP-16's step at 10 Hz, as the synthetic revolution's
  const PerceptionResult filled = runPerception(input, settings);
  ASSERT_EQ(filled.status, PerceptionStatus::Ok) << filled.message;
  EXPECT_GT(filled.stats.gap_fill_points, 0U);
  // The inflated face 0.35 m inside each wall is occupied all the way to 35 m on.
  EXPECT_EQ(freeCellsAlongWall(filled.layer, 2.0 - 0.3, 1.0, 35.0), 0);
  EXPECT_EQ(freeCellsAlongWall(filled.layer, -2.0 + 0.3, 1.0, 35.0), 0);
  // The memory gets only what the rays hit.
  EXPECT_EQ(filled.observed_background.size(), filled.stats.background_points);

  settings.gap_fill_azimuth_step_deg = 0.0;
  const PerceptionResult unfilled = runPerception(input, settings);
  EXPECT_EQ(unfilled.stats.gap_fill_points, 0U);
  EXPECT_GT(freeCellsAlongWall(unfilled.layer, 2.0 - 0.3, 1.0, 35.0), 20);
}

}  // namespace
}  // namespace ifar::perception
