#include "drivers/velodyne/point_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace ifar::velodyne {
namespace {

// The PCD header states the point count before the points; it is written as blanks this wide and
// filled in at the end, so a capture of any length streams through without holding its points.
constexpr int kCountWidth = 20;

std::string lowerCase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool endsWith(const std::string& text, const std::string& suffix)
{
  return text.size() > suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::optional<PointFileFormat> pointFileFormat(const std::string& path)
{
  const std::string lower = lowerCase(path);
  if (endsWith(lower, ".csv")) {
    return PointFileFormat::kCsv;
  }
  if (endsWith(lower, ".pcd")) {
    return PointFileFormat::kPcd;
  }
  return std::nullopt;
}

PointFileWriter::PointFileWriter(const std::string& path) : path_(path)
{
  const std::optional<PointFileFormat> format = pointFileFormat(path);
  if (!format) {
    error_ = "'" + path + "': the points file must end in .csv or .pcd";
    return;
  }
  format_ = *format;
  file_.open(path, std::ios::out | std::ios::trunc);
  if (!file_) {
    error_ = "cannot write '" + path + "'";
    return;
  }
  if (format_ == PointFileFormat::kCsv) {
    file_ << "x,y,z,intensity,ring,azimuth,distance,return_index,time_us\n";
    return;
  }
  file_ << "# .PCD v0.7 - ifar-velodyne-driver points: x forward, y left, z up (m); time_us = device "
           "microseconds past the hour\n"
           "VERSION 0.7\n"
           "FIELDS x y z intensity ring azimuth distance return_index time_us\n"
           "SIZE 4 4 4 1 1 4 4 1 8\n"
           "TYPE F F F U U F F U F\n"
           "COUNT 1 1 1 1 1 1 1 1 1\n"
           "WIDTH ";
  width_position_ = file_.tellp();
  file_ << std::string(kCountWidth, ' ') << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS ";
  points_position_ = file_.tellp();
  file_ << std::string(kCountWidth, ' ') << "\nDATA ascii\n";
}

void PointFileWriter::add(const std::vector<Point>& points, std::uint32_t packet_time_past_hour)
{
  if (!error_.empty()) {
    return;
  }
  const char* row = format_ == PointFileFormat::kCsv ? "{},{},{},{},{},{},{},{},{:.3f}\n"
                                                     : "{} {} {} {} {} {} {} {} {:.3f}\n";
  fmt::memory_buffer buffer;
  for (const Point& point : points) {
    const double time_us =
        static_cast<double>(packet_time_past_hour) + static_cast<double>(point.time_offset_us);
    fmt::format_to(std::back_inserter(buffer), fmt::runtime(row), point.x, point.y, point.z,
                   static_cast<unsigned>(point.reflectivity), static_cast<unsigned>(point.ring),
                   point.azimuth_degrees, point.distance, static_cast<unsigned>(point.return_index), time_us);
  }
  file_.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
  points_ += static_cast<std::int64_t>(points.size());
}

bool PointFileWriter::finish()
{
  if (!error_.empty()) {
    return false;
  }
  if (format_ == PointFileFormat::kPcd) {
    const std::string count = fmt::format("{:<{}}", points_, kCountWidth);
    file_.seekp(width_position_);
    file_ << count;
    file_.seekp(points_position_);
    file_ << count;
  }
  file_.close();
  if (file_.fail()) {
    error_ = "writing '" + path_ + "' failed";
    return false;
  }
  return true;
}

}  // namespace ifar::velodyne
