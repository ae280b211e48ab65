#pragma once
// Publishes a simulated drive (testing/simulated_feed.hpp) on an LCM bus in real time,
// as the velodyne driver and the state estimator would: VELODYNE_PACKET and POSE stamped with the wall
// clock, and the GOAL resent every 200 ms as commands on the bus are.

#include <cstdint>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "ifar/goal_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "testing/simulated_feed.hpp"

namespace ifar::replay_testing {

pose_t toPoseMessage(const test_support::FeedRecord& record, std::int64_t utime);
velodyne_packet_t toPacketMessage(const test_support::FeedRecord& record, std::int64_t utime);

/// Sends every record at its own time shifted to now (handling the bus meanwhile, so subscriptions of
/// `bus` keep being served) and `goal` with the first record and every 200 ms after.
void publishInRealTime(lcm::LCM& bus, const std::vector<test_support::FeedRecord>& records, goal_t goal);

}  // namespace ifar::replay_testing
