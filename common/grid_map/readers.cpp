#include "common/grid_map/readers.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <yaml-cpp/yaml.h>

namespace ifar::grid_map {
namespace {

std::string where(const std::string& path, int line)
{
  return path + ":" + std::to_string(line) + ": ";
}

/// Reads "key value" where value is a positive integer; returns false with `error` set otherwise.
bool readHeaderNumber(std::istream& input, const std::string& path, int& line, const std::string& key,
                      int& value, std::string& error)
{
  std::string text;
  ++line;
  if (!std::getline(input, text)) {
    error = where(path, line) + "missing '" + key + "' line";
    return false;
  }
  std::istringstream fields(text);
  std::string found;
  long long number = 0;
  if (!(fields >> found >> number) || found != key) {
    error = where(path, line) + "expected '" + key + " <number>', found '" + text + "'";
    return false;
  }
  if (number <= 0 || number > 100000) {
    error = where(path, line) + key + " " + std::to_string(number) + " is out of range (1..100000)";
    return false;
  }
  value = static_cast<int>(number);
  return true;
}

/// Why a map of `width` x `height` cells, each taking at least `bytes_per_cell` of the file, cannot be
/// read from `input` (positioned after the header of `path`); empty when it can.
std::string sizeProblem(std::istream& input, const std::string& path, int width, int height,
                        std::int64_t bytes_per_cell, const MapReadLimits& limits)
{
  const std::int64_t cells = static_cast<std::int64_t>(width) * height;
  if (cells > limits.max_cells) {
    return path + ": " + std::to_string(width) + " x " + std::to_string(height) +
           " cells exceed the limit of " + std::to_string(limits.max_cells);
  }
  const std::streampos here = input.tellg();
  input.seekg(0, std::ios::end);
  const std::streampos end = input.tellg();
  input.seekg(here);
  if (here < 0 || end < 0 || !input) {
    return path + ": cannot tell the file's size";
  }
  const std::int64_t remaining = static_cast<std::int64_t>(end - here);
  if (remaining < cells * bytes_per_cell) {
    return path + ": the header says " + std::to_string(width) + " x " + std::to_string(height) +
           " cells but only " + std::to_string(remaining) + " bytes follow it";
  }
  return {};
}

/// Non-empty when `path` exists and is not a regular file (a folder, or a device or pipe that may never
/// end); a missing file is left to the reader's "cannot open".
std::string notRegularFile(const std::string& path)
{
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  return !std::filesystem::exists(status) || std::filesystem::is_regular_file(status)
             ? std::string()
             : path + ": not a regular file";
}

void trimCarriageReturn(std::string& text)
{
  if (!text.empty() && text.back() == '\r') {
    text.pop_back();
  }
}

}  // namespace

MapReadResult readMovingAiMap(const std::string& path, const MapReadLimits& limits)
{
  MapReadResult result;
  result.error = notRegularFile(path);
  if (!result.error.empty()) {
    return result;
  }
  std::ifstream input(path, std::ios::binary);
  if (!input) {
    result.error = path + ": cannot open";
    return result;
  }
  int line = 1;
  std::string text;
  if (!std::getline(input, text)) {
    result.error = where(path, line) + "empty file";
    return result;
  }
  trimCarriageReturn(text);
  if (text.rfind("type", 0) != 0) {
    result.error = where(path, line) + "expected 'type <name>', found '" + text + "'";
    return result;
  }
  int height = 0;
  int width = 0;
  if (!readHeaderNumber(input, path, line, "height", height, result.error) ||
      !readHeaderNumber(input, path, line, "width", width, result.error)) {
    return result;
  }
  ++line;
  if (!std::getline(input, text) || (trimCarriageReturn(text), text != "map")) {
    result.error = where(path, line) + "expected 'map'";
    return result;
  }
  // Each row is its width in characters (and a line break, except perhaps the last).
  result.error = sizeProblem(input, path, width, height, 1, limits);
  if (!result.error.empty()) {
    return result;
  }
  GridMap map(width, height, 1.0, geometry::Point::Zero(), Cell::Free);
  for (int y = 0; y < height; ++y) {
    ++line;
    if (!std::getline(input, text)) {
      result.error = where(path, line) + "file ends after " + std::to_string(y) + " of " +
                     std::to_string(height) + " rows";
      return result;
    }
    trimCarriageReturn(text);
    if (static_cast<int>(text.size()) != width) {
      result.error = where(path, line) + "row has " + std::to_string(text.size()) + " cells, expected " +
                     std::to_string(width);
      return result;
    }
    for (int x = 0; x < width; ++x) {
      switch (text[static_cast<std::size_t>(x)]) {
        case '.':
        case 'G':
        case 'S':
          break;
        case '@':
        case 'O':
        case 'T':
        case 'W':
          map.set(x, y, Cell::Blocked);
          break;
        default:
          result.error = where(path, line) + "column " + std::to_string(x + 1) +
                         ": unknown cell character '" + std::string(1, text[static_cast<std::size_t>(x)]) +
                         "'";
          return result;
      }
    }
  }
  result.map = std::move(map);
  return result;
}

ScenarioReadResult readMovingAiScenarios(const std::string& path)
{
  ScenarioReadResult result;
  std::ifstream input(path);
  if (!input) {
    result.error = path + ": cannot open";
    return result;
  }
  std::string text;
  int line = 1;
  if (!std::getline(input, text) || (trimCarriageReturn(text), text.rfind("version", 0) != 0)) {
    result.error = where(path, line) + "expected 'version 1'";
    return result;
  }
  while (std::getline(input, text)) {
    ++line;
    trimCarriageReturn(text);
    if (text.find_first_not_of(" \t") == std::string::npos) {
      continue;
    }
    std::istringstream fields(text);
    Scenario scenario;
    double start_x = 0.0;
    double start_y = 0.0;
    double goal_x = 0.0;
    double goal_y = 0.0;
    if (!(fields >> scenario.bucket >> scenario.map_name >> scenario.map_width >> scenario.map_height >>
          start_x >> start_y >> goal_x >> goal_y >> scenario.optimal_length)) {
      result.error = where(path, line) +
                     "expected 'bucket map width height start_x start_y goal_x goal_y length', found '" +
                     text + "'";
      return result;
    }
    scenario.start = geometry::Point(start_x, start_y);
    scenario.goal = geometry::Point(goal_x, goal_y);
    if (!scenario.start.allFinite() || !scenario.goal.allFinite() ||
        !std::isfinite(scenario.optimal_length)) {
      result.error = where(path, line) + "non-finite number";
      return result;
    }
    result.scenarios.push_back(scenario);
  }
  return result;
}

namespace {

std::string directoryOf(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

/// Next PGM header token, skipping whitespace and '#' comments.
bool nextPgmToken(std::istream& input, std::string& token)
{
  token.clear();
  int character = input.get();
  while (character != EOF) {
    if (character == '#') {
      while (character != EOF && character != '\n') {
        character = input.get();
      }
    } else if (std::isspace(character) != 0) {
      character = input.get();
    } else {
      break;
    }
  }
  while (character != EOF && std::isspace(character) == 0 && character != '#') {
    token.push_back(static_cast<char>(character));
    character = input.get();
  }
  // The single whitespace after the max value is consumed above, as P5 requires.
  return !token.empty();
}

bool parseInRange(const std::string& token, long long lowest, long long highest, int& value)
{
  char* end = nullptr;
  const long long number = std::strtoll(token.c_str(), &end, 10);
  if (end == token.c_str() || *end != '\0' || number < lowest || number > highest) {
    return false;
  }
  value = static_cast<int>(number);
  return true;
}

bool parsePositive(const std::string& token, long long limit, int& value)
{
  return parseInRange(token, 1, limit, value);
}

}  // namespace

MapReadResult readMapServer(const std::string& yaml_path, const MapReadLimits& limits)
{
  MapReadResult result;
  YAML::Node root;
  try {
    root = YAML::LoadFile(yaml_path);
  } catch (const YAML::BadFile&) {
    result.error = yaml_path + ": cannot open";
    return result;
  } catch (const YAML::Exception& error) {
    result.error = yaml_path + ":" + std::to_string(error.mark.line + 1) + ": " + error.msg;
    return result;
  }
  if (!root.IsMap()) {
    result.error = yaml_path + ": expected a map of keys";
    return result;
  }
  std::string image;
  double resolution = 0.0;
  std::vector<double> origin;
  int negate = 0;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  std::string mode = "trinary";
  const auto fail = [&](const std::string& key, const std::string& problem) {
    result.error = yaml_path + ": key '" + key + "': " + problem;
    return result;
  };
  for (const auto& entry : root) {
    const std::string key = entry.first.as<std::string>();
    try {
      if (key == "image") {
        image = entry.second.as<std::string>();
      } else if (key == "resolution") {
        resolution = entry.second.as<double>();
      } else if (key == "origin") {
        origin = entry.second.as<std::vector<double>>();
      } else if (key == "negate") {
        negate = entry.second.as<int>();
      } else if (key == "occupied_thresh") {
        occupied_thresh = entry.second.as<double>();
      } else if (key == "free_thresh") {
        free_thresh = entry.second.as<double>();
      } else if (key == "mode") {
        mode = entry.second.as<std::string>();
      } else {
        return fail(key, "unknown key");
      }
    } catch (const YAML::Exception&) {
      return fail(key, "wrong type");
    }
  }
  if (image.empty()) {
    return fail("image", "missing");
  }
  if (!(std::isfinite(resolution) && resolution > 0.0)) {
    return fail("resolution", "missing or not a positive number");
  }
  if (origin.size() != 3 || !std::isfinite(origin[0]) || !std::isfinite(origin[1]) ||
      !std::isfinite(origin[2])) {
    return fail("origin", "expected [x, y, yaw] with finite numbers");
  }
  if (origin[2] != 0.0) {
    return fail("origin", "a non-zero yaw is not supported");
  }
  if (negate != 0 && negate != 1) {
    return fail("negate", "expected 0 or 1");
  }
  if (!(free_thresh >= 0.0 && free_thresh <= occupied_thresh && occupied_thresh <= 1.0)) {
    return fail("occupied_thresh", "expected 0 <= free_thresh <= occupied_thresh <= 1");
  }
  if (mode != "trinary" && mode != "scale") {
    return fail("mode", "expected trinary or scale (raw is not supported)");
  }

  const std::string image_path = image.front() == '/' ? image : directoryOf(yaml_path) + image;
  result.error = notRegularFile(image_path);
  if (!result.error.empty()) {
    result.error += " (image of " + yaml_path + ")";
    return result;
  }
  std::ifstream input(image_path, std::ios::binary);
  if (!input) {
    result.error = image_path + ": cannot open (image of " + yaml_path + ")";
    return result;
  }
  std::string magic;
  std::string token;
  int width = 0;
  int height = 0;
  int max_value = 0;
  if (!nextPgmToken(input, magic) || (magic != "P5" && magic != "P2")) {
    result.error = image_path + ": not a PGM file (expected P5 or P2)";
    return result;
  }
  if (!nextPgmToken(input, token) || !parsePositive(token, 100000, width) || !nextPgmToken(input, token) ||
      !parsePositive(token, 100000, height)) {
    result.error = image_path + ": header: bad width or height";
    return result;
  }
  if (!nextPgmToken(input, token) || !parsePositive(token, 65535, max_value)) {
    result.error = image_path + ": header: bad maximum value";
    return result;
  }
  // P5 holds one byte a pixel (two above 255), P2 at least a digit and a separator.
  result.error =
      sizeProblem(input, image_path, width, height, magic == "P2" || max_value > 255 ? 2 : 1, limits);
  if (!result.error.empty()) {
    return result;
  }
  GridMap map(width, height, resolution, geometry::Point(origin[0], origin[1]), Cell::Free);
  const bool wide = max_value > 255;
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      int value = 0;
      if (magic == "P5") {
        const int high = input.get();
        const int low = wide ? input.get() : 0;
        if (!input) {
          result.error = image_path + ": pixel data ends at row " + std::to_string(row) + " of " +
                         std::to_string(height);
          return result;
        }
        value = wide ? (high << 8) | low : high;
      } else if (!nextPgmToken(input, token) || !parseInRange(token, 0, 65535, value)) {
        result.error = image_path + ": pixel " + std::to_string(row * width + column) + ": bad value";
        return result;
      }
      if (value > max_value) {
        result.error = image_path + ": pixel at row " + std::to_string(row) + " column " +
                       std::to_string(column) + " exceeds the maximum value";
        return result;
      }
      const double brightness = static_cast<double>(value) / max_value;
      const double occupancy = negate != 0 ? brightness : 1.0 - brightness;
      Cell cell = Cell::Unknown;
      if (occupancy > occupied_thresh) {
        cell = Cell::Blocked;
      } else if (occupancy < free_thresh) {
        cell = Cell::Free;
      }
      map.set(column, height - 1 - row, cell);
    }
  }
  result.map = std::move(map);
  return result;
}

MapReadResult readGridMapFile(const std::string& path, const MapReadLimits& limits)
{
  const auto ends_with = [&](const std::string& suffix) {
    return path.size() >= suffix.size() &&
           path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends_with(".yaml") || ends_with(".yml")) {
    return readMapServer(path, limits);
  }
  return readMovingAiMap(path, limits);
}

}  // namespace ifar::grid_map
