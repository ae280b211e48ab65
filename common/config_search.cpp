#include "common/config_search.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "common/config.hpp"

#ifndef IFAR_CHECKOUT_CONFIG_DIR
#error "IFAR_CHECKOUT_CONFIG_DIR: the build's config/ folder, set by common/CMakeLists.txt"
#endif
#ifndef IFAR_DATA_FROM_BIN
#error "IFAR_DATA_FROM_BIN: share/ifar relative to the installed bin/, set by common/CMakeLists.txt"
#endif

namespace ifar::common {
namespace {

namespace fs = std::filesystem;

std::string environmentValue(const char* name)
{
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

bool isFolder(const fs::path& path)
{
  std::error_code error;
  return fs::is_directory(path, error);
}

bool isFile(const fs::path& path)
{
  std::error_code error;
  return fs::is_regular_file(path, error);
}

/// The user's folder: $XDG_CONFIG_HOME/ifar, else $HOME/.config/ifar; "" without either.
std::string userFolder()
{
  const std::string xdg = environmentValue("XDG_CONFIG_HOME");
  if (!xdg.empty()) {
    return (fs::path(xdg) / "ifar").string();
  }
  const std::string home = environmentValue("HOME");
  return home.empty() ? std::string() : (fs::path(home) / ".config" / "ifar").string();
}

/// share/ifar of the install the running program belongs to: bin/../share/ifar; "" when unknown.
std::string installFolder()
{
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error) {
    return {};
  }
  return (program.parent_path() / IFAR_DATA_FROM_BIN).lexically_normal().string();
}

/// "A (origin), B (origin)" for a message about where a file was looked for.
std::string foldersText(const std::vector<ConfigFolder>& folders)
{
  if (folders.empty()) {
    return std::string("any configuration folder (set ") + kConfigDirectoryVariable + " or install ifar)";
  }
  std::string text;
  for (const ConfigFolder& folder : folders) {
    text += (text.empty() ? "" : ", ") + folder.path + " (" + folder.origin + ")";
  }
  return text;
}

}  // namespace

ConfigSearchPath ConfigSearchPath::standard()
{
  ConfigSearchPath search;
  const auto add = [&search](const std::string& folder, const std::string& origin) {
    if (!folder.empty() && isFolder(folder)) {
      search.folders_.push_back({folder, origin});
    }
  };
  add(environmentValue(kConfigDirectoryVariable), kConfigDirectoryVariable);
  add(userFolder(), "user folder");
  add(installFolder(), "install");
  add(IFAR_CHECKOUT_CONFIG_DIR, "checkout");
  return search;
}

ConfigSearchPath ConfigSearchPath::withFirst(const std::string& folder, const std::string& origin) const
{
  ConfigSearchPath search;
  search.folders_.push_back({folder, origin});
  search.folders_.insert(search.folders_.end(), folders_.begin(), folders_.end());
  return search;
}

std::optional<FoundConfig> ConfigSearchPath::find(const std::string& relative) const
{
  for (const ConfigFolder& folder : folders_) {
    const fs::path candidate = fs::path(folder.path) / relative;
    if (isFile(candidate)) {
      return FoundConfig{candidate.lexically_normal().string(), folder.origin};
    }
  }
  return std::nullopt;
}

FoundConfig ConfigSearchPath::locate(const std::string& relative) const
{
  if (auto found = find(relative)) {
    return *found;
  }
  throw ConfigError(relative + ": not found in " + foldersText(folders_));
}

FoundConfig resolveConfigFile(const std::string& given, const std::string& default_name)
{
  if (given.empty()) {
    return ConfigSearchPath::standard().locate(default_name);
  }
  const fs::path path(given);
  if (path.is_absolute() || isFile(path) || isFolder(path)) {
    return FoundConfig{given, "command line"};  // loadFile names the problem with a path given as it is
  }
  const ConfigSearchPath search = ConfigSearchPath::standard();
  if (auto found = search.find(given)) {
    return *found;
  }
  throw ConfigError(given + ": no such file from the working directory, nor in " +
                    foldersText(search.folders()));
}

FoundConfig resolveReferencedFile(const std::string& name, const std::string& referring_file)
{
  if (fs::path(name).is_absolute()) {
    return FoundConfig{name, referring_file};
  }
  std::string beside = fs::path(referring_file).parent_path().string();
  if (beside.empty()) {
    beside = ".";
  }
  const ConfigSearchPath search = ConfigSearchPath::standard().withFirst(beside, "beside " + referring_file);
  try {
    return search.locate(name);
  } catch (const ConfigError& error) {
    throw ConfigError(referring_file + ": " + error.what());
  }
}

std::string describeFiles(const std::vector<FoundConfig>& files)
{
  std::string text;
  std::string folder;
  std::string origin;
  const auto closeGroup = [&] {
    if (!folder.empty()) {
      text += " from " + folder + " (" + origin + ")";
    }
  };
  for (const FoundConfig& file : files) {
    const fs::path path(file.path);
    const std::string file_folder = path.parent_path().string();
    if (file_folder != folder || file.origin != origin) {
      closeGroup();
      text += text.empty() ? "" : "; ";
      folder = file_folder;
      origin = file.origin;
    } else {
      text += ", ";
    }
    text += path.filename().string();
  }
  closeGroup();
  return text;
}

std::optional<FoundConfig> findNamedInput(const std::string& name, const std::string& folder)
{
  if (isFile(name)) {
    return FoundConfig{name, "command line"};
  }
  if (fs::path(name).is_absolute()) {
    return std::nullopt;
  }
  const ConfigSearchPath search = ConfigSearchPath::standard();
  const fs::path relative = fs::path(folder) / name;
  for (const fs::path& candidate : {relative, fs::path(relative.string() + ".yaml")}) {
    if (auto found = search.find(candidate.string())) {
      return found;
    }
  }
  return std::nullopt;
}

}  // namespace ifar::common
