#pragma once
// Decoded points written to a file for a person or another tool to look at: CSV with a header row, or
// ASCII PCD (readable by PCL and CloudCompare), chosen by the file's extension.
//
// Columns: x, y, z (metres, sensor frame: x forward, y left, z up; PCL's grabbers use y forward, x right),
// intensity (the reflectivity byte), ring (0 lowest .. 15 highest beam), azimuth (degrees), distance
// (metres), return_index (0 last or only return, 1 strongest of a dual pair), time_us (device clock:
// microseconds past the hour, the packet timestamp plus the point's firing offset). Floats are written in
// the shortest text that reads back to the same value.

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "drivers/velodyne/point.hpp"

namespace ifar::velodyne {

enum class PointFileFormat : std::uint8_t { kCsv, kPcd };

/// The format `path`'s extension names: ".csv" or ".pcd" (any case); nullopt for any other.
std::optional<PointFileFormat> pointFileFormat(const std::string& path);

class PointFileWriter {
 public:
  /// Creates `path` (format from its extension); check error() before adding points.
  explicit PointFileWriter(const std::string& path);

  /// "" while all is well, else what went wrong, naming the file.
  const std::string& error() const { return error_; }

  /// One packet's points; `packet_time_past_hour` is its timestamp (microseconds past the hour).
  void add(const std::vector<Point>& points, std::uint32_t packet_time_past_hour);

  /// Completes the file (PCD: the point count goes into the header). False, with error(), when writing
  /// failed.
  bool finish();

  std::int64_t points() const { return points_; }

 private:
  std::string path_;
  PointFileFormat format_ = PointFileFormat::kCsv;
  std::ofstream file_;
  std::string error_;
  std::int64_t points_ = 0;
  std::streampos width_position_ = -1;   // PCD: where the WIDTH value is written once known
  std::streampos points_position_ = -1;  // PCD: where the POINTS value is written once known
};

}  // namespace ifar::velodyne
