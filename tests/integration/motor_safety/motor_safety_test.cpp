// ifar-sim and ifar-motor-driver as real processes over LCM (the CAN bus on the LCM bridge, CAN_VEHICLE),
// with this test in the executive's place publishing VELOCITY_CMD at 50 Hz:
//  - no command, however large, puts more than the wheel limit into RPDO1 (issue 52, item 1);
//  - a motor driver frozen by SIGSTOP, or killed by SIGKILL, is stopped by the drives' own watchdog:
//    EMCY 0x8250 and quick stop within 200 ms, then the vehicle at rest (issue 52, item 2).
// Each test has its own LCM port and log folder; they run one at a time (real time, timing measured).
// The measured numbers are printed.

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "common/time.hpp"
#include "ifar/can_frame_t.hpp"
#include "ifar/velocity_cmd_t.hpp"
#include "ifar/world_state_t.hpp"
#include "testing/child_process.hpp"
#include "testing/temporary_directory.hpp"

namespace {

using ifar::test_support::readText;

using Clock = std::chrono::steady_clock;
using ifar::test_support::ChildOptions;
using ifar::test_support::ChildProcess;

constexpr std::int32_t kWheelLimit = 9066;  // (1.0 + 1.2 x 0.6 / 2) / 0.15 x 1000, config/vehicle.yaml
constexpr std::int64_t kStopBudgetUs = 200'000;

// An empty 30 m x 30 m hall, the vehicle in the middle: room to drive circles at 0.8 m/s.
constexpr const char* kWorld = R"(name: open_hall
units: m
start: {x: 15, y: 15, heading_deg: 0}
obstacles:
  - name: south
    polygon: [0, 0,  30, 0,  30, 0.3,  0, 0.3]
  - name: north
    polygon: [0, 29.7,  30, 29.7,  30, 30,  0, 30]
  - name: west
    polygon: [0, 0.3,  0.3, 0.3,  0.3, 29.7,  0, 29.7]
  - name: east
    polygon: [29.7, 0.3,  30, 0.3,  30, 29.7,  29.7, 29.7]
)";

/// What the test sees on the bus: RPDO1, TPDO1 and EMCY of the drives (as can_frame_t, stamped by the
/// sender's bridge with its wall clock), and the vehicle's ground-truth speed.
struct BusRecord {
  struct Rpdo {
    std::int64_t utime;
    int node;
    std::uint16_t controlword;
    std::int32_t target;
  };
  struct Tpdo {
    std::int64_t utime;
    int node;
    std::uint16_t statusword;
  };
  struct Emergency {
    std::int64_t utime;
    int node;
    std::uint16_t code;
  };
  std::vector<Rpdo> rpdos;
  std::vector<Tpdo> tpdos;
  std::vector<Emergency> emergencies;
  std::vector<std::pair<std::int64_t, double>> speeds;  // receive utime, m/s over the last 50 ms
  std::optional<ifar::world_state_t> previous_truth;

  void onFrame(const lcm::ReceiveBuffer*, const std::string&, const ifar::can_frame_t* frame)
  {
    const auto u16 = [frame](int at) {
      return static_cast<std::uint16_t>(static_cast<std::uint8_t>(frame->data[at]) |
                                        static_cast<std::uint8_t>(frame->data[at + 1]) << 8);
    };
    const int node = frame->id & 0x7F;
    if ((frame->id == 0x201 || frame->id == 0x202) && frame->dlc == 6) {
      const auto target = static_cast<std::int32_t>(static_cast<std::uint32_t>(u16(2)) |
                                                    static_cast<std::uint32_t>(u16(4)) << 16);
      rpdos.push_back({frame->utime, node, u16(0), target});
    } else if ((frame->id == 0x181 || frame->id == 0x182) && frame->dlc == 6) {
      tpdos.push_back({frame->utime, node, u16(0)});
    } else if ((frame->id == 0x081 || frame->id == 0x082) && frame->dlc == 8) {
      emergencies.push_back({frame->utime, node, u16(0)});
    }
  }
  void onTruth(const lcm::ReceiveBuffer* buffer, const std::string&, const ifar::world_state_t* truth)
  {
    if (previous_truth && truth->utime > previous_truth->utime) {
      const double seconds = static_cast<double>(truth->utime - previous_truth->utime) * 1e-6;
      speeds.emplace_back(buffer->recv_utime, std::hypot(truth->vehicle_x - previous_truth->vehicle_x,
                                                         truth->vehicle_y - previous_truth->vehicle_y) /
                                                  seconds);
    }
    previous_truth = *truth;
  }
  double speed() const { return speeds.empty() ? 0.0 : speeds.back().second; }
};

