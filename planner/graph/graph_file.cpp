#include "planner/graph/graph_file.hpp"

#include <charconv>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

namespace ifar::graph {
namespace {

std::uint64_t fnv1a(const std::string& text, std::size_t length)
{
  std::uint64_t hash = 14695981039346656037ULL;
  for (std::size_t index = 0; index < length; ++index) {
    hash ^= static_cast<unsigned char>(text[index]);
    hash *= 1099511628211ULL;
  }
  return hash;
}

std::string formatNumber(double value)
{
  char text[40];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

/// Reads "<keyword> <count>" from a line.
bool readCount(const std::string& line, const std::string& keyword, std::size_t& count)
{
  std::istringstream fields(line);
  std::string found;
  long long value = -1;
  std::string extra;
  if (!(fields >> found >> value) || found != keyword || value < 0 || (fields >> extra)) {
    return false;
  }
  count = static_cast<std::size_t>(value);
  return true;
}

}  // namespace

std::string serializeGraph(const DvGraph& graph)
{
  std::ostringstream out;
  out << "ifar-dv-graph " << kGraphFileVersion << "\n";
  out << "slots " << graph.vertexSlots().size() << "\n";
  out << "vertices " << graph.vertexCount() << "\n";
  for (const auto& vertex : graph.vertexSlots()) {
    if (!vertex.alive) {
      continue;
    }
    out << "v " << vertex.id << " " << static_cast<int>(vertex.kind) << " "
        << formatNumber(vertex.position.x()) << " " << formatNumber(vertex.position.y()) << " "
        << formatNumber(vertex.previous.x()) << " " << formatNumber(vertex.previous.y()) << " "
        << formatNumber(vertex.next.x()) << " " << formatNumber(vertex.next.y()) << " " << vertex.object_id
        << " " << vertex.unseen_votes << "\n";
  }
  out << "edges " << graph.visibilityEdgeCount() << "\n";
  for (const auto& vertex : graph.vertexSlots()) {
    if (!vertex.alive) {
      continue;
    }
    for (const auto& link : graph.visibilityLinks(vertex.id)) {
      if (vertex.id < link.other) {
        out << "e " << vertex.id << " " << link.other << "\n";
      }
    }
  }
  out << "interactions " << graph.interactionEdgeCount() << "\n";
  for (const auto& edge : graph.interactionEdges()) {
    if (edge.alive) {
      out << "i " << edge.from << " " << edge.to << " " << edge.object_id << " " << formatNumber(edge.cost)
          << " " << edge.push_plan << "\n";
    }
  }
  std::string text = out.str();
  char checksum[40];
  std::snprintf(checksum, sizeof(checksum), "checksum %016" PRIx64 "\n", fnv1a(text, text.size()));
  return text + checksum;
}

std::string saveGraph(const DvGraph& graph, const std::string& path)
{
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      return path + ": cannot write";
    }
    out << serializeGraph(graph);
    if (!out.flush()) {
      return path + ": write failed";
    }
  }
  // Replace atomically so a crash mid-write never leaves a half graph under the real name.
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    return path + ": cannot replace the file";
  }
  return {};
}

