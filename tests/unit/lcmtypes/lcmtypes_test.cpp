// Every project LCM type encodes and decodes to equal values, and no deployed type changes silently.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "ifar/path_t.hpp"
#include "ifar/pose_t.hpp"
#include "lcmtypes/samples/sample_messages.hpp"

namespace {

using ifar::lcmtypes_samples::allSampleMessages;

const std::string kFingerprintFile = std::string(IFAR_SOURCE_DIR) + "/lcmtypes/fingerprints.txt";

std::map<std::string, std::string> readFingerprints()
{
  std::map<std::string, std::string> result;
  std::ifstream stream(kFingerprintFile);
  std::string line;
  while (std::getline(stream, line)) {
    if (line.empty() || line.front() == '#') {
      continue;
    }
    std::istringstream fields(line);
    std::string name;
    std::string fingerprint;
    fields >> name >> fingerprint;
    result[name] = fingerprint;
  }
  return result;
}

std::string hex(std::int64_t fingerprint)
{
  char text[32];
  std::snprintf(text, sizeof(text), "0x%016llx", static_cast<unsigned long long>(fingerprint));
  return text;
}

TEST(LcmTypes, EverySampleRoundTripsToEqualValues)
{
  for (const auto& sample : allSampleMessages()) {
    std::vector<std::uint8_t> reencoded;
    ASSERT_TRUE(sample.reencode(sample.encoded, reencoded)) << sample.type_name << " did not decode";
    EXPECT_EQ(reencoded, sample.encoded) << sample.type_name << " changed in an encode/decode round trip";
  }
}

TEST(LcmTypes, TruncatedBytesDoNotDecode)
{
  for (const auto& sample : allSampleMessages()) {
    std::vector<std::uint8_t> truncated(sample.encoded.begin(), sample.encoded.end() - 1);
    std::vector<std::uint8_t> reencoded;
    EXPECT_FALSE(sample.reencode(truncated, reencoded))
        << sample.type_name << " decoded from truncated bytes";
  }
}

TEST(LcmTypes, NestedValuesSurviveTheRoundTrip)
{
  for (const auto& sample : allSampleMessages()) {
    if (sample.type_name != "path_t") {
      continue;
    }
    ifar::path_t path;
    ASSERT_EQ(path.decode(sample.encoded.data(), 0, static_cast<int>(sample.encoded.size())),
              static_cast<int>(sample.encoded.size()));
    ASSERT_EQ(path.num_waypoints, 3);
    EXPECT_DOUBLE_EQ(path.waypoints[2].x, 3.0);
    EXPECT_EQ(path.waypoints[2].kind, ifar::waypoint_t::KIND_PUSH);
    ASSERT_EQ(path.num_push_plans, 1);
    ASSERT_EQ(path.push_plans[0].num_controls, 3);
    EXPECT_EQ(path.push_plans[0].controls[1].kind, ifar::push_control_t::KIND_SWITCH_CONTACT);
    EXPECT_DOUBLE_EQ(path.push_plans[0].expected_cost, 7.5);
    EXPECT_EQ(path.push_plans[0].object_id, 42);
    return;
  }
  FAIL() << "no path_t sample";
}

TEST(LcmTypes, EveryGeneratedTypeHasASample)
{
  std::ifstream list(IFAR_LCM_TYPE_LIST);
  ASSERT_TRUE(list) << "cannot read the generated type list " << IFAR_LCM_TYPE_LIST;
  std::set<std::string> sampled;
  for (const auto& sample : allSampleMessages()) {
    sampled.insert(sample.type_name);
  }
  std::string name;
  while (list >> name) {
    EXPECT_EQ(sampled.count(name), 1U)
        << "lcmtypes/" << name << ".lcm has no sample: add one to lcmtypes/samples/sample_messages.cpp";
  }
}

TEST(LcmTypes, DeployedTypesKeepTheirFingerprints)
{
  const auto recorded = readFingerprints();
  ASSERT_FALSE(recorded.empty()) << "cannot read " << kFingerprintFile;
  std::set<std::string> present;
  for (const auto& sample : allSampleMessages()) {
    present.insert(sample.type_name);
    const auto found = recorded.find(sample.type_name);
    if (found == recorded.end()) {
      ADD_FAILURE() << "new type " << sample.type_name << ": add the line '" << sample.type_name << " "
                    << hex(sample.fingerprint)
                    << "' to lcmtypes/fingerprints.txt (ifar-lcm-fingerprints prints it)";
      continue;
    }
    EXPECT_EQ(found->second, hex(sample.fingerprint))
        << sample.type_name << " was edited: its fingerprint changed from " << found->second << " to "
        << hex(sample.fingerprint)
        << ". Deployed types must not change (logs and running vehicles decode by fingerprint): revert the "
           "edit and add a new type instead (for example "
        << sample.type_name.substr(0, sample.type_name.size() - 2) << "_v2_t).";
  }
  for (const auto& [name, fingerprint] : recorded) {
    EXPECT_EQ(present.count(name), 1U) << "deployed type " << name << " (" << fingerprint
                                       << ") was removed: keep it so old logs still decode";
  }
}

TEST(LcmTypes, PoseFieldsKeepTheirValues)
{
  for (const auto& sample : allSampleMessages()) {
    if (sample.type_name != "pose_t") {
      continue;
    }
    ifar::pose_t pose;
    ASSERT_GT(pose.decode(sample.encoded.data(), 0, static_cast<int>(sample.encoded.size())), 0);
    EXPECT_EQ(pose.utime, 1'763'800'000'123'456);
    EXPECT_DOUBLE_EQ(pose.position[0], 10.5);
    EXPECT_DOUBLE_EQ(pose.orientation[3], 0.3826834323650898);
    EXPECT_DOUBLE_EQ(pose.angular_velocity[2], 0.3);
    return;
  }
  FAIL() << "no pose_t sample";
}

}  // namespace
