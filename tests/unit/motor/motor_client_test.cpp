#include "drivers/motor/motor_client.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "drivers/motor/drive_configuration.hpp"

#include "tests/unit/motor/lockstep.hpp"

namespace ifar::motor {
namespace {

struct Sent {
  std::uint32_t id;
  std::vector<std::uint8_t> bytes;
  bool operator==(const Sent& other) const { return id == other.id && bytes == other.bytes; }
};

std::vector<Sent> describe(const std::vector<can::Frame>& frames)
{
  std::vector<Sent> result;
  for (const can::Frame& frame : frames) {
    result.push_back(
        {frame.id, std::vector<std::uint8_t>(frame.data.begin(), frame.data.begin() + frame.dlc)});
  }
  return result;
}

std::ostream& operator<<(std::ostream& out, const Sent& sent)
{
  out << std::hex << sent.id << "#";
  for (const auto byte : sent.bytes)
    out << static_cast<int>(byte) << ".";
  return out;
}

class MotorClientTest : public ::testing::Test {
 protected:
  MotorClient client{MotorClientSettings{}};
  DriveEmulator drive{DriveEmulatorSettings{}};
  Lockstep lockstep{client, drive};

  void enable(std::int32_t velocity = 1000)
  {
    lockstep.run(10, true, velocity);
    ASSERT_EQ(client.status(lockstep.now_us).phase, ClientPhase::kRunning);
    ASSERT_EQ(drive.driveState(), DriveState::kOperationEnabled);
  }
};

TEST_F(MotorClientTest, EnableSequenceBytesOnTheWire)
{
  lockstep.run(6, true, 1000);
  const std::vector<Sent> expected = {
      {0x000, {0x01, 0x01}},                          // NMT start node 1
      {0x201, {0x06, 0x00, 0x00, 0x00, 0x00, 0x00}},  // shutdown -> ready to switch on
      {0x201, {0x07, 0x00, 0x00, 0x00, 0x00, 0x00}},  // switch on -> switched on
      {0x201, {0x0F, 0x00, 0x00, 0x00, 0x00, 0x00}},  // enable operation, still zero velocity
      {0x201, {0x0F, 0x00, 0xE8, 0x03, 0x00, 0x00}},  // running: 1000 = 0x03E8
  };
  EXPECT_EQ(describe(lockstep.client_frames), expected);
  EXPECT_EQ(drive.driveState(), DriveState::kOperationEnabled);
  EXPECT_EQ(drive.commandedVelocity(), 1000);
  const MotorStatus status = client.status(lockstep.now_us);
  EXPECT_EQ(status.phase, ClientPhase::kRunning);
  EXPECT_EQ(status.reason, StopReason::kNone);
  EXPECT_TRUE(status.heartbeat_ok);
  EXPECT_EQ(status.target_velocity, 1000);
}

TEST_F(MotorClientTest, StaleCommandGivesZeroVelocityThenDisables)
{
  enable(1000);
  lockstep.run(30, true, 1000);
  EXPECT_EQ(drive.actualVelocity(), 1000);
  lockstep.client_frames.clear();
  lockstep.run(20, false);  // 200 ms of silence: still fresh
  ASSERT_FALSE(lockstep.client_frames.empty());
  EXPECT_EQ(decodeRpdo1(lockstep.client_frames.back(), 1)->target_velocity, 1000);
  lockstep.client_frames.clear();
  lockstep.step(false);  // 210 ms: stale
  ASSERT_EQ(lockstep.client_frames.size(), 1u);
  const auto stopping = decodeRpdo1(lockstep.client_frames[0], 1);
  EXPECT_EQ(stopping->controlword, kControlEnableOperation);
  EXPECT_EQ(stopping->target_velocity, 0);
  EXPECT_EQ(client.status(lockstep.now_us).phase, ClientPhase::kStopping);
  EXPECT_EQ(client.status(lockstep.now_us).reason, StopReason::kStaleCommand);
  lockstep.run(20, false);  // the drive ramps down at 20000/s: 50 ms
  EXPECT_EQ(drive.actualVelocity(), 0);
  EXPECT_EQ(client.status(lockstep.now_us).phase, ClientPhase::kStopped);
  EXPECT_EQ(drive.driveState(), DriveState::kReadyToSwitchOn);
  EXPECT_EQ(decodeRpdo1(lockstep.client_frames.back(), 1)->controlword, kControlShutdown);
  for (const can::Frame& frame : lockstep.client_frames) {
    EXPECT_EQ(decodeRpdo1(frame, 1)->target_velocity, 0);
  }
  // Commands again: the client re-enables by itself.
  lockstep.run(5, true, -500);
  EXPECT_EQ(client.status(lockstep.now_us).phase, ClientPhase::kRunning);
  EXPECT_EQ(drive.commandedVelocity(), -500);
}

TEST_F(MotorClientTest, DriveFaultStopsAndLatchesUntilReset)
{
  enable(800);
  drive.injectFault(0x2310);
  lockstep.step(true, 800);  // the client sends before the drive's EMCY arrives in this cycle
  lockstep.client_frames.clear();
  lockstep.run(5, true, 800);
  MotorStatus status = client.status(lockstep.now_us);
  EXPECT_TRUE(status.fault_latched);
  EXPECT_EQ(status.emergency_code, 0x2310);
  EXPECT_EQ(status.reason, StopReason::kDriveFault);
  EXPECT_EQ(status.phase, ClientPhase::kStopped);
  for (const can::Frame& frame : lockstep.client_frames) {
    EXPECT_EQ(decodeRpdo1(frame, 1)->target_velocity, 0);
  }
  lockstep.run(50, true, 800);  // fresh commands do not clear a fault
  EXPECT_EQ(drive.driveState(), DriveState::kFault);

  client.requestFaultReset();
  lockstep.client_frames.clear();
  lockstep.run(8, true, 800);
  ASSERT_FALSE(lockstep.client_frames.empty());
  EXPECT_EQ(decodeRpdo1(lockstep.client_frames[0], 1)->controlword, kControlFaultReset);
  status = client.status(lockstep.now_us);
  EXPECT_EQ(status.phase, ClientPhase::kRunning);
  EXPECT_FALSE(status.fault_latched);
  EXPECT_EQ(status.emergency_code, 0);  // the drive's EMCY "error reset"
  EXPECT_EQ(drive.commandedVelocity(), 800);
}

TEST_F(MotorClientTest, EmergencyAloneTriggersSafeStop)
{
  enable(600);
  client.onFrame(encodeEmergency({0x4210, 0x08, 1}), lockstep.now_us);  // over-temperature
  lockstep.client_frames.clear();
  lockstep.step(true, 600);
  ASSERT_EQ(lockstep.client_frames.size(), 1u);
  EXPECT_EQ(decodeRpdo1(lockstep.client_frames[0], 1)->target_velocity, 0);
  EXPECT_EQ(client.status(lockstep.now_us).reason, StopReason::kDriveFault);
}

TEST_F(MotorClientTest, LostHeartbeatStopsAndRecovers)
{
  enable(1000);
  lockstep.run(10, true, 1000);
  drive.setHeartbeatEnabled(false);
  lockstep.run(35, true, 1000);  // > 300 ms since the last heartbeat
  MotorStatus status = client.status(lockstep.now_us);
  EXPECT_FALSE(status.heartbeat_ok);
  EXPECT_EQ(status.reason, StopReason::kHeartbeatLost);
  EXPECT_NE(status.phase, ClientPhase::kRunning);
  EXPECT_EQ(decodeRpdo1(lockstep.client_frames.back(), 1)->target_velocity, 0);
  lockstep.run(20, true, 1000);
  EXPECT_EQ(client.status(lockstep.now_us).phase, ClientPhase::kStopped);
  EXPECT_EQ(drive.actualVelocity(), 0);
  drive.setHeartbeatEnabled(true);
  lockstep.run(20, true, 1000);
  EXPECT_EQ(client.status(lockstep.now_us).phase, ClientPhase::kRunning);
}

TEST_F(MotorClientTest, SilentDriveIsDisabledAfterTheStopTimeout)
{
  enable(1000);
  lockstep.run(10, true, 1000);
  drive.setTransmitting(false);
  lockstep.deliver_to_drive = false;
  lockstep.run(31, true, 1000);
  EXPECT_EQ(client.status(lockstep.now_us).phase, ClientPhase::kStopping);  // no feedback: keep braking
  lockstep.run(100, true, 1000);
  EXPECT_EQ(client.status(lockstep.now_us).phase, ClientPhase::kStopped);
  EXPECT_EQ(decodeRpdo1(lockstep.client_frames.back(), 1)->controlword, kControlShutdown);
}

TEST_F(MotorClientTest, OperatorDisableStops)
{
  enable(1000);
  client.setEnabled(false);
  lockstep.run(10, true, 1000);
  EXPECT_EQ(client.status(lockstep.now_us).reason, StopReason::kNotEnabled);
  EXPECT_EQ(drive.commandedVelocity(), 0);
}

TEST_F(MotorClientTest, WrongLengthFramesAndUnknownIdsAreCountedNotFatal)
{
  enable(1000);
  client.onFrame(can::makeFrame(0x181, {0x37, 0x02, 0x00}), lockstep.now_us);   // TPDO1 too short
  client.onFrame(can::makeFrame(0x701, {0x05, 0x05}), lockstep.now_us);         // heartbeat too long
  client.onFrame(can::makeFrame(0x081, {0x10, 0x23}), lockstep.now_us);         // EMCY too short
  client.onFrame(can::makeFrame(0x123, {0x01}), lockstep.now_us);               // unknown id
  client.onFrame(encodeHeartbeat(5, NmtState::kOperational), lockstep.now_us);  // another node
  const MotorStatus status = client.status(lockstep.now_us);
  EXPECT_EQ(status.bad_frames, 3);
  EXPECT_GE(status.ignored_frames, 2);
  EXPECT_FALSE(status.fault_latched);
  lockstep.run(3, true, 1000);
  EXPECT_EQ(client.status(lockstep.now_us).phase, ClientPhase::kRunning);
}

TEST_F(MotorClientTest, ANewClientStopsADriveLeftRunning)
{
  enable(1200);
  lockstep.run(10, true, 1200);
  MotorClient restarted{MotorClientSettings{}};  // the executive restarted: no commands yet
  Lockstep after_restart(restarted, drive);
  after_restart.now_us = lockstep.now_us;
  after_restart.run(40, false);
  EXPECT_EQ(drive.commandedVelocity(), 0);
  EXPECT_EQ(drive.actualVelocity(), 0);
  EXPECT_EQ(drive.driveState(), DriveState::kReadyToSwitchOn);
  EXPECT_EQ(restarted.status(after_restart.now_us).reason, StopReason::kStaleCommand);
}

TEST_F(MotorClientTest, NeverSendsMoreThanItsMaximumVelocity)
{
  MotorClientSettings settings;
  settings.max_velocity = 9066;
  MotorClient limited(settings);
  DriveEmulator limited_drive{DriveEmulatorSettings{}};
  Lockstep link(limited, limited_drive);
  link.run(10, true, 2'000'000'000);
  link.run(3, true, -2'000'000'000);
  ASSERT_EQ(limited.status(link.now_us).phase, ClientPhase::kRunning);
  for (const can::Frame& frame : link.client_frames) {
    if (const auto rpdo = decodeRpdo1(frame, 1)) {
      EXPECT_LE(std::abs(rpdo->target_velocity), 9066);
    }
  }
  EXPECT_EQ(decodeRpdo1(link.client_frames.back(), 1)->target_velocity, -9066);
}

// A client with a start-up configuration (the drive's limits and watchdogs, drive_configuration.hpp).
MotorClientSettings configuringSettings()
{
  MotorClientSettings settings;
  DriveSetup setup;
  setup.max_velocity = 9066;
  setup.acceleration = 10666;
  setup.deceleration = 10666;
  setup.quick_stop_deceleration = 10666;
  setup.master_node_id = 127;
  setup.master_heartbeat_timeout_ms = 0;  // no driver heartbeat in this test: not watched
  setup.rpdo_timeout_ms = 100;
  settings.configuration = driveConfigurationWrites(setup);
  return settings;
}

TEST(MotorClientConfiguration, EnablesOnlyAfterEveryWriteIsConfirmed)
{
  MotorClient client(configuringSettings());
  DriveEmulator drive{DriveEmulatorSettings{}};
  Lockstep link(client, drive);
  link.run(5, true, 1000);
  EXPECT_EQ(client.status(link.now_us).phase, ClientPhase::kConfiguring);
  EXPECT_EQ(client.status(link.now_us).reason, StopReason::kConfiguring);
  link.run(10, true, 1000);
  // Ten SDO downloads, one per cycle as each answer arrives, then NMT start and the enable sequence.
  std::vector<std::uint32_t> ids;
  for (const can::Frame& frame : link.client_frames) {
    ids.push_back(frame.id);
  }
  ASSERT_GE(ids.size(), 12u);
  EXPECT_EQ(std::vector<std::uint32_t>(ids.begin(), ids.begin() + 10),
            (std::vector<std::uint32_t>(10, 0x601)))
      << "not ten SDO requests before anything else";
  EXPECT_EQ(ids[10], 0x000u);  // NMT start, only now
  link.run(10, true, 20'000);
  const MotorStatus status = client.status(link.now_us);
  EXPECT_TRUE(status.configured);
  EXPECT_EQ(status.phase, ClientPhase::kRunning);
  EXPECT_EQ(drive.objects().max_profile_velocity, 9066u);
  EXPECT_EQ(drive.objects().rpdo_event_timer_ms, 100);
  EXPECT_EQ(drive.commandedVelocity(), 9066);  // the client's own clamp, and the drive's
}

TEST(MotorClientConfiguration, ARefusedWriteKeepsTheDriveDisabledWithTheReason)
{
  MotorClientSettings settings;
  settings.configuration = {{0x6060, 0, 9, 1}};  // cyclic synchronous velocity: not what this drive does
  MotorClient client(settings);
  DriveEmulator drive{DriveEmulatorSettings{}};
  Lockstep link(client, drive);
  link.run(30, true, 1000);
  const MotorStatus status = client.status(link.now_us);
  EXPECT_EQ(status.reason, StopReason::kConfigurationFailed);
  EXPECT_FALSE(status.configured);
  EXPECT_EQ(status.configuration_error,
            "drive 1 object 0x6060:00 = 9 (0x09) refused: SDO abort 0x06090030 (invalid value for parameter "
            "(value range exceeded))");
  EXPECT_EQ(drive.driveState(), DriveState::kSwitchOnDisabled);
  EXPECT_EQ(drive.nmtState(), NmtState::kPreOperational);  // not even started
}

TEST_F(MotorClientTest, ACommunicationErrorEmergencyDoesNotLatch)
{
  enable(600);
  client.onFrame(encodeEmergency({kEmergencyRpdoTimeout, 0x11, 1}), lockstep.now_us);
  const MotorStatus status = client.status(lockstep.now_us);
  EXPECT_FALSE(status.fault_latched);
  EXPECT_EQ(status.emergency_code, 0x8250);
  EXPECT_EQ(status.reason, StopReason::kNone);
  lockstep.run(3, true, 600);
  EXPECT_EQ(client.status(lockstep.now_us).phase, ClientPhase::kRunning);
}

TEST(WheelVelocities, DifferentialDriveKinematics)
{
  const auto straight = wheelVelocities(1.0, 0.0, 0.6, 0.15);
  EXPECT_EQ(straight.left, 6667);
  EXPECT_EQ(straight.right, 6667);
  const auto turn = wheelVelocities(0.0, 1.0, 0.6, 0.15);
  EXPECT_EQ(turn.left, -2000);
  EXPECT_EQ(turn.right, 2000);
  EXPECT_EQ(wheelVelocities(1.0, 0.0, 0.6, 0.0).left, 0);
}

}  // namespace
}  // namespace ifar::motor
