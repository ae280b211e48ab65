#include "drivers/motor/drive_emulator.hpp"

#include <gtest/gtest.h>

namespace ifar::motor {
namespace {

TEST(DriveEmulator, BootsThenSendsHeartbeatsAndTpdoWhenOperational)
{
  DriveEmulator drive({3, 100'000, 10'000, true, 20'000.0});
  auto frames = drive.update(0);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].id, 0x703u);
  EXPECT_EQ(frames[0].data[0], 0x00);  // boot-up
  EXPECT_EQ(drive.nmtState(), NmtState::kPreOperational);
  EXPECT_TRUE(drive.update(50'000).empty());
  frames = drive.update(100'000);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].data[0], 0x7F);                          // pre-operational heartbeat
  drive.onFrame(encodeNmt({NmtCommand::kStart, 0}), 100'000);  // broadcast start
  EXPECT_EQ(drive.nmtState(), NmtState::kOperational);
  frames = drive.update(110'000);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].id, 0x183u);
  EXPECT_EQ(decodeTpdo1(frames[0], 3)->statusword, statuswordFor(DriveState::kSwitchOnDisabled));
}

TEST(DriveEmulator, FollowsTheEnableSequenceAndRampsVelocity)
{
  DriveEmulator drive;
  drive.update(0);
  drive.onFrame(encodeNmt({NmtCommand::kStart, 1}), 0);
  drive.onFrame(encodeRpdo1(1, {kControlEnableOperation, 500}), 0);
  EXPECT_EQ(drive.driveState(), DriveState::kSwitchOnDisabled);  // 0x0F first is refused
  drive.onFrame(encodeRpdo1(1, {kControlShutdown, 0}), 0);
  EXPECT_EQ(drive.driveState(), DriveState::kReadyToSwitchOn);
  drive.onFrame(encodeRpdo1(1, {kControlSwitchOn, 0}), 0);
  EXPECT_EQ(drive.driveState(), DriveState::kSwitchedOn);
  drive.onFrame(encodeRpdo1(1, {kControlEnableOperation, 1000}), 0);
  EXPECT_EQ(drive.driveState(), DriveState::kOperationEnabled);
  EXPECT_EQ(drive.commandedVelocity(), 1000);
  drive.update(10'000);  // 20000 units/s * 0.01 s = 200
  EXPECT_EQ(drive.actualVelocity(), 200);
  drive.update(100'000);
  EXPECT_EQ(drive.actualVelocity(), 1000);
}

TEST(DriveEmulator, FaultSendsEmergencyAndResetsOnTheEdge)
{
  DriveEmulator drive;
  drive.update(0);
  drive.onFrame(encodeNmt({NmtCommand::kStart, 1}), 0);
  drive.injectFault(0x2310);
  auto frames = drive.update(10'000);
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames[0].id, 0x081u);
  EXPECT_EQ(decodeEmergency(frames[0], 1)->error_code, 0x2310);
  EXPECT_EQ(drive.driveState(), DriveState::kFault);
  drive.onFrame(encodeRpdo1(1, {kControlFaultReset, 0}), 10'000);
  EXPECT_EQ(drive.driveState(), DriveState::kSwitchOnDisabled);
  frames = drive.update(20'000);
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(decodeEmergency(frames[0], 1)->error_code, 0x0000);
}

TEST(DriveEmulator, IgnoresPdosUnlessOperationalAndCountsWrongLengths)
{
  DriveEmulator drive;
  drive.update(0);
  drive.onFrame(encodeRpdo1(1, {kControlShutdown, 0}), 0);
  EXPECT_EQ(drive.driveState(), DriveState::kSwitchOnDisabled);
  drive.onFrame(can::makeFrame(0x201, {0x06, 0x00}), 0);
  drive.onFrame(can::makeFrame(0x000, {0x01}), 0);
  EXPECT_EQ(drive.badFrames(), 2);
  drive.onFrame(encodeRpdo1(2, {kControlShutdown, 0}), 0);  // another node's
  EXPECT_EQ(drive.badFrames(), 2);
}

}  // namespace
}  // namespace ifar::motor
