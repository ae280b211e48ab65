#include "planner/interaction/settings_loader.hpp"

#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace ifar::interaction {
namespace {

InteractionSettings load(const std::string& yaml)
{
  return loadInteractionSettings(common::ConfigNode::loadString(yaml, "planner.yaml"),
                                 common::VehicleSettings{});
}

std::string errorOf(const std::string& yaml)
{
  try {
    load(yaml);
  } catch (const common::ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(InteractionSettingsLoaderTest, ReadsKeysAndTakesThePusherFromTheVehicle)
{
  common::VehicleSettings vehicle;
  vehicle.bumper_friction = 0.3;
  const InteractionSettings settings = loadInteractionSettings(
      common::ConfigNode::loadString("primitive_length_m: 0.3\nmax_expansions: 100\nreference_force_n: 50\n",
                                     "planner.yaml"),
      vehicle);
  EXPECT_DOUBLE_EQ(settings.search.primitive_length_m, 0.3);
  EXPECT_EQ(settings.search.max_expansions, 100U);
  EXPECT_DOUBLE_EQ(settings.search.reference_force_n, 50.0);
  EXPECT_DOUBLE_EQ(settings.search.time_budget_s, SearchSettings{}.time_budget_s);
  EXPECT_DOUBLE_EQ(settings.pusher.bumper_friction, 0.3);
  EXPECT_DOUBLE_EQ(settings.pusher.inflation_m, vehicle.width_m / 2.0);
  EXPECT_DOUBLE_EQ(settings.pusher.bumper_to_axle_m, vehicle.length_m / 2.0);
  EXPECT_NEAR(settings.pusher.max_push_force_n, 0.7 * 80.0 * 9.81, 1e-9);
}

TEST(InteractionSettingsLoaderTest, ReadsThePlannerLoopKeysThePassageMarginAndTheUnseenDepth)
{
  const InteractionSettings settings = loadInteractionSettings(
      common::ConfigNode::loadString(
          "default_mass_kg: 35\ndefault_ground_friction: 0.6\nframe_budget_ms: 20\n"
          "track_association_m: 0.8\ntrack_drop_frames: 7\npassage_margin_m: 0\nreach_m: 45\n"
          "outline_memory_restart_m: 1.5\nunseen_depth_m: 0\n",
          "planner.yaml"),
      common::VehicleSettings{});
  EXPECT_DOUBLE_EQ(settings.loop.default_physics.mass_kg, 35.0);
  EXPECT_DOUBLE_EQ(settings.loop.default_physics.ground_friction, 0.6);
  EXPECT_DOUBLE_EQ(settings.loop.frame_budget_ms, 20.0);
  EXPECT_DOUBLE_EQ(settings.loop.track_association_m, 0.8);
  EXPECT_EQ(settings.loop.track_drop_frames, 7);
  EXPECT_DOUBLE_EQ(settings.loop.reach_m, 45.0);
  EXPECT_DOUBLE_EQ(settings.loop.outline_memory_restart_m, 1.5);
  EXPECT_DOUBLE_EQ(load("").loop.outline_memory_restart_m, 0.0);  // off unless asked for
  EXPECT_DOUBLE_EQ(settings.search.passage_margin_m, 0.0);
  EXPECT_THAT(errorOf("passage_margin_m: -0.1\n"), ::testing::HasSubstr("passage_margin_m"));
  EXPECT_DOUBLE_EQ(settings.search.unseen_depth_m, 0.0);
  EXPECT_DOUBLE_EQ(load("").search.unseen_depth_m, 0.5);
  EXPECT_THAT(errorOf("unseen_depth_m: -1\n"),
              ::testing::HasSubstr("key 'unseen_depth_m': must be at least 0 m, got -1"));
  EXPECT_THAT(errorOf("frame_budget_ms: 0\n"), ::testing::HasSubstr("frame_budget_ms"));
  EXPECT_THAT(errorOf("track_drop_frames: 0\n"), ::testing::HasSubstr("track_drop_frames"));
  EXPECT_THAT(errorOf("reach_m: 0\n"), ::testing::HasSubstr("reach_m"));
  EXPECT_THAT(errorOf("outline_memory_restart_m: -1\n"),
              ::testing::HasSubstr("key 'outline_memory_restart_m': must be at least 0 m, got -1"));
}

TEST(InteractionSettingsLoaderTest, TheExtendedSearchRadiusIsOffOrBeyondTheSearchRadius)
{
  EXPECT_DOUBLE_EQ(load("").search.extended_search_radius_m, 0.0);
  EXPECT_DOUBLE_EQ(load("extended_search_radius_m: 8\n").search.extended_search_radius_m, 8.0);
  EXPECT_DOUBLE_EQ(load("extended_search_radius_m: 0\n").search.extended_search_radius_m, 0.0);
  EXPECT_THAT(errorOf("extended_search_radius_m: -1\n"), ::testing::HasSubstr("extended_search_radius_m"));
  EXPECT_THAT(
      errorOf("extended_search_radius_m: 3\n"),
      ::testing::HasSubstr("key 'extended_search_radius_m': must be 0 (off) or larger than search_radius_m"));
  EXPECT_THAT(errorOf("search_radius_m: 9\nextended_search_radius_m: 8\n"),
              ::testing::HasSubstr("extended_search_radius_m"));
}

TEST(InteractionSettingsLoaderTest, TheCorridorPushLengthIsOffOrBeyondTheSearchRadius)
{
  EXPECT_DOUBLE_EQ(load("").search.corridor_push_length_m, 0.0);
  EXPECT_DOUBLE_EQ(load("corridor_push_length_m: 60\n").search.corridor_push_length_m, 60.0);
  EXPECT_THAT(
      errorOf("corridor_push_length_m: 2\n"),
      ::testing::HasSubstr("key 'corridor_push_length_m': must be 0 (off) or larger than search_radius_m"));
  EXPECT_THAT(errorOf("corridor_push_length_m: .nan\n"), ::testing::HasSubstr("corridor_push_length_m"));
}

TEST(InteractionSettingsLoaderTest, RejectsBadValuesAndUnknownKeysByName)
{
  EXPECT_THAT(errorOf("time_budget_s: -1\n"), ::testing::HasSubstr("time_budget_s"));
  EXPECT_THAT(errorOf("heading_bins: 0\n"), ::testing::HasSubstr("heading_bins"));
  EXPECT_THAT(errorOf("primitive_lenght_m: 0.3\n"), ::testing::HasSubstr("primitive_lenght_m"));
}

}  // namespace
}  // namespace ifar::interaction
