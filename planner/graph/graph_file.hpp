#pragma once
// Saving and loading the global DV-graph (a prior map for the next run). Text format, version 1:
//
//   ifar-dv-graph 1
//   slots <number of vertex slots, dead ones included>
//   vertices <count>
//   v <id> <kind 0..3> <x> <y> <previous x> <previous y> <next x> <next y> <object id> <unseen votes>
//   edges <count>
//   e <id> <id>
//   interactions <count>
//   i <from id> <to id> <object id> <cost J> <push plan handle>
//   checksum <FNV-1a 64 of every byte before this line, 16 hex digits>
//
// Vertex ids are kept (ids strictly increasing in the file). Numbers are written with 17 significant
// digits so a round trip is exact. Loading validates everything and reports the first problem.

#include <cstddef>
#include <cstdint>
#include <string>

#include "planner/graph/dv_graph.hpp"

namespace ifar::graph {

constexpr int kGraphFileVersion = 1;

/// Empty on success, else the reason (file named).
std::string saveGraph(const DvGraph& graph, const std::string& path);

/// What a reader accepts before it allocates: the slots a file declares are made before its vertices
/// are read, so a header cannot ask for more than this.
struct GraphReadLimits {
  std::size_t max_slots = std::size_t{1} << 22U;  // 4.2 million: ten times a 1024 x 1024 map's graph
  std::uintmax_t max_file_bytes = std::uintmax_t{1} << 30U;  // 1 GiB
};

struct GraphLoadResult {
  DvGraph graph;
  std::string error;  // "<file>:<line>: <reason>" or "<file>: <reason>"; empty on success
  bool ok() const { return error.empty(); }
};

/// Only a regular file of at most limits.max_file_bytes is read.
GraphLoadResult loadGraph(const std::string& path, const GraphReadLimits& limits = {});

/// The same, on text in memory (`source_name` stands in for the file name in messages).
std::string serializeGraph(const DvGraph& graph);
GraphLoadResult parseGraph(const std::string& text, const std::string& source_name,
                           const GraphReadLimits& limits = {});

}  // namespace ifar::graph
