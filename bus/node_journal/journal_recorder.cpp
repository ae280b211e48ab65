#include "bus/node_journal/journal_recorder.hpp"

#include <limits>
#include <stdexcept>
#include <utility>

#include "bus/node_journal/input_hash.hpp"

namespace ifar::node_journal {

JournalRecorder::JournalRecorder(std::string node, std::int64_t start_utime, std::int32_t pid)
{
  batch_.node = std::move(node);
  batch_.start_utime = start_utime;
  batch_.pid = pid;
}

void JournalRecorder::input(const std::string& channel, common::ByteView bytes, std::int64_t utime)
{
  auto found = channel_codes_.find(channel);
  if (found == channel_codes_.end()) {
    // A node subscribes to a handful of channels: running out of codes is a wiring bug.
    if (batch_.channels.size() >= static_cast<std::size_t>(std::numeric_limits<std::int16_t>::max())) {
      throw std::length_error("node journal: too many input channels");
    }
    found = channel_codes_.emplace(channel, static_cast<std::int16_t>(batch_.channels.size())).first;
    batch_.channels.push_back(channel);
  }
  add(node_journal_t::KIND_INPUT, found->second, utime, inputHash(bytes));
}

void JournalRecorder::timer(std::int16_t code, std::int64_t utime)
{
  add(node_journal_t::KIND_TIMER, code, utime, 0);
}

void JournalRecorder::jobFinished(std::int64_t stamp)
{
  add(node_journal_t::KIND_JOB_FINISHED, 0, stamp, 0);
}

void JournalRecorder::stop(std::int64_t utime)
{
  add(node_journal_t::KIND_STOP, 0, utime, 0);
}

void JournalRecorder::add(std::int8_t kind, std::int16_t code, std::int64_t utime, std::int32_t hash)
{
  batch_.kinds.push_back(kind);
  batch_.codes.push_back(code);
  batch_.utimes.push_back(utime);
  batch_.hashes.push_back(hash);
}

std::optional<node_journal_t> JournalRecorder::takeBatch(std::int64_t now_utime)
{
  if (batch_.kinds.empty()) {
    return std::nullopt;
  }
  node_journal_t batch = batch_;
  batch.utime = now_utime;
  batch.first_event = first_event_;
  batch.num_channels = static_cast<std::int16_t>(batch.channels.size());
  batch.num_events = static_cast<std::int32_t>(batch.kinds.size());
  batch.settings = first_event_ == 0 ? settings_ : std::string();
  first_event_ += batch.num_events;
  batch_.kinds.clear();
  batch_.codes.clear();
  batch_.utimes.clear();
  batch_.hashes.clear();
  return batch;
}

}  // namespace ifar::node_journal
