#include "tools/replay/replay_report.hpp"

#include <array>
#include <cstdio>

namespace ifar::replay {

void ReplayReport::count(const std::string& channel, Verdict verdict)
{
  switch (verdict) {
    case Verdict::kPublish:
      ++published_;
      return;
    case Verdict::kNotSelected:
      ++not_selected_;
      return;
    case Verdict::kCommand:
    case Verdict::kDriveCommand:
      ++commands_;
      ++commands_by_channel_[channel];
      return;
  }
}

std::string ReplayReport::progressLine(std::int64_t log_elapsed_us, std::uint64_t position,
                                       std::uint64_t size, bool paused) const
{
  const double percent = size > 0 ? 100.0 * static_cast<double>(position) / static_cast<double>(size) : 100.0;
  std::array<char, 160> text{};
  std::snprintf(text.data(), text.size(), "log %.1f s, %.0f%%, %llu published, %llu commands left out%s",
                static_cast<double>(log_elapsed_us) * 1e-6, percent,
                static_cast<unsigned long long>(published_), static_cast<unsigned long long>(commands_),
                paused ? ", paused" : "");
  return text.data();
}

std::string ReplayReport::summary() const
{
  std::string text = std::to_string(published_) + " messages published, " + std::to_string(commands_) +
                     " commands left out, " + std::to_string(not_selected_) + " not selected";
  for (const auto& [channel, count] : commands_by_channel_) {
    text += "\n  left out on " + channel + ": " + std::to_string(count);
  }
  return text;
}

}  // namespace ifar::replay
