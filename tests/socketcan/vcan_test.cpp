// SocketCAN against a real kernel: runs inside qemu (tests/socketcan/run-vcan-test) with vcan0 up
// (MTU 72, so FD frames can be sent) and vcan1 created but down. Statically linked.

#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <thread>

#include "drivers/can/error_frame.hpp"
#include "drivers/can/socketcan_bus.hpp"
#include "drivers/force_sensor/force_monitor.hpp"
#include "drivers/motor/drive_configuration.hpp"
#include "drivers/motor/motor_client.hpp"
#include "sim/can_nodes/drive_emulator.hpp"

namespace ifar::can {
namespace {

using std::chrono::microseconds;

std::unique_ptr<SocketCanBus> openOrFail(const std::string& name)
{
  auto opened = SocketCanBus::open(name);
  EXPECT_NE(opened.bus, nullptr) << opened.error;
  return std::move(opened.bus);
}

std::int64_t wallMicroseconds()
{
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::int64_t steadyMicroseconds()
{
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

TEST(Vcan, OpeningAMissingInterfaceNamesIt)
{
  const auto opened = SocketCanBus::open("vcan9");
  EXPECT_EQ(opened.bus, nullptr);
  EXPECT_NE(opened.error.find("no CAN interface named 'vcan9'"), std::string::npos) << opened.error;
}

TEST(Vcan, KernelFiltersByIdAndMask)
{
  auto sender = openOrFail("vcan0");
  auto tpdo_listener = openOrFail("vcan0");
  auto extended_listener = openOrFail("vcan0");
  ASSERT_TRUE(sender && tpdo_listener && extended_listener);
  tpdo_listener->setFilters({Filter{0x180, 0x780, false}});
  extended_listener->setFilters({Filter{0x18FF0000, 0x1FFF0000, true}});
  Frame extended = makeFrame(0x18FF1234, {0xEE});
  extended.flags = kFlagExtended;
  Frame also_181_but_extended = makeFrame(0x181, {0xDD});
  also_181_but_extended.flags = kFlagExtended;
  for (const Frame& frame : {makeFrame(0x181, {1}), makeFrame(0x201, {2}), extended, also_181_but_extended,
                             makeFrame(0x1FF, {3})}) {
    ASSERT_EQ(sender->send(frame).status, IoStatus::kOk);
  }
  auto first = tpdo_listener->receive(microseconds(200'000));
  ASSERT_EQ(first.status, IoStatus::kOk);
  EXPECT_EQ(first.frame.id, 0x181u);
  EXPECT_FALSE(first.frame.extended());
  auto second = tpdo_listener->receive(microseconds(200'000));
  ASSERT_EQ(second.status, IoStatus::kOk);
  EXPECT_EQ(second.frame.id, 0x1FFu);
  EXPECT_EQ(tpdo_listener->receive(microseconds(20'000)).status, IoStatus::kTimeout);

  auto only = extended_listener->receive(microseconds(200'000));
  ASSERT_EQ(only.status, IoStatus::kOk);
  EXPECT_EQ(only.frame.id, 0x18FF1234u);
  EXPECT_TRUE(only.frame.extended());
  EXPECT_EQ(only.frame.data[0], 0xEE);
  EXPECT_EQ(extended_listener->receive(microseconds(20'000)).status, IoStatus::kTimeout);
  EXPECT_EQ(sender->receive(microseconds(0)).status, IoStatus::kTimeout);  // own frames not echoed
}

TEST(Vcan, ReceiveOwnFramesWhenAsked)
{
  auto bus = openOrFail("vcan0");
  ASSERT_TRUE(bus);
  ASSERT_TRUE(bus->setReceiveOwnFrames(true));
  ASSERT_EQ(bus->send(makeFrame(0x321, {9})).status, IoStatus::kOk);
  const auto echoed = bus->receive(microseconds(200'000));
  ASSERT_EQ(echoed.status, IoStatus::kOk);
  EXPECT_EQ(echoed.frame.id, 0x321u);
}

TEST(Vcan, ErrorFramesChangeTheBusState)
{
  auto injector = openOrFail("vcan0");
  auto listener = openOrFail("vcan0");
  ASSERT_TRUE(injector && listener);
  ASSERT_EQ(injector->send(makeErrorFrame(kErrorController, kControllerTxPassive)).status, IoStatus::kOk);
  auto passive = listener->receive(microseconds(200'000));
  ASSERT_EQ(passive.status, IoStatus::kOk);
  EXPECT_TRUE(passive.frame.error());
  EXPECT_EQ(passive.frame.id, kErrorController);
  EXPECT_EQ(passive.frame.data[1], kControllerTxPassive);
  EXPECT_EQ(listener->state(), BusState::kPassive);
  ASSERT_EQ(injector->send(makeErrorFrame(kErrorBusOff)).status, IoStatus::kOk);
  ASSERT_EQ(listener->receive(microseconds(200'000)).status, IoStatus::kOk);
  EXPECT_EQ(listener->state(), BusState::kBusOff);
  ASSERT_EQ(injector->send(makeErrorFrame(kErrorRestarted)).status, IoStatus::kOk);
  ASSERT_EQ(listener->receive(microseconds(200'000)).status, IoStatus::kOk);
  EXPECT_EQ(listener->state(), BusState::kActive);
  EXPECT_EQ(listener->counters().error_frames, 3);
  EXPECT_EQ(listener->counters().frames_received, 0);
}

TEST(Vcan, KernelTimestampsAreWallClock)
{
  auto sender = openOrFail("vcan0");
  auto listener = openOrFail("vcan0");
  ASSERT_TRUE(sender && listener);
  const std::int64_t before = wallMicroseconds();
  ASSERT_EQ(sender->send(makeFrame(0x100, {1})).status, IoStatus::kOk);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  const auto received = listener->receive(microseconds(200'000));
  const std::int64_t after = wallMicroseconds();
  ASSERT_EQ(received.status, IoStatus::kOk);
  EXPECT_GE(received.frame.timestamp_us, before);
  EXPECT_LE(received.frame.timestamp_us, after);
  // Stamped on arrival in the kernel, not when we read it 30 ms later.
  EXPECT_LT(received.frame.timestamp_us, after - 20'000);
}

TEST(Vcan, FdSizedReadsOfClassicFramesAreAccepted)
{
  auto listener = openOrFail("vcan0");
  ASSERT_TRUE(listener);
  const int fd_socket = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
  ASSERT_GE(fd_socket, 0);
  const int enable = 1;
  ASSERT_EQ(::setsockopt(fd_socket, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, &enable, sizeof(enable)), 0);
  ifreq request{};
  std::strcpy(request.ifr_name, "vcan0");
  ASSERT_EQ(::ioctl(fd_socket, SIOCGIFINDEX, &request), 0);
  sockaddr_can address{};
  address.can_family = AF_CAN;
  address.can_ifindex = request.ifr_ifindex;
  ASSERT_EQ(::bind(fd_socket, reinterpret_cast<const sockaddr*>(&address), sizeof(address)), 0);
  canfd_frame classic_in_fd{};
  classic_in_fd.can_id = 0x222;
  classic_in_fd.len = 4;
  classic_in_fd.data[0] = 0xAB;
  ASSERT_EQ(::write(fd_socket, &classic_in_fd, CANFD_MTU), static_cast<ssize_t>(CANFD_MTU));
  canfd_frame long_fd{};
  long_fd.can_id = 0x223;
  long_fd.len = 12;
  ASSERT_EQ(::write(fd_socket, &long_fd, CANFD_MTU), static_cast<ssize_t>(CANFD_MTU));
  ::close(fd_socket);
  const auto received = listener->receive(microseconds(200'000));
  ASSERT_EQ(received.status, IoStatus::kOk);
  EXPECT_EQ(received.frame.id, 0x222u);
  EXPECT_EQ(received.frame.dlc, 4);
  EXPECT_EQ(received.frame.data[0], 0xAB);
  EXPECT_EQ(listener->receive(microseconds(50'000)).status, IoStatus::kTimeout);
  EXPECT_EQ(listener->counters().bad_frames, 1);  // the 12-byte FD frame
}

TEST(Vcan, SendingOnADownInterfaceIsAWriteError)
{
  auto down = openOrFail("vcan1");
  ASSERT_TRUE(down);
  const auto sent = down->send(makeFrame(0x1, {1}));
  EXPECT_EQ(sent.status, IoStatus::kError);
  EXPECT_NE(sent.error.find("vcan1"), std::string::npos) << sent.error;
  EXPECT_EQ(down->counters().write_errors, 1);
}

// The vehicle's CAN traffic over a real kernel: a drive emulator and a force sensor emulator on their
// own sockets, the motor client and the force monitor on another, 10 ms cycles in real time.
TEST(Vcan, ForceSensorAndMotorExchange)
{
  auto vehicle_side = openOrFail("vcan0");
  auto drive_side = openOrFail("vcan0");
  auto sensor_side = openOrFail("vcan0");
  ASSERT_TRUE(vehicle_side && drive_side && sensor_side);
  drive_side->setFilters({Filter{0x000, 0x7FF, false}, Filter{0x201, 0x7FF, false}});

  motor::MotorClient client;
  sim::DriveEmulator drive;
  force_sensor::ForceSensorEmulator sensor;
  force_sensor::ForceMonitor monitor;

  const auto cycle = [&](bool sensor_on, std::int32_t velocity) {
    const std::int64_t now = steadyMicroseconds();
    if (sensor_on) {
      ASSERT_EQ(sensor_side->send(sensor.nextFrame(123.4)).status, IoStatus::kOk);
    }
    for (const Frame& frame : drive.update(now)) {
      ASSERT_EQ(drive_side->send(frame).status, IoStatus::kOk);
    }
    client.command(velocity, now);
    for (const Frame& frame : client.update(now)) {
      ASSERT_EQ(vehicle_side->send(frame).status, IoStatus::kOk);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const std::int64_t after = steadyMicroseconds();
    while (true) {
      const auto received = drive_side->receive(microseconds(0));
      if (received.status != IoStatus::kOk)
        break;
      drive.onFrame(received.frame, after);
    }
    while (true) {
      const auto received = vehicle_side->receive(microseconds(0));
      if (received.status != IoStatus::kOk)
        break;
      if (monitor.onFrame(received.frame, after) == force_sensor::FrameVerdict::kIgnored) {
        client.onFrame(received.frame, after);
      }
    }
  };

  for (int index = 0; index < 40; ++index)
    cycle(true, 1500);
  const auto status = client.status(steadyMicroseconds());
  EXPECT_EQ(status.phase, motor::ClientPhase::kRunning) << motor::toString(status.phase);
  EXPECT_EQ(drive.driveState(), motor::DriveState::kOperationEnabled);
  EXPECT_EQ(drive.commandedVelocity(), 1500);
  EXPECT_GT(status.actual_velocity, 0);
  EXPECT_EQ(status.bad_frames, 0);
  const auto sample = monitor.sample(steadyMicroseconds());
  EXPECT_EQ(sample.status, 0);
  EXPECT_NEAR(sample.force_newtons, 123.4, 1e-3);
  EXPECT_EQ(sample.frames_bad, 0);

  for (int index = 0; index < 8; ++index)
    cycle(false, 1500);  // the sensor goes quiet for > 50 ms
  EXPECT_NE(monitor.sample(steadyMicroseconds()).status & force_sensor::kHealthSilent, 0);

  drive.injectFault(0x2310);
  for (int index = 0; index < 5; ++index)
    cycle(true, 1500);
  const auto faulted = client.status(steadyMicroseconds());
  EXPECT_TRUE(faulted.fault_latched);
  EXPECT_EQ(faulted.emergency_code, 0x2310);
  EXPECT_EQ(drive.commandedVelocity(), 0);
}

// The start-up SDO configuration and the drive's watchdog over a real kernel: the client writes the
// limits and the RPDO deadline (100 ms), enables the drive, then falls silent; the drive stops itself
// and says so with EMCY 0x8250.
TEST(Vcan, SdoConfigurationAndTheDrivesWatchdog)
{
  auto vehicle_side = openOrFail("vcan0");
  auto drive_side = openOrFail("vcan0");
  ASSERT_TRUE(vehicle_side && drive_side);
  drive_side->setFilters(
      {Filter{0x000, 0x7FF, false}, Filter{0x201, 0x7FF, false}, Filter{0x601, 0x7FF, false}});

  motor::MotorClientSettings settings;
  motor::DriveSetup setup;
  setup.max_velocity = 9066;
  setup.acceleration = 10666;
  setup.deceleration = 10666;
  setup.quick_stop_deceleration = 10666;
  setup.rpdo_timeout_ms = 100;
  settings.configuration = motor::driveConfigurationWrites(setup);
  motor::MotorClient client(settings);
  sim::DriveEmulator drive;
  std::vector<std::uint16_t> emergencies;

  const auto cycle = [&](bool client_alive) {
    const std::int64_t now = steadyMicroseconds();
    for (const Frame& frame : drive.update(now)) {
      ASSERT_EQ(drive_side->send(frame).status, IoStatus::kOk);
    }
    if (client_alive) {
      client.command(20'000, now);
      for (const Frame& frame : client.update(now)) {
        ASSERT_EQ(vehicle_side->send(frame).status, IoStatus::kOk);
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const std::int64_t after = steadyMicroseconds();
    for (auto received = drive_side->receive(microseconds(0)); received.status == IoStatus::kOk;
         received = drive_side->receive(microseconds(0))) {
      drive.onFrame(received.frame, after);
    }
    for (auto received = vehicle_side->receive(microseconds(0)); received.status == IoStatus::kOk;
         received = vehicle_side->receive(microseconds(0))) {
      client.onFrame(received.frame, after);
      if (const auto emergency = motor::decodeEmergency(received.frame, 1)) {
        emergencies.push_back(emergency->error_code);
      }
    }
  };

  for (int index = 0; index < 60 && client.status(steadyMicroseconds()).phase != motor::ClientPhase::kRunning;
       ++index) {
    cycle(true);
  }
  const auto status = client.status(steadyMicroseconds());
  ASSERT_EQ(status.phase, motor::ClientPhase::kRunning) << motor::toString(status.reason);
  EXPECT_TRUE(status.configured);
  EXPECT_EQ(drive.objects().rpdo_event_timer_ms, 100);
  EXPECT_EQ(drive.commandedVelocity(), 9066);  // 20000 asked, the limit written by SDO

  const std::int64_t silent_from = steadyMicroseconds();
  std::int64_t stopped_after = -1;
  for (int index = 0; index < 50 && stopped_after < 0; ++index) {
    cycle(false);
    if (drive.commandedVelocity() == 0) {
      stopped_after = steadyMicroseconds() - silent_from;
    }
  }
  EXPECT_EQ(drive.driveState(), motor::DriveState::kQuickStopActive);
  EXPECT_GE(stopped_after, 100'000);  // not before the deadline
  cycle(false);
  ASSERT_FALSE(emergencies.empty());
  EXPECT_EQ(emergencies.back(), motor::kEmergencyRpdoTimeout);
  std::printf("vcan: drive stopped itself %.1f ms after the client fell silent (EMCY 0x%04X)\n",
              static_cast<double>(stopped_after) * 1e-3, emergencies.back());
}

}  // namespace
}  // namespace ifar::can

// The result line the qemu runner looks for.
int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  std::printf("IFAR-SOCKETCAN-RESULT: %s\n", result == 0 ? "PASS" : "FAIL");
  std::fflush(stdout);
  return result;
}
