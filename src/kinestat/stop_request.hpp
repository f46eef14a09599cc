// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A caller's request that a long computation stop early (Ctrl-C in the Python module). The
// library never watches signals or any other process-wide state (DESIGN.md): the caller owns the
// flag and sets it from wherever it learns of the request (typically another thread); the
// library polls it between the stages of an analysis and in its long loops and then throws
// Stopped. Polling is one relaxed atomic load, so a check per step of a loop costs nothing.

#include <atomic>
#include <exception>

namespace kinestat {

/// Thrown where a StopRequest was found set. Deliberately not a kinestat::Error: the catch
/// blocks that turn an Error into a message (a sweep's error line, a verdict's note) must not
/// swallow it.
class Stopped : public std::exception {
 public:
  const char* what() const noexcept override { return "stopped at the caller's request"; }
};

/// Where to look for a request to stop; by default nowhere (never stops). The flag belongs to
/// the caller and must outlive the computation.
struct StopRequest {
  const std::atomic<bool>* flag = nullptr;

  /// True once the caller has set the flag.
  bool requested() const noexcept { return flag != nullptr && flag->load(std::memory_order_relaxed); }
  /// Throws Stopped when the caller has set the flag.
  void throw_if_requested() const {
    if (requested()) throw Stopped();
  }
};

}  // namespace kinestat
