#pragma once
// Replacing the current process with another program, so signals (Ctrl-C) reach it directly.

#include <string>
#include <vector>

namespace ifar::tools {

/// The folder holding the running executable (resolved through /proc/self/exe).
std::string executableDirectory();

/// execvp(arguments[0], arguments). Returns only on failure, with a message naming the program.
std::string replaceProcess(const std::vector<std::string>& arguments);

/// Names NAME of the executables ifar-NAME in `directory`, sorted.
std::vector<std::string> externalSubcommands(const std::string& directory);

/// `command` found on PATH (or as given when it contains a slash and exists); "" when not found.
std::string findProgram(const std::string& command);

}  // namespace ifar::tools
