#include "sim/importers/svg_path.hpp"

#include <cctype>
#include <charconv>
#include <cstring>

namespace ifar::sim {
namespace {

using geometry::Point;

bool isCommand(char character)
{
  return std::strchr("MmLlHhVvZzCcSsQqTtAa", character) != nullptr && character != '\0';
}

class PathParser {
 public:
  PathParser(const std::string& data, int curve_segments) : data_(data), curve_segments_(curve_segments) {}

  SvgPathParse run()
  {
    SvgPathParse result;
    char command = '\0';
    while (true) {
      skipSeparators();
      if (position_ >= data_.size()) {
        break;
      }
      const char next = data_[position_];
      if (std::isalpha(static_cast<unsigned char>(next)) != 0) {
        if (!isCommand(next)) {
          return fail(result, "unknown path command '" + std::string(1, next) + "'");
        }
        if (next == 'A' || next == 'a') {
          return fail(result, "elliptical arc command '" + std::string(1, next) + "' is not supported");
        }
        command = next;
        ++position_;
        if (command == 'Z' || command == 'z') {
          closeSubpath(result);
          continue;
        }
      } else if (command == '\0') {
        return fail(result, "path data must start with a moveto command");
      } else if (command == 'Z' || command == 'z') {
        return fail(result, "number after closepath without a command");
      }
      if (!execute(command, result)) {
        return result;
      }
      // After a moveto, further coordinate pairs are implicit linetos.
      if (command == 'M') {
        command = 'L';
      } else if (command == 'm') {
        command = 'l';
      }
    }
    finishSubpath(result);
    return result;
  }

 private:
  SvgPathParse& fail(SvgPathParse& result, const std::string& problem) const
  {
    result.error = "at character " + std::to_string(position_) + ": " + problem;
    return result;
  }

  void skipSeparators()
  {
    while (position_ < data_.size() &&
           (std::isspace(static_cast<unsigned char>(data_[position_])) != 0 || data_[position_] == ',')) {
      ++position_;
    }
  }

  /// SVG number: sign, digits, fraction, exponent; "1.5.5" reads as 1.5 then .5.
  bool readNumber(double& value)
  {
    skipSeparators();
    std::size_t end = position_;
    if (end < data_.size() && (data_[end] == '-' || data_[end] == '+')) {
      ++end;
    }
    bool digits = false;
    while (end < data_.size() && std::isdigit(static_cast<unsigned char>(data_[end])) != 0) {
      ++end;
      digits = true;
    }
    if (end < data_.size() && data_[end] == '.') {
      ++end;
      while (end < data_.size() && std::isdigit(static_cast<unsigned char>(data_[end])) != 0) {
        ++end;
        digits = true;
      }
    }
    if (!digits) {
      return false;
    }
    if (end < data_.size() && (data_[end] == 'e' || data_[end] == 'E')) {
      std::size_t exponent = end + 1;
      if (exponent < data_.size() && (data_[exponent] == '-' || data_[exponent] == '+')) {
        ++exponent;
      }
      if (exponent < data_.size() && std::isdigit(static_cast<unsigned char>(data_[exponent])) != 0) {
        end = exponent;
        while (end < data_.size() && std::isdigit(static_cast<unsigned char>(data_[end])) != 0) {
          ++end;
        }
      }
    }
    std::size_t begin = position_;
    if (data_[begin] == '+') {
      ++begin;  // from_chars does not take a plus sign
    }
    const auto parsed = std::from_chars(data_.data() + begin, data_.data() + end, value);
    if (parsed.ec != std::errc() || parsed.ptr != data_.data() + end) {
      return false;
    }
    position_ = end;
    return true;
  }

  bool readNumbers(double* values, int count, SvgPathParse& result, char command)
  {
    for (int index = 0; index < count; ++index) {
      if (!readNumber(values[index])) {
        fail(result, std::string("command '") + command + "' expects " + std::to_string(count) + " numbers");
        return false;
      }
    }
    return true;
  }

  void finishSubpath(SvgPathParse& result)
  {
    if (!current_.points.empty()) {
      result.subpaths.push_back(std::move(current_));
    }
    current_ = SvgSubpath();
  }

  void closeSubpath(SvgPathParse& result)
  {
    if (!current_.points.empty()) {
      current_.closed = true;
      pen_ = subpath_start_;
    }
    finishSubpath(result);
    last_control_valid_ = false;
  }

