#include "tools/view/view_hub.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifar/goal_t.hpp"
#include "ifar/pose_t.hpp"
#include "lcmtypes/message_schema.hpp"

namespace ifar::view {
namespace {

constexpr std::int64_t kStart = 1'700'000'000'000'000;

template <typename Message>
std::vector<std::uint8_t> encoded(const Message& message)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

class ViewHubTest : public ::testing::Test {
 protected:
  ViewHubTest()
      : hub(lcmtypes::messageSchema(), FeedSettings{}, "{\"view\":\"hello\"}",
            [this](ClientId client, const std::vector<WebFrame>& frames) {
              for (const WebFrame& frame : frames) {
                sent[client].push_back(frame.bytes);
              }
            })
  {
  }

  void goal(double x, std::int64_t receive_utime)
  {
    goal_t message{};
    message.utime = receive_utime;
    message.goal_id = 1;
    message.x = x;
    const std::vector<std::uint8_t> bytes = encoded(message);
    hub.onMessage("GOAL", common::ByteView(bytes.data(), bytes.size()), receive_utime);
  }

  void pose(std::int64_t utime, std::int64_t receive_utime)
  {
    pose_t message{};
    message.utime = utime;
    message.orientation[0] = 1.0;
    const std::vector<std::uint8_t> bytes = encoded(message);
    hub.onMessage("POSE", common::ByteView(bytes.data(), bytes.size()), receive_utime);
  }

  std::map<ClientId, std::vector<std::string>> sent;
  ViewHub hub;
};

TEST_F(ViewHubTest, APageThatJoinsGetsHelloTheNewestOfEachChannelAndTheTrajectoryFirst)
{
  goal(3.0, kStart);
  goal(4.0, kStart + 1);
  EXPECT_TRUE(sent.empty());  // no page yet
  hub.onClientEvent({ClientEvent::Kind::kJoined, 7, "127.0.0.1", "/ws"});
  ASSERT_EQ(sent[7].size(), 3U);
  EXPECT_EQ(sent[7][0], "{\"view\":\"hello\"}");
  EXPECT_NE(sent[7][1].find("\"x\":4,"), std::string::npos) << sent[7][1];
  EXPECT_EQ(sent[7][2], "{\"view\":\"trajectory\",\"first_utime\":0,\"points\":[]}");
  goal(5.0, kStart + 2);
  ASSERT_EQ(sent[7].size(), 4U);
  EXPECT_NE(sent[7][3].find("\"x\":5,"), std::string::npos);
  EXPECT_EQ(hub.pages(), 1U);
}

TEST_F(ViewHubTest, EveryPageGetsTheSameFramesUntilItLeaves)
{
  hub.onClientEvent({ClientEvent::Kind::kJoined, 1, "a", "/ws"});
  hub.onClientEvent({ClientEvent::Kind::kJoined, 2, "b", "/ws"});
  goal(1.0, kStart);
  hub.onClientEvent({ClientEvent::Kind::kLeft, 1, "", "/ws"});
  goal(2.0, kStart + 1);
  EXPECT_EQ(sent[1].size(), 3U);  // hello, trajectory, one goal
  EXPECT_EQ(sent[2].size(), 4U);
  EXPECT_EQ(hub.pages(), 1U);
}

TEST_F(ViewHubTest, ATimeJumpSendsAResetBeforeThePose)
{
  hub.onClientEvent({ClientEvent::Kind::kJoined, 1, "a", "/ws"});
  pose(kStart + 10'000'000, kStart);
  pose(kStart, kStart + 200'000);
  ASSERT_EQ(sent[1].size(), 5U);
  EXPECT_EQ(sent[1][3].rfind("{\"view\":\"reset\",\"reason\":\"the pose time went back 10 s", 0), 0U)
      << sent[1][3];
  EXPECT_EQ(sent[1][4].rfind("{\"channel\":\"POSE\"", 0), 0U);
}

TEST_F(ViewHubTest, TickSendsTheChannelCountsOnceASecond)
{
  hub.onClientEvent({ClientEvent::Kind::kJoined, 1, "a", "/ws"});
  goal(1.0, kStart);
  hub.tick(kStart);
  hub.tick(kStart + 500'000);
  hub.tick(kStart + 1'000'000);
  ASSERT_EQ(sent[1].size(), 5U);
  EXPECT_EQ(sent[1][3].rfind("{\"view\":\"channels\",\"now_utime\":1700000000000000,", 0), 0U);
  EXPECT_EQ(sent[1][4].rfind("{\"view\":\"channels\",\"now_utime\":1700000001000000,", 0), 0U);
}

}  // namespace
}  // namespace ifar::view
