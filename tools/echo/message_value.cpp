#include "tools/echo/message_value.hpp"

#include <cstring>
#include <optional>

#include "common/byte_order.hpp"
#include "common/lcm_wire/claim_check.hpp"
#include "tools/echo/schema_fingerprint.hpp"

namespace ifar::echo {
namespace {

using lcm_wire::FieldKind;

constexpr std::size_t kFingerprintSize = 8;

/// Reads members in wire order. The claims were checked first, so every read is backed; each read still
/// checks, so a schema and bytes that disagree end in an error, not a read past the end.
class ValueReader {
 public:
  ValueReader(const lcm_wire::Schema& schema, common::ByteView bytes) : schema_(schema), bytes_(bytes) {}

  std::optional<Members> readStruct(const lcm_wire::StructType& type)
  {
    Members members;
    members.reserve(type.fields.size());
    for (const lcm_wire::Field& field : type.fields) {
      std::optional<Value> value = readDimension(type, field, members, 0);
      if (!value) {
        return std::nullopt;
      }
      members.emplace_back(field.name, std::move(*value));
    }
    return members;
  }

  std::size_t position() const { return position_; }
  void skip(std::size_t count) { position_ += count; }

 private:
  /// The member's array from dimension `depth` on (the scalar itself past the last dimension).
  std::optional<Value> readDimension(const lcm_wire::StructType& type, const lcm_wire::Field& field,
                                     const Members& earlier, std::size_t depth)
  {
    if (depth == field.dimensions.size()) {
      return readScalar(field);
    }
    const lcm_wire::Dimension& dimension = field.dimensions[depth];
    const std::int64_t count =
        dimension.is_variable ? earlier[dimension.length_field].second.integer : dimension.fixed_count;
    // Every element takes at least one byte.
    if (count < 0 || static_cast<std::uint64_t>(count) > bytes_.size() - position_) {
      return std::nullopt;
    }
    const auto elements = static_cast<std::size_t>(count);
    Value list;
    if (field.kind == FieldKind::kByte && depth + 1 == field.dimensions.size()) {
      list.kind = Value::Kind::kBytes;
      list.text.assign(reinterpret_cast<const char*>(bytes_.data() + position_), elements);
      position_ += elements;
      return list;
    }
    list.kind = Value::Kind::kList;
    list.elements.reserve(elements);
    for (std::size_t element = 0; element < elements; ++element) {
      std::optional<Value> value = readDimension(type, field, earlier, depth + 1);
      if (!value) {
        return std::nullopt;
      }
      list.elements.push_back(std::move(*value));
    }
    return list;
  }

  std::optional<Value> readScalar(const lcm_wire::Field& field)
  {
    Value value;
    const std::size_t size = lcm_wire::fixedWireSize(field.kind);
    if (field.kind == FieldKind::kStruct) {
      std::optional<Members> members = readStruct(schema_.types()[field.struct_index]);
      if (!members) {
        return std::nullopt;
      }
      value.kind = Value::Kind::kStruct;
      value.members = std::move(*members);
      return value;
    }
    if (field.kind == FieldKind::kString) {
      if (!take(4)) {
        return std::nullopt;
      }
      const auto length = static_cast<std::int32_t>(common::readUint32Be(bytes_.data() + position_ - 4));
      if (length < 1 || static_cast<std::size_t>(length) > bytes_.size() - position_) {
        return std::nullopt;
      }
      value.kind = Value::Kind::kString;
      // The length counts the NUL at the end, which is not part of the string.
      value.text.assign(reinterpret_cast<const char*>(bytes_.data() + position_),
                        static_cast<std::size_t>(length) - 1);
      position_ += static_cast<std::size_t>(length);
      return value;
    }
    if (!take(size)) {
      return std::nullopt;
    }
    const std::uint8_t* data = bytes_.data() + position_ - size;
    switch (field.kind) {
      case FieldKind::kByte:
        value.integer = data[0];
        break;
      case FieldKind::kInt8:
        value.integer = data[0] < 0x80 ? data[0] : data[0] - 0x100;  // two's complement
        break;
      case FieldKind::kInt16:
        value.integer = static_cast<std::int16_t>(common::readUint16Be(data));
        break;
      case FieldKind::kInt32:
        value.integer = static_cast<std::int32_t>(common::readUint32Be(data));
        break;
      case FieldKind::kInt64:
        value.integer = static_cast<std::int64_t>(common::readUint64Be(data));
        break;
      case FieldKind::kBoolean:
        value.kind = Value::Kind::kBoolean;
        value.boolean = data[0] != 0;
        break;
      case FieldKind::kFloat: {
        const std::uint32_t bits = common::readUint32Be(data);
        float real = 0.0F;
        std::memcpy(&real, &bits, sizeof(real));
        value.kind = Value::Kind::kFloat;
        value.real = real;
        break;
      }
      case FieldKind::kDouble: {
        const std::uint64_t bits = common::readUint64Be(data);
        std::memcpy(&value.real, &bits, sizeof(value.real));
        value.kind = Value::Kind::kDouble;
        break;
      }
      default:
        return std::nullopt;
    }
    return value;
  }

  bool take(std::size_t count)
  {
    if (count > bytes_.size() - position_) {
      return false;
    }
    position_ += count;
    return true;
  }

  const lcm_wire::Schema& schema_;
  common::ByteView bytes_;
  std::size_t position_ = 0;
};

}  // namespace

MessageTypes::MessageTypes(const lcm_wire::Schema& schema) : schema_(schema)
{
  for (const lcm_wire::StructType& type : schema.types()) {
    by_fingerprint_[fingerprintOf(schema, type)] = &type;
  }
}

const lcm_wire::StructType* MessageTypes::typeOf(common::ByteView message) const
{
  if (message.size() < kFingerprintSize) {
    return nullptr;
  }
  const auto found = by_fingerprint_.find(static_cast<std::int64_t>(common::readUint64Be(message.data())));
  return found == by_fingerprint_.end() ? nullptr : found->second;
}

std::variant<Members, std::string> MessageTypes::decode(const lcm_wire::StructType& type,
                                                        common::ByteView message) const
{
  if (std::optional<std::string> claim = lcm_wire::findUnbackedClaim(schema_, type, message)) {
    return *claim;
  }
  ValueReader reader(schema_, message);
  reader.skip(kFingerprintSize);
  std::optional<Members> members = reader.readStruct(type);
  if (!members) {
    return type.name + " does not decode: its bytes do not fit its definition";
  }
  return std::move(*members);
}

}  // namespace ifar::echo
