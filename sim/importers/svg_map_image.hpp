#pragma once
// The map bitmap of a namosim ROS-map scenario: an SVG <image> holding its map as a PNG data URI
// (citi_ing.svg's map_layer), read as an occupancy grid the way map_server reads a map image (trinary:
// occupancy p = (255 - grey) / 255 above 0.65 blocked, below 0.196 free, else unknown; a pixel less than
// half opaque unknown), and placed where the SVG draws it.

#include <cstdint>
#include <optional>
#include <string>

#include "common/geometry/point.hpp"
#include "common/grid_map/grid_map.hpp"
#include "sim/importers/xml_elements.hpp"

namespace ifar::sim {

/// Largest bitmap read (pixels): a bound for any input, far above real scenario maps.
constexpr std::int64_t kSvgMapImageMaxPixels = 16'000'000;

struct SvgMapImage {
  /// One cell a pixel; cell (x, y) is pixel column x of row y, row 0 at the top (y down, as in SVG).
  grid_map::GridMap cells;
  /// Where pixel corner (0, 0) lands in the element's user units, and the size of one pixel there.
  geometry::Point origin;
  geometry::Point pixel_size;
  /// The pixel corner (x, y) in the element's user units.
  geometry::Point cornerAt(double x, double y) const
  {
    return origin + geometry::Point(x * pixel_size.x(), y * pixel_size.y());
  }
};

/// The element's bitmap and placement (x, y, width, height, preserveAspectRatio "none" or the default
/// centred fit), or nullopt with `problem` set ("only PNG data URIs are read", "PNG data: ...").
std::optional<SvgMapImage> readSvgMapImage(const XmlElement& image, std::string& problem);

/// Base64 (RFC 4648, white space ignored), or nullopt when anything else is in it. Exposed for tests.
std::optional<std::string> decodeBase64(const std::string& text);

}  // namespace ifar::sim
