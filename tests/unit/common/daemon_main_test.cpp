#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "common/daemon_main.hpp"

namespace {

namespace fs = std::filesystem;

class DaemonMain : public ::testing::Test {
 protected:
  void SetUp() override
  {
    directory_ =
        fs::temp_directory_path() / ("ifar-daemon-main-" + std::to_string(::getpid()) + "-" +
                                     ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  std::string writeConfig(const std::string& text) const
  {
    const fs::path path = directory_ / "daemon.yaml";
    std::ofstream(path) << text;
    return path.string();
  }

  /// Runs runDaemon with `arguments` (after the program name, console logging only); the body reads one
  /// key of its own (`rate_hz`, optional, greater than zero), checks for unknown keys and records the URL
  /// it was given and the rate.
  int run(std::vector<std::string> arguments)
  {
    arguments.insert(arguments.begin(), {"ifar-test", "--log-dir", ""});
    std::vector<char*> argv;
    for (std::string& argument : arguments) {
      argv.push_back(argument.data());
    }
    return ifar::common::runDaemon(static_cast<int>(argv.size()), argv.data(),
                                   {"daemon-main-test", "test daemon", "", {}},
                                   [this](ifar::common::DaemonContext& context) {
                                     rate_ = context.config.optionalPositive("rate_hz", 2.5);
                                     context.config.rejectUnknownKeys();
                                     url_ = context.lcm_url;
                                     return 0;
                                   });
  }

  /// runDaemon with --print-config and a daemon whose settings are one key, `rate_hz`; stdout captured.
  int printConfig(const std::string& config, std::string& printed, const std::vector<std::string>& extra = {})
  {
    std::vector<std::string> arguments = {"ifar-test", "--log-dir", "", "--config", config, "--print-config"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (std::string& argument : arguments) {
      argv.push_back(argument.data());
    }
    const auto describe = [](const ifar::common::ConfigNode& node) {
      const double rate = node.optional<double>("rate_hz", 2.5);
      return "rate_hz: " + std::to_string(rate) + "\n";
    };
    ::testing::internal::CaptureStdout();
    const int code = ifar::common::runDaemon(static_cast<int>(argv.size()), argv.data(),
                                             {"daemon-main-test", "test daemon", "", describe},
                                             [this](ifar::common::DaemonContext&) {
                                               url_ = "(the daemon ran)";
                                               return 0;
                                             });
    printed = ::testing::internal::GetCapturedStdout();
    return code;
  }

  fs::path directory_;
  std::string url_ = "(not recorded)";
  double rate_ = 0.0;
};

TEST_F(DaemonMain, PrintConfigPrintsTheCommonKeysAndTheDaemonsThenExitsWithoutRunning)
{
  std::string printed;
  EXPECT_EQ(printConfig(writeConfig("log_level: warn\nrate_hz: 5\n"), printed), 0);
  EXPECT_EQ(url_, "(not recorded)");
  EXPECT_NE(printed.find("\nlog_level: \"warn\"  # trace, debug"), std::string::npos) << printed;
  EXPECT_NE(printed.find("\nlcm_url: \"\"  # LCM URL"), std::string::npos) << printed;
  EXPECT_NE(printed.find("\nrate_hz: 5.000000\n"), std::string::npos) << printed;
}

TEST_F(DaemonMain, PrintConfigRejectsAnUnknownKeyLikeStartUp)
{
  std::string printed;
  EXPECT_EQ(printConfig(writeConfig("rate_hz: 5\nrate_hz_typo: 6\n"), printed), 2);
  EXPECT_EQ(printed, "");
}

constexpr const char* kConfigured = "udpm://239.255.76.67:7667?ttl=0";
constexpr const char* kCommandLine = "udpm://239.255.76.68:7668?ttl=0";

TEST_F(DaemonMain, TheConfigsLcmUrlIsUsed)
{
  const std::string config = writeConfig(std::string("lcm_url: ") + kConfigured + "\nlog_level: warn\n");
  EXPECT_EQ(run({"--config", config}), 0);
  EXPECT_EQ(url_, kConfigured);
}

// The config keeps its lcm_url for the vehicle; a test or a replay on another bus overrides it.
TEST_F(DaemonMain, LcmUrlOnTheCommandLineOverridesTheConfigsWithoutMakingItAnUnknownKey)
{
  const std::string config = writeConfig(std::string("lcm_url: ") + kConfigured + "\nlog_level: warn\n");
  EXPECT_EQ(run({"--config", config, "--lcm-url", kCommandLine}), 0);
  EXPECT_EQ(url_, kCommandLine);
}

TEST_F(DaemonMain, AnUnknownKeyStopsStartUpWithExitCodeTwo)
{
  const std::string config = writeConfig("lcm_urll: udpm://239.255.76.67:7667\n");
  EXPECT_EQ(run({"--config", config, "--lcm-url", kCommandLine}), 2);
  EXPECT_EQ(url_, "(not recorded)");
}

TEST_F(DaemonMain, ABadLogLevelNamesWhereItCameFrom)
{
  const std::string config = writeConfig("log_level: loud\n");
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--config", config}), 2);
  EXPECT_NE(
      ::testing::internal::GetCapturedStderr().find(config + ": key 'log_level': unknown log level 'loud'"),
      std::string::npos);

  const std::string good = writeConfig("log_level: warn\n");
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--config", good, "--log-level", "chatty"}), 2);
  EXPECT_NE(::testing::internal::GetCapturedStderr().find("--log-level: unknown log level 'chatty'"),
            std::string::npos);
}

// A launch file gives each stack its own ports this way, without a copy of the config.
TEST_F(DaemonMain, SetReplacesAKeyOfTheConfigOrAddsOneTheFileLacks)
{
  const std::string config = writeConfig(std::string("lcm_url: ") + kConfigured + "\nrate_hz: 5\n");
  EXPECT_EQ(
      run({"--config", config, "--set", "rate_hz=7.5", "--set", std::string("lcm_url=") + kCommandLine}), 0);
  EXPECT_EQ(rate_, 7.5);
  EXPECT_EQ(url_, kCommandLine);

  EXPECT_EQ(run({"--set", "rate_hz=4", "--set", "log_level=warn"}), 0);  // no configuration file at all
  EXPECT_EQ(rate_, 4.0);
}

TEST_F(DaemonMain, ASetValueIsCheckedLikeTheFilesAndTheMessageNamesTheOption)
{
  const std::string config = writeConfig("rate_hz: 5\nlog_level: warn\n");
  for (const auto& [assignment, expected] : std::vector<std::pair<std::string, std::string>>{
           {"rate_hz=-1", "--set rate_hz=-1: key 'rate_hz': must be greater than zero"},
           {"rate_hz=fast", "--set rate_hz=fast: key 'rate_hz': expected number, got 'fast'"},
           {"rate_hx=1", "--set rate_hx=1: key 'rate_hx': unknown key"},
           {"rate_hz", "--set rate_hz: expected KEY=VALUE"},
           {"rate_hz.max=1", "--set rate_hz.max=1: key 'rate_hz' holds '5' in " + config + ", not a map"},
           {"log_level=loud", "--set log_level=loud: key 'log_level': unknown log level 'loud'"}}) {
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(run({"--config", config, "--set", assignment}), 2) << assignment;
    const std::string error = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(error.find("ifar-daemon-main-test: error: " + expected), std::string::npos) << error;
    EXPECT_EQ(url_, "(not recorded)");
  }
}

// One value per --set: an argument after it is not swallowed as a second one.
TEST_F(DaemonMain, SetTakesOneValueEachTime)
{
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--set", "rate_hz=7", "stray"}), 2);
  EXPECT_NE(::testing::internal::GetCapturedStderr().find("stray"), std::string::npos);
  EXPECT_EQ(url_, "(not recorded)");
}

TEST_F(DaemonMain, PrintConfigShowsTheSetValues)
{
  std::string printed;
  EXPECT_EQ(printConfig(writeConfig("rate_hz: 5\n"), printed, {"--set", "rate_hz=7"}), 0);
  EXPECT_NE(printed.find("\nrate_hz: 7.000000\n"), std::string::npos) << printed;
}

}  // namespace
