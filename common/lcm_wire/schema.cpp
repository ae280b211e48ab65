#include "common/lcm_wire/schema.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>
#include <utility>

namespace ifar::lcm_wire {

std::size_t fixedWireSize(FieldKind kind)
{
  switch (kind) {
    case FieldKind::kInt8:
    case FieldKind::kBoolean:
    case FieldKind::kByte:
      return 1;
    case FieldKind::kInt16:
      return 2;
    case FieldKind::kInt32:
    case FieldKind::kFloat:
      return 4;
    case FieldKind::kInt64:
    case FieldKind::kDouble:
      return 8;
    case FieldKind::kString:
    case FieldKind::kStruct:
      return 0;
  }
  return 0;
}

bool isInteger(FieldKind kind)
{
  return kind == FieldKind::kInt8 || kind == FieldKind::kInt16 || kind == FieldKind::kInt32 ||
         kind == FieldKind::kInt64 || kind == FieldKind::kByte;
}

namespace {

struct Token {
  std::string text;
  int line = 0;
};

bool isWordCharacter(char character)
{
  return std::isalnum(static_cast<unsigned char>(character)) != 0 || character == '_' || character == '.' ||
         character == '-' || character == '+';
}

/// Words (names, numbers, qualified type names) and the punctuation `{ } [ ] ; , =`, comments dropped.
std::vector<Token> tokenize(std::string_view text, const std::string& file_name)
{
  std::vector<Token> tokens;
  int line = 1;
  std::size_t position = 0;
  while (position < text.size()) {
    const char character = text[position];
    if (character == '\n') {
      ++line;
      ++position;
    } else if (std::isspace(static_cast<unsigned char>(character)) != 0) {
      ++position;
    } else if (text.compare(position, 2, "//") == 0) {
      position = std::min(text.find('\n', position), text.size());
    } else if (text.compare(position, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", position + 2);
      if (end == std::string_view::npos) {
        throw SchemaError(file_name + ":" + std::to_string(line) + ": comment never closed");
      }
      line += static_cast<int>(std::count(text.begin() + static_cast<std::ptrdiff_t>(position),
                                          text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
      position = end + 2;
    } else if (std::string_view("{}[];,=").find(character) != std::string_view::npos) {
      tokens.push_back({std::string(1, character), line});
      ++position;
    } else if (isWordCharacter(character)) {
      const std::size_t start = position;
      while (position < text.size() && isWordCharacter(text[position])) {
        ++position;
      }
      tokens.push_back({std::string(text.substr(start, position - start)), line});
    } else {
      throw SchemaError(file_name + ":" + std::to_string(line) + ": unexpected character '" +
                        std::string(1, character) + "'");
    }
  }
  return tokens;
}

std::optional<FieldKind> primitiveKind(const std::string& type_name)
{
  static constexpr std::pair<std::string_view, FieldKind> kPrimitives[] = {
      {"int8_t", FieldKind::kInt8},     {"int16_t", FieldKind::kInt16}, {"int32_t", FieldKind::kInt32},
      {"int64_t", FieldKind::kInt64},   {"float", FieldKind::kFloat},   {"double", FieldKind::kDouble},
      {"boolean", FieldKind::kBoolean}, {"byte", FieldKind::kByte},     {"string", FieldKind::kString},
  };
  for (const auto& [name, kind] : kPrimitives) {
    if (type_name == name) {
      return kind;
    }
  }
  return std::nullopt;
}

bool isName(const std::string& word)
{
  return !word.empty() && (std::isalpha(static_cast<unsigned char>(word[0])) != 0 || word[0] == '_') &&
         std::all_of(word.begin(), word.end(), [](char character) {
           return std::isalnum(static_cast<unsigned char>(character)) != 0 || character == '_';
         });
}

/// A struct member whose type is another struct, resolved once every file is read.
struct PendingStructReference {
  std::size_t type_index = 0;
  std::size_t field_index = 0;
  std::string type_name;
  std::string where;  // "file:line"
};

class FileParser {
 public:
  FileParser(std::vector<Token> tokens, std::string file_name)
      : tokens_(std::move(tokens)), file_name_(std::move(file_name))
  {
  }

  void parseInto(std::vector<StructType>& types, std::vector<PendingStructReference>& pending)
  {
    while (!atEnd()) {
      const Token keyword = next("'package' or 'struct'");
      if (keyword.text == "package") {
        next("a package name");
        expect(";");
      } else if (keyword.text == "struct") {
        parseStruct(types, pending);
      } else {
        fail(keyword, "expected 'package' or 'struct', found '" + keyword.text + "'");
      }
    }
  }

 private:
  void parseStruct(std::vector<StructType>& types, std::vector<PendingStructReference>& pending)
  {
    StructType type;
    const Token name = next("a struct name");
    if (!isName(name.text)) {
      fail(name, "'" + name.text + "' is not a struct name");
    }
    type.name = name.text;
    expect("{");
    while (peek("a member or '}'").text != "}") {
      const Token first = next("a member");
      if (first.text == "const") {
        while (next("';' ending the constant").text != ";") {
        }
        continue;
      }
      parseMembers(first, type, types.size(), pending);
    }
    const Token closing = next("'}'");
    if (type.fields.empty()) {
      fail(closing, "struct '" + type.name + "' has no members");
    }
    types.push_back(std::move(type));
  }

  /// `TYPE name[dims]..., name[dims]...;` with `type_token` already read.
  void parseMembers(const Token& type_token, StructType& type, std::size_t type_index,
                    std::vector<PendingStructReference>& pending)
  {
    const std::string type_name = type_token.text.substr(type_token.text.rfind('.') + 1);
    const std::optional<FieldKind> kind = primitiveKind(type_name);
    if (!kind && !isName(type_name)) {
      fail(type_token, "'" + type_token.text + "' is not a type");
    }
    while (true) {
      const Token name = next("a member name");
      if (!isName(name.text)) {
        fail(name, "'" + name.text + "' is not a member name");
      }
      Field field;
      field.name = name.text;
      field.kind = kind.value_or(FieldKind::kStruct);
      while (peek("';', ',' or '['").text == "[") {
        next("'['");
        field.dimensions.push_back(parseDimension(type));
        expect("]");
      }
      const bool variable = std::any_of(field.dimensions.begin(), field.dimensions.end(),
                                        [](const Dimension& dimension) { return dimension.is_variable; });
      if (variable && field.dimensions.size() > 1) {
        fail(name, "member '" + field.name +
                       "': multi-dimensional arrays with a variable dimension are not supported");
      }
      if (!kind) {
        pending.push_back({type_index, type.fields.size(), type_name, where(type_token)});
      }
      type.fields.push_back(std::move(field));
      const Token separator = next("';' or ','");
      if (separator.text == ";") {
        return;
      }
      if (separator.text != ",") {
        fail(separator, "expected ';' or ',', found '" + separator.text + "'");
      }
    }
  }

  Dimension parseDimension(StructType& type)
  {
    const Token size = next("an array size");
    Dimension dimension;
    std::int64_t count = 0;
    const char* const end = size.text.data() + size.text.size();
    if (std::from_chars(size.text.data(), end, count).ptr == end) {
      if (count < 0) {
        fail(size, "negative array size " + size.text);
      }
      dimension.fixed_count = count;
      return dimension;
    }
    for (std::size_t index = 0; index < type.fields.size(); ++index) {
      Field& field = type.fields[index];
      if (field.name == size.text) {
        if (!isInteger(field.kind) || !field.dimensions.empty()) {
          fail(size, "array length '" + size.text + "' is not an integer member");
        }
        if (field.length_slot == kNoLengthSlot) {
          field.length_slot = type.length_slots++;
        }
        dimension.is_variable = true;
        dimension.length_field = index;
        return dimension;
      }
    }
    fail(size, "array length '" + size.text + "' names no earlier member of '" + type.name + "'");
  }

  bool atEnd() const { return position_ >= tokens_.size(); }

  const Token& peek(const std::string& wanted) const
  {
    if (atEnd()) {
      throw SchemaError(file_name_ + ": ends where " + wanted + " was expected");
    }
    return tokens_[position_];
  }

  Token next(const std::string& wanted)
  {
    const Token& token = peek(wanted);
    ++position_;
    return token;
  }

  void expect(const std::string& text)
  {
    const Token token = next("'" + text + "'");
    if (token.text != text) {
      fail(token, "expected '" + text + "', found '" + token.text + "'");
    }
  }

  std::string where(const Token& token) const { return file_name_ + ":" + std::to_string(token.line); }

  [[noreturn]] void fail(const Token& token, const std::string& problem) const
  {
    throw SchemaError(where(token) + ": " + problem);
  }

  std::vector<Token> tokens_;
  std::string file_name_;
  std::size_t position_ = 0;
};

/// Fills in min_wire_size; `state` 0 unvisited, 1 in progress, 2 done.
std::size_t computeMinWireSize(std::vector<StructType>& types, std::size_t index, std::vector<int>& state)
{
  if (state[index] == 2) {
    return types[index].min_wire_size;
  }
  if (state[index] == 1) {
    throw SchemaError("struct '" + types[index].name + "' contains itself");
  }
  state[index] = 1;
  std::size_t size = 0;
  bool fixed_size = true;
  for (Field& field : types[index].fields) {
    std::size_t count = 1;
    for (const Dimension& dimension : field.dimensions) {
      count = dimension.is_variable ? 0 : count * static_cast<std::size_t>(dimension.fixed_count);
      fixed_size = fixed_size && !dimension.is_variable;
    }
    field.min_element_size = fixedWireSize(field.kind);
    if (field.kind == FieldKind::kString) {
      field.min_element_size = 5;  // int32 length, and the terminating NUL the length counts
      fixed_size = false;
    } else if (field.kind == FieldKind::kStruct) {
      field.min_element_size = computeMinWireSize(types, field.struct_index, state);
      fixed_size = fixed_size && types[field.struct_index].fixed_size;
    }
    size += count * field.min_element_size;
  }
  // Only zero-length fixed arrays take no bytes; min_wire_size stays at least 1 so counts stay bounded,
  // and such a struct is not of fixed size (its one byte is not really there).
  types[index].fixed_size = fixed_size && size > 0;
  types[index].min_wire_size = std::max<std::size_t>(size, 1);
  state[index] = 2;
  return types[index].min_wire_size;
}

}  // namespace

Schema Schema::parse(const std::vector<std::string_view>& sources, const std::vector<std::string>& names)
{
  if (sources.size() != names.size()) {
    throw SchemaError("Schema::parse: " + std::to_string(sources.size()) + " sources but " +
                      std::to_string(names.size()) + " names");
  }
  Schema schema;
  std::vector<PendingStructReference> pending;
  for (std::size_t file = 0; file < sources.size(); ++file) {
    FileParser(tokenize(sources[file], names[file]), names[file]).parseInto(schema.types_, pending);
  }
  for (std::size_t index = 0; index < schema.types_.size(); ++index) {
    for (std::size_t other = index + 1; other < schema.types_.size(); ++other) {
      if (schema.types_[index].name == schema.types_[other].name) {
        throw SchemaError("struct '" + schema.types_[index].name + "' is defined twice");
      }
    }
  }
  for (const PendingStructReference& reference : pending) {
    const auto found = std::find_if(schema.types_.begin(), schema.types_.end(),
                                    [&](const StructType& type) { return type.name == reference.type_name; });
    if (found == schema.types_.end()) {
      throw SchemaError(reference.where + ": unknown type '" + reference.type_name + "'");
    }
    schema.types_[reference.type_index].fields[reference.field_index].struct_index =
        static_cast<std::size_t>(found - schema.types_.begin());
  }
  std::vector<int> state(schema.types_.size(), 0);
  for (std::size_t index = 0; index < schema.types_.size(); ++index) {
    computeMinWireSize(schema.types_, index, state);
  }
  return schema;
}

const StructType* Schema::find(std::string_view name) const
{
  const auto found =
      std::find_if(types_.begin(), types_.end(), [&](const StructType& type) { return type.name == name; });
  return found == types_.end() ? nullptr : &*found;
}

}  // namespace ifar::lcm_wire
