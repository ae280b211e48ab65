// Reading .lcm definitions: layouts, minimum sizes, and the errors for what the reader refuses.

#include "common/lcm_wire/schema.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace ifar::lcm_wire {
namespace {

constexpr std::string_view kPoint = R"(package demo;
/* A point,
   over three lines. */
struct point_t
{
  const int8_t KIND_A = 0, KIND_B = 1;  // not on the wire
  double x, y;
  int8_t kind;
}
)";

constexpr std::string_view kShape = R"(package demo;

struct shape_t
{
  int64_t       utime;
  string        name;          // int32 length, then the bytes and a NUL
  float         scale[2][3];
  int16_t       num_points;
  demo.point_t  points[num_points];
  boolean       closed;
  byte          tag[4];
}
)";

Schema parseOne(std::string_view text)
{
  return Schema::parse({text}, {"test.lcm"});
}

std::string parseError(const std::vector<std::string_view>& texts)
{
  std::vector<std::string> names;
  for (std::size_t index = 0; index < texts.size(); ++index) {
    names.push_back("file" + std::to_string(index) + ".lcm");
  }
  try {
    Schema::parse(texts, names);
  } catch (const SchemaError& error) {
    return error.what();
  }
  return "no error";
}

TEST(LcmWireSchema, ReadsMembersDimensionsAndNestedTypes)
{
  // The shape refers to the point before the point's file is read: references resolve at the end.
  const Schema schema = Schema::parse({kShape, kPoint}, {"shape_t.lcm", "point_t.lcm"});
  ASSERT_EQ(schema.types().size(), 2U);
  const StructType* point = schema.find("point_t");
  const StructType* shape = schema.find("shape_t");
  ASSERT_NE(point, nullptr);
  ASSERT_NE(shape, nullptr);
  EXPECT_EQ(schema.find("demo.point_t"), nullptr);
  EXPECT_EQ(schema.find("line_t"), nullptr);

  ASSERT_EQ(point->fields.size(), 3U);
  EXPECT_EQ(point->fields[0].name, "x");
  EXPECT_EQ(point->fields[1].name, "y");
  EXPECT_EQ(point->fields[1].kind, FieldKind::kDouble);
  EXPECT_EQ(point->fields[2].kind, FieldKind::kInt8);
  EXPECT_EQ(point->min_wire_size, 17U);
  EXPECT_TRUE(point->fixed_size);
  EXPECT_EQ(point->length_slots, 0U);

  ASSERT_EQ(shape->fields.size(), 7U);
  EXPECT_EQ(shape->fields[1].kind, FieldKind::kString);
  const Field& scale = shape->fields[2];
  ASSERT_EQ(scale.dimensions.size(), 2U);
  EXPECT_FALSE(scale.dimensions[0].is_variable);
  EXPECT_EQ(scale.dimensions[0].fixed_count, 2);
  EXPECT_EQ(scale.dimensions[1].fixed_count, 3);
  const Field& points = shape->fields[4];
  EXPECT_EQ(points.kind, FieldKind::kStruct);
  EXPECT_EQ(&schema.types()[points.struct_index], point);
  ASSERT_EQ(points.dimensions.size(), 1U);
  EXPECT_TRUE(points.dimensions[0].is_variable);
  EXPECT_EQ(points.dimensions[0].length_field, 3U);
  EXPECT_EQ(shape->fields[5].kind, FieldKind::kBoolean);
  EXPECT_EQ(shape->fields[6].kind, FieldKind::kByte);
  // utime 8, empty name 5, scale 24, num_points 2, no points, closed 1, tag 4.
  EXPECT_EQ(shape->min_wire_size, 44U);
  EXPECT_EQ(shape->fields[1].min_element_size, 5U);  // a string: its int32 length and the NUL
  EXPECT_EQ(shape->fields[2].min_element_size, 4U);
  EXPECT_EQ(points.min_element_size, 17U);  // a point_t
  EXPECT_FALSE(shape->fixed_size);
  EXPECT_EQ(shape->length_slots, 1U);
  EXPECT_EQ(shape->fields[3].length_slot, 0U);
  EXPECT_EQ(shape->fields[0].length_slot, kNoLengthSlot);
}

TEST(LcmWireSchema, WireSizesOfThePrimitives)
{
  EXPECT_EQ(fixedWireSize(FieldKind::kBoolean), 1U);
  EXPECT_EQ(fixedWireSize(FieldKind::kInt16), 2U);
  EXPECT_EQ(fixedWireSize(FieldKind::kFloat), 4U);
  EXPECT_EQ(fixedWireSize(FieldKind::kInt64), 8U);
  EXPECT_EQ(fixedWireSize(FieldKind::kString), 0U);
  EXPECT_TRUE(isInteger(FieldKind::kByte));
  EXPECT_FALSE(isInteger(FieldKind::kBoolean));
  EXPECT_FALSE(isInteger(FieldKind::kDouble));
}

TEST(LcmWireSchema, AStructWithOnlyEmptyArraysStillTakesAByte)
{
  const Schema schema = parseOne("struct empty_t { double none[0]; }\nstruct holder_t { empty_t inside; }");
  EXPECT_EQ(schema.find("empty_t")->min_wire_size, 1U);
  EXPECT_FALSE(schema.find("empty_t")->fixed_size);
  EXPECT_FALSE(schema.find("holder_t")->fixed_size);
}

TEST(LcmWireSchema, ErrorsNameTheFileTheLineAndTheProblem)
{
  EXPECT_EQ(parseError({"struct a_t\n{\n  int32_t n;\n  b_t items[n];\n}\n"}),
            "file0.lcm:4: unknown type 'b_t'");
  EXPECT_EQ(parseError({"struct a_t\n{\n  double items[n];\n  int32_t n;\n}\n"}),
            "file0.lcm:3: array length 'n' names no earlier member of 'a_t'");
  EXPECT_EQ(parseError({"struct a_t\n{\n  double n;\n  double items[n];\n}\n"}),
            "file0.lcm:4: array length 'n' is not an integer member");
  EXPECT_EQ(
      parseError({"struct a_t\n{\n  int32_t n;\n  double grid[n][2];\n}\n"}),
      "file0.lcm:4: member 'grid': multi-dimensional arrays with a variable dimension are not supported");
  EXPECT_EQ(parseError({"struct a_t\n{\n}\n"}), "file0.lcm:3: struct 'a_t' has no members");
  EXPECT_EQ(parseError({"struct a_t { double x[-2]; }"}), "file0.lcm:1: negative array size -2");
  EXPECT_EQ(parseError({"struct a_t\n{\n  /* never closed\n"}), "file0.lcm:3: comment never closed");
  EXPECT_EQ(parseError({"struct a_t { double x }"}), "file0.lcm:1: expected ';' or ',', found '}'");
  EXPECT_EQ(parseError({"struct a_t { double x;"}), "file0.lcm: ends where a member or '}' was expected");
  EXPECT_EQ(parseError({"enum a_t { X }"}), "file0.lcm:1: expected 'package' or 'struct', found 'enum'");
  EXPECT_EQ(parseError({"struct a_t { double x; }", "\nstruct a_t { double y; }"}),
            "struct 'a_t' is defined twice");
  EXPECT_EQ(parseError({"struct a_t { b_t b; }", "struct b_t { a_t a; }"}), "struct 'a_t' contains itself");
  EXPECT_EQ(parseError({"struct a_t { double x; } $"}), "file0.lcm:1: unexpected character '$'");
}

}  // namespace
}  // namespace ifar::lcm_wire