GraphLoadResult parseGraph(const std::string& text, const std::string& source_name,
                           const GraphReadLimits& limits)
{
  GraphLoadResult result;
  const auto fail = [&](int line, const std::string& reason) {
    result.error = source_name + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + reason;
    result.graph = DvGraph();
    return result;
  };
  // Checksum first: a truncated or edited file is rejected before anything is parsed.
  const std::size_t end = !text.empty() && text.back() == '\n' ? text.size() - 1 : text.size();
  const std::size_t last_line = text.rfind('\n', end == 0 ? 0 : end - 1);
  const std::size_t checksum_start = last_line == std::string::npos ? 0 : last_line + 1;
  const std::string checksum_line = text.substr(checksum_start, end - checksum_start);
  if (checksum_line.rfind("checksum ", 0) != 0) {
    return fail(0, "missing checksum line (file truncated?)");
  }
  std::uint64_t stored = 0;
  const char* const digits_end = checksum_line.data() + checksum_line.size();
  const std::from_chars_result parsed = std::from_chars(checksum_line.data() + 9, digits_end, stored, 16);
  if (checksum_line.size() != 9 + 16 || parsed.ec != std::errc() || parsed.ptr != digits_end) {
    return fail(0, "malformed checksum line");
  }
  if (stored != fnv1a(text, checksum_start)) {
    return fail(0, "checksum mismatch (file corrupted or edited)");
  }

  std::istringstream input(text.substr(0, checksum_start));
  std::string line;
  int line_number = 0;
  const auto next = [&]() {
    ++line_number;
    return static_cast<bool>(std::getline(input, line));
  };
  if (!next()) {
    return fail(1, "empty file");
  }
  {
    std::istringstream fields(line);
    std::string magic;
    int version = 0;
    if (!(fields >> magic >> version) || magic != "ifar-dv-graph") {
      return fail(line_number, "not an ifar DV-graph file");
    }
    if (version != kGraphFileVersion) {
      return fail(line_number, "unsupported version " + std::to_string(version) + " (this build reads " +
                                   std::to_string(kGraphFileVersion) + ")");
    }
  }
  std::size_t slots = 0;
  if (!next() || !readCount(line, "slots", slots)) {
    return fail(line_number, "expected 'slots <count>'");
  }
  if (slots > limits.max_slots) {
    return fail(line_number, "slots " + std::to_string(slots) + " beyond the reader's limit of " +
                                 std::to_string(limits.max_slots));
  }
  std::size_t count = 0;
  if (!next() || !readCount(line, "vertices", count) || count > slots) {
    return fail(line_number, "expected 'vertices <count>' with count <= slots");
  }
  DvGraph graph;
  for (std::size_t index = 0; index < count; ++index) {
    if (!next()) {
      return fail(line_number, "file ends inside the vertex list");
    }
    std::istringstream fields(line);
    std::string tag;
    long long id = -1;
    int kind = -1;
    Vertex vertex;
    double values[6] = {};
    std::string extra;
    if (!(fields >> tag >> id >> kind >> values[0] >> values[1] >> values[2] >> values[3] >> values[4] >>
          values[5] >> vertex.object_id >> vertex.unseen_votes) ||
        tag != "v" || (fields >> extra)) {
      return fail(line_number, "malformed vertex line");
    }
    if (id < static_cast<long long>(graph.vertexSlots().size()) || id >= static_cast<long long>(slots)) {
      return fail(line_number, "vertex id " + std::to_string(id) + " out of order or beyond the slot count");
    }
    if (kind < 0 || kind > 3) {
      return fail(line_number, "unknown vertex kind " + std::to_string(kind));
    }
    for (const double value : values) {
      if (!std::isfinite(value)) {
        return fail(line_number, "non-finite coordinate");
      }
    }
    if (vertex.unseen_votes < 0) {
      return fail(line_number, "negative unseen votes");
    }
    // Dead slots before this id keep later ids stable.
    while (static_cast<long long>(graph.vertexSlots().size()) < id) {
      graph.removeVertex(graph.addVertex(Vertex{}));
    }
    vertex.kind = static_cast<VertexKind>(kind);
    vertex.position = geometry::Point(values[0], values[1]);
    vertex.previous = geometry::Point(values[2], values[3]);
    vertex.next = geometry::Point(values[4], values[5]);
    graph.addVertex(vertex);
  }
  while (graph.vertexSlots().size() < slots) {
    graph.removeVertex(graph.addVertex(Vertex{}));
  }
  if (!next() || !readCount(line, "edges", count)) {
    return fail(line_number, "expected 'edges <count>'");
  }
  for (std::size_t index = 0; index < count; ++index) {
    if (!next()) {
      return fail(line_number, "file ends inside the edge list");
    }
    std::istringstream fields(line);
    std::string tag;
    long long first = -1;
    long long second = -1;
    std::string extra;
    if (!(fields >> tag >> first >> second) || tag != "e" || (fields >> extra) || first < 0 || second < 0 ||
        first > 0xFFFFFFFELL || second > 0xFFFFFFFELL) {
      return fail(line_number, "malformed edge line");
    }
    const auto status = graph.addVisibilityEdge(static_cast<VertexId>(first), static_cast<VertexId>(second));
    if (status == EdgeStatus::Rejected) {
      return fail(line_number, "edge refers to a missing vertex or joins a vertex to itself");
    }
    if (status == EdgeStatus::AlreadyPresent) {
      return fail(line_number, "duplicate edge");
    }
  }
  if (!next() || !readCount(line, "interactions", count)) {
    return fail(line_number, "expected 'interactions <count>'");
  }
  for (std::size_t index = 0; index < count; ++index) {
    if (!next()) {
      return fail(line_number, "file ends inside the interaction list");
    }
    std::istringstream fields(line);
    std::string tag;
    long long from = -1;
    long long to = -1;
    InteractionEdge edge;
    std::string extra;
    if (!(fields >> tag >> from >> to >> edge.object_id >> edge.cost >> edge.push_plan) || tag != "i" ||
        (fields >> extra) || from < 0 || to < 0 || from > 0xFFFFFFFELL || to > 0xFFFFFFFELL) {
      return fail(line_number, "malformed interaction line");
    }
    edge.from = static_cast<VertexId>(from);
    edge.to = static_cast<VertexId>(to);
    if (!graph.addInteractionEdge(edge)) {
      return fail(line_number, "interaction edge with a missing vertex or a negative / non-finite cost");
    }
  }
  if (next() && !line.empty()) {
    return fail(line_number, "unexpected content after the interaction list");
  }
  result.graph = std::move(graph);
  return result;
}

GraphLoadResult loadGraph(const std::string& path, const GraphReadLimits& limits)
{
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    GraphLoadResult result;
    result.error = path + (std::filesystem::exists(path, error) ? ": not a regular file" : ": cannot open");
    return result;
  }
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error || bytes > limits.max_file_bytes) {
    GraphLoadResult result;
    result.error = path + ": " +
                   (error ? "cannot read its size"
                          : std::to_string(bytes) + " bytes, beyond the reader's limit of " +
                                std::to_string(limits.max_file_bytes));
    return result;
  }
  std::ifstream input(path, std::ios::binary);
  if (!input) {
    GraphLoadResult result;
    result.error = path + ": cannot open";
    return result;
  }
  std::ostringstream buffer;
  buffer << input.rdbuf();
  return parseGraph(buffer.str(), path);
}

}  // namespace ifar::graph