  void lineTo(const Point& point)
  {
    if (current_.points.empty()) {
      current_.points.push_back(pen_);  // drawing after Z continues from the subpath's start
    }
    current_.points.push_back(point);
    pen_ = point;
  }

  void cubic(const Point& first, const Point& second, const Point& end)
  {
    const Point begin = pen_;
    for (int step = 1; step <= curve_segments_; ++step) {
      const double t = static_cast<double>(step) / curve_segments_;
      const double u = 1.0 - t;
      lineTo(u * u * u * begin + 3.0 * u * u * t * first + 3.0 * u * t * t * second + t * t * t * end);
    }
    last_control_ = second;
    last_control_valid_ = true;
    last_was_cubic_ = true;
  }

  void quadratic(const Point& control, const Point& end)
  {
    const Point begin = pen_;
    for (int step = 1; step <= curve_segments_; ++step) {
      const double t = static_cast<double>(step) / curve_segments_;
      const double u = 1.0 - t;
      lineTo(u * u * begin + 2.0 * u * t * control + t * t * end);
    }
    last_control_ = control;
    last_control_valid_ = true;
    last_was_cubic_ = false;
  }

  /// The reflection of the previous curve's control point, or the pen when the previous command differs.
  Point reflected(bool want_cubic) const
  {
    if (last_control_valid_ && last_was_cubic_ == want_cubic) {
      return 2.0 * pen_ - last_control_;
    }
    return pen_;
  }

  bool execute(char command, SvgPathParse& result)
  {
    const bool relative = std::islower(static_cast<unsigned char>(command)) != 0;
    const Point origin = relative ? pen_ : Point(0.0, 0.0);
    double values[6];
    bool curve = false;
    switch (std::toupper(static_cast<unsigned char>(command))) {
      case 'M': {
        if (!readNumbers(values, 2, result, command)) {
          return false;
        }
        finishSubpath(result);
        pen_ = origin + Point(values[0], values[1]);
        subpath_start_ = pen_;
        current_.points.push_back(pen_);
        break;
      }
      case 'L': {
        if (!readNumbers(values, 2, result, command)) {
          return false;
        }
        lineTo(origin + Point(values[0], values[1]));
        break;
      }
      case 'H': {
        if (!readNumbers(values, 1, result, command)) {
          return false;
        }
        lineTo(Point(relative ? pen_.x() + values[0] : values[0], pen_.y()));
        break;
      }
      case 'V': {
        if (!readNumbers(values, 1, result, command)) {
          return false;
        }
        lineTo(Point(pen_.x(), relative ? pen_.y() + values[0] : values[0]));
        break;
      }
      case 'C': {
        if (!readNumbers(values, 6, result, command)) {
          return false;
        }
        cubic(origin + Point(values[0], values[1]), origin + Point(values[2], values[3]),
              origin + Point(values[4], values[5]));
        curve = true;
        break;
      }
      case 'S': {
        if (!readNumbers(values, 4, result, command)) {
          return false;
        }
        cubic(reflected(true), origin + Point(values[0], values[1]), origin + Point(values[2], values[3]));
        curve = true;
        break;
      }
      case 'Q': {
        if (!readNumbers(values, 4, result, command)) {
          return false;
        }
        quadratic(origin + Point(values[0], values[1]), origin + Point(values[2], values[3]));
        curve = true;
        break;
      }
      case 'T': {
        if (!readNumbers(values, 2, result, command)) {
          return false;
        }
        quadratic(reflected(false), origin + Point(values[0], values[1]));
        curve = true;
        break;
      }
      default:
        fail(result, std::string("unexpected command '") + command + "'");
        return false;
    }
    if (!curve) {
      last_control_valid_ = false;
    }
    return true;
  }

  const std::string& data_;
  const int curve_segments_;
  std::size_t position_ = 0;
  Point pen_ = Point(0.0, 0.0);
  Point subpath_start_ = Point(0.0, 0.0);
  Point last_control_ = Point(0.0, 0.0);
  bool last_control_valid_ = false;
  bool last_was_cubic_ = false;
  SvgSubpath current_;
};

}  // namespace

SvgPathParse parseSvgPath(const std::string& data, int curve_segments)
{
  return PathParser(data, curve_segments < 1 ? 1 : curve_segments).run();
}

}  // namespace ifar::sim
