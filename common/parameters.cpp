#include "common/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace ifar::common {
namespace {

std::string withUnit(const std::string& number, const std::string& unit)
{
  return unit.empty() ? number : number + " " + unit;
}

bool bounded(double value)
{
  return std::isfinite(value);
}

/// The declared range cut down to what the field's integer type holds.
ParameterRange integerRange(const ParameterInfo& info)
{
  ParameterRange range = info.range;
  if (!(range.low >= static_cast<double>(info.integer_min))) {
    range.low = static_cast<double>(info.integer_min);
    range.low_inclusive = true;
  }
  if (!(range.high <= static_cast<double>(info.integer_max))) {
    range.high = static_cast<double>(info.integer_max);
    range.high_inclusive = true;
  }
  return range;
}

std::string joinNames(const std::vector<std::string>& names, const std::string& before,
                      const std::string& after)
{
  std::string out;
  for (std::size_t index = 0; index < names.size(); ++index) {
    out += index == 0 ? "" : ", ";
    out += before;
    out += names[index];
    out += after;
  }
  return out;
}

const char* typeName(ParameterType type)
{
  switch (type) {
    case ParameterType::boolean:
      return "boolean";
    case ParameterType::integer:
      return "integer";
    case ParameterType::real:
      return "real";
    case ParameterType::text:
      return "text";
    case ParameterType::choice:
      return "choice";
  }
  return "?";
}

std::string rangeCell(const ParameterInfo& info)
{
  switch (info.type) {
    case ParameterType::boolean:
      return "";
    case ParameterType::choice:
      return joinNames(info.names, "`", "`");
    case ParameterType::text:
      return info.range.non_empty ? "not empty" : "";
    case ParameterType::integer:
    case ParameterType::real:
      break;
  }
  return info.range.describe();
}

std::string escapeCell(const std::string& text)
{
  std::string out;
  for (const char character : text) {
    out += character == '|' ? std::string("\\|") : std::string(1, character);
  }
  return out;
}

ParameterValue readNumber(const ConfigNode& node, const ParameterInfo& info)
{
  if (info.type == ParameterType::integer) {
    const auto value = node.required<std::int64_t>(info.key);
    // The declared range first: its message is the one a reader expects; then what the field holds.
    const ParameterRange range =
        info.range.contains(static_cast<double>(value)) ? integerRange(info) : info.range;
    if (!range.contains(static_cast<double>(value))) {
      node.fail(info.key, range.requirement(info.unit) + ", got " + std::to_string(value));
    }
    return value;
  }
  const auto value = node.required<double>(info.key);
  if (!std::isfinite(value) || !info.range.contains(value)) {
    node.fail(info.key, info.range.requirement(info.unit) + ", got " + formatNumber(value));
  }
  return value;
}

}  // namespace

bool ParameterRange::contains(double value) const
{
  const bool above_low = low_inclusive ? value >= low : value > low;
  const bool below_high = high_inclusive ? value <= high : value < high;
  return above_low && below_high;
}

std::string ParameterRange::describe() const
{
  if (non_empty) {
    return "not empty";
  }
  if (bounded(low) && bounded(high)) {
    return std::string(low_inclusive ? "[" : "(") + formatNumber(low) + ", " + formatNumber(high) +
           (high_inclusive ? "]" : ")");
  }
  if (bounded(low)) {
    return std::string(low_inclusive ? ">= " : "> ") + formatNumber(low);
  }
  if (bounded(high)) {
    return std::string(high_inclusive ? "<= " : "< ") + formatNumber(high);
  }
  return "any";
}

std::string ParameterRange::requirement(const std::string& unit) const
{
  if (non_empty) {
    return "must not be empty";
  }
  if (bounded(low) && bounded(high)) {
    return "must be in " + withUnit(describe(), unit);
  }
  if (bounded(low)) {
    return std::string(low_inclusive ? "must be at least " : "must be greater than ") +
           withUnit(formatNumber(low), unit);
  }
  if (bounded(high)) {
    return std::string(high_inclusive ? "must be at most " : "must be less than ") +
           withUnit(formatNumber(high), unit);
  }
  return "must be a finite number";
}

