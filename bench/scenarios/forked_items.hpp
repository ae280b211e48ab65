#pragma once
// Items of work (planner queries, runner runs) answered in child processes, so that one that crashes
// (a segfault or an abort in a third-party planner) or hangs costs its own row, recorded with the
// reason, and never the rest of the suite.
//
// A child answers a run of consecutive items, so a planner's caches and heap stay warm from one query to
// the next as they would in one process; when it dies, the item it was on is recorded as failed and a new
// child goes on with the next.

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace ifar::scenarios {

/// How an item ended.
struct ForkedOutcome {
  bool answered = false;
  std::string answer;  ///< what the child's `answer` returned, when answered
  /// When not answered: "error" (crashed, exited or could not start), "timeout" (killed at the
  /// deadline) or "skipped" (`skip` said so), and why, e.g. "crashed: signal 11 (Segmentation fault)".
  std::string status;
  std::string reason;
};

struct ForkedItems {
  std::size_t count = 0;
  int parallel = 1;                 ///< children at once (at least 1)
  std::size_t items_per_child = 1;  ///< consecutive items one child answers (at least 1)
  /// Runs in a child: item i's answer. What it throws ends the child (status "error").
  std::function<std::string(std::size_t)> answer;
  /// Wall time item i may take, from the child's start or its previous answer; then it is killed.
  std::function<std::chrono::milliseconds(std::size_t)> deadline;
  /// Runs in the parent before a child starts on item i: true leaves item i out. May be empty.
  std::function<bool(std::size_t)> skip;
  /// Runs in the parent as each item ends, in the order they end.
  std::function<void(std::size_t, const ForkedOutcome&)> finished;
};

/// Answers every item and returns when each has been passed to `finished`. Call it while the process
/// has one thread: a child forked from a threaded process may inherit a lock another thread held.
void runForked(const ForkedItems& items);

}  // namespace ifar::scenarios
