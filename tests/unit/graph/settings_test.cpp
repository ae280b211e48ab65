#include <gtest/gtest.h>

#include "common/config.hpp"
#include "planner/graph/settings.hpp"

namespace ifar::graph {
namespace {

TEST(GraphSettings, ReadsSection)
{
  const auto root = common::ConfigNode::loadString(
      "graph:\n  association_distance_m: 0.4\n  votes: 7\n  view_radius_m: 20.0\n", "planner.yaml");
  const GraphSettings settings = loadGraphSettings(root.child("graph"));
  EXPECT_DOUBLE_EQ(settings.association_distance_m, 0.4);
  EXPECT_EQ(settings.votes, 7);
  EXPECT_DOUBLE_EQ(settings.view_radius_m, 20.0);
  EXPECT_DOUBLE_EQ(settings.bucket_size_m, 0.0);
}

TEST(GraphSettings, BadValuesNamed)
{
  const auto zero_votes = common::ConfigNode::loadString("graph:\n  votes: 0\n", "planner.yaml");
  try {
    loadGraphSettings(zero_votes.child("graph"));
    FAIL() << "expected ConfigError";
  } catch (const common::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("votes"), std::string::npos) << error.what();
  }
  const auto unknown = common::ConfigNode::loadString("graph:\n  vots: 3\n", "planner.yaml");
  EXPECT_THROW(loadGraphSettings(unknown.child("graph")), common::ConfigError);
}

TEST(GraphSettings, RoutePreferenceIsAFractionUpToAHalf)
{
  const auto root = common::ConfigNode::loadString("graph:\n  route_preference: 0.25\n", "planner.yaml");
  EXPECT_DOUBLE_EQ(loadGraphSettings(root.child("graph")).route_preference, 0.25);
  for (const char* bad : {"-0.1", "0.6", ".nan"}) {
    const auto wrong = common::ConfigNode::loadString(
        std::string("graph:\n  route_preference: ") + bad + "\n", "planner.yaml");
    try {
      loadGraphSettings(wrong.child("graph"));
      ADD_FAILURE() << "route_preference " << bad << " was accepted";
    } catch (const common::ConfigError& error) {
      EXPECT_NE(std::string(error.what()).find("route_preference"), std::string::npos) << error.what();
    }
  }
}

TEST(GraphSettings, RoutePreferenceCapIsMetresOrZero)
{
  const auto root = common::ConfigNode::loadString("graph:\n  route_preference_cap_m: 2.5\n", "planner.yaml");
  EXPECT_DOUBLE_EQ(loadGraphSettings(root.child("graph")).route_preference_cap_m, 2.5);
  for (const char* bad : {"-1", ".inf", ".nan"}) {
    const auto wrong = common::ConfigNode::loadString(
        std::string("graph:\n  route_preference_cap_m: ") + bad + "\n", "planner.yaml");
    try {
      loadGraphSettings(wrong.child("graph"));
      ADD_FAILURE() << "route_preference_cap_m " << bad << " was accepted";
    } catch (const common::ConfigError& error) {
      EXPECT_NE(std::string(error.what()).find("route_preference_cap_m"), std::string::npos) << error.what();
    }
  }
}

TEST(GraphSettings, ShippedConfigLoads)
{
  const auto root = common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/planner.yaml");
  const GraphSettings settings = loadGraphSettings(root.child("graph"));
  EXPECT_GE(settings.votes, 1);
}

}  // namespace
}  // namespace ifar::graph
