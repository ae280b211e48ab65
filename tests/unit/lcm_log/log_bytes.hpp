#pragma once
// LCM log bytes written by hand for the log reader's tests, independently of the reader (and of liblcm, so
// the lengths in a header can say anything): big-endian sync word, event number, timestamp, channel
// length, data length, then the channel and the data. The format test checks liblcm reads these too.

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace ifar::lcm_log::test {

using Bytes = std::vector<std::uint8_t>;

inline void appendBigEndian(Bytes& bytes, std::uint64_t value, int size)
{
  for (int shift = 8 * (size - 1); shift >= 0; shift -= 8) {
    bytes.push_back(static_cast<std::uint8_t>(value >> static_cast<unsigned>(shift)));
  }
}

/// A 28-byte event header; the lengths are whatever the test wants them to claim.
inline Bytes eventHeader(std::int64_t event_number, std::int64_t timestamp_us, std::int32_t channel_length,
                         std::int32_t data_length)
{
  Bytes bytes;
  appendBigEndian(bytes, 0xEDA1DA01U, 4);
  appendBigEndian(bytes, static_cast<std::uint64_t>(event_number), 8);
  appendBigEndian(bytes, static_cast<std::uint64_t>(timestamp_us), 8);
  appendBigEndian(bytes, static_cast<std::uint32_t>(channel_length), 4);
  appendBigEndian(bytes, static_cast<std::uint32_t>(data_length), 4);
  return bytes;
}

/// A whole, valid event.
inline Bytes eventBytes(std::int64_t event_number, std::int64_t timestamp_us, const std::string& channel,
                        const Bytes& data)
{
  Bytes bytes = eventHeader(event_number, timestamp_us, static_cast<std::int32_t>(channel.size()),
                            static_cast<std::int32_t>(data.size()));
  bytes.insert(bytes.end(), channel.begin(), channel.end());
  bytes.insert(bytes.end(), data.begin(), data.end());
  return bytes;
}

inline void append(Bytes& bytes, const Bytes& more)
{
  bytes.insert(bytes.end(), more.begin(), more.end());
}

inline bool writeFile(const std::string& path, const Bytes& bytes)
{
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(file);
}

}  // namespace ifar::lcm_log::test
