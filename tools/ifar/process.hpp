#pragma once
// Running other programs from the ifar commands: replacing the current process (so signals such as Ctrl-C
// reach the program directly), finding programs and the subcommands beside ifar, and naming how one ended.

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

/// The first line `command` prints on stdout (stdin and stderr closed off), waited for at most `timeout_ms`
/// (then it is killed); "" when it prints none, cannot start or takes too long.
std::string firstOutputLine(const std::vector<std::string>& command, int timeout_ms);

/// A wait() status in words: "exited with code 1", "killed by signal 9 (Killed)".
std::string describeExitStatus(int status);

}  // namespace ifar::tools
