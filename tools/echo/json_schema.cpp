#include "tools/echo/json_schema.hpp"

#include "common/json_text.hpp"

namespace ifar::echo {
namespace {

using lcm_wire::FieldKind;

std::string structSchema(const lcm_wire::Schema& schema, const lcm_wire::StructType& type);

/// The schema of one element of `field`, past its array dimensions.
std::string scalarSchema(const lcm_wire::Schema& schema, const lcm_wire::Field& field)
{
  switch (field.kind) {
    case FieldKind::kInt8:
    case FieldKind::kInt16:
    case FieldKind::kInt32:
    case FieldKind::kInt64:
    case FieldKind::kByte:
      return R"({"type":"integer"})";
    case FieldKind::kFloat:
    case FieldKind::kDouble:
      return R"({"type":"number","description":"null when NaN or infinite"})";
    case FieldKind::kBoolean:
      return R"({"type":"boolean"})";
    case FieldKind::kString:
      return R"({"type":"string"})";
    case FieldKind::kStruct:
      return structSchema(schema, schema.types()[field.struct_index]);
  }
  return "{}";
}

/// The schema of `field` from array dimension `depth` on, as message_value.cpp reads it: the innermost
/// dimension of a byte array is one string of hex digits.
std::string memberSchema(const lcm_wire::Schema& schema, const lcm_wire::Field& field, std::size_t depth)
{
  if (depth == field.dimensions.size()) {
    return scalarSchema(schema, field);
  }
  const lcm_wire::Dimension& dimension = field.dimensions[depth];
  if (field.kind == FieldKind::kByte && depth + 1 == field.dimensions.size()) {
    std::string text = R"({"type":"string","contentEncoding":"base16")";
    if (!dimension.is_variable) {
      const std::string digits = std::to_string(2 * dimension.fixed_count);
      text += ",\"minLength\":" + digits + ",\"maxLength\":" + digits;
    }
    return text + "}";
  }
  std::string text = R"({"type":"array","items":)" + memberSchema(schema, field, depth + 1);
  if (!dimension.is_variable) {
    const std::string count = std::to_string(dimension.fixed_count);
    text += ",\"minItems\":" + count + ",\"maxItems\":" + count;
  }
  return text + "}";
}

std::string structSchema(const lcm_wire::Schema& schema, const lcm_wire::StructType& type)
{
  std::string properties;
  std::string required;
  for (const lcm_wire::Field& field : type.fields) {
    const std::string name = common::jsonString(field.name);
    properties += (properties.empty() ? "" : ",") + name + ":" + memberSchema(schema, field, 0);
    required += (required.empty() ? "" : ",") + name;
  }
  return R"({"type":"object","title":)" + common::jsonString(type.name) + R"(,"properties":{)" + properties +
         R"(},"required":[)" + required + "]}";
}

}  // namespace

std::string jsonSchemaOf(const lcm_wire::Schema& schema, const lcm_wire::StructType& type)
{
  std::string text = structSchema(schema, type);
  // The dialect once, at the root.
  text.insert(1, R"("$schema":"https://json-schema.org/draft/2020-12/schema",)");
  return text;
}

}  // namespace ifar::echo
