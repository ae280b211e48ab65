#pragma once
// Strict YAML configuration: every key a component reads is declared by reading it, and whatever the
// file holds beyond that is an error. Errors name the file, the key path and the expected type, so a
// bad config stops start-up with a message a person can act on.
//
//   const auto root = ifar::common::ConfigNode::loadFile("config/planner.yaml");
//   PlannerSettings settings;
//   settings.rate_hz = root.required<double>("rate_hz");
//   settings.votes = root.optional<int>("graph.votes", 10);   // dotted paths reach into maps
//   const auto lidar = root.child("lidar");                  // or take a child node
//   root.rejectUnknownKeys();                                // after everything is read
//
// A ConfigNode is a cheap handle; children share the record of which keys were read.

#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace ifar::common {

/// Thrown for any problem with a configuration file. what() names file, key and problem.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ConfigNode {
 public:
  /// Parses a YAML file. Throws ConfigError naming the file (and line) when it cannot be read or parsed.
  static ConfigNode loadFile(const std::string& path);
  /// Parses YAML text; `source_name` stands in for the file name in messages.
  static ConfigNode loadString(const std::string& text, const std::string& source_name);

  /// The value at a dotted key path. Throws ConfigError when missing or not convertible to T.
  /// T: bool, int, std::int64_t, double, std::string, std::vector<double>, std::vector<std::string>.
  template <typename T>
  T required(const std::string& key) const;

  /// Like required(), but returns `fallback` when the key is absent (a wrong type still throws).
  template <typename T>
  T optional(const std::string& key, const T& fallback) const;

  /// required<double>(key) that must be greater than zero (NaN fails too), else ConfigError
  /// "<file>: key '<k>': must be greater than zero, got <value>".
  double requiredPositive(const std::string& key) const;
  /// optional<double>(key, fallback) with the same check on a value that is present.
  double optionalPositive(const std::string& key, double fallback) const;

  bool has(const std::string& key) const;

  /// The map at a dotted key path. Throws ConfigError when missing or not a map.
  ConfigNode child(const std::string& key) const;

  /// The elements of the sequence at `key`, each a node (for lists of maps). Missing = empty.
  std::vector<ConfigNode> sequence(const std::string& key) const;

  /// Keys of this map, in file order.
  std::vector<std::string> keys() const;

  /// Throws ConfigError naming the first key under this node that nothing has read.
  void rejectUnknownKeys() const;

  /// Marks every key under `key` as read (for free-form sections handed to another parser).
  void acceptAllUnder(const std::string& key) const;

  /// "file: key 'a.b'" style location of a key under this node, for callers' own messages.
  std::string describe(const std::string& key) const;

  const std::string& sourceName() const { return *source_name_; }
  const std::string& path() const { return path_; }

  /// Throws ConfigError "<file>: key '<path>': <problem>".
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

  /// Replaces the value at a dotted key path with `value_yaml` (YAML text: a scalar, or a flow list or
  /// map; "" is null, which reads as absent), making missing maps on the way: an override from the
  /// command line, applied before anything reads the config, so the key is then read and checked like the
  /// file's own. Messages about the key or anything under it name `origin` instead of the file, e.g.
  /// "--set lidar.port=70000: key 'lidar.port': must be in [1, 65535], got 70000". Throws ConfigError
  /// naming `origin` when the value is not YAML or a key on the way holds something other than a map.
  void set(const std::string& key, const std::string& value_yaml, const std::string& origin);

 private:
  ConfigNode(const YAML::Node& node, std::string path, std::shared_ptr<const std::string> source_name,
             std::shared_ptr<std::set<std::string>> read_keys,
             std::shared_ptr<std::map<std::string, std::string>> origins);
  YAML::Node lookup(const std::string& key, std::string& full_path) const;
  /// Where the key at `full_path` came from: the `origin` of a set() at or above it, else the file.
  const std::string& sourceOf(const std::string& full_path) const;
  void collectUnread(const YAML::Node& node, const std::string& path, std::vector<std::string>& out) const;

  YAML::Node node_;
  std::string path_;
  std::shared_ptr<const std::string> source_name_;
  std::shared_ptr<std::set<std::string>> read_keys_;
  std::shared_ptr<std::map<std::string, std::string>> origins_;  // full key path -> set()'s origin
};

}  // namespace ifar::common
