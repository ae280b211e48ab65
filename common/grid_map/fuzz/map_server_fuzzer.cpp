// libFuzzer entry: any bytes as a map_server description and its image. The input is the YAML, then a
// line "#pgm", then the PGM bytes; both go to scratch files (the reader takes a path), and the YAML names
// the image (the seeds say "image: fuzz.pgm"). Bad input is an error value, never an exception, and an
// accepted map holds no more cells than the image has bytes.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "common/grid_map/fuzz/scratch_folder.hpp"
#include "common/grid_map/readers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace ifar::grid_map;
  static const std::string kSeparator = "\n#pgm\n";
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t separator = input.find(kSeparator);
  const std::size_t yaml_size = separator == std::string::npos ? size : separator;
  const std::size_t image_start = separator == std::string::npos ? size : separator + kSeparator.size();
  const std::string yaml_path = fuzz::writeScratchFile("fuzz.yaml", input.data(), yaml_size);
  fuzz::writeScratchFile("fuzz.pgm", input.data() + image_start, size - image_start);

  const MapReadResult result = readMapServer(yaml_path);
  if (result.ok()) {
    const std::size_t cells =
        static_cast<std::size_t>(result.map.width()) * static_cast<std::size_t>(result.map.height());
    if (cells > size) {
      std::abort();
    }
  } else if (result.error.empty()) {
    std::abort();
  }
  return 0;
}
