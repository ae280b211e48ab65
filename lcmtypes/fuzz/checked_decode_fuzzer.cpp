// libFuzzer: arbitrary bytes as each project message type (the first input byte picks the type, the
// type hash is put in front of the rest). The checked decode must never crash, never allocate what the
// bytes merely claim (scripts/fuzz-lcm caps single allocations at 16 MB), and never refuse what LCM's
// generated decode takes: bytes whose every claim is backed must decode to exactly the length the claim
// check walked. (Bytes with an unbacked claim are refused by the checked decode before LCM sees them.)
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "common/lcm_wire/claim_check.hpp"
#include "lcmtypes/message_schema.hpp"
#include "lcmtypes/samples/sample_messages.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const std::vector<ifar::lcmtypes_samples::SampleMessage> samples =
      ifar::lcmtypes_samples::allSampleMessages();
  if (size == 0) {
    return 0;
  }
  const auto& sample = samples[data[0] % samples.size()];
  std::vector<std::uint8_t> bytes(sample.encoded.begin(), sample.encoded.begin() + 8);  // the hash
  bytes.insert(bytes.end(), data + 1, data + size);

  const auto& schema = ifar::lcmtypes::messageSchema();
  const auto* type = schema.find(sample.type_name);
  if (type == nullptr) {
    std::abort();
  }
  std::vector<std::uint8_t> reencoded;
  if (const auto length = ifar::lcm_wire::encodedLength(schema, *type, bytes)) {
    bytes.resize(*length);
    if (!sample.reencode(bytes, reencoded)) {
      std::abort();  // the walk and LCM's decode disagree on where this message ends
    }
  } else if (sample.reencode(bytes, reencoded)) {
    std::abort();  // the checked decode took bytes the claim check refuses
  }
  return 0;
}
