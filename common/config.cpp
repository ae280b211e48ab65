#include "common/config.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ifar::common {
namespace {

template <typename T>
const char* typeName();
template <>
const char* typeName<bool>()
{
  return "boolean (true/false)";
}
template <>
const char* typeName<int>()
{
  return "integer";
}
template <>
const char* typeName<std::int64_t>()
{
  return "integer";
}
template <>
const char* typeName<double>()
{
  return "number";
}
template <>
const char* typeName<std::string>()
{
  return "string";
}
template <>
const char* typeName<std::vector<double>>()
{
  return "list of numbers";
}
template <>
const char* typeName<std::vector<std::string>>()
{
  return "list of strings";
}

std::string joinPath(const std::string& parent, const std::string& key)
{
  return parent.empty() ? key : parent + "." + key;
}

/// A scalar as an error quotes it: its first line, at most 80 characters (a file of another format read as
/// YAML is one long scalar, and a message must not repeat the file).
std::string quoteScalar(const std::string& scalar)
{
  constexpr std::size_t kQuotedLength = 80;
  const std::size_t line_end = scalar.find('\n');
  std::string quoted = scalar.substr(0, std::min(line_end, kQuotedLength));
  if (quoted.size() < scalar.size()) {
    quoted += "...";
  }
  return "'" + quoted + "'";
}

std::string describeValue(const YAML::Node& node)
{
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      return quoteScalar(node.Scalar());
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Null:
      return "nothing";
    default:
      return "an undefined value";
  }
}

// yaml-cpp converts leniently in places (any scalar is a string, 1.0 is not an int but "1" is a double);
// these checks keep the reported expectation exact.
template <typename T>
bool convert(const YAML::Node& node, T& out)
{
  if (!node.IsScalar()) {
    return false;
  }
  try {
    out = node.as<T>();
    return true;
  } catch (const YAML::Exception&) {
    return false;
  }
}

template <typename Element>
bool convertList(const YAML::Node& node, std::vector<Element>& out)
{
  if (!node.IsSequence()) {
    return false;
  }
  out.clear();
  for (const auto& element : node) {
    Element value{};
    if (!convert(element, value)) {
      return false;
    }
    out.push_back(value);
  }
  return true;
}

template <>
bool convert(const YAML::Node& node, std::vector<double>& out)
{
  return convertList(node, out);
}

template <>
bool convert(const YAML::Node& node, std::vector<std::string>& out)
{
  return convertList(node, out);
}

std::vector<std::string> splitKey(const std::string& key)
{
  std::vector<std::string> parts;
  std::stringstream stream(key);
  std::string part;
  while (std::getline(stream, part, '.')) {
    parts.push_back(part);
  }
  return parts;
}

/// The most nodes a document may hold once its aliases are expanded. An alias names a subtree again, so a
/// few hundred bytes of nested aliases expand to billions of nodes and every walk over the tree would never
/// end; the largest world file this project reads (10^5 objects) stays far below this.
constexpr std::size_t kMaxExpandedNodes = 4'000'000;

