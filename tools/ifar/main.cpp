// ifar: the operator's command. Built-in subcommands start the LCM tools with the project's settings;
// `ifar NAME ...` runs the executable ifar-NAME beside this one (sim, render, plan, ... each component
// ships its own), so components add subcommands without touching this file.

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "tools/ifar/process.hpp"

namespace {

using ifar::tools::executableDirectory;
using ifar::tools::externalSubcommands;
using ifar::tools::findProgram;
using ifar::tools::replaceProcess;

const char* kBuiltIns[] = {"spy", "record", "replay"};

std::string externalList()
{
  std::string text = "\nComponent subcommands (ifar NAME --help for each):\n";
  for (const auto& name : externalSubcommands(executableDirectory())) {
    text += "  " + name + "\n";
  }
  return text;
}

int fail(const std::string& message)
{
  std::cerr << "ifar: error: " << message << std::endl;
  return 1;
}

void useLcmUrl(const std::string& url)
{
  if (!url.empty()) {
    setenv("LCM_DEFAULT_URL", url.c_str(), 1);
  }
}

std::string typesJar(const std::string& requested)
{
  if (!requested.empty()) {
    return requested;
  }
  const char* environment = std::getenv("IFAR_TYPES_JAR");
  if (environment != nullptr && *environment != '\0') {
    return environment;
  }
  // Beside the build tree this binary came from, else where CMake put it.
  const auto sibling = std::filesystem::path(executableDirectory()) / ".." / "lcmtypes" / "ifar_lcmtypes.jar";
  return std::filesystem::exists(sibling) ? sibling.lexically_normal().string() : std::string(IFAR_TYPES_JAR);
}

int runSpy(const std::string& jar_override, const std::string& url)
{
  const std::string jar = typesJar(jar_override);
  if (!std::filesystem::exists(jar)) {
    return fail("the project's LCM types jar '" + jar +
                "' does not exist: build the project first (scripts/setup)");
  }
  const std::string chart_jar = "/usr/share/java/jchart2d.jar";
  if (!std::filesystem::exists(chart_jar)) {
    return fail(chart_jar + " is missing: install libjchart2d-java (scripts/setup does)");
  }
  useLcmUrl(url);
  // /usr/bin/lcm-spy passes -Xincgc, which Java 17 rejects; start the Spy class directly.
  const std::string class_path = std::string(IFAR_LCM_JAR) + ":" + chart_jar + ":" + jar;
  std::cerr << "ifar spy: lcm-spy with the project's types from " << jar << std::endl;
  return fail(replaceProcess({"java", "-Djava.net.preferIPv4Stack=true", "-cp", class_path, "lcm.spy.Spy"}));
}

int runRecord(const std::string& directory, const std::string& name_pattern, double split_mb, int rotate,
              const std::string& channels, const std::string& url)
{
  if (findProgram("lcm-logger").empty()) {
    return fail("lcm-logger is not installed: install liblcm-bin (scripts/setup does)");
  }
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    return fail("cannot create the log folder '" + directory + "': " + error.message());
  }
  useLcmUrl(url);
  const std::string file = (std::filesystem::path(directory) / name_pattern).string();
  std::vector<std::string> arguments = {"lcm-logger", "--strftime", "--channel=" + channels};
  if (rotate > 0) {
    // Always writes FILE.0, renaming older files out of the way and deleting the oldest.
    arguments.push_back("--rotate=" + std::to_string(rotate));
  } else {
    // The short form: lcm-logger 1.3.1's long --increment takes an argument, so it swallowed the file
    // name when it came last (with --split-mb 0) and the log went to ./lcmlog-DATE.00.
    arguments.push_back("-i");
  }
  if (split_mb > 0.0) {
    arguments.push_back("--split-mb=" + std::to_string(split_mb));
  }
  arguments.push_back(file);
  std::cerr << "ifar record: logging channels '" << channels << "' to " << file
            << (rotate > 0 ? " (rotating " + std::to_string(rotate) + " files)" : std::string(" (numbered)"))
            << "; stop with Ctrl-C" << std::endl;
  return fail(replaceProcess(arguments));
}

