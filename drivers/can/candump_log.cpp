#include "drivers/can/candump_log.hpp"

#include <cinttypes>
#include <cstdio>
#include <fstream>

#include "drivers/can/error_frame.hpp"

namespace ifar::can {
namespace {

constexpr std::uint32_t kLogErrorFlag = 0x20000000;  // CAN_ERR_FLAG as candump prints it in the id

int hexValue(char character)
{
  if (character >= '0' && character <= '9')
    return character - '0';
  if (character >= 'a' && character <= 'f')
    return character - 'a' + 10;
  if (character >= 'A' && character <= 'F')
    return character - 'A' + 10;
  return -1;
}

bool isSpace(char character)
{
  return character == ' ' || character == '\t' || character == '\r' || character == '\n';
}

std::string_view trim(std::string_view text)
{
  while (!text.empty() && isSpace(text.front()))
    text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back()))
    text.remove_suffix(1);
  return text;
}

std::string_view nextToken(std::string_view& text)
{
  while (!text.empty() && isSpace(text.front()))
    text.remove_prefix(1);
  std::size_t end = 0;
  while (end < text.size() && !isSpace(text[end]))
    ++end;
  const std::string_view token = text.substr(0, end);
  text.remove_prefix(end);
  return token;
}

ParsedLine reject(LineStatus status, std::string problem)
{
  ParsedLine result;
  result.status = status;
  result.problem = std::move(problem);
  return result;
}

// "1700000000.010000" -> microseconds; false when not digits '.' digits.
bool parseTimestamp(std::string_view text, std::int64_t& microseconds)
{
  const std::size_t dot = text.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot > 12 || dot + 1 >= text.size()) {
    return false;
  }
  std::int64_t seconds = 0;
  for (std::size_t index = 0; index < dot; ++index) {
    const int digit = hexValue(text[index]);
    if (digit < 0 || digit > 9)
      return false;
    seconds = seconds * 10 + digit;
  }
  std::int64_t fraction = 0;
  int digits = 0;
  for (std::size_t index = dot + 1; index < text.size(); ++index) {
    const int digit = hexValue(text[index]);
    if (digit < 0 || digit > 9)
      return false;
    if (digits < 6) {
      fraction = fraction * 10 + digit;
      ++digits;
    }
  }
  while (digits < 6) {
    fraction *= 10;
    ++digits;
  }
  microseconds = seconds * 1'000'000 + fraction;
  return true;
}

}  // namespace

ParsedLine parseCandumpLine(std::string_view line)
{
  line = trim(line);
  if (line.empty()) {
    return reject(LineStatus::kBlank, "blank line");
  }
  std::string_view rest = line;
  const std::string_view stamp_token = nextToken(rest);
  if (stamp_token.size() < 3 || stamp_token.front() != '(' || stamp_token.back() != ')') {
    return reject(LineStatus::kMalformed, "expected '(seconds.microseconds)' at the start");
  }
  std::int64_t timestamp_us = 0;
  if (!parseTimestamp(stamp_token.substr(1, stamp_token.size() - 2), timestamp_us)) {
    return reject(LineStatus::kMalformed, "bad timestamp '" + std::string(stamp_token) + "'");
  }
  const std::string_view interface = nextToken(rest);
  const std::string_view frame_text = nextToken(rest);
  if (interface.empty() || frame_text.empty()) {
    return reject(LineStatus::kMalformed, "expected 'interface id#data' after the timestamp");
  }
  // Whatever follows (newer can-utils append a direction flag) is ignored.
  const std::size_t hash = frame_text.find('#');
  if (hash == std::string_view::npos) {
    return reject(LineStatus::kMalformed, "no '#' between id and data in '" + std::string(frame_text) + "'");
  }
  if (hash + 1 < frame_text.size() && frame_text[hash + 1] == '#') {
    return reject(LineStatus::kUnsupportedFd, "CAN FD frame (id##...) not supported");
  }
  const std::string_view id_text = frame_text.substr(0, hash);
  if (id_text.size() != 3 && id_text.size() != 8) {
    return reject(LineStatus::kMalformed, "id '" + std::string(id_text) + "' is not 3 or 8 hex digits");
  }
  std::uint32_t raw_id = 0;
  for (const char character : id_text) {
    const int digit = hexValue(character);
    if (digit < 0) {
      return reject(LineStatus::kMalformed, "id '" + std::string(id_text) + "' is not hexadecimal");
    }
    raw_id = (raw_id << 4) | static_cast<std::uint32_t>(digit);
  }
  ParsedLine result;
  Frame& frame = result.frame;
  frame.timestamp_us = timestamp_us;
  if (id_text.size() == 3) {
    if (raw_id > kStandardIdMask) {
      return reject(LineStatus::kMalformed, "standard id " + std::string(id_text) + " exceeds 7FF");
    }
    frame.id = raw_id;
  } else if ((raw_id & kLogErrorFlag) != 0) {
    frame.flags = kFlagError;
    frame.id = raw_id & kExtendedIdMask & ~kLogErrorFlag;
  } else {
    frame.flags = kFlagExtended;
    frame.id = raw_id & kExtendedIdMask;
  }
  std::string_view data_text = frame_text.substr(hash + 1);
  if (!data_text.empty() && (data_text.front() == 'R' || data_text.front() == 'r')) {
    frame.flags |= kFlagRemote;
    if (data_text.size() >= 2) {
      const int length = hexValue(data_text[1]);
      if (length < 0 || length > kMaxDataLength || data_text.size() > 2) {
        return reject(LineStatus::kMalformed, "bad remote frame length in '" + std::string(frame_text) + "'");
      }
      frame.dlc = static_cast<std::uint8_t>(length);
    }
  } else {
    // Optional "_X" suffix: the raw DLC 9..F of a classic 8-byte frame; the payload is what counts.
    const std::size_t underscore = data_text.find('_');
    if (underscore != std::string_view::npos) {
      const std::string_view suffix = data_text.substr(underscore + 1);
      if (suffix.size() != 1 || hexValue(suffix[0]) < 9) {
        return reject(LineStatus::kMalformed, "bad dlc suffix in '" + std::string(frame_text) + "'");
      }
      data_text = data_text.substr(0, underscore);
    }
    std::size_t index = 0;
    while (index < data_text.size()) {
      if (data_text[index] == '.') {  // can-utils accepts dots between bytes
        ++index;
        continue;
      }
      if (frame.dlc >= kMaxDataLength || index + 1 >= data_text.size()) {
        return reject(LineStatus::kMalformed, "data in '" + std::string(frame_text) +
                                                  "' is longer than 8 bytes or has an odd digit count");
      }
      const int high = hexValue(data_text[index]);
      const int low = hexValue(data_text[index + 1]);
      if (high < 0 || low < 0) {
        return reject(LineStatus::kMalformed, "data in '" + std::string(frame_text) + "' is not hexadecimal");
      }
      frame.data[frame.dlc++] = static_cast<std::uint8_t>((high << 4) | low);
      index += 2;
    }
  }
  result.status = LineStatus::kOk;
  result.interface = std::string(interface);
  return result;
}

