#pragma once
// The layout of LCM messages on the wire, read from .lcm definition files, so bytes can be checked
// against a type without LCM's generated code. That code sizes every variable-length array to whatever
// length the bytes claim before checking that they hold it; a schema lets a checker refuse such a claim
// first (claim_check.hpp).
//
// The part of the LCM language a schema needs (https://lcm-proj.github.io/lcm/content/lcm-language-ref.html):
// `package`, `struct`, members of the primitive types, `string` and other structs, fixed and
// variable-length arrays, and `const` declarations (which are not on the wire). Comments of both kinds.
// Multi-dimensional arrays with a variable dimension are refused: a zero inner length lets an outer
// length claim any count without bytes behind it, and no project type needs them.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ifar::lcm_wire {

enum class FieldKind : std::uint8_t {
  kInt8,
  kInt16,
  kInt32,
  kInt64,
  kFloat,
  kDouble,
  kBoolean,
  kByte,
  kString,
  kStruct,
};

/// Bytes one element takes on the wire, for the fixed-size kinds; 0 for strings and structs.
std::size_t fixedWireSize(FieldKind kind);
bool isInteger(FieldKind kind);

/// Marks a member that holds no array length.
constexpr std::size_t kNoLengthSlot = static_cast<std::size_t>(-1);

/// One array dimension: a fixed count, or the value of an earlier integer member of the same struct.
struct Dimension {
  bool is_variable = false;
  std::int64_t fixed_count = 0;
  std::size_t length_field = 0;  ///< index of the member holding the count, when is_variable
};

struct Field {
  std::string name;
  FieldKind kind = FieldKind::kInt8;
  std::size_t struct_index = 0;       ///< the member's type in Schema::types(), when kind is kStruct
  std::vector<Dimension> dimensions;  ///< empty for a scalar member
  /// For a member other members take their length from: its place among the struct's length_slots.
  std::size_t length_slot = kNoLengthSlot;
  /// The fewest bytes one element takes on the wire (a string 5: its int32 length and the NUL it counts;
  /// a struct its min_wire_size).
  std::size_t min_element_size = 1;
};

struct StructType {
  std::string name;  ///< without the package, as the generated getTypeName() returns it
  std::vector<Field> fields;
  /// The fewest bytes one encoding of the struct takes, without the type hash: variable arrays empty,
  /// strings empty. Never less than 1, so a count times it bounds the bytes a claim needs.
  std::size_t min_wire_size = 1;
  /// True when every encoding takes exactly min_wire_size bytes (no variable arrays, no strings).
  bool fixed_size = true;
  /// How many of its members hold array lengths.
  std::size_t length_slots = 0;
};

/// A definition file that does not parse, or types that do not fit together.
class SchemaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Schema {
 public:
  /// Reads the types of all `sources` (each the text of one .lcm file; `names` label them in errors,
  /// one per source). Throws SchemaError naming the file, the line and the problem.
  static Schema parse(const std::vector<std::string_view>& sources, const std::vector<std::string>& names);

  const std::vector<StructType>& types() const { return types_; }
  /// The type of that name (without its package), or nullptr.
  const StructType* find(std::string_view name) const;

 private:
  std::vector<StructType> types_;
};

}  // namespace ifar::lcm_wire
