#include "sim/importers/svg_shapes.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "sim/importers/svg_number.hpp"

namespace ifar::sim {
namespace {

std::string number(double value)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.17g", value);
  return buffer;
}

std::string point(double x, double y)
{
  return number(x) + "," + number(y) + " ";
}

/// An arc command to (x, y) with radii (rx, ry), small and positive-angle sweep.
std::string arcTo(double rx, double ry, double x, double y)
{
  return "A " + number(rx) + "," + number(ry) + " 0 0 1 " + point(x, y);
}

/// Four length attributes (0 when absent); false with `error` set when one is not a length.
bool fourLengths(const XmlElement& element, const char* const (&keys)[4], double (&values)[4],
                 std::string& error)
{
  for (int index = 0; index < 4; ++index) {
    const auto value = svgLengthAttribute(element, keys[index], 0.0, error);
    if (!value) {
      return false;
    }
    values[index] = *value;
  }
  return true;
}

std::optional<std::string> rectData(const XmlElement& element, std::string& error)
{
  double values[4];
  if (!fourLengths(element, {"x", "y", "width", "height"}, values, error)) {
    return std::nullopt;
  }
  const double x = values[0];
  const double y = values[1];
  const double width = values[2];
  const double height = values[3];
  if (width < 0.0 || height < 0.0) {
    error = "negative width or height";
    return std::nullopt;
  }
  if (width == 0.0 || height == 0.0) {
    return std::string();  // not rendered
  }
  const auto rx_given = svgLengthAttribute(element, "rx", -1.0, error);
  const auto ry_given = svgLengthAttribute(element, "ry", -1.0, error);
  if (!rx_given || !ry_given) {
    return std::nullopt;
  }
  // SVG 1.1 9.2: a missing radius takes the other's value; both are clamped to half the side.
  double rx = *rx_given >= 0.0 ? *rx_given : std::max(0.0, *ry_given);
  double ry = *ry_given >= 0.0 ? *ry_given : rx;
  rx = std::min(rx, 0.5 * width);
  ry = std::min(ry, 0.5 * height);
  if (rx == 0.0 || ry == 0.0) {
    return "M " + point(x, y) + "H " + number(x + width) + " V " + number(y + height) + " H " + number(x) +
           " Z";
  }
  return "M " + point(x + rx, y) + "H " + number(x + width - rx) + " " + arcTo(rx, ry, x + width, y + ry) +
         "V " + number(y + height - ry) + " " + arcTo(rx, ry, x + width - rx, y + height) + "H " +
         number(x + rx) + " " + arcTo(rx, ry, x, y + height - ry) + "V " + number(y + ry) + " " +
         arcTo(rx, ry, x + rx, y) + "Z";
}

std::optional<std::string> ellipseData(const XmlElement& element, bool circle, std::string& error)
{
  const auto cx = svgLengthAttribute(element, "cx", 0.0, error);
  const auto cy = svgLengthAttribute(element, "cy", 0.0, error);
  const auto rx = svgLengthAttribute(element, circle ? "r" : "rx", 0.0, error);
  const auto ry = svgLengthAttribute(element, circle ? "r" : "ry", 0.0, error);
  if (!cx || !cy || !rx || !ry) {
    return std::nullopt;
  }
  if (*rx < 0.0 || *ry < 0.0) {
    error = "negative radius";
    return std::nullopt;
  }
  if (*rx == 0.0 || *ry == 0.0) {
    return std::string();  // not rendered
  }
  return "M " + point(*cx + *rx, *cy) + arcTo(*rx, *ry, *cx - *rx, *cy) + arcTo(*rx, *ry, *cx + *rx, *cy) +
         "Z";
}

std::optional<std::string> pointsData(const XmlElement& element, bool closed, std::string& error)
{
  const auto numbers = parseSvgNumberList(element.attribute("points").value_or(""));
  if (!numbers) {
    error = "attribute 'points' is not a list of numbers";
    return std::nullopt;
  }
  if (numbers->size() % 2 != 0) {
    error = "attribute 'points' needs x, y pairs, got an odd count of " + std::to_string(numbers->size()) +
            " numbers";
    return std::nullopt;
  }
  std::string data;
  for (std::size_t index = 0; index + 1 < numbers->size(); index += 2) {
    data += (index == 0 ? "M " : "L ") + point((*numbers)[index], (*numbers)[index + 1]);
  }
  return data.empty() || !closed ? data : data + "Z";
}

std::optional<std::string> lineData(const XmlElement& element, std::string& error)
{
  double values[4];
  if (!fourLengths(element, {"x1", "y1", "x2", "y2"}, values, error)) {
    return std::nullopt;
  }
  return "M " + point(values[0], values[1]) + "L " + point(values[2], values[3]);
}

}  // namespace

std::optional<double> svgLengthAttribute(const XmlElement& element, const std::string& key, double fallback,
                                         std::string& error)
{
  const auto text = element.attribute(key);
  if (!text) {
    return fallback;
  }
  std::size_t position = 0;
  double value = 0.0;
  if (readSvgNumber(*text, position, value)) {
    std::string rest = text->substr(position);
    rest.erase(std::remove_if(rest.begin(), rest.end(),
                              [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }),
               rest.end());
    if (rest.empty() || rest == "px") {
      return value;
    }
  }
  error = "attribute '" + key + "' is not a length in user units: '" + text->substr(0, 40) + "'";
  return std::nullopt;
}

bool isSvgShapeElement(const std::string& local_name)
{
  return local_name == "path" || local_name == "rect" || local_name == "circle" || local_name == "ellipse" ||
         local_name == "polygon" || local_name == "polyline" || local_name == "line";
}

std::optional<std::string> svgShapePathData(const XmlElement& element, std::string& error)
{
  const std::string local = element.localName();
  if (local == "path") {
    auto data = element.attribute("d");
    if (!data) {
      error = "path has no 'd' attribute";
    }
    return data;
  }
  if (local == "rect") {
    return rectData(element, error);
  }
  if (local == "circle" || local == "ellipse") {
    return ellipseData(element, local == "circle", error);
  }
  if (local == "polygon" || local == "polyline") {
    return pointsData(element, local == "polygon", error);
  }
  if (local == "line") {
    return lineData(element, error);
  }
  error =
      "unsupported element (expected <path>, <rect>, <circle>, <ellipse>, <polygon>, <polyline> or <line>)";
  return std::nullopt;
}

SvgPathParse svgShapeOutline(const XmlElement& element, const SvgFlattening& flattening)
{
  SvgPathParse result;
  const auto data = svgShapePathData(element, result.error);
  if (!data) {
    return result;
  }
  result = parseSvgPath(*data, flattening);
  if (!result.error.empty()) {
    result.error = (element.localName() == "path" ? "path data " : "shape ") + result.error;
  }
  return result;
}

}  // namespace ifar::sim
