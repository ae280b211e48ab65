#include "drivers/motor/sdo.hpp"

namespace ifar::motor {
namespace {

constexpr std::uint8_t kSdoLength = 8;
constexpr std::uint8_t kCommandMask = 0xE0;      // bits 7-5: the command specifier
constexpr std::uint8_t kDownloadRequest = 0x20;  // client: initiate download
constexpr std::uint8_t kDownloadAnswer = 0x60;   // server: initiate download confirmed
constexpr std::uint8_t kAbort = 0x80;            // either side
constexpr std::uint8_t kExpedited = 0x02;        // bit 1: the data is in this frame
constexpr std::uint8_t kSizeIndicated = 0x01;    // bit 0: bits 3-2 say how many bytes are unused

bool isSdoFrame(const can::Frame& frame, std::uint32_t cob_id)
{
  return !frame.extended() && !frame.remote() && !frame.error() && frame.id == cob_id &&
         frame.dlc == kSdoLength;
}

bool validNode(std::uint8_t node_id)
{
  return node_id >= 1 && node_id <= 127;
}

can::Frame sdoFrame(std::uint32_t cob_id, std::uint8_t command, std::uint16_t index, std::uint8_t subindex,
                    std::uint32_t payload)
{
  can::Frame frame;
  frame.id = cob_id;
  frame.dlc = kSdoLength;
  frame.data[0] = command;
  can::writeU16Le(frame.data.data() + 1, index);
  frame.data[3] = subindex;
  can::writeU32Le(frame.data.data() + 4, payload);
  return frame;
}

}  // namespace

const char* sdoAbortText(std::uint32_t abort_code)
{
  switch (abort_code) {
    case kAbortTimedOut:
      return "SDO protocol timed out";
    case kAbortBadCommand:
      return "command specifier not valid or unknown";
    case kAbortReadOnly:
      return "attempt to write a read only object";
    case kAbortNoObject:
      return "object does not exist in the object dictionary";
    case kAbortIncompatible:
      return "general parameter incompatibility";
    case kAbortLengthMismatch:
      return "data type does not match, length of service parameter does not match";
    case kAbortNoSubindex:
      return "sub-index does not exist";
    case kAbortValueRange:
      return "invalid value for parameter (value range exceeded)";
    case kAbortGeneral:
      return "general error";
    case kAbortDeviceState:
      return "data cannot be transferred or stored because of the present device state";
    default:
      return "unknown abort code";
  }
}

can::Frame encodeSdoDownload(std::uint8_t node_id, const SdoWrite& write)
{
  const std::uint8_t size = write.size >= 1 && write.size <= 4 ? write.size : 4;
  const auto unused = static_cast<std::uint8_t>(4 - size);
  const auto command =
      static_cast<std::uint8_t>(kDownloadRequest | (unused << 2) | kExpedited | kSizeIndicated);
  const std::uint32_t mask = size == 4 ? 0xFFFF'FFFFU : (1U << (8U * size)) - 1U;
  return sdoFrame(kSdoRequestBase + node_id, command, write.index, write.subindex, write.value & mask);
}

can::Frame encodeSdoDownloadConfirmed(std::uint8_t node_id, std::uint16_t index, std::uint8_t subindex)
{
  return sdoFrame(kSdoAnswerBase + node_id, kDownloadAnswer, index, subindex, 0);
}

can::Frame encodeSdoAbort(std::uint32_t cob_id, std::uint16_t index, std::uint8_t subindex,
                          std::uint32_t abort_code)
{
  return sdoFrame(cob_id, kAbort, index, subindex, abort_code);
}

std::optional<SdoRequest> decodeSdoRequest(const can::Frame& frame, std::uint8_t node_id)
{
  if (!validNode(node_id) || !isSdoFrame(frame, kSdoRequestBase + node_id)) {
    return std::nullopt;
  }
  SdoRequest request;
  request.write.index = can::readU16Le(frame.data.data() + 1);
  request.write.subindex = frame.data[3];
  const std::uint8_t command = frame.data[0];
  if (command == kAbort) {
    request.kind = SdoRequest::Kind::kAbort;
    request.abort_code = can::readU32Le(frame.data.data() + 4);
    return request;
  }
  // Only an expedited download with its size stated carries a whole value in this one frame.
  const bool expedited_download = (command & kCommandMask) == kDownloadRequest &&
                                  (command & kExpedited) != 0 && (command & kSizeIndicated) != 0;
  if (!expedited_download) {
    request.kind = SdoRequest::Kind::kUnsupported;
    return request;
  }
  request.write.size = static_cast<std::uint8_t>(4 - ((command >> 2) & 0x03));
  const std::uint32_t raw = can::readU32Le(frame.data.data() + 4);
  request.write.value = request.write.size == 4 ? raw : raw & ((1U << (8U * request.write.size)) - 1U);
  return request;
}

std::optional<SdoAnswer> decodeSdoAnswer(const can::Frame& frame, std::uint8_t node_id)
{
  if (!validNode(node_id) || !isSdoFrame(frame, kSdoAnswerBase + node_id)) {
    return std::nullopt;
  }
  SdoAnswer answer;
  answer.index = can::readU16Le(frame.data.data() + 1);
  answer.subindex = frame.data[3];
  if (frame.data[0] == kDownloadAnswer) {
    answer.kind = SdoAnswer::Kind::kDownloadConfirmed;
    return answer;
  }
  if (frame.data[0] == kAbort) {
    answer.kind = SdoAnswer::Kind::kAbort;
    answer.abort_code = can::readU32Le(frame.data.data() + 4);
    return answer;
  }
  return std::nullopt;
}

}  // namespace ifar::motor
