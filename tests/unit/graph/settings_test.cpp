#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

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

/// Each of `values` for `key` stops loading with an error that names the key.
void expectRejected(const std::string& key, std::initializer_list<const char*> values)
{
  for (const char* bad : values) {
    const auto wrong = common::ConfigNode::loadString("graph:\n  " + key + ": " + bad + "\n", "planner.yaml");
    try {
      loadGraphSettings(wrong.child("graph"));
      ADD_FAILURE() << key << " " << bad << " was accepted";
    } catch (const common::ConfigError& error) {
      EXPECT_NE(std::string(error.what()).find(key), std::string::npos) << error.what();
    }
  }
}

TEST(GraphSettings, RoutePreferenceIsAFractionUpToAHalf)
{
  const auto root = common::ConfigNode::loadString("graph:\n  route_preference: 0.25\n", "planner.yaml");
  EXPECT_DOUBLE_EQ(loadGraphSettings(root.child("graph")).route_preference, 0.25);
  expectRejected("route_preference", {"-0.1", "0.6", ".nan"});
}

TEST(GraphSettings, RoutePreferenceCapIsMetresOrZero)
{
  const auto root = common::ConfigNode::loadString("graph:\n  route_preference_cap_m: 2.5\n", "planner.yaml");
  EXPECT_DOUBLE_EQ(loadGraphSettings(root.child("graph")).route_preference_cap_m, 2.5);
  expectRejected("route_preference_cap_m", {"-1", ".inf", ".nan"});
}

TEST(GraphSettings, UnseenCostIsAFactorAndSeenRangeMetres)
{
  const auto defaults = common::ConfigNode::loadString("graph:\n  votes: 10\n", "planner.yaml");
  EXPECT_DOUBLE_EQ(loadGraphSettings(defaults.child("graph")).unseen_cost, 0.0);
  const auto root =
      common::ConfigNode::loadString("graph:\n  unseen_cost: 1.5\n  seen_range_m: 12\n", "planner.yaml");
  const GraphSettings settings = loadGraphSettings(root.child("graph"));
  EXPECT_DOUBLE_EQ(settings.unseen_cost, 1.5);
  EXPECT_DOUBLE_EQ(settings.seen_range_m, 12.0);
  expectRejected("unseen_cost", {"-0.5", "11", ".inf", ".nan"});
  expectRejected("seen_range_m", {"0", "-3", "250", ".nan"});
}

TEST(GraphSettings, ShippedConfigLoads)
{
  const auto root = common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/planner.yaml");
  const GraphSettings settings = loadGraphSettings(root.child("graph"));
  EXPECT_GE(settings.votes, 1);
}

}  // namespace
}  // namespace ifar::graph