class MotorSafetyTest : public ::testing::Test {
 protected:
  void SetUp() override
  {
    directory_ = std::make_unique<ifar::test_support::TemporaryDirectory>(
        std::string("ifar-motor-safety-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    folder_ = directory_->path().string();
    ASSERT_FALSE(folder_.empty());
    std::ofstream(folder_ + "/hall.yaml") << kWorld;
  }
  void TearDown() override
  {
    if (directory_ && HasFailure()) {
      directory_->keep();
      std::cout << "logs of the failed run kept in " << folder_ << "\n";
    }
    directory_.reset();
  }

  /// Starts the simulator and the motor driver on `url`, subscribes the record; false when LCM cannot.
  bool start(const std::string& url)
  {
    lcm_ = std::make_unique<lcm::LCM>(url);
    if (!lcm_->good()) {
      return false;
    }
    lcm_->subscribe("CAN_VEHICLE", &BusRecord::onFrame, &record_);
    lcm_->subscribe("SIM_GROUND_TRUTH", &BusRecord::onTruth, &record_);
    const std::string bin = std::string(IFAR_BINARY_DIR) + "/bin/";
    // The project's sim.yaml without the lidar: no VLP-16 packets from this test.
    sim_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{bin + "ifar-sim", folder_ + "/hall.yaml", "--set", "lidar.enabled=false",
                                 "--lcm-url", url, "--log-dir", folder_},
        ChildOptions{folder_ + "/sim.out", IFAR_SOURCE_DIR, {}});
    motor_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{bin + "ifar-motor-driver", "--config", "config/can.yaml", "--lcm-url", url,
                                 "--log-dir", folder_},
        ChildOptions{folder_ + "/motor.out", IFAR_SOURCE_DIR, {}});
    return sim_->started() && motor_->started();
  }

  /// Publishes (linear, angular) on VELOCITY_CMD every 20 ms for at most `seconds`, handling what
  /// arrives, until `done` says so; `done` is asked after every message. True when `done` was met.
  bool drive(double linear, double angular, double seconds, const std::function<bool()>& done = {})
  {
    return handle(std::make_pair(linear, angular), seconds, done);
  }
  /// The same without publishing: the executive has fallen silent.
  bool listen(double seconds, const std::function<bool()>& done)
  {
    return handle(std::nullopt, seconds, done);
  }
  bool handle(const std::optional<std::pair<double, double>>& velocity, double seconds,
              const std::function<bool()>& done)
  {
    const Clock::time_point until =
        Clock::now() + std::chrono::microseconds(static_cast<std::int64_t>(seconds * 1e6));
    Clock::time_point next_command = Clock::now();
    while (Clock::now() < until) {
      if (velocity && Clock::now() >= next_command) {
        ifar::velocity_cmd_t command{};
        command.utime = ifar::common::nowMicroseconds();
        command.linear_velocity = velocity->first;
        command.angular_velocity = velocity->second;
        lcm_->publish("VELOCITY_CMD", &command);
        last_command_utime_ = command.utime;
        next_command += std::chrono::milliseconds(20);
      }
      if (lcm_->handleTimeout(5) > 0 && done && done()) {
        return true;
      }
    }
    return false;
  }

  /// Both drives running: the last RPDO1 to each enables operation with a non-zero target.
  bool drivesRunning() const
  {
    bool left = false;
    bool right = false;
    for (auto it = record_.rpdos.rbegin(); it != record_.rpdos.rend() && !(left && right); ++it) {
      const bool running = it->controlword == 0x0F && it->target != 0;
      left = left || (it->node == 1 && running);
      right = right || (it->node == 2 && running);
    }
    return left && right;
  }

  /// Starts both processes and drives (linear, angular) until the vehicle holds `speed` for 0.5 s.
  void startAndReach(const std::string& url, double linear, double angular, double speed)
  {
    ASSERT_TRUE(start(url)) << "cannot start on " << url;
    int steady = 0;
    const bool reached = drive(linear, angular, 20.0, [&] {
      steady = record_.speed() >= speed ? steady + 1 : 0;
      return steady >= 10 && drivesRunning();
    });
    ASSERT_TRUE(reached) << "the vehicle never reached " << speed << " m/s:\n"
                         << readText(folder_ + "/motor.out") << readText(folder_ + "/sim.out");
  }

  void expectDrivesStopThemselves(int signal_number, const char* what);

  std::unique_ptr<ifar::test_support::TemporaryDirectory> directory_;
  std::string folder_;
  std::unique_ptr<lcm::LCM> lcm_;
  std::int64_t last_command_utime_ = 0;
  BusRecord record_;
  std::unique_ptr<ChildProcess> sim_;
  std::unique_ptr<ChildProcess> motor_;
};

