#include "tools/ifar/process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace ifar::tools {

std::string executableDirectory()
{
  std::error_code error;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::string(".") : self.parent_path().string();
}

std::string replaceProcess(const std::vector<std::string>& arguments)
{
  std::vector<char*> argv;
  argv.reserve(arguments.size() + 1);
  for (const auto& argument : arguments) {
    argv.push_back(const_cast<char*>(argument.c_str()));  // execvp's signature predates const
  }
  argv.push_back(nullptr);
  execvp(argv[0], argv.data());
  return "cannot run '" + arguments.front() + "': " + std::strerror(errno);
}

std::vector<std::string> externalSubcommands(const std::string& directory)
{
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    const std::string file = entry.path().filename().string();
    if (file.rfind("ifar-", 0) == 0 && entry.is_regular_file() && access(entry.path().c_str(), X_OK) == 0) {
      names.push_back(file.substr(5));
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string findProgram(const std::string& command)
{
  if (command.find('/') != std::string::npos) {
    return access(command.c_str(), X_OK) == 0 ? command : std::string();
  }
  const char* path = std::getenv("PATH");
  std::stringstream folders(path != nullptr ? path : "/usr/bin:/bin");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    std::string candidate = (folder.empty() ? std::string(".") : folder) + "/" + command;
    if (access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
  }
  return "";
}

std::string firstOutputLine(const std::vector<std::string>& command, int timeout_ms)
{
  int pipe_ends[2];
  if (pipe2(pipe_ends, O_CLOEXEC) != 0) {
    return "";
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  std::vector<char*> argv;
  argv.reserve(command.size() + 1);
  for (const auto& argument : command) {
    argv.push_back(const_cast<char*>(argument.c_str()));  // posix_spawn's signature predates const
  }
  argv.push_back(nullptr);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[1]);
  std::string output;
  if (spawned == 0) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
    char buffer[256];
    while (output.find('\n') == std::string::npos) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      pollfd readable{pipe_ends[0], POLLIN, 0};
      if (left.count() <= 0 || poll(&readable, 1, static_cast<int>(left.count())) <= 0) {
        break;
      }
      const ssize_t count = read(pipe_ends[0], buffer, sizeof(buffer));
      if (count <= 0) {
        break;
      }
      output.append(buffer, static_cast<std::size_t>(count));
    }
    kill(child, SIGKILL);  // done with it, whether it has finished or not
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
  }
  close(pipe_ends[0]);
  return output.substr(0, output.find('\n'));
}

std::string describeExitStatus(int status)
{
  if (WIFEXITED(status)) {
    return "exited with code " + std::to_string(WEXITSTATUS(status));
  }
  if (WIFSIGNALED(status)) {
    return std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
           strsignal(WTERMSIG(status)) + ")";
  }
  return "stopped";
}

}  // namespace ifar::tools
