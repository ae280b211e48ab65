#include "common/config_search.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/config.hpp"
#include "testing/temporary_directory.hpp"

namespace ifar::common {
namespace {

namespace fs = std::filesystem;

const std::string kCheckout = std::string(IFAR_SOURCE_DIR) + "/config";

void writeFile(const fs::path& path, const std::string& text = "a: 1\n")
{
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

/// The environment the search path reads, set for one test: IFAR_CONFIG_DIR and HOME point into a
/// private folder (XDG_CONFIG_HOME unset), and are put back afterwards.
class ConfigSearchTest : public ::testing::Test {
 protected:
  void SetUp() override
  {
    ASSERT_FALSE(folder_.path().empty());
    for (const char* name : {kConfigDirectoryVariable, "HOME", "XDG_CONFIG_HOME"}) {
      const char* value = std::getenv(name);
      saved_.emplace_back(name, value ? std::optional<std::string>(value) : std::nullopt);
    }
    environment_ = folder_.path() / "etc";
    home_ = folder_.path() / "home";
    fs::create_directories(environment_);
    fs::create_directories(home_ / ".config" / "ifar");
    setenv(kConfigDirectoryVariable, environment_.c_str(), 1);
    setenv("HOME", home_.c_str(), 1);
    unsetenv("XDG_CONFIG_HOME");
  }
  void TearDown() override
  {
    for (const auto& [name, value] : saved_) {
      if (value) {
        setenv(name.c_str(), value->c_str(), 1);
      } else {
        unsetenv(name.c_str());
      }
    }
  }
  fs::path userFolder() const { return home_ / ".config" / "ifar"; }

  test_support::TemporaryDirectory folder_{"config-search"};
  fs::path environment_;
  fs::path home_;
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

TEST_F(ConfigSearchTest, StandardOrderIsEnvironmentUserThenCheckout)
{
  const ConfigSearchPath search = ConfigSearchPath::standard();
  // The test program lives in build/tests: no share/ifar beside it, so no install folder.
  ASSERT_EQ(search.folders().size(), 3u);
  EXPECT_EQ(search.folders()[0].path, environment_.string());
  EXPECT_EQ(search.folders()[0].origin, "IFAR_CONFIG_DIR");
  EXPECT_EQ(search.folders()[1].path, userFolder().string());
  EXPECT_EQ(search.folders()[1].origin, "user folder");
  EXPECT_EQ(search.folders()[2].path, kCheckout);
  EXPECT_EQ(search.folders()[2].origin, "checkout");
}

TEST_F(ConfigSearchTest, XdgConfigHomeReplacesDotConfigAndMissingFoldersAreSkipped)
{
  setenv("XDG_CONFIG_HOME", (folder_.path() / "xdg").c_str(), 1);  // no ifar/ under it
  fs::remove_all(environment_);
  const ConfigSearchPath search = ConfigSearchPath::standard();
  ASSERT_EQ(search.folders().size(), 1u);
  EXPECT_EQ(search.folders()[0].origin, "checkout");
  fs::create_directories(folder_.path() / "xdg" / "ifar");
  EXPECT_EQ(ConfigSearchPath::standard().folders()[0].path, (folder_.path() / "xdg" / "ifar").string());
}

TEST_F(ConfigSearchTest, FirstFolderHoldingTheFileWinsFileByFile)
{
  writeFile(userFolder() / "planner.yaml");
  writeFile(environment_ / "can.yaml");
  const ConfigSearchPath search = ConfigSearchPath::standard();
  EXPECT_EQ(search.locate("can.yaml").path, (environment_ / "can.yaml").string());
  EXPECT_EQ(search.locate("can.yaml").origin, "IFAR_CONFIG_DIR");
  EXPECT_EQ(search.locate("planner.yaml").path, (userFolder() / "planner.yaml").string());
  EXPECT_EQ(search.locate("planner.yaml").origin, "user folder");
  EXPECT_EQ(search.locate("vehicle.yaml").path, kCheckout + "/vehicle.yaml");
  EXPECT_EQ(search.locate("worlds/demo_room.yaml").path, kCheckout + "/worlds/demo_room.yaml");
  const fs::path first = folder_.path() / "first";
  writeFile(first / "can.yaml");
  EXPECT_EQ(search.withFirst(first.string(), "--config-dir").locate("can.yaml").origin, "--config-dir");
}

TEST_F(ConfigSearchTest, NotFoundNamesEveryFolderLookedIn)
{
  try {
    ConfigSearchPath::standard().locate("nothing.yaml");
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()), "nothing.yaml: not found in " + environment_.string() +
                                             " (IFAR_CONFIG_DIR), " + userFolder().string() +
                                             " (user folder), " + kCheckout + " (checkout)");
  }
}

TEST_F(ConfigSearchTest, CommandLineFileIsUsedAsGivenElseSearched)
{
  const fs::path mine = folder_.path() / "mine.yaml";
  writeFile(mine);
  EXPECT_EQ(resolveConfigFile(mine.string(), "planner.yaml").path, mine.string());
  EXPECT_EQ(resolveConfigFile(mine.string(), "planner.yaml").origin, "command line");
  EXPECT_EQ(resolveConfigFile("", "planner.yaml").path, kCheckout + "/planner.yaml");
  // Relative and not here: a name on the search path (a launch file's --config onboard/can.yaml).
  EXPECT_EQ(resolveConfigFile("onboard/can.yaml", "can.yaml").path, kCheckout + "/onboard/can.yaml");
  // An absolute path that does not exist is left for loadFile to name.
  EXPECT_EQ(resolveConfigFile("/nonexistent/x.yaml", "can.yaml").path, "/nonexistent/x.yaml");
  EXPECT_THROW(resolveConfigFile("nowhere/x.yaml", "can.yaml"), ConfigError);
}

TEST_F(ConfigSearchTest, ReferencedFileIsBesideTheReferrerElseOnThePath)
{
  const fs::path referrer = folder_.path() / "mine" / "planner.yaml";
  writeFile(referrer);
  EXPECT_EQ(resolveReferencedFile("vehicle.yaml", referrer.string()).path, kCheckout + "/vehicle.yaml");
  writeFile(folder_.path() / "mine" / "vehicle.yaml");
  const FoundConfig beside = resolveReferencedFile("vehicle.yaml", referrer.string());
  EXPECT_EQ(beside.path, (folder_.path() / "mine" / "vehicle.yaml").string());
  EXPECT_EQ(beside.origin, "beside " + referrer.string());
  EXPECT_EQ(resolveReferencedFile("/abs/vehicle.yaml", referrer.string()).path, "/abs/vehicle.yaml");
  try {
    resolveReferencedFile("other.yaml", referrer.string());
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(
                  referrer.string() + ": other.yaml: not found in " + (folder_.path() / "mine").string(), 0),
              0u)
        << message;
  }
}

TEST_F(ConfigSearchTest, NamedInputsAreFilesOrNamesInTheirFolder)
{
  EXPECT_EQ(findNamedInput("demo_room", "worlds")->path, kCheckout + "/worlds/demo_room.yaml");
  EXPECT_EQ(findNamedInput("demo_room.yaml", "worlds")->path, kCheckout + "/worlds/demo_room.yaml");
  EXPECT_EQ(findNamedInput("vehicle", "launch")->path, kCheckout + "/launch/vehicle.yaml");
  writeFile(environment_ / "worlds" / "demo_room.yaml");
  EXPECT_EQ(findNamedInput("demo_room", "worlds")->origin, "IFAR_CONFIG_DIR");
  const fs::path file = folder_.path() / "room.yaml";
  writeFile(file);
  EXPECT_EQ(findNamedInput(file.string(), "worlds")->origin, "command line");
  EXPECT_FALSE(findNamedInput("castle", "worlds").has_value());
  EXPECT_FALSE(findNamedInput("/nonexistent/demo_room", "worlds").has_value());
}

TEST(ConfigSearchDescription, GroupsFilesByFolder)
{
  EXPECT_EQ(
      describeFiles({{"/etc/ifar/can.yaml", "IFAR_CONFIG_DIR"},
                     {"/usr/share/ifar/vehicle.yaml", "install"},
                     {"/usr/share/ifar/planner.yaml", "install"}}),
      "can.yaml from /etc/ifar (IFAR_CONFIG_DIR); vehicle.yaml, planner.yaml from /usr/share/ifar (install)");
  EXPECT_EQ(describeFiles({}), "");
}

}  // namespace
}  // namespace ifar::common
