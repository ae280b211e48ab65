#pragma once
// What a daemon's run loop handed its node core, kept in order so a log of the daemons replays the node
// exactly (ifar replay-test): which logged message each input was (channel and hash) with the receive time
// the node was given, each timer with the clock it read, each finished planner job with its stamp. The
// node's behaviour depends on nothing else the log lacks. Batches leave as node_journal_t; the recorder
// has no bus (bus/node_journal_publisher.hpp publishes them).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/span.hpp"
#include "ifar/node_journal_t.hpp"

namespace ifar::node_journal {

class JournalRecorder {
 public:
  /// `node`: "planner" or "executive"; `start_utime`: the node's clock when it was made.
  JournalRecorder(std::string node, std::int64_t start_utime, std::int32_t pid);

  /// An input message handed to the node at `utime` (the receive time it was given).
  void input(const std::string& channel, common::ByteView bytes, std::int64_t utime);
  /// A timer of the node's (its code) run at `utime`.
  void timer(std::int16_t code, std::int64_t utime);
  /// A finished planner job taken by the loop; `stamp`: the time its outputs carry.
  void jobFinished(std::int64_t stamp);
  /// The node's stop outputs at `utime`.
  void stop(std::int64_t utime);
  /// The node's own configuration as it runs (YAML), sent with the first batch.
  void setSettings(std::string yaml) { settings_ = std::move(yaml); }

  /// The events since the last batch as one message stamped `now_utime`; nothing when there are none.
  std::optional<node_journal_t> takeBatch(std::int64_t now_utime);

  std::int64_t events() const { return first_event_ + static_cast<std::int64_t>(batch_.kinds.size()); }

 private:
  void add(std::int8_t kind, std::int16_t code, std::int64_t utime, std::int32_t hash);

  node_journal_t batch_{};  // the header fields and the events not yet taken
  std::map<std::string, std::int16_t> channel_codes_;
  std::int64_t first_event_ = 0;
  std::string settings_;
};

}  // namespace ifar::node_journal
