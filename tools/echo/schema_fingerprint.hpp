#pragma once
// The fingerprint of an LCM type, computed from its schema as lcm-gen computes the one its generated code
// returns from getHash(): a hash of each member's name, primitive type and array dimensions, plus the
// fingerprints of the struct types it holds (each counted once per member, a type already being hashed
// further up counting 0), rotated left by one bit. A message's first 8 bytes are its type's fingerprint,
// so any message of a type in the schema can be recognised without code generated for it.

#include <cstdint>

#include "common/lcm_wire/schema.hpp"

namespace ifar::echo {

/// The fingerprint (getHash()) of `type`, one of `schema`'s types.
std::int64_t fingerprintOf(const lcm_wire::Schema& schema, const lcm_wire::StructType& type);

}  // namespace ifar::echo
