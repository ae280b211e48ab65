#include "drivers/motor/drive_configurator.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "drivers/motor/drive_configuration.hpp"

namespace ifar::motor {
namespace {

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

// The project's vehicle (config/vehicle.yaml) and can.yaml: wheel limit 9066, acceleration 10666,
// the driver is node 127, drive watchdog 150 ms heartbeat and 100 ms RPDO.
DriveSetup vehicleSetup()
{
  DriveSetup setup;
  setup.max_velocity = 9066;
  setup.acceleration = 10666;
  setup.deceleration = 10666;
  setup.quick_stop_deceleration = 10666;
  setup.master_node_id = 127;
  setup.master_heartbeat_timeout_ms = 150;
  setup.rpdo_timeout_ms = 100;
  return setup;
}

DriveConfiguratorSettings settingsFor(std::uint8_t node_id)
{
  return DriveConfiguratorSettings{node_id, driveConfigurationWrites(vehicleSetup()), 50'000, 3, 1'000'000};
}

TEST(DriveConfigurator, WritesEachObjectAfterTheLastIsConfirmed)
{
  DriveConfigurator configurator(settingsFor(1));
  std::vector<std::string> sent;
  std::int64_t now = 0;
  while (!configurator.done() && now < 1'000'000) {
    for (const can::Frame& frame : configurator.update(now)) {
      sent.push_back(hex(frame));
      EXPECT_TRUE(configurator.update(now).empty()) << "a second transfer while one is in flight";
      const auto request = decodeSdoRequest(frame, 1);
      configurator.onAnswer(
          *decodeSdoAnswer(encodeSdoDownloadConfirmed(1, request->write.index, request->write.subindex), 1),
          now);
    }
    now += 10'000;
  }
  const std::vector<std::string> expected = {
      "601#2F60600003000000",  // 0x6060 modes of operation = 3, profile velocity
      "601#237F60006A230000",  // 0x607F max profile velocity = 9066 (0x236A)
      "601#23836000AA290000",  // 0x6083 profile acceleration = 10666 (0x29AA)
      "601#23846000AA290000",  // 0x6084 profile deceleration
      "601#23856000AA290000",  // 0x6085 quick stop deceleration
      "601#2B5A600002000000",  // 0x605A quick stop option = 2: ramp, then switch on disabled
      "601#2B07600003000000",  // 0x6007 abort connection option = 3: quick stop
      "601#2F29100101000000",  // 0x1029:01 communication error: no NMT state change
      "601#2316100196007F00",  // 0x1016:01 consumer heartbeat: node 127, 150 ms
      "601#2B00140564000000",  // 0x1400:05 RPDO1 event timer (deadline) 100 ms
  };
  EXPECT_EQ(sent, expected);
  EXPECT_TRUE(configurator.done());
  EXPECT_TRUE(configurator.error().empty());
}

TEST(DriveConfigurator, RepeatsATimedOutWriteAfterAnAbortThenGivesUpAndStartsOver)
{
  DriveConfigurator configurator(settingsFor(2));
  EXPECT_EQ(hex(configurator.update(0).at(0)), "602#2F60600003000000");
  EXPECT_TRUE(configurator.update(50'000).empty());  // 50 ms: still in time
  const auto repeat = configurator.update(60'000);
  ASSERT_EQ(repeat.size(), 2u);
  EXPECT_EQ(hex(repeat[0]), "602#8060600000000405");  // abort 0x05040000: SDO protocol timed out
  EXPECT_EQ(hex(repeat[1]), "602#2F60600003000000");
  ASSERT_EQ(configurator.update(120'000).size(), 2u);  // third attempt
  const auto last = configurator.update(180'000);
  ASSERT_EQ(last.size(), 1u);  // the abort; no fourth attempt
  EXPECT_TRUE(configurator.failed());
  EXPECT_FALSE(configurator.done());
  EXPECT_EQ(configurator.error(), "drive 2 object 0x6060:00 = 3 (0x03): no answer in 3 attempts of 50 ms");
  EXPECT_EQ(configurator.timeouts(), 3);
  EXPECT_TRUE(configurator.update(1'179'000).empty());  // waits a second
  EXPECT_EQ(hex(configurator.update(1'180'000).at(0)), "602#2F60600003000000");
}

TEST(DriveConfigurator, AnAbortFromTheDriveFailsNamingTheObjectAndCode)
{
  DriveConfigurator configurator(settingsFor(1));
  configurator.update(0);
  configurator.onAnswer(*decodeSdoAnswer(encodeSdoDownloadConfirmed(1, 0x6060, 0), 1), 0);
  configurator.update(10'000);  // 0x607F in flight
  // An answer for another object changes nothing.
  configurator.onAnswer(*decodeSdoAnswer(encodeSdoDownloadConfirmed(1, 0x6083, 0), 1), 10'000);
  EXPECT_FALSE(configurator.failed());
  configurator.onAnswer(*decodeSdoAnswer(encodeSdoAbort(0x581, 0x607F, 0, kAbortValueRange), 1), 10'000);
  EXPECT_TRUE(configurator.failed());
  EXPECT_EQ(configurator.error(),
            "drive 1 object 0x607F:00 = 9066 (0x0000236A) refused: SDO abort 0x06090030 (invalid value for "
            "parameter (value range exceeded))");
  // Starting over after the pause, from the first object.
  EXPECT_EQ(hex(configurator.update(1'010'000).at(0)), "601#2F60600003000000");
}

TEST(DriveConfigurator, RestartConfiguresAgainFromTheFirstObject)
{
  DriveConfigurator configurator(DriveConfiguratorSettings{1, {{0x6060, 0, 3, 1}}, 50'000, 3, 1'000'000});
  configurator.update(0);
  configurator.onAnswer(*decodeSdoAnswer(encodeSdoDownloadConfirmed(1, 0x6060, 0), 1), 0);
  EXPECT_TRUE(configurator.done());
  EXPECT_TRUE(configurator.update(10'000).empty());
  configurator.restart();  // the drive booted again
  EXPECT_FALSE(configurator.done());
  EXPECT_EQ(configurator.update(20'000).size(), 1u);
  EXPECT_TRUE(DriveConfigurator(DriveConfiguratorSettings{}).done());  // nothing to write
}

}  // namespace
}  // namespace ifar::motor
