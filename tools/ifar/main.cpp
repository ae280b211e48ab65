// ifar: the operator's command. `ifar spy` starts lcm-spy with the project's types; `ifar NAME ...` runs the
// executable ifar-NAME beside this one (record, replay, echo, sim, render, plan, ... each component ships
// its own), so components add subcommands without touching this file.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "tools/ifar/lcm_java.hpp"
#include "tools/ifar/process.hpp"
#include "tools/ifar/version.hpp"

namespace {

using ifar::tools::executableDirectory;
using ifar::tools::externalSubcommands;
using ifar::tools::findProgram;
using ifar::tools::replaceProcess;

const char* kBuiltIns[] = {"spy"};

/// Every ifar-NAME beside this program with the first sentence of its description (`--describe`).
std::string externalList()
{
  std::string text = "\nComponent subcommands (ifar NAME --help for each):\n";
  const std::string directory = executableDirectory();
  for (const auto& name : externalSubcommands(directory)) {
    std::string program = directory;
    program += "/ifar-";
    program += name;
    const std::string description = ifar::tools::firstOutputLine({program, "--describe"}, 2000);
    std::string line = "  " + name;
    line.resize(std::max<std::size_t>(line.size() + 1, 20), ' ');
    text += line;
    text += description + "\n";
  }
  return text;
}

int fail(const std::string& message)
{
  std::cerr << "ifar: error: " << message << '\n';
  return 1;
}

int runSpy(const std::string& jar_override, const std::string& url)
{
  const std::string jar = ifar::tools::typesJar(jar_override);
  if (const std::string problem = ifar::tools::typesJarProblem(jar); !problem.empty()) {
    return fail(problem);
  }
  const std::string chart_jar = "/usr/share/java/jchart2d.jar";
  if (!std::filesystem::exists(chart_jar)) {
    return fail(chart_jar + " is missing: install libjchart2d-java (scripts/setup does)");
  }
  if (!url.empty()) {
    setenv("LCM_DEFAULT_URL", url.c_str(), 1);
  }
  std::cerr << "ifar spy: lcm-spy with the project's types from " << jar << '\n';
  return fail(replaceProcess(ifar::tools::lcmJavaCommand({chart_jar, jar}, "lcm.spy.Spy", {})));
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

  CLI::App app{
      "ifar: navigation among movable obstacles on LCM. `ifar spy` is built in; the others are "
      "the ifar-NAME programs beside this one."};
  app.footer(externalList);
  app.set_version_flag("--version", std::string("ifar ") + ifar::tools::projectVersion() + " (commit " +
                                        ifar::tools::gitCommit() + ")");
  app.require_subcommand(1);

  std::string url;
  std::string jar;
  auto* spy = app.add_subcommand("spy", "lcm-spy with the project's message types (Java 17)");
  spy->add_option("--types-jar", jar, "jar of the project's LCM types (default: the build's)");
  spy->add_option("--lcm-url", url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");

  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  return runSpy(jar, url);
}
