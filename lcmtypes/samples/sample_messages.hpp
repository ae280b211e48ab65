#pragma once
// One sample value of every project LCM type, with every field set to something other than its default,
// for the round-trip, fingerprint and record/replay tests. A new .lcm file needs an entry here; the
// fingerprint test fails until it has one.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/span.hpp"

namespace ifar::lcmtypes_samples {

struct SampleMessage {
  std::string type_name;              // e.g. "pose_t"
  std::string channel;                // the channel it travels on, e.g. "POSE"
  std::int64_t fingerprint;           // the type's LCM hash (getHash())
  std::vector<std::uint8_t> encoded;  // the sample value, encoded
  /// Decodes `bytes` as this type and encodes the result again; false when the bytes do not decode.
  /// Equal re-encoded bytes mean equal field values.
  std::function<bool(common::ByteView bytes, std::vector<std::uint8_t>& reencoded)> reencode;
};

/// Every project type, one sample each, in alphabetical order of type name.
std::vector<SampleMessage> allSampleMessages();

}  // namespace ifar::lcmtypes_samples
