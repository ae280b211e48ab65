#include "sim/importers/svg_map_image.hpp"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <vector>

#include "sim/importers/svg_shapes.hpp"

namespace ifar::sim {
namespace {

int base64Value(char character)
{
  if (character >= 'A' && character <= 'Z') {
    return character - 'A';
  }
  if (character >= 'a' && character <= 'z') {
    return character - 'a' + 26;
  }
  if (character >= '0' && character <= '9') {
    return character - '0' + 52;
  }
  if (character == '+') {
    return 62;
  }
  return character == '/' ? 63 : -1;
}

/// map_server's trinary reading of one pixel (negate 0, its default thresholds).
grid_map::Cell cellOf(png_byte grey, png_byte alpha)
{
  constexpr double kOccupied = 0.65;
  constexpr double kFree = 0.196;
  if (alpha < 128) {
    return grid_map::Cell::Unknown;
  }
  const double occupancy = (255.0 - grey) / 255.0;
  if (occupancy > kOccupied) {
    return grid_map::Cell::Blocked;
  }
  return occupancy < kFree ? grid_map::Cell::Free : grid_map::Cell::Unknown;
}

/// The PNG's pixels as a grid, or nullopt with `problem` set.
std::optional<grid_map::GridMap> decodePng(const std::string& bytes, std::string& problem)
{
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()) == 0) {
    problem = std::string("PNG data: ") + image.message;
    return std::nullopt;
  }
  const std::int64_t pixels = static_cast<std::int64_t>(image.width) * image.height;
  if (image.width == 0 || image.height == 0 || pixels > kSvgMapImageMaxPixels) {
    png_image_free(&image);
    problem = "PNG of " + std::to_string(image.width) + " x " + std::to_string(image.height) +
              " pixels (at most " + std::to_string(kSvgMapImageMaxPixels) + " are read)";
    return std::nullopt;
  }
  image.format = PNG_FORMAT_GA;  // grey and alpha, 8 bits each
  // Map images hold occupancy, not light: 16-bit samples scale down as they are (libpng would otherwise
  // take them for linear light and brighten the greys by its sRGB curve).
  image.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
  std::vector<png_byte> samples(PNG_IMAGE_SIZE(image));
  if (png_image_finish_read(&image, nullptr, samples.data(), 0, nullptr) == 0) {
    problem = std::string("PNG data: ") + image.message;
    png_image_free(&image);
    return std::nullopt;
  }
  const int width = static_cast<int>(image.width);
  const int height = static_cast<int>(image.height);
  grid_map::GridMap cells(width, height, 1.0, geometry::Point(0.0, 0.0));
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const std::size_t at = 2 * (static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                                  static_cast<std::size_t>(column));
      cells.set(column, row, cellOf(samples[at], samples[at + 1]));
    }
  }
  return cells;
}

}  // namespace

std::optional<std::string> decodeBase64(const std::string& text)
{
  std::string bytes;
  bytes.reserve(text.size() * 3 / 4);
  unsigned int buffer = 0;
  int bits = 0;
  bool padded = false;
  for (const char character : text) {
    if (std::isspace(static_cast<unsigned char>(character)) != 0) {
      continue;
    }
    if (character == '=') {
      padded = true;
      continue;
    }
    const int value = base64Value(character);
    if (value < 0 || padded) {
      return std::nullopt;
    }
    buffer = ((buffer << 6U) | static_cast<unsigned int>(value)) & 0xFFFFFFU;
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<char>((buffer >> static_cast<unsigned int>(bits)) & 0xFFU));
    }
  }
  return bytes;
}

std::optional<SvgMapImage> readSvgMapImage(const XmlElement& image, std::string& problem)
{
  const std::string href = image.attribute("xlink:href").value_or(image.attribute("href").value_or(""));
  const std::string png_prefix = "data:image/png";
  const auto comma = href.find(',');
  if (href.compare(0, png_prefix.size(), png_prefix) != 0 || comma == std::string::npos ||
      href.rfind(";base64", comma) == std::string::npos) {
    problem = "only PNG data URIs (data:image/png;base64,...) are read, not '" + href.substr(0, 40) + "'";
    return std::nullopt;
  }
  const auto bytes = decodeBase64(href.substr(comma + 1));
  if (!bytes) {
    problem = "the data URI is not base64";
    return std::nullopt;
  }
  auto cells = decodePng(*bytes, problem);
  if (!cells) {
    return std::nullopt;
  }
  const double pixels_x = cells->width();
  const double pixels_y = cells->height();
  const auto x = svgLengthAttribute(image, "x", 0.0, problem);
  const auto y = svgLengthAttribute(image, "y", 0.0, problem);
  const auto width = svgLengthAttribute(image, "width", pixels_x, problem);
  const auto height = svgLengthAttribute(image, "height", pixels_y, problem);
  if (!x || !y || !width || !height) {
    return std::nullopt;
  }
  if (!(*width > 0.0) || !(*height > 0.0)) {
    problem = "width and height must be positive";
    return std::nullopt;
  }
  SvgMapImage map{std::move(*cells), geometry::Point(*x, *y),
                  geometry::Point(*width / pixels_x, *height / pixels_y)};
  if (image.attribute("preserveAspectRatio").value_or("") != "none") {
    // SVG's default, xMidYMid meet: the whole bitmap, undistorted, centred in the box.
    const double fit = std::min(*width / pixels_x, *height / pixels_y);
    map.pixel_size = geometry::Point(fit, fit);
    map.origin += 0.5 * geometry::Point(*width - fit * pixels_x, *height - fit * pixels_y);
  }
  return map;
}

}  // namespace ifar::sim
