// SPDX-License-Identifier: MIT
// A request to stop a long run early (Ctrl-C, SIGTERM from a batch system). The one piece of
// process-wide state: a signal handler can only reach a global. Runs poll it once per step and
// stop cleanly, writing their results so far.
#pragma once
#include <atomic>

namespace drydem {

inline std::atomic<int>& stop_signal() {
    static std::atomic<int> signal{0};
    return signal;
}
/// Asks every running simulation to stop after its current step (async-signal-safe).
inline void request_stop(int signal_number) {
    stop_signal().store(signal_number, std::memory_order_relaxed);
}
inline int stop_requested() { return stop_signal().load(std::memory_order_relaxed); }

} // namespace drydem
