#pragma once
// A settings struct's parameters declared once: for each key its field, unit, range and a one-line
// meaning; the default is the struct's own default member value. The loader with its type and range
// checks, the reference table in docs/configuration.md and the --print-config dump all come from that
// one declaration.
//
//   const common::ParameterTable<FollowerSettings>& followerParameters()
//   {
//     static const auto table = common::ParameterTable<FollowerSettings>()
//         .add("horizon_s", &FollowerSettings::horizon_s, "s", Range::positive(), "arcs are checked this far
//         ahead") .add("limits.max_linear_velocity", [](auto& s) -> auto& { return
//         s.limits.max_linear_velocity; },
//              "m/s", Range::interval(0.0, false, 5.0, true), "top speed while following");
//     return table;
//   }
//   const FollowerSettings follower = followerParameters().load(root.child("follower"));
//
// Keys are dotted paths below the node a table is read from. A field is named by a member pointer or by
// a generic lambda returning a reference to it (`[](auto& s) -> auto& { return s.a.b; }`, so one lambda
// serves the const dump and the loader). Fields may be bool, any integer, float or double, std::string,
// or an enum declared with choice() and its names.

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "common/config.hpp"

namespace ifar::common {

/// The values a number may take (an interval, either end open or closed, infinite = unbounded), or for a
/// text that it must not be empty.
struct ParameterRange {
  double low = -std::numeric_limits<double>::infinity();
  bool low_inclusive = true;
  double high = std::numeric_limits<double>::infinity();
  bool high_inclusive = true;
  bool non_empty = false;

  static ParameterRange any() { return {}; }
  static ParameterRange positive() { return interval(0.0, false, kUnbounded, true); }
  static ParameterRange nonNegative() { return atLeast(0.0); }
  static ParameterRange atLeast(double low) { return interval(low, true, kUnbounded, true); }
  static ParameterRange between(double low, double high) { return interval(low, true, high, true); }
  static ParameterRange interval(double low, bool low_inclusive, double high, bool high_inclusive)
  {
    return {low, low_inclusive, high, high_inclusive, false};
  }
  static ParameterRange nonEmpty() { return {-kUnbounded, true, kUnbounded, true, true}; }

  bool contains(double value) const;
  /// The range as a reader writes it: "> 0", ">= 1", "[0, 0.5]", "(0, 5]", "any", "not empty".
  std::string describe() const;
  /// The complaint about a value outside it: "must be in (0, 5] m/s", "must be greater than 0".
  std::string requirement(const std::string& unit) const;

  static constexpr double kUnbounded = std::numeric_limits<double>::infinity();
};

enum class ParameterType { boolean, integer, real, text, choice };

/// What a parameter is, without its field: enough to read, check, document and print it.
struct ParameterInfo {
  std::string key;  // dotted path below the table's node
  ParameterType type = ParameterType::real;
  std::string unit;  // "" for counts, names and plain numbers
  ParameterRange range;
  std::vector<std::string> names;  // choice: the allowed names
  std::string meaning;             // one line: what the value does to the vehicle, sensor or geometry
  bool required = false;           // a missing key is an error (else the default stays)
  std::int64_t integer_min = std::numeric_limits<std::int64_t>::min();  // what the field's type holds
  std::int64_t integer_max = std::numeric_limits<std::int64_t>::max();
};

/// One value as a table sees it: booleans, integers (any width), reals, texts and choice names.
using ParameterValue = std::variant<bool, std::int64_t, double, std::string>;

/// Reads `info.key` under `node` (`current` when optional and absent) and checks its type and range.
/// Throws ConfigError "<file>: key '<path>': must be in (0, 5] m/s, got 7".
ParameterValue readParameter(const ConfigNode& node, const ParameterInfo& info,
                             const ParameterValue& current);

/// A number as short as it can be written and still read back to the same double ("0.15", "200").
std::string formatNumber(double value);
/// A value as YAML writes it: reals always with a point ("200.0"), texts quoted, names plain.
std::string yamlValue(const ParameterInfo& info, const ParameterValue& value);

/// A Markdown table (key, type, unit, default, range, meaning) of `infos` with their `defaults`.
std::string parameterMarkdown(const std::vector<ParameterInfo>& infos,
                              const std::vector<ParameterValue>& defaults);

/// Effective values of one or more tables as one YAML document: dotted keys become nested maps (a map
/// given by two tables is written once), each value with its meaning and unit as a comment.
class ConfigDump {
 public:
  /// One value at the dotted `path` (from the document's root).
  void add(const std::string& path, const std::string& yaml_value, const std::string& comment);
  /// A line of comment above everything added later at the top level.
  void note(const std::string& comment);
  std::string yaml() const;

