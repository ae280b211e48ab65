// The whole stack as real processes over UDP multicast (issue #7 checks): `ifar launch
// config/launch/sim_demo.yaml` starts ifar-sim, the Velodyne, force and motor drivers, the planner, the
// executive, lcm-logger and a goal sender that ends the launch when the executive reports the goal
// reached; the demo's log replays the planner and the executive exactly (ifar replay-test). Each test runs on
// its own LCM port, lidar UDP port (IFAR_LIDAR_PORT: 237NN next to LCM port 77NN) and log folder, so no stack
// hears another's; the tests still run one at a time (RUN_SERIAL): each stack runs in real time with about
// ten processes, and two at once on a two-core machine would stretch the stop latencies they measure.

#include <dirent.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
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
#include "ifar/affordance_t.hpp"
#include "ifar/exec_status_t.hpp"
#include "ifar/heartbeat_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/velocity_cmd_t.hpp"
#include "ifar/world_state_t.hpp"
#include "testing/child_process.hpp"
#include "testing/temporary_directory.hpp"

namespace {

using ifar::test_support::readText;

using Clock = std::chrono::steady_clock;

/// Folder entries whose name contains `part`, full paths.
std::vector<std::string> filesNamed(const std::string& folder, const std::string& part)
{
  std::vector<std::string> found;
  DIR* directory = opendir(folder.c_str());
  if (directory == nullptr) {
    return found;
  }
  while (const dirent* entry = readdir(directory)) {
    const std::string name = entry->d_name;
    if (name.find(part) != std::string::npos) {
      found.push_back(folder + "/" + name);
    }
  }
  closedir(directory);
  return found;
}

/// The launched stack: `ifar-launch config/launch/sim_demo.yaml` from the repository, with the launch
/// file's variables set (IFAR_LOG_DIR the test's folder, IFAR_LIDAR_PORT `lidar_port`); stopped with
/// SIGTERM (then SIGKILL) if still running when destroyed.
class LaunchedStack {
 public:
  LaunchedStack(const std::string& folder, const std::string& lcm_url, int lidar_port,
                std::map<std::string, std::string> variables, double duration_s)
      : folder_(folder),
        launch_({std::string(IFAR_BINARY_DIR) + "/bin/ifar-launch", "config/launch/sim_demo.yaml",
                 "--duration", std::to_string(duration_s), "--no-colour"},
                optionsFor(folder, lcm_url, lidar_port, std::move(variables)))
  {
  }

  bool started() const { return launch_.started(); }
  std::optional<int> exitCode() const { return exit_code_; }

  /// True when the launch exited within `seconds` (its exit code is then in exitCode()).
  bool waitFor(double seconds)
  {
    exit_code_ = launch_.waitFor(seconds);
    return exit_code_.has_value();
  }

  /// The process id of the launched child running `program` (its /proc comm name), or -1.
  pid_t childRunning(const std::string& program) const
  {
    DIR* proc = opendir("/proc");
    pid_t found = -1;
    while (const dirent* entry = proc != nullptr ? readdir(proc) : nullptr) {
      const std::string name = entry->d_name;
      if (name.find_first_not_of("0123456789") != std::string::npos) {
        continue;
      }
      // /proc/PID/stat: "pid (comm) state ppid ..."
      const std::string stat = readText("/proc/" + name + "/stat");
      const std::size_t open = stat.find('(');
      const std::size_t close = stat.rfind(')');
      if (open == std::string::npos || close == std::string::npos) {
        continue;
      }
      std::istringstream rest(stat.substr(close + 2));
      char state = 0;
      pid_t parent = -1;
      rest >> state >> parent;
      if (parent == launch_.pid() && stat.substr(open + 1, close - open - 1) == program.substr(0, 15)) {
        found = static_cast<pid_t>(std::stoi(name));
      }
    }
    if (proc != nullptr) {
      closedir(proc);
    }
    return found;
  }

  std::string launchOutput() const { return readText(folder_ + "/launch.out"); }

