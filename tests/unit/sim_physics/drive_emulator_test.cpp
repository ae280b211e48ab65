#include "sim/can_nodes/drive_emulator.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace ifar::sim {
namespace {

using namespace motor;  // the frames and states of the link under test

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

// --- SDO server, limits and watchdogs -----------------------------------------------------------

std::string hex(const can::Frame& frame)
{
  char text[40];
  std::snprintf(text, sizeof(text), "%03X#", static_cast<unsigned>(frame.id));
  std::string result = text;
  for (int index = 0; index < frame.dlc; ++index) {
    std::snprintf(text, sizeof(text), "%02X", frame.data[static_cast<std::size_t>(index)]);
    result += text;
  }
  return result;
}

/// A drive of node 1, booted and operational at t = 0, with each write answered and confirmed.
class ConfiguredDrive : public ::testing::Test {
 protected:
  DriveEmulator drive{DriveEmulatorSettings{1, 100'000, 10'000, true, 20'000.0}};
  std::int64_t now = 0;

  void SetUp() override
  {
    drive.update(0);
    drive.onFrame(encodeNmt({NmtCommand::kStart, 1}), 0);
  }
  std::string write(SdoWrite object)
  {
    drive.onFrame(encodeSdoDownload(1, object), now);
    for (const can::Frame& frame : drive.update(now)) {
      if (frame.id == 0x581) {
        return hex(frame);
      }
    }
    return "no answer";
  }
  /// Enable sequence by RPDO1, then `velocity`.
  void enable(std::int32_t velocity)
  {
    for (const std::uint16_t controlword : {kControlShutdown, kControlSwitchOn, kControlEnableOperation}) {
      drive.onFrame(encodeRpdo1(1, {controlword, 0}), now);
    }
    drive.onFrame(encodeRpdo1(1, {kControlEnableOperation, velocity}), now);
    ASSERT_EQ(drive.driveState(), DriveState::kOperationEnabled);
  }
  /// `cycles` of 10 ms: RPDO1 with `velocity` when `rpdo`, the driver's heartbeat (node 127) every 50 ms
  /// when `heartbeat`; returns what the drive sent.
  std::vector<can::Frame> run(int cycles, bool rpdo, bool heartbeat, std::int32_t velocity = 0)
  {
    std::vector<can::Frame> sent;
    for (int index = 0; index < cycles; ++index) {
      now += 10'000;
      if (rpdo) {
        drive.onFrame(encodeRpdo1(1, {kControlEnableOperation, velocity}), now);
      }
      if (heartbeat && now % 50'000 == 0) {
        drive.onFrame(encodeHeartbeat(127, NmtState::kOperational), now);
      }
      for (const can::Frame& frame : drive.update(now)) {
        sent.push_back(frame);
      }
    }
    return sent;
  }
  static std::vector<std::string> emergencies(const std::vector<can::Frame>& frames)
  {
    std::vector<std::string> result;
    for (const can::Frame& frame : frames) {
      if (frame.id == 0x081) {
        result.push_back(hex(frame));
      }
    }
    return result;
  }
};

TEST_F(ConfiguredDrive, SdoServerConfirmsWhatItHoldsAndAbortsTheRest)
{
  EXPECT_EQ(write({0x607F, 0x00, 9066, 4}), "581#607F600000000000");
  EXPECT_EQ(drive.objects().max_profile_velocity, 9066u);
  EXPECT_EQ(write({0x1016, 0x01, 0x007F0096, 4}), "581#6016100100000000");
  EXPECT_EQ(drive.objects().watchedNode(), 127);
  EXPECT_EQ(write({0x2000, 0x00, 1, 4}), "581#8000200000000206");           // 0x06020000 no such object
  EXPECT_EQ(write({0x607F, 0x00, 9066, 2}), "581#807F600010000706");        // 0x06070010 wrong length
  EXPECT_EQ(write({0x6007, 0x00, 7, 2}), "581#8007600030000906");           // 0x06090030 value range
  EXPECT_EQ(write({0x1016, 0x00, 1, 1}), "581#8016100002000106");           // 0x06010002 read only
  EXPECT_EQ(write({0x1016, 0x02, 0x007F0096, 4}), "581#8016100211000906");  // 0x06090011 no sub-index
  EXPECT_EQ(drive.objects().abort_connection_option, kAbortConnectionDisableVoltage);  // unchanged
  // An upload request is not served: abort 0x05040001.
  drive.onFrame(can::makeFrame(0x601, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0}), now);
  std::vector<std::string> answers;
  for (const can::Frame& frame : drive.update(now)) {
    if (frame.id == 0x581) {
      answers.push_back(hex(frame));
    }
  }
  EXPECT_EQ(answers, (std::vector<std::string>{"581#8041600001000405"}));
}

TEST_F(ConfiguredDrive, HonoursItsMaximumVelocityAndAccelerations)
{
  write({0x607F, 0x00, 9066, 4});
  write({0x6083, 0x00, 10666, 4});
  write({0x6084, 0x00, 20000, 4});
  enable(20'000);
  EXPECT_EQ(drive.commandedVelocity(), 9066);
  run(1, true, false, 20'000);
  EXPECT_EQ(drive.velocityDemand(), 107);  // 10666 x 0.01 s
  run(99, true, false, 20'000);
  EXPECT_EQ(drive.velocityDemand(), 9066);
  run(1, true, false, -20'000);
  EXPECT_EQ(drive.velocityDemand(), 9066 - 200);  // slowing down at 0x6084
}

TEST_F(ConfiguredDrive, RpdoDeadlineQuickStopsTheWheelWithEmergency8250)
{
  write({0x6085, 0x00, 10666, 4});
  write({0x6007, 0x00, 3, 2});
  write({0x1029, 0x01, 1, 1});
  write({0x1400, 0x05, 100, 2});
  enable(0);
  run(60, true, false, 5000);
  ASSERT_EQ(drive.commandedVelocity(), 5000);
  const std::int64_t last_rpdo = now;
  EXPECT_TRUE(emergencies(run(10, false, false)).empty());  // 100 ms without RPDO: not yet
  EXPECT_EQ(drive.driveState(), DriveState::kOperationEnabled);
  const auto tripped = run(1, false, false);  // 110 ms
  EXPECT_EQ(now - last_rpdo, 110'000);
  EXPECT_EQ(emergencies(tripped),
            (std::vector<std::string>{"081#5082110000000000"}));  // 0x8250, register 0x11
  EXPECT_EQ(drive.driveState(), DriveState::kQuickStopActive);
  EXPECT_EQ(drive.commandedVelocity(), 0);
  EXPECT_EQ(drive.nmtState(), NmtState::kOperational);  // 0x1029:01 = 1: no NMT change
  const std::int32_t demand = drive.velocityDemand();
  EXPECT_EQ(demand, 5000 - 107);  // braking on the quick stop ramp (0x6085)
  run(60, false, false);
  EXPECT_EQ(drive.velocityDemand(), 0);
  EXPECT_EQ(drive.driveState(), DriveState::kSwitchOnDisabled);  // 0x605A = 2
  // RPDOs again: EMCY "error reset"; enable operation alone does not restart the wheel...
  const auto back = run(1, true, false, 5000);
  EXPECT_EQ(emergencies(back), (std::vector<std::string>{"081#0000000000000000"}));
  EXPECT_EQ(drive.driveState(), DriveState::kSwitchOnDisabled);
  EXPECT_EQ(drive.commandedVelocity(), 0);
  // ...the enable sequence does.
  enable(5000);
  EXPECT_EQ(drive.commandedVelocity(), 5000);
}

TEST_F(ConfiguredDrive, HeartbeatConsumerQuickStopsWithEmergency8130)
{
  write({0x6007, 0x00, 3, 2});
  write({0x1016, 0x01, 0x007F0096, 4});  // node 127, 150 ms
  write({0x1029, 0x01, 1, 1});
  enable(0);
  run(20, true, true, 3000);  // now 200 ms: the last heartbeat at 200 ms
  const std::int64_t last_beat = now;
  std::vector<std::string> tripped;
  while (tripped.empty() && now < 1'000'000) {
    tripped = emergencies(run(1, true, false, 3000));  // RPDOs still flow: only the heartbeat is gone
  }
  EXPECT_EQ(now - last_beat, 160'000);                                     // the first update after 150 ms
  EXPECT_EQ(tripped, (std::vector<std::string>{"081#3081110000000000"}));  // 0x8130, register 0x11
  EXPECT_EQ(drive.driveState(), DriveState::kQuickStopActive);
  EXPECT_EQ(drive.commandedVelocity(), 0);
  // The heartbeat back: error reset.
  now = 450'000 - 10'000;
  EXPECT_EQ(emergencies(run(1, true, true, 3000)), (std::vector<std::string>{"081#0000000000000000"}));
}

TEST_F(ConfiguredDrive, UnconfiguredWatchdogsNeverTrip)
{
  enable(1000);
  EXPECT_TRUE(emergencies(run(200, false, false)).empty());
  EXPECT_EQ(drive.driveState(), DriveState::kOperationEnabled);
}

}  // namespace
}  // namespace ifar::sim
