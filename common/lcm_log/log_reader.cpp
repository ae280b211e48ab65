#include "common/lcm_log/log_reader.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "common/byte_order.hpp"

namespace ifar::lcm_log {
namespace {

using common::readUint32Be;
using common::readUint64Be;

// Garbage is scanned in pieces this big: small enough to stay in cache, large enough for few reads.
constexpr std::size_t kScanChunkSize = std::size_t{64} * 1024U;

std::string hex32(std::uint32_t value)
{
  std::array<char, 16> text{};
  std::snprintf(text.data(), text.size(), "0x%08X", static_cast<unsigned int>(value));
  return text.data();
}

std::string plural(std::uint64_t count, const char* noun)
{
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

}  // namespace

const char* toString(LogProblemKind kind)
{
  switch (kind) {
    case LogProblemKind::kBadSyncWord:
      return "bad sync word";
    case LogProblemKind::kTruncatedHeader:
      return "truncated event header";
    case LogProblemKind::kTruncatedEvent:
      return "truncated event";
    case LogProblemKind::kBadChannelLength:
      return "channel length out of range";
    case LogProblemKind::kBadDataLength:
      return "negative data length";
    case LogProblemKind::kReadError:
      return "read error";
  }
  return "unknown log problem";
}

LogReader LogReader::open(const std::string& path)
{
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    return LogReader("'" + path + "' is a directory, not an LCM log");
  }
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!file->is_open()) {
    return LogReader("cannot open '" + path + "': " + std::strerror(errno));
  }
  LogReader reader(std::move(file));
  if (!reader.open_error_.empty()) {
    reader.open_error_ = "'" + path + "': " + reader.open_error_;
  }
  return reader;
}

LogReader::LogReader(std::unique_ptr<std::istream> stream) : stream_(std::move(stream))
{
  // Every claimed length is checked against the bytes left, so the size must be known up front. A log
  // that lcm-logger is still writing is read up to its size at this moment.
  if (!stream_ || !stream_->seekg(0, std::ios::end)) {
    open_error_ = "cannot find the size of the log (not a seekable file)";
    return;
  }
  const std::streamoff size = stream_->tellg();
  if (size < 0 || !stream_->seekg(0, std::ios::beg)) {
    open_error_ = "cannot find the size of the log (not a seekable file)";
    return;
  }
  file_size_ = static_cast<std::uint64_t>(size);
}

bool LogReader::next(LogEvent& event)
{
  while (!finished_ && open_error_.empty()) {
    const std::uint64_t remaining = file_size_ - position_;
    if (remaining == 0) {
      finished_ = true;
      break;
    }
    const std::uint64_t start = position_;
    std::array<std::uint8_t, kHeaderSize> header{};
    const std::uint64_t header_bytes = std::min<std::uint64_t>(remaining, kHeaderSize);
    if (!readBytes(header.data(), header_bytes)) {
      break;
    }
    if (header_bytes < 4) {
      // Too short for a sync word: the start of a header cut off by the end of the file, or garbage.
      constexpr std::array<std::uint8_t, 4> kSyncBytes = {0xED, 0xA1, 0xDA, 0x01};
      const bool cut_header = std::equal(header.begin(), header.begin() + header_bytes, kSyncBytes.begin());
      addProblem(cut_header ? LogProblemKind::kTruncatedHeader : LogProblemKind::kBadSyncWord, start,
                 "byte " + std::to_string(start) + ": " + plural(remaining, "byte") +
                     " at the end of the file, too few for an event header; skipped");
      skipped_bytes_ += remaining;
      finished_ = true;
      break;
    }
    const std::uint32_t sync_word = readUint32Be(header.data());
    if (sync_word != kSyncWord) {
      skipToNextSyncWord(start, LogProblemKind::kBadSyncWord, "bad sync word " + hex32(sync_word));
      continue;
    }
    if (header_bytes < kHeaderSize) {
      // A later sync word would have even fewer bytes after it: nothing valid can follow.
      addProblem(LogProblemKind::kTruncatedHeader, start,
                 "byte " + std::to_string(start) +
                     ": event header truncated: " + std::to_string(kHeaderSize) + " bytes needed, only " +
                     std::to_string(remaining) + " left; skipped");
      skipped_bytes_ += remaining;
      finished_ = true;
      break;
    }
    const auto channel_length = static_cast<std::int32_t>(readUint32Be(header.data() + 20));
    const auto data_length = static_cast<std::int32_t>(readUint32Be(header.data() + 24));
    if (channel_length < 1 || channel_length > kMaxChannelLength) {
      skipToNextSyncWord(start, LogProblemKind::kBadChannelLength,
                         "channel length " + std::to_string(channel_length) + " out of range 1.." +
                             std::to_string(kMaxChannelLength));
      continue;
    }
    if (data_length < 0) {
      skipToNextSyncWord(start, LogProblemKind::kBadDataLength,
                         "negative data length " + std::to_string(data_length));
      continue;
    }
    const std::uint64_t body_bytes =
        static_cast<std::uint64_t>(channel_length) + static_cast<std::uint64_t>(data_length);
    if (body_bytes > remaining - kHeaderSize) {
      // Checked before any allocation: a header claiming 2 GB in a 100-byte file costs nothing.
      skipToNextSyncWord(start, LogProblemKind::kTruncatedEvent,
                         "event truncated: header claims " + std::to_string(channel_length) +
                             " channel and " + std::to_string(data_length) + " data bytes, only " +
                             std::to_string(remaining - kHeaderSize) + " bytes follow the header");
      continue;
    }
    event.event_number = static_cast<std::int64_t>(readUint64Be(header.data() + 4));
    event.timestamp_us = static_cast<std::int64_t>(readUint64Be(header.data() + 12));
    event.channel.resize(static_cast<std::size_t>(channel_length));
    event.data.resize(static_cast<std::size_t>(data_length));
    if (!readBytes(event.channel.data(), event.channel.size()) ||
        !readBytes(event.data.data(), event.data.size())) {
      break;
    }
    ++event_count_;
    return true;
  }
  return false;
}