/// yaml-cpp keeps both entries of a key given twice in one map and lookups see the first: an edit
/// appended to a file would be silently ignored, so a repeated key is an error naming its line. A list or
/// a map used as a key (YAML's "? " complex keys) names no setting and is an error as well. Counts the
/// nodes it walks into `walked` and refuses a document with more than kMaxExpandedNodes.
void rejectDuplicateKeys(const YAML::Node& node, const std::string& path, const std::string& source_name,
                         std::size_t& walked)
{
  if (++walked > kMaxExpandedNodes) {
    throw ConfigError(source_name + ": more than " + std::to_string(kMaxExpandedNodes) +
                      " YAML nodes once its aliases are expanded (near key '" + path +
                      "'): refused as too large (an alias bomb?)");
  }
  if (node.IsMap()) {
    std::set<std::string> seen;
    for (const auto& entry : node) {
      if (entry.first.IsSequence() || entry.first.IsMap()) {
        throw ConfigError(source_name + ":" + std::to_string(entry.first.Mark().line + 1) + ": a key " +
                          (path.empty() ? std::string("at the top level") : "under '" + path + "'") + " is " +
                          describeValue(entry.first) + ", not a name");
      }
      const std::string key = entry.first.Scalar();
      const std::string full_path = joinPath(path, key);
      if (!seen.insert(key).second) {
        std::string message = source_name;
        message += ":" + std::to_string(entry.first.Mark().line + 1);
        message += ": key '" + full_path + "': given twice in the same map";
        throw ConfigError(message);
      }
      rejectDuplicateKeys(entry.second, full_path, source_name, walked);
    }
  } else if (node.IsSequence()) {
    for (std::size_t index = 0; index < node.size(); ++index) {
      rejectDuplicateKeys(node[index], path + "[" + std::to_string(index) + "]", source_name, walked);
    }
  }
}

}  // namespace

ConfigNode::ConfigNode(const YAML::Node& node, std::string path,
                       std::shared_ptr<const std::string> source_name,
                       std::shared_ptr<std::set<std::string>> read_keys,
                       std::shared_ptr<std::map<std::string, std::string>> origins)
    : node_(node),
      path_(std::move(path)),
      source_name_(std::move(source_name)),
      read_keys_(std::move(read_keys)),
      origins_(std::move(origins))
{
}

ConfigNode ConfigNode::loadFile(const std::string& path)
{
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw ConfigError(path + ": is a folder, not a configuration file");
  }
  std::ifstream stream(path);
  if (!stream) {
    throw ConfigError(path + ": cannot open the configuration file");
  }
  std::stringstream text;
  text << stream.rdbuf();
  return loadString(text.str(), path);
}

ConfigNode ConfigNode::loadString(const std::string& text, const std::string& source_name)
{
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& error) {
    throw ConfigError(source_name + ":" + std::to_string(error.mark.line + 1) + ":" +
                      std::to_string(error.mark.column + 1) + ": YAML syntax error: " + error.msg);
  }
  if (root.IsNull()) {
    root = YAML::Node(YAML::NodeType::Map);
  }
  if (!root.IsMap()) {
    throw ConfigError(source_name + ": the top level must be a map of settings, found " +
                      describeValue(root));
  }
  std::size_t walked = 0;
  rejectDuplicateKeys(root, "", source_name, walked);
  return ConfigNode(root, "", std::make_shared<const std::string>(source_name),
                    std::make_shared<std::set<std::string>>(),
                    std::make_shared<std::map<std::string, std::string>>());
}

const std::string& ConfigNode::sourceOf(const std::string& full_path) const
{
  const std::string* source = source_name_.get();
  std::size_t longest = 0;  // the closest set() wins: --set a={b: 1} --set a.b=2 names the second
  for (const auto& [path, origin] : *origins_) {
    const bool at_or_under =
        full_path == path ||
        (full_path.size() > path.size() && full_path.compare(0, path.size(), path) == 0 &&
         (full_path[path.size()] == '.' || full_path[path.size()] == '['));
    if (at_or_under && path.size() > longest) {
      source = &origin;
      longest = path.size();
    }
  }
  return *source;
}

std::string ConfigNode::describe(const std::string& key) const
{
  const std::string full_path = joinPath(path_, key);
  return sourceOf(full_path) + ": key '" + full_path + "'";
}

