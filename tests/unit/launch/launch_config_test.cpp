#include <map>
#include <string>

#include <gtest/gtest.h>

#include "tools/launch/launch_config.hpp"
#include "tools/launch/variables.hpp"

namespace {

using ifar::launch::expandVariables;
using ifar::launch::Expansion;

ifar::launch::VariableLookup lookupIn(const std::map<std::string, std::string>& variables)
{
  return [variables](const std::string& name) -> std::optional<std::string> {
    const auto found = variables.find(name);
    if (found == variables.end()) {
      return std::nullopt;
    }
    return found->second;
  };
}

TEST(Variables, ExpandsSetVariablesAndFallbacks)
{
  const auto lookup = lookupIn({{"WORLD", "worlds/heavy.yaml"}, {"EMPTY", ""}});
  EXPECT_EQ(expandVariables("${WORLD}", lookup).text, "worlds/heavy.yaml");
  EXPECT_EQ(expandVariables("--world=${WORLD}!", lookup).text, "--world=worlds/heavy.yaml!");
  EXPECT_EQ(expandVariables("${GOAL_X:-8}", lookup).text, "8");
  EXPECT_EQ(expandVariables("${EMPTY:-fallback}", lookup).text, "fallback");
  EXPECT_EQ(expandVariables("${WORLD:-other}", lookup).text, "worlds/heavy.yaml");
  EXPECT_EQ(expandVariables("${A:-1} ${B:-2}", lookup).text, "1 2");
  EXPECT_EQ(expandVariables("cost $5 and $HOME stay", lookup).text, "cost $5 and $HOME stay");
  EXPECT_EQ(expandVariables("${A:-}", lookup).text, "");
}

TEST(Variables, ReportsUnsetUnterminatedAndBadNames)
{
  const auto lookup = lookupIn({});
  const Expansion unset = expandVariables("x ${WORLD} y", lookup);
  EXPECT_EQ(unset.error, "variable 'WORLD' is not set (write ${WORLD:-fallback} for a default)");
  EXPECT_EQ(expandVariables("${WORLD", lookup).error, "unterminated '${' in '${WORLD'");
  EXPECT_EQ(expandVariables("${1X}", lookup).error,
            "'${1X}' does not name a variable (letters, digits and _)");
  EXPECT_EQ(expandVariables("${}", lookup).error, "'${}' does not name a variable (letters, digits and _)");
}

TEST(LaunchConfig, ExpandsCommandsAndEnvironment)
{
  const auto root = ifar::common::ConfigNode::loadString(
      "processes:\n"
      "  - name: sim\n"
      "    command: [ifar-sim, '${WORLD:-config/worlds/demo_room.yaml}', --log-dir, '${LOG_DIR}']\n"
      "    environment: {SPDLOG_LEVEL: '${LEVEL:-info}'}\n",
      "test.yaml");
  const auto spec = ifar::launch::loadLaunchSpec(root, lookupIn({{"LOG_DIR", "/tmp/run"}}));
  ASSERT_EQ(spec.processes.size(), 1U);
  EXPECT_EQ(spec.processes[0].command,
            (std::vector<std::string>{"ifar-sim", "config/worlds/demo_room.yaml", "--log-dir", "/tmp/run"}));
  EXPECT_EQ(spec.processes[0].environment.at("SPDLOG_LEVEL"), "info");
}

TEST(LaunchConfig, UnsetVariableNamesTheKey)
{
  const auto root = ifar::common::ConfigNode::loadString(
      "processes:\n"
      "  - name: sim\n"
      "    command: [ifar-sim, '${WORLD}']\n",
      "test.yaml");
  try {
    ifar::launch::loadLaunchSpec(root, lookupIn({}));
    FAIL() << "an unset variable must be refused";
  } catch (const ifar::common::ConfigError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("test.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find("command"), std::string::npos) << message;
    EXPECT_NE(message.find("variable 'WORLD' is not set"), std::string::npos) << message;
  }
}

}  // namespace

TEST(LaunchConfig, AfterNamesEarlierProcessesOnly)
{
  const auto root = ifar::common::ConfigNode::loadString(
      "start_wait_s: 4\n"
      "processes:\n"
      "  - name: recorder\n"
      "    command: [ifar, record]\n"
      "  - name: planner\n"
      "    command: [ifar-planner]\n"
      "    after: [recorder]\n",
      "test.yaml");
  const auto spec = ifar::launch::loadLaunchSpec(root, lookupIn({}));
  EXPECT_EQ(spec.start_wait_s, 4.0);
  EXPECT_TRUE(spec.processes[0].after.empty());
  EXPECT_EQ(spec.processes[1].after, (std::vector<std::string>{"recorder"}));
  for (const char* after : {"[planner]", "[executive]"}) {
    const auto later = ifar::common::ConfigNode::loadString(std::string("processes:\n"
                                                                        "  - name: planner\n"
                                                                        "    command: [ifar-planner]\n"
                                                                        "    after: ") +
                                                                after +
                                                                "\n"
                                                                "  - name: executive\n"
                                                                "    command: [ifar-executive]\n",
                                                            "test.yaml");
    try {
      ifar::launch::loadLaunchSpec(later, lookupIn({}));
      FAIL() << "after " << after << " must be refused";
    } catch (const ifar::common::ConfigError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("is not a process listed before planner"), std::string::npos) << message;
      EXPECT_NE(message.find("after"), std::string::npos) << message;
    }
  }
}
