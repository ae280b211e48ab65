#include "drivers/motor/canopen_frames.hpp"

#include <gtest/gtest.h>

namespace ifar::motor {
namespace {

std::vector<std::uint8_t> bytes(const can::Frame& frame)
{
  return std::vector<std::uint8_t>(frame.data.begin(), frame.data.begin() + frame.dlc);
}

TEST(CanopenFrames, NmtStartBytes)
{
  const can::Frame frame = encodeNmt({NmtCommand::kStart, 1});
  EXPECT_EQ(frame.id, 0x000u);
  EXPECT_EQ(bytes(frame), (std::vector<std::uint8_t>{0x01, 0x01}));
  EXPECT_EQ(bytes(encodeNmt({NmtCommand::kResetNode, 0})), (std::vector<std::uint8_t>{0x81, 0x00}));
}

TEST(CanopenFrames, Rpdo1Bytes)
{
  // Enable operation, -1000 (0xFFFFFC18) to node 2: controlword LE then velocity LE.
  const can::Frame frame = encodeRpdo1(2, {0x000F, -1000});
  EXPECT_EQ(frame.id, 0x202u);
  EXPECT_EQ(bytes(frame), (std::vector<std::uint8_t>{0x0F, 0x00, 0x18, 0xFC, 0xFF, 0xFF}));
  const auto decoded = decodeRpdo1(frame, 2);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(decoded->controlword, 0x000F);
  EXPECT_EQ(decoded->target_velocity, -1000);
}

TEST(CanopenFrames, HeartbeatBytes)
{
  const can::Frame frame = encodeHeartbeat(1, NmtState::kOperational);
  EXPECT_EQ(frame.id, 0x701u);
  EXPECT_EQ(bytes(frame), (std::vector<std::uint8_t>{0x05}));
  EXPECT_EQ(decodeHeartbeat(frame, 1), NmtState::kOperational);
  EXPECT_FALSE(decodeHeartbeat(frame, 2));
  EXPECT_FALSE(decodeHeartbeat(can::makeFrame(0x701, {0x33}), 1));        // not a state
  EXPECT_FALSE(decodeHeartbeat(can::makeFrame(0x701, {0x05, 0x00}), 1));  // wrong length
}

TEST(CanopenFrames, Tpdo1AndEmergency)
{
  const auto feedback = decodeTpdo1(can::makeFrame(0x181, {0x37, 0x02, 0xE8, 0x03, 0x00, 0x00}), 1);
  ASSERT_TRUE(feedback);
  EXPECT_EQ(feedback->statusword, 0x0237);
  EXPECT_EQ(feedback->actual_velocity, 1000);
  EXPECT_EQ(driveStateFromStatusword(feedback->statusword), DriveState::kOperationEnabled);
  EXPECT_FALSE(decodeTpdo1(can::makeFrame(0x181, {0x37, 0x02, 0xE8, 0x03, 0x00}), 1));

  const can::Frame emergency = encodeEmergency({0x2310, 0x01, 3});
  EXPECT_EQ(emergency.id, 0x083u);
  EXPECT_EQ(bytes(emergency), (std::vector<std::uint8_t>{0x10, 0x23, 0x01, 0, 0, 0, 0, 0}));
  const auto decoded = decodeEmergency(emergency, 3);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(decoded->error_code, 0x2310);
}

TEST(CanopenFrames, StatuswordStates)
{
  EXPECT_EQ(driveStateFromStatusword(0x0250), DriveState::kSwitchOnDisabled);
  EXPECT_EQ(driveStateFromStatusword(0x0231), DriveState::kReadyToSwitchOn);
  EXPECT_EQ(driveStateFromStatusword(0x0233), DriveState::kSwitchedOn);
  EXPECT_EQ(driveStateFromStatusword(0x0237), DriveState::kOperationEnabled);
  EXPECT_EQ(driveStateFromStatusword(0x0217), DriveState::kQuickStopActive);
  EXPECT_EQ(driveStateFromStatusword(0x0218), DriveState::kFault);
  EXPECT_EQ(driveStateFromStatusword(0x021F), DriveState::kFaultReactionActive);
  for (const DriveState state :
       {DriveState::kSwitchOnDisabled, DriveState::kReadyToSwitchOn, DriveState::kSwitchedOn,
        DriveState::kOperationEnabled, DriveState::kFault}) {
    EXPECT_EQ(driveStateFromStatusword(statuswordFor(state)), state) << toString(state);
  }
}

}  // namespace
}  // namespace ifar::motor
