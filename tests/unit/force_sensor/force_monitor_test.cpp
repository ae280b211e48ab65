#include "drivers/force_sensor/force_monitor.hpp"

#include <gtest/gtest.h>

namespace ifar::force_sensor {
namespace {

TEST(ForceMonitor, SilentBeforeTheFirstFrame)
{
  ForceMonitor monitor;
  EXPECT_EQ(monitor.sample(0).status, kHealthSilent);
}

TEST(ForceMonitor, HealthyStreamThenSilentAfterFiftyMilliseconds)
{
  ForceMonitor monitor;
  ForceSensorEmulator sensor;
  std::int64_t now = 1'000'000;
  for (int index = 0; index < 10; ++index, now += 10'000) {
    EXPECT_EQ(monitor.onFrame(sensor.nextFrame(42.0), now), FrameVerdict::kAccepted);
  }
  const std::int64_t last = now - 10'000;
  const auto healthy = monitor.sample(last + 50'000);
  EXPECT_EQ(healthy.status, 0);
  EXPECT_NEAR(healthy.force_newtons, 42.0, 1e-9);
  EXPECT_EQ(healthy.counter, 9);
  EXPECT_EQ(healthy.receive_time_us, last);
  EXPECT_EQ(monitor.sample(last + 50'001).status, kHealthSilent);
}

TEST(ForceMonitor, StuckCounterIsFlaggedAfterThreeFramesAndClears)
{
  ForceMonitor monitor;
  ForceSensorEmulator sensor;
  std::int64_t now = 0;
  monitor.onFrame(sensor.nextFrame(1.0), now += 10'000);
  sensor.setCounterFrozen(true);
  monitor.onFrame(sensor.nextFrame(1.0), now += 10'000);
  monitor.onFrame(sensor.nextFrame(1.0), now += 10'000);
  EXPECT_EQ(monitor.sample(now).status, 0);  // two frames with one counter: not yet
  monitor.onFrame(sensor.nextFrame(1.0), now += 10'000);
  EXPECT_EQ(monitor.sample(now).status, kHealthCounterStuck);
  sensor.setCounterFrozen(false);
  sensor.nextFrame(1.0);
  monitor.onFrame(sensor.nextFrame(1.0), now += 10'000);
  EXPECT_EQ(monitor.sample(now).status, 0);
}

TEST(ForceMonitor, CountsBadFramesAndLostFramesAndIgnoresOtherIds)
{
  ForceMonitor monitor;
  ForceSensorEmulator sensor;
  monitor.onFrame(sensor.nextFrame(1.0), 0);
  can::Frame bad = sensor.nextFrame(1.0);
  bad.dlc = 4;
  EXPECT_EQ(monitor.onFrame(bad, 10'000), FrameVerdict::kBad);
  EXPECT_EQ(monitor.onFrame(can::makeFrame(0x181, {1, 2}), 10'000), FrameVerdict::kIgnored);
  sensor.nextFrame(1.0);
  EXPECT_EQ(monitor.onFrame(sensor.nextFrame(5.0), 30'000), FrameVerdict::kAccepted);
  const auto sample = monitor.sample(30'000);
  EXPECT_EQ(sample.frames_bad, 1);
  EXPECT_EQ(sample.frames_lost, 2);  // counters 1 (bad) and 2 never arrived valid
  EXPECT_EQ(sample.counter, 3);
  EXPECT_NEAR(sample.force_newtons, 5.0, 1e-9);
}

TEST(ForceMonitor, ReportsOverloadAndFault)
{
  ForceMonitor monitor;
  ForceSensorEmulator sensor(100.0);
  sensor.setFault(true);
  monitor.onFrame(sensor.nextFrame(150.0), 0);
  EXPECT_EQ(monitor.sample(0).status, kHealthOverload | kHealthFault);
}

}  // namespace
}  // namespace ifar::force_sensor
