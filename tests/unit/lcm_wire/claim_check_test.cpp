// The length-claim check on hand-built encodings: backed claims pass, and each kind of unbacked one is
// named with its member and byte offset.

#include "common/lcm_wire/claim_check.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace ifar::lcm_wire {
namespace {

constexpr const char* kDefinitions = R"(
struct point_t { double x; double y; }
struct shape_t
{
  int32_t  num_points;
  point_t  points[num_points];
  string   name;
  int64_t  num_tags;
  byte     tags[num_tags];
  int16_t  scale[2];
}
)";

class Bytes {
 public:
  Bytes() { append(0x0123456789abcdefULL, 8); }  // the type hash, which the check skips
  Bytes& append(std::uint64_t value, int size)
  {
    for (int shift = 8 * (size - 1); shift >= 0; shift -= 8) {
      bytes_.push_back(static_cast<std::uint8_t>(value >> shift));
    }
    return *this;
  }
  Bytes& int32(std::int32_t value) { return append(static_cast<std::uint32_t>(value), 4); }
  Bytes& int64(std::int64_t value) { return append(static_cast<std::uint64_t>(value), 8); }
  Bytes& string(const std::string& text)
  {
    int32(static_cast<std::int32_t>(text.size() + 1));
    bytes_.insert(bytes_.end(), text.begin(), text.end());
    bytes_.push_back(0);
    return *this;
  }
  Bytes& zeros(std::size_t count)
  {
    bytes_.insert(bytes_.end(), count, 0);
    return *this;
  }
  const std::vector<std::uint8_t>& data() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

class ClaimCheck : public ::testing::Test {
 protected:
  std::optional<std::string> check(const Bytes& bytes) const
  {
    return findUnbackedClaim(schema_, *schema_.find("shape_t"), bytes.data());
  }

  Schema schema_ = Schema::parse({kDefinitions}, {"shape.lcm"});
};

TEST_F(ClaimCheck, BackedClaimsPass)
{
  EXPECT_EQ(check(Bytes().int32(2).zeros(32).string("box").int64(3).zeros(3).zeros(4)), std::nullopt);
  EXPECT_EQ(check(Bytes().int32(0).string("").int64(0).zeros(4)), std::nullopt);
  // Bytes after the message are LCM's decode's business, as they are for the check.
  EXPECT_EQ(check(Bytes().int32(0).string("").int64(0).zeros(4).zeros(100)), std::nullopt);
}

TEST_F(ClaimCheck, TheEncodedLengthIsWhereTheMessageEnds)
{
  const StructType& shape = *schema_.find("shape_t");
  // hash 8, count 4, two points 32, "box" 8, tag count 8, three tags, scale 4.
  const Bytes bytes = Bytes().int32(2).zeros(32).string("box").int64(3).zeros(3).zeros(4);
  EXPECT_EQ(encodedLength(schema_, shape, bytes.data()), 67U);
  EXPECT_EQ(encodedLength(schema_, shape, Bytes(bytes).zeros(9).data()), 67U);
  EXPECT_EQ(encodedLength(schema_, shape, Bytes().int32(3).zeros(47).data()), std::nullopt);
}

TEST_F(ClaimCheck, AnArrayCountBeyondTheBytesIsNamed)
{
  EXPECT_EQ(check(Bytes().int32(1'000'000'000).zeros(40)),
            "shape_t.points claims 1000000000 elements of at least 16 bytes at byte 12, 40 bytes left");
  // Three points need 48 bytes; 47 are left.
  EXPECT_EQ(check(Bytes().int32(3).zeros(47)),
            "shape_t.points claims 3 elements of at least 16 bytes at byte 12, 47 bytes left");
  EXPECT_EQ(check(Bytes().int32(-1).zeros(40)), "shape_t.points claims -1 elements at byte 12");
}

TEST_F(ClaimCheck, AnInt64CountTooLargeToMultiplyIsRefused)
{
  EXPECT_EQ(check(Bytes().int32(0).string("").int64(INT64_MAX).zeros(8)),
            "shape_t.tags claims 9223372036854775807 elements of at least 1 bytes at byte 25, 8 bytes left");
}

TEST_F(ClaimCheck, BadStringLengthsAreNamed)
{
  EXPECT_EQ(check(Bytes().int32(0).int32(0).zeros(20)),
            "shape_t.name claims a string of 0 bytes (its NUL included) at byte 12, 20 bytes left");
  EXPECT_EQ(check(Bytes().int32(0).int32(-5).zeros(20)),
            "shape_t.name claims a string of -5 bytes (its NUL included) at byte 12, 20 bytes left");
  EXPECT_EQ(check(Bytes().int32(0).int32(2'000'000'000).zeros(20)),
            "shape_t.name claims a string of 2000000000 bytes (its NUL included) at byte 12, 20 bytes left");
  EXPECT_EQ(check(Bytes().int32(0).zeros(2)),
            "shape_t.name is cut off: needs at least 5 bytes at byte 12, 2 bytes left");
}

TEST_F(ClaimCheck, FixedMembersCutOffAreNamed)
{
  EXPECT_EQ(check(Bytes().int32(0).string("").int64(0).zeros(3)),
            "shape_t.scale is cut off: needs at least 4 bytes at byte 25, 3 bytes left");
  EXPECT_EQ(check(Bytes().zeros(2)),
            "shape_t.num_points is cut off: needs at least 4 bytes at byte 8, 2 bytes left");
  const std::vector<std::uint8_t> five_bytes(5, 0);
  EXPECT_EQ(findUnbackedClaim(schema_, *schema_.find("shape_t"), five_bytes),
            "shape_t needs its 8-byte type hash, 5 bytes given");
}

TEST_F(ClaimCheck, AClaimInsideANestedElementIsNamedWithItsIndex)
{
  const Schema schema = Schema::parse({"struct inner_t { int32_t n; double values[n]; }\n"
                                       "struct outer_t { int32_t count; inner_t items[count]; }"},
                                      {"nested.lcm"});
  // Item 0 holds one value; item 1 claims 70000 of them with 8 bytes left.
  const Bytes bytes = Bytes().int32(2).int32(1).zeros(8).int32(70000).zeros(8);
  EXPECT_EQ(findUnbackedClaim(schema, *schema.find("outer_t"), bytes.data()),
            "outer_t.items[1].values claims 70000 elements of at least 8 bytes at byte 28, 8 bytes left");
}

}  // namespace
}  // namespace ifar::lcm_wire
