#include "tools/replay_test/message_comparison.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <variant>

namespace ifar::replay_test {
namespace {

using echo::Members;
using echo::Value;

std::string realText(double value)
{
  std::array<char, 40> text{};
  const auto result = std::to_chars(text.begin(), text.end(), value);
  return std::string(text.data(), result.ptr);
}

std::string valueText(const Value& value)
{
  switch (value.kind) {
    case Value::Kind::kInteger:
      return std::to_string(value.integer);
    case Value::Kind::kDouble:
    case Value::Kind::kFloat:
      return realText(value.real);
    case Value::Kind::kBoolean:
      return value.boolean ? "true" : "false";
    case Value::Kind::kString:
      return "\"" + value.text + "\"";
    case Value::Kind::kBytes:
      return std::to_string(value.text.size()) + " bytes";
    case Value::Kind::kList:
      return std::to_string(value.elements.size()) + " elements";
    case Value::Kind::kStruct:
      return "a struct";
  }
  return "";
}

class Comparison {
 public:
  explicit Comparison(const ComparisonSettings& settings) : settings_(settings) {}

  std::string members(const std::string& type_name, const Members& recorded, const Members& replayed,
                      const std::string& prefix) const
  {
    for (std::size_t index = 0; index < recorded.size() && index < replayed.size(); ++index) {
      const std::string& name = recorded[index].first;
      std::string qualified = type_name;
      qualified.append(".").append(name);
      if (prefix.empty() && settings_.ignored.count(qualified) > 0) {
        continue;
      }
      std::string where = prefix;
      if (!where.empty()) {
        where += '.';
      }
      where += name;
      std::string difference = value(recorded[index].second, replayed[index].second, where, type_name);
      if (!difference.empty()) {
        return difference;
      }
    }
    return {};
  }

 private:
  std::string value(const Value& recorded, const Value& replayed, const std::string& where,
                    const std::string& type_name) const
  {
    const auto differs = [&] {
      return where + ": recorded " + valueText(recorded) + ", replayed " + valueText(replayed);
    };
    if (recorded.kind != replayed.kind) {
      return differs();
    }
    switch (recorded.kind) {
      case Value::Kind::kInteger:
        return recorded.integer == replayed.integer ? std::string() : differs();
      case Value::Kind::kDouble:
      case Value::Kind::kFloat: {
        const bool both_nan = std::isnan(recorded.real) && std::isnan(replayed.real);
        const bool same = both_nan || recorded.real == replayed.real ||
                          std::fabs(recorded.real - replayed.real) <= settings_.tolerance;
        return same ? std::string() : differs();
      }
      case Value::Kind::kBoolean:
        return recorded.boolean == replayed.boolean ? std::string() : differs();
      case Value::Kind::kString:
      case Value::Kind::kBytes:
        return recorded.text == replayed.text ? std::string() : differs();
      case Value::Kind::kList: {
        if (recorded.elements.size() != replayed.elements.size()) {
          return differs();
        }
        for (std::size_t index = 0; index < recorded.elements.size(); ++index) {
          std::string element = where;
          element.append("[").append(std::to_string(index)).append("]");
          std::string difference =
              value(recorded.elements[index], replayed.elements[index], element, type_name);
          if (!difference.empty()) {
            return difference;
          }
        }
        return {};
      }
      case Value::Kind::kStruct:
        return members(type_name, recorded.members, replayed.members, where);
    }
    return {};
  }

  const ComparisonSettings& settings_;
};

}  // namespace

std::string firstDifference(const echo::MessageTypes& types, common::ByteView recorded,
                            common::ByteView replayed, const ComparisonSettings& settings)
{
  const lcm_wire::StructType* recorded_type = types.typeOf(recorded);
  const lcm_wire::StructType* replayed_type = types.typeOf(replayed);
  if (recorded_type == nullptr || replayed_type == nullptr) {
    return "not a project type";
  }
  if (recorded_type != replayed_type) {
    return "type: recorded " + recorded_type->name + ", replayed " + replayed_type->name;
  }
  auto recorded_members = types.decode(*recorded_type, recorded);
  auto replayed_members = types.decode(*replayed_type, replayed);
  if (const auto* problem = std::get_if<std::string>(&recorded_members)) {
    return "the recorded message does not decode: " + *problem;
  }
  if (const auto* problem = std::get_if<std::string>(&replayed_members)) {
    return "the replayed message does not decode: " + *problem;
  }
  return Comparison(settings).members(recorded_type->name, std::get<Members>(recorded_members),
                                      std::get<Members>(replayed_members), "");
}

}  // namespace ifar::replay_test