void ConfigNode::set(const std::string& key, const std::string& value_yaml, const std::string& origin)
{
  const std::vector<std::string> parts = splitKey(key);
  if (key.empty() || key.back() == '.' ||
      std::any_of(parts.begin(), parts.end(), [](const std::string& part) { return part.empty(); })) {
    throw ConfigError(origin + ": '" + key + "' is not a key path (names joined by '.', e.g. lidar.port)");
  }
  YAML::Node value;
  try {
    value = YAML::Load(value_yaml);
  } catch (const YAML::ParserException& error) {
    throw ConfigError(origin + ": the value is not YAML: " + error.msg);
  }
  std::size_t walked = 0;
  rejectDuplicateKeys(value, joinPath(path_, key), origin, walked);
  YAML::Node current = node_;
  std::string full_path = path_;
  for (std::size_t index = 0; index + 1 < parts.size(); ++index) {
    YAML::Node next = current[parts[index]];  // a new entry only once it is given a value
    full_path = joinPath(full_path, parts[index]);
    if (!next.IsDefined() || next.IsNull()) {
      next = YAML::Node(YAML::NodeType::Map);
    } else if (!next.IsMap()) {
      std::string message = origin;
      message += ": key '" + full_path + "' holds " + describeValue(next);
      message += " in " + *source_name_ + ", not a map of settings";
      throw ConfigError(message);
    }
    current.reset(next);  // operator= would overwrite the referenced node's value in the tree
  }
  current[parts.back()] = value;
  (*origins_)[joinPath(path_, key)] = origin;
}

void ConfigNode::fail(const std::string& key, const std::string& problem) const
{
  throw ConfigError(describe(key) + ": " + problem);
}

YAML::Node ConfigNode::lookup(const std::string& key, std::string& full_path) const
{
  YAML::Node current = node_;
  full_path = path_;
  for (const auto& part : splitKey(key)) {
    if (!current.IsMap()) {
      return YAML::Node(YAML::NodeType::Undefined);
    }
    // operator[] on a const node does not insert.
    const YAML::Node& as_const = current;
    YAML::Node next = as_const[part];
    full_path = joinPath(full_path, part);
    read_keys_->insert(full_path);
    if (!next.IsDefined()) {
      return next;
    }
    current.reset(next);  // operator= would overwrite the referenced node's value in the tree
  }
  return current;
}

bool ConfigNode::has(const std::string& key) const
{
  std::string full_path;
  const YAML::Node value = lookup(key, full_path);
  return value.IsDefined() && !value.IsNull();
}

template <typename T>
T ConfigNode::required(const std::string& key) const
{
  std::string full_path;
  const YAML::Node value = lookup(key, full_path);
  if (!value.IsDefined() || value.IsNull()) {
    fail(key, std::string("missing required key (expected ") + typeName<T>() + ")");
  }
  T result{};
  if (!convert(value, result)) {
    fail(key, std::string("expected ") + typeName<T>() + ", got " + describeValue(value));
  }
  return result;
}

template <typename T>
T ConfigNode::optional(const std::string& key, const T& fallback) const
{
  return has(key) ? required<T>(key) : fallback;
}

double ConfigNode::requiredPositive(const std::string& key) const
{
  const double value = required<double>(key);
  if (!(value > 0.0)) {
    fail(key, "must be greater than zero, got " + std::to_string(value));
  }
  return value;
}

double ConfigNode::optionalPositive(const std::string& key, double fallback) const
{
  return has(key) ? requiredPositive(key) : fallback;
}

ConfigNode ConfigNode::child(const std::string& key) const
{
  std::string full_path;
  const YAML::Node value = lookup(key, full_path);
  if (!value.IsDefined() || value.IsNull()) {
    fail(key, "missing required section (expected a map)");
  }
  if (!value.IsMap()) {
    fail(key, "expected a map, got " + describeValue(value));
  }
  return ConfigNode(value, full_path, source_name_, read_keys_, origins_);
}

std::vector<ConfigNode> ConfigNode::sequence(const std::string& key) const
{
  std::string full_path;
  const YAML::Node value = lookup(key, full_path);
  std::vector<ConfigNode> elements;
  if (!value.IsDefined() || value.IsNull()) {
    return elements;
  }
  if (!value.IsSequence()) {
    fail(key, "expected a list, got " + describeValue(value));
  }
  for (std::size_t index = 0; index < value.size(); ++index) {
    const std::string element_path = full_path + "[" + std::to_string(index) + "]";
    read_keys_->insert(element_path);
    elements.push_back(ConfigNode(value[index], element_path, source_name_, read_keys_, origins_));
  }
  return elements;
}

