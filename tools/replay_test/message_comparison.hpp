#pragma once
// Two encodings of one message compared member by member through the schema (tools/echo's decoding), so a
// difference is named by where it is: "waypoints[2].x: recorded 8.35, replayed 8.41". Integers, booleans,
// strings and bytes must be equal; reals within `tolerance` (0: the same value, NaN equal to NaN); the
// message's own members named in `ignored` ("planner_status_t.total_ms") are not compared.

#include <set>
#include <string>

#include "common/span.hpp"
#include "tools/echo/message_value.hpp"

namespace ifar::replay_test {

struct ComparisonSettings {
  double tolerance = 0.0;         ///< absolute, in each real member's own unit
  std::set<std::string> ignored;  ///< "type_t.member", members of the message itself
};

/// Where `replayed` first differs from `recorded`, or "" when they agree. Bytes of different types, or that
/// do not decode, are a difference too (named so).
std::string firstDifference(const echo::MessageTypes& types, common::ByteView recorded,
                            common::ByteView replayed, const ComparisonSettings& settings);

}  // namespace ifar::replay_test
