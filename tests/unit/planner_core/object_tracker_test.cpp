// Stable movable-object ids across frames, and the occupancy rectangles of the interaction scene.

#include <algorithm>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "planner/core/object_tracker.hpp"
#include "planner/core/occupancy_rectangles.hpp"

namespace ifar::planner {
namespace {

geometry::Polygon box(double centre_x, double centre_y, double half_x, double half_y)
{
  return {geometry::Point(centre_x - half_x, centre_y - half_y),
          geometry::Point(centre_x + half_x, centre_y - half_y),
          geometry::Point(centre_x + half_x, centre_y + half_y),
          geometry::Point(centre_x - half_x, centre_y + half_y)};
}

const geometry::Point kVehicle(0.0, 0.0);

TEST(ObjectTracker, KeepsIdsWhileObjectsShiftAndGivesNewOnesToNewObjects)
{
  ObjectTracker tracker{TrackerSettings{}};
  const TrackingResult first = tracker.update({box(5.0, 0.0, 0.5, 0.5), box(0.0, 5.0, 0.4, 0.4)}, kVehicle);
  ASSERT_EQ(first.polygon_ids.size(), 2U);
  EXPECT_EQ(first.polygon_ids[0], 1);
  EXPECT_EQ(first.polygon_ids[1], 2);
  EXPECT_EQ(first.seen.size(), 2U);
  // Listed in another order, shifted by perception noise, plus a new object.
  const TrackingResult second = tracker.update(
      {box(0.1, 5.05, 0.4, 0.4), box(-6.0, 0.0, 0.5, 0.5), box(5.08, -0.05, 0.5, 0.5)}, kVehicle);
  EXPECT_EQ(second.polygon_ids, (std::vector<std::int64_t>{2, 3, 1}));
  EXPECT_TRUE(second.dropped.empty());
  ASSERT_EQ(second.seen.size(), 3U);
  EXPECT_EQ(second.seen[0].id, 1);
  EXPECT_NEAR(second.seen[0].centroid.x(), 5.08, 1e-9);
}

TEST(ObjectTracker, SplitOutlinesShareTheObjectsId)
{
  ObjectTracker tracker{TrackerSettings{}};
  tracker.update({box(5.0, 0.0, 0.6, 0.5)}, kVehicle);
  // The sensor splits the object into two pieces (a gap in the returns): one id, hull as outline.
  const TrackingResult split = tracker.update({box(4.7, 0.0, 0.3, 0.5), box(5.35, 0.0, 0.25, 0.5)}, kVehicle);
  EXPECT_EQ(split.polygon_ids, (std::vector<std::int64_t>{1, 1}));
  ASSERT_EQ(split.seen.size(), 1U);
  EXPECT_NEAR(split.seen[0].centroid.x(), 5.0, 0.01);
  EXPECT_EQ(tracker.size(), 1U);
  // A new object seen split from its first frame is one object too.
  const TrackingResult fresh =
      tracker.update({box(5.0, 0.0, 0.6, 0.5), box(0.0, 8.0, 0.3, 0.3), box(0.5, 8.0, 0.25, 0.3)}, kVehicle);
  EXPECT_EQ(fresh.polygon_ids, (std::vector<std::int64_t>{1, 2, 2}));
}

TEST(ObjectTracker, TouchingObjectsDoNotThrashIds)
{
  ObjectTracker tracker{TrackerSettings{}};
  tracker.update({box(5.0, 0.0, 0.4, 0.4), box(5.9, 0.0, 0.4, 0.4)}, kVehicle);
  // Pushed together: one outline covering both for a few frames.
  for (int frame = 0; frame < 8; ++frame) {
    const TrackingResult merged = tracker.update({box(5.42, 0.0, 0.85, 0.4)}, kVehicle);
    ASSERT_EQ(merged.polygon_ids.size(), 1U);
    EXPECT_TRUE(merged.polygon_ids[0] == 1 || merged.polygon_ids[0] == 2);
    EXPECT_TRUE(merged.dropped.empty()) << "frame " << frame;
  }
  EXPECT_EQ(tracker.size(), 2U);
  // Apart again: each keeps its own id, no new ones.
  const TrackingResult apart = tracker.update({box(5.9, 0.0, 0.4, 0.4), box(5.0, 0.0, 0.4, 0.4)}, kVehicle);
  std::vector<std::int64_t> ids = apart.polygon_ids;
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(tracker.size(), 2U);
}

TEST(ObjectTracker, DropsObjectsUnseenInViewOnlyAfterSeveralFrames)
{
  TrackerSettings settings;
  settings.drop_after_frames = 3;
  settings.view_radius_m = 10.0;
  ObjectTracker tracker{settings};
  tracker.update({box(5.0, 0.0, 0.4, 0.4), box(30.0, 0.0, 0.4, 0.4)}, kVehicle);
  EXPECT_TRUE(tracker.update({}, kVehicle).dropped.empty());
  EXPECT_TRUE(tracker.update({}, kVehicle).dropped.empty());
  const TrackingResult third = tracker.update({}, kVehicle);
  EXPECT_EQ(third.dropped, (std::vector<std::int64_t>{1}));  // the far one is out of view: kept
  EXPECT_FALSE(tracker.contains(1));
  EXPECT_TRUE(tracker.contains(2));
  // Ids are never reused.
  EXPECT_EQ(tracker.update({box(5.0, 0.0, 0.4, 0.4)}, kVehicle).polygon_ids, (std::vector<std::int64_t>{3}));
  EXPECT_TRUE(tracker.forget(2));
  EXPECT_FALSE(tracker.forget(2));
}

TEST(ObjectTracker, AnObjectOutOfSightIsNotMissing)
{
  TrackerSettings settings;
  settings.drop_after_frames = 2;
  ObjectTracker tracker{settings};
  tracker.update({box(5.0, 0.0, 0.4, 0.4)}, kVehicle);
  // Behind a wall for many frames: kept, and found again under its id.
  const auto behind_wall = [](const geometry::Point&) { return false; };
  for (int frame = 0; frame < 10; ++frame) {
    EXPECT_TRUE(tracker.update({}, kVehicle, behind_wall).dropped.empty()) << "frame " << frame;
  }
  EXPECT_EQ(tracker.update({box(5.1, 0.0, 0.4, 0.4)}, kVehicle, behind_wall).polygon_ids,
            (std::vector<std::int64_t>{1}));
  // In sight and not seen: missing, dropped after two frames.
  const auto in_the_open = [](const geometry::Point&) { return true; };
  EXPECT_TRUE(tracker.update({}, kVehicle, in_the_open).dropped.empty());
  EXPECT_EQ(tracker.update({}, kVehicle, in_the_open).dropped, (std::vector<std::int64_t>{1}));
}

// BLOCKED_PASSAGE names no object: the planner asks which one lies at the vehicle's way to the point it
// could not reach.
TEST(ObjectTracker, TheObjectNearestASegmentWithinTheRadius)
{
  ObjectTracker tracker{TrackerSettings{}};
  tracker.update({box(5.0, 0.0, 0.5, 0.5), box(5.0, 3.0, 0.5, 0.5)}, kVehicle);
  // Through object 1.
  EXPECT_EQ(tracker.nearestTo(geometry::Segment{{4.0, -2.0}, {6.0, 2.0}}, 0.15), 1);
  // Passing 0.1 m beside object 2's west face (x = 4.5), 1.5 m from object 1.
  EXPECT_EQ(tracker.nearestTo(geometry::Segment{{4.4, 1.5}, {4.4, 4.0}}, 0.15), 2);
  // 0.3 m off: none within 0.15 m, object 2 within 0.5 m.
  EXPECT_FALSE(tracker.nearestTo(geometry::Segment{{4.2, 2.0}, {4.2, 4.0}}, 0.15).has_value());
  EXPECT_EQ(tracker.nearestTo(geometry::Segment{{4.2, 2.0}, {4.2, 4.0}}, 0.5), 2);
}

TEST(OccupancyRectangles, CoverExactlyTheOccupiedCellsInTheRegion)
{
  perception::LayerGrid grid;
  grid.origin = geometry::Point(10.0, 20.0);
  grid.cell_size_m = 0.5;
  grid.cells = 6;
  std::vector<std::uint8_t> occupancy(36, 0);
  const auto set = [&](int column, int row) { occupancy[static_cast<std::size_t>(row * 6 + column)] = 1; };
  for (int row = 0; row < 6; ++row) {
    set(0, row);  // a wall along the left side
  }
  set(3, 2);
  set(4, 2);
  set(3, 3);
  set(4, 3);  // a 2 x 2 block
  set(5, 5);  // a single cell
  const std::vector<geometry::Polygon> all =
      occupancyRectangles(grid, occupancy, geometry::Point(0.0, 0.0), geometry::Point(100.0, 100.0));
  ASSERT_EQ(all.size(), 3U);
  double area = 0.0;
  for (const geometry::Polygon& rectangle : all) {
    ASSERT_EQ(rectangle.size(), 4U);
    EXPECT_GT(geometry::signedArea(rectangle), 0.0);
    area += geometry::area(rectangle);
  }
  EXPECT_DOUBLE_EQ(area, 11 * 0.25);
  EXPECT_DOUBLE_EQ(all[0][0].x(), 10.0);
  EXPECT_DOUBLE_EQ(all[0][2].y(), 23.0);  // the whole wall in one piece
  // Only cells whose centres lie in the region.
  const std::vector<geometry::Polygon> clipped =
      occupancyRectangles(grid, occupancy, geometry::Point(11.4, 21.0), geometry::Point(12.6, 21.6));
  ASSERT_EQ(clipped.size(), 1U);
  EXPECT_DOUBLE_EQ(geometry::area(clipped[0]), 2 * 0.25);
  // A mismatched raster gives nothing.
  EXPECT_TRUE(occupancyRectangles(grid, std::vector<std::uint8_t>(5, 1), geometry::Point(0.0, 0.0),
                                  geometry::Point(100.0, 100.0))
                  .empty());
}

}  // namespace
}  // namespace ifar::planner
