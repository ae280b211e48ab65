#pragma once
// A daemon's journal on the bus: every input the run loop hands the node (node_journal::JournalRecorder
// says why), batches published at 4 Hz and the rest when it goes, so the recorder's log of the daemons
// replays each node exactly (ifar replay-test, docs/record_replay.md).

#include <cstdint>
#include <functional>
#include <set>
#include <string>

#include "bus/node_journal/journal_recorder.hpp"
#include "bus/run_loop.hpp"

namespace ifar::bus {

class NodeJournalPublisher {
 public:
  /// Journals what `loop` (which must outlive this object) delivers on the node's `inputs` from now on,
  /// on `channel` as `node` started at `start_utime` (the loop's other subscriptions, such as the
  /// duplicate-process watch, are not the node's). `before_input` runs before each input is journaled and
  /// handed over (the planner takes its worker's finished jobs there, so they come first in the journal as
  /// in the node).
  NodeJournalPublisher(RunLoop& loop, std::string channel, std::string node, std::int64_t start_utime,
                       std::set<std::string> inputs, std::function<void()> before_input = {});
  ~NodeJournalPublisher();
  NodeJournalPublisher(const NodeJournalPublisher&) = delete;
  NodeJournalPublisher& operator=(const NodeJournalPublisher&) = delete;

  node_journal::JournalRecorder& recorder() { return recorder_; }
  /// Publishes the events not yet published.
  void flush();

 private:
  RunLoop& loop_;
  std::string channel_;
  node_journal::JournalRecorder recorder_;
};

}  // namespace ifar::bus
