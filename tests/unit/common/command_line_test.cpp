#include "common/command_line.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace ifar::common {
namespace {

TEST(CommaNumbers, ParsesXYAndOptionalHeading)
{
  EXPECT_EQ(parseCommaNumbers("8,26", 2, 2), (std::vector<double>{8.0, 26.0}));
  EXPECT_EQ(parseCommaNumbers("-3.5,1e1", 2, 2), (std::vector<double>{-3.5, 10.0}));
  EXPECT_EQ(parseCommaNumbers("1,2,1.57", 2, 3), (std::vector<double>{1.0, 2.0, 1.57}));
  EXPECT_EQ(parseCommaNumbers("1,2", 2, 3), (std::vector<double>{1.0, 2.0}));
}

TEST(CommaNumbers, RefusesAnythingElse)
{
  for (const std::string text : {"", "3", "1 2", "1,", ",2", "1,2,3", "nan,5", "inf,1", "1,2x", "a,b"}) {
    EXPECT_FALSE(parseCommaNumbers(text, 2, 2).has_value()) << text;
  }
}

/// Runs `app` on `arguments` (program name first); the exit code parseCommandLine asks for, -1 to go on.
int parse(CLI::App& app, std::vector<std::string> arguments)
{
  std::vector<char*> argv;
  for (std::string& argument : arguments) {
    argv.push_back(argument.data());
  }
  const auto exit_code = parseCommandLine(app, static_cast<int>(argv.size()), argv.data());
  return exit_code ? *exit_code : -1;
}

TEST(CoordinatesOption, FillsTheValuesOrFailsWithExitCode2)
{
  CLI::App app{"test"};
  std::vector<double> goal;
  addCoordinatesOption(app, "--goal", goal, "X,Y", 2, 2, "goal");
  EXPECT_EQ(parse(app, {"test", "--goal", "-3,4"}), -1);
  EXPECT_EQ(goal, (std::vector<double>{-3.0, 4.0}));

  CLI::App bad{"test"};
  std::vector<double> start;
  addCoordinatesOption(bad, "start", start, "X,Y[,HEADING_RAD]", 2, 3, "start");
  testing::internal::CaptureStderr();
  EXPECT_EQ(parse(bad, {"test", "3"}), kBadInputExitCode);
  const std::string error = testing::internal::GetCapturedStderr();
  EXPECT_NE(error.find("start: expected X,Y[,HEADING_RAD] (numbers separated by commas), got '3'"),
            std::string::npos)
      << error;
  EXPECT_TRUE(start.empty());
}

}  // namespace
}  // namespace ifar::common
