// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The root of every error kinestat throws on purpose. A caller catches kinestat::Error once
// and gets the message, the exit code a command should end with and, for input problems,
// where in which file the problem is. std::bad_alloc (out of memory) stays what it is.

#include <stdexcept>
#include <string>
#include <utility>

namespace kinestat {

/// A position in an input file. Lines and columns are 1-based; 0 means "unknown".
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

/// Exit code of a command for input that is malformed, inconsistent or degenerate.
inline constexpr int kExitBadInput = 2;

/// Base of kinestat's errors: bad input, degenerate geometry, models that cannot be analysed.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message, SourceLocation where = {}, int exit_code = kExitBadInput)
      : std::runtime_error(message), where_(std::move(where)), exit_code_(exit_code) {}

  /// The file position the error concerns; empty file and line 0 when it has none.
  const SourceLocation& where() const noexcept { return where_; }
  /// The exit code a command reporting this error ends with.
  int exit_code() const noexcept { return exit_code_; }

 private:
  SourceLocation where_;
  int exit_code_;
};

}  // namespace kinestat
