// The whole stack as real processes over UDP multicast (issue #7 checks): `ifar launch
// config/launch/sim_demo.yaml` starts ifar-sim, the Velodyne, force and motor drivers, the planner, the
// executive, lcm-logger and a goal sender that ends the launch when the executive reports the goal
// reached. Each test runs on its own LCM port and log folder; the tests run one at a time (RUN_SERIAL)
// because the stack runs in real time and the simulator sends its VLP-16 packets to UDP port 2368.

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "common/time.hpp"
#include "ifar/affordance_t.hpp"
#include "ifar/exec_status_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/world_state_t.hpp"

extern char** environ;

namespace {

using Clock = std::chrono::steady_clock;

std::string makeTemporaryFolder(const std::string& name)
{
  std::string pattern = "/tmp/ifar-system-" + name + "-XXXXXX";
  if (mkdtemp(pattern.data()) == nullptr) {
    return {};
  }
  return pattern;
}

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

std::string readText(const std::string& path)
{
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/// Runs a program with extra environment variables and its output in `output_path`; waits for it.
int runProgram(const std::vector<std::string>& arguments, const std::string& output_path)
{
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, output_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<char*> argv;
  for (const std::string& argument : arguments) {
    argv.push_back(const_cast<char*>(argument.c_str()));
  }
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    return -1;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The launched stack: `ifar-launch config/launch/sim_demo.yaml` from the repository, with the launch
/// file's variables set. Stopped with SIGINT (then SIGKILL) if still running when destroyed.
class LaunchedStack {
 public:
  LaunchedStack(const std::string& folder, const std::string& lcm_url,
                const std::map<std::string, std::string>& variables, double duration_s)
      : folder_(folder)
  {
    std::vector<std::string> environment;
    for (char** entry = environ; *entry != nullptr; ++entry) {
      const std::string text = *entry;
      if (text.rfind("LCM_DEFAULT_URL=", 0) != 0 && text.rfind("IFAR_", 0) != 0) {
        environment.push_back(text);
      }
    }
    environment.push_back("LCM_DEFAULT_URL=" + lcm_url);
    environment.push_back("IFAR_LOG_DIR=" + folder);
    for (const auto& [name, value] : variables) {
      environment.push_back(name + "=" + value);
    }
    std::vector<char*> envp;
    for (std::string& entry : environment) {
      envp.push_back(entry.data());
    }
    envp.push_back(nullptr);
    const std::vector<std::string> arguments = {std::string(IFAR_BINARY_DIR) + "/bin/ifar-launch",
                                                "config/launch/sim_demo.yaml", "--duration",
                                                std::to_string(duration_s), "--no-colour"};
    std::vector<char*> argv;
    for (const std::string& argument : arguments) {
      argv.push_back(const_cast<char*>(argument.c_str()));
    }
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string output = folder + "/launch.out";
    posix_spawn_file_actions_addopen(&actions, 1, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), envp.data()) != 0) {
      pid_ = -1;
    }
    posix_spawn_file_actions_destroy(&actions);
  }
  ~LaunchedStack()
  {
    if (pid_ > 0) {
      kill(pid_, SIGINT);
      if (!waitFor(10.0)) {
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
      }
    }
  }
  LaunchedStack(const LaunchedStack&) = delete;
  LaunchedStack& operator=(const LaunchedStack&) = delete;

  bool started() const { return pid_ > 0; }
  pid_t pid() const { return pid_; }
  std::optional<int> exitCode() const { return exit_code_; }

  /// True when the launch exited within `seconds` (its exit code is then in exitCode()).
  bool waitFor(double seconds)
  {
    const Clock::time_point deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    while (pid_ > 0 && Clock::now() < deadline) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        pid_ = -1;
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return pid_ <= 0;
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
      if (parent == pid_ && stat.substr(open + 1, close - open - 1) == program.substr(0, 15)) {
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
  std::string folder_;
  pid_t pid_ = -1;
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
    ASSERT_EQ(chdir(IFAR_SOURCE_DIR), 0);  // the launch file and configs are relative to the repository
    folder_ = makeTemporaryFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
    ASSERT_FALSE(folder_.empty());
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
    const int check =
        runProgram({std::string(IFAR_BINARY_DIR) + "/bin/ifar-log-info", "--check", logs.front()},
                   folder_ + "/log-check.out");
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
  }

  std::string folder_;
};

TEST_F(SystemTest, DemoArrivesAfterPushingTheBox)
{
  LaunchedStack stack(folder_, "udpm://239.255.76.67:7781?ttl=0", {{"IFAR_GOAL_WAIT_S", "150"}}, 170.0);
  ASSERT_TRUE(stack.started());
  ASSERT_TRUE(stack.waitFor(185.0)) << "the launch did not end";
  EXPECT_EQ(stack.exitCode(), 0) << "goal not reached:\n" << stack.launchOutput();
  const LoggedRun run = readLog(recordedLog());
  expectArrived(run, 8.0, 26.0);
  ASSERT_TRUE(run.last_status.has_value());
  EXPECT_GE(run.last_status->pushes, 1) << "the vehicle arrived without pushing the box";
  EXPECT_GE(run.max_push_plans, 1) << "no GLOBAL_PATH carried a push plan";
}

TEST_F(SystemTest, HeavyBoxIsMarkedUnpushableAndTheVehicleGoesAround)
{
  const std::string world = std::string(IFAR_SOURCE_DIR) + "/config/worlds/demo_room_heavy.yaml";
  LaunchedStack stack(folder_, "udpm://239.255.76.67:7782?ttl=0",
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

/// Ground truth speeds as they arrive, with their receive times.
struct TruthWatcher {
  std::optional<ifar::world_state_t> previous;
  std::vector<std::pair<std::int64_t, double>> speeds;  // receive utime, m/s
  void onTruth(const lcm::ReceiveBuffer* buffer, const std::string&, const ifar::world_state_t* truth)
  {
    if (previous && truth->utime > previous->utime) {
      const double seconds = static_cast<double>(truth->utime - previous->utime) * 1e-6;
      const double distance =
          std::hypot(truth->vehicle_x - previous->vehicle_x, truth->vehicle_y - previous->vehicle_y);
      speeds.emplace_back(buffer->recv_utime, distance / seconds);
    }
    previous = *truth;
  }
};

TEST_F(SystemTest, KillingThePlannerStopsTheVehicleAndTheRunCompletesAfterRespawn)
{
  const std::string url = "udpm://239.255.76.67:7783?ttl=0";
  lcm::LCM bus(url);
  if (!bus.good()) {
    GTEST_SKIP() << "LCM cannot start on " << url;
  }
  TruthWatcher watcher;
  bus.subscribe("SIM_GROUND_TRUTH", &TruthWatcher::onTruth, &watcher);
  LaunchedStack stack(folder_, url, {{"IFAR_GOAL_WAIT_S", "170"}}, 190.0);
  ASSERT_TRUE(stack.started());

  // Wait until the vehicle has driven at speed for a second.
  const Clock::time_point give_up = Clock::now() + std::chrono::seconds(60);
  int moving = 0;
  while (moving < 20 && Clock::now() < give_up) {
    if (bus.handleTimeout(100) > 0 && !watcher.speeds.empty()) {
      moving = watcher.speeds.back().second > 0.2 ? moving + 1 : 0;
    }
  }
  ASSERT_GE(moving, 20) << "the vehicle never drove:\n" << stack.launchOutput();
  const pid_t planner = stack.childRunning("ifar-planner");
  ASSERT_GT(planner, 0) << "no ifar-planner child of the launch";
  const std::int64_t killed_utime = ifar::common::nowMicroseconds();
  ASSERT_EQ(kill(planner, SIGKILL), 0);

  // The first ground truth showing the vehicle at rest after the kill.
  std::optional<std::int64_t> stopped_utime;
  const Clock::time_point watch_until = Clock::now() + std::chrono::seconds(3);
  while (!stopped_utime && Clock::now() < watch_until) {
    if (bus.handleTimeout(100) > 0) {
      const auto& [received, speed] = watcher.speeds.back();
      if (received > killed_utime && speed < 0.02) {
        stopped_utime = received;
      }
    }
  }
  ASSERT_TRUE(stopped_utime.has_value()) << "the vehicle did not stop within 3 s of the planner's death";
  const double stop_ms = static_cast<double>(*stopped_utime - killed_utime) * 1e-3;
  std::cout << "vehicle at rest " << stop_ms << " ms after kill -9 of the planner (ground truth at 20 Hz)"
            << std::endl;
  // 200 ms is the requirement; ground truth comes every 50 ms and the speed is measured over one period.
  EXPECT_LE(stop_ms, 250.0);

  // The planner respawns and the run completes.
  ASSERT_TRUE(stack.waitFor(185.0)) << "the launch did not end";
  EXPECT_EQ(stack.exitCode(), 0) << "goal not reached after the planner respawned:\n" << stack.launchOutput();
  const std::string output = stack.launchOutput();
  EXPECT_NE(output.find("restarting planner"), std::string::npos) << output;
}

}  // namespace
