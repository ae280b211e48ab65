#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/logging.hpp"

namespace {

using ifar::common::chooseLogLevel;
using ifar::common::LoggingOptions;

TEST(Logging, CommandLineBeatsEnvironmentBeatsConfig)
{
  LoggingOptions options;
  EXPECT_EQ(chooseLogLevel(options, nullptr), spdlog::level::info);
  options.config_level = "warn";
  EXPECT_EQ(chooseLogLevel(options, nullptr), spdlog::level::warn);
  EXPECT_EQ(chooseLogLevel(options, ""), spdlog::level::warn);
  EXPECT_EQ(chooseLogLevel(options, "debug"), spdlog::level::debug);
  options.command_line_level = "error";
  EXPECT_EQ(chooseLogLevel(options, "debug"), spdlog::level::err);
}

TEST(Logging, UnknownLevelIsRejectedWithTheName)
{
  try {
    ifar::common::parseLogLevel("loud");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("'loud'"), std::string::npos);
  }
}

TEST(Logging, WritesANamedRotatingFile)
{
  const auto folder =
      std::filesystem::temp_directory_path() / ("ifar_logging_test_" + std::to_string(getpid()));
  std::filesystem::remove_all(folder);
  LoggingOptions options;
  options.log_directory = folder.string();
  options.command_line_level = "debug";
  auto logger = ifar::common::makeLogger("unit_daemon", options);
  logger->debug("hello {}", 42);
  // A string from the bus with a line break and an ANSI escape: still one line, nothing forged.
  logger->info("E_STOP by {}", "operator\n2026-11-29 00:00:00.000 [executive] [info] all clear\x1b[2J");
  logger->trace("not shown");
  logger->flush();
  std::ifstream file(folder / "unit_daemon.log");
  ASSERT_TRUE(file) << "no log file in " << folder;
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_NE(text.str().find("[unit_daemon] [debug] hello 42"), std::string::npos) << text.str();
  const std::string contents = text.str();
  EXPECT_EQ(std::count(contents.begin(), contents.end(), '\n'), 2) << contents;
  EXPECT_EQ(text.str().find("not shown"), std::string::npos);
  EXPECT_NE(
      text.str().find("E_STOP by operator\\n2026-11-29 00:00:00.000 [executive] [info] all clear\\x1b[2J"),
      std::string::npos)
      << text.str();
  EXPECT_EQ(spdlog::get("unit_daemon"), logger);
  std::filesystem::remove_all(folder);
}

TEST(Logging, ControlCharactersAreEscaped)
{
  EXPECT_EQ(ifar::common::escapeControlCharacters("a\nb\rc\td\x01\x7f e"), "a\\nb\\rc\\td\\x01\\x7f e");
  EXPECT_EQ(ifar::common::escapeControlCharacters("plain text, 42 N"), "plain text, 42 N");
}

}  // namespace
