#pragma once
// Test input for the planner: a simulated world's VLP-16 packets and pose estimates, recorded as a
// time-ordered log in memory and fed into a FrameAssembler.

#include <cstdint>
#include <vector>

#include "planner/core/frame_assembler.hpp"
#include "sim/world/world.hpp"

namespace ifar::test_support {

struct FeedRecord {
  enum class Kind { Packet, Pose };
  Kind kind = Kind::Packet;
  std::int64_t utime = 0;
  std::vector<std::uint8_t> payload;  // packets
  planner::PoseSample pose;           // poses
};

/// Runs the simulator for `seconds` with the velocity command (linear m/s, angular rad/s) and records every
/// packet and one pose per 10 ms step.
std::vector<FeedRecord> recordSimulation(const sim::World& world, double seconds, double linear = 0.0,
                                         double angular = 0.0);

/// Feeds the records in order (the clock is each record's own time) and returns the completed frames.
std::vector<planner::FrameInput> feedAll(const std::vector<FeedRecord>& records,
                                         planner::FrameAssembler& assembler);

/// A planar pose as a PoseSample.
planner::PoseSample planarPose(std::int64_t utime, double x, double y, double heading);

}  // namespace ifar::test_support
