#include "tools/echo/schema_fingerprint.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace ifar::echo {
namespace {

using lcm_wire::FieldKind;

// lcm-gen's hash step on a signed 64-bit value: shift left 8, xor the value arithmetically shifted right
// 55, add the character.
std::uint64_t hashStep(std::uint64_t value, char character)
{
  const auto arithmetic_shift = static_cast<std::uint64_t>(static_cast<std::int64_t>(value) >> 55);
  return ((value << 8U) ^ arithmetic_shift) +
         static_cast<std::uint64_t>(static_cast<std::int64_t>(character));
}

std::uint64_t hashText(std::uint64_t value, const std::string& text)
{
  value = hashStep(value, static_cast<char>(text.size()));
  for (const char character : text) {
    value = hashStep(value, character);
  }
  return value;
}

const char* primitiveName(FieldKind kind)
{
  switch (kind) {
    case FieldKind::kInt8:
      return "int8_t";
    case FieldKind::kInt16:
      return "int16_t";
    case FieldKind::kInt32:
      return "int32_t";
    case FieldKind::kInt64:
      return "int64_t";
    case FieldKind::kFloat:
      return "float";
    case FieldKind::kDouble:
      return "double";
    case FieldKind::kBoolean:
      return "boolean";
    case FieldKind::kByte:
      return "byte";
    case FieldKind::kString:
      return "string";
    case FieldKind::kStruct:
      return nullptr;
  }
  return nullptr;
}

/// The hash of the type's own members, without the types it holds.
std::uint64_t memberHash(const lcm_wire::StructType& type)
{
  constexpr std::uint64_t kSeed = 0x12345678;
  constexpr char kConstantDimension = 0;
  constexpr char kVariableDimension = 1;
  std::uint64_t value = kSeed;
  for (const lcm_wire::Field& field : type.fields) {
    value = hashText(value, field.name);
    if (const char* primitive = primitiveName(field.kind)) {
      value = hashText(value, primitive);
    }
    value = hashStep(value, static_cast<char>(field.dimensions.size()));
    for (const lcm_wire::Dimension& dimension : field.dimensions) {
      value = hashStep(value, dimension.is_variable ? kVariableDimension : kConstantDimension);
      value = hashText(value, dimension.is_variable ? type.fields[dimension.length_field].name
                                                    : std::to_string(dimension.fixed_count));
    }
  }
  return value;
}

std::uint64_t recursiveHash(const lcm_wire::Schema& schema, std::size_t type_index,
                            std::vector<std::size_t>& parents)
{
  if (std::find(parents.begin(), parents.end(), type_index) != parents.end()) {
    return 0;
  }
  parents.push_back(type_index);
  const lcm_wire::StructType& type = schema.types()[type_index];
  std::uint64_t hash = memberHash(type);
  for (const lcm_wire::Field& field : type.fields) {
    if (field.kind == FieldKind::kStruct) {
      hash += recursiveHash(schema, field.struct_index, parents);
    }
  }
  parents.pop_back();
  return (hash << 1U) + ((hash >> 63U) & 1U);
}

}  // namespace

std::int64_t fingerprintOf(const lcm_wire::Schema& schema, const lcm_wire::StructType& type)
{
  const auto index = static_cast<std::size_t>(&type - schema.types().data());
  std::vector<std::size_t> parents;
  return static_cast<std::int64_t>(recursiveHash(schema, index, parents));
}

}  // namespace ifar::echo
