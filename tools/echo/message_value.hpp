#pragma once
// An LCM message decoded by its schema into values with names, for printing: any type in the schema, found by
// the fingerprint in the message's first 8 bytes, with no code generated for it. Bytes from the bus or a log
// are walked as lcm_wire does before anything is read (claim_check.hpp), so a message that claims more than
// it holds is refused naming the member, never read past its end.

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "common/lcm_wire/schema.hpp"
#include "common/span.hpp"

namespace ifar::echo {

struct Value;
/// A struct's members in the order of its definition.
using Members = std::vector<std::pair<std::string, Value>>;

/// One member's value. Integers of every width (and single bytes) are kInteger; a float keeps its single
/// precision so it prints with the digits it has; an array of bytes is one kBytes value.
struct Value {
  enum class Kind : std::uint8_t { kInteger, kDouble, kFloat, kBoolean, kString, kBytes, kList, kStruct };
  Kind kind = Kind::kInteger;
  std::int64_t integer = 0;
  double real = 0.0;
  bool boolean = false;
  std::string text;             // a string's characters (without its NUL), or the bytes of kBytes
  std::vector<Value> elements;  // kList
  Members members;              // kStruct
};

/// The project's message types by fingerprint.
class MessageTypes {
 public:
  /// `schema` must outlive this object.
  explicit MessageTypes(const lcm_wire::Schema& schema);

  /// The type whose fingerprint `message` starts with, or nullptr (shorter than 8 bytes, or no such type).
  const lcm_wire::StructType* typeOf(common::ByteView message) const;

  /// Decodes `message` as `type`: its members, or why it does not decode (a claim its bytes cannot back,
  /// named by member and byte offset).
  std::variant<Members, std::string> decode(const lcm_wire::StructType& type, common::ByteView message) const;

 private:
  const lcm_wire::Schema& schema_;
  std::map<std::int64_t, const lcm_wire::StructType*> by_fingerprint_;
};

}  // namespace ifar::echo
