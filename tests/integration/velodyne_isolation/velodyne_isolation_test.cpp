// Two simulator + Velodyne driver pairs as real processes on one host, each pair on its own LCM URL and
// lidar UDP port (given by --set, as config/launch/sim_demo.yaml gives IFAR_LIDAR_PORT): each driver
// publishes its own simulator's packets and none of the other's. The simulators spin at different rates,
// which every packet shows: from one firing block to the next the azimuth advances 0.2 degrees at 5 Hz and
// 0.4 degrees at 10 Hz.

#include <poll.h>
#include <signal.h>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "ifar/velodyne_packet_t.hpp"
#include "testing/child_process.hpp"
#include "testing/temporary_directory.hpp"

namespace {

using ifar::test_support::readText;

using Clock = std::chrono::steady_clock;
using ifar::test_support::ChildOptions;
using ifar::test_support::ChildProcess;

/// The VELODYNE_PACKET messages of one LCM URL, counted by the simulator rate they show.
struct PacketRecord {
  int count = 0;
  int wrong_port = 0;  // arrived on another UDP port than the pair's
  int slow = 0;        // azimuth steps of 0.2 degrees between blocks: the 5 Hz simulator
  int fast = 0;        // 0.4 degrees: the 10 Hz simulator
  int port = 0;

  void onPacket(const lcm::ReceiveBuffer*, const std::string&, const ifar::velodyne_packet_t* packet)
  {
    ++count;
    wrong_port += packet->port != port ? 1 : 0;
    if (packet->size != 1206) {
      return;
    }
    // Twelve 100-byte blocks: 0xFFEE, then the azimuth in hundredths of a degree (little-endian).
    const auto byte = [packet](int at) { return static_cast<int>(packet->data[at]); };
    const auto azimuth = [&byte](int block) { return byte(block * 100 + 2) | byte(block * 100 + 3) << 8; };
    const int step = (azimuth(1) - azimuth(0) + 36000) % 36000;
    slow += step < 30 ? 1 : 0;
    fast += step >= 30 && step < 50 ? 1 : 0;
  }
};

/// A simulator and a Velodyne driver on their own LCM URL and lidar port, stopped when destroyed.
struct SensorPair {
  std::unique_ptr<lcm::LCM> bus;
  PacketRecord record;
  std::unique_ptr<ChildProcess> sim;
  std::unique_ptr<ChildProcess> driver;
  std::string sim_output;
  std::string driver_output;

  /// Subscribes to `url` and starts both processes; false when LCM cannot start on `url`.
  bool start(const std::string& folder, const std::string& name, const std::string& url, int lidar_port,
             const std::string& world, double rotation_hz)
  {
    bus = std::make_unique<lcm::LCM>(url);
    if (!bus->good()) {
      return false;
    }
    record.port = lidar_port;
    bus->subscribe("VELODYNE_PACKET", &PacketRecord::onPacket, &record);
    const std::string bin = std::string(IFAR_BINARY_DIR) + "/bin/";
    const std::string port = std::to_string(lidar_port);
    sim_output = folder + "/" + name + "-sim.out";
    driver_output = folder + "/" + name + "-driver.out";
    driver = std::make_unique<ChildProcess>(
        std::vector<std::string>{bin + "ifar-velodyne-driver", "--lcm-url", url, "--set", "data_port=" + port,
                                 "--log-dir", ""},
        ChildOptions{driver_output, IFAR_SOURCE_DIR, {}});
    sim = std::make_unique<ChildProcess>(
        std::vector<std::string>{bin + "ifar-sim", "--builtin", world, "--lcm-url", url, "--set",
                                 "lidar.port=" + port, "--set",
                                 "lidar.rotation_hz=" + std::to_string(rotation_hz), "--log-dir", ""},
        ChildOptions{sim_output, IFAR_SOURCE_DIR, {}});
    return true;
  }

  std::string outputs() const
  {
    return "simulator:\n" + readText(sim_output) + "driver:\n" + readText(driver_output);
  }
};

TEST(VelodyneIsolation, TwoSimulatorDriverPairsOnOneHostEachPublishOnlyTheirOwnPackets)
{
  ifar::test_support::TemporaryDirectory directory("ifar-velodyne-isolation");
  const std::string folder = directory.path().string();
  SensorPair slow;
  SensorPair fast;
  if (!slow.start(folder, "slow", "udpm://239.255.76.67:7795?ttl=0", 23795, "room", 5.0) ||
      !fast.start(folder, "fast", "udpm://239.255.76.67:7796?ttl=0", 23796, "tunnel", 10.0)) {
    GTEST_SKIP() << "LCM cannot start on this host";
  }
  ASSERT_TRUE(slow.sim->started() && slow.driver->started() && fast.sim->started() && fast.driver->started());

  // About two seconds of packets from each (754 a second), at most 15 s for both to get there.
  constexpr int kWanted = 1500;
  const Clock::time_point give_up = Clock::now() + std::chrono::seconds(15);
  while ((slow.record.count < kWanted || fast.record.count < kWanted) && Clock::now() < give_up) {
    pollfd descriptors[2] = {{slow.bus->getFileno(), POLLIN, 0}, {fast.bus->getFileno(), POLLIN, 0}};
    if (poll(descriptors, 2, 100) <= 0) {
      continue;
    }
    if ((descriptors[0].revents & POLLIN) != 0) {
      slow.bus->handle();
    }
    if ((descriptors[1].revents & POLLIN) != 0) {
      fast.bus->handle();
    }
  }
  for (SensorPair* pair : {&slow, &fast}) {
    EXPECT_EQ(pair->driver->stop(SIGTERM), 0) << pair->outputs();
    EXPECT_EQ(pair->sim->stop(SIGTERM), 0) << pair->outputs();
  }
  std::cout << "5 Hz pair: " << slow.record.count << " packets (" << slow.record.slow << " at 5 Hz, "
            << slow.record.fast << " at 10 Hz); 10 Hz pair: " << fast.record.count << " packets ("
            << fast.record.slow << " at 5 Hz, " << fast.record.fast << " at 10 Hz)" << std::endl;

  EXPECT_GE(slow.record.count, kWanted) << slow.outputs();
  EXPECT_GE(fast.record.count, kWanted) << fast.outputs();
  EXPECT_EQ(slow.record.wrong_port, 0);
  EXPECT_EQ(fast.record.wrong_port, 0);
  EXPECT_EQ(slow.record.slow, slow.record.count) << "the 5 Hz pair's driver published other packets";
  EXPECT_EQ(slow.record.fast, 0) << "the 5 Hz pair's driver published the 10 Hz simulator's packets";
  EXPECT_EQ(fast.record.fast, fast.record.count) << "the 10 Hz pair's driver published other packets";
  EXPECT_EQ(fast.record.slow, 0) << "the 10 Hz pair's driver published the 5 Hz simulator's packets";
}

}  // namespace
