#pragma once
// Signal actions for processes that read their signals from a signalfd (daemons, ifar launch).

#include <signal.h>

namespace ifar::common {

/// Sets the action of every signal in `signals` back to the default. A signal inherited as ignored (a
/// shell starts background jobs with SIGINT ignored) is discarded before a signalfd can read it, so the
/// process could not be stopped cleanly. Async-signal-safe: also usable between fork and exec.
void restoreDefaultActions(const sigset_t& signals);

}  // namespace ifar::common