int runReplay(const std::string& log, double speed, const std::string& channels, const std::string& url)
{
  if (!std::filesystem::is_regular_file(log)) {
    return fail("log file '" + log + "' does not exist or is not a file");
  }
  if (findProgram("lcm-logplayer").empty()) {
    return fail("lcm-logplayer is not installed: install liblcm-bin (scripts/setup does)");
  }
  useLcmUrl(url);
  std::vector<std::string> arguments = {"lcm-logplayer", "--speed=" + std::to_string(speed)};
  if (!channels.empty()) {
    arguments.push_back("--regexp=" + channels);
  }
  arguments.push_back(log);
  return fail(replaceProcess(arguments));
}

}  // namespace

int main(int argc, char** argv)
{
  // A subcommand that is not built in belongs to a component: hand over to ifar-NAME.
  if (argc >= 2 && argv[1][0] != '-') {
    const std::string name = argv[1];
    bool built_in = false;
    for (const char* candidate : kBuiltIns) {
      built_in = built_in || name == candidate;
    }
    if (!built_in) {
      const std::string program = executableDirectory() + "/ifar-" + name;
      if (findProgram(program).empty()) {
        std::cerr << "ifar: unknown subcommand '" << name << "'" << externalList();
        return 2;
      }
      std::vector<std::string> arguments = {program};
      arguments.insert(arguments.end(), argv + 2, argv + argc);
      return fail(replaceProcess(arguments));
    }
  }

  CLI::App app{"ifar: navigation among movable obstacles on LCM. Built-in subcommands wrap the LCM tools."};
  app.footer(externalList());
  app.require_subcommand(1);

  std::string url;
  std::string jar;
  auto* spy = app.add_subcommand("spy", "lcm-spy with the project's message types (Java 17)");
  spy->add_option("--types-jar", jar, "jar of the project's LCM types (default: the build's)");
  spy->add_option("--lcm-url", url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");

  std::string directory = "logs";
  std::string name_pattern = "ifar-%Y-%m-%d-%H%M%S.lcmlog";
  double split_mb = 512.0;
  int rotate = 0;
  std::string channels = ".*";
  auto* record = app.add_subcommand("record", "lcm-logger into logs/ with a timestamped name and splitting");
  record->add_option("--dir", directory, "folder for the logs")->capture_default_str();
  record->add_option("--name", name_pattern, "file name, strftime-formatted")->capture_default_str();
  record->add_option("--split-mb", split_mb, "start a new numbered file after this many MB (0 = never)")
      ->check(ifar::common::atLeast(0))
      ->capture_default_str();
  record
      ->add_option("--rotate", rotate,
                   "keep only this many files, newest as NAME.0 (0 = number them instead)")
      ->check(ifar::common::atLeast(0))
      ->capture_default_str();
  record->add_option("--channels", channels, "regular expression of channels to record")
      ->capture_default_str();
  record->add_option("--lcm-url", url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");

  std::string log;
  double speed = 1.0;
  std::string replay_channels;
  auto* replay = app.add_subcommand("replay", "lcm-logplayer: publish a recorded log onto LCM again");
  replay->add_option("log", log, "the .lcmlog file")->required();
  replay->add_option("--speed", speed, "playback speed multiplier (0 = as fast as possible)")
      ->check(ifar::common::atLeast(0))
      ->capture_default_str();
  replay->add_option("--channels", replay_channels, "regular expression of channels to play (default all)");
  replay->add_option("--lcm-url", url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");

  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  if (spy->parsed()) {
    return runSpy(jar, url);
  }
  if (record->parsed()) {
    return runRecord(directory, name_pattern, split_mb, rotate, channels, url);
  }
  return runReplay(log, speed, replay_channels, url);
}
