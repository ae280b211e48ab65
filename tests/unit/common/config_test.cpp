#include <gtest/gtest.h>

#include "common/config.hpp"

namespace {

using ifar::common::ConfigError;
using ifar::common::ConfigNode;

// The message of the ConfigError `body` throws, or "" when it throws nothing.
template <typename Body>
std::string errorOf(Body body)
{
  try {
    body();
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

const char* kPlanner = R"(
rate_hz: 2.5
name: planner
enabled: true
graph:
  votes: 10
  radius: 0.5
  weights: [1.0, 2.5]
layers:
  - {name: background, cell: 0.15}
  - {name: movable, cell: 0.3}
)";

TEST(Config, ReadsValuesOfEveryType)
{
  const auto root = ConfigNode::loadString(kPlanner, "planner.yaml");
  EXPECT_DOUBLE_EQ(root.required<double>("rate_hz"), 2.5);
  EXPECT_EQ(root.required<std::string>("name"), "planner");
  EXPECT_TRUE(root.required<bool>("enabled"));
  EXPECT_EQ(root.required<int>("graph.votes"), 10);
  EXPECT_EQ(root.child("graph").required<std::int64_t>("votes"), 10);
  EXPECT_EQ(root.required<std::vector<double>>("graph.weights"), (std::vector<double>{1.0, 2.5}));
  EXPECT_EQ(root.optional<int>("graph.missing", 7), 7);
  const auto layers = root.sequence("layers");
  ASSERT_EQ(layers.size(), 2U);
  EXPECT_EQ(layers[1].required<std::string>("name"), "movable");
  EXPECT_DOUBLE_EQ(layers[1].required<double>("cell"), 0.3);
}

TEST(Config, AcceptsAFileWhoseKeysWereAllRead)
{
  const auto root = ConfigNode::loadString(kPlanner, "planner.yaml");
  root.required<double>("rate_hz");
  root.required<std::string>("name");
  root.required<bool>("enabled");
  const auto graph = root.child("graph");
  graph.required<int>("votes");
  graph.required<double>("radius");
  graph.required<std::vector<double>>("weights");
  for (const auto& layer : root.sequence("layers")) {
    layer.required<std::string>("name");
    layer.required<double>("cell");
  }
  EXPECT_NO_THROW(root.rejectUnknownKeys());
}

TEST(Config, UnknownKeyNamesFileAndKey)
{
  const auto root =
      ConfigNode::loadString("rate_hz: 2.5\ngraph:\n  votes: 3\n  vots: 4\n", "config/planner.yaml");
  root.required<double>("rate_hz");
  root.child("graph").required<int>("votes");
  EXPECT_EQ(errorOf([&] { root.rejectUnknownKeys(); }),
            "config/planner.yaml: key 'graph.vots': unknown key (no setting has this name)");
}

TEST(Config, UnknownKeyInsideAListOfMaps)
{
  const auto root = ConfigNode::loadString("layers:\n  - {name: a, colour: red}\n", "w.yaml");
  root.sequence("layers")[0].required<std::string>("name");
  EXPECT_EQ(errorOf([&] { root.rejectUnknownKeys(); }),
            "w.yaml: key 'layers[0].colour': unknown key (no setting has this name)");
}

TEST(Config, MissingRequiredKeyNamesTheExpectedType)
{
  const auto root = ConfigNode::loadString("graph: {votes: 3}\n", "planner.yaml");
  EXPECT_EQ(errorOf([&] { root.required<double>("graph.radius"); }),
            "planner.yaml: key 'graph.radius': missing required key (expected number)");
}

TEST(Config, WrongTypesNameExpectationAndValue)
{
  const auto root = ConfigNode::loadString("votes: ten\nrate: [1, 2]\nflag: maybe\ncount: 2.5\n", "p.yaml");
  EXPECT_EQ(errorOf([&] { root.required<int>("votes"); }),
            "p.yaml: key 'votes': expected integer, got 'ten'");
  EXPECT_EQ(errorOf([&] { root.required<double>("rate"); }),
            "p.yaml: key 'rate': expected number, got a list");
  EXPECT_EQ(errorOf([&] { root.required<bool>("flag"); }),
            "p.yaml: key 'flag': expected boolean (true/false), got 'maybe'");
  EXPECT_EQ(errorOf([&] { root.required<int>("count"); }),
            "p.yaml: key 'count': expected integer, got '2.5'");
  EXPECT_EQ(errorOf([&] { root.optional<int>("votes", 1); }),
            "p.yaml: key 'votes': expected integer, got 'ten'");
  EXPECT_EQ(errorOf([&] { root.child("votes"); }), "p.yaml: key 'votes': expected a map, got 'ten'");
}

TEST(Config, SyntaxErrorNamesLine)
{
  const std::string message = errorOf([] { ConfigNode::loadString("a: 1\nb: [1, 2\n", "bad.yaml"); });
  EXPECT_EQ(message.rfind("bad.yaml:", 0), 0U) << message;
  EXPECT_NE(message.find("YAML syntax error"), std::string::npos) << message;
}

TEST(Config, MissingFileIsAnError)
{
  EXPECT_EQ(errorOf([] { ConfigNode::loadFile("/nonexistent/x.yaml"); }),
            "/nonexistent/x.yaml: cannot open the configuration file");
}

TEST(Config, AFolderIsNotAConfigurationFile)
{
  EXPECT_EQ(errorOf([] { ConfigNode::loadFile("/tmp"); }), "/tmp: is a folder, not a configuration file");
}

// An edit appended to a file would otherwise be ignored: lookups see the first of the two.
TEST(Config, AKeyGivenTwiceInOneMapNamesItsSecondLine)
{
  EXPECT_EQ(errorOf([] { ConfigNode::loadString("votes: 10\nname: x\nvotes: 12\n", "d.yaml"); }),
            "d.yaml:3: key 'votes': given twice in the same map");
  EXPECT_EQ(errorOf([] { ConfigNode::loadString("graph:\n  votes: 10\n  votes: 12\n", "d.yaml"); }),
            "d.yaml:3: key 'graph.votes': given twice in the same map");
  EXPECT_EQ(errorOf([] {
              ConfigNode::loadString("layers:\n  - {name: a, cell: 1}\n  - {name: b, name: c}\n", "d.yaml");
            }),
            "d.yaml:3: key 'layers[1].name': given twice in the same map");
  EXPECT_NO_THROW(ConfigNode::loadString("a:\n  votes: 1\nb:\n  votes: 2\n", "d.yaml"));
}

// Found by scripts/fuzz-files (launch_file_fuzzer): a "? " complex key got past loading, and reading the
// keys (rejectUnknownKeys, keys(), acceptAllUnder) threw yaml-cpp's bad conversion instead of a ConfigError.
TEST(Config, AListOrMapUsedAsAKeyIsAnErrorNamingItsLine)
{
  EXPECT_EQ(errorOf([] { ConfigNode::loadString("name: x\n? [a, b]\n: 1\n", "k.yaml"); }),
            "k.yaml:2: a key at the top level is a list, not a name");
  EXPECT_EQ(errorOf([] {
              ConfigNode::loadString("processes:\n  - name: a\n    ? respawn: true\n    : 2\n", "k.yaml");
            }),
            "k.yaml:3: a key under 'processes[0]' is a map, not a name");
  EXPECT_EQ(errorOf([] { ConfigNode::loadString("graph: {? {votes: 1} : 2}\n", "k.yaml"); }),
            "k.yaml:1: a key under 'graph' is a map, not a name");
}

TEST(Config, TopLevelMustBeAMap)
{
  EXPECT_EQ(errorOf([] { ConfigNode::loadString("- 1\n- 2\n", "l.yaml"); }),
            "l.yaml: the top level must be a map of settings, found a list");
}

TEST(Config, EmptyFileIsAnEmptyMap)
{
  const auto root = ConfigNode::loadString("", "empty.yaml");
  EXPECT_FALSE(root.has("anything"));
  EXPECT_NO_THROW(root.rejectUnknownKeys());
}

TEST(Config, AcceptAllUnderSkipsAFreeFormSection)
{
  const auto root = ConfigNode::loadString("name: x\nextra: {a: 1, b: [1, {c: 2}]}\n", "f.yaml");
  root.required<std::string>("name");
  root.acceptAllUnder("extra");
  EXPECT_NO_THROW(root.rejectUnknownKeys());
}

}  // namespace

namespace {

TEST(Config, PositiveNumbersAreCheckedWithKeyAndValue)
{
  const auto root = ConfigNode::loadString("rate: 2.5\nzero: 0\nnegative: -1.5\nnan: .nan\n", "r.yaml");
  EXPECT_DOUBLE_EQ(root.requiredPositive("rate"), 2.5);
  EXPECT_DOUBLE_EQ(root.optionalPositive("absent", 4.0), 4.0);
  EXPECT_EQ(errorOf([&] { root.requiredPositive("zero"); }),
            "r.yaml: key 'zero': must be greater than zero, got 0.000000");
  EXPECT_EQ(errorOf([&] { root.optionalPositive("negative", 1.0); }),
            "r.yaml: key 'negative': must be greater than zero, got -1.500000");
  EXPECT_EQ(
      errorOf([&] { root.requiredPositive("nan"); }).rfind("r.yaml: key 'nan': must be greater than zero", 0),
      0U);
}

}  // namespace

namespace ifar::common {
namespace {

/// Nine aliases of the level below, `levels` deep: 9^levels nodes once expanded, in a few hundred bytes.
std::string aliasBomb(int levels)
{
  std::string text = "a0: &a0 [x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level <= levels; ++level) {
    const std::string below = "*a" + std::to_string(level - 1);
    text += "a" + std::to_string(level) + ": &a" + std::to_string(level) + " [";
    for (int copy = 0; copy < 9; ++copy) {
      text += (copy > 0 ? ", " : "") + below;
    }
    text += "]\n";
  }
  return text;
}

TEST(ConfigAliases, AnAliasBombIsRefusedNamingTheFileInsteadOfExpanding)
{
  const std::string bomb = aliasBomb(8);
  ASSERT_LT(bomb.size(), 600U);
  try {
    ConfigNode::loadString(bomb, "bomb.yaml");
    FAIL() << "an alias bomb was accepted";
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("bomb.yaml: more than 4000000 YAML nodes"), std::string::npos)
        << error.what();
  }
}

TEST(ConfigAliases, ModestAliasesStillLoad)
{
  const ConfigNode node = ConfigNode::loadString(aliasBomb(3) + "speed: 2.5\n", "anchors.yaml");
  EXPECT_DOUBLE_EQ(node.required<double>("speed"), 2.5);
}

TEST(ConfigSet, ReplacesAValueAndMakesTheMapsOnTheWay)
{
  auto root = ConfigNode::loadString(kPlanner, "planner.yaml");
  root.set("graph.votes", "12", "--set graph.votes=12");
  root.set("graph.weights", "[3, 4.5]", "--set graph.weights=[3, 4.5]");
  root.set("lidar.port", "2400", "--set lidar.port=2400");
  EXPECT_EQ(root.required<int>("graph.votes"), 12);
  EXPECT_EQ(root.required<std::vector<double>>("graph.weights"), (std::vector<double>{3.0, 4.5}));
  EXPECT_DOUBLE_EQ(root.required<double>("graph.radius"), 0.5);  // its neighbours stay
  EXPECT_EQ(root.child("lidar").required<int>("port"), 2400);
  EXPECT_EQ(root.sequence("layers").size(), 2U);
}

TEST(ConfigSet, MessagesAboutASetKeyNameWhereItCameFrom)
{
  auto root = ConfigNode::loadString("rate_hz: 2.5\ngraph: {votes: 10, radius: 0.5}\n", "planner.yaml");
  root.set("graph.votes", "many", "--set graph.votes=many");
  EXPECT_EQ(errorOf([&] { root.child("graph").required<int>("votes"); }),
            "--set graph.votes=many: key 'graph.votes': expected integer, got 'many'");
  EXPECT_EQ(root.child("graph").describe("radius"), "planner.yaml: key 'graph.radius'");

  root.set("graph.vots", "3", "--set graph.vots=3");
  root.required<double>("rate_hz");
  root.required<double>("graph.radius");
  EXPECT_EQ(errorOf([&] { root.rejectUnknownKeys(); }),
            "--set graph.vots=3: key 'graph.vots': unknown key (no setting has this name)");
}

TEST(ConfigSet, TheClosestSetNamesAKey)
{
  auto root = ConfigNode::loadString("graph: {votes: 10}\n", "planner.yaml");
  root.set("graph", "{votes: 3, radius: 0.5}", "first");
  root.set("graph.votes", "x", "second");
  EXPECT_EQ(root.describe("graph.radius"), "first: key 'graph.radius'");
  EXPECT_EQ(root.describe("graph.votes"), "second: key 'graph.votes'");
  EXPECT_EQ(root.describe("graphs"), "planner.yaml: key 'graphs'");
}

TEST(ConfigSet, RefusesABadKeyPathOrValueNamingWhereItCameFrom)
{
  auto root = ConfigNode::loadString(kPlanner, "planner.yaml");
  EXPECT_EQ(errorOf([&] { root.set("rate_hz.max", "1", "origin"); }),
            "origin: key 'rate_hz' holds '2.5' in planner.yaml, not a map of settings");
  EXPECT_EQ(errorOf([&] { root.set("layers.cell", "1", "origin"); }),
            "origin: key 'layers' holds a list in planner.yaml, not a map of settings");
  for (const char* key : {"", "graph..votes", ".graph", "graph."}) {
    EXPECT_EQ(errorOf([&] { root.set(key, "1", "origin"); }),
              std::string("origin: '") + key + "' is not a key path (names joined by '.', e.g. lidar.port)");
  }
  EXPECT_NE(errorOf([&] { root.set("graph.votes", "[1", "origin"); }).find("origin: the value is not YAML: "),
            std::string::npos);
  EXPECT_NE(errorOf([&] { root.set("graph", "{a: 1, a: 2}", "origin"); }).find("given twice"),
            std::string::npos);
  EXPECT_EQ(root.required<int>("graph.votes"), 10);  // nothing changed
}

}  // namespace
}  // namespace ifar::common
