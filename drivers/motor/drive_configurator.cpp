#include "drivers/motor/drive_configurator.hpp"

#include <cstdio>
#include <utility>

namespace ifar::motor {

DriveConfigurator::DriveConfigurator(DriveConfiguratorSettings settings) : settings_(std::move(settings))
{
  if (settings_.attempts < 1) {
    settings_.attempts = 1;
  }
}

void DriveConfigurator::restart()
{
  next_ = 0;
  attempt_ = 0;
  sent_at_us_.reset();
  failed_at_us_.reset();
}

std::string DriveConfigurator::describe(const SdoWrite& write) const
{
  char text[96];
  std::snprintf(text, sizeof(text), "drive %u object 0x%04X:%02X = %u (0x%0*X)",
                static_cast<unsigned>(settings_.node_id), static_cast<unsigned>(write.index),
                static_cast<unsigned>(write.subindex), static_cast<unsigned>(write.value),
                static_cast<int>(2 * write.size), static_cast<unsigned>(write.value));
  return text;
}

void DriveConfigurator::fail(std::string error, std::int64_t now_us)
{
  error_ = std::move(error);
  failed_at_us_ = now_us;
  sent_at_us_.reset();
  ++failures_;
}

void DriveConfigurator::onAnswer(const SdoAnswer& answer, std::int64_t now_us)
{
  if (done() || !sent_at_us_) {
    return;
  }
  const SdoWrite& write = settings_.writes[next_];
  if (answer.index != write.index || answer.subindex != write.subindex) {
    return;
  }
  if (answer.kind == SdoAnswer::Kind::kAbort) {
    char code[16];
    std::snprintf(code, sizeof(code), "0x%08X", static_cast<unsigned>(answer.abort_code));
    fail(describe(write) + " refused: SDO abort " + code + " (" + sdoAbortText(answer.abort_code) + ")",
         now_us);
    return;
  }
  sent_at_us_.reset();
  attempt_ = 0;
  ++next_;
  if (done()) {
    error_.clear();
  }
}

std::vector<can::Frame> DriveConfigurator::update(std::int64_t now_us)
{
  std::vector<can::Frame> frames;
  if (done()) {
    return frames;
  }
  if (failed_at_us_) {
    if (now_us - *failed_at_us_ < settings_.retry_us) {
      return frames;
    }
    restart();
  }
  const SdoWrite& write = settings_.writes[next_];
  if (sent_at_us_) {
    if (now_us - *sent_at_us_ <= settings_.timeout_us) {
      return frames;  // waiting for the answer
    }
    // Tell the drive the transfer is over before starting another on the same channel.
    frames.push_back(
        encodeSdoAbort(kSdoRequestBase + settings_.node_id, write.index, write.subindex, kAbortTimedOut));
    ++timeouts_;
    if (attempt_ >= settings_.attempts) {
      fail(describe(write) + ": no answer in " + std::to_string(settings_.attempts) + " attempts of " +
               std::to_string(settings_.timeout_us / 1000) + " ms",
           now_us);
      return frames;
    }
  }
  frames.push_back(encodeSdoDownload(settings_.node_id, write));
  sent_at_us_ = now_us;
  ++attempt_;
  return frames;
}

}  // namespace ifar::motor
