#pragma once
// Checks every length an encoded LCM message claims (array counts, string lengths) against the bytes
// that follow it, before LCM's generated decode allocates what the claims ask for. One bus message
// claiming a billion doubles made that decode zero-fill 8 GB before it noticed the message was 60
// bytes long; with this check first, what a decode can allocate is bounded by a small multiple of the
// message's own size.

#include <cstddef>
#include <optional>
#include <string>

#include "common/lcm_wire/schema.hpp"
#include "common/span.hpp"

namespace ifar::lcm_wire {

/// Walks `message` (an encoding with its 8-byte type hash, as on the bus and in logs) as `type` of
/// `schema`. Returns a description of the first claim the bytes cannot back, naming the member and
/// the byte offset, e.g. "path_t.waypoints claims 100000000 elements of at least 29 bytes at byte 53,
/// 4 bytes left"; std::nullopt when every claim is backed. Does not check the hash, and accepts bytes
/// after the message, as LCM's decode does.
std::optional<std::string> findUnbackedClaim(const Schema& schema, const StructType& type,
                                             common::ByteView message);

/// The bytes the message at the start of `message` takes, type hash included, when every claim is
/// backed; std::nullopt otherwise. LCM's decode of a backed message takes exactly as many.
std::optional<std::size_t> encodedLength(const Schema& schema, const StructType& type,
                                         common::ByteView message);

}  // namespace ifar::lcm_wire
