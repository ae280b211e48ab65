#include "bench/scenarios/forked_items.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <iostream>
#include <list>
#include <stdexcept>
#include <utility>
#include <vector>

namespace ifar::scenarios {
namespace {

using Clock = std::chrono::steady_clock;

/// Closes the descriptor it owns.
class Descriptor {
 public:
  explicit Descriptor(int descriptor = -1) : descriptor_(descriptor) {}
  Descriptor(Descriptor&& other) noexcept : descriptor_(std::exchange(other.descriptor_, -1)) {}
  Descriptor& operator=(Descriptor&& other) noexcept
  {
    if (this != &other) {
      reset();
      descriptor_ = std::exchange(other.descriptor_, -1);
    }
    return *this;
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() { reset(); }
  int get() const { return descriptor_; }
  void reset()
  {
    if (descriptor_ >= 0) {
      ::close(descriptor_);
      descriptor_ = -1;
    }
  }

 private:
  int descriptor_;
};

/// Items [first, last) still to answer.
struct Range {
  std::size_t first = 0;
  std::size_t last = 0;
};

/// A child answering a range: the item it is on is `next`.
struct Child {
  pid_t pid = -1;
  Descriptor pipe;
  std::size_t next = 0;
  std::size_t last = 0;
  Clock::time_point deadline;
  std::string received;  // bytes of answers not yet complete
};

bool writeAll(int descriptor, const std::string& bytes)
{
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t count = ::write(descriptor, bytes.data() + written, bytes.size() - written);
    if (count < 0 && errno == EINTR) {
      continue;
    }
    if (count <= 0) {
      return false;
    }
    written += static_cast<std::size_t>(count);
  }
  return true;
}

// Each answer on the pipe is its size in decimal, a newline, then its bytes.
[[noreturn]] void answerRange(int descriptor, const ForkedItems& items, Range range)
{
  for (std::size_t index = range.first; index < range.last; ++index) {
    std::string answer;
    try {
      answer = items.answer(index);
    } catch (const std::exception& error) {
      std::cerr << "item " << index << " threw: " << error.what() << "\n";
      ::_exit(4);
    } catch (...) {
      std::cerr << "item " << index << " threw a non-standard exception\n";
      ::_exit(4);
    }
    if (!writeAll(descriptor, std::to_string(answer.size()) + "\n" + answer)) {
      ::_exit(3);
    }
  }
  // _exit, not exit: the parent's buffers and atexit handlers are the parent's to flush and run.
  ::_exit(0);
}

/// Takes every complete answer off `child.received`.
std::vector<std::string> completeAnswers(Child& child)
{
  std::vector<std::string> answers;
  for (;;) {
    const std::size_t newline = child.received.find('\n');
    if (newline == std::string::npos) {
      break;
    }
    const std::size_t size = std::stoull(child.received.substr(0, newline));
    if (child.received.size() - newline - 1 < size) {
      break;
    }
    answers.push_back(child.received.substr(newline + 1, size));
    child.received.erase(0, newline + 1 + size);
  }
  return answers;
}

int reap(pid_t pid)
{
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

std::string whyNoAnswer(int status)
{
  if (WIFSIGNALED(status)) {
    const int signal_number = WTERMSIG(status);
    const char* name = ::strsignal(signal_number);
    return "crashed: signal " + std::to_string(signal_number) + " (" + (name != nullptr ? name : "unknown") +
           ")";
  }
  return "its child process exited with status " +
         std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + " without an answer";
}

ForkedOutcome failed(std::string status, std::string reason)
{
  ForkedOutcome outcome;
  outcome.status = std::move(status);
  outcome.reason = std::move(reason);
  return outcome;
}

std::string secondsText(std::chrono::milliseconds duration)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", std::chrono::duration<double>(duration).count());
  return text;
}

}  // namespace

void runForked(const ForkedItems& items)
{
  const std::size_t per_child = std::max<std::size_t>(1, items.items_per_child);
  std::deque<Range> pending;
  for (std::size_t first = 0; first < items.count; first += per_child) {
    pending.push_back({first, std::min(items.count, first + per_child)});
  }
  std::list<Child> children;
  const auto start_children = [&] {
    while (static_cast<int>(children.size()) < std::max(1, items.parallel) && !pending.empty()) {
      Range range = pending.front();
      pending.pop_front();
      while (range.first < range.last && items.skip && items.skip(range.first)) {
        items.finished(range.first, failed("skipped", "skipped"));
        ++range.first;
      }
      if (range.first == range.last) {
        continue;
      }
      int ends[2];
      if (::pipe2(ends, O_CLOEXEC) != 0) {
        items.finished(range.first,
                       failed("error", std::string("not run: no pipe: ") + std::strerror(errno)));
        pending.push_front({range.first + 1, range.last});
        continue;
      }
      Descriptor read_end(ends[0]);
      Descriptor write_end(ends[1]);
      // What is buffered now would otherwise be written twice, once by each process.
      std::cout.flush();
      std::fflush(nullptr);
      const pid_t pid = ::fork();
      if (pid < 0) {
        items.finished(range.first,
                       failed("error", std::string("not run: no child process: ") + std::strerror(errno)));
        pending.push_front({range.first + 1, range.last});
        continue;
      }
      if (pid == 0) {
        read_end.reset();
        answerRange(write_end.get(), items, range);
      }
      Child child;
      child.pid = pid;
      child.pipe = std::move(read_end);
      child.next = range.first;
      child.last = range.last;
      child.deadline = Clock::now() + items.deadline(range.first);
      children.push_back(std::move(child));
    }
  };
  // Ends `child`: the item it was on failed with `outcome`, a new child takes the rest of its range.
  const auto give_up_on = [&](std::list<Child>::iterator child, const ForkedOutcome& outcome) {
    if (child->next < child->last) {
      items.finished(child->next, outcome);
      if (child->next + 1 < child->last) {
        pending.push_front({child->next + 1, child->last});
      }
    }
    return children.erase(child);
  };

  start_children();
  while (!children.empty()) {
    std::vector<pollfd> waiting;
    Clock::time_point soonest = children.front().deadline;
    for (const Child& child : children) {
      waiting.push_back({child.pipe.get(), POLLIN, 0});
      soonest = std::min(soonest, child.deadline);
    }
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(soonest - Clock::now());
    const int timeout_ms = static_cast<int>(std::clamp<long long>(left.count(), 0, 1000));
    if (::poll(waiting.data(), waiting.size(), timeout_ms) < 0 && errno != EINTR) {
      throw std::runtime_error(std::string("waiting for child processes: ") + std::strerror(errno));
    }
    std::size_t slot = 0;
    for (auto child = children.begin(); child != children.end(); ++slot) {
      bool closed = false;
      if ((waiting[slot].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
        char buffer[65536];
        const ssize_t count = ::read(child->pipe.get(), buffer, sizeof(buffer));
        if (count > 0) {
          child->received.append(buffer, static_cast<std::size_t>(count));
        } else if (count == 0 || errno != EINTR) {
          closed = true;
        }
      }
      for (std::string& answer : completeAnswers(*child)) {
        if (child->next < child->last) {
          ForkedOutcome outcome;
          outcome.answered = true;
          outcome.answer = std::move(answer);
          items.finished(child->next, outcome);
          ++child->next;
          if (child->next < child->last) {
            child->deadline = Clock::now() + items.deadline(child->next);
          }
        }
      }
      if (closed) {
        const int status = reap(child->pid);
        child = give_up_on(child, failed("error", whyNoAnswer(status)));
        continue;
      }
      if (child->next < child->last && Clock::now() >= child->deadline) {
        ::kill(child->pid, SIGKILL);
        reap(child->pid);
        child =
            give_up_on(child, failed("timeout", "killed after " + secondsText(items.deadline(child->next)) +
                                                    " s of wall time without an answer"));
        continue;
      }
      ++child;
    }
    start_children();
  }
}

}  // namespace ifar::scenarios
