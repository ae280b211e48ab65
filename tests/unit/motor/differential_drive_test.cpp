#include "drivers/motor/differential_drive.hpp"

#include <gtest/gtest.h>

#include "sim/can_nodes/drive_emulator.hpp"

namespace ifar::motor {
namespace {

using sim::DriveEmulator;
using sim::DriveEmulatorSettings;

class DifferentialDriveTest : public ::testing::Test {
 protected:
  DifferentialDrive vehicle{DifferentialDriveSettings{}};
  DriveEmulator left{DriveEmulatorSettings{1, 100'000, 10'000, true, 20'000.0}};
  DriveEmulator right{DriveEmulatorSettings{2, 100'000, 10'000, true, 20'000.0}};
  std::int64_t now = 0;

  void run(int cycles, double linear, double angular)
  {
    for (int index = 0; index < cycles; ++index) {
      now += 10'000;
      vehicle.command(linear, angular, now);
      for (const can::Frame& frame : vehicle.update(now)) {
        left.onFrame(frame, now);
        right.onFrame(frame, now);
      }
      for (DriveEmulator* drive : {&left, &right}) {
        for (const can::Frame& frame : drive->update(now))
          vehicle.onFrame(frame, now);
      }
    }
  }
};

TEST_F(DifferentialDriveTest, TurnsBodyVelocityIntoWheelVelocities)
{
  run(10, 0.3, 0.5);  // left (0.3 - 0.15) / 0.15 = 1 rad/s, right (0.3 + 0.15) / 0.15 = 3 rad/s
  ASSERT_TRUE(vehicle.running(now));
  EXPECT_EQ(left.commandedVelocity(), 1000);
  EXPECT_EQ(right.commandedVelocity(), 3000);
}

TEST_F(DifferentialDriveTest, AFaultOnOneSideHoldsTheOtherAtZero)
{
  run(10, 0.5, 0.0);
  ASSERT_TRUE(vehicle.running(now));
  left.injectFault(0x2310);
  run(3, 0.5, 0.0);
  EXPECT_FALSE(vehicle.running(now));
  EXPECT_EQ(vehicle.leftStatus(now).reason, StopReason::kDriveFault);
  EXPECT_EQ(right.commandedVelocity(), 0);  // healthy side enabled, but held at zero
  EXPECT_EQ(right.driveState(), DriveState::kOperationEnabled);
  vehicle.requestFaultReset();
  run(10, 0.5, 0.0);
  EXPECT_TRUE(vehicle.running(now));
  EXPECT_EQ(left.commandedVelocity(), 3333);
  EXPECT_EQ(right.commandedVelocity(), 3333);
}

TEST(DifferentialDrive, RejectsDuplicateNodeIds)
{
  DifferentialDriveSettings settings;
  settings.right.node_id = 1;
  EXPECT_THROW(DifferentialDrive{settings}, std::invalid_argument);
}

}  // namespace
}  // namespace ifar::motor
