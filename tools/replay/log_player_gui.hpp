#pragma once
// lcm-logplayer-gui (lcm.logging.LogPlayer in lcm.jar) for `ifar replay --gui`. It plays what it is given and
// can switch channels off but not single CAN frames, so every channel on which `ifar replay` would leave
// something out starts switched off (its --filter), and the user can switch it on in the window.

#include <set>
#include <string>
#include <vector>

namespace ifar::replay {

/// A Java regular expression that matches exactly the names in `names`, each quoted (\Q...\E) so no
/// character of a name is taken as regex syntax; "" for no names.
std::string javaRegexOfNames(const std::set<std::string>& names);

/// LogPlayer's arguments: `lcm_url` (when not empty), the channels in `switched_off` filtered out, paused at
/// the start when `paused`, `log`.
std::vector<std::string> logPlayerArguments(const std::string& log, const std::set<std::string>& switched_off,
                                            const std::string& lcm_url, bool paused);

}  // namespace ifar::replay