 private:
  static ifar::test_support::ChildOptions optionsFor(const std::string& folder, const std::string& lcm_url,
                                                     int lidar_port,
                                                     std::map<std::string, std::string> variables)
  {
    // Every variable of the launch file is set, so none leaks in from the environment of the test.
    const std::map<std::string, std::string> defaults = {{"IFAR_WORLD", "config/worlds/demo_room.yaml"},
                                                         {"IFAR_GOAL_X", "8"},
                                                         {"IFAR_GOAL_Y", "26"},
                                                         {"IFAR_GOAL_WAIT_S", "170"}};
    variables.insert(defaults.begin(), defaults.end());  // keeps the test's own values
    variables["IFAR_LOG_DIR"] = folder;
    variables["IFAR_LIDAR_PORT"] = std::to_string(lidar_port);
    variables["LCM_DEFAULT_URL"] = lcm_url;
    // The launch file and the configs it names are relative to the repository.
    return ifar::test_support::ChildOptions{folder + "/launch.out", IFAR_SOURCE_DIR, std::move(variables)};
  }

  std::string folder_;
  ifar::test_support::ChildProcess launch_;
  std::optional<int> exit_code_;
};

/// What a recorded log says about a run.
struct LoggedRun {
  std::map<std::string, int> channel_counts;
  std::optional<ifar::exec_status_t> last_status;  // goal 1
  std::optional<ifar::world_state_t> last_truth;
  std::vector<ifar::affordance_t> affordances;
  std::vector<ifar::path_t> paths_after_first_affordance;
  int max_push_plans = 0;
  std::map<std::string, int> heartbeats;     // beats per process name
  std::map<std::string, int> ok_heartbeats;  // ... of them with health OK
};

template <typename Message>
bool decodeEvent(const lcm::LogEvent& event, Message& message)
{
  return message.decode(event.data, 0, event.datalen) == event.datalen;
}

LoggedRun readLog(const std::string& path)
{
  LoggedRun run;
  lcm::LogFile log(path, "r");
  if (!log.good()) {
    return run;
  }
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    ++run.channel_counts[event->channel];
    if (event->channel == "EXEC_STATUS") {
      ifar::exec_status_t status;
      if (decodeEvent(*event, status) && status.goal_id == 1) {
        run.last_status = status;
      }
    } else if (event->channel == "SIM_GROUND_TRUTH") {
      ifar::world_state_t truth;
      if (decodeEvent(*event, truth)) {
        run.last_truth = truth;
      }
    } else if (event->channel == "AFFORDANCE") {
      ifar::affordance_t affordance;
      if (decodeEvent(*event, affordance)) {
        run.affordances.push_back(affordance);
      }
    } else if (event->channel == "HEARTBEAT") {
      ifar::heartbeat_t beat;
      if (decodeEvent(*event, beat)) {
        ++run.heartbeats[beat.process];
        run.ok_heartbeats[beat.process] += beat.health == ifar::heartbeat_t::HEALTH_OK ? 1 : 0;
      }
    } else if (event->channel == "GLOBAL_PATH") {
      ifar::path_t path_message;
      if (decodeEvent(*event, path_message)) {
        run.max_push_plans = std::max(run.max_push_plans, path_message.num_push_plans);
        if (!run.affordances.empty()) {
          run.paths_after_first_affordance.push_back(path_message);
        }
      }
    }
  }
  return run;
}