TEST_F(MotorSafetyTest, NoCommandPutsMoreThanTheWheelLimitIntoRpdo1)
{
  startAndReach("udpm://239.255.76.67:7791?ttl=0", 0.3, 0.0, 0.25);
  std::map<std::string, std::int32_t> largest;
  // Each for long enough to reach its limit at 1 m/s^2 (from 1 m/s forward to 1 m/s back: 2 s).
  const auto run = [&](const std::string& name, double linear, double angular, double seconds) {
    const std::size_t from = record_.rpdos.size();
    drive(linear, angular, seconds);
    std::int32_t most = 0;
    for (std::size_t index = from; index < record_.rpdos.size(); ++index) {
      most = std::max(most, std::abs(record_.rpdos[index].target));
    }
    largest[name] = most;
  };
  run("v=1e9", 1e9, 0.0, 1.5);
  run("v=5", 5.0, 0.0, 1.0);
  run("v=-1e9", -1e9, 0.0, 2.5);
  run("v=NaN", std::nan(""), 0.0, 1.0);  // refused: the last good command until it goes stale, then a stop
  run("v=1, w=1e9", 1.0, 1e9, 1.5);
  std::int32_t overall = 0;
  for (const auto& rpdo : record_.rpdos) {
    overall = std::max(overall, std::abs(rpdo.target));
  }
  std::cout << "RPDO1 largest |target velocity| (0.001 rad/s; wheel limit " << kWheelLimit << "):";
  for (const auto& [name, most] : largest) {
    std::cout << " " << name << ": " << most << ";";
  }
  std::cout << " overall " << overall << " in " << record_.rpdos.size() << " RPDO1 frames" << std::endl;
  EXPECT_LE(overall, kWheelLimit);
  EXPECT_EQ(largest["v=1e9"], 6667);  // 1 m/s, the linear limit
  EXPECT_EQ(largest["v=5"], 6667);
  EXPECT_EQ(largest["v=-1e9"], 6667);
  // Scaled by one factor to 1.2 rad/s (and 1.2e-9 m/s): turning on the spot, 1.2 x 0.3 / 0.15 = 2.4 rad/s.
  EXPECT_EQ(largest["v=1, w=1e9"], 2400);
}

