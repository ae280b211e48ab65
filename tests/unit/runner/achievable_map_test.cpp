// The achievable map: a light box in the only door is no obstacle (it can be pushed aside), a heavy one
// is; a point in an inflated wall is moved out and the move counts.

#include "system/achievable_map.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "tests/unit/scenarios/test_worlds.hpp"

namespace ifar::runner {
namespace {

using geometry::Point;

TEST(AchievableMap, ALightBoxInTheDoorIsNoObstacleAHeavyOneIs)
{
  const common::VehicleSettings vehicle;
  AchievableMapSettings settings;
  settings.inflation_m = 0.5 * vehicle.width_m;
  graph::SearchScratch scratch;

  const PlanningGraph light =
      buildAchievableMap(scenarios::test::twoRoomsWithDoorBox(false), vehicle, settings);
  // Straight through the door's middle, on the line y = 5 that the inflated jambs leave free.
  EXPECT_NEAR(achievableDistance(light, Point(5.0, 5.0), Point(25.0, 5.0), scratch), 20.0, 1e-9);

  const PlanningGraph heavy =
      buildAchievableMap(scenarios::test::twoRoomsWithDoorBox(true), vehicle, settings);
  EXPECT_TRUE(std::isinf(achievableDistance(heavy, Point(5.0, 5.0), Point(25.0, 5.0), scratch)));
  // Within one room the box does not matter.
  EXPECT_NEAR(achievableDistance(heavy, Point(5.0, 5.0), Point(5.0, 8.0), scratch), 3.0, 1e-9);
}

TEST(AchievableMap, APointInAnInflatedWallIsMovedOutAndTheMoveCounts)
{
  const common::VehicleSettings vehicle;
  AchievableMapSettings settings;
  settings.inflation_m = 0.5 * vehicle.width_m;
  graph::SearchScratch scratch;
  const PlanningGraph map =
      buildAchievableMap(scenarios::test::twoRoomsWithDoorBox(false), vehicle, settings);
  // 0.3 m above the south wall (top at y = 0.2): its inflated raster (0.35 m on 0.15 m cells) reaches
  // y = 0.6, so the point moves 0.1 m up first, then straight on to a goal on the line y = 0.6.
  const double distance = achievableDistance(map, Point(5.0, 0.5), Point(9.0, 0.6), scratch);
  EXPECT_NEAR(distance, 0.1 + 4.0, 1e-6);
}

}  // namespace
}  // namespace ifar::runner
