#include "tools/ifar/lcm_java.hpp"

#include <cstdlib>
#include <filesystem>

#include "tools/ifar/process.hpp"

namespace ifar::tools {

std::string typesJar(const std::string& requested)
{
  if (!requested.empty()) {
    return requested;
  }
  const char* environment = std::getenv("IFAR_TYPES_JAR");
  if (environment != nullptr && *environment != '\0') {
    return environment;
  }
  // Beside the program: build/lcmtypes in a build tree, share/java in an install; else the build's own.
  const std::filesystem::path programs(executableDirectory());
  for (const auto& sibling : {programs / ".." / "lcmtypes" / "ifar_lcmtypes.jar",
                              programs / ".." / "share" / "java" / "ifar_lcmtypes.jar"}) {
    if (std::filesystem::exists(sibling)) {
      return sibling.lexically_normal().string();
    }
  }
  return IFAR_TYPES_JAR;
}

std::string typesJarProblem(const std::string& jar)
{
  if (std::filesystem::exists(jar)) {
    return "";
  }
  return "the project's LCM types jar '" + jar + "' does not exist: build the project first (scripts/setup)";
}

std::vector<std::string> lcmJavaCommand(const std::vector<std::string>& jars, const std::string& main_class,
                                        const std::vector<std::string>& arguments)
{
  std::string class_path = IFAR_LCM_JAR;
  for (const auto& jar : jars) {
    class_path += ":" + jar;
  }
  std::vector<std::string> command = {"java", "-Djava.net.preferIPv4Stack=true", "-cp", class_path,
                                      main_class};
  command.insert(command.end(), arguments.begin(), arguments.end());
  return command;
}

}  // namespace ifar::tools