std::vector<std::string> ConfigNode::keys() const
{
  std::vector<std::string> result;
  if (node_.IsMap()) {
    for (const auto& entry : node_) {
      result.push_back(entry.first.as<std::string>());
    }
  }
  return result;
}

void ConfigNode::collectUnread(const YAML::Node& node, const std::string& path,
                               std::vector<std::string>& out) const
{
  if (node.IsMap()) {
    for (const auto& entry : node) {
      const std::string key_path = joinPath(path, entry.first.as<std::string>());
      if (read_keys_->count(key_path) == 0) {
        out.push_back(key_path);
      } else {
        collectUnread(entry.second, key_path, out);
      }
    }
  } else if (node.IsSequence()) {
    for (std::size_t index = 0; index < node.size(); ++index) {
      const std::string element_path = path + "[" + std::to_string(index) + "]";
      // Lists of scalars are read whole; lists of maps are walked through sequence().
      if (read_keys_->count(element_path) != 0) {
        collectUnread(node[index], element_path, out);
      }
    }
  }
}

void ConfigNode::rejectUnknownKeys() const
{
  std::vector<std::string> unread;
  collectUnread(node_, path_, unread);
  if (!unread.empty()) {
    std::string message =
        sourceOf(unread.front()) + ": key '" + unread.front() + "': unknown key (no setting has this name";
    if (unread.size() > 1) {
      message += "; " + std::to_string(unread.size() - 1) + " more unknown key(s)";
    }
    throw ConfigError(message + ")");
  }
}

void ConfigNode::acceptAllUnder(const std::string& key) const
{
  std::string full_path;
  const YAML::Node value = lookup(key, full_path);
  if (!value.IsDefined()) {
    return;
  }
  // Record every nested key as read.
  std::vector<std::pair<YAML::Node, std::string>> pending{{value, full_path}};
  while (!pending.empty()) {
    auto [node, path] = pending.back();
    pending.pop_back();
    if (node.IsMap()) {
      for (const auto& entry : node) {
        const std::string key_path = joinPath(path, entry.first.as<std::string>());
        read_keys_->insert(key_path);
        pending.emplace_back(entry.second, key_path);
      }
    } else if (node.IsSequence()) {
      for (std::size_t index = 0; index < node.size(); ++index) {
        const std::string element_path = path + "[" + std::to_string(index) + "]";
        read_keys_->insert(element_path);
        pending.emplace_back(node[index], element_path);
      }
    }
  }
}

template bool ConfigNode::required<bool>(const std::string&) const;
template int ConfigNode::required<int>(const std::string&) const;
template std::int64_t ConfigNode::required<std::int64_t>(const std::string&) const;
template double ConfigNode::required<double>(const std::string&) const;
template std::string ConfigNode::required<std::string>(const std::string&) const;
template std::vector<double> ConfigNode::required<std::vector<double>>(const std::string&) const;
template std::vector<std::string> ConfigNode::required<std::vector<std::string>>(const std::string&) const;
template bool ConfigNode::optional<bool>(const std::string&, const bool&) const;
template int ConfigNode::optional<int>(const std::string&, const int&) const;
template std::int64_t ConfigNode::optional<std::int64_t>(const std::string&, const std::int64_t&) const;
template double ConfigNode::optional<double>(const std::string&, const double&) const;
template std::string ConfigNode::optional<std::string>(const std::string&, const std::string&) const;
template std::vector<double> ConfigNode::optional<std::vector<double>>(const std::string&,
                                                                       const std::vector<double>&) const;
template std::vector<std::string> ConfigNode::optional<std::vector<std::string>>(
    const std::string&, const std::vector<std::string>&) const;

}  // namespace ifar::common
