#pragma once
// Cooperative interruption: the CLI's SIGINT/SIGTERM handler records the signal, and long loops
// (each claim, each numeric sample) call throw_if_interrupted(), so a run stops within one sample.

#include <atomic>
#include <stdexcept>
#include <string>

namespace simpson::verify {

/// The signal that asked the run to stop, or 0. Lock-free, so a signal handler may store to it.
inline std::atomic<int>& interruption_signal() {
  static std::atomic<int> signal{0};
  return signal;
}

/// Thrown by throw_if_interrupted(); carries the signal number.
class interrupted : public std::runtime_error {
 public:
  explicit interrupted(int signal) : std::runtime_error("interrupted by signal " + std::to_string(signal)), signal_(signal) {}
  int signal() const noexcept { return signal_; }

 private:
  int signal_;
};

inline void throw_if_interrupted() {
  if (const int s = interruption_signal().load(std::memory_order_relaxed); s != 0) throw interrupted(s);
}

}  // namespace simpson::verify