 private:
  struct Node {
    std::string name;
    std::string value;    // leaves only
    std::string comment;  // leaves: the meaning; a note: the note's text
    bool leaf = false;
    bool is_note = false;
    std::vector<std::size_t> children;
  };
  std::size_t childNamed(std::size_t parent, const std::string& name);
  void write(std::size_t node, int depth, std::string& out) const;

  std::vector<Node> nodes_{Node{}};  // [0] is the root
};

enum class Presence { optional, required };

template <typename Settings>
class ParameterTable {
  template <typename Access>
  using FieldOf =
      std::remove_cv_t<std::remove_reference_t<decltype(std::declval<Access>()(std::declval<Settings&>()))>>;

 public:
  /// `presence`: whether every key of the table must be in the file.
  explicit ParameterTable(Presence presence = Presence::optional) : presence_(presence) {}

  /// A field named by a member pointer.
  template <typename Field>
  ParameterTable& add(std::string key, Field Settings::*member, std::string unit, ParameterRange range,
                      std::string meaning)
  {
    return add(
        std::move(key), [member](auto& settings) -> auto& { return settings.*member; }, std::move(unit),
        range, std::move(meaning));
  }

  /// A field named by a generic lambda returning a reference to it.
  template <typename Access>
  ParameterTable& add(std::string key, Access access, std::string unit, ParameterRange range,
                      std::string meaning)
  {
    using Field = FieldOf<Access>;
    static_assert(!std::is_enum_v<Field>, "an enum field is declared with choice() and its names");
    ParameterInfo info =
        makeInfo(std::move(key), typeOf<Field>(), std::move(unit), range, std::move(meaning));
    if constexpr (std::is_integral_v<Field> && !std::is_same_v<Field, bool>) {
      info.integer_min = static_cast<std::int64_t>(std::numeric_limits<Field>::lowest());
      if constexpr (!std::is_unsigned_v<Field> || sizeof(Field) < sizeof(std::int64_t)) {
        info.integer_max = static_cast<std::int64_t>(std::numeric_limits<Field>::max());
      }
    }
    entries_.push_back(
        {std::move(info), [access](const Settings& settings) { return toValue(access(settings)); },
         [access](Settings& settings, const ParameterValue& value) { fromValue(value, access(settings)); }});
    return *this;
  }

  /// An enum field named by a member pointer, stored as one of `names`.
  template <typename Enum>
  ParameterTable& choice(std::string key, Enum Settings::*member,
                         std::vector<std::pair<std::string, Enum>> names, std::string meaning)
  {
    return choice(
        std::move(key), [member](auto& settings) -> auto& { return settings.*member; }, std::move(names),
        std::move(meaning));
  }

  /// An enum field named by a generic lambda, stored as one of `names`.
  template <typename Access>
  ParameterTable& choice(std::string key, Access access,
                         std::vector<std::pair<std::string, FieldOf<Access>>> names, std::string meaning)
  {
    ParameterInfo info =
        makeInfo(std::move(key), ParameterType::choice, "", ParameterRange::any(), std::move(meaning));
    for (const auto& entry : names) {
      info.names.push_back(entry.first);
    }
    entries_.push_back({std::move(info),
                        [access, names](const Settings& settings) -> ParameterValue {
                          for (const auto& [name, value] : names) {
                            if (access(settings) == value) {
                              return name;
                            }
                          }
                          return std::string("?");
                        },
                        [access, names](Settings& settings, const ParameterValue& value) {
                          for (const auto& [name, option] : names) {
                            if (std::get<std::string>(value) == name) {
                              access(settings) = option;
                            }
                          }
                        }});
    return *this;
  }

