#include "common/signals.hpp"

namespace ifar::common {

void restoreDefaultActions(const sigset_t& signals)
{
  struct sigaction action {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  for (int signal_number = 1; signal_number < NSIG; ++signal_number) {
    if (sigismember(&signals, signal_number) == 1) {
      sigaction(signal_number, &action, nullptr);
    }
  }
}

}  // namespace ifar::common
