#include "tools/replay_test/message_comparison.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "ifar/goal_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "lcmtypes/message_schema.hpp"

namespace ifar::replay_test {
namespace {

template <typename Message>
std::vector<std::uint8_t> encoded(const Message& message)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

path_t pathThrough(double second_x)
{
  path_t path{};
  path.valid = true;
  path.num_waypoints = 2;
  path.waypoints.resize(2);
  path.waypoints[0].x = 1.0;
  path.waypoints[1].x = second_x;
  path.waypoints[1].object_id = -1;
  return path;
}

class MessageComparisonTest : public ::testing::Test {
 protected:
  template <typename Recorded, typename Replayed>
  std::string compare(const Recorded& recorded, const Replayed& replayed)
  {
    const std::vector<std::uint8_t> first = encoded(recorded);
    const std::vector<std::uint8_t> second = encoded(replayed);
    return firstDifference(types, common::ByteView(first.data(), first.size()),
                           common::ByteView(second.data(), second.size()), settings);
  }

  echo::MessageTypes types{lcmtypes::messageSchema()};
  ComparisonSettings settings;
};

TEST_F(MessageComparisonTest, TheSameMessageAgrees)
{
  EXPECT_EQ(compare(pathThrough(2.0), pathThrough(2.0)), "");
}

TEST_F(MessageComparisonTest, ADifferenceIsNamedByItsPathWithBothValues)
{
  EXPECT_EQ(compare(pathThrough(2.0), pathThrough(2.5)), "waypoints[1].x: recorded 2, replayed 2.5");
}

TEST_F(MessageComparisonTest, RealsWithinTheToleranceAgree)
{
  settings.tolerance = 0.01;
  EXPECT_EQ(compare(pathThrough(2.0), pathThrough(2.009)), "");
  EXPECT_EQ(compare(pathThrough(2.0), pathThrough(2.02)), "waypoints[1].x: recorded 2, replayed 2.02");
}

TEST_F(MessageComparisonTest, ArraysOfAnotherLengthDiffer)
{
  path_t longer = pathThrough(2.0);
  longer.num_waypoints = 3;
  longer.waypoints.resize(3);
  EXPECT_EQ(compare(pathThrough(2.0), longer), "num_waypoints: recorded 2, replayed 3");
}

TEST_F(MessageComparisonTest, IgnoredMembersAndNanAreNotDifferences)
{
  planner_status_t recorded{};
  recorded.total_ms = 3.5F;
  recorded.search_ms = std::nanf("");
  planner_status_t replayed = recorded;
  replayed.total_ms = 9.25F;
  EXPECT_EQ(compare(recorded, replayed), "total_ms: recorded 3.5, replayed 9.25");
  settings.ignored = {"planner_status_t.total_ms"};
  EXPECT_EQ(compare(recorded, replayed), "");
  replayed.message = "no path";
  EXPECT_EQ(compare(recorded, replayed), "message: recorded \"\", replayed \"no path\"");
}

TEST_F(MessageComparisonTest, MessagesOfAnotherTypeDiffer)
{
  EXPECT_EQ(compare(pathThrough(2.0), goal_t{}), "type: recorded path_t, replayed goal_t");
}

}  // namespace
}  // namespace ifar::replay_test
