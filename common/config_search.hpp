#pragma once
// Where configuration is found, so every command runs from any folder: one search path, first match wins.
//
//   1. a folder the command line names (ifar run --config-dir DIR), or the folder of the file that names
//      another (planner.yaml's vehicle_config, the vehicle.yaml beside the executive's config);
//   2. $IFAR_CONFIG_DIR;
//   3. the user's folder: $XDG_CONFIG_HOME/ifar, else ~/.config/ifar;
//   4. the install's share/ifar, found beside the running program's bin/;
//   5. the checkout the program was built from (its config/ folder).
//
// Names are relative to a folder of the path: "planner.yaml", "worlds/demo_room.yaml",
// "launch/vehicle.yaml". A folder that does not exist is skipped, so one file can be overridden without
// copying the others (IFAR_CONFIG_DIR=/etc/ifar holding only can.yaml).
//
//   const common::FoundConfig found = common::resolveConfigFile(given_on_command_line, "planner.yaml");
//   logger.info("configuration {} ({})", found.path, found.origin);

#include <optional>
#include <string>
#include <vector>

namespace ifar::common {

/// The environment variable naming a folder searched before the user's and the install's.
inline constexpr const char* kConfigDirectoryVariable = "IFAR_CONFIG_DIR";

/// One folder of the search path and why it is on it ("IFAR_CONFIG_DIR", "install", ...).
struct ConfigFolder {
  std::string path;
  std::string origin;
};

/// A file found on the search path: its path and the origin of the folder it was found in.
struct FoundConfig {
  std::string path;
  std::string origin;
};

class ConfigSearchPath {
 public:
  /// Folders 2 to 5 above, read from the environment and the running program's location at each call.
  static ConfigSearchPath standard();

  /// This path with `folder` searched first (origin says why, e.g. "--config-dir").
  ConfigSearchPath withFirst(const std::string& folder, const std::string& origin) const;

  /// The first folder holding the regular file `relative`; nullopt when none does.
  std::optional<FoundConfig> find(const std::string& relative) const;

  /// find(), or ConfigError "<relative>: not found in <folder> (<origin>), ..." naming every folder.
  FoundConfig locate(const std::string& relative) const;

  const std::vector<ConfigFolder>& folders() const { return folders_; }

 private:
  std::vector<ConfigFolder> folders_;
};

/// The configuration file of a command: `given` (its --config value; "" when not given) or else
/// `default_name`. A given path that names a file from the working directory is used as it is; a relative
/// one that does not, and the default name, are looked up on the standard search path. Throws ConfigError
/// naming the file and every folder looked in when there is none.
FoundConfig resolveConfigFile(const std::string& given, const std::string& default_name);

/// A file named inside the configuration file `referring_file` (vehicle_config: vehicle.yaml): an
/// absolute path as it is; a relative one beside `referring_file`, else on the standard search path.
/// Throws ConfigError naming `name`, the referring file and the folders looked in when it is nowhere.
FoundConfig resolveReferencedFile(const std::string& name, const std::string& referring_file);

/// "vehicle.yaml, planner.yaml from /etc/ifar (IFAR_CONFIG_DIR); can.yaml from ... (install)": the files,
/// grouped by the folder they were found in, for a command's report of what it read.
std::string describeFiles(const std::vector<FoundConfig>& files);

/// An input named by the user that may be a path or a name on the search path (a world, a launch file):
/// `name` when it exists from the working directory, else the first of `folder/name` and
/// `folder/name.yaml` found on the standard search path; nullopt when neither is anywhere.
std::optional<FoundConfig> findNamedInput(const std::string& name, const std::string& folder);

}  // namespace ifar::common