std::string formatCandumpLine(const Frame& frame, const std::string& interface)
{
  char buffer[128];
  const std::int64_t seconds = frame.timestamp_us / 1'000'000;
  const std::int64_t micros = frame.timestamp_us % 1'000'000;
  int length = std::snprintf(buffer, sizeof(buffer), "(%010" PRId64 ".%06" PRId64 ") ", seconds,
                             micros < 0 ? -micros : micros);
  std::string line(buffer, static_cast<std::size_t>(length));
  line += interface;
  line += ' ';
  if (frame.error()) {
    length = std::snprintf(buffer, sizeof(buffer), "%08" PRIX32,
                           (frame.id & kExtendedIdMask & ~kLogErrorFlag) | kLogErrorFlag);
  } else if (frame.extended()) {
    length = std::snprintf(buffer, sizeof(buffer), "%08" PRIX32, frame.id & kExtendedIdMask);
  } else {
    length = std::snprintf(buffer, sizeof(buffer), "%03" PRIX32, frame.id & kStandardIdMask);
  }
  line.append(buffer, static_cast<std::size_t>(length));
  line += '#';
  const std::uint8_t dlc = frame.dlc <= kMaxDataLength ? frame.dlc : kMaxDataLength;
  if (frame.remote()) {
    line += 'R';
    if (dlc > 0) {
      line += static_cast<char>('0' + dlc);
    }
    return line;
  }
  static constexpr char kHex[] = "0123456789ABCDEF";
  for (std::uint8_t index = 0; index < dlc; ++index) {
    line += kHex[frame.data[index] >> 4];
    line += kHex[frame.data[index] & 0x0F];
  }
  return line;
}

CandumpLogBus::CandumpLogBus(std::unique_ptr<std::istream> input, std::unique_ptr<std::ostream> output,
                             std::string interface)
    : input_(std::move(input)), output_(std::move(output)), interface_(std::move(interface))
{
}

CandumpLogBus::OpenResult CandumpLogBus::open(const std::string& input_path, const std::string& output_path,
                                              const std::string& interface)
{
  OpenResult result;
  std::unique_ptr<std::istream> input;
  std::unique_ptr<std::ostream> output;
  if (!input_path.empty()) {
    auto file = std::make_unique<std::ifstream>(input_path);
    if (!*file) {
      result.error = "cannot open candump log '" + input_path + "' for reading";
      return result;
    }
    input = std::move(file);
  }
  if (!output_path.empty()) {
    auto file = std::make_unique<std::ofstream>(output_path, std::ios::app);
    if (!*file) {
      result.error = "cannot open candump log '" + output_path + "' for writing";
      return result;
    }
    output = std::move(file);
  }
  result.bus = std::make_unique<CandumpLogBus>(std::move(input), std::move(output), interface);
  return result;
}

SendResult CandumpLogBus::send(const Frame& frame)
{
  if (!output_) {
    ++counters_.write_errors;
    return {IoStatus::kError, name() + ": no output log to write to"};
  }
  *output_ << formatCandumpLine(frame, interface_) << '\n';
  output_->flush();
  if (!*output_) {
    ++counters_.write_errors;
    return {IoStatus::kError, name() + ": writing the log failed"};
  }
  ++counters_.frames_sent;
  return {};
}

ReceiveResult CandumpLogBus::receive(std::chrono::microseconds /*timeout*/)
{
  if (!input_) {
    return {IoStatus::kEndOfStream, {}, {}};
  }
  std::string line;
  while (std::getline(*input_, line)) {
    const ParsedLine parsed = parseCandumpLine(line);
    if (parsed.status == LineStatus::kBlank) {
      continue;
    }
    if (parsed.status != LineStatus::kOk) {
      ++counters_.bad_frames;
      continue;
    }
    if (parsed.frame.error()) {
      ++counters_.error_frames;
      if (const auto next = stateAfterErrorFrame(parsed.frame, state_)) {
        state_ = *next;
      }
      return {IoStatus::kOk, parsed.frame, {}};
    }
    if (accepts(filters_, parsed.frame)) {
      ++counters_.frames_received;
      return {IoStatus::kOk, parsed.frame, {}};
    }
  }
  return {IoStatus::kEndOfStream, {}, {}};
}

}  // namespace ifar::can
