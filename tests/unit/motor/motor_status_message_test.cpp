#include "drivers/motor/motor_status_message.hpp"

#include <gtest/gtest.h>

namespace ifar::motor {
namespace {

TEST(MotorStatusMessage, CopiesEveryField)
{
  MotorStatus status;
  status.node_id = 2;
  status.nmt_state = NmtState::kOperational;
  status.heartbeat_ok = true;
  status.statusword = 0x0218;
  status.drive_state = DriveState::kFault;
  status.target_velocity = 0;
  status.actual_velocity = -12;
  status.emergency_code = 0x2310;
  status.reason = StopReason::kDriveFault;
  const ifar::motor_status_t message = toMessage(status, 1234);
  EXPECT_EQ(message.utime, 1234);
  EXPECT_EQ(message.node_id, 2);
  EXPECT_EQ(message.nmt_state, 0x05);
  EXPECT_TRUE(message.heartbeat_ok);
  EXPECT_EQ(message.statusword, 0x0218);
  EXPECT_EQ(message.drive_state, ifar::motor_status_t::DRIVE_FAULT);
  EXPECT_EQ(message.actual_velocity, -12);
  EXPECT_EQ(message.emergency_code, 0x2310);
  EXPECT_EQ(message.reason, "drive fault");
}

TEST(MotorStatusMessage, RunningDriveHasNoReason)
{
  MotorStatus status;
  status.statusword = 0x0237;
  status.drive_state = DriveState::kOperationEnabled;
  const ifar::motor_status_t message = toMessage(status, 0);
  EXPECT_EQ(message.drive_state, ifar::motor_status_t::DRIVE_OPERATION_ENABLED);
  EXPECT_EQ(message.reason, "");
  EXPECT_EQ(message.nmt_state, 0);
}

}  // namespace
}  // namespace ifar::motor
