#include "tests/replay/feed_publisher.hpp"

#include "common/time.hpp"

namespace ifar::replay_testing {

using test_support::FeedRecord;

pose_t toPoseMessage(const FeedRecord& record, std::int64_t utime)
{
  pose_t pose{};
  pose.utime = utime;
  pose.position[0] = record.pose.position.x();
  pose.position[1] = record.pose.position.y();
  pose.position[2] = record.pose.position.z();
  pose.orientation[0] = record.pose.orientation.w();
  pose.orientation[1] = record.pose.orientation.x();
  pose.orientation[2] = record.pose.orientation.y();
  pose.orientation[3] = record.pose.orientation.z();
  return pose;
}

velodyne_packet_t toPacketMessage(const FeedRecord& record, std::int64_t utime)
{
  velodyne_packet_t packet{};
  packet.utime = utime;
  packet.port = 2368;
  packet.size = static_cast<std::int32_t>(record.payload.size());
  packet.data.assign(record.payload.begin(), record.payload.end());
  return packet;
}

void publishInRealTime(lcm::LCM& bus, const std::vector<FeedRecord>& records, goal_t goal)
{
  if (records.empty()) {
    return;
  }
  const std::int64_t offset = common::nowMicroseconds() - records.front().utime;
  std::int64_t next_goal_utime = 0;
  for (const FeedRecord& record : records) {
    const std::int64_t utime = record.utime + offset;
    while (common::nowMicroseconds() < utime) {
      bus.handleTimeout(1);
    }
    if (utime >= next_goal_utime) {
      goal.utime = utime;
      bus.publish("GOAL", &goal);
      next_goal_utime = utime + 200'000;
    }
    if (record.kind == FeedRecord::Kind::Pose) {
      const pose_t pose = toPoseMessage(record, utime);
      bus.publish("POSE", &pose);
    } else {
      const velodyne_packet_t packet = toPacketMessage(record, utime);
      bus.publish("VELODYNE_PACKET", &packet);
    }
  }
}

}  // namespace ifar::replay_testing
