#include "bus/duplicate_process_watch.hpp"

#include <utility>

namespace ifar::bus {

DuplicateProcessWatch::DuplicateProcessWatch(std::string process, std::int32_t own_pid,
                                             std::int64_t forget_after_us)
    : process_(std::move(process)), own_pid_(own_pid), forget_after_us_(forget_after_us)
{
}

std::optional<std::string> DuplicateProcessWatch::onBeat(const std::string& process, std::int32_t pid,
                                                         std::int64_t now_us)
{
  if (process != process_ || pid == own_pid_) {
    return std::nullopt;
  }
  const auto [entry, inserted] = others_.try_emplace(pid, now_us);
  const bool returning = !inserted && now_us - entry->second > forget_after_us_;
  entry->second = now_us;
  if (!inserted && !returning) {
    return std::nullopt;
  }
  return "another " + process_ + " (pid " + std::to_string(pid) +
         ") beats on this LCM URL beside this one (pid " + std::to_string(own_pid_) +
         "): two stacks or a replayed log share the bus; give each stack its own LCM URL";
}

std::string DuplicateProcessWatch::problem(std::int64_t now_us) const
{
  std::string pids;
  for (const auto& [pid, last_us] : others_) {
    if (now_us - last_us <= forget_after_us_) {
      pids += (pids.empty() ? "" : ", ") + std::to_string(pid);
    }
  }
  return pids.empty() ? std::string() : "another " + process_ + " on this LCM URL (pid " + pids + ")";
}

}  // namespace ifar::bus
