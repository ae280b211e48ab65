#include "testing/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>
#include <utility>

extern char** environ;

namespace ifar::test_support {
namespace {

/// This process's environment with `overrides` replacing or adding entries.
std::vector<std::string> childEnvironment(const std::map<std::string, std::string>& overrides)
{
  std::vector<std::string> entries;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string text = *entry;
    const std::string name = text.substr(0, text.find('='));
    if (overrides.count(name) == 0) {
      entries.push_back(text);
    }
  }
  for (const auto& [name, value] : overrides) {
    std::string entry = name;
    entry += '=';
    entry += value;
    entries.push_back(std::move(entry));
  }
  return entries;
}

std::vector<char*> pointersTo(std::vector<std::string>& texts)
{
  std::vector<char*> pointers;
  pointers.reserve(texts.size() + 1);
  for (std::string& text : texts) {
    pointers.push_back(text.data());
  }
  pointers.push_back(nullptr);
  return pointers;
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& arguments, const ChildOptions& options)
{
  if (arguments.empty()) {
    return;
  }
  std::vector<std::string> argument_texts = arguments;
  std::vector<std::string> environment = childEnvironment(options.environment);
  const std::vector<char*> argv = pointersTo(argument_texts);
  const std::vector<char*> envp = pointersTo(environment);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!options.output_path.empty()) {
    posix_spawn_file_actions_addopen(&actions, 1, options.output_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
  }
  if (!options.working_directory.empty()) {
    posix_spawn_file_actions_addchdir_np(&actions, options.working_directory.c_str());
  }
  if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), envp.data()) != 0) {
    pid_ = -1;
  }
  posix_spawn_file_actions_destroy(&actions);
}

ChildProcess::~ChildProcess()
{
  if (pid_ > 0) {
    stop(SIGTERM);
  }
}

std::optional<int> ChildProcess::waitFor(double seconds)
{
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (pid_ > 0) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      break;
    }
    if (std::chrono::steady_clock::now() >= deadline) {
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return exit_code_;
}

int ChildProcess::stop(int signal_number)
{
  if (pid_ <= 0) {
    return exit_code_.value_or(-1);
  }
  kill(pid_, signal_number);
  if (const std::optional<int> code = waitFor(5.0)) {
    return *code;
  }
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
  pid_ = -1;
  exit_code_ = -1;
  return -1;
}

int runToEnd(const std::vector<std::string>& arguments, const ChildOptions& options, double timeout_s)
{
  ChildProcess child(arguments, options);
  if (!child.started()) {
    return -1;
  }
  if (const std::optional<int> code = child.waitFor(timeout_s)) {
    return *code;
  }
  child.stop(SIGKILL);
  return -1;
}

std::string readText(const std::string& path)
{
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace ifar::test_support
