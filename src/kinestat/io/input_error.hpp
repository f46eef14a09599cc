// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The one error type for bad input: every message names file, line and column so that a
// user can jump straight to the problem (`file:line:column: what was expected`).

#include <string>
#include <vector>

#include "kinestat/error.hpp"

namespace kinestat::io {

using kinestat::SourceLocation;

/// Thrown by readers for malformed or inconsistent input. `what()` is the full one-line
/// message `file:line:column: error: <problem>`; the CLI prints it and exits with code 2.
class InputError : public Error {
 public:
  InputError(SourceLocation where, const std::string& problem);
  const std::string& problem() const { return problem_; }
  /// The notices the reader gave before it met the error (an older spelling read, for
  /// example, that explains the error): the command prints them before the error line.
  const std::vector<std::string>& notices() const { return notices_; }
  /// Sets notices(); the model readers call it on the way out.
  void set_notices(std::vector<std::string> notices) { notices_ = std::move(notices); }

 private:
  std::string problem_;
  std::vector<std::string> notices_;
};

}  // namespace kinestat::io
