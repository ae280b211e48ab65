#include "common/lcm_log/log_writer.hpp"

#include <array>
#include <limits>

#include "common/lcm_log/log_reader.hpp"

namespace ifar::lcm_log {
namespace {

template <std::size_t Size>
void putBigEndian(std::array<std::uint8_t, kHeaderSize>& header, std::size_t offset, std::uint64_t value)
{
  for (std::size_t index = 0; index < Size; ++index) {
    header[offset + index] = static_cast<std::uint8_t>(value >> (8 * (Size - 1 - index)));
  }
}

}  // namespace

LogWriter::LogWriter(const std::string& path) : path_(path), file_(path, std::ios::binary | std::ios::trunc)
{
  if (!file_) {
    open_error_ = path + ": cannot create the log file";
  }
}

bool LogWriter::write(const std::string& channel, std::int64_t timestamp_us, common::ByteView data)
{
  if (channel.empty() || channel.size() > static_cast<std::size_t>(kMaxChannelLength)) {
    write_error_ = "channel name of " + std::to_string(channel.size()) + " bytes (1 to " +
                   std::to_string(kMaxChannelLength) + " allowed)";
    return false;
  }
  if (data.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    write_error_ = channel + ": message of " + std::to_string(data.size()) + " bytes does not fit an event";
    return false;
  }
  std::array<std::uint8_t, kHeaderSize> header{};
  putBigEndian<4>(header, 0, kSyncWord);
  putBigEndian<8>(header, 4, static_cast<std::uint64_t>(next_event_number_));
  putBigEndian<8>(header, 12, static_cast<std::uint64_t>(timestamp_us));
  putBigEndian<4>(header, 20, channel.size());
  putBigEndian<4>(header, 24, data.size());
  file_.write(reinterpret_cast<const char*>(header.data()), static_cast<std::streamsize>(header.size()));
  file_.write(channel.data(), static_cast<std::streamsize>(channel.size()));
  file_.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
  if (!file_) {
    write_error_ = path_ + ": write failed after " + std::to_string(next_event_number_) + " events";
    return false;
  }
  ++next_event_number_;
  return true;
}

}  // namespace ifar::lcm_log
