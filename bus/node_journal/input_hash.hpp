#pragma once
// The hash by which a node's journal names an input message: the log holds the message itself, so the
// journal only needs to tell which of the logged messages the node took (a logger may hold one the node
// never got, or the other way round).

#include <cstdint>

#include "common/span.hpp"

namespace ifar::node_journal {

/// FNV-1a (32 bit) of `bytes`, as a signed int32 (the journal's LCM field).
std::int32_t inputHash(common::ByteView bytes);

}  // namespace ifar::node_journal
