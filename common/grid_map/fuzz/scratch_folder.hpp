#pragma once
// A folder of this fuzzer process's own for the input files of the path-only readers, under TMPDIR. libFuzzer
// ends without running exit handlers, so the folder stays: scripts/fuzz-files points TMPDIR at a folder it
// removes itself.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace ifar::grid_map::fuzz {

inline const std::filesystem::path& scratchFolder()
{
  static const std::filesystem::path folder = [] {
    const auto path = std::filesystem::temp_directory_path() / ("ifar-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return folder;
}

/// Writes `bytes` to `name` in the scratch folder and returns its path.
inline std::string writeScratchFile(const std::string& name, const char* bytes, std::size_t size)
{
  const std::string path = (scratchFolder() / name).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes, static_cast<std::streamsize>(size));
  if (!out.flush()) {
    std::abort();  // the fuzzer's own failure, not the reader's
  }
  return path;
}

}  // namespace ifar::grid_map::fuzz