std::string LogReader::problemSummary() const
{
  if (problem_count_ == 0) {
    return {};
  }
  std::string summary =
      plural(problem_count_, "problem") + ", " + plural(skipped_bytes_, "byte") + " skipped";
  if (!problems_.empty()) {
    summary += "; first: " + problems_.front().description;
  }
  return summary;
}

bool LogReader::readBytes(void* bytes, std::uint64_t count)
{
  if (count == 0) {
    return true;
  }
  stream_->read(static_cast<char*>(bytes), static_cast<std::streamsize>(count));
  const auto got = static_cast<std::uint64_t>(stream_->gcount());
  if (got != count) {
    addProblem(LogProblemKind::kReadError, position_ + got,
               "byte " + std::to_string(position_ + got) + ": read error: the log ended before its size of " +
                   std::to_string(file_size_) + " bytes (did it change while being read?)");
    finished_ = true;
    return false;
  }
  position_ += count;
  return true;
}

std::uint64_t LogReader::findSyncWord(std::uint64_t from)
{
  stream_->clear();
  if (from >= file_size_ || !stream_->seekg(static_cast<std::streamoff>(from), std::ios::beg)) {
    return file_size_;
  }
  // The last four bytes read, as liblcm scans: a sync word split between two chunks is still found.
  std::uint32_t window = 0;
  std::uint64_t offset = from;  // of the next byte to look at
  std::vector<char> chunk(kScanChunkSize);
  while (offset < file_size_) {
    const std::uint64_t wanted = std::min<std::uint64_t>(kScanChunkSize, file_size_ - offset);
    stream_->read(chunk.data(), static_cast<std::streamsize>(wanted));
    const auto got = static_cast<std::uint64_t>(stream_->gcount());
    for (std::uint64_t index = 0; index < got; ++index) {
      window = (window << 8U) | static_cast<std::uint8_t>(chunk[index]);
      ++offset;
      if (window == kSyncWord && offset - from >= 4) {
        return offset - 4;
      }
    }
    if (got != wanted) {
      break;  // the stream ended early: next() reports the read error when it gets there
    }
  }
  return file_size_;
}

void LogReader::skipToNextSyncWord(std::uint64_t start, LogProblemKind kind, const std::string& what)
{
  const std::uint64_t next_sync = findSyncWord(start + 1);
  const std::uint64_t skipped = next_sync - start;
  skipped_bytes_ += skipped;
  std::string description =
      "byte " + std::to_string(start) + ": " + what + "; skipped " + plural(skipped, "byte") + " to ";
  description += next_sync < file_size_ ? "the next sync word at byte " + std::to_string(next_sync)
                                        : std::string("the end of the file");
  addProblem(kind, start, description);
  position_ = next_sync;
  stream_->clear();
  if (position_ < file_size_ && !stream_->seekg(static_cast<std::streamoff>(position_), std::ios::beg)) {
    addProblem(LogProblemKind::kReadError, position_,
               "byte " + std::to_string(position_) + ": read error: cannot seek there");
    finished_ = true;
  }
  if (position_ >= file_size_) {
    finished_ = true;
  }
}

void LogReader::addProblem(LogProblemKind kind, std::uint64_t offset, const std::string& description)
{
  ++problem_count_;
  if (problems_.size() < kMaxKeptProblems) {
    problems_.push_back(LogProblem{kind, offset, description});
  }
}

}  // namespace ifar::lcm_log
