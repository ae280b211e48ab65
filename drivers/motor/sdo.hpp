#pragma once
// CANopen (CiA 301) SDO expedited download: the one SDO service the motor client uses, to write the
// drives' limits and watchdogs at start-up (docs/can_frames.md, "Start-up configuration"). A client
// request goes to 0x600 + node, the server's answer comes from 0x580 + node, both 8 bytes:
//
//   byte 0     command specifier: request 0x23 / 0x27 / 0x2B / 0x2F (4 / 3 / 2 / 1 data bytes),
//              answer 0x60 (download confirmed), either side 0x80 (abort)
//   bytes 1-2  object index, uint16 LE
//   byte 3     sub-index
//   bytes 4-7  the value, LE, unused bytes 0 (request); 0 (answer); abort code, uint32 LE (abort)
//
// Encoders build exact bytes; decoders never throw and return nullopt for a frame of the wrong id,
// length or command specifier.

#include <cstdint>
#include <optional>

#include "drivers/can/frame.hpp"

namespace ifar::motor {

constexpr std::uint32_t kSdoRequestBase = 0x600;  // client -> server, + node id
constexpr std::uint32_t kSdoAnswerBase = 0x580;   // server -> client, + node id

/// SDO abort codes (CiA 301) the client and the drive emulator use.
constexpr std::uint32_t kAbortTimedOut = 0x0504'0000;        // SDO protocol timed out
constexpr std::uint32_t kAbortBadCommand = 0x0504'0001;      // command specifier not valid or unknown
constexpr std::uint32_t kAbortReadOnly = 0x0601'0002;        // attempt to write a read only object
constexpr std::uint32_t kAbortNoObject = 0x0602'0000;        // object does not exist
constexpr std::uint32_t kAbortIncompatible = 0x0604'0043;    // general parameter incompatibility
constexpr std::uint32_t kAbortLengthMismatch = 0x0607'0010;  // data type does not match in length
constexpr std::uint32_t kAbortNoSubindex = 0x0609'0011;      // sub-index does not exist
constexpr std::uint32_t kAbortValueRange = 0x0609'0030;      // value range of parameter exceeded
constexpr std::uint32_t kAbortGeneral = 0x0800'0000;         // general error
constexpr std::uint32_t kAbortDeviceState = 0x0800'0022;     // not possible in the present device state
/// What an abort code means, for error messages ("value range of parameter exceeded").
const char* sdoAbortText(std::uint32_t abort_code);

/// One object written by expedited download: `size` bytes (1, 2 or 4) of `value`, little-endian.
struct SdoWrite {
  std::uint16_t index = 0;
  std::uint8_t subindex = 0;
  std::uint32_t value = 0;  // the object's bytes; a signed object's value as its two's complement
  std::uint8_t size = 4;
  bool operator==(const SdoWrite& other) const
  {
    return index == other.index && subindex == other.subindex && value == other.value && size == other.size;
  }
};

/// What a client sends (decoded by the server): a download request or an abort.
struct SdoRequest {
  enum class Kind { kDownload, kAbort, kUnsupported };
  Kind kind = Kind::kDownload;
  SdoWrite write;                // kDownload: what to write (size 1..4); others: index and sub-index
  std::uint32_t abort_code = 0;  // kAbort
};

/// What a server answers (decoded by the client).
struct SdoAnswer {
  enum class Kind { kDownloadConfirmed, kAbort };
  Kind kind = Kind::kDownloadConfirmed;
  std::uint16_t index = 0;
  std::uint8_t subindex = 0;
  std::uint32_t abort_code = 0;  // kAbort
};

/// The expedited download request for `write` to node `node_id`. `write.size` outside 1..4 is taken as 4.
can::Frame encodeSdoDownload(std::uint8_t node_id, const SdoWrite& write);
/// The server's confirmation of a download of index:subindex.
can::Frame encodeSdoDownloadConfirmed(std::uint8_t node_id, std::uint16_t index, std::uint8_t subindex);
/// An abort of the transfer of index:subindex, on `cob_id` (0x600 + n from a client, 0x580 + n from a
/// server).
can::Frame encodeSdoAbort(std::uint32_t cob_id, std::uint16_t index, std::uint8_t subindex,
                          std::uint32_t abort_code);

/// A request to `node_id` (id 0x600 + node_id, 8 bytes). Segmented, block and upload requests decode as
/// kUnsupported (a server answers them with kAbortBadCommand).
std::optional<SdoRequest> decodeSdoRequest(const can::Frame& frame, std::uint8_t node_id);
/// An answer from `node_id` (id 0x580 + node_id, 8 bytes): a download confirmation or an abort; other
/// answers (uploads, segments) are nullopt.
std::optional<SdoAnswer> decodeSdoAnswer(const can::Frame& frame, std::uint8_t node_id);

}  // namespace ifar::motor
