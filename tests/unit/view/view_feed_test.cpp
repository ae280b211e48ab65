#include "tools/view/view_feed.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifar/can_frame_t.hpp"
#include "ifar/heartbeat_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velodyne_packet_t.hpp"
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

pose_t poseAt(double x, double y, std::int64_t utime)
{
  pose_t pose{};
  pose.utime = utime;
  pose.position[0] = x;
  pose.position[1] = y;
  pose.orientation[0] = 1.0;
  return pose;
}

heartbeat_t beat(const std::string& process, std::int8_t health)
{
  heartbeat_t heartbeat{};
  heartbeat.utime = kStart;
  heartbeat.process = process;
  heartbeat.pid = 42;
  heartbeat.health = health;
  return heartbeat;
}

class ViewFeedTest : public ::testing::Test {
 protected:
  template <typename Message>
  FeedUpdate give(const std::string& channel, const Message& message, std::int64_t receive_utime)
  {
    const std::vector<std::uint8_t> bytes = encoded(message);
    return feed.onMessage(channel, common::ByteView(bytes.data(), bytes.size()), receive_utime);
  }

  FeedSettings settings() const
  {
    FeedSettings chosen;
    chosen.max_rate_hz = 10.0;  // one message per 100 ms
    chosen.trajectory_spacing_m = 0.5;
    chosen.max_trajectory_points = 8;
    return chosen;
  }

  ViewFeed feed{lcmtypes::messageSchema(), settings()};
};

TEST_F(ViewFeedTest, ForwardsAMessageAsTheJsonLineEchoPrints)
{
  const FeedUpdate update = give("HEARTBEAT", beat("planner", heartbeat_t::HEALTH_DEGRADED), kStart + 7);
  ASSERT_TRUE(update.publication.has_value());
  EXPECT_FALSE(update.reset.has_value());
  EXPECT_EQ(update.publication->type_name, "heartbeat_t");
  EXPECT_EQ(update.publication->message_json,
            "{\"utime\":1700000000000000,\"process\":\"planner\",\"pid\":42,\"sequence\":0,\"health\":1,"
            "\"message\":\"\"}");
  EXPECT_EQ(
      update.publication->page_line,
      "{\"channel\":\"HEARTBEAT\",\"type\":\"heartbeat_t\",\"receive_utime\":1700000000000007,\"message\":" +
          update.publication->message_json + "}");
}

TEST_F(ViewFeedTest, RawSensorStreamsAndForeignBytesAreCountedNotForwarded)
{
  velodyne_packet_t packet{};
  packet.size = 3;
  packet.data = {1, 2, 3};
  EXPECT_FALSE(give("VELODYNE_PACKET", packet, kStart).publication.has_value());
  can_frame_t frame{};
  EXPECT_FALSE(give("CAN_VEHICLE", frame, kStart).publication.has_value());
  const std::vector<std::uint8_t> foreign(20, 0xAB);
  EXPECT_FALSE(feed.onMessage("OTHER", common::ByteView(foreign.data(), foreign.size()), kStart).publication);
  const std::vector<ChannelStatistics> statistics = feed.statistics(kStart);
  ASSERT_EQ(statistics.size(), 3U);
  EXPECT_EQ(statistics[0].channel, "CAN_VEHICLE");
  EXPECT_EQ(statistics[0].type_name, "can_frame_t");
  EXPECT_EQ(statistics[0].messages, 1);
  EXPECT_EQ(statistics[0].forwarded, 0);
  EXPECT_EQ(statistics[1].channel, "OTHER");
  EXPECT_EQ(statistics[1].undecodable, 1);
  EXPECT_EQ(statistics[1].type_name, "");
  EXPECT_EQ(statistics[2].channel, "VELODYNE_PACKET");
  EXPECT_EQ(statistics[2].bytes, static_cast<std::int64_t>(encoded(packet).size()));
  EXPECT_TRUE(feed.latest().empty());
}

