#include "sim/importers/xml_elements.hpp"

#include <algorithm>
#include <cctype>

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

bool isNameCharacter(char character)
{
  const auto byte = static_cast<unsigned char>(character);
  return std::isalnum(byte) != 0 || character == ':' || character == '_' || character == '-' ||
         character == '.' || byte >= 0x80;
}

std::string decodeEntities(const std::string& raw)
{
  static const std::pair<const char*, char> kEntities[] = {
      {"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t index = 0; index < raw.size();) {
    bool replaced = false;
    if (raw[index] == '&') {
      for (const auto& [entity, character] : kEntities) {
        const std::string name(entity);
        if (raw.compare(index, name.size(), name) == 0) {
          out += character;
          index += name.size();
          replaced = true;
          break;
        }
      }
    }
    if (!replaced) {
      out += raw[index++];
    }
  }
  return out;
}

class Scanner {
 public:
  explicit Scanner(const std::string& text) : text_(text) {}

  XmlScan run()
  {
    XmlScan scan;
    while (position_ < text_.size()) {
      const auto open = text_.find('<', position_);
      if (open == std::string::npos) {
        break;
      }
      advanceTo(open);
      if (startsWith("<!--")) {
        if (!skipPast("-->", scan)) {
          return scan;
        }
      } else if (startsWith("<![CDATA[")) {
        if (!skipPast("]]>", scan)) {
          return scan;
        }
      } else if (startsWith("</")) {
        if (!readEndTag(scan)) {
          return scan;
        }
      } else if (startsWith("<?") || startsWith("<!")) {
        // Declarations and the doctype carry nothing the importer reads.
        if (!skipPast(">", scan)) {
          return scan;
        }
      } else if (!readElement(scan)) {
        return scan;
      }
    }
    if (!open_.empty()) {
      const XmlElement& unclosed = scan.elements[static_cast<std::size_t>(open_.back())];
      fail(scan, "element <" + unclosed.name + "> (line " + std::to_string(unclosed.line) + ") not closed");
    }
    return scan;
  }

 private:
  bool startsWith(const char* prefix) const
  {
    return text_.compare(position_, std::char_traits<char>::length(prefix), prefix) == 0;
  }

  void advanceTo(std::size_t target)
  {
    line_ += static_cast<int>(std::count(text_.begin() + static_cast<std::ptrdiff_t>(position_),
                                         text_.begin() + static_cast<std::ptrdiff_t>(target), '\n'));
    position_ = target;
  }

  bool fail(XmlScan& scan, const std::string& problem) const
  {
    scan.error = "line " + std::to_string(line_) + ": " + problem;
    return false;
  }

  bool skipPast(const std::string& terminator, XmlScan& scan)
  {
    const auto end = text_.find(terminator, position_);
    if (end == std::string::npos) {
      return fail(scan, "markup not closed (missing '" + terminator + "')");
    }
    advanceTo(end + terminator.size());
    return true;
  }

  void skipSpace()
  {
    while (position_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[position_])) != 0) {
      if (text_[position_] == '\n') {
        ++line_;
      }
      ++position_;
    }
  }

  std::string readName()
  {
    const auto begin = position_;
    while (position_ < text_.size() && isNameCharacter(text_[position_])) {
      ++position_;
    }
    return text_.substr(begin, position_ - begin);
  }

  bool readEndTag(XmlScan& scan)
  {
    position_ += 2;  // "</"
    const std::string name = readName();
    skipSpace();
    if (position_ >= text_.size() || text_[position_] != '>') {
      return fail(scan, "end tag </" + name + "> not closed by '>'");
    }
    ++position_;
    if (open_.empty()) {
      return fail(scan, "end tag </" + name + "> without a start tag");
    }
    const XmlElement& innermost = scan.elements[static_cast<std::size_t>(open_.back())];
    if (innermost.name != name) {
      return fail(scan, "end tag </" + name + "> does not match <" + innermost.name + "> (line " +
                            std::to_string(innermost.line) + ")");
    }
    open_.pop_back();
    return true;
  }

  bool readElement(XmlScan& scan)
  {
    XmlElement element;
    element.line = line_;
    element.parent = open_.empty() ? -1 : open_.back();
    ++position_;  // '<'
    element.name = readName();
    if (element.name.empty()) {
      return fail(scan, "'<' not followed by an element name");
    }
    bool has_content = false;
    while (true) {
      skipSpace();
      if (position_ >= text_.size()) {
        return fail(scan, "element <" + element.name + "> not closed");
      }
      if (text_[position_] == '>') {
        ++position_;
        has_content = true;
        break;
      }
      if (startsWith("/>")) {
        position_ += 2;
        break;
      }
      const auto key = readName();
      if (key.empty()) {
        return fail(scan, "element <" + element.name + ">: unexpected character '" +
                              std::string(1, text_[position_]) + "'");
      }
      skipSpace();
      if (position_ >= text_.size() || text_[position_] != '=') {
        return fail(scan, "element <" + element.name + ">: attribute '" + key + "' has no value");
      }
      ++position_;
      skipSpace();
      if (position_ >= text_.size() || (text_[position_] != '"' && text_[position_] != '\'')) {
        return fail(scan, "element <" + element.name + ">: attribute '" + key + "' value not quoted");
      }
      const char quote = text_[position_];
      const auto close = text_.find(quote, position_ + 1);
      if (close == std::string::npos) {
        return fail(scan, "element <" + element.name + ">: attribute '" + key + "' value not closed");
      }
      const std::string raw = text_.substr(position_ + 1, close - position_ - 1);
      advanceTo(close + 1);
      if (!element.attributes.emplace(key, decodeEntities(raw)).second) {
        return fail(scan, "element <" + element.name + ">: attribute '" + key + "' repeated");
      }
    }
    if (has_content) {
      if (static_cast<int>(open_.size()) >= kXmlMaxDepth) {
        return fail(scan, "elements nested more than " + std::to_string(kXmlMaxDepth) + " deep");
      }
      open_.push_back(static_cast<int>(scan.elements.size()));
    }
    scan.elements.push_back(std::move(element));
    return true;
  }

  const std::string& text_;
  std::size_t position_ = 0;
  int line_ = 1;
  std::vector<int> open_;  // indices of the elements whose end tag is still to come, outermost first
};

}  // namespace

XmlScan scanXmlElements(const std::string& text)
{
  return Scanner(text).run();
}

}  // namespace ifar::sim