ParameterValue readParameter(const ConfigNode& node, const ParameterInfo& info, const ParameterValue& current)
{
  if (!info.required && !node.has(info.key)) {
    return current;
  }
  switch (info.type) {
    case ParameterType::boolean:
      return node.required<bool>(info.key);
    case ParameterType::integer:
    case ParameterType::real:
      return readNumber(node, info);
    case ParameterType::text: {
      auto value = node.required<std::string>(info.key);
      if (info.range.non_empty && value.empty()) {
        node.fail(info.key, info.range.requirement(info.unit));
      }
      return value;
    }
    case ParameterType::choice: {
      auto value = node.required<std::string>(info.key);
      if (std::find(info.names.begin(), info.names.end(), value) == info.names.end()) {
        node.fail(info.key, "must be one of " + joinNames(info.names, "", "") + ", got '" + value + "'");
      }
      return value;
    }
  }
  return current;
}

std::string formatNumber(double value)
{
  // At least as many digits as the integer part has, so 200 is "200", not "2e+02".
  const int integer_digits = std::isfinite(value) && std::abs(value) >= 1.0
                                 ? static_cast<int>(std::floor(std::log10(std::abs(value)))) + 1
                                 : 1;
  char buffer[64];
  for (int precision = std::min(integer_digits, 17); precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof(buffer), "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) {
      break;
    }
  }
  return buffer;
}

std::string yamlValue(const ParameterInfo& info, const ParameterValue& value)
{
  switch (info.type) {
    case ParameterType::boolean:
      return std::get<bool>(value) ? "true" : "false";
    case ParameterType::integer:
      return std::to_string(std::get<std::int64_t>(value));
    case ParameterType::choice:
      return std::get<std::string>(value);
    case ParameterType::text: {
      std::string out = "\"";
      for (const char character : std::get<std::string>(value)) {
        out += (character == '"' || character == '\\') ? std::string("\\") + character
                                                       : std::string(1, character);
      }
      return out + "\"";
    }
    case ParameterType::real:
      break;
  }
  // A point in every real, before any exponent, so YAML 1.1 readers take it for a float too.
  std::string text = formatNumber(std::get<double>(value));
  if (text.find_first_of(".ni") == std::string::npos) {
    const std::size_t exponent = text.find('e');
    text.insert(exponent == std::string::npos ? text.size() : exponent, ".0");
  }
  return text;
}

std::string parameterMarkdown(const std::vector<ParameterInfo>& infos,
                              const std::vector<ParameterValue>& defaults)
{
  std::ostringstream out;
  out << "| Key | Type | Unit | Default | Range | Meaning |\n| --- | --- | --- | --- | --- | --- |\n";
  for (std::size_t index = 0; index < infos.size(); ++index) {
    const ParameterInfo& info = infos[index];
    const std::string default_cell =
        info.required ? "required" : "`" + yamlValue(info, defaults[index]) + "`";
    out << "| `" << info.key << "` | " << typeName(info.type) << " | " << info.unit << " | " << default_cell
        << " | " << rangeCell(info) << " | " << escapeCell(info.meaning) << " |\n";
  }
  return out.str();
}

std::size_t ConfigDump::childNamed(std::size_t parent, const std::string& name)
{
  for (const std::size_t child : nodes_[parent].children) {
    if (!nodes_[child].is_note && nodes_[child].name == name) {
      return child;
    }
  }
  Node node;
  node.name = name;
  nodes_.push_back(node);
  nodes_[parent].children.push_back(nodes_.size() - 1);
  return nodes_.size() - 1;
}

void ConfigDump::add(const std::string& path, const std::string& yaml_value, const std::string& comment)
{
  std::size_t node = 0;
  std::stringstream parts(path);
  std::string part;
  while (std::getline(parts, part, '.')) {
    node = childNamed(node, part);
  }
  nodes_[node].leaf = true;
  nodes_[node].value = yaml_value;
  nodes_[node].comment = comment;
}

void ConfigDump::note(const std::string& comment)
{
  Node node;
  node.is_note = true;
  node.comment = comment;
  nodes_.push_back(node);
  nodes_[0].children.push_back(nodes_.size() - 1);
}

void ConfigDump::write(std::size_t node, int depth, std::string& out) const
{
  const std::string indent(static_cast<std::size_t>(depth) * 2, ' ');
  for (const std::size_t child : nodes_[node].children) {
    const Node& entry = nodes_[child];
    if (entry.is_note) {
      out += indent + "# " + entry.comment + "\n";
    } else if (entry.leaf) {
      out += indent + entry.name + ": " + entry.value +
             (entry.comment.empty() ? "" : "  # " + entry.comment) + "\n";
    } else {
      out += indent + entry.name + ":\n";
      write(child, depth + 1, out);
    }
  }
}

std::string ConfigDump::yaml() const
{
  std::string out;
  write(0, 0, out);
  return out;
}

}  // namespace ifar::common