  /// A value kept in another form than the file's (a rate kept as a period, milliseconds kept as
  /// microseconds): `read` gives the file's value from the settings, `write` stores a file value.
  template <typename Value>
  ParameterTable& converted(std::string key, std::string unit, ParameterRange range, std::string meaning,
                            std::function<Value(const Settings&)> read,
                            std::function<void(Settings&, Value)> write)
  {
    entries_.push_back({makeInfo(std::move(key), typeOf<Value>(), std::move(unit), range, std::move(meaning)),
                        [read](const Settings& settings) { return toValue(read(settings)); },
                        [write](Settings& settings, const ParameterValue& value) {
                          Value stored{};
                          fromValue(value, stored);
                          write(settings, stored);
                        }});
    return *this;
  }

  /// Makes the key added last required, in a table whose keys are otherwise optional (a key with no
  /// default that could be right, such as a drive's node id).
  ParameterTable& required()
  {
    entries_.back().info.required = true;
    return *this;
  }

  /// Reads every key into `settings` (absent optional keys keep what `settings` holds); leaves the
  /// unknown-key check to the caller.
  void read(const ConfigNode& node, Settings& settings) const
  {
    for (const auto& entry : entries_) {
      entry.set(settings, readParameter(node, entry.info, entry.get(settings)));
    }
  }

  /// The defaults with every key of `node` read, unknown keys under `node` rejected.
  Settings load(const ConfigNode& node) const
  {
    Settings settings{};
    read(node, settings);
    node.rejectUnknownKeys();
    return settings;
  }

  std::vector<ParameterInfo> infos() const
  {
    std::vector<ParameterInfo> out;
    for (const auto& entry : entries_) {
      out.push_back(entry.info);
    }
    return out;
  }

  std::vector<ParameterValue> values(const Settings& settings) const
  {
    std::vector<ParameterValue> out;
    for (const auto& entry : entries_) {
      out.push_back(entry.get(settings));
    }
    return out;
  }

  /// The reference table, defaults from a value-initialised Settings.
  std::string markdown() const { return parameterMarkdown(infos(), values(Settings{})); }

  /// Adds `settings`' values under the dotted `section` ("" = the document's root).
  void dump(const Settings& settings, const std::string& section, ConfigDump& out) const
  {
    for (const auto& entry : entries_) {
      const std::string unit = entry.info.unit.empty() ? "" : " [" + entry.info.unit + "]";
      out.add(section.empty() ? entry.info.key : section + "." + entry.info.key,
              yamlValue(entry.info, entry.get(settings)), entry.info.meaning + unit);
    }
  }

  std::string yaml(const Settings& settings, const std::string& section = "") const
  {
    ConfigDump out;
    dump(settings, section, out);
    return out.yaml();
  }

 private:
  struct Entry {
    ParameterInfo info;
    std::function<ParameterValue(const Settings&)> get;
    std::function<void(Settings&, const ParameterValue&)> set;
  };

  ParameterInfo makeInfo(std::string key, ParameterType type, std::string unit, ParameterRange range,
                         std::string meaning) const
  {
    ParameterInfo info;
    info.key = std::move(key);
    info.type = type;
    info.unit = std::move(unit);
    info.range = range;
    info.meaning = std::move(meaning);
    info.required = presence_ == Presence::required;
    return info;
  }

  template <typename Field>
  static constexpr ParameterType typeOf()
  {
    if constexpr (std::is_same_v<Field, bool>) {
      return ParameterType::boolean;
    } else if constexpr (std::is_integral_v<Field>) {
      return ParameterType::integer;
    } else if constexpr (std::is_floating_point_v<Field>) {
      return ParameterType::real;
    } else {
      static_assert(std::is_same_v<Field, std::string>, "a parameter is a bool, number or string");
      return ParameterType::text;
    }
  }

  template <typename Field>
  static ParameterValue toValue(const Field& field)
  {
    if constexpr (std::is_same_v<Field, bool> || std::is_same_v<Field, std::string>) {
      return field;
    } else if constexpr (std::is_integral_v<Field>) {
      return static_cast<std::int64_t>(field);
    } else {
      return static_cast<double>(field);
    }
  }

  template <typename Field>
  static void fromValue(const ParameterValue& value, Field& field)
  {
    if constexpr (std::is_same_v<Field, bool> || std::is_same_v<Field, std::string>) {
      field = std::get<Field>(value);
    } else if constexpr (std::is_integral_v<Field>) {
      field = static_cast<Field>(std::get<std::int64_t>(value));
    } else {
      field = static_cast<Field>(std::get<double>(value));
    }
  }

  Presence presence_;
  std::vector<Entry> entries_;
};

}  // namespace ifar::common