void MotorSafetyTest::expectDrivesStopThemselves(int signal_number, const char* what)
{
  const double speed_before = record_.speed();
  const std::int64_t last_rpdo_us = record_.rpdos.empty() ? 0 : record_.rpdos.back().utime;
  const std::size_t emergencies_before = record_.emergencies.size();
  const std::size_t tpdos_before = record_.tpdos.size();
  const std::int64_t signalled_us = ifar::common::nowMicroseconds();
  ASSERT_EQ(kill(motor_->pid(), signal_number), 0);
  std::optional<std::int64_t> at_rest_us;
  drive(0.8, 0.3, 3.0, [&] {  // the executive keeps commanding: only the motor driver is gone
    if (!at_rest_us && record_.speeds.back().first > signalled_us && record_.speed() < 0.02) {
      at_rest_us = record_.speeds.back().first;
    }
    return at_rest_us.has_value();
  });
  std::map<int, std::int64_t> tripped_us;  // first EMCY 0x8250 / 0x8130 per drive
  std::map<int, std::uint16_t> codes;
  for (std::size_t index = emergencies_before; index < record_.emergencies.size(); ++index) {
    const auto& emergency = record_.emergencies[index];
    if ((emergency.code == 0x8250 || emergency.code == 0x8130) && tripped_us.count(emergency.node) == 0) {
      tripped_us[emergency.node] = emergency.utime;
      codes[emergency.node] = emergency.code;
    }
  }
  std::map<int, std::int64_t> quick_stop_us;  // first TPDO1 reporting quick stop active per drive
  for (std::size_t index = tpdos_before; index < record_.tpdos.size(); ++index) {
    const auto& tpdo = record_.tpdos[index];
    if ((tpdo.statusword & 0x6F) == 0x07 && quick_stop_us.count(tpdo.node) == 0) {
      quick_stop_us[tpdo.node] = tpdo.utime;
    }
  }
  ASSERT_EQ(tripped_us.size(), 2u) << "the drives sent no watchdog EMCY after " << what;
  ASSERT_TRUE(at_rest_us) << "the vehicle did not come to rest within 3 s of " << what;
  const auto ms = [](std::int64_t microseconds) { return static_cast<double>(microseconds) * 1e-3; };
  std::cout << what << " at " << speed_before << " m/s (last RPDO1 " << ms(signalled_us - last_rpdo_us)
            << " ms before): drives stopped themselves (EMCY 0x" << std::hex << codes[1] << ", 0x" << codes[2]
            << std::dec << ", target zero, quick stop) after " << ms(tripped_us[1] - signalled_us)
            << " ms (left), " << ms(tripped_us[2] - signalled_us)
            << " ms (right); quick stop reported on TPDO1 after " << ms(quick_stop_us[1] - signalled_us)
            << " / " << ms(quick_stop_us[2] - signalled_us)
            << " ms; vehicle at rest (ground truth, 20 Hz) after " << ms(*at_rest_us - signalled_us) << " ms"
            << std::endl;
  for (const int node : {1, 2}) {
    EXPECT_LE(tripped_us[node] - signalled_us, kStopBudgetUs) << "drive " << node;
  }
  // From then on the drives brake on their quick-stop ramp; the vehicle follows at its
  // max_linear_acceleration (1 m/s^2), measured over one 50 ms ground-truth period.
  EXPECT_LE(*at_rest_us - signalled_us,
            kStopBudgetUs + static_cast<std::int64_t>(speed_before * 1e6) + 150'000);
}

TEST_F(MotorSafetyTest, AFrozenMotorDriverIsStoppedByTheDrivesWithin200Milliseconds)
{
  startAndReach("udpm://239.255.76.67:7792?ttl=0", 0.8, 0.3, 0.75);
  expectDrivesStopThemselves(SIGSTOP, "SIGSTOP of ifar-motor-driver");
  // Thawed after 2 s: the driver refuses what queued up meanwhile (stale by its utime) and runs the
  // drives again through their enable sequence on fresh commands.
  drive(0.8, 0.3, 1.0);  // frozen about 2 s in all
  ASSERT_EQ(kill(motor_->pid(), SIGCONT), 0);
  int steady = 0;
  const bool again = drive(0.8, 0.3, 10.0, [&] {
    steady = record_.speed() >= 0.75 ? steady + 1 : 0;
    return steady >= 10;
  });
  EXPECT_TRUE(again) << "the vehicle did not drive again after SIGCONT:\n"
                     << readText(folder_ + "/motor.out");
  EXPECT_NE(readText(folder_ + "/motor.out").find("stale: utime"), std::string::npos)
      << "the commands queued during the freeze were not refused as stale";
}

TEST_F(MotorSafetyTest, AnExecutiveFallenSilentIsStoppedByTheMotorDriverWithin200Milliseconds)
{
  startAndReach("udpm://239.255.76.67:7794?ttl=0", 0.8, 0.3, 0.75);
  const double speed_before = record_.speed();
  const std::int64_t last_command_us = last_command_utime_;
  const std::size_t rpdos_before = record_.rpdos.size();
  std::map<int, std::int64_t> zero_us;  // first RPDO1 with target 0 per drive
  std::optional<std::int64_t> at_rest_us;
  listen(3.0, [&] {
    for (std::size_t index = rpdos_before; index < record_.rpdos.size(); ++index) {
      const auto& rpdo = record_.rpdos[index];
      if (rpdo.target == 0 && zero_us.count(rpdo.node) == 0) {
        zero_us[rpdo.node] = rpdo.utime;
      }
    }
    if (!at_rest_us && record_.speeds.back().first > last_command_us && record_.speed() < 0.02) {
      at_rest_us = record_.speeds.back().first;
    }
    return at_rest_us.has_value() && zero_us.size() == 2;
  });
  ASSERT_EQ(zero_us.size(), 2u) << "no zero RPDO1 within 3 s of the last command";
  ASSERT_TRUE(at_rest_us) << "the vehicle did not come to rest within 3 s of the last command";
  const auto ms = [](std::int64_t microseconds) { return static_cast<double>(microseconds) * 1e-3; };
  std::cout << "VELOCITY_CMD silent at " << speed_before << " m/s: RPDO1 target zero after "
            << ms(zero_us[1] - last_command_us) << " ms (left), " << ms(zero_us[2] - last_command_us)
            << " ms (right) from the last command's utime; vehicle at rest after "
            << ms(*at_rest_us - last_command_us) << " ms" << std::endl;
  for (const int node : {1, 2}) {
    EXPECT_LE(zero_us[node] - last_command_us, kStopBudgetUs) << "drive " << node;
  }
}

TEST_F(MotorSafetyTest, AKilledMotorDriverIsStoppedByTheDrivesWithin200Milliseconds)
{
  startAndReach("udpm://239.255.76.67:7793?ttl=0", 0.8, 0.3, 0.75);
  expectDrivesStopThemselves(SIGKILL, "SIGKILL of ifar-motor-driver");
}

}  // namespace
