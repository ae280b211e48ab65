#include "sim/importers/svg_document.hpp"

#include <algorithm>
#include <cmath>

#include "sim/importers/svg_number.hpp"
#include "sim/importers/svg_shapes.hpp"

namespace ifar::sim {
namespace {

bool isUndrawnContainer(const std::string& local_name)
{
  static const char* const kNames[] = {"defs",   "metadata",    "clipPath",  "mask",  "symbol", "pattern",
                                       "marker", "namo_config", "namedview", "title", "desc"};
  return std::any_of(std::begin(kNames), std::end(kNames),
                     [&local_name](const char* name) { return local_name == name; });
}

}  // namespace

std::optional<SvgViewBox> parseSvgViewBox(const std::string& text)
{
  const auto numbers = parseSvgNumberList(text);
  if (!numbers || numbers->size() != 4) {
    return std::nullopt;
  }
  SvgViewBox box{(*numbers)[0], (*numbers)[1], (*numbers)[2], (*numbers)[3]};
  if (!(box.width > 0.0) || !(box.height > 0.0) || !std::isfinite(box.width) || !std::isfinite(box.height) ||
      !std::isfinite(box.min_x) || !std::isfinite(box.min_y)) {
    return std::nullopt;
  }
  return box;
}

SvgDocument::Parse SvgDocument::parse(const std::string& text)
{
  Parse result;
  XmlScan scan = scanXmlElements(text);
  if (!scan.error.empty()) {
    result.error = "malformed XML at " + scan.error;
    return result;
  }
  SvgDocument document;
  document.elements_ = std::move(scan.elements);
  const auto& elements = document.elements_;
  if (elements.empty() || elements.front().localName() != "svg") {
    result.error = "no <svg> root element with a viewBox";
    return result;
  }
  const auto view_box_text = elements.front().attribute("viewBox");
  if (!view_box_text) {
    result.error = document.describe(0) + ": no viewBox attribute (needed to flip y)";
    return result;
  }
  const auto view_box = parseSvgViewBox(*view_box_text);
  if (!view_box) {
    result.error = document.describe(0) + ": viewBox '" + view_box_text->substr(0, 80) +
                   "' is not four numbers with positive width and height";
    return result;
  }
  document.view_box_ = *view_box;
  const std::size_t count = elements.size();
  document.user_space_.assign(count, SvgTransform::Identity());
  document.bad_transforms_.assign(count, BadTransform());
  document.drawn_.assign(count, true);
  // Parents come before their children in document order, so one pass composes every user space.
  for (std::size_t index = 0; index < count; ++index) {
    const XmlElement& element = elements[index];
    SvgTransform parent_space = SvgTransform::Identity();
    if (element.parent >= 0) {
      const auto parent = static_cast<std::size_t>(element.parent);
      parent_space = document.user_space_[parent];
      document.bad_transforms_[index] = document.bad_transforms_[parent];
      document.drawn_[index] = document.drawn_[parent];
    }
    if (isUndrawnContainer(element.localName())) {
      document.drawn_[index] = false;
    }
    document.user_space_[index] = parent_space;
    if (const auto own = element.attribute("transform"); own && document.bad_transforms_[index].element < 0) {
      const SvgTransformParse parsed = parseSvgTransform(*own);
      if (!parsed.error.empty()) {
        document.bad_transforms_[index] = BadTransform{static_cast<int>(index), parsed.error};
      } else {
        document.user_space_[index] = parent_space * parsed.transform;
      }
    }
    if (const auto id = element.attribute("id")) {
      document.ids_.emplace(*id, index);
    }
  }
  result.document = std::move(document);
  return result;
}

std::optional<std::size_t> SvgDocument::findById(const std::string& id) const
{
  const auto found = ids_.find(id);
  if (found == ids_.end()) {
    return std::nullopt;
  }
  return found->second;
}

bool SvgDocument::isInside(std::size_t index, std::size_t ancestor) const
{
  for (int parent = elements_[index].parent; parent >= 0;
       parent = elements_[static_cast<std::size_t>(parent)].parent) {
    if (static_cast<std::size_t>(parent) == ancestor) {
      return true;
    }
  }
  return false;
}

std::string SvgDocument::describe(std::size_t index) const
{
  const XmlElement& element = elements_[index];
  const auto id = element.attribute("id");
  return "element <" + element.name + ">" + (id ? " '" + id->substr(0, 80) + "'" : std::string()) +
         " (line " + std::to_string(element.line) + ")";
}

SvgPathParse SvgDocument::outline(std::size_t index, double tolerance) const
{
  if (const BadTransform& bad = bad_transforms_[index]; bad.element >= 0) {
    SvgPathParse failed;
    failed.error = (static_cast<std::size_t>(bad.element) == index
                        ? std::string("transform")
                        : "transform of " + describe(static_cast<std::size_t>(bad.element))) +
                   ": " + bad.problem;
    return failed;
  }
  const SvgTransform& space = user_space_[index];
  const double stretch = largestStretch(space);
  SvgFlattening flattening;
  flattening.tolerance = stretch > 0.0 && std::isfinite(stretch) ? tolerance / stretch : tolerance;
  SvgPathParse parsed = svgShapeOutline(elements_[index], flattening);
  if (!space.matrix().isIdentity()) {
    for (auto& subpath : parsed.subpaths) {
      for (auto& point : subpath.points) {
        point = space * point;
      }
    }
  }
  return parsed;
}

}  // namespace ifar::sim
