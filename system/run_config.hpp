#pragma once
// The runner's settings from the same config files the daemons read (vehicle.yaml, planner.yaml,
// executive.yaml, sim.yaml, can.yaml and velodyne.yaml, each the first on the configuration search path,
// common/config_search.hpp, with the directory given first when there is one), with the daemons' strict
// loaders: a typo or a bad value in any file stops the run with the file and key named. The channels are
// the daemons' (the simulated bus routes by them); the transport keys (CAN interface, UDP host, log level,
// LCM URL) are read and then unused; vehicle.yaml is always the one in the same directory (the
// `vehicle_config` paths inside planner.yaml and sim.yaml name it for the daemons). `config_directory` ""
// is the standard search path alone; a directory that does not exist is a ConfigError.

#include <string>
#include <vector>

#include "common/config_search.hpp"
#include "system/scenario_runner.hpp"

namespace ifar::runner {

/// A request with every setting filled in from `config_directory`; world and goal are left empty.
/// `sensing` (one of sensingProfileNames(); empty: sim.yaml's sensing.profile) picks the simulator's
/// sensing profile as ifar-sim --sensing does: sim.yaml's other sensing keys still override its values.
/// Throws common::ConfigError naming the file and key, std::invalid_argument for an unknown profile.
RunRequest loadRunSettings(const std::string& config_directory, const std::string& sensing = "");

/// The effective settings of every file in `config_directory` as a YAML stream, one document per file,
/// each key's meaning as a comment (ifar run --print-config). Throws as loadRunSettings does.
std::string runConfigYaml(const std::string& config_directory);

/// Where each of the six files is found (ifar run says which files it used). Throws as loadRunSettings does.
std::vector<common::FoundConfig> runConfigFiles(const std::string& config_directory);

/// The simulator's named sensing profiles ("ideal" first), for --sensing.
std::vector<std::string> sensingProfileNames();

}  // namespace ifar::runner
