#include "sim/importers/xml_elements.hpp"

#include <tinyxml2.h>

#include <utility>

namespace ifar::sim {

std::string XmlElement::localName() const
{
  const auto colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

std::optional<std::string> XmlElement::attribute(const std::string& key) const
{
  const auto found = attributes.find(key);
  if (found == attributes.end()) {
    return std::nullopt;
  }
  return found->second;
}

namespace {

/// tinyxml2's error as the project states it: what went wrong, naming the element when tinyxml2 does.
std::string describeError(const tinyxml2::XMLDocument& document)
{
  // ErrorStr() ends in "Line number=N: XMLElement name=NAME" when the error is about an element.
  const std::string detail = document.ErrorStr();
  const std::string marker = "XMLElement name=";
  const auto named = detail.find(marker);
  const std::string element =
      named == std::string::npos ? std::string() : "element <" + detail.substr(named + marker.size()) + ">";
  const std::string prefix = element.empty() ? std::string() : element + ": ";
  switch (document.ErrorID()) {
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE:
      return prefix + "an attribute cannot be read (a value not quoted or not closed, or a name repeated)";
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT:
      return prefix + "not closed by its own end tag";
    case tinyxml2::XML_ERROR_PARSING_ELEMENT:
      return prefix + "markup not closed";
    case tinyxml2::XML_ERROR_PARSING_COMMENT:
      return "comment not closed (missing '-->')";
    case tinyxml2::XML_ERROR_PARSING_CDATA:
      return "CDATA section not closed (missing ']]>')";
    case tinyxml2::XML_ERROR_PARSING_DECLARATION:
      return "declaration not closed (missing '?>')";
    case tinyxml2::XML_ERROR_PARSING_UNKNOWN:
      return "markup '<!...' not closed";
    case tinyxml2::XML_ERROR_EMPTY_DOCUMENT:
      return "no element in the document";
    case tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED:
      return "elements nested more than " + std::to_string(kXmlMaxDepth) + " deep";
    default:
      return prefix + document.ErrorName();
  }
}

}  // namespace

XmlScan scanXmlElements(const std::string& text)
{
  XmlScan scan;
  tinyxml2::XMLDocument document(true, tinyxml2::PRESERVE_WHITESPACE);
  if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    scan.error = "line " + std::to_string(document.ErrorLineNum()) + ": " + describeError(document);
    return scan;
  }
  // Depth first in document order, without recursion: (element, index of its parent, its depth).
  struct Pending {
    const tinyxml2::XMLElement* element;
    int parent;
    int depth;
  };
  std::vector<Pending> pending;
  for (const tinyxml2::XMLElement* top = document.LastChildElement(); top != nullptr;
       top = top->PreviousSiblingElement()) {
    pending.push_back({top, -1, 1});
  }
  while (!pending.empty()) {
    const Pending next = pending.back();
    pending.pop_back();
    if (next.depth > kXmlMaxDepth) {
      scan.elements.clear();
      scan.error = "line " + std::to_string(next.element->GetLineNum()) + ": elements nested more than " +
                   std::to_string(kXmlMaxDepth) + " deep";
      return scan;
    }
    XmlElement element;
    element.name = next.element->Name();
    element.line = next.element->GetLineNum();
    element.parent = next.parent;
    for (const tinyxml2::XMLAttribute* attribute = next.element->FirstAttribute(); attribute != nullptr;
         attribute = attribute->Next()) {
      element.attributes.emplace(attribute->Name(), attribute->Value());
    }
    const int index = static_cast<int>(scan.elements.size());
    scan.elements.push_back(std::move(element));
    for (const tinyxml2::XMLElement* child = next.element->LastChildElement(); child != nullptr;
         child = child->PreviousSiblingElement()) {
      pending.push_back({child, index, next.depth + 1});
    }
  }
  return scan;
}

}  // namespace ifar::sim
