#pragma once
// A JSON Schema (draft 2020-12) of the JSON that jsonObject (message_format.hpp) prints for a type, built
// from the LCM schema compiled in: for tools that want the shape of `ifar echo --json`'s messages before the
// first one arrives (the Foxglove WebSocket protocol advertises it with each channel). Integers are
// "integer"; floats and doubles "number" (NaN and infinity print as null, said in the description); booleans;
// strings; byte arrays one hex "string"; arrays "array" with their fixed length as minItems and maxItems;
// nested structs inline "object"s.

#include <string>

#include "common/lcm_wire/schema.hpp"

namespace ifar::echo {

/// The schema of `type`'s JSON object as JSON text, titled by the type's name. `type` must be one of
/// `schema`'s types.
std::string jsonSchemaOf(const lcm_wire::Schema& schema, const lcm_wire::StructType& type);

}  // namespace ifar::echo
