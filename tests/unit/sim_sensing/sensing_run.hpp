#pragma once
// A short closed-loop run of the simulator node as the daemon wires it: two motor clients enable the
// emulated drives over CAN and drive the vehicle into a box, while everything the node sends (VLP-16
// packets, CAN frames, POSE) is kept as bytes, so two runs can be compared byte for byte.

#include <cstdint>
#include <vector>

#include "drivers/can/frame.hpp"
#include "ifar/pose_t.hpp"
#include "sim/node/simulator_node.hpp"
#include "sim/world/world.hpp"

namespace ifar::sim::testing {

struct RunBytes {
  std::vector<std::uint8_t> packets;  // every VLP-16 packet, concatenated
  std::vector<std::uint8_t> frames;   // id, length and data of every CAN frame sent
  std::vector<std::uint8_t> poses;    // every pose_t, LCM-encoded
  std::vector<ifar::pose_t> pose_messages;
  std::vector<StepOutput> outputs;        // per step, packets left out (ground truth, estimates, forces)
  std::vector<std::int32_t> left_actual;  // TPDO1 actual velocity of the left drive, 0.001 rad/s
};

/// Runs `steps` steps of 5 ms commanding `linear` m/s (and `angular` rad/s after half the steps).
RunBytes runNode(const World& world, const SimNodeSettings& settings, int steps, double linear,
                 double angular);

/// FNV-1a over the bytes (a fingerprint of a run).
std::uint64_t fingerprint(const std::vector<std::uint8_t>& bytes);

}  // namespace ifar::sim::testing
