// libFuzzer entry: any bytes as a DV-graph file (planner/graph/graph_file.hpp), read as they are and, since
// a mutation almost never keeps the checksum right, again with a correct checksum line appended. Bad input
// is an error value, never an exception, and a graph that loads must survive its own round trip. The slot
// limit is lowered from its default (4.2 million slots, some 500 MB, which a 100-byte header may ask for by
// design) so that scripts/fuzz-files' allocation cap catches a reader that does not keep to its limit.

#include <cinttypes>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "planner/graph/graph_file.hpp"

namespace {

/// FNV-1a 64 of `text`, as the file's checksum line states it.
std::string checksumLine(const std::string& text)
{
  std::uint64_t hash = 14695981039346656037ULL;
  for (const char character : text) {
    hash ^= static_cast<unsigned char>(character);
    hash *= 1099511628211ULL;
  }
  char line[40];
  std::snprintf(line, sizeof(line), "checksum %016" PRIx64 "\n", hash);
  return line;
}

void check(const std::string& text)
{
  using namespace ifar::graph;
  GraphReadLimits limits;
  limits.max_slots = std::size_t{1} << 16U;
  const GraphLoadResult result = parseGraph(text, "fuzz.graph", limits);
  if (!result.ok()) {
    return;
  }
  const std::string saved = serializeGraph(result.graph);
  const GraphLoadResult again = parseGraph(saved, "saved.graph", limits);
  if (!again.ok()) {
    std::fprintf(stderr, "a saved graph does not load again: %s\n%s\n", again.error.c_str(), saved.c_str());
    std::abort();
  }
  if (serializeGraph(again.graph) != saved) {
    std::fprintf(stderr, "a saved graph changes on a round trip:\n%s\n", saved.c_str());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::string text(reinterpret_cast<const char*>(data), size);
  check(text);
  if (!text.empty() && text.back() != '\n') {
    text += '\n';
  }
  check(text + checksumLine(text));
  return 0;
}
