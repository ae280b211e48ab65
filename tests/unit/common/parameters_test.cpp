#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "common/config.hpp"
#include "common/parameters.hpp"

namespace {

using ifar::common::ConfigError;
using ifar::common::ConfigNode;
using ifar::common::ParameterRange;
using ifar::common::ParameterTable;
using ifar::common::Presence;

enum class Mode { Off, Gentle, Firm };

struct Limits {
  double max_linear_velocity = 0.8;
};

struct Follower {
  Limits limits;
  int samples = 5;
  std::uint8_t node_id = 1;
  bool enabled = true;
  std::string channel = "POSE";
  Mode mode = Mode::Gentle;
  double period_s = 0.005;
};

const ParameterTable<Follower>& followerTable(Presence presence)
{
  static const auto make = [](Presence wanted) {
    return ParameterTable<Follower>(wanted)
        .add(
            "limits.max_linear_velocity", [](auto& s) -> auto& { return s.limits.max_linear_velocity; },
            "m/s", ParameterRange::interval(0.0, false, 5.0, true), "top speed while following")
        .add("samples", &Follower::samples, "", ParameterRange::atLeast(1), "forward speeds tried per cycle")
        .add("node_id", &Follower::node_id, "", ParameterRange::between(1, 127), "CANopen node of the drive")
        .add("enabled", &Follower::enabled, "", ParameterRange::any(), "follow paths at all")
        .add("channel", &Follower::channel, "", ParameterRange::nonEmpty(), "where poses arrive")
        .choice(
            "mode", [](auto& s) -> auto& { return s.mode; },
            {{"off", Mode::Off}, {"gentle", Mode::Gentle}, {"firm", Mode::Firm}}, "how hard to push | pull")
        .converted<double>(
            "rate_hz", "Hz", ParameterRange::positive(), "control cycles per second",
            [](const Follower& s) { return 1.0 / s.period_s; },
            [](Follower& s, double rate) { s.period_s = 1.0 / rate; });
  };
  static const auto optional = make(Presence::optional);
  static const auto required = make(Presence::required);
  return presence == Presence::optional ? optional : required;
}

// The message of the ConfigError loading `text` throws, or "" when it loads.
std::string loadError(const std::string& text, Presence presence = Presence::optional)
{
  try {
    followerTable(presence).load(ConfigNode::loadString(text, "follower.yaml"));
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(Parameters, ReadsEveryTypeIntoItsField)
{
  const Follower follower =
      followerTable(Presence::optional)
          .load(ConfigNode::loadString("limits: {max_linear_velocity: 1.5}\nsamples: 7\n"
                                       "node_id: 9\nenabled: false\nchannel: ODOM\n"
                                       "mode: firm\nrate_hz: 50\n",
                                       "follower.yaml"));
  EXPECT_EQ(follower.limits.max_linear_velocity, 1.5);
  EXPECT_EQ(follower.samples, 7);
  EXPECT_EQ(follower.node_id, 9);
  EXPECT_FALSE(follower.enabled);
  EXPECT_EQ(follower.channel, "ODOM");
  EXPECT_EQ(follower.mode, Mode::Firm);
  EXPECT_EQ(follower.period_s, 1.0 / 50.0);
}

TEST(Parameters, AbsentOptionalKeysKeepTheStructDefaults)
{
  const Follower follower =
      followerTable(Presence::optional).load(ConfigNode::loadString("", "follower.yaml"));
  EXPECT_EQ(follower.limits.max_linear_velocity, 0.8);
  EXPECT_EQ(follower.samples, 5);
  EXPECT_EQ(follower.mode, Mode::Gentle);
  EXPECT_EQ(follower.period_s, 0.005);
}

TEST(Parameters, ARequiredTableNamesTheMissingKey)
{
  EXPECT_NE(
      loadError("samples: 3\n", Presence::required).find("follower.yaml: key 'limits.max_linear_velocity'"),
      std::string::npos);
}

TEST(Parameters, RangeErrorsNameFileKeyRangeAndValue)
{
  EXPECT_EQ(loadError("limits: {max_linear_velocity: 7}\n"),
            "follower.yaml: key 'limits.max_linear_velocity': must be in (0, 5] m/s, got 7");
  EXPECT_EQ(loadError("limits: {max_linear_velocity: 0}\n"),
            "follower.yaml: key 'limits.max_linear_velocity': must be in (0, 5] m/s, got 0");
  EXPECT_EQ(loadError("limits: {max_linear_velocity: .nan}\n"),
            "follower.yaml: key 'limits.max_linear_velocity': must be in (0, 5] m/s, got nan");
  EXPECT_EQ(loadError("samples: 0\n"), "follower.yaml: key 'samples': must be at least 1, got 0");
  EXPECT_EQ(loadError("node_id: 128\n"), "follower.yaml: key 'node_id': must be in [1, 127], got 128");
  EXPECT_EQ(loadError("channel: \"\"\n"), "follower.yaml: key 'channel': must not be empty");
  EXPECT_EQ(loadError("mode: hard\n"),
            "follower.yaml: key 'mode': must be one of off, gentle, firm, got 'hard'");
  EXPECT_EQ(loadError("rate_hz: -1\n"), "follower.yaml: key 'rate_hz': must be greater than 0 Hz, got -1");
}

TEST(Parameters, ANumberTooLargeForTheFieldIsARangeError)
{
  EXPECT_EQ(loadError("samples: 3000000000\n"),
            "follower.yaml: key 'samples': must be in [1, 2147483647], got 3000000000");
}

TEST(Parameters, TypeErrorsNameTheExpectedType)
{
  EXPECT_NE(loadError("samples: 2.5\n").find("key 'samples'"), std::string::npos);
  EXPECT_NE(loadError("samples: 2.5\n").find("integer"), std::string::npos);
  EXPECT_NE(loadError("enabled: maybe\n").find("boolean"), std::string::npos);
  EXPECT_NE(loadError("limits: {max_linear_velocity: fast}\n").find("number"), std::string::npos);
}

TEST(Parameters, UnknownKeysAreRejected)
{
  EXPECT_NE(
      loadError("limits: {max_linear_velocity: 1, max_turn: 2}\n").find("'limits.max_turn': unknown key"),
      std::string::npos);
}

TEST(Parameters, MarkdownTableHasEveryColumn)
{
  EXPECT_EQ(followerTable(Presence::optional).markdown(),
            "| Key | Type | Unit | Default | Range | Meaning |\n"
            "| --- | --- | --- | --- | --- | --- |\n"
            "| `limits.max_linear_velocity` | real | m/s | `0.8` | (0, 5] | top speed while following |\n"
            "| `samples` | integer |  | `5` | >= 1 | forward speeds tried per cycle |\n"
            "| `node_id` | integer |  | `1` | [1, 127] | CANopen node of the drive |\n"
            "| `enabled` | boolean |  | `true` |  | follow paths at all |\n"
            "| `channel` | text |  | `\"POSE\"` | not empty | where poses arrive |\n"
            "| `mode` | choice |  | `gentle` | `off`, `gentle`, `firm` | how hard to push \\| pull |\n"
            "| `rate_hz` | real | Hz | `200.0` | > 0 | control cycles per second |\n");
  EXPECT_NE(followerTable(Presence::required).markdown().find("| real | m/s | required | (0, 5] |"),
            std::string::npos);
}

TEST(Parameters, YamlDumpNestsKeysAndCommentsMeanings)
{
  Follower follower;
  follower.limits.max_linear_velocity = 1e-5;
  EXPECT_EQ(followerTable(Presence::optional).yaml(follower, "follower"),
            "follower:\n"
            "  limits:\n"
            "    max_linear_velocity: 1.0e-05  # top speed while following [m/s]\n"
            "  samples: 5  # forward speeds tried per cycle\n"
            "  node_id: 1  # CANopen node of the drive\n"
            "  enabled: true  # follow paths at all\n"
            "  channel: \"POSE\"  # where poses arrive\n"
            "  mode: gentle  # how hard to push | pull\n"
            "  rate_hz: 200.0  # control cycles per second [Hz]\n");
}

TEST(Parameters, YamlDumpReadsBackToTheSameSettings)
{
  Follower follower;
  follower.limits.max_linear_velocity = 0.15;
  follower.channel = "a \"quoted\" name";
  const Follower again =
      followerTable(Presence::required)
          .load(ConfigNode::loadString(followerTable(Presence::optional).yaml(follower), "dump"));
  EXPECT_EQ(again.limits.max_linear_velocity, 0.15);
  EXPECT_EQ(again.channel, follower.channel);
  EXPECT_EQ(again.period_s, follower.period_s);
}

TEST(Parameters, ADumpWritesAMapTwoTablesShareOnce)
{
  ifar::common::ConfigDump dump;
  dump.note("the follower");
  dump.add("follower.samples", "5", "");
  dump.add("rate_hz", "2.5", "updates");
  dump.add("follower.enabled", "true", "on");
  EXPECT_EQ(dump.yaml(),
            "# the follower\nfollower:\n  samples: 5\n  enabled: true  # on\nrate_hz: 2.5  # updates\n");
}

TEST(Parameters, NumbersAreWrittenAsShortAsTheyReadBack)
{
  EXPECT_EQ(ifar::common::formatNumber(0.15), "0.15");
  EXPECT_EQ(ifar::common::formatNumber(200.0), "200");
  EXPECT_EQ(ifar::common::formatNumber(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(ifar::common::formatNumber(4194304.0), "4194304");
}

}  // namespace
