#include "testing/simulated_feed.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "common/vehicle.hpp"
#include "sim/simulator/simulator.hpp"

namespace ifar::test_support {

planner::PoseSample planarPose(std::int64_t utime, double x, double y, double heading)
{
  planner::PoseSample pose;
  pose.utime = utime;
  pose.position = Eigen::Vector3d(x, y, 0.0);
  pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()));
  return pose;
}

std::vector<FeedRecord> recordSimulation(const sim::World& world, double seconds, double linear,
                                         double angular)
{
  sim::SimulatorSettings settings;
  sim::Simulator simulator(world, common::VehicleSettings{}, settings);
  simulator.setVelocityCommand(linear, angular);
  std::vector<FeedRecord> records;
  constexpr double kStep = 0.01;
  const int steps = static_cast<int>(std::lround(seconds / kStep));
  for (int step = 0; step < steps; ++step) {
    const sim::StepOutput output = simulator.step(kStep);
    FeedRecord pose;
    pose.kind = FeedRecord::Kind::Pose;
    pose.utime = output.utime;  // when it arrives; the estimate is as of pose_estimate_utime (latency)
    pose.pose = planarPose(output.pose_estimate_utime, output.pose_estimate.pose.x,
                           output.pose_estimate.pose.y, output.pose_estimate.pose.heading);
    records.push_back(pose);
    for (const auto& packet : output.packets) {
      FeedRecord record;
      record.kind = FeedRecord::Kind::Packet;
      record.utime = output.utime;
      record.payload.assign(packet.begin(), packet.end());
      records.push_back(std::move(record));
    }
  }
  return records;
}

std::vector<planner::FrameInput> feedAll(const std::vector<FeedRecord>& records,
                                         planner::FrameAssembler& assembler)
{
  std::vector<planner::FrameInput> frames;
  for (const FeedRecord& record : records) {
    if (record.kind == FeedRecord::Kind::Pose) {
      assembler.addPose(record.pose, record.utime);
    } else {
      assembler.addPacket(common::ByteView(record.payload.data(), record.payload.size()), record.utime,
                          record.utime);
    }
    for (planner::FrameInput& frame : assembler.takeFrames()) {
      frames.push_back(std::move(frame));
    }
  }
  return frames;
}

}  // namespace ifar::test_support