class SystemTest : public ::testing::Test {
 protected:
  void SetUp() override
  {
    directory_ = std::make_unique<ifar::test_support::TemporaryDirectory>(
        std::string("ifar-system-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    folder_ = directory_->path().string();
    ASSERT_FALSE(folder_.empty());
  }

  // The folder holds a ~50 MB log: it goes when the test passed and stays for a look when it failed.
  void TearDown() override
  {
    if (directory_ && !folder_.empty() && HasFailure()) {
      directory_->keep();
      std::cout << "logs of the failed run kept in " << folder_ << "\n";
    }
    directory_.reset();
  }

  /// The one log the recorder wrote; checks that every message in it decodes (ifar log-info --check).
  std::string recordedLog()
  {
    // ifar record splits logs: demo-<time>.lcmlog.00 is the first part.
    const std::vector<std::string> logs = filesNamed(folder_, ".lcmlog");
    EXPECT_EQ(logs.size(), 1U) << "expected one log in " << folder_;
    if (logs.empty()) {
      return {};
    }
    const int check = ifar::test_support::runToEnd(
        {std::string(IFAR_BINARY_DIR) + "/bin/ifar-log-info", "--check", logs.front()},
        ifar::test_support::ChildOptions{folder_ + "/log-check.out", "", {}}, 60.0);
    EXPECT_EQ(check, 0) << readText(folder_ + "/log-check.out");
    return logs.front();
  }

  static void expectArrived(const LoggedRun& run, double goal_x, double goal_y)
  {
    ASSERT_TRUE(run.last_status.has_value()) << "no EXEC_STATUS for goal 1 in the log";
    EXPECT_EQ(run.last_status->mode, ifar::exec_status_t::MODE_ARRIVED) << run.last_status->reason;
    ASSERT_TRUE(run.last_truth.has_value()) << "no SIM_GROUND_TRUTH in the log";
    const double distance =
        std::hypot(run.last_truth->vehicle_x - goal_x, run.last_truth->vehicle_y - goal_y);
    EXPECT_LT(distance, 1.0) << "ground truth ends at (" << run.last_truth->vehicle_x << ", "
                             << run.last_truth->vehicle_y << ")";
    for (const char* channel : {"VELODYNE_PACKET", "POSE", "GLOBAL_PATH", "DV_GRAPH", "PLANNER_STATUS",
                                "EXEC_STATUS", "VELOCITY_CMD", "FORCE", "SIM_GROUND_TRUTH"}) {
      EXPECT_GT(run.channel_counts.count(channel) != 0 ? run.channel_counts.at(channel) : 0, 0)
          << channel << " is missing from the log";
    }
    // Every daemon beats once a second; the shortest run lasts well over 30 s.
    for (const char* process :
         {"sim", "velodyne-driver", "force-driver", "motor-driver", "planner", "executive"}) {
      EXPECT_GE(run.heartbeats.count(process) != 0 ? run.heartbeats.at(process) : 0, 20)
          << "too few heartbeats from " << process << " in the log";
      // Healthy most of the time: its inputs flow and nothing malformed arrives.
      EXPECT_GE(run.ok_heartbeats.count(process) != 0 ? run.ok_heartbeats.at(process) : 0, 15)
          << "too few healthy heartbeats from " << process;
    }
  }

  struct ReplayTestRun {
    int exit_code = -1;
    std::string output;
  };
  /// ifar-replay-test on `log` with the repository's configuration.
  ReplayTestRun replayTest(const std::string& log, std::vector<std::string> arguments) const
  {
    std::vector<std::string> command = {std::string(IFAR_BINARY_DIR) + "/bin/ifar-replay-test", log,
                                        "--config-dir", std::string(IFAR_SOURCE_DIR) + "/config"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    const std::string output = folder_ + "/replay-test.out";
    ReplayTestRun run;
    run.exit_code =
        ifar::test_support::runToEnd(command, ifar::test_support::ChildOptions{output, "", {}}, 120.0);
    run.output = readText(output);
    return run;
  }
  /// True when the report's line for `channel` has as many replayed as recorded, at least `at_least`, and
  /// says they are the same.
  static bool sameCountAndSame(const std::string& output, const std::string& channel, int at_least)
  {
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line)) {
      std::istringstream fields(line);
      std::string name;
      int recorded = -1;
      std::string recorded_word;
      int replayed = -2;
      std::string replayed_word;
      std::string verdict;
      if (fields >> name >> recorded >> recorded_word >> replayed >> replayed_word >> verdict &&
          name == channel) {
        return recorded == replayed && recorded >= at_least && verdict == "same";
      }
    }
    return false;
  }

  std::unique_ptr<ifar::test_support::TemporaryDirectory> directory_;
  std::string folder_;  // directory_'s path
};

TEST_F(SystemTest, DemoArrivesAfterPushingTheBox)
{
  LaunchedStack stack(folder_, "udpm://239.255.76.67:7781?ttl=0", 23781, {{"IFAR_GOAL_WAIT_S", "150"}},
                      170.0);
  ASSERT_TRUE(stack.started());
  ASSERT_TRUE(stack.waitFor(185.0)) << "the launch did not end";
  EXPECT_EQ(stack.exitCode(), 0) << "goal not reached:\n" << stack.launchOutput();
  const std::string log = recordedLog();
  const LoggedRun run = readLog(log);
  expectArrived(run, 8.0, 26.0);
  ASSERT_TRUE(run.last_status.has_value());
  EXPECT_GE(run.last_status->pushes, 1) << "the vehicle arrived without pushing the box";
  EXPECT_GE(run.max_push_plans, 1) << "no GLOBAL_PATH carried a push plan";

  // The demo's own log as a regression test: each node replayed by its journal gives what it published,
  // with the configuration the journal states (the planner ran on the test's lidar port, 23781).
  const ReplayTestRun planner = replayTest(log, {"--node", "planner"});
  EXPECT_EQ(planner.exit_code, 0) << planner.output;
  EXPECT_NE(planner.output.find("settings from the planner's journal\n"), std::string::npos)
      << planner.output;
  EXPECT_TRUE(sameCountAndSame(planner.output, "GLOBAL_PATH", 500)) << planner.output;
  EXPECT_TRUE(sameCountAndSame(planner.output, "DV_GRAPH", 50)) << planner.output;
  EXPECT_NE(planner.output.find("timers from the planner's journal on PLANNER_JOURNAL"), std::string::npos)
      << planner.output;
  const ReplayTestRun executive = replayTest(log, {"--node", "executive"});
  EXPECT_EQ(executive.exit_code, 0) << executive.output;
  EXPECT_TRUE(sameCountAndSame(executive.output, "VELOCITY_CMD", 1000)) << executive.output;
  const ReplayTestRun changed =
      replayTest(log, {"--node", "planner", "--set", "interaction.reference_force_n=50"});
  EXPECT_EQ(changed.exit_code, 1) << changed.output;
  EXPECT_NE(changed.output.find("\ndifferent: "), std::string::npos) << changed.output;
  // The repository's planner.yaml listens on the default lidar port: the replay cannot find its packets.
  const ReplayTestRun from_directory = replayTest(log, {"--node", "planner", "--node-config-from-dir"});
  EXPECT_NE(from_directory.exit_code, 0) << from_directory.output;
}

TEST_F(SystemTest, HeavyBoxIsMarkedUnpushableAndTheVehicleGoesAround)
{
  const std::string world = std::string(IFAR_SOURCE_DIR) + "/config/worlds/demo_room_heavy.yaml";
  LaunchedStack stack(folder_, "udpm://239.255.76.67:7782?ttl=0", 23782,
                      {{"IFAR_WORLD", world}, {"IFAR_GOAL_WAIT_S", "200"}}, 220.0);
  ASSERT_TRUE(stack.started());
  ASSERT_TRUE(stack.waitFor(235.0)) << "the launch did not end";
  EXPECT_EQ(stack.exitCode(), 0) << "goal not reached:\n" << stack.launchOutput();
  const LoggedRun run = readLog(recordedLog());
  expectArrived(run, 8.0, 26.0);
  ASSERT_FALSE(run.affordances.empty()) << "no AFFORDANCE in the log";
  EXPECT_FALSE(run.affordances.front().pushable);
  EXPECT_EQ(run.affordances.front().reason, ifar::affordance_t::REASON_NO_MOTION);
  // The replan: a path after the affordance that pushes nothing, the way round the partition.
  bool replanned_without_push = false;
  for (const ifar::path_t& path : run.paths_after_first_affordance) {
    replanned_without_push = replanned_without_push || (path.valid && path.num_push_plans == 0);
  }
  EXPECT_TRUE(replanned_without_push) << "no push-free GLOBAL_PATH after the AFFORDANCE";
  ASSERT_TRUE(run.last_status.has_value());
  EXPECT_GE(run.last_status->replans, 1);
  EXPECT_EQ(run.last_status->pushes, 0);
}

/// Ground truth speeds and the executive's zero-velocity commands as they arrive, with receive times.
struct StopWatcher {
  std::optional<ifar::world_state_t> previous;
  std::vector<std::pair<std::int64_t, double>> speeds;               // receive utime, m/s
  std::vector<std::int64_t> zero_commands;                           // receive utimes of VELOCITY_CMD (0, 0)
  std::vector<std::pair<std::int64_t, ifar::world_state_t>> truths;  // receive utime, ground truth
  void onTruth(const lcm::ReceiveBuffer* buffer, const std::string&, const ifar::world_state_t* truth)
  {
    truths.emplace_back(buffer->recv_utime, *truth);
    if (previous && truth->utime > previous->utime) {
      const double seconds = static_cast<double>(truth->utime - previous->utime) * 1e-6;
      const double distance =
          std::hypot(truth->vehicle_x - previous->vehicle_x, truth->vehicle_y - previous->vehicle_y);
      speeds.emplace_back(buffer->recv_utime, distance / seconds);
    }
    previous = *truth;
  }
  void onCommand(const lcm::ReceiveBuffer* buffer, const std::string&, const ifar::velocity_cmd_t* command)
  {
    if (command->linear_velocity == 0.0 && command->angular_velocity == 0.0) {
      zero_commands.push_back(buffer->recv_utime);
    }
  }
  /// Handles `bus` until the vehicle has held more than 0.2 m/s for 20 ground-truth samples (a second) or
  /// `seconds` pass: its last speed, or nullopt when it never drove.
  std::optional<double> waitUntilDriving(lcm::LCM& bus, double seconds)
  {
    const Clock::time_point give_up =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    int moving = 0;
    while (moving < 20 && Clock::now() < give_up) {
      if (bus.handleTimeout(100) > 0 && !speeds.empty()) {
        moving = speeds.back().second > 0.2 ? moving + 1 : 0;
      }
    }
    return moving >= 20 ? std::optional<double>(speeds.back().second) : std::nullopt;
  }
  /// The receive time of the first zero-velocity command after `since_utime`.
  std::optional<std::int64_t> firstZeroCommandAfter(std::int64_t since_utime) const
  {
    for (const std::int64_t received : zero_commands) {
      if (received > since_utime) {
        return received;
      }
    }
    return std::nullopt;
  }
  /// The highest ground-truth speed received from `from_utime` to `to_utime`, or `floor` when higher.
  double fastestBetween(std::int64_t from_utime, std::int64_t to_utime, double floor) const
  {
    double fastest = floor;
    for (const auto& [received, speed] : speeds) {
      if (received >= from_utime && received <= to_utime) {
        fastest = std::max(fastest, speed);
      }
    }
    return fastest;
  }
  /// The receive time of the first ground truth at rest (under 0.02 m/s) after `since_utime`.
  std::optional<std::int64_t> firstRestAfter(std::int64_t since_utime) const
  {
    for (const auto& [received, speed] : speeds) {
      if (received > since_utime && speed < 0.02) {
        return received;
      }
    }
    return std::nullopt;
  }
};

TEST_F(SystemTest, KillingThePlannerStopsTheVehicleAndTheRunCompletesAfterRespawn)
{
  const std::string url = "udpm://239.255.76.67:7783?ttl=0";
  const int lidar_port = 23783;
  lcm::LCM bus(url);
  if (!bus.good()) {
    GTEST_SKIP() << "LCM cannot start on " << url;
  }
  StopWatcher watcher;
  bus.subscribe("SIM_GROUND_TRUTH", &StopWatcher::onTruth, &watcher);
  bus.subscribe("VELOCITY_CMD", &StopWatcher::onCommand, &watcher);
  LaunchedStack stack(folder_, url, lidar_port, {{"IFAR_GOAL_WAIT_S", "170"}}, 190.0);
  ASSERT_TRUE(stack.started());

  const std::optional<double> driving = watcher.waitUntilDriving(bus, 60.0);
  ASSERT_TRUE(driving.has_value()) << "the vehicle never drove:\n" << stack.launchOutput();
  const double speed_at_kill = *driving;
  const pid_t planner = stack.childRunning("ifar-planner");
  ASSERT_GT(planner, 0) << "no ifar-planner child of the launch";
  const std::int64_t killed_utime = ifar::common::nowMicroseconds();
  ASSERT_EQ(kill(planner, SIGKILL), 0);

  // The first zero-velocity command and the first ground truth at rest after the kill.
  const Clock::time_point watch_until = Clock::now() + std::chrono::seconds(3);
  while (!watcher.firstRestAfter(killed_utime) && Clock::now() < watch_until) {
    bus.handleTimeout(100);
  }
  const std::optional<std::int64_t> commanded_utime = watcher.firstZeroCommandAfter(killed_utime);
  const std::optional<std::int64_t> stopped_utime = watcher.firstRestAfter(killed_utime);
  ASSERT_TRUE(commanded_utime.has_value()) << "no zero VELOCITY_CMD within 3 s of the planner's death";
  ASSERT_TRUE(stopped_utime.has_value()) << "the vehicle did not stop within 3 s of the planner's death";
  const double command_ms = static_cast<double>(*commanded_utime - killed_utime) * 1e-3;
  const double stop_ms = static_cast<double>(*stopped_utime - killed_utime) * 1e-3;
  // Until the zero command the executive still drives the last path and may speed up: braking starts from
  // the speed the vehicle had then.
  const double speed_at_command = watcher.fastestBetween(killed_utime, *commanded_utime, speed_at_kill);
  std::cout << "planner killed at " << speed_at_kill << " m/s: zero velocity commanded after " << command_ms
            << " ms at " << speed_at_command << " m/s, vehicle at rest (ground truth, 20 Hz) after "
            << stop_ms << " ms" << std::endl;
  // The requirement: zero velocity commanded within 200 ms of the planner's death. The wheels then brake
  // at vehicle.yaml's max_linear_acceleration (1 m/s^2), so rest follows speed / (1 m/s^2) later, plus
  // the way to the wheels (LCM to the motor driver, CANopen RPDO, the drive's ramp, the wheel response)
  // and one 50 ms ground-truth period over which the speed is measured: 300 ms allowed for those.
  EXPECT_LE(command_ms, 200.0);
  EXPECT_LE(stop_ms, command_ms + 1000.0 * speed_at_command / 1.0 + 300.0);

  // The planner respawns and the run completes.
  ASSERT_TRUE(stack.waitFor(185.0)) << "the launch did not end";
  EXPECT_EQ(stack.exitCode(), 0) << "goal not reached after the planner respawned:\n" << stack.launchOutput();
  const std::string output = stack.launchOutput();
  EXPECT_NE(output.find("restarting planner"), std::string::npos) << output;
}

/// Ground-truth distance the vehicle covered between two receive times.
double travelledBetween(const StopWatcher& watcher, std::int64_t from_utime, std::int64_t to_utime)
{
  double distance = 0.0;
  const ifar::world_state_t* previous = nullptr;
  for (const auto& [received, truth] : watcher.truths) {
    if (received < from_utime || received > to_utime) {
      continue;
    }
    if (previous != nullptr) {
      distance += std::hypot(truth.vehicle_x - previous->vehicle_x, truth.vehicle_y - previous->vehicle_y);
    }
    previous = &truth;
  }
  return distance;
}

TEST_F(SystemTest, AFrozenLidarDriverStopsTheVehicleAndItDrivesOnWhenTheLidarIsBack)
{
  const std::string url = "udpm://239.255.76.67:7784?ttl=0";
  const int lidar_port = 23784;
  lcm::LCM bus(url);
  if (!bus.good()) {
    GTEST_SKIP() << "LCM cannot start on " << url;
  }
  StopWatcher watcher;
  bus.subscribe("SIM_GROUND_TRUTH", &StopWatcher::onTruth, &watcher);
  bus.subscribe("VELOCITY_CMD", &StopWatcher::onCommand, &watcher);
  LaunchedStack stack(folder_, url, lidar_port, {{"IFAR_GOAL_WAIT_S", "170"}}, 190.0);
  ASSERT_TRUE(stack.started());
  const std::optional<double> driving = watcher.waitUntilDriving(bus, 60.0);
  ASSERT_TRUE(driving.has_value()) << "the vehicle never drove:\n" << stack.launchOutput();
  const double speed_at_freeze = *driving;
  const pid_t lidar = stack.childRunning("ifar-velodyne-driver");
  ASSERT_GT(lidar, 0) << "no ifar-velodyne-driver child of the launch";
  const std::int64_t frozen_utime = ifar::common::nowMicroseconds();
  ASSERT_EQ(kill(lidar, SIGSTOP), 0);

  // Two seconds without obstacle points, as a sensor unplugged for that long.
  const Clock::time_point thaw = Clock::now() + std::chrono::seconds(2);
  while (Clock::now() < thaw) {
    bus.handleTimeout(50);
  }
  const std::optional<std::int64_t> commanded_utime = watcher.firstZeroCommandAfter(frozen_utime);
  const std::optional<std::int64_t> stopped_utime = watcher.firstRestAfter(frozen_utime);
  const std::int64_t thawed_utime = ifar::common::nowMicroseconds();
  ASSERT_EQ(kill(lidar, SIGCONT), 0);
  ASSERT_TRUE(commanded_utime.has_value()) << "no zero VELOCITY_CMD while the lidar was frozen";
  ASSERT_TRUE(stopped_utime.has_value()) << "the vehicle did not stop while the lidar was frozen";
  const double command_ms = static_cast<double>(*commanded_utime - frozen_utime) * 1e-3;
  const double blind_m = travelledBetween(watcher, frozen_utime, thawed_utime);
  double peak_speed = 0.0;  // the vehicle may still have been accelerating when the lidar froze
  for (const auto& [received, speed] : watcher.speeds) {
    peak_speed =
        received > frozen_utime && received < thawed_utime ? std::max(peak_speed, speed) : peak_speed;
  }
  std::cout << "lidar frozen at " << speed_at_freeze << " m/s: zero velocity commanded after " << command_ms
            << " ms, at rest after " << static_cast<double>(*stopped_utime - frozen_utime) * 1e-3 << " ms, "
            << blind_m << " m driven in the 2 s without the lidar (peak " << peak_speed << " m/s)"
            << std::endl;
  // The points go stale 0.5 s (executive.yaml stale_after_s.obstacles) after the last packet; the next
  // 20 ms cycle commands zero. Then the way to the wheels (300 ms, as for a dead planner) and braking at
  // 1 m/s^2 from at most the peak speed; 0.1 m for the 20 Hz ground truth's sampling.
  const double command_s = command_ms * 1e-3;
  EXPECT_LE(command_ms, 500.0 + 200.0);
  EXPECT_LE(blind_m, peak_speed * (command_s + 0.3) + peak_speed * peak_speed / 2.0 + 0.1);

  // The lidar back: the vehicle drives on.
  bool again = false;
  const Clock::time_point resume_until = Clock::now() + std::chrono::seconds(15);
  while (!again && Clock::now() < resume_until) {
    if (bus.handleTimeout(100) > 0 && !watcher.speeds.empty()) {
      again = watcher.speeds.back().first > thawed_utime && watcher.speeds.back().second > 0.2;
    }
  }
  EXPECT_TRUE(again) << "the vehicle did not drive on after the lidar came back:\n" << stack.launchOutput();
}

}  // namespace
