#pragma once
// Starting LCM's Java tools (lcm-spy, lcm-logplayer-gui) on Java 17 with the project's types. Debian's
// wrapper scripts pass -Xincgc, which Java 17 rejects, so the tools start their main classes directly, with
// the types jar on the class path (lcm-spy finds message types through it).

#include <string>
#include <vector>

namespace ifar::tools {

/// The jar of the project's LCM types: `requested` when not empty, else IFAR_TYPES_JAR from the
/// environment, else the build's (beside the build tree this binary came from, else where CMake put it).
std::string typesJar(const std::string& requested);

/// The command that runs `main_class` of lcm.jar with `jars` after lcm.jar on the class path, then
/// `arguments`.
std::vector<std::string> lcmJavaCommand(const std::vector<std::string>& jars, const std::string& main_class,
                                        const std::vector<std::string>& arguments);

/// Why the types jar cannot be used ("" when it exists).
std::string typesJarProblem(const std::string& jar);

}  // namespace ifar::tools
