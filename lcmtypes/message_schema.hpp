#pragma once
// The project's message types as lcm_wire reads them from the .lcm files, which the build compiles in
// (message_schema_sources.cpp, generated from lcmtypes/*.lcm at configure time). Lets any code check an
// encoding's claims before LCM's generated decode trusts them (checked_decode.hpp).

#include <string_view>
#include <vector>

#include "common/lcm_wire/schema.hpp"

namespace ifar::lcmtypes {

struct LcmDefinition {
  std::string_view file_name;  ///< e.g. "path_t.lcm"
  std::string_view text;       ///< the file's contents
};

/// Every .lcm file of lcmtypes/, as built in.
std::vector<LcmDefinition> lcmDefinitions();

/// The schema of all of them, parsed on first use and constant after.
const lcm_wire::Schema& messageSchema();

}  // namespace ifar::lcmtypes
