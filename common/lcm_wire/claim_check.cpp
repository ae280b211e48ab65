#include "common/lcm_wire/claim_check.hpp"

#include <array>
#include <cstdint>
#include <vector>

#include "common/byte_order.hpp"

namespace ifar::lcm_wire {

namespace {

constexpr std::size_t kHashSize = 8;

/// Walks the bytes member by member as the generated decode would, without allocating. Errors name
/// the member relative to the struct being walked; each enclosing struct prefixes its own member.
class ClaimWalker {
 public:
  ClaimWalker(const Schema& schema, common::ByteView bytes) : schema_(schema), bytes_(bytes) {}

  std::optional<std::string> walkStruct(const StructType& type, std::size_t& position) const
  {
    // The values of the members that hold array lengths; on the stack for the few every type has.
    constexpr std::size_t kStackSlots = 8;
    std::array<std::int64_t, kStackSlots> stack_lengths{};
    std::vector<std::int64_t> heap_lengths;
    std::int64_t* lengths = stack_lengths.data();
    if (type.length_slots > kStackSlots) {
      heap_lengths.resize(type.length_slots);
      lengths = heap_lengths.data();
    }
    for (const Field& field : type.fields) {
      const std::size_t left = bytes_.size() - position;
      std::int64_t count = 1;
      for (const Dimension& dimension : field.dimensions) {
        count *= dimension.is_variable ? lengths[type.fields[dimension.length_field].length_slot]
                                       : dimension.fixed_count;
      }
      if (count < 0) {
        return field.name + " claims " + std::to_string(count) + " elements at byte " +
               std::to_string(position);
      }
      const std::size_t element_size = field.min_element_size;
      // Each element takes at least one byte, so a count beyond the bytes left is refused before it is
      // multiplied (an int64 length member could overflow the product).
      if (static_cast<std::uint64_t>(count) > left || static_cast<std::size_t>(count) * element_size > left) {
        const std::string rest =
            " at byte " + std::to_string(position) + ", " + std::to_string(left) + " bytes left";
        if (!isVariable(field)) {
          return field.name + " is cut off: needs at least " +
                 std::to_string(static_cast<std::size_t>(count) * element_size) + " bytes" + rest;
        }
        return field.name + " claims " + std::to_string(count) + " elements of at least " +
               std::to_string(element_size) + " bytes" + rest;
      }
      const auto elements = static_cast<std::size_t>(count);
      if (field.kind == FieldKind::kString) {
        for (std::size_t element = 0; element < elements; ++element) {
          if (auto problem = walkString(position)) {
            return field.name + indexText(field, element) + " " + *problem;
          }
        }
      } else if (field.kind == FieldKind::kStruct && !schema_.types()[field.struct_index].fixed_size) {
        const StructType& element_type = schema_.types()[field.struct_index];
        for (std::size_t element = 0; element < elements; ++element) {
          if (auto problem = walkStruct(element_type, position)) {
            return field.name + indexText(field, element) + "." + *problem;
          }
        }
      } else {
        if (field.length_slot != kNoLengthSlot) {
          lengths[field.length_slot] = readInteger(field.kind, position);
        }
        position += elements * element_size;  // fixed-size elements: all backed, as checked above
      }
    }
    return std::nullopt;
  }

 private:
  static bool isVariable(const Field& field)
  {
    return !field.dimensions.empty() && field.dimensions.front().is_variable;
  }

  static std::string indexText(const Field& field, std::size_t element)
  {
    return field.dimensions.empty() ? std::string() : "[" + std::to_string(element) + "]";
  }

  /// The generated decode reads the int32 length (which counts the NUL) and then that many bytes.
  std::optional<std::string> walkString(std::size_t& position) const
  {
    if (bytes_.size() - position < 4) {
      return "has its length cut off at byte " + std::to_string(position);
    }
    const auto length = static_cast<std::int32_t>(common::readUint32Be(bytes_.data() + position));
    position += 4;
    const std::size_t left = bytes_.size() - position;
    if (length < 1 || static_cast<std::size_t>(length) > left) {
      return "claims a string of " + std::to_string(length) + " bytes (its NUL included) at byte " +
             std::to_string(position - 4) + ", " + std::to_string(left) + " bytes left";
    }
    position += static_cast<std::size_t>(length);
    return std::nullopt;
  }

  std::int64_t readInteger(FieldKind kind, std::size_t position) const
  {
    const std::uint8_t* data = bytes_.data() + position;
    switch (kind) {
      case FieldKind::kByte:
        return data[0];
      case FieldKind::kInt8:
        return static_cast<std::int8_t>(data[0]);
      case FieldKind::kInt16:
        return static_cast<std::int16_t>(common::readUint16Be(data));
      case FieldKind::kInt32:
        return static_cast<std::int32_t>(common::readUint32Be(data));
      case FieldKind::kInt64:
        return static_cast<std::int64_t>(common::readUint64Be(data));
      default:
        return 0;
    }
  }

  const Schema& schema_;
  common::ByteView bytes_;
};

/// Walks the whole message; `position` ends where it does when every claim is backed.
std::optional<std::string> walkMessage(const Schema& schema, const StructType& type, common::ByteView message,
                                       std::size_t& position)
{
  if (message.size() < kHashSize) {
    return type.name + " needs its 8-byte type hash, " + std::to_string(message.size()) + " bytes given";
  }
  position = kHashSize;
  if (auto problem = ClaimWalker(schema, message).walkStruct(type, position)) {
    return type.name + "." + *problem;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> findUnbackedClaim(const Schema& schema, const StructType& type,
                                             common::ByteView message)
{
  std::size_t position = 0;
  return walkMessage(schema, type, message, position);
}

std::optional<std::size_t> encodedLength(const Schema& schema, const StructType& type,
                                         common::ByteView message)
{
  std::size_t position = 0;
  if (walkMessage(schema, type, message, position)) {
    return std::nullopt;
  }
  return position;
}

}  // namespace ifar::lcm_wire