TEST_F(ViewFeedTest, AFastChannelIsThinnedAndItsLastMessageStillGoes)
{
  // Poses every 20 ms: at 10 Hz the first goes, the next four wait their turn and only the newest of them
  // goes.
  int forwarded = 0;
  for (int index = 0; index < 5; ++index) {
    forwarded +=
        give("POSE", poseAt(index, 0.0, kStart + index * 20'000), kStart + index * 20'000).publication ? 1
                                                                                                       : 0;
  }
  EXPECT_EQ(forwarded, 1);
  EXPECT_TRUE(feed.due(kStart + 90'000).empty());  // 100 ms have not passed since the first
  const std::vector<Publication> due = feed.due(kStart + 100'000);
  ASSERT_EQ(due.size(), 1U);
  EXPECT_NE(due[0].message_json.find("\"position\":[4,0,0]"), std::string::npos) << due[0].message_json;
  EXPECT_TRUE(feed.due(kStart + 300'000).empty());  // nothing held any more
  EXPECT_EQ(feed.statistics(kStart + 100'000)[0].forwarded, 2);
  EXPECT_EQ(feed.statistics(kStart + 100'000)[0].messages, 5);
}

TEST_F(ViewFeedTest, HeartbeatsAreNeverThinnedAndALatePageGetsEachProcesssLast)
{
  EXPECT_TRUE(give("HEARTBEAT", beat("planner", heartbeat_t::HEALTH_OK), kStart).publication);
  EXPECT_TRUE(give("HEARTBEAT", beat("executive", heartbeat_t::HEALTH_OK), kStart + 1).publication);
  EXPECT_TRUE(give("HEARTBEAT", beat("planner", heartbeat_t::HEALTH_ERROR), kStart + 2).publication);
  give("POSE", poseAt(1.0, 2.0, kStart), kStart);
  const std::vector<Publication> latest = feed.latest();
  ASSERT_EQ(latest.size(), 3U);  // channel order, then process order on HEARTBEAT
  EXPECT_NE(latest[0].message_json.find("\"process\":\"executive\""), std::string::npos);
  EXPECT_NE(latest[1].message_json.find("\"process\":\"planner\""), std::string::npos);
  EXPECT_NE(latest[1].message_json.find("\"health\":2"), std::string::npos);
  EXPECT_EQ(latest[2].channel, "POSE");
}

TEST_F(ViewFeedTest, TheLatestIncludesAMessageHeldBackByTheRateLimit)
{
  give("POSE", poseAt(1.0, 0.0, kStart), kStart);
  give("POSE", poseAt(2.0, 0.0, kStart + 10'000), kStart + 10'000);  // held
  const std::vector<Publication> latest = feed.latest();
  ASSERT_EQ(latest.size(), 1U);
  EXPECT_NE(latest[0].message_json.find("\"position\":[2,0,0]"), std::string::npos);
}

TEST_F(ViewFeedTest, TheTrajectoryKeepsPosesApartAndHalvesWhenFull)
{
  give("POSE", poseAt(0.0, 0.0, kStart), kStart);
  give("POSE", poseAt(0.3, 0.0, kStart + 1), kStart + 1);  // within 0.5 m of the last kept
  give("POSE", poseAt(0.6, 0.0, kStart + 2), kStart + 2);
  ASSERT_EQ(feed.trajectory().size(), 2U);
  EXPECT_DOUBLE_EQ(feed.trajectory()[1].x, 0.6);
  EXPECT_EQ(feed.trajectoryLine(),
            "{\"view\":\"trajectory\",\"first_utime\":1700000000000000,\"points\":[[0,0],[0.6,0]]}");
  for (int index = 2; index < 8; ++index) {
    give("POSE", poseAt(0.6 * index, 0.0, kStart + index + 1), kStart + index + 1);
  }
  // The eighth point fills it: points 0, 2, 4, 6 stay and the newest is kept as well.
  ASSERT_EQ(feed.trajectory().size(), 5U);
  EXPECT_DOUBLE_EQ(feed.trajectory()[1].x, 1.2);
  EXPECT_DOUBLE_EQ(feed.trajectory()[3].x, 3.6);
  EXPECT_DOUBLE_EQ(feed.trajectory()[4].x, 4.2);
}

TEST_F(ViewFeedTest, APoseStampedWellBeforeTheLastStartsTheTrajectoryAgain)
{
  give("POSE", poseAt(0.0, 0.0, kStart + 60'000'000), kStart);
  give("POSE", poseAt(5.0, 0.0, kStart + 60'500'000), kStart + 500'000);
  EXPECT_FALSE(
      give("POSE", poseAt(5.0, 1.0, kStart + 59'900'000), kStart + 600'000).reset);  // 0.6 s back: jitter
  const FeedUpdate restarted = give("POSE", poseAt(1.0, 1.0, kStart), kStart + 700'000);
  ASSERT_TRUE(restarted.reset.has_value());
  EXPECT_EQ(*restarted.reset, "the pose time went back 59.9 s (a replay or simulator started again)");
  ASSERT_EQ(feed.trajectory().size(), 1U);
  EXPECT_DOUBLE_EQ(feed.trajectory()[0].x, 1.0);
}

TEST_F(ViewFeedTest, RatesAreCountedOverTheLastThreeSeconds)
{
  for (int index = 0; index < 30; ++index) {
    give("HEARTBEAT", beat("sim", heartbeat_t::HEALTH_OK), kStart + index * 100'000);
  }
  EXPECT_DOUBLE_EQ(feed.statistics(kStart + 2'950'000)[0].rate_hz, 10.0);
  EXPECT_DOUBLE_EQ(feed.statistics(kStart + 4'450'000)[0].rate_hz, 5.0);  // the last 15 beats
  const std::size_t beat_bytes = encoded(beat("sim", heartbeat_t::HEALTH_OK)).size();
  EXPECT_EQ(feed.statisticsLine(kStart + 2'950'000),
            "{\"view\":\"channels\",\"now_utime\":1700000002950000,\"channels\":[{\"channel\":\"HEARTBEAT\","
            "\"type\":\"heartbeat_t\",\"messages\":30,\"forwarded\":30,\"undecodable\":0,\"bytes\":" +
                std::to_string(30 * beat_bytes) + ",\"rate_hz\":10}]}");
}

}  // namespace
}  // namespace ifar::view
